"""The exact value of every quantity a student may give, at a position or at
any crank angle, from the Solution (never recomputed here): the plans, the
output's S, V, a, the force analysis. A force quantity is read off any
`ForceAnalysis` by the same function, so a mistake recomputed by the force
analysis (forces.force_analysis_at's keywords) gives the value the student
would have found by making it.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np

if TYPE_CHECKING:  # pragma: no cover
    from ..forces import ForceAnalysis
    from ..kinematics.plans import PlanView
    from ..solution import Solution

POLE = ""  # a segment's end at the pole

# the 5 % check of the diagrams against the plans (seed 003 (12), (13))
CHECK_KINDS = ("check_V", "check_a", "check_delta", "check_verdict")


@dataclass(frozen=True)
class Where:
    """A position of the analysis (`index`) or any crank angle (index None)."""

    index: int | None
    phi1_deg: float

    @property
    def key(self) -> tuple:
        return ("i", self.index) if self.index is not None else ("phi", round(self.phi1_deg, 9))


@dataclass(frozen=True)
class Answer:
    """One value of the answers file."""

    entry: str  # where it is written: "position[1].velocity.B"
    where: Where
    kind: str  # a key of KINDS
    name: str  # "B", "2", "pb", "R12", "an_BA"; "" for F_bal, M_bal
    value: float
    signed: bool = False
    label: str = ""  # as the report names it: "V_B", "pb (V plan)", "R12"
    mu: float | None = None  # the scale the value is read at (segments, ordinates)
    other_mu: float | None = None  # the other plan's μ at the same position
    segment: tuple[str, str] | None = None  # the two images of a plan segment
    extra: tuple[Any, ...] = field(default=())  # what the kind needs besides (a component ...)

    @property
    def position(self) -> int | None:
        return self.where.index


def size(v: Any) -> float:
    return float(math.hypot(float(v[0]), float(v[1])))


@dataclass(frozen=True)
class Grid:
    """The student's own graphical differentiation (answers' [diagrams]): the
    turn in `divisions` equal parts, the pole distances and the time axis
    (mm) when given."""

    divisions: int
    H_V: float | None = None
    H_a: float | None = None
    L: float | None = None


class Exact:
    """Plans and force analyses of the solution, at positions or angles, cached;
    the diagrams' V and a by the tool's grid, or by the student's (`grid`)."""

    def __init__(self, solution: Solution, grid: Grid | None = None) -> None:
        self.solution = solution
        self.grid = grid
        self._plans: dict[tuple, PlanView] = {}
        self._forces: dict[tuple, ForceAnalysis] = {}
        self._on_grid: dict[int, tuple[float, float]] | None = None

    def on_grid(self, index: int) -> tuple[float, float]:
        """V and a of the output at a position, by the graphical differentiation
        (seed 003 §1.7) of S over the student's grid, read off the smooth
        curves at the position's time."""
        if self._on_grid is None:
            from ..diagrams import DEFAULT_TIME_AXIS_MM, graphical_differentiation

            assert self.grid is not None
            sol = self.solution
            n, d = sol.mechanism.study.positions, self.grid.divisions
            phi0 = sol.positions[sol.entry(0)].phi1_deg
            angles = phi0 + sol.sense_sign * 360.0 * np.arange(d) / d
            sweep = sol.sweep_at(angles % 360.0)
            problem = next((sweep.problem(k) for k in range(d) if sweep.problem(k)), None)
            if problem is not None:
                raise problem
            s = sol.output_along(sweep)[0]
            L = self.grid.L or DEFAULT_TIME_AXIS_MM
            n1 = sol.mechanism.drive.n1_rpm
            dg = graphical_differentiation(
                s - s[0], n1=n1, mu_S=sol.mu_l, L=L, H1=self.grid.H_V, H2=self.grid.H_a
            )
            T = 60.0 / n1
            v, a = dg.values_at(T * np.arange(n) / n)
            self._on_grid = {i: (float(v[i]), float(a[i])) for i in range(n)}
        return self._on_grid[index]

    def where(self, *, index: int | None = None, phi1_deg: float | None = None) -> Where:
        if index is not None:
            return Where(index, self.solution.positions[self.solution.entry(index)].phi1_deg)
        assert phi1_deg is not None
        return Where(None, float(phi1_deg))

    def plan(self, w: Where) -> PlanView:
        if w.key not in self._plans:
            from ..kinematics.plans import plan_view

            if w.index is not None:
                self._plans[w.key] = self.solution.plan(w.index)
            else:
                # the solution's kinematic handle: its problem raised, if any
                sweep = self.solution.at(w.phi1_deg % 360.0)
                self._plans[w.key] = plan_view(sweep, 0, None)
        return self._plans[w.key]

    def forces(self, w: Where, **mistake: Any) -> ForceAnalysis:
        """The force analysis at `w`; with keywords of force_analysis_at, the
        analysis with that mistake made."""
        key = (w.key, tuple(sorted((k, _hashable(v)) for k, v in mistake.items())))
        if "weight_at" in mistake:  # given as pairs (link, point): hashable
            mistake = {**mistake, "weight_at": dict(mistake["weight_at"])}
        if key not in self._forces:
            if not mistake:
                if w.index is not None:
                    fa = self.solution.forces_at(w.index)
                else:
                    fa = self.solution.forces_at(phi1_deg=w.phi1_deg)
            else:
                from ..forces import force_analysis_at

                state = (
                    self.solution.state(w.index)
                    if w.index is not None
                    else self.solution.state(phi1_deg=w.phi1_deg)
                )
                fa = force_analysis_at(state, mu_l=self.solution.mu_l, **mistake)
            self._forces[key] = fa
        return self._forces[key]

    def output(self, index: int) -> tuple[float, float, float]:
        """S (from position 0), V, a of the output along the working direction at a position."""
        sol = self.solution
        s, v, a = sol.output_along(sol.sweep)
        k0, k = sol.entry(0), sol.entry(index)
        return float(s[k] - s[k0]), float(v[k]), float(a[k])

    # --- a kinematic answer's value -----------------------------------------------
    def kinematic(self, a: Answer, w: Where | None = None, kind: str | None = None) -> float:
        """In SI units, or mm at the answer's μ for a segment (another position `w`,
        the other plan's `kind`: a mistake recomputed)."""
        w = w or a.where
        kind = kind or a.kind
        plan = self.plan(w)
        if kind in ("velocity", "acceleration"):
            images = plan.velocity_images if kind == "velocity" else plan.acceleration_images
            return size(images[a.name])
        if kind in ("omega", "eps"):
            x = (plan.omega if kind == "omega" else plan.eps)[int(a.name)]
            return x if a.signed else abs(x)
        if kind in ("velocity_plan_mm", "acceleration_plan_mm"):
            assert a.mu is not None
            return self.plan_vector(plan, kind, a) / a.mu
        if kind in ("mu_V", "mu_a"):  # V_A / pa or a_A / πa of the student's own pa
            images = plan.velocity_images if kind == "mu_V" else plan.acceleration_images
            return size(images[a.name]) / a.extra[0]
        if kind in CHECK_KINDS:  # the 5 % check of the diagrams against the plans
            sc = self.solution.require_diagrams().sheet_check
            if kind == "check_verdict":
                if self.grid is None:
                    return 1.0 if sc.passed else 0.0
                return 1.0 if all(self._judged(v).passed for v in sc.values) else 0.0
            column, quantity = a.extra
            val = next(v for v in sc.values if v.index == w.index and v.quantity == quantity)
            if self.grid is not None:
                val = self._judged(val)
            return {"plan": val.plan, "diagram": val.diagram, "error": val.error_percent}[column]
        if kind == "diagram":
            assert w.index is not None and a.mu is not None
            s, v, acc = self.output(w.index)
            if self.grid is not None:
                v, acc = self.on_grid(w.index)
            return {"S": s, "V": v, "a": acc}[a.extra[0]] / a.mu
        raise KeyError(kind)

    def _judged(self, val: Any) -> Any:
        """An investigated value of the 5 % check with the diagram's value on the
        student's grid (formula (12) or (13); ill-conditioned as the tool judges it)."""
        from dataclasses import replace

        from ..diagrams import ERROR_LIMIT_PERCENT

        diagram = self.on_grid(val.index)[0 if val.quantity == "v" else 1]
        err = (val.plan - diagram) / val.plan * 100.0 if val.plan else 0.0
        passed = val.ill_conditioned or abs(err) <= ERROR_LIMIT_PERCENT
        return replace(
            val,
            diagram=diagram,
            error_percent=err,
            absolute_error=abs(val.plan - diagram),
            passed=passed,
        )

    @staticmethod
    def plan_vector(plan: PlanView, kind: str, a: Answer) -> float:
        """|segment| (SI) of a plan: between two images, or a component."""
        if a.segment is None:
            label = a.extra[0]
            comps = [
                c
                for g in plan.groups
                for c in (g.velocity if kind == "velocity_plan_mm" else g.acceleration)
            ]
            return next(c.magnitude for c in comps if c.label == label)
        images = plan.velocity_images if kind == "velocity_plan_mm" else plan.acceleration_images
        p, q = (np.zeros(2) if e == POLE else images[e] for e in a.segment)
        return size(q - p)


