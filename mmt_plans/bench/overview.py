"""The figures issue 25 asks for, each beside its reference, in one table.

- the sweep against a closed form in numpy (cases A and B of `sweeps`, N = 12,
  360, 36,000): the ratio of the times per call, goal ≤ 2 at 12 angles and
  ≤ 1.2 from 360 up;
- `solve()` of the six-bar (case B and samples/six_link_press.toml): goal
  3 ms (a Mechanism solved again: its kinematic handle is kept; "first"
  includes the structure and the branch search); CPU time, like the sweeps;
- `analyze` start-up over `python -c "import numpy, click"`: goal ≤ 150 ms;
- both sheets as SVG and as PDF, the note, one batch item (both sheets
  SVG+PDF, results.json, note.pdf), each for the default sample from a loaded
  Mechanism: goals 0.5 s, 1 s, 1 s, 1.5 s (wall time; beside each sheets'
  figure the CPU time of its two processes, the sheets composed on two cores
  by mmt_plans.forked, and a fresh `mmt-plans draw` process, what a user
  waits for); beside the note, its own part
  (its pages from sheets composed beforehand, as in a batch item) and a
  fresh `mmt-plans note` process (imports, fonts and Cairo included), both
  against the note's goal;
- with `keys`, the 55 seed-003 task keys with notes by `mmt-plans batch` on
  two workers: goal 30 s.

Ratios are measured/goal, or ours/numpy: under 1 meets the goal.
"""

from __future__ import annotations

import os
import sys
import tempfile
import time
from collections.abc import Callable, Sequence
from pathlib import Path

from ..model import Mechanism
from ..report import table
from .sweeps import mechanisms, sweep_rows
from .timing import best_cpu_times, best_time, best_wall_and_cpu, median_run

DEFAULT = "six_link_press"
GOALS = {
    "solve": 3e-3,
    "startup": 0.150,
    "sheets_svg": 0.5,  # issue 21: both sheets in SVG under 0.5 s, in PDF under 1 s
    "sheets_pdf": 1.0,
    "note": 1.0,
    "item": 1.5,
    "keys": 30.0,
}
KEY_WORKERS = 2


def _figure(x: float) -> str:
    return f"{x:.0f}" if abs(x) >= 100 else f"{x:.3g}"


def _row(what: str, measured: float, unit: str, reference: str, goal: float) -> list[str]:
    scale = {"ms": 1e3, "s": 1.0}[unit]
    return [
        what,
        f"{_figure(measured * scale)} {unit}",
        reference,
        f"{_figure(goal * scale)} {unit}",
        f"{measured / goal:.2f}",
    ]


def solve_rows(sample_dir: Path, repeat: int) -> list[list[str]]:
    from ..solution import solve
    from ..spec import load

    rows = []
    mech_b = mechanisms()["B"][0]
    press = Path(sample_dir) / f"{DEFAULT}.toml"
    cases = [("B", mech_b)] + ([(press.stem, load(press))] if press.is_file() else [])
    for name, mech in cases:
        solve(mech)

        def again(m: Mechanism = mech) -> object:
            return solve(m)

        def first(m: Mechanism = mech) -> object:
            return solve(m.with_changes())

        t, t_first = best_cpu_times((again, first), repeat, 5)
        rows.append(_row(f"solve {name}", t, "ms", "goal", GOALS["solve"]))
        rows.append(_row(f"solve {name}, first", t_first, "ms", "goal", GOALS["solve"]))
    return rows


def startup_row(sample_dir: Path, runs: int = 7) -> list[str]:
    def median(args: list[str]) -> float:
        return median_run(args, runs)

    sample = Path(sample_dir) / f"{DEFAULT}.toml"
    base = median([sys.executable, "-c", "import numpy, click"])
    analyze = median([sys.executable, "-m", "mmt_plans", "analyze", str(sample), "--quiet"])
    return _row(
        "analyze start-up",
        analyze - base,
        "ms",
        f"over numpy+click {base * 1e3:.0f} ms",
        GOALS["startup"],
    )


