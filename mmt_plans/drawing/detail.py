"""Detail views (GOST 2.305, "виносний елемент") of any drawing whose names
crowd: a disc of the drawing, marked on it by a thin circle and a capital
letter, drawn again apart at a larger scale of the standard series (2:1, 2.5:1,
4:1, 5:1, 10:1) and lettered there.

A drawing lists the names it writes (`Name`: where each stands, the room it
takes, whether it is an arm's lettered along its arm) and where the names it
wrote crowd (the points they name, found by the sheet linter's rules on the
drawing made without details); `choose_details` picks the discs that hold the
most of the crowd and the ratio at which each disc's names find room. The
drawing itself draws what lies in a disc and letters it only in its detail view
(`clipped` cuts a line at the disc's edge there).
"""

from __future__ import annotations

import math
import re
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np
import shapely

from ..render.backend import PointLike
from ..render.recording import Arc, Arrow, Call, Circle, Line, Polygon, Polyline
from .labels import NEAR_MM

__all__ = [
    "DETAIL_LETTERS",
    "Detail",
    "Name",
    "choose_details",
    "clipped",
    "cut_to_disc",
    "heads_outside",
    "name_area",
    "outline_in_disc",
    "roomy_ratio",
    "spread",
]


@dataclass(frozen=True)
class Detail:
    """A detail view: the disc of `radius` round `centre` (both in the
    drawing's own unit, m or m/s, so at any of its scales) where its names
    crowd, drawn again `ratio` times larger and lettered there; the drawing
    marks it with a thin circle and `letter`."""

    letter: str
    centre: tuple[float, float]
    radius: float
    ratio: float


@dataclass(frozen=True)
class Name:
    """A name a drawing writes: where it stands (mm at the drawing's scale),
    the area of its box (mm²) and, for an arm's name lettered along its arm,
    that arm's length (mm)."""

    at: np.ndarray
    area: float
    arm_mm: float | None = None


# the series of a detail's scales (GOST 2.302: 2:1, 2.5:1, 4:1, 5:1, 10:1)
DETAIL_RATIOS = (2.0, 2.5, 4.0, 5.0, 10.0)
# the radii (mm at the drawing's scale) of the discs tried round a crowd
DETAIL_RADII = (8.0, 12.0, 16.0, 20.0, 25.0)
# the share of a detail's disc (widened by NEAR_MM) its names may cover:
NAME_SHARE = 0.12
DETAIL_MM = 70.0  # the largest radius of a detail's disc, mm
ARM_NAMED_MM = 6.0  # the shortest arm a detail names along it, mm
# a detail's letter: a capital that names no point, force or arm (G, F, R, M, S,
# K, P, O, I, Q, J read as loads, images or digits)
DETAIL_LETTERS = "ABCDEHLNTUVWXYZ"
# where a detail's letter is tried by its disc's rim, in turn: up and right
# first, then the other diagonals, then up, right, left and down
_DIAGONAL = math.sqrt(0.5)
_RIM_DIRECTIONS = (
    (_DIAGONAL, _DIAGONAL),
    (-_DIAGONAL, _DIAGONAL),
    (_DIAGONAL, -_DIAGONAL),
    (-_DIAGONAL, -_DIAGONAL),
    (0.0, 1.0),
    (1.0, 0.0),
    (-1.0, 0.0),
    (0.0, -1.0),
)
LETTER_W = 2.3  # mm per character of a 3.5 mm name, a bound for counting room
_TEXT = 3.5


def name_area(markup: str) -> float:
    """A bound of the area (mm²) a 3.5 mm name `markup` takes with its clearance."""
    return (len(re.sub(r"[_{}]", "", markup)) * LETTER_W + 1.5) * (_TEXT + 1.5)


