"""Force plans group by group (seed 003 §2.6–2.8; seed 000 §4.3–4.4).

The groups are taken apart in the reverse order of their attachment: the
last group first, each one loaded with its links' weights, inertia forces and
moments, the external forces and the reactions of the groups attached after
it (R43 = −R34), then the driving link with the balancing force. No friction:
a revolute pair's reaction passes through its pin; a prismatic pair's is
normal to the guide, at a point found from a moment equation.

Per kind, outer–inner–outer, links (L1, L2) joined to the known K1, K2:

RRR, RRP  the reaction at a revolute outer pair is R = R^n + R^t, R^n along
          the link (outer pin to inner pin), R^t perpendicular; R^t from the
          moment equation of its link about the inner pin B; the normal
          components (and a prismatic outer reaction, normal to its guide)
          close the group's force polygon; the inner reaction closes the
          polygon of link L1 (seed 003 §2.6: R34^n + R34^t + G4 + F_IN4 + R54 = 0);
          the point of a prismatic reaction from ΣM_B of its link.
PRP       both outer reactions are normal to their guides: the group's polygon
          gives both, link L1's polygon the inner reaction at B, ΣM_B of each
          link the points of application.
RPR       the inner reaction is normal to the slot: ΣM of link L2 about its
          pivot (with the line of action that ΣM of L1 about its pivot puts
          it on) gives its magnitude, as the shaper's ΣM_C(3) = 0 does; each
          outer reaction then closes its own link's polygon.
RPP       link L2 lies between two guides: its polygon gives both normal
          reactions; link L1's polygon gives the outer reaction at its pin;
          moment equations give the points of application.

Each 2×2 system is solved exactly (numpy.linalg.solve).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Literal, Mapping

import numpy as np

from ..model import FRAME, Prismatic, Revolute
from ..structure import AssurGroup, other_link
from .errors import ForceError
from .loads import AppliedForce, Loads
from .state import PositionState, cross, xy

PairKind = Literal["R", "P"]

# sine of the angle between the two unknown directions of a force plan below
# which the plan is singular (the group is at a dead position)
SINGULAR_SIN = 1e-12


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
        return xy(complex(*self.direction) * self.value)


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

    def reversed(self) -> "Reaction":
        """R_ji = −R_ij, at the same point."""
        comps = tuple(ReactionComponent(_swap_label(c.label, self.by, self.on), c.direction,
                                        -c.value) for c in self.components)
        return Reaction(self.on, self.by, self.pair, self.kind, xy(-_c(self.force)), self.point,
                        -self.couple + 0.0, comps)

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


def solve_groups(loads: Loads) -> tuple[tuple[GroupForces, ...], DrivingLinkForces]:
    """Every group, last attached first, then the driving link."""
    state = loads.state
    mech = state.mech
    passed: dict[int, list[AppliedForce]] = {}
    results = []
    for group in reversed(state.groups):
        if not group.is_dyad or group.kind not in _KINDS:
            raise ForceError(f"group {group.label} of links {group.name} is not a class II group",
                             "only dyads have force plans here", phi1_deg=state.phi1_deg,
                             group=group.name)
        L1, L2 = group.links
        bodies = {lid: loads.on_link(lid) + tuple(passed.get(lid, ())) for lid in (L1, L2)}
        solver = _KINDS[group.kind](state, group, bodies)
        result = solver.solve()
        results.append(result)
        for r in result.reactions[:2]:  # the outer reactions act on the links before
            if r.by != FRAME:
                passed.setdefault(r.by, []).append(r.reversed().applied())
    driver = _driving_link(state, loads, tuple(passed.get(mech.drive.link, ())))
    return tuple(results), driver


# --- the five kinds ---------------------------------------------------------------------

class _GroupSolver:
    def __init__(self, state: PositionState, group: AssurGroup,
                 bodies: dict[int, tuple[AppliedForce, ...]]) -> None:
        self.state = state
        self.group = group
        self.L1, self.L2 = group.links
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
            raise ForceError(f"the directions of {what} are parallel: the force plan does not "
                             "close (the group is at a dead position)",
                             "choose another force position", phi1_deg=self.state.phi1_deg,
                             group=self.group.name)
        x = np.linalg.solve(np.array([[d1.real, d2.real], [d1.imag, d2.imag]]),
                            np.array([rhs.real, rhs.imag]))
        return float(x[0]), float(x[1])

    def unit_along(self, A: complex, B: complex, link: int) -> tuple[complex, float]:
        d = B - A
        length = abs(d)
        if length == 0.0:
            raise ForceError(f"link {link} has its two pairs at one point: its reaction has no "
                             "normal direction", "give the link a length",
                             phi1_deg=self.state.phi1_deg, group=self.group.name)
        return d / length, length

    def tangential(self, pair: Revolute, link: int, K: int, B: complex, b: str
                   ) -> tuple[complex, complex, float, float]:
        """R_KL^t from ΣM_B(link) = 0 (seed 003 §2.6–2.7; seed 000 (1.32)): with
        n along the link from its outer pin A to B and t = i·n,
        ΣM_B = M_B(loads) + (A − B) × R^t·t = M_B(loads) − R^t·AB = 0."""
        A = self.pin(pair)
        n, AB = self.unit_along(A, B, link)
        MB = self.M(link, B)
        Rt = MB / AB
        name = reaction_name(K, link)
        self.steps.append(f"Sum M_{b}(link {link}) = 0: {fmt(MB)} - {name}^t * {pair.point}{b} = 0 "
                          f"-> {name}^t = {fmt(MB)} / {fmt(AB)} = {fmt(Rt)} N")
        return A, n, AB, Rt

    def prismatic_reaction(self, pair: Prismatic, by: int, on: int, N: float, P: complex,
                           M_P: float, why: str) -> Reaction:
        """The reaction N·(i·u) of a prismatic pair whose moment about P is M_P,
        placed on the sliding line (or kept as a couple when N vanishes)."""
        u, Q0 = self.state.guide(pair)
        nn = 1j * u
        force = N * nn
        M_Q0 = M_P + cross(P - Q0, force)  # moment about the slider's point
        scale = max(abs(N), *(abs(_c(f.force)) for lid in self.bodies for f in self.bodies[lid]),
                    1e-300)
        name = reaction_name(by, on)
        if abs(N) > 1e-9 * scale:
            x = M_Q0 / N
            point, couple = Q0 + x * u, 0.0
            self.steps.append(f"{why}: {name} acts {fmt(x * 1e3)} mm from {pair.slider_point} "
                              f"along the guide")
        else:
            point, couple = Q0, M_Q0
            self.steps.append(f"{why}: {name} has no normal force; the pair carries a couple "
                              f"{fmt(M_Q0)} N*m")
        return Reaction(by, on, pair.name, "P", xy(force), xy(point), couple,
                        (ReactionComponent(f"{name}^n", xy(nn), N),))

    def polygon(self, title: str, sides: list[tuple[str, complex, bool]]) -> ForcePolygon:
        vectors, start = [], 0j
        for label, vec, known in sides:
            vectors.append(PolygonVector(label, xy(vec), xy(start), known))
            start += vec
        eq = " + ".join(label for label, _, _ in sides) + " = 0"
        return ForcePolygon(title, eq, tuple(vectors))

    def load_sides(self, link: int) -> list[tuple[str, complex, bool]]:
        """The known forces of a link's free body, in the order they were applied."""
        return [(f.label, _c(f.force), True) for f in self.bodies[link]
                if not (f.force[0] == 0.0 and f.force[1] == 0.0 and f.couple)]

    def result(self, reactions: tuple[Reaction, Reaction, Reaction],
               polygons: tuple[ForcePolygon, ...]) -> GroupForces:
        bodies = {lid: self.bodies[lid] for lid in (self.L1, self.L2)}
        for r in reactions:
            for lid, rr in ((r.on, r), (r.by, r.reversed())):
                if lid in bodies:
                    bodies[lid] = bodies[lid] + (rr.applied(),)
        return GroupForces(self.group.name, self.group.kind or "", (self.L1, self.L2), reactions,
                           polygons, bodies, tuple(self.steps))

    def solve(self) -> GroupForces:  # pragma: no cover - abstract
        raise NotImplementedError


