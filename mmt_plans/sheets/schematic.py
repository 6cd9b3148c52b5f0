"""A small kinematic scheme of a mechanism at one position, to check a task at a glance.

The scheme is the mechanism at position 0 of its study (the file's φ1 where
the study gives one, since seed 002's files set `zero = φ1`) in the
conventional symbols: frame pivots and guides hatched, links as main lines,
revolute joints as small circles, sliders as rectangles on their guides, the
crank's ω1 as an arc with an arrowhead in the drive's sense, point letters,
link numbers, and the working direction of the output. It is scaled to fit a
box (no standard scale: it is a picture, not a drawing to measure).

`write_task_schematics` lays out one scheme per task file on a contact sheet;
`write_task_files` draws the first variant of each task on its own page.
"""

from __future__ import annotations

import math
import os
import re
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
from shapely.geometry import LineString

from ..drawing.labels import Labels, arc_line
from ..drawing.markup import point_markup
from ..drawing.page import Page, Rect, draw_frame
from ..drawing.pose import Block, Guide, GuideKind, Pose, draw_poses
from ..drawing.sketch import Sketch
from ..drawing.symbols import unit_vector
from ..errors import shown
from ..i18n import Language, catalogue, check_language
from ..model import FRAME, Mechanism, Prismatic
from ..render.output import write_drawing
from ..render.recording import RecordingBackend
from ..solution import Solution

__all__ = [
    "FrameDimension",
    "frame_dimensions",
    "LABEL_GROUP",
    "NUMBER_GROUP",
    "sketch_schematic",
    "sketch_caption",
    "task_of",
    "write_task_schematics",
    "write_task_files",
]

LABEL_GROUP = "point-"  # + point name: the group of one point letter
NUMBER_GROUP = "link-"  # + link id: the group of one link number

_LETTER = 2.5  # point letters and link numbers, mm
_CAPTION = 2.5
_PIN = 0.9  # radius of a revolute joint, mm
_CLEAR = 0.35  # letters and the ω1 arc keep this far off drawn lines, mm
_POINT_GAP = 1.5  # a point's letter this far from the point, mm
# a letter crowded out of the places beside what it names goes at most this much
# further (mm), and else where it covers least: a scheme is small, and a letter
# far off names nothing
_RINGS = (0.0, 1.0, 2.0, 3.5, 5.0)
_BLOCK = (3.2, 1.9)  # half length and half height of a slider, mm
_RAM = 1.45  # a slider that carries another one at its point is drawn this much larger
_BASE = (6.0, 3.2)  # width and depth of a frame pivot's symbol, mm
_GUIDE_MARGIN = 4.0  # a guide runs this far past the slider's stroke, mm
_DENSE = 145  # crank angles of the sweep that finds the strokes along the guides
_PAD = 2.0  # Sketch.extent's clearance

# --- the mechanism at one position -------------------------------------------------


@dataclass(frozen=True)
class _Guide:
    """A prismatic pair at the drawn position: the line (m) and the slider on it."""

    pair: Prismatic
    u: np.ndarray  # unit direction, global
    ends: tuple[np.ndarray, np.ndarray]  # the stroke of the slider point along the line, m
    at: np.ndarray  # the slider point, m


def _pose(solution: Solution, k: int) -> tuple[dict[str, np.ndarray], list[_Guide]]:
    """Every named point at entry k (m) and every guide with its stroke."""
    mech = solution.mechanism
    sw = solution.sweep
    problem = solution.problem(k)
    if problem is not None and not bool(sw.ok[k]):
        raise problem
    pts = {n: np.asarray(sw.points[n][k], dtype=float) for n in mech.point_owners}
    dense = solution.dense  # the turn from position 0
    ok = np.asarray(dense.ok, dtype=bool)
    guides = []
    for pair in mech.sliders:
        d_local = complex(*np.asarray(pair.direction, dtype=float))
        t_local = complex(*np.asarray(pair.through, dtype=float))

        def line(sweep: Any, idx: Any) -> tuple[np.ndarray, np.ndarray]:
            if pair.guide == FRAME:
                return np.full_like(sweep.phi1_deg[idx], t_local, dtype=complex), np.full_like(
                    sweep.phi1_deg[idx], d_local, dtype=complex
                )
            state = sweep.links[pair.guide]
            return state.at(t_local)[idx], state.e[idx] * d_local

        g, u = line(dense, ok)
        s = ((dense.position_of(pair.slider_point)[ok] - g) * np.conj(u)).real
        g_k, u_k = line(sw, [k])
        g0, u0 = complex(g_k[0]), complex(u_k[0])
        ends = (g0 + float(s.min()) * u0, g0 + float(s.max()) * u0)
        guides.append(
            _Guide(
                pair,
                np.array([u0.real, u0.imag]),
                tuple(np.array([e.real, e.imag]) for e in ends),  # type: ignore[arg-type]
                pts[pair.slider_point],
            )
        )
    return pts, guides


