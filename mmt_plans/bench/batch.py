"""The batch over the seed-003 tasks for `make bench`."""

from __future__ import annotations

import os
import time
from collections.abc import Callable, Sequence
from pathlib import Path

from ..batch import find_files, run_batch
from ..report import table
from ..sheets.compose import available_sheets


def bench_batch(files: Sequence[Path], repeat: int, echo: Callable[[str], None] = print) -> None:
    """`mmt-plans bench` section: the batch over samples/tasks/seed003 (sheets,
    JSON and notes included) on every core, total and per file, and where the
    time of one file goes. Run once: it takes about a minute."""
    import tempfile

    base = Path(files[0]).parent if files else Path("samples")
    tasks_dir = base / "tasks" / "seed003"
    if not tasks_dir.is_dir():
        echo(f"Batch: {tasks_dir} not found, skipped")
        return
    batch_files = find_files([tasks_dir])
    jobs = os.cpu_count() or 1
    with tempfile.TemporaryDirectory() as tmp:
        t0 = time.perf_counter()
        results = run_batch(batch_files, tmp, jobs=jobs)
        total = time.perf_counter() - t0
    done = sum(r.ok for r in results)
    worker = [r.seconds for r in results]
    echo(
        f"Batch over {tasks_dir} ({len(batch_files)} files, {jobs} processes; sheets "
        f"{'+'.join(map(str, _sheets()))} SVG+PDF, results.json, note.pdf): {done} done"
    )
    stage_names = ["analysis", "results", "sheets", "note"]
    sums = {s: sum(r.stages.get(s, 0.0) for r in results) for s in stage_names}
    busy = sum(worker)
    rows = [
        ["total (wall)", f"{total:.2f}", f"{total / len(results) * 1e3:.0f}", ""],
        [
            "worker time",
            f"{busy:.2f}",
            f"{busy / len(results) * 1e3:.0f}",
            f"{busy / total:.2f} cores busy",
        ],
        [
            "slowest file",
            f"{max(worker):.2f}",
            "",
            Path(max(results, key=lambda r: r.seconds).path).stem,
        ],
    ]
    for s in stage_names:
        rows.append(
            [
                f"  {s}",
                f"{sums[s]:.2f}",
                f"{sums[s] / len(results) * 1e3:.0f}",
                f"{sums[s] / busy * 100:.0f} % of worker time" if busy else "",
            ]
        )
    echo(table(["batch", "s", "per file ms", "note"], rows))
    echo("")


def _sheets() -> list[int]:
    return sorted(available_sheets())
