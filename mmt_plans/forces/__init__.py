"""Force (kinetostatic) analysis of sheet 2 (seed 003 §2.1–2.10).

    >>> import mmt_plans
    >>> from mmt_plans.forces import force_analysis
    >>> a = mmt_plans.load("samples/six_link_press.toml").analyze()
    >>> fa = force_analysis(a)              # at the analysis' force position
    >>> round(fa.discrepancy_percent, 9)
    0.0

`loads` (weights, inertia forces and moments, the production resistance),
`groups` (force plans group by group, last group first, then the driving
link), `lever` (Zhukovsky's lever), `reduction` (reduced moment and reduced
moment of inertia at every position).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any, Mapping

import numpy as np

from ..model import Stroke
from .errors import ForceError
from .groups import (DrivingLinkForces, ForcePolygon, GroupForces, PolygonVector, Reaction,
                     ReactionComponent, reaction_name, solve_groups, with_reactions)
from .lever import LeverForce, ZhukovskyLever, zhukovsky_lever
from .loads import (AppliedForce, ExternalForce, LinkLoads, Loads, ShiftedInertiaForce, link_loads,
                    loads_at)
from .reduction import Reduction, reduction
from .state import PositionState, state_at

if TYPE_CHECKING:  # pragma: no cover
    from ..analysis import Analysis

__all__ = [
    "force_analysis", "ForceAnalysis", "text", "ForceError",
    "loads_at", "Loads", "LinkLoads", "ExternalForce", "ShiftedInertiaForce", "AppliedForce",
    "Reaction", "ReactionComponent", "ForcePolygon", "PolygonVector", "GroupForces",
    "DrivingLinkForces", "reaction_name", "ZhukovskyLever", "LeverForce", "Reduction",
    "reduction", "PositionState", "state_at",
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
    analysis: "Analysis | None" = field(default=None, repr=False, compare=False)

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

    def reduction(self) -> Reduction | None:
        """Reduced moment and moment of inertia at the analysis' positions."""
        return None if self.analysis is None else reduction(self.analysis)

    def to_json(self, *, with_reduction: bool = True) -> dict[str, Any]:
        """SPEC_FORMAT's `forces` object, plus loads, details and the reduction."""
        out: dict[str, Any] = {
            "index": self.index,
            "phi1_deg": self.phi1_deg,
            "balancing_force_plans": _f(self.balancing_force_plans),
            "balancing_force_lever": _f(self.balancing_force_lever),
            "discrepancy_percent": _f(self.discrepancy_percent),
            "balancing_moment": _f(self.balancing_moment),
            "reactions": {name: _pair(r.force) for name, r in self.reactions.items()},
            # --- additions to the contract -------------------------------------------------
            "stroke": self.stroke,
            "balancing_force_vector": _pair(self.driving_link.balancing_vector),
            "balancing_force_lever_couples": _f(self.lever.balancing_force_couples),
            "reaction_details": {
                name: {"by": r.by, "on": r.on, "pair": r.pair, "kind": r.kind,
                       "magnitude": r.magnitude, "point": _pair(r.point), "couple": _f(r.couple),
                       "components": {c.label: _f(c.value) for c in r.components}}
                for name, r in self.reactions.items()},
            "loads": {
                str(lid): {
                    "mass": ll.mass, "J": ll.J, "S": _pair(ll.centre_of_mass),
                    "a_S": _pair(ll.acceleration_cm), "eps": _f(ll.eps),
                    "G": _pair(ll.weight), "F_in": _pair(ll.inertia_force),
                    "M_in": _f(ll.inertia_moment),
                    "h": None if ll.shifted_inertia_force is None
                    else _f(ll.shifted_inertia_force.arm),
                    "h_mm": None if ll.shifted_inertia_force is None
                    or ll.shifted_inertia_force.arm_mm is None
                    else _f(ll.shifted_inertia_force.arm_mm),
                    "K": None if ll.shifted_inertia_force is None
                    else _pair(ll.shifted_inertia_force.point)}
                for lid, ll in self.loads.links.items()},
            "external_forces": {
                f.name: {"link": f.link, "at": f.at, "point": _pair(f.point),
                         "force": _pair(f.force), "acting": f.acting, "rule": f.rule}
                for f in self.loads.production_resistance},
        }
        if with_reduction and self.analysis is not None:
            red = self.reduction()
            if red is not None:
                out["reduction"] = red.to_json()
        return out


