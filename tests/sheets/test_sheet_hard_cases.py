"""The sheets on mechanisms nobody tuned the layout for (tests/data/hard):
one regression test per defect of issues 21 and 26, named after it."""

from __future__ import annotations

import math
from functools import cache
from pathlib import Path

import numpy as np
import pytest
from click.testing import CliRunner

import mmt_plans
from mmt_plans.cli import main
from mmt_plans.drawing.layout import LayoutError
from mmt_plans.drawing.page import Page
from mmt_plans.errors import MmtError
from mmt_plans.i18n import catalogue
from mmt_plans.render.recording import RecordingBackend
from mmt_plans.sheets import sheet1 as sheet1_module
from mmt_plans.sheets import sheet2 as sheet2_module
from mmt_plans.sheets.sheet1 import compose_sheet1
from mmt_plans.sheets.sheet2 import compose_sheet2

HARD = Path(__file__).resolve().parents[1] / "data" / "hard"


@cache
def _solution(name: str):
    return mmt_plans.solve(mmt_plans.load(HARD / f"{name}.toml"))


def _texts(backend: RecordingBackend, group: str) -> str:
    return "".join(c["content"] for c in backend.in_group(group) if c.name == "text")


@pytest.mark.parametrize("path", sorted(HARD.glob("*.toml")), ids=lambda p: p.stem)
def test_every_hard_case_loads(path):
    assert mmt_plans.load(path).links


def test_unloaded_group_polygon_is_a_point_with_its_note():
    # Group 4-5 is massless and carries no force: every side of its polygon is
    # zero. Sheet 2 used to enlarge that polygon a series step at a time for
    # ever; now it is drawn as one point with a note, at a bounded scale.
    solution = _solution("unloaded_group")
    fa = solution.require_forces()
    group = next(g for g in fa.groups if g.name == "4-5")
    assert all(v.magnitude == 0.0 for p in group.polygons for v in p.vectors)
    backend = RecordingBackend()
    sheet = compose_sheet2(solution, backend, "en")
    gid = "force-polygon-4-5"
    calls = backend.in_group(gid)
    assert [c for c in calls if c.name == "circle"], "the zero polygon is drawn as a point"
    assert not [c for c in calls if c.name == "arrow"], "a zero polygon has no arrow"
    note = catalogue("en").words("sheet2")["zero_polygon"].split("{")[0]
    assert note in _texts(backend, gid)
    # its scale is the textbook's, not one enlarged without end
    assert sheet.scales["mu_F 4-5"] == 1.0


def test_unloaded_group_fill_never_enlarges_a_zero_polygon():
    solution = _solution("unloaded_group")
    fa = solution.require_forces()
    composer = sheet2_module._Composer(
        fa, solution, RecordingBackend().look, "en", sheet2_module.Page.of("A1")
    )
    steps = composer._steps(0, 0)
    steps["poly 4-5"] = -1
    assert not composer._allowed(steps)
    steps["poly 4-5"] = 0
    steps["poly 2-3"] = 2 * sheet2_module._FINEST - 1
    assert not composer._allowed(steps), "no drawing is enlarged without a bound"


def test_extra_angles_near_360_crank_spokes_no_zero_division():
    # Spokes at 0 and 359.9999999999 deg are one spoke: the gap between them
    # is empty, not a division by sin(0).
    centre = np.zeros(2)
    spokes = [
        50.0 * np.array([math.cos(math.radians(a)), math.sin(math.radians(a))])
        for a in (0.0, 90.0, 180.0, 270.0, 359.9999999999)
    ]
    tip = np.array([8.0, 1.0])
    anchor = sheet1_module._between_spokes(centre, tip, spokes, 7.0)
    assert np.all(np.isfinite(anchor))
    # the label goes on a gap's bisector (45, 135, 225 or 315 deg), the one nearest the tip
    angle = math.degrees(math.atan2(anchor[1], anchor[0])) % 360.0
    assert min(abs(angle - a) for a in (45.0, 135.0, 225.0, 315.0)) < 1e-6


def test_extra_angles_near_360_sheet1_draws():
    backend = RecordingBackend()
    compose_sheet1(_solution("extra_angles_near_360"), backend, "en")
    assert backend.in_group("mechanism")


