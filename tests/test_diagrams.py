"""Graphical differentiation (seed 003, 1.7) and the 5 % check (1.8).

The reference mechanism is a central slider-crank, r = 0.1 m, l = 0.4 m, e = 0,
n1 = 100 rpm (ω = 2π·100/60 = 10.472 rad/s, one turn T = 0.6 s). Its slider:

    x(φ) = r cos φ + sqrt(l² − (r sin φ + e)²),      φ = ω t.

With u = r sin φ + e, w = sqrt(l² − u²), u' = r cos φ, w' = −u u'/w:

    x'(φ)  = −r sin φ − u r cos φ / w
    x''(φ) = −r cos φ − (r² cos² φ − u r sin φ)/w − u² r² cos² φ / w³
    ẋ = ω x',  ẍ = ω² x''  (ω constant).

Position 0 is φ = 0, where x is largest (x(0) = r + l = 0.5 m); the working
stroke runs towards −x, so s = x(0) − x(φ), V = −ẋ, a = −ẍ, and s_0 = 0.
"""

from __future__ import annotations

import dataclasses
import math

import mpmath
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from mmt_plans.diagrams import (
    DIFFERENTIATION_METHODS,
    GRID_REFINEMENTS,
    ErrorFlag,
    GraphicalDerivative,
    KinematicDiagrams,
    central_difference_derivatives,
    choose_grid,
    chord_derivatives,
    compare_with_plans,
    derived_scale,
    graphical_differentiation,
    judge,
    pole_distance,
    spectral_derivatives,
    textbook_derivatives,
    time_scale,
)

R, L_ROD, E, N1 = 0.1, 0.4, 0.0, 100.0
OMEGA = 2 * math.pi * N1 / 60


def x_of(phi, r=R, l=L_ROD, e=E):
    return r * np.cos(phi) + np.sqrt(l**2 - (r * np.sin(phi) + e) ** 2)


def dx_dphi(phi, r=R, l=L_ROD, e=E):
    u = r * np.sin(phi) + e
    w = np.sqrt(l**2 - u**2)
    return -r * np.sin(phi) - u * r * np.cos(phi) / w


def d2x_dphi2(phi, r=R, l=L_ROD, e=E):
    u = r * np.sin(phi) + e
    w = np.sqrt(l**2 - u**2)
    c, s = np.cos(phi), np.sin(phi)
    return -r * c - (r**2 * c**2 - u * r * s) / w - u**2 * r**2 * c**2 / w**3


def crank_angles(n):
    return 2 * np.pi * np.arange(n) / n


def slider_s(n):
    return x_of(0.0) - x_of(crank_angles(n))


def slider_v(n):
    return -OMEGA * dx_dphi(crank_angles(n))


def slider_a(n):
    return -(OMEGA**2) * d2x_dphi2(crank_angles(n))


def max_rel_error(approx, exact):
    return float(np.max(np.abs(approx - exact)) / np.max(np.abs(exact)))


# --------------------------------------------------------------------------- the closed form itself


@pytest.mark.parametrize("e", [0.0, 0.03])
@pytest.mark.parametrize("phi", [0.3, 1.7, 4.0])
def test_closed_form_derivatives_match_numerical_differentiation(phi, e):
    # The hand derivatives above are the yardstick of everything below: check
    # them once against mpmath's numerical derivative of x(φ).
    mpmath.mp.dps = 30

    def x(p):
        return R * mpmath.cos(p) + mpmath.sqrt(L_ROD**2 - (R * mpmath.sin(p) + e) ** 2)

    assert float(mpmath.diff(x, phi, 1)) == pytest.approx(float(dx_dphi(phi, e=e)), rel=1e-12)
    assert float(mpmath.diff(x, phi, 2)) == pytest.approx(float(d2x_dphi2(phi, e=e)), rel=1e-12)


# --------------------------------------------------------------------------- scales


