"""What every dyad kind shares: the working state of a link over the angles
(`Motion`), a leg of a plan's vector equation (`Leg`), a group's plan
(`GroupPlan`), Cramer's rule, and the protocol of a kind (`DyadSolver`):
positions in closed form, the plans as the textbook draws them.

Each dyad is oriented outer–inner–outer: link L1 joins the known link K1 by the
first outer pair, L2 joins K2 by the last one. For the plans every kind writes
two vector equations for one point X (seed 003 §1.3, §1.5):

    V_X = V_1 + d1·x1 = V_2 + d2·x2
    a_X = a_1 + n_1 + d1·y1 = a_2 + n_2 + d2·y2

where a leg is either a rotation of a link about a known point P
(d = i·(X - P), x = ω, n = -ω²·(X - P) the normal component, y = ε) or a slide
relative to a known link K along the guide u (d = u, x = the relative
velocity, n = 2·ω_K·x·i·u the Coriolis component, y = the relative
acceleration). The tangential directions of the acceleration plan are those of
the velocity plan, so one 2×2 determinant serves both.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import cached_property
from typing import Any, Literal

import numpy as np

from ...model import Mechanism, Prismatic, Revolute
from ...structure import AssurGroup
from ..geometry import cross, quiet

LegKind = Literal["rotation", "slide"]


# the sine of the angle between two guides below which they count as parallel
PARALLEL = 1e-6


# ω and ε of a link only placed (a group's positions, before its plan)
_REST = 0.0


class Motion:
    """Working state of one link over N crank angles: pose e^{iθ}, origin o,
    ω, velocity and acceleration of the origin, ε.

    A point with local coordinates p sits at o + e·p and moves with
    V = v + iω·e·p, a = a + (iε - ω²)·e·p (the textbook's V_P = V_O + ω × OP,
    a_P = a_O + ε × OP - ω²·OP). The factors iω·e and (iε - ω²)·e are kept,
    so each further point costs one product and one sum. The frame's entries
    are plain numbers, not arrays.
    """

    __slots__ = ("e", "o", "w", "v", "eps", "a", "spin", "spin_acc")

    def __init__(self, e, o, w=_REST, v=0j, eps=_REST, a=0j) -> None:
        self.e, self.o = e, o
        if w is _REST and eps is _REST:
            # placed, not yet turning (a group's positions): iω·e = (iε - ω²)·e = 0
            self.w, self.v, self.eps, self.a = w, v, eps, a
            self.spin = self.spin_acc = 0j
            return
        self._set(w, v, eps, a)

    @classmethod
    def of(cls, state) -> Motion:
        """The working state again from a solved one (a `chain.LinkState`;
        a long sweep's does not keep iω·e and (iε - ω²)·e: made again here,
        by the same operations on the same numbers)."""
        if state.spin is None:
            return cls(state.e, state.o, state.omega, state.v, state.eps, state.a)
        m = cls.__new__(cls)
        for name in cls.__slots__:
            setattr(m, name, getattr(state, "omega" if name == "w" else name))
        return m

    def _set(self, w, v, eps, a) -> None:
        self.w, self.v, self.eps, self.a = w, v, eps, a
        # iω·e and (iε - ω²)·e; over arrays, i·e (exact) times ω and the factor
        # iε - ω² filled in part by part take fewer passes than complex products
        if isinstance(w, np.ndarray):
            self.spin = (self.e * 1j) * w
        else:
            self.spin = self.e * (1j * w) if w else 0j
        if isinstance(w, np.ndarray) and isinstance(eps, np.ndarray) and w.shape == eps.shape:
            # -ω² written straight into the real parts, ε into the imaginary
            factor = np.empty(w.shape, dtype=complex)
            np.multiply(w, w, out=factor.real)
            np.negative(factor.real, out=factor.real)
            factor.imag = eps
            self.spin_acc = self.e * factor
        else:
            self.spin_acc = self.e * _complex(-(w * w), eps) if _given(w) or _given(eps) else 0j

    # `_plus` written out (read at every point of every pass)
    def at(self, p_local: complex):
        if not p_local:
            return self.o
        o, x = self.o, self.e * p_local
        return x if o.__class__ is complex and not o else o + x

    def vel_at(self, p_local: complex):
        if not p_local:
            return self.v
        v, x = self.v, self.spin * p_local
        return x if v.__class__ is complex and not v else v + x

    def acc_at(self, p_local: complex):
        if not p_local:
            return self.a
        a, x = self.a, self.spin_acc * p_local
        return x if a.__class__ is complex and not a else a + x

    def vel(self, P):
        """Velocity of the link's point that is at P now."""
        return self.v + ((P - self.o) * 1j) * self.w if _given(self.w) else self.v

    def acc(self, P):
        if not (_given(self.w) or _given(self.eps)):
            return self.a
        return self.a + (1j * self.eps - self.w * self.w) * (P - self.o)

    def move_with(self, p_local, V_P, a_P, w, eps) -> None:
        """Give the link ω, ε and the motion of its point p (local coordinates)."""
        self._set(w, V_P, eps, a_P)
        if _given(p_local):
            self.v = V_P - self.spin * p_local
            self.a = a_P - self.spin_acc * p_local

    def local(self, P):
        """Local coordinates of the link's point that is at P now."""
        return (P - self.o) * np.conj(self.e)


