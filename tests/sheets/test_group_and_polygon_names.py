"""Sheet 2's group drawings and force polygons (issue #21).

A reaction whose line of action lies far off its group (a guide's normal
force, R_{0,11} of gen 20's group 10-11) is drawn at the block with the
couple that carries it there. The couple was named "M0_11", lettering that
reads "M011" with a subscript the placer had not kept room for (it
overlapped R_{0,11}); it is M_{0,11}, named as the reaction it carries.

A polygon's side shorter than its arrowhead whose name finds no place by it
(gen 165's R^τ_{9,10}, 1.9 mm between the long R^n_{9,10} and R_{9,10}) stood
unnamed, its name 9.4 mm off: it is drawn as a plain line closing the chain
and named in a line under the polygon."""

from __future__ import annotations

import math
from functools import cache

import pytest

from mmt_plans.generate import generate_one
from mmt_plans.render.look import load_look
from mmt_plans.render.recording import Arrow, Line, RecordingBackend
from mmt_plans.sheets import sheet2
from mmt_plans.sheets.lint import SheetView, lint
from mmt_plans.sheets.sheet2 import compose_sheet2
from mmt_plans.solution import solve
from mmt_plans.spec import loads


@cache
def _solution(seed: int):
    g = generate_one(seed)
    return solve(loads(g.toml, f"{g.name}.toml"))


@cache
def _sheet(seed: int, lang: str) -> SheetView:
    backend = RecordingBackend(841.0, 594.0)
    compose_sheet2(_solution(seed), backend, lang)
    return SheetView.of(backend, lang, f"gen {seed} sheet 2 {lang}")


@pytest.mark.parametrize("lang", ["en", "uk"])
def test_a_far_reactions_couple_is_named_as_the_reaction(lang):
    view = _sheet(20, lang)
    couples = [
        lab for lab in view.labels if "group-10-11" in lab.groups and lab.text.startswith("M0")
    ]
    assert [lab.text for lab in couples] == ["M0,11"]
    (couple,) = couples
    assert couple.naming is not None and couple.naming.markup == "M_{0,11}"
    assert not [f for f in lint(view, ["label-clear", "label-near"]) if "M0" in str(f)]


def _polygon_10_11(lang: str, unnamed: frozenset[str] = frozenset()):
    fa = _solution(165).require_forces()
    (g,) = [g for g in fa.groups if g.name == "10-11"]
    return sheet2.sketch_force_polygons(
        g.polygons, 2.5, load_look(), lang, "force-polygon-10-11", "group 10-11", unnamed=unnamed
    )


@pytest.mark.parametrize("lang", ["en", "uk"])
def test_a_side_too_short_for_its_name_is_a_line_named_under_the_polygon(lang):
    sk = _polygon_10_11(lang)
    view = SheetView(list(sk.calls), 841.0, 594.0, lang, "polygon 10-11")
    # the side, 1.9 mm at 2.5 N/mm, is no arrow but a dashed line of that length
    arrows = [c for c in sk.calls if isinstance(c, Arrow)]
    assert all(c.length >= 3.5 for c in arrows)
    short = [c for c in sk.calls if isinstance(c, Line) and 1.0 < math.dist(c.start, c.end) < 3.5]
    assert [c.line for c in short if c.line != "thin"] == ["dashed"]
    # its name, in the line under the polygon and nowhere by it
    notes = [lab.text for lab in view.labels if lab.naming is None and "(" in lab.text]
    assert [n for n in notes if "Rτ9,10" in n] == [
        {
            "en": "shorter than an arrowhead (3.5 mm), drawn as lines: Rτ9,10",
            "uk": "коротші за вістря стрілки (3,5 мм), показані лініями: Rτ9,10",
        }[lang]
    ]
    assert "Rτ9,10" not in {lab.text for lab in view.labels if lab.naming is not None}
    assert lint(view, ["label-near", "arrows-named", "label-clear"]) == []


@pytest.mark.parametrize("lang", ["en", "uk"])
def test_gen_165_sheet_2_polygon_10_11_has_no_finding(lang):
    view = _sheet(165, lang)
    found = [f for f in lint(view) if "9,10" in str(f) or f.rule == "arrows-named"]
    assert found == []
