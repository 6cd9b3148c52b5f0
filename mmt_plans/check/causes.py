"""Why a value is wrong: the slips of a single reading, and the force
analysis' mistakes as scenarios for the mistake models (mistakes.py).

A slip is one specific mistake in reading one value, recomputed: a sign
swapped; the other plan's μ or a neighbouring μ of the standard series; the
image of another point, plan or position; another pair's reaction, another
link's value, another force's arm or an arm from another point; a plan's
known component drawn reversed. It is named when the student's value matches
it within a quarter of the tolerance and clearly better than every other
candidate (`clear`), a slip among many like it only to a reading's precision
(README, "Checking a student's work"). Nothing else is guessed: a wrong value
with no such match and no mistake model explaining it is "wrong, cause
unknown".
"""

from __future__ import annotations

import math
from collections.abc import Iterator
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np

from ..scales import series
from .quantities import (
    CHECK_KINDS,
    POLE,
    Answer,
    Exact,
    Where,
    arm_about,
    arm_forces,
    force_value,
    size,
)

if TYPE_CHECKING:  # pragma: no cover
    from ..forces import ForceAnalysis

# Two candidates closer than this (relative) are the same value: one mistake
# that another implies (the crank's radial inertia force moves no F_bal).
SAME = 1e-9

# A value read off a drawing to 3 significant figures is good to about 0.5 %:
# two candidates nearer each other than that cannot be told apart.
READING = 0.005

KINEMATIC = {
    "velocity",
    "acceleration",
    "omega",
    "eps",
    "velocity_plan_mm",
    "acceleration_plan_mm",
    "mu_V",
    "mu_a",
    "diagram",
    "check_V",
    "check_a",
    "check_delta",
    "check_verdict",
}


# the fields of a cause that are values of the exact solution (`--hide-exact` hides them)
REVEALING = ("value", "exact", "mm")


@dataclass(frozen=True)
class Cause:
    """A named mistake: a catalogue key of [check] and its fields (numbers are
    formatted in the report's language); `group` the force mistake it belongs
    to, shared by the values it explains."""

    key: str
    fields: tuple[tuple[str, Any], ...] = ()
    group: str | None = None

    def text(self, cat: Any, *, hide_values: bool = False) -> str:
        """In the catalogue's language; `hide_values` leaves out the numbers
        that would give an exact value away (`--hide-exact`)."""
        hidden = cat.word("check", "hidden_value")
        fields = {
            k: (
                hidden
                if hide_values and k in REVEALING
                else cat.number(v, 4)
                if isinstance(v, float)
                else v.text(cat, hide_values=hide_values)
                if isinstance(v, Cause)
                else str(v)
            )
            for k, v in self.fields
        }
        return cat.word("check", self.key, **fields)


@dataclass(frozen=True)
class Candidate:
    value: float
    cause: Cause


# --- the force analysis with one mistake made ------------------------------------------


@dataclass(frozen=True)
class Scenario:
    group: str  # the mistake (without R0d's): shared by the values it explains
    cause: Cause
    options: tuple[tuple[str, Any], ...]
    # also recomputed with R0d without F_bal (a force at the wrong point is not:
    # its small change would only blur R0d's own mistake)
    combines: bool = True


