"""The 5 % check of seed 003 §1.8 as the sheet prints it: at the investigated
positions, by formulas (12) and (13), on the diagrams the sheet draws; every
sample's key passes it, and the verdict agrees with the numbers."""

from __future__ import annotations

import glob
from pathlib import Path

import numpy as np
import pytest

import mmt_plans
from mmt_plans.diagrams import ILL_CONDITIONED
from mmt_plans.results_json import diagrams_json

ROOT = Path(__file__).resolve().parents[1]
FILES = sorted(glob.glob(str(ROOT / "samples" / "*.toml"))) + sorted(
    glob.glob(str(ROOT / "samples" / "tasks" / "*" / "*.toml")))


@pytest.mark.parametrize("path", FILES, ids=lambda p: Path(p).stem)
def test_every_key_passes_its_check_on_the_drawn_grid(path):
    sol = mmt_plans.solve(mmt_plans.load(path))
    dg = sol.diagrams
    assert dg is not None
    sc = dg.sheet_check
    assert sc.passed, [v for v in sc.values if not v.passed]
    c = dg.construction
    n = sol.mechanism.study.positions
    # the drawn grid holds the positions: n·k divisions, k the refinement
    assert sc.intervals == n * dg.refinement == len(c.abscissae)
    # recompute (12) and (13) from what is drawn: the construction's ordinates
    # times its scale at the investigated positions, the plans from the sweep
    wd = np.asarray(sol.mechanism.study.working_direction)
    out = sol.mechanism.study.output
    phi = sol.positions[0].phi1_deg + sol.sense_sign * 360.0 * np.arange(sc.intervals) / sc.intervals
    grid = sol.sweep_at(phi)
    v_all, a_all = grid.v[out] @ wd, grid.a[out] @ wd
    seen = set()
    for val in sc.values:
        i, k = val.index, dg.refinement
        plan = (sol.sweep.v[out] if val.quantity == "v" else sol.sweep.a[out])[sol.entry(i)] @ wd
        drawn = (c.velocity if val.quantity == "v" else c.acceleration).ordinates[i * k] * (
            c.mu_V if val.quantity == "v" else c.mu_a)
        assert val.plan == pytest.approx(plan, rel=1e-12, abs=1e-12)
        assert val.diagram == pytest.approx(drawn, rel=1e-12)
        largest = np.abs(v_all if val.quantity == "v" else a_all).max()
        ill = abs(plan) < ILL_CONDITIONED * largest
        assert val.ill_conditioned == ill
        if not ill:
            err = (plan - drawn) / plan * 100
            assert val.error_percent == pytest.approx(err, rel=1e-9)
            assert abs(err) <= 5.0
        seen.add((i, val.quantity))
    assert seen == {(i, q) for i in sol.plan_positions for q in "va"}
    # the JSON says the same as the sheet's table
    js = diagrams_json(sol)
    assert js["passed"] is True and js["grid_intervals"] == sc.intervals
    assert len(js["investigated"]) == 2 * len(sol.plan_positions)


DRAWN = [ROOT / "samples" / "six_link_press.toml", ROOT / "samples" / "shaper.toml",
         ROOT / "samples" / "tasks" / "seed003" / "task01_v1.toml"]


@pytest.mark.parametrize("path", DRAWN, ids=lambda p: Path(p).stem)
def test_the_check_reads_the_diagrams_sheet_1_draws(path):
    """The values judged by (12)/(13) are the ordinates sheet 1 draws, read off
    its V and a curves in millimetres and times the scales the JSON gives; the
    poles written on the sheet are the JSON's."""
    from mmt_plans.drawing.page import Page
    from mmt_plans.i18n import catalogue
    from mmt_plans.render.recording import RecordingBackend
    from mmt_plans.sheets.sheet1 import compose_sheet1

    sol = mmt_plans.solve(mmt_plans.load(path), forces=False)
    backend = RecordingBackend()
    sheet = compose_sheet1(sol, backend, "en", page=Page.of("A1"))
    backend.close()
    js = diagrams_json(sol)
    scales = js["scales"]
    for key, name in (("mu_S", "mu_S"), ("mu_V_diagram", "mu_V"), ("mu_a_diagram", "mu_a"),
                      ("H1", "H1_mm"), ("H2", "H2_mm")):
        assert sheet.scales[key] == scales[name], key
    c = sol.diagrams.construction
    for gid, q, mu, H in (("diagram-v", "v", scales["mu_V"], scales["H1_mm"]),
                          ("diagram-a", "a", scales["mu_a"], scales["H2_mm"])):
        calls = backend.in_group(gid)
        axis = [a for a in calls if a.name == "arrow" and a["line"] == "main"
                and abs(a["start"][1] - a["end"][1]) < 1e-9]
        assert len(axis) == 1
        y0 = axis[0]["start"][1]
        curve = [p for p in calls if p.name == "polyline" and p["line"] == "main"]
        assert len(curve) == 1
        pts = np.asarray(curve[0]["points"])
        x0 = pts[0][0]  # the curve starts on the ordinate axis
        words = catalogue("en").words("diagram_axes")["pole"].format(H=f"{H:g}")
        assert words in [t["content"] for t in calls if t.name == "text"]
        for val in (v for v in js["investigated"] if v["quantity"] == q):
            x = c.abscissae[val["index"] * sol.diagrams.refinement]
            k = int(np.argmin(np.abs(pts[:, 0] - x0 - x)))
            assert abs(pts[k, 0] - x0 - x) < 1e-9
            drawn = (pts[k, 1] - y0) * mu
            assert drawn == pytest.approx(val["diagram"], rel=1e-9, abs=1e-12)
