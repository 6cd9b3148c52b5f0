"""The diagnoser against a corpus of student work made by an independent
construction (corpus.py): the rates of README's table.

Each answers file is a student's sheet: the plans at one or two positions,
the force analysis at one, every value read off with a drawing's error. A
file makes one or two mistakes really (in corpus.py's own construction);
the values a mistake leaves unchanged carry 2–4 % drawing error, the values
it changes 0–1 % reading error on top of it. The rates:

- right causes: of the failing values a listed mistake made ("wrong"), those
  whose cause names that mistake (alone or among "either … or …");
- false causes: of the failing values (those a listed mistake made and those
  15–60 % off by no listed mistake, "wrong, unlisted"), those named with a
  mistake that was not made;
- false fails: values no mistake changed that fail (drawn within 4 %).

    PYTHONPATH=. python -m tests.check.test_corpus     # prints README's table
"""

from __future__ import annotations

import math
from collections import defaultdict
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import pytest

import mmt_plans
from mmt_plans.check import check, loads_answers

from .corpus import MECHANISMS, ForceMethod, Forces, Kin, Mechanism, Method, forces

RPM = 30.0 / math.pi
MU_V, MU_A, MU_F = 0.02, 0.5, 50.0


@dataclass(frozen=True)
class Sheet:
    """One student's answers file: where they drew and what they did wrong."""

    name: str
    mistakes: tuple[str, ...]  # the tool's model families it should name
    kin_at: tuple[int, ...]
    force_at: int
    method: Method = Method()  # their construction of the plans (every position)
    force_method: ForceMethod = ForceMethod()
    plans_from: dict[int, int] = field(default_factory=dict)  # position -> drawn at
    forces_from: int | None = None  # the force analysis made at this position
    forces_turned: float = 0.0  # … or at its crank angle plus this (degrees)
    forces_mirrored: bool = False  # … or at minus its crank angle (measured the other way)
    method_at: int | None = None  # the construction's mistake made at this position only
    degrees_as_radians: bool = False  # the crank angle in degrees taken as radians
    from_axis: bool = False  # position i at i·360°/n from the x axis, not from position 0
    swapped: tuple[str, str] | None = None  # two images swapped on both plans
    slips: bool = False  # a sign swapped, a segment read at the other plan's μ
    unlisted: bool = False  # a third of the values wrong by no listed mistake
    arm_from: tuple[str, str] | None = None  # (force, point): its arm h' taken about that point


POINTS = {
    "shaper": ("A", "B", "D", "S3", "S4"),
    "crosshead": ("A", "B", "D", "S2", "S4", "S5"),
    "press": ("A", "B", "D", "E", "S2", "S3", "S4"),
}
SEGMENTS = {
    "shaper": (("", "B"), ("", "D"), ("B", "D")),
    "crosshead": (("", "B"), ("", "D"), ("A", "B")),
    "press": (("", "B"), ("", "E"), ("D", "E"), ("A", "B")),
}
TURNS = {"shaper": (2, 3, 4), "crosshead": (2, 4, 5), "press": (2, 3, 4)}
TURNING = {"shaper": 3, "crosshead": 5, "press": 3}
OUTPUT_LINK = 5


