"""RRP: a link turning about A whose far pin B slides along a guide: B where
the circle |AB| = l1 meets the guide line."""

from __future__ import annotations

import numpy as np

from ..geometry import circle_line, cross, turn_between
from .base import DyadSolver, Motion, conj, cramer, entry, origin, parallel_somewhere, plain_zero


class RRP(DyadSolver):
    has_branches = True

    def _make_locals(self) -> tuple[complex, complex, complex, complex]:
        """A in K1, A and B in L1, B in L2 (local coordinates), read at every pass."""
        a, b = self.outer1.point, self.inner.point
        return (
            self.loc(self.K1, a),
            self.loc(self.L1, a),
            self.loc(self.L1, b),
            self.loc(self.L2, b),
        )

    def positions(self, m, sign):
        Ak, A1, B1, B2 = self._locals
        A = m[self.K1].at(Ak)
        e2 = m[self.K2].e  # the slider keeps the guide's angle (a number on the frame)
        P0, u = self.prism_line(self.outer2, m, self.L2, B2, e2)
        B = circle_line(A, abs(B1 - A1), P0, u, sign)
        e1 = turn_between(A1, B1, A, B)
        m[self.L1] = Motion(e1, origin(A, e1, A1))
        m[self.L2] = Motion(e2, B - e2 * B2 if B2 else B)

    def carried(self):
        return self._at_origin((self.L1, self.K1, self.outer1.point))

    def legs(self, m):
        a, b = self.outer1.point, self.inner.point
        K2 = m[self.K2]
        B = m[self.L1].at(self.loc(self.L1, b))
        u = m[self.L2].e * self.direction_of(self.outer2)
        return (
            b,
            B,
            self.rotation(self.L1, a, B, self.K1, m),
            self.slide(self.L2, self.K2, B, u, K2, f"{b}{self.K2}"),
        )

    def motion(self, m, least_sin):
        """The plan of B (seed 003 §1.3) in closed form over the angles. With
        the radius r = B - A and the guide u, V_A + iω1·r = V_B∈K2 + V_rel·u
        is, multiplied by conj(u) and by conj(r), ω1 = Im(conj(u)·R) / Re(conj(u)·r)
        and V_rel = -Re(conj(r)·R) / Re(conj(u)·r) with R = V_B∈K2 - V_A; the
        accelerations likewise, with R = a_B∈K2 + the Coriolis component
        - a_A + ω1²·r. The same plan as `plan`, in fewer passes."""
        Ak, A1, B1, B2 = self._locals
        L1, L2, K2 = m[self.L1], m[self.L2], m[self.K2]
        K1 = m[self.K1]
        VA, aA = K1.vel_at(Ak), K1.acc_at(Ak)  # known_motion's
        u = L2.e * self.direction_of(self.outer2)
        r = L1.e * (B1 - A1)
        cu = conj(u)
        det = (cu * r).real
        parallel = parallel_somewhere(det)
        turning = isinstance(K2.w, np.ndarray) or bool(K2.w)
        if turning:  # a guide that turns: B's point on it
            B = L1.at(B1)
            V0, a0 = K2.vel(B), K2.acc(B)
        else:
            V0, a0 = K2.v, K2.a
        R = V0 - VA
        w1 = cramer((cu * R).imag, det, parallel)
        R_a = r * (w1 * w1) - aA if plain_zero(a0) else (a0 - aA) + r * (w1 * w1)
        if turning:  # the Coriolis component 2·ω_K2·V_rel·i·u
            slide = cramer(-(conj(r) * R).real, det, parallel)
            R_a = R_a + u * (2j * K2.w * slide)
        eps1 = cramer((cu * R_a).imag, det, parallel)
        L1.move_with(A1, VA, aA, w1, eps1)
        # B moves with link 1's point B (to V_A + iω1·r, a_A + (iε1 - ω1²)·r)
        L2.move_with(
            B2,
            VA + L1.spin * (B1 - A1),
            aA + L1.spin_acc * (B1 - A1),
            K2.w,
            K2.eps,
        )
        # |d1·d2| = |r|·|u|, the link's length times the guide's
        if least_sin is None:  # where it is regular is not asked for
            return None
        return np.abs(det) > least_sin * (abs(B1 - A1) * abs(u))

    def place(self, m, plan):
        l1, _ = plan.legs
        K2 = m[self.K2]
        self.turn_about(m, l1, self.outer1.point)
        m[self.L2].move_with(self.loc(self.L2, self.inner.point), plan.V_X, plan.a_X, K2.w, K2.eps)

    def failure(self, m, i, phi):
        a, b = self.outer1.point, self.inner.point
        A = entry(m[self.K1].at(self.loc(self.K1, a)), i)
        l1 = abs(self.loc(self.L1, b) - self.loc(self.L1, a))
        P0, u = self.prism_line(self.outer2, m, self.L2, self.loc(self.L2, b), m[self.K2].e)
        P0, u = entry(P0, i), entry(u, i)
        dist = abs(cross(u, A - P0))
        return (
            f"link {self.L1} (l = {l1:.6g} m) cannot reach the guide of link {self.L2}: "
            f"{b}'s line is {dist:.6g} m from {a}"
        )

    def _reach(self, m):
        a, b = self.outer1.point, self.inner.point
        A = m[self.K1].at(self.loc(self.K1, a))
        l1 = abs(self.loc(self.L1, b) - self.loc(self.L1, a))
        P0, u = self.prism_line(self.outer2, m, self.L2, self.loc(self.L2, b), m[self.K2].e)
        return np.abs(cross(u, A - P0)), l1

    def margin(self, m):
        dist, l1 = self._reach(m)
        return l1 - dist

    def cure(self, m, bad):
        dist, l1 = self._reach(m)
        dist = np.broadcast_to(dist, np.shape(bad))[bad]
        if dist.size:
            return (
                f"make l{self.L1} at least the greatest distance of {self.outer1.point} from "
                f"{self.inner.point}'s line, {float(np.nanmax(dist)):.6g} m (now {l1:.6g} m), "
                "or move the guide closer"
            )
        return super().cure(m, bad)

    def branch_meaning(self, sign):
        return (
            f"{self.inner.point} at the {'far' if sign > 0 else 'near'} intersection "
            "along the guide"
        )
