"""The force analysis's own error: bad input that the spec reader cannot see.

It is raised for a position that does not exist, a force whose direction is
undefined at the position asked for (acts = "always" on a point at rest), and
a force plan whose two unknown directions are parallel.
"""

from __future__ import annotations

from ..errors import MmtError


class ForceError(MmtError, ValueError):
    """The force analysis cannot be done as asked; the message says why and what to change."""

    def __init__(self, problem: str, fix: str = "", *, phi1_deg: float | None = None,
                 group: str | None = None) -> None:
        self.problem, self.fix, self.phi1_deg, self.group = problem, fix, phi1_deg, group
        where = []
        if phi1_deg is not None:
            where.append(f"at phi1 = {phi1_deg:.6g} deg")
        if group is not None:
            where.append(f"group {group}")
        text = (", ".join(where) + ": " if where else "") + problem
        if fix:
            text += f"\n  fix: {fix}"
        super().__init__(text)