def _plain(v) -> complex:
    """An [x, y] as a complex number, an array's through Python floats (no
    numpy scalars): the same values as complex(*v)."""
    return complex(*v.tolist()) if v.__class__ is np.ndarray else complex(*v)


def plain_zero(x) -> bool:
    """Whether x is zero as a plain number (the crank's pivot at the origin,
    a pivot's velocity and acceleration, the frame's)."""
    return x.__class__ is complex and not x


def _plus(base, x):
    """base + x; x itself where base is a plain zero (`plain_zero`): no pass."""
    return x if plain_zero(base) else base + x


def _complex(re, im):
    """re + i·im without complex arithmetic (arrays or numbers)."""
    if not (isinstance(re, np.ndarray) or isinstance(im, np.ndarray)):
        return complex(re, im)
    shape_re, shape_im = np.shape(re), np.shape(im)
    z = np.empty(
        shape_re if shape_re == shape_im else np.broadcast_shapes(shape_re, shape_im),
        dtype=complex,
    )
    z.real, z.imag = re, im
    return z


def _given(x) -> bool:
    """An array, or a number that is not zero (the frame's ω, a point at the origin)."""
    return isinstance(x, np.ndarray) or bool(x)


@dataclass
class Leg:
    kind: LegKind
    start: str  # the plan image the leg starts from (a point, or "X∈K")
    unknown: str  # what the leg's magnitude is: "ω2", "V_EX", …
    d: np.ndarray  # direction line of the unknown component
    # arrays over the angles, or plain numbers where they are the frame's
    V0: Any  # velocity at the leg's start
    a0: Any  # acceleration at the leg's start
    link: int  # the rotating link, or the link slid on
    P: Any = None  # centre of the rotation
    x: Any = None  # the plan's unknowns, solved later: x of the velocity plan
    n: Any = None  # normal (rotation) or Coriolis (slide) component
    y: Any = None  # and y of the acceleration plan
    centre: str = ""  # a rotation's centre as the mechanism names it ("O", "o")

    def normal(self, m: dict) -> Any:
        """-ω²·(X - P) of a rotation (d = i·(X - P)), 2·ω_K·x·i·u of a slide."""
        if self.kind == "rotation":
            return (self.d * 1j) * (self.x * self.x)
        w = m[self.link].w
        if not _given(w):
            return 0j  # no Coriolis component on a guide that does not turn
        return self.d * (2j * w * self.x)


@dataclass
class GroupPlan:
    """One group's velocity and acceleration plan over the N angles."""

    group: AssurGroup
    X_name: str
    X: np.ndarray  # the point whose two equations are solved
    legs: tuple[Leg, Leg]
    # the sine of the angle between the two direction lines, if worked out
    # already (else `sin_angle` works it out when asked for)
    given_sin: Any = field(default=None, repr=False)
    det: Any = field(default=None, repr=False)  # cross(d2, d1), the plans' determinant

    @cached_property
    def sin_angle(self) -> np.ndarray:
        """Sine of the angle between the two direction lines."""
        if self.given_sin is not None:
            return self.given_sin  # type: ignore[no-any-return]
        leg1, leg2 = self.legs
        det = cross(leg2.d, leg1.d) if self.det is None else self.det
        with quiet():
            return np.abs(det) / (np.abs(leg1.d) * np.abs(leg2.d))  # type: ignore[no-any-return]

    def regular(self, least_sin: float) -> Any:
        """Where the sine of the angle between the direction lines is above
        `least_sin` (sin_angle > least_sin, without the division)."""
        leg1, leg2 = self.legs
        det = cross(leg2.d, leg1.d) if self.det is None else self.det
        with quiet():
            return np.abs(det) > least_sin * np.abs(leg1.d * leg2.d)

    @cached_property
    def V_X(self) -> np.ndarray:
        leg = self.legs[0]
        return leg.V0 + leg.d * leg.x

    @cached_property
    def a_X(self) -> np.ndarray:
        leg = self.legs[0]
        return leg.a0 + leg.n + leg.d * leg.y


