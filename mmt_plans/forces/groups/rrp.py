"""Force calculation of a dyad of kind RRP (see forces/groups/__init__.py)."""

from __future__ import annotations

from ..state import xy_rows
from .base import GroupForces, GroupSolver, Reaction, ReactionComponent, fmt, reaction_name


class RRP(GroupSolver):
    def solve(self) -> GroupForces:
        L1, L2, K1, K2 = self.L1, self.L2, self.K1, self.K2
        b = self.inner.point
        B = self.pin(self.inner)
        A, n1, _, Rt1 = self.tangential(self.outer1, L1, K1, B, b)
        t1 = 1j * n1
        u2, _ = self.state.guide(self.outer2)
        nn2 = 1j * u2
        F1, F2 = self.F(L1), self.F(L2)
        r1, r2 = reaction_name(K1, L1), reaction_name(K2, L2)
        Rn1, N2 = self.solve2(n1, nn2, -(Rt1 * t1 + F1 + F2), f"{r1}^n and {r2}")
        self.steps.append(
            f"group polygon: {r1}^n = {fmt(Rn1)} N, {r2} = {fmt(N2)} N (normal to the guide)"
        )
        R1 = Rn1 * n1 + Rt1 * t1
        R_inner = -(R1 + F1)
        ri = reaction_name(L2, L1)
        self.steps.append(f"link {L1} polygon: {ri} = {fmt(abs(R_inner))} N")
        # ΣM_B(L2) = 0: R_{L1 L2} passes through B, so M_B(R_{K2 L2}) = −M_B(loads of L2)
        R2 = self.prismatic_reaction(
            self.outer2, K2, L2, N2, B, -self.M(L2, B), f"Sum M_{b}(link {L2}) = 0"
        )
        # the reactions' vectors as [x, y] rows of one array (the same numbers)
        R1_, A_, n1_, t1_, Ri_, B_ = xy_rows([R1, A, n1, t1, R_inner, B])
        reactions = (
            Reaction(
                K1,
                L1,
                self.outer1.name,
                "R",
                R1_,
                A_,
                0.0,
                (
                    ReactionComponent(f"{r1}^n", n1_, Rn1),
                    ReactionComponent(f"{r1}^t", t1_, Rt1),
                ),
            ),
            R2,
            Reaction(L2, L1, self.inner.name, "R", Ri_, B_),
        )
        group = self.polygon(
            f"group {self.group.name}",
            [
                (f"{r1}^n", Rn1 * n1, False),
                (f"{r1}^t", Rt1 * t1, True),
                *self.load_sides(L1),
                *self.load_sides(L2),
                (r2, N2 * nn2, False),
            ],
        )
        link = self.polygon(
            f"link {L1}",
            [
                (f"{r1}^n", Rn1 * n1, True),
                (f"{r1}^t", Rt1 * t1, True),
                *self.load_sides(L1),
                (ri, R_inner, False),
            ],
        )
        return self.result(reactions, (group, link))
