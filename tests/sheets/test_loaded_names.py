"""The names of sheet 2's loaded mechanism near what they name (#21): ω1's
arc round the crank's pivot opens where the points named inside its circle
stand (the crank's S1 and pin on a crank shorter than the arc's radius), so
their names find a place or a leader out through the open side."""

from __future__ import annotations

import math

import numpy as np
import pytest
from lettering import solved_seed

from mmt_plans.render.look import load_look
from mmt_plans.render.recording import Arc, RecordingBackend
from mmt_plans.sheets.lint import SheetView, lint
from mmt_plans.sheets.sheet2 import _ARC_SPAN, _Drawing, compose_sheet2


def _behind_the_arc(centre: np.ndarray, start: float, at: np.ndarray) -> bool:
    d = at - centre
    return (math.degrees(math.atan2(d[1], d[0])) - start) % 360.0 <= _ARC_SPAN


def test_the_arc_opens_towards_the_points_named_inside_it():
    state = solved_seed(212).require_forces().loads.state
    d = _Drawing(load_look(), state, 1.0)
    centre = np.array([100.0, 100.0])
    inside = [centre + 4.0 * np.array([math.cos(a), math.sin(a)]) for a in (0.2, 0.7)]
    for k, at in enumerate(inside):
        d.later(at, f"S_{{{k + 1}}}")
    d.later(centre + np.array([30.0, 0.0]), "B")  # outside the circle: no wall
    start = d._arc_start(centre, 1.0, "ω_{1}", 9.0, None)
    assert not any(_behind_the_arc(centre, start, at) for at in inside)


def test_an_empty_circle_keeps_the_first_start():
    state = solved_seed(212).require_forces().loads.state
    d = _Drawing(load_look(), state, 1.0)
    centre = np.array([100.0, 100.0])
    d.later(centre, "O")  # the pivot's own name is `name`'s, not walled in
    d.later(centre + np.array([0.0, 20.0]), "A")
    assert d._arc_start(centre, 1.0, "ω_{1}", 9.0, None) == 20.0


# gen 212 (RRR-RRP-RRP-RPR): its crank O2-C is 7 mm long on the loaded
# mechanism, S1 at its middle inside ω1's 9 mm arc, which was turned to leave
# room for 'O2' and ω1 alone: 'S1' stood 9.9 mm off (en and uk), walled in.
@pytest.mark.parametrize("lang", ["en", "uk"])
def test_gen_212s_crank_names_stand_near(lang):
    backend = RecordingBackend(841.0, 594.0)
    compose_sheet2(solved_seed(212), backend, lang)  # type: ignore[arg-type]
    view = SheetView.of(backend, lang, f"gen 212 {lang}")  # type: ignore[arg-type]
    where = {
        (round(lab.box.centroid.x, 1), round(lab.box.centroid.y, 1)): lab.groups[:1]
        for lab in view.labels
    }
    found = [
        str(f)
        for f in lint(view, ["label-near", "label-clear"])
        if where.get(f.where, ("",))[0].startswith("force-mechanism")
    ]
    assert found == []
    (arc,) = [
        c for c in view.calls if isinstance(c, Arc) and view.top_group(c) == "force-mechanism"
    ]
    assert arc.radius == pytest.approx(9.0)
