"""Loads (seed 003 §2.1–2.5) and the production resistance in and out of the
working stroke."""

from __future__ import annotations

import numpy as np
import pytest
from force_checks import ROOT, c, cross, equilibrium_residuals, virtual_power_balancing_force

import mmt_plans
from mmt_plans.forces.loads import link_loads
from mmt_plans.errors import MmtError
from mmt_plans.forces import ForceError

PRESS = ROOT / "samples" / "six_link_press.toml"
FOUR_BAR = ROOT / "samples" / "four_bar_coupler.toml"


@pytest.fixture(scope="module")
def press():
    return mmt_plans.solve(mmt_plans.load(PRESS))


def test_weights_inertia_forces_and_moments(press):
    mech, sw = press.mechanism, press.sweep
    k = press.entry(2)
    loads = link_loads(press.state(press.positions[k].index), 0.005)
    assert loads.index == 2 and loads.phi1_deg == press.positions[k].phi1_deg
    for lid, link in mech.links.items():
        ll = loads.links[lid]
        assert np.array_equal(ll.weight, [0.0, -link.mass * 9.81])  # (14)
        a_S = sw.a[f"S{lid}"][k]
        assert np.allclose(ll.inertia_force, -link.mass * a_S, rtol=0, atol=1e-12)  # (15)
        assert ll.J == pytest.approx(link.k * link.mass * link.length**2)  # (16)
        assert ll.inertia_moment == pytest.approx(-ll.J * sw.eps[lid][k], rel=1e-15)  # (17)
        sh = ll.shifted_inertia_force
        assert sh is not None
        S, K, F = c(ll.centre_of_mass), c(sh.point), c(ll.inertia_force)
        # (18): the shifted force has the moment M_IN about S, at the arm h
        assert cross(K - S, F) == pytest.approx(ll.inertia_moment, rel=1e-12, abs=1e-15)
        assert abs(K - S) == pytest.approx(sh.arm, rel=1e-12, abs=1e-18)
        assert sh.arm == pytest.approx(abs(ll.inertia_moment) / abs(F), rel=1e-12)
        assert sh.arm_mm == pytest.approx(sh.arm / 0.005, rel=1e-15)  # (19)
    with pytest.raises(ForceError):
        link_loads(press.state(press.positions[k].index), -1.0)


def test_loads_are_read_only(press):
    ll = link_loads(press.state(press.positions[0].index)).links[2]
    with pytest.raises(ValueError):
        ll.inertia_force[0] = 1.0
    with pytest.raises(AttributeError):
        ll.mass = 3.0  # type: ignore[misc]


def test_gravity_off(press):
    a = mmt_plans.solve(press.mechanism.with_changes(g=0.0))
    for ll in link_loads(a.state(a.positions[0].index)).links.values():
        assert np.array_equal(ll.weight, [0.0, 0.0])


def test_loads_at_any_angle(press):
    loads = link_loads(press.state(phi1_deg=123.0))
    sw = press.chain.sweep(np.array([123.0]))
    assert loads.index is None and loads.phi1_deg == 123.0
    assert np.allclose(loads.links[4].inertia_force, -80.0 * sw.a["S4"][0], rtol=0, atol=1e-12)
    assert loads.stroke == press.stroke_of(123.0)


def test_production_resistance_off_in_the_idle_stroke(press):
    k = press.entry(8)
    assert press.positions[k].stroke == "idle"
    fa = press.forces_at(8)
    (f,) = fa.loads.production_resistance
    assert f.name == "F_PR" and not f.acting and np.array_equal(f.force, [0.0, 0.0])
    # the same as a press without the force
    bare = mmt_plans.solve(press.mechanism.with_changes(forces=()))
    fb = bare.forces_at(8)
    assert fa.balancing_force_plans == pytest.approx(fb.balancing_force_plans, rel=1e-12)
    for name, r in fa.reactions.items():
        assert np.allclose(r.force, fb.reactions[name].force, rtol=1e-12, atol=1e-9)


def test_production_resistance_acts_in_the_working_stroke(press):
    k = press.entry(2)
    assert press.positions[k].stroke == "working"
    fa = press.forces_at(2)
    (f,) = fa.loads.production_resistance
    assert f.acting and np.array_equal(f.force, [-9000.0, 0.0])  # along −working_direction
    bare = (mmt_plans.solve(press.mechanism.with_changes(forces=()))).forces_at(2)
    V_E = c(press.sweep.v["E"][k])
    V_A = abs(c(press.sweep.v["A"][k]))
    # the force adds −F·V_E / V_A to F_bal (equal powers)
    assert fa.balancing_force_plans - bare.balancing_force_plans == pytest.approx(
        9000.0 * V_E.real / V_A, rel=1e-9)
    assert V_E.real > 0


def test_always_opposes_the_velocity():
    a = mmt_plans.solve(mmt_plans.load(FOUR_BAR))
    for pos in a.positions:
        k = a.entry(pos.index)
        (f,) = link_loads(a.state(a.positions[k].index)).production_resistance
        V = c(a.sweep.v["B"][k])
        F = c(f.force)
        if abs(V) > 1e-9:
            assert f.acting and not f.at_rest and abs(F) == pytest.approx(150.0)
            assert abs(F + 150.0 * V / abs(V)) < 1e-9
        else:  # an extreme position of the rocker: B stops, the resistance is zero (SPEC_FORMAT)
            assert pos.index == 0
            assert not f.acting and f.at_rest and F == 0


