"""RPP: a link pinned at A whose partner slides on it and on an outer guide:
the partner where the two guide lines meet."""

from __future__ import annotations

import numpy as np

from ..geometry import cross, line_line
from .base import PARALLEL, DyadSolver, Motion


class RPP(DyadSolver):
    def positions(self, m, sign):
        a = self.outer1.point
        A = m[self.K1].at(self.loc(self.K1, a))
        e = m[self.K2].e * np.ones_like(A)  # both keep the outer guide's angle
        m[self.L1] = Motion(e, A - e * self.loc(self.L1, a))
        P1, u1 = self.prism_line(self.inner, m, self.L2, 0j, e)
        P2, u2 = self.prism_line(self.outer2, m, self.L2, 0j, e)
        m[self.L2] = Motion(e, line_line(P1, u1, P2, u2))

    def legs(self, m):
        a = self.outer1.point
        K1, K2 = m[self.K1], m[self.K2]
        A = K1.at(self.loc(self.K1, a))
        L1 = m[self.L1]
        p = self.loc(self.K1, a)
        L1.move_with(self.loc(self.L1, a), K1.vel_at(p), K1.acc_at(p), K2.w, K2.eps)
        u1 = m[self.inner.guide].e * self.direction_of(self.inner)
        u2 = m[self.L2].e * self.direction_of(self.outer2)
        return (
            f"{a}{self.L2}",
            A,
            self.slide(self.L2, self.L1, A, u1, L1, a.lower()),
            self.slide(self.L2, self.K2, A, u2, K2, f"{a}{self.K2}"),
        )

    def place(self, m, plan):
        K2, L2 = m[self.K2], m[self.L2]
        L2.move_with(L2.local(plan.X), plan.V_X, plan.a_X, K2.w, K2.eps)

    def failure(self, m, i, phi):
        return f"the guides of link {self.L2} are parallel"

    def margin(self, m):
        e = m[self.K2].e
        u_in, u_out = e * self.direction_of(self.inner), e * self.direction_of(self.outer2)
        # parallel guides never meet: the sine of their angle must stay above zero
        return np.abs(cross(u_in, u_out)) - PARALLEL

    def cure(self, m, bad):
        return f"turn the guides of link {self.L2} so that they are not parallel"