def _free_direction(directions: Iterable[np.ndarray]) -> np.ndarray:
    """The middle of the widest gap between directions leaving a point."""
    # in [0, 2π), rounded: a direction along an axis must not come out as +π
    # or -π by the sign of a rounding error
    angles = sorted(
        {
            round(math.atan2(d[1], d[0]) % (2 * math.pi), 6) % round(2 * math.pi, 6)
            for d in directions
            if float(np.hypot(*d)) > 1e-9
        }
    )
    if not angles:
        return np.array([math.cos(math.radians(45)), math.sin(math.radians(45))])
    gaps = [
        ((angles[(i + 1) % len(angles)] - a) % (2 * math.pi) or 2 * math.pi, a)
        for i, a in enumerate(angles)
    ]
    gap, a = max(gaps)
    mid = a + gap / 2.0
    return np.array([math.cos(mid), math.sin(mid)])


def _clear_of_pivots(
    lo: float,
    hi: float,
    at: np.ndarray,
    u: np.ndarray,
    n: np.ndarray,
    grow: float,
    pivots: Sequence[np.ndarray],
    hatched: bool = True,
) -> tuple[float, float]:
    """Shorten a guide (lo..hi along u from the slider at `at`) that would run
    through the symbol of a frame pivot, keeping the side the slider is on."""
    for p in pivots:
        across = float(np.dot(p - at, n))
        # a frame guide lies _BLOCK[1]·grow under the path, a slot on it; the
        # pivot's symbol reaches _BASE[1] under p
        low = -(_BASE[1] + _BLOCK[1] * grow + 2.0) if hatched else -(_BASE[1] + 1.0)
        if not low < across < 2.0:
            continue
        t = float(np.dot(p - at, u))
        half = _BASE[0] / 2.0 + 1.5
        if lo < t + half and t - half < hi:
            if t < 0.0:
                lo = max(lo, min(t + half, -_BLOCK[0] * grow - 1.0))
            else:
                hi = min(hi, max(t - half, _BLOCK[0] * grow + 1.0))
    return lo, hi