# --- a force answer's value, off any force analysis ------------------------------------


def force_value(fa: ForceAnalysis, a: Answer, mu_l: float) -> float:
    """The answer's quantity in this force analysis (N, N·m, m, or mm at the answer's μ)."""
    return FORCE_KINDS[a.kind](fa, a, mu_l)


def _reaction(fa: ForceAnalysis, name: str):
    by, on = reaction_links(name, fa)
    return fa.reaction(by, on)


def reaction_links(name: str, fa: ForceAnalysis) -> tuple[int, int]:
    import re

    if name == "R0d":
        return 0, fa.driving_link.link
    m = re.fullmatch(r"R(?:(\d)(\d)|(\d+)_(\d+))", name)
    if m is None:
        raise KeyError(name)
    return (int(m[1]), int(m[2])) if m[1] else (int(m[3]), int(m[4]))


def component(fa: ForceAnalysis, name: str, which: str) -> float:
    """|R_ij^n| or |R_ij^τ| ('n' or 't'); 0 when the reaction has no such component
    (its kind does not split it)."""
    r = _reaction(fa, name)
    for c in r.components:
        if c.label.endswith("^" + which):
            return abs(c.value)
    raise KeyError(f"{name}^{which}")


def _named_force(fa: ForceAnalysis, name: str) -> float:
    """|force| of a vector of sheet 2 by its name: R12, R12t, R12n, G2, F_in2, F_bal, F_PR."""
    if name == "F_bal":
        return abs(fa.balancing_force_plans)
    if name.startswith("G") and name[1:].isdigit():
        return size(fa.loads.links[int(name[1:])].weight)
    if name.startswith("F_in") and name[4:].isdigit():
        return size(fa.loads.links[int(name[4:])].inertia_force)
    for f in fa.loads.production_resistance:
        if f.name == name:
            return size(f.force)
    if name[-1:] in ("t", "n", "τ") and name.startswith("R"):
        return component(fa, name[:-1], "n" if name.endswith("n") else "t")
    return _reaction(fa, name).magnitude


