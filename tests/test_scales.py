import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from mmt_plans.scales import (
    ACCELERATION_PLAN,
    FORCE_PLAN,
    MANTISSAS,
    TARGETS,
    VELOCITY_PLAN,
    format_number,
    format_scale,
    is_standard,
    scale_for,
    scale_label,
    series,
    standard_scale,
)

raw_scales = st.floats(min_value=1e-7, max_value=1e7, allow_nan=False, allow_infinity=False)
magnitudes = st.floats(min_value=1e-4, max_value=1e7, allow_nan=False, allow_infinity=False)


def test_one_decade_is_the_textbook_series():
    # seed 000 §2.2: 1, 2, 4, 5, 8 and the combinations 25 and 125, times 10^±k.
    assert list(series(0.01, 0.1)) == [0.01, 0.0125, 0.02, 0.025, 0.04, 0.05, 0.08, 0.1]
    assert list(series(10, 200)) == [10, 12.5, 20, 25, 40, 50, 80, 100, 125, 200]
    assert MANTISSAS == (1, 1.25, 2, 2.5, 4, 5, 8)


@pytest.mark.parametrize("mu", [1, 2, 4, 5, 8, 25, 125, 0.0125, 0.025, 0.005, 1e-6, 8e5, 2000])
def test_series_values_are_standard(mu):
    assert is_standard(mu)


@pytest.mark.parametrize("mu", [3, 0.3, 6, 7.5, 1.5, 0.015, 0, -0.01, math.nan, math.inf, 1.26])
def test_other_values_are_not(mu):
    assert not is_standard(mu)


@given(raw_scales)
def test_rounding_up_gives_a_series_value_at_most_one_step_up(raw):
    mu = standard_scale(raw)
    assert is_standard(mu)
    # The widest step of the series is 1.25 -> 2 (x1.6).
    assert raw * (1 - 1e-9) <= mu <= raw * 1.6 * (1 + 1e-9)


@given(magnitudes, st.sampled_from(["acceleration", "force"]))
def test_wide_ranges_always_get_a_drawing_inside_them(magnitude, kind):
    # πa 100...200 mm and |F_PR| 150...300 mm are wider than any series step.
    target = TARGETS[kind]
    mu = scale_for(magnitude, target)
    assert is_standard(mu)
    assert target.contains(magnitude / mu)


@settings(max_examples=300)
@given(magnitudes)
def test_velocity_plan_in_range_or_just_longer_when_no_value_fits(magnitude):
    mu = scale_for(magnitude, VELOCITY_PLAN)
    assert is_standard(mu)
    length = magnitude / mu
    if not VELOCITY_PLAN.contains(length):
        assert length > VELOCITY_PLAN.high
        # ...and really no series value draws pa within 100...150 mm.
        lo, hi = magnitude / VELOCITY_PLAN.high, magnitude / VELOCITY_PLAN.low
        assert list(series(lo * (1 + 1e-9), hi * (1 - 1e-9))) == []


def test_crank_velocity_example():
    # n1 = 90 rpm, l_OA = 0.2 m: omega1 = pi*90/30 = 9.4248 1/s, V_A = 1.885 m/s.
    v_a = math.pi * 90 / 30 * 0.2
    # V_A / 120 mm = 0.0157 rounds up to 0.02: pa = 94 mm, under 100 mm.
    assert standard_scale(v_a / 120) == 0.02
    # 0.0125 gives pa = 150.8 mm, 0.02 gives 94.2 mm: neither is in 100...150,
    # the textbook's "not less than" picks the longer one.
    assert scale_for(v_a, VELOCITY_PLAN) == 0.0125


def test_force_plan_example():
    # F_PR = 9 kN (task 1, variant 1): 9000 / 200 mm = 45 -> 50 N/mm, |F_PR| = 180 mm.
    assert scale_for(9000.0, FORCE_PLAN) == 50
    assert standard_scale(9000.0 / 200, FORCE_PLAN) == 50


def test_acceleration_plan_prefers_nearest_in_range():
    # a_A = 17.77 m/s^2: raw 17.77/150 = 0.1185; 0.125 draws 142 mm.
    assert scale_for(17.77, ACCELERATION_PLAN) == 0.125


@pytest.mark.parametrize("bad", [0.0, -1.0, math.nan, math.inf])
def test_bad_raw_scales_are_refused(bad):
    with pytest.raises(ValueError):
        standard_scale(bad)
    with pytest.raises(ValueError):
        scale_for(bad, FORCE_PLAN)


def test_labels():
    assert format_scale(0.01, "velocity") == "μV = 0.01 (m/s)/mm"
    assert format_scale(0.005, "length") == "μ_l = 0.005 m/mm"
    assert format_scale(50, "force") == "μF = 50 N/mm"
    assert format_scale(0.0125, "acceleration") == "μ_a = 0.0125 (m/s²)/mm"
    assert format_scale(0.01, "velocity", "uk") == "μV = 0,01 (м/с)/мм"
    assert format_scale(0.005, "length", "uk") == "μ_l = 0,005 м/мм"
    assert format_scale(50, "force", "uk") == "μF = 50 Н/мм"
    assert format_scale(0.01, "velocity", "uk", decimal_comma=False) == "μV = 0.01 (м/с)/мм"


def test_label_markup_for_rich_text():
    assert scale_label(0.01, "velocity").markup() == "μ_{V} = 0.01 (m/s)/mm"


def test_unknown_quantity_or_language():
    with pytest.raises(ValueError):
        format_scale(0.01, "speed")  # type: ignore[arg-type]
    with pytest.raises(ValueError):
        format_scale(0.01, "velocity", "de")  # type: ignore[arg-type]


@pytest.mark.parametrize(
    "value, text",
    [(0.005, "0.005"), (50, "50"), (2000, "2000"), (1.25e-5, "0.0000125"), (12.5, "12.5"), (0.1, "0.1")],
)
def test_numbers_are_plain_decimals(value, text):
    assert format_number(value) == text


@given(raw_scales)
def test_labels_of_series_values_round_trip(raw):
    mu = standard_scale(raw)
    value = scale_label(mu, "force").value
    assert float(value) == mu
    assert "e" not in value.lower()