def sheets(kind: str, mech: Mechanism) -> list[Sheet]:
    t = TURNING[kind]
    out = [
        Sheet("right", (), (1, 4), 4),
        Sheet("a^n left out", ("normal_left_out",), (2,), 2, Method(normal=0.0)),
        Sheet(
            f"a^τ of link {t} reversed",
            (f"tangential_reversed_{t}",),
            (1,),
            1,
            Method(eps_reversed=(t,)),
        ),
        Sheet("rpm as rad/s", ("rpm_as_rad",), (2, 5), 5, Method(omega_factor=RPM)),
        Sheet("plans at another position", ("plans_at_3",), (2,), 5, plans_from={2: 3}),
        Sheet("forces at another position", ("forces_at_6",), (1,), 5, forces_from=6),
        # half a turn on is another position here (12 and 10 positions)
        Sheet("forces half a turn on", ("forces_at_",), (1,), 3, forces_turned=180.0),
        Sheet(
            "forces at minus the crank angle",
            ("forces_at_",),
            (1,),
            {"shaper": 3, "crosshead": 1, "press": 2}[kind],
            forces_mirrored=True,
        ),
        # the cranks carry no inertia (their centres of mass on the pivots, J = 0):
        # "every link" and "links 2–5" are the same mistake
        Sheet(
            "inertia left out",
            ("inertia_all", "inertia_others"),
            (1,),
            2,
            force_method=ForceMethod(()),
        ),
        Sheet(
            "inertia of links 2–5 left out",
            ("inertia_others",),
            (4,),
            3,
            force_method=ForceMethod((1,)),
        ),
        Sheet("weights left out", ("gravity",), (1,), 1, force_method=ForceMethod(gravity=False)),
        Sheet(
            "lever not turned",
            ("lever_not_turned",),
            (2,),
            2,
            force_method=ForceMethod(lever_turned=False),
        ),
        Sheet(
            "F_in5 left out",
            ("inertia_5",),
            (3,),
            4,
            force_method=ForceMethod((1, 2, 3, 4)),
        ),
        Sheet(
            "a^n left out at 1; weights left out at 4",
            ("normal_left_out", "gravity"),
            (1,),
            4,
            Method(normal=0.0),
            ForceMethod(gravity=False),
            method_at=1,
        ),
    ]
    heavy = {"shaper": 3, "crosshead": 2, "press": 3}[kind]
    out += [
        Sheet("angle in degrees as radians", ("deg_as_rad",), (2,), 2, degrees_as_radians=True),
        Sheet("rad/s as rpm", ("rad_as_rpm",), (4,), 4, Method(omega_factor=1 / RPM)),
        Sheet("angles from the x axis", ("angle_from_axis",), (2, 7), 7, from_axis=True),
        Sheet(
            "a^n left out in the last group",
            ("normal_left_out_4-5",),
            (3,),
            3,
            Method(normal_groups=("4-5",)),
        ),
        Sheet(
            "M_in left out (F_in at S)",
            ("moments_all", "at_s"),
            (1,),
            3,
            force_method=ForceMethod(moments=False),
        ),
        Sheet(
            f"G{heavy} at another point",
            (f"weight_{heavy}_",),
            (1,),
            2,
            force_method=ForceMethod(weight_at=((heavy, "D" if kind != "crosshead" else "B"),)),
        ),
        Sheet(
            "images b and d swapped",
            ("images_B_D_both",),
            (2,),
            5,
            swapped=("B", "D"),
        ),
        Sheet(
            "slips: a sign, the other plan's μ, read off the other plan",
            ("cause_sign", "cause_mu_divided", "cause_read_off_acceleration"),
            (3,),
            5,
            slips=True,
        ),
    ]
    if kind != "shaper":
        other = {"crosshead": "F", "press": "C"}[kind]
        out.append(
            Sheet(
                f"G2's arm measured from {other} (the group's other link)",
                ("cause_arm_from",),
                (1,),
                2,
                arm_from=("G2", other),
            )
        )
    out += [
        Sheet("wrong by no listed mistake", (), (1, 3), 3, unlisted=True),
        Sheet("wrong by no listed mistake (2)", (), (5,), 4, unlisted=True),
    ]
    if kind == "shaper":
        out += [
            Sheet("Coriolis reversed", ("coriolis_reversed",), (1, 2), 2, Method(coriolis=-1.0)),
            Sheet("Coriolis left out", ("coriolis_left_out",), (5,), 5, Method(coriolis=0.0)),
            Sheet(
                "Coriolis reversed at 2; lever not turned at 4",
                ("coriolis_reversed", "lever_not_turned"),
                (2,),
                4,
                Method(coriolis=-1.0),
                ForceMethod(lever_turned=False),
                method_at=2,
            ),
        ]
    return out


