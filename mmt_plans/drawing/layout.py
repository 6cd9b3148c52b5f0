"""Placing drawings on a sheet and checking that nothing overlaps.

Every element on a sheet (a kinematic scheme, a plan, a table, a label, the
main inscription) registers its footprint: a shapely polygon in page mm.
`SheetLayout.place` finds room for a rectangle inside the frame and clear of
what is already there; `find_overlaps` / `SheetLayout.overlaps` report every
pair of footprints that share area (or come closer than a clearance).
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass
from typing import Any, Literal, Union

import numpy as np
import shapely
from shapely.geometry import Polygon, box
from shapely.geometry.base import BaseGeometry

from ..errors import MmtError
from ..render.backend import PointLike, as_point
from .page import Page, Rect

__all__ = [
    "first_free",
    "nearest_free",
    "pack",
    "ElementKind",
    "Corner",
    "Element",
    "LayoutError",
    "FootprintLike",
    "as_footprint",
    "find_overlaps",
    "SheetLayout",
]

ElementKind = Literal["drawing", "label", "table", "title_block", "note"]
Corner = Literal["top-left", "top-right", "bottom-left", "bottom-right"]
FootprintLike = Union[Rect, BaseGeometry, Sequence[PointLike]]  # noqa: UP007 (a runtime alias)

_EPS = 1e-9


class LayoutError(MmtError, ValueError):
    """A drawing that does not fit in the free space of its sheet."""


def as_footprint(shape: FootprintLike) -> BaseGeometry:
    """A shapely geometry from a Rect, a shapely geometry or a ring of points."""
    if isinstance(shape, Rect):
        return box(*shape.bounds)
    if isinstance(shape, BaseGeometry):
        return shape
    points = [as_point(p) for p in shape]
    if len(points) < 3:
        raise ValueError("a footprint polygon needs at least three points")
    return Polygon(points)


@dataclass(frozen=True)
class Element:
    """Something drawn on the sheet, by name, kind and footprint."""

    name: str
    kind: ElementKind
    footprint: BaseGeometry

    @property
    def bounds(self) -> Rect:
        return Rect.from_bounds(*self.footprint.bounds)


def _clash(a: BaseGeometry, b: BaseGeometry, clearance: float) -> bool:
    if clearance > 0.0:
        return a.distance(b) < clearance - _EPS
    # Interiors meet: touching along an edge or at a corner is allowed.
    return a.intersects(b) and not a.touches(b)


def find_overlaps(
    elements: Iterable[Element] | Mapping[str, FootprintLike], clearance: float = 0.0
) -> list[tuple[str, str]]:
    """Every pair of elements whose footprints overlap, in registration order.

    With clearance > 0, pairs closer than `clearance` mm count as well.
    """
    if isinstance(elements, Mapping):
        items = [(name, as_footprint(shape)) for name, shape in elements.items()]
    else:
        items = [(e.name, e.footprint) for e in elements]
    geoms = [g for _, g in items]
    tree = shapely.STRtree(geoms)
    pairs: list[tuple[int, int]] = []
    for i, g in enumerate(geoms):
        probe = g.buffer(clearance) if clearance > 0.0 else g
        for j in sorted(int(k) for k in tree.query(probe)):
            if j > i and _clash(g, geoms[j], clearance):
                pairs.append((i, j))
    return [(items[i][0], items[j][0]) for i, j in sorted(pairs)]


def _is_box(shape: BaseGeometry) -> bool:
    """True for an axis-parallel rectangle (the footprint of a placed Rect)."""
    x0, y0, x1, y1 = shape.bounds
    return shape.geom_type == "Polygon" and abs(shape.area - (x1 - x0) * (y1 - y0)) <= _EPS


def _candidates(
    region: Rect, boxes: np.ndarray, width: float, height: float, gap: float, corner: str
) -> np.ndarray:
    """Corners (x, y) a width × height rectangle may take (the grid of
    _axes' columns × rows); nearest `corner` first, rows first."""
    xs, ys = _axes(region, boxes, width, height, gap, corner)
    X, Y = (a.ravel() for a in np.meshgrid(xs, ys))
    return np.stack([X, Y], axis=1)


def _axes(
    region: Rect, boxes: np.ndarray, width: float, height: float, gap: float, corner: str
) -> tuple[np.ndarray, np.ndarray]:
    """The columns (x) and rows (y) a width × height rectangle's lower-left
    corner may take: in line with the region's edges and, `gap` away, with
    the boxes' edges (x0, y0, x1, y1 rows); each nearest `corner` first."""
    xs, ys = _axis_lists(region, boxes.tolist(), width, height, gap, corner)
    return np.array(xs, dtype=float), np.array(ys, dtype=float)


def _axis_lists(
    region: Rect, boxes: list[list[float]], width: float, height: float, gap: float, corner: str
) -> tuple[list[float], list[float]]:
    """_axes as lists (a few dozen values: Python's own floats are quicker than numpy's)."""
    xs = _places(
        region.left, region.right, width, [b[0] for b in boxes], [b[2] for b in boxes], gap
    )
    ys = _places(
        region.bottom, region.top, height, [b[1] for b in boxes], [b[3] for b in boxes], gap
    )
    if corner.startswith("top"):
        ys.reverse()
    if not corner.endswith("left"):
        xs.reverse()
    return xs, ys


def _places(
    lo: float, hi: float, size: float, box_lo: list[float], box_hi: list[float], gap: float
) -> list[float]:
    """Where a side `size` long may start along one axis of [lo, hi]: at
    either end, or `gap` beyond a box's side; ascending, each once."""
    first, last = lo - _EPS, hi - size + _EPS
    values = {lo, hi - size}
    values.update(v + gap for v in box_hi)
    values.update(v - gap - size for v in box_lo)
    return sorted(v for v in values if first <= v <= last)


def first_free(
    region: Rect, boxes: np.ndarray, width: float, height: float, gap: float, corner: str
) -> tuple[float, float] | None:
    """The packer of both sheets: the lower-left corner of the first candidate
    (_candidates) for a width × height rectangle in `region` that keeps `gap`
    mm from every box (x0, y0, x1, y1 rows; with gap 0, interiors do not
    meet), on arrays; None when there is no room. The candidates are the
    grid of _axes' columns × rows, tested as (rows, columns, boxes) arrays in
    the order _candidates gives them (nearest `corner` first, rows first): a
    few rows first, then four times as many, the first free one ending it."""
    xs, ys = _axis_lists(region, boxes.tolist(), width, height, gap, corner)
    if not xs or not ys:
        return None
    if not len(boxes):
        return float(xs[0]), float(ys[0])
    X, Y = np.array(xs), np.array(ys)
    # the gap between each column/row and each box (negative where they overlap)
    dx = np.maximum(boxes[None, :, 0] - (X[:, None] + width), X[:, None] - boxes[None, :, 2])
    dy = np.maximum(boxes[None, :, 1] - (Y[:, None] + height), Y[:, None] - boxes[None, :, 3])
    g = gap - _EPS  # within `gap` of a box: the squared distance, no square roots
    if g > 0:
        # within it exactly where ex² + ey² < g² (which holds only where the
        # gaps dx, dy are both under g as well)
        ex, ey = np.maximum(dx, 0.0), np.maximum(dy, 0.0)
        ex2, ey2 = ex * ex, ey * ey
        start, size = 0, 4
        while start < len(ys):
            clash = ((ey2[start : start + size, None, :] + ex2[None, :, :]) < g * g).any(axis=2)
            ok = np.flatnonzero(~clash)  # row-major: rows first, then columns
            if ok.size:
                row, col = divmod(int(ok[0]), len(xs))
                return float(xs[col]), float(ys[start + row])
            start, size = start + size, 4 * size
        return None
    DX, DY = dx[None, :, :], dy[:, None, :]  # (rows, columns, boxes)
    if gap > 0:
        ex, ey = np.maximum(dx, 0.0), np.maximum(dy, 0.0)
        near = (ex * ex)[None, :, :] + (ey * ey)[:, None, :] < g * g
        clash = ((DX < g) & (DY < g) & near).any(axis=2)
    else:
        clash = ((DX < 0) & (DY < 0)).any(axis=2)
    ok = np.flatnonzero(~clash)
    if not ok.size:
        return None
    row, col = divmod(int(ok[0]), len(xs))
    return float(xs[col]), float(ys[row])


def nearest_free(
    region: Rect, boxes: np.ndarray, width: float, height: float, gap: float, near: Rect
) -> tuple[float, float] | None:
    """As `first_free` (the same candidates, `gap` mm from every box), the
    free one nearest the rectangle `near` (a detail view beside the drawing
    it details), the first of them in `first_free`'s order (from `near`'s
    corner nearest the region's middle) on a tie; None when none is free."""
    mid_x = (region.left + region.right) / 2
    mid_y = (region.bottom + region.top) / 2
    corner = ("top" if (near.bottom + near.top) / 2 < mid_y else "bottom") + (
        "-right" if (near.left + near.right) / 2 < mid_x else "-left"
    )
    at = _candidates(region, boxes, width, height, gap, corner)
    if not len(at):
        return None
    X, Y = at[:, 0], at[:, 1]
    if len(boxes):
        dx = np.maximum(boxes[None, :, 0] - (X[:, None] + width), X[:, None] - boxes[None, :, 2])
        dy = np.maximum(boxes[None, :, 1] - (Y[:, None] + height), Y[:, None] - boxes[None, :, 3])
        ex, ey = np.maximum(dx, 0.0), np.maximum(dy, 0.0)
        g = gap - _EPS
        clash = (
            ((ex * ex + ey * ey) < g * g).any(axis=1)
            if g > 0
            else ((dx < 0) & (dy < 0)).any(axis=1)
        )
        X, Y = X[~clash], Y[~clash]
    if not X.size:
        return None
    gx = np.maximum.reduce([near.left - (X + width), X - near.right, np.zeros_like(X)])
    gy = np.maximum.reduce([near.bottom - (Y + height), Y - near.top, np.zeros_like(Y)])
    k = int(np.argmin(np.round(np.hypot(gx, gy), 6)))
    return float(X[k]), float(Y[k])


class SheetLayout:
    """The elements of one sheet and the free space left for more.

    The main inscription is registered at the start as "title-block". Free
    space is the frame's interior less `frame_clearance` on each side; new
    drawings keep `gap` mm from every element.
    """

    def __init__(self, page: Page, *, gap: float = 10.0, frame_clearance: float = 5.0) -> None:
        if gap < 0 or frame_clearance < 0:
            raise ValueError("gap and frame_clearance must not be negative")
        self.page = page
        self.gap = float(gap)
        self.frame_clearance = float(frame_clearance)
        self._elements: dict[str, Element] = {}
        self.register("title-block", page.title_block.rect, "title_block")

    @property
    def elements(self) -> tuple[Element, ...]:
        return tuple(self._elements.values())

    def __getitem__(self, name: str) -> Element:
        return self._elements[name]

    @property
    def region(self) -> Rect:
        """Where drawings may go: the frame's interior less the clearance."""
        return self.page.frame.inset(self.frame_clearance)

    def register(self, name: str, shape: FootprintLike, kind: ElementKind = "drawing") -> Element:
        """Record an element that was placed by other means (labels, free drawings)."""
        if name in self._elements:
            raise ValueError(f"an element named {name!r} is already on the sheet")
        element = Element(name, kind, as_footprint(shape))
        self._elements[name] = element
        return element

    def fits(self, rect: Rect, gap: float | None = None, within: Rect | None = None) -> bool:
        """True if rect lies in the region (or `within`) and keeps `gap` from every element."""
        gap = self.gap if gap is None else gap
        region = within if within is not None else self.region
        if not region.contains(rect, tol=1e-6):
            return False
        candidate = box(*rect.bounds)
        return not any(_clash(candidate, e.footprint, gap) for e in self._elements.values())

    def place(
        self,
        name: str,
        width: float,
        height: float,
        *,
        kind: ElementKind = "drawing",
        corner: Corner = "top-left",
        within: Rect | None = None,
        gap: float | None = None,
        near: Rect | None = None,
    ) -> Rect:
        """Find room for a width × height rectangle, register it, return it.

        Candidate positions line up with the region's edges and with the edges
        of placed elements (a gap away); the one nearest `corner` wins, rows
        first: "top-left" fills the top of the sheet from the left, then goes
        down. With `near`, the one nearest that rectangle (`nearest_free`).
        """
        if not (width > 0 and height > 0):
            raise ValueError(f"{name}: a drawing needs a positive size, got {width} x {height}")
        region = within if within is not None else self.region
        rect = self._free(width, height, corner, region, gap, near)
        if rect is not None:
            self.register(name, rect, kind)
            return rect
        raise LayoutError(
            f"{name}: no room for {width:.0f} x {height:.0f} mm on the sheet "
            f"(free region {region.width:.0f} x {region.height:.0f} mm, "
            f"{len(self._elements)} elements placed)"
        )

    def room_near(self, width: float, height: float, near: Rect) -> Rect | None:
        """Where `place` would put a width × height rectangle `near` a
        rectangle, registering nothing; None where the sheet has no room."""
        if not (width > 0 and height > 0):
            return None
        return self._free(width, height, "top-left", self.region, None, near)

    def _free(
        self,
        width: float,
        height: float,
        corner: Corner,
        region: Rect,
        gap: float | None,
        near: Rect | None,
    ) -> Rect | None:
        """`place`'s search: the free width × height rectangle it takes, or None."""
        gap = self.gap if gap is None else float(gap)
        boxes = np.array([e.footprint.bounds for e in self._elements.values()]).reshape(-1, 4)
        if all(_is_box(e.footprint) for e in self._elements.values()):
            at = (
                first_free(region, boxes, width, height, gap, corner)
                if near is None
                else nearest_free(region, boxes, width, height, gap, near)
            )
            return None if at is None else Rect(at[0], at[1], width, height)
        # a footprint of another shape: each candidate tried against it exactly
        for x, y in _candidates(region, boxes, width, height, gap, corner):
            rect = Rect(float(x), float(y), width, height)
            if self.fits(rect, gap, region):
                return rect
        return None

    def overlaps(self, clearance: float = 0.0) -> list[tuple[str, str]]:
        """Pairs of registered elements whose footprints overlap."""
        return find_overlaps(self._elements.values(), clearance)

    def outside(self) -> list[str]:
        """Elements that leave the frame's interior (the main inscription excepted)."""
        frame = box(*self.page.frame.bounds)
        return [
            e.name
            for e in self._elements.values()
            if e.kind != "title_block" and not frame.buffer(_EPS).contains(e.footprint)
        ]

    def problems(self, clearance: float = 0.0) -> list[str]:
        """Human-readable list of overlaps and elements outside the frame."""
        out = [f"{a} overlaps {b}" for a, b in self.overlaps(clearance)]
        out += [f"{name} leaves the frame" for name in self.outside()]
        return out


def pack(
    page: Page,
    items: Sequence[tuple[str, float, float, str]],
    gap: float,
    placed: Mapping[str, Rect] | None = None,
    frame_clearance: float = 5.0,
    known: dict[Any, tuple[float, float] | None] | None = None,
) -> dict[str, Rect] | None:
    """Rectangles for (name, width, height, corner) in turn, as
    SheetLayout.place finds them (first_free: inside the frame less
    `frame_clearance`, `gap` mm from the title block, from those `placed`
    before and from each other, the candidate nearest the corner, rows
    first), without registering footprints: None when one finds no room. The
    packer of both sheets' trial layouts. `known` (a dict kept for one page)
    remembers where each item went after the same items before it, so that
    trials sharing the start of their order place that start once."""
    region = page.frame.inset(frame_clearance)
    tb = page.title_block.rect
    boxes = [(tb.left, tb.bottom, tb.right, tb.top)]
    boxes += [(r.left, r.bottom, r.right, r.top) for r in (placed or {}).values()]
    out: dict[str, Rect] = dict(placed or {})
    start = (gap, frame_clearance, tuple((n, r.x, r.y, r.width, r.height) for n, r in out.items()))
    for i, (name, w, h, corner) in enumerate(items):
        key = (start, tuple(items[: i + 1])) if known is not None else None
        if known is not None and key in known:
            at = known[key]
        else:
            at = first_free(region, np.array(boxes), w, h, gap, corner)
            if known is not None:
                known[key] = at
        if at is None:
            return None
        out[name] = Rect(at[0], at[1], w, h)
        boxes.append((at[0], at[1], at[0] + w, at[1] + h))
    return out
