"""The names of a force polygon's sides (issue #21): a polygon's short sides
along one column (task09_v2's group 4-5: R^τ24, G4, F_i4, G5, F_i5, 1.6-4 mm
each, walled in by its long sides) are each named near their side. Where
two of them stood far in turn (F_i5 written first took G5's place), every
name that stood far in an order is written on the fine grid in the orders
after it (Labels.fine_kept), so the last walled-in one finds room there
too, within the box the first orders letter the polygon in."""

from __future__ import annotations

from functools import cache
from pathlib import Path

import pytest

import mmt_plans
from mmt_plans.render.look import load_look
from mmt_plans.render.recording import Arrow, RecordingBackend
from mmt_plans.sheets import sheet2
from mmt_plans.sheets.lint import SheetView, lint
from mmt_plans.sheets.sheet2 import compose_sheet2

ROOT = Path(__file__).resolve().parents[2]
TASK09_V2 = ROOT / "samples" / "tasks" / "seed003" / "task09_v2.toml"


@cache
def _solution():
    return mmt_plans.solve(mmt_plans.load(TASK09_V2))


def _polygon_4_5(monkeypatch, orders: int, fine_kept: bool):
    """task09_v2's polygon of group 4-5 (uk) at the scale its sheet draws
    it, its labels written in `orders` orders, with or without fine_kept."""
    monkeypatch.setattr(sheet2, "_RETRY_ORDERS", orders)
    # the lettering alone: no short side drawn as a line and named under the polygon
    monkeypatch.setattr(sheet2, "_UNNAMED_BELOW", 0.0)
    monkeypatch.setattr(sheet2, "_FORCE_LABELLING", dict(sheet2._LABELLING, fine_kept=fine_kept))
    fa = _solution().require_forces()
    (g,) = [g for g in fa.groups if g.name == "4-5"]
    return sheet2.sketch_force_polygons(
        g.polygons, 40.0, load_look(), "uk", "force-polygon-4-5", "group 4-5"
    )


def test_regression_task09_v2_uk_sheet_2_has_no_finding():
    # 'F_i5' stood 15.5 mm from its side (1.6 mm long, beside G5's) before
    backend = RecordingBackend(841.0, 594.0)
    compose_sheet2(_solution(), backend, "uk")
    assert lint(SheetView.of(backend, "uk", "task09_v2")) == []


def test_a_polygons_short_sides_in_one_column_are_each_named_near_their_side(monkeypatch):
    sk = _polygon_4_5(monkeypatch, 6, fine_kept=True)
    view = SheetView(list(sk.calls), 841.0, 594.0, "uk", "polygon 4-5")
    sides = [c for c in sk.calls if isinstance(c, Arrow) and c.length >= 1.0]
    short = [c for c in sides if c.length < 5.0]
    assert len(short) >= 4  # the column of short sides this is about
    named = {lab.text for lab in view.labels}
    assert {"G4", "Fi4", "G5", "Fi5"} <= named
    assert lint(view, ["label-near", "arrows-named", "label-clear"]) == []


@pytest.mark.parametrize("orders", [1, 6])
def test_names_kept_on_the_fine_grid_letter_the_polygon_within_the_same_box(
    monkeypatch, orders
):
    # without fine_kept one name stands far after six orders (the order that
    # names all of them leads one past the polygon's box, so it is not kept);
    # with it six orders name all of them within the box two orders take
    before = _polygon_4_5(monkeypatch, orders, fine_kept=False)
    after = _polygon_4_5(monkeypatch, orders, fine_kept=True)
    assert before.label_counts is not None and after.label_counts is not None
    assert before.label_counts.far == 1
    assert after.label_counts.far == (1 if orders == 1 else 0)
    assert after.extent() == before.extent()
