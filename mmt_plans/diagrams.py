"""S–V–a diagrams of the output point by graphical differentiation (seed 003, 1.7–1.8).

The module knows nothing of mechanisms: it receives the output's displacement
``s`` (m, signed along the working direction, ``s[0] = 0`` at position 0) at
``n`` equal crank steps over one turn, and builds the textbook's construction
as data a sheet can draw:

1. the S diagram: points ``(i·L/n, s_i/μ_S)`` mm, joined by chords;
2. from the pole H1, ``OH1`` mm left of the origin of the V diagram, a ray
   parallel to each chord meets the ordinate axis at ``K_i``, at the height
   ``OH1·Δs_mm/Δt_mm``; carried horizontally to the middle of the interval it
   gives the points ``1'', 2'', …``;
3. a smooth curve through those points (a periodic cubic spline) is the V
   diagram; read at each position it gives V there;
4. the same again from the V diagram, with the pole H2, gives the a diagram.

Scales: μ_t = 60/(n1·L), μ_V = μ_S/(μ_t·OH1), μ_a = μ_V/(μ_t·OH2).

Pole distances when not given: the scale ``μ_source/(μ_t·OH)`` is a value of
the standard series (1, 1.25, 2, 2.5, 4, 5, 8)·10^k (seed 000: 1, 2, 4, 5, 8,
25, 125 times a power of ten), as every scale on the sheet is. OH is a whole
number of millimetres in 30…50 when one lands exactly on the series; of equal
ones the longest pole wins, since a longer pole draws a taller diagram that
is read more accurately. Otherwise OH is the longest exact length in 30…50
that makes the scale a series value (the series never skips more than a
factor 1.6 < 50/30, so there is always one); it is drawn to that length and
labelled to 0.01 mm.

Values in SI do not depend on L, μ_S, OH1 or OH2: the scales cancel, and V at
the middle of an interval is exactly the chord's slope Δs/Δt.

`compare_with_plans` is the 5 % check of 1.8, formulas (12) and (13), with
the reason for every position that fails it. `spectral_derivatives` and
`central_difference_derivatives` differentiate the same samples far more
accurately, for a benchmark of time against error.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from functools import lru_cache
from types import MappingProxyType
from typing import TYPE_CHECKING, Literal, cast

import numpy as np

if TYPE_CHECKING:  # numpy.typing costs ~10 ms to import: only the type checker reads it
    from numpy.typing import ArrayLike

from mmt_plans.scales import LENGTH_MANTISSA_TEXT, MANTISSAS, DrawnLength, is_standard, series

__all__ = [
    "DEFAULT_TIME_AXIS_MM",
    "POLE_DISTANCE_RANGE_MM",
    "POSITION_CANDIDATES",
    "DIFFERENTIATION_METHODS",
    "GraphicalDerivative",
    "KinematicDiagrams",
    "ErrorFlag",
    "PlanComparison",
    "time_scale",
    "derived_scale",
    "pole_distance",
    "ROUND_POLE_DISTANCES_MM",
    "DiagramScales",
    "diagram_scales",
    "graphical_differentiation",
    "compare_with_plans",
    "spectral_derivatives",
    "central_difference_derivatives",
    "textbook_derivatives",
    "chord_derivatives",
    "GRID_REFINEMENTS",
    "ILL_CONDITIONED",
    "InvestigatedValue",
    "GridTrial",
    "GridChoice",
    "SheetCheck",
    "choose_grid",
    "judge",
]

Array = np.ndarray  # NDArray[np.float64] to the type checker (annotations are strings)

DEFAULT_TIME_AXIS_MM = 240.0
# one turn of the crank on the time axis of a sheet: μ_t from the standard
# series makes it 150 … 240 mm (240 mm when T/240 is itself a series value)
# the tallest an S, V or a diagram is drawn on sheet 1 (the three stand in one
# column under the mechanism): the Solution chooses μ_S and the poles for it
DIAGRAM_HEIGHT_MM = 70.0
TIME_AXIS = DrawnLength("L", 150.0, DEFAULT_TIME_AXIS_MM, DEFAULT_TIME_AXIS_MM)
POLE_DISTANCE_RANGE_MM = (30, 50)
POSITION_CANDIDATES = (12, 24, 36, 48, 72, 120, 360)
ERROR_LIMIT_PERCENT = 5.0

# A plan value this small next to the largest one is a zero of the curve (an
# extreme position for V): formula (12)/(13) has nothing to divide by.
_ZERO_PLAN = 1e-6
# Below this share of the largest plan value, a relative error is a large
# number made from a small absolute one: the curve is crossing zero.
_SMALL_PLAN = 0.25


def _frozen(values: ArrayLike) -> Array:
    arr = np.array(values, dtype=np.float64)
    arr.setflags(write=False)
    return arr


def _diff(y: Array) -> Array:
    """np.diff of a 1-d array: the same subtraction, y[1:] - y[:-1], without
    its wrapper (a solve differentiates a dozen short arrays)."""
    return np.subtract(y[1:], y[:-1])


def _closed(y: Array) -> Array:
    """y with its first value again at the end (np.append(y, y[0]): one turn
    closed), by one concatenation."""
    return np.concatenate((y, y[:1]))


def _columns(x: Array, y: Array) -> Array:
    """np.column_stack([x, y]) of two 1-d float arrays, filled in place."""
    out = np.empty((x.size, 2))
    out[:, 0], out[:, 1] = x, y
    return out


try:  # the FFTs np.fft.rfft and np.fft.irfft run, called without their wrappers
    from numpy.fft import _pocketfft_umath as _pfu  # type: ignore[attr-defined]

    _RFFT_EVEN, _RFFT_ODD, _IRFFT = _pfu.rfft_n_even, _pfu.rfft_n_odd, _pfu.irfft
except (ImportError, AttributeError):  # pragma: no cover - another numpy: its own functions
    _pfu = None


def _rfft(y: Array) -> Array:
    """np.fft.rfft(y) of a 1-d float array: numpy's own transform (the same
    ufunc, factor 1 and output), called as `np.fft.rfft` calls it."""
    if _pfu is None:  # pragma: no cover
        return np.fft.rfft(y)
    n = y.size
    out = np.empty(n // 2 + 1, dtype=np.complex128)
    return (_RFFT_EVEN if n % 2 == 0 else _RFFT_ODD)(y, 1, axes=_FFT_AXES, out=out)  # type: ignore[no-any-return]


def _irfft(c: Array, n: int) -> Array:
    """np.fft.irfft(c, n) of a 1-d complex array (factor 1/n, as it scales)."""
    if _pfu is None:  # pragma: no cover
        return np.fft.irfft(c, n)
    return _IRFFT(c, _inverse(n), axes=_FFT_AXES, out=np.empty(n))  # type: ignore[no-any-return]


_FFT_AXES = [(0,), (), (0,)]


@lru_cache(maxsize=64)
def _inverse(n: int) -> np.float64:
    """np.fft's factor of an inverse transform of n points: 1/n as it computes it."""
    return np.reciprocal(n, dtype=np.float64)  # type: ignore[no-any-return]


