"""Vector kernels over many crank angles at once.

A plane vector is a complex number x + iy: turning by θ is a product with
e^{iθ}, the perpendicular (k × r) is i·r, so a link's velocity field reads
V_P = V_O + i·ω·(P - O) as the textbook writes it. NaN marks a position where
a construction does not exist; it never leaves the solver (see `chain.Sweep`).
"""

from __future__ import annotations

import threading
from collections.abc import Callable
from typing import Any

import numpy as np

# relative size of rounding noise accepted as "exactly at the limit position"
ROUNDING = 8 * np.finfo(float).eps


class _Depth(threading.local):
    """How many `quiet` contexts a thread is in (0 until it enters one)."""

    depth = 0


_DEPTH = _Depth()


class quiet:
    """`np.errstate(all="ignore")` for a whole computation over the angles (NaN
    and ±inf are its data, checked where it ends): the outermost use in a
    thread sets it, nested uses cost a counter, not numpy's context machinery.
    The counter is per thread (the web page checks in several threads)."""

    __slots__ = ("_outer",)

    def __enter__(self) -> None:
        depth = _DEPTH.depth
        if depth == 0:
            self._outer = np.errstate(all="ignore")
            self._outer.__enter__()
        _DEPTH.depth = depth + 1

    def __exit__(self, *exc: Any) -> None:
        depth = _DEPTH.depth - 1
        _DEPTH.depth = depth
        if depth == 0:
            self._outer.__exit__(*exc)


def cross(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """z-component of a × b."""
    return a.real * b.imag - a.imag * b.real


def dot(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    return a.real * b.real + a.imag * b.imag


def as_complex(p) -> complex:
    return complex(p[0], p[1])


def _at_limit(h2: np.ndarray, scale: Callable[[], np.ndarray]) -> np.ndarray:
    """h² with rounding noise below zero taken as zero.

    At a toggle (|AC| = r1 + r2 exactly) rounding may leave h² a few ulps
    below zero: that is the limit position itself, not a failure to assemble.
    Mostly nothing is below zero, and one reduction says so; only then is
    `scale()`, the size of the terms h² is the difference of, computed.
    """
    if not np.fmin.reduce(h2, axis=None, initial=np.inf) < 0:
        return h2
    return np.where((h2 < 0) & (h2 > -ROUNDING * scale()), 0.0, h2)


def circle_circle(A: np.ndarray, r1: float, C: np.ndarray, r2: float, sign: int) -> np.ndarray:
    """The point B with |AB| = r1, |CB| = r2; sign +1 puts B left of A→C."""
    d = C - A
    L2 = d.real**2 + d.imag**2
    L = np.sqrt(L2)
    along = (r1 * r1 - r2 * r2 + L2) / (2 * L)
    h2 = _at_limit(r1 * r1 - along * along, lambda: r1 * r1 + L2)
    with quiet():
        h = np.sqrt(h2)
    return A + (d * (1 / L)) * (along + 1j * sign * h)  # d / L to the last bit, see turn_between


def circle_line(A: np.ndarray, r: float, P0: np.ndarray, u: np.ndarray, sign: int) -> np.ndarray:
    """The point X on the line P0 + t·u (|u| = 1) with |AX| = r; sign +1 takes the larger t.

    Seen along the guide, (P0 - A)·conj(u) = b + i·h: b how far P0 is ahead of
    the foot of the perpendicular from A, h the distance of A from the line;
    then X = P0 + (±√(r² - h²) - b)·u."""
    w = P0 - A
    along_x = u.__class__ is complex and u == 1  # a guide along x: no turn
    t = w if along_x else w * np.conj(u)
    h = t.imag
    half2 = _at_limit(r * r - h * h, lambda: r * r + (w.real**2 + w.imag**2))
    with quiet():
        half = np.sqrt(half2)
    along = half - t.real if sign > 0 else -(half + t.real)
    return P0 + (along if along_x else along * u)


def line_line(P1: np.ndarray, u1: np.ndarray, P2: np.ndarray, u2: np.ndarray) -> np.ndarray:
    """Intersection of P1 + t·u1 and P2 + s·u2 (NaN where they are parallel)."""
    det = cross(u1, u2)
    with quiet():
        t = np.where(det != 0, cross(P2 - P1, u2) / np.where(det != 0, det, 1.0), np.nan)
    return P1 + t * u1


def turn_between(p_local: complex, q_local: complex, P: Any, Q: Any) -> Any:
    """e^{iθ} of a link whose local points p, q sit at global P, Q: the
    direction of (Q - P)/(q - p).

    With q - p along the link's local x axis, the usual case, the division is
    by a real number, whose size the direction does not keep: Q - P itself,
    or P - Q where q lies behind p. The length is divided by as a product
    with its reciprocal (numpy's complex division by a real number does just
    that, to the last bit, and takes longer)."""
    c = q_local - p_local
    if c.imag == 0 and c.real:
        q = Q - P if c.real > 0 else P - Q
    else:
        q = (Q - P) / c
    if not isinstance(q, np.ndarray) or not q.ndim:  # a group fixed to the frame: numbers
        q = complex(q)
        return q / abs(q) if q else complex("nan")
    with quiet():
        size = np.abs(q)
        np.divide(1.0, size, out=size)
        q *= size
    return q
