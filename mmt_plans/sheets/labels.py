"""Letters beside drawn vectors and points, placed where they hit nothing.

A draughtsman writes a label next to what it names, on whichever side is
free. `Labels` does the same for one drawing: it keeps the boxes of the
labels already written and the lines already drawn (shapely), tries the
places round the anchor nearest first, and writes the label at the first one
that touches neither. When every place is taken it takes the one that covers
the least, so a label is never dropped.
"""

from __future__ import annotations

import math
from typing import Iterable, Sequence

import numpy as np
import shapely
from shapely import STRtree
from shapely.geometry import LineString, Point, box
from shapely.geometry.base import BaseGeometry

from ..render.recording import Call, RecordingBackend

__all__ = ["Labels"]

# the directions tried round an anchor, preferred first: the given side, then
# round the compass
_COMPASS = tuple(np.exp(1j * math.radians(a)) for a in
                 (45, 135, -45, -135, 90, -90, 0, 180, 22.5, 67.5, 112.5, 157.5, -22.5, -67.5,
                  -112.5, -157.5))
_RINGS = (0.0, 2.5, 5.0, 9.0, 14.0)  # mm further out, tried in turn


class Labels:
    """Places rich-text labels on a recording sketch without collisions."""

    def __init__(self, sketch: RecordingBackend, size: float) -> None:
        self.sketch = sketch
        self.size = size
        self.boxes: list[BaseGeometry] = []
        self._obstacles: list[BaseGeometry] = []  # lines and points, kept `_clearance` mm off
        self._clearance: list[float] = []
        self._tree: STRtree | None = None

    def avoid_line(self, start: Sequence[float], end: Sequence[float], clearance: float = 0.4) -> None:
        """Keep labels `clearance` mm off a drawn segment."""
        if math.dist(start, end) > 1e-9:
            self._obstacles.append(LineString([tuple(start), tuple(end)]))
        else:
            self._obstacles.append(Point(tuple(start)))
        self._clearance.append(clearance)
        self._tree = None

    def avoid_circle(self, centre: Sequence[float], radius: float) -> None:
        self._obstacles.append(Point(tuple(centre)))
        self._clearance.append(radius)
        self._tree = None

    def avoid_drawn(self, calls: Iterable[Call], clearance: float = 0.3) -> None:
        """Keep labels off everything already recorded: lines, polylines, the
        edges of polygons, arrows and circles."""
        for c in calls:
            if c.name in ("line", "arrow", "polyline", "polygon"):
                p = c.points()
                for a, b in zip(p, p[1:] + (p[:1] if c.name == "polygon" else [])):
                    self.avoid_line(a, b, clearance)
            elif c.name == "circle":
                self.avoid_circle(c["center"], c["radius"] + clearance)

    def width(self, markup: str) -> float:
        probe = RecordingBackend(look=self.sketch.look)
        return probe.rich_text((0.0, 0.0), markup, self.size)

    def place(self, anchor: Sequence[float], markup: str, *, towards: Sequence[float] | None = None,
              distance: float = 1.5) -> BaseGeometry:
        """Write `markup` beside `anchor`, first trying the side `towards` points to."""
        w, h = self.width(markup) + 0.4, self.size + 0.4
        # an index drops 0.3 of the letter height under the line
        drop = 0.3 * self.size if "_{" in markup else 0.0
        x, y = float(anchor[0]), float(anchor[1])
        dirs = np.array(_COMPASS)
        if towards is not None and math.hypot(*towards) > 1e-12:
            t = complex(towards[0], towards[1]) / math.hypot(*towards)
            dirs = dirs[np.argsort(-(dirs.real * t.real + dirs.imag * t.imag), kind="stable")]
        # every candidate at once, nearest ring first: the box's nearest corner
        # (or edge middle) `ring` mm from the anchor
        ring = (distance + np.array(_RINGS))[:, None]
        cx = (x + dirs.real * (ring + w / 2 * np.sqrt(np.abs(dirs.real)))).ravel()
        cy = (y + dirs.imag * (ring + h / 2 * np.sqrt(np.abs(dirs.imag)))).ravel()
        x0, x1, y0, y1 = cx - w / 2, cx + w / 2, cy - h / 2 - drop, cy + h / 2
        cost = np.zeros(cx.size)
        if self.boxes:
            b = np.array([g.bounds for g in self.boxes])
            dx = np.minimum(x1[:, None], b[:, 2]) - np.maximum(x0[:, None], b[:, 0])
            dy = np.minimum(y1[:, None], b[:, 3]) - np.maximum(y0[:, None], b[:, 1])
            cost += (np.clip(dx, 0, None) * np.clip(dy, 0, None)).sum(axis=1)
        if self._obstacles:
            if self._tree is None:
                self._tree = STRtree(self._obstacles)
                self._reach = np.array(self._clearance)
            boxes = shapely.box(x0, y0, x1, y1)
            near = self._tree.query(boxes, predicate="dwithin", distance=float(self._reach.max()))
            if near.shape[1]:
                gap = shapely.distance(boxes[near[0]], np.asarray(self._obstacles, dtype=object)[near[1]])
                hit = near[0][gap < self._reach[near[1]]]
                cost += 0.25 * np.bincount(hit, minlength=cx.size)
        free = np.flatnonzero(cost <= 1e-9)
        k = int(free[0]) if free.size else int(np.argmin(cost))
        return self._write(float(cx[k]), float(cy[k]), markup,
                           box(x0[k], y0[k], x1[k], y1[k]))

    def _write(self, cx: float, cy: float, markup: str, footprint: BaseGeometry) -> BaseGeometry:
        self.sketch.rich_text((cx, cy), markup, self.size, anchor="center", valign="middle")
        self.boxes.append(footprint)
        return footprint

