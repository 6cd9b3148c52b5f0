"""`mmt-plans check`: a student's answers against the exact values.

The answers are built here from the exact values (mmt_plans' public API) and
then spoilt the way a student spoils them; no expected number is copied from
the tool's output.
"""

import math
from pathlib import Path

import numpy as np
import pytest
from click.testing import CliRunner

import mmt_plans
from mmt_plans.check import check, load_answers, loads_answers
from mmt_plans.cli import main


ROOT = Path(__file__).resolve().parents[1]
PRESS = ROOT / "samples" / "six_link_press.toml"
EXAMPLE = ROOT / "samples" / "answers" / "six_link_press.answers.toml"
MU_V, MU_A = 0.02, 0.125  # the scales the "student" states for their plans


@pytest.fixture(scope="module")
def analysis():
    return mmt_plans.solve(mmt_plans.load(PRESS))


def size(v) -> float:
    return float(np.hypot(*v))


def exact_answers(analysis) -> dict:
    """A perfect answers file as a dict: every kind of value at positions 2 and 8."""
    positions = []
    for i in (2, 8):
        plan = analysis.plan(i)
        v, a = plan.velocity_images, plan.acceleration_images
        positions.append({
            "index": i, "mu_V": MU_V, "mu_a": MU_A,
            "velocity": {p: size(v[p]) for p in "ABDE"},
            "acceleration": {p: size(a[p]) for p in "ABDE"},
            "omega": {str(k): plan.omega[k] for k in (2, 3, 4)},
            "eps": {str(k): plan.eps[k] for k in (2, 3, 4)},
            "velocity_plan_mm": {"pb": size(v["B"]) / MU_V, "ab": size(v["B"] - v["A"]) / MU_V},
            "acceleration_plan_mm": {"pib": size(a["B"]) / MU_A,
                                     "ab": size(a["B"] - a["A"]) / MU_A},
        })
    fa = analysis.forces_at(2)
    forces = {"index": 2, "balancing_force_plans": fa.balancing_force_plans,
              "balancing_force_lever": fa.balancing_force_lever,
              "balancing_moment": fa.balancing_moment,
              "reactions": {name: r.magnitude for name, r in fa.reactions.items()}}
    return {"position": positions, "forces": forces}


def to_toml(answers: dict, tolerance: float | None = None) -> str:
    def inline(d: dict) -> str:
        return "{ " + ", ".join(f'"{k}" = {v!r}' for k, v in d.items()) + " }"

    out = [] if tolerance is None else ["[check]", f"tolerance_percent = {tolerance!r}", ""]
    for pos in answers.get("position", []):
        out.append("[[position]]")
        out += [f"{k} = {inline(v) if isinstance(v, dict) else repr(v)}" for k, v in pos.items()]
        out.append("")
    if "forces" in answers:
        out.append("[forces]")
        out += [f"{k} = {inline(v) if isinstance(v, dict) else repr(v)}"
                for k, v in answers["forces"].items()]
    return "\n".join(out) + "\n"


def run(tmp_path, text: str, *args: str):
    path = tmp_path / "answers.toml"
    path.write_text(text, encoding="utf-8")
    return CliRunner().invoke(main, ["check", str(PRESS), str(path), *args])


def checked(analysis, answers: dict, tolerance: float | None = None):
    return check(analysis, loads_answers(to_toml(answers), analysis), tolerance)


def only_failure(result, label: str):
    assert [v.answer.label for v in result.failures] == [label]
    return result.failures[0]


# --- passing ------------------------------------------------------------------------

def test_perfect_answers_pass(tmp_path, analysis):
    answers = exact_answers(analysis)
    result = run(tmp_path, to_toml(answers))
    assert result.exit_code == 0, result.output
    res = checked(analysis, answers)
    assert len(res.values) == 2 * (4 + 4 + 3 + 3 + 2 + 2) + 3 + len(answers["forces"]["reactions"])
    assert all(v.passed and abs(v.deviation_percent) < 1e-9 for v in res.values)