def _scheme(
    mech: Mechanism,
    P: dict[str, np.ndarray],
    guides: Sequence[_Guide],
    scale: float,
    carried: set[str],
    lines_at: dict[str, list[np.ndarray]],
) -> Pose:
    """The scheme's pose in mm; `lines_at` gets the directions of the lines
    leaving each point, where its letter must not go."""
    owners = mech.point_owners
    # Guides of the frame, hatched on the side away from the crank's pivot;
    # the slot of a moving link a main line along it over the stroke.
    centre = P[mech.crank_pivot]
    pivots = [P[n] for n, o in owners.items() if FRAME in o and len(o) > 1]
    drawn_guides = []
    for g in guides:
        u = g.u.copy()
        n = np.array([-u[1], u[0]])
        at = g.at * scale
        if float(np.dot(centre - at, n)) < -1e-6:
            u, n = -u, -n
        a, b = g.ends[0] * scale, g.ends[1] * scale
        lo, hi = sorted((float(np.dot(a - at, u)), float(np.dot(b - at, u))))
        grow = _RAM if g.pair.guide == FRAME and g.pair.slider_point in carried else 1.0
        lo -= _BLOCK[0] * grow + _GUIDE_MARGIN
        hi += _BLOCK[0] * grow + _GUIDE_MARGIN
        lo, hi = _clear_of_pivots(lo, hi, at, u, n, grow, pivots, hatched=g.pair.guide == FRAME)
        lines_at[g.pair.slider_point] += [u, -u]
        kind: GuideKind = "frame" if g.pair.guide == FRAME else "slot"
        drawn_guides.append(Guide(at + lo * u, at + hi * u, u, kind, _BLOCK[1] * grow))

    # Links: a main line between every two of their points.
    for link in mech.links.values():
        names = [p for p in link.points if p in P]
        for i in range(len(names)):
            for j in range(i + 1, len(names)):
                a, b = P[names[i]], P[names[j]]
                if float(np.hypot(*(b - a))) > 1e-6:
                    lines_at[names[i]].append(b - a)
                    lines_at[names[j]].append(a - b)

    # Sliders: frame-guided ones first, so that a block in a slot lies on top.
    blocks = []
    for g in sorted(guides, key=lambda g: g.pair.guide != FRAME):
        grow = _RAM if g.pair.guide == FRAME and g.pair.slider_point in carried else 1.0
        size = (_BLOCK[0] * grow, _BLOCK[1] * grow)
        blocks.append(Block((g.pair.slider, g.pair.guide), g.at * scale, g.u, size))

    # Joints: circles where links meet, a dot at a point of one link only.
    joints = [name for name, o in owners.items() if FRAME not in o]
    bases = [name for name, o in owners.items() if FRAME in o and len(o) > 1]
    for name in bases:
        lines_at[name] += [
            np.array([-1.0, -1.5]),
            np.array([1.0, -1.5]),
            np.array([0.0, -1.0]),
        ]
    return Pose(
        P,
        [link.points for link in mech.links.values()],
        pins=joints,
        pin_radius=_PIN,
        dots=frozenset(name for name in joints if len(owners[name]) == 1),
        pivots=bases,
        base=_BASE,
        guides=drawn_guides,
        blocks=blocks,
    )


