"""One pose of a mechanism in the conventional symbols (GOST 2.770): links as
lines, revolute pairs as small circles, the frame's pivots and guides hatched,
sliders as blocks on their guides.

Every drawing of a mechanism goes through `draw_poses`: sheet 1's positions,
sheet 2's loaded mechanism, its groups cut out and its driving link, and the
task schematics. A caller builds the `Pose` (where each thing is, in the
drawing's mm, and how large its symbols are) and gets back a `PoseDrawn`
naming what was drawn, for the labels to keep clear of and to name.

Several poses drawn together (sheet 1's positions) are drawn layer by layer,
as a draughtsman inks them: guides, then the links of every pose, then the
blocks, the joints, the frame's pivots on top. A block or a joint of another
position that stands where one is drawn (within `_SAME`) is drawn once; a
block that overlaps one of its pair already drawn (two positions close
together) is drawn thin, in outline, as the draughtsman draws the later one.
"""

from __future__ import annotations

import itertools
from collections.abc import Collection, Mapping, Sequence
from dataclasses import dataclass, field
from typing import Literal

import numpy as np

from ..render.backend import Backend, LineType
from .symbols import hatched_base, hatched_guide, slider_block

__all__ = ["Block", "Guide", "GuideKind", "Pose", "PoseDrawn", "draw_poses", "block_corners"]

GuideKind = Literal["frame", "slot"]
Vec = np.ndarray

# mm: two blocks (or two pins) this close are one on paper, under half the
# main line's width (0.7 mm): drawn once
_SAME = 0.3


@dataclass(frozen=True)
class Guide:
    """A slider's guide from `start` to `end` along its path (mm), `u` the unit
    from start to end. A frame's guide is hatched `offset` mm to the right of
    the path; a slot of a moving link is a main line on it."""

    start: Vec
    end: Vec
    u: Vec
    kind: GuideKind
    offset: float = 3.5


@dataclass(frozen=True)
class Block:
    """A slider's block centred at `centre`, its length along the unit `u`."""

    pair: tuple[int, int]  # the slider's link and its guide's: blocks of one pair are compared
    centre: Vec
    u: Vec
    half: tuple[float, float]  # half length, half height, mm


@dataclass(frozen=True)
class Pose:
    """One position of a mechanism in the drawing's mm, with its symbols' sizes."""

    points: Mapping[str, Vec]
    links: Sequence[Collection[str]]  # each link's points: a line between every two
    line: LineType = "main"  # the links' lines
    pins: Sequence[str] = ()  # joints of moving links: circles, or dots for those in `dots`
    pin_radius: float = 1.2
    dots: frozenset[str] = frozenset()  # points of one link only
    dot_radius: float = 0.5
    pivots: Sequence[str] = ()  # the frame's pivots: a hatched base
    base: tuple[float, float] = (8.0, 4.0)  # a pivot's width and depth, mm
    guides: Sequence[Guide] = ()
    blocks: Sequence[Block] = ()


@dataclass(frozen=True)
class PoseDrawn:
    """What `draw_poses` drew, in the drawing's mm."""

    segments: tuple[tuple[Vec, Vec], ...] = ()  # the links' lines and the slots
    blocks: tuple[tuple[Vec, ...], ...] = ()  # each block drawn: its corners
    thin_blocks: int = 0  # of them, drawn thin beside a block they overlap
    pins: tuple[tuple[Vec, float], ...] = ()  # centre, radius
    pivots: tuple[Vec, ...] = ()
    links: dict[tuple[int, int], tuple[tuple[Vec, Vec], ...]] = field(default_factory=dict)
    # (pose, link) → that link's lines, where its ω and ε arcs go
    extent: tuple[float, float, float, float] | None = None  # xmin, ymin, xmax, ymax, mm


def block_corners(block: Block) -> list[Vec]:
    n = np.array([-block.u[1], block.u[0]])
    hl, hh = block.half
    return [
        block.centre + sx * hl * block.u + sy * hh * n
        for sx, sy in ((-1, -1), (1, -1), (1, 1), (-1, 1))
    ]


