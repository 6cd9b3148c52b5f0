"""The quantities of sheets 1 and 2 the first round could not take (the groups'
arms h' about the inner pin, the 5 % check of the diagrams) and the cause "a
force applied at the wrong point" (issue 15). Right and wrong answers are
built here by another route: the geometry of the state written out, another
mechanism file, the results being linear in the loads; the diagnosing code
is never called to build them."""

import math
from pathlib import Path

import numpy as np
import pytest
from click.testing import CliRunner

import mmt_plans
from mmt_plans.check import check, loads_answers
from mmt_plans.cli import main

ROOT = Path(__file__).resolve().parents[2]
EXAMPLE = ROOT / "samples" / "answers" / "seed002_example.toml"
PRESS = ROOT / "samples" / "six_link_press.toml"
PHI = 210.862
M2, J2 = 10.4, 0.2812  # link 2 of seed 002's example (AB = 400 mm, C off it)


@pytest.fixture(scope="module")
def example():
    return mmt_plans.solve(mmt_plans.load(EXAMPLE))


def variant(tmp_path, **changes):
    text = EXAMPLE.read_text(encoding="utf-8")
    for old, new in changes.items():
        assert old in text
        text = text.replace(old, new)
    path = tmp_path / "variant.toml"
    path.write_text(text, encoding="utf-8")
    return mmt_plans.solve(mmt_plans.load(path))


def cross(a: complex, b: complex) -> float:
    return a.real * b.imag - a.imag * b.real


def link2(example):
    """S2, B, F_in2 = -m·a_S2, M_in2 = -J·ε2 of the example at PHI, from the state."""
    state = example.state(phi1_deg=PHI)
    A, B = state.point(2, "A"), state.point(2, "B")
    S = (A + B) / 2  # the default centre of mass: midpoint of the first two points
    pose = state.links[2]
    return A, B, S, -M2 * pose.acc(S), -J2 * pose.eps


def answers_text(forces: dict, **scalars) -> str:
    lines = ["[forces]", f"phi1_deg = {PHI!r}"]
    lines += [f"{k} = {v!r}" for k, v in scalars.items()]
    for key, values in forces.items():
        inner = ", ".join(f'"{n}" = {float(x)!r}' for n, x in values.items())
        lines.append(f"{key} = {{ {inner} }}")
    return "\n".join(lines) + "\n"


def run(solution, text, tolerance=None):
    return check(solution, loads_answers(text, solution), tolerance)


# --- the groups' arms h' about the inner pin ----------------------------------------------


def test_group_arms_right_by_the_geometry(example):
    A, B, S, F, M = link2(example)
    h_g2 = abs((S - B).real)  # G2 is vertical: its arm about B is horizontal
    # F_in2 shifted to K: its moment about B is that of F_in2 at S plus M_in2
    h_f2 = abs(cross(S - B, F) + M) / abs(F)
    state = example.state(phi1_deg=PHI)
    C, D = state.point(4, "C"), state.point(4, "D")
    h_g4 = abs(((C + D) / 2 - D).real)  # group 4-5: link 4 about its inner pin D
    text = answers_text(
        {"group_arms_m": {"G2": h_g2, "F_in2": h_f2}, "group_arms_mm": {"G4": h_g4 / 0.004}},
        mu_l_groups=0.004,
    )
    res = run(example, text)
    assert res.passed, [(v.answer.label, v.exact, v.answer.value) for v in res.values]
    assert [v.answer.label for v in res.values] == ["h'_G2", "h'_F_in2", "h'_G4 (mm)"]
    assert min(h_g2, h_f2, h_g4) > 0.01  # real arms, not zeros that pass by the zero rule
    # off by an unexplained factor: wrong, cause unknown
    res = run(example, answers_text({"group_arms_m": {"F_in2": h_f2 * 1.37}}))
    assert not res.passed and res.values[0].cause is None


