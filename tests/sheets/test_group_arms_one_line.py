"""Sheet 2's group drawings: arms h'_i along one line named by one label (issue #21).

The arms of ΣM_B = 0 all leave the group's inner pin B. Where two of them run
along one line (gen 15's group 10-11: h'_1 of G_10 and h'_2 of F_in10, their
feet 0.3 mm apart, both running left from the pin in the slider's block),
their two names crowded each other and the block's names: "h'2" stood 14.6 mm
from its arm and 'S11' 6.7 mm from its point. As on the lever (h_{3,13,15}),
those arms are named by one label, "h'_{1,2}", along the longest, where
naming each on its own leaves some name crowded."""

from __future__ import annotations

import math
from functools import cache

from mmt_plans.generate import generate_one
from mmt_plans.render.recording import Line, RecordingBackend
from mmt_plans.sheets.lint import SheetView, lint
from mmt_plans.sheets.sheet2 import compose_sheet2
from mmt_plans.solution import solve
from mmt_plans.spec import loads


@cache
def _sheet(seed: int, lang: str) -> SheetView:
    g = generate_one(seed)
    backend = RecordingBackend(841.0, 594.0)
    compose_sheet2(solve(loads(g.toml, f"{g.name}.toml")), backend, lang)
    return SheetView.of(backend, lang, f"gen {seed} sheet 2 {lang}")


def _in_group(view: SheetView, gid: str):
    return [lab for lab in view.labels if gid in lab.groups and lab.naming is not None]


def test_two_arms_along_one_line_are_named_by_one_label():
    view = _sheet(15, "en")
    arms = [lab for lab in _in_group(view, "group-10-11") if lab.text.startswith("h'")]
    assert [lab.naming.markup for lab in arms] == ["h'_{1,2}"]
    (arm,) = arms
    # named along the longer arm, within the rule's reach of it
    start, end = arm.naming.anchor, arm.naming.end
    assert math.dist(start, end) > 12.0
    # both arms are drawn: two thin lines from the pin, along one line
    from_pin = [
        c
        for c in view.calls
        if isinstance(c, Line)
        and c.line == "thin"
        and "group-10-11" in c.groups
        and math.dist(c.start, start) < 1e-6
    ]
    assert len(from_pin) == 2
    feet = sorted((c.end for c in from_pin), key=lambda p: math.dist(p, start))
    u = ((end[0] - start[0]) / math.dist(start, end), (end[1] - start[1]) / math.dist(start, end))
    off = abs(u[0] * (feet[0][1] - start[1]) - u[1] * (feet[0][0] - start[0]))
    assert off <= 0.5


def test_the_groups_names_stand_near_what_they_name():
    view = _sheet(15, "en")
    found = [
        f
        for f in lint(view, ["label-near", "label-clear"])
        if any(
            "group-10-11" in lab.groups
            for lab in view.labels
            if (round(lab.box.centroid.x, 1), round(lab.box.centroid.y, 1)) == f.where
        )
    ]
    assert found == []


def test_arms_on_lines_of_their_own_keep_a_name_each():
    """gen 34's h'_1 and h'_2 of group 10-11 leave the pin 4° apart (their feet
    0.8 mm off one line): two arms, two names."""
    view = _sheet(34, "uk")
    arms = [lab.naming.markup for lab in _in_group(view, "group-10-11")]
    assert "h'_{1}" in arms and "h'_{2}" in arms
