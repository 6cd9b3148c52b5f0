"""PRP: two sliders on two guides joined by the inner pin B: B where the two
guide lines meet."""

from __future__ import annotations

import numpy as np

from ..geometry import cross, line_line
from .base import PARALLEL, DyadSolver, Motion


class PRP(DyadSolver):
    def positions(self, m, sign):
        b = self.inner.point
        B1, B2 = self.loc(self.L1, b), self.loc(self.L2, b)
        n = np.ones_like(m[self.K1].o * m[self.K2].o)
        e1, e2 = m[self.K1].e * n, m[self.K2].e * n
        P1, u1 = self.prism_line(self.outer1, m, self.L1, B1, e1)
        P2, u2 = self.prism_line(self.outer2, m, self.L2, B2, e2)
        B = line_line(P1, u1, P2, u2)
        m[self.L1] = Motion(e1, B - e1 * B1)
        m[self.L2] = Motion(e2, B - e2 * B2)

    def legs(self, m):
        b = self.inner.point
        K1, K2 = m[self.K1], m[self.K2]
        B = m[self.L1].at(self.loc(self.L1, b))
        u1 = m[self.L1].e * self.direction_of(self.outer1)
        u2 = m[self.L2].e * self.direction_of(self.outer2)
        return (
            b,
            B,
            self.slide(self.L1, self.K1, B, u1, K1, f"{b}{self.K1}"),
            self.slide(self.L2, self.K2, B, u2, K2, f"{b}{self.K2}"),
        )

    def place(self, m, plan):
        b = self.inner.point
        for L, K in ((self.L1, self.K1), (self.L2, self.K2)):
            m[L].move_with(self.loc(L, b), plan.V_X, plan.a_X, m[K].w, m[K].eps)

    def failure(self, m, i, phi):
        return f"the guides of links {self.L1} and {self.L2} are parallel"

    def margin(self, m):
        u1 = m[self.K1].e * self.direction_of(self.outer1)
        u2 = m[self.K2].e * self.direction_of(self.outer2)
        # parallel guides never meet: the sine of their angle must stay above zero
        return np.abs(cross(u1, u2)) - PARALLEL

    def cure(self, m, bad):
        return f"turn the guides of links {self.L1} and {self.L2} so that they never run parallel"