def _draw(
    solution: Solution,
    k: int,
    scale: float,
    look: Any,
    pose: tuple[dict[str, np.ndarray], list[_Guide]],
) -> Sketch:
    """The scheme at `scale` mm per m, in local mm."""
    mech = solution.mechanism
    pts_m, guides = pose
    P = {n: p * scale for n, p in pts_m.items()}
    owners = mech.point_owners
    sk = Sketch(look)
    # Sliders that carry another slider at their point (a ram with the block of
    # a slot, a crosshead with its slot) are drawn larger, the other on top.
    carried = {g.pair.slider_point for g in guides if g.pair.guide != FRAME}
    lines_at: dict[str, list[np.ndarray]] = {n: [] for n in P}

    with sk.group("schematic", "schematic"):
        centre = P[mech.crank_pivot]
        draw_poses(sk, [_scheme(mech, P, guides, scale, carried, lines_at)])

        # What the ω1 arc, the output's arrow and the lettering keep clear of.
        labels = Labels(sk, _LETTER, rings=_RINGS, follow=False, leaders=False)
        labels.avoid_drawn(sk.calls, _CLEAR, solid=True)

        # ω1: an arc round the crank's pivot, clear of the crank and the base.
        pin = P[mech.crank_pin]
        crank_mm = float(np.hypot(*(pin - centre)))
        r = min(7.0, max(4.0, 0.45 * crank_mm))
        # rounded, so that the last bits of the solution cannot flip a near tie
        mid = float(
            min(
                range(0, 360, 10),
                key=lambda m: round(
                    labels.covered(arc_line(centre, r, m - 50, m + 50).buffer(1.2)), 2
                ),
            )
        )
        head = math.degrees(2.0 / r)  # the arrowhead takes about 2 mm of the arc
        ccw = mech.drive.sense == "ccw"
        a0, a1 = mid - 50.0, mid + 50.0
        tip, tail = (a1, a1 - head) if ccw else (a0, a0 + head)

        def on_arc(deg: float) -> np.ndarray:
            return centre + r * np.array([math.cos(math.radians(deg)), math.sin(math.radians(deg))])

        drawn = len(sk.calls)
        sk.arc(centre, r, a0 if ccw else a0 + head * 0.5, a1 - head * 0.5 if ccw else a1, "thin")
        sk.arrow(on_arc(tail), on_arc(tip), "thin", head_length=2.0, head_width=1.2)
        labels.avoid_drawn(sk.calls[drawn:], _CLEAR, solid=True)
        omega_dir = on_arc(mid) - centre
        omega_at = on_arc(mid)

        # The output's working direction: an arrow beside the output point.
        out = mech.study.output
        w = unit_vector(np.asarray(mech.study.working_direction, dtype=float))
        wn = np.array([-w[1], w[0]])
        q = P[out]
        # Ahead of the block on its path if that is free, else beside it.
        s = q + (_BLOCK[0] * _RAM + 1.5) * w
        choices = [(s, s + 8.0 * w)]
        for side in (1.0, -1.0):
            s = q + side * (_BLOCK[1] * _RAM + 2.2) * wn - 3.5 * w
            choices.append((s, s + 8.0 * w))
        a, b = min(choices, key=lambda ab: round(labels.covered(LineString(ab).buffer(1.0)), 2))
        drawn = len(sk.calls)
        sk.arrow(a, b, "main", head_length=2.5, head_width=1.4)
        labels.avoid_drawn(sk.calls[drawn:], _CLEAR, solid=True)

        # Letters of the points, then the numbers of the links.
        labels.place(
            omega_at, "ω_{1}", towards=unit_vector(omega_dir), distance=1.0, group="omega-1"
        )
        # the letter of a slider's point goes outside its block
        gap = {name: _POINT_GAP for name in P}
        for g in guides:
            grow = _RAM if g.pair.guide == FRAME and g.pair.slider_point in carried else 1.0
            gap[g.pair.slider_point] = max(gap[g.pair.slider_point], _BLOCK[1] * grow + 0.5)
        for name in sorted(P, key=lambda n: (FRAME not in owners[n], n)):
            labels.place(
                P[name],
                point_markup(name),
                towards=_free_direction(lines_at[name]),
                distance=gap[name],
                group=f"{LABEL_GROUP}{name}",
            )
        guide_of = {g.pair.slider: g for g in guides}
        for lid, link in mech.links.items():
            group = f"{NUMBER_GROUP}{lid}"
            names = [p for p in link.points if p in P]
            segs = [
                (P[names[i]], P[names[j]])
                for i in range(len(names))
                for j in range(i + 1, len(names))
            ]
            segs = [s for s in segs if float(np.hypot(*(s[1] - s[0]))) > 1e-6]
            if segs:
                # beside the link's longest line, at its middle if that is free
                a, b = max(segs, key=lambda s: float(np.hypot(*(s[1] - s[0]))))
                labels.place_along(a, b, str(lid), distance=0.8, group=group)
            elif lid in guide_of:
                # beside the slider's block
                g = guide_of[lid]
                grow = _RAM if g.pair.guide == FRAME and g.pair.slider_point in carried else 1.0
                c, half = P[g.pair.slider_point], (_BLOCK[0] * grow + 1.0) * g.u
                labels.place_along(
                    c - half, c + half, str(lid), distance=_BLOCK[1] * grow + 0.4, group=group
                )
            elif names:
                labels.place(
                    P[names[0]],
                    str(lid),
                    towards=np.array([0.0, 1.0]),
                    distance=_POINT_GAP,
                    group=group,
                )
    return sk


_DIM_STEP = 5.0  # mm between stacked dimension lines
_DIM_TEXT = 2.2  # mm


@dataclass(frozen=True)
class FrameDimension:
    """A distance of the frame's geometry from the crank's pivot, in m."""

    horizontal: bool  # measured along x (drawn below), else along y (drawn left)
    start: str  # the crank's pivot
    end: str  # a frame point, or "guide <slider point>"
    value: float  # signed, m (end less start)


def frame_dimensions(mech: Any) -> list[FrameDimension]:
    """The frame's dimensions of a task's scheme: each frame point's dx and dy
    from the crank's pivot, and each frame guide's offset from it."""
    pivot = mech.crank_pivot
    o = np.asarray(mech.frame[pivot], dtype=float)
    out = []
    for name, p in mech.frame.items():
        d = np.asarray(p, dtype=float) - o
        if name == pivot:
            continue
        if abs(d[0]) > 1e-9:
            out.append(FrameDimension(True, pivot, name, float(d[0])))
        if abs(d[1]) > 1e-9:
            out.append(FrameDimension(False, pivot, name, float(d[1])))
    for pair in mech.sliders:
        if pair.guide != FRAME:
            continue
        u = np.asarray(pair.direction, dtype=float)
        t = np.asarray(pair.through, dtype=float) - o
        if abs(u[1]) < 1e-9 and abs(t[1]) > 1e-9:  # a horizontal guide: its height
            out.append(FrameDimension(False, pivot, f"guide {pair.slider_point}", float(t[1])))
        elif abs(u[0]) < 1e-9 and abs(t[0]) > 1e-9:  # a vertical guide: its x
            out.append(FrameDimension(True, pivot, f"guide {pair.slider_point}", float(t[0])))
    return out


