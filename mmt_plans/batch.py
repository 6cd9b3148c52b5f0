"""Answer keys for many mechanism files at once (`mmt-plans batch`).

For each file, into OUT/<file stem>/: the sheets (SVG and PDF, every sheet
`available_sheets()` offers), results.json (what `analyze --json` writes) and
note.pdf (the A4 calculation note). Files run in parallel processes; a file
that fails is reported by its message and the others are still done.
"""

from __future__ import annotations

import csv
import json
import math
import os
import time
from concurrent.futures import ProcessPoolExecutor, as_completed
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable, Iterable, Iterator, Sequence

from .errors import MmtError
from .report import table

__all__ = ["BatchError", "FileResult", "find_files", "plan_outputs", "process_file",
           "run_batch", "summary_rows", "summary_table", "write_summary_csv", "SUMMARY_HEADERS"]

SUMMARY_HEADERS = ["file", "status", "W", "class", "F_bal plans N", "F_bal lever N",
                   "discrepancy %", "5 % check", "time s"]


class BatchError(MmtError, ValueError):
    """A batch input that names no mechanism file."""


@dataclass(frozen=True)
class FileResult:
    """What became of one file: its numbers for the summary, or why it failed."""

    path: str
    out_dir: str
    ok: bool
    message: str | None = None
    W: int | None = None
    mechanism_class: int | None = None
    balancing_force_plans: float | None = None
    balancing_force_lever: float | None = None
    discrepancy_percent: float | None = None
    diagrams_passed: bool | None = None
    seconds: float = 0.0
    written: tuple[str, ...] = ()
    stages: dict[str, float] = field(default_factory=dict)  # seconds per stage


def find_files(inputs: Iterable[str | os.PathLike[str]]) -> list[Path]:
    """The mechanism files named: files as given, directories searched
    recursively for *.toml; each file once, in the order found."""
    out: list[Path] = []
    seen: set[Path] = set()
    for item in inputs:
        p = Path(item)
        if p.is_dir():
            found = sorted(p.rglob("*.toml"))
            if not found:
                raise BatchError(f"{p}: no *.toml files in this directory (searched recursively)")
        elif p.exists():
            found = [p]
        else:
            raise BatchError(f"{p}: no such file or directory")
        for f in found:
            key = f.resolve()
            if key not in seen:
                seen.add(key)
                out.append(f)
    if not out:
        raise BatchError("no mechanism files given")
    return out


def plan_outputs(files: Sequence[Path], out: Path) -> list[Path]:
    """OUT/<stem> for each file; stems that repeat (task01_v1 of two seeds)
    take their parent folders' names in front until they differ."""
    names = [f.stem for f in files]
    depth = 0
    while len(set(names)) < len(names) and depth < 8:
        depth += 1
        counts: dict[str, int] = {}
        for n in names:
            counts[n] = counts.get(n, 0) + 1
        names = [("-".join(f.resolve().parent.parts[-depth:] + (f.stem,)) if counts[n] > 1 else n)
                 for f, n in zip(files, names)]
    return [out / n for n in names]