class RRR(_GroupSolver):
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
        reactions = (
            Reaction(K1, L1, self.outer1.name, "R", xy(R1), xy(A), 0.0,
                     (ReactionComponent(f"{r1}^n", xy(n1), Rn1),
                      ReactionComponent(f"{r1}^t", xy(t1), Rt1))),
            Reaction(K2, L2, self.outer2.name, "R", xy(R2), xy(C), 0.0,
                     (ReactionComponent(f"{r2}^n", xy(n2), Rn2),
                      ReactionComponent(f"{r2}^t", xy(t2), Rt2))),
            Reaction(L2, L1, self.inner.name, "R", xy(R_inner), xy(B)))
        group = self.polygon(f"group {self.group.name}", [
            (f"{r1}^n", Rn1 * n1, False), (f"{r1}^t", Rt1 * t1, True),
            *self.load_sides(L1), *self.load_sides(L2),
            (f"{r2}^t", Rt2 * t2, True), (f"{r2}^n", Rn2 * n2, False)])
        link = self.polygon(f"link {L1}", [
            (f"{r1}^n", Rn1 * n1, True), (f"{r1}^t", Rt1 * t1, True),
            *self.load_sides(L1), (ri, R_inner, False)])
        return self.result(reactions, (group, link))


class RRP(_GroupSolver):
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
        self.steps.append(f"group polygon: {r1}^n = {fmt(Rn1)} N, {r2} = {fmt(N2)} N "
                          f"(normal to the guide)")
        R1 = Rn1 * n1 + Rt1 * t1
        R_inner = -(R1 + F1)
        ri = reaction_name(L2, L1)
        self.steps.append(f"link {L1} polygon: {ri} = {fmt(abs(R_inner))} N")
        # ΣM_B(L2) = 0: R_{L1 L2} passes through B, so M_B(R_{K2 L2}) = −M_B(loads of L2)
        R2 = self.prismatic_reaction(self.outer2, K2, L2, N2, B, -self.M(L2, B),
                                     f"Sum M_{b}(link {L2}) = 0")
        reactions = (
            Reaction(K1, L1, self.outer1.name, "R", xy(R1), xy(A), 0.0,
                     (ReactionComponent(f"{r1}^n", xy(n1), Rn1),
                      ReactionComponent(f"{r1}^t", xy(t1), Rt1))),
            R2,
            Reaction(L2, L1, self.inner.name, "R", xy(R_inner), xy(B)))
        group = self.polygon(f"group {self.group.name}", [
            (f"{r1}^n", Rn1 * n1, False), (f"{r1}^t", Rt1 * t1, True),
            *self.load_sides(L1), *self.load_sides(L2), (r2, N2 * nn2, False)])
        link = self.polygon(f"link {L1}", [
            (f"{r1}^n", Rn1 * n1, True), (f"{r1}^t", Rt1 * t1, True),
            *self.load_sides(L1), (ri, R_inner, False)])
        return self.result(reactions, (group, link))


