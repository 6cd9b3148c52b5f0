"""Properties on random assemblable mechanisms (hypothesis): loop closure at
every angle, no branch jump over a whole turn, the velocity plan closes."""

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

import mmt_plans
from mechanisms import four_bar_toml, slider_crank_toml
from mmt_plans.kinematics.geometry import cross

TURN = np.linspace(0.0, 360.0, 1441)  # 0.25° steps, both ends
MM = 1e-3


def four_bar(r, d, l, c, sign):
    b_sketch = "" if sign is None else f"[sketch]\nA = [{r}, 0]\nB = [{d / 2}, {sign * 10 * l}]\n"
    return 'title = "random four-bar"\n' + four_bar_toml(r, d, l, c, extra=b_sketch)


@st.composite
def grashof_crank_rocker(draw):
    r = draw(st.floats(10, 100))
    d = draw(st.floats(3 * r, 1000))
    l = draw(st.floats(1.2 * r, 1000))
    lo, hi = abs(d - l) + r * 1.05, d + l - r * 1.05  # |d - l| + r < c < d + l - r: the crank turns fully
    c = draw(st.floats(lo, hi).filter(lambda c: c > 1))
    return r, d, l, c


@settings(max_examples=40, deadline=None)
@given(grashof_crank_rocker(), st.sampled_from([1, -1, None]))
def test_four_bar_closes_and_never_jumps(dims, sign):
    r, d, l, c = dims
    mech = mmt_plans.loads(four_bar(r, d, l, c, sign))
    sw = mmt_plans.sweep(mech, TURN).check()
    A, B, C = (sw.position_of(n) for n in "ABC")
    assert np.abs(np.abs(B - A) - l * MM).max() < 1e-9 * MM
    assert np.abs(np.abs(B - C) - c * MM).max() < 1e-9 * MM
    # one branch all the way round: B stays on one side of A→C, and the turn closes
    side = np.sign(cross(C - A, B - A))
    assert np.all(side == side[0])
    assert abs(B[-1] - B[0]) < 1e-9 * MM
    # the velocity plan closes: V_B = V_A + V_BA with V_BA ⊥ AB, and V_B ⊥ CB
    VA, VB = sw.velocity_of("A"), sw.velocity_of("B")
    scale = mech.drive.omega * r * MM
    assert np.abs(((VB - VA) * np.conj(B - A)).real).max() < 1e-9 * scale * l * MM
    assert np.abs((VB * np.conj(B - C)).real).max() < 1e-9 * scale * c * MM


@settings(max_examples=40, deadline=None)
@given(st.floats(10, 200), st.floats(1.2, 6), st.floats(-0.9, 0.9))
def test_slider_crank_closes_and_never_jumps(r, ratio, offset):
    l = r * ratio
    e = offset * (l - r)  # |e| < l - r: the crank turns fully
    mech = mmt_plans.loads(slider_crank_toml(r, l, e, drive="omega = 20"))
    sw = mmt_plans.sweep(mech, TURN).check()
    A, B = sw.position_of("A"), sw.position_of("B")
    assert np.abs(np.abs(B - A) - l * MM).max() < 1e-9 * MM
    assert np.abs(B.imag - e * MM).max() < 1e-9 * MM
    assert np.all(B.real > A.real)  # the default branch: the far intersection, all the way round
    VA, VB = sw.velocity_of("A"), sw.velocity_of("B")
    assert np.abs(VB.imag).max() < 1e-12
    assert np.abs(((VB - VA) * np.conj(B - A)).real).max() < 1e-9 * 20 * r * MM * l * MM


@settings(max_examples=40, deadline=None)
@given(st.floats(20, 200), st.floats(1.2, 5), st.floats(1.5, 4))
def test_slotted_link_closes_and_never_jumps(r, dist_ratio, arm_ratio):
    d = r * dist_ratio  # pivot distance > crank: the slotted link rocks
    arm = d * arm_ratio
    mech = mmt_plans.loads(f"""
[drive]
rpm = 60
[study]
output = "B"
[frame]
O = [0, 0]
C = [0, {-d}]
[[link]]
id = 1
points = {{ O = [0, 0], A = [{r}, 0] }}
[[link]]
id = 2
points = {{ A = [0, 0] }}
[[link]]
id = 3
points = {{ C = [0, 0], B = [{arm}, 0] }}
[[slider]]
link = 2
on = 3
[sketch]
A = [0, {r}]
B = [0, {arm - d}]
""")
    sw = mmt_plans.sweep(mech, TURN).check()
    A, B, C = sw.position_of("A"), sw.position_of("B"), sw.position_of("C")
    # the block's point lies on the slot's line C→B at every angle
    assert np.abs(cross(B - C, A - C) / np.abs(B - C)).max() < 1e-9 * MM
    assert np.all(B.imag > C.imag)  # the sketched branch (arm up) all the way round
    # no jump: each step of the slot's angle is the integral of ω3 over it (trapezoid, O(Δt³))
    step = np.angle(sw.links[3].e[1:] / sw.links[3].e[:-1])
    dt = np.radians(TURN[1] - TURN[0]) / mech.drive.omega
    assert np.abs(step - 0.5 * (sw.omega[3][1:] + sw.omega[3][:-1]) * dt).max() < 1e-3
    # velocity plan: V_A3 = V_A2 + V_rel (∥ slot) and V_A3 = ω3 × CA
    VA = sw.velocity_of("A")
    VA3 = sw.links[3].vel(A)
    rel = VA3 - VA
    assert np.abs(cross(rel, B - C)).max() < 1e-9 * np.abs(B - C).max() * 6.3 * r * MM
    assert np.array_equal(sw.omega[2], sw.omega[3])  # the block turns with the slot
