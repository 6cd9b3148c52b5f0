"""Reduction to the crank (seed 002 tasks 5, 6), checked against positions
differentiated numerically — a route that does not use the velocity plans:

    V_P ≈ ω1·(P(φ + h) − P(φ − h)) / 2h,   ω_i ≈ ω1·(θ_i(φ + h) − θ_i(φ − h)) / 2h
    J_red = Σ (m·V_S² + J·ω²) / ω1²,   M_red = Σ F·V / ω1  (central differences: error ~ h²)
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest
from force_checks import ROOT, SAMPLES

import mmt_plans
from mmt_plans.forces.reduction import reduce_sweep

H_DEG = 1e-4


def by_differences(a):
    mech = a.mechanism
    phi = np.array([p.phi1_deg for p in a.positions])
    h = np.radians(H_DEG)
    ahead, back = mmt_plans.sweep(mech, phi + H_DEG), mmt_plans.sweep(mech, phi - H_DEG)
    w1 = mech.drive.signed_omega
    energy = np.zeros(len(phi))
    for lid, link in mech.links.items():
        V = w1 * (ahead.points[link.cm_name] - back.points[link.cm_name]) / (2 * h)
        dtheta = np.angle(ahead.links[lid].e / back.links[lid].e)
        w = w1 * dtheta / (2 * h)
        energy += link.mass * (V**2).sum(axis=1) + link.J * w**2
    J_red = energy / w1**2
    power = np.zeros(len(phi))
    wd = mech.study.working_direction
    working = np.array([p.stroke == "working" for p in a.positions])
    for f in mech.forces:
        V = w1 * (ahead.points[f.at] - back.points[f.at]) / (2 * h)
        assert f.direction is None  # the samples' resistances
        if f.acts == "working":
            power += np.where(working, -f.magnitude * (V @ wd), 0.0)
        else:  # against the velocity
            power += -f.magnitude * np.hypot(V[:, 0], V[:, 1])
    return J_red, power / abs(w1)


@pytest.mark.parametrize("path", SAMPLES, ids=lambda p: p.stem)
def test_reduced_inertia_and_moment(path):
    a = mmt_plans.solve(mmt_plans.load(path))
    red = a.reduction
    J_red, M_red = by_differences(a)
    assert np.allclose(red.reduced_inertia, J_red, rtol=1e-6, atol=0)
    scale = np.abs(M_red).max()
    assert np.allclose(red.reduced_moment, M_red, rtol=0, atol=1e-6 * scale)
    assert red.index == tuple(p.index for p in a.positions)
    # the crank alone: J_red >= J_1 + m_1·(OS1)² > 0
    assert (red.reduced_inertia > 0).all()


def test_sign_of_the_reduced_moment():
    """Seed 002 task 5: M = −F_KO·v_S5/ω1 < 0 — the resistance takes energy
    from the drive; zero in the idle stroke."""
    a = mmt_plans.solve(mmt_plans.load(ROOT / "samples" / "six_link_press.toml"))
    red = a.reduction
    for pos, m in zip(a.positions, red.reduced_moment):
        if pos.stroke == "idle":
            assert m == 0.0
        else:
            assert m <= 1e-9
    k = a.entry(2)
    V_E = a.sweep.v["E"][k]
    assert red.reduced_moment[k] == pytest.approx(-9000.0 * V_E[0] / a.mechanism.drive.omega)
    assert red.reduced_moment_of["F_PR"][k] == red.reduced_moment[k]


def test_reduced_moment_is_balanced_by_the_balancing_moment():
    """Massless links and no gravity: M_bal + M_red = 0 at every position."""
    mech = mmt_plans.load(ROOT / "samples" / "six_link_press.toml")
    links = {lid: replace(link, mass=0.0, J=0.0) for lid, link in mech.links.items()}
    a = mmt_plans.solve(mech.with_changes(links=links, g=0.0))
    red = a.reduction
    assert np.all(red.reduced_inertia == 0.0)
    for k, pos in enumerate(a.positions):
        fa = a.forces_at(pos.index)
        assert fa.balancing_moment == pytest.approx(-red.reduced_moment[k], rel=1e-9, abs=1e-9)


def test_reduction_at_any_angles():
    a = mmt_plans.solve(mmt_plans.load(ROOT / "samples" / "shaper.toml"))
    phi = np.linspace(0, 360, 73)
    red = reduce_sweep(a.mechanism, a.sweep_at(phi % 360), (None,) * len(phi),
                       tuple(a.stroke_of(x % 360) for x in phi))
    assert red.phi1_deg.shape == (73,) and all(i is None for i in red.index)
    at_positions = a.reduction
    k = 3
    phi_k = a.positions[k].phi1_deg
    again = reduce_sweep(a.mechanism, a.sweep_at([phi_k]), (None,), (a.stroke_of(phi_k),))
    assert again.reduced_inertia[0] == pytest.approx(at_positions.reduced_inertia[k], rel=1e-14)
    assert again.reduced_moment[0] == pytest.approx(at_positions.reduced_moment[k], rel=1e-14)
