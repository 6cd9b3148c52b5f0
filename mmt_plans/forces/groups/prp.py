"""Force calculation of a dyad of kind PRP (see forces/groups/__init__.py)."""

from __future__ import annotations

from ..state import xy
from .base import GroupForces, GroupSolver, Reaction, fmt, reaction_name


class PRP(GroupSolver):
    def solve(self) -> GroupForces:
        L1, L2, K1, K2 = self.L1, self.L2, self.K1, self.K2
        b = self.inner.point
        B = self.pin(self.inner)
        u1, _ = self.state.guide(self.outer1)
        u2, _ = self.state.guide(self.outer2)
        nn1, nn2 = 1j * u1, 1j * u2
        F1, F2 = self.F(L1), self.F(L2)
        r1, r2 = reaction_name(K1, L1), reaction_name(K2, L2)
        N1, N2 = self.solve2(nn1, nn2, -(F1 + F2), f"{r1} and {r2}")
        self.steps.append(
            f"group polygon: {r1} = {fmt(N1)} N, {r2} = {fmt(N2)} N (normal to their guides)"
        )
        R_inner = -(N1 * nn1 + F1)
        ri = reaction_name(L2, L1)
        self.steps.append(f"link {L1} polygon: {ri} = {fmt(abs(R_inner))} N")
        R1 = self.prismatic_reaction(
            self.outer1, K1, L1, N1, B, -self.M(L1, B), f"Sum M_{b}(link {L1}) = 0"
        )
        R2 = self.prismatic_reaction(
            self.outer2, K2, L2, N2, B, -self.M(L2, B), f"Sum M_{b}(link {L2}) = 0"
        )
        reactions = (R1, R2, Reaction(L2, L1, self.inner.name, "R", xy(R_inner), xy(B)))
        group = self.polygon(
            f"group {self.group.name}",
            [
                (r1, N1 * nn1, False),
                *self.load_sides(L1),
                *self.load_sides(L2),
                (r2, N2 * nn2, False),
            ],
        )
        link = self.polygon(
            f"link {L1}", [(r1, N1 * nn1, True), *self.load_sides(L1), (ri, R_inner, False)]
        )
        return self.result(reactions, (group, link))
