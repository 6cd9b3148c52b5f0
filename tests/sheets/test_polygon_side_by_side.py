"""Force polygons: vectors on one line are drawn side by side, never on top
of each other (issue 21: R12, R23, R43 on one line; the crosshead's group
4-5 collapsing onto one vertical line)."""

from __future__ import annotations

import itertools
import math
from functools import cache
from pathlib import Path

import pytest

import mmt_plans
from mmt_plans.render.recording import RecordingBackend
from mmt_plans.sheets.sheet2 import compose_sheet2

ROOT = Path(__file__).resolve().parents[2]
CASES = [ROOT / "samples" / "six_link_press.toml",
         ROOT / "tests" / "data" / "hard" / "crosshead_mid_chain.toml"]


@cache
def _draw(path: Path):
    backend = RecordingBackend()
    sheet = compose_sheet2(mmt_plans.solve(mmt_plans.load(path)), backend, "en")
    backend.close()
    return backend, sheet


def _overlap(a, b) -> float:
    """mm of arrow b (sampled every 0.05 mm) within 0.5 mm of arrow a's
    segment, the two parallel within 1° (0 otherwise): both sides measured."""
    def one_way(a, b):
        (ax, ay), (bx, by) = a["start"], b["start"]
        la, lb = a["length"], b["length"]
        ux, uy = (a["end"][0] - ax) / la, (a["end"][1] - ay) / la
        vx, vy = (b["end"][0] - bx) / lb, (b["end"][1] - by) / lb
        if abs(ux * vy - uy * vx) > math.sin(math.radians(1.0)):
            return 0.0
        step, near = 0.05, 0
        for k in range(int(lb / step) + 1):
            px, py = bx + vx * k * step - ax, by + vy * k * step - ay
            t = min(max(px * ux + py * uy, 0.0), la)
            near += math.hypot(px - t * ux, py - t * uy) <= 0.5
        return max(0, near - 1) * step
    return max(one_way(a, b), one_way(b, a))


@pytest.mark.parametrize("path", CASES, ids=[p.stem for p in CASES])
def test_no_two_arrows_of_a_polygon_overlap_along_one_line(path):
    backend, sheet = _draw(path)
    fa = sheet.forces
    gids = [f"force-polygon-{g.name}" for g in fa.groups]
    gids.append(f"force-polygon-{fa.driving_link.link}")
    for gid in gids:
        arrows = [c for c in backend.in_group(gid) if c.name == "arrow" and c["length"] > 1e-6]
        assert arrows, gid
        for a, b in itertools.combinations(arrows, 2):
            assert _overlap(a, b) <= 1.0, (gid, a["start"], b["start"])


def test_the_crosshead_polygon_did_have_collinear_sides():
    """The case is a real one: group 4-5 of the crosshead has sides on one
    line (parallel and on one line in the exact geometry), so the test above
    checks the shifting, not an empty case."""
    _, sheet = _draw(CASES[1])
    group = next(g for g in sheet.forces.groups if g.name == "4-5")
    mu = sheet.scales["mu_F 4-5"]
    exact = [
        {"start": tuple(v.start / mu), "end": tuple(v.end / mu), "length": v.magnitude / mu}
        for v in group.polygons[0].vectors if v.magnitude / mu > 1.0
    ]
    assert any(_overlap(a, b) > 1.0 for a, b in itertools.combinations(exact, 2))