def test_time_velocity_and_acceleration_scales():
    # μ_t = 60/(n1·L) = 60/(100·240) = 0.0025 s/mm
    assert time_scale(100, 240) == pytest.approx(0.0025, rel=1e-15)
    # μ_V = μ_S/(μ_t·OH1) = 0.002/(0.0025·40) = 0.02 (m/s)/mm
    assert derived_scale(0.002, 0.0025, 40) == pytest.approx(0.02, rel=1e-15)
    # μ_a = μ_V/(μ_t·OH2) = 0.02/(0.0025·50) = 0.16 (m/s²)/mm
    assert derived_scale(0.02, 0.0025, 50) == pytest.approx(0.16, rel=1e-15)

    d = graphical_differentiation(slider_s(12), n1=100, mu_S=0.002, L=240, H1=40, H2=50)
    assert (d.mu_t, d.H1, d.H2) == (pytest.approx(0.0025), 40.0, 50.0)
    assert d.mu_V == pytest.approx(0.02, rel=1e-15)
    assert d.mu_a == pytest.approx(0.16, rel=1e-15)


def test_pole_distance_tie_goes_to_the_longer_pole():
    # μ_S = 0.002, μ_t = 0.0025: μ_V(OH) = 0.8/OH. In 30…50 mm two whole OH give
    # a standard scale exactly: OH = 32 → 0.025 and OH = 40 → 0.02. The longer wins.
    assert pole_distance(0.002, 0.0025) == 40.0
    # Then μ_a(OH) = 0.02/(0.0025·OH) = 8/OH: OH = 32 → 0.25, OH = 40 → 0.2; again 40.
    d = graphical_differentiation(slider_s(12), n1=100, mu_S=0.002, L=240)
    assert (d.H1, d.H2) == (40.0, 40.0)
    assert d.mu_V == pytest.approx(0.02, rel=1e-14)
    assert d.mu_a == pytest.approx(0.2, rel=1e-14)


def test_pole_distance_exact_when_no_whole_millimetre_is():
    # n1 = 111.3, L = 200: μ_t = 60/22260; μ_S = 0.001 → μ_V(OH) = 0.371/OH.
    # No whole OH in 30…50 gives a series value (0.01 needs 37.1, 0.008 needs
    # 46.375, 0.0125 needs 29.68 < 30): the longest exact pole, 46.375 mm → 0.008.
    mu_t = time_scale(111.3, 200)
    H = pole_distance(0.001, mu_t)
    assert H == pytest.approx(0.001 / mu_t / 0.008, rel=1e-12)
    assert derived_scale(0.001, mu_t, H) == pytest.approx(0.008, rel=1e-12)


STANDARD = [m * 10.0**k for k in range(-8, 6) for m in (1, 1.25, 2, 2.5, 4, 5, 8)]


@settings(max_examples=200, deadline=None)
@given(mu_S=st.floats(1e-5, 1e-1), mu_t=st.floats(1e-4, 1e-1))
def test_default_pole_makes_the_scale_standard(mu_S, mu_t):
    # The series never skips more than ×1.6 < 50/30, so some standard μ has its
    # exact OH in [30, 50]: the derived scale is always a series value.
    H = pole_distance(mu_S, mu_t)
    assert 30 - 1e-9 <= H <= 50 + 1e-9
    mu = mu_S / (mu_t * H)
    assert min(abs(math.log(mu / m)) for m in STANDARD) <= 1e-9


# --------------------------------------------------------------------------- the construction


def test_interval_1_2_by_hand():
    # 12 positions, L = 240 mm → Δt_mm = 20 mm; μ_S = 0.002 m/mm, OH1 = 40 mm.
    # x(30°) = 0.0866025 + sqrt(0.16 − 0.0025) = 0.4834652, s1 = 0.0165348 m
    # x(60°) = 0.05 + sqrt(0.16 − 0.0075)      = 0.4405125, s2 = 0.0594875 m
    # Δs_mm = 0.0429528/0.002 = 21.47638 mm;
    # K2 = OH1·Δs_mm/Δt_mm = 40·21.47638/20 = 42.95275 mm
    # μ_V = 0.002/(0.0025·40) = 0.02 → V at the middle of 1–2 = 42.95275·0.02 = 0.859055 m/s,
    # which is the chord's slope Δs/Δt = 0.0429528/0.05.
    s = slider_s(12)
    d = graphical_differentiation(s, n1=N1, mu_S=0.002, L=240, H1=40, H2=40)
    k_height = 40 * ((s[2] - s[1]) / 0.002) / 20
    assert d.velocity.k_points[1, 1] == pytest.approx(k_height, rel=1e-12)
    assert d.velocity.mid_points[1] == pytest.approx([30.0, k_height], rel=1e-12)
    v_mid = d.velocity.mid_points[1, 1] * d.mu_V
    assert v_mid == pytest.approx(k_height * 0.02, rel=1e-12)
    assert v_mid == pytest.approx((s[2] - s[1]) / 0.05, rel=1e-12)
    assert k_height == pytest.approx(42.952753, rel=1e-7)
    assert v_mid == pytest.approx(0.8590551, rel=1e-7)


