"""The results JSON of ../shared/SPEC_FORMAT.md, written from a `Solution`.

Everything in SI units; vectors as [x, y]; no NaN or infinity: a quantity
that does not exist (a position that does not assemble) is written as its
`problem` instead. Additions to the contract are marked below.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from .diagrams import GRID_REFINEMENTS
from .errors import AssemblyError
from .forces import ForceAnalysis
from .forces.reduction import Reduction
from .model import Mechanism
from .solution import Solution

__all__ = ["SCHEMA", "results", "forces_json", "diagrams_json", "reduction_json"]

SCHEMA = "mmt_plans/results@1"


def results(solution: Solution, *, diagrams: bool = True) -> dict[str, Any]:
    """The whole results object (`mmt-plans analyze --json`)."""
    sw = solution.sweep
    mech = solution.mechanism
    cms = _cm_names(mech)
    point_names = [n for n in solution.chain.locate if n not in cms]
    positions: list[dict[str, Any]] = []
    kinematics: list[dict[str, Any]] = []
    for k, pos in enumerate(solution.positions):
        head: dict[str, Any] = {"index": pos.index, "phi1_deg": pos.phi1_deg}
        problem = solution.problem(k)
        if isinstance(problem, AssemblyError):
            positions.append({**head, "stroke": pos.stroke, "problem": str(problem)})
            kinematics.append({**head, "problem": str(problem)})
            continue
        positions.append(
            {
                **head,
                "stroke": pos.stroke,
                "points": {n: _pair(sw.points[n][k]) for n in point_names},
            }
        )
        if problem is not None:
            kinematics.append({**head, "problem": str(problem)})
            continue
        kinematics.append(
            {
                **head,
                "v": {n: _pair(sw.v[n][k]) for n in point_names},
                "a": {n: _pair(sw.a[n][k]) for n in point_names},
                "v_cm": {str(lk.id): _pair(sw.v[lk.cm_name][k]) for lk in mech.links.values()},
                "a_cm": {str(lk.id): _pair(sw.a[lk.cm_name][k]) for lk in mech.links.values()},
                "omega": {str(lid): float(sw.omega[lid][k]) for lid in mech.links},
                "eps": {str(lid): float(sw.eps[lid][k]) for lid in mech.links},
            }
        )
    drive = mech.drive
    ext = solution.extremes
    return {
        "schema": SCHEMA,
        "title": mech.title,
        "structure": solution.structure.as_dict(),
        "drive": {
            "link": drive.link,
            "omega": drive.signed_omega,
            "sense": drive.sense,
            "gear_ratio": None if drive.gear_train is None else drive.gear_train.ratio,
            "n1_rpm": drive.n1_rpm,
        },
        # --- additions to the contract ------------------------------------------------------
        "branches": solution.branches.to_json(),
        "extremes_deg": None if ext is None else {"working_start": ext[0], "working_end": ext[1]},
        "limits_of_assembly_deg": None if solution.limits is None else list(solution.limits),
        "plans": list(solution.plan_positions),
        # ------------------------------------------------------------------------------------
        "positions": positions,
        "kinematics": kinematics,
        **({"diagrams": diagrams_json(solution)} if diagrams else {}),
        "forces": forces_json(solution),
    }


def diagrams_json(solution: Solution) -> dict[str, Any]:
    output = solution.mechanism.study.output
    if solution.diagrams is None:
        return {"output": output, "problem": solution.diagrams_problem}
    dg = solution.diagrams
    construction, check, sc = dg.construction, dg.check, dg.sheet_check
    n = solution.mechanism.study.positions
    return {
        "output": output,
        "phi1_deg": [solution.positions[i].phi1_deg for i in range(n)],
        "s": [float(x) for x in dg.at_position(construction.s)],
        "v_diagram": [float(x) for x in dg.at_position(construction.v)],
        "a_diagram": [float(x) for x in dg.at_position(construction.a)],
        "v_plan": [float(x) for x in dg.v_plan],
        "a_plan": [float(x) for x in dg.a_plan],
        "error_percent": {"v": list(check.v_error_percent), "a": list(check.a_error_percent)},
        "scales": {
            "mu_S": construction.mu_S,
            "mu_t": construction.mu_t,
            "mu_V": construction.mu_V,
            "mu_a": construction.mu_a,
            "H1_mm": construction.H1,
            "H2_mm": construction.H2,
            "L_mm": construction.L,
            # series steps of μ_S above μ_l (0: μ_S = μ_l, as seed 003 §1.7 draws it)
            "mu_S_steps": dg.scales.mu_S_steps,
        },
        "limit_percent": sc.limit_percent,
        # seed 003 §1.8: the investigated positions, on the diagrams drawn
        "passed": sc.passed,
        "grid_intervals": sc.intervals,
        "investigated": [
            {
                "index": v.index,
                "quantity": v.quantity,
                "plan": v.plan,
                "diagram": v.diagram,
                "error_percent": v.error_percent,
                "absolute_error": v.absolute_error,
                "ill_conditioned": v.ill_conditioned,
                "passed": v.passed,
                # "formula": (12)/(13) as written; "absolute_error": under 5 % of
                # its largest magnitude and passed on no grid of the series
                "judged_by": v.judged_by,
                "plan_share_percent": v.plan_share_percent,
            }
            for v in sc.values
        ],
        # the series n·k tried in turn, coarsest first, up to the one drawn (or all)
        "grid_series": [n * k for k in GRID_REFINEMENTS],
        "grids_tried": [
            {
                "intervals": t.intervals,
                "passed": t.passed,
                "refinement": t.refinement,
                "errors": [
                    {
                        "index": i,
                        "quantity": q,
                        "error_percent": e if math.isfinite(e) else None,
                    }
                    for i, q, e in t.errors
                ],
            }
            for t in sc.trials
        ],
        "flags": [
            {
                "quantity": f.quantity,
                "index": f.index,
                "error_percent": f.error_percent,
                "kind": f.kind,
                "reason": f.reason,
            }
            for f in check.flags
        ],
    }


def forces_json(solution: Solution) -> dict[str, Any]:
    """SPEC_FORMAT's `forces` object at the force position (with `problem`
    instead when that position has no kinematics or no force plan)."""
    if solution.forces is None:
        k = solution.entry(solution.force_position)
        return {
            "index": solution.force_position,
            "phi1_deg": solution.positions[k].phi1_deg,
            "problem": solution.forces_problem,
        }
    out = force_analysis_json(solution.forces)
    out["reduction"] = reduction_json(solution.reduction)
    return out


def force_analysis_json(fa: ForceAnalysis) -> dict[str, Any]:
    """SPEC_FORMAT's `forces` object, plus loads and details (additions)."""
    return {
        "index": fa.index,
        "phi1_deg": fa.phi1_deg,
        "balancing_force_plans": _f(fa.balancing_force_plans),
        "balancing_force_lever": _f(fa.balancing_force_lever),
        "discrepancy_percent": _f(fa.discrepancy_percent),
        "balancing_moment": _f(fa.balancing_moment),
        "reactions": {name: _pair(r.force) for name, r in fa.reactions.items()},
        # --- additions to the contract -------------------------------------------------
        "stroke": fa.stroke,
        "balancing_force_vector": _pair(fa.driving_link.balancing_vector),
        "balancing_force_lever_couples": _f(fa.lever.balancing_force_couples),
        "reaction_details": {
            name: {
                "by": r.by,
                "on": r.on,
                "pair": r.pair,
                "kind": r.kind,
                "magnitude": r.magnitude,
                "point": _pair(r.point),
                "couple": _f(r.couple),
                "components": {c.label: _f(c.value) for c in r.components},
            }
            for name, r in fa.reactions.items()
        },
        "loads": {
            str(lid): {
                "mass": ll.mass,
                "J": ll.J,
                "S": _pair(ll.centre_of_mass),
                "a_S": _pair(ll.acceleration_cm),
                "eps": _f(ll.eps),
                "G": _pair(ll.weight),
                "F_in": _pair(ll.inertia_force),
                "M_in": _f(ll.inertia_moment),
                "h": None if ll.shifted_inertia_force is None else _f(ll.shifted_inertia_force.arm),
                "h_mm": None
                if ll.shifted_inertia_force is None or ll.shifted_inertia_force.arm_mm is None
                else _f(ll.shifted_inertia_force.arm_mm),
                "K": None
                if ll.shifted_inertia_force is None
                else _pair(ll.shifted_inertia_force.point),
            }
            for lid, ll in fa.loads.links.items()
        },
        "external_forces": {
            f.name: {
                "link": f.link,
                "at": f.at,
                "point": _pair(f.point),
                "force": _pair(f.force),
                "acting": f.acting,
                "at_rest": f.at_rest,
                "rule": f.rule,
            }
            for f in fa.loads.production_resistance
        },
    }


def reduction_json(red: Reduction) -> dict[str, Any]:
    return {
        "phi1_deg": _list(red.phi1_deg),
        "index": list(red.index),
        "stroke": list(red.stroke),
        "reduced_moment": _list(red.reduced_moment),
        "reduced_moment_of": {k: _list(v) for k, v in red.reduced_moment_of.items()},
        "reduced_inertia": _list(red.reduced_inertia),
    }


def _f(x: float) -> float | None:
    x = float(x)
    return x if math.isfinite(x) else None


def _pair(v: Any) -> list[float]:
    return [float(v[0]) + 0.0, float(v[1]) + 0.0]  # + 0.0: no -0.0


def _list(a: np.ndarray) -> list[float | None]:
    return [float(x) if np.isfinite(x) else None for x in a]


def _cm_names(mech: Mechanism) -> set[str]:
    return {lk.cm_name for lk in mech.links.values()} - set(mech.point_owners)
