"""Force (kinetostatic) analysis of sheet 2 (seed 003 §2.1–2.10).

    >>> import mmt_plans
    >>> fa = mmt_plans.solve(mmt_plans.load("samples/six_link_press.toml")).forces
    >>> round(fa.discrepancy_percent, 9)
    0.0

`loads` (weights, inertia forces and moments, the production resistance),
`groups` (force plans group by group, last group first, then the driving
link), `lever` (Zhukovsky's lever), `reduction` (reduced moment and reduced
moment of inertia at every position).
"""

from __future__ import annotations

import math
from collections.abc import Collection, Mapping
from dataclasses import dataclass

from ..model import Stroke
from .errors import ForceError
from .groups import (
    DrivingLinkForces,
    ForcePolygon,
    GroupForces,
    PolygonVector,
    Reaction,
    ReactionComponent,
    reaction_name,
    solve_groups,
    with_reactions,
)
from .lever import LeverForce, ZhukovskyLever, zhukovsky_lever
from .loads import AppliedForce, ExternalForce, LinkLoads, Loads, ShiftedInertiaForce, link_loads
from .reduction import Reduction
from .state import PositionState

__all__ = [
    "force_analysis_at",
    "ForceAnalysis",
    "ForceError",
    "Loads",
    "LinkLoads",
    "ExternalForce",
    "ShiftedInertiaForce",
    "AppliedForce",
    "Reaction",
    "ReactionComponent",
    "ForcePolygon",
    "PolygonVector",
    "GroupForces",
    "DrivingLinkForces",
    "reaction_name",
    "ZhukovskyLever",
    "LeverForce",
    "Reduction",
    "PositionState",
]


@dataclass(frozen=True)
class ForceAnalysis:
    """The force calculation at one position: loads, the groups' force plans,
    the driving link, Zhukovsky's lever and the comparison (21)."""

    index: int | None
    phi1_deg: float
    stroke: Stroke
    loads: Loads
    groups: tuple[GroupForces, ...]  # in the order solved: the last attached group first
    driving_link: DrivingLinkForces
    reactions: Mapping[str, Reaction]  # every pair once, R01 last
    lever: ZhukovskyLever

    @property
    def balancing_force_plans(self) -> float:
        """F_bal.pl, N, from ΣM_O of the driving link (positive: drives)."""
        return self.driving_link.balancing_force

    @property
    def balancing_force_lever(self) -> float:
        """F_bal.z, N, from Zhukovsky's lever."""
        return self.lever.balancing_force

    @property
    def balancing_moment(self) -> float:
        return self.driving_link.balancing_moment

    @property
    def discrepancy_percent(self) -> float:
        """Seed 003 (21): |F_bal.z − F_bal.pl| / |F_bal.z| · 100 (NaN when F_bal.z = 0)."""
        z, pl = self.balancing_force_lever, self.balancing_force_plans
        if z == 0.0:
            return 0.0 if pl == 0.0 else math.nan
        return abs(z - pl) / abs(z) * 100.0

    def reaction(self, by: int, on: int) -> Reaction:
        """R_ij, whichever way round the pair's reaction was found."""
        for r in self.reactions.values():
            if (r.by, r.on) == (by, on):
                return r
            if (r.by, r.on) == (on, by):
                return r.reversed()
        raise KeyError(f"no pair joins links {by} and {on}")

    def free_body(self, link: int) -> tuple[AppliedForce, ...]:
        """Every force on a link as the solution loads it: its loads, the
        reactions of its pairs (and F_bal on the driving link)."""
        if link == self.driving_link.link:
            return self.driving_link.free_body
        for g in self.groups:
            if link in g.free_bodies:
                return g.free_bodies[link]
        raise KeyError(f"link {link} is not a moving link")


def force_analysis_at(
    state: PositionState,
    *,
    mu_l: float | None = None,
    inertia_forces: Collection[int] | None = None,
    inertia_moments: Collection[int] | None = None,
    gravity: bool = True,
    balancing_in_r0d: bool = True,
    lever_turn_deg: float | None = None,
    inertia_moments_reversed: Collection[int] = (),
    weight_at: Mapping[int, str] | None = None,
) -> ForceAnalysis:
    """The force analysis at the position of `state`: loads, the groups' force
    plans from the last attached group, the driving link, Zhukovsky's lever.
    `mu_l` (m/mm) gives the shifted inertia forces' arms in mm of the drawing.

    The other keywords make one mistake on purpose, so that the student check
    can recompute it (defaults: the textbook's calculation): the links whose
    inertia forces / moments are kept (None: all), gravity, F_bal in the
    driving link's polygon (False: R0d without it), the lever's turn, the
    links whose M_IN is taken the wrong way (F_IN shifted to the wrong side
    of S), a point of a link where its G is applied in place of S."""
    loads = link_loads(
        state,
        mu_l,
        inertia_forces=inertia_forces,
        inertia_moments=inertia_moments,
        gravity=gravity,
        inertia_moments_reversed=inertia_moments_reversed,
        weight_at=weight_at,
    )
    groups, driver = solve_groups(loads, balancing_in_r0d=balancing_in_r0d)
    lever = zhukovsky_lever(loads, turn_deg=lever_turn_deg)
    return ForceAnalysis(
        state.index,
        state.phi1_deg,
        state.stroke,
        loads,
        groups,
        driver,
        with_reactions(groups, driver),
        lever,
    )
