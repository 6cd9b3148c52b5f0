"""The sheet linter's run over many mechanisms (`make sheets-lint`): both
sheets of every sample, seed task, hard case, variant and generated
mechanism composed in en and uk and checked by the rules of `lint`; a table
of rule × mechanisms passing, and each failing mechanism's file and findings
written out.

Apart from `lint` because it composes sheets, and a composer may ask the
linter's rules about its own trial drawings (sheet 2's lever details)."""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

from ..render.recording import RecordingBackend
from .lint import RULES, Finding, SheetView, lint, lint_pair


@dataclass(frozen=True)
class Case:
    """One mechanism to lint: a name and its file's text."""

    name: str
    toml: str
    path: str = ""


def lint_case(case: Case) -> tuple[Case, list[Finding], set[str]]:
    """Every sheet of one mechanism in en and uk: its findings, and the rules
    that were checked (a sheet that cannot be composed is a finding of
    ``composes``)."""
    from ..errors import MmtError
    from ..solution import solve
    from ..spec import loads
    from .compose import available_sheets

    findings: list[Finding] = []
    checked: set[str] = {"composes"}
    try:
        solution = solve(loads(case.toml, case.path or case.name))
    except MmtError as err:
        return case, [Finding("composes", f"not solved: {err}", (0.0, 0.0), case.name)], checked
    # sheets 1 and 2, and the further sheets of a force analysis too large for sheet 2
    for n, compose in sorted(available_sheets(solution).items()):
        views: dict[str, SheetView] = {}
        for lang in ("en", "uk"):
            name = f"{case.name} sheet {n} {lang}"
            backend = RecordingBackend(841.0, 594.0)
            try:
                compose(solution, backend, lang)
            except MmtError as err:
                findings.append(Finding("composes", str(err).splitlines()[0], (0.0, 0.0), name))
                continue
            except Exception as err:  # a bug: reported, the run goes on
                findings.append(Finding("composes", f"crash: {err!r}", (0.0, 0.0), name))
                continue
            try:
                views[lang] = SheetView.of(backend, lang, name)  # type: ignore[arg-type]
                findings.extend(lint(views[lang]))
            except Exception as err:  # a bug of the linter: reported, the run goes on
                findings.append(Finding("composes", f"lint crash: {err!r}", (0.0, 0.0), name))
                continue
            checked.update(RULES)
        if len(views) == 2:
            findings.extend(lint_pair(views["en"], views["uk"]))
    return case, findings, checked


def cases(
    generated: int, variants: int, spread: float, root: str = ".", every: int = 1
) -> list[Case]:
    """Every sample and seed task (every `every`-th task), the hard cases of
    tests/data/hard, `variants` variants
    of every sample family at ±`spread` %, and `generated` mechanisms of the
    seeded generator."""
    from pathlib import Path

    from ..errors import MmtError
    from ..variants import make_variants

    base = Path(root)
    samples = sorted((base / "samples").glob("*.toml"))
    tasks = sorted((base / "samples" / "tasks").rglob("*.toml"))[:: max(1, every)]
    hard = sorted((base / "tests" / "data" / "hard").glob("*.toml"))  # the hard cases of #21
    out = [Case(p.stem, p.read_text(encoding="utf-8"), str(p)) for p in samples + tasks + hard]
    for p in samples if variants else []:
        made = []
        for wide in (spread, spread / 2, spread / 4):  # the widest spread that gives them
            try:
                made = make_variants(p, variants, seed=21, spread_percent=wide)
                break
            except MmtError:
                continue
        out += [
            Case(f"{p.stem}_v{v.number:02d}", v.text, f"{p.stem}_v{v.number:02d}.toml")
            for v in made
        ]
    return out + [_generated_case(seed) for seed in range(generated)]


def _generated_case(seed: int) -> Case:
    from ..generate import generate_one

    g = generate_one(seed)
    return Case(g.name, g.toml, f"{g.name}.toml")


def _seed_list(text: str) -> list[int]:
    """ "3,7,10-12" → [3, 7, 10, 11, 12]."""
    out: list[int] = []
    for part in filter(None, (p.strip() for p in text.split(","))):
        lo, _, hi = part.partition("-")
        out += range(int(lo), int(hi or lo) + 1)
    return out


def main(argv: Sequence[str] | None = None) -> int:
    """`python -m mmt_plans.sheets.lint_run`: lint every case, print the table of
    rule × mechanisms passing / failing, write each failing mechanism's file
    and findings under --out. Exit 1 when a rule fails anywhere."""
    import argparse
    import collections
    import multiprocessing
    from pathlib import Path

    ap = argparse.ArgumentParser(prog="python -m mmt_plans.sheets.lint_run")
    ap.add_argument("--generated", type=int, default=200)
    ap.add_argument("--variants", type=int, default=5, help="variants of every sample")
    ap.add_argument("--spread", type=float, default=40.0, help="the variants' spread, %%")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--every", type=int, default=1, help="lint every k-th seed task only")
    ap.add_argument("--out", default="out/sheets-lint")
    ap.add_argument(
        "--only", nargs="+", default=None, metavar="FILE", help="lint these mechanism files only"
    )
    ap.add_argument(
        "--seeds", default=None, help="generated mechanisms of these seeds only: 3,7,10-19"
    )
    args = ap.parse_args(argv)
    if args.only or args.seeds:
        todo = [
            Case(Path(p).stem, Path(p).read_text(encoding="utf-8"), str(p)) for p in args.only or []
        ] + [_generated_case(seed) for seed in _seed_list(args.seeds or "")]
    else:
        todo = cases(args.generated, args.variants, args.spread, every=args.every)
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    failing: dict[str, set[str]] = collections.defaultdict(set)
    checked: dict[str, set[str]] = collections.defaultdict(set)
    done = 0
    with multiprocessing.get_context("spawn").Pool(args.jobs) as pool:
        for case, found, rules in pool.imap_unordered(lint_case, todo):
            done += 1
            for r in rules:
                checked[r].add(case.name)
            for f in found:
                failing[f.rule].add(case.name)
            if found:
                folder = out / case.name
                folder.mkdir(parents=True, exist_ok=True)
                (folder / f"{case.name}.toml").write_text(case.toml, encoding="utf-8")
                (folder / "findings.txt").write_text(
                    "\n".join(map(str, found)) + "\n", encoding="utf-8"
                )
            print(f"[{done}/{len(todo)}] {case.name}: {len(found)} findings", flush=True)
    width = max(map(len, [*RULES, "composes"]))
    print(
        f"\n{'rule':<{width}}  passes  fails  (of {len(todo)} mechanisms, en and uk, both sheets)"
    )
    for rule in ["composes", *RULES]:
        n = len(checked[rule])
        bad = len(failing[rule])
        print(f"{rule:<{width}}  {n - bad:6d}  {bad:5d}")
    print(f"\nfailing mechanisms and their findings: {out}/")
    return 1 if failing else 0


if __name__ == "__main__":
    raise SystemExit(main())
