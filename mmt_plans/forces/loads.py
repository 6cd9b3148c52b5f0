"""The loads of every link at one position (seed 003 §2.1–2.5, seed 002 task 4.1).

    G_i = m_i·g, along −y                                   (14)
    F_IN.i = −m_i·a_Si, at the centre of mass S_i           (15)
    J_Si = k·m_i·l_i²  (model.Link.J; given or by default)  (16)
    M_IN.i = −J_Si·ε_i                                      (17)
    h_F_IN.i = M_IN.i / F_IN.i,  |h| = h / μ_l  (mm)        (18), (19)

and the external forces of `[[force]]` (the production resistance F_PR).
Moments are signed counter-clockwise positive, as ε is.
"""

from __future__ import annotations

import math
from collections.abc import Collection, Mapping
from dataclasses import dataclass, field
from typing import Literal

import numpy as np

from ..model import Force, Stroke
from .errors import ForceError
from .state import PositionState, xy, xy_rows

ForceRule = Literal["working", "always", "fixed"]

# an inertia force below this fraction of m·a_A (the crank pin's acceleration)
# is rounding noise of a centre of mass that does not accelerate (one on a
# fixed pivot): it is not shifted, and the inertia moment stays a couple
NOISE = 1e-12

# |V| below this fraction of |V_A| counts as "at rest": a force that opposes
# the velocity then opposes the acceleration (the motion about to start)
REST = 1e-12


@dataclass(frozen=True)
class AppliedForce:
    """One load on a link's free body: `force` acting at `point`, plus a
    `couple` (N·m, counter-clockwise positive) for an inertia moment or a
    prismatic pair that transmits a pure couple."""

    label: str
    force: np.ndarray
    point: np.ndarray
    couple: float = 0.0

    def moment_about(self, P: np.ndarray) -> float:
        r = self.point - P
        return float(r[0] * self.force[1] - r[1] * self.force[0]) + self.couple


@dataclass(frozen=True)
class ShiftedInertiaForce:
    """F_IN.i moved off S_i by the arm h so that its moment about S_i equals
    M_IN.i (seed 003 §2.5): the force of the textbook's point K_i."""

    link: int
    force: np.ndarray
    point: np.ndarray  # K_i (global, m)
    arm: float  # |h| = |M_IN| / |F_IN|, m          (18)
    arm_mm: float | None  # |h| / μ_l, mm of the drawing (19); None without μ_l


@dataclass(frozen=True)
class LinkLoads:
    """The weight, inertia force and inertia moment of one link."""

    link: int
    mass: float
    J: float  # kg·m² about S
    centre_of_mass: np.ndarray  # S_i, m
    acceleration_cm: np.ndarray  # a_Si, m/s²
    eps: float  # ε_i, rad/s²
    weight: np.ndarray  # G_i, N
    inertia_force: np.ndarray  # F_IN.i, N
    inertia_moment: float  # M_IN.i, N·m
    # None when F_IN.i = 0 (to rounding): the inertia moment then stays a couple
    shifted_inertia_force: ShiftedInertiaForce | None
    # G_i applied at a point of the link other than S_i (a mistake recomputed
    # for the student check): its name and position; None: at S_i
    weight_at: str | None = None
    weight_point: np.ndarray | None = None

    @property
    def cm_name(self) -> str:
        return f"S{self.link}"


@dataclass(frozen=True)
class ExternalForce:
    """A `[[force]]` entry at this position: zero when it does not act."""

    name: str
    link: int
    at: str
    point: np.ndarray
    force: np.ndarray
    magnitude: float  # N, as given
    rule: ForceRule  # "working": only in the working stroke; "always": against V_at; "fixed"
    acting: bool  # False in the idle stroke of a force that acts in the working stroke only
    at_rest: bool = False  # "always" at an instant where its point is at rest: zero there


# the force of a pure couple (read-only: one array for every couple)
_NO_FORCE = xy(0j)