def test_chords_rays_and_mid_points_are_the_textbook_figure():
    n = 12
    d = graphical_differentiation(slider_s(n), n1=N1, mu_S=0.002, L=240)
    for step in (d.velocity, d.acceleration):
        assert step.pole == pytest.approx([-step.pole_distance, 0.0])
        chord = step.chords[:, 1] - step.chords[:, 0]
        ray = step.rays[:, 1] - step.rays[:, 0]
        # A ray from the pole is parallel to its chord: their cross product is zero.
        assert np.allclose(chord[:, 0] * ray[:, 1] - chord[:, 1] * ray[:, 0], 0.0, atol=1e-9)
        assert np.all(step.rays[:, 0] == step.pole)
        assert np.all(step.k_points[:, 0] == 0.0)  # K lies on the ordinate axis
        # K carried horizontally to the middle of its interval.
        assert step.mid_points[:, 1] == pytest.approx(step.k_points[:, 1])
        middle = (step.chords[:, 0, 0] + step.chords[:, 1, 0]) / 2
        assert step.mid_points[:, 0] == pytest.approx(middle)
        # The smooth curve passes through the mid points and closes over the turn.
        assert step.read(step.mid_points[:, 0]) == pytest.approx(step.mid_points[:, 1], abs=1e-9)
        assert step.curve[0, 1] == pytest.approx(step.curve[-1, 1], abs=1e-9)
        assert step.curve[0, 0] == 0.0 and step.curve[-1, 0] == pytest.approx(240.0)
        assert step.read(d.abscissae) == pytest.approx(step.ordinates, abs=1e-9)
    # The S diagram: s/μ_S at i·L/n, closing at L with s_0.
    assert d.s_points[:, 0] == pytest.approx(np.arange(n + 1) * 20.0)
    assert d.s_points[:-1, 1] == pytest.approx(slider_s(n) / 0.002)
    assert d.s_points[-1, 1] == d.s_points[0, 1]
    # The a diagram differentiates the V diagram where it is read.
    assert d.acceleration.source_points[:-1, 1] == pytest.approx(d.velocity.ordinates)
    assert d.t == pytest.approx(np.arange(n) * 0.05)
    assert d.values_at(d.t)[0] == pytest.approx(d.v, abs=1e-12)
    assert d.values_at(d.t)[1] == pytest.approx(d.a, abs=1e-9)


def test_chord_of_a_sine_by_hand():
    # s = A sin(ωt): the chord over [t_i, t_i+1] has slope
    # A(sin ωt_{i+1} − sin ωt_i)/Δt = A ω cos(ω t_mid) · sin(ωΔt/2)/(ωΔt/2).
    n, A = 12, 0.05
    t = np.arange(n) * (60 / N1 / n)
    d = graphical_differentiation(A * np.sin(OMEGA * t), n1=N1, mu_S=0.001, L=240)
    half = OMEGA * (60 / N1 / n) / 2
    t_mid = t + 60 / N1 / n / 2
    expected = A * OMEGA * np.cos(OMEGA * t_mid) * math.sin(half) / half
    assert d.velocity.mid_points[:, 1] * d.mu_V == pytest.approx(expected, rel=1e-12, abs=1e-15)


def _array_fields(obj):
    for f in dataclasses.fields(obj):
        value = getattr(obj, f.name)
        if isinstance(value, np.ndarray):
            yield f.name, value
        elif isinstance(value, GraphicalDerivative):
            yield from _array_fields(value)


def test_arrays_are_read_only_and_results_frozen():
    d = graphical_differentiation(slider_s(12), n1=N1, mu_S=0.002)
    arrays = dict(_array_fields(d))
    assert {"s", "v", "a", "t", "chords", "rays", "k_points", "mid_points", "curve"} <= set(arrays)
    for name, arr in arrays.items():
        assert not arr.flags.writeable, name
    with pytest.raises(dataclasses.FrozenInstanceError):
        d.mu_V = 1.0  # type: ignore[misc]
    for method in DIFFERENTIATION_METHODS.values():
        v, a = method(slider_s(12), n1=N1)
        assert not v.flags.writeable and not a.flags.writeable