def _draw_dimensions(
    sk: Sketch,
    solution: Solution,
    scale: float,
    shift: np.ndarray,
    dims: list[FrameDimension],
    lang: Language,
) -> None:
    """Dimension lines for `dims` below and left of what `sk` holds; a point p
    (m) of the scheme is at p·scale + shift (mm)."""
    mech = solution.mechanism
    pivot = mech.crank_pivot

    def at(p: np.ndarray) -> np.ndarray:
        return np.asarray(p, dtype=float) * scale + shift

    pts = {pivot: np.asarray(mech.frame[pivot], dtype=float)}
    cat = catalogue(lang)
    ext = sk.extent()
    o = at(pts[pivot])
    n_h = n_v = 0
    with sk.group("dimensions", "dimensions"):
        for d in dims:
            if d.end.startswith("guide "):
                end_m = pts[pivot] + ([d.value, 0.0] if d.horizontal else [0.0, d.value])
            else:
                end_m = np.asarray(mech.frame[d.end], dtype=float)
            e = at(end_m)
            text = cat.plain_number(round(abs(d.value) * 1e3, 6) + 0.0)
            if d.horizontal:
                y = ext.y + _PAD - _DIM_STEP * (n_h + 0.6)
                n_h += 1
                for p in (o, e):
                    sk.line((p[0], p[1]), (p[0], y - 1.0), "thin")
                mid = ((o[0] + e[0]) / 2.0, y)
                for end in (o[0], e[0]):
                    sk.arrow(mid, (end, y), "thin", head_length=1.8, head_width=0.7)
                sk.text((mid[0], y + 0.6), text, _DIM_TEXT, anchor="center")
            else:
                x = ext.x + _PAD - _DIM_STEP * (n_v + 0.6)
                n_v += 1
                for p in (o, e):
                    sk.line((p[0], p[1]), (x - 1.0, p[1]), "thin")
                mid = (x, (o[1] + e[1]) / 2.0)
                for end in (o[1], e[1]):
                    sk.arrow(mid, (x, end), "thin", head_length=1.8, head_width=0.7)
                sk.text((x - 0.6, mid[1]), text, _DIM_TEXT, anchor="center", rotation=90.0)


def _geometry_bounds(
    pose: tuple[dict[str, np.ndarray], list[_Guide]],
) -> tuple[float, float, float, float]:
    pts_m, guides = pose
    xy = list(pts_m.values()) + [e for g in guides for e in g.ends]
    arr = np.array(xy, dtype=float)
    return (
        float(arr[:, 0].min()),
        float(arr[:, 1].min()),
        float(arr[:, 0].max()),
        float(arr[:, 1].max()),
    )


def _shifted(sk: Sketch, dx: float, dy: float) -> Sketch:
    out = Sketch(sk.look)
    sk.replay(out, dx, dy)
    return out


def sketch_schematic(
    solution: Solution,
    look: Any,
    lang: Language = "en",
    *,
    width_mm: float = 100.0,
    height_mm: float = 70.0,
    position: int = 0,
    dimensions: bool = False,
) -> Sketch:
    """The kinematic scheme at `position`, fitted into the box (0, 0)–(width_mm, height_mm).

    Every point letter is drawn in a group "point-<name>", every link number
    in a group "link-<id>" (class "label"), so that they can be found again.
    With `dimensions`, the frame's geometry is dimensioned below and left of
    the scheme in mm (group "dimensions"): each frame point's horizontal and
    vertical distance from the crank's pivot, and each frame guide's distance
    from it across the guide (`frame_dimensions`).
    """
    check_language(lang)
    if dimensions:
        dims = frame_dimensions(solution.mechanism)
        left = _DIM_STEP * (sum(not d.horizontal for d in dims) + 0.5)
        below = _DIM_STEP * (sum(d.horizontal for d in dims) + 0.5)
        inner, scale, shift = _fitted(solution, look, width_mm - left, height_mm - below, position)
        out = _shifted(inner, left, below)
        _draw_dimensions(out, solution, scale, shift + np.array([left, below]), dims, lang)
        return out
    return _fitted(solution, look, width_mm, height_mm, position)[0]


