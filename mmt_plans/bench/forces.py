"""Force analysis times for `make bench` (target: under 2 ms per position, six-link press).

Per position: the loads, every group's force plan, the driving link and
Zhukovsky's lever from the solution's kinematics (solved once, as the sheet
and the JSON use it). `all positions` runs it at every position of the study,
as the tests and an answer key for every position do.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from pathlib import Path

from ..errors import MmtError
from ..forces import force_analysis_at
from ..report import table
from ..solution import solve
from ..spec import load
from .timing import best_time


def bench_forces(files: Sequence[Path], repeat: int, echo: Callable[[str], None]) -> None:
    rows = []
    for path in files:
        solution = solve(load(path))
        if not all(g.is_dyad for g in solution.structure.groups):
            continue
        indices = [
            p.index
            for p in solution.positions
            if p.index is not None and solution.problem(solution.entry(p.index)) is None
        ]
        if solution.forces is None:
            rows.append([path.stem, "-", "-", f"not solved: {solution.forces_problem}"])
            continue
        state = solution.state(solution.force_position)
        one = best_time(lambda: force_analysis_at(state, mu_l=solution.mu_l), repeat, number=5)
        states = [solution.state(i) for i in indices]

        def every() -> None:
            for st in states:
                try:
                    force_analysis_at(st, mu_l=solution.mu_l)
                except MmtError:
                    pass  # a dead position of a group: reported by analyze, not timed apart

        t_all = best_time(every, repeat)
        rows.append(
            [
                path.stem,
                f"{one * 1e3:.3f}",
                str(len(indices)),
                f"{t_all / max(1, len(indices)) * 1e3:.3f}",
            ]
        )
    echo("Force analysis per position (loads, groups, driving link, Zhukovsky's lever):")
    echo(table(["sample", "force position ms", "positions", "mean per position ms"], rows))
    echo("")
