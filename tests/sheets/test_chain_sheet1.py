"""Sheet 1 of a mechanism whose drawing in all its positions cannot hold the
ω/ε arcs of its links (issue 21): tests/data/hard/chain_25_links, a strip
~250 × 30 mm at 1:20 carrying 2 × 24 links' arcs, had ~120 ω/ε names standing
9–20 mm off their arcs. Where the plan positions' links have less than
_ARC_CROWD mm² round them each (_arcs_crowd), each plan position is drawn in a
view of its own ("Position 3") with its links' ω/ε arcs and its points'
names, and the drawing in all positions carries the positions, the
trajectories, the names and ω1 only."""

from __future__ import annotations

from functools import cache
from pathlib import Path

import pytest

from mmt_plans.render.recording import RecordingBackend
from mmt_plans.sheets import sheet1 as sheet1_module
from mmt_plans.sheets.lint import SheetView, lint
from mmt_plans.sheets.sheet1 import compose_sheet1
from mmt_plans.solution import Solution, solve
from mmt_plans.spec import loads

ROOT = Path(__file__).resolve().parents[2]


@cache
def _solution(path: str) -> Solution:
    return solve(loads((ROOT / path).read_text(encoding="utf-8"), path))


@cache
def _sheet1(path: str, lang: str) -> tuple[SheetView, sheet1_module.Sheet1]:
    backend = RecordingBackend(841.0, 594.0)
    result = compose_sheet1(_solution(path), backend, lang)  # type: ignore[arg-type]
    return SheetView.of(backend, lang, f"{path} sheet 1 {lang}"), result  # type: ignore[arg-type]


CHAIN = "tests/data/hard/chain_25_links.toml"


@pytest.mark.parametrize("lang", ["en", "uk"])
def test_chain_25_plan_positions_drawn_in_views_of_their_own(lang):
    view, result = _sheet1(CHAIN, lang)
    solution = _solution(CHAIN)
    assert sheet1_module._arcs_crowd(solution, result.scales["mu_l"])
    views = {f"mechanism-position-{i}" for i in solution.plan_positions}
    assert views <= set(result.placed)

    def named(group: str) -> list[str]:
        return [lab.text for lab in view.labels if lab.naming and lab.groups[:1] == (group,)]

    # the drawing in all positions: no link's ω or ε but ω1, the drive's
    assert [t for t in named("mechanism") if t[:1] in "ωε"] == ["ω1"]
    for gid in views:
        spins = [t for t in named(gid) if t[:1] in "ωε"]
        assert len(spins) >= 12, gid  # the moving links' ω, ε at that position
        assert {"C1", "D1", "B12"} <= set(named(gid)), gid
    # the drawing in all positions is lettered clean now (its position
    # numbers and point names had 22 findings of the 140)
    box = result.placed["mechanism"]
    inside = [
        f
        for f in lint(view, ["label-near", "label-clear"])
        if box.x <= f.where[0] <= box.x + box.width and box.y <= f.where[1] <= box.y + box.height
    ]
    assert inside == []


@pytest.mark.parametrize("lang", ["en", "uk"])
def test_chain_25_sheet1_findings_below_the_bound(lang):
    # 70 a language before (each link's arcs at both positions in one strip
    # 30 mm tall); the views, at 1:20 (uk: 14 findings each) or 1:25 where
    # the sheet has no room for them larger (en), still crowd: see README
    view, _ = _sheet1(CHAIN, lang)
    assert len(lint(view)) <= 56


@pytest.mark.parametrize("path", ["samples/six_link_press.toml", "samples/five_dyads.toml"])
def test_a_mechanism_with_room_for_its_arcs_keeps_them_in_its_drawing(path):
    _, result = _sheet1(path, "en")
    assert not sheet1_module._arcs_crowd(_solution(path), result.scales["mu_l"])
    assert not [n for n in result.placed if n.startswith("mechanism-position")]
