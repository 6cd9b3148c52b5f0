"""What the force calculation of every dyad kind shares: reactions, force
polygons, the results of a group and of the driving link, and the protocol
of a kind (`GroupSolver`: moment equations, 2×2 polygons, prismatic pairs)."""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from functools import lru_cache
from typing import Any, Literal

import numpy as np

from ...model import Prismatic, Revolute
from ...structure import AssurGroup, other_link
from ..errors import ForceError
from ..loads import AppliedForce
from ..state import PositionState, cross, xy, xy_rows

PairKind = Literal["R", "P"]

# sine of the angle between the two unknown directions of a force plan below
# which the plan is singular (the group is at a dead position)
SINGULAR_SIN = 1e-12


@lru_cache(maxsize=256)
def reaction_name(by: int, on: int) -> str:
    """R_ij, the force link i exerts on link j; `Ri_j` when a number has two digits."""
    return f"R{by}{on}" if by < 10 and on < 10 else f"R{by}_{on}"


@dataclass(frozen=True)
class ReactionComponent:
    """A component of a reaction along a known direction, as the textbook
    splits R34 = R34^n + R34^t. A negative value means it points against
    `direction` ("change its direction to the opposite")."""

    label: str
    direction: np.ndarray  # unit vector
    value: float  # N

    @property
    def vector(self) -> np.ndarray:
        return xy(_c(self.direction) * self.value)


@dataclass(frozen=True)
class Reaction:
    """R_ij: the force link `by` exerts on link `on` in one kinematic pair.

    It acts at `point`: the pin of a revolute pair; for a prismatic pair the
    point of the sliding line where its moment is that of the pair's reaction.
    A prismatic pair whose normal force vanishes may still carry a `couple`.
    """

    by: int
    on: int
    pair: str
    kind: PairKind
    force: np.ndarray
    point: np.ndarray
    couple: float = 0.0
    components: tuple[ReactionComponent, ...] = ()

    @property
    def name(self) -> str:
        return reaction_name(self.by, self.on)

    @property
    def magnitude(self) -> float:
        return float(math.hypot(self.force[0], self.force[1]))

    def reversed(self) -> Reaction:
        """R_ji = −R_ij, at the same point."""
        comps = tuple(
            ReactionComponent(_swap_label(c.label, self.by, self.on), c.direction, -c.value)
            for c in self.components
        )
        return Reaction(
            self.on,
            self.by,
            self.pair,
            self.kind,
            xy(-_c(self.force)),
            self.point,
            -self.couple + 0.0,
            comps,
        )

    def applied(self) -> AppliedForce:
        return AppliedForce(self.name, self.force, self.point, self.couple)


@dataclass(frozen=True)
class PolygonVector:
    """One side of a force polygon, drawn from `start` (N, the plan's origin at 0)."""

    label: str
    vector: np.ndarray
    start: np.ndarray
    known: bool  # known before the polygon is drawn; False: found by closing it

    @property
    def end(self) -> np.ndarray:
        return xy(_c(self.start) + _c(self.vector))

    @property
    def magnitude(self) -> float:
        return float(math.hypot(self.vector[0], self.vector[1]))


@dataclass(frozen=True)
class ForcePolygon:
    """A closed force polygon (plan of forces): the vector equation of one
    group or link, its sides head to tail from the origin."""

    title: str  # "group 4-5", "link 4", "link 1"
    equation: str
    vectors: tuple[PolygonVector, ...]

    @property
    def closure(self) -> float:
        """|Σ| of the sides: zero for a closed polygon (up to rounding)."""
        return abs(sum((_c(v.vector) for v in self.vectors), 0j))

    @property
    def largest(self) -> float:
        return max((v.magnitude for v in self.vectors), default=0.0)


@dataclass(frozen=True)
class GroupForces:
    """The force calculation of one Assur group."""

    name: str  # "4-5"
    kind: str
    links: tuple[int, int]  # (L1, L2), outer–inner–outer
    reactions: tuple[Reaction, ...]  # outer at L1, outer at L2, inner
    polygons: tuple[ForcePolygon, ...]
    free_bodies: Mapping[int, tuple[AppliedForce, ...]]  # every force on L1 and L2
    steps: tuple[str, ...]


