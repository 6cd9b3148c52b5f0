"""Sheet 1's mechanism detail view drawn to the size of its disc: the crank's
pivot in the disc, ω1's arc walled in by the spokes of the crank's positions
was drawn outside the crank pin's circle, which at the view's ratio is far
larger than the view (gen 81: 19 mm at 1:100, so a 10:1 view of a 4 mm disc
grew to 386 x 394 mm round a 190 mm arc, found no room on the sheet, and the
knot Z, J, W went unlettered, its names 21 mm off). In a detail view the arc
stays in the disc. Of the choices that letter the drawing better, the sheet
takes the first whose views find room (`mechanism_detail_options`): a
draughtsman takes the enlargement that fits. The views' size for gen 81 and
the held-out gen 240 (its pivots Q and E 6 mm apart at 1:250); gen 240's whole
sheet 1 judged by the sheet linter's own rules, en and uk (#21)."""

from __future__ import annotations

import functools

import numpy as np
import pytest
from lettering import solved_seed

from mmt_plans.drawing.detail import DETAIL_LETTERS, DETAIL_RATIOS, Detail
from mmt_plans.drawing.markup import point_markup
from mmt_plans.render.look import load_look
from mmt_plans.render.recording import RecordingBackend
from mmt_plans.sheets import sheet1
from mmt_plans.sheets.lint import SheetView, lint
from mmt_plans.sheets.sheet1 import compose_sheet1, sketch_mechanism

# (seed, the μl sheet 1 draws it at): a knot round the crank's pivot
KNOTS = ((81, 0.01), (240, 0.004))
_DISC_MM = 4.0  # a disc of this radius at the drawing's scale round the pivot
_NAME_MM = 10.0  # a name by the disc's rim, or the view's title, past its edge at most


@pytest.mark.parametrize("lang", ["en", "uk"])
@pytest.mark.parametrize(("seed", "mu_l"), KNOTS)
@pytest.mark.parametrize("ratio", DETAIL_RATIOS)
def test_the_crank_pivots_detail_view_is_as_large_as_its_disc(seed, mu_l, ratio, lang):
    solution = solved_seed(seed)
    mech = solution.mechanism
    pivot = np.asarray(solution.sweep.points[mech.crank_pivot][0], float)
    letter = next(x for x in DETAIL_LETTERS if x not in {p[:1].upper() for p in mech.point_owners})
    detail = Detail(letter, (float(pivot[0]), float(pivot[1])), _DISC_MM * mu_l, ratio)
    view = sketch_mechanism(solution, mu_l, load_look(), lang, (detail,), detail)
    ext = view.extent()
    # the view's disc as drawn, or (a small view) the largest arc ω1 is tried
    # on round the pivot: never the crank pin's circle at the view's ratio
    edge = max(2.0 * _DISC_MM * ratio, 2.0 * max(sheet1._CRANK_RADII))
    assert ext.width <= edge + 2.0 * _NAME_MM
    assert ext.height <= edge + 2.0 * _NAME_MM
    # and ω1 still named there, by its arc round the pivot
    assert any(c.naming is not None and c.naming.markup == "ω_{1}" for c in view.calls)


@functools.cache
def _sheet(seed: int, lang: str):
    backend = RecordingBackend(841.0, 594.0)
    drawn = compose_sheet1(solved_seed(seed), backend, lang)
    return SheetView.of(backend, lang, f"gen{seed:04d} sheet 1 {lang}"), drawn


# Gen 81's whole sheet 1 is not clean yet: its knot Z, J, W (three pivots
# close together at 1:100): J and W still stand 16 mm off, en and uk (10 findings -> 4);
# only the held-out gen 240 is judged whole here.
@pytest.mark.parametrize("lang", ["en", "uk"])
@pytest.mark.parametrize("seed", [240])
def test_the_knots_sheet_1_is_lint_clean(seed, lang):
    view, _ = _sheet(seed, lang)
    assert not lint(view), lint(view)


@pytest.mark.parametrize("lang", ["en", "uk"])
@pytest.mark.parametrize("seed", [240])
def test_the_knots_detail_view_lies_in_the_mechanisms_field(seed, lang):
    view, drawn = _sheet(seed, lang)
    assert "mechanism-detail" in drawn.placed
    box, field = drawn.placed["mechanism-detail"], drawn.field
    assert field is not None
    assert field.left - 1e-6 <= box.left and box.right <= field.right + 1e-6
    assert field.bottom - 1e-6 <= box.bottom and box.top <= field.top + 1e-6
    assert not box.overlaps(drawn.placed["mechanism"])
    # the knot's pivots named there, and only there
    pivots = {p for p, owners in solved_seed(seed).mechanism.point_owners.items() if 0 in owners}
    crank = solved_seed(seed).mechanism.crank_pivot
    named = [
        lab
        for lab in view.labels
        if lab.naming is not None and lab.naming.markup == point_markup(crank) and crank in pivots
    ]
    assert len(named) == 1
    assert any(g.startswith("mechanism-detail") for g in named[0].runs[0].groups)