def choose_details(
    names: Sequence[Name],
    crowded: np.ndarray,
    centres: Iterable[np.ndarray],
    mu: float,
    letters: Iterable[str],
    most: int,
    *,
    points: np.ndarray | None = None,
    spacing: float = 0.0,
    widest: float = DETAIL_MM,
    tightest: float | None = None,
    radii: Sequence[float] = DETAIL_RADII,
    fewest: int = 1,
    ratios: Sequence[float] = DETAIL_RATIOS,
) -> tuple[Detail, ...]:
    """The detail views a drawing at `mu` needs where the names standing for
    the points `crowded` (mm) found no place near: at most `most` discs
    apart, each round one of `centres` or such a point, of a radius of
    DETAIL_RADII, each holding the most of those points left (the largest
    such: the whole crowd); each drawn at the first ratio of the series that
    leaves `names` in it NAME_SHARE of its room and names its shortest arm
    along it (or draws the disc `widest` wide); lettered in turn by `letters`.
    With `points` (mm, what the drawing names at their places: a mechanism's
    points), the ratio also sets those in the disc `spacing` apart (a quarter
    of them nearer their neighbour at most: `spread`); with `tightest` (a
    share), the smallest disc of `radii` that holds that share of the most
    any holds: the crowd's core, whose loads and names crowd the rest. A disc
    past the first is taken only where it holds `fewest` of those points at
    least (a crowd of its own, not a name or two a leader serves). `ratios`:
    the series its ratios are taken from."""
    where = np.array([n.at for n in names], dtype=float).reshape(-1, 2)
    areas = np.array([n.area for n in names])
    arms = np.array([math.inf if n.arm_mm is None else n.arm_mm for n in names])
    candidates = [*centres, *crowded]
    out: list[Detail] = []
    left = np.ones(len(crowded), dtype=bool)  # the crowded names no disc taken holds
    for letter in list(letters)[:most]:
        discs: list[tuple[int, float, np.ndarray]] = []  # held, radius, centre
        for c in candidates:
            near = np.hypot(*(crowded - c).T) if len(crowded) else np.zeros(0)
            for r in radii:
                if any(math.dist(c, np.asarray(d.centre) / mu) < r + d.radius / mu for d in out):
                    continue  # discs apart: a name is the drawing's or one detail's
                held = int(((near <= r) & left).sum())
                if held:
                    discs.append((held, r, c))
        if not discs:
            break
        most_held = max(h for h, _, _ in discs)
        if out and most_held < fewest:
            break
        if tightest is None:
            best = max(discs, key=lambda d: (d[0], d[1]))
        else:  # the smallest of those that hold nearly the most
            best = min(
                (d for d in discs if d[0] >= tightest * most_held), key=lambda d: (d[1], -d[0])
            )
        r, c = best[1], best[2]
        left &= np.hypot(*(crowded - c).T) > r
        inside = np.hypot(*(where - c).T) <= r
        demand = float(areas[inside].sum())
        # the arms in the disc long enough, at the ratio, to be named along
        shortest = float(arms[inside].min()) if inside.any() else math.inf
        apart = spread(points[np.hypot(*(points - c).T) <= r]) if points is not None else math.inf
        ratio = roomy_ratio(
            demand, r, shortest, ratios=ratios, widest=widest, apart=apart, spacing=spacing
        )
        out.append(Detail(letter, (float(c[0]) * mu, float(c[1]) * mu), r * mu, ratio))
    return tuple(out)


def roomy_ratio(
    demand: float,
    r: float,
    shortest: float,
    *,
    ratios: Sequence[float] = DETAIL_RATIOS,
    widest: float = DETAIL_MM,
    apart: float = math.inf,
    spacing: float = 0.0,
) -> float:
    """The first of `ratios` at which a disc of radius `r` (mm at the
    drawing's scale) leaves the names in it (`demand`, mm² of boxes)
    NAME_SHARE of its room, names its `shortest` arm along it and sets its
    points `apart` at least `spacing` apart, or draws it `widest` wide; the
    last ratio if none does."""
    return next(
        (
            k
            for k in ratios
            if (
                demand <= NAME_SHARE * math.pi * (k * r + NEAR_MM) ** 2
                and k * shortest >= ARM_NAMED_MM
                and k * apart >= spacing
            )
            or k * r >= widest
        ),
        ratios[-1],
    )


def spread(points: np.ndarray, merged: float = 0.3) -> float:
    """How far apart `points` (mm) stand: the distance to its nearest
    neighbour that a quarter of them are nearer than (points nearer than
    `merged` are one place, named once); inf for fewer than two places."""
    pts = np.asarray(points, float).reshape(-1, 2)
    if len(pts) < 2:
        return math.inf
    d = np.hypot(*(pts[:, None, :] - pts[None, :, :]).transpose(2, 0, 1))
    d[d < merged] = math.inf
    nearest = d.min(axis=1)
    nearest = nearest[np.isfinite(nearest)]
    return float(np.percentile(nearest, 25)) if len(nearest) else math.inf


