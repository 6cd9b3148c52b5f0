"""The closed-form slider-crank (any textbook; seed 000 ch. 2):

    x_B = r cos φ + sqrt(l² - (r sin φ - e)²)       (guide y = e)
    dx_B/dφ = -r sin φ - r cos φ (r sin φ - e) / L,   L = sqrt(l² - (r sin φ - e)²)
    the rod's direction A→B is (L, e - r sin φ): its angle is -β with sin β = (r sin φ - e)/l,
    so ω2 = -dβ/dt = -ω1 r cos φ / (l cos β)
    V_B = ω1 dx_B/dφ,  a_B = ω1² d²x_B/dφ²  (ω1 constant)
"""

import math

import numpy as np
import pytest

import mmt_plans

R, L_ROD, E = 0.1, 0.4, 0.03
RPM = 300.0


def closed_form(phi):
    w = math.pi * RPM / 30
    s, c = np.sin(phi), np.cos(phi)
    q = R * s - E
    root = np.sqrt(L_ROD**2 - q * q)
    x = R * c + root
    dq = R * c
    dx = -R * s - q * dq / root
    # d/dφ of (-q dq / root) = -(dq² + q d2q)/root - q² dq² / root³, with d2q = -R s
    d2x = -R * c - (dq * dq - q * R * s) / root - (q * dq) ** 2 / root**3
    # the rod's angle β from B to A: sin β = q / l, so ω2 = dβ/dt
    beta = np.arcsin(q / L_ROD)
    dbeta = dq / (L_ROD * np.cos(beta))
    return x, w * dx, w * w * d2x, -beta, -w * dbeta


@pytest.fixture(scope="module")
def mech():
    return mmt_plans.load("samples/offset_slider_crank.toml")


def test_slider_crank_matches_closed_form(mech):
    phi = np.linspace(0, 2 * np.pi, 721)
    sw = mmt_plans.sweep(mech, np.degrees(phi)).check()
    x, v, a, angle2, w2 = closed_form(phi)
    scale = R * (math.pi * RPM / 30) ** 2
    assert np.abs(sw.points["B"][:, 0] - x).max() < 1e-12
    assert np.abs(sw.points["B"][:, 1] - E).max() < 1e-15
    assert np.abs(sw.v["B"][:, 0] - v).max() < 1e-12 * scale
    assert np.abs(sw.a["B"][:, 0] - a).max() < 1e-12 * scale * 10
    assert np.abs(np.angle(sw.links[2].e) - angle2).max() < 1e-12
    assert np.abs(sw.omega[2] - w2).max() < 1e-12 * (math.pi * RPM / 30)


def test_rod_angular_velocity_sign(mech):
    # at φ = 90° the pin moves left at r ω1 and B is still: the rod AB turns ...
    # V_B = V_A + ω2 × AB;  with A above the guide and B to the right, V_A = (-rω, 0):
    # x: 0... solve: V_Bx = -rω1 - ω2 (yB - yA) ⇒ with V_B·ŷ = 0: 0 = 0 + ω2 (xB - xA) ⇒ ω2 = 0
    sw = mmt_plans.sweep(mech, np.array([90.0]))
    assert abs(sw.omega[2][0]) < 1e-12
    assert sw.v["B"][0, 0] == pytest.approx(-R * math.pi * RPM / 30, rel=1e-12)
