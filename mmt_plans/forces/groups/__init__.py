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

from ...model import FRAME
from ..errors import ForceError
from ..loads import AppliedForce, Loads
from ..state import PositionState, cross, xy
from .base import (
    DrivingLinkForces,
    ForcePolygon,
    GroupForces,
    GroupSolver,
    PolygonVector,
    Reaction,
    ReactionComponent,
    _c,
    _load_sides,
    fmt,
    head_to_tail,
    reaction_name,
)
from .prp import PRP
from .rpp import RPP
from .rpr import RPR
from .rrp import RRP
from .rrr import RRR

__all__ = [
    "GROUPS",
    "GroupSolver",
    "Reaction",
    "ReactionComponent",
    "PolygonVector",
    "ForcePolygon",
    "GroupForces",
    "DrivingLinkForces",
    "solve_groups",
    "reaction_name",
    "with_reactions",
]

GROUPS: dict[str, type[GroupSolver]] = {"RRR": RRR, "RRP": RRP, "RPR": RPR, "PRP": PRP, "RPP": RPP}


def solve_groups(
    loads: Loads, *, balancing_in_r0d: bool = True
) -> tuple[tuple[GroupForces, ...], DrivingLinkForces]:
    """Every group, last attached first, then the driving link.
    `balancing_in_r0d` False closes the driving link's polygon without F_bal
    (a mistake recomputed for the student check)."""
    state = loads.state
    mech = state.mech
    passed: dict[int, list[AppliedForce]] = {}
    results = []
    for group in reversed(state.groups):
        if not group.is_dyad or group.kind not in GROUPS:
            raise ForceError(
                f"group {group.label} of links {group.name} is not a class II group",
                "only dyads have force plans here",
                phi1_deg=state.phi1_deg,
                group=group.name,
            )
        L1, L2 = group.links
        bodies = {lid: loads.on_link(lid) + tuple(passed.get(lid, ())) for lid in (L1, L2)}
        solver = GROUPS[group.kind](state, group, bodies)
        result = solver.solve()
        results.append(result)
        for r in result.reactions[:2]:  # the outer reactions act on the links before
            if r.by != FRAME:
                passed.setdefault(r.by, []).append(r.reversed().applied())
    driver = _driving_link(state, loads, tuple(passed.get(mech.drive.link, ())), balancing_in_r0d)
    return tuple(results), driver


# --- the driving link ---------------------------------------------------------------------


def _driving_link(
    state: PositionState,
    loads: Loads,
    passed: tuple[AppliedForce, ...],
    balancing_in_r0d: bool = True,
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
    steps = [
        f"Sum M_{o}(link {d}) = 0: {fmt(M_O)} + F_bal * {o}{a} = 0 (positive in the sense "
        f"of rotation) -> F_bal = {fmt(F_bal)} N, M_bal = F_bal * {o}{a} = {fmt(F_bal * OA)} N*m"
    ]
    F = sum((_c(f.force) for f in body), 0j)
    R01 = -(F + F_bal * t) if balancing_in_r0d else -F
    pair = next(p for p in mech.revolutes if p.point == o and set(p.links) == {FRAME, d})
    reaction = Reaction(FRAME, d, pair.name, "R", xy(R01), xy(O))
    name = reaction.name
    steps.append(f"link {d} polygon: {name} = {fmt(abs(R01))} N")
    sides = _load_sides(body)
    sides += [("F_bal", F_bal * t, True), (name, R01, False)]
    polygon = ForcePolygon(
        f"link {d}", " + ".join(s_[0] for s_ in sides) + " = 0", head_to_tail(sides)
    )
    free = body + (AppliedForce("F_bal", xy(F_bal * t), xy(A)), reaction.applied())
    return DrivingLinkForces(
        d, o, a, F_bal, xy(F_bal * t), F_bal * OA, reaction, polygon, free, tuple(steps)
    )


def with_reactions(
    groups: tuple[GroupForces, ...], driver: DrivingLinkForces
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
