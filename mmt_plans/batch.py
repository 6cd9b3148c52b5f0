"""Answer keys for many mechanism files at once (`mmt-plans batch`).

For each file, into OUT/<file stem>/: the sheets (SVG and PDF, every sheet
`available_sheets()` offers), results.json (what `analyze --json` writes) and
note.pdf (the A4 calculation note). Files run in parallel processes; a file
that fails is reported by its message and the others are still done.

Hygiene:
- files whose stems clash (task01_v1 of two seeds) keep their relative path
  under OUT (OUT/seed002/task01_v1/); no output ever lands outside OUT (no
  `..`, no absolute part, a folder that resolves outside OUT is refused);
- every output is written atomically (files.py; synced to the disk by a
  thread of the item while its next stage is computed: results.json and
  the sheets while the note is drawn), and a finished file records
  a manifest, MANIFEST_NAME, written last, with its input's SHA-256 and its
  outputs' sizes; a later run skips a file whose manifest matches and whose
  outputs are all there ("kept"), unless `force`.
"""

from __future__ import annotations

import contextlib
import csv
import hashlib
import io
import json
import math
import os
import signal
import stat
import threading
import time
from collections.abc import Callable, Iterable, Iterator, Sequence
from concurrent.futures import Future, ProcessPoolExecutor, as_completed
from dataclasses import dataclass, field
from pathlib import Path, PurePosixPath
from typing import TYPE_CHECKING, cast

from .errors import MmtError, shown
from .forked import FEWER_COLLECTIONS, die_with
from .report import table

if TYPE_CHECKING:  # pragma: no cover
    from .i18n import Language
    from .model import Mechanism
    from .solution import Solution

__all__ = [
    "BatchError",
    "FileResult",
    "find_files",
    "plan_outputs",
    "process_file",
    "run_batch",
    "summary_rows",
    "summary_table",
    "write_summary_csv",
    "SUMMARY_HEADERS",
    "MANIFEST_NAME",
    "read_manifest",
]

MANIFEST_NAME = ".mmt-batch.json"
MANIFEST_SCHEMA = "mmt_plans/batch-item@1"
SUMMARY_NAME = "summary.csv"
QUIZ_XML, QUIZ_GIFT = "quiz.xml", "quiz.gift"  # batch --moodle
# names in OUT that no item's folder takes (an input quiz.xml.toml goes to OUT/quiz.xml-2)
RESERVED_NAMES = frozenset({SUMMARY_NAME, QUIZ_XML, QUIZ_GIFT})
SHEET_FORMATS = ("svg", "pdf")  # the sheets a batch writes unless --format says otherwise

SUMMARY_HEADERS = [
    "file",
    "status",
    "W",
    "class",
    "F_bal plans N",
    "F_bal lever N",
    "discrepancy %",
    "5 % check",
    "time s",
]


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
    cpu_seconds: float = 0.0  # the item's process CPU time (its writing thread's too)
    written: tuple[str, ...] = ()
    stages: dict[str, float] = field(default_factory=dict)  # seconds per stage
    kept: bool = False  # done by an earlier run (its manifest matched): not redone


def find_files(inputs: Iterable[str | os.PathLike[str]]) -> list[Path]:
    """The mechanism files named: files as given, directories searched
    recursively for *.toml; each file once, in the order found."""
    out: list[Path] = []
    seen: set[Path] = set()
    for item in inputs:
        p = Path(item)
        try:  # not Path.is_dir(): it raises on a name too long (ENAMETOOLONG)
            mode = os.stat(p).st_mode
        except FileNotFoundError:
            raise BatchError(f"{shown(p)}: no such file or directory") from None
        except OSError as err:
            raise BatchError(
                f"{shown(p)}: cannot be read ({err.strerror})\n  fix: check the path"
            ) from None
        if stat.S_ISDIR(mode):
            found = _tomls_under(p)
            if not found:
                raise BatchError(
                    f"{shown(p)}: no *.toml files in this directory (searched recursively)"
                )
        else:
            found = [p]
        for f in found:
            key = f.resolve()
            if key not in seen:
                seen.add(key)
                out.append(f)
    if not out:
        raise BatchError("no mechanism files given")
    return out


def _tomls_under(folder: Path) -> list[Path]:
    """*.toml files under `folder`, sorted; folders reached through a symbolic
    link are not entered (a link to a parent would never end)."""
    found = []
    for root, dirs, names in os.walk(folder):
        dirs.sort()
        found += [Path(root) / n for n in names if n.endswith(".toml")]
    return sorted(found)