def _lever(fa: ForceAnalysis, a: Answer, mu_l: float) -> float:
    lever = fa.lever
    assert a.mu is not None
    if a.name.startswith("h_"):
        label = a.name[2:]
        if label == "F_bal":
            return abs(lever.balancing.arm) / a.mu
        f = next(f for f in lever.forces if f.label == label)
        return abs(f.arm) / a.mu
    point = a.extra[0]
    return size(lever.images[point]) / a.mu


def arm_forces(
    fa: ForceAnalysis,
) -> dict[str, tuple[np.ndarray, np.ndarray, np.ndarray, int]]:
    """The forces of each group's moment equations about its inner pin (ΣM_B(L) = 0,
    the equation of R^τ of an outer pair split into R^n and R^τ; sheet 2 draws
    their arms h'_k): the force's label -> (force N, its point m, the pin B m).
    The inertia force acts at K_i (shifted by h_i), as the sheet draws it; the
    last item is the link the force acts on."""
    out: dict[str, tuple[np.ndarray, np.ndarray, np.ndarray, int]] = {}
    for g in fa.groups:
        inner = g.reactions[2]
        if inner.kind != "R":
            continue
        own = {name for r in g.reactions for name in (r.name, r.reversed().name)}
        B = np.asarray(inner.point, float)
        for k, L in enumerate(g.links):
            if len(g.reactions[k].components) != 2:
                continue
            for f in g.free_bodies[L]:
                if f.label in own or size(f.force) == 0.0:
                    continue
                P = np.asarray(f.point, float)
                if f.label == f"F_in{L}":
                    sh = fa.loads.links[L].shifted_inertia_force
                    if sh is not None:
                        P = np.asarray(sh.point, float)
                out[f.label] = (np.asarray(f.force, float), P, B, L)
    return out