def test_group_arm_of_the_inertia_force_at_s(example):
    # F_in2 left at S2 (not shifted to K2): its arm about B is that of the force at S.
    A, B, S, F, M = link2(example)
    h_at_s = abs(cross(S - B, F)) / abs(F)
    res = run(example, answers_text({"group_arms_m": {"F_in2": h_at_s}}))
    (v,) = res.values
    assert not v.passed and v.cause_key == "cause_inertia_at_s", v.cause
    assert v.cause == "F_in2 applied at S2, not shifted to K2 (M_in2 left out)"


def test_group_arm_of_the_inertia_force_shifted_the_wrong_way(example):
    A, B, S, F, M = link2(example)
    h_wrong = abs(cross(S - B, F) - M) / abs(F)
    res = run(example, answers_text({"group_arms_m": {"F_in2": h_wrong}}))
    (v,) = res.values
    # S2 is the midpoint of AB: K2 mirrored about S2 has the arm about B that K2
    # has about A, so "the arm measured from A" gives the same number and both
    # are named (issue 23: "either … or …")
    assert not v.passed and v.cause_key == "cause_either", v.cause
    assert v.cause.startswith("either F_in2 shifted to the wrong side of S2")
    assert "the arm measured from A" in v.cause


def test_group_arm_measured_from_the_outer_pin(example):
    A, B, S, F, M = link2(example)
    h_from_a = abs((S - A).real)  # G2's arm about A instead of B
    res = run(example, answers_text({"group_arms_m": {"G2": h_from_a * 1.0001}}))
    (v,) = res.values
    # S2 is the midpoint of AB: the arm from A equals the arm from B
    assert v.passed
    C = example.state(phi1_deg=PHI).point(2, "C")
    h_from_c = abs((S - C).real)
    res = run(example, answers_text({"group_arms_m": {"G2": h_from_c}}))
    (v,) = res.values
    assert not v.passed and v.cause.startswith("the arm measured from C, not from the inner pin B")


def test_unknown_arm_is_refused(tmp_path):
    path = tmp_path / "a.toml"
    path.write_text(answers_text({"group_arms_m": {"G3": 0.1}}), encoding="utf-8")
    result = CliRunner().invoke(main, ["check", str(EXAMPLE), str(path)])
    assert result.exit_code == 2
    assert "forces.group_arms_m.G3" in result.output
    assert "forces with an arm h': G4, F_in4, G2, F_in2, R42" in result.output


# --- a force applied at the wrong point: the force analysis ---------------------------------


def force_values(fa) -> dict:
    return {
        "balancing_force_plans": fa.balancing_force_plans,
        "reactions": {n: r.magnitude for n, r in fa.reactions.items()},
    }


def forces_text(bal: float, reactions: dict) -> str:
    inner = ", ".join(f'"{n}" = {float(x)!r}' for n, x in reactions.items())
    return f"[forces]\nphi1_deg = {PHI!r}\nbalancing_force_plans = {bal!r}\nreactions = {{ {inner} }}\n"


def test_inertia_force_shifted_the_wrong_way(tmp_path):
    # M_in2 taken the wrong way: every result is linear in M_in2, so
    # X(-M) = 2·X(0) − X(M), X(0) from a file where link 2 has J = 0. Link 4
    # turns without inertia here (J = 0): its M_in (0.75 N·m in the example)
    # is too small for a reading to tell "link 2" from "links 2 and 4".
    example = variant(tmp_path, **{"J = 0.25": "J = 0"})
    no_j2 = variant(tmp_path, **{"J = 0.25": "J = 0", "J = 0.2812": "J = 0"})
    no_j2 = no_j2.forces_at(phi1_deg=PHI)
    right = example.forces_at(phi1_deg=PHI)
    bal = 2 * no_j2.balancing_force_plans - right.balancing_force_plans
    reactions = {
        n: float(np.hypot(*(2 * no_j2.reactions[n].force - r.force)))
        for n, r in right.reactions.items()
    }
    res = run(example, forces_text(bal, reactions), tolerance=1)
    named = {v.answer.label: v.cause_key for v in res.failures}
    assert named["F_bal (plans)"] == "cause_shift_reversed", named
    (v,) = [v for v in res.values if v.answer.label == "F_bal (plans)"]
    assert v.cause == "F_in2 shifted to the wrong side of S2 (M_in2 taken the wrong way)"
    assert all(k == "cause_shift_reversed" for k in named.values()), named
    assert len(named) >= 3


