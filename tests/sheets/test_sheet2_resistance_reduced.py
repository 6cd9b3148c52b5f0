"""A polygon of F_PR whose other sides run far past it: gen 223 (RRR-RRR-PRP-RRR,
a long frame). At |F_PR| = 150 mm (seed 003, formula (20)) its polygon of group
8-9 is 648 mm tall, taller than the A1 field: sheet 2 had no arrangement at any
scale and `draw` stopped with a layout error. Where the sheet has none with
|F_PR| held at 150 mm, that polygon too goes coarser and says so under it."""

from __future__ import annotations

import functools

import pytest

from mmt_plans.drawing.page import Page
from mmt_plans.render.recording import RecordingBackend
from mmt_plans.sheets.lint import SheetView, guide_sizes
from mmt_plans.sheets.sheet2 import compose_sheet2

from lettering import solved_seed


@functools.lru_cache(maxsize=None)
def _sheet(lang: str):
    solution = solved_seed(223)
    backend = RecordingBackend(841.0, 594.0)
    return solution, backend, compose_sheet2(solution, backend, lang)


@pytest.mark.parametrize("lang", ["en", "uk"])
def test_the_sheet_composes_with_the_resistance_polygon_reduced(lang):
    solution, backend, sheet = _sheet(lang)
    fa = solution.require_forces()
    group = next(g for g in fa.groups if any(
        v.label.startswith("F_PR") for p in g.polygons for v in p.vectors))
    f_pr = max(v.magnitude for p in group.polygons for v in p.vectors if v.label.startswith("F_PR"))
    drawn = f_pr / sheet.scales[f"mu_F {group.name}"]
    assert drawn < 150.0  # the guide's 150 mm let go: it did not fit
    # every drawing inside the frame
    f = Page.of("A1").frame
    for name, r in sheet.placed.items():
        assert f.x - 1e-6 <= r.x and r.x + r.width <= f.x + f.width + 1e-6, name
        assert f.y - 1e-6 <= r.y and r.y + r.height <= f.y + f.height + 1e-6, name
    # said under that polygon, in the sheet's language
    word = "reduced to fit" if lang == "en" else "зменшено"
    texts = [c["content"] for c in backend.in_group(f"force-polygon-{group.name}")
             if c.name == "text"]
    assert any(word in t for t in texts), texts
    view = SheetView.of(backend, lang, f"gen 223 sheet 2 {lang}")
    assert list(guide_sizes(view)) == []