def _fitted(
    solution: Solution, look: Any, width_mm: float, height_mm: float, position: int
) -> tuple[Sketch, float, np.ndarray]:
    """The scheme fitted into the box, its scale (mm per m) and its shift (mm):
    a point p (m) is drawn at p·scale + shift."""
    k = solution.entry(position)
    pose = _pose(solution, k)
    x0, y0, x1, y1 = _geometry_bounds(pose)
    gw, gh = max(x1 - x0, 1e-6), max(y1 - y0, 1e-6)
    scale = min((width_mm - 16.0) / gw, (height_mm - 16.0) / gh)
    scale = max(scale, 1e-3)
    sk = _draw(solution, k, scale, look, pose)
    for _ in range(6):
        ext = sk.extent()
        if ext.width <= width_mm + 1e-6 and ext.height <= height_mm + 1e-6:
            break
        # The symbols keep their size in mm; only the geometry scales.
        over_w, over_h = ext.width - gw * scale, ext.height - gh * scale
        fit = min((width_mm - over_w) / (gw * scale), (height_mm - over_h) / (gh * scale))
        scale *= max(0.3, min(0.97, fit * 0.99))
        sk = _draw(solution, k, scale, look, pose)
    ext = sk.extent()
    if ext.width > width_mm + 1e-6 or ext.height > height_mm + 1e-6:
        raise ValueError(
            f"{shown(solution.mechanism.path)}: the scheme does not fit {width_mm:g} x {height_mm:g} mm"
        )
    dx = (width_mm - ext.width) / 2.0 - ext.x
    dy = (height_mm - ext.height) / 2.0 - ext.y
    return _shifted(sk, dx, dy), scale, np.array([dx, dy])


# --- captions, contact sheets, files of one task -------------------------------------


def task_of(path: str | os.PathLike[str]) -> tuple[int, int] | None:
    """(task, variant) from a file name "task03_v2" or "task3_v07"."""
    m = re.search(r"task(\d+)_v(\d+)", Path(path).stem)
    return (int(m.group(1)), int(m.group(2))) if m else None


def _formula(sk: Sketch, pos: tuple[float, float], formula: str, size: float) -> float:
    """The structural formula with drawn arrows (osifont has no arrow glyph); its width."""
    x, y = pos
    start = x
    for i, part in enumerate(str(formula).split("<-")):
        if i:
            sk.arrow(
                (x + 4.5, y + size * 0.35),
                (x + 1.0, y + size * 0.35),
                "thin",
                head_length=1.5,
                head_width=1.0,
            )
            x += 5.5
        x += sk.rich_text((x, y), part.strip(), size)
    return x - start


def sketch_caption(
    solution: Solution,
    path: str | os.PathLike[str],
    look: Any,
    lang: Language,
    width: float,
    size: float = _CAPTION,
) -> Sketch:
    """Two lines centred on x = 0 under y = 0: "Task 3, variant 2, φ1 = …" and the formula."""
    words = catalogue(lang).words("schematic")
    tv = task_of(path)
    first = words["task"].format(task=tv[0], variant=tv[1]) if tv else str(solution.mechanism.title)
    if solution.mechanism.study.zero is not None:
        first += ", " + words["position"].format(phi=float(solution.positions[0].phi1_deg))
    sk = Sketch(look)
    sk.text((0.0, -size), first, size, anchor="center", max_width=width)
    probe = Sketch(look)
    w = _formula(probe, (0.0, 0.0), solution.structure.formula, size)
    probe.replay(sk, -w / 2.0, -2.0 * size - 2.0)
    return sk


def _grid(
    page: Page, rows: int, cols: int, head: float, caption: float
) -> tuple[Page, float, float]:
    best = None
    for p in (page.landscape(), page.portrait()):
        f = p.frame.inset(4.0)
        cw, ch = f.width / cols, (f.height - head) / rows
        score = min(cw, ch - caption)
        if best is None or score > best[0]:
            best = (score, p, cw, ch)
    assert best is not None
    return best[1], best[2], best[3]


