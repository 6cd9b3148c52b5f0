"""Force analysis times for `make bench` (target: under 2 ms per position, six-link press).

Per position: the loads, every group's force plan, the driving link and
Zhukovsky's lever from the analysis' kinematics (the analysis itself is built
once, as the sheet and the JSON use it). `all positions` runs it at every
position of the study, as the tests and an answer key for every position do.
"""

from __future__ import annotations

from pathlib import Path
from typing import Callable, Sequence

from .. import load
from ..bench import best_time
from ..report import table
from . import force_analysis
from .errors import ForceError


def bench_forces(files: Sequence[Path], repeat: int, echo: Callable[[str], None]) -> None:
    rows = []
    for path in files:
        analysis = load(path).analyze()
        if analysis.mech.structure.groups and not all(g.is_dyad for g in analysis.mech.structure.groups):
            continue
        indices = [p.index for p in analysis.positions if analysis.problem(analysis.entry(p.index)) is None]
        try:
            force_analysis(analysis)
        except ForceError as err:
            rows.append([path.stem, "-", "-", f"not solved: {err}"])
            continue
        one = best_time(lambda: force_analysis(analysis), repeat, number=5)

        def every() -> None:
            for i in indices:
                try:
                    force_analysis(analysis, i)
                except ForceError:
                    pass  # a dead position of a group: reported by analyze, not timed apart

        t_all = best_time(every, repeat)
        rows.append([path.stem, f"{one * 1e3:.3f}", str(len(indices)),
                     f"{t_all / max(1, len(indices)) * 1e3:.3f}"])
    echo("Force analysis per position (loads, groups, driving link, Zhukovsky's lever):")
    echo(table(["sample", "force position ms", "positions", "mean per position ms"], rows))
    echo("")