def _safe_part(name: str) -> str:
    """One folder name of an output path: never empty, `.` or `..`, no separator
    or control character."""
    name = shown(name, 100).replace("/", "_").replace("\\", "_").replace("\0", "_")
    return name if name.strip(".") else "_" + name


def plan_outputs(files: Sequence[Path], out: Path) -> list[Path]:
    """OUT/<stem> for each file. Files whose stems clash (task01_v1 of two
    seeds, compared without case) keep their path relative to the folder the
    clashing files share: OUT/seed002/task01_v1, OUT/seed003/task01_v1. Every
    part is a plain folder name (no `..`, no absolute part), and the folders
    are distinct."""
    out = Path(out)
    stems = [_safe_part(f.stem) for f in files]
    counts: dict[str, int] = {}
    for n in stems:
        counts[n.lower()] = counts.get(n.lower(), 0) + 1
    resolved = [Path(os.path.abspath(f)) for f in files]
    clashing = [r for r, n in zip(resolved, stems) if counts[n.lower()] > 1]
    base = Path(os.path.commonpath([str(r.parent) for r in clashing])) if clashing else None
    rels: list[PurePosixPath] = []
    for f, r, n in zip(files, resolved, stems):
        if counts[n.lower()] == 1 or base is None:
            rels.append(PurePosixPath(n))
            continue
        parts = [_safe_part(x) for x in r.relative_to(base).parts[:-1]]
        rels.append(PurePosixPath(*parts, n))
    # still equal (a.toml and a.TOML in one folder): number them
    taken: set[str] = set()
    final: list[Path] = []
    for rel in rels:
        key, k = str(rel).lower(), 1
        while key in taken or key in RESERVED_NAMES:
            k += 1
            key = f"{str(rel).lower()}-{k}"
        taken.add(key)
        final.append(out / (rel if k == 1 else rel.with_name(f"{rel.name}-{k}")))
    return final


def _inside(folder: Path, out: Path) -> bool:
    """Whether `folder`, symbolic links resolved, lies inside `out`."""
    try:
        folder.resolve().relative_to(out.resolve())
    except ValueError:
        return False
    return True


def _sha256(path: str | os.PathLike[str]) -> str | None:
    from .files import read_input

    try:
        return hashlib.sha256(read_input(path).encode("utf-8")).hexdigest()
    except MmtError:
        return None


