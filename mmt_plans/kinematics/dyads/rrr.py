"""RRR: two links turning about their outer pins, joined by the inner pin B:
B from the intersection of two circles (|AB| = l1, |CB| = l2)."""

from __future__ import annotations

import numpy as np

from ..geometry import circle_circle, turn_between
from .base import DyadSolver, Motion, conj, cramer, entry, origin, parallel_somewhere


class RRR(DyadSolver):
    has_branches = True

    def _make_locals(self) -> tuple[complex, complex, complex, complex, complex, complex]:
        """A in K1 and C in K2, A and B in L1, C and B in L2 (local coordinates),
        read at every pass."""
        a, b, c = self.outer1.point, self.inner.point, self.outer2.point
        return (
            self.loc(self.K1, a),
            self.loc(self.K2, c),
            self.loc(self.L1, a),
            self.loc(self.L1, b),
            self.loc(self.L2, c),
            self.loc(self.L2, b),
        )

    def positions(self, m, sign):
        Ak, Ck, A1, B1, C2, B2 = self._locals
        A = m[self.K1].at(Ak)
        C = m[self.K2].at(Ck)
        B = circle_circle(A, abs(B1 - A1), C, abs(B2 - C2), sign)
        e1 = turn_between(A1, B1, A, B)
        e2 = turn_between(C2, B2, C, B)
        m[self.L1] = Motion(e1, origin(A, e1, A1))
        m[self.L2] = Motion(e2, origin(C, e2, C2))

    def carried(self):
        return self._at_origin(
            (self.L1, self.K1, self.outer1.point), (self.L2, self.K2, self.outer2.point)
        )

    def legs(self, m):
        a, b, c = self.outer1.point, self.inner.point, self.outer2.point
        B = m[self.L1].at(self.loc(self.L1, b))
        return (
            b,
            B,
            self.rotation(self.L1, a, B, self.K1, m),
            self.rotation(self.L2, c, B, self.K2, m),
        )

    def motion(self, m, least_sin):
        """The plan of B (seed 003 §1.3) in closed form over the angles. With
        the radii r1 = B - A, r2 = B - C, V_A + iω1·r1 = V_C + iω2·r2 is,
        multiplied by conj(r2) and by conj(r1) and read in its real part,
        ω1 = Re(conj(r2)·R) / Im(conj(r1)·r2) and ω2 = Re(conj(r1)·R) / Im(conj(r1)·r2)
        with R = V_C - V_A; the accelerations likewise, with
        R = a_C - a_A + ω1²·r1 - ω2²·r2 (the normal components carried over).
        The same plan as `plan`, in fewer passes."""
        Ak, Ck, A1, B1, C2, B2 = self._locals
        L1, L2 = m[self.L1], m[self.L2]
        K1, K2 = m[self.K1], m[self.K2]
        VA, aA = K1.vel_at(Ak), K1.acc_at(Ak)  # known_motion's
        VC, aC = K2.vel_at(Ck), K2.acc_at(Ck)
        r1, r2 = L1.e * (B1 - A1), L2.e * (B2 - C2)
        c1, c2 = conj(r1), conj(r2)
        det = (c1 * r2).imag
        parallel = parallel_somewhere(det)
        R = VC - VA
        w1 = cramer((c2 * R).real, det, parallel)
        w2 = cramer((c1 * R).real, det, parallel)
        R = (aC - aA) + (r1 * (w1 * w1) - r2 * (w2 * w2))
        eps1 = cramer((c2 * R).real, det, parallel)
        eps2 = cramer((c1 * R).real, det, parallel)
        L1.move_with(A1, VA, aA, w1, eps1)
        L2.move_with(C2, VC, aC, w2, eps2)
        # |d1·d2| = |r1|·|r2|, the links' lengths
        if least_sin is None:  # where it is regular is not asked for
            return None
        return np.abs(det) > least_sin * (abs(B1 - A1) * abs(B2 - C2))

    def place(self, m, plan):
        l1, l2 = plan.legs
        self.turn_about(m, l1, self.outer1.point)
        self.turn_about(m, l2, self.outer2.point)

    def failure(self, m, i, phi):
        a, b, c = self.outer1.point, self.inner.point, self.outer2.point
        A = entry(m[self.K1].at(self.loc(self.K1, a)), i)
        C = entry(m[self.K2].at(self.loc(self.K2, c)), i)
        l1 = abs(self.loc(self.L1, b) - self.loc(self.L1, a))
        l2 = abs(self.loc(self.L2, b) - self.loc(self.L2, c))
        d = abs(C - A)
        if d > l1 + l2:
            return (
                f"links {self.L1} and {self.L2} cannot reach: |{a}{c}| = {d:.6g} m > "
                f"l{self.L1} + l{self.L2} = {l1 + l2:.6g} m"
            )
        return (
            f"links {self.L1} and {self.L2} cannot close: |{a}{c}| = {d:.6g} m < "
            f"|l{self.L1} - l{self.L2}| = {abs(l1 - l2):.6g} m"
        )

    def _reach(self, m):
        a, b, c = self.outer1.point, self.inner.point, self.outer2.point
        A = m[self.K1].at(self.loc(self.K1, a))
        C = m[self.K2].at(self.loc(self.K2, c))
        l1 = abs(self.loc(self.L1, b) - self.loc(self.L1, a))
        l2 = abs(self.loc(self.L2, b) - self.loc(self.L2, c))
        return np.abs(C - A), l1, l2

    def margin(self, m):
        d, l1, l2 = self._reach(m)
        return np.minimum(l1 + l2 - d, d - abs(l1 - l2))

    def cure(self, m, bad):
        d, l1, l2 = self._reach(m)
        d = np.broadcast_to(d, np.shape(bad))[bad]
        a, c = self.outer1.point, self.outer2.point
        L1, L2 = self.L1, self.L2
        cures = []
        if d.size and float(np.nanmax(d)) > l1 + l2:
            cures.append(
                f"make l{L1} + l{L2} at least max |{a}{c}| = {float(np.nanmax(d)):.6g} m "
                f"(now {l1 + l2:.6g} m)"
            )
        if d.size and float(np.nanmin(d)) < abs(l1 - l2):
            cures.append(
                f"make |l{L1} - l{L2}| at most min |{a}{c}| = {float(np.nanmin(d)):.6g} m "
                f"(now {abs(l1 - l2):.6g} m)"
            )
        return " and ".join(cures) or super().cure(m, bad)

    def branch_meaning(self, sign):
        a, b, c = self.outer1.point, self.inner.point, self.outer2.point
        return f"{b} to the {'left' if sign > 0 else 'right'} of {a}->{c}"
