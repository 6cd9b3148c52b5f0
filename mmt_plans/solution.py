"""Solve a mechanism once into a frozen `Solution`: everything a sheet, the
note, the check and the results JSON need.

    >>> import mmt_plans
    >>> solution = mmt_plans.solve(mmt_plans.load("samples/six_link_press.toml"))
    >>> solution.structure.formula
    'I(0,1) <- II(2,3) <- II(4,5)'

The order is the textbook's: structure (seed 003 §1.1), the assembly branches
and the turn, the extreme positions and the n positions (§1.2), the
kinematics at every position (the plans of §1.3–1.6 are read from it), the
S–V–a diagrams with the 5 % check (§1.7–1.8), the force analysis at the force
position (§2.1–2.11), the reduction to the crank (seed 002 tasks 5–6).
A part that cannot be computed (a position where the mechanism cannot
assemble, diagrams of a partial turn) is kept as its problem, never as NaN.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from functools import lru_cache
from typing import Literal, cast

import numpy as np

from .diagrams import (
    DIAGRAM_HEIGHT_MM,
    ERROR_LIMIT_PERCENT,
    TIME_AXIS,
    DiagramScales,
    KinematicDiagrams,
    PlanComparison,
    SheetCheck,
    choose_grid,
    compare_with_plans,
    diagram_scales,
    graphical_differentiation,
    judge,
)
from .errors import ForceError, MmtError, StructureError, partial_turn_error, shown
from .forces import ForceAnalysis, force_analysis_at
from .forces.reduction import Reduction, reduce_sweep
from .forces.state import PositionState, from_sweep
from .kinematics.branches import Branches
from .kinematics.chain import Chain, Sweep
from .kinematics.geometry import quiet
from .kinematics.handle import Kinematics, kinematics
from .kinematics.plans import PlanView, plan_view
from .model import Mechanism, Stroke
from .scales import LENGTH_MANTISSA_TEXT, DrawnLength, scale_for
from .structure import Structure

__all__ = ["Position", "Diagrams", "Solution", "solve", "sweep", "EXTREME_TOL_DEG"]

EXTREME_TOL_DEG = 1e-9
EXTREME_TIE = 1e-9  # of the stroke: two extreme positions this equal in s are a tie
PLAN_TIE_DEG = 1e-6  # two positions this equally near the middle of a stroke are a tie
GRID = 1440
# the fine grid the displacements are read from: 24 steps to a position step,
# so that every grid n·k of the 5 % check's series (k = 1 … 12) is among them
BASE_STEPS = 24
DENSE = 181  # crank angles of the trajectories drawn on sheet 1 (position 0 twice)
# the extreme search's grid over a whole turn (deg), the same for every mechanism
_WHOLE_TURN = np.linspace(0.0, 360.0, GRID, endpoint=False)
_WHOLE_TURN.setflags(write=False)


@dataclass(frozen=True)
class Position:
    index: int | None  # None for an extra angle of `study.angles`
    phi1_deg: float
    stroke: Stroke


@dataclass(frozen=True)
class Diagrams:
    """The graphical differentiation (mm and SI) and its 5 % check against the plans.

    `construction` is drawn at `scales`, the one μ_S and the poles OH1, OH2
    that sheet 1 draws, the note writes and the results JSON carries."""

    construction: KinematicDiagrams
    check: PlanComparison  # every position of the study against the drawn construction
    v_plan: np.ndarray  # V of the output along the working direction at the positions
    a_plan: np.ndarray
    sheet_check: SheetCheck  # the verdict: the investigated positions, on the grid drawn
    refinement: int  # divisions of the diagrams per position step
    scales: DiagramScales  # μ_S (μ_l or a series step above it) and the whole-millimetre poles

    def at_position(self, values: np.ndarray) -> np.ndarray:
        """A construction's values (on its grid) at the n positions."""
        return np.asarray(values)[:: self.refinement]

    @property
    def passed(self) -> bool:
        return self.sheet_check.passed


