"""The layout rule of both sheets (issue #21): the guide's sizes (seed 003:
pa, πa 100 … 200 mm as each plan's longest vector from its pole; a force
polygon's longest side 150 … 300 mm), or a note on the sheet saying the
drawing is reduced; one set of scales for the en and the uk sheet; the
diagrams S, V, a from the top; the mechanism's field."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import mmt_plans
from mmt_plans.drawing.page import Page, Rect
from mmt_plans.drawing.layout import SheetLayout
from mmt_plans.sheets.compose import compose
from mmt_plans.sheets.sheet1 import mechanism_field

ROOT = Path(__file__).resolve().parents[2]
CASES = ["six_link_press", "shaper"]
REDUCED = ("reduced", "зменшено")


@pytest.fixture(scope="module", params=CASES)
def composed(request):
    solution = mmt_plans.solve(mmt_plans.load(ROOT / "samples" / f"{request.param}.toml"))
    return solution, {lang: compose(solution, lang) for lang in ("en", "uk")}


def _texts(sheet, gid):
    return [c["content"] for c in sheet.calls if c.name == "text" and gid in c.groups]


def _pole_longest(solution, i, kind):
    """Independently of the sheet's code: the longest absolute vector of the
    plan's moving points (the S points are drawn as dots) and of the
    components that start at the pole."""
    view = solution.plan(i)
    images = view.velocity_images if kind == "velocity" else view.acceleration_images
    owners = solution.mechanism.point_owners
    moving = [p for p, o in owners.items() if 0 not in o and not p.startswith("S")]
    out = max(float(np.hypot(*images[p])) for p in moving if p in images)
    for g in view.groups:
        for c in g.velocity if kind == "velocity" else g.acceleration:
            if np.hypot(*c.start) == 0.0:
                out = max(out, float(np.hypot(*c.vector)))
    return out


def test_plans_within_the_guide_or_reduced_with_a_reason(composed):
    solution, sheets = composed
    for lang, s in sheets.items():
        first, _ = s.scales
        for i in solution.plan_positions:
            for kind, mu in (("velocity", first.mu_V[i]), ("acceleration", first.mu_a[i])):
                drawn = _pole_longest(solution, i, kind) / mu
                assert drawn <= 200.0 + 1e-6, (lang, kind, i, drawn)
                if drawn < 100.0:
                    texts = _texts(s.first, f"{kind}-plan-{i}")
                    assert any(w in t for t in texts for w in REDUCED), (lang, kind, i, drawn)


def test_force_polygons_within_the_guide_or_reduced_with_a_reason(composed):
    solution, sheets = composed
    fa = solution.require_forces()
    sets = {f"group {g.name}": (g.name, g.polygons) for g in fa.groups}
    sets[f"link {fa.driving_link.link}"] = (str(fa.driving_link.link), (fa.driving_link.polygon,))
    for lang, s in sheets.items():
        _, second = s.scales
        for title, (name, polygons) in sets.items():
            side = max(abs(v.magnitude) for p in polygons for v in p.vectors)
            if side == 0.0:
                continue
            drawn = side / second.mu_F[title]
            assert drawn <= 300.0 + 1e-6, (lang, title, drawn)
            if drawn < 150.0:
                texts = _texts(s.second, f"force-polygon-{name}")
                assert any(w in t for t in texts for w in REDUCED), (lang, title, drawn)


def test_en_and_uk_drawn_at_the_same_scales(composed):
    _, sheets = composed
    assert sheets["en"].scales == sheets["uk"].scales


def test_diagrams_s_v_a_from_the_top(composed):
    _, sheets = composed
    for s in sheets.values():
        tops = {}
        for which in "sva":
            ys = [
                y
                for c in s.first.calls
                if f"diagram-{which}" in c.groups and c.bbox() is not None
                for y in (c.bbox()[1], c.bbox()[3])
            ]
            tops[which] = (min(ys), max(ys))
        assert tops["s"][0] > tops["v"][1] - 1e-6
        assert tops["v"][0] > tops["a"][1] - 1e-6


def test_mechanism_field_gives_a_tall_drawing_the_height_and_a_wide_one_the_width():
    layout = SheetLayout(Page.of("A1"), gap=8.0)
    region = layout.region
    # the diagrams 400 x 300 mm bottom right (600 mm from the right edge), the
    # tables 300 x 150 mm top right
    diagrams = Rect(region.right - 600.0, region.bottom, 400.0, 300.0)
    layout.register("diagrams", diagrams)
    layout.register("tables", Rect(region.right - 300.0, region.top - 150.0, 300.0, 150.0), "table")
    tall = mechanism_field(layout, 8.0, (100.0, 400.0))
    wide = mechanism_field(layout, 8.0, (400.0, 100.0))
    # tall: the sheet's whole height, left of the diagrams
    assert (tall.left, tall.bottom, tall.top) == pytest.approx(
        (region.left, region.bottom, region.top)
    )
    assert tall.right == pytest.approx(diagrams.left - 8.0)
    # wide: above the diagrams, up to the tables
    assert wide.right == pytest.approx(region.right - 300.0 - 8.0)
    assert wide.bottom == pytest.approx(diagrams.top + 8.0)
    assert wide.top == pytest.approx(region.top)
    for field in (tall, wide):  # clear of everything placed, by the gap
        for e in layout.elements:
            b = e.bounds
            apart = (
                b.left >= field.right + 8.0 - 1e-6
                or b.right <= field.left - 8.0 + 1e-6
                or b.bottom >= field.top + 8.0 - 1e-6
                or b.top <= field.bottom - 8.0 + 1e-6
            )
            assert apart, (e.name, field)
