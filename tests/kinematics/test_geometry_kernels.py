"""The position kernels against their definitions, on many random cases:
`turn_between` gives back the turn that placed the link (whichever way its
local points lie), `circle_line` a point on the line at the radius, the
branch sign choosing which of the two."""

from __future__ import annotations

import numpy as np
import pytest

from mmt_plans.kinematics.geometry import circle_line, turn_between

RNG = np.random.default_rng(25)
N = 500


@pytest.mark.parametrize(
    "p, q",
    [(0j, 0.8 + 0j), (0.3 + 0j, -0.5 + 0j), (0.1 - 0.2j, 0.4 + 0.7j), (0.5 + 0j, 0.5 + 0.3j)],
    ids=["along x", "behind on x", "oblique", "along y"],
)
def test_turn_between_gives_back_the_turn(p, q):
    theta = RNG.uniform(-np.pi, np.pi, N)
    e = np.exp(1j * theta)
    o = RNG.uniform(-2.0, 2.0, N) + 1j * RNG.uniform(-2.0, 2.0, N)
    got = turn_between(p, q, o + e * p, o + e * q)
    assert np.abs(got - e).max() < 1e-14
    assert np.abs(np.abs(got) - 1.0).max() < 4e-16


@pytest.mark.parametrize("u", [1 + 0j, np.exp(0.7j), np.exp(-2.1j)], ids=["x", "tilted", "backwards"])
@pytest.mark.parametrize("sign", [1, -1])
def test_circle_line_is_on_the_line_at_the_radius(u, sign):
    A = RNG.uniform(-1.0, 1.0, N) + 1j * RNG.uniform(-1.0, 1.0, N)
    P0 = 0.2 - 0.1j
    r = 1.7  # longer than any distance of A from the line: always two points
    X = circle_line(A, r, P0, u, sign)
    assert np.abs(np.abs(X - A) - r).max() < 1e-14
    # on the line: no component across it
    along = (X - P0) * np.conj(u)
    assert np.abs(along.imag).max() < 1e-14
    # the sign takes the farther point along u (+1) or the nearer (-1)
    other = circle_line(A, r, P0, u, -sign)
    t, t_other = along.real, ((other - P0) * np.conj(u)).real
    assert np.all(sign * (t - t_other) > 0)


def test_circle_line_out_of_reach_is_nan():
    A = np.array([0.0 + 2.0j, 0.0 + 0.5j])
    X = circle_line(A, 1.0, 0j, 1 + 0j, 1)
    assert np.isnan(X[0]) and np.isfinite(X[1])