class PRP(_GroupSolver):
    def solve(self) -> GroupForces:
        L1, L2, K1, K2 = self.L1, self.L2, self.K1, self.K2
        b = self.inner.point
        B = self.pin(self.inner)
        u1, _ = self.state.guide(self.outer1)
        u2, _ = self.state.guide(self.outer2)
        nn1, nn2 = 1j * u1, 1j * u2
        F1, F2 = self.F(L1), self.F(L2)
        r1, r2 = reaction_name(K1, L1), reaction_name(K2, L2)
        N1, N2 = self.solve2(nn1, nn2, -(F1 + F2), f"{r1} and {r2}")
        self.steps.append(f"group polygon: {r1} = {fmt(N1)} N, {r2} = {fmt(N2)} N "
                          f"(normal to their guides)")
        R_inner = -(N1 * nn1 + F1)
        ri = reaction_name(L2, L1)
        self.steps.append(f"link {L1} polygon: {ri} = {fmt(abs(R_inner))} N")
        R1 = self.prismatic_reaction(self.outer1, K1, L1, N1, B, -self.M(L1, B),
                                     f"Sum M_{b}(link {L1}) = 0")
        R2 = self.prismatic_reaction(self.outer2, K2, L2, N2, B, -self.M(L2, B),
                                     f"Sum M_{b}(link {L2}) = 0")
        reactions = (R1, R2, Reaction(L2, L1, self.inner.name, "R", xy(R_inner), xy(B)))
        group = self.polygon(f"group {self.group.name}", [
            (r1, N1 * nn1, False), *self.load_sides(L1), *self.load_sides(L2),
            (r2, N2 * nn2, False)])
        link = self.polygon(f"link {L1}", [
            (r1, N1 * nn1, True), *self.load_sides(L1), (ri, R_inner, False)])
        return self.result(reactions, (group, link))