def _overlap(a: Block, b: Block) -> Literal["same", "overlap", "apart"]:
    """How block b lies against block a of the same slider."""
    if a.pair != b.pair:
        return "apart"
    parallel = abs(float(a.u[0] * b.u[1] - a.u[1] * b.u[0])) < 1e-3
    d = b.centre - a.centre
    if parallel and float(np.hypot(*d)) < _SAME and np.allclose(a.half, b.half, atol=_SAME):
        return "same"
    along = abs(float(np.dot(d, a.u)))
    across = abs(float(a.u[0] * d[1] - a.u[1] * d[0]))
    if parallel and along < a.half[0] + b.half[0] and across < a.half[1] + b.half[1]:
        return "overlap"
    return "apart"


def _apart(a: Vec, b: Vec) -> bool:
    return float(np.hypot(*(b - a))) > 1e-6


def draw_poses(out: Backend, poses: Sequence[Pose]) -> PoseDrawn:
    """Draw `poses` layer by layer; returns what was drawn."""
    segments: list[tuple[Vec, Vec]] = []
    links: dict[tuple[int, int], tuple[tuple[Vec, Vec], ...]] = {}
    for pose in poses:
        for g in pose.guides:
            if g.kind == "frame":
                hatched_guide(out, g.start, g.end, g.u, g.offset)
            else:
                out.line(g.start, g.end, "main")
                segments.append((g.start, g.end))
    for i, pose in enumerate(poses):
        for j, names in enumerate(pose.links):
            drawn = []
            for a, b in itertools.combinations([n for n in names if n in pose.points], 2):
                pa, pb = pose.points[a], pose.points[b]
                if np.all(np.isfinite(pa)) and np.all(np.isfinite(pb)) and _apart(pa, pb):
                    out.line(pa, pb, pose.line)
                    drawn.append((pa, pb))
            segments += drawn
            links[(i, j)] = tuple(drawn)
    blocks: list[Block] = []
    corners: list[tuple[Vec, ...]] = []
    thin = 0
    for pose in poses:
        for block in pose.blocks:
            met = [_overlap(drawn_block, block) for drawn_block in blocks]
            if "same" in met:
                continue
            outline = "overlap" in met
            thin += outline
            blocks.append(block)
            c = block_corners(block)
            slider_block(out, c, "thin" if outline else "main", "none" if outline else "white")
            corners.append(tuple(c))
    pins: list[tuple[Vec, float]] = []
    for pose in poses:
        for name in pose.pins:
            dot = name in pose.dots
            r = pose.dot_radius if dot else pose.pin_radius
            at = pose.points[name]
            if any(q == r and float(np.hypot(*(at - p))) < _SAME for p, q in pins):
                continue  # the same joint of another position, where it stands
            out.circle(at, r, "main", "black" if dot else "white")
            pins.append((at, r))
    pivots: list[Vec] = []
    reach: list[Vec] = []  # what the drawing covers, for its extent
    for pose in poses:
        width, down = pose.base
        for name in pose.pivots:
            hatched_base(out, pose.points[name], width, down)
            pivots.append(pose.points[name])
            reach += [pose.points[name] + (sx * width / 2.0, -down - 2.0) for sx in (-1, 1)]
        for g in pose.guides:
            n = np.array([-g.u[1], g.u[0]])
            reach += [q + t * n for q in (g.start, g.end) for t in (2.0, -g.offset - 2.5)]
    reach += [p for seg in segments for p in seg] + [p for c in corners for p in c]
    reach += [c + (sx * r, sy * r) for c, r in pins for sx in (-1, 1) for sy in (-1, 1)]
    extent = None
    if reach:
        (x0, y0), (x1, y1) = np.min(reach, axis=0), np.max(reach, axis=0)
        extent = (float(x0), float(y0), float(x1), float(y1))
    return PoseDrawn(
        tuple(segments), tuple(corners), thin, tuple(pins), tuple(pivots), links, extent
    )