@settings(max_examples=50, deadline=None)
@given(
    L=st.floats(100, 300),
    mu_S=st.floats(1e-4, 1e-2),
    H1=st.floats(30, 50),
    H2=st.floats(30, 50),
    shift=st.floats(-1, 1),
)
def test_values_do_not_depend_on_the_scales(L, mu_S, H1, H2, shift):
    # μ_V = μ_S/(μ_t·OH1) undoes every scale of the drawing, and a constant
    # added to s has no slope: V and a are the same however it is drawn.
    s = slider_s(12)
    ref = graphical_differentiation(s, n1=N1, mu_S=0.002, L=240, H1=40, H2=40)
    d = graphical_differentiation(s + shift, n1=N1, mu_S=mu_S, L=L, H1=H1, H2=H2)
    assert d.v == pytest.approx(ref.v, abs=1e-9 * np.max(np.abs(ref.v)))
    assert d.a == pytest.approx(ref.a, abs=1e-9 * np.max(np.abs(ref.a)))


def test_bad_samples_are_refused():
    with pytest.raises(ValueError):
        graphical_differentiation([0.0, 1.0, np.nan, 0.5], n1=N1, mu_S=0.001)
    with pytest.raises(ValueError):
        graphical_differentiation([0.0, 1.0, 0.5], n1=N1, mu_S=0.001)
    with pytest.raises(ValueError):
        graphical_differentiation(slider_s(12), n1=0.0, mu_S=0.001)
    with pytest.raises(ValueError):
        graphical_differentiation(slider_s(12), n1=N1, mu_S=0.001, H1=0.0)


# --------------------------------------------------------------------------- accuracy


def test_textbook_error_falls_as_dt_squared_and_spectral_is_far_better():
    # The chord's slope is the derivative at the middle of the interval up to
    # Δt²·s'''/24, and the smooth curve adds O(Δt⁴): doubling the positions
    # should divide the error by 4. The slider's harmonics fall like λ^k
    # (λ = r/l = 1/4), so the Fourier derivative of even 12 samples is exact to
    # about λ^12 ≈ 6e-8 of the largest value.
    previous = None
    for n in (12, 24, 48, 96):
        s, v, a = slider_s(n), slider_v(n), slider_a(n)
        tv, ta = textbook_derivatives(s, n1=N1)
        sv, sa = spectral_derivatives(s, n1=N1)
        cv, ca = central_difference_derivatives(s, n1=N1, order=8)
        e_text = (max_rel_error(tv, v), max_rel_error(ta, a))
        assert max_rel_error(sv, v) < 1e-4 * e_text[0]
        assert max_rel_error(sa, a) < 1e-4 * e_text[1]
        assert max_rel_error(cv, v) < 0.1 * e_text[0]
        assert max_rel_error(ca, a) < 0.1 * e_text[1]
        if previous is not None:
            assert 3.5 < previous[0] / e_text[0] < 4.5
            assert 3.5 < previous[1] / e_text[1] < 4.5
        previous = e_text
    # at 12 positions the construction is within a few per cent of the largest value
    assert max_rel_error(textbook_derivatives(slider_s(12), n1=N1)[0], slider_v(12)) < 0.03


def test_eighth_order_differences_converge_at_eighth_order():
    # Error ∝ Δt⁸: doubling the positions divides it by 2⁸ = 256 (asymptotically).
    errors = [max_rel_error(central_difference_derivatives(slider_s(n), n1=N1)[0], slider_v(n))
              for n in (12, 24, 48)]
    assert errors[0] / errors[1] > 100
    assert errors[1] / errors[2] > 100