# --------------------------------------------------------------------------- scales


def time_scale(n1: float, L: float) -> float:
    """μ_t = 60/(n1·L), s/mm: one turn of the crank over L mm (seed 003, 1.7)."""
    if not (n1 > 0 and L > 0):
        raise ValueError(f"n1 and L must be positive, got n1={n1!r}, L={L!r}")
    return 60.0 / (n1 * L)


def derived_scale(mu_source: float, mu_t: float, H: float) -> float:
    """μ_V = μ_S/(μ_t·OH1) or μ_a = μ_V/(μ_t·OH2) (seed 003, 1.7)."""
    return mu_source / (mu_t * H)


def _distance_to_standard(mu: float) -> float:
    """|ln(μ/μ_std)| to the nearest value of the standard series."""
    exponent = math.floor(math.log10(mu))
    best = math.inf
    for k in (exponent - 1, exponent, exponent + 1):
        for m in MANTISSAS:
            best = min(best, abs(math.log(mu / (m * 10.0**k))))
    return best


def pole_distance(mu_source: float, mu_t: float) -> float:
    """OH (mm) in 30…50 making μ_source/(μ_t·OH) a standard scale exactly:
    whole millimetres where one does (the longest), else the longest exact
    length that does. See the module docstring."""
    lo, hi = POLE_DISTANCE_RANGE_MM
    for H in range(hi, lo - 1, -1):  # longest first, so a tie keeps the longer pole
        if _distance_to_standard(derived_scale(mu_source, mu_t, H)) <= 1e-9:
            return float(H)
    # the series values reachable with a pole in [lo, hi], longest pole first
    ratio = mu_source / mu_t
    reachable = sorted(series(ratio / hi, ratio / lo))
    return ratio / reachable[0]


# The pole distances a sheet draws: whole millimetres a draughtsman sets off
# with a rule, the textbook's 30 … 50 mm first (seed 003 §1.7), longest first.
ROUND_POLE_DISTANCES_MM: tuple[float, ...] = (50.0, 40.0, 30.0, 60.0, 25.0, 80.0, 20.0, 100.0)


@dataclass(frozen=True)
class DiagramScales:
    """What a sheet chose for its S, V, a diagrams: μ_S and the poles OH1, OH2."""

    mu_S: float  # m/mm
    H1: float  # mm, one of ROUND_POLE_DISTANCES_MM
    H2: float  # mm
    mu_S_steps: int  # series steps above μ_l (0: μ_S = μ_l, as seed 003 §1.7 draws it)
    standard: bool  # μ_V and μ_a are values of the standard series


def diagram_scales(
    s: ArrayLike, *, n1: float, L: float, mu_l: float, max_height: float
) -> DiagramScales:
    """μ_S and whole-millimetre poles for the diagrams of `s` (m, n equal steps).

    μ_S = μ_l (seed 003 §1.7: "drawn on a scale μ_S = μ_l") unless a diagram
    would then be taller than `max_height` mm; then μ_S goes up the series of
    μ_l (1, 2, 2.5, 4, 5 × 10^k) one step at a time. The poles come from
    ROUND_POLE_DISTANCES_MM such that μ_V = μ_S/(μ_t·OH1) and μ_a =
    μ_V/(μ_t·OH2) are standard scales; of those, both poles in 30 … 50 mm
    first, then the tallest diagrams. Where no pair makes both scales standard
    the poles still come from the list (`standard` False)."""
    if not (mu_l > 0 and max_height > 0):
        raise ValueError(f"mu_l and max_height must be positive, got {mu_l!r}, {max_height!r}")
    ref = _drawn_heights(_check_samples(s), n1=n1, mu_S=mu_l, L=L, H1=40.0, H2=40.0)
    h_s, h_v, h_a = ref.heights_mm
    mu_t = ref.mu_t
    textbook = (POLE_DISTANCE_RANGE_MM[0], POLE_DISTANCE_RANGE_MM[1])
    # each pole with whether it lies in 30 … 50 mm; the height allowed; the
    # reference scales read once
    poles = [(H, int(textbook[0] <= H <= textbook[1])) for H in ROUND_POLE_DISTANCES_MM]
    tallest = max_height * (1 + 1e-9)
    ref_mu_V, ref_mu_a = ref.mu_V, ref.mu_a
    relaxed: DiagramScales | None = None
    for steps, mu_S in enumerate(series(mu_l * (1 - 1e-9), mu_l * 1e4, LENGTH_MANTISSA_TEXT)):
        if h_s * mu_l / mu_S > max_height * (1 + 1e-9):
            continue
        # every pair of poles that draws both diagrams within the height, with
        # its key after `standard`: both poles in 30 … 50 mm, then the tallest
        # (derived_scale written out: μ/(μ_t·OH), the same operations)
        pairs: list[tuple[tuple[int, float, float], float, float, float, float]] = []
        for H1, in_1 in poles:
            mu_V = mu_S / (mu_t * H1)
            tall_v = h_v * ref_mu_V / mu_V
            if tall_v > tallest:
                continue
            for H2, in_2 in poles:
                mu_a = mu_V / (mu_t * H2)
                tall_a = h_a * ref_mu_a / mu_a
                if tall_a > tallest:
                    continue
                low = tall_a if tall_a < tall_v else tall_v  # min(tall_v, tall_a)
                pairs.append(((in_1 + in_2, low, tall_v + tall_a), H1, H2, mu_V, mu_a))
        # the first pair of the highest key (standard first): the pairs from
        # the highest key after `standard` down (a stable sort keeps the first
        # of equal keys first), the first standard one, else the first of all
        best: DiagramScales | None = None
        standard_v: dict[float, bool] = {}  # by H1
        for _, H1, H2, mu_V, mu_a in sorted(pairs, key=lambda pair: pair[0], reverse=True):
            if H1 not in standard_v:
                standard_v[H1] = is_standard(mu_V)
            if standard_v[H1] and is_standard(mu_a):
                best = DiagramScales(mu_S, H1, H2, steps, True)
                break
        if best is None and pairs:
            _, H1, H2, _, _ = max(pairs, key=lambda pair: pair[0])
            best = DiagramScales(mu_S, H1, H2, steps, False)
        if best is not None and best.standard:
            return best
        if best is not None and relaxed is None:
            relaxed = best
        if steps >= 6 and relaxed is not None:
            return relaxed
    if relaxed is not None:
        return relaxed
    raise ValueError("no scales draw the diagrams within the height given")


