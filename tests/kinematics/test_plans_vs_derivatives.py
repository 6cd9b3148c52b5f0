"""The plans against an independent route: a high-order numerical derivative
of the exact positions, at every position of every sample."""

import numpy as np

import mmt_plans
from mmt_plans.kinematics.branches import build_chain
from mmt_plans.results_json import results as results_json

# 8th-order central difference weights for the first derivative
WEIGHTS = np.array([1 / 280, -4 / 105, 1 / 5, -4 / 5, 0, 4 / 5, -1 / 5, 4 / 105, -1 / 280])
STEP_DEG = 2e-3


def derivative(mech, phi, field):
    """d/dt of `field(sweep)` by finite differences in the crank angle (ε1 = 0)."""
    dt = np.radians(STEP_DEG) / mech.drive.signed_omega
    total = 0
    for k, w in zip(range(-4, 5), WEIGHTS):
        if w:
            total = total + w * field(mmt_plans.sweep(mech, phi + k * STEP_DEG))
    return total / dt


def test_velocities_and_accelerations_equal_derivatives(sample_path):
    mech = mmt_plans.load(sample_path)
    analysis = mmt_plans.solve(mech)
    phi = np.array([p.phi1_deg for p in analysis.positions])
    sw = analysis.sweep.check()
    w1, r = abs(mech.drive.signed_omega), mech.crank_length
    for name in build_chain(mech).locate:
        dv = derivative(mech, phi, lambda s: s.points[name])
        da = derivative(mech, phi, lambda s: s.v[name])
        assert np.abs(dv - sw.v[name]).max() <= 1e-7 * w1 * r, name
        assert np.abs(da - sw.a[name]).max() <= 1e-7 * w1 * w1 * r, name
    for lid in mech.links:
        # the turn of the link from its angle at the position itself: small, so
        # no wrap at ±180° can enter the differences
        e0 = sw.links[lid].e
        dw = derivative(mech, phi, lambda s: np.angle(s.links[lid].e / e0))
        de = derivative(mech, phi, lambda s: s.omega[lid])
        assert np.abs(dw - sw.omega[lid]).max() <= 1e-7 * w1, lid
        assert np.abs(de - sw.eps[lid]).max() <= 1e-7 * w1 * w1, lid


def test_every_position_has_kinematics(sample_path):
    analysis = mmt_plans.solve(mmt_plans.load(sample_path))
    results = results_json(analysis)
    assert len(results["kinematics"]) == analysis.mechanism.study.positions + len(analysis.mechanism.study.angles)
    for entry in results["kinematics"]:
        assert "problem" not in entry
        assert all(np.isfinite(v).all() for v in entry["v"].values())