def test_second_order_difference_of_a_sine_by_hand():
    # (sin ω(t+Δt) − sin ω(t−Δt))/2Δt = ω cos ωt · sin(ωΔt)/(ωΔt)
    # (sin ω(t+Δt) − 2 sin ωt + sin ω(t−Δt))/Δt²
    #     = −ω² sin ωt · (2 − 2cos ωΔt)/(ωΔt)²
    n = 12
    dt = 60 / N1 / n
    t = np.arange(n) * dt
    v, a = central_difference_derivatives(np.sin(OMEGA * t), n1=N1, order=2)
    q = OMEGA * dt
    assert v == pytest.approx(OMEGA * np.cos(OMEGA * t) * math.sin(q) / q, abs=1e-12)
    expected_a = -(OMEGA**2) * np.sin(OMEGA * t) * (2 - 2 * math.cos(q)) / q**2
    assert a == pytest.approx(expected_a, abs=1e-10)


@settings(max_examples=50, deadline=None)
@given(
    n=st.sampled_from([12, 13, 24, 36]),
    coeffs=st.lists(st.tuples(st.floats(-1, 1), st.floats(-1, 1)), min_size=1, max_size=5),
)
def test_spectral_derivative_is_exact_below_the_nyquist_harmonic(n, coeffs):
    # s = Σ a_k cos kφ + b_k sin kφ with k ≤ 5 < n/2, φ = ωt:
    # V = Σ kω(−a_k sin kφ + b_k cos kφ), a = −Σ (kω)²(a_k cos kφ + b_k sin kφ).
    phi = crank_angles(n)
    s = np.zeros(n)
    v = np.zeros(n)
    a = np.zeros(n)
    for k, (ak, bk) in enumerate(coeffs, start=1):
        s += ak * np.cos(k * phi) + bk * np.sin(k * phi)
        v += k * OMEGA * (-ak * np.sin(k * phi) + bk * np.cos(k * phi))
        a -= (k * OMEGA) ** 2 * (ak * np.cos(k * phi) + bk * np.sin(k * phi))
    sv, sa = spectral_derivatives(s, n1=N1)
    assert sv == pytest.approx(v, abs=1e-10)
    assert sa == pytest.approx(a, abs=1e-8)


# --------------------------------------------------------------------------- the 5 % check


def _diagrams(n=12):
    d = graphical_differentiation(slider_s(n), n1=N1, mu_S=0.002)
    return d, slider_v(n).copy(), slider_a(n).copy()


def _flag(flags, quantity, index) -> ErrorFlag | None:
    found = [f for f in flags if f.quantity == quantity and f.index == index]
    return found[0] if found else None


def test_extreme_positions_are_explained_as_sign_changes():
    # e = 0: the slider stops at φ = 0 (position 0) and φ = 180° (position 6);
    # V_plan = 0 there, formula (12) divides by zero.
    d, v, a = _diagrams()
    c = compare_with_plans(d.v, d.a, v, a, n1=N1, s=d.s)
    assert c.v_error_percent[0] is None and c.v_error_percent[6] is None
    for i in (0, 6):
        f = _flag(c.flags, "v", i)
        assert f is not None and f.kind == "sign_change" and f.construction_own
        assert "extreme position" in f.reason
    # a(60°) = −ω² x''(60°) = ω²(0.05 − 0.0128 + 0.0003) = 4.11 m/s² > 0 and
    # a(90°) = −ω² r²/sqrt(l² − r²) = −2.83 m/s² < 0:
    # a changes sign between positions 2 and 3, and |a(90°)| is only about a fifth
    # of |a(0)| = ω²(r + r²/l) = 13.7 m/s², so the construction's few-per-cent-of-
    # the-largest error is magnified there.
    assert a[2] == pytest.approx(4.11, abs=0.01)
    assert a[3] == pytest.approx(-(OMEGA**2) * R**2 / math.sqrt(L_ROD**2 - R**2), rel=1e-12)
    f = _flag(c.flags, "a", 3)
    assert f is not None and f.kind == "sign_change" and f.error_percent is not None
    assert abs(f.error_percent) > 5 and "changes sign" in f.reason
    # Every failure of exact plans is the construction's own.
    assert all(f.construction_own for f in c.flags)


