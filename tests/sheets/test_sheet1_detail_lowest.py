"""Sheet 1's mechanism detail view where its knot's place leaves the sheet
no room (issue #21): the view goes in the mechanism's field nearest the
knot it details; where the rest of the sheet then finds no room, in the
field's lowest free place instead. Held-out gen 441 (1:100): its view by the
crank's knot took the room beside the drawing that the 315 mm velocity plan
of position 11 stands in, so no layout held the view; the sheet was drawn
plain and 'D' stood 11.2 mm off its pivot, walled in by blocks. The field
under the drawing was 200 mm high and empty."""

from __future__ import annotations

import functools

import pytest
from lettering import solved_seed

from mmt_plans.drawing.layout import LayoutError, Page
from mmt_plans.render.recording import RecordingBackend
from mmt_plans.sheets import sheet1
from mmt_plans.sheets.lint import SheetView, lint
from mmt_plans.sheets.sheet1 import compose_sheet1

SEED = 441


@functools.cache
def _sheet(lang: str):
    backend = RecordingBackend(841.0, 594.0)
    drawn = compose_sheet1(solved_seed(SEED), backend, lang)
    return SheetView.of(backend, lang, f"gen{SEED:04d} sheet 1 {lang}"), drawn


def test_the_knot_gets_its_view_in_the_field_under_the_drawing():
    _, drawn = _sheet("en")
    details = [n for n in drawn.placed if n.startswith("mechanism-detail")]
    assert details, "no detail view of the crank's knot"
    field, mech = drawn.field, drawn.placed["mechanism"]
    assert field is not None
    for name in details:
        rect = drawn.placed[name]
        assert field.left - 1e-6 <= rect.left and rect.right <= field.right + 1e-6
        assert field.bottom - 1e-6 <= rect.bottom and rect.top <= mech.bottom + 1e-6


@pytest.mark.parametrize("lang", ["en", "uk"])
def test_every_name_near_and_clear(lang):
    """(uk's field is 18 mm wider: there the view by its knot finds room.)"""
    view, _ = _sheet(lang)
    rules = ["label-near", "label-clear", "leader-clear", "names-unique", "field-filled"]
    assert lint(view, rules) == []


def test_the_knots_place_is_tried_first(monkeypatch):
    """The lowest place is the second choice: asked only after the layout
    with the view by its knot failed, and not after the mechanism itself
    found no room in its field (no place of a view helps that)."""
    calls: list[tuple[bool, bool]] = []  # (by its knot, a detail view in the order)
    once = sheet1._layout_once

    def spy(*args, by_knot=True):
        detailed = any(n.startswith("mechanism-detail") for n in args[2])
        calls.append((by_knot, detailed))
        if by_knot and detailed:
            raise LayoutError("velocity-plan-11: no room")
        return once(*args, by_knot=by_knot)

    monkeypatch.setattr(sheet1, "_layout_once", spy)
    backend = RecordingBackend(841.0, 594.0)
    compose_sheet1(solved_seed(SEED), backend, "en")
    retries = [k for k, (by_knot, _) in enumerate(calls) if not by_knot]
    assert retries, "the lowest place never tried"
    # only with detail views, each right after the try by the knot failed
    assert all(calls[k][1] and calls[k - 1] == (True, True) for k in retries)
    assert all(calls[k + 1] == (False, True) for k, c in enumerate(calls[:-1]) if c == (True, True))

    calls.clear()

    def field_too_small(*args, by_knot=True):
        calls.append((by_knot, True))
        raise LayoutError("mechanism: 156 x 370 mm is larger than its field")

    monkeypatch.setattr(sheet1, "_layout_once", field_too_small)
    with pytest.raises(LayoutError):
        sheet1._try_layout(*_args_with_detail())
    assert calls == [(True, True)]


def _args_with_detail():
    """_try_layout's arguments for an order holding a mechanism detail view
    (the sketches are not reached: _layout_once is replaced)."""
    order = ["mechanism", "mechanism-detail"]
    return Page.of("A1"), {}, order, 8.0, True