@dataclass(frozen=True)
class DrivingLinkForces:
    """Seed 003 §2.8: ΣM_O = 0 gives F_bal at A ⊥ OA; G1 + F_IN1 + R21 + F_bal + R01 = 0."""

    link: int
    pivot: str  # O
    pin: str  # A
    balancing_force: float  # N, positive in the sense of the crank's rotation
    balancing_vector: np.ndarray  # F_bal as a vector at A
    balancing_moment: float  # N·m, F_bal·OA, signed the same way
    reaction: Reaction  # R01
    polygon: ForcePolygon
    free_body: tuple[AppliedForce, ...]  # every force on the link, F_bal and R01 included
    steps: tuple[str, ...]


class GroupSolver:
    def __init__(
        self, state: PositionState, group: AssurGroup, bodies: dict[int, tuple[AppliedForce, ...]]
    ) -> None:
        self.state = state
        self.group = group
        self.L1, self.L2 = group.links
        # the kind fixes which pairs are revolute and which prismatic
        self.outer1: Any
        self.inner: Any
        self.outer2: Any
        self.outer1, self.inner, self.outer2 = group.pairs
        self.K1 = other_link(self.outer1, self.L1)
        self.K2 = other_link(self.outer2, self.L2)
        self.bodies = bodies
        self.steps: list[str] = []

    # loads of a link's free body
    def F(self, link: int) -> complex:
        return sum((_c(f.force) for f in self.bodies[link]), 0j)

    def M(self, link: int, P: complex) -> float:
        return sum((cross(_c(f.point) - P, _c(f.force)) + f.couple for f in self.bodies[link]), 0.0)

    def pin(self, pair: Revolute) -> complex:
        return self.state.point(pair.links[1], pair.point)

    def solve2(self, d1: complex, d2: complex, rhs: complex, what: str) -> tuple[float, float]:
        """x1, x2 of d1·x1 + d2·x2 = rhs (a force polygon closed by two known directions)."""
        norm = abs(d1) * abs(d2)
        if norm == 0.0 or abs(cross(d1, d2)) <= SINGULAR_SIN * norm:
            raise ForceError(
                f"the directions of {what} are parallel: the force plan does not "
                "close (the group is at a dead position)",
                "choose another force position",
                phi1_deg=self.state.phi1_deg,
                group=self.group.name,
            )
        x = np.linalg.solve(
            np.array([[d1.real, d2.real], [d1.imag, d2.imag]]), np.array([rhs.real, rhs.imag])
        )
        return float(x[0]), float(x[1])

    def unit_along(self, A: complex, B: complex, link: int) -> tuple[complex, float]:
        d = B - A
        length = abs(d)
        if length == 0.0:
            raise ForceError(
                f"link {link} has its two pairs at one point: its reaction has no normal direction",
                "give the link a length",
                phi1_deg=self.state.phi1_deg,
                group=self.group.name,
            )
        return d / length, length

    def tangential(
        self, pair: Revolute, link: int, K: int, B: complex, b: str
    ) -> tuple[complex, complex, float, float]:
        """R_KL^t from ΣM_B(link) = 0 (seed 003 §2.6–2.7; seed 000 (1.32)): with
        n along the link from its outer pin A to B and t = i·n,
        ΣM_B = M_B(loads) + (A − B) × R^t·t = M_B(loads) − R^t·AB = 0."""
        A = self.pin(pair)
        n, AB = self.unit_along(A, B, link)
        MB = self.M(link, B)
        Rt = MB / AB
        name = reaction_name(K, link)
        self.steps.append(
            f"Sum M_{b}(link {link}) = 0: {fmt(MB)} - {name}^t * {pair.point}{b} = 0 "
            f"-> {name}^t = {fmt(MB)} / {fmt(AB)} = {fmt(Rt)} N"
        )
        return A, n, AB, Rt

    def prismatic_reaction(
        self, pair: Prismatic, by: int, on: int, N: float, P: complex, M_P: float, why: str
    ) -> Reaction:
        """The reaction N·(i·u) of a prismatic pair whose moment about P is M_P,
        placed on the sliding line (or kept as a couple when N vanishes)."""
        u, Q0 = self.state.guide(pair)
        nn = 1j * u
        force = N * nn
        M_Q0 = M_P + cross(P - Q0, force)  # moment about the slider's point
        scale = max(
            abs(N), *(abs(_c(f.force)) for lid in self.bodies for f in self.bodies[lid]), 1e-300
        )
        name = reaction_name(by, on)
        if abs(N) > 1e-9 * scale:
            x = M_Q0 / N
            point, couple = Q0 + x * u, 0.0
            self.steps.append(
                f"{why}: {name} acts {fmt(x * 1e3)} mm from {pair.slider_point} along the guide"
            )
        else:
            point, couple = Q0, M_Q0
            self.steps.append(
                f"{why}: {name} has no normal force; the pair carries a couple {fmt(M_Q0)} N*m"
            )
        return Reaction(
            by,
            on,
            pair.name,
            "P",
            xy(force),
            xy(point),
            couple,
            (ReactionComponent(f"{name}^n", xy(nn), N),),
        )

    def polygon(self, title: str, sides: list[tuple[str, complex, bool]]) -> ForcePolygon:
        return ForcePolygon(title, " + ".join(s[0] for s in sides) + " = 0", head_to_tail(sides))

    def load_sides(self, link: int) -> list[tuple[str, complex, bool]]:
        """The known forces of a link's free body, in the order they were applied."""
        return _load_sides(self.bodies[link])

    def result(
        self, reactions: tuple[Reaction, Reaction, Reaction], polygons: tuple[ForcePolygon, ...]
    ) -> GroupForces:
        bodies = {lid: self.bodies[lid] for lid in (self.L1, self.L2)}
        for r in reactions:
            if r.on in bodies:
                bodies[r.on] = bodies[r.on] + (r.applied(),)
            if r.by in bodies:  # R_ji on the other link (made only where it is one of the group's)
                bodies[r.by] = bodies[r.by] + (r.reversed().applied(),)
        return GroupForces(
            self.group.name,
            self.group.kind or "",
            (self.L1, self.L2),
            reactions,
            polygons,
            bodies,
            tuple(self.steps),
        )

    def solve(self) -> GroupForces:  # pragma: no cover - abstract
        raise NotImplementedError