def test_a_deliberately_bad_plan_value_is_blamed_on_the_plan():
    d, v, a = _diagrams()
    v[4] *= 1.2  # Δ_V ≈ 1 − 1/1.2 ≈ 16.7 %: far beyond what chords of 30° can do
    a[1] += 0.2 * np.max(np.abs(a))
    c = compare_with_plans(d.v, d.a, v, a, n1=N1, s=d.s)
    fv = _flag(c.flags, "v", 4)
    assert fv is not None and fv.kind == "plan_mismatch" and not fv.construction_own
    assert fv.error_percent == pytest.approx((v[4] - d.v[4]) / v[4] * 100)
    assert fv.error_percent == pytest.approx(100 / 6, abs=2.0)
    fa = _flag(c.flags, "a", 1)
    assert fa is not None and fa.kind == "plan_mismatch"
    # Without the displacements the fault cannot be placed.
    c0 = compare_with_plans(d.v, d.a, v, a, n1=N1)
    assert _flag(c0.flags, "v", 4).kind == "unexplained"  # type: ignore[union-attr]


def test_error_percent_is_formula_12():
    d, v, a = _diagrams()
    c = compare_with_plans(d.v, d.a, v, a, n1=N1)
    for i in (1, 2, 3, 4, 5):
        assert c.v_error_percent[i] == pytest.approx((v[i] - d.v[i]) / v[i] * 100, rel=1e-12)
        assert c.a_error_percent[i] == pytest.approx((a[i] - d.a[i]) / a[i] * 100, rel=1e-12)
    ok = compare_with_plans(v, a, v, a, n1=N1)
    assert all(f.error_percent is None for f in ok.flags)  # only the zeros of V remain
    assert ok.positions_needed == 12 and ok.positions_needed_how == "current"


def test_positions_needed_for_the_slider_crank():
    # The worst curable error at 12 positions is a at position 3 (> 5 %, see
    # above). It falls as Δt²: 24 positions divide it by 4, under 5 % as long as
    # it was under 20 %, which the Δt² law from n·sqrt(worst/5) also says.
    d, v, a = _diagrams()
    v[4] *= 1.2  # a wrong plan is not cured by more positions and must not count
    c = compare_with_plans(d.v, d.a, v, a, n1=N1, s_of_n=slider_s)
    worst = max(abs(f.error_percent) for f in c.flags if f.construction_own and f.error_percent)
    assert 5 < worst < 20
    assert c.positions_needed == 24 and c.positions_needed_how == "trial"
    assert c.trials[0][0] == 24 and c.trials[0][1] < 5
    assert c.trials[0][1] == pytest.approx(worst / 4, rel=0.1)
    assert _flag(c.flags, "v", 4).kind == "plan_mismatch"  # type: ignore[union-attr]
    estimated = compare_with_plans(d.v, d.a, v, a, n1=N1, s=d.s)
    assert estimated.positions_needed == 24 and estimated.positions_needed_how == "estimate"


def test_fast_change_of_a_sharp_motion():
    # s = exp(k cos φ) − exp(k), k = 1.5: a = ω²(k² sin²φ − k cos φ) e^{k cos φ}
    # has its sharp peak at φ = 0 (a = −1.5 ω² e^1.5, the largest in magnitude),
    # far from any sign change, where 30° chords cannot follow it.
    k = 1.5

    def s_of_n(n):
        return np.exp(k * np.cos(crank_angles(n))) - np.exp(k)

    phi = crank_angles(12)
    v = -OMEGA * k * np.sin(phi) * np.exp(k * np.cos(phi))
    a = OMEGA**2 * (k**2 * np.sin(phi) ** 2 - k * np.cos(phi)) * np.exp(k * np.cos(phi))
    d = graphical_differentiation(s_of_n(12), n1=N1, mu_S=0.01)
    c = compare_with_plans(d.v, d.a, v, a, n1=N1, s_of_n=s_of_n)
    f = _flag(c.flags, "a", 0)
    assert f is not None and f.kind == "fast_change" and f.construction_own
    assert all(f.construction_own for f in c.flags)
    # The answer is the first trial that passes, and every earlier one failed.
    assert c.positions_needed_how == "trial"
    assert c.trials[-1] == (c.positions_needed, pytest.approx(c.trials[-1][1]))
    assert c.trials[-1][1] <= 5 and all(w > 5 for _, w in c.trials[:-1])
    assert c.positions_needed > 12


def test_mismatched_lengths_are_refused():
    d, v, a = _diagrams()
    with pytest.raises(ValueError):
        compare_with_plans(d.v, d.a, v[:-1], a, n1=N1)