class RPR(_GroupSolver):
    def solve(self) -> GroupForces:
        L1, L2, K1, K2 = self.L1, self.L2, self.K1, self.K2
        a, c = self.outer1.point, self.outer2.point
        P1, P2 = self.pin(self.outer1), self.pin(self.outer2)
        u, _ = self.state.guide(self.inner)
        nn = 1j * u
        ri = reaction_name(L1, L2)
        # ΣM_a(L1) = 0 puts R_{L1 L2} on the line whose moment about P1 is M1;
        # ΣM_c(L2) = M_c(loads of L2) + M1 + (P1 − P2) × N·nn = 0 gives N
        M1 = self.M(L1, P1)
        M2 = self.M(L2, P2)
        arm = cross(P1 - P2, nn)
        if abs(arm) <= SINGULAR_SIN * abs(P1 - P2) or P1 == P2:
            raise ForceError(f"{ri} has no arm about {c}: the slot is perpendicular to {a}{c} "
                             "(a dead position)", "choose another force position",
                             phi1_deg=self.state.phi1_deg, group=self.group.name)
        N = -(M2 + M1) / arm
        self.steps.append(f"Sum M_{c}(link {L2}) = 0: {fmt(M2)} + {fmt(M1)} + {ri} * "
                          f"{fmt(arm)} = 0 -> {ri} = {fmt(N)} N (normal to the slot)")
        R_in = self.prismatic_reaction(self.inner, L1, L2, N, P1, M1, f"Sum M_{a}(link {L1}) = 0")
        F1, F2 = self.F(L1), self.F(L2)
        R1 = -(F1 - N * nn)  # link L1: loads + R_{L2 L1} + R_{K1 L1} = 0
        R2 = -(F2 + N * nn)  # link L2: loads + R_{L1 L2} + R_{K2 L2} = 0
        r1, r2 = reaction_name(K1, L1), reaction_name(K2, L2)
        self.steps.append(f"link {L2} polygon: {r2} = {fmt(abs(R2))} N; "
                          f"link {L1} polygon: {r1} = {fmt(abs(R1))} N")
        reactions = (Reaction(K1, L1, self.outer1.name, "R", xy(R1), xy(P1)),
                     Reaction(K2, L2, self.outer2.name, "R", xy(R2), xy(P2)), R_in)
        link2 = self.polygon(f"link {L2}", [
            *self.load_sides(L2), (ri, N * nn, True), (r2, R2, False)])
        link1 = self.polygon(f"link {L1}", [
            *self.load_sides(L1), (reaction_name(L2, L1), -N * nn, True), (r1, R1, False)])
        return self.result(reactions, (link2, link1))


class RPP(_GroupSolver):
    def solve(self) -> GroupForces:
        L1, L2, K1, K2 = self.L1, self.L2, self.K1, self.K2
        a = self.outer1.point
        A = self.pin(self.outer1)
        u_in, _ = self.state.guide(self.inner)
        u2, _ = self.state.guide(self.outer2)
        nn_in, nn2 = 1j * u_in, 1j * u2
        F1, F2 = self.F(L1), self.F(L2)
        ri, r2, r1 = reaction_name(L1, L2), reaction_name(K2, L2), reaction_name(K1, L1)
        N_in, N2 = self.solve2(nn_in, nn2, -F2, f"{ri} and {r2}")
        self.steps.append(f"link {L2} polygon: {ri} = {fmt(N_in)} N, {r2} = {fmt(N2)} N "
                          f"(normal to their guides)")
        R1 = -(F1 - N_in * nn_in)  # link L1: loads + R_{L2 L1} + R_{K1 L1} = 0
        self.steps.append(f"link {L1} polygon: {r1} = {fmt(abs(R1))} N")
        M1 = self.M(L1, A)
        R_in = self.prismatic_reaction(self.inner, L1, L2, N_in, A, M1, f"Sum M_{a}(link {L1}) = 0")
        R2 = self.prismatic_reaction(self.outer2, K2, L2, N2, A, -self.M(L2, A) - M1,
                                     f"Sum M_{a}(link {L2}) = 0")
        reactions = (Reaction(K1, L1, self.outer1.name, "R", xy(R1), xy(A)), R2, R_in)
        link2 = self.polygon(f"link {L2}", [
            (ri, N_in * nn_in, False), *self.load_sides(L2), (r2, N2 * nn2, False)])
        link1 = self.polygon(f"link {L1}", [
            *self.load_sides(L1), (reaction_name(L2, L1), -N_in * nn_in, True), (r1, R1, False)])
        return self.result(reactions, (link2, link1))