def scenarios(exact: Exact) -> list[Scenario]:
    mech = exact.solution.mechanism
    moving = list(mech.links)
    d = mech.drive.link
    others = [lid for lid in moving if lid != d]
    heavy = [lid for lid in moving if mech.links[lid].mass or mech.links[lid].J]
    # a force applied at the wrong point: F_in of one link at S (its M_in left
    # out), F_in shifted to the wrong side of S; named before the mistakes of
    # every link that give the same value where only one link turns
    turning = [lid for lid in moving if mech.links[lid].J]
    one_link: list[Scenario] = []
    if len(turning) > 1:
        for lid in turning:
            kept = tuple(x for x in moving if x != lid)
            one_link += [
                Scenario(
                    f"at_s_{lid}",
                    Cause("cause_inertia_at_s", (("link", str(lid)),)),
                    (("inertia_moments", kept),),
                    False,
                ),
                Scenario(
                    f"shift_reversed_{lid}",
                    Cause("cause_shift_reversed", (("link", str(lid)),)),
                    (("inertia_moments_reversed", (lid,)),),
                    False,
                ),
            ]
    out = [
        Scenario(
            "inertia_others",
            Cause("cause_inertia_links", (("links", _links(others)),)),
            (("inertia_forces", (d,)), ("inertia_moments", (d,))),
        ),
        Scenario(
            "inertia_all",
            Cause("cause_inertia_all"),
            (("inertia_forces", ()), ("inertia_moments", ())),
        ),
        *one_link,
        Scenario("moments_all", Cause("cause_moments_all"), (("inertia_moments", ()),)),
        Scenario("gravity", Cause("cause_gravity"), (("gravity", False),)),
    ]
    if turning:
        out.append(
            Scenario(
                "shift_reversed",
                Cause("cause_shift_reversed_all")
                if len(turning) > 1
                else Cause("cause_shift_reversed", (("link", str(turning[0])),)),
                (("inertia_moments_reversed", tuple(turning)),),
                False,
            )
        )
    if len(heavy) > 1:
        for lid in heavy:
            kept = tuple(x for x in moving if x != lid)
            out.append(
                Scenario(
                    f"inertia_{lid}",
                    Cause("cause_inertia_link", (("link", str(lid)),)),
                    (("inertia_forces", kept), ("inertia_moments", kept)),
                )
            )
    out += _weights_elsewhere(exact)
    s = 1.0 if mech.drive.sense == "ccw" else -1.0
    out += [
        Scenario("lever_not_turned", Cause("cause_lever_not_turned"), (("lever_turn_deg", 0.0),)),
        Scenario(
            "lever_wrong_way",
            Cause("cause_lever_wrong_way"),
            (("lever_turn_deg", 90.0 * s),),
        ),
    ]
    return out


def _weights_elsewhere(exact: Exact) -> list[Scenario]:
    """G_i applied at each point of link i that is not its centre of mass."""
    mech = exact.solution.mechanism
    out = []
    for lid, link in mech.links.items():
        if not link.mass:
            continue
        length = max(link.length, 1e-300)
        for name in link.points:
            if abs(complex(*link.points[name]) - complex(*link.cm)) <= 1e-9 * length:
                continue
            out.append(
                Scenario(
                    f"weight_{lid}_{name}",
                    Cause("cause_weight_at", (("link", str(lid)), ("point", name))),
                    (("weight_at", ((lid, name),)),),
                    False,
                )
            )
    return out


def _links(links: list[int]) -> str:
    if len(links) > 2 and links == list(range(links[0], links[-1] + 1)):
        return f"{links[0]}–{links[-1]}"
    return ", ".join(str(x) for x in links)


def force_candidates(
    a: Answer, exact: Exact, x: float, *, slips_only: bool = False
) -> Iterator[Candidate]:
    """The value with each force mistake made; `slips_only`: only the slips of
    a single reading (a sign, another pair's reaction, link's value or arm)."""
    sol = exact.solution
    w = a.where
    mu_l = sol.mu_l
    d = sol.mechanism.drive.link
    is_r0d = (
        a.kind in ("reaction", "reaction_component", "force_plan_mm")
        and _is_r0d(a, d)
        and not slips_only
    )
    if a.signed:
        yield Candidate(-x, Cause("cause_sign", (("exact", x),)))
    for sc in [] if slips_only else scenarios(exact):
        if sc.group.startswith("lever") and a.kind not in ("balancing_force_lever", "lever_mm"):
            continue
        fa = exact.forces(w, **dict(sc.options))
        v = _value(fa, a, mu_l)
        if v is not None:
            yield Candidate(v, Cause(sc.cause.key, sc.cause.fields, sc.group))
    if is_r0d:
        fa = exact.forces(w, balancing_in_r0d=False)
        r0d = (("name", fa.driving_link.reaction.name), ("link", str(d)))
        yield Candidate(force_value(fa, a, mu_l), Cause("cause_r0d_without_fbal", r0d, "r0d"))
        for sc in scenarios(exact):
            if sc.group.startswith("lever") or not sc.combines:
                continue
            fa = exact.forces(w, balancing_in_r0d=False, **dict(sc.options))
            v = _value(fa, a, mu_l)
            if v is None:
                continue
            yield Candidate(
                v,
                Cause(
                    "cause_r0d_without_fbal_and",
                    (*r0d, ("also", Cause(sc.cause.key, sc.cause.fields))),
                    sc.group,
                ),
            )
    fa = exact.forces(w)
    if a.kind == "reaction":
        r = _reaction_of(fa, a.name)
        for other in fa.reactions.values():
            if {other.by, other.on} != {r.by, r.on}:
                yield Candidate(
                    other.magnitude,
                    Cause(
                        "cause_other_reaction", (("name", other.name), ("value", other.magnitude))
                    ),
                )
    if a.kind in ("group_arm_m", "group_arm_mm"):
        yield from _arm_candidates(a, fa, mu_l)
    if a.kind in ("weight", "inertia_force", "inertia_moment", "inertia_arm_m", "inertia_arm_mm"):
        for lid in fa.loads.links:
            if str(lid) != a.name:
                v = force_value(fa, Answer(a.entry, w, a.kind, str(lid), a.value, mu=a.mu), mu_l)
                yield Candidate(v, Cause("cause_other_link", (("link", str(lid)), ("value", v))))


