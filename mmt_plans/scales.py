"""The standard series of drawing scales (scaling factors) μ.

A scale μ is a physical quantity per millimetre of drawing: μ_l = l_OA / OA in
m/mm (seed 000, eq. 1.8; seed 003, eq. 2), μV = V_A / pa in (m/s)/mm (seed
003, eq. 5), μa = a_A / πa in (m/s²)/mm (eq. 9), μF = F_PR / |F_PR| in N/mm
(eq. 20). A raw scale is rounded to the standard series; seed 000, §2.2
"Construction of Mechanism Diagrams and Selection of Scales":

    "It should be noted that the scales are formed by the following numbers:
    1, 2, 4, 5, 8 or their combinations 25 and 125 multiplied by 10^±k,
    where k = 1, 2, 3 ... etc."

("Треба відмітити, що масштаби утворюються із таких цифр: 1, 2, 4, 5, 8 або
їх сполучень 25 і 125 помножених на 10^±k".) Within one decade the series is
therefore 1, 1.25, 2, 2.5, 4, 5, 8 (25 = 2.5·10, 125 = 1.25·100).

The ranges of the drawn segments come from seed 003: pa not less than
100 ... 150 mm (§1.3), πa ≈ 100 ... 200 mm (§1.5), |F_PR| = 150 ... 300 mm
(§2.6).
"""

from __future__ import annotations

import math
from collections.abc import Iterator
from dataclasses import dataclass
from decimal import Decimal
from functools import lru_cache
from typing import Literal, get_args

from .i18n import Language, catalogue, check_language

__all__ = [
    "MANTISSAS",
    "DrawnLength",
    "VELOCITY_PLAN",
    "ACCELERATION_PLAN",
    "FORCE_PLAN",
    "TARGETS",
    "Quantity",
    "QUANTITIES",
    "ScaleLabel",
    "series",
    "is_standard",
    "standard_scale",
    "scale_for",
    "scale_label",
    "format_scale",
    "format_number",
]

# One decade of the series, as exact decimal strings so that a series value
# becomes the float nearest to the decimal (0.0125, not 0.012500000000000001).
_MANTISSA_TEXT = ("1", "1.25", "2", "2.5", "4", "5", "8")
MANTISSAS: tuple[float, ...] = tuple(float(m) for m in _MANTISSA_TEXT)
# The scales of a drawing of the mechanism itself (μ_l): seed 003's 1, 2, 2.5,
# 4, 5 × 10^k, which are the ratios of GOST 2.302 (1:2, 1:2.5, 1:4, 1:5, 1:10,
# 1:20, 1:25, 1:40, 1:50 ... and 2:1, 2.5:1, 4:1, 5:1, 10:1 ...).
LENGTH_MANTISSA_TEXT = ("1", "2", "2.5", "4", "5")
LENGTH_MANTISSAS: tuple[float, ...] = tuple(float(m) for m in LENGTH_MANTISSA_TEXT)

# Relative tolerance for deciding that a float is a series value.
_REL_TOL = 1e-9


@dataclass(frozen=True)
class DrawnLength:
    """The range, in mm, that the segment representing a quantity should have.

    `nominal` is the length a raw scale is usually computed for (μ = value /
    nominal); it lies inside [low, high].
    """

    name: str
    low: float
    high: float
    nominal: float

    def __post_init__(self) -> None:
        if not (0 < self.low <= self.nominal <= self.high):
            raise ValueError(f"{self.name}: need 0 < low <= nominal <= high")

    def contains(self, length_mm: float) -> bool:
        return self.low * (1 - _REL_TOL) <= length_mm <= self.high * (1 + _REL_TOL)


VELOCITY_PLAN = DrawnLength("pa", 100.0, 150.0, 120.0)
ACCELERATION_PLAN = DrawnLength("πa", 100.0, 200.0, 150.0)
FORCE_PLAN = DrawnLength("|F_PR|", 150.0, 300.0, 200.0)

TARGETS: dict[str, DrawnLength] = {
    "velocity": VELOCITY_PLAN,
    "acceleration": ACCELERATION_PLAN,
    "force": FORCE_PLAN,
}


