"""A student's answers against the exact values (`mmt-plans check`).

The student writes what they measured on their hand drawing in an answers
file (README.md, "Checking a student's work"), at a position `index` or at
any crank angle `phi1_deg`: speeds and accelerations, ω and ε, plan segments
and components with the plans' μ, the output's diagram ordinates, the force
analysis (reactions and their components, G, F_in, M_in, arms, force-plan
and lever segments, F_bal, M_bal), and the grid of their own differentiation
of the diagrams. Each value is compared with the exact one from the
Solution. The failing values get causes by a joint diagnosis: the smallest
set of mistake models, each a change to the method recomputed through the
Solution's own machinery, that explains them together (mistakes.py); the
values left, by the slips of a single reading (causes.py).
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING

from .answers import (
    LIMITS,
    MU_MAX,
    MU_MIN,
    TOLERANCE_MAX,
    VALUE_MAX,
    VALUES_MAX,
    Answers,
    load_answers,
    loads_answers,
)
from .causes import (
    KINEMATIC,
    Candidate,
    Cause,
    clear,
    force_candidates,
    kinematic_candidates,
    rank,
)
from .mistakes import diagnose
from .quantities import Answer, Exact, Where, force_value
from .report import CheckedValue, CheckResult

if TYPE_CHECKING:  # pragma: no cover
    from ..solution import Solution

__all__ = [
    "DEFAULT_TOLERANCE_PERCENT",
    "LIMITS",
    "MU_MIN",
    "MU_MAX",
    "TOLERANCE_MAX",
    "VALUE_MAX",
    "VALUES_MAX",
    "Answer",
    "Answers",
    "Cause",
    "CheckedValue",
    "CheckResult",
    "Where",
    "check",
    "check_file",
    "load_answers",
    "loads_answers",
]

DEFAULT_TOLERANCE_PERCENT = 5.0

# An exact value this small against the largest of its kind is zero: the
# position's ε1 of a uniformly turning crank, a point on the frame.
_ZERO = 1e-9


def check(
    analysis: Solution,
    answers: Answers,
    tolerance_percent: float | None = None,
    *,
    mechanism: str | None = None,
) -> CheckResult:
    """Every answer against the exact value. The tolerance is `tolerance_percent`,
    else the answers file's, else 5 %."""
    tol = (
        tolerance_percent
        if tolerance_percent is not None
        else answers.tolerance_percent
        if answers.tolerance_percent is not None
        else DEFAULT_TOLERANCE_PERCENT
    )
    frac = tol / 100.0
    exact = Exact(analysis, answers.grid)
    drawn = _drawn(analysis, answers, exact)
    rows: list[tuple[Answer, float, float | None, bool]] = []
    for a in answers.values:
        x = _exact(exact, a)
        if a.kind == "check_verdict":  # true or false: no deviation
            rows.append((a, x, None, a.value == x))
            continue
        band = _band(exact, a)
        if a.kind == "check_delta":  # a percentage: its deviation in percentage points
            deviation = a.value - x
            # on the student's grid: the points its diagram value's band gives δ
            limit = tol if band is None else tol * band
            rows.append((a, x, deviation, abs(deviation) <= limit))
            continue
        largest = _largest(exact, a)
        if abs(x) <= _ZERO * largest:  # an exact zero: within tol of the largest value
            rows.append((a, 0.0, None, abs(a.value) <= frac * largest))
            continue
        deviation = (a.value - x) / abs(x) * 100.0
        passed = abs(deviation) <= tol
        if band is not None:  # a hand-drawn curve: good to a share of its height
            passed = abs(a.value - x) <= frac * band
        rows.append((a, x, deviation, passed))
    # The joint diagnosis: the mistakes recomputed through the construction
    # that explain the failing values together (mistakes.py).
    failing = {k for k, (a, _, _, passed) in enumerate(rows) if not passed}
    named: dict[int, Cause] = diagnose(
        exact,
        list(answers.values),
        # the exact values as computed (not the zeros a row shows for them)
        [x if x or a.kind == "check_verdict" else _exact(exact, a) for a, x, _, _ in rows],
        {k for k in failing if answers.values[k].kind != "check_verdict"},
        frac,
        _exact,
        lambda k: _slips(answers.values[k], exact, rows[k][1], drawn),
    )
    # The values left, one by one: a slip of a single reading that matches clearly.
    for k in sorted(failing - set(named)):
        a, x = answers.values[k], rows[k][1]
        if a.kind == "check_verdict" or (x == 0.0 and rows[k][2] is None):
            continue
        best = clear(rank(a.value, x, _slips(a, exact, x, drawn)), frac)
        if best is not None:
            named[k] = best.causes[0]
    out = tuple(
        CheckedValue(a, float(x), None if dev is None else float(dev), bool(passed), named.get(k))
        for k, (a, x, dev, passed) in enumerate(rows)
    )
    grid = None
    if any(
        a.kind in ("diagram", "check_V", "check_a", "check_delta", "check_verdict")
        for a in answers.values
    ):
        grid = (
            (answers.grid.divisions, True)
            if answers.grid is not None
            else (analysis.require_diagrams().sheet_check.intervals, False)
        )
    return CheckResult(mechanism or str(analysis.mechanism.path), answers.path, tol, out, grid)


def check_file(
    mechanism_path: str | Path, answers_path: str | Path, tolerance_percent: float | None = None
) -> CheckResult:
    """`mmt-plans check FILE ANSWERS` as a function."""
    from ..solution import solve
    from ..spec import load

    analysis = solve(load(mechanism_path))
    answers = load_answers(answers_path, analysis)
    return check(analysis, answers, tolerance_percent, mechanism=str(mechanism_path))