def _value(fa: ForceAnalysis, a: Answer, mu_l: float) -> float | None:
    """The answer's quantity in a force analysis with a mistake made; None where
    the mistake removes it (the arm of an inertia force left out)."""
    try:
        return force_value(fa, a, mu_l)
    except (KeyError, StopIteration):
        return None


def _arm_candidates(a: Answer, fa: ForceAnalysis, mu_l: float) -> Iterator[Candidate]:
    """A group's arm h' measured from another point than the inner pin, of
    the link or of the group's other link, or another force's arm of the
    group's equations."""
    forces = arm_forces(fa)
    F, P, B, link = forces[a.name]
    scale = 1.0 if a.kind == "group_arm_m" else (a.mu or mu_l)
    state = fa.loads.state
    group = next((g.links for g in fa.groups if link in g.links), (link,))
    points = {n: _xy(state.point(lid, n)) for lid in group for n in state.mech.links[lid].points}
    pivot = next((n for n, Q in points.items() if size(Q - B) < 1e-9), "B")
    for n, Q in points.items():
        if size(Q - B) <= 1e-9 * max(size(P - B), 1e-300):
            continue
        v = arm_about(F, P, Q) / scale
        yield Candidate(v, Cause("cause_arm_from", (("point", n), ("pivot", pivot), ("value", v))))
    for other, (F2, P2, B2, link2) in forces.items():
        if other != a.name and link2 in group:
            v = arm_about(F2, P2, B2) / scale
            yield Candidate(v, Cause("cause_other_arm", (("force", other), ("value", v))))


def _xy(z: complex) -> np.ndarray:
    return np.array([z.real, z.imag])


def _is_r0d(a: Answer, d: int) -> bool:
    name = a.extra[0] if a.kind == "reaction_component" else a.name
    return name in ("R0d", f"R0{d}", f"R{d}0", f"R0_{d}", f"R{d}_0")


def _reaction_of(fa: ForceAnalysis, name: str):
    from .quantities import reaction_links

    return fa.reaction(*reaction_links(name, fa))


# --- kinematics -------------------------------------------------------------------------

_OTHER = {
    "velocity": "acceleration",
    "acceleration": "velocity",
    "omega": "eps",
    "eps": "omega",
    "velocity_plan_mm": "acceleration_plan_mm",
    "acceleration_plan_mm": "velocity_plan_mm",
}