def _decade(value: float) -> int:
    """Exponent k with value = m·10^k and 1 <= m < 10, robust to float noise."""
    k = math.floor(math.log10(value))
    # log10 of 1000 may come out as 2.9999999999999996; correct by one.
    if value / 10.0**k >= 10.0 * (1 - _REL_TOL):
        k += 1
    elif value / 10.0**k < 1.0 * (1 - _REL_TOL):
        k -= 1
    return k


@lru_cache(maxsize=512)
def _value(text: str, k: int) -> float:
    # a mantissa of the series times a power of ten: a few dozen pairs in all,
    # each worked out once (decimal arithmetic is slow, and read at every solve)
    return float(Decimal(text).scaleb(k))


def series(low: float, high: float, mantissas: tuple[str, ...] = _MANTISSA_TEXT) -> Iterator[float]:
    """Every series value μ with low <= μ <= high, ascending (`mantissas`:
    the decade's values as decimal text; LENGTH_MANTISSA_TEXT for μ_l)."""
    if not (0 < low <= high) or not math.isfinite(high):
        raise ValueError(f"series needs 0 < low <= high < inf, got {low!r}, {high!r}")
    k = _decade(low)
    while True:
        for text in mantissas:
            mu = _value(text, k)
            if mu > high * (1 + _REL_TOL):
                return
            if mu >= low * (1 - _REL_TOL):
                yield mu
        k += 1


def is_standard(mu: float) -> bool:
    """True if `mu` is m·10^k with m in 1, 1.25, 2, 2.5, 4, 5, 8 and k an integer."""
    if not (isinstance(mu, (int, float)) and math.isfinite(mu) and mu > 0):
        return False
    m = mu / 10.0 ** _decade(mu)
    return any(math.isclose(m, s, rel_tol=_REL_TOL) for s in MANTISSAS)


def _next_up(raw: float, mantissas: tuple[str, ...] = _MANTISSA_TEXT) -> float:
    """The smallest series value >= raw."""
    return next(series(raw, raw * 10.0, mantissas))


def _next_down(raw: float, mantissas: tuple[str, ...] = _MANTISSA_TEXT) -> float:
    """The largest series value <= raw."""
    return list(series(raw / 10.0, raw, mantissas))[-1]


def standard_scale(
    raw: float,
    target: DrawnLength | None = None,
    *,
    nominal_mm: float | None = None,
    mantissas: tuple[str, ...] = _MANTISSA_TEXT,
) -> float:
    """Round a raw scale (quantity per mm, e.g. V_A / 120 mm) to the series.

    Without `target`: the next series value up, so that the drawn segment gets
    no longer than the length the raw scale was computed for (it shrinks by at
    most 1.6 times, the widest step of the series, 1.25 → 2).

    With `target`: the raw scale is taken as magnitude / `nominal_mm`
    (default `target.nominal`) and the result is the series value nearest to
    `raw` whose drawn length magnitude / μ lies in [target.low, target.high],
    rounding up on a tie. The series steps by up to 1.6 times, so a range
    narrower than that (pa 100 ... 150 mm) can miss every value: then the
    scale giving the shortest drawing longer than the range is chosen, since
    seed 003 states these lengths as lower bounds ("not less than").
    """
    if not (isinstance(raw, (int, float)) and math.isfinite(raw) and raw > 0):
        raise ValueError(f"a scale must be a finite positive number, got {raw!r}")
    if target is None:
        return _next_up(raw, mantissas)
    nominal = target.nominal if nominal_mm is None else nominal_mm
    if not (math.isfinite(nominal) and nominal > 0):
        raise ValueError(f"nominal_mm must be a finite positive length, got {nominal!r}")
    magnitude = raw * nominal
    # Every series value whose drawn length can be in range, with one value
    # beyond each end so that the fallback has neighbours to choose from.
    lo_mu = _next_down(magnitude / target.high, mantissas)
    hi_mu = _next_up(magnitude / target.low, mantissas)
    candidates = list(series(lo_mu, hi_mu, mantissas))

    fitting = [mu for mu in candidates if target.contains(magnitude / mu)]
    if fitting:
        # Nearest to the raw scale; on a tie the larger (rounded-up) value.
        return min(fitting, key=lambda mu: (abs(math.log(mu / raw)), -mu))
    # Largest μ whose drawing is still longer than the range. lo_mu draws at
    # least target.high long, so the list is never empty.
    return max(mu for mu in candidates if magnitude / mu > target.high)