def test_crank_pin_against_closed_form(analysis):
    # V_A = ω1·l_OA, a_A = ω1²·l_OA for a crank turning at a constant 100 rpm,
    # l_OA = 0.2 m: the student's hand values 2.09 m/s and 21.9 m/s² pass.
    w1 = 2 * math.pi * 100 / 60
    res = checked(analysis, {"position": [{"index": 2, "velocity": {"A": 2.09},
                                           "acceleration": {"A": 21.9}}]})
    assert [v.exact for v in res.values] == pytest.approx([w1 * 0.2, w1 * w1 * 0.2], rel=1e-12)
    assert res.passed


def test_shipped_example_passes(analysis):
    result = CliRunner().invoke(main, ["check", str(PRESS), str(EXAMPLE)])
    assert result.exit_code == 0, result.output
    res = check(analysis, load_answers(EXAMPLE, analysis))
    devs = [abs(v.deviation_percent) for v in res.values]
    # Rounded to 3 significant figures: off by less than 0.5 %, but off.
    assert max(devs) < 0.5 and sum(d > 0 for d in devs) > len(devs) / 2


def test_an_exact_zero(analysis):
    # A slider does not turn: ω5 = 0; "zero" is judged against the largest ω (ω1).
    ok = checked(analysis, {"position": [{"index": 2, "omega": {"5": 0.0}, "eps": {"1": 0}}]})
    assert ok.passed and ok.values[0].deviation_percent is None
    bad = checked(analysis, {"position": [{"index": 2, "omega": {"5": 1.0}}]})
    assert not bad.passed


# --- failing ------------------------------------------------------------------------

def test_six_percent_error_fails_on_exactly_that_value(tmp_path, analysis):
    answers = exact_answers(analysis)
    answers["position"][0]["velocity"]["B"] *= 1.06
    result = run(tmp_path, to_toml(answers))
    assert result.exit_code == 1, result.output
    fail = [line for line in result.output.splitlines() if "FAIL" in line]
    assert len(fail) == 1 and " V_B " in fail[0]
    bad = only_failure(checked(analysis, answers), "V_B")
    assert bad.deviation_percent == pytest.approx(6.0)
    assert bad.answer.position == 2
    assert bad.cause is None  # no mistake we know reproduces a 6 % slip


def test_tolerance_from_the_option_and_the_file(tmp_path, analysis):
    answers = exact_answers(analysis)
    answers["position"][0]["velocity"]["B"] *= 1.06
    assert run(tmp_path, to_toml(answers), "--tolerance", "7").exit_code == 0
    assert run(tmp_path, to_toml(answers, tolerance=7)).exit_code == 0
    assert run(tmp_path, to_toml(answers, tolerance=7), "--tolerance", "5").exit_code == 1


def spoil(analysis, where: str, key: str, name: str, value_of):
    answers = exact_answers(analysis)
    table = answers["forces"] if where == "forces" else answers["position"][0]
    if name:
        table[key][name] = value_of(table[key][name])
    else:
        table[key] = value_of(table[key])
    return checked(analysis, answers)


def test_segment_multiplied_by_the_wrong_mu(analysis):
    # V_B = pb·μa instead of pb·μV.
    bad = only_failure(spoil(analysis, "position", "velocity", "B", lambda v: v / MU_V * MU_A),
                       "V_B")
    assert bad.cause_key == "cause_mu_multiplied"
    assert "mu_a = 0.125 instead of mu_V = 0.02" in bad.cause


def test_value_off_by_ten_is_no_named_cause(analysis):
    # No generic ratio diagnoses: ten times a reaction is no mistake recomputed.
    bad = only_failure(spoil(analysis, "forces", "reactions", "R12", lambda v: v * 10), "R12")
    assert bad.cause is None