@dataclass(frozen=True)
class Solution:
    """A mechanism solved: frozen, read by every output."""

    mechanism: Mechanism
    structure: Structure
    chain: Chain  # the kinematic model on its branches (more angles: `sweep_at`)
    branches: Branches
    limits: tuple[float, float] | None  # limits of assembly of a partial turn (drive sense)
    extremes: tuple[float, float] | None  # crank angles of the output's extreme positions
    working_span_deg: float | None
    positions: tuple[Position, ...]
    plan_positions: tuple[int, ...]
    force_position: int
    sweep: Sweep  # the kinematics at every position and extra angle
    mu_l: float  # the scale of the mechanism's drawing, m/mm
    dense: Sweep  # DENSE angles counter-clockwise over the turn from position 0 (trajectories)
    s_dense: np.ndarray | None  # S of the output, a dozen steps to a division of the diagrams, m
    diagrams: Diagrams | None
    diagrams_problem: str | None
    forces: ForceAnalysis | None
    forces_problem: str | None
    reduction: Reduction
    kinematics: Kinematics  # the chain built once: `kinematics.sweep(angles)`, `.at(angle)`

    # --- reading ---------------------------------------------------------------------
    @property
    def sense_sign(self) -> int:
        return 1 if self.mechanism.drive.sense == "ccw" else -1

    @property
    def assembly_ranges(self) -> tuple[tuple[float, float], ...]:
        return self.branches.ranges

    def entry(self, index: int) -> int:
        """Where position `index` sits in `positions`."""
        for k, p in enumerate(self.positions):
            if p.index == index:
                return k
        raise ForceError(
            f"position {index} does not exist",
            f"use a position 0..{self.mechanism.study.positions - 1}",
        )

    def problem(self, k: int) -> MmtError | None:
        """Why entry k of `positions` has no kinematics (None when it has)."""
        return self.sweep.problem(k)

    def plan(self, index: int) -> PlanView:
        """The velocity and acceleration plan at position `index` (its problem raised)."""
        k = self.entry(index)
        problem = self.problem(k)
        if problem is not None:
            raise problem
        return plan_view(self.sweep, k, index)

    def output_along(self, sweep: Sweep) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        return output_along(self.mechanism, sweep)

    def stroke_of(self, phi1_deg: float) -> Stroke:
        return _stroke_of(
            self.mechanism, self.chain, self.limits, self.extremes, self.working_span_deg, phi1_deg
        )

    def require_forces(self) -> ForceAnalysis:
        """The force analysis at the force position, or its problem raised."""
        if self.forces is None:
            raise MmtError(self.forces_problem or "no force analysis")
        return self.forces

    def require_diagrams(self) -> Diagrams:
        if self.diagrams is None:
            raise MmtError(self.diagrams_problem or "no kinematic diagrams")
        return self.diagrams

    # --- more angles, for the check and the tests ----------------------------------------
    def sweep_at(self, phi1_deg: Sequence[float] | np.ndarray) -> Sweep:
        """The kinematics at other crank angles, on the same branches."""
        return self.kinematics.sweep(np.atleast_1d(np.asarray(phi1_deg, dtype=float)))

    def at(self, phi1_deg: float) -> Sweep:
        """The kinematics at one crank angle (`Kinematics.at`)."""
        return self.kinematics.at(phi1_deg)

    def state(self, index: int | None = None, *, phi1_deg: float | None = None) -> PositionState:
        """Where every link is and how it moves at position `index`, or at any crank angle."""
        if (index is None) == (phi1_deg is None):
            raise ForceError(
                "give a position index or a crank angle, not both",
                "call with index or phi1_deg=...",
            )
        if phi1_deg is not None:
            phi = float(phi1_deg) % 360.0
            return from_sweep(self.mechanism, self.sweep_at([phi]), 0, None, self.stroke_of(phi))
        if isinstance(index, bool) or not isinstance(index, (int, np.integer)):
            raise ForceError(
                f"the position index {index!r} is not a whole number",
                "give a position index, e.g. 2",
            )
        k = self.entry(int(index))
        pos = self.positions[k]
        return from_sweep(self.mechanism, self.sweep, k, pos.index, pos.stroke)

    def forces_at(
        self, index: int | None = None, *, phi1_deg: float | None = None
    ) -> ForceAnalysis:
        """The force analysis at another position or crank angle (the force
        position's is `forces`)."""
        if index is None and phi1_deg is None:
            return self.require_forces()
        if index == self.force_position and phi1_deg is None and self.forces is not None:
            return self.forces
        return force_analysis_at(self.state(index, phi1_deg=phi1_deg), mu_l=self.mu_l)


