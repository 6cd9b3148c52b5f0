"""Sheet writing times for `make bench` (targets: both sheets as SVG under
0.5 s, as PDF under 1 s, for the default sample; both sheets of the eleven-link
hard case under 2 s; six named points 10 mm apart on one link no slower than
the default sample by more than its extra drawing).

Each figure starts from a loaded mechanism: it solves it (everything the
sheets draw), composes, writes SVG, and for PDF converts through Cairo. The
seconds are wall time; on two cores two sheets are composed and written in
two processes (mmt_plans.forked), and the CPU seconds are both processes'.
"""

from __future__ import annotations

import tempfile
from collections.abc import Callable, Sequence
from pathlib import Path

from ..report import table
from ..sheets.compose import available_sheets, write_sheets
from ..solution import solve
from ..spec import load
from .timing import best_wall_and_cpu

DEFAULT = "six_link_press"
# mechanisms nobody tuned the layout for (issue 21), in a source checkout
HARD = Path(__file__).resolve().parents[2] / "tests" / "data" / "hard"
HARD_CASES = ("eleven_links_compound_hinge", "six_points_10mm_apart")


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

                    t, cpu = best_wall_and_cpu(write, max(1, repeat // 2))
                    what = f"sheet {numbers[0]}" if len(numbers) == 1 else "both"
                    rows.append([path.stem, what, fmt, f"{t:.3f}", f"{cpu:.3f}"])
            for name in HARD_CASES:
                hard = HARD / f"{name}.toml"
                if not hard.is_file():
                    continue
                hard_mech = load(hard)

                def write_hard() -> None:
                    write_sheets(solve(hard_mech), out, ("svg",), "en", tuple(sheets))

                t, cpu = best_wall_and_cpu(write_hard, max(1, repeat // 4))
                rows.append([name, "both", "svg", f"{t:.3f}", f"{cpu:.3f}"])
    echo("Writing the A1 sheets (analysis on demand + compose + write; PDF through Cairo):")
    echo(table(["sample", "sheets", "format", "seconds", "CPU s"], rows))
    echo(
        "targets: both sheets as SVG < 0.5 s, as PDF < 1 s; "
        "the eleven-link hard case (tests/data/hard) < 2 s"
    )
    echo("")
