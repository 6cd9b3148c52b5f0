"""Hard cases: dead centres, near-parallel plan lines, extreme proportions, a
mechanism that assembles over part of the turn. References are computed in
50-digit arithmetic (mpmath) from the closed forms; each test states and
asserts how many digits survive."""

import json
import math

import mpmath as mp
import numpy as np
import pytest

import mmt_plans
from mmt_plans.results_json import results as results_json
from mechanisms import four_bar_toml, slider_crank_toml

mp.mp.dps = 50


def slider_crank(r_mm, l_mm, rpm=100.0, e_mm=0.0):
    return mmt_plans.loads(slider_crank_toml(r_mm, l_mm, e_mm, drive=f"rpm = {rpm}"))


def slider_crank_reference(r, l, w, phi_deg, e=0.0):
    """x_B, V_B, a_B, ω2, ε2 in 50 digits, by differentiating the closed form."""
    r, l, w, e = mp.mpf(r), mp.mpf(l), mp.mpf(w), mp.mpf(e)

    def x(p):
        return r * mp.cos(p) + mp.sqrt(l**2 - (r * mp.sin(p) - e) ** 2)

    def ang(p):  # the rod's angle A→B
        return mp.atan2(e - r * mp.sin(p), x(p) - r * mp.cos(p))

    p = mp.radians(mp.mpf(phi_deg))
    return (x(p), w * mp.diff(x, p), w**2 * mp.diff(x, p, 2), w * mp.diff(ang, p),
            w**2 * mp.diff(ang, p, 2))


def digits(err, scale):
    return float(-mp.log10(mp.mpf(abs(err)) / scale)) if err else 17.0


@pytest.mark.parametrize("ratio", [1.05, 4.0])
@pytest.mark.parametrize("delta", [1e-3, 1e-6, 1e-9, 0.0])
def test_dead_centre_of_a_slider_crank(ratio, delta):
    r, l = 100.0, 100.0 * ratio
    mech = slider_crank(r, l)
    w = mech.drive.omega
    for phi in (delta, 180.0 - delta):
        sw = mmt_plans.sweep(mech, [phi]).check()  # finite, no error: a dead centre of the crank is no singular plan
        ref = slider_crank_reference(r / 1e3, l / 1e3, w, phi)
        got = (sw.points["B"][0, 0], sw.v["B"][0, 0], sw.a["B"][0, 0], sw.omega[2][0], sw.eps[2][0])
        scales = (r / 1e3, w * r / 1e3, w * w * r / 1e3, w, w * w)
        kept = [digits(g - rf, s) for g, rf, s in zip(got, ref, scales)]
        # at a crank dead centre the plan's lines are perpendicular (rod ⊥ guide normal):
        # 15 digits of every quantity survive, relative to its scale (r, ωr, ω²r, ω, ω²)
        assert min(kept) >= 15, (phi, kept)


def toggle_four_bar():
    # |AC| reaches l2 + l3 = 400 mm exactly at phi1 = 180: the coupler and rocker in line
    return mmt_plans.loads(four_bar_toml(100, 300, 250, 150, rpm=60))


def four_bar_reference(phi_deg, w, sign=1):
    """ω2, ω3 in 50 digits from the same circle intersection and 2×2 plan."""
    r, d, l, c = (mp.mpf(x) / 1000 for x in (100, 300, 250, 150))
    p = mp.radians(mp.mpf(phi_deg))
    A = mp.mpc(r * mp.cos(p), r * mp.sin(p))
    C = mp.mpc(d, 0)
    D = C - A
    L = abs(D)
    along = (l**2 - c**2 + L**2) / (2 * L)
    h = mp.sqrt(max(l**2 - along**2, 0))
    B = A + D / L * (along + sign * 1j * h)
    VA = 1j * w * (A - 0)
    d1, d2 = 1j * (B - A), 1j * (B - C)

    def cross(a, b):
        return a.real * b.imag - a.imag * b.real

    det = cross(d2, d1)
    return cross(d2, -VA) / det, cross(d1, -VA) / det, abs(det) / (abs(d1) * abs(d2))


