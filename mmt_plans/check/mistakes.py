"""Mistake models: a change to the method, run through the Solution's own
machinery, giving every value downstream of it.

A model is one mistake a student makes in the construction: the Coriolis
term of a group's acceleration plan reversed or left out, the normal
accelerations left out, a^τ of a link turned the wrong way (its ε taken the
other way about its pivot), the crank's speed in rpm taken as rad/s (or the
reverse), the crank angle in degrees taken as radians, the plans or the force
analysis made at another position, and the force analysis' own mistakes
(forces.force_analysis_at's keywords: inertia, weights, a force at the wrong
point, the lever not turned, R0d without F_bal). `Mistaken` is an `Exact`
whose plans and force analyses are those of the model, so every quantity a
student may give is read off them by the same functions as the exact one
(quantities.py): the groups' plans are solved by the dyad solvers' own legs
and `place`, the loads and force plans by `force_analysis_at`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from typing import TYPE_CHECKING, Any, Literal

import numpy as np

from ..errors import MmtError
from .causes import READING, Cause, Scenario, scenarios
from .quantities import Exact, Where

if TYPE_CHECKING:  # pragma: no cover
    from ..forces import ForceAnalysis
    from ..kinematics.chain import Sweep
    from ..kinematics.plans import PlanView
    from ..solution import Solution

# what a model changes: the plans (and the forces built on them), or only the forces
Reach = Literal["kinematics", "forces", "images"]
# the force analysis has two routes, the force plans by groups and Zhukovsky's
# lever: a student may make a mistake in one of them and not in the other
Route = Literal["", "plans", "lever"]


@dataclass(frozen=True)
class Construction:
    """How the student's plans are constructed: the textbook's method with
    the changes given (every default is the textbook's)."""

    coriolis: Literal["ok", "reversed", "left_out"] = "ok"
    coriolis_groups: tuple[str, ...] = ()  # the groups it is made in (() every group)
    normal_left_out: tuple[str, ...] = ()  # groups whose a^n are left out ("*": every group)
    eps_reversed: tuple[int, ...] = ()  # links whose a^τ is turned the wrong way
    omega_factor: float = 1.0  # ω1 used / ω1: 30/π for rpm taken as rad/s
    # the crank angle in degrees taken as radians; counted from the x axis, not
    # from position 0 (position i at i·360°/n in the drive's sense)
    angle: Literal["", "rad_as_deg", "deg_as_rad", "from_axis"] = ""


@dataclass(frozen=True)
class Model:
    """One mistake: what it changes (`construction`, force `options`, the
    position `instead` the plans or forces were made at), where (`at`, a
    Where.key; None: in every construction) and its name (`cause`)."""

    key: str
    cause: Cause
    reach: Reach
    construction: Construction | None = None
    options: tuple[tuple[str, Any], ...] = ()
    at: tuple | None = None
    instead: Where | None = None
    swapped: tuple[str, str, str] = ("", "", "")  # two points' images swapped on a plan
    route: Route = ""  # a force mistake made in one route only ("": in both)

    def on_route(self, kind: str) -> bool:
        """Whether a value of `kind` is made on this model's force route."""
        if not self.route or kind not in _FORCE_KINDS:
            return True
        if kind in _LOADS_KINDS:  # the loads are found before either route: unchanged
            return False
        return (kind in _LEVER_KINDS) == (self.route == "lever")

    def changes(self, where: Where, kind: Reach) -> bool:
        """Whether the model changes the construction `kind` at `where`."""
        if self.at is not None and self.at != where.key:
            return False
        if self.reach == "images":
            return kind == "kinematics"
        return kind == "forces" or self.reach == "kinematics"


class Mistaken(Exact):
    """The plans and force analyses of a solution with one mistake made."""

    def __init__(self, solution: Solution, model: Model, exact: Exact) -> None:
        super().__init__(solution)
        self.model = model
        self.exact = exact

    def plan(self, w: Where) -> PlanView:
        if not self.model.changes(w, "kinematics"):
            return self.exact.plan(w)
        if self.model.reach == "images":
            view = self.exact.plan(w)
            b, d, plans = self.model.swapped
            v_img, a_img = dict(view.velocity_images), dict(view.acceleration_images)
            if "velocity" in plans:
                v_img[b], v_img[d] = v_img[d], v_img[b]
            if "acceleration" in plans:
                a_img[b], a_img[d] = a_img[d], a_img[b]
            return replace(view, velocity_images=v_img, acceleration_images=a_img)
        if w.key not in self._plans:
            from ..kinematics.plans import plan_view

            phi, _ = self._angle(w)
            sweep = construct(self.solution, phi, self.model.construction or Construction())
            view = plan_view(sweep, 0, w.index)
            # the image a group's two equations give (where a mistake makes the
            # fields of its two links disagree there, the plan's point is this one)
            images = dict(view.acceleration_images)
            for plan in sweep.plans:
                if plan.group.kind in ("RRR", "RRP"):
                    z = complex(np.asarray(plan.a_X).reshape(-1)[0])
                    images[plan.X_name] = _xy(z)
            self._plans[w.key] = replace(view, acceleration_images=images)
        return self._plans[w.key]

    def forces(self, w: Where, **mistake: Any) -> ForceAnalysis:
        if not self.model.changes(w, "forces") or mistake:
            return self.exact.forces(w, **mistake)
        if w.key not in self._forces:
            from ..forces import force_analysis_at
            from ..forces.state import from_sweep

            sol = self.solution
            options = dict(self.model.options)
            if "weight_at" in options:
                options["weight_at"] = dict(options["weight_at"])
            phi, index = self._angle(w)
            if self.model.reach == "kinematics":
                sweep = construct(sol, phi, self.model.construction or Construction())
                stroke = sol.stroke_of(phi)
                state = from_sweep(sol.mechanism, sweep, 0, index, stroke)
            elif index is not None:
                state = sol.state(index)
            else:
                state = sol.state(phi1_deg=phi)
            self._forces[w.key] = force_analysis_at(state, mu_l=sol.mu_l, **options)
        return self._forces[w.key]

    def _angle(self, w: Where) -> tuple[float, int | None]:
        """The crank angle the construction at `w` was made at (and its position)."""
        if self.model.instead is not None:
            return self.model.instead.phi1_deg, self.model.instead.index
        c = self.model.construction
        if c is not None and c.angle == "deg_as_rad":
            return math.degrees(w.phi1_deg) % 360.0, None
        if c is not None and c.angle == "rad_as_deg":
            return math.radians(w.phi1_deg) % 360.0, None
        if c is not None and c.angle == "from_axis" and w.index is not None:
            sol = self.solution
            step = 360.0 / sol.mechanism.study.positions
            return (sol.sense_sign * step * w.index) % 360.0, None
        return w.phi1_deg, w.index


def _xy(z: complex) -> np.ndarray:
    arr = np.array([z.real, z.imag])
    arr.setflags(write=False)
    return arr


# a Motion's fields in LinkState's order (e, o, ω, v, ε, a)
_MOTION = (
    ("e", complex),
    ("o", complex),
    ("w", float),
    ("v", complex),
    ("eps", float),
    ("a", complex),
)


def _one(x: Any, dtype: type) -> np.ndarray:
    """A Motion's field at the one angle as a read-only array of one entry."""
    arr: np.ndarray = np.array(np.broadcast_to(np.asarray(x, dtype=dtype), (1,)))
    arr.setflags(write=False)
    return arr


def _cramer(det: Any, d1: Any, d2: Any, rhs: Any) -> tuple[Any, Any]:
    """x1, x2 of d1·x1 − d2·x2 = rhs with det = d2 × d1 (the plans' 2×2 system)."""
    from ..kinematics.geometry import cross

    with np.errstate(divide="ignore", invalid="ignore"):
        return cross(d2, rhs) / det, cross(d1, rhs) / det


def construct(solution: Solution, phi1_deg: float, c: Construction) -> Sweep:
    """The plans at one crank angle, built group by group as the textbook
    draws them (the dyad solvers' own legs, Cramer's rule and `place`), with
    the construction's changes made; a position that does not assemble raises
    its AssemblyError."""
    from ..kinematics.chain import Chain, LinkState, Sweep
    from ..kinematics.dyads.base import GroupPlan
    from ..kinematics.geometry import cross

    chain = solution.chain
    if c.omega_factor != 1.0:
        mech = solution.mechanism
        drive = replace(mech.drive, omega=mech.drive.omega * c.omega_factor)
        faster = Chain(replace(mech, drive=drive), chain.solvers)
        faster.branches, faster.choice = chain.branches, chain.choice
        chain = faster
    phi = np.array([float(phi1_deg)])
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        m = chain.place_all(np.radians(phi), chain.branches)
        failed, singular, plans = {}, {}, []
        for solver in chain.solvers:
            name = solver.group.name
            X_name, X, leg1, leg2 = solver.legs(m)
            det = cross(leg2.d, leg1.d)
            leg1.x, leg2.x = _cramer(det, leg1.d, leg2.d, leg2.V0 - leg1.V0)
            solver.after_velocities(m, leg1, leg2)
            for leg in (leg1, leg2):
                leg.n = leg.normal(m)
                if leg.kind == "slide" and c.coriolis != "ok":
                    if not c.coriolis_groups or name in c.coriolis_groups:
                        leg.n = -leg.n if c.coriolis == "reversed" else 0 * leg.n
                if leg.kind == "rotation" and (
                    "*" in c.normal_left_out or name in c.normal_left_out
                ):
                    leg.n = 0 * leg.n
            rhs = (leg2.a0 + leg2.n) - (leg1.a0 + leg1.n)
            leg1.y, leg2.y = _cramer(det, leg1.d, leg2.d, rhs)
            sin_angle = np.abs(det) / (np.abs(leg1.d) * np.abs(leg2.d))
            plan = GroupPlan(solver.group, X_name, X, (leg1, leg2), sin_angle)
            solver.place(m, plan)
            for leg in (leg1, leg2):
                if leg.kind == "rotation" and leg.link in c.eps_reversed:
                    mo = m[leg.link]
                    p = mo.local(leg.P)
                    mo.move_with(p, mo.vel_at(p), mo.acc_at(p), mo.w, -mo.eps)
            L1, L2 = m[solver.L1], m[solver.L2]
            bad = ~np.isfinite(np.broadcast_to(L1.o + L2.o + L1.e + L2.e, phi.shape))
            failed[name] = bad.copy()
            singular[name] = ~bad & ~np.broadcast_to(sin_angle > 1e-12, phi.shape)
            plans.append(plan)
    states = {
        lid: LinkState(
            e=_one(mo.e, complex),
            o=_one(mo.o, complex),
            omega=_one(mo.w, float),
            v=_one(mo.v, complex),
            eps=_one(mo.eps, float),
            a=_one(mo.a, complex),
            spin=_one(mo.spin, complex),
            spin_acc=_one(mo.spin_acc, complex),
        )
        for lid, mo in m.items()
    }
    sweep = Sweep(chain, phi, states, failed, singular, solved_plans=tuple(plans))
    problem = sweep.problem(0)
    if problem is not None:
        raise problem
    return sweep


# --- the models of a solution and an answers file ----------------------------------------


def models(exact: Exact, kin_at: list[Where], force_at: list[Where]) -> list[Model]:
    """Every mistake model for answers given at these positions: the
    construction's mistakes in every plan and at each position alone; the
    plans or forces of a position made at another one; the force analysis'
    mistakes."""
    sol = exact.solution
    mech = sol.mechanism
    out: list[Model] = []
    slide_groups, rotating = _groups(exact)
    constructions: list[tuple[str, Cause, Construction]] = []
    for g in slide_groups:
        label = (("group", g),)
        one = (g,) if len(slide_groups) > 1 else ()
        constructions += [
            (
                f"coriolis_reversed_{g}",
                Cause("cause_coriolis_reversed", label),
                Construction("reversed", one),
            ),
            (
                f"coriolis_left_out_{g}",
                Cause("cause_coriolis_left_out", label),
                Construction("left_out", one),
            ),
        ]
        if len(slide_groups) == 1:
            break
    if len(slide_groups) > 1:
        constructions += [
            ("coriolis_reversed", Cause("cause_coriolis_reversed_all"), Construction("reversed")),
            ("coriolis_left_out", Cause("cause_coriolis_left_out_all"), Construction("left_out")),
        ]
    if rotating:
        constructions.append(
            (
                "normal_left_out",
                Cause("cause_normal_left_out"),
                Construction(normal_left_out=("*",)),
            )
        )
    if len(rotating) > 1:
        for g in rotating:
            constructions.append(
                (
                    f"normal_left_out_{g}",
                    Cause("cause_normal_left_out_group", (("group", g),)),
                    Construction(normal_left_out=(g,)),
                )
            )
    for lid in _turning_links(exact):
        constructions.append(
            (
                f"tangential_reversed_{lid}",
                Cause("cause_tangential_reversed", (("link", str(lid)),)),
                Construction(eps_reversed=(lid,)),
            )
        )
    rpm = 30.0 / math.pi
    constructions += [
        ("rpm_as_rad", Cause("cause_rpm_as_rad"), Construction(omega_factor=rpm)),
        ("rad_as_rpm", Cause("cause_rad_as_rpm"), Construction(omega_factor=1.0 / rpm)),
        ("deg_as_rad", Cause("cause_deg_as_rad"), Construction(angle="deg_as_rad")),
        ("angle_from_axis", Cause("cause_angle_from_axis"), Construction(angle="from_axis")),
    ]
    places = list({w.key: w for w in [*kin_at, *force_at]}.values())
    for key, cause, c in constructions:
        out.append(Model(key, cause, "kinematics", c))
        if len(places) > 1:
            for w in places:
                out.append(Model(f"{key}@{w.key}", _at(cause, w), "kinematics", c, at=w.key))
    # two images swapped on a plan (the labels b and d written the other way round)
    points = [
        name for lid, link in mech.links.items() for name in link.points if name not in mech.frame
    ]
    points = list(dict.fromkeys(points))
    for w in kin_at:
        for i, b in enumerate(points):
            for d in points[i + 1 :]:
                for plans, what in (
                    ("velocity acceleration", "both"),
                    ("velocity", "velocity"),
                    ("acceleration", "acceleration"),
                ):
                    pair = (("first", b.lower()), ("second", d.lower()))
                    out.append(
                        Model(
                            f"images_{b}_{d}_{what}@{w.key}",
                            _at(Cause(f"cause_images_swapped_{what}", pair), w)
                            if len(kin_at) > 1
                            else Cause(f"cause_images_swapped_{what}", pair),
                            "images",
                            at=w.key,
                            swapped=(b, d, plans),
                        )
                    )
    # the plans or the forces of a position made at another position
    n = mech.study.positions
    for w in places:
        for j in range(n):
            if j == w.index:
                continue
            try:
                other = exact.where(index=j)
                if sol.problem(sol.entry(j)) is not None:
                    continue
            except MmtError:
                continue
            fields = (("position", str(j)),)
            if any(w.key == k.key for k in kin_at):
                out.append(
                    Model(
                        f"plans_at_{j}@{w.key}",
                        Cause("cause_plans_at_position", (*fields, ("at", _where(w)))),
                        "kinematics",
                        at=w.key,
                        instead=other,
                    )
                )
            if any(w.key == k.key for k in force_at):
                out.append(
                    Model(
                        f"forces_at_{j}@{w.key}",
                        Cause("cause_forces_at_position", (*fields, ("at", _where(w)))),
                        "forces",
                        at=w.key,
                        instead=other,
                    )
                )
    # or at another crank angle: half a turn on, or measured the other way round
    for w in places:
        for phi in ((w.phi1_deg + 180.0) % 360.0, (-w.phi1_deg) % 360.0):
            if any(abs((phi - p.phi1_deg + 180.0) % 360.0 - 180.0) < 1e-6 for p in sol.positions):
                continue  # a position: modelled above
            other = exact.where(phi1_deg=phi)
            at_angle: tuple[tuple[str, Any], ...] = (("angle", f"{phi:.6g}"), ("at", _where(w)))
            if any(w.key == k.key for k in kin_at):
                out.append(
                    Model(
                        f"plans_at_angle_{phi:.6g}@{w.key}",
                        Cause("cause_plans_at_angle", at_angle),
                        "kinematics",
                        at=w.key,
                        instead=other,
                    )
                )
            if any(w.key == k.key for k in force_at):
                out.append(
                    Model(
                        f"forces_at_angle_{phi:.6g}@{w.key}",
                        Cause("cause_forces_at_angle", at_angle),
                        "forces",
                        at=w.key,
                        instead=other,
                    )
                )
    for w in force_at:
        for sc in scenarios(exact):
            # the lever turned the wrong way only swaps F_bal's sign: a sign swapped
            if sc.group != "lever_wrong_way":
                whole = _force_model(sc, w, len(force_at) > 1)
                out.append(whole)
                for route in ("plans", "lever"):
                    out.append(replace(whole, key=f"{whole.key}@{route}", route=route))
        out.append(
            Model(
                f"r0d@{w.key}",
                Cause(
                    "cause_r0d_without_fbal",
                    (
                        ("name", exact.forces(w).driving_link.reaction.name),
                        ("link", str(mech.drive.link)),
                    ),
                ),
                "forces",
                options=(("balancing_in_r0d", False),),
                at=w.key,
            )
        )
    return out


def _force_model(sc: Scenario, w: Where, several: bool) -> Model:
    return Model(
        f"{sc.group}@{w.key}",
        _at(sc.cause, w) if several else sc.cause,
        "forces",
        options=sc.options,
        at=w.key,
    )


def _at(cause: Cause, w: Where) -> Cause:
    """The cause at one construction: "… (position 2)"."""
    return Cause("cause_at_position", (("what", cause), ("position", _where(w))))


def _where(w: Where) -> Cause:
    """ "position 2" or "φ1 = 210.862°", in the report's language."""
    if w.index is not None:
        return Cause("at_index", (("index", str(w.index)),))
    return Cause("at_phi", (("phi", f"{w.phi1_deg:g}"),))


def _groups(exact: Exact) -> tuple[list[str], list[str]]:
    """The groups with a slide on a turning link (a Coriolis term) and those with a rotation."""
    sweep = exact.solution.sweep
    slides, rotations = [], []
    for plan in sweep.plans:
        for leg in plan.legs:
            if leg.kind == "slide" and not isinstance(leg.n, complex) and np.any(leg.n != 0):
                slides.append(plan.group.name)
                break
        if any(leg.kind == "rotation" for leg in plan.legs):
            rotations.append(plan.group.name)
    return slides, rotations


def _turning_links(exact: Exact) -> list[int]:
    """Links turned about a pivot by a group's rotation leg (a^τ = ε × l)."""
    out: list[int] = []
    for plan in exact.solution.sweep.plans:
        for leg in plan.legs:
            if leg.kind == "rotation" and leg.link not in out:
                out.append(leg.link)
    return out


# --- the joint diagnosis -------------------------------------------------------------------


@dataclass(frozen=True)
class Explained:
    """The values (their indices in the answers) one mistake explains together."""

    model: Model
    values: frozenset[int]
    predicted: dict[int, float]
    everywhere: dict[int, float]  # its value of every answer it gives one for


def diagnose(
    exact: Exact,
    answers: list[Any],
    exact_values: list[float],
    failing: set[int],
    frac: float,
    value_of: Any,
    slips: Any = None,
) -> dict[int, Cause]:
    """The smallest set of mistakes that explains the failing values together
    (README, "Causes"): a model explains a failing value when its
    recomputation of the value is within a quarter of the tolerance of the
    student's; it is admissible when no value it makes fail (moves beyond the
    tolerance) is one the student got right. The model explaining most of the
    values not yet explained is taken, then the next; models that give the
    same numbers for those values are named together ("either … or …"). A
    model that explains a single value is taken only when no other admissible
    model explains it with another number. `value_of(mistaken, answer)` reads
    a value off a Mistaken."""
    from .causes import miss

    kin_at, force_at = [], []
    for a in answers:
        if a.kind in _PLAN_KINDS:
            kin_at.append(a.where)
        elif a.kind not in _DIAGRAM_KINDS:
            force_at.append(a.where)
    kin_at = list({w.key: w for w in kin_at}.values())
    force_at = list({w.key: w for w in force_at}.values())
    candidates: list[Explained] = []
    for model in models(exact, kin_at, force_at):
        mistaken = Mistaken(exact.solution, model, exact)
        explained: set[int] = set()
        predicted: dict[int, float] = {}
        everywhere: dict[int, float] = {}
        admissible = True
        for k, a in enumerate(answers):
            if model.at is not None and a.where.key != model.at:
                continue  # made in another construction: the value is unchanged
            if not model.on_route(a.kind):
                continue  # made on the other route of the force analysis: unchanged
            if a.kind in _DIAGRAM_KINDS and not _scales_diagrams(model):
                continue
            try:
                v = _predict(mistaken, model, a, exact_values[k], value_of)
            except (MmtError, KeyError, StopIteration, ValueError, ZeroDivisionError):
                continue  # the mistake removes the quantity (an arm of a force left out)
            if v is None or not math.isfinite(v):
                continue
            everywhere[k] = v
            x = exact_values[k]
            moved = abs(v - x) > 1e-9 * max(abs(x), abs(v))
            if not moved:
                continue
            close = miss(a.value, v) <= frac / 4
            if k in failing:
                if close:
                    explained.add(k)
                    predicted[k] = v
            elif abs(v - x) > frac * abs(x) and not close:
                admissible = False
                break
        # two images swapped show in two values at least (one is another point's image)
        if admissible and len(explained) >= (2 if model.reach == "images" else 1):
            candidates.append(Explained(model, frozenset(explained), predicted, everywhere))

    def _joins(c: Explained, a: Any, k: int, r0d: bool) -> bool:
        """Whether the model (with R0d without F_bal) reproduces the value within
        the tolerance, nearer than the exact value."""
        model = c.model
        if r0d:
            if a.kind not in _FORCE_KINDS or model.reach != "forces":
                return False
            model = replace(
                model, key=model.key + "+r0d", options=(*model.options, ("balancing_in_r0d", False))
            )
        if not model.changes(a.where, "forces" if a.kind in _FORCE_KINDS else "kinematics"):
            return False
        if not model.on_route(a.kind):
            return False
        x = exact_values[k]
        try:
            v = _predict(Mistaken(exact.solution, model, exact), model, a, x, value_of)
        except (MmtError, KeyError, StopIteration, ValueError, ZeroDivisionError):
            return False
        return v is not None and miss(a.value, v) <= frac and miss(a.value, v) < miss(a.value, x)

    named: dict[int, Cause] = {}
    chosen: list[tuple[list[Explained], set[int]]] = []
    left = set(failing)
    while left:
        best: list[Explained] = []
        gain = 0
        for c in candidates:
            g = len(c.values & left)
            if g > gain:
                best, gain = [c], g
            elif g == gain and g > 0:
                best.append(c)
        if gain == 0:
            break
        first = best[0]
        covered = first.values & left
        same = [
            c
            for c in best
            if c.values & left == covered
            and all(_equal(c.predicted[k], first.predicted[k]) for k in covered)
        ]
        if gain == 1:
            # one value near one of many models' numbers may be chance: the
            # nearest must match to a reading's precision (a force left out:
            # its 0 exactly) and the next other number be farther by more
            (k,) = covered
            given = answers[k].value
            others = sorted(
                (c for c in candidates if k in c.values),
                key=lambda c: miss(given, c.predicted[k]),
            )
            first = others[0]
            if first.model.instead is not None:
                # another position's or angle's value is one of many: a slip (causes.py)
                left -= covered
                continue
            nearest = miss(given, first.predicted[k])
            same = [c for c in others if _equal(c.predicted[k], first.predicted[k])]
            rest = [miss(given, c.predicted[k]) for c in others if c not in same]
            if nearest > READING or (rest and rest[0] - nearest <= READING):
                left -= covered
                continue
        # of one kind of mistake (one link's, links 2–n, every link) giving the
        # same numbers for every value, the most specific one
        one: dict[tuple, Explained] = {}
        for c in sorted(same, key=lambda c: _specific(c.model.key)):
            numbers = tuple(sorted((k, f"{v:.9g}") for k, v in c.everywhere.items()))
            one.setdefault((_family(c.model.key), numbers), c)
        alternatives = list(one.values())
        for k in covered:
            named[k] = _cause_of(alternatives, _same_slips(slips, k, first.predicted[k]))
        left -= covered
        if gain > 1:
            chosen.append((alternatives, set(covered)))
    # The failing values of a construction that a mistake explaining several
    # of its values reproduces within the tolerance, nearer than the exact
    # value, join it (a drawing's own error on top of the mistake); a
    # reaction of the frame on the driving link may also have been taken
    # from the link's polygon without F_bal. A value that only some of the
    # alternatives ("either … or …") reproduce tells them apart.
    for alternatives, group in chosen:
        joined: dict[int, tuple[list[Explained], bool]] = {}
        for k in sorted(left):
            fits = [c for c in alternatives if _joins(c, answers[k], k, False)]
            r0d = False
            if not fits:
                fits = [c for c in alternatives if _joins(c, answers[k], k, True)]
                r0d = True
            if fits:
                joined[k] = (fits, r0d)
        for fits, _ in joined.values():
            if len(fits) < len(alternatives):
                alternatives = fits
        for k, (fits, r0d) in joined.items():
            if not any(c in alternatives for c in fits):
                continue
            cause = _cause_of(alternatives)
            if r0d:
                fa = exact.forces(answers[k].where)
                cause = Cause(
                    "cause_r0d_without_fbal_and",
                    (
                        ("name", fa.driving_link.reaction.name),
                        ("link", str(fa.driving_link.link)),
                        ("also", replace(cause, group=None)),
                    ),
                    cause.group,
                )
            named[k] = cause
            left.discard(k)
        for k in group:
            named[k] = _cause_of(
                alternatives, _same_slips(slips, k, alternatives[0].predicted.get(k))
            )
    return named


_PLAN_KINDS = {
    "velocity",
    "acceleration",
    "omega",
    "eps",
    "velocity_plan_mm",
    "acceleration_plan_mm",
    "mu_V",
    "mu_a",
}
_FORCE_KINDS = {
    "balancing_force_plans",
    "balancing_force_lever",
    "balancing_moment",
    "reaction",
    "reaction_component",
    "weight",
    "inertia_force",
    "inertia_moment",
    "inertia_arm_m",
    "inertia_arm_mm",
    "force_plan_mm",
    "lever_mm",
    "group_arm_m",
    "group_arm_mm",
}
_LEVER_KINDS = {"balancing_force_lever", "lever_mm"}
_LOADS_KINDS = {"weight", "inertia_force", "inertia_moment", "inertia_arm_m", "inertia_arm_mm"}
_DIAGRAM_KINDS = {"diagram", "check_V", "check_a", "check_delta", "check_verdict"}


def _scales_diagrams(model: Model) -> bool:
    c = model.construction
    return c is not None and c.omega_factor != 1.0 and model.at is None


def _predict(mistaken: Mistaken, model: Model, a: Any, x: float, value_of: Any) -> float | None:
    """The answer's value with the model's mistake made."""
    if a.kind in _LOADS_KINDS and model.options:
        return None  # a force left out of the plans is still in the loads table
    if a.kind in _DIAGRAM_KINDS:
        if a.kind in ("check_verdict", "check_delta"):
            return None
        f = model.construction.omega_factor if model.construction else 1.0
        what = a.extra[0] if a.kind == "diagram" else a.extra[1]
        power = {"S": 0, "V": 1, "v": 1, "a": 2}[what]
        return x * f**power
    return float(value_of(mistaken, a))


def _family(key: str) -> str:
    """A model's kind without its link or group: shift_reversed_2 and shift_reversed."""
    import re

    base = re.sub(r"_(both|velocity|acceleration)$", "", key.split("@")[0])
    base = re.sub(r"_[\d\-]+$", "", base)
    return {"inertia_others": "inertia", "inertia_all": "inertia", "moments_all": "at_s"}.get(
        base, base
    )


def _specific(key: str) -> int:
    """0 for a mistake of one link or group, 1 for links 2–n, 2 for every link."""
    import re

    base = key.split("@")[0]
    if re.search(r"_[\d\-]+$", base) or base.endswith(("_velocity", "_acceleration")):
        return 0
    return 1 if base.endswith("others") else 2


def _equal(x: float, y: float) -> bool:
    return abs(x - y) <= 1e-9 * max(abs(x), abs(y), 1e-300)


def _cause_of(alternatives: list[Explained], slips: tuple[Cause, ...] = ()) -> Cause:
    return _either(
        [replace(c.model.cause, group=c.model.key.split("@")[0]) for c in alternatives]
        + list(slips)
    )


# slips of a single reading that are a model's mistake seen in one value
_SAME_AS_A_MODEL = {"cause_other_position", "cause_other_point", "cause_other_segment"}


def _same_slips(slips: Any, k: int, value: float | None) -> tuple[Cause, ...]:
    """The slips of a single reading (`slips(k)`: their candidates) that give
    the model's number for the value: named with it ("either … or …")."""
    if slips is None or value is None:
        return ()
    return tuple(
        c.cause
        for c in slips(k)
        if c.cause.group is None and c.cause.key not in _SAME_AS_A_MODEL and _equal(c.value, value)
    )


def _either(causes: list[Cause]) -> Cause:
    """One cause, or "either … or …" of mistakes that give the same numbers."""
    unique = list(dict.fromkeys(causes))
    if len(unique) == 1:
        return unique[0]
    rest = unique[-1]
    for c in reversed(unique[1:-1]):
        rest = Cause("cause_or", (("first", c), ("second", rest)))
    return Cause("cause_either", (("first", unique[0]), ("second", rest)), "either")
