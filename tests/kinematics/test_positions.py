"""Position 0, strokes, positions and plans as SPEC_FORMAT.md defines them."""

import math

import numpy as np
import pytest

import mmt_plans
from mmt_plans.results_json import results as results_json


@pytest.mark.parametrize("name", ["six_link_press", "offset_slider_crank", "shaper",
                                  "four_bar_coupler", "five_dyads"])
def test_position_zero_is_the_extreme_to_machine_precision(name):
    a = mmt_plans.solve(mmt_plans.load(f"samples/{name}.toml"))
    mech = a.mechanism
    wd = mech.study.working_direction
    lo, hi = a.extremes
    sw = mmt_plans.sweep(mech, [lo, hi])
    v = sw.v[mech.study.output] @ wd
    vmax = np.abs(mmt_plans.sweep(mech, np.arange(0, 360, 1.0)).v[mech.study.output] @ wd).max()
    assert np.all(np.abs(v) < 1e-13 * vmax)
    s = sw.points[mech.study.output] @ wd
    grid = mmt_plans.sweep(mech, np.arange(0, 360, 0.1)).points[mech.study.output] @ wd
    assert s[0] <= grid.min() + 1e-15 and s[1] >= grid.max() - 1e-15
    assert a.positions[0].phi1_deg == pytest.approx(lo % 360, abs=1e-12)
    assert a.positions[0].stroke == "working"


def test_slider_crank_extremes_by_hand():
    # offset slider-crank, e = 30, r = 100, l = 400: B is farthest right when the crank
    # and rod are in line: sin φ = e/(l + r); nearest left when folded: sin φ = -e/(l - r)
    a = mmt_plans.solve(mmt_plans.load("samples/offset_slider_crank.toml"))
    lo, hi = a.extremes
    assert hi == pytest.approx(math.degrees(math.asin(30 / 500)), abs=1e-12)
    assert lo == pytest.approx(180 + math.degrees(math.asin(30 / 300)), abs=1e-12)
    # working stroke from lo to hi counter-clockwise: 360 - lo + hi
    assert a.working_span_deg == pytest.approx(360 - lo + hi, abs=1e-12)


def test_positions_step_in_the_drive_sense_and_strokes():
    text = open("samples/offset_slider_crank.toml").read().replace("rpm = 300", 'rpm = 300\nsense = "cw"')
    a = mmt_plans.solve(mmt_plans.loads(text))
    phis = [p.phi1_deg for p in a.positions]
    steps = [((phis[i + 1] - phis[i] + 180) % 360) - 180 for i in range(len(phis) - 1)]
    assert np.allclose(steps, -30.0)
    # clockwise: the working stroke starts at the left extreme
    lo, hi = a.extremes
    assert a.stroke_of(lo) == "working" and a.stroke_of(hi) == "working"
    worked = [p.stroke for p in a.positions]
    assert worked.count("working") + worked.count("idle") == 12
    # the default plans are one working and one idle position
    i, j = a.plan_positions
    assert a.positions[i].stroke == "working" and a.positions[j].stroke == "idle"


def test_extra_angles_get_their_own_entries():
    text = open("samples/six_link_press.toml").read().replace("angles = []", "angles = [210, 30]")
    a = mmt_plans.solve(mmt_plans.loads(text))
    res = results_json(a)
    extras = [k for k in res["kinematics"] if k["index"] is None]
    assert [e["phi1_deg"] for e in extras] == [210.0, 30.0]
    # the same angle through a plain sweep gives the same numbers
    sw = mmt_plans.sweep(a.mechanism, [210.0])
    assert extras[0]["v"]["E"] == pytest.approx(list(sw.v["E"][0]), abs=1e-15)