def sweep(mechanism: Mechanism, phi1_deg: Sequence[float] | np.ndarray) -> Sweep:
    """Positions, velocities and accelerations of every point, ω and ε of every
    link, over many crank angles at once (NaN where a group cannot assemble;
    see `Sweep.check()`). The chain is built on the first call for a Mechanism
    and reused after (`kinematics(mechanism)`)."""
    return kinematics(mechanism).sweep(phi1_deg)


def output_along(mech: Mechanism, sweep: Sweep) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """s, V, a of the output along the working direction (SI, signed)."""
    wd = np.conj(complex(*mech.study.working_direction))
    out = mech.study.output
    return (
        (sweep.position_of(out) * wd).real,
        (sweep.velocity_of(out) * wd).real,
        (sweep.acceleration_of(out) * wd).real,
    )


# --- solving -------------------------------------------------------------------------------


def solve(
    mechanism: Mechanism, *, partial_turn: bool | None = None, forces: bool = True
) -> Solution:
    """Solve `mechanism` (the order of the module docstring). A crank that
    cannot make a whole turn raises `PartialTurnError` unless the file or
    `partial_turn=True` opts in. `forces=False` leaves out the force analysis
    (sheet 1 alone)."""
    mech = mechanism if not partial_turn else mechanism.with_partial_turn()
    # the kinematics in one quiet context (NaN is the kernels' data; each
    # kernel's own context is then a counter, not numpy's machinery)
    with quiet():
        handle = kinematics(mech)
        structure, chain, branches = handle.structure, handle.chain, handle.branches
        if not branches.whole_turn and (not mech.study.partial_turn or not branches.ranges):
            # refused; also when opted in, if it assembles at no crank angle at all
            raise partial_turn_error(mech, branches)
        # the extreme positions and the displacements follow from the kinematics
        # alone: searched once per handle (a Mechanism solved again reads them)
        turn = handle.kept("turn", lambda: _Turn(mech, chain, branches))
        positions = turn.positions()
        phi0 = positions[0].phi1_deg
        # the positions and the trajectories' angles, in one pass of the kernels
        sw, dense = chain.sweeps(
            np.array([p.phi1_deg for p in positions]), np.linspace(phi0, phi0 + 360.0, DENSE)
        )
    plan_positions = turn.plan_positions(positions)
    fp = mech.study.force_position
    force_position = plan_positions[0] if fp is None else fp
    mu_l = _mechanism_scale(mech, dense)
    diagrams, diagrams_problem, s_dense = None, None, None
    try:
        diagrams = _diagrams(mech, turn, positions, sw, mu_l, plan_positions)
        # the smooth S curve: a dozen points to every division of the diagrams
        s_dense = turn.displacements(max(DENSE - 1, 12 * diagrams.sheet_check.intervals))
    except MmtError as err:
        diagrams_problem = str(err)
    force_analysis, forces_problem = None, None
    k = next(i for i, p in enumerate(positions) if p.index == force_position)
    if forces:
        try:
            state = from_sweep(mech, sw, k, force_position, positions[k].stroke)
            force_analysis = force_analysis_at(state, mu_l=mu_l)
        except MmtError as err:
            forces_problem = str(err)
    else:
        forces_problem = "the force analysis was not asked for"
    reduction = reduce_sweep(
        mech, sw, tuple(p.index for p in positions), tuple(p.stroke for p in positions)
    )
    return Solution(
        mechanism=mech,
        structure=structure,
        chain=chain,
        branches=branches,
        limits=turn.limits,
        extremes=turn.extremes,
        working_span_deg=turn.working_span_deg,
        positions=positions,
        plan_positions=plan_positions,
        force_position=force_position,
        sweep=sw,
        mu_l=mu_l,
        dense=dense,
        s_dense=s_dense,
        diagrams=diagrams,
        diagrams_problem=diagrams_problem,
        forces=force_analysis,
        forces_problem=forces_problem,
        reduction=reduction,
        kinematics=handle,
    )


