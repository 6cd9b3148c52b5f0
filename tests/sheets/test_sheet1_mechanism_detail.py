"""Sheet 1's mechanism whose names crowd in a knot of joints (a crank 0.8 mm
long at 1:200 among near-coincident pivots): a detail view (GOST 2.305) of
the knot, drawn at a larger scale of the standard series and lettered there,
the disc marked on the drawing by a thin circle and its letter (#21), judged by
the sheet linter's own rules."""

from __future__ import annotations

import functools

import numpy as np
from lettering import near_findings, solved_seed

from mmt_plans.drawing.detail import DETAIL_LETTERS, DETAIL_RATIOS
from mmt_plans.render.look import load_look
from mmt_plans.render.recording import Text
from mmt_plans.sheets.crowd import crowded_names
from mmt_plans.sheets.sheet1 import mechanism_details, sketch_mechanism, sketch_mechanism_details

# gen 63 (RPR-RRP-RRR-RPP-RRP) at the scale sheet 1 draws it, 1:200: its
# crank, four pivots and three blocks within 4 mm; 12 names far or on an arc
KNOT, MU_L = 63, 0.2


@functools.cache
def _plain():
    solution = solved_seed(KNOT)
    return sketch_mechanism(solution, MU_L, load_look(), "en")


def _letters(solution) -> str:
    used = {n[:1].upper() for n in solution.mechanism.point_owners}
    return "".join(x for x in DETAIL_LETTERS if x not in used)


@functools.cache
def _details():
    solution = solved_seed(KNOT)
    return mechanism_details(solution, MU_L, crowded_names(_plain(), "en"), _letters(solution))


def _point_names(sketch, solution) -> list[str]:
    points = set(solution.mechanism.point_owners)
    return [
        c.naming.markup.replace("_{", "").replace("}", "")
        for c in sketch.calls
        if isinstance(c, Text) and c.naming is not None and c.content.strip()
        and c.naming.markup.replace("_{", "").replace("}", "") in points
        and c.content == c.naming.markup[:1]  # a name's first run, once per label
    ]


def test_a_knot_of_joints_gets_a_detail_round_it_at_a_larger_standard_scale():
    solution = solved_seed(KNOT)
    assert len(crowded_names(_plain(), "en")) >= 3
    (detail,) = _details()
    assert detail.ratio in DETAIL_RATIOS and detail.ratio > 1.0
    assert detail.letter not in {n[:1].upper() for n in solution.mechanism.point_owners}
    # the disc holds the knot: the crank's pivot and pin at position 0
    centre, radius = np.asarray(detail.centre), detail.radius
    for p in (solution.mechanism.crank_pivot, solution.mechanism.crank_pin):
        at = np.asarray(solution.sweep.points[p][0], dtype=float)
        assert np.hypot(*(at - centre)) <= radius


def test_the_knots_names_stand_near_in_the_detail_view():
    solution = solved_seed(KNOT)
    plain = _plain()
    made = sketch_mechanism_details(solution, MU_L, load_look(), "en", _letters(solution), plain)
    assert made is not None
    main, (view,) = made
    before = near_findings(plain)
    after = near_findings(main) + near_findings(view)
    assert not near_findings(main)  # the drawing's own names all stand near
    assert len(after) <= len(before) // 3
    # every point named once, in the drawing or in its detail view
    names = _point_names(main, solution) + _point_names(view, solution)
    named = [p for p in solution.mechanism.point_owners if p in solution.sweep.points]
    assert sorted(names) == sorted(named)


def test_the_detail_letters_the_knot_in_ukrainian_too():
    solution = solved_seed(KNOT)
    details = _details()
    look = load_look()
    main = sketch_mechanism(solution, MU_L, look, "uk", details)
    view = sketch_mechanism(solution, MU_L, look, "uk", details, details[0])
    assert not near_findings(main, "uk")
    assert len(near_findings(view, "uk")) <= 4
    title = [c.content for c in view.calls if isinstance(c, Text) and "(" in c.content]
    assert title == [f"{details[0].letter} ({details[0].ratio:g}:1)"]
