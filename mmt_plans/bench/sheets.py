"""Sheet writing times for `make bench` (targets: both sheets as SVG under
0.5 s, as PDF under 3 s, for the default sample).

Each figure starts from a loaded mechanism: it solves it (everything the
sheets draw), composes, writes SVG, and for PDF converts through Cairo.
"""

from __future__ import annotations

import tempfile
from collections.abc import Callable, Sequence
from pathlib import Path

from ..report import table
from ..sheets.compose import available_sheets, write_sheets
from ..solution import solve
from ..spec import load
from .timing import best_time

DEFAULT = "six_link_press"


def bench_sheets(files: Sequence[Path], repeat: int, echo: Callable[[str], None]) -> None:
    chosen = [p for p in files if p.stem == DEFAULT] or list(files[:1])
    sheets = sorted(available_sheets())
    rows = []
    with tempfile.TemporaryDirectory() as out:
        for path in chosen:
            mech = load(path)
            for fmt in ("svg", "pdf"):
                for numbers in [*((n,) for n in sheets), tuple(sheets)]:

                    def write() -> None:
                        write_sheets(solve(mech), out, (fmt,), "en", numbers)

                    t = best_time(write, max(1, repeat // 2))
                    what = f"sheet {numbers[0]}" if len(numbers) == 1 else "both"
                    rows.append([path.stem, what, fmt, f"{t:.3f}"])
    echo("Writing the A1 sheets (analysis on demand + compose + write; PDF through Cairo):")
    echo(table(["sample", "sheets", "format", "seconds"], rows))
    echo("targets: both sheets as SVG < 0.5 s, as PDF < 3 s")
    echo("")
