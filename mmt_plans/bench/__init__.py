"""`mmt-plans bench` / `make bench`: per-item times, measured in-process.

Each figure is the best of several repeats (the least disturbed by the rest
of the machine), reported per position or per crank angle.
"""

from __future__ import annotations

import subprocess
import sys
from collections.abc import Callable
from pathlib import Path

from ..report import table
from ..spec import load
from .timing import best_time, full_analysis

_SWEEP = """
import sys, numpy as np
from mmt_plans.bench.timing import best_time, sweep_everything
from mmt_plans.kinematics.branches import build_chain
from mmt_plans.spec import load
chain = build_chain(load(sys.argv[1]))  # built once, as a script sweeping many times would
phi = np.linspace(0.0, 360.0, int(sys.argv[2]), endpoint=False)
print(best_time(lambda: sweep_everything(chain, phi), int(sys.argv[3])))
"""


def sweep_time(path: Path, count: int, repeat: int) -> float:
    """Best time of one sweep of `count` angles of the file at `path`, measured
    in a fresh Python process."""
    done = subprocess.run(
        [sys.executable, "-c", _SWEEP, str(path), str(count), str(repeat)],
        capture_output=True,
        text=True,
        check=True,
    )
    return float(done.stdout.strip().splitlines()[-1])


def _check_samples(sample_dir: Path, keys: bool) -> None:
    """The files the bench times are there, or a message naming the folder and
    the fix (not a subprocess's failure reported as a bug)."""
    from ..errors import SettingError
    from .overview import DEFAULT

    needed = [sample_dir / f"{DEFAULT}.toml"] + ([sample_dir / "tasks" / "seed003"] if keys else [])
    for path in needed:
        if not path.exists():
            raise SettingError(
                f"--samples {sample_dir}: {path} does not exist\n"
                "  fix: run from the repository's root (where samples/ is), or pass "
                "--samples PATH/TO/samples"
            )


def run_benchmarks(
    sample_dir: Path, quick: bool = False, echo=print, keys: bool = False, summary: bool = False
) -> None:
    """The overview of issue 25's figures (`overview`), then, unless `summary`,
    every detailed section; `keys` adds the 55 seed-task keys on two workers."""
    from .overview import bench_overview

    _check_samples(Path(sample_dir), keys)
    repeat = 3 if quick else 7
    bench_overview(Path(sample_dir), repeat, echo, keys)
    if summary:
        return
    files = sorted(Path(sample_dir).glob("*.toml"))
    rows = []
    for path in files:
        mech = load(path)
        n = mech.study.positions + len(mech.study.angles)
        t = best_time(lambda: full_analysis(mech, diagrams=False), repeat)
        t_d = best_time(lambda: full_analysis(mech), repeat)
        rows.append([path.stem, str(n), f"{t * 1e3:.2f}", f"{t / n * 1e6:.0f}", f"{t_d * 1e3:.2f}"])
    echo("Analysis in-process: kinematics = structure, branches, extremes, positions, plans, JSON;")
    echo("with diagrams = also graphical differentiation and the 5 % check (with its trials)")
    echo(
        table(["sample", "positions", "kinematics ms", "per position us", "with diagrams ms"], rows)
    )
    echo("")

    rows = []
    for path in files:
        for count in (360, 36_000):
            t = sweep_time(path, count, repeat)
            rows.append([path.stem, str(count), f"{t * 1e3:.2f}", f"{t / count * 1e6:.3f}"])
    echo("Vectorised sweep: positions, velocities, accelerations of every point, omega and eps")
    echo("(each sample in a fresh process, so that no other sample's memory shapes its figure)")
    echo(table(["sample", "angles", "total ms", "per angle us"], rows))
    echo("")

    for section in _extra_sections():
        section(files, repeat, echo)


def _extra_sections() -> list[Callable]:
    """Benchmarks of the later stages: forces, diagrams, sheets, the batch."""
    from .diagrams import bench_diagrams
    from .forces import bench_forces
    from .note import bench_note
    from .sheets import bench_sheets
    from .startup import bench_startup

    # the seed-003 batch is the overview's keys row (`--keys`), on two workers
    return [bench_startup, bench_forces, bench_diagrams, bench_sheets, bench_note]