FIXED = """
title = "slider-crank with a fixed-direction force"
[drive]
link = 1
rpm = 300
[study]
output = "B"
[frame]
O = [0, 0]
[[link]]
id = 1
points = { O = [0, 0], A = [100, 0] }
mass = 2
[[link]]
id = 2
points = { A = [0, 0], B = [400, 0] }
mass = 5
[[link]]
id = 3
points = { B = [0, 0] }
mass = 8
[[slider]]
link = 3
on = 0
through = [0, 30]
angle = 0
[sketch]
A = [0, 100]
B = [390, 30]
[[force]]
name = "F_down"
link = 2
at = "B"
magnitude = 500
direction = [0, -1]
%s
"""


def test_fixed_direction_against_the_motion_is_refused():
    # SPEC_FORMAT: `direction` together with acts = "always" is an error
    with pytest.raises(mmt_plans.SpecError) as err:
        mmt_plans.loads(FIXED % 'acts = "always"')
    assert "force[1].acts" in str(err.value) and "fix:" in str(err.value)


@pytest.mark.parametrize("acts, idle_acts", [("", True), ('acts = "working"', False)])
def test_fixed_direction(acts, idle_acts):
    a = mmt_plans.solve(mmt_plans.loads(FIXED % acts))
    for pos in a.positions:
        k = a.entry(pos.index)
        fa = a.forces_at(pos.index)
        (f,) = fa.loads.production_resistance
        acting = idle_acts or pos.stroke == "working"
        assert f.acting == acting and f.rule == "fixed"
        assert np.array_equal(f.force, [0.0, -500.0] if acting else [0.0, 0.0])
        for link, (F, M, scale) in equilibrium_residuals(a.mechanism, a.sweep, k, pos.stroke,
                                                         fa).items():
            assert F <= 1e-9 * scale and M <= 1e-9 * scale
        expected = virtual_power_balancing_force(a.mechanism, a.sweep, k, pos.stroke)
        assert fa.balancing_force_plans == pytest.approx(expected, rel=1e-9)


ROCKER_CM_AT_PIVOT = FOUR_BAR.read_text().replace(
    "points = { C = [0, 0], B = [200, 0] }\nmass = 3",
    "points = { C = [0, 0], B = [200, 0] }\nmass = 3\ncm = [0, 0]\nJ = 0.4")


def test_zero_inertia_force_keeps_the_couple():
    """A rocker with its centre of mass on the fixed pivot: F_IN3 = 0 while
    M_IN3 = −J3·ε3 is not; nothing to shift, so the couple stays (and goes on
    the lever as two forces M/l at C and B)."""
    assert "cm = [0, 0]" in ROCKER_CM_AT_PIVOT
    a = mmt_plans.solve(mmt_plans.loads(ROCKER_CM_AT_PIVOT))
    fa = a.forces_at()
    ll = fa.loads.links[3]
    assert np.hypot(*ll.inertia_force) < 1e-12  # rounding noise at most
    assert abs(ll.inertia_moment) > 1e-3
    assert ll.shifted_inertia_force is None
    labels = [f.label for f in fa.lever.forces]
    assert "F_M3" in labels and "F'_M3" in labels
    pair = [f for f in fa.lever.forces if f.label in ("F_M3", "F'_M3")]
    assert {f.point for f in pair} == {"C", "B"}
    assert np.allclose(pair[0].force, -pair[1].force)
    C, B = (c(a.sweep.points[p][a.entry(fa.index)]) for p in "CB")
    F_B = c(next(f for f in pair if f.point == "B").force)
    assert cross(B - C, F_B) == pytest.approx(ll.inertia_moment, rel=1e-12)  # F' = M / l
    k = a.entry(fa.index)
    expected = virtual_power_balancing_force(a.mechanism, a.sweep, k, a.positions[k].stroke)
    assert fa.balancing_force_plans == pytest.approx(expected, rel=1e-9)
    assert fa.balancing_force_lever == pytest.approx(expected, rel=1e-9)
    for link, (F, M, scale) in equilibrium_residuals(a.mechanism, a.sweep, k, a.positions[k].stroke,
                                                     fa).items():
        assert F <= 1e-9 * scale and M <= 1e-9 * scale


def test_errors_are_clear(press):
    with pytest.raises(ForceError, match="position 99 does not exist") as err:
        press.forces_at(99)
    assert isinstance(err.value, MmtError) and isinstance(err.value, ValueError)
    with pytest.raises(ForceError):
        press.forces_at(True)  # type: ignore[arg-type]
    with pytest.raises(ForceError):
        press.forces_at(2, phi1_deg=10.0)
    at_rest = PRESS.read_text().replace('at = "E"', 'at = "E"\ndirection = [1, 0]')
    assert (mmt_plans.solve(mmt_plans.loads(at_rest))).forces_at().loads.production_resistance[0].rule \
        == "fixed"
    # a force against the motion of the crank's pivot, which never moves: always at rest, zero
    pivot = FOUR_BAR.read_text().replace('link = 3\nat = "B"', 'link = 1\nat = "O"')
    assert 'at = "O"' in pivot
    (f,) = (mmt_plans.solve(mmt_plans.loads(pivot))).forces_at().loads.production_resistance
    assert f.at_rest and not f.acting and not f.force.any()


def test_a_position_that_does_not_assemble():
    """A crank too long for the four-bar cannot turn: at an angle where the
    group does not assemble, the kinematics' own error comes through."""
    text = FOUR_BAR.read_text().replace("A = [80, 0]", "A = [200, 0]")
    with pytest.raises(MmtError, match="cannot make a whole turn"):
        mmt_plans.solve(mmt_plans.loads(text)).positions
    mech = mmt_plans.loads(text.replace("[study]", "[study]\npartial_turn = true"))
    an = mmt_plans.solve(mech)
    bad = next(phi for phi in np.arange(0.0, 360.0, 5.0)
               if an.chain.sweep(np.array([phi])).problem(0) is not None)
    with pytest.raises(MmtError, match="cannot assemble"):
        an.forces_at(phi1_deg=float(bad))
