"""Closed forms with massless links and no gravity, the production resistance
the only load.

Offset slider-crank (r = OA, l = AB, guide y = e), seed 000 ch. 2:
    x_B = r cos φ + sqrt(l² − (r sin φ − e)²),  V_B = ω1·dx_B/dφ
    equal powers: F_bal·V_A = F_bal·ω1·r = F_PR·|V_B|   (F_PR against V_B in the working stroke)
    the rod is a two-force member: R12 ∥ AB; at the slider R03 ⊥ guide and
    R03 = F_PR·tan β, tan β = (r sin φ − e) / sqrt(l² − (r sin φ − e)²).

Scotch yoke (samples/forces_scotch_yoke.toml): x_Y = r cos φ, V_Y = −r ω1 sin φ;
    F_PR = (−F, 0) in the working stroke, so F_bal = −F sin φ; the block passes
    R12 = (F, 0); the yoke's guide carries no normal force but the couple
    y_A·F = F r sin φ (ΣM_Y of the yoke: (0, y_A) × (F, 0) + C = 0).
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest
from force_checks import ROOT, c, cross

import mmt_plans


R, L_ROD, E, F_PR = 0.1, 0.4, 0.03, 2000.0


def massless(path):
    mech = mmt_plans.load(path)
    links = {lid: replace(link, mass=0.0, J=0.0) for lid, link in mech.links.items()}
    return mmt_plans.solve(mech.with_changes(links=links, g=0.0))


@pytest.fixture(scope="module")
def slider_crank():
    return massless(ROOT / "samples" / "offset_slider_crank.toml")


def test_slider_crank_balancing_force_by_hand(slider_crank):
    a = slider_crank
    w = a.mechanism.drive.omega
    working = 0
    for pos in a.positions:
        fa = a.forces_at(pos.index)
        phi = math.radians(pos.phi1_deg)
        q = R * math.sin(phi) - E
        root = math.sqrt(L_ROD**2 - q * q)
        V_B = w * (-R * math.sin(phi) - q * R * math.cos(phi) / root)
        if pos.stroke == "working":
            working += 1
            # F_bal·r = F_PR·|V_B|/ω1
            assert fa.balancing_force_plans * R == pytest.approx(F_PR * abs(V_B) / w, rel=1e-9,
                                                                 abs=1e-9 * F_PR * R)
            assert fa.balancing_force_plans >= -1e-9  # it drives against the resistance
            A, B = c(a.sweep.points["A"][a.entry(pos.index)]), c(a.sweep.points["B"][a.entry(pos.index)])
            R12 = c(fa.reactions["R12"].force)
            assert abs(cross(R12, B - A)) <= 1e-9 * abs(R12) * abs(B - A)
            R03 = fa.reactions["R03"]
            assert R03.force[0] == pytest.approx(0.0, abs=1e-9 * F_PR)
            assert abs(R03.force[1]) == pytest.approx(F_PR * abs(q) / root, rel=1e-9, abs=1e-9)
        else:  # nothing loads the mechanism in the idle stroke
            assert fa.balancing_force_plans == pytest.approx(0.0, abs=1e-12)
            assert all(r.magnitude <= 1e-12 for r in fa.reactions.values())
    assert working >= 6


def test_scotch_yoke_by_hand():
    a = massless(ROOT / "samples" / "forces_scotch_yoke.toml")
    r = 0.12
    for pos in a.positions:
        fa = a.forces_at(pos.index)
        phi = math.radians(pos.phi1_deg)
        F = 1000.0 if pos.stroke == "working" else 0.0
        assert fa.balancing_force_plans == pytest.approx(-F * math.sin(phi), abs=1e-9 * 1000)
        assert fa.balancing_force_lever == pytest.approx(-F * math.sin(phi), abs=1e-9 * 1000)
        assert np.allclose(fa.reactions["R12"].force, [F, 0.0], atol=1e-9 * 1000)
        R03 = fa.reactions["R03"]
        assert np.allclose(R03.force, [0.0, 0.0], atol=1e-9 * 1000)
        Y = c(a.sweep.points["Y"][a.entry(pos.index)])
        moment_about_Y = cross(c(R03.point) - Y, c(R03.force)) + R03.couple
        assert moment_about_Y == pytest.approx(F * r * math.sin(phi), abs=1e-9 * 1000 * r)
