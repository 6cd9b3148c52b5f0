"""Lettering of both sheets against everything drawn: no label covers a line,
a hatch, an arc, an arrow, a dimension line or another label; force polygons
at the textbook's size; coincident forces told apart (issue 13)."""

from __future__ import annotations

import itertools
import math
import re
from functools import cache
from pathlib import Path

import numpy as np
import pytest
from shapely.geometry import Point

import mmt_plans
from mmt_plans.render.recording import RecordingBackend
from mmt_plans.scales import FORCE_PLAN
from mmt_plans.sheets.sheet1 import compose_sheet1
from mmt_plans.sheets.sheet2 import compose_sheet2

from lettering import label_clashes_anywhere, label_hits

ROOT = Path(__file__).resolve().parents[2]
SAMPLES = sorted((ROOT / "samples").glob("*.toml"))
TASKS = sorted((ROOT / "samples" / "tasks").glob("seed*/*.toml"))

# Sheet-1 overlaps made by sheet1.py's own geometry, not by the label placer
# (sheet1.py belongs to another part of issue 13): (the label's group, a
# pattern of its text) → the reason. A sheet-1 case with such overlaps is
# checked for every other overlap first, then skipped naming them.
SHEET1_KNOWN: list[tuple[str, str, str]] = [
]


@cache
def _solution(path: Path):
    return mmt_plans.solve(mmt_plans.load(path))


@cache  # one drawing per case, shared by the tests that read it
def _draw(path: Path, sheet: int, lang: str = "en"):
    backend = RecordingBackend()
    compose = compose_sheet1 if sheet == 1 else compose_sheet2
    result = compose(_solution(path), backend, lang)  # type: ignore[arg-type]
    backend.close()
    return backend, result


def _cases():
    for path in SAMPLES:
        for lang in ("en", "uk"):
            for sheet in (1, 2):
                case = f"{path.stem}-{lang}-{sheet}"
                yield pytest.param(path, sheet, lang, id=case, marks=_crowded(case))


# Still open (issue 13): the placer finds no free place in these crowded
# drawings and writes the label where it covers least. Strict: a case that
# becomes clean fails until it is taken off this list.
CROWDED: dict[str, str] = {}  # five_dyads sheet 1 (en, uk) became clean with issue 21


def _crowded(case_id: str):
    reason = CROWDED.get(case_id)
    return [pytest.mark.xfail(reason=reason, strict=True)] if reason else []


def _known(hit) -> str | None:
    text, _, _, group = hit
    for prefix, pattern, reason in SHEET1_KNOWN:
        if group.startswith(prefix) and re.fullmatch(pattern, text):
            return reason
    return None


@pytest.mark.parametrize("path, sheet, lang", list(_cases()))
def test_no_label_on_a_drawn_primitive_or_another_label(path, sheet, lang):
    backend, _ = _draw(path, sheet, lang)
    hits = label_hits(backend)
    assert label_clashes_anywhere(backend) == []
    if sheet == 2:
        assert hits == []
        return
    assert [h for h in hits if _known(h) is None] == []
    reasons = sorted({r for h in hits if (r := _known(h)) is not None})
    if reasons:
        pytest.skip("sheet 1 geometry: " + "; ".join(reasons))


@pytest.mark.parametrize(
    "path",
    [
        pytest.param(p, id=f"{p.parent.name}/{p.stem}", marks=_crowded(f"{p.parent.name}/{p.stem}"))
        for p in TASKS
    ],
)
def test_sheet2_of_every_seed_task_is_clean(path):
    backend, sheet = _draw(path, 2)
    assert label_hits(backend) == []
    assert label_clashes_anywhere(backend) == []
    _check_polygon_sizes(backend, sheet)
    assert _coincident_arrows(backend, sheet) == []


def _check_polygon_sizes(backend, sheet):
    """Seed 003 §2.6: |F_PR| ≥ 150 mm on its polygon, measured on the drawn
    arrows, whatever else the sheet shrinks; a polygon without F_PR has its
    largest side at least 150 mm unless the sheet had to shrink to fit."""
    fa = sheet.forces
    owners = [(g.name, g.polygons) for g in fa.groups]
    owners.append((str(fa.driving_link.link), (fa.driving_link.polygon,)))
    for name, polygons in owners:
        lengths = [
            c["length"] for c in backend.in_group(f"force-polygon-{name}") if c.name == "arrow"
        ]
        if sheet.shrink <= 0:  # at the textbook's scales every polygon keeps the guide
            assert max(lengths) >= FORCE_PLAN.low - 1e-6, name
        resistance = [
            float(np.hypot(*v.vector)) for p in polygons for v in p.vectors if v.label == "F_PR"
        ]
        largest = max(p.largest for p in polygons)
        # the guide holds for F_PR where F_PR at 150 mm leaves the largest side within 300 mm
        if resistance and max(resistance) * FORCE_PLAN.high / FORCE_PLAN.low >= largest:
            mu_F = sheet.scales[f"mu_F {name}"]
            drawn = max(resistance) / mu_F
            assert drawn >= FORCE_PLAN.low - 1e-6, (name, drawn)
            assert any(math.isclose(length, drawn, rel_tol=1e-6) for length in lengths)


