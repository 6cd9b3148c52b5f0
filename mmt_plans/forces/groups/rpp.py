"""Force calculation of a dyad of kind RPP (see forces/groups/__init__.py)."""

from __future__ import annotations

from ..state import xy
from .base import GroupForces, GroupSolver, Reaction, fmt, reaction_name


class RPP(GroupSolver):
    def solve(self) -> GroupForces:
        L1, L2, K1, K2 = self.L1, self.L2, self.K1, self.K2
        a = self.outer1.point
        A = self.pin(self.outer1)
        u_in, _ = self.state.guide(self.inner)
        u2, _ = self.state.guide(self.outer2)
        nn_in, nn2 = 1j * u_in, 1j * u2
        F1, F2 = self.F(L1), self.F(L2)
        ri, r2, r1 = reaction_name(L1, L2), reaction_name(K2, L2), reaction_name(K1, L1)
        N_in, N2 = self.solve2(nn_in, nn2, -F2, f"{ri} and {r2}")
        self.steps.append(
            f"link {L2} polygon: {ri} = {fmt(N_in)} N, {r2} = {fmt(N2)} N (normal to their guides)"
        )
        R1 = -(F1 - N_in * nn_in)  # link L1: loads + R_{L2 L1} + R_{K1 L1} = 0
        self.steps.append(f"link {L1} polygon: {r1} = {fmt(abs(R1))} N")
        M1 = self.M(L1, A)
        R_in = self.prismatic_reaction(self.inner, L1, L2, N_in, A, M1, f"Sum M_{a}(link {L1}) = 0")
        R2 = self.prismatic_reaction(
            self.outer2, K2, L2, N2, A, -self.M(L2, A) - M1, f"Sum M_{a}(link {L2}) = 0"
        )
        reactions = (Reaction(K1, L1, self.outer1.name, "R", xy(R1), xy(A)), R2, R_in)
        link2 = self.polygon(
            f"link {L2}", [(ri, N_in * nn_in, False), *self.load_sides(L2), (r2, N2 * nn2, False)]
        )
        link1 = self.polygon(
            f"link {L1}",
            [*self.load_sides(L1), (reaction_name(L2, L1), -N_in * nn_in, True), (r1, R1, False)],
        )
        return self.result(reactions, (link2, link1))