def process_file(path: str | os.PathLike[str], out_dir: str | os.PathLike[str],
                 lang: str = "en") -> FileResult:
    """Analyse one file and write its sheets, results.json and note.pdf.

    Never raises: an `MmtError` becomes the result's message; anything else
    (a bug) too, named by its type, so one file cannot stop the batch."""
    from .note import write_note
    from .results_json import results as results_json
    from .sheets.compose import available_sheets, write_sheets
    from .solution import solve
    from .spec import load

    t0 = time.perf_counter()
    stages: dict[str, float] = {}
    written: list[str] = []
    out = Path(out_dir)
    info: dict = {}
    problems: list[str] = []

    def stage(name: str, fn: Callable[[], object]) -> object:
        t = time.perf_counter()
        try:
            return fn()
        except MmtError as err:
            problems.append(f"{name}: {err}")
        except Exception as err:  # a bug: reported, the batch goes on
            problems.append(f"{name}: internal error {type(err).__name__}: {err}")
        finally:
            stages[name] = stages.get(name, 0.0) + time.perf_counter() - t
        return None

    analysis = stage("analysis", lambda: solve(load(path)))
    if analysis is None:
        return FileResult(str(path), str(out), False, problems[0],
                          seconds=time.perf_counter() - t0, stages=stages)
    out.mkdir(parents=True, exist_ok=True)

    def results() -> None:
        data = results_json(analysis)
        target = out / "results.json"
        target.write_text(json.dumps(data, indent=1, allow_nan=False) + "\n", encoding="utf-8")
        written.append(str(target))
        info["json"] = data

    def sheets() -> None:
        paths = write_sheets(analysis, out, formats=("svg", "pdf"), lang=lang,  # type: ignore[arg-type]
                             sheets=sorted(available_sheets()))
        written.extend(str(p) for p in paths)

    def note() -> None:
        written.append(str(write_note(analysis, out / "note.pdf", lang=lang)))  # type: ignore[arg-type]

    stage("results", results)
    stage("sheets", sheets)
    stage("note", note)
    data = info.get("json", {})
    st = data.get("structure", {})
    forces = data.get("forces", {})
    diagrams = data.get("diagrams", {})
    if "problem" in forces:
        problems.append(f"forces: {forces['problem']}")
    return FileResult(
        str(path), str(out), not problems, "; ".join(problems) or None,
        W=st.get("W"), mechanism_class=st.get("mechanism_class"),
        balancing_force_plans=forces.get("balancing_force_plans"),
        balancing_force_lever=forces.get("balancing_force_lever"),
        discrepancy_percent=forces.get("discrepancy_percent"),
        diagrams_passed=diagrams.get("passed"),
        seconds=time.perf_counter() - t0, written=tuple(written), stages=stages)


def _run(args: tuple[str, str, str]) -> FileResult:
    return process_file(*args)


def run_batch(files: Sequence[Path], out: str | os.PathLike[str], *, jobs: int | None = None,
              lang: str = "en", progress: Callable[[FileResult], None] | None = None
              ) -> list[FileResult]:
    """Process `files` with `jobs` processes (default: every core); results in
    the order of `files`. `progress(result)` is called as each file finishes."""
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    targets = plan_outputs(list(files), out)
    tasks = [(str(f), str(t), lang) for f, t in zip(files, targets)]
    jobs = max(1, jobs or os.cpu_count() or 1)
    results: list[FileResult | None] = [None] * len(tasks)
    if jobs == 1 or len(tasks) == 1:
        for i, task in enumerate(tasks):
            results[i] = _run(task)
            if progress:
                progress(results[i])  # type: ignore[arg-type]
    else:
        with ProcessPoolExecutor(max_workers=min(jobs, len(tasks))) as pool:
            futures = {pool.submit(_run, task): i for i, task in enumerate(tasks)}
            for fut in as_completed(futures):
                i = futures[fut]
                try:
                    results[i] = fut.result()
                except Exception as err:  # the worker process itself died
                    results[i] = FileResult(tasks[i][0], tasks[i][1], False,
                                            f"worker failed: {type(err).__name__}: {err}")
                if progress:
                    progress(results[i])  # type: ignore[arg-type]
    return [r for r in results if r is not None]


# --- the summary -------------------------------------------------------------------------

def _num(x: float | None, digits: int = 6) -> str:
    if x is None or (isinstance(x, float) and not math.isfinite(x)):
        return "-"
    return f"{float(x) + 0.0:.{digits}g}"


def summary_rows(results: Sequence[FileResult]) -> list[list[str]]:
    rows = []
    for r in results:
        passed = "-" if r.diagrams_passed is None else ("passed" if r.diagrams_passed else "NOT passed")
        rows.append([Path(r.out_dir).name,
                     "done" if r.ok else "FAILED",
                     "-" if r.W is None else str(r.W),
                     "-" if r.mechanism_class is None else str(r.mechanism_class),
                     _num(r.balancing_force_plans), _num(r.balancing_force_lever),
                     _num(r.discrepancy_percent, 3), passed, f"{r.seconds:.2f}"])
    return rows


def summary_table(results: Sequence[FileResult]) -> str:
    return table(SUMMARY_HEADERS, summary_rows(results))


def write_summary_csv(results: Sequence[FileResult], target: str | os.PathLike[str]) -> Path:
    target = Path(target)
    with target.open("w", newline="", encoding="utf-8") as fh:
        w = csv.writer(fh)
        w.writerow(["path", *SUMMARY_HEADERS[1:], "message"])
        for r, row in zip(results, summary_rows(results)):
            w.writerow([r.path, *row[1:], r.message or ""])
    return target


def failures(results: Sequence[FileResult]) -> Iterator[FileResult]:
    return (r for r in results if not r.ok)