# --- helpers ----------------------------------------------------------------------------


def head_to_tail(sides: list[tuple[str, complex, bool]]) -> tuple[PolygonVector, ...]:
    """The sides of a force polygon head to tail from the origin (each vector
    and where it starts as [x, y], made together)."""
    starts, start = [], 0j
    for _, vec, _ in sides:
        starts.append(start)
        start += vec
    rows = xy_rows([vec for _, vec, _ in sides] + starts)
    n = len(sides)
    return tuple(
        PolygonVector(label, rows[i], rows[n + i], known)
        for i, (label, _, known) in enumerate(sides)
    )


def _load_sides(body: tuple[AppliedForce, ...]) -> list[tuple[str, complex, bool]]:
    """The known forces of a free body as polygon sides, but a pure couple's
    (a zero force, both parts 0.0: its complex number is 0)."""
    sides = []
    for f in body:
        F = _c(f.force)
        if not (F == 0 and f.couple):
            sides.append((f.label, F, True))
    return sides


def _c(v: np.ndarray) -> complex:
    return complex(*v.tolist())  # through Python floats (no numpy scalars): the same values


def _swap_label(label: str, by: int, on: int) -> str:
    old, new = reaction_name(by, on), reaction_name(on, by)
    return new + label[len(old) :] if label.startswith(old) else label


def fmt(x: float) -> str:
    return f"{x + 0.0:.6g}"  # + 0.0: no "-0"
