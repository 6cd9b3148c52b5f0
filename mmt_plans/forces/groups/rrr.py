"""Force calculation of a dyad of kind RRR (see forces/groups/__init__.py)."""

from __future__ import annotations

from ..state import xy_rows
from .base import GroupForces, GroupSolver, Reaction, ReactionComponent, fmt, reaction_name


class RRR(GroupSolver):
    def solve(self) -> GroupForces:
        L1, L2, K1, K2 = self.L1, self.L2, self.K1, self.K2
        b = self.inner.point
        B = self.pin(self.inner)
        A, n1, _, Rt1 = self.tangential(self.outer1, L1, K1, B, b)
        C, n2, _, Rt2 = self.tangential(self.outer2, L2, K2, B, b)
        t1, t2 = 1j * n1, 1j * n2
        F1, F2 = self.F(L1), self.F(L2)
        r1, r2 = reaction_name(K1, L1), reaction_name(K2, L2)
        Rn1, Rn2 = self.solve2(n1, n2, -(Rt1 * t1 + F1 + F2 + Rt2 * t2), f"{r1}^n and {r2}^n")
        self.steps.append(f"group polygon: {r1}^n = {fmt(Rn1)} N, {r2}^n = {fmt(Rn2)} N")
        R1 = Rn1 * n1 + Rt1 * t1
        R2 = Rn2 * n2 + Rt2 * t2
        R_inner = -(R1 + F1)  # link L1's polygon
        ri = reaction_name(L2, L1)
        self.steps.append(f"link {L1} polygon: {ri} = {fmt(abs(R_inner))} N")
        # the reactions' vectors as [x, y] rows of one array (the same numbers)
        R1_, A_, n1_, t1_, R2_, C_, n2_, t2_, Ri_, B_ = xy_rows(
            [R1, A, n1, t1, R2, C, n2, t2, R_inner, B]
        )
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
            Reaction(
                K2,
                L2,
                self.outer2.name,
                "R",
                R2_,
                C_,
                0.0,
                (
                    ReactionComponent(f"{r2}^n", n2_, Rn2),
                    ReactionComponent(f"{r2}^t", t2_, Rt2),
                ),
            ),
            Reaction(L2, L1, self.inner.name, "R", Ri_, B_),
        )
        group = self.polygon(
            f"group {self.group.name}",
            [
                (f"{r1}^n", Rn1 * n1, False),
                (f"{r1}^t", Rt1 * t1, True),
                *self.load_sides(L1),
                *self.load_sides(L2),
                (f"{r2}^t", Rt2 * t2, True),
                (f"{r2}^n", Rn2 * n2, False),
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