def values_of(
    mech: Mechanism, kind: str, k: Kin, fo: Forces | None, fm: ForceMethod = ForceMethod()
) -> dict:
    """Every value a sheet gives from one construction, keyed (section, key, name)."""
    out: dict[tuple[str, str, str], float] = {}
    if fo is None:
        for p in POINTS[kind]:
            out["velocity", p] = abs(k.V[p])
            out["acceleration", p] = abs(k.A[p])
        for lid in TURNS[kind]:
            out["omega", str(lid)] = k.w[lid]
            out["eps", str(lid)] = k.e[lid]
        for a, b in SEGMENTS[kind]:
            va = k.V[a] if a else 0j
            aa = k.A[a] if a else 0j
            name = ("p" if not a else a.lower()) + b.lower()
            out["velocity_plan_mm", name] = abs(k.V[b] - va) / MU_V
            out["acceleration_plan_mm", "pi" + name[1:] if not a else name] = abs(k.A[b] - aa) / MU_A
        return out
    out["balancing_force_plans", ""] = fo.F_bal
    out["balancing_force_lever", ""] = fo.F_bal_lever
    out["balancing_moment", ""] = fo.F_bal * mech.crank
    for n, r in fo.reactions.items():
        out["reactions", n] = r
    for lk in mech.links[1:]:
        out["inertia_forces", str(lk.id)] = fo.F_in[lk.id]
        if lk.J:
            out["inertia_moments", str(lk.id)] = fo.M_in[lk.id]
    for label, (link, pin) in ARMS[kind].items():
        out["group_arms_m", label] = _arm(mech, k, label, link, pin, fm)
    out["weights", "5"] = fo.G[5]
    out["force_plan_mm", "R12"] = fo.reactions["R12"] / MU_F
    out["force_plan_mm", "G5"] = fo.G[5] / MU_F
    out["force_plan_mm", "F_in5"] = fo.F_in[5] / MU_F
    return out


# the arms h' of the groups' moment equations about their inner pins (README):
# force label -> (its link, the inner pin)
ARMS = {
    "shaper": {"G4": (4, "D"), "F_in4": (4, "D")},
    "crosshead": {"G2": (2, "B"), "F_in2": (2, "B"), "G4": (4, "D"), "F_in4": (4, "D")},
    "press": {"G2": (2, "B"), "F_in2": (2, "B"), "G4": (4, "E"), "F_in4": (4, "E")},
}


def _arm(
    mech: Mechanism, k: Kin, label: str, link: int, about: str, fm: ForceMethod = ForceMethod()
) -> float:
    """|(P − B) × F| / |F| of G at S or of F_in at K (shifted by h = M_in / F_in),
    where the student's method applies them."""
    lk = next(x for x in mech.links if x.id == link)
    S = k.P[lk.cm]
    if label.startswith("G"):
        at = dict(fm.weight_at).get(link)
        F, P = -1j * lk.mass * 9.81, S if at is None else k.P[at]
    else:
        F = -lk.mass * k.A[lk.cm]
        M = -lk.J * k.e[link] if fm.moments else 0.0
        P = S - M * 1j * F / abs(F) ** 2
    r = P - k.P[about]
    return abs((r.conjugate() * F).imag) / abs(F)


def student(mech: Mechanism, kind: str, sheet: Sheet, angles: list[float], rng) -> tuple[str, dict]:
    """The answers file's text and, per value, (right value, student's, changed)."""
    given: dict = {}
    text = []
    for i in sheet.kin_at:
        right = values_of(mech, kind, mech.kin(angles[i]), None)
        drawn_at = sheet.plans_from.get(i, i)
        method = sheet.method if sheet.method_at in (None, i) else Method()
        angle = angles[drawn_at]
        if sheet.degrees_as_radians:
            angle = math.degrees(angle) % 360.0
        if sheet.from_axis:
            angle = _from_axis(mech, len(angles), drawn_at)
        k = mech.kin(angle, method)
        if sheet.swapped is not None:
            b, d = sheet.swapped
            k.V[b], k.V[d] = k.V[d], k.V[b]
            k.A[b], k.A[d] = k.A[d], k.A[b]
        wrong = values_of(mech, kind, k, None)
        if sheet.slips:
            right_k = mech.kin(angles[i])
            lid = TURNS[kind][1]
            wrong["omega", str(lid)] = -right_k.w[lid]
            seg = ("velocity_plan_mm", "pb")
            wrong[seg] = right[seg] * MU_V / MU_A  # V_B divided by μa
            wrong["velocity", "A"] = abs(right_k.A["A"])  # read off the acceleration plan
        rows = _spoil(right, wrong, rng, sheet.unlisted)
        given.update({(i, *key): v for key, v in rows.items()})
        text.append(_section("[[position]]", i, rows, {"mu_V": MU_V, "mu_a": MU_A}))
    f = sheet.force_at
    right = values_of(mech, kind, mech.kin(angles[f]), forces(mech, mech.kin(angles[f])))
    method = sheet.method if sheet.method_at in (None, f) else Method()
    at = sheet.forces_from if sheet.forces_from is not None else f
    angle = (angles[at] + sheet.forces_turned) % 360.0
    if sheet.forces_mirrored:
        angle = -angle % 360.0
    if sheet.degrees_as_radians:
        angle = math.degrees(angle) % 360.0
    if sheet.from_axis:
        angle = _from_axis(mech, len(angles), at)
    k = mech.kin(angle, method)
    wrong = values_of(mech, kind, k, forces(mech, k, sheet.force_method), sheet.force_method)
    if sheet.arm_from is not None:
        label, point = sheet.arm_from
        link = ARMS[kind][label][0]
        wrong["group_arms_m", label] = _arm(mech, k, label, link, point, sheet.force_method)
    # a force left out of the force plans is a 0 there (the loads table, computed
    # before the plans, still has it: forces() gives G, F_in, M_in regardless)
    kept = sheet.force_method.inertia
    for lid in range(1, 6):
        if kept is not None and lid not in kept and ("force_plan_mm", f"F_in{lid}") in wrong:
            wrong["force_plan_mm", f"F_in{lid}"] = 0.0
    if not sheet.force_method.gravity:
        wrong["force_plan_mm", "G5"] = 0.0
    rows = _spoil(right, wrong, rng, sheet.unlisted)
    given.update({(f, *key): v for key, v in rows.items()})
    text.append(_section("[forces]", f, rows, {"mu_F": MU_F}))
    return "\n".join(text), given