@pytest.mark.parametrize("cond", [1e4, 1e8, 1e10])
def test_plan_with_nearly_parallel_lines_keeps_16_minus_log_cond_digits(cond):
    """The 2×2 plan solve alone: two direction lines at an angle 1/cond, with
    inputs exact in binary, against the same solve in 50 digits."""
    from mmt_plans.kinematics.dyads import solve_two_lines

    angle = 1.0 / cond
    d1 = np.array([complex(0.3, 0.4)])
    d2 = d1 * complex(math.cos(angle), math.sin(angle))
    b1, b2 = np.array([complex(0.25, -1.5)]), np.array([complex(-0.75, 2.0)])
    x1, x2 = solve_two_lines(d1, b1, d2, b2)
    D1, D2 = mp.mpc(d1[0]), mp.mpc(d2[0])
    rhs = mp.mpc(b2[0]) - mp.mpc(b1[0])

    def cr(a, b):
        return a.real * b.imag - a.imag * b.real

    X1, X2 = cr(D2, rhs) / cr(D2, D1), cr(D1, rhs) / cr(D2, D1)
    kept = min(digits(x1[0] - X1, abs(X1)), digits(x2[0] - X2, abs(X2)))
    assert np.isfinite(x1[0]) and np.isfinite(x2[0])
    assert kept >= 16 - math.log10(cond) - 1, kept


@pytest.mark.parametrize("delta", [1e-1, 1e-2, 1e-3])
def test_mechanism_near_a_toggle_keeps_16_minus_2_log_cond_digits(delta):
    """Near a toggle the position itself is ill-conditioned in the crank angle:
    B moves by ~l/sin for a rounding of A, and the plan divides by sin again,
    so about 2·log10(cond) digits are lost (cond = 1/sin of the plan lines' angle)."""
    mech = toggle_four_bar()
    w = mech.drive.omega
    sw = mmt_plans.sweep(mech, [180.0 - delta]).check()
    w2, w3, sin_ref = four_bar_reference(180.0 - delta, w)
    cond = 1 / float(sin_ref)
    kept = min(digits(sw.omega[2][0] - w2, w), digits(sw.omega[3][0] - w3, w))
    assert kept >= 16 - 2 * math.log10(cond) - 1, (cond, kept)


def test_toggle_within_rounding_is_reported_as_singular_not_nan():
    # 1e-6 deg from the toggle, |AC| differs from l2 + l3 by 37.5·δ² mm ≈ 1e-14 mm:
    # below double precision, so the position is the toggle itself: a singular plan
    mech = toggle_four_bar()
    sw = mmt_plans.sweep(mech, [180.0 - 1e-6])
    assert not sw.ok[0]
    assert isinstance(sw.problem(0), mmt_plans.SingularPlanError)
    assert "at phi1 = 179.999999 deg" in str(sw.problem(0))


def test_exactly_parallel_plan_lines_are_reported_not_inf():
    mech = toggle_four_bar()
    sw = mmt_plans.sweep(mech, [90.0, 180.0, 270.0])
    assert list(sw.ok) == [True, False, True]
    err = sw.problem(1)
    assert isinstance(err, mmt_plans.SingularPlanError)
    assert "at phi1 = 180 deg, the plan of group 2-3 is singular" in str(err)
    # the analysis of the other positions is still done, and the JSON has no inf or NaN:
    # the toggle asked for as an extra angle is reported there as singular
    analysis = mmt_plans.solve(mmt_plans.loads(four_bar_toml(100, 300, 250, 150, rpm=60).replace(
        'output = "B"', 'output = "B"\nangles = [180]')))
    out = json.loads(json.dumps(results_json(analysis), allow_nan=False))
    extra = [p for p in out["kinematics"] if p["index"] is None]
    assert len(extra) == 1 and extra[0]["phi1_deg"] == 180.0
    assert "is singular" in extra[0]["problem"]
    assert sum("problem" in p for p in out["kinematics"]) == 1