def read_manifest(out_dir: str | os.PathLike[str]) -> dict | None:
    """The manifest of a finished item, or None (missing, unreadable, another schema)."""
    try:
        data = json.loads((Path(out_dir) / MANIFEST_NAME).read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return None
    return data if isinstance(data, dict) and data.get("schema") == MANIFEST_SCHEMA else None


Fields = tuple[tuple[str, str], ...]  # --field KEY=VALUE pairs, sorted by key


def _settings(
    lang: str,
    formats: Sequence[str] = SHEET_FORMATS,
    extras: Sequence[str] = (),
    fields: Fields = (),
) -> dict:
    from . import __version__

    return {
        "lang": lang,
        "version": __version__,
        "formats": list(formats),
        "extras": list(extras),
        "fields": dict(fields),
    }


def _kept(
    path: str,
    out: Path,
    lang: str,
    formats: Sequence[str] = SHEET_FORMATS,
    extras: Sequence[str] = (),
    fields: Fields = (),
) -> FileResult | None:
    """The result of an earlier run when its manifest matches the input and
    its outputs are all there, as they were written; else None."""
    manifest = read_manifest(out)
    if manifest is None or manifest.get("settings") != _settings(lang, formats, extras, fields):
        return None
    digest = _sha256(path)
    if digest is None or manifest.get("input_sha256") != digest:
        return None
    outputs = manifest.get("outputs")
    if not isinstance(outputs, dict) or not outputs:
        return None
    for name, size in outputs.items():
        target = out / name
        if (
            not isinstance(name, str)
            or "/" in name
            or name.startswith(".")
            or not target.is_file()
            or target.is_symlink()
            or target.stat().st_size != size
        ):
            return None
    summary = manifest.get("summary", {})
    return FileResult(
        str(path),
        str(out),
        True,
        None,
        W=summary.get("W"),
        mechanism_class=summary.get("mechanism_class"),
        balancing_force_plans=summary.get("balancing_force_plans"),
        balancing_force_lever=summary.get("balancing_force_lever"),
        discrepancy_percent=summary.get("discrepancy_percent"),
        diagrams_passed=summary.get("diagrams_passed"),
        written=tuple(str(out / n) for n in outputs),
        kept=True,
    )


def process_file(
    path: str | os.PathLike[str],
    out_dir: str | os.PathLike[str],
    lang: str = "en",
    force: bool = True,
    formats: Sequence[str] = ("svg", "pdf"),
    extras: Sequence[str] = (),
    fields: Fields | dict[str, str] = (),
) -> FileResult:
    """Analyse one file and write its sheets, results.json and note.pdf, then
    its manifest; with `force` False, a file whose manifest matches is kept.
    `fields` (--field KEY=VALUE) are written over the file's [sheet] table.

    Never raises: an `MmtError` becomes the result's message; anything else
    (a bug) too, named by its type, so one file cannot stop the batch."""
    from .numerics import quiet_numerics

    with quiet_numerics():
        pairs = tuple(sorted(dict(fields).items()))
        return _process_file(
            str(path), Path(out_dir), lang, force, tuple(formats), tuple(extras), pairs
        )


def _process_file(
    path: str,
    out: Path,
    lang: str,
    force: bool,
    formats: tuple[str, ...] = ("svg", "pdf"),
    extras: tuple[str, ...] = (),
    fields: Fields = (),
) -> FileResult:
    from .files import ensure_dir, finite_json, write_text_atomic
    from .solution import solve
    from .spec import load

    if not force:
        kept = _kept(path, out, lang, formats, extras, fields)
        if kept is not None:
            return kept
    t0, c0 = time.perf_counter(), time.process_time()
    stages: dict[str, float] = {}
    written: list[str] = []
    info: dict = {}
    problems: list[str] = []

    def stage(name: str, fn: Callable[[], object]) -> object:
        t = time.perf_counter()
        try:
            return fn()
        except Exception as err:
            problems.append(_problem(name, err))
        finally:
            stages[name] = stages.get(name, 0.0) + time.perf_counter() - t
        return None

    def failed() -> FileResult:
        """The item stopped at its first problem."""
        return FileResult(
            str(path),
            str(out),
            False,
            problems[0],
            seconds=time.perf_counter() - t0,
            cpu_seconds=time.process_time() - c0,
            stages=stages,
        )

    digest = _sha256(path)  # before the analysis: what the manifest vouches for
    analysis = stage("analysis", lambda: solve(_with_fields(load(path), fields)))
    if analysis is None:
        return failed()

    def prepare() -> None:
        ensure_dir(out)
        try:  # a redone item is not finished until its new manifest is written
            (out / MANIFEST_NAME).unlink()
        except FileNotFoundError:
            pass

    stage("output folder", prepare)
    if problems:
        return failed()

    solution = cast("Solution", analysis)
    with _Writes(out) as writes:
        _outputs(solution, path, out, lang, formats, extras, stage, writes, info)
        t = time.perf_counter()
        for name, target in writes.finish():
            if isinstance(target, Exception):
                problems.append(_problem(name, target))
            else:
                written.append(str(target))
        stages["writing"] = time.perf_counter() - t  # waited for: the rest was hidden

    data = info.get("json", {})
    st = data.get("structure", {})
    forces = data.get("forces", {})
    diagrams = data.get("diagrams", {})
    if "problem" in forces:
        problems.append(f"forces: {forces['problem']}")
    summary = dict(
        W=st.get("W"),
        mechanism_class=st.get("mechanism_class"),
        balancing_force_plans=forces.get("balancing_force_plans"),
        balancing_force_lever=forces.get("balancing_force_lever"),
        discrepancy_percent=forces.get("discrepancy_percent"),
        diagrams_passed=diagrams.get("passed"),
    )
    if not problems and digest is not None:

        def manifest() -> None:
            data = {
                "schema": MANIFEST_SCHEMA,
                "input": path,
                "input_sha256": digest,
                "settings": _settings(lang, formats, extras, fields),
                "outputs": {Path(w).name: Path(w).stat().st_size for w in written},
                "summary": summary,
            }
            write_text_atomic(out / MANIFEST_NAME, finite_json(data, path))

        stage("manifest", manifest)
    return FileResult(
        str(path),
        str(out),
        not problems,
        "; ".join(problems) or None,
        **summary,
        seconds=time.perf_counter() - t0,
        cpu_seconds=time.process_time() - c0,
        written=tuple(written),
        stages=stages,
    )


def _problem(stage: str, err: Exception) -> str:
    """What a stage's failure says in the summary: an `MmtError` its message,
    anything else (a bug) named by its type."""
    if isinstance(err, MmtError):
        return f"{stage}: {err}"
    return f"{stage}: internal error ({type(err).__name__}: {shown(err, 300)}), please report it"


class _Writes:
    """An item's outputs written atomically (files.write_bytes_atomic: the
    data and the rename synced to the disk) by one thread of their own, in
    the order added, while the item's next stage is computed: the syncs'
    waiting, about a twentieth of an item, is mostly hidden. `finish()` waits
    for all of them: the manifest is written after, as before."""

    def __init__(self, out: Path) -> None:
        from concurrent.futures import ThreadPoolExecutor

        self._out = out
        self._pool = ThreadPoolExecutor(1, thread_name_prefix="mmt-batch-write")
        self._pending: list[tuple[str, Future[Path]]] = []

    def add(self, stage: str, name: str, data: bytes) -> None:
        from .files import write_bytes_atomic

        self._pending.append((stage, self._pool.submit(write_bytes_atomic, self._out / name, data)))

    def finish(self) -> list[tuple[str, Path | Exception]]:
        """(stage, the path written or why it was not) of each output, in order."""
        done: list[tuple[str, Path | Exception]] = []
        for stage, future in self._pending:
            try:
                done.append((stage, future.result()))
            except Exception as err:
                done.append((stage, err))
        self._pending = []
        return done

    def __enter__(self) -> _Writes:
        return self

    def __exit__(self, *exc: object) -> None:
        self._pool.shutdown(wait=True)  # never a thread left writing after the item


def _outputs(
    solution: Solution,
    path: str,
    out: Path,
    lang: str,
    formats: tuple[str, ...],
    extras: tuple[str, ...],
    stage: Callable[[str, Callable[[], object]], object],
    writes: _Writes,
    info: dict,
) -> None:
    """An item's outputs made, each stage through `stage`, and handed to
    `writes` in the order they are listed in the manifest: results.json, the
    sheets, the note, the scheme (batch --moodle); the JSON's data kept in
    `info["json"]` for the summary."""
    from .files import finite_json
    from .note import note_pdf
    from .results_json import results as results_json
    from .sheets.compose import ComposedSheets, available_sheets, compose, rendered_composed

    def results() -> None:
        data = results_json(solution)
        writes.add("results", "results.json", finite_json(data, path).encode("utf-8"))
        info["json"] = data

    stage("results", results)
    # the sheets composed once: written as sheets, read by the note (its scales, its figures)
    composed = cast(
        "ComposedSheets | None",
        stage(
            "sheets", lambda: compose(solution, cast("Language", lang), available_sheets(solution))
        ),
    )

    def sheets() -> None:
        assert composed is not None
        for name, data in rendered_composed(
            composed, solution, formats, sorted(available_sheets(solution))
        ):
            writes.add("sheets", name, data)

    def note() -> None:
        assert composed is not None
        writes.add("note", "note.pdf", note_pdf(solution, cast("Language", lang), None, composed))

    def scheme() -> None:
        # the variant's kinematic scheme, for the quiz (batch --moodle)
        from .lms.keys import SCHEME_NAME
        from .render.output import render
        from .render.recording import RecordingBackend
        from .sheets.schematic import sketch_schematic

        # with its names and the frame's dimensions: the quiz gives the rest
        recording = RecordingBackend(140.0, 100.0)
        sketch_schematic(
            solution,
            recording.look,
            cast("Language", lang),
            width_mm=140.0,
            height_mm=100.0,
            dimensions=True,
        ).replay(recording)
        writes.add("scheme", SCHEME_NAME, render(recording, "png"))

    if composed is not None:
        stage("sheets", sheets)
        stage("note", note)
    if "scheme" in extras:
        stage("scheme", scheme)


def _with_fields(mech: Mechanism, fields: Fields) -> Mechanism:
    """The mechanism with --field's pairs written over its [sheet] table."""
    if not fields:
        return mech
    return mech.with_changes(sheet={**dict(mech.sheet or {}), **dict(fields)})


def _run(
    args: tuple[str, str, str, bool, tuple[str, ...], tuple[str, ...], Fields],
) -> FileResult:
    return process_file(*args)


_PARENT_WATCH_SECONDS = 1.0


def _die_with_parent(parent: int, *, pdeathsig: bool = True) -> None:
    """This worker ends when the process `parent` does, even killed by
    SIGKILL (which lets it clean up nothing): on Linux the kernel sends us
    SIGKILL then (prctl PR_SET_PDEATHSIG, forked.die_with); everywhere, a
    thread that sees our parent change ends us within a second. A batch
    killed with -9 leaves no worker waiting for ever."""
    import sys
    import threading

    if pdeathsig and sys.platform.startswith("linux"):
        die_with(parent)
    if os.getppid() != parent:  # the parent died before prctl took effect
        os._exit(1)

    def watch() -> None:
        while True:
            time.sleep(_PARENT_WATCH_SECONDS)
            if os.getppid() != parent:
                os._exit(1)

    threading.Thread(target=watch, name="mmt-parent-watch", daemon=True).start()


def _file_size(path: str) -> int:
    """The size of `path` in bytes (0 where it cannot be read): how long its item takes, roughly."""
    try:
        return os.path.getsize(path)
    except OSError:
        return 0


# a worker's cyclic garbage collector: the young generation collected every
# 5,000 allocations of containers instead of 700 (an item makes many
# short-lived ones: recorded calls, label boxes, points), the older ones as usual
_WORKER_GC_THRESHOLD = FEWER_COLLECTIONS


def _worker_start(parent: int) -> None:
    # Ctrl-C is the parent's to handle: workers print no traceback of their own.
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    _die_with_parent(parent)
    _worker_collector()


def _worker_collector() -> None:
    """What every item imports, imported now and frozen (gc.freeze: the
    collector never walks those objects again), and the young generation
    collected less often: collection was about 6 % of an item's time, after
    this about 2 %. The outputs do not depend on when garbage is collected."""
    import gc

    from . import note, results_json, solution, spec  # noqa: F401
    from .render import cairo_pdf, svg  # noqa: F401
    from .sheets import compose  # noqa: F401

    gc.collect()
    gc.freeze()
    gc.set_threshold(*_WORKER_GC_THRESHOLD)


_IN_PROCESS = threading.Lock()  # guards the count below and the collector's settings
_in_process_runs: list[tuple[tuple[int, int, int], int]] = []  # (thresholds, frozen) kept


@contextlib.contextmanager
def _collector_of_items() -> Iterator[None]:
    """The items done in this process (--jobs 1, or one file) with a worker's
    collector (_worker_collector); the process's own settings back when the
    last of the runs in this process ends (runs in two threads at once share them)."""
    import gc

    with _IN_PROCESS:
        if not _in_process_runs:
            kept = cast("tuple[int, int, int]", gc.get_threshold())
            _in_process_runs.append((kept, gc.get_freeze_count()))
            _worker_collector()
        else:
            _in_process_runs.append(_in_process_runs[0])
    try:
        yield
    finally:
        with _IN_PROCESS:
            kept, frozen = _in_process_runs.pop()
            if not _in_process_runs:
                if not frozen:  # a caller that froze its objects keeps them frozen
                    gc.unfreeze()
                gc.set_threshold(*kept)


def run_batch(
    files: Sequence[Path],
    out: str | os.PathLike[str],
    *,
    jobs: int | None = None,
    lang: str = "en",
    progress: Callable[[FileResult], None] | None = None,
    force: bool = True,
    formats: Sequence[str] = ("svg", "pdf"),
    extras: Sequence[str] = (),
    fields: dict[str, str] | None = None,
) -> list[FileResult]:
    """Process `files` with `jobs` processes (default: every core); results in
    the order of `files`. `progress(result)` is called as each file finishes.
    With `force` False a file finished by an earlier run (its manifest matches,
    its outputs are there) is kept rather than redone."""
    from .files import ensure_dir, sweep_stale_temporaries

    out = ensure_dir(out)
    targets = plan_outputs(list(files), out)
    # the temporaries a killed earlier run left, also in the folders of files
    # kept from it (a kept file writes nothing there to sweep them)
    for t in targets:
        if _inside(t, out):
            sweep_stale_temporaries(t)
    results: list[FileResult | None] = [None] * len(targets)
    pairs: Fields = tuple(sorted((fields or {}).items()))
    tasks: list[tuple[str, str, str, bool, tuple[str, ...], tuple[str, ...], Fields]] = []
    index: list[int] = []
    for i, (f, t) in enumerate(zip(files, targets)):
        if not _inside(t, out):  # OUT/x is a symbolic link to elsewhere
            results[i] = FileResult(
                str(f),
                str(t),
                False,
                f"{shown(t)} leads outside {shown(out)} (a symbolic link): "
                "nothing written there; remove the link",
            )
            if progress:
                progress(results[i])  # type: ignore[arg-type]
            continue
        tasks.append((str(f), str(t), lang, force, tuple(formats), tuple(extras), pairs))
        index.append(i)
    jobs = max(1, jobs or os.cpu_count() or 1)
    if jobs == 1 or len(tasks) <= 1:
        with _collector_of_items():
            for i, task in zip(index, tasks):
                results[i] = _run(task)
                if progress:
                    progress(results[i])  # type: ignore[arg-type]
    else:
        pool = ProcessPoolExecutor(
            max_workers=min(jobs, len(tasks)),
            initializer=_worker_start,
            initargs=(os.getpid(),),
        )
        try:
            # the largest files (the most links: the longest items) first, so
            # that no long item is left to run alone at the end
            jobs_in = sorted(zip(index, tasks), key=lambda it: -_file_size(it[1][0]))
            futures = {pool.submit(_run, task): i for i, task in jobs_in}
            for fut in as_completed(futures):
                i = futures[fut]
                try:
                    results[i] = fut.result()
                except Exception as err:  # the worker process itself died
                    results[i] = FileResult(
                        str(files[i]),
                        str(targets[i]),
                        False,
                        f"worker failed: {type(err).__name__}: {shown(err, 300)}",
                    )
                if progress:
                    progress(results[i])  # type: ignore[arg-type]
        except BaseException:
            # Ctrl-C: drop what has not started, stop the workers (their
            # outputs are atomic: nothing is left half-written)
            pool.shutdown(wait=False, cancel_futures=True)
            for proc in list(getattr(pool, "_processes", {}).values()):
                proc.terminate()
            raise
        pool.shutdown(wait=True)
    return [r for r in results if r is not None]


# --- the summary -------------------------------------------------------------------------


def _num(x: float | None, digits: int = 6) -> str:
    if x is None or (isinstance(x, float) and not math.isfinite(x)):
        return "-"
    return f"{float(x) + 0.0:.{digits}g}"


def summary_rows(
    results: Sequence[FileResult], out: str | os.PathLike[str] | None = None
) -> list[list[str]]:
    """One row per file: its output folder (relative to `out` when given), status
    ("done", "kept" from an earlier run, "FAILED") and numbers."""
    rows = []
    for r in results:
        passed = (
            "-" if r.diagrams_passed is None else ("passed" if r.diagrams_passed else "NOT passed")
        )
        name = Path(r.out_dir).name
        if out is not None:
            try:
                name = Path(r.out_dir).relative_to(out).as_posix()
            except ValueError:
                pass
        rows.append(
            [
                shown(name, 80),
                "kept" if r.kept else "done" if r.ok else "FAILED",
                "-" if r.W is None else str(r.W),
                "-" if r.mechanism_class is None else str(r.mechanism_class),
                _num(r.balancing_force_plans),
                _num(r.balancing_force_lever),
                _num(r.discrepancy_percent, 3),
                passed,
                f"{r.seconds:.2f}",
            ]
        )
    return rows


def summary_table(results: Sequence[FileResult], out: str | os.PathLike[str] | None = None) -> str:
    return table(SUMMARY_HEADERS, summary_rows(results, out))


def write_summary_csv(results: Sequence[FileResult], target: str | os.PathLike[str]) -> Path:
    """The summary with every file's path and, for a failure, its message (atomically)."""
    from .files import write_text_atomic

    buffer = io.StringIO(newline="")
    w = csv.writer(buffer)
    w.writerow(["path", *SUMMARY_HEADERS[1:], "message"])
    for r, row in zip(results, summary_rows(results)):
        w.writerow([r.path, *row[1:], r.message or ""])
    return write_text_atomic(target, buffer.getvalue())


def failures(results: Sequence[FileResult]) -> Iterator[FileResult]:
    return (r for r in results if not r.ok)