def _mechanism_scale(mech: Mechanism, dense: Sweep) -> float:
    """Scale of the mechanism drawing: the standard value that draws the span
    of every point's trajectory (the dense sweep's, over one turn) in
    150–300 mm (μ_l = l_OA / OA, (2))."""
    ok = dense.ok  # where the chain is solved
    if ok.all():  # everywhere: every position as it is (no copy through the mask)
        pts = np.concatenate([dense.position_of(n) for n in mech.point_owners])
    else:
        pts = np.concatenate([dense.position_of(n)[ok] for n in mech.point_owners])
    x, y = pts.real, pts.imag  # np.ptp's max - min, without its wrapper
    span = max(x.max() - x.min(), y.max() - y.min(), mech.crank_length)
    return scale_for(
        float(span), DrawnLength("mechanism", 150.0, 300.0, 220.0), LENGTH_MANTISSA_TEXT
    )


@lru_cache(maxsize=64)
def _time_axis(T: float) -> float:
    """L, mm: one turn of T s drawn at the standard μ_t that makes it 150 … 240
    mm (the same for every mechanism at that speed)."""
    return T / scale_for(T, TIME_AXIS)


def _diagrams(
    mech: Mechanism,
    turn: _Turn,
    positions: tuple[Position, ...],
    sw: Sweep,
    mu_l: float,
    investigated: tuple[int, ...],
) -> Diagrams:
    """The graphical differentiation and its 5 % check against the plans (seed
    003 §1.7–1.8), judged at the investigated positions on the diagrams drawn:
    the S diagram over n·k divisions of the turn (the positions among them),
    the first grid of the series n·k (diagrams.choose_grid) on which every
    investigated position passes by (12)/(13) as written."""
    if turn.limits is not None:
        raise MmtError(
            "no kinematic diagrams: the crank does not make a whole turn "
            "(partial_turn), and the diagrams of 1.7 cover one turn"
        )
    n = mech.study.positions
    entry = {p.index: j for j, p in reversed(list(enumerate(positions)))}  # the first of each
    k = [entry[i] for i in range(n)]
    ok = sw.ok
    if not ok[k].all():
        bad = next(i for i in range(n) if not ok[k[i]])
        raise sw.problem(k[bad]) or MmtError("diagrams need every position")
    _, v, a = (x[k] for x in output_along(mech, sw))
    n1 = mech.drive.n1_rpm
    # the time axis: the standard μ_t that draws one turn in 150 … 240 mm
    T = 60.0 / n1
    L = _time_axis(T)
    # the largest magnitudes over the turn: the fine grid of the extreme search
    # and the positions themselves
    largest = (
        max(turn.largest[0], float(np.abs(v).max())),
        max(turn.largest[1], float(np.abs(a).max())),
    )
    # seed 003 §1.8 on the grids of the series n·k: the first on which every
    # investigated position passes by (12)/(13) as written
    choice = choose_grid(
        turn.displacements,
        n=n,
        n1=n1,
        investigated=investigated,
        v_plan=v,
        a_plan=a,
        largest=largest,
    )
    refinement = choice.refinement
    s_grid = turn.displacements(n * refinement)
    # μ_S = μ_l unless a diagram would be taller than sheet 1 holds, then up
    # the series; round poles from ROUND_POLE_DISTANCES_MM (diagram_scales)
    scales = diagram_scales(s_grid, n1=n1, L=L, mu_l=mu_l, max_height=DIAGRAM_HEIGHT_MM)
    construction = graphical_differentiation(
        s_grid, n1=n1, mu_S=scales.mu_S, L=L, H1=scales.H1, H2=scales.H2
    )
    values = []
    for i in investigated:
        for q, plan, drawn, big in (
            ("v", v, construction.v, largest[0]),
            ("a", a, construction.a, largest[1]),
        ):
            quantity = cast("Literal['v', 'a']", q)
            values.append(
                judge(
                    i,
                    quantity,
                    float(plan[i]),
                    float(drawn[i * refinement]),
                    big,
                    exempt=(i, q) in choice.exempt,
                )
            )
    tried = tuple((t.intervals, t.passed) for t in choice.trials)
    sheet_check = SheetCheck(
        n * refinement, refinement, ERROR_LIMIT_PERCENT, tuple(values), tried, choice.trials
    )
    at_positions = slice(None, None, refinement)
    check = compare_with_plans(
        construction.v[at_positions],
        construction.a[at_positions],
        v,
        a,
        n1=n1,
        s=construction.s[at_positions],
        candidates=(),
    )
    return Diagrams(construction, check, v, a, sheet_check, refinement, scales)