def output_rows(sample_dir: Path, repeat: int) -> list[list[str]]:
    """Both sheets (SVG, PDF), the note and one batch item, from a loaded Mechanism."""
    from ..batch import process_file
    from ..note import write_note
    from ..sheets.compose import available_sheets, compose, write_sheets
    from ..solution import solve
    from ..spec import load

    path = Path(sample_dir) / f"{DEFAULT}.toml"
    mech = load(path)
    sheets = sorted(available_sheets())
    rows = []
    times = max(1, repeat // 3)
    fresh = 1 if repeat <= 3 else 3  # runs of a command in a fresh process (median)
    with tempfile.TemporaryDirectory() as out:
        for fmt in ("svg", "pdf"):

            def write(f: str = fmt) -> object:
                return write_sheets(solve(mech), out, (f,), "en", sheets)

            t, cpu = best_wall_and_cpu(write, times)
            rows.append(_row(f"both sheets {fmt.upper()}", t, "s", "goal", GOALS[f"sheets_{fmt}"]))
            # (on two cores the sheets are composed in two processes: the CPU they take)
            rows.append(_row("  its CPU, both processes", cpu, "s", "goal", GOALS[f"sheets_{fmt}"]))
            # what a user waits for: `mmt-plans draw` in a fresh process (imports,
            # the package's bytecode as `make` leaves it, the file read and solved)
            t_draw = median_run(
                [sys.executable, "-m", "mmt_plans", "draw", str(path), "-o", out]
                + ["--format", fmt],
                fresh,
            )
            rows.append(
                _row(
                    f"  a fresh `mmt-plans draw --format {fmt}`",
                    t_draw,
                    "s",
                    "goal",
                    GOALS[f"sheets_{fmt}"],
                )
            )
        t = best_time(lambda: write_note(solve(mech), Path(out) / "note.pdf"), times)
        rows.append(_row("note (PDF)", t, "s", "goal", GOALS["note"]))
        # the note's own part: its pages from sheets composed beforehand (a batch item's note)
        solution = solve(mech)
        composed = compose(solution, "en", available_sheets())
        t_own = best_time(
            lambda: write_note(solution, Path(out) / "note.pdf", composed=composed), times
        )
        rows.append(
            _row("  of it: the note from composed sheets", t_own, "s", "goal", GOALS["note"])
        )
        # what a user waits for: `mmt-plans note` in a fresh process (imports, fonts, Cairo)
        t_cli = median_run(
            [sys.executable, "-m", "mmt_plans", "note", str(path), "-o", str(Path(out) / "n.pdf")],
            fresh,
        )
        rows.append(_row("note, a fresh `mmt-plans note`", t_cli, "s", "goal", GOALS["note"]))
        t = best_time(lambda: process_file(str(path), Path(out) / "item", "en", True), times)
        rows.append(_row("batch item", t, "s", "goal", GOALS["item"]))
    return rows


def keys_rows(sample_dir: Path, echo: Callable[[str], None]) -> list[list[str]]:
    """The 55 seed-003 task keys with notes, `mmt-plans batch` on two workers,
    and where the workers' time went."""
    from ..batch import find_files, run_batch

    tasks = Path(sample_dir) / "tasks" / "seed003"
    files = find_files([tasks])
    with tempfile.TemporaryDirectory() as out:
        t0 = time.perf_counter()
        results = run_batch(files, out, jobs=KEY_WORKERS)
        total = time.perf_counter() - t0
    busy = sum(r.seconds for r in results) or 1.0
    cpu = sum(r.cpu_seconds for r in results)  # what survives a loaded machine
    stages: dict[str, float] = {}
    for r in results:
        for name, s in r.stages.items():
            stages[name] = stages.get(name, 0.0) + s
    where = ", ".join(f"{k} {v / busy * 100:.0f} %" for k, v in sorted(stages.items()) if v > 0.005)
    echo(f"keys: {len(files)} files, {sum(r.ok for r in results)} done; worker time: {where}")
    return [
        _row(
            f"{len(files)} seed-003 keys, {KEY_WORKERS} workers",
            total,
            "s",
            f"{busy / len(results):.2f} s per item, {cpu / len(results):.2f} s cpu per key",
            GOALS["keys"],
        )
    ]


def bench_overview(
    sample_dir: Path, repeat: int, echo: Callable[[str], None], keys: bool = False
) -> None:
    echo("Issue 25's figures, each beside its reference (ratio < 1 meets the goal):")
    sweep = sweep_rows(repeat)
    echo(
        table(
            ["case", "N", "mmt_plans us/angle", "numpy us/angle", "ratio", "goal ratio"],
            sweep,
        )
    )
    echo(
        "A: slider-crank r 200, l 800 mm, guide 70 mm below O; B: six-bar (issue 25); "
        "both sides give every point's position, V, a as [x, y] and omega, eps of every link"
    )
    rows = solve_rows(sample_dir, repeat)
    rows.append(startup_row(sample_dir))
    rows += output_rows(sample_dir, repeat)
    if keys:
        rows += keys_rows(sample_dir, echo)
    echo(table(["figure", "measured", "reference", "goal", "ratio"], rows))
    if not keys:
        echo("(the 55 seed-task keys: `mmt-plans bench --keys`, or `make bench KEYS=1`)")
    echo(f"({os.cpu_count()} cores; load average {os.getloadavg()[0]:.1f})")
    echo("")


def overview_only(sample_dir: Path, quick: bool, keys: bool, echo: Callable[[str], None]) -> None:
    bench_overview(sample_dir, 3 if quick else 7, echo, keys)


__all__: Sequence[str] = ["bench_overview", "overview_only", "GOALS"]
