"""A sheet-1 plan whose names crowd round its pole: a detail view (GOST 2.305)
of the crowd, drawn at a larger scale of the standard series beside the plan
and lettered there (#21), judged by the sheet linter's own rules."""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np
from lettering import near_findings, solved_seed

from mmt_plans.drawing.detail import DETAIL_RATIOS
from mmt_plans.render.look import load_look
from mmt_plans.render.recording import BeginGroup, RecordingBackend, Text
from mmt_plans.sheets.crowd import crowded_names
from mmt_plans.sheets.lint import SheetView, arrows_named, label_near
from mmt_plans.sheets.sheet1 import (
    _plan_scales,
    compose_sheet1,
    plan_details,
    sketch_plan,
    sketch_plan_details,
)
from mmt_plans.solution import solve
from mmt_plans.spec import load

ROOT = Path(__file__).resolve().parents[2]
# gen 110 (RPR-PRP-RRR-RPP-RPR), acceleration plan of position 3 drawn two
# series steps coarse: fifteen names within 5 mm of its pole
CROWDED = 110


def _plan(lang="en"):
    solution = solved_seed(CROWDED)
    mu = _plan_scales(solution, 2)["acceleration 3"]
    look = load_look()
    plain, images = sketch_plan(solution, 3, mu, "acceleration", look, lang)
    return solution, mu, look, plain, images


def test_a_crowded_plan_gets_a_detail_at_a_larger_standard_scale():
    solution, mu, look, plain, images = _plan()
    crowd = crowded_names(plain, "en")
    assert len(crowd) >= 3
    (detail,) = plan_details(solution, 3, mu, "acceleration", crowd, "AUWXYZ")
    assert detail.ratio in DETAIL_RATIOS and detail.ratio > 1.0
    assert detail.letter not in {n[:1].upper() for n in solution.mechanism.point_owners}
    # the disc holds the crowd: the pole and the images packed round it
    centre, radius = np.asarray(detail.centre) / mu, detail.radius / mu
    inside = [n for n, v in images.items() if np.hypot(*(v - centre)) <= radius]
    assert len(inside) >= 3


def test_the_crowds_names_stand_near_in_the_detail_view():
    for lang in ("en", "uk"):
        solution, mu, look, plain, _ = _plan(lang)
        made = sketch_plan_details(solution, 3, mu, "acceleration", look, lang)
        assert made is not None
        main, (view,), letters = made
        assert len(letters) == 1
        # the names found far from what they name: fewer on the plan, none in its detail
        assert len(near_findings(main, lang)) < len(near_findings(plain, lang))
        assert near_findings(view, lang) == []
        # a vector whose head is in the disc is the detail's, head and name: on the
        # plan none is left with no name near it
        assert list(arrows_named(SheetView(list(main.calls), 841.0, 594.0, lang))) == []
        named = [c for c in view.calls if isinstance(c, Text) and c.naming is not None]
        assert len(named) >= 8  # the crowd lettered there
        # titled by its letter and its scale, as sheet 2's details are
        titles = [c.content for c in view.calls if isinstance(c, Text)]
        assert any(re.fullmatch(rf"{letters} \(\d+(,|\.)?\d*:1\)", t) for t in titles)
        # the plan marks the crowd by the letter
        assert letters in [c.content for c in main.calls if isinstance(c, Text)]


def test_a_plan_without_a_crowd_gets_no_detail():
    solution = solve(load(ROOT / "samples" / "six_link_press.toml"))
    look = load_look()
    for kind in ("velocity", "acceleration"):
        i = solution.plan_positions[0]
        mu = _plan_scales(solution)[f"{kind} {i}"]
        assert sketch_plan_details(solution, i, mu, kind, look, "en") is None


def test_the_sheet_draws_the_detail_and_its_crowd_near():
    solution = solved_seed(CROWDED)
    backend = RecordingBackend(841.0, 594.0)
    compose_sheet1(solution, backend, "en")
    groups = {c.id: c.cls for c in backend.calls if isinstance(c, BeginGroup)}
    assert groups.get("acceleration-plan-3-detail") == "plan-detail"
    view = SheetView.of(backend, "en", "gen0110 sheet 1 en")
    # the names found far on the plan: 4 of its components' (a^τ, a^r, a^n) on main's sheet
    boxes = np.array(
        [c.bbox() for c in backend.calls if "acceleration-plan-3" in c.groups and c.bbox()]
    )
    x0, y0 = boxes[:, :2].min(axis=0)
    x1, y1 = boxes[:, 2:].max(axis=0)
    near = [f for f in label_near(view) if x0 <= f.where[0] <= x1 and y0 <= f.where[1] <= y1]
    assert len(near) <= 1