def test_extreme_proportions_one_mm_beside_ten_metres_at_3000_rpm():
    # a 1 mm crank driving a 10 m rod at 3000 rpm, lengths to 0.001 mm
    r, l = 1.0, 10000.001
    mech = slider_crank(r, l, rpm=3000.0, e_mm=0.0)
    w = mech.drive.omega
    phis = [0.0, 37.123, 90.0, 200.5, 333.3]
    sw = mmt_plans.sweep(mech, phis).check()
    for k, phi in enumerate(phis):
        ref = slider_crank_reference(r / 1e3, l / 1e3, w, phi)
        got = (sw.points["B"][k, 0], sw.v["B"][k, 0], sw.a["B"][k, 0], sw.omega[2][k], sw.eps[2][k])
        # x_B ≈ 10 m carries 16 digits of 10 m, that is 16 - log10(10 m / 1 mm) = 12
        # digits of the 1 mm crank, less half a digit of accumulated rounding
        assert digits(got[0] - ref[0], r / 1e3) >= 11.5
        assert digits(got[1] - ref[1], w * r / 1e3) >= 12
        assert digits(got[2] - ref[2], w * w * r / 1e3) >= 11
        assert digits(got[3] - ref[3], w * r / l) >= 11  # ω2 is 1e-4 of ω1 here
        assert digits(got[4] - ref[4], w * w * r / l) >= 10


def test_lengths_at_micrometre_resolution_keep_their_value():
    mech = slider_crank(123.457, 456.789, rpm=100.0, e_mm=12.345)
    sw = mmt_plans.sweep(mech, [10.0]).check()
    A, B = sw.position_of("A")[0], sw.position_of("B")[0]
    assert abs(abs(B - A) - 0.456789) < 1e-15
    assert abs(B.imag - 0.012345) < 1e-17


def test_rocker_rocker_is_refused_with_the_crank_angles_that_work():
    # r = 200, d = 300, l = 150, c = 240: |AC| ≤ l + c = 390 needs
    # cos φ ≥ (200² + 300² - 390²) / (2·200·300) = -0.18416…, i.e. |φ| ≤ 100.6126…°
    mech = mmt_plans.loads(four_bar_toml(200, 300, 150, 240, rpm=30))
    edge = math.degrees(math.acos((200**2 + 300**2 - 390**2) / (2 * 200 * 300)))
    with pytest.raises(mmt_plans.errors.PartialTurnError) as err:
        mmt_plans.solve(mech).positions
    (start, end), = err.value.ranges
    assert start == pytest.approx(360 - edge, abs=1e-8)
    assert end == pytest.approx(edge, abs=1e-8)
    text = str(err.value)
    assert f"{360 - edge:.6g}°…{edge:.6g}°" in text
    assert "group 2-3" in text and "cannot reach" in text and "partial_turn = true" in text


def test_rocker_rocker_opted_in_analyses_the_range_without_fake_extremes():
    mech = mmt_plans.loads(four_bar_toml(200, 300, 150, 240, rpm=30,
                                         extra="").replace("[study]", "[study]\npartial_turn = true"))
    analysis = mmt_plans.solve(mech)
    edge = math.degrees(math.acos((200**2 + 300**2 - 390**2) / (2 * 200 * 300)))
    first, last = analysis.limits  # counter-clockwise crank: from 360 - edge to edge
    assert first == pytest.approx(360 - edge, abs=1e-8) and last == pytest.approx(edge, abs=1e-8)
    phis = [p.phi1_deg for p in analysis.positions]
    ahead = [(phi - first) % 360.0 for phi in phis]
    span = (last - first) % 360.0
    # every position strictly inside the range, none at a limit of assembly
    assert all(0.0 < a < span for a in ahead)
    results = results_json(analysis)
    json.dumps(results, allow_nan=False)  # never inf or NaN
    assert all("problem" not in p for p in results["kinematics"])
    assert results["limits_of_assembly_deg"] == [pytest.approx(first), pytest.approx(last)]
    assert "problem" in results["diagrams"]
    # an extreme position, if any is named, is a zero of the output's velocity, not a limit
    if analysis.extremes is not None:
        for phi in analysis.extremes:
            assert abs((phi - first) % 360.0) > 1e-6 and abs((phi - last) % 360.0) > 1e-6
            sw = mmt_plans.sweep(mech, [phi]).check()
            v = sw.v["B"][0] @ np.asarray(mech.study.working_direction)
            assert abs(v) <= 1e-12 * np.abs(analysis.sweep.v["B"]).max()
