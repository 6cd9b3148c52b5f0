"""The analysis a sheet needs, computed on demand: extreme positions and
strokes, the n positions, kinematics at every position, the plans at the
planned ones, and the results JSON of SPEC_FORMAT.md.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property
from typing import Any

import numpy as np

from .errors import AssemblyError, MmtError, StructureError, partial_turn_error
from .kinematics.chain import Sweep
from .kinematics.plans import PlanView, plan_view
from .model import Mechanism, Stroke

SCHEMA = "mmt_plans/results@1"
EXTREME_TOL_DEG = 1e-9
GRID = 1440


@dataclass(frozen=True)
class Position:
    index: int | None  # None for an extra angle of `study.angles`
    phi1_deg: float
    stroke: Stroke


class Analysis:
    """Everything `mmt-plans analyze` reports, each part computed when asked."""

    def __init__(self, mech: Mechanism) -> None:
        self.mech = mech

    @property
    def structure(self):
        return self.mech.structure

    @property
    def chain(self):
        return self.mech.chain

    # --- extreme positions and strokes ---------------------------------------------
    def _along(self, sweep: Sweep) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """s, ds/dφ and d²s/dφ² of the output along the working direction (ε1 = 0)."""
        w = self.mech.drive.signed_omega
        s, v, a = self.output_along(sweep)
        return s, v / w, a / (w * w)

    # --- the turn: whole, or the range where the mechanism assembles -----------------
    @cached_property
    def branches(self):
        """The assembly branches (kinematics/branches.py); a crank that cannot
        make a whole turn is refused unless the file opts in (partial_turn)."""
        choice = self.chain.choice
        if not choice.whole_turn and not self.mech.study.partial_turn:
            raise partial_turn_error(self.mech, choice)
        return choice

    @property
    def partial(self) -> bool:
        return not self.branches.whole_turn

    @property
    def assembly_ranges(self) -> tuple[tuple[float, float], ...]:
        """Crank-angle intervals (deg, counter-clockwise from start to end) where
        every group assembles; ((0, 360),) for a mechanism that turns fully."""
        return self.chain.choice.ranges

    @cached_property
    def limits(self) -> tuple[float, float] | None:
        """The limits of assembly of the range analysed (the longest), in the
        drive's sense: (first, last); None for a whole turn."""
        if not self.partial:
            return None
        lo, hi = max(self.assembly_ranges, key=lambda r: (r[1] - r[0]) % 360.0)
        return (lo, hi) if self.sense_sign > 0 else (hi, lo)

    @property
    def span_deg(self) -> float:
        """Crank angle the positions are spread over: 360, or the range analysed."""
        if self.limits is None:
            return 360.0
        a, b = self.limits
        return ((b - a) * self.sense_sign) % 360.0

    # --- extreme positions and strokes ---------------------------------------------
    def _along(self, sweep: Sweep) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """s, ds/dφ and d²s/dφ² of the output along the working direction (ε1 = 0)."""
        w = self.mech.drive.signed_omega
        s, v, a = self.output_along(sweep)
        return s, v / w, a / (w * w)

    @cached_property
    def extremes(self) -> tuple[float, float] | None:
        """Crank angles (deg) of the output's least and greatest position along
        the working direction: zeros of ds/dφ to machine precision (Newton with
        the exact d²s/dφ² of the acceleration plan, kept in a bracket where ds/dφ
        changes sign). In a partial turn only zeros inside the range count (the
        limits of assembly are not extreme positions); None when there are none."""
        if self.limits is None:
            grid = np.linspace(0.0, 360.0, GRID, endpoint=False)
        else:
            a = self.limits[0]
            grid = a + self.sense_sign * self.span_deg * (np.arange(1, GRID) / GRID)
        sw = self.chain.sweep(grid)
        s, ds, _ = self._along(sw)
        ok = sw.ok & np.isfinite(s) & np.isfinite(ds)
        if not ok.any():
            raise sw.problem(0) or StructureError("the mechanism assembles at no crank angle")
        if np.ptp(s[ok]) < 1e-12 * max(1.0, float(np.max(np.abs(s[ok])))):
            raise StructureError(
                f"{self.mech.path}: output {self.mech.study.output} does not move along the "
                "working direction: set study.working_direction or study.zero")
        # brackets [φ_i, φ_i+1] of the grid where ds/dφ changes sign
        nxt = np.roll(np.arange(grid.size), -1)
        if self.limits is not None:
            nxt[-1] = grid.size - 1
        change = ok & ok[nxt] & (np.sign(ds) != np.sign(ds[nxt])) & (nxt != np.arange(grid.size))
        idx = np.flatnonzero(change)
        if not idx.size:
            return None
        step = 360.0 / GRID if self.limits is None else self.span_deg / GRID
        lo_b = grid[idx]
        hi_b = lo_b + (step if self.limits is None else self.sense_sign * step)
        roots = self._root(np.minimum(lo_b, hi_b), np.maximum(lo_b, hi_b))
        s_roots, _, _ = self._along(self.chain.sweep(roots))
        return float(roots[int(np.argmin(s_roots))] % 360.0), float(roots[int(np.argmax(s_roots))] % 360.0)

    def _root(self, a: np.ndarray, b: np.ndarray) -> np.ndarray:
        """Zeros of ds/dφ in the brackets [a, b] (deg, ds/dφ changes sign in
        each): Newton's steps where they stay in the bracket, bisection where
        they would leave it (rtsafe), all brackets at once."""
        _, fa, _ = self._along(self.chain.sweep(a))
        a, b = a.astype(float).copy(), b.astype(float).copy()
        phi = 0.5 * (a + b)
        for _ in range(200):
            _, f, df = self._along(self.chain.sweep(phi))
            # keep the sign-change bracket
            same = np.sign(f) == np.sign(fa)
            a = np.where(same, phi, a)
            fa = np.where(same, f, fa)
            b = np.where(same, b, phi)
            with np.errstate(divide="ignore", invalid="ignore"):
                newton = phi - np.degrees(f / df)
            inside = np.isfinite(newton) & (newton > a) & (newton < b)
            new = np.where(inside, newton, 0.5 * (a + b))
            done = (f == 0) | (np.abs(new - phi) <= 4 * np.finfo(float).eps * np.maximum(1.0, np.abs(phi)))
            phi = np.where(f == 0, phi, new)
            if done.all():
                break
        return phi

    @property
    def sense_sign(self) -> int:
        return 1 if self.mech.drive.sense == "ccw" else -1

    @cached_property
    def working_span_deg(self) -> float:
        if self.extremes is None:
            return float("nan")
        lo, hi = self.extremes
        return ((hi - lo) * self.sense_sign) % 360.0

    def stroke_of(self, phi1_deg: float) -> Stroke:
        if self.limits is not None or self.extremes is None:
            # a partial turn: working where the output moves along the working direction
            _, ds, _ = self._along(self.chain.sweep(np.array([phi1_deg])))
            return "working" if float(ds[0]) * self.sense_sign > 0 else "idle"
        lo, _ = self.extremes
        ahead = ((phi1_deg - lo) * self.sense_sign) % 360.0
        if ahead <= self.working_span_deg + EXTREME_TOL_DEG or ahead >= 360.0 - EXTREME_TOL_DEG:
            return "working"
        return "idle"

    # --- positions ------------------------------------------------------------------
    @cached_property
    def phi0_deg(self) -> float:
        if self.limits is not None:  # half a step in from the first limit of assembly
            return (self.limits[0] + self.sense_sign * self.span_deg / (2 * self.mech.study.positions)) % 360.0
        zero = self.mech.study.zero
        if zero is None:
            if self.extremes is None:
                raise StructureError(
                    f"{self.mech.path}: output {self.mech.study.output} has no extreme position "
                    "along the working direction: set study.zero or study.working_direction")
            return self.extremes[0]
        return zero % 360.0

    @cached_property
    def positions(self) -> tuple[Position, ...]:
        self.branches  # refuse a partial turn before anything is computed
        n = self.mech.study.positions
        out = []
        for i in range(n):
            phi = (self.phi0_deg + self.sense_sign * self.span_deg * i / n) % 360.0
            out.append(Position(i, phi, self.stroke_of(phi)))
        for phi in self.mech.study.angles:
            out.append(Position(None, phi % 360.0, self.stroke_of(phi % 360.0)))
        return tuple(out)

    @cached_property
    def plan_positions(self) -> tuple[int, ...]:
        """`study.plans`, or the positions nearest the middle of the working
        and of the idle stroke (SPEC_FORMAT's default); in a partial turn the
        positions at a quarter and at three quarters of the range."""
        if self.mech.study.plans is not None:
            return self.mech.study.plans
        n = self.mech.study.positions
        if self.limits is not None or self.extremes is None:
            return (n // 4, (3 * n) // 4)
        lo, hi = self.extremes
        span = self.working_span_deg
        mids = [lo + self.sense_sign * span / 2, hi + self.sense_sign * (360.0 - span) / 2]
        picks = []
        for mid in mids:
            dist = [abs((p.phi1_deg - mid + 180.0) % 360.0 - 180.0)
                    for p in self.positions if p.index is not None]
            picks.append(int(np.argmin(dist)))
        return tuple(picks)

    @property
    def force_position(self) -> int:
        fp = self.mech.study.force_position
        return self.plan_positions[0] if fp is None else fp

    # --- kinematics -----------------------------------------------------------------
    @cached_property
    def sweep(self) -> Sweep:
        """Kinematics at every position and extra angle, in one vectorised pass."""
        return self.chain.sweep(np.array([p.phi1_deg for p in self.positions]))

    def problem(self, k: int) -> MmtError | None:
        """Why entry k of `positions` has no kinematics (None when it has)."""
        return self.sweep.problem(k)

    def entry(self, index: int) -> int:
        """Where position `index` sits in `positions`."""
        return next(k for k, p in enumerate(self.positions) if p.index == index)

    def plan(self, index: int) -> PlanView:
        """The velocity and acceleration plan at position `index`."""
        k = self.entry(index)
        problem = self.problem(k)
        if problem is not None:
            raise problem
        return plan_view(self.sweep, k, index)

    # --- S–V–a diagrams of the output (seed 003 §1.7–1.8) ------------------------------
    @cached_property
    def mu_l(self) -> float:
        """Scale of the mechanism drawing: the standard value that draws the
        span of every point's trajectory in 150–300 mm (μ_l = l_OA / OA, (2))."""
        from .scales import DrawnLength, scale_for

        grid = self.chain.sweep(np.linspace(0.0, 360.0, 72, endpoint=False))
        pts = np.concatenate([grid.position_of(n)[grid.ok] for n in self.mech.point_owners])
        span = max(np.ptp(pts.real), np.ptp(pts.imag), self.mech.crank_length)
        return scale_for(span, DrawnLength("mechanism", 150.0, 300.0, 220.0))

    def output_along(self, sweep: Sweep) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """s, V, a of the output along the working direction (SI, signed)."""
        wd = np.conj(complex(*self.mech.study.working_direction))
        out = self.mech.study.output
        return ((sweep.position_of(out) * wd).real, (sweep.velocity_of(out) * wd).real,
                (sweep.acceleration_of(out) * wd).real)

    def displacements(self, n: int) -> np.ndarray:
        """s of the output at n equal crank steps from position 0 (s = 0 there), m:
        the smooth S curve of the diagram, and the trials of the 5 % check."""
        phi = self.phi0_deg + self.sense_sign * 360.0 * np.arange(n) / n
        s, _, _ = self.output_along(self.chain.sweep(phi))
        return s - s[0]

    @cached_property
    def diagrams(self):
        """The graphical differentiation and its 5 % check against the plans."""
        from .diagrams import (DIAGRAM_HEIGHT_MM, TIME_AXIS, compare_with_plans,
                               graphical_differentiation)
        from .scales import scale_for, series

        if self.limits is not None:
            raise MmtError("no kinematic diagrams: the crank does not make a whole turn "
                           "(partial_turn), and the diagrams of 1.7 cover one turn")
        n = self.mech.study.positions
        k = [self.entry(i) for i in range(n)]
        if not self.sweep.ok[k].all():
            bad = next(i for i in range(n) if not self.sweep.ok[k[i]])
            raise self.problem(k[bad]) or MmtError("diagrams need every position")
        s, v, a = (x[k] for x in self.output_along(self.sweep))
        s = s - s[0]
        n1 = self.mech.drive.n1_rpm
        # the time axis: the standard μ_t that draws one turn in 150 … 240 mm
        T = 60.0 / n1
        L = T / scale_for(T, TIME_AXIS)
        # μ_S from μ_l up the series until no diagram is taller than the sheet
        # can hold: the heights of V and a grow with μ_t·OH/μ_S and μ_t²·OH1·OH2/μ_S
        for mu_S in series(self.mu_l * (1 - 1e-9), self.mu_l * 1e3):
            construction = graphical_differentiation(s, n1=n1, mu_S=mu_S, L=L)
            if max(construction.heights_mm) <= DIAGRAM_HEIGHT_MM:
                break
        check = compare_with_plans(construction.v, construction.a, v, a, n1=n1, s=s,
                                   s_of_n=self.displacements)
        return construction, check, v, a

    def diagrams_json(self) -> dict[str, Any]:
        try:
            construction, check, v, a = self.diagrams
        except MmtError as err:
            return {"output": self.mech.study.output, "problem": str(err)}
        n = self.mech.study.positions
        return {
            "output": self.mech.study.output,
            "phi1_deg": [self.positions[i].phi1_deg for i in range(n)],
            "s": [float(x) for x in construction.s],
            "v_diagram": [float(x) for x in construction.v],
            "a_diagram": [float(x) for x in construction.a],
            "v_plan": [float(x) for x in v],
            "a_plan": [float(x) for x in a],
            "error_percent": {"v": list(check.v_error_percent), "a": list(check.a_error_percent)},
            "scales": {"mu_S": construction.mu_S, "mu_t": construction.mu_t,
                       "mu_V": construction.mu_V, "mu_a": construction.mu_a,
                       "H1_mm": construction.H1, "H2_mm": construction.H2, "L_mm": construction.L},
            "limit_percent": check.limit_percent,
            "passed": check.passed,
            "flags": [{"quantity": f.quantity, "index": f.index, "error_percent": f.error_percent,
                       "kind": f.kind, "reason": f.reason} for f in check.flags],
            "positions_needed": check.positions_needed,
        }

    # --- results JSON ---------------------------------------------------------------
    def to_json(self, diagrams: bool = True) -> dict[str, Any]:
        sw = self.sweep
        mech = self.mech
        cms = _cm_names(mech)
        point_names = [n for n in self.chain.locate if n not in cms]
        positions, kinematics = [], []
        for k, pos in enumerate(self.positions):
            head = {"index": pos.index, "phi1_deg": pos.phi1_deg}
            problem = self.problem(k)
            if isinstance(problem, AssemblyError):
                positions.append({**head, "stroke": pos.stroke, "problem": str(problem)})
                kinematics.append({**head, "problem": str(problem)})
                continue
            positions.append({**head, "stroke": pos.stroke,
                              "points": {n: _pair(sw.points[n][k]) for n in point_names}})
            if problem is not None:
                kinematics.append({**head, "problem": str(problem)})
                continue
            kinematics.append({
                **head,
                "v": {n: _pair(sw.v[n][k]) for n in point_names},
                "a": {n: _pair(sw.a[n][k]) for n in point_names},
                "v_cm": {str(l.id): _pair(sw.v[l.cm_name][k]) for l in mech.links.values()},
                "a_cm": {str(l.id): _pair(sw.a[l.cm_name][k]) for l in mech.links.values()},
                "omega": {str(lid): float(sw.omega[lid][k]) for lid in mech.links},
                "eps": {str(lid): float(sw.eps[lid][k]) for lid in mech.links},
            })
        drive = mech.drive
        return {
            "schema": SCHEMA,
            "title": mech.title,
            "structure": self.structure.as_dict(),
            "drive": {"link": drive.link, "omega": drive.signed_omega, "sense": drive.sense,
                      "gear_ratio": None if drive.gear_train is None else drive.gear_train.ratio,
                      "n1_rpm": drive.n1_rpm},
            "branches": self.branches.to_json(),
            "extremes_deg": None if self.extremes is None else
            {"working_start": self.extremes[0], "working_end": self.extremes[1]},
            "limits_of_assembly_deg": None if self.limits is None else list(self.limits),
            "plans": list(self.plan_positions),
            "positions": positions,
            "kinematics": kinematics,
            **({"diagrams": self.diagrams_json()} if diagrams else {}),
            "forces": self.forces_json(),
        }

    def forces_json(self) -> dict[str, Any]:
        """SPEC_FORMAT's `forces` object at the force position (with `problem`
        instead when that position has no kinematics or no force plan)."""
        from .forces import force_analysis

        try:
            return force_analysis(self).to_json()
        except MmtError as err:
            k = self.entry(self.force_position)
            return {"index": self.force_position, "phi1_deg": self.positions[k].phi1_deg,
                    "problem": str(err)}


def _pair(v) -> list[float]:
    return [float(v[0]), float(v[1])]


def _cm_names(mech: Mechanism) -> set[str]:
    return {l.cm_name for l in mech.links.values()} - set(mech.point_owners)

