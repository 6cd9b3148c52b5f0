"""The shortcuts of issue 25 give the numbers of the long way, to the bit:
the positions-only path, the singular mask without the sine's division, the
branch search's placing kept on its grid, the turn kept on the handle."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import mmt_plans
from mmt_plans.kinematics.branches import _Search
from mmt_plans.kinematics.chain import SINGULAR_SIN
from mmt_plans.kinematics.geometry import quiet

ROOT = Path(__file__).resolve().parents[2]
SAMPLES = sorted((ROOT / "samples").glob("*.toml"))


@pytest.mark.parametrize("path", SAMPLES, ids=lambda p: p.stem)
def test_point_position_is_point_motions_position(path):
    mech = mmt_plans.load(path)
    chain = mmt_plans.kinematics(mech).chain
    phi = np.linspace(-30.0, 400.0, 301)
    for name in mech.point_owners:
        _, P, _, _ = chain.point_motion(phi, name)
        assert np.array_equal(chain.point_position(phi, name), P, equal_nan=True)


@pytest.mark.parametrize("path", SAMPLES, ids=lambda p: p.stem)
def test_regular_is_the_sine_above_the_limit(path):
    chain = mmt_plans.kinematics(mmt_plans.load(path)).chain
    sw = chain.sweep(np.linspace(0.0, 360.0, 721))
    for plan in sw.plans:
        with quiet():
            sine = np.abs(plan.det) / (np.abs(plan.legs[0].d) * np.abs(plan.legs[1].d))
        assert np.array_equal(plan.sin_angle, sine, equal_nan=True)
        assert np.array_equal(
            np.broadcast_to(plan.regular(SINGULAR_SIN), sine.shape), sine > SINGULAR_SIN
        )


def test_regular_is_false_at_parallel_lines():
    """A plan whose direction lines are parallel (det = 0) is not regular."""
    chain = mmt_plans.kinematics(mmt_plans.load(SAMPLES[0])).chain
    plan = chain.sweep(np.array([0.0])).plans[0]
    leg1, leg2 = plan.legs
    saved = leg2.d
    try:
        leg2.d = leg1.d * 3.0
        plan.det = leg1.d.real * leg2.d.imag - leg1.d.imag * leg2.d.real
        assert not np.any(plan.regular(SINGULAR_SIN))
    finally:
        leg2.d = saved


@pytest.mark.parametrize("path", SAMPLES, ids=lambda p: p.stem)
def test_the_grid_placing_is_the_chains(path):
    chain = mmt_plans.kinematics(mmt_plans.load(path)).chain
    search = _Search(chain)
    signs: tuple[int, ...] = ()
    for solver in chain.solvers:
        for sign in (1, -1):
            trial = (*signs, sign)
            kept = search.margins(search.grid, trial)
            afresh = search.margins(search.grid.copy(), trial)  # not the grid: placed again
            assert len(kept) == len(afresh) == len(trial)
            for a, b in zip(kept, afresh):
                assert np.array_equal(a, b, equal_nan=True)
        signs += (chain.branches[solver.name],)


def test_the_turn_is_searched_once_per_mechanism():
    mech = mmt_plans.load(ROOT / "samples" / "six_link_press.toml")
    first = mmt_plans.solve(mech)
    handle = mmt_plans.kinematics(mech)
    turn = handle.kept("turn", lambda: pytest.fail("the turn was not kept"))
    again = mmt_plans.solve(mech)
    assert handle.kept("turn", lambda: None) is turn
    assert again.extremes == first.extremes
    assert [p.phi1_deg for p in again.positions] == [p.phi1_deg for p in first.positions]
    assert np.array_equal(again.s_dense, first.s_dense)
    # a changed copy searches its own
    other = mech.with_changes(title="copy")
    mmt_plans.solve(other)
    assert mmt_plans.kinematics(other).kept("turn", lambda: None) is not turn


@pytest.mark.parametrize("path", SAMPLES, ids=lambda p: p.stem)
def test_point_motion_only_is_point_motions(path):
    """The Newton steps' kernel (the plans' regular mask left out) moves the
    point as the full pass does, to the bit."""
    mech = mmt_plans.load(path)
    chain = mmt_plans.kinematics(mech).chain
    phi = np.linspace(-30.0, 400.0, 37)
    for name in mech.point_owners:
        _, P, V, A = chain.point_motion(phi, name)
        P2, V2, A2 = chain.point_motion_only(phi, name)
        for x, y in ((P, P2), (V, V2), (A, A2)):
            assert np.array_equal(x, y, equal_nan=True)


def test_quiet_nests_and_is_per_thread():
    import threading

    before = np.geterr()
    seen = {}
    with quiet():
        with quiet():
            assert np.geterr()["invalid"] == "ignore"
        assert np.geterr()["invalid"] == "ignore"  # the inner exit keeps the outer's

        def other() -> None:
            seen["outside"] = np.geterr()["invalid"]  # numpy's state is per thread
            with quiet():
                seen["inside"] = np.geterr()["invalid"]
            seen["after"] = np.geterr()["invalid"]

        t = threading.Thread(target=other)
        t.start()
        t.join()
    assert np.geterr() == before
    assert seen == {"outside": before["invalid"], "inside": "ignore", "after": before["invalid"]}
