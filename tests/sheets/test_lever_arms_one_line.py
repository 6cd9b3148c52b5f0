"""The arms of Zhukovsky's lever along one line from p (#21): the arms of the
weights all run along the horizontal through p, the feet of those on one
side one after another on one line. Where their names, one each, crowd
there, the lever names those along one line by one label, "h_{3,13,15}",
along the longest."""

from __future__ import annotations

from functools import cache

import numpy as np
import pytest

from mmt_plans.generate import generate_one
from mmt_plans.render.recording import RecordingBackend
from mmt_plans.sheets.lint import SheetView, _at, label_near
from mmt_plans.sheets.sheet2 import _one_per_line, compose_sheet2
from mmt_plans.solution import solve
from mmt_plans.spec import loads

ALONG = 88  # gen 88 (RPP-RRR-RPR-RRR-RRP): five arms run left from p along the horizontal


def _feet(*feet: tuple[tuple[float, float], list[str]]):
    return {(i, 0): (np.array(at, dtype=float), numbers) for i, (at, numbers) in enumerate(feet)}


def test_arms_along_one_line_from_p_are_one_label_along_the_longest():
    """Three feet left of p on the horizontal (0.3 mm off it at most) are one
    label at the farthest, its numbers in order; a foot right of p, and one
    on a line 20° off, keep their own."""
    merged = _one_per_line(
        _feet(
            ((-4.0, 0.0), ["13"]),
            ((-12.0, 0.3), ["3"]),
            ((-25.0, 0.0), ["15", "16"]),
            ((9.0, 0.0), ["2"]),
            ((-10.0, -3.64), ["5"]),
        )
    )
    by_numbers = {",".join(numbers): tuple(foot) for foot, numbers in merged}
    assert by_numbers == {
        "3,13,15,16": (-25.0, 0.0),
        "2": (9.0, 0.0),
        "5": (-10.0, -3.64),
    }


def test_feet_apart_keep_their_own_labels():
    """No two feet along one line: the labels as they were."""
    feet = _feet(((5.0, 5.0), ["1"]), ((-5.0, 5.0), ["2"]), ((0.0, -7.0), ["3"]))
    assert sorted(n for _, numbers in _one_per_line(feet) for n in numbers) == ["1", "2", "3"]
    assert len(_one_per_line(feet)) == 3


@cache
def _sheet(lang: str):
    g = generate_one(ALONG)
    backend = RecordingBackend(841.0, 594.0)
    compose_sheet2(solve(loads(g.toml, f"{g.name}.toml")), backend, lang)
    return SheetView.of(backend, lang, g.name)


@pytest.mark.parametrize("lang", ["en", "uk"])
def test_the_arms_along_one_line_from_p_are_named_near_them(lang):
    """Gen 88 on sheet 2: the arms of G_1, G_3, G_13, G_15 and G_19 run left
    from p along the horizontal; their names, one each, stood stacked under
    it 10-17 mm off (h_13, h_15, h_19 in uk). Named by one label along the
    longest, "h_{1,3,13,15,19}", no name of an arm along the horizontal
    through p stands far (judged by the linter's own rule)."""
    view = _sheet(lang)
    far = {f.where for f in label_near(view)}
    arms = [
        lab
        for lab in view.labels
        if lab.naming is not None
        and lab.naming.markup.startswith("h_{")
        and lab.naming.end is not None
        and abs(lab.naming.anchor[1] - lab.naming.end[1]) < 0.01
    ]
    assert any(lab.naming.markup.count(",") >= 2 for lab in arms)
    assert [lab.text for lab in arms if _at(lab.box) in far] == []