def test_result_types():
    d, v, a = _diagrams()
    assert isinstance(d, KinematicDiagrams) and d.n == 12
    c = compare_with_plans(d.v, d.a, v, a, n1=N1)
    assert c.limit_percent == 5.0 and c.positions == 12 and not c.passed


_SAMPLE_FILES = sorted(
    (__import__("pathlib").Path(__file__).resolve().parents[1] / "samples").glob("*.toml")
)


@pytest.mark.parametrize("path", _SAMPLE_FILES, ids=lambda p: p.stem)
def test_the_solution_holds_one_mu_S_and_round_poles(path):
    """One μ_S and one pair of poles for the sheet, the note and the JSON:
    whole millimetres from the short list, μ_S = μ_l or the fewest series steps
    above it that keep every diagram within DIAGRAM_HEIGHT_MM."""
    import mmt_plans
    from mmt_plans.diagrams import DIAGRAM_HEIGHT_MM, ROUND_POLE_DISTANCES_MM
    from mmt_plans.results_json import diagrams_json
    from mmt_plans.scales import is_standard

    sol = mmt_plans.solve(mmt_plans.load(path), forces=False)
    dg = sol.diagrams
    c, sc = dg.construction, dg.scales
    assert (c.mu_S, c.H1, c.H2) == (sc.mu_S, sc.H1, sc.H2)
    assert sc.H1 in ROUND_POLE_DISTANCES_MM and sc.H2 in ROUND_POLE_DISTANCES_MM
    assert max(c.heights_mm) <= DIAGRAM_HEIGHT_MM + 1e-6
    # μ_V, μ_a by the textbook's formulas from what the construction holds
    assert c.mu_V == pytest.approx(c.mu_S / (c.mu_t * c.H1), rel=1e-12)
    assert c.mu_a == pytest.approx(c.mu_V / (c.mu_t * c.H2), rel=1e-12)
    assert is_standard(c.mu_V) and is_standard(c.mu_a)
    # μ_S is μ_l's series: (1, 2, 2.5, 4, 5)·10^k from μ_l, mu_S_steps steps up
    ratio = sc.mu_S / sol.mu_l
    assert (sc.mu_S_steps == 0) == math.isclose(ratio, 1.0, rel_tol=1e-9)
    if sc.mu_S_steps:  # one step lower, the S diagram would be too tall or the poles not found
        assert ratio > 1.0
    js = diagrams_json(sol)["scales"]
    assert (js["mu_S"], js["H1_mm"], js["H2_mm"]) == (sc.mu_S, sc.H1, sc.H2)
    assert js["mu_S_steps"] == sc.mu_S_steps


# --- the 5 % check on the grids of one series (seed 003 §1.8) ---------------------------


def test_chord_derivatives_are_the_drawn_constructions_values():
    """The check's trials read V and a without drawing; the drawn construction
    at any scales gives the same values (the scales cancel)."""
    s = np.random.default_rng(1).normal(size=24)
    drawn = graphical_differentiation(s, n1=37.0, mu_S=0.004, L=200.0, H1=35.0, H2=45.0)
    v, a = chord_derivatives(s, n1=37.0)
    assert np.allclose(v, drawn.v, rtol=0, atol=1e-13 * np.abs(v).max())
    assert np.allclose(a, drawn.a, rtol=0, atol=1e-13 * np.abs(a).max())


def _two_harmonics(delta_deg: float, b: float = -0.3):
    """s = cos θ + b·cos 2θ at θ = 2πj/m − δ, n1 = 60 rpm (ω = 2π rad/s): V and a
    at the 12 positions in closed form, and their largest magnitudes."""
    w, delta = 2.0 * np.pi, np.radians(delta_deg)

    def s_of_n(m):
        th = 2.0 * np.pi * np.arange(m) / m - delta
        return np.cos(th) + b * np.cos(2.0 * th)

    th = 2.0 * np.pi * np.arange(12) / 12 - delta
    v = -w * (np.sin(th) + 2.0 * b * np.sin(2.0 * th))
    a = -w * w * (np.cos(th) + 4.0 * b * np.cos(2.0 * th))
    fine = np.linspace(0.0, 2.0 * np.pi, 200_001)
    largest = (
        float(np.abs(w * (np.sin(fine) + 2 * b * np.sin(2 * fine))).max()),
        float(np.abs(w * w * (np.cos(fine) + 4 * b * np.cos(2 * fine))).max()),
    )
    return s_of_n, v, a, largest


