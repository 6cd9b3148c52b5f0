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
    # 30 mm tall); 54 (en) and 28 (uk) with the views at 1:25 and 1:20, every
    # coupler drawn with arcs for its ω ~ 2e-6 1/s; the rockers' arcs alone:
    # the views at 1:20 in both, a rocker's arcs over a joint's name in 9
    # places; the views' joints named round their arcs: none
    view, _ = _sheet1(CHAIN, lang)
    assert lint(view) == []


@pytest.mark.parametrize("lang", ["en", "uk"])
def test_chain_25_couplers_that_do_not_turn_have_no_arcs(lang):
    # chain_25's couplers 4, 6 ... 24 (parallelograms to the file's three
    # decimals) turn at ~2e-6 1/s, which Table 3 writes 0.0000: no ω/ε arc
    # shows a sense for them; the rockers' and link 2's do
    view, result = _sheet1(CHAIN, lang)
    solution = _solution(CHAIN)
    for i in solution.plan_positions:
        k = solution.entry(i)
        named = {
            lab.text
            for lab in view.labels
            if lab.naming and lab.groups[:1] == (sheet1_module._view_name(i),)
        }
        for lid in solution.mechanism.links:
            if lid == solution.mechanism.drive.link:
                continue
            omega = float(solution.sweep.omega[lid][k])
            assert (f"ω{lid}" in named) == (abs(omega) >= 5e-5), (i, lid, omega)
            assert lid % 2 or lid == 2 or abs(omega) < 1e-5


def test_chain_25_drawn_at_the_same_scales_in_both_languages():
    # the drawing in all positions and the views at 1:20 in en and uk (en's
    # views were at 1:25, its sheet having no room for them at 1:20)
    for lang in ("en", "uk"):
        _, result = _sheet1(CHAIN, lang)
        assert result.scales["mu_l"] == pytest.approx(0.02)
    sizes = [
        {n: (round(r.width), round(r.height)) for n, r in _sheet1(CHAIN, lang)[1].placed.items()}
        for lang in ("en", "uk")
    ]
    views = [n for n in sizes[0] if n.startswith("mechanism")]
    assert [sizes[0][n] for n in views] == [sizes[1][n] for n in views]


@pytest.mark.parametrize("path", ["samples/six_link_press.toml", "samples/five_dyads.toml"])
def test_a_mechanism_with_room_for_its_arcs_keeps_them_in_its_drawing(path):
    _, result = _sheet1(path, "en")
    assert not sheet1_module._arcs_crowd(_solution(path), result.scales["mu_l"])
    assert not [n for n in result.placed if n.startswith("mechanism-position")]
