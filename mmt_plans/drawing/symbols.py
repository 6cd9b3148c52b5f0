"""The conventional symbols of a kinematic scheme, drawn into a sketch: frame
pivots, guides hatched, the arc of ω, ε or a couple."""

from __future__ import annotations

import math

import numpy as np

from ..render.backend import Backend, Fill, LineType, PointLike

__all__ = ["unit_vector", "sense_arc", "hatched_base", "hatched_guide", "slider_block"]


def unit_vector(v: np.ndarray) -> np.ndarray:
    n = float(np.hypot(*v))
    return v / n if n > 1e-12 else np.array([1.0, 0.0])


def sense_arc(
    sk: Backend,
    centre: PointLike,
    radius: float,
    sense: float,
    start_deg: float = 20.0,
    end_deg: float = 250.0,
    line: LineType = "main",
) -> np.ndarray:
    """An arc round `centre` with its arrowhead in the sense of `sense` (ccw
    positive): the direction of ω, ε or a couple. Returns the arrow's tip."""
    c = np.asarray(centre, dtype=float)
    sk.arc(c, radius, start_deg, end_deg, line)
    t = math.radians(end_deg if sense > 0 else start_deg)
    radial = np.array([math.cos(t), math.sin(t)])
    tip = c + radius * radial
    tangent = np.array([-radial[1], radial[0]]) * (1.0 if sense > 0 else -1.0)
    sk.arrow(tip - 2.5 * tangent, tip, "main", head_length=2.5, head_width=1.0)
    return tip


def hatched_base(sk: Backend, p: np.ndarray, width: float = 8.0, down: float = 4.0) -> None:
    """A frame pivot: two legs, a hatched ground line and the pin over the legs."""
    x, y = p
    sk.line((x, y), (x - width / 3, y - down), "main")
    sk.line((x, y), (x + width / 3, y - down), "main")
    gy = y - down
    sk.line((x - width / 2, gy), (x + width / 2, gy), "main")
    for k in range(5):
        hx = x - width / 2 + k * width / 4 + 0.5
        sk.line((hx, gy), (hx - 2.0, gy - 2.0), "thin")
    sk.circle((x, y), 1.2, "main", "white")


def hatched_guide(sk: Backend, a: np.ndarray, b: np.ndarray, u: np.ndarray, offset: float) -> None:
    """A slider's guide: a main line `offset` mm under the slider's path, hatched
    below, and the path itself as the guide's centre line (dash-dot, GOST 2.303)."""
    n = np.array([-u[1], u[0]])
    sk.line(a - 2.0 * u, b + 2.0 * u, "dashdot")
    a, b = a - offset * n, b - offset * n
    sk.line(a, b, "main")
    length = float(np.hypot(*(b - a)))
    steps = max(2, int(length / 4.0))
    for k in range(steps + 1):
        q = a + (b - a) * k / steps
        sk.line(q, q - 2.0 * (u + n), "thin")


def slider_block(sk: Backend, corners: list[np.ndarray], line: LineType, fill: Fill) -> None:
    """A slider's block: the rectangle of its four corners."""
    sk.polygon([(float(p[0]), float(p[1])) for p in corners], line, fill)