@pytest.mark.parametrize("path", SAMPLES, ids=[p.stem for p in SAMPLES])
def test_force_polygons_meet_the_guide_size(path):
    backend, sheet = _draw(path, 2)
    _check_polygon_sizes(backend, sheet)


def _coincident_arrows(backend, sheet):
    """Pairs of force arrows of one drawing (not a polygon) on one line that
    share more than half a millimetre of it."""
    out = []
    drawings = ["force-mechanism", "driving-link", "zhukovsky-lever"]
    drawings += [f"group-{g.name}" for g in sheet.forces.groups]
    for gid in drawings:
        arrows = [c for c in backend.in_group(gid) if c.name == "arrow" and c["length"] > 3.0]
        for a, b in itertools.combinations(arrows, 2):
            (ax, ay), (bx, by) = a["start"], b["start"]
            ux, uy = ((a["end"][0] - ax) / a["length"], (a["end"][1] - ay) / a["length"])
            vx, vy = ((b["end"][0] - bx) / b["length"], (b["end"][1] - by) / b["length"])
            if abs(ux * vx + uy * vy) < 0.999:
                continue
            if abs(ux * (by - ay) - uy * (bx - ax)) > 0.5:  # not on one line
                continue
            t0 = ux * (bx - ax) + uy * (by - ay)
            t1 = ux * (b["end"][0] - ax) + uy * (b["end"][1] - ay)
            if min(a["length"], max(t0, t1)) - max(0.0, min(t0, t1)) > 0.5:
                out.append((gid, a["start"], b["start"]))
    return out


@pytest.mark.parametrize("path", SAMPLES, ids=[p.stem for p in SAMPLES])
def test_coincident_forces_are_told_apart(path):
    backend, sheet = _draw(path, 2)
    assert _coincident_arrows(backend, sheet) == []


def test_coincident_forces_on_the_lever_share_one_arrow_and_name_both():
    """six_link_press: F_PR and F_in5 act at e along the guide in one sense:
    one arrow with both names, not two arrows on top of each other."""
    backend, _ = _draw(ROOT / "samples" / "six_link_press.toml", 2)
    lever = [c["content"] for c in backend.in_group("zhukovsky-lever") if c.name == "text"]
    joined = "".join(lever)
    assert "PR" in joined and "in5" in joined
    assert _coincident_arrows(backend, _draw(ROOT / "samples" / "six_link_press.toml", 2)[1]) == []


def test_lever_names_the_images_of_centres_of_mass_and_force_points():
    backend, sheet = _draw(ROOT / "samples" / "six_link_press.toml", 2)
    texts = [c["content"] for c in backend.in_group("zhukovsky-lever") if c.name == "text"]
    points = {f.point for f in sheet.forces.lever.forces if f.point[0] in "SK"}
    assert points
    joined = " ".join(texts).replace(" ", "")  # "d, s" "5" → "d,s5"
    for p in points:
        assert re.search(rf"(^|[^a-z]){p[0].lower()}{p[1:]}($|[^0-9])", joined), p


def test_a_label_pushed_far_from_its_point_is_tied_to_it_by_a_leader():
    """Lines 3 mm apart round a point leave no room near it: the label goes
    further out, a thin leader runs from the point to it, and neither the
    label nor the leader touches a line (the leader is a primitive the
    checker reads like any other)."""
    from mmt_plans.drawing.labels import Labels
    from mmt_plans.drawing.sketch import Sketch

    sk = Sketch(RecordingBackend().look)
    xs = [1.5 + 3.0 * k for k in range(7)]
    for x in [*xs, *(-x for x in xs)]:
        sk.line((x, -6.0), (x, 6.0), "thin")
    labels = Labels(sk, 3.5, spacing=None, leaders=True)
    footprint = labels.place((0.0, 0.0), "F_{in5}", towards=(1.0, 1.0))
    assert footprint.distance(Point(0.0, 0.0)) > 6.0
    leaders = [c for c in sk.calls if c.name == "line" and math.dist(c["start"], (0, 0)) < 1e-9]
    assert len(leaders) == 1
    end = leaders[0]["end"]
    assert 0.0 < footprint.distance(Point(end)) < 0.5  # it reaches the label
    assert label_hits(sk) == [] and labels.unsettled == 0