def _from_axis(mech: Mechanism, n: int, i: int) -> float:
    """Position i counted from the x axis in the crank's sense of rotation."""
    sense = -1.0 if "sense = \"cw\"" in mech.toml else 1.0
    return (sense * 360.0 * i / n) % 360.0


def _spoil(right: dict, wrong: dict, rng, unlisted: bool = False) -> dict:
    """The student's values: right ones with 2–4 % drawing error, the ones the
    mistake changed with 0–1 % reading error; `unlisted`: a third of them
    15–60 % off by no mistake the tool knows."""
    out = {}
    for key, x in right.items():
        w = wrong[key]
        if unlisted and rng.uniform() < 1 / 3:
            w = x * (1 + rng.choice([-1, 1]) * rng.uniform(0.15, 0.6))
        changed = abs(w - x) > 1e-6 * max(abs(x), 1e-12)
        if changed:
            v = w * (1 + rng.uniform(-0.01, 0.01))
        else:
            v = x * (1 + rng.choice([-1, 1]) * rng.uniform(0.02, 0.04))
        if key[0] not in ("omega", "eps", "balancing_force_plans", "balancing_force_lever",
                          "balancing_moment"):
            v = abs(v)
        out[key] = (x, v, changed)
    return out


def _section(head: str, i: int, rows: dict, scales: dict) -> str:
    tables: dict[str, dict] = defaultdict(dict)
    singles = {}
    for (key, name), (_, v, _) in rows.items():
        if name:
            tables[key][name] = float(v)
        else:
            singles[key] = float(v)
    lines = [head, f"index = {i}"]
    lines += [f"{k} = {v!r}" for k, v in scales.items()]
    lines += [f"{k} = {v!r}" for k, v in singles.items()]
    for key, t in tables.items():
        lines.append(f"{key} = {{ " + ", ".join(f'"{n}" = {v!r}' for n, v in t.items()) + " }")
    return "\n".join(lines) + "\n"


def groups_of(cause) -> set[str]:
    out = set()
    if cause is None:
        return out
    if cause.group:
        out.add(cause.group)
    for _, v in cause.fields:
        if hasattr(v, "fields"):
            out |= groups_of(v)
    return out


def keys_of(cause) -> set[str]:
    out = set()
    if cause is None:
        return out
    out.add(cause.key)
    for _, v in cause.fields:
        if hasattr(v, "fields"):
            out |= keys_of(v)
    return out


def _matches(cause, mistakes: tuple[str, ...]) -> bool:
    """The cause names one of the sheet's mistakes: a model (its group) or a
    slip of a single reading (its catalogue key)."""
    names = groups_of(cause) | keys_of(cause)
    return any(g.startswith(m) for g in names for m in mistakes)