@dataclass(frozen=True)
class Loads:
    """Every load of every link at one position."""

    index: int | None
    phi1_deg: float
    stroke: Stroke
    g: float
    mu_l: float | None  # m/mm of the mechanism's drawing, when given
    links: Mapping[int, LinkLoads]
    production_resistance: tuple[ExternalForce, ...]
    state: PositionState = field(repr=False, compare=False)

    def on_link(self, link: int) -> tuple[AppliedForce, ...]:
        """The link's own loads as a free body gets them: G, F_IN at S (its
        moment M_IN as a couple) and the external forces on it."""
        out = []
        ll = self.links.get(link)
        if ll is not None:
            S = ll.centre_of_mass
            if ll.mass:
                G_at = S if ll.weight_point is None else ll.weight_point
                out.append(AppliedForce(f"G{link}", ll.weight, G_at))
                out.append(AppliedForce(f"F_in{link}", ll.inertia_force, S))
            if ll.inertia_moment:
                out.append(AppliedForce(f"M_in{link}", _NO_FORCE, S, ll.inertia_moment))
        for f in self.production_resistance:
            if f.link == link and f.acting:
                out.append(AppliedForce(f.name, f.force, f.point))
        return tuple(out)

    def weight(self, link: int) -> np.ndarray:
        return self.links[link].weight

    def inertia_force(self, link: int) -> np.ndarray:
        return self.links[link].inertia_force

    def inertia_moment(self, link: int) -> float:
        return self.links[link].inertia_moment


def link_loads(
    state: PositionState,
    mu_l: float | None = None,
    *,
    inertia_forces: Collection[int] | None = None,
    inertia_moments: Collection[int] | None = None,
    gravity: bool = True,
    inertia_moments_reversed: Collection[int] = (),
    weight_at: Mapping[int, str] | None = None,
) -> Loads:
    """Every link's loads. The keywords make a mistake on purpose, for the
    student check to recompute it: `inertia_forces` / `inertia_moments` the
    links whose F_IN / M_IN are kept (None: all), `gravity` False leaves out
    every G, `inertia_moments_reversed` the links whose M_IN is taken the
    wrong way (F_IN shifted to the wrong side of S: K mirrored about S),
    `weight_at` a point of the link (by name) where G is applied in place of
    S. The defaults are the textbook's calculation."""
    if mu_l is not None and not (math.isfinite(mu_l) and mu_l > 0):
        raise ForceError(
            f"the length scale mu_l = {mu_l!r} m/mm is not a positive number",
            "give the drawing's scale, e.g. mu_l = 0.005",
        )
    mech = state.mech
    g = mech.g
    d = mech.drive.link
    a_A = abs(state.links[d].acc(state.point(d, mech.crank_pin)))
    # every link's vectors first, then their [x, y] rows made at once (the same numbers)
    found = []
    vectors: list[complex] = []
    for lid, link in mech.links.items():
        pose = state.links[lid]
        S = state.centre_of_mass(lid)
        a_S = pose.acc(S)
        F_in = -link.mass * a_S
        M_in = -link.J * pose.eps
        if inertia_forces is not None and lid not in inertia_forces:
            F_in = 0j
        if inertia_moments is not None and lid not in inertia_moments:
            M_in = 0.0
        if lid in inertia_moments_reversed:
            M_in = -M_in
        G_at, G_point = None, None
        if weight_at is not None and lid in weight_at:
            G_at = weight_at[lid]
            if G_at not in link.points:
                raise ForceError(
                    f"link {lid} has no point {G_at!r} to apply its weight at",
                    f"name one of its points: {', '.join(link.points)}",
                )
            G_point = xy(state.point(lid, G_at))
        shift = _shift(S, F_in, M_in, NOISE * link.mass * a_A)
        found.append((lid, link, pose, M_in, G_at, G_point, shift))
        vectors += (S, a_S, complex(0.0, -link.mass * g if gravity else 0.0), F_in)
        if shift is not None:
            vectors.append(shift[0])
    rows = iter(xy_rows(vectors))
    links = {}
    for lid, link, pose, M_in, G_at, G_point, shift in found:
        S_xy, a_S_xy, G_xy, F_in_xy = next(rows), next(rows), next(rows), next(rows)
        shifted = None
        if shift is not None:
            h = shift[1]
            shifted = ShiftedInertiaForce(
                lid, F_in_xy, next(rows), h, None if mu_l is None else h / mu_l
            )
        links[lid] = LinkLoads(
            link=lid,
            mass=link.mass,
            J=link.J,
            centre_of_mass=S_xy,
            acceleration_cm=a_S_xy,
            eps=pose.eps,
            weight=G_xy,
            inertia_force=F_in_xy,
            inertia_moment=M_in + 0.0,
            shifted_inertia_force=shifted,
            weight_at=G_at,
            weight_point=G_point,
        )
    external = tuple(external_force(f, state) for f in mech.forces)
    return Loads(state.index, state.phi1_deg, state.stroke, g, mu_l, links, external, state)