def kinematic_candidates(
    a: Answer, exact: Exact, x: float, drawn: list[Where]
) -> Iterator[Candidate]:
    if a.signed:
        yield Candidate(-x, Cause("cause_sign", (("exact", x),)))
    yield from _scale_slips(a, x)
    if a.kind in ("check_V", "check_a"):  # the other column of the check's table
        column, quantity = a.extra
        other = "diagram" if column == "plan" else "plan"
        v = exact.kinematic(
            Answer(a.entry, a.where, a.kind, a.name, a.value, extra=(other, quantity))
        )
        yield Candidate(v, Cause(f"cause_check_{other}", (("value", v),)))
    if a.kind in ("mu_V", "mu_a", "diagram", *CHECK_KINDS):
        return
    plan = exact.plan(a.where)
    other = _OTHER[a.kind]
    if a.kind in ("velocity", "acceleration", "omega", "eps"):
        v = exact.kinematic(a, kind=other)
        yield Candidate(v, Cause(f"cause_read_off_{other}", (("value", v),)))
        if a.kind in ("velocity", "acceleration") and a.mu and a.other_mu:
            mm = v / a.other_mu
            yield Candidate(
                mm * a.mu,
                Cause(
                    "cause_other_plan_segment",
                    (
                        ("segment", ("pi" if other == "acceleration" else "p") + a.name.lower()),
                        ("mm", mm),
                        ("mu", a.mu),
                    ),
                ),
            )
    elif a.other_mu is not None and a.segment is not None:
        other_answer = Answer(
            a.entry, a.where, other, a.name, a.value, mu=a.other_mu, segment=a.segment
        )
        v = exact.kinematic(other_answer)
        yield Candidate(v, Cause(f"cause_read_off_{other}", (("value", v),)))
    for w in drawn:
        if w.key != a.where.key:
            v = exact.kinematic(a, w)
            yield Candidate(
                v,
                Cause(
                    "cause_other_position",
                    (
                        ("position", str(w.index) if w.index is not None else f"{w.phi1_deg:g}°"),
                        ("value", v),
                    ),
                ),
            )
    if a.kind in ("velocity", "acceleration"):
        for n in plan.velocity_images:
            if n != a.name:
                v = exact.kinematic(Answer(a.entry, a.where, a.kind, n, a.value))
                yield Candidate(v, Cause("cause_other_point", (("point", n), ("value", v))))
    elif a.kind in ("omega", "eps"):
        for lid in plan.omega:
            if str(lid) != a.name:
                v = exact.kinematic(Answer(a.entry, a.where, a.kind, str(lid), a.value, a.signed))
                yield Candidate(v, Cause("cause_other_link", (("link", str(lid)), ("value", v))))
    elif a.segment is not None:
        start, end = a.segment
        for n in [POLE, *plan.velocity_images]:
            for seg in ((start, n), (n, end)):
                if n in a.segment or seg[0] == seg[1]:
                    continue
                v = exact.kinematic(
                    Answer(a.entry, a.where, a.kind, a.name, a.value, mu=a.mu, segment=seg)
                )
                from .answers import segment_name

                yield Candidate(
                    v,
                    Cause(
                        "cause_other_segment",
                        (("segment", segment_name(a.kind, seg)), ("value", v)),
                    ),
                )
    yield from _reversed_components(a, exact)


def _reversed_components(a: Answer, exact: Exact) -> Iterator[Candidate]:
    """The group's point found with one known component (a^n or a^k) drawn
    reversed: the two direction lines then meet elsewhere."""
    if a.kind not in ("acceleration", "acceleration_plan_mm"):
        return
    plan = exact.plan(a.where)
    for g in plan.groups:
        comps = g.acceleration
        if len(comps) != 4:
            continue
        n1, t1, n2, t2 = comps
        if a.kind == "acceleration" and a.name != g.point:
            continue
        if a.kind == "acceleration_plan_mm" and not (
            a.segment in ((POLE, g.point), (g.point, POLE))
            or (a.segment is None and a.extra[0] in (t1.label, t2.label))
        ):
            continue
        for flip, known in ((0, n1), (1, n2)):
            if known.magnitude <= SAME * max(t1.magnitude, t2.magnitude, 1e-300):
                continue
            image = _meet(n1, t1, n2, t2, flip)
            if image is None:
                continue
            X, y1, y2 = image
            if a.kind == "acceleration":
                v = size(X)
            elif a.segment is not None:
                v = size(X) / (a.mu or 1.0)
            else:
                v = (y1 if a.extra[0] == t1.label else y2) / (a.mu or 1.0)
            yield Candidate(v, Cause("cause_component_reversed", (("what", known.label),)))


def _meet(n1, t1, n2, t2, flip: int):
    """Where a0_1 ± n1 + y1·d1 = a0_2 ± n2 + y2·d2 (one of the two n reversed)."""
    d1, d2 = (np.asarray(t.vector, float) for t in (t1, t2))
    if size(d1) == 0 or size(d2) == 0:
        return None
    d1, d2 = d1 / size(d1), d2 / size(d2)
    s1, s2 = (-1.0, 1.0) if flip == 0 else (1.0, -1.0)
    p1 = np.asarray(n1.start, float) + s1 * np.asarray(n1.vector, float)
    p2 = np.asarray(n2.start, float) + s2 * np.asarray(n2.vector, float)
    m = np.column_stack([d1, -d2])
    if abs(np.linalg.det(m)) < 1e-12:
        return None
    y1, y2 = np.linalg.solve(m, p2 - p1)
    return p1 + y1 * d1, abs(float(y1)), abs(float(y2))