def run_corpus(tmp: Path) -> dict:
    """Every sheet of every mechanism checked: counts per mistake, and the files."""
    rng = np.random.default_rng(23)
    table: dict[str, dict[str, int]] = defaultdict(lambda: defaultdict(int))
    for kind, mech in MECHANISMS.items():
        path = tmp / f"{kind}.toml"
        path.write_text(mech.toml, encoding="utf-8")
        solution = mmt_plans.solve(mmt_plans.load(path))
        angles = [p.phi1_deg for p in solution.positions]
        for sheet in sheets(kind, mech):
            text, given = student(mech, kind, sheet, angles, rng)
            answers = loads_answers(text, solution, f"{kind}: {sheet.name}")
            result = check(solution, answers)
            row = table[f"{kind}: {sheet.name}"]
            for v in result.values:
                a = v.answer
                if a.kind in ("mu_V", "mu_a"):
                    continue
                key = _key(a)
                _, value, changed = given[key]
                row["values"] += 1
                if not changed:
                    row["false fails"] += not v.passed
                    continue
                if v.passed:
                    row["changed, within tolerance"] += 1
                    continue
                if not sheet.mistakes:  # wrong by no listed mistake: no cause is right
                    row["wrong, unlisted"] += 1
                    row["false cause" if v.named is not None else "cause unknown"] += 1
                    continue
                row["wrong"] += 1
                if v.named is None:
                    row["cause unknown"] += 1
                elif _matches(v.named, sheet.mistakes):
                    row["right cause"] += 1
                else:
                    row["false cause"] += 1
    return table


def _key(a) -> tuple:
    section = {
        "velocity": "velocity",
        "acceleration": "acceleration",
        "omega": "omega",
        "eps": "eps",
        "velocity_plan_mm": "velocity_plan_mm",
        "acceleration_plan_mm": "acceleration_plan_mm",
        "reaction": "reactions",
        "weight": "weights",
        "inertia_force": "inertia_forces",
        "inertia_moment": "inertia_moments",
        "force_plan_mm": "force_plan_mm",
        "group_arm_m": "group_arms_m",
    }.get(a.kind, a.kind)
    return (a.where.index, section, a.name)


def totals(table: dict) -> dict[str, int]:
    out: dict[str, int] = defaultdict(int)
    for row in table.values():
        for k, n in row.items():
            out[k] += n
    return out


def markdown(table: dict) -> str:
    cols = [
        "values",
        "wrong",
        "right cause",
        "wrong, unlisted",
        "false cause",
        "cause unknown",
        "false fails",
    ]
    lines = ["| sheet | " + " | ".join(cols) + " |", "|---" * (len(cols) + 1) + "|"]
    for name, row in table.items():
        lines.append(f"| {name} | " + " | ".join(str(row.get(c, 0)) for c in cols) + " |")
    t = totals(table)
    lines.append("| **all** | " + " | ".join(f"**{t.get(c, 0)}**" for c in cols) + " |")
    return "\n".join(lines)


@pytest.fixture(scope="module")
def corpus(tmp_path_factory):
    return run_corpus(tmp_path_factory.mktemp("corpus"))


def test_the_independent_construction_agrees_with_the_tool(tmp_path):
    """corpus.py's own closed forms, plans and equilibrium give the exact values."""
    for kind, mech in MECHANISMS.items():
        path = tmp_path / f"{kind}.toml"
        path.write_text(mech.toml, encoding="utf-8")
        solution = mmt_plans.solve(mmt_plans.load(path))
        for i in (1, 4):
            plan = solution.plan(i)
            k = mech.kin(plan.phi1_deg)
            for p in POINTS[kind]:
                assert abs(complex(*plan.acceleration_images[p]) - k.A[p]) < 1e-9 * abs(k.A["A"])
            fa = solution.forces_at(i)
            fo = forces(mech, k)
            assert fa.balancing_force_plans == pytest.approx(fo.F_bal, rel=1e-9)
            for n, r in fo.reactions.items():
                assert fa.reaction(int(n[1]), int(n[2])).magnitude == pytest.approx(r, rel=1e-9)


def test_corpus_rates(corpus):
    t = totals(corpus)
    assert t["false fails"] == 0, markdown(corpus)
    assert t["wrong"] >= 150
    assert t["wrong, unlisted"] >= 100
    assert t["right cause"] >= 0.80 * t["wrong"], markdown(corpus)
    assert t["false cause"] <= 0.02 * (t["wrong"] + t["wrong, unlisted"]), markdown(corpus)


if __name__ == "__main__":  # README's table
    import tempfile

    with tempfile.TemporaryDirectory() as tmp:
        print(markdown(run_corpus(Path(tmp))))
