"""The S, V, a diagrams take the room that is left on sheet 1 (issue #21,
field-filled): one turn of the crank over the width free beside them, at a
series μ_t, their heights at series μ_S, μ_V, μ_a; the field then filled by
the linter's rule and the guide's sizes of the plans kept."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

import mmt_plans
from mmt_plans.diagrams import ROUND_POLE_DISTANCES_MM
from mmt_plans.generate import generate_one
from mmt_plans.render.recording import RecordingBackend
from mmt_plans.sheets.lint import SheetView, lint
from mmt_plans.sheets.sheet1 import compose_sheet1
from mmt_plans.spec import loads

ROOT = Path(__file__).resolve().parents[2]
# field-filled failed on these before the rule: 57 %, 52 %, 56 % empty
CASES = ["four_bar_coupler", "gen1", "gen40"]
SERIES = (1.0, 1.25, 2.0, 2.5, 4.0, 5.0, 8.0)  # GOST 2.302 / seed 003: the mantissas


def _solve(name):
    if name.startswith("gen"):
        g = generate_one(int(name[3:]))
        return mmt_plans.solve(loads(g.toml, f"{g.name}.toml"))
    return mmt_plans.solve(mmt_plans.load(ROOT / "samples" / f"{name}.toml"))


@pytest.fixture(scope="module", params=CASES)
def drawn(request):
    solution = _solve(request.param)
    backend = RecordingBackend(841.0, 594.0)
    sheet = compose_sheet1(solution, backend, "en")
    return request.param, solution, backend, sheet


def _series(mu):
    m = mu / 10.0 ** math.floor(math.log10(mu) + 1e-12)
    return any(math.isclose(m, s, rel_tol=1e-9) for s in SERIES)


def _curve(backend, gid):
    lines = [c for c in backend.calls if gid in c.groups and c.name == "polyline"]
    assert len(lines) == 1, gid
    return np.asarray(lines[0]["points"], dtype=float)


def test_field_filled_and_guide_sizes_pass(drawn):
    name, _, backend, _ = drawn
    view = SheetView.of(backend, "en", name)
    assert lint(view, ["field-filled", "guide-sizes"]) == []


def test_the_diagrams_grew_into_the_free_room(drawn):
    """Wider than the Solution's time axis (150 … 240 mm): the room beside
    the column was taken."""
    _, solution, backend, _ = drawn
    own = solution.require_diagrams().construction
    curve = _curve(backend, "diagram-s")
    assert np.ptp(curve[:, 0]) > own.L + 50.0


def test_one_turn_on_the_time_axis_at_a_series_scale(drawn):
    _, solution, backend, sheet = drawn
    mu_t = sheet.scales["mu_t"]
    assert _series(mu_t)
    T = 60.0 / solution.mechanism.drive.n1_rpm  # one turn, s
    for gid in ("diagram-s", "diagram-v", "diagram-a"):
        curve = _curve(backend, gid)
        assert math.isclose(np.ptp(curve[:, 0]) * mu_t, T, rel_tol=1e-9), gid
    # the positions numbered along the axis: 0 … n−1 and 0 again (one cycle)
    n = solution.mechanism.study.positions
    numbers = [
        c["content"]
        for c in backend.calls
        if "diagram-s" in c.groups and c.name == "text" and c["content"].isdigit()
    ]
    assert sorted(numbers, key=int) == sorted([str(i) for i in range(n)] + ["0"], key=int)


def test_the_ordinates_follow_series_scales(drawn):
    """μ_S, μ_V, μ_a series values, μ_V = μ_S/(μ_t·OH1), μ_a = μ_V/(μ_t·OH2)
    with round poles; the drawn curves read at them give the Solution's S, V
    and a (the construction is the same in SI, whatever its scales)."""
    _, solution, backend, sheet = drawn
    sc = sheet.scales
    own = solution.require_diagrams().construction
    assert sc["H1"] in ROUND_POLE_DISTANCES_MM and sc["H2"] in ROUND_POLE_DISTANCES_MM
    for key in ("mu_S", "mu_V_diagram", "mu_a_diagram"):
        assert _series(sc[key]), (key, sc[key])
    assert math.isclose(sc["mu_V_diagram"], sc["mu_S"] / (sc["mu_t"] * sc["H1"]), rel_tol=1e-9)
    assert math.isclose(sc["mu_a_diagram"], sc["mu_V_diagram"] / (sc["mu_t"] * sc["H2"]), rel_tol=1e-9)
    # μ_S never coarser than the Solution's (the line under S says why μ_S ≠ μ_l)
    assert sc["mu_S"] <= own.mu_S * (1 + 1e-9)
    s_dense = np.asarray(solution.s_dense, dtype=float)
    assert math.isclose(np.ptp(_curve(backend, "diagram-s")[:, 1]) * sc["mu_S"], np.ptp(s_dense), rel_tol=1e-9)
    for gid, mu, theirs in (
        ("diagram-v", sc["mu_V_diagram"], own.velocity.curve[:, 1] * own.mu_V),
        ("diagram-a", sc["mu_a_diagram"], own.acceleration.curve[:, 1] * own.mu_a),
    ):
        ours = _curve(backend, gid)[:, 1]
        ours = (ours - ours[0] + theirs[0] / mu) * mu  # the axis where the curve starts
        assert np.allclose(ours, theirs, rtol=0, atol=1e-9 * np.abs(theirs).max()), gid