def test_weight_at_another_point(tmp_path, example):
    # G2 at A instead of S2: the results are linear in the loads; the change is
    # that of two files without inertia (a crank turning very slowly), one with
    # link 2's centre of mass at A.
    slow = {"omega = 25.31": "omega = 0.001"}
    at_s = variant(tmp_path, **slow).forces_at(phi1_deg=PHI)
    at_a = variant(tmp_path, **slow, **{"mass = 10.4": "mass = 10.4\ncm = [0, 0]"}).forces_at(
        phi1_deg=PHI
    )
    right = example.forces_at(phi1_deg=PHI)
    bal = right.balancing_force_plans + at_a.balancing_force_plans - at_s.balancing_force_plans
    reactions = {
        n: float(np.hypot(*(r.force + at_a.reactions[n].force - at_s.reactions[n].force)))
        for n, r in right.reactions.items()
    }
    res = run(example, forces_text(bal, reactions))
    (v,) = [v for v in res.values if v.answer.label == "F_bal (plans)"]
    assert not v.passed and v.cause == "G2 applied at A instead of S2", v.cause
    assert not math.isclose(bal, right.balancing_force_plans, rel_tol=0.05)


# --- the 5 % check of the diagrams against the plans ----------------------------------------


def sheet_check_values(solution, i):
    """V and a of the output along the working direction from position i's plan,
    and the drawn diagrams' ordinates there (construction, SI)."""
    mech = solution.mechanism
    wd = np.asarray(mech.study.working_direction, float)
    wd = wd / np.hypot(*wd)
    plan = solution.plan(i)
    v = float(np.dot(plan.velocity_images[mech.study.output], wd))
    a = float(np.dot(plan.acceleration_images[mech.study.output], wd))
    dg = solution.diagrams
    k = i * dg.sheet_check.refinement
    return v, float(dg.construction.v[k]), a, float(dg.construction.a[k])


def test_sheet_check_right_and_wrong():
    solution = mmt_plans.solve(mmt_plans.load(PRESS))
    v_p, v_d, a_p, a_d = sheet_check_values(solution, 2)
    dv, da = (v_p - v_d) / v_p * 100, (a_p - a_d) / a_p * 100  # formulas (12), (13)
    verdict = abs(dv) <= 5 and abs(da) <= 5
    text = (
        f"[diagrams]\ncheck_passed = {str(verdict).lower()}\n"
        f'V_plan = {{ "2" = {v_p!r} }}\nV_diagram = {{ "2" = {v_d!r} }}\n'
        f'dV_percent = {{ "2" = {dv!r} }}\na_plan = {{ "2" = {a_p!r} }}\n'
        f'a_diagram = {{ "2" = {a_d!r} }}\nda_percent = {{ "2" = {da!r} }}\n'
    )
    res = run(solution, text)
    assert res.passed, [(v.answer.label, v.exact, v.answer.value) for v in res.values]
    assert len(res.values) == 7
    # the plan's and the diagram's values swapped; δ of the opposite sign; the verdict wrong
    a_d_far = a_d * (1 + 0.5 * (a_d - a_p) / abs(a_p))  # no reading of the table
    text = (
        f"[diagrams]\ncheck_passed = {str(not verdict).lower()}\n"
        f'dV_percent = {{ "2" = {-dv - 10!r} }}\na_plan = {{ "2" = {a_d!r} }}\n'
        f'a_diagram = {{ "2" = {a_d_far!r} }}\n'
    )
    res = run(solution, text, tolerance=1)
    by = {v.answer.label: v for v in res.values}
    assert not by["5 % check passed"].passed and by["5 % check passed"].cause is None
    assert not by["a (plan)"].passed
    assert by["a (plan)"].cause_key == "cause_check_diagram"
    assert not by["δV %"].passed and by["δV %"].deviation_percent == pytest.approx(-2 * dv - 10)
    row = next(line for line in res.text().splitlines() if "5 % check passed" in line)
    assert row.split()[0] == "-"  # the verdict of every investigated position
    data = res.json_data()["values"][0]
    assert data["position"] is None and data["phi1_deg"] is None and data["unit"] == ""
    cells = row.split("passed")[1].split()
    assert cells[:4] == (["yes", "no", "-", "FAIL"] if verdict else ["no", "yes", "-", "FAIL"])