def _task_files(task_dir: str | os.PathLike[str]) -> list[Path]:
    files = sorted(Path(task_dir).glob("*.toml"), key=lambda p: (task_of(p) or (0, 0), p.name))
    if not files:
        raise FileNotFoundError(f"no mechanism files in {task_dir}")
    return files


def write_task_schematics(
    task_dir: str | os.PathLike[str],
    out_svg: str | os.PathLike[str],
    lang: Language = "en",
    *,
    page: str = "A2",
) -> Path:
    """One small scheme per task file on one page: a row per task, a column per variant."""
    from ..solution import solve
    from ..spec import load

    files = _task_files(task_dir)
    tasks = sorted({(task_of(f) or (0, 0))[0] for f in files})
    variants = sorted({(task_of(f) or (0, 0))[1] for f in files})
    caption_h = 2.0 * _CAPTION + 5.0
    head = 10.0
    pg, cw, ch = _grid(Page.of(page), len(tasks), len(variants), head, caption_h)
    frame = pg.frame.inset(4.0)
    title = f"{Path(task_dir).name}: task schematics"
    backend = RecordingBackend(pg.width, pg.height)
    draw_frame(backend, pg)
    look = backend.look
    seed = Path(task_dir).name
    with backend.group("heading", "heading"):
        backend.text(
            (frame.left, frame.top - 5.0),
            catalogue(lang).words("schematic")["heading"].format(seed=seed),
            3.5,
            valign="middle",
        )
    top = frame.top - head
    for f in files:
        tv = task_of(f) or (0, 0)
        row, col = tasks.index(tv[0]), variants.index(tv[1])
        cell = Rect(frame.left + col * cw, top - (row + 1) * ch, cw, ch)
        solution = solve(load(f))
        sk = sketch_schematic(
            solution, look, lang, width_mm=cw - 2.0, height_mm=ch - caption_h - 1.0
        )
        with backend.group(f"cell-{f.stem}", "cell"):
            backend.rectangle((cell.x, cell.y), cell.width, cell.height, "thin")
            sk.replay(backend, cell.x + 1.0, cell.y + caption_h)
            cap = sketch_caption(solution, f, look, lang, cw - 3.0)
            cap.replay(backend, cell.x + cw / 2.0, cell.y + caption_h)
    out = Path(out_svg)
    out.parent.mkdir(parents=True, exist_ok=True)
    return write_drawing(backend, out, "svg", title)


def write_task_files(
    task_dir: str | os.PathLike[str],
    out_dir: str | os.PathLike[str],
    lang: Language = "en",
    *,
    width_mm: float = 170.0,
    height_mm: float = 110.0,
) -> list[Path]:
    """task_NN.svg: the first variant of each task, drawn large with its title and formula."""
    from ..render.look import load_look
    from ..solution import solve
    from ..spec import load

    out_dir = Path(out_dir)
    out_dir.mkdir(parents=True, exist_ok=True)
    firsts: dict[int, Path] = {}
    for f in _task_files(task_dir):
        tv = task_of(f)
        if tv is not None:
            firsts.setdefault(tv[0], f)
    written = []
    for task, f in sorted(firsts.items()):
        solution = solve(load(f))
        margin, size = 8.0, 3.5
        look = load_look()
        title_lines = look.lettering.wrap(str(solution.mechanism.title), size, width_mm)
        cap_h = 2.0 * _CAPTION + 5.0
        title_h = look.lettering.block_height(len(title_lines), size) + 4.0
        height = margin + title_h + height_mm + cap_h + margin
        backend = RecordingBackend(width_mm + 2 * margin, height)
        y = height - margin - size
        with backend.group("title", "heading"):
            for line in title_lines:
                backend.text((margin, y), line, size)
                y -= look.lettering.line_pitch * size
        sk = sketch_schematic(solution, look, lang, width_mm=width_mm, height_mm=height_mm)
        sk.replay(backend, margin, margin + cap_h)
        sketch_caption(solution, f, look, lang, width_mm).replay(
            backend, margin + width_mm / 2.0, margin + cap_h
        )
        path = out_dir / f"task_{task:02d}.svg"
        written.append(write_drawing(backend, path, "svg", str(solution.mechanism.title)))
    return written
