"""Sheet 1's mechanism with a knot of frame pivots a fraction of a millimetre
apart at the scale it is drawn (generated "near-coincident pivots"): its
detail view at 10:1 still leaves them 4-6 mm apart, each walled in by the
links' main lines of the drawn positions, so that a name finds no free place
near and no leader that crosses no main line (gen 70 'W' 16 mm off). Such a
knot is drawn again on a smaller disc at GOST 2.302's enlargements past 10:1
(20:1, 40:1), its pivots set _MECHANISM_APART_MM apart, and lettered there;
a disc whose letter is walled in, on a larger disc (#21). Judged by the
sheet linter's own rules."""

from __future__ import annotations

import functools
import re

import numpy as np
import pytest
from lettering import near_findings, solved_seed

from mmt_plans.drawing.detail import DETAIL_LETTERS, DETAIL_RATIOS, spread
from mmt_plans.drawing.markup import point_markup
from mmt_plans.render.look import load_look
from mmt_plans.sheets import sheet1
from mmt_plans.sheets.sheet1 import sketch_mechanism, sketch_mechanism_details

# gen 70 (RPR-RPP-RRR-RRR: P, W, G 4.4 and 7 mm apart at 1:100), drawn at
# 1:100 on sheet 1
KNOTS = (70,)
MU_L = 0.01
_TITLE = re.compile(r"[A-Z] \((\d+):1\)")  # a detail view's title, "A (20:1)"


def _letters(solution) -> str:
    used = {n[:1].upper() for n in solution.mechanism.point_owners}
    return "".join(x for x in DETAIL_LETTERS if x not in used)


def _views(solution) -> sheet1.Views:
    return "apart" if sheet1._arcs_crowd(solution, MU_L) else None


@functools.cache
def _plain(seed: int):
    solution = solved_seed(seed)
    return sketch_mechanism(solution, MU_L, load_look(), "en", views=_views(solution))


@functools.cache
def _detailed(seed: int):
    solution = solved_seed(seed)
    return sketch_mechanism_details(
        solution, MU_L, load_look(), "en", _letters(solution), _plain(seed), _views(solution)
    )


def _point_findings(findings, solution) -> list:
    names = {point_markup(p) for p in solution.mechanism.point_owners}
    return [f for f in findings if f.message.split("'")[1] in names]


@pytest.mark.parametrize("seed", KNOTS)
def test_the_knot_is_drawn_past_ten_to_one_with_its_pivots_set_apart(seed):
    solution = solved_seed(seed)
    made = _detailed(seed)
    assert made is not None
    _, views = made
    (view,) = views
    (title,) = [m for c in view.calls if c.name == "text" and (m := _TITLE.match(c.content))]
    ratio = float(title.group(1))
    assert ratio in (20.0, 40.0) and ratio > max(DETAIL_RATIOS)
    # the view's edge: its disc at the drawing's scale
    (edge,) = [c for c in view.calls if c.name == "circle" and c["radius"] > 10.0]
    radius = edge["radius"] / ratio
    # the pivots in the view stand at least _MECHANISM_APART_MM apart
    centre = np.asarray(view.detail_of)
    _, points = sheet1._mechanism_names(solution, MU_L)
    inside = points[np.hypot(*(points - centre).T) <= radius + 1e-9]
    assert len(inside) >= 3
    assert spread(inside) * ratio >= sheet1._MECHANISM_APART_MM


@pytest.mark.parametrize("seed", KNOTS)
def test_the_knots_pivots_are_named_near_or_led_to(seed):
    solution = solved_seed(seed)
    before = _point_findings(near_findings(_plain(seed)), solution)
    assert before  # what the view mends: pivots' names far in the plain drawing
    main, views = _detailed(seed)
    after = [f for sk in (main, *views) for f in _point_findings(near_findings(sk), solution)]
    assert not after


# gen 265 (RPP-RPR-PRP-RRR at 1:100): the crank's pivot O walled in by the
# blocks of its sliders; a disc of 4 mm round it leaves its letter's rim
# under the blocks (the letter 15 mm off), one of 6 mm letters both
WALLED_RIM = 265


def test_a_disc_whose_letter_is_walled_in_is_drawn_larger():
    solution = solved_seed(WALLED_RIM)
    plain = _plain(WALLED_RIM)
    assert _point_findings(near_findings(plain), solution)  # 'O' far in the plain drawing
    made = _detailed(WALLED_RIM)
    assert made is not None
    main, (view,) = made
    assert not near_findings(main)  # the disc's letter too
    assert not near_findings(view)
    # the crank's pivot named in the view
    pivot = point_markup(solution.mechanism.crank_pivot)
    assert any(c.naming is not None and c.naming.markup == pivot for c in view.calls)
    (edge,) = [c for c in view.calls if c.name == "circle" and c["radius"] > 5.0]
    (title,) = [m for c in view.calls if c.name == "text" and (m := _TITLE.match(c.content))]
    assert edge["radius"] / float(title.group(1)) > 4.0 + 1e-9  # larger than the first disc