def clipped(
    a: np.ndarray, b: np.ndarray, centre: np.ndarray, radius: float
) -> tuple[np.ndarray, np.ndarray] | None:
    """The part of the segment a–b inside the disc, or None."""
    d = b - a
    f = a - centre
    A = float(np.dot(d, d))
    if A < 1e-12:
        return (a, b) if float(np.hypot(*f)) <= radius else None
    B = 2.0 * float(np.dot(f, d))
    C = float(np.dot(f, f)) - radius * radius
    disc = B * B - 4.0 * A * C
    if disc <= 0.0:
        return None
    root = math.sqrt(disc)
    t0, t1 = max(0.0, (-B - root) / (2.0 * A)), min(1.0, (-B + root) / (2.0 * A))
    if t1 - t0 < 1e-9:
        return None
    return a + t0 * d, a + t1 * d


def outline_in_disc(c: Polyline, disc: Any) -> list[Call]:
    """The parts of an outline (a polygon's area, a polyline's run) inside a
    detail's `disc` (a shapely polygon), each an outline of its kind."""
    shape = shapely.Polygon(c.vertices) if isinstance(c, Polygon) else None
    cut = (shape if shape is not None else shapely.LineString(c.vertices)).intersection(disc)
    kept: list[Call] = []
    for g in getattr(cut, "geoms", [cut]):
        if g.is_empty:
            continue
        if g.geom_type == "Polygon":
            kept.append(c.with_changes(vertices=tuple(g.exterior.coords[:-1])))
        elif g.geom_type == "LineString":
            kept.append(c.with_changes(vertices=tuple(g.coords)))
    return kept


def cut_to_disc(
    calls: Sequence[Call], centre: np.ndarray, radius: float, arrows: bool = True
) -> list[Call]:
    """A detail view's `calls` cut at its disc's edge: lines and outlines
    clipped; an arrow clipped, its head kept where its end lies in the disc (a
    plain line of its kind where it does not), or kept whole without `arrows`
    (a load applied in the view); circles and arcs kept where their centre is
    in it; the rest (lettering) kept."""
    disc = shapely.Point(*map(float, centre)).buffer(radius, 64)
    kept: list[Call] = []
    for c in calls:
        if isinstance(c, Line) or (arrows and isinstance(c, Arrow)):
            part = clipped(np.asarray(c.start, float), np.asarray(c.end, float), centre, radius)
            if part is None:
                continue
            start, end = (
                (float(part[0][0]), float(part[0][1])),
                (float(part[1][0]), float(part[1][1])),
            )
            if isinstance(c, Arrow) and math.dist(end, c.end) > 1e-9:
                kept.append(Line("line", {"start": start, "end": end, "line": c.line}, c.groups))
            else:
                kept.append(c.with_changes(start=start, end=end))
        elif isinstance(c, Polyline):
            kept += outline_in_disc(c, disc)
        elif isinstance(c, (Circle, Arc)):
            if math.dist(c.center, centre) <= radius:
                kept.append(c)
        else:
            kept.append(c)
    return kept


def heads_outside(calls: Sequence[Call], discs: Sequence[tuple[np.ndarray, float]]) -> list[Call]:
    """A drawing's `calls` with its details' `discs` marked: an arrow whose
    head lies in a disc is drawn (a plain line of its kind) only up to the
    disc's edge, its head and name being its detail view's; one wholly in the
    disc only there. The rest kept."""
    kept: list[Call] = []
    for c in calls:
        disc = (
            next((d for d in discs if math.dist(c.end, d[0]) <= d[1]), None)
            if isinstance(c, Arrow)
            else None
        )
        if not isinstance(c, Arrow) or disc is None:
            kept.append(c)
            continue
        start = np.asarray(c.start, float)
        part = clipped(start, np.asarray(c.end, float), *disc)
        if part is None or float(np.hypot(*(part[0] - start))) < 1e-9:
            continue
        edge = (float(part[0][0]), float(part[0][1]))
        kept.append(Line("line", {"start": c.start, "end": edge, "line": c.line}, c.groups))
    return kept


def rim_anchors(centre: PointLike, radius: float) -> list[tuple[np.ndarray, np.ndarray]]:
    """Where a detail's letter is tried by its disc (centre, radius, mm):
    (anchor, towards) pairs on the rim, up and right first, each pointing
    away from the centre (`Labels.place_first`); the first is where
    the drawings write it."""
    middle = np.asarray(centre, dtype=float)
    rims = [middle + radius * np.array(u) for u in _RIM_DIRECTIONS]
    return [(rim, rim - middle) for rim in rims]