def test_six_points_10mm_apart_arcs_tried_beside_a_bounded_number_of_segments(monkeypatch):
    # Link 2 has eight points (28 segments); its ω/ε arcs used to be tried
    # beside every one of them (23.6 s for sheet 1). Now beside its longest
    # _MAX_SEGMENTS only, and every rotating link still gets its arcs.
    seen: list[int] = []
    real = sheet1_module._ArcPlacer.beside

    def counting(self, segments, spins, *rest):
        out = real(self, segments, spins, *rest)
        seen.append(len(segments))
        return out

    monkeypatch.setattr(sheet1_module._ArcPlacer, "beside", counting)
    backend = RecordingBackend()
    compose_sheet1(_solution("six_points_10mm_apart"), backend, "en")
    assert max(seen) == 28  # the link of eight points was offered all its segments
    labels = _texts(backend, "mechanism")
    for lid in (2, 3, 4):
        assert f"ω{lid}" in labels.replace("_", "")


def test_beside_keeps_the_longest_segments_of_a_link_of_many_points():
    from mmt_plans.drawing.sketch import Sketch

    sk = Sketch(RecordingBackend().look)
    placer = sheet1_module._ArcPlacer(sk)
    a = np.array([0.0, 0.0])
    points = [a + np.array([x, 0.0]) for x in (0.0, 100.0, 101.0, 102.0, 103.0, 104.0, 105.0)]
    segments = [(p, q) for i, p in enumerate(points) for q in points[i + 1 :]]
    centre, _, rooms, *_ = placer.beside(segments, [(5.0, 1.0), (8.0, -1.0)])
    assert len(rooms) == 2
    # the arcs sit along the long part of the link, not among the close points
    assert 10.0 < centre[0] < 95.0


def test_chain_25_links_sheet2_on_a3_fails_early_naming_the_file(monkeypatch):
    # Where even the compact sheet 2 (equations in short lines, tables in
    # parts) cannot hold twelve groups and their polygons (here on A3; on A1
    # it now composes, test_chain_25_links_composes_both_sheets), it fails once
    # the coarsest scales are found not to fit, plain and compact, with the
    # file, what did not fit and what to do. (Issue #21 item 1 changed this
    # test: it was A1, which then failed; two layouts are now tried, so the
    # bound is two rows of scales and coarsest, 5 each.)
    solution = _solution("chain_25_links")
    tried: list[dict[str, int]] = []
    real = sheet2_module._Composer.fits

    def counting(self, steps):
        tried.append(dict(steps))
        return real(self, steps)

    monkeypatch.setattr(sheet2_module._Composer, "fits", counting)
    with pytest.raises(LayoutError) as err:
        compose_sheet2(solution, RecordingBackend(), "en", page=Page.of("A3"))
    text = str(err.value)
    assert isinstance(err.value, MmtError)
    assert "chain_25_links.toml" in text
    assert "dm²" in text or "no room" in text  # what did not fit
    assert "fix:" in text
    # (the lever's detail views, issue #21: a third layout, compact without
    # them, is tried where the lever has any, as chain_25's has)
    assert len(tried) <= 3 * 5, "failing takes a row of scales and the coarsest, no more"


def test_a_sheet_that_cannot_compose_exits_2_and_writes_no_sheet(tmp_path, monkeypatch):
    # chain_25_links on A3 (the A1 sheets now hold it): draw stops with exit
    # 2, the file named, no traceback, no sheet left written.
    class A3:
        @staticmethod
        def of(name: str) -> Page:
            return Page.of("A3")

    for module in (sheet1_module, sheet2_module):
        monkeypatch.setattr(module, "Page", A3)
    out = tmp_path / "out"
    result = CliRunner().invoke(
        main, ["draw", str(HARD / "chain_25_links.toml"), "-o", str(out), "--format", "svg"]
    )
    assert result.exit_code == 2, result.output
    assert "chain_25_links.toml" in result.output
    assert "Traceback" not in result.output
    assert not list(out.glob("sheet*")), "no sheet is left written when one cannot be laid out"


@cache
def _chain_25_sheets():
    solution = _solution("chain_25_links")
    first, second = RecordingBackend(), RecordingBackend()
    return (
        (first, compose_sheet1(solution, first, "en")),
        (second, compose_sheet2(solution, second, "en")),
    )


def _bounds(backend: RecordingBackend, gid: str) -> tuple[float, float, float, float]:
    boxes = [b for c in backend.in_group(gid) if (b := c.bbox()) is not None]
    return (
        min(b[0] for b in boxes),
        min(b[1] for b in boxes),
        max(b[2] for b in boxes),
        max(b[3] for b in boxes),
    )