def force_analysis(analysis: "Analysis", index: int | None = None, *,
                   phi1_deg: float | None = None, mu_l: float | None = None) -> ForceAnalysis:
    """The force analysis at position `index` (default: the analysis' force
    position), or at any crank angle `phi1_deg`. `mu_l` (m/mm) gives the
    shifted inertia forces' arms in mm of the drawing as well."""
    if phi1_deg is not None:
        if index is not None:
            raise ForceError("give a position index or a crank angle, not both",
                             "call force_analysis(analysis, index) or (analysis, phi1_deg=...)")
        state = state_at(analysis, phi1_deg=phi1_deg)
    else:
        if index is None:
            index = analysis.force_position
        if isinstance(index, bool) or not isinstance(index, (int, np.integer)):
            raise ForceError(f"the position index {index!r} is not a whole number",
                             "give a position index, e.g. 2")
        try:
            entry = analysis.entry(int(index))
        except StopIteration:
            n = analysis.mech.study.positions
            raise ForceError(f"position {index} does not exist",
                             f"use a position 0..{n - 1}") from None
        state = state_at(analysis, entry)
    return force_analysis_at(state, mu_l=mu_l, analysis=analysis)


def force_analysis_at(state: PositionState, *, mu_l: float | None = None,
                      analysis: "Analysis | None" = None) -> ForceAnalysis:
    loads = link_loads(state, mu_l)
    groups, driver = solve_groups(loads)
    lever = zhukovsky_lever(loads)
    return ForceAnalysis(state.index, state.phi1_deg, state.stroke, loads, groups, driver,
                         with_reactions(groups, driver), lever, analysis)


# --- text tables ------------------------------------------------------------------------

def text(fa: ForceAnalysis) -> str:
    """Readable tables: loads, reactions per pair, the balancing force by both
    methods and the discrepancy (what `mmt-plans analyze` prints)."""
    head = (f"Force analysis at position {fa.index}" if fa.index is not None
            else "Force analysis")
    out = [f"{head}: phi1 = {fa.phi1_deg:.6f} deg, {fa.stroke} stroke"]
    rows = []
    for lid, ll in fa.loads.links.items():
        F = ll.inertia_force
        sh = ll.shifted_inertia_force
        rows.append([str(lid), _n(ll.mass), _n(ll.J), _n(-ll.weight[1]), _n(F[0]), _n(F[1]),
                     _n(math.hypot(*F)), _n(ll.inertia_moment),
                     "-" if sh is None else _n(sh.arm * 1e3),
                     "-" if sh is None or sh.arm_mm is None else _n(sh.arm_mm)])
    out.append(_indent(_table(["link", "m kg", "J kg*m2", "G N", "F_in x N", "F_in y N",
                               "|F_in| N", "M_in N*m", "h mm", "h drawn mm"], rows)))
    if fa.loads.production_resistance:
        rows = [[f.name, str(f.link), f.at, _n(f.force[0]), _n(f.force[1]),
                 _n(math.hypot(*f.force)), "yes" if f.acting else "no (idle stroke)"]
                for f in fa.loads.production_resistance]
        out.append(_indent(_table(["force", "link", "at", "Fx N", "Fy N", "|F| N", "acts"], rows)))
    for g in fa.groups:
        out.append(f"  group {g.name} ({g.kind}):")
        out += [f"    {s}" for s in g.steps]
    out.append(f"  driving link {fa.driving_link.link}:")
    out += [f"    {s}" for s in fa.driving_link.steps]
    rows = []
    for name, r in fa.reactions.items():
        rows.append([name, r.pair, _n(r.force[0]), _n(r.force[1]), _n(r.magnitude),
                     _n(r.point[0] * 1e3), _n(r.point[1] * 1e3),
                     _n(r.couple) if r.couple else "-"])
    out.append(_indent(_table(["reaction", "pair", "Rx N", "Ry N", "|R| N", "at x mm", "at y mm",
                               "couple N*m"], rows)))
    d = fa.discrepancy_percent
    out.append(f"  balancing force: plans F_bal = {fa.balancing_force_plans:.6g} N, "
               f"Zhukovsky's lever F_bal = {fa.balancing_force_lever:.6g} N, "
               f"discrepancy = {'-' if math.isnan(d) else f'{d:.3g}'} % "
               f"({'driving' if fa.balancing_force_plans >= 0 else 'braking'})")
    out.append(f"  balancing moment M_bal = {fa.balancing_moment:.6g} N*m")
    return "\n".join(out)


def _n(x: float, digits: int = 6) -> str:
    return f"{float(x) + 0.0:.{digits}g}"  # + 0.0: no "-0"


def _table(headers: list[str], rows: list[list[str]]) -> str:
    widths = [max(len(h), *(len(r[i]) for r in rows)) if rows else len(h)
              for i, h in enumerate(headers)]
    lines = ["  ".join(h.rjust(w) for h, w in zip(headers, widths)),
             "  ".join("-" * w for w in widths)]
    lines += ["  ".join(c.rjust(w) for c, w in zip(r, widths)) for r in rows]
    return "\n".join(lines)


def _indent(s: str) -> str:
    return "\n".join("  " + line for line in s.splitlines())


def _f(x: float) -> float | None:
    x = float(x)
    return x if math.isfinite(x) else None


def _pair(v: np.ndarray) -> list[float]:
    return [float(v[0]) + 0.0, float(v[1]) + 0.0]  # + 0.0: no -0.0

