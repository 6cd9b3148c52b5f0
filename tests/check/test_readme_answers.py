"""The README's answers-format example: every key is read, one example per quantity."""

import re
from pathlib import Path

import mmt_plans
from mmt_plans.check import loads_answers
from mmt_plans.check.answers import KEYS

ROOT = Path(__file__).resolve().parents[2]


def readme_example() -> str:
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    section = readme[readme.index("## Checking a student's work") :]
    return re.search(r"```toml\n(.*?)```", section, re.S)[1]


def test_readme_example_is_read_and_complete():
    text = readme_example()
    solution = mmt_plans.solve(mmt_plans.load(ROOT / "samples" / "six_link_press.toml"))
    answers = loads_answers(text, solution)
    kinds = {a.kind for a in answers.values}
    assert kinds == {
        "velocity",
        "acceleration",
        "omega",
        "eps",
        "velocity_plan_mm",
        "acceleration_plan_mm",
        "mu_V",
        "mu_a",
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
        "diagram",
        "group_arm_m",
        "group_arm_mm",
        "check_V",
        "check_a",
        "check_delta",
        "check_verdict",
    }
    # every key the reader accepts appears in the example (phi1_deg as a comment)
    for section, keys in KEYS.items():
        for key in keys:
            assert re.search(rf"(^|\W){re.escape(key)}\b", text, re.M), (section, key)