def test_plan_drawn_at_the_neighbouring_scale(analysis):
    # The plan was drawn at μV = 0.025 (the next standard value) but 0.02 is stated.
    bad = only_failure(spoil(analysis, "position", "velocity_plan_mm", "pb",
                             lambda mm: mm * MU_V / 0.025), "pb (V plan)")
    assert bad.cause_key == "cause_series_drawn" and "drawn at 0.025" in bad.cause


def test_segment_divided_by_the_other_mu(analysis):
    bad = only_failure(spoil(analysis, "position", "acceleration_plan_mm", "pib",
                             lambda mm: mm * MU_A / MU_V), "pib (a plan)")
    assert "divided by mu_V = 0.02 instead of mu_a = 0.125" in bad.cause


@pytest.mark.parametrize("key,label", [("omega", "omega3"), ("eps", "eps3")])
def test_sign_swap_on_omega_and_eps(analysis, key, label):
    bad = only_failure(spoil(analysis, "position", key, "3", lambda w: -w), label)
    assert bad.cause.startswith("sign or direction swapped")


def test_sign_swap_of_the_balancing_force(analysis):
    bad = only_failure(spoil(analysis, "forces", "balancing_force_lever", "", lambda f: -f),
                       "F_bal (lever)")
    assert bad.cause.startswith("sign or direction swapped")


def test_velocity_read_off_the_acceleration_plan(tmp_path, analysis):
    a_b = size(analysis.plan(2).acceleration_images["B"])
    res = spoil(analysis, "position", "velocity", "B", lambda v: a_b)
    bad = only_failure(res, "V_B")
    assert bad.cause.startswith("read off the acceleration plan")
    answers = exact_answers(analysis)
    answers["position"][0]["velocity"]["B"] = a_b
    out = run(tmp_path, to_toml(answers)).output
    assert "read off the acceleration plan: " in out


def test_value_from_another_position(analysis):
    b8 = size(analysis.plan(8).velocity_images["B"])
    bad = only_failure(spoil(analysis, "position", "velocity", "B", lambda v: b8), "V_B")
    assert bad.cause.startswith("taken from position 8")


def test_another_points_image(analysis):
    a = size(analysis.plan(2).velocity_images["A"])
    bad = only_failure(spoil(analysis, "position", "velocity", "B", lambda v: a), "V_B")
    assert bad.cause.startswith("another point's image") and ": A, " in bad.cause


def test_another_pairs_reaction(analysis):
    r05 = analysis.forces_at(2).reaction(0, 5).magnitude
    bad = only_failure(spoil(analysis, "forces", "reactions", "R12", lambda r: r05), "R12")
    assert "another pair's reaction: R05" in bad.cause


def test_reaction_named_either_way_round(analysis):
    r = analysis.forces_at(2).reaction(1, 2).magnitude
    res = checked(analysis, {"forces": {"reactions": {"R21": r, "R12": r}}})
    assert res.passed and [v.exact for v in res.values] == pytest.approx([r, r])


def test_segment_names(analysis):
    plan = analysis.plan(2)
    pb = size(plan.velocity_images["B"]) / MU_V
    pib = size(plan.acceleration_images["B"]) / MU_A
    as2 = size(plan.velocity_images["S2"] - plan.velocity_images["A"]) / MU_V
    res = checked(analysis, {"position": [{
        "index": 2, "mu_V": MU_V, "mu_a": MU_A,
        "velocity_plan_mm": {"pb": pb, "p-b": pb, "as2": as2, "a-s2": as2, "s2a": as2},
        "acceleration_plan_mm": {"pib": pib, "πb": pib, "pb": pib}}]})
    assert res.passed and all(v.deviation_percent == pytest.approx(0, abs=1e-9)
                              for v in res.values)


# --- bad answers files --------------------------------------------------------------