def test_chain_25_links_composes_both_sheets():
    # The README's limit of 25 links, twelve RRR groups: sheet 1's tables of
    # 74 and 93 rows continue in parts; sheet 2 is compact (the equations in
    # lines of 90 mm, its tables in parts). Every drawing and table inside
    # the frame, none over another.
    frame = Page.of("A1").frame
    for backend, result in _chain_25_sheets():
        rects = list(result.placed.items())
        for name, r in rects:
            assert frame.x - 1e-6 <= r.x and r.x + r.width <= frame.x + frame.width + 1e-6, name
            assert frame.y - 1e-6 <= r.y and r.y + r.height <= frame.y + frame.height + 1e-6, name
        for k, (a, ra) in enumerate(rects):
            for b, rb in rects[k + 1 :]:
                dx = min(ra.x + ra.width, rb.x + rb.width) - max(ra.x, rb.x)
                dy = min(ra.y + ra.height, rb.y + rb.height) - max(ra.y, rb.y)
                assert dx <= 1e-6 or dy <= 1e-6, (a, b)


def test_chain_25_links_tables_continue_in_parts_with_their_header():
    (first, _), (second, _) = _chain_25_sheets()
    groups = {
        c["id"] for b in (first, second) for c in b.calls if c.name == "begin_group"
    }
    # velocities: 74 rows, ceil(74 / 32) = 3 parts (drawing/table.rows_per_part)
    assert {"table-velocities", "table-velocities-2", "table-velocities-3"} <= groups
    assert "table-velocities-4" not in groups
    texts = [c["content"] for c in first.named("text")]
    assert "Table 1 – Velocities, m/s" in texts
    assert texts.count("Continuation of Table 1") == 2
    assert "Continuation of Table 2" in texts  # accelerations
    for backend in (first, second):
        for gid in {c["id"] for c in backend.calls if c.name == "begin_group"}:
            if gid.startswith("table"):
                x0, y0, x1, y1 = _bounds(backend, gid)
                assert y1 - y0 <= 280.0 + 1e-6, (gid, y1 - y0)
    # the lever's table of 52 forces in two parts, the header in each
    lever = [_texts(second, g) for g in ("table-lever", "table-lever-2")]
    assert all("h" in t and "F, N" in t for t in lever)
    assert "Continuation of Table 3" in lever[1]


def test_point_named_p_image_is_not_the_pole():
    # A point named P used to get the image "p", the letter of the pole of
    # the velocity plan and of the lever. Its image is p' (the README says so).
    from mmt_plans.drawing.markup import image_markup

    assert image_markup("P") == "p'"
    assert image_markup("B") == "b" and image_markup("S2") == "s_{2}"
    solution = _solution("point_named_p")
    backend = RecordingBackend()
    compose_sheet1(solution, backend, "en")
    for i in solution.plan_positions:
        texts = [c["content"] for c in backend.in_group(f"velocity-plan-{i}") if c.name == "text"]
        assert texts.count("p") == 1, "p names the pole only"
        assert any("p'" in t for t in texts), "the image of P is p'"
    backend2 = RecordingBackend()
    compose_sheet2(solution, backend2, "en")
    lever = [c["content"] for c in backend2.in_group("zhukovsky-lever") if c.name == "text"]
    assert lever.count("p") == 1
    assert any("p'" in t for t in lever)


def test_seed003_task3_rods_at_rest_get_their_eps_arcs():
    # Seed 003, task 3: at the planned positions the rods 2 and 4 are at rest
    # for an instant (ω = 0) while ε = ±68.9 1/s²; sheet 1 drew no arc for
    # them (a link with ω = 0 was skipped whole). Now each gets its ε arc.
    root = Path(__file__).resolve().parents[2]
    solution = mmt_plans.solve(mmt_plans.load(root / "samples/tasks/seed003/task03_v1.toml"))
    expected = 0
    for i in solution.plan_positions:
        k = solution.entry(i)
        for lid in (2, 4):
            assert abs(float(solution.sweep.omega[lid][k])) < 1e-9
            assert abs(float(solution.sweep.eps[lid][k])) > 1.0
            expected += 1
    backend = RecordingBackend()
    compose_sheet1(solution, backend, "en")
    texts = [c["content"] for c in backend.in_group("mechanism") if c.name == "text"]
    assert texts.count("ε") == expected