def _slips(a: Answer, exact: Exact, x: float, drawn: list[Where]) -> list[Candidate]:
    """The candidates of a value's single-reading slips (the mistake models'
    own recomputations are diagnose's)."""
    if a.kind == "check_verdict":
        return []
    if a.kind in KINEMATIC:
        return list(kinematic_candidates(a, exact, x, drawn))
    return list(force_candidates(a, exact, x, slips_only=True))


def _band(exact: Exact, a: Answer) -> float | None:
    """On the student's grid (answers' `divisions`), a diagram's value is
    judged within the tolerance of the diagram's largest ordinate over the
    turn, not of its own size (a smooth curve drawn by hand through the
    chords' mid points is good to a share of its height, and a value near
    the axis has no relative precision): that largest value, in the answer's
    terms (mm for an ordinate, m/s or m/s² for the check's diagram column;
    for δ its largest over |plan| · 100 in percentage points / the tolerance
    in percent, i.e. largest / |plan|). None: judged as any value."""
    if exact.grid is None:
        return None
    sol = exact.solution
    n = sol.mechanism.study.positions
    if a.kind == "diagram" and a.extra[0] in ("V", "a"):
        col = 0 if a.extra[0] == "V" else 1
        return max(abs(exact.on_grid(i)[col]) for i in range(n)) / (a.mu or 1.0)
    if a.kind in ("check_V", "check_a") and a.extra[0] == "diagram":
        col = 0 if a.extra[1] == "v" else 1
        return max(abs(exact.on_grid(i)[col]) for i in range(n))
    if a.kind == "check_delta":
        col = 0 if a.extra[1] == "v" else 1
        largest = max(abs(exact.on_grid(i)[col]) for i in range(n))
        sc = sol.require_diagrams().sheet_check
        plan = next(
            v.plan for v in sc.values if v.index == a.where.index and v.quantity == a.extra[1]
        )
        return largest / abs(plan)
    return None


def _exact(exact: Exact, a: Answer) -> float:
    if a.kind in KINEMATIC:
        return exact.kinematic(a)
    return force_value(exact.forces(a.where), a, exact.solution.mu_l)


def _largest(exact: Exact, a: Answer) -> float:
    """The largest value of the answer's kind at its position: what "zero" is measured against."""
    from .quantities import size

    if a.kind in ("velocity", "acceleration", "velocity_plan_mm", "acceleration_plan_mm"):
        plan = exact.plan(a.where)
        images = plan.velocity_images if a.kind.startswith("velocity") else plan.acceleration_images
        big = max(size(v) for v in images.values())
        return big / a.mu if a.mu is not None and a.kind.endswith("_mm") else big
    if a.kind in ("omega", "eps"):
        plan = exact.plan(a.where)
        return max(abs(x) for x in (plan.omega if a.kind == "omega" else plan.eps).values())
    if a.kind in ("mu_V", "mu_a"):
        return abs(exact.kinematic(a))
    if a.kind in ("check_V", "check_a"):
        sc = exact.solution.require_diagrams().sheet_check
        q = a.extra[1]
        return max(max(abs(v.plan), abs(v.diagram)) for v in sc.values if v.quantity == q)
    if a.kind == "diagram":
        sol = exact.solution
        what = a.extra[0]
        vals = [
            exact.output(p.index)[("S", "V", "a").index(what)]
            for p in sol.positions
            if p.index is not None and sol.problem(sol.entry(p.index)) is None
        ]
        return max(abs(v) for v in vals) / (a.mu or 1.0)
    fa = exact.forces(a.where)
    if a.kind in ("weight", "inertia_force", "inertia_moment", "inertia_arm_m", "inertia_arm_mm"):
        return max(
            [
                abs(
                    force_value(
                        fa,
                        Answer(a.entry, a.where, a.kind, str(lid), 0.0, mu=a.mu),
                        exact.solution.mu_l,
                    )
                )
                for lid in fa.loads.links
            ]
        )
    if a.kind in ("group_arm_m", "group_arm_mm"):
        from .quantities import arm_about, arm_forces

        arms = [arm_about(F, P, B) for F, P, B, _ in arm_forces(fa).values()]
        return max(arms) / (a.mu or exact.solution.mu_l if a.kind == "group_arm_mm" else 1.0)
    big = max(
        [
            abs(fa.balancing_force_plans),
            abs(fa.balancing_force_lever),
            *(r.magnitude for r in fa.reactions.values()),
        ]
    )
    if a.kind == "balancing_moment":
        return max(abs(fa.balancing_moment), 1e-300)
    if a.kind == "force_plan_mm":
        return big / (a.mu or 1.0)
    if a.kind == "lever_mm":
        lever = fa.lever
        return max([lever.pa, *(abs(f.arm) for f in lever.forces)]) / (a.mu or 1.0)
    return big


def _drawn(analysis: Solution, answers: Answers, exact: Exact) -> list[Where]:
    """The positions whose plans are drawn: the analysis' and the answers file's."""
    out: dict[tuple, Where] = {}
    for i in analysis.plan_positions:
        w = exact.where(index=i)
        out[w.key] = w
    for a in answers.values:
        if a.kind in KINEMATIC and a.kind != "diagram":
            out.setdefault(a.where.key, a.where)
    return list(out.values())
