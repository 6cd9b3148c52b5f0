"""Every sample, every position: each link in equilibrium under its own loads
(rebuilt here from the file and the kinematics), the reactions of its pairs
and F_bal; R_ij = −R_ji; F_bal equal to the virtual-power value; Zhukovsky's
lever equal to the force plans."""

from __future__ import annotations

import numpy as np
import pytest
from force_checks import (SAMPLES, balancing_direction, c, equilibrium_residuals, pairs_of,
                          virtual_power_balancing_force)
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

import mmt_plans

from mmt_plans.forces.groups import reaction_name

TOL = 1e-9


@pytest.fixture(scope="module", params=SAMPLES, ids=lambda p: p.stem)
def analysis(request):
    return mmt_plans.solve(mmt_plans.load(request.param))


def every_position(analysis):
    for k, pos in enumerate(analysis.positions):
        if pos.index is not None and analysis.problem(k) is None:
            yield k, pos, analysis.forces_at(pos.index)


def test_every_link_in_equilibrium(analysis):
    mech, sweep = analysis.mechanism, analysis.sweep
    checked = 0
    for k, pos, fa in every_position(analysis):
        for link, (F, M, scale) in equilibrium_residuals(mech, sweep, k, pos.stroke, fa).items():
            assert F <= TOL * scale, (pos.index, link, F, scale)
            assert M <= TOL * scale, (pos.index, link, M, scale)
        checked += 1
    assert checked == mech.study.positions


def test_reactions_are_equal_and_opposite(analysis):
    """The reaction one group finds and the one the next group is loaded with
    (R43 = −R34), as the free bodies of the two links carry them."""
    mech = analysis.mechanism
    for _, pos, fa in every_position(analysis):
        for i, j, name in pairs_of(mech):
            if 0 in (i, j):
                continue
            on_j = [f for f in fa.free_body(j) if f.label == reaction_name(i, j)]
            on_i = [f for f in fa.free_body(i) if f.label == reaction_name(j, i)]
            assert len(on_j) == 1 and len(on_i) == 1, (pos.index, name)
            fj, fi = on_j[0], on_i[0]
            scale = max(1.0, float(np.hypot(*fj.force)))
            assert np.allclose(fj.force, -fi.force, rtol=0, atol=1e-12 * scale)
            assert np.allclose(fj.point, fi.point, rtol=0, atol=1e-15)
            assert abs(fj.couple + fi.couple) <= 1e-12 * scale


def test_every_pair_listed_once(analysis):
    mech = analysis.mechanism
    fa = analysis.forces_at()
    listed = sorted(tuple(sorted((r.by, r.on))) for r in fa.reactions.values())
    assert listed == sorted(tuple(sorted((i, j))) for i, j, _ in pairs_of(mech))
    for name, r in fa.reactions.items():
        assert name == reaction_name(r.by, r.on)
    assert reaction_name(0, mech.drive.link) in fa.reactions


def test_balancing_force_by_virtual_power(analysis):
    mech, sweep = analysis.mechanism, analysis.sweep
    for k, pos, fa in every_position(analysis):
        expected = virtual_power_balancing_force(mech, sweep, k, pos.stroke)
        assert abs(fa.balancing_force_plans - expected) <= TOL * abs(expected), pos.index
        # the vector acts at A perpendicular to OA, in the sense of rotation when positive
        t = balancing_direction(mech, sweep, k)
        assert abs(c(fa.driving_link.balancing_vector) - fa.balancing_force_plans * t) \
            <= 1e-12 * abs(expected)
        r = abs(c(sweep.points[mech.crank_pin][k]) - c(sweep.points[mech.crank_pivot][k]))
        assert abs(fa.balancing_moment - fa.balancing_force_plans * r) <= 1e-12 * abs(expected) * r


def test_lever_agrees_with_plans(analysis):
    for _, pos, fa in every_position(analysis):
        plans = fa.balancing_force_plans
        assert abs(fa.balancing_force_lever - plans) <= TOL * abs(plans)
        assert abs(fa.lever.balancing_force_couples - plans) <= TOL * abs(plans)
        assert fa.discrepancy_percent <= 1e-7


def test_lever_moments_balance(analysis):
    """Σ M_p = 0 on the lever, the balancing force included (1.41)."""
    for _, pos, fa in every_position(analysis):
        lever = fa.lever
        total = sum(f.moment for f in lever.forces) + lever.balancing.moment
        biggest = max(abs(f.moment) for f in (*lever.forces, lever.balancing))
        assert abs(total) <= 1e-12 * biggest
        for f in lever.forces:  # moment = F·h, and the arm is the pole's distance to the line
            F = c(f.force)
            if abs(F):
                assert abs(f.moment - abs(F) * f.arm) <= 1e-12 * abs(f.moment) + 1e-300
                dist = abs((c(f.image) * F.conjugate()).imag) / abs(F)
                assert abs(abs(f.arm) - dist) <= 1e-12 * max(dist, 1.0)


def test_force_polygons_close(analysis):
    for _, pos, fa in every_position(analysis):
        polygons = [p for g in fa.groups for p in g.polygons] + [fa.driving_link.polygon]
        for poly in polygons:
            assert poly.closure <= 1e-12 * poly.largest, (pos.index, poly.title)
            start = 0j
            for v in poly.vectors:  # head to tail from the origin
                assert abs(c(v.start) - start) <= 1e-12 * poly.largest
                start = c(v.end)
            assert any(not v.known for v in poly.vectors)
            assert poly.equation.endswith("= 0")


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(phi=st.floats(0.0, 360.0, allow_nan=False))
def test_equilibrium_at_any_angle(analysis, phi):
    mech = analysis.mechanism
    sweep = analysis.chain.sweep(np.array([phi]))
    assume(sweep.problem(0) is None)
    stroke = analysis.stroke_of(phi % 360.0)
    fa = analysis.forces_at(phi1_deg=phi)
    assert fa.index is None
    for link, (F, M, scale) in equilibrium_residuals(mech, sweep, 0, stroke, fa).items():
        assert F <= TOL * scale and M <= TOL * scale, (phi, link)
    expected = virtual_power_balancing_force(mech, sweep, 0, stroke)
    assert abs(fa.balancing_force_plans - expected) <= TOL * abs(expected)
    assert abs(fa.balancing_force_lever - expected) <= TOL * abs(expected)


@pytest.mark.parametrize("name", ["six_link_press", "shaper", "five_dyads"])
def test_clockwise_crank(name):
    """With the crank turning clockwise F_bal is still positive when it drives;
    the lever's plan is turned by +90° (against the rotation)."""
    from dataclasses import replace

    from force_checks import ROOT

    mech = mmt_plans.load(ROOT / "samples" / f"{name}.toml")
    a = mmt_plans.solve(mech.with_changes(drive=replace(mech.drive, sense="cw")))
    for k, pos, fa in every_position(a):
        assert fa.lever.turn_deg == 90.0
        expected = virtual_power_balancing_force(a.mechanism, a.sweep, k, pos.stroke)
        assert abs(fa.balancing_force_plans - expected) <= TOL * abs(expected)
        assert abs(fa.balancing_force_lever - expected) <= TOL * abs(expected)
        t = balancing_direction(a.mechanism, a.sweep, k)
        V_A = c(a.sweep.v[a.mechanism.crank_pin][k])
        assert abs(t - V_A / abs(V_A)) < 1e-12  # "in the sense of rotation" is along V_A
        for link, (F, M, scale) in equilibrium_residuals(a.mechanism, a.sweep, k, pos.stroke,
                                                         fa).items():
            assert F <= TOL * scale and M <= TOL * scale