def test_sheet_check_refuses_a_percentage_near_zero(tmp_path):
    # investigated at position 0, an extreme position: V_plan = 0 there, so no
    # grid passes it by (12) and the check gives its absolute error instead
    press = tmp_path / "press.toml"
    press.write_text(PRESS.read_text().replace("plans = [2, 8]", "plans = [0, 8]"))
    solution = mmt_plans.solve(mmt_plans.load(press))
    ill = [v for v in solution.diagrams.sheet_check.values if v.ill_conditioned]
    assert ill, "V is zero at the extreme position 0"
    i = ill[0].index
    key = "dV_percent" if ill[0].quantity == "v" else "da_percent"
    path = tmp_path / "a.toml"
    path.write_text(f'[diagrams]\n{key} = {{ "{i}" = 3.0 }}\n', encoding="utf-8")
    result = CliRunner().invoke(main, ["check", str(press), str(path)])
    assert result.exit_code == 2
    assert f"diagrams.{key}.{i}" in result.output and "absolute error" in result.output
    path.write_text('[diagrams]\nV_plan = { "5" = 1.0 }\n', encoding="utf-8")
    result = CliRunner().invoke(main, ["check", str(PRESS), str(path)])
    assert result.exit_code == 2 and 'investigated position: "2", "8"' in result.output


def test_ukrainian_words_of_the_new_rows():
    solution = mmt_plans.solve(mmt_plans.load(PRESS))
    res = run(solution, "[diagrams]\ncheck_passed = false\n")
    row = next(line for line in res.text("uk").splitlines() if "перевірку 5 % виконано" in line)
    assert "так       ні" in row and "ПОМИЛКА" in row, row


@pytest.mark.parametrize("path", [PRESS, EXAMPLE], ids=["press", "seed002"])
def test_random_wrong_arms_get_no_cause(path):
    solution = mmt_plans.solve(mmt_plans.load(path))
    state = solution.state(solution.force_position)
    fa = solution.forces
    rng = np.random.default_rng(15)
    arms = {}
    for g in fa.groups:  # G of the first link of each group about the inner pin
        L = g.links[0]
        B = state.point(L, g.reactions[2].pair)
        S = state.centre_of_mass(L)
        arms[f"G{L}"] = abs((S - B).real)
    for _ in range(5):
        given = {
            k: h * (rng.uniform(1.31, 1.39) if rng.random() < 0.5 else rng.uniform(0.52, 0.58))
            for k, h in arms.items()
        }
        res = run(
            solution,
            answers_text({"group_arms_m": given}).replace(
                f"phi1_deg = {PHI!r}", f"index = {solution.force_position}"
            ),
        )
        assert not any(v.passed for v in res.values)
        for v in res.values:  # only a chance coincidence, within a quarter of the tolerance
            if v.named is not None:
                there = dict(v.named.fields)["value"]
                assert abs(v.answer.value - there) <= 0.0125 * there, v.cause