def solve_two_lines(d1, b1, d2, b2):
    """x1, x2 of b1 + d1·x1 = b2 + d2·x2: a 2×2 system by Cramer's rule."""
    return _cramer(cross(d2, d1), d1, d2, b2 - b1)


def _cramer(det, d1, d2, rhs, singular=None):
    """Cramer's rule with the determinant cross(d2, d1) given (the velocity and
    the acceleration plan share it); NaN, not ±inf, where the lines are parallel
    (`singular`: det == 0 anywhere, if the caller knows)."""
    with quiet():
        x1 = cross(d2, rhs) / det
        x2 = cross(d1, rhs) / det
    if singular is None:
        singular = parallel_somewhere(det)
    if singular:
        zero = det == 0
        x1 = np.where(zero, np.nan, x1)
        x2 = np.where(zero, np.nan, x2)
    return x1, x2


def parallel_somewhere(det) -> bool:
    """Whether the determinant is zero at any angle."""
    # an array's all() is whether every entry is non-zero (NaN counts as non-zero)
    return not det.all() if isinstance(det, np.ndarray) else det == 0


class DyadSolver:
    """Closed-form position and plans of one dyad of the mechanism."""

    has_branches = False

    def __init__(self, mech: Mechanism, group: AssurGroup) -> None:
        self.mech = mech
        self.group = group
        self.name = group.name  # the group's name, read at every sweep
        self._locs: dict[tuple[int, str], complex] = {}  # local coordinates, read once
        # a prismatic pair's direction and point as complex numbers, by the pair's id
        # (the pairs are the Mechanism's, alive as long as it is)
        self._guides: dict[int, tuple[complex, complex]] = {}
        self.L1, self.L2 = group.links
        # the kind fixes which pairs are revolute and which prismatic
        self.outer1: Any
        self.inner: Any
        self.outer2: Any
        self.outer1, self.inner, self.outer2 = group.pairs
        self.K1 = other_link(self.outer1, self.L1)
        self.K2 = other_link(self.outer2, self.L2)
        self.kind = group.kind

    def _make_locals(self) -> tuple[complex, ...]:
        """The local coordinates a kind reads at every pass (RRR, RRP)."""
        raise NotImplementedError(self.kind)

    @property
    def _locals(
        self,
    ) -> Any:  # kept in the instance's dictionary (cached_property's lock costs more)
        found = self.__dict__.get("_kept_locals")
        if found is None:
            found = self.__dict__["_kept_locals"] = self._make_locals()
        return found

    # local coordinates as complex numbers
    def loc(self, link: int, name: str) -> complex:
        found = self._locs.get((link, name))
        if found is None:
            pts = self.mech.frame if link == 0 else self.mech.links[link].points
            p = pts[name]
            found = self._locs[link, name] = complex(p[0], p[1])
        return found

    def direction_of(self, pair: Prismatic) -> complex:
        """The guide's unit direction (guide-link coordinates) as a complex
        number, read once (through Python floats: the same values)."""
        found = self._guides.get(id(pair))
        if found is None:
            found = self._guides[id(pair)] = (_plain(pair.direction), _plain(pair.through))
        return found[0]

    def through_of(self, pair: Prismatic) -> complex:
        """A point of the guide line (guide-link coordinates), read once."""
        self.direction_of(pair)
        return self._guides[id(pair)][1]

    def prism_line(self, pair: Prismatic, m: dict, unknown: int, Q_local: complex, e):
        """The line (P0, u) on which the point Q of the unknown link lies, its angle e known."""
        direction, through = self.direction_of(pair), self.through_of(pair)
        S_local = self.loc(pair.slider, pair.slider_point)
        u = e * direction
        if unknown == pair.slider:
            K = m[pair.guide]
            P0 = K.at(through) - e * (S_local - Q_local)
        else:
            K = m[pair.slider]
            P0 = K.at(S_local) + e * (Q_local - through)
        return P0, u

    def after_velocities(self, m: dict, leg1: Leg, leg2: Leg) -> None:
        """Hook between the velocity and the acceleration plan."""

    def carried(self) -> list[tuple[int, int, str]]:
        """(L, K, P) for each link L of the group whose origin is its pair P with
        the known link K: placing L hands it the velocity and acceleration of
        K's point P as they are (`move_with` at the origin), so L's v and a are
        P's, to the last bit."""
        return []

    def _at_origin(self, *joins: tuple[int, int, str]) -> list[tuple[int, int, str]]:
        return [(L, K, P) for L, K, P in joins if not self.loc(L, P)]

    def positions(self, m: dict, sign: int) -> None:  # pragma: no cover - abstract
        raise NotImplementedError

    def legs(self, m: dict) -> tuple[str, np.ndarray, Leg, Leg]:  # pragma: no cover
        raise NotImplementedError

    def place(self, m: dict, plan: GroupPlan) -> None:  # pragma: no cover
        raise NotImplementedError

    def failure(self, m: dict, i: int, phi: float) -> str:  # pragma: no cover
        raise NotImplementedError

    def margin(self, m: dict):  # pragma: no cover - abstract
        """How far the group is from failing to assemble, over the angles:
        positive where it assembles, zero at a limit position (a toggle),
        negative where it cannot (a length in m, or the sine of the angle
        between two guides)."""
        raise NotImplementedError

    def cure(self, m: dict, bad) -> str:
        """What to change so that the group assembles at the angles `bad`
        (a mask over the angles of `m`)."""
        return "change the lengths of the group's links"

    def branch_meaning(self, sign: int) -> str:
        return "one configuration"

    # --- the plans ---------------------------------------------------------------
    def plan(self, m: dict, place: bool = True) -> GroupPlan:
        """Solve the group's velocity and acceleration plan, then (`place`) give
        its links their ω, ε and the motion of their origins."""
        X_name, X, leg1, leg2 = self.legs(m)
        det = cross(leg2.d, leg1.d)
        parallel = parallel_somewhere(det)
        leg1.x, leg2.x = _cramer(det, leg1.d, leg2.d, leg2.V0 - leg1.V0, parallel)
        self.after_velocities(m, leg1, leg2)
        leg1.n, leg2.n = leg1.normal(m), leg2.normal(m)
        leg1.y, leg2.y = _cramer(
            det, leg1.d, leg2.d, (leg2.a0 + leg2.n) - (leg1.a0 + leg1.n), parallel
        )
        plan = GroupPlan(self.group, X_name, X, (leg1, leg2), det=det)
        if place:
            self.place(m, plan)
        return plan

    def motion(self, m: dict, least_sin: float | None) -> Any:
        """Give the group's links their ω, ε and the motion of their origins
        (what `plan` solves and `place` hands on) and say where the plan is
        regular (`GroupPlan.regular`), without keeping the plan's records: a
        sweep needs the links' motion; the plans are solved again from it when
        asked for (`chain.Sweep.plans`). A kind may solve it in fewer passes
        (RRR and RRP do, in closed form)."""
        plan = self.plan(m)
        return None if least_sin is None else plan.regular(least_sin)

    def known_motion(self, m: dict, K: int, name: str) -> tuple[Any, Any]:
        """Velocity and acceleration of the point `name` of the known link K."""
        p = self.loc(K, name)
        k = m[K]
        return k.vel_at(p), k.acc_at(p)

    def rotation(self, link: int, P_name: str, X, K: int, m: dict) -> Leg:
        """Link `link` turning about its pair P with the known link K."""
        p = self.loc(K, P_name)
        P = m[K].at(p)
        return Leg(
            "rotation",
            P_name.lower(),
            f"ω{link}",
            1j * (X - P),
            m[K].vel_at(p),
            m[K].acc_at(p),
            link,
            P=P,
            centre=P_name,
        )

    def slide(self, link: int, on: int, X, u, K: Motion, start: str) -> Leg:
        return Leg("slide", start, f"V{link}/{on}", u, K.vel(X), K.acc(X), on)

    def turn_about(self, m: dict, leg: Leg, P_name: str) -> None:
        """Place the link of a rotation leg: its pivot moves as the leg's start."""
        m[leg.link].move_with(self.loc(leg.link, P_name), leg.V0, leg.a0, leg.x, leg.y)


def origin(P, e, p_local: complex):
    """Origin P - e·p of a link whose local point p sits at P. A link whose
    origin is its pivot keeps that pivot (one number on the frame)."""
    if not p_local:
        return P
    return P - e * p_local


def entry(x, i: int):
    """Entry i of an array over the angles, or the number a frame point is."""
    return x[i] if isinstance(x, np.ndarray) else x


def other_link(pair: Revolute | Prismatic, link: int) -> int:
    a, b = pair.links
    return b if a == link else a


def cramer(numerator, det, parallel: bool):
    """numerator / det, NaN where the plan's lines are parallel, det = 0
    (`parallel`: anywhere, `parallel_somewhere(det)`), as `_cramer` gives."""
    x = np.divide(numerator, det)
    if parallel:
        return np.where(det == 0, np.nan, x)
    return x


def conj(z):
    """The conjugate of an array, or of a number (the frame's)."""
    return np.conj(z) if isinstance(z, np.ndarray) else z.conjugate()