def shifted_inertia_force(
    link: int, S: complex, F_in: complex, M_in: float, mu_l: float | None, zero: float = 0.0
) -> ShiftedInertiaForce | None:
    """Seed 003 (18), (19): K = S + r with r ⊥ F_IN and r × F_IN = M_IN.
    None when |F_IN| <= zero (no force to shift: the couple stays)."""
    shift = _shift(S, F_in, M_in, zero)
    if shift is None:
        return None
    K, h = shift
    return ShiftedInertiaForce(link, xy(F_in), xy(K), h, None if mu_l is None else h / mu_l)


def _shift(S: complex, F_in: complex, M_in: float, zero: float) -> tuple[complex, float] | None:
    """K_i and the arm h of `shifted_inertia_force` (None: nothing to shift)."""
    F2 = F_in.real * F_in.real + F_in.imag * F_in.imag
    if F2 == 0.0 or math.sqrt(F2) <= zero:
        return None
    r = -1j * F_in * M_in / F2
    return S + r, abs(M_in) / math.sqrt(F2)


def external_force(f: Force, state: PositionState) -> ExternalForce:
    """SPEC_FORMAT `[[force]]`: acts = "working" (default) pushes along
    −working_direction in the working stroke and vanishes in the idle one;
    acts = "always" opposes the velocity of `at` (at an instant of rest, the
    motion about to start); a `direction` is fixed and acts in every position
    unless acts = "working" is written."""
    mech = state.mech
    P = state.point(f.link, f.at)
    rule: ForceRule
    if f.direction is not None:
        rule = "fixed"
        direction = complex(f.direction[0], f.direction[1])
        acting = f.acts == "always" or state.stroke == "working"
    elif f.acts == "working":
        rule = "working"
        wd = mech.study.working_direction
        direction = -complex(wd[0], wd[1])
        acting = state.stroke == "working"
    else:
        rule = "always"
        direction = _against_motion(f, state, P)
        acting = direction != 0
    force = f.magnitude * direction if acting else 0j
    return ExternalForce(
        f.name,
        f.link,
        f.at,
        xy(P),
        xy(force),
        f.magnitude,
        rule,
        acting,
        at_rest=rule == "always" and not acting,
    )


def _against_motion(f: Force, state: PositionState, P: complex) -> complex:
    """The unit vector opposing the velocity of `at`; zero at an instant when
    `at` is at rest (SPEC_FORMAT: a resistance opposing the motion vanishes
    when its point stops)."""
    mech = state.mech
    d = mech.drive.link
    A = state.point(d, mech.crank_pin)
    V = state.links[f.link].vel(P)
    if abs(V) > REST * abs(state.links[d].vel(A)):
        return -V / abs(V)
    return 0j