@dataclass(frozen=True)
class _Heights:
    """What `diagram_scales` reads of a trial construction: its scales and
    the drawn heights of its three diagrams (`KinematicDiagrams.heights_mm`)."""

    mu_t: float
    mu_V: float
    mu_a: float
    heights_mm: tuple[float, float, float]


def _drawn_heights(
    s: Array, *, n1: float, mu_S: float, L: float, H1: float, H2: float, samples_per_interval=16
) -> _Heights:
    """The heights `graphical_differentiation` would draw, by the same
    operations on the same numbers, without the construction's records (the
    chords, the rays, the frozen copies)."""
    n = s.size
    mu_t = time_scale(n1, L)
    mu_V = derived_scale(mu_S, mu_t, H1)
    mu_a = derived_scale(mu_V, mu_t, H2)
    x = np.arange(n + 1) * (L / n)
    h = float(x[1] - x[0])
    dx = _diff(x)

    def extent(y: Array) -> float:
        return float(max(0.0, y.max()) - min(0.0, y.min()))

    def derivative(y: Array, H: float) -> tuple[Array, Array, Array]:
        mid = H * (_diff(y) / dx)
        M = _periodic_spline_moments(mid, h)
        return _spline_on_grid(mid, M, h, samples_per_interval), mid, M

    y_s = _closed(s) / mu_S
    curve_v, mid_v, M_v = derivative(y_s, H1)
    ordinates = _spline_at_nodes(mid_v, M_v, h)
    curve_a, _, _ = derivative(_closed(ordinates), H2)
    return _Heights(mu_t, mu_V, mu_a, (extent(y_s), extent(curve_v), extent(curve_a)))


# --------------------------------------------------------------------------- the smooth curve


def _periodic_spline_moments(y: Array, h: float) -> Array:
    """Second derivatives M_j of the periodic cubic spline through y_j at step h.

    M_{j-1} + 4 M_j + M_{j+1} = 6/h² (y_{j-1} − 2 y_j + y_{j+1}) is circulant, so
    the discrete Fourier transform diagonalises it; 4 + 2 cos θ ≥ 2 never vanishes.
    """
    n = y.size
    return _irfft(_rfft(y) * (_spline_factor(n) / (h * h)), n)


