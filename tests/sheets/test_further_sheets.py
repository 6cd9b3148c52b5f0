"""A force analysis too large for one sheet 2 continues on further sheets
(README, Sheet 2; sheets/common.further_groups): the 25-link chain of twelve
RRR groups keeps on sheet 2 the loaded mechanism, the driving link and its
polygon, the lever and the tables; its groups with their force polygons go on
sheets 3–4, six to a sheet at the guide's 150–300 mm. An ordinary mechanism
keeps its two sheets."""

from __future__ import annotations

from functools import cache
from pathlib import Path

import pytest
from click.testing import CliRunner

import mmt_plans
from mmt_plans.cli import main
from mmt_plans.drawing.page import Page
from mmt_plans.i18n import catalogue
from mmt_plans.scales import FORCE_PLAN
from mmt_plans.sheets.common import SHEET2_GROUPS, further_groups, sheet_count, title_fields
from mmt_plans.sheets.compose import SheetNotAvailable, available_sheets, compose
from mmt_plans.sheets.lint import SheetView, lint

ROOT = Path(__file__).resolve().parents[2]
CHAIN = ROOT / "tests" / "data" / "hard" / "chain_25_links.toml"
SLIDER = ROOT / "samples" / "offset_slider_crank.toml"


@cache
def _chain():
    return mmt_plans.solve(mmt_plans.load(CHAIN))


@cache
def _chain_sheets():
    return compose(_chain(), "en")


def _title_cells(sheet) -> dict[str, list[str]]:
    block = Page.of("A1").title_block
    out: dict[str, list[str]] = {}
    for c in sheet.recording().in_group("title-block"):
        if c.name != "text":
            continue
        for cell in ("title", "sheet", "sheets", "designation"):
            r = block.cell(cell)
            if r.left <= c["pos"][0] <= r.right and r.bottom <= c["pos"][1] <= r.top:
                out.setdefault(cell, []).append(c["content"])
    return out


def test_further_groups_rule():
    # sheet 2 holds up to SHEET2_GROUPS groups; more go six to a further
    # sheet, as evenly as their number allows, each group once, in order
    assert further_groups(SHEET2_GROUPS) == ()
    assert [len(r) for r in further_groups(12)] == [6, 6]
    assert [len(r) for r in further_groups(13)] == [4, 5, 4]
    assert [len(r) for r in further_groups(6)] == [6]
    for count in range(SHEET2_GROUPS + 1, 30):
        runs = further_groups(count)
        assert [i for r in runs for i in r] == list(range(count))
        assert max(len(r) for r in runs) <= 6


def test_chain_25_composes_four_sheets_each_group_once():
    solution = _chain()
    fa = solution.require_forces()
    assert sheet_count(solution) == 4
    assert sorted(available_sheets(solution)) == [1, 2, 3, 4]
    composed = _chain_sheets()
    assert [s.number for s in composed.further] == [3, 4]
    drawn = {n: composed.sheet(n).drawings for n in range(2, 5)}
    # sheet 2: the loaded mechanism, the driving link and its polygon, the lever
    assert {"force-mechanism", "driving-link", "force-polygon-1", "zhukovsky-lever"} <= set(
        drawn[2]
    )
    assert not [d for d in drawn[2] if d.startswith("group-")]
    # every group and its polygon drawn once across sheets 3-4, in the order solved
    groups = [d[len("group-") :] for n in (3, 4) for d in drawn[n] if d.startswith("group-")]
    assert groups == [g.name for g in fa.groups]
    for n in (3, 4):
        mine = [d[len("group-") :] for d in drawn[n] if d.startswith("group-")]
        assert sorted(d for d in drawn[n] if d.startswith("force-polygon-")) == sorted(
            f"force-polygon-{g}" for g in mine
        )
    # the note finds each group's figure on its sheet
    assert [composed.holding(f"group-{g.name}") for g in fa.groups] == [3] * 6 + [4] * 6
    assert composed.holding("zhukovsky-lever") == 2
    # the note reads every group's scale (sheet 2's record with the further sheets')
    _, second = composed.scales
    assert second is not None and set(second.mu_l_group) == {g.name for g in fa.groups}
    assert set(second.mu_F) == {f"group {g.name}" for g in fa.groups} | {"link 1"}


def test_chain_25_polygons_at_the_guides_size():
    # the further sheets draw each group's polygons at the guide's scale
    # (longest side 150-300 mm): none "reduced to fit"
    composed = _chain_sheets()
    fa = _chain().require_forces()
    reduced = catalogue("en").words("sheet2")["polygon_reduced"].split("(")[0].strip()
    for n in (3, 4):
        sheet = composed.sheet(n)
        texts = [c["content"] for c in sheet.calls if c.name == "text"]
        assert not [t for t in texts if reduced in t]
        scales = sheet.scales
        for g in fa.groups:
            if g.name in scales.mu_l_group:
                longest = max(p.largest for p in g.polygons) / scales.mu_F[f"group {g.name}"]
                assert FORCE_PLAN.low <= longest <= FORCE_PLAN.high + 1e-6, (g.name, longest)


def test_chain_25_title_blocks_number_the_sheets():
    composed = _chain_sheets()
    words = catalogue("en").words("sheet2")
    for n in range(1, 5):
        got = _title_cells(composed.sheet(n))
        assert [t.strip() for t in got["sheet"] if t.strip().isdigit()] == [str(n)]
        assert [t.strip() for t in got["sheets"] if t.strip().isdigit()] == ["4"]
        assert got["designation"][0].endswith(f".0{n}")
    title = " ".join(_title_cells(composed.sheet(2))["title"])
    assert "sheets 3–4" in title, title
    for n in (3, 4):
        assert words["further_sheet"] in " ".join(_title_cells(composed.sheet(n))["title"])
    # the Ukrainian sheets count the same
    for n in range(1, 5):
        fields = title_fields(_chain(), 0.01, "uk", sheet=n)
        assert (fields["sheet"], fields["sheets"]) == (str(n), "4")


def test_chain_25_further_sheets_pass_the_linter():
    # sheet 2 took 515 findings when it held the twelve groups (a blob of a
    # mechanism at 0.25 m/mm, polygons reduced to fit); its further sheets
    # pass every rule: names near, clear, the polygons in the guide, the
    # field filled (the polygons enlarged within 300 mm)
    composed = _chain_sheets()
    for n in (2, 3, 4):
        view = SheetView.of(composed.sheet(n).recording(), "en", f"chain_25 sheet {n}")
        found = lint(view)
        assert not found, [f.message for f in found]


def test_ordinary_mechanism_keeps_two_sheets():
    solution = mmt_plans.solve(mmt_plans.load(SLIDER))
    assert sheet_count(solution) == 2
    assert sorted(available_sheets(solution)) == [1, 2]
    composed = compose(solution, "en")
    assert composed.further == ()
    with pytest.raises(SheetNotAvailable):
        composed.sheet(3)
    assert title_fields(solution, 0.01, "uk", sheet=2)["sheets"] == "2"


def test_draw_sheet_beyond_the_last_is_a_clean_error(tmp_path):
    result = CliRunner().invoke(
        main, ["draw", str(SLIDER), "-o", str(tmp_path), "--format", "svg", "--sheet", "3"]
    )
    assert result.exit_code == 2, result.output
    assert "Traceback" not in result.output
    assert "sheet 3" in result.output
    assert not list(tmp_path.glob("sheet*"))
