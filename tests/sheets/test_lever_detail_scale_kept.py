"""The lever's detail views where the lever reaches sheet 2 smaller than the
scale they were chosen at (#21): each is drawn at the first ratio of the
series that draws it at its scale of that lever or larger, so that its names
keep the room they were given."""

from __future__ import annotations

from mmt_plans.drawing.detail import DETAIL_MM, Detail
from mmt_plans.generate import generate_one
from mmt_plans.render.recording import RecordingBackend
from mmt_plans.sheets.lint import SheetView, lint
from mmt_plans.sheets.sheet2 import _drawn_at, compose_sheet2
from mmt_plans.solution import solve
from mmt_plans.spec import loads

CROWD = 30  # gen 30 (RRR-RRR-RRR-RRP-RRR): A (40:1) round p, chosen at 1:0.008


def test_a_view_keeps_its_scale_on_a_lever_drawn_smaller():
    """A, 1.5 mm round p at 40:1 of the lever at 1:0.008, is 50:1 of the
    lever at 1:0.01 (its scale, 1:0.0002, kept); on the lever at its own or
    a larger scale it is drawn as chosen; a ratio that would draw it past
    DETAIL_MM in radius is not taken."""
    view = Detail("A", (0.0, 0.0), 0.012, 40.0)
    assert _drawn_at(view, 0.01, 0.008).ratio == 50.0
    assert _drawn_at(view, 0.008, 0.008) == view
    assert _drawn_at(view, 0.005, 0.008) == view
    wide = Detail("B", (0.0, 0.0), 0.2, 2.5)  # 20 mm at 1:0.01: 50 mm at 2.5:1
    at = _drawn_at(wide, 0.0125, 0.01)
    assert at.ratio == 4.0 and at.ratio * 0.2 / 0.0125 <= DETAIL_MM
    assert _drawn_at(wide, 0.01, 0.0025).ratio == 2.5  # 4:1 would be 80 mm


def _names_in_views(lang: str) -> tuple[list[str], object]:
    g = generate_one(CROWD)
    backend = RecordingBackend(841.0, 594.0)
    sheet = compose_sheet2(solve(loads(g.toml, f"{g.name}.toml")), backend, lang)
    found = lint(SheetView.of(backend, lang, g.name), ["label-near", "label-clear"])
    views = [r for name, r in sheet.placed.items() if name.startswith("zhukovsky-lever-detail")]
    crowded = [
        str(f)
        for f in found
        for r in views
        if r.x - 1 <= f.where[0] <= r.x + r.width + 1
        and r.y - 1 <= f.where[1] <= r.y + r.height + 1
    ]
    return crowded, sheet


def test_the_view_of_a_lever_drawn_a_step_smaller_keeps_its_names_near():
    """Gen 30 on sheet 2 (uk): the lever reaches the sheet at 1:0.01, a step
    smaller than the 1:0.008 its view A (40:1 round p, 30 names) was chosen
    at; drawn at 40:1 there, 10 of the view's names stood 10-26 mm off or on
    a line. Drawn at 50:1 (its scale kept) at most 3 do, as in en, where the
    lever is drawn at 1:0.008 and the view at 40:1 (1 name off)."""
    crowded, sheet = _names_in_views("uk")
    assert sheet.scales["mu_V"] == 0.01
    assert [d.ratio for d in sheet.details] == [50.0]
    assert len(crowded) <= 3, crowded
    crowded, sheet = _names_in_views("en")
    assert sheet.scales["mu_V"] == 0.008 and [d.ratio for d in sheet.details] == [40.0]
    assert len(crowded) <= 1, crowded