def _sign(x: float) -> float:
    """np.sign of a float: -1, 0 or 1, NaN for NaN."""
    return float((x > 0) - (x < 0)) if x == x else math.nan


def _stroke_of(
    mech: Mechanism, chain: Chain, limits, extremes, working_span_deg, phi1_deg: float
) -> Stroke:
    sense = 1 if mech.drive.sense == "ccw" else -1
    if limits is not None or extremes is None:
        # a partial turn: working where the output moves along the working direction
        _, v, _ = output_along(mech, chain.sweep(np.array([phi1_deg])))
        return "working" if float(v[0]) / mech.drive.signed_omega * sense > 0 else "idle"
    lo, _ = extremes
    ahead = ((phi1_deg - lo) * sense) % 360.0
    if ahead <= working_span_deg + EXTREME_TOL_DEG or ahead >= 360.0 - EXTREME_TOL_DEG:
        return "working"
    return "idle"


class _Turn:
    """The crank's turn: the range analysed, the extreme positions, the positions."""

    def __init__(self, mech: Mechanism, chain: Chain, branches: Branches) -> None:
        self.mech, self.chain = mech, chain
        self.sense = 1 if mech.drive.sense == "ccw" else -1
        self.limits: tuple[float, float] | None = None
        self.largest = (0.0, 0.0)  # |V|, |a| of the output over the turn, the fine grid's
        self._displacements: dict[int, np.ndarray] = {}  # by the number of steps
        if not branches.whole_turn:
            lo, hi = max(branches.ranges, key=lambda r: (r[1] - r[0]) % 360.0)
            self.limits = (lo, hi) if self.sense > 0 else (hi, lo)
        self.extremes = self._extremes()
        self.working_span_deg = (
            None
            if self.extremes is None
            else ((self.extremes[1] - self.extremes[0]) * self.sense) % 360.0
        )
        self.phi0 = self._phi0()

    @property
    def span_deg(self) -> float:
        """Crank angle the positions are spread over: 360, or the range analysed."""
        if self.limits is None:
            return 360.0
        a, b = self.limits
        return ((b - a) * self.sense) % 360.0

    def output(self, phi1_deg: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """Where the chain is solved, and s, V, a of the output along the working
        direction (SI, signed) at the crank angles: the searches' kernel."""
        ok, P, V, A = self.chain.point_motion(phi1_deg, self.mech.study.output)
        wd = np.conj(complex(*self.mech.study.working_direction))
        return ok, (P * wd).real, (V * wd).real, (A * wd).real

    def along(self, phi1_deg: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """s, ds/dφ and d²s/dφ² of the output along the working direction (ε1 = 0)
        (the kernel of `output`, without where the chain is solved)."""
        w = self.mech.drive.signed_omega
        P, V, A = self.chain.point_motion_only(phi1_deg, self.mech.study.output)
        wd = np.conj(complex(*self.mech.study.working_direction))
        return (P * wd).real, (V * wd).real / w, (A * wd).real / (w * w)

    def _extremes(self) -> tuple[float, float] | None:
        with quiet():  # NaN is the kernels' data here (one context for every step)
            return self._extremes_quietly()

    def _extremes_quietly(self) -> tuple[float, float] | None:
        """Crank angles (deg) of the output's least and greatest position along
        the working direction: zeros of ds/dφ to machine precision (Newton with
        the exact d²s/dφ² of the acceleration plan, kept in a bracket where ds/dφ
        changes sign). In a partial turn only zeros inside the range count (the
        limits of assembly are not extreme positions); None when there are none."""
        if self.limits is None:
            grid = _WHOLE_TURN
        else:
            grid = self.limits[0] + self.sense * self.span_deg * (np.arange(1, GRID) / GRID)
        solved, s, v, a = self.output(grid)
        w = self.mech.drive.signed_omega
        ds = v / w
        ok = solved & np.isfinite(s) & np.isfinite(ds)
        if not ok.any():
            raise self.chain.sweep(grid[:1]).problem(0) or StructureError(
                "the mechanism assembles at no crank angle"
            )
        everywhere = bool(ok.all())
        # (indexing by `ok` where it holds everywhere would copy the same values)
        v_ok, a_ok, s_ok = (v, a, s) if everywhere else (v[ok], a[ok], s[ok])
        self.largest = (float(np.abs(v_ok).max()), float(np.abs(a_ok).max()))
        if s_ok.max() - s_ok.min() < 1e-12 * max(1.0, float(np.abs(s_ok).max())):
            raise StructureError(
                f"{shown(self.mech.path)}: output {self.mech.study.output} does not move along the "
                "working direction: set study.working_direction or study.zero"
            )
        # brackets [φ_i, φ_i+1] of the grid where ds/dφ changes sign
        nxt = np.concatenate((np.arange(1, grid.size), [0]))  # np.roll(arange, -1)
        if self.limits is not None:
            nxt[-1] = grid.size - 1
            change = (
                ok & ok[nxt] & (np.sign(ds) != np.sign(ds[nxt])) & (nxt != np.arange(grid.size))
            )
        else:
            # the whole turn: the next of the last is the first (never itself)
            sign = np.sign(ds)
            change = sign != np.concatenate((sign[1:], sign[:1]))
            if not everywhere:
                change &= ok & np.concatenate((ok[1:], ok[:1]))
        idx = np.flatnonzero(change)
        if not idx.size:
            return None
        step = 360.0 / GRID if self.limits is None else self.span_deg / GRID
        lo_b = grid[idx]
        hi_b = lo_b + (step if self.limits is None else self.sense * step)
        # ds/dφ at each bracket's ends, read off the grid
        ascending = lo_b <= hi_b
        fa = np.where(ascending, ds[idx], ds[nxt[idx]])
        fb = np.where(ascending, ds[nxt[idx]], ds[idx])
        roots, s_roots = self._root(np.minimum(lo_b, hi_b), np.maximum(lo_b, hi_b), fa, fb)
        # Two extremes of equal s (the output passing its farthest place twice a
        # turn) are a tie, not a choice for rounding to make: of the tied ones,
        # the pair that makes the working stroke longest.
        tol = EXTREME_TIE * max(float(s_roots.max() - s_roots.min()), np.finfo(float).tiny)
        lows = roots[s_roots <= s_roots.min() + tol] % 360.0
        highs = roots[s_roots >= s_roots.max() - tol] % 360.0
        lo, hi = max(
            ((float(x), float(y)) for x in lows for y in highs),
            key=lambda pair: ((pair[1] - pair[0]) * self.sense) % 360.0,
        )
        return lo, hi

    def _root(
        self, a: np.ndarray, b: np.ndarray, fa: np.ndarray, fb: np.ndarray
    ) -> tuple[np.ndarray, np.ndarray]:
        """Zeros of ds/dφ in the brackets [a, b] (deg, ds/dφ changes sign in
        each, fa and fb its values at the ends): from the chord's zero,
        Newton's steps where they stay in the bracket, bisection where they
        would leave it (rtsafe), all brackets at once. With s at each zero, from
        the last step (which moved φ by a few ulps at most, where ds/dφ = 0: s
        is the same to far below rounding)."""
        a, b = a.astype(float).copy(), b.astype(float).copy()
        # the chord's zero: a grid step's worth of curvature from the root, so
        # Newton's quadratic steps reach machine precision in two or three
        # (no warnings: `_extremes` runs quietly)
        chord = a - fa * (b - a) / (fb - fa)
        phi = np.where(np.isfinite(chord) & (chord > a) & (chord < b), chord, 0.5 * (a + b))
        # The brackets' bookkeeping is a few numbers each (one or two
        # brackets): plain floats, by the same IEEE operations the arrays
        # would do (math.degrees multiplies by numpy's 180/π); each step's
        # kernel is one pass over every bracket.
        A, B, FA = a.tolist(), b.tolist(), fa.tolist()
        PHI = phi.tolist()
        DONE = [False] * len(PHI)
        S_AT = [0.0] * len(PHI)
        eps4 = float(4 * np.finfo(float).eps)
        for _ in range(200):
            s_, f_, df_ = self.along(np.array(PHI))
            S, F, DF = s_.tolist(), f_.tolist(), df_.tolist()
            for j, (s, f, df) in enumerate(zip(S, F, DF)):
                if not DONE[j]:
                    S_AT[j] = s
                x = PHI[j]
                if _sign(f) == _sign(FA[j]):  # keep the sign-change bracket
                    A[j], FA[j] = x, f
                else:
                    B[j] = x
                # a Newton step onto an end of the bracket is still inside it: near
                # the root rounding puts it there, and bisection would crawl from afar
                newton = x - math.degrees(f / df) if df != 0 else math.nan
                inside = math.isfinite(newton) and A[j] <= newton <= B[j]
                new = newton if inside else 0.5 * (A[j] + B[j])
                tol = eps4 * max(1.0, abs(x))
                converged = f == 0 or abs(new - x) <= tol or B[j] - A[j] <= tol
                # a bracket once converged stays where it converged
                if not (DONE[j] or f == 0):
                    PHI[j] = new
                DONE[j] = DONE[j] or converged
            if all(DONE):
                break
        return np.array(PHI), np.array(S_AT)

    def _phi0(self) -> float:
        if self.limits is not None:  # half a step in from the first limit of assembly
            n = self.mech.study.positions
            return (self.limits[0] + self.sense * self.span_deg / (2 * n)) % 360.0
        zero = self.mech.study.zero
        if zero is None:
            if self.extremes is None:
                raise StructureError(
                    f"{shown(self.mech.path)}: output {self.mech.study.output} has no extreme position "
                    "along the working direction: set study.zero or study.working_direction"
                )
            return self.extremes[0]
        return zero % 360.0

    def stroke_of(self, phi1_deg: float) -> Stroke:
        return _stroke_of(
            self.mech, self.chain, self.limits, self.extremes, self.working_span_deg, phi1_deg
        )

    def positions(self) -> tuple[Position, ...]:
        n = self.mech.study.positions
        out = []
        for i in range(n):
            phi = (self.phi0 + self.sense * self.span_deg * i / n) % 360.0
            out.append(Position(i, phi, self.stroke_of(phi)))
        for phi in self.mech.study.angles:
            out.append(Position(None, phi % 360.0, self.stroke_of(phi % 360.0)))
        return tuple(out)

    def plan_positions(self, positions: tuple[Position, ...]) -> tuple[int, ...]:
        """`study.plans`, or the positions nearest the middle of the working
        and of the idle stroke (SPEC_FORMAT's default); in a partial turn the
        positions at a quarter and at three quarters of the range."""
        if self.mech.study.plans is not None:
            return self.mech.study.plans
        n = self.mech.study.positions
        if self.limits is not None or self.extremes is None or self.working_span_deg is None:
            return (n // 4, (3 * n) // 4)
        lo, hi = self.extremes
        span = self.working_span_deg
        mids = [lo + self.sense * span / 2, hi + self.sense * (360.0 - span) / 2]
        picks = []
        for mid in mids:
            dist = [
                abs((p.phi1_deg - mid + 180.0) % 360.0 - 180.0)
                for p in positions
                if p.index is not None
            ]
            # a tie (within PLAN_TIE_DEG, SPEC_FORMAT) goes to the lower index,
            # not to whichever rounding made a hair nearer
            nearest = min(dist)
            picks.append(next(i for i, d in enumerate(dist) if d <= nearest + PLAN_TIE_DEG))
        return tuple(picks)

    def displacements(self, n: int) -> np.ndarray:
        """s of the output at n equal crank steps from position 0 (s = 0 there), m:
        the smooth S curve of the diagram, and the grids of the 5 % check."""
        found = self._displacements.get(n)
        if found is None:
            # every grid of the 5 % check's series, and the S curve of most
            # grids drawn, is every so many steps of one fine grid: one sweep
            fine = self.mech.study.positions * BASE_STEPS
            if n != fine and fine % n == 0:
                found = self.displacements(fine)[:: fine // n]
            else:
                phi = self.phi0 + self.sense * 360.0 * np.arange(n) / n
                # where the output is (not how it moves): the groups' positions alone
                P = self.chain.point_position(phi, self.mech.study.output)
                s = (P * np.conj(complex(*self.mech.study.working_direction))).real
                found = s - s[0]
            found.setflags(write=False)
            self._displacements[n] = found
        return found