def scale_for(
    magnitude: float, target: DrawnLength, mantissas: tuple[str, ...] = _MANTISSA_TEXT
) -> float:
    """The series scale that draws `magnitude` with a length in `target`.

    magnitude is the quantity drawn by the reference segment: V_A for pa,
    a_A for πa, F_PR for |F_PR|.
    """
    if not (isinstance(magnitude, (int, float)) and math.isfinite(magnitude) and magnitude > 0):
        raise ValueError(f"the drawn quantity must be finite and positive, got {magnitude!r}")
    return standard_scale(magnitude / target.nominal, target, mantissas=mantissas)


# --- labels -----------------------------------------------------------------

Quantity = Literal[
    "length", "displacement", "velocity", "acceleration", "force", "time", "moment", "angle"
]


@dataclass(frozen=True)
class _QuantityIndex:
    index: str


# the index of each scale's μ; its unit comes from the language's catalogue
QUANTITIES: dict[str, _QuantityIndex] = {
    "length": _QuantityIndex("l"),
    "displacement": _QuantityIndex("S"),
    "velocity": _QuantityIndex("V"),
    "acceleration": _QuantityIndex("a"),
    "force": _QuantityIndex("F"),
    "time": _QuantityIndex("t"),
    "moment": _QuantityIndex("M"),
    "angle": _QuantityIndex("φ"),
}
assert set(QUANTITIES) == set(get_args(Quantity))


def format_number(value: float, *, decimal_comma: bool = False) -> str:
    """Plain positional decimal, no exponent, no trailing zeros: 0.0125, 50, 2000
    (the catalogue's plain_number; a decimal comma as the Ukrainian one writes it)."""
    return catalogue("uk" if decimal_comma else "en").plain_number(value)


@dataclass(frozen=True)
class ScaleLabel:
    """A scale caption in parts, so a renderer can set the index as a subscript."""

    symbol: str  # "μ"
    index: str  # "V", "l", "F"
    value: str  # "0.01"
    unit: str  # "(m/s)/mm"

    def markup(self) -> str:
        """For Backend.rich_text: "μ_{V} = 0.01 (m/s)/mm" sets V as a subscript."""
        return f"{self.symbol}_{{{self.index}}} = {self.value} {self.unit}"

    def __str__(self) -> str:
        # A lowercase index written on the line reads badly ("μl" looks like
        # "μ1"), so the plain-text form marks it as a subscript with "_".
        index = f"_{self.index}" if self.index[:1].islower() else self.index
        return f"{self.symbol}{index} = {self.value} {self.unit}"


def scale_label(
    mu: float,
    quantity: Quantity,
    lang: Language = "en",
    *,
    decimal_comma: bool | None = None,
) -> ScaleLabel:
    """The parts of a label like "μV = 0.01 (m/s)/mm".

    Ukrainian labels use a decimal comma unless `decimal_comma` says otherwise.
    """
    try:
        units = QUANTITIES[quantity]
    except KeyError:
        raise ValueError(
            f"unknown quantity {quantity!r}; expected one of {', '.join(QUANTITIES)}"
        ) from None
    words = catalogue(check_language(lang))
    comma = (words.decimal == ",") if decimal_comma is None else decimal_comma
    unit = str(words.words("scale_units")[quantity])
    return ScaleLabel("μ", units.index, format_number(mu, decimal_comma=comma), unit)


def format_scale(
    mu: float,
    quantity: Quantity,
    lang: Language = "en",
    *,
    decimal_comma: bool | None = None,
) -> str:
    """ "μV = 0.01 (m/s)/mm", "μ_l = 0.005 m/mm", "μF = 50 N/mm"; "μV = 0,01 (м/с)/мм"."""
    return str(scale_label(mu, quantity, lang, decimal_comma=decimal_comma))
