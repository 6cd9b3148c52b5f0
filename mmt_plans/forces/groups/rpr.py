"""Force calculation of a dyad of kind RPR (see forces/groups/__init__.py)."""

from __future__ import annotations

from ...errors import ForceError
from ..state import cross, xy
from .base import SINGULAR_SIN, GroupForces, GroupSolver, Reaction, fmt, reaction_name


class RPR(GroupSolver):
    def solve(self) -> GroupForces:
        L1, L2, K1, K2 = self.L1, self.L2, self.K1, self.K2
        a, c = self.outer1.point, self.outer2.point
        P1, P2 = self.pin(self.outer1), self.pin(self.outer2)
        u, _ = self.state.guide(self.inner)
        nn = 1j * u
        ri = reaction_name(L1, L2)
        # ΣM_a(L1) = 0 puts R_{L1 L2} on the line whose moment about P1 is M1;
        # ΣM_c(L2) = M_c(loads of L2) + M1 + (P1 − P2) × N·nn = 0 gives N
        M1 = self.M(L1, P1)
        M2 = self.M(L2, P2)
        arm = cross(P1 - P2, nn)
        if abs(arm) <= SINGULAR_SIN * abs(P1 - P2) or P1 == P2:
            raise ForceError(
                f"{ri} has no arm about {c}: the slot is perpendicular to {a}{c} (a dead position)",
                "choose another force position",
                phi1_deg=self.state.phi1_deg,
                group=self.group.name,
            )
        N = -(M2 + M1) / arm
        self.steps.append(
            f"Sum M_{c}(link {L2}) = 0: {fmt(M2)} + {fmt(M1)} + {ri} * "
            f"{fmt(arm)} = 0 -> {ri} = {fmt(N)} N (normal to the slot)"
        )
        R_in = self.prismatic_reaction(self.inner, L1, L2, N, P1, M1, f"Sum M_{a}(link {L1}) = 0")
        F1, F2 = self.F(L1), self.F(L2)
        R1 = -(F1 - N * nn)  # link L1: loads + R_{L2 L1} + R_{K1 L1} = 0
        R2 = -(F2 + N * nn)  # link L2: loads + R_{L1 L2} + R_{K2 L2} = 0
        r1, r2 = reaction_name(K1, L1), reaction_name(K2, L2)
        self.steps.append(
            f"link {L2} polygon: {r2} = {fmt(abs(R2))} N; "
            f"link {L1} polygon: {r1} = {fmt(abs(R1))} N"
        )
        reactions = (
            Reaction(K1, L1, self.outer1.name, "R", xy(R1), xy(P1)),
            Reaction(K2, L2, self.outer2.name, "R", xy(R2), xy(P2)),
            R_in,
        )
        link2 = self.polygon(
            f"link {L2}", [*self.load_sides(L2), (ri, N * nn, True), (r2, R2, False)]
        )
        link1 = self.polygon(
            f"link {L1}",
            [*self.load_sides(L1), (reaction_name(L2, L1), -N * nn, True), (r1, R1, False)],
        )
        return self.result(reactions, (link2, link1))
