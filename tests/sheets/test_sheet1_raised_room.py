"""Sheet 1's diagrams lifted clear of the title block where the field is
left too empty (issue #21, field-filled; in the last pass, the diagrams'
scales from the whole series): the column may then run on to the region's
right edge over the title block.

Held-out gens 411 (en and uk) and 428 (uk) failed the rule before this
(51 % and 50 % of the field empty): a tall, narrow mechanism whose plans
stop at the guide's 200 mm, and the diagrams' column, standing on the
sheet's foot, stopped short of the title block beside it."""

from __future__ import annotations

import pytest

import mmt_plans
from mmt_plans.drawing.layout import Page, Rect, SheetLayout
from mmt_plans.generate import generate_one
from mmt_plans.render.recording import RecordingBackend
from mmt_plans.sheets.lint import SheetView, lint
from mmt_plans.sheets.sheet1 import _diagram_rooms, compose_sheet1
from mmt_plans.spec import loads

GAP = 8.0


def _layout() -> tuple[SheetLayout, Rect, Rect]:
    """A column on the sheet's foot left of the title block, a table above
    the block: the column's room on its foot ends at the block."""
    page = Page.of("A1")
    layout = SheetLayout(page, gap=GAP)
    block = layout["title-block"].bounds
    region = layout.region
    column = Rect(region.left + 150.0, region.bottom, 300.0, 200.0)
    layout.register("diagrams", column)
    layout.register("table", Rect(region.right - 150.0, region.top - 120.0, 150.0, 120.0), "table")
    return layout, column, block


def _clear(room: Rect, layout: SheetLayout) -> bool:
    return all(
        e.name == "diagrams"
        or room.right <= e.bounds.left - GAP + 1e-6
        or room.left >= e.bounds.right + GAP - 1e-6
        or room.top <= e.bounds.bottom - GAP + 1e-6
        or room.bottom >= e.bounds.top + GAP - 1e-6
        for e in layout.elements
    )


def test_on_its_foot_the_room_stops_at_the_title_block():
    layout, column, block = _layout()
    rooms = _diagram_rooms(layout, column, GAP)
    assert rooms
    assert all(r.bottom == column.bottom and r.right <= block.left - GAP + 1e-6 for r in rooms)
    assert all(_clear(r, layout) for r in rooms)


def test_raised_the_room_runs_over_the_title_block_to_the_right_edge():
    layout, column, block = _layout()
    rooms = _diagram_rooms(layout, column, GAP, raised=True)
    over = [r for r in rooms if r.bottom > column.bottom]
    assert over, "no room lifted clear of the title block"
    assert all(r.bottom == pytest.approx(block.top + GAP) for r in over)
    assert max(r.right for r in over) == pytest.approx(layout.region.right)
    # each is still clear of every element and at least as wide as the column,
    # three quarters as high
    assert all(_clear(r, layout) for r in rooms)
    assert all(r.width >= column.width - 1e-6 and r.height >= 0.75 * column.height for r in rooms)


@pytest.mark.parametrize("case", ["411:en", "411:uk", "428:uk"])
def test_held_out_tall_narrow_mechanisms_fill_the_field(case):
    seed, lang = case.split(":")
    g = generate_one(int(seed))
    solution = mmt_plans.solve(loads(g.toml, f"{g.name}.toml"))
    backend = RecordingBackend(841.0, 594.0)
    sheet = compose_sheet1(solution, backend, lang)
    view = SheetView.of(backend, lang, case)
    rules = ["field-filled", "guide-sizes", "label-near", "label-clear", "letter-height"]
    assert lint(view, rules) == []
    diagrams = sheet.layout["diagrams"].bounds
    block = sheet.layout["title-block"].bounds
    # the column stands over the title block, running on past its left edge
    assert diagrams.bottom >= block.top
    assert diagrams.right > block.left