_KINDS: dict[str, type[_GroupSolver]] = {"RRR": RRR, "RRP": RRP, "RPR": RPR, "PRP": PRP, "RPP": RPP}


# --- the driving link ---------------------------------------------------------------------

def _driving_link(state: PositionState, loads: Loads, passed: tuple[AppliedForce, ...]
                  ) -> DrivingLinkForces:
    """ΣM_O = 0: M_O(G1, F_IN1, M_IN1, R21, …) + F_bal·OA·s = 0, F_bal along
    s·i·(A − O)/OA (s = +1 for a counter-clockwise crank): positive drives."""
    mech = state.mech
    d = mech.drive.link
    o, a = mech.crank_pivot, mech.crank_pin
    O, A = state.point(d, o), state.point(d, a)
    OA = abs(A - O)
    s = 1.0 if mech.drive.sense == "ccw" else -1.0
    t = s * 1j * (A - O) / OA
    body = loads.on_link(d) + passed
    M_O = sum((cross(_c(f.point) - O, _c(f.force)) + f.couple for f in body), 0.0)
    F_bal = -M_O / (s * OA)
    steps = [f"Sum M_{o}(link {d}) = 0: {fmt(M_O)} + F_bal * {o}{a} = 0 (positive in the sense "
             f"of rotation) -> F_bal = {fmt(F_bal)} N, M_bal = F_bal * {o}{a} = {fmt(F_bal * OA)} N*m"]
    F = sum((_c(f.force) for f in body), 0j)
    R01 = -(F + F_bal * t)
    pair = next(p for p in mech.revolutes if p.point == o and set(p.links) == {FRAME, d})
    reaction = Reaction(FRAME, d, pair.name, "R", xy(R01), xy(O))
    name = reaction.name
    steps.append(f"link {d} polygon: {name} = {fmt(abs(R01))} N")
    sides: list[tuple[str, complex, bool]] = [
        (f.label, _c(f.force), True) for f in body
        if not (f.force[0] == 0.0 and f.force[1] == 0.0 and f.couple)]
    sides += [("F_bal", F_bal * t, True), (name, R01, False)]
    vectors, start = [], 0j
    for label, vec, known in sides:
        vectors.append(PolygonVector(label, xy(vec), xy(start), known))
        start += vec
    polygon = ForcePolygon(f"link {d}", " + ".join(s_[0] for s_ in sides) + " = 0",
                           tuple(vectors))
    free = body + (AppliedForce("F_bal", xy(F_bal * t), xy(A)), reaction.applied())
    return DrivingLinkForces(d, o, a, F_bal, xy(F_bal * t), F_bal * OA, reaction, polygon, free,
                             tuple(steps))


# --- helpers ----------------------------------------------------------------------------

def _c(v: np.ndarray) -> complex:
    return complex(v[0], v[1])


def _swap_label(label: str, by: int, on: int) -> str:
    old, new = reaction_name(by, on), reaction_name(on, by)
    return new + label[len(old):] if label.startswith(old) else label


def fmt(x: float) -> str:
    return f"{x + 0.0:.6g}"  # + 0.0: no "-0"


def with_reactions(groups: tuple[GroupForces, ...], driver: DrivingLinkForces
                   ) -> dict[str, Reaction]:
    """Each pair's reaction once, in the order found: the groups' outer and
    inner reactions, then R01."""
    out: dict[str, Reaction] = {}
    for g in groups:
        for r in g.reactions:
            key = r.name if r.name not in out else f"{r.name}@{r.pair}"
            out[key] = r
    r = driver.reaction
    out[r.name if r.name not in out else f"{r.name}@{r.pair}"] = r
    return out


__all__ = ["Reaction", "ReactionComponent", "PolygonVector", "ForcePolygon", "GroupForces",
           "DrivingLinkForces", "solve_groups", "reaction_name", "with_reactions"]