def _independent_error(s_of_n, m, i, q, plan):
    d = graphical_differentiation(s_of_n(m), n1=60.0, mu_S=0.01, L=240.0, H1=40.0, H2=40.0)
    k = m // 12
    return (plan - (d.v if q == "v" else d.a)[i * k]) / plan * 100.0


def test_a_small_value_a_finer_grid_passes_is_not_exempted():
    """V at position 0 is 0.5 % of its largest magnitude (ill-conditioned), yet
    the grid of 36 passes it by (12) as written: no exemption, 36 is drawn,
    12 and 24 were tried and fail."""
    s_of_n, v, a, largest = _two_harmonics(2.0)
    assert abs(v[0]) < 0.05 * largest[0]
    choice = choose_grid(
        s_of_n, n=12, n1=60.0, investigated=(0, 3), v_plan=v, a_plan=a, largest=largest
    )
    assert choice.exempt == frozenset()
    assert [t.intervals for t in choice.trials] == [12, 24, 36]
    assert choice.refinement == 3
    for t in choice.trials:
        errs = [_independent_error(s_of_n, t.intervals, i, q, (v if q == "v" else a)[i])
                for i in (0, 3) for q in "va"]
        assert t.passed == all(abs(e) <= 5.0 for e in errs)
        assert [e for _, _, e in t.errors] == pytest.approx(errs, rel=1e-9)
    assert not choice.trials[0].passed and not choice.trials[1].passed
    assert choice.trials[2].passed


def test_a_zero_plan_value_is_judged_by_its_absolute_error_on_the_first_grid_passing_the_rest():
    """At an extreme position V_plan = 0: (12) is undefined on every grid, so V
    there is the one value judged by its absolute error; the grid is the first
    on which every other value passes by (12)/(13)."""
    s_of_n, v, a, largest = _two_harmonics(0.0)
    v = v.copy()
    v[0] = 0.0
    choice = choose_grid(
        s_of_n, n=12, n1=60.0, investigated=(0, 3), v_plan=v, a_plan=a, largest=largest
    )
    assert choice.exempt == {(0, "v")}
    assert [t.intervals for t in choice.trials] == [12 * k for k in GRID_REFINEMENTS]
    chosen = next(t for t in choice.trials if t.refinement == choice.refinement)
    assert [(i, q) for i, q, _ in chosen.failing] == [(0, "v")]
    for t in choice.trials:
        if t.refinement < choice.refinement:
            assert any((i, q) != (0, "v") for i, q, _ in t.failing)
    val = judge(0, "v", 0.0, 1e-3, largest[0], exempt=True)
    assert val.ill_conditioned and val.passed and val.judged_by == "absolute_error"
    assert val.absolute_error == pytest.approx(1e-3)
    # without the exemption (12)/(13) fails it, whatever the share
    assert not judge(0, "v", 0.01, 0.02, largest[0]).passed


# --- the short cuts a solve takes (#25 speed): numpy's own numbers, bit for bit ---------------


@pytest.mark.parametrize("n", [4, 5, 12, 36, 37, 288])
def test_fft_short_cuts_are_numpys_own(n: int) -> None:
    """_rfft / _irfft call the transforms np.fft.rfft / irfft call, with their
    factors: the same bits (strided input too, as the spline's middles are)."""
    from mmt_plans.diagrams import _irfft, _rfft

    rng = np.random.default_rng(n)
    y = rng.normal(size=(n, 2))[:, 1]  # a strided column
    c = np.fft.rfft(y)
    assert np.array_equal(_rfft(y), c)
    assert np.array_equal(_irfft(c * 1.7j, n), np.fft.irfft(c * 1.7j, n))
    assert np.array_equal(_irfft(c, n), np.fft.irfft(c, n))


def test_array_short_cuts_are_numpys_own() -> None:
    from mmt_plans.diagrams import _closed, _columns, _diff

    rng = np.random.default_rng(7)
    y = rng.normal(size=(13, 2))[:, 0]
    x = np.arange(13) * 0.37
    assert np.array_equal(_diff(y), np.diff(y))
    assert np.array_equal(_closed(y), np.append(y, y[0]))
    assert np.array_equal(_columns(x, y), np.column_stack([x, y]))
