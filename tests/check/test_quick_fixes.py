"""Regression tests of issue 23's quick fixes: `--json` on every quantity kind,
a mechanism with a point named like a pole, a 0 for a force left out, the uk
labels, `--hide-exact`."""

import json
import re
from pathlib import Path

import numpy as np
from click.testing import CliRunner

import mmt_plans
from mmt_plans.check import check, loads_answers
from mmt_plans.cli import main

from .test_readme_answers import readme_example

ROOT = Path(__file__).resolve().parents[2]
PRESS = ROOT / "samples" / "six_link_press.toml"


def invoke(tmp_path, mech: Path, text: str, *args: str):
    path = tmp_path / "answers.toml"
    path.write_text(text, encoding="utf-8")
    return CliRunner().invoke(main, ["check", str(mech), str(path), *args])


def test_json_report_of_every_quantity_kind(tmp_path):
    """Regression: a numpy bool in the report made `--json` exit 3 whenever
    inertia_moments, inertia arms or reaction_components were given."""
    text = readme_example()
    solution = mmt_plans.solve(mmt_plans.load(PRESS))
    kinds = {a.kind for a in loads_answers(text, solution).values}
    assert len(kinds) == 27  # every kind (test_readme_answers lists them)
    report = tmp_path / "report.json"
    res = invoke(tmp_path, PRESS, text, "--json", str(report))
    assert res.exit_code in (0, 1), res.output
    data = json.loads(report.read_text(encoding="utf-8"))
    assert len(data["values"]) == len(loads_answers(text, solution).values)
    assert all(isinstance(v["passed"], bool) for v in data["values"])
    # and with --hide-exact, in Ukrainian
    res = invoke(tmp_path, PRESS, text, "--json", str(report), "--hide-exact", "--lang", "uk")
    assert res.exit_code in (0, 1), res.output
    data = json.loads(report.read_text(encoding="utf-8"))
    assert all(v["exact"] is None and v["error_percent"] is None for v in data["values"])


def renamed(tmp_path, old: str, new: str) -> Path:
    """The press with its point `old` called `new` (sketch too)."""
    text = PRESS.read_text(encoding="utf-8")
    text = re.sub(rf"\b{old}\b(?= =)", new, text)
    text = text.replace(f'"{old}"', f'"{new}"')
    path = tmp_path / "press_p.toml"
    path.write_text(text, encoding="utf-8")
    return path


def test_pole_segments_of_a_mechanism_with_a_point_p(tmp_path):
    """Regression: with a point P every segment from the pole was refused
    ("'p-a' can be read as p-a or p-a")."""
    mech = renamed(tmp_path, "B", "P")
    solution = mmt_plans.solve(mmt_plans.load(mech))
    plan = solution.plan(2)
    v, a = plan.velocity_images, plan.acceleration_images
    mu_v, mu_a = 0.02, 0.125
    pa = float(np.hypot(*v["A"])) / mu_v
    pP = float(np.hypot(*v["P"])) / mu_v
    aP = float(np.hypot(*(v["P"] - v["A"]))) / mu_v
    piP = float(np.hypot(*a["P"])) / mu_a
    text = (
        "[[position]]\nindex = 2\nmu_V = 0.02\nmu_a = 0.125\n"
        f'velocity_plan_mm = {{ pa = {pa}, "p-a" = {pa}, "p-P" = {pP}, pP = {pP}, '
        f'"a-P" = {aP}, "P-a" = {aP} }}\n'
        f'acceleration_plan_mm = {{ "pi-P" = {piP}, "πP" = {piP} }}\n'
    )
    answers = loads_answers(text, solution)
    segments = [a.segment for a in answers.values if a.segment is not None]
    assert segments[:2] == [("", "A"), ("", "A")]
    assert segments[2:4] == [("", "P"), ("", "P")]
    assert set(segments[4:6]) == {("A", "P"), ("P", "A")}
    res = invoke(tmp_path, mech, text)
    assert res.exit_code == 0, res.output


def test_a_zero_for_a_force_left_out_is_diagnosed():
    """Regression: a 0 given for F_in of a link the student left out was
    "cause unknown" (zero candidates were skipped)."""
    solution = mmt_plans.solve(mmt_plans.load(PRESS))
    fa = solution.forces_at(2)
    f_in5 = float(np.hypot(*fa.loads.links[5].inertia_force))
    mu_f = 100.0
    text = f"[forces]\nindex = 2\nmu_F = {mu_f}\nforce_plan_mm = {{ F_in5 = 0, G4 = {f_in5 / mu_f} }}\n"
    res = check(solution, loads_answers(text, solution))
    bad = {v.answer.label: v for v in res.values}
    assert not bad["F_in5 (force plan)"].passed
    assert bad["F_in5 (force plan)"].named is not None
    assert "5" in bad["F_in5 (force plan)"].cause


def test_uk_labels_as_the_sheets_write_them(tmp_path):
    solution = mmt_plans.solve(mmt_plans.load(PRESS))
    plan = solution.plan(2)
    fa = solution.forces_at(2)
    text = (
        f'[[position]]\nindex = 2\nomega = {{ "2" = {plan.omega[2]} }}\n'
        f'eps_magnitude = {{ "3" = {abs(plan.eps[3])} }}\n'
        f"[forces]\nindex = 2\nbalancing_force_plans = {-fa.balancing_force_plans}\n"
        f"balancing_moment = {fa.balancing_moment}\n"
    )
    out = invoke(tmp_path, PRESS, text, "--lang", "uk").output
    assert "ω2" in out and "|ε3|" in out and "F_зр (плани сил)" in out and "M_зр" in out
    assert "omega2" not in out and "F_bal" not in out


def test_hide_exact_shows_verdicts_and_causes_without_values(tmp_path):
    solution = mmt_plans.solve(mmt_plans.load(PRESS))
    plan, other = solution.plan(2), solution.plan(8)
    exact = float(np.hypot(*plan.velocity_images["B"]))
    there = float(np.hypot(*other.velocity_images["B"]))
    text = f"[[position]]\nindex = 2\nvelocity = {{ B = {there} }}\n"
    shown = invoke(tmp_path, PRESS, text).output
    hidden = invoke(tmp_path, PRESS, text, "--hide-exact")
    assert hidden.exit_code == 1
    assert "position 8" in hidden.output
    assert f"{exact:.6g}" in shown and f"{exact:.6g}" not in hidden.output
    # nor the deviation, which with the student's value gives the exact one
    deviation = f"{(there - exact) / exact * 100:+.2f}"
    assert deviation in shown and deviation not in hidden.output


def test_hide_exact_hides_the_values_a_cause_quotes(tmp_path):
    solution = mmt_plans.solve(mmt_plans.load(PRESS))
    plan = solution.plan(2)
    v_a = float(np.hypot(*plan.velocity_images["A"]))
    text = f"[[position]]\nindex = 2\nvelocity = {{ B = {v_a} }}\n"
    shown = invoke(tmp_path, PRESS, text).output
    hidden = invoke(tmp_path, PRESS, text, "--hide-exact").output
    assert "another point's image on the same plan: A, " in shown
    assert "another point's image on the same plan: A, (hidden)" in hidden