@lru_cache(maxsize=64)
def _spline_factor(n: int) -> Array:
    """6·(2 cos θ − 2)/(4 + 2 cos θ) at the harmonics θ = 2πk/n, k = 0 … n/2: the
    circulant system of the periodic spline, divided out (a real signal's
    spectrum is symmetric, so half of it says all)."""
    c = np.cos(2.0 * np.pi * np.arange(n // 2 + 1) / n)
    return _frozen(6.0 * (2.0 * c - 2.0) / (4.0 + 2.0 * c))


def _periodic_spline_eval(x: Array, x0: float, h: float, y: Array, M: Array) -> Array:
    """The periodic cubic spline with nodes x0 + j·h, ordinates y and moments M, at x."""
    n = y.size
    u = np.mod((np.asarray(x, dtype=np.float64) - x0) / h, n)
    j = np.minimum(np.floor(u).astype(np.int64), n - 1)
    tau = u - j
    j1 = (j + 1) % n
    linear = (1.0 - tau) * y[j] + tau * y[j1]
    return linear - h**2 / 6.0 * tau * (1.0 - tau) * ((2.0 - tau) * M[j] + (1.0 + tau) * M[j1])


def _spline_at_nodes(y: Array, M: Array, h: float) -> Array:
    """The spline through the middles of the intervals, read at the grid points:
    each half way (τ = ½) between the middles j − 1 (wrapping) and j, where
    `_periodic_spline_eval` is (y_j−1 + y_j)/2 − h²/16·(M_j−1 + M_j)."""
    out = y + np.concatenate((y[-1:], y[:-1]))
    out *= 0.5
    out -= h * h / 16.0 * (M + np.concatenate((M[-1:], M[:-1])))
    return out


@lru_cache(maxsize=64)
def _grid_weights(n: int, per_interval: int) -> tuple[Array, Array, Array, Array, Array, Array]:
    """Where the samples i/per_interval of the grid's steps (i = 0 … n·per_interval)
    fall between the middles of the intervals: the indices j, j + 1 and the
    weights of y_j, y_j+1, M_j, M_j+1 (the latter times h²) of
    `_periodic_spline_eval`, with τ exact (u = i/per_interval − ½)."""
    i = np.arange(n * per_interval + 1)
    u = np.mod(i / per_interval - 0.5, n)
    j = np.minimum(np.floor(u).astype(np.int64), n - 1)
    tau = u - j
    j1 = (j + 1) % n
    bend = -tau * (1.0 - tau) / 6.0
    return tuple(  # type: ignore[return-value]
        _frozen(a) if a.dtype == np.float64 else a
        for a in (j, j1, 1.0 - tau, tau, bend * (2.0 - tau), bend * (1.0 + tau))
    )


def _spline_on_grid(y: Array, M: Array, h: float, per_interval: int) -> Array:
    """The spline through the middles, sampled `per_interval` times a step from
    the first grid point to the last (the drawn curve)."""
    j, j1, wy0, wy1, wm0, wm1 = _grid_weights(y.size, per_interval)
    return wy0 * y[j] + wy1 * y[j1] + (h * h) * (wm0 * M[j] + wm1 * M[j1])


# --------------------------------------------------------------------------- the construction


@dataclass(frozen=True)
class GraphicalDerivative:
    """One graphical differentiation (S → V or V → a), in the new diagram's own axes, mm.

    The new diagram's origin is at (0, 0), time to the right; the pole H sits at
    (−OH, 0). The differentiated curve is given in its own axes as well.
    """

    pole_distance: float  # OH, mm
    pole: Array  # (2,): H = (−OH, 0)
    source_points: Array  # (n+1, 2): the differentiated diagram at positions 0…n (n closes)
    chords: Array  # (n, 2, 2): 0–1′, 1′–2′, … as [start, end]
    rays: Array  # (n, 2, 2): H–K_i, parallel to chord i
    k_points: Array  # (n, 2): K_i = (0, OH·slope_i)
    mid_points: Array  # (n, 2): 1″, 2″, …: K_i carried to the middle of interval i
    curve: Array  # (m, 2): the smooth curve through the mid points, 0 … L
    ordinates: Array  # (n,): the curve read at positions 0…n−1, mm
    scale: float  # μ of the new diagram (μ_V or μ_a)
    values: Array  # (n,): ordinates · scale, SI

    def read(self, x_mm: ArrayLike) -> Array:
        """The smooth curve's ordinate (mm) at abscissae x_mm (periodic in L)."""
        x_mid = self.mid_points[:, 0]
        h = float(x_mid[1] - x_mid[0])
        y = np.asarray(self.mid_points[:, 1])
        return _periodic_spline_eval(
            np.asarray(x_mm, dtype=np.float64),
            float(x_mid[0]),
            h,
            y,
            _periodic_spline_moments(y, h),
        )


@dataclass(frozen=True)
class KinematicDiagrams:
    """S, V, a of the output over one turn: the construction (mm) and the values (SI)."""

    n1: float  # crank speed, rpm
    L: float  # time axis, mm
    mu_t: float  # s/mm
    mu_S: float  # m/mm
    mu_V: float  # (m/s)/mm
    mu_a: float  # (m/s²)/mm
    H1: float  # pole distance OH1, mm
    H2: float  # pole distance OH2, mm
    abscissae: Array  # (n,): positions on the time axis, mm
    t: Array  # (n,): time of each position, s
    s_points: Array  # (n+1, 2): the S diagram, mm (point n closes the turn)
    velocity: GraphicalDerivative  # S → V
    acceleration: GraphicalDerivative  # V → a
    s: Array  # (n,) m
    v: Array  # (n,) m/s
    a: Array  # (n,) m/s²

    @property
    def n(self) -> int:
        return int(self.s.size)

    @property
    def heights_mm(self) -> tuple[float, float, float]:
        """Drawn heights of the S, V and a diagrams (the curves' extent, axis included), mm."""

        def extent(y: Array) -> float:
            return float(max(0.0, y.max()) - min(0.0, y.min()))

        return (
            extent(self.s_points[:, 1]),
            extent(self.velocity.curve[:, 1]),
            extent(self.acceleration.curve[:, 1]),
        )

    def values_at(self, t: ArrayLike) -> tuple[Array, Array]:
        """V and a read off the smooth curves at times t (s)."""
        x = np.asarray(t, dtype=np.float64) / self.mu_t
        return (self.velocity.read(x) * self.mu_V, self.acceleration.read(x) * self.mu_a)


def _differentiate(
    points: Array, H: float, scale: float, samples_per_interval: int
) -> GraphicalDerivative:
    x, y = points[:, 0], points[:, 1]
    n = x.size - 1
    slope = _diff(y) / _diff(x)
    # the records filled in place (each array made here once, then frozen)
    k = np.zeros((n, 2))
    k[:, 1] = H * slope
    mid = np.empty((n, 2))
    mid[:, 0] = 0.5 * (x[:-1] + x[1:])
    mid[:, 1] = k[:, 1]
    pole = np.array([-H, 0.0])
    chords = np.empty((n, 2, 2))
    chords[:, 0], chords[:, 1] = points[:-1], points[1:]
    rays = np.empty((n, 2, 2))
    rays[:, 0], rays[:, 1] = pole, k

    h = float(x[1] - x[0])
    M = _periodic_spline_moments(mid[:, 1], h)
    L = float(x[-1])
    curve = np.empty((n * samples_per_interval + 1, 2))
    curve[:, 0] = _linspace(L, n * samples_per_interval + 1)
    curve[:, 1] = _spline_on_grid(mid[:, 1], M, h, samples_per_interval)
    ordinates = _spline_at_nodes(mid[:, 1], M, h)

    return GraphicalDerivative(
        pole_distance=float(H),
        pole=_made_here(pole),
        source_points=_frozen(points),
        chords=_made_here(chords),
        rays=_made_here(rays),
        k_points=_made_here(k),
        mid_points=_made_here(mid),
        curve=_made_here(curve),
        ordinates=_made_here(ordinates),
        scale=float(scale),
        values=_made_here(ordinates * scale),
    )


def _made_here(arr: Array) -> Array:
    """An array its maker alone holds, frozen as it is (`_frozen` without the copy)."""
    arr.setflags(write=False)
    return arr


@lru_cache(maxsize=64)
def _linspace(stop: float, num: int) -> Array:
    """np.linspace(0, stop, num), made once for each time axis and grid."""
    return _made_here(np.linspace(0.0, stop, num))


def _check_samples(s: ArrayLike, name: str = "s") -> Array:
    arr = np.asarray(s, dtype=np.float64)
    if arr.ndim != 1 or arr.size < 4:
        raise ValueError(f"{name} must be a 1-d array of at least 4 positions, got {arr.shape}")
    if not np.isfinite(arr).all():
        raise ValueError(f"{name} must be finite at every position")
    return arr


def graphical_differentiation(
    s: ArrayLike,
    *,
    n1: float,
    mu_S: float,
    L: float = DEFAULT_TIME_AXIS_MM,
    H1: float | None = None,
    H2: float | None = None,
    samples_per_interval: int = 16,
) -> KinematicDiagrams:
    """Graphical differentiation of S_E(t) into V_E(t) and a_E(t) (seed 003, 1.7).

    ``s``: displacement (m) at n equal crank steps over one turn, position 0
    first; n1 in rpm; L and the pole distances in mm; μ_S in m/mm. A pole
    distance left as None follows the rule of the module docstring.
    V_E = |i − i*|·μ_V at each position, with μ_t = 60/(n1·L),
    μ_V = μ_S/(μ_t·OH1), μ_a = μ_V/(μ_t·OH2).
    """
    s_arr = _check_samples(s)
    if not mu_S > 0:
        raise ValueError(f"mu_S must be positive, got {mu_S!r}")
    if samples_per_interval < 1:
        raise ValueError(f"samples_per_interval must be at least 1, got {samples_per_interval!r}")
    for name, H in (("H1", H1), ("H2", H2)):
        if H is not None and not H > 0:
            raise ValueError(f"{name} must be positive, got {H!r}")
    n = s_arr.size
    mu_t = time_scale(n1, L)
    H1 = pole_distance(mu_S, mu_t) if H1 is None else float(H1)
    mu_V = derived_scale(mu_S, mu_t, H1)
    H2 = pole_distance(mu_V, mu_t) if H2 is None else float(H2)
    mu_a = derived_scale(mu_V, mu_t, H2)

    # Position n is position 0 one turn later: the chords close the cycle.
    x = np.arange(n + 1) * (L / n)
    s_points = _columns(x, _closed(s_arr) / mu_S)
    velocity = _differentiate(s_points, H1, mu_V, samples_per_interval)
    # The V diagram is differentiated where it is read: at the positions.
    v_points = _columns(x, _closed(velocity.ordinates))
    acceleration = _differentiate(v_points, H2, mu_a, samples_per_interval)

    return KinematicDiagrams(
        n1=float(n1),
        L=float(L),
        mu_t=mu_t,
        mu_S=float(mu_S),
        mu_V=mu_V,
        mu_a=mu_a,
        H1=H1,
        H2=H2,
        abscissae=_frozen(x[:-1]),
        t=_frozen(x[:-1] * mu_t),
        s_points=_frozen(s_points),
        velocity=velocity,
        acceleration=acceleration,
        s=_frozen(s_arr),
        v=velocity.values,
        a=acceleration.values,
    )


# --------------------------------------------------------------------------- better differentiation


def _omega(n1: float) -> float:
    if not n1 > 0:
        raise ValueError(f"n1 must be positive, got {n1!r}")
    return 2.0 * np.pi * n1 / 60.0


def spectral_derivatives(s: ArrayLike, *, n1: float) -> tuple[Array, Array]:
    """V = ds/dt and a = d²s/dt² at the positions by the periodic Fourier derivative.

    s(t) repeats every turn, so its k-th harmonic turns at k·ω1: multiply by
    i·k·ω1 once for V, twice for a. The Nyquist harmonic of an even n has no
    sign to give a first derivative, so it is dropped there and kept for a.
    Exact for displacements with no harmonic above n/2.
    """
    s_arr = _check_samples(s)
    n = s_arr.size
    w = _omega(n1)
    k = np.arange(n // 2 + 1, dtype=np.float64)
    c = _rfft(s_arr)
    d1 = 1j * k * w
    if n % 2 == 0:
        d1[-1] = 0.0
    v = _irfft(c * d1, n)
    a = _irfft(c * -((k * w) ** 2), n)
    return _frozen(v), _frozen(a)


@lru_cache(maxsize=32)
def _central_weights(derivative: int, half_width: int) -> Array:
    """Weights c_j, j = −m…m, with Σ c_j j^p / p! = δ(p, derivative): Taylor's conditions."""
    j = np.arange(-half_width, half_width + 1, dtype=np.float64)
    p = np.arange(2 * half_width + 1)
    A = j[None, :] ** p[:, None] / np.array([math.factorial(int(q)) for q in p])[:, None]
    rhs = np.zeros(p.size)
    rhs[derivative] = 1.0
    return _frozen(np.linalg.solve(A, rhs))


def central_difference_derivatives(
    s: ArrayLike, *, n1: float, order: int = 8
) -> tuple[Array, Array]:
    """V and a at the positions by periodic central differences of the given even order.

    order 2 is the centred chord (V_i ≈ (s_{i+1} − s_{i−1})/2Δt); order 8 uses four
    neighbours each side, error O(Δt^8).
    """
    if order < 2 or order % 2:
        raise ValueError(f"order must be even and at least 2, got {order!r}")
    s_arr = _check_samples(s)
    m = order // 2
    if 2 * m + 1 > s_arr.size:
        raise ValueError(f"order {order} needs at least {2 * m + 1} positions, got {s_arr.size}")
    _omega(n1)
    dt = 60.0 / (n1 * s_arr.size)
    n = s_arr.size
    wrapped = np.concatenate((s_arr[n - m :], s_arr, s_arr[:m]))  # m either side, over the turn
    # row j: s_{i+j-m} for every i; the weighted rows summed down the rows in
    # order (a reduction along the first axis adds row after row, as a loop would)
    shifted = wrapped[_window(n, m)]
    v = np.add.reduce(_central_weights(1, m)[:, None] * shifted, axis=0)
    a = np.add.reduce(_central_weights(2, m)[:, None] * shifted, axis=0)
    return _frozen(v / dt), _frozen(a / dt**2)


@lru_cache(maxsize=32)
def _window(n: int, half_width: int) -> Array:
    """Indices of `wrapped` (half_width either side): row j holds i + j for i = 0 … n−1."""
    return np.arange(n)[None, :] + np.arange(2 * half_width + 1)[:, None]


def textbook_derivatives(s: ArrayLike, *, n1: float) -> tuple[Array, Array]:
    """V and a at the positions by the construction of 1.7 (scales cancel, so any will do)."""
    d = graphical_differentiation(s, n1=n1, mu_S=1.0, H1=40.0, H2=40.0, samples_per_interval=1)
    return d.v, d.a


DIFFERENTIATION_METHODS: Mapping[str, Callable[..., tuple[Array, Array]]] = MappingProxyType(
    {
        "textbook": textbook_derivatives,
        "central8": central_difference_derivatives,
        "spectral": spectral_derivatives,
    }
)


# --------------------------------------------------------------------------- the 5 % check

FlagKind = Literal["sign_change", "small_value", "fast_change", "plan_mismatch", "unexplained"]


@dataclass(frozen=True)
class ErrorFlag:
    """A position where formula (12) or (13) exceeds the limit, or cannot be evaluated."""

    quantity: Literal["v", "a"]
    index: int
    error_percent: float | None  # None: the plan value is zero, (12)/(13) is undefined
    plan: float
    diagram: float
    kind: FlagKind
    reason: str

    @property
    def construction_own(self) -> bool:
        """True when the graphical construction itself, not the plan, makes the error."""
        return self.kind in ("sign_change", "small_value", "fast_change")


@dataclass(frozen=True)
class PlanComparison:
    """The check of 1.8: Δ_V, Δ_a at every position (percent), the failures and the cure."""

    v_error_percent: tuple[float | None, ...]
    a_error_percent: tuple[float | None, ...]
    flags: tuple[ErrorFlag, ...]
    limit_percent: float
    positions: int  # positions of the diagrams compared
    # Fewest positions that bring every construction-own error with a defined
    # value under the limit; `positions` itself when nothing needs it.
    positions_needed: int
    positions_needed_how: Literal["current", "trial", "estimate"]
    # (positions, worst error in percent over those positions) for each trial
    trials: tuple[tuple[int, float], ...]

    @property
    def passed(self) -> bool:
        return not self.flags


def _relative_error(plan: Array, diagram: Array) -> list[float | None]:
    """Formula (12)/(13): (plan − diagram)/plan · 100 %, None where the plan is zero."""
    big = float(np.abs(plan).max()) if plan.size else 0.0
    with np.errstate(divide="ignore", invalid="ignore"):
        errors = ((plan - diagram) / plan * 100.0).tolist()
    zero = (np.abs(plan) <= _ZERO_PLAN * big).tolist() if big != 0.0 else [True] * plan.size
    return [None if z else e for z, e in zip(zero, errors)]


def _sign_changes_next_to(plan: Array, i: int) -> bool:
    n = plan.size
    # Round-off leaves a zero of the plan (an extreme position) with either sign.
    sign = np.where(np.abs(plan) <= _ZERO_PLAN * float(np.abs(plan).max()), 0.0, np.sign(plan))
    return bool(sign[i] * sign[(i - 1) % n] <= 0.0 or sign[i] * sign[(i + 1) % n] <= 0.0)


def _reference(
    s: Array | None, s_of_n: Callable[[int], np.ndarray] | None, n: int, n1: float
) -> tuple[Array, Array, Array, Array] | None:
    """Accurate V, a at the n positions and a bound on their own error.

    With s_of_n, the spectral derivative of at least 360 positions (an even
    multiple of n, so the n positions are among them); otherwise of the n samples, its
    error bounded by how far the 8th-order differences are from it.
    """
    if s_of_n is not None:
        m = 2 * math.ceil(180 / n)  # even, so half as many samples still hold the n positions
        fine = _check_samples(s_of_n(n * m), f"s_of_n({n * m})")
        if fine.size != n * m:
            raise ValueError(f"s_of_n({n * m}) returned {fine.size} values")
        v, a = spectral_derivatives(fine, n1=n1)
        # The spectral error falls faster than any power of Δt: the distance to
        # the derivative of every other sample bounds the fine one's error.
        v2, a2 = spectral_derivatives(fine[::2], n1=n1)
        h = m // 2
        return v[::m], a[::m], np.abs(v2[::h] - v[::m]), np.abs(a2[::h] - a[::m])
    if s is None:
        return None
    if s.size != n:
        raise ValueError(f"s has {s.size} positions, the diagrams {n}")
    v, a = spectral_derivatives(s, n1=n1)
    if n >= 9:
        vc, ac = central_difference_derivatives(s, n1=n1, order=8)
        return v, a, np.abs(vc - v), np.abs(ac - a)
    return v, a, np.zeros(n), np.zeros(n)


def _explain(
    quantity: Literal["v", "a"],
    i: int,
    err: float | None,
    plan: Array,
    diagram: Array,
    ref: Array | None,
    ref_err: Array | None,
    limit: float,
    n: int,
) -> tuple[FlagKind, str]:
    p, d = float(plan[i]), float(diagram[i])
    sym, unit = ("V", "m/s") if quantity == "v" else ("a", "m/s²")
    if ref is not None and ref_err is not None:
        miss = abs(p - float(ref[i]))
        if miss > max(limit / 100.0 * abs(p), 3.0 * float(ref_err[i])) and miss > 1e-9 * float(
            np.abs(plan).max()
        ):
            return "plan_mismatch", (
                f"an accurate derivative of the same displacements gives"
                f" {sym} = {float(ref[i]):.6g} {unit},"
                f" not the plan's {p:.6g} {unit}: the plan (or the displacement) is wrong here,"
                " not the construction"
            )
    big = float(np.abs(plan).max())
    if _sign_changes_next_to(plan, i):
        where = (
            "an extreme position of the output, where V changes sign"
            if quantity == "v"
            else "where a changes sign (V at its largest or smallest)"
        )
        if err is None:
            return "sign_change", (
                f"{sym}_plan is zero here ({where}): formula ({12 if quantity == 'v' else 13}) is"
                f" undefined; the construction reads {d:.6g} {unit}"
            )
        return "sign_change", (
            f"next to {where}: {sym}_plan = {p:.6g} {unit} is small, so the construction's"
            f" absolute error {abs(p - d):.3g} {unit} is {abs(err):.3g} % of it"
        )
    if abs(p) < _SMALL_PLAN * big:
        return "small_value", (
            f"{sym}_plan = {p:.6g} {unit} is only {abs(p) / big * 100:.3g} % of the largest value,"
            f" so the construction's absolute error {abs(p - d):.3g} {unit}"
            f" is {abs(err or 0):.3g} % of it"
        )
    if ref is None:
        return "unexplained", (
            f"no displacements were given to tell the construction's error from the plan's:"
            f" {sym}_plan = {p:.6g}, {sym}_diagram = {d:.6g} {unit}"
        )
    k = (i + 1) % n
    change = abs(float(plan[k]) - float(plan[i - 1])) / 2.0
    return "fast_change", (
        f"{sym} changes fast here (about {change:.3g} {unit} per interval of {360.0 / n:.3g}°):"
        f" the chords of {n} positions cut the curve; more positions shorten them"
    )


def compare_with_plans(
    v_diagram: ArrayLike,
    a_diagram: ArrayLike,
    v_plan: ArrayLike,
    a_plan: ArrayLike,
    *,
    n1: float,
    s: ArrayLike | None = None,
    s_of_n: Callable[[int], np.ndarray] | None = None,
    limit_percent: float = ERROR_LIMIT_PERCENT,
    candidates: Sequence[int] = POSITION_CANDIDATES,
) -> PlanComparison:
    """Δ_V = (V_plan − V_diagrams)/V_plan·100 % (12) and Δ_a likewise (13), seed 003 1.8.

    All arrays are signed along the working direction, one value per position.
    ``s`` (the displacements the diagrams were drawn from) or ``s_of_n`` (the
    displacements at any number of equal steps from the same position 0) lets
    each failure be told apart: the construction's own error (a sign change, a
    fast change) or a plan that disagrees with the motion. With ``s_of_n`` the
    cure is found by redrawing with each candidate number of positions;
    without it, by the construction's Δt² law: n·sqrt(worst/limit).
    """
    vd, ad = np.asarray(v_diagram, float), np.asarray(a_diagram, float)
    vp, ap = np.asarray(v_plan, float), np.asarray(a_plan, float)
    n = vd.size
    for name, arr in (("a_diagram", ad), ("v_plan", vp), ("a_plan", ap)):
        if arr.shape != (n,):
            raise ValueError(f"{name} has shape {arr.shape}, v_diagram {vd.shape}")
    if not np.isfinite(np.concatenate((vd, ad, vp, ap))).all():
        raise ValueError("diagram and plan values must be finite")
    s_arr = None if s is None else _check_samples(s)

    ev, ea = _relative_error(vp, vd), _relative_error(ap, ad)
    ref = _reference(s_arr, s_of_n, n, n1)

    flags: list[ErrorFlag] = []
    for quantity, errs, plan, diagram, r, re in (
        ("v", ev, vp, vd, None if ref is None else ref[0], None if ref is None else ref[2]),
        ("a", ea, ap, ad, None if ref is None else ref[1], None if ref is None else ref[3]),
    ):
        for i, err in enumerate(errs):
            if err is not None and abs(err) <= limit_percent:
                continue
            q = cast("Literal['v', 'a']", quantity)
            kind, reason = _explain(q, i, err, plan, diagram, r, re, limit_percent, n)
            flags.append(ErrorFlag(q, i, err, float(plan[i]), float(diagram[i]), kind, reason))

    # Only errors the construction makes, and that (12)/(13) can measure, can be cured by positions.
    curable = [f for f in flags if f.construction_own and f.error_percent is not None]
    trials: list[tuple[int, float]] = []
    needed: int | None = n
    how: Literal["current", "trial", "estimate"] = "current"
    if curable:
        worst = max(abs(f.error_percent or 0.0) for f in curable)
        needed, how = None, "estimate"
        last_n, last_worst = n, worst
        if s_of_n is not None:
            t = np.arange(n) * (60.0 / (n1 * n))
            for c in sorted(int(c) for c in candidates if int(c) > n):
                d = graphical_differentiation(
                    s_of_n(c), n1=n1, mu_S=1.0, H1=40.0, H2=40.0, samples_per_interval=1
                )
                v_c, a_c = d.values_at(t)
                worst_c = 0.0
                for f in curable:
                    plan, value = (vp, v_c) if f.quantity == "v" else (ap, a_c)
                    p = plan[f.index]
                    worst_c = max(worst_c, abs((p - value[f.index]) / p) * 100.0)
                trials.append((c, float(worst_c)))
                last_n, last_worst = c, worst_c
                if worst_c <= limit_percent:
                    needed, how = c, "trial"
                    break
        if needed is None:
            estimate = math.ceil(last_n * math.sqrt(last_worst / limit_percent))
            larger = [int(c) for c in candidates if int(c) >= estimate and int(c) > last_n]
            needed = min(larger) if larger else estimate

    assert needed is not None
    return PlanComparison(
        v_error_percent=tuple(ev),
        a_error_percent=tuple(ea),
        flags=tuple(flags),
        limit_percent=float(limit_percent),
        positions=n,
        positions_needed=needed,
        positions_needed_how=how,
        trials=tuple(trials),
    )


# --------------------------------------------------------------------------- the check of the sheet

# A plan value under this share of its largest magnitude over the turn makes
# formula (12)/(13) ill-conditioned: a small absolute error becomes a large
# relative one. Such a value is reported by its absolute error, not failed --
# but only when no grid of the series passes it by (12)/(13) as written.
ILL_CONDITIONED = 0.05
# The series of grids tried: n·k divisions of the turn, k in one position
# step (the positions stay grid points), coarsest first.
GRID_REFINEMENTS = (1, 2, 3, 4, 6, 8, 12)


def chord_derivatives(s: ArrayLike, *, n1: float) -> tuple[Array, Array]:
    """V and a at the n grid points by the construction of 1.7, in SI, without
    drawing it: the chords' slopes at the middles of the intervals, the periodic
    spline through them read at the grid points, and the same again for a.
    Equal to `graphical_differentiation(s, ...).v, .a` at any scales (they cancel)."""
    s_arr = _check_samples(s)
    dt = 60.0 / (float(n1) * s_arr.size)
    v = _chord_derivative(s_arr, dt)
    return v, _chord_derivative(v, dt)


def _chord_derivative(y: Array, dt: float) -> Array:
    # slope of chord j sits at the middle of interval j; grid point i lies half
    # way between the middles j = i − 1 and i, where the spline of
    # `_periodic_spline_eval` is (y_j + y_j1)/2 − dt²/16·(M_j + M_j1)
    slope = np.empty_like(y)
    np.subtract(y[1:], y[:-1], out=slope[:-1])
    slope[-1] = y[0] - y[-1]
    slope /= dt
    M = _periodic_spline_moments(slope, dt)
    # each grid point from its two neighbouring middles: j − 1 (wrapping) and j
    out = slope + np.concatenate((slope[-1:], slope[:-1]))
    out *= 0.5
    out -= dt * dt / 16.0 * (M + np.concatenate((M[-1:], M[:-1])))
    return out


JudgedBy = Literal["formula", "absolute_error"]


@dataclass(frozen=True)
class InvestigatedValue:
    """Formula (12) or (13) at one investigated position, on the drawn diagrams."""

    index: int  # the position
    quantity: Literal["v", "a"]
    plan: float
    diagram: float
    error_percent: float  # (plan − diagram)/plan·100
    absolute_error: float  # |plan − diagram|
    # judged by its absolute error: |plan| is under ILL_CONDITIONED of its
    # largest magnitude over the turn AND no grid of the series passes it by
    # (12)/(13); everything else is judged by (12)/(13) as written
    ill_conditioned: bool
    passed: bool  # |error_percent| within the limit, or judged by its absolute error
    plan_share_percent: float = 100.0  # |plan| over its largest magnitude over the turn, %

    @property
    def judged_by(self) -> JudgedBy:
        return "absolute_error" if self.ill_conditioned else "formula"


@dataclass(frozen=True)
class GridTrial:
    """One grid of the series: (12)/(13) at every investigated position on it."""

    intervals: int  # n·k divisions of the turn
    refinement: int  # k
    errors: tuple[tuple[int, Literal["v", "a"], float], ...]  # (index, quantity, error %)
    limit_percent: float

    @property
    def failing(self) -> tuple[tuple[int, Literal["v", "a"], float], ...]:
        return tuple(e for e in self.errors if not abs(e[2]) <= self.limit_percent)

    @property
    def passed(self) -> bool:
        """Every investigated position within the limit by (12)/(13) as written."""
        return not self.failing


@dataclass(frozen=True)
class SheetCheck:
    """The 5 % check of seed 003 §1.8 at the investigated positions, judged on
    the diagrams the sheet draws: over `intervals` divisions of the turn
    (`refinement` per position step), the first grid of GRID_REFINEMENTS on
    which every investigated position passes by (12)/(13)."""

    intervals: int
    refinement: int
    limit_percent: float
    values: tuple[InvestigatedValue, ...]
    tried: tuple[tuple[int, bool], ...]  # (intervals, passed by (12)/(13)) for each grid tried
    trials: tuple[GridTrial, ...] = ()  # the same grids with their errors

    @property
    def passed(self) -> bool:
        return all(v.passed for v in self.values)


def _relative_percent(plan: float, diagram: float) -> float:
    return (plan - diagram) / plan * 100.0 if plan != 0.0 else math.inf


def judge(
    index: int,
    quantity: Literal["v", "a"],
    plan: float,
    diagram: float,
    largest: float,
    limit_percent: float = ERROR_LIMIT_PERCENT,
    *,
    exempt: bool = False,
) -> InvestigatedValue:
    """One value of the check by (12)/(13); `exempt` (no grid of the series
    passes it, and it is ill-conditioned there) judges it by its absolute error."""
    ill = exempt and abs(plan) < ILL_CONDITIONED * largest
    err = _relative_percent(plan, diagram)
    passed = ill or abs(err) <= limit_percent
    return InvestigatedValue(
        index,
        quantity,
        float(plan),
        float(diagram),
        float(err) if math.isfinite(err) else 0.0,
        abs(plan - diagram),
        ill,
        bool(passed),
        abs(plan) / largest * 100.0 if largest > 0 else 0.0,
    )


@dataclass(frozen=True)
class GridChoice:
    """The grid a sheet draws its diagrams on, and the values judged by their
    absolute error (ill-conditioned and passed by no grid of the series)."""

    refinement: int
    trials: tuple[GridTrial, ...]
    exempt: frozenset[tuple[int, str]]


def choose_grid(
    s_of_n: Callable[[int], np.ndarray],
    *,
    n: int,
    n1: float,
    investigated: Sequence[int],
    v_plan: ArrayLike,
    a_plan: ArrayLike,
    largest: tuple[float, float],
    limit_percent: float = ERROR_LIMIT_PERCENT,
    series: Sequence[int] = GRID_REFINEMENTS,
) -> GridChoice:
    """Seed 003 §1.8 on the grids of one series (n·k divisions, k in `series`):
    the first grid on which every investigated position passes by (12)/(13) as
    written. When none does, a value that passes on no grid and is under
    ILL_CONDITIONED of its largest magnitude (`largest`: V, a) is judged by its
    absolute error, and the grid is the first on which every other value passes;
    failing that, the grid with the fewest failures (the check fails)."""
    vp, ap = np.asarray(v_plan, float), np.asarray(a_plan, float)
    trials: list[GridTrial] = []
    for k in series:
        v_d, a_d = chord_derivatives(s_of_n(n * k), n1=n1)
        errors: list[tuple[int, Literal["v", "a"], float]] = []
        for i in investigated:
            errors.append((i, "v", _relative_percent(float(vp[i]), float(v_d[i * k]))))
            errors.append((i, "a", _relative_percent(float(ap[i]), float(a_d[i * k]))))
        trial = GridTrial(n * k, k, tuple(errors), float(limit_percent))
        trials.append(trial)
        if trial.passed:
            return GridChoice(k, tuple(trials), frozenset())
    never = set.intersection(*({(i, q) for i, q, _ in t.failing} for t in trials))
    plan_of = {"v": vp, "a": ap}
    big = {"v": largest[0], "a": largest[1]}
    exempt = frozenset(
        (i, q) for i, q in never if abs(float(plan_of[q][i])) < ILL_CONDITIONED * big[q]
    )
    for t in trials:
        if all((i, q) in exempt for i, q, _ in t.failing):
            return GridChoice(t.refinement, tuple(trials), exempt)
    fewest = min(trials, key=lambda t: sum((i, q) not in exempt for i, q, _ in t.failing))
    return GridChoice(fewest.refinement, tuple(trials), exempt)