def arm_about(F: np.ndarray, P: np.ndarray, B: np.ndarray) -> float:
    """The arm of F acting at P about B, m: |(P − B) × F| / |F|."""
    r = P - B
    return abs(float(r[0] * F[1] - r[1] * F[0])) / size(F)


def group_arm(fa: ForceAnalysis, a: Answer) -> float:
    """The arm h of a force in its group's moment equation about the inner pin, m."""
    F, P, B, _ = arm_forces(fa)[a.name]
    return arm_about(F, P, B)


FORCE_KINDS: dict[str, Callable[[ForceAnalysis, Answer, float], float]] = {
    "balancing_force_plans": lambda fa, a, _: _signed(fa.balancing_force_plans, a),
    "balancing_force_lever": lambda fa, a, _: _signed(fa.balancing_force_lever, a),
    "balancing_moment": lambda fa, a, _: _signed(fa.balancing_moment, a),
    "reaction": lambda fa, a, _: _reaction(fa, a.name).magnitude,
    "reaction_component": lambda fa, a, _: component(fa, a.extra[0], a.extra[1]),
    "weight": lambda fa, a, _: size(fa.loads.links[int(a.name)].weight),
    "inertia_force": lambda fa, a, _: size(fa.loads.links[int(a.name)].inertia_force),
    "inertia_moment": lambda fa, a, _: abs(fa.loads.links[int(a.name)].inertia_moment),
    "inertia_arm_m": lambda fa, a, _: _arm(fa, a),
    "inertia_arm_mm": lambda fa, a, mu_l: _arm(fa, a) / (a.mu or mu_l),
    "force_plan_mm": lambda fa, a, _: _named_force(fa, a.name) / (a.mu or 1.0),
    "lever_mm": _lever,
    "group_arm_m": lambda fa, a, _: group_arm(fa, a),
    "group_arm_mm": lambda fa, a, mu_l: group_arm(fa, a) / (a.mu or mu_l),
}


def _signed(x: float, a: Answer) -> float:
    return x if a.signed else abs(x)


def _arm(fa: ForceAnalysis, a: Answer) -> float:
    ll = fa.loads.links[int(a.name)]
    sh = ll.shifted_inertia_force
    return 0.0 if sh is None else sh.arm


def _hashable(v: Any) -> Any:
    if isinstance(v, (list, tuple, set, frozenset)):
        return tuple(sorted(v))
    return v
