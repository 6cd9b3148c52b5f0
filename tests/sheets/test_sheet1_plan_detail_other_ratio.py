"""A plan's detail view whose names still crowd at the ratio its names' room
chose (`roomy_ratio`): a draughtsman takes another enlargement of the series.
Gen 20's acceleration plan 4, one series step coarser than its guide's: the
detail round s7 and its normal component drawn at 4:1 walled s5 in (10.5 mm
off on sheet 1, en), which at 5:1 stands by its image. The views are drawn at
the other ratios, nearest first, and the first leaving no name crowded kept
(#21). Judged by the sheet linter's own rules, en and uk."""

from __future__ import annotations

import functools
import re

import pytest
from lettering import solved_seed

from mmt_plans.drawing.detail import DETAIL_LETTERS, DETAIL_RATIOS
from mmt_plans.render.look import load_look
from mmt_plans.render.recording import RecordingBackend
from mmt_plans.sheets import sheet1
from mmt_plans.sheets.crowd import crowded_names
from mmt_plans.sheets.lint import SheetView, lint

SEED, PLAN = 20, 4
_TITLE = re.compile(r"[A-Z] \((\d+(?:[.,]\d+)?):1\)")


@pytest.mark.parametrize("lang", ["en", "uk"])
@pytest.mark.parametrize("shrink", [0, 1, 2])
def test_the_plans_detail_views_leave_no_name_crowded(shrink, lang):
    solution = solved_seed(SEED)
    mu = sheet1._plan_scales(solution, shrink)[f"acceleration {PLAN}"]
    made = sheet1.sketch_plan_details(
        solution, PLAN, mu, "acceleration", load_look(), lang, "", DETAIL_LETTERS
    )
    if made is None:
        return  # no crowd at this scale: nothing to detail
    plan, views, _ = made
    assert not len(crowded_names(plan, lang))
    for view in views:
        assert not len(crowded_names(view, lang))
        # at a ratio of the standard series, titled so
        (title,) = [m for c in view.calls if c.name == "text" and (m := _TITLE.match(c.content))]
        assert float(title.group(1).replace(",", ".")) in DETAIL_RATIOS


@functools.cache
def _sheet(lang: str) -> SheetView:
    backend = RecordingBackend(841.0, 594.0)
    sheet1.compose_sheet1(solved_seed(SEED), backend, lang)
    return SheetView.of(backend, lang, f"gen{SEED:04d} sheet 1 {lang}")


@pytest.mark.parametrize("lang", ["en", "uk"])
def test_sheet_1_is_lint_clean(lang):
    findings = lint(_sheet(lang))
    assert not findings, findings