BAD = [
    # (name, answers text, the entry named, words of the fix)
    ("unknown key", "[[position]]\nindex = 2\nvelocty = { B = 1 }\n",
     "position[1].velocty", "did you mean 'velocity'"),
    ("unknown section", "[answers]\nx = 1\n", "answers", "allowed keys"),
    ("unknown point", "[[position]]\nindex = 2\nvelocity = { Q = 1 }\n",
     "position[1] (index 2).velocity.Q", "points of this mechanism: O, C, A, B"),
    ("point in the wrong case", "[[position]]\nindex = 2\nvelocity = { b = 1 }\n",
     "position[1] (index 2).velocity.b", "did you mean 'B'"),
    ("unknown link", "[[position]]\nindex = 2\nomega = { 7 = 1 }\n",
     "position[1] (index 2).omega.7", "links of this mechanism: 1, 2, 3, 4, 5"),
    ("unknown position", "[[position]]\nindex = 12\nvelocity = { B = 1 }\n",
     "position[1].index", "use a position 0..11"),
    ("position not a number", "[[position]]\nindex = \"two\"\nvelocity = { B = 1 }\n",
     "position[1].index", "use a position 0..11"),
    ("missing index", "[[position]]\nvelocity = { B = 1 }\n", "position[1].index",
     "add index ="),
    ("same position twice", "[[position]]\nindex = 2\nvelocity = { B = 1 }\n"
     "[[position]]\nindex = 2\nvelocity = { A = 1 }\n", "position[2].index",
     "write each position once"),
    ("non-number", "[[position]]\nindex = 2\nvelocity = { B = \"2.9\" }\n",
     "position[1] (index 2).velocity.B", "write B = <number>"),
    ("negative magnitude", "[[position]]\nindex = 2\nomega_magnitude = { 2 = -1.4 }\n",
     "position[1] (index 2).omega_magnitude.2", "write the signed value under omega"),
    ("segment without mu", "[[position]]\nindex = 2\nvelocity_plan_mm = { pb = 146 }\n",
     "position[1] (index 2).velocity_plan_mm", "add mu_V ="),
    ("unknown segment", "[[position]]\nindex = 2\nmu_V = 0.02\nvelocity_plan_mm = { pq = 146 }\n",
     "position[1] (index 2).velocity_plan_mm.pq", "the pole p and lower-case point names"),
    ("pi on the velocity plan", "[[position]]\nindex = 2\nmu_V = 0.02\n"
     "velocity_plan_mm = { pib = 146 }\n", "position[1] (index 2).velocity_plan_mm.pib",
     "the pole p and"),
    ("unknown reaction", "[forces]\nreactions = { R15 = 100 }\n", "forces.reactions.R15",
     "this mechanism's pairs"),
    ("not a reaction", "[forces]\nreactions = { F12 = 100 }\n", "forces.reactions.F12",
     "write R and the two links"),
    ("zero tolerance", "[check]\ntolerance_percent = 0\n", "check.tolerance_percent",
     "above zero"),
    ("nothing to check", "[check]\ntolerance_percent = 5\n", "file", "add a [[position]]"),
    ("bad TOML", "[[position]\nindex = 2\n", "TOML", "fix the TOML syntax"),
]


@pytest.mark.parametrize("name,text,entry,fix", BAD, ids=[b[0] for b in BAD])
def test_bad_answers_file(tmp_path, name, text, entry, fix):
    result = run(tmp_path, text)
    assert result.exit_code == 2, result.output
    assert "Traceback" not in result.output
    message = result.output
    assert message.startswith(f"error: {tmp_path / 'answers.toml'}: {entry}:"), message
    assert f"fix: {fix}" in message or fix in message, message


def test_missing_answers_file(tmp_path):
    result = CliRunner().invoke(main, ["check", str(PRESS), str(tmp_path / "none.toml")])
    assert result.exit_code == 2 and "cannot be read" in result.output


def test_segment_of_the_other_plan_at_this_plans_scale(analysis):
    # πb measured on the acceleration plan, multiplied by μV.
    a_b = size(analysis.plan(2).acceleration_images["B"])
    bad = only_failure(spoil(analysis, "position", "velocity", "B", lambda v: a_b / MU_A * MU_V),
                       "V_B")
    assert bad.cause.startswith("the segment pib of the other plan")
