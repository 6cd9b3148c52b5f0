"""RPR: a block pinned at A sliding in a slot of a link turning about C (the
slotted link): the slot's angle from an arcsine."""

from __future__ import annotations

import numpy as np

from ...model import Prismatic
from ..geometry import cross, quiet
from .base import DyadSolver, Leg, Motion, entry


class RPR(DyadSolver):
    has_branches = True

    def _parts(self, m):
        pair: Prismatic = self.inner
        s, g = pair.slider, pair.guide
        a, c = self.outer1.point, self.outer2.point
        pivot = {self.L1: (a, self.K1), self.L2: (c, self.K2)}
        ps_name, Ks = pivot[s]
        pg_name, Kg = pivot[g]
        Ps = m[Ks].at(self.loc(Ks, ps_name))
        Pg = m[Kg].at(self.loc(Kg, pg_name))
        ps, pg = self.loc(s, ps_name), self.loc(g, pg_name)
        d = self.direction_of(pair)
        offset = cross((self.loc(s, pair.slider_point) - ps) - (self.through_of(pair) - pg), d)
        return s, g, Ps, Pg, ps, pg, d, offset

    def positions(self, m, sign):
        s, g, Ps, Pg, ps, pg, d, offset = self._parts(m)
        w = Ps - Pg
        # cross(w, e·d) = -offset: |w|·sin(arg(e·d) - arg(w)) = -offset
        with quiet():
            psi = np.arcsin(-offset / np.abs(w))
        if sign < 0:
            psi = np.pi - psi
        e = (w / np.abs(w)) * np.conj(d) * np.exp(1j * psi)
        m[s] = Motion(e, Ps - e * ps)
        m[g] = Motion(e, Pg - e * pg)

    def legs(self, m):
        a, c = self.outer1.point, self.outer2.point
        K1, p = m[self.K1], self.loc(self.K1, a)
        A = K1.at(p)
        u = m[self.inner.guide].e * self.direction_of(self.inner)
        # X is the point of L2 that coincides with A (the textbook's A3)
        slide = Leg(
            "slide", a.lower(), f"V{a}{self.L2}{a}{self.L1}", u, K1.vel_at(p), K1.acc_at(p), self.L1
        )
        return f"{a}{self.L2}", A, slide, self.rotation(self.L2, c, A, self.K2, m)

    def carried(self):
        return self._at_origin(
            (self.L1, self.K1, self.outer1.point), (self.L2, self.K2, self.outer2.point)
        )

    def after_velocities(self, m, leg1, leg2):
        # the slide's Coriolis term needs ω of L1, which is ω of L2, found by
        # the velocity plan: give L1 its ω before the acceleration plan
        m[self.L1].w = leg2.x

    def place(self, m, plan):
        slide, rot = plan.legs
        self.turn_about(m, rot, self.outer2.point)
        m[self.L1].move_with(self.loc(self.L1, self.outer1.point), slide.V0, slide.a0, rot.x, rot.y)

    def failure(self, m, i, phi):
        s, g, Ps, Pg, ps, pg, d, offset = self._parts(m)
        w = abs(entry(Ps - Pg, i))
        return (
            f"the guide of link {g} passes {abs(offset):.6g} m from link {s}'s point, "
            f"but the pivots are only {w:.6g} m apart"
        )

    def margin(self, m):
        s, g, Ps, Pg, ps, pg, d, offset = self._parts(m)
        return np.abs(Ps - Pg) - abs(offset)

    def cure(self, m, bad):
        s, g, Ps, Pg, ps, pg, d, offset = self._parts(m)
        w = np.broadcast_to(np.abs(Ps - Pg), np.shape(bad))[bad]
        if w.size:
            return (
                f"make the offset of link {g}'s guide at most the least distance of the "
                f"pivots, {float(np.nanmin(w)):.6g} m (now {abs(offset):.6g} m)"
            )
        return super().cure(m, bad)

    def branch_meaning(self, sign):
        return f"guide of link {self.inner.guide} turned {'+' if sign > 0 else '-'}arcsin"
