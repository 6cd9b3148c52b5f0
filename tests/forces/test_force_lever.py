"""Zhukovsky's lever as the textbook builds it (seed 003 §2.9, seed 000 §4.5)."""

from __future__ import annotations

import numpy as np
import pytest
from force_checks import ROOT, c, cross

import mmt_plans



@pytest.fixture(scope="module")
def press():
    a = mmt_plans.solve(mmt_plans.load(ROOT / "samples" / "six_link_press.toml"))
    return a, a.forces_at(2)


def test_plan_turned_against_the_rotation(press):
    a, fa = press
    k = a.entry(2)
    assert fa.lever.turn_deg == -90.0  # a counter-clockwise crank: turned clockwise
    for name in "ABCDE":
        V = a.sweep.v[name][k]
        assert np.allclose(fa.lever.images[name], [V[1], -V[0]], rtol=0, atol=1e-15)
    assert fa.lever.pa == pytest.approx(np.hypot(*a.sweep.v["A"][k]))


def test_forces_at_their_images(press):
    a, fa = press
    labels = [f.label for f in fa.lever.forces]
    for i in range(1, 6):
        assert f"G{i}" in labels and f"F_in{i}" in labels
    assert "F_PR" in labels
    by = {f.label: f for f in fa.lever.forces}
    assert by["F_PR"].point == "E" and by["G2"].point == "S2" and by["F_in2"].point == "K2"
    # the inertia force of link 2 acts at the image of K2, the point its shift puts it on
    K2 = c(fa.loads.links[2].shifted_inertia_force.point)
    state = a.sweep.links[2]
    k = a.entry(2)
    V_K2 = complex(state.v[k]) + 1j * float(state.omega[k]) * (K2 - complex(state.o[k]))
    assert abs(c(by["F_in2"].image) - (-1j) * V_K2) < 1e-12
    bal = fa.lever.balancing
    assert bal.point == "A"
    assert abs(cross(c(bal.image), c(bal.force)) - bal.moment) < 1e-9
    # perpendicular to pa
    assert abs((c(bal.image).conjugate() * c(bal.force)).real) <= 1e-12 * abs(c(bal.force))


def test_couples_variant(press):
    a, fa = press
    labels = [f.label for f in fa.lever.couple_forces]
    for i in (2, 3, 4):  # links that turn with ε ≠ 0 and have J > 0
        assert f"F_M{i}" in labels and f"F'_M{i}" in labels
    assert fa.lever.balancing_force_couples == pytest.approx(fa.lever.balancing_force, rel=1e-12)
