"""A detail disc's letter on the lever is written by its rim where it stands
near it, up and right first, then round the rim (RIM_ANGLES, as sheet 1 letters
its discs) (#21). Gen 90: the lever's lines wall in the upper right of disc
A's rim; its letter, tried there alone, stood 10 mm off its rim in en and uk."""

from __future__ import annotations

import math
from functools import cache

import pytest
from shapely.geometry import Point

from mmt_plans.drawing.labels import NEAR_MM
from mmt_plans.generate import generate_one
from mmt_plans.render.recording import Circle, RecordingBackend
from mmt_plans.sheets.lint import SheetView, lint
from mmt_plans.sheets.sheet2 import compose_sheet2
from mmt_plans.solution import solve
from mmt_plans.spec import loads

WALLED = 90  # gen 90 (RPR-PRP-RRR-RPP): its lever's detail view A


@cache
def _sheet(seed: int, lang: str):
    """Sheet 2 of generated mechanism `seed`: the composition, the recorded
    view and the linter's findings."""
    g = generate_one(seed)
    solution = solve(loads(g.toml, f"{g.name}.toml"))
    backend = RecordingBackend(841.0, 594.0)
    result = compose_sheet2(solution, backend, lang)
    view = SheetView.of(backend, lang, g.name)
    return result, view, list(lint(view))


@pytest.mark.parametrize("lang", ["en"])
def test_regression_gen90_lever_disc_letter_stands_by_its_rim(lang):
    result, view, found = _sheet(WALLED, lang)
    assert result.details  # the lever has its detail views
    letters = {d.letter for d in result.details}
    assert not [f for f in found if f.rule == "label-near" and f.message[1:2] in letters]
    rims = [
        Point(c.center).buffer(c.radius).exterior
        for c in view.calls
        if isinstance(c, Circle) and c.groups and c.groups[0] == "zhukovsky-lever"
    ]
    for letter in letters:
        (label,) = [lab for lab in view.labels if lab.text == letter and lab.naming is not None]
        # it names a point of a disc's rim, and stands within NEAR_MM of it
        anchor = Point(label.naming.anchor)
        assert min(rim.distance(anchor) for rim in rims) < 0.05
        assert label.box.distance(anchor) <= NEAR_MM
        assert math.isfinite(label.box.area) and label.box.area > 0.0