def _scale_slips(a: Answer, x: float) -> Iterator[Candidate]:
    """The other plan's μ, or a neighbouring μ of the standard series, in place
    of the student's own stated μ."""
    if a.mu is None:
        return
    names = {
        "velocity": ("mu_V", "mu_a"),
        "velocity_plan_mm": ("mu_V", "mu_a"),
        "acceleration": ("mu_a", "mu_V"),
        "acceleration_plan_mm": ("mu_a", "mu_V"),
        "diagram": ("mu_" + (a.extra[0] if a.extra else "S"), ""),
    }
    if a.kind not in names:
        return
    mine, other = names[a.kind]
    reads = a.kind in ("velocity", "acceleration")  # value = segment × μ
    if a.other_mu is not None:
        f = a.other_mu / a.mu if reads else a.mu / a.other_mu
        yield Candidate(
            x * f,
            Cause(
                "cause_mu_multiplied" if reads else "cause_mu_divided",
                (("used", other), ("used_mu", a.other_mu), ("mine", mine), ("mu", a.mu)),
            ),
        )
    for nb in _neighbours(a.mu):
        f = nb / a.mu if reads else a.mu / nb
        yield Candidate(
            x * f,
            Cause(
                "cause_series_multiplied" if reads else "cause_series_drawn",
                (("used_mu", nb), ("mine", mine), ("mu", a.mu)),
            ),
        )


def _neighbours(mu: float) -> tuple[float, float]:
    """The standard-series values just below and just above μ."""
    below = [s for s in series(mu / 2, mu) if s < mu * (1 - 1e-9)]
    above = [s for s in series(mu, mu * 2) if s > mu * (1 + 1e-9)]
    return below[-1], above[0]


# --- choosing ---------------------------------------------------------------------------


@dataclass(frozen=True)
class Ranked:
    miss: float  # |student − candidate| / |candidate|
    causes: tuple[Cause, ...]  # every mistake that gives this same value


def rank(value: float, exact_value: float, candidates: list[Candidate]) -> list[Ranked]:
    """Distinct candidate values, nearest the student's first; a candidate equal
    to the exact value explains nothing."""
    merged: list[tuple[float, list[Cause]]] = []
    for c in candidates:
        # a zero candidate stays: a force left out is a 0 in the student's plan
        if not np.isfinite(c.value):
            continue
        if abs(c.value - exact_value) <= SAME * max(abs(exact_value), abs(c.value)):
            continue
        for v, causes in merged:
            if abs(v - c.value) <= SAME * max(abs(v), abs(c.value)):
                causes.append(c.cause)
                break
        else:
            merged.append((c.value, [c.cause]))
    out = [Ranked(miss(value, v), tuple(causes)) for v, causes in merged]
    out.sort(key=lambda r: r.miss)
    return out


def miss(value: float, candidate: float) -> float:
    """|value − candidate| / |candidate|; against a zero candidate, 0 for a
    zero (the force left out) and infinitely far for anything else."""
    if candidate == 0.0:
        return 0.0 if value == 0.0 else math.inf
    return abs(value - candidate) / abs(candidate)


def clear(ranked: list[Ranked], tol: float) -> Ranked | None:
    """The best candidate when it is within a quarter of the tolerance and
    clearly better than the next: that one is not, or it is farther by more
    than a reading's precision (READING)."""
    if not ranked or ranked[0].miss > tol / 4:
        return None
    if len(ranked) > 1:
        second = ranked[1].miss
        if second <= tol / 4 and second - ranked[0].miss <= READING:
            return None
    # a slip among many like it (another position's, point's, segment's,
    # link's value): a random error lands near one of them by chance, so it
    # must match to a reading's precision
    if ranked[0].miss > READING and all(c.key in MANY for c in ranked[0].causes):
        return None
    return ranked[0]


MANY = {
    "cause_other_position",
    "cause_other_point",
    "cause_other_segment",
    "cause_other_link",
    "cause_other_reaction",
    # the neighbours of a μ in the standard series: fixed ratios 0.8, 1.25 …
    "cause_series_multiplied",
    "cause_series_drawn",
}
