"""Letters beside drawn vectors and points, placed where they hit nothing.

A draughtsman writes a label next to what it names, on whichever side is
free. `Labels` does the same for one drawing: it keeps the boxes of the
labels already written and everything already drawn (shapely), tries the
places round the anchor nearest first, and writes the label at the first one
that touches neither. One rule holds every label, the sheet linter's
label-near: its box is within NEAR_MM of what it names (the point, or the
segment of an arrow or a link), or a thin leader of its own joins the two.
A point drawn inside a small filled outline (a slider's block: its pin, its
mass centre) is named beside the outline, as a draughtsman writes it: the
distance is measured to the outline (`enclosing`), and a leader starts on it.
So where nothing near is free it goes further out and draws a leader from
the anchor to it (one that crosses nothing first, else a few thin lines;
never a main line, lettering, an arrowhead or a dot; with `across_main`, as
the last resort, the fewest main lines). Where no leader finds a place
either, it takes the place near the anchor that covers least, so a label is
never dropped and never far from what it names.

What is drawn is read from the sketch itself (`follow`): before each label
the placer takes every call recorded since the last one — lines, hatching,
arrows with their heads, arcs, circles, polygons, other lettering — so no
drawing has to list its lines by hand.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Collection, Iterable, Iterator, Sequence
from contextlib import contextmanager, nullcontext
from dataclasses import dataclass, field
from typing import Any, cast

import numpy as np
import shapely
from shapely import STRtree
from shapely.geometry import LineString, Point, Polygon, box
from shapely.geometry.base import BaseGeometry

from ..render.backend import PointLike
from ..render.recording import Call, Line, NamingKind, RecordingBackend, Text

__all__ = [
    "BLOCK_MM",
    "FINE_LEADER_DIRS",
    "FINE_LEADER_GROUP",
    "FINE_LEADER_RINGS",
    "LabelCounts",
    "LOOKALIKE",
    "LOOKALIKE_MM",
    "NEAR_MM",
    "Labels",
    "arc_line",
    "drawn_shapes",
    "drawn_shapes_of",
    "enclosing",
]

# The rule of every label (and of the sheet linter's label-near): its box
# within NEAR_MM of what it names, or a thin leader of its own joins the two.
NEAR_MM = 6.0
# what a candidate box may be from what it names: the box written is the
# lettering's, up to 0.2 mm inside the box the placer keeps free
_NEAR_KEPT = NEAR_MM - 0.5
# and what the lettering itself may be from it (as the sheet linter measures
# it): its runs' boxes lie up to 0.5 mm inside the box kept free (an index's
# box short of its advance and the italic lean), and 0.5 mm inset at a corner
# either way is past NEAR_MM - _NEAR_KEPT; less a hair the sheet's layout may
# round off
_NEAR_WRITTEN = NEAR_MM - 0.01
# a filled outline no wider or taller than this (mm) that holds a named point
# is a symbol drawn round it (a slider's block, 12 × 7 mm): the point's name
# is near when it is near the outline
BLOCK_MM = 15.0

# the directions tried round an anchor, preferred first: the given side, then
# round the compass
_COMPASS = tuple(
    np.exp(1j * math.radians(a))
    for a in (
        45,
        135,
        -45,
        -135,
        90,
        -90,
        0,
        180,
        22.5,
        67.5,
        112.5,
        157.5,
        -22.5,
        -67.5,
        -112.5,
        -157.5,
        *(11.25 + 22.5 * k for k in range(16)),
    )
)
# mm further out, tried in turn: finely within NEAR_MM, then beyond (a place
# there is taken only with a leader, or where no leader finds room)
_RINGS = (0.0, 1.2, 2.5, 3.5, 4.2, 5.0, 9.0, 14.0)
# where no ring near the anchor is free: further out, tied to the anchor by a
# thin leader line, in 24 directions
_LEADER_RINGS = (6.0, 10.0, 15.0, 21.0, 28.0, 36.0)
_LEADER_DIRS = 24
# finer, for a drawing crowded round its points (sheet 1's mechanism and plans):
# rings 1.5-3.5 mm apart from just past the near places, every 10°
FINE_LEADER_RINGS = (4.5, 6.0, 7.5, 9.0, 11.0, 13.0, 15.5, 18.0, 21.0, 24.5, 28.0, 32.0, 36.0)
FINE_LEADER_DIRS = 36
# with the fine rings, this many asked about together, nearest first: a short
# leader that crosses a thin line is better than one three times as long that
# crosses none
FINE_LEADER_GROUP = 4
# the leader is clear of everything from this far (mm) from the anchor on,
# past the pin and the lines that meet there
_LEADER_START = 1.8
_LEADER_ALONG = (1.5, 8.0)  # a leader longer (mm) within this of a line runs along it
# thin lines a leader may cross where none crosses fewer: the last (a pole
# ringed by a lever's arms and lines of action) before a name stands untied
_LEADER_CROSSINGS = (2, 6, 12)
# what crossing a main line counts among them, where a leader may (`across_main`)
_MAIN_CROSSED = 3
# a leader's boxes asked about in blocks of this many, nearest first, then 4 times as many
_LEADER_BLOCK = 256
# what meets at a leader's foot (the arc and arrowhead of the ω it names, the
# links at a joint) it leaves at this clearance, mm, not the one kept from
# all else: it touches them there by design, and past the pin it crosses none
_FOOT_CLEAR = 0.15
# what touches a leader's foot lies within 0.05 mm of it: only what has its box
# this near the foot (rounding kept) is measured
_AT_FOOT = 0.05 + 1e-9
# how many obstacle indexes a placer keeps (`_index`): the one before a
# trial, and those of the trials nested in it
_INDEXES_KEPT = 4
# a distance measured in numpy is taken as shapely's where it is this far (mm)
# from the one it is compared with: nearer, shapely is asked (both are exact
# to far less: the same answer)
_ROUNDING = 1e-6
# names that read alike (O and 0, o and 0, l and 1) stand at least this far
# apart, mm, box to box (the sheet linter's names-unique)
LOOKALIKE_MM = 15.0
LOOKALIKE = ({"O", "0"}, {"o", "0"}, {"l", "1"}, {"O", "o"})
_ALONG = (0.5, 0.35, 0.65, 0.2, 0.8)  # where along a segment a label is tried, in turn
# where no place of the compass round an anchor is free: every place on a grid
# this fine (mm) within NEAR_MM of it, at least _FINE_OFF mm off it, tried
# (nearest first) before a leader; not for a label whose grid would hold more
# than _FINE_MOST places (a long arrow's)
_FINE_STEP = 0.5
_FINE_OFF = 0.5
_FINE_MOST = 40_000
# where no place near is free and no leader reaches one: the fine grid once
# more, a box this much (mm) smaller each side, so that lettering stands
# 0.25 mm off a line instead of 0.6 mm (still clear of it)
_TIGHT = 0.35
# and then a leader further out than the rings (mm), from any of these
# fractions along a named segment (the ends and every tenth)
_WIDE_RINGS = (42.0, 50.0, 60.0)
_WIDE_ALONG = tuple(np.round(np.linspace(0.0, 1.0, 11), 2))
# `shortest_leaders`: a grid of boxes this fine (mm), up to this far (mm)
# from what the label names, each led from the nearest point of it
_SHORTEST_STEP = 0.5
_SHORTEST_REACH = 16.0
# at most this many places on that grid: round a long segment (a link's name,
# some 250 mm and longer) the grid is made coarser to hold no more
_SHORTEST_MOST = 250_000
# how many of the grid's boxes are asked about the obstacles first (then 4 times as many)
_FINE_BLOCK = 64
# how many times `write_later(retry=True)` writes the labels again, those that
# found no place first
_RETRIES = 1
# past _RETRIES, `write_later` writes the labels again only while at most
# this many of them stand far (a few walled in, not a crowded drawing)
_FEW_FAR = 2


@dataclass(frozen=True)
class LabelCounts:
    """How well a drawing is lettered, the less the better (`Labels.counts`)."""

    unsettled: int  # labels written where they cover something: no place was free
    # labels written far from what they name with no leader (none reached), or
    # led across main lines (`Labels.across_main`)
    far: int
    # whether `write_later(grow=True)` could letter the drawing otherwise: an
    # order past _RETRIES kept from it by the box, or its orders cut short by
    # many standing far (False: lettered with `grow`, the same drawing); not
    # a count: counts compare equal whatever it is
    grows: bool = field(default=False, compare=False)


class Labels:
    """Places rich-text labels on a recording sketch without collisions."""

    def __init__(
        self,
        sketch: RecordingBackend,
        size: float,
        *,
        rings: PointLike = _RINGS,
        follow: bool = True,
        clearance: float = 0.4,
        spacing: float | None = 0.0,
        leaders: bool = True,
        leader_rings: Sequence[float] = _LEADER_RINGS,
        leader_dirs: int = _LEADER_DIRS,
        leader_group: int | None = None,
        words: Callable[[str], str] | None = None,
        fine: bool = True,
        fine_far: bool = False,
        fine_kept: bool = False,
        wide_leaders: bool = False,
        smaller: float | None = None,
        short_ends: bool = False,
        shortest_leaders: bool = False,
        across_main: bool = False,
    ) -> None:
        self.sketch = sketch
        # with `across_main` (and `fine`), a label that finds no free place
        # near what it names and no leader to one that crosses no main line
        # is led across main lines (fewest first, each counting
        # _MAIN_CROSSED thin ones) before it stands far: GOST 2.316 keeps a
        # leader off the drawing's lines where it can be; a pivot in the fan
        # of its positions' links has no free side (gen 332's U). One that
        # crosses a main line still counts as far (`far`): a drawing that
        # needs none is preferred
        self.across_main = across_main
        self._across = False  # while that last resort is asked
        # with `shortest_leaders` (and `fine`), a label no leader of the rings
        # reaches a place from is led once more, in the last resort before it
        # stands far: to each free box of a grid round what it names, on the
        # shortest line from it (as the sheet linter measures a leader), the
        # nearest box first; a place no ring's direction from the anchor or
        # the fractions along a segment hits (held-out gen 289's lever: G5)
        self.shortest_leaders = shortest_leaders
        # with `short_ends`, a segment too short to be led from along it (a
        # plan's component amid the pole's lettering) is led from its ends
        # too, in the last resort before its name stands far
        self.short_ends = short_ends
        self.size = size
        # with `smaller` (a letter height below `size`, GOST's 2.5 mm at
        # least), a label that finds no free place near what it names and no
        # leader to one at `size` is tried once more at that height (a name
        # walled in by lines: the smaller figures of the positions' numbers)
        # before it stands far
        self.smaller = smaller
        # the lettering as the sheet's language writes it (F_in4 is F_i4 on a
        # Ukrainian sheet): measured and written so, where it is placed
        self._say = words or (lambda markup: markup)
        self._widths: dict[tuple[str, float], float] = {}  # `width` of (markup, size)
        # `_lettering` of (markup, size)
        self._letterings: dict[tuple[str, float], tuple[float, float, float, float]] = {}
        # labels side by side keep `spacing` mm apart; None: a word space (else they read as one)
        self.spacing = (
            sketch.look.lettering.advance_width(" ", size) + 0.2 if spacing is None else spacing
        )
        # with `leaders` (without them only where a test wants the near places
        # alone), a label with no free place near its anchor goes further out,
        # tied to the anchor by a thin leader line
        self.leaders = leaders
        # with `fine`, a label none of the compass's places holds is tried on
        # a fine grid of places near its anchor before a leader (_fine_near)
        self.fine = fine
        # with `fine_far` (where `fine` is off), the fine grid only for the
        # labels `write_later(retry=True)` found no place near at first: the
        # crowded ones, written first with it, the easy ones as before
        self.fine_far = fine_far
        # with `fine_kept` too, a label that went far in any order written is
        # on the fine grid in every order after it, not in the next alone: one
        # walled in by another that went far before it may find room only on
        # the grid (task09_v2's G5 and F_in5, two short sides of one column)
        self.fine_kept = fine_kept
        # with `wide_leaders`, a label no leader of `leader_rings` reaches a
        # place from is led once more, on the finer rings (FINE_LEADER_RINGS,
        # FINE_LEADER_DIRS directions), before it stands far with no leader
        self.wide_leaders = wide_leaders
        # how far out a leader's box may go (mm past `distance`, in turn), in how many directions
        self.leader_rings = np.array(leader_rings, dtype=float)
        self._leader_dirs = np.exp(1j * np.radians(360.0 / leader_dirs * np.arange(leader_dirs)))
        # how many rings are asked about together (None: all at once)
        self.leader_group = leader_group or len(self.leader_rings)
        # with `follow`, every call recorded on `sketch` is avoided, `clearance` mm off
        self.follow = follow
        self.clearance = clearance
        self._seen = 0
        # how much further out than `distance` a label may go, tried in turn; past
        # the last ring it is written where it covers least
        self.rings = np.array(rings, dtype=float)
        self.boxes: list[BaseGeometry] = []
        # the bounds of `boxes` and an array of them, made once per change of them (`_boxes_changed`)
        self._boxes_bounds: np.ndarray | None = None
        self._boxes_array: np.ndarray | None = None
        self._texts: list[str] = []  # the markup of each of `boxes`
        self._obstacles: list[BaseGeometry] = []  # shapes, each kept its `_clearance` mm off
        self._clearance: list[float] = []
        self._heavy: list[bool] = []  # which obstacles are main (heavy) lines: never crossed
        self._leaders: set[int] = set()  # which obstacles are leaders (never crossed)
        self._outlines: list[BaseGeometry] = []  # filled polygons drawn (blocks): see `enclosing`
        self._tree: _ObstacleIndex | None = None
        # each obstacle's serial (never given twice): the obstacles up to one
        # are the same shapes while it stands at the same place in the list
        # (the lists only grow at the end or are cut back), so an index built
        # of them serves again when a trial is undone (`_index`)
        self._serials: list[int] = []
        self._next_serial = 0
        self._indexes: dict[tuple[int, int], tuple[_ObstacleIndex, np.ndarray]] = {}
        self._grown: BaseGeometry | None = None
        self._covered: dict[
            bytes, float
        ] = {}  # `covered` of each shape asked, while `_grown` holds
        self.unsettled = 0  # labels written where they cover something: no place was free
        # labels written far from what they name with no leader (none reached),
        # or with one across main lines (`across_main`)
        self.far = 0
        self.grows = False  # LabelCounts.grows: what `grow` would have written otherwise
        self._later: list[tuple[str, Sequence[float], str, PointLike | None, PointLike | None]] = []
        # while `write_later` tries its orders: what each label wrote, by the
        # label, with the region its writing read and what stood there (_Memo)
        self._memo: dict[Any, list[_Memo]] | None = None
        self._memo_base = 0  # the obstacles before the labels (the drawing's own)
        # the bounds and WKB of the obstacles past `_memo_base` (leaders), by their id
        self._memo_shapes: dict[int, tuple[BaseGeometry, tuple[float, ...], bytes]] = {}
        # the box (x0, y0, x1, y1) the label being written has asked about so far
        self._reads: list[float] | None = None

    def avoid(self, shape: BaseGeometry, clearance: float, *, heavy: bool = False) -> None:
        """Keep labels `clearance` mm off any shape (a filled polygon is avoided
        whole); a `heavy` one (a main line) no leader crosses."""
        self._obstacles.append(shape)
        self._clearance.append(clearance)
        self._heavy.append(heavy)
        self._serials.append(self._next_serial)
        self._next_serial += 1
        self._tree = None
        self._grown = None

    def avoid_line(
        self, start: PointLike, end: PointLike, clearance: float = 0.4, *, heavy: bool = False
    ) -> None:
        """Keep labels `clearance` mm off a drawn segment (a `heavy` one, a main
        line, no leader crosses)."""
        if math.dist(start, end) > 1e-9:
            self.avoid(LineString([tuple(start), tuple(end)]), clearance, heavy=heavy)
        else:
            self.avoid(Point(tuple(start)), clearance)

    def avoid_circle(self, centre: PointLike, radius: float) -> None:
        self.avoid(Point(tuple(centre)), radius)

    def avoid_drawn(
        self, calls: Iterable[Call], clearance: float = 0.3, *, solid: bool = False
    ) -> None:
        """Keep labels off everything already recorded: lines, polylines, the
        edges of polygons, arrows and circles; with `solid`, also the inside
        of polygons and the length of arcs. (A placer that follows its sketch
        does this by itself.)"""
        if self.follow and calls is self.sketch.calls:
            self._sync()
            return
        for c in calls:
            heavy = getattr(c, "line", None) == "main"
            if solid and c.name == "polygon":
                self.avoid(Polygon(c["points"]), clearance)
            elif solid and c.name == "arc":
                arc = arc_line(c["center"], c["radius"], c["start_deg"], c["end_deg"])
                self.avoid(arc, clearance, heavy=heavy)
            elif c.name in ("line", "arrow", "polyline", "polygon"):
                p = c.points()
                for a, b in zip(p, p[1:] + (p[:1] if c.name == "polygon" else [])):
                    self.avoid_line(a, b, clearance, heavy=heavy)
            elif c.name == "circle":
                self.avoid_circle(c["center"], c["radius"] + clearance)

    def _sync(self) -> None:
        """Avoid every call recorded on the sketch since the last look."""
        if not self.follow:
            return
        calls = self.sketch.calls
        new = calls[self._seen :]
        for c, shapes in zip(new, drawn_shapes_of(new, self.sketch)):
            heavy = getattr(c, "line", None) == "main"
            for shape in shapes:
                self.avoid(shape, self.clearance, heavy=heavy)
                if c.name == "polygon" and shape.geom_type == "Polygon":
                    self._outlines.append(shape)
        self._seen = len(calls)

    def covered(self, shape: BaseGeometry) -> float:
        """The area of `shape` (mm²) within the clearance of what labels avoid:
        how much a symbol drawn there would cover."""
        self._sync()
        if not self._obstacles:
            return 0.0
        if self._grown is None:
            shapes = np.asarray(self._obstacles, dtype=object)
            self._grown = shapely.unary_union(shapely.buffer(shapes, np.array(self._clearance)))
            shapely.prepare(self._grown)
            self._covered = {}  # (a plan's images are asked about twice: measured once)
        key = shape.wkb
        if key not in self._covered:
            inside = self._grown.intersects(shape)
            self._covered[key] = float(shape.intersection(self._grown).area) if inside else 0.0
        return self._covered[key]

    def free(self, bounds: tuple[float, float, float, float]) -> bool:
        """Whether a box (x0, y0, x1, y1) comes within the clearance of nothing
        labels avoid (one query of the segment index; `covered` measures how much)."""
        self._sync()
        x0, y0, x1, y1 = (np.array([v], dtype=float) for v in bounds)
        return bool(self._clear(x0, y0, x1, y1)[0])

    def free_boxes(self, bounds: np.ndarray) -> np.ndarray:
        """`free` of each of the boxes `bounds` (x0, y0, x1, y1 rows), in one query."""
        self._sync()
        return self._clear(bounds[:, 0], bounds[:, 1], bounds[:, 2], bounds[:, 3])

    def first_free(self, bounds: np.ndarray) -> int | None:
        """The index of the first of the boxes `bounds` (x0, y0, x1, y1 rows)
        that `free` finds free, or None: the boxes asked about in growing
        batches, not one query each."""
        self._sync()
        return self._first_clear(bounds[:, 0], bounds[:, 1], bounds[:, 2], bounds[:, 3], 16)

    def _first_clear(
        self, x0: np.ndarray, y0: np.ndarray, x1: np.ndarray, y1: np.ndarray, block: int
    ) -> int | None:
        """The index of the first of the boxes that `_clear` finds clear, or
        None: asked about in blocks of `block`, then 4 times as many (at most
        1024), the first clear one ending it."""
        start, size = 0, block
        while start < x0.size:
            part = slice(start, start + size)
            free = np.flatnonzero(self._clear(x0[part], y0[part], x1[part], y1[part]))
            if free.size:
                return start + int(free[0])
            start, size = start + size, min(4 * size, 1024)
        return None

    def rooms(
        self,
        anchor: PointLike,
        markup: str,
        *,
        towards: PointLike | None = None,
        distance: float = 1.5,
        keep_off: BaseGeometry | None = None,
        first: PointLike | None = None,
    ) -> np.ndarray:
        """The centres (n × 2, in the order `place` tries them, `first` before
        all where given) of the places near `anchor` (within NEAR_MM) where
        `markup` would stand free of everything drawn and written, and of
        `keep_off` (a shape still to be drawn: the arc the label names) by the
        clearance. Asking writes nothing: a drawing chooses where its symbol
        goes by where its label finds room."""
        self._sync()
        x, y = float(anchor[0]), float(anchor[1])
        cx, cy, w, h, drop = self._around(np.array([x, y]), markup, towards, distance)
        if first is not None:
            cx = np.concatenate([[float(first[0])], cx])
            cy = np.concatenate([[float(first[1])], cy])
        return self._rooms((x, y), cx, cy, markup, keep_off)

    def is_room(
        self,
        anchor: PointLike,
        markup: str,
        centre: PointLike,
        *,
        keep_off: BaseGeometry | None = None,
    ) -> bool:
        """Whether the box of `markup` centred at `centre` is one of `rooms`
        (near `anchor`, free): asked of that one box alone."""
        self._sync()
        cx, cy = np.array([float(centre[0])]), np.array([float(centre[1])])
        return bool(
            len(self._rooms((float(anchor[0]), float(anchor[1])), cx, cy, markup, keep_off))
        )

    def _rooms(
        self,
        anchor: tuple[float, float],
        cx: np.ndarray,
        cy: np.ndarray,
        markup: str,
        keep_off: BaseGeometry | None,
    ) -> np.ndarray:
        """Those of the boxes of `markup` centred at cx, cy that are `rooms`."""
        x, y = anchor
        w, h, drop = self._extent(markup)
        x0, x1, y0, y1 = cx - w / 2, cx + w / 2, cy - h / 2 - drop, cy + h / 2
        near = self._near(("point", (x, y), None), markup, cx, cy, (x0, y0, x1, y1))
        idx = np.flatnonzero(near)
        if not idx.size:
            return np.zeros((0, 2))
        x0, x1, y0, y1 = x0[idx], x1[idx], y0[idx], y1[idx]
        cost = self._label_cost(x0, y0, x1, y1) + self._lookalike_cost(markup, x0, y0, x1, y1)
        if keep_off is not None:
            gap = shapely.distance(shapely.box(x0, y0, x1, y1), keep_off)
            # (its arrowhead stands 0.5 mm either side of it)
            cost += np.asarray(gap, dtype=float) < self.clearance + 0.6
        # the obstacles asked only about the boxes still free, and only whether any is met
        ok = np.flatnonzero(cost <= 1e-9)
        ok = ok[self._clear(x0[ok], y0[ok], x1[ok], y1[ok])]
        k = idx[ok]
        return np.c_[cx[k], cy[k]]

    def width(self, markup: str) -> float:
        """The width of the lettering, mm (of its longest line); measured once
        a markup and letter height (a retry writes the same names again)."""
        key = (markup, self.size)
        if key not in self._widths:
            probe = RecordingBackend(look=self.sketch.look)
            lines = self._say(markup).split("\n")
            self._widths[key] = max(probe.rich_text((0.0, 0.0), line, self.size) for line in lines)
        return self._widths[key]

    def _lettering(self, markup: str) -> tuple[float, float, float, float]:
        """The box (x0, y0, x1, y1) of the runs `markup` writes centred at
        (0, 0), as the recording keeps them (and the sheet linter reads them):
        measured once a markup and letter height."""
        key = (markup, self.size)
        if key not in self._letterings:
            probe = RecordingBackend(look=self.sketch.look)
            lines = self._say(markup).split("\n")
            for i, text in enumerate(lines):
                y = ((len(lines) - 1) / 2 - i) * self._pitch
                probe.rich_text((0.0, y), text, self.size, anchor="center", valign="middle")
            runs = np.array([c.box() for c in probe.calls if isinstance(c, Text)])
            self._letterings[key] = (
                float(runs[:, 0].min()),
                float(runs[:, 1].min()),
                float(runs[:, 2].max()),
                float(runs[:, 3].max()),
            )
        return self._letterings[key]

    def _near(
        self,
        names: tuple[NamingKind, PointLike, PointLike | None],
        markup: str,
        cx: np.ndarray,
        cy: np.ndarray,
        kept: tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray],
        outline: BaseGeometry | None = None,
    ) -> np.ndarray:
        """Which of the boxes `kept` (x0, y0, x1, y1) of `markup` centred at
        cx, cy stand near what it names: the box within _NEAR_KEPT of it, and
        the lettering written there within _NEAR_WRITTEN (the label-near rule
        measures the lettering; at a corner of the box it lies further in than
        the margin between the two)."""
        gap = _gap(names, *kept, outline)
        near = gap <= _NEAR_KEPT
        if near.any():
            lx0, ly0, lx1, ly1 = self._lettering(markup)
            x0, y0, x1, y1 = kept
            # the lettering lies at most this far further (it is inside the box):
            # measured again only where that may take it past _NEAR_WRITTEN
            inset = np.hypot(
                np.maximum(cx + lx0 - x0, x1 - cx - lx1), np.maximum(cy + ly0 - y0, y1 - cy - ly1)
            )
            k = np.flatnonzero(near & (gap + inset > _NEAR_WRITTEN))
            if k.size:
                written = _gap(names, cx[k] + lx0, cy[k] + ly0, cx[k] + lx1, cy[k] + ly1, outline)
                near[k] = written <= _NEAR_WRITTEN
        return near

    def later(
        self,
        anchor: PointLike,
        markup: str,
        towards: PointLike | None = None,
        first: PointLike | None = None,
    ) -> None:
        """A label to write with `write_later`, once every line is drawn and avoided
        (`first`: the centre tried before all others, a room kept for it)."""
        self._later.append(("at", tuple(float(v) for v in anchor), markup, towards, first))

    def later_along(
        self,
        start: PointLike,
        end: PointLike,
        markup: str,
        along: Sequence[float] | None = None,
    ) -> None:
        """A label to write beside the segment start–end (`place_along`, at the
        fractions `along` of it where given) with `write_later`."""
        self._later.append(
            ("along", tuple(float(v) for v in start), markup, tuple(float(v) for v in end), along)
        )

    def later_arrow(
        self, start: PointLike, end: PointLike, markup: str, along: Sequence[float] | None = None
    ) -> None:
        """A label to write at the head of the arrow start–end (`place_arrow`,
        beside its shaft at the fractions `along` of it where given) with `write_later`."""
        self._later.append(
            ("arrow", tuple(float(v) for v in start), markup, tuple(float(v) for v in end), along)
        )

    def write_later(self, *, retry: bool | int = False, grow: bool = False) -> None:
        """Write the labels kept by `later`, `later_along` and `later_arrow`, in the order they came.

        With `retry`, where some of them found no place near what they name
        (nor a leader to one), all are written again with those first: a
        draughtsman letters the crowded places before the easy ones (with
        `fine_far`, those on the fine grid of places too). The order kept is
        the one that leaves fewest written on something, then fewest far (the
        first, on a tie). With `retry` a number, written again up to that many
        times (else _RETRIES), those that went far in the last order first
        each time, past _RETRIES only while at most _FEW_FAR stand far: a
        name walled in by one written before it then goes before that one,
        and so on down a crowded cluster. Past _RETRIES an order is kept only
        where it letters the drawing within the box the best order before did
        (a drawing is fitted on a sheet by its box); with `grow` (a drawing
        given the room round it on a laid-out sheet), whatever its box."""
        retries = _RETRIES if retry is True else int(retry)
        todo = list(self._later)
        self._later.clear()
        if not retry:
            self._write_all(todo)
            return
        saved = self._state()
        with self._memoised():
            self._write_orders(todo, saved, retries, grow)

    @contextmanager
    def _memoised(self) -> Iterator[None]:
        """While orders of labels are written: each label's writing kept
        (`_memo_write`), forgotten after."""
        self._memo, self._memo_base = {}, len(self._obstacles)
        try:
            yield
        finally:
            self._memo = None
            self._memo_shapes = {}

    def _write_orders(
        self,
        todo: list[tuple[str, Sequence[float], str, PointLike | None, PointLike | None]],
        saved: tuple[Any, ...],
        retries: int,
        grow: bool,
    ) -> None:
        """`write_later`'s orders of `todo` (`saved`: the state before the first)."""
        far = self._write_all(todo)
        # the better order: fewer written on something, then fewer far
        best: tuple[tuple[int, int], list[int]] = (
            (self.unsettled - saved[-2], len(far)),
            list(range(len(todo))),
        )
        order = best[1]
        written = self._written(saved)  # what the best order wrote, to put back
        # the box the best of the first _RETRIES + 1 orders letters the
        # drawing in: past them an order that letters past it (a leader
        # further out) is not kept, so more orders never make a drawing
        # larger (a sheet that held its drawings holds them still)
        slot = self.lettered_bounds()
        went: set[int] = set()  # (with `fine_kept`) every label that went far so far
        fine: set[int] = set()
        for n in range(retries):
            # those that went far, first (already first: the same order writes the same)
            again = [*(order[i] for i in far), *(j for k, j in enumerate(order) if k not in far)]
            fine_before = fine
            if self.fine_far and self.fine_kept:
                went |= {order[i] for i in far}
                fine = {k for k, j in enumerate(again) if j in went}
            else:
                fine = set(range(len(far))) if self.fine_far else set()
            if again == order and (not fine or self.fine_kept and fine == fine_before):
                break
            order = again
            self._restore(saved)
            # (an order that cannot letter better than the best is cut short
            # where nothing reads its far ones: the last, or one the loop ends after)
            last = n + 1 == retries or (n + 1 >= _RETRIES and best[0][1] > _FEW_FAR and not grow)
            far = self._write_all(
                [todo[j] for j in order], fine, (saved[-2], best[0]) if last else None
            )
            if (self.unsettled - saved[-2], len(far)) < best[0]:
                bounds = self.lettered_bounds()
                if grow or n < _RETRIES or _within(bounds, slot):
                    best = ((self.unsettled - saved[-2], len(far)), order)
                    written = self._written(saved)
                    slot = bounds if n < _RETRIES else slot
                else:
                    self.grows = True  # kept from the drawing by its box alone
            if n + 1 >= _RETRIES and best[0][1] > _FEW_FAR and not grow:
                # many stand far: crowded past what another order mends
                self.grows |= n + 1 < retries  # `grow` writes the orders left
                break
        if order is not best[1]:  # the last order written is not the best: the best again
            self._restore(saved)
            self._put_back(written)

    def lettered_bounds(self) -> np.ndarray:
        """The box (x0, y0, x1, y1) of everything drawn and written: the
        obstacles (leaders among them) and the lettering."""
        self._sync()
        shapes = np.asarray([*self._obstacles, *self.boxes], dtype=object)
        if not len(shapes):
            return np.zeros(4)
        return np.asarray(shapely.total_bounds(shapes), dtype=float)

    def counts(self) -> LabelCounts:
        """How many labels found no free place, how many stand far."""
        return LabelCounts(self.unsettled, self.far, self.grows)

    def write_each(
        self,
        writes: Sequence[Callable[[], object]],
        orders: Sequence[Sequence[int]] = (),
        most: int | None = None,
    ) -> None:
        """Call each of `writes` (each writes one label: `place`,
        `place_along`, `place_arrow`, at the letter height it sets) in turn;
        where some of them found no place near what they name (nor a leader
        to one), all once more in each of the `orders` (their places in
        `writes`) in turn, then in the best order so far with those that went
        far in it first (as `write_later` with `retry`), until none goes far;
        the order that leaves fewest written on something, then fewest far,
        kept; where more than `most` went far in the first, it is kept (too
        crowded for another order to help). Each of `writes` writes the same
        label whenever it is called in the same state: one is written again
        in another order as it was before where what it asks about stands as
        then (`_memo_write`)."""
        saved = self._state()
        with self._memoised():
            self._write_each_orders(writes, orders, most, saved)

    def _write_each_orders(
        self,
        writes: Sequence[Callable[[], object]],
        orders: Sequence[Sequence[int]],
        most: int | None,
        saved: tuple[Any, ...],
    ) -> None:
        """`write_each`'s orders of `writes` (`saved`: the state before the first)."""
        tries: list[list[int] | None] = [list(range(len(writes))), *map(list, orders), None]
        best: tuple[tuple[int, int], list[int], list[int], tuple[Any, ...]] | None = None
        last: list[int] = []
        for order in tries:
            if order is None:  # the best order's far ones first
                assert best is not None
                _, kept, went, _ = best
                order = [*went, *(k for k in kept if k not in went)]
            if best is not None:
                self._restore(saved)
            # (an order that cannot letter better than the best is cut short:
            # it is not kept, and the next reads the best's far ones)
            bound = None if best is None else (saved[-2], best[0])
            far = [order[i] for i in self._each([writes[k] for k in order], bound)]
            score = (self.unsettled - saved[-2], len(far))
            last = order
            if best is None or score < best[0]:
                best = (score, order, far, self._written(saved))
            if not far or (most is not None and len(far) > most and order is tries[0]):
                break
        assert best is not None
        if last is not best[1]:  # the last order written is not the best: the best again
            self._restore(saved)
            self._put_back(best[3])

    def _each(
        self,
        writes: Sequence[Callable[[], object]],
        bound: tuple[int, tuple[int, int]] | None = None,
    ) -> list[int]:
        """Call `writes` in turn; which of them (their places in it) went far
        (where it cannot beat `bound`, cut short: `_beaten`)."""
        far: list[int] = []
        for k, write in enumerate(writes):
            before = self.far
            if self._memo is None:
                write()
            else:
                self._memo_write((id(write), self.fine, self.size), None, write)
            if self.far > before:
                far.append(k)
                if self._beaten(bound, len(far)):
                    break
        return far

    def _beaten(self, bound: tuple[int, tuple[int, int]] | None, far: int) -> bool:
        """Whether an order whose writing has left `far` labels far can no
        longer letter better than `bound` (the unsettled count before it and
        the best order's (unsettled, far)): its counts only grow."""
        if bound is None:
            return False
        base, (unsettled, most) = bound
        now = self.unsettled - base
        return now > unsettled or (now == unsettled and far >= most)

    def _write_all(
        self,
        todo: Sequence[tuple[str, Sequence[float], str, PointLike | None, PointLike | None]],
        fine: Collection[int] = (),
        bound: tuple[int, tuple[int, int]] | None = None,
    ) -> list[int]:
        """Write `todo` in order (those at the places `fine` in it with the
        fine grid); which of them (their places in it) went far (where it
        cannot beat `bound`, cut short: `_beaten`)."""
        far: list[int] = []
        plain = self.fine
        for k, item in enumerate(todo):
            before = self.far
            self.fine = plain or k in fine
            if self._memo is None:
                self._write_one(*item)
            else:  # (the same label, written as before where what it asks about stands as then)
                self._memo_write(
                    (id(item), self.fine, self.size), item[2], lambda: self._write_one(*item)
                )
            if self.far > before:
                far.append(k)
                if self._beaten(bound, len(far)):
                    break
        self.fine = plain
        return far

    def _write_one(
        self,
        kind: str,
        anchor: Sequence[float],
        markup: str,
        other: PointLike | None,
        first: PointLike | None,
    ) -> None:
        """Write one label kept by `later`, `later_along` or `later_arrow`."""
        if kind == "along":  # `first` holds the fractions along it, if any
            assert other is not None
            along = None if first is None else [float(t) for t in first]
            self.place_along(anchor, other, markup, around=True, along=along)
        elif kind == "arrow":  # `first` holds the fractions along its shaft, if any
            assert other is not None
            along = None if first is None else [float(t) for t in first]
            self.place_arrow(anchor, other, markup, along=along)
        else:
            self.place(anchor, markup, towards=other, first=first)

    def _memo_write(
        self, key: tuple[Any, ...], markup: str | None, write: Callable[[], object]
    ) -> None:
        """`write()` (that writes the label `markup`, None: not known
        beforehand), or what it wrote in an order before where the
        labels and leaders written since the drawing, within reach of the
        region that writing asked about, stand as they stood then: the
        placer's every answer reads only those (and the drawing, the same in
        every order), so it writes the same again (a retry order moves the
        labels of a crowded place and leaves the others as they were)."""
        assert self._memo is not None
        boxes, obstacles = len(self.boxes), len(self._obstacles)
        for memo in self._memo.get(key, ()):
            if self._standing(memo.region, markup, boxes, obstacles) == memo.standing:
                self._write_again(memo)
                return
        state = self._state()
        self._reads = [math.inf, math.inf, -math.inf, -math.inf]
        try:
            write()
            region = tuple(self._reads)
        finally:
            self._reads = None
        calls, boxes, obstacles, outlines = state[:4]
        self._memo.setdefault(key, []).append(
            _Memo(
                region,
                self._standing(region, markup, boxes, obstacles),
                tuple(self.sketch.calls[calls:]),
                tuple(self.boxes[boxes:]),
                tuple(self._texts[boxes:]),
                tuple(self._obstacles[obstacles:]),
                tuple(self._clearance[obstacles:]),
                tuple(self._heavy[obstacles:]),
                tuple(self._outlines[outlines:]),
                tuple(sorted(i - obstacles for i in self._leaders - state[4])),
                self.unsettled - state[5],
                self.far - state[6],
                len(self.sketch.calls) - self._seen if self.follow else 0,
            )
        )

    def _read(self, x0: np.ndarray, y0: np.ndarray, x1: np.ndarray, y1: np.ndarray) -> None:
        """The boxes (or two-point lines) from x0, y0 to x1, y1 are asked
        about: the region `_memo_write` compares grown round them."""
        reads = self._reads
        if reads is not None and x0.size:
            reads[0] = min(reads[0], float(np.minimum(x0, x1).min()))
            reads[1] = min(reads[1], float(np.minimum(y0, y1).min()))
            reads[2] = max(reads[2], float(np.maximum(x0, x1).max()))
            reads[3] = max(reads[3], float(np.maximum(y0, y1).max()))

    def _read_led(
        self, cx: np.ndarray, cy: np.ndarray, ax: np.ndarray, ay: np.ndarray, *extent: float
    ) -> None:
        """`_read` of the boxes centred at cx, cy (width, height, drop
        `extent`) led from ax, ay: of them and their feet (their leaders between)."""
        if self._reads is not None:
            w, h, drop = extent
            self._read(cx - w / 2, cy - h / 2 - drop, cx + w / 2, cy + h / 2)
            self._read(ax, ay, ax, ay)

    def _standing(
        self, region: tuple[float, ...], markup: str | None, boxes: int, obstacles: int
    ) -> tuple[Any, ...]:
        """What of the first `boxes` labels and of the obstacles from the
        drawing's own to the first `obstacles` (leaders) stands within reach
        of `region` (x0, y0, x1, y1): within any distance the placer measures
        from a box or a leader it asks about (spacing, clearances, a line run
        along), lettering that reads like `markup` (any that reads like
        another, where it is None) within LOOKALIKE_MM."""
        x0, y0, x1, y1 = region
        if x0 > x1:  # nothing asked about
            return ()
        grown = max(self.spacing, self.clearance, _FOOT_CLEAR, _LEADER_ALONG[0]) + 1.0
        alike = LOOKALIKE_MM + 1.0
        b = self._written_bounds()[:boxes] if boxes else np.zeros((0, 4))
        reach: float | np.ndarray = grown
        if markup is None:
            reach = np.array(
                [
                    alike if any(t in alikes for alikes in LOOKALIKE) else grown
                    for t in self._texts[:boxes]
                ]
            )
        elif any(markup in alikes for alikes in LOOKALIKE):
            reach = np.array(
                [alike if {t, markup} in LOOKALIKE else grown for t in self._texts[:boxes]]
            )
        near = np.flatnonzero(
            (b[:, 0] <= x1 + reach)
            & (b[:, 2] >= x0 - reach)
            & (b[:, 1] <= y1 + reach)
            & (b[:, 3] >= y0 - reach)
        )
        led = []
        for i in range(self._memo_base, obstacles):
            shape = self._obstacles[i]
            kept = self._memo_shapes.get(id(shape))
            if kept is None or kept[0] is not shape:  # (an id is kept with its shape)
                kept = self._memo_shapes[id(shape)] = (shape, shape.bounds, shape.wkb)
            bx0, by0, bx1, by1 = kept[1]
            if bx0 <= x1 + grown and bx1 >= x0 - grown and by0 <= y1 + grown and by1 >= y0 - grown:
                led.append((kept[2], self._clearance[i], self._heavy[i], i in self._leaders))
        return b[near].tobytes(), tuple(self._texts[i] for i in near), tuple(led)

    def _write_again(self, memo: _Memo) -> None:
        """What `memo` keeps a label wrote, written again as it was."""
        obstacles = len(self._obstacles)
        self._extend(
            memo.calls,
            memo.boxes,
            memo.texts,
            memo.obstacles,
            memo.clearance,
            memo.heavy,
            memo.outlines,
        )
        self._leaders.update(obstacles + i for i in memo.leaders)
        self.unsettled += memo.unsettled
        self.far += memo.far
        if self.follow:  # (what it drew past its last label is still to be avoided)
            self._seen = len(self.sketch.calls) - memo.unseen
        self._tree = None
        self._grown = None

    def _state(self) -> tuple[Any, ...]:
        """What writing labels changes, to go back to (`_restore`)."""
        self._sync()
        return (
            len(self.sketch.calls),
            len(self.boxes),
            len(self._obstacles),
            len(self._outlines),
            set(self._leaders),
            self.unsettled,
            self.far,
        )

    def _written(self, state: tuple[Any, ...]) -> tuple[Any, ...]:
        """What was written since `_state` (`_put_back` writes it again as it was)."""
        self._sync()
        calls, boxes, obstacles, outlines = state[:4]
        return (
            self.sketch.calls[calls:],
            self.boxes[boxes:],
            self._texts[boxes:],
            self._obstacles[obstacles:],
            self._clearance[obstacles:],
            self._heavy[obstacles:],
            self._outlines[outlines:],
            set(self._leaders),
            self.unsettled,
            self.far,
        )

    def _put_back(self, written: tuple[Any, ...]) -> None:
        """After `_restore`, what `_written` kept, as if written again."""
        calls, boxes, texts, obstacles, clearance, heavy, outlines, leaders, unsettled, far = (
            written
        )
        self._extend(calls, boxes, texts, obstacles, clearance, heavy, outlines)
        self._counts_back(leaders, unsettled, far)

    def _extend(
        self,
        calls: Sequence[Call],
        boxes: Sequence[BaseGeometry],
        texts: Sequence[str],
        obstacles: Sequence[BaseGeometry],
        clearance: Sequence[float],
        heavy: Sequence[bool],
        outlines: Sequence[BaseGeometry],
    ) -> None:
        """What labels wrote (`_written`, a `_Memo`) added to the sketch and
        the placer's lists again; the counts and leaders left to the caller."""
        self.sketch.calls.extend(calls)
        self.boxes.extend(boxes)
        self._boxes_changed()
        self._texts.extend(texts)
        self._obstacles.extend(obstacles)
        self._clearance.extend(clearance)
        self._heavy.extend(heavy)
        self._serials.extend(range(self._next_serial, self._next_serial + len(obstacles)))
        self._next_serial += len(obstacles)
        self._outlines.extend(outlines)

    def _restore(self, state: tuple[Any, ...]) -> None:
        """Undo the labels written since `_state` (their lettering and leaders)."""
        calls, boxes, obstacles, outlines, leaders, unsettled, far = state
        del self.sketch.calls[calls:]
        del self.boxes[boxes:], self._texts[boxes:]
        self._boxes_changed()
        del self._obstacles[obstacles:], self._clearance[obstacles:], self._heavy[obstacles:]
        del self._serials[obstacles:]
        del self._outlines[outlines:]
        self._counts_back(leaders, unsettled, far)

    def _boxes_changed(self) -> None:
        """`boxes` written or undone: their bounds and array made again when asked."""
        self._boxes_bounds = None
        self._boxes_array = None

    def _written_bounds(self) -> np.ndarray:
        """The bounds of the labels written (x0, y0, x1, y1 rows)."""
        if self._boxes_bounds is None:
            self._boxes_bounds = shapely.bounds(self.boxes).reshape(-1, 4)
        return self._boxes_bounds

    def _near_written(
        self, lines: np.ndarray, x0: np.ndarray, y0: np.ndarray, x1: np.ndarray, y1: np.ndarray
    ) -> np.ndarray:
        """Which of the two-point `lines` (from x0, y0 to x1, y1) come within
        _FOOT_CLEAR of a label written, as a tree of the labels asks it
        (`STRtree.query` with "dwithin"): the pairs whose boxes meet so grown
        measured in numpy (`_segment_box`), shapely asked only about those
        within rounding of _FOOT_CLEAR."""
        b = self._written_bounds()
        grown = _FOOT_CLEAR + _ROUNDING  # (more pairs than the tree's, never fewer)
        lx, hx = np.minimum(x0, x1) - grown, np.maximum(x0, x1) + grown
        ly, hy = np.minimum(y0, y1) - grown, np.maximum(y0, y1) + grown
        li, bi = np.nonzero(
            (lx[:, None] <= b[:, 2])
            & (hx[:, None] >= b[:, 0])
            & (ly[:, None] <= b[:, 3])
            & (hy[:, None] >= b[:, 1])
        )
        near = np.zeros(len(lines), dtype=bool)
        if not li.size:
            return near
        gap = _segment_box(np.c_[x0[li], y0[li], x1[li], y1[li]], b[bi])
        near[li[gap <= _FOOT_CLEAR - _ROUNDING]] = True
        ask = (np.abs(gap - _FOOT_CLEAR) < _ROUNDING) & ~near[li]
        if ask.any():
            li, bi = li[ask], bi[ask]
            shapely.prepare(lines[li])
            hit = shapely.dwithin(lines[li], self._written_boxes()[bi], _FOOT_CLEAR)
            near[li[hit]] = True
        return near

    def _written_boxes(self) -> np.ndarray:
        """The labels written as an array (leaders keep off them)."""
        if self._boxes_array is None:
            self._boxes_array = np.asarray(self.boxes, dtype=object)
        return self._boxes_array

    def _counts_back(self, leaders: set[Any], unsettled: int, far: int) -> None:
        """After the written labels' lists were cut or extended: the leaders
        and counts as they were then, the obstacles indexed again."""
        self._leaders = set(leaders)
        self.unsettled, self.far = unsettled, far
        self._seen = len(self.sketch.calls)
        self._tree = None
        self._grown = None

    def place(
        self,
        anchor: PointLike,
        markup: str,
        *,
        towards: PointLike | None = None,
        distance: float = 1.5,
        group: str | None = None,
        first: PointLike | None = None,
    ) -> BaseGeometry:
        """Write `markup` beside `anchor`, first trying the side `towards` points to
        (centred at `first` before all, where given: a room kept for it);
        inside a group `group` (class "label") if one is named. The names of
        things at one point ("d, s_{5}") go one under another where in one
        line they find no room near it."""
        x, y = float(anchor[0]), float(anchor[1])
        tries = [markup, "\n".join(f"{m}," for m in markup.split(", "))[:-1]]
        tries = tries[:1] if ", " not in markup else tries

        def write(settle: bool) -> BaseGeometry | None:
            for k, text in enumerate(tries):
                cx, cy, w, h, drop = self._around(np.array([x, y]), text, towards, distance)
                if first is not None and not k:
                    cx = np.concatenate([[float(first[0])], cx])
                    cy = np.concatenate([[float(first[1])], cy])
                footprint = self._write_first_free(
                    cx,
                    cy,
                    w,
                    h,
                    drop,
                    text,
                    group,
                    leader=((x, y), towards, distance),
                    settle=settle and k == len(tries) - 1,
                    names=("point", (x, y), None),
                )
                if footprint is not None:
                    return footprint
            return None

        return self._at_sizes(write)

    def place_first(
        self,
        anchors: Sequence[tuple[PointLike, PointLike | None]],
        markup: str,
        *,
        distance: float = 1.5,
        clear: bool = False,
    ) -> BaseGeometry:
        """Name a thing drawn at several places (a joint at each of a
        mechanism's positions drawn in main lines, a detail's disc by any
        point of its rim), each an (anchor, towards) pair, preferred first:
        `place` at the first where the name stands near it or is led to it
        (with `clear`, and is written on nothing); where it stands far at
        every one, at the first (as `place` alone writes it)."""
        saved = self._state() if len(anchors) > 1 else None
        for anchor, towards in anchors:
            before = (self.far, self.unsettled)
            footprint = self.place(anchor, markup, towards=towards, distance=distance)
            if (
                saved is None
                or self.far == before[0]
                and (not clear or self.unsettled == before[1])
            ):
                return footprint
            self._restore(saved)
        anchor, towards = anchors[0]
        return self.place(anchor, markup, towards=towards, distance=distance)

    @contextmanager
    def trial(self) -> Iterator[None]:
        """What is drawn on the sketch and written inside, undone after: a
        symbol drawn for a trial of where its labels find places."""
        saved = self._state()
        try:
            yield
        finally:
            self._restore(saved)

    def finds_place(
        self, anchor: PointLike, markup: str, *, towards: PointLike | None = None
    ) -> list[BaseGeometry] | None:
        """Whether `place` would write `markup` near `anchor` or led to it:
        the box it would take and its leader, if any (None: it would stand
        far). Asking writes nothing: a drawing chooses where its symbol goes
        by where its label finds a place."""
        before, drawn = self.far, len(self.sketch.calls)
        with self.trial():
            footprint = self.place(anchor, markup, towards=towards)
            led = [c for c in self.sketch.calls[drawn:] if isinstance(c, Line)]
            if self.far != before:
                return None
            return [footprint, *(LineString([c.start, c.end]) for c in led)]

    def _at_sizes(self, write: Callable[[bool], BaseGeometry | None]) -> BaseGeometry:
        """`write(settle)` at the letter height `size`; where that finds no
        place near and no leader (and `smaller` is set), at `smaller` (with
        `settle`: where none is found then either, written far)."""
        if self.smaller is None or self.smaller >= self.size:
            footprint = write(True)
        else:
            footprint = write(False)
            if footprint is None:
                kept = self.size
                self.size = self.smaller
                try:
                    footprint = write(True)
                finally:
                    self.size = kept
        assert footprint is not None, "the last try always writes"
        return footprint

    def place_arrow(
        self,
        start: PointLike,
        end: PointLike,
        markup: str,
        *,
        group: str | None = None,
        along: Sequence[float] | None = None,
    ) -> BaseGeometry:
        """Write a force's name by the head of its arrow start–end, on the side
        it points to; where that is taken, beside its shaft (at the fractions
        `along` of it, by default 0.5, 0.35 and 0.65 of it);
        else further out from the head with a leader."""
        a, b = np.asarray(start, dtype=float), np.asarray(end, dtype=float)
        u = (b - a) / max(float(np.hypot(*(b - a))), 1e-12)
        # the names of forces that share the arrow one under another where in one line they find no room
        tries = [markup, "\n".join(f"{m}," for m in markup.split(", "))[:-1]]
        tries = tries[:1] if ", " not in markup else tries

        def write(settle: bool) -> BaseGeometry | None:
            for k, text in enumerate(tries):
                cx, cy, w, h, drop = self._around(b, text, u, 1.5)
                sx, sy = self._beside(a, b, text, 1.0, _ALONG[:3] if along is None else along)
                footprint = self._write_first_free(
                    np.concatenate([cx, sx]),
                    np.concatenate([cy, sy]),
                    w,
                    h,
                    drop,
                    text,
                    group,
                    leader=((float(b[0]), float(b[1])), (float(u[0]), float(u[1])), 1.5),
                    settle=settle and k == len(tries) - 1,
                    names=("arrow", a, b),
                )
                if footprint is not None:
                    return footprint
            return None

        return self._at_sizes(write)

    def _around(
        self, anchor: np.ndarray, markup: str, towards: PointLike | None, distance: float
    ) -> tuple[np.ndarray, np.ndarray, float, float, float]:
        """Centres of the boxes round `anchor`, every candidate at once, nearest
        ring first (the box's nearest corner or edge middle `ring` mm from the
        anchor), the side `towards` first; the box's width, height and drop."""
        w, h, drop = self._extent(markup)
        x, y = float(anchor[0]), float(anchor[1])
        dirs = np.array(_COMPASS)
        if towards is not None and math.hypot(*towards) > 1e-12:
            t = complex(towards[0], towards[1]) / math.hypot(*towards)
            dirs = dirs[np.argsort(-(dirs.real * t.real + dirs.imag * t.imag), kind="stable")]
        ring = (distance + self.rings)[:, None]
        cx = (x + dirs.real * (ring + w / 2 * np.sqrt(np.abs(dirs.real)))).ravel()
        cy = (y + dirs.imag * (ring + h / 2 * np.sqrt(np.abs(dirs.imag)))).ravel()
        return cx, cy, w, h, drop

    def _beside(
        self, a: np.ndarray, b: np.ndarray, markup: str, distance: float, along: Sequence[float]
    ) -> tuple[np.ndarray, np.ndarray]:
        """Centres of the boxes beside the segment a–b at the fractions `along`,
        either side, nearest ring first."""
        w, h, drop = self._extent(markup)
        d = (b - a) / max(float(np.hypot(*(b - a))), 1e-12)
        sides = np.array([complex(-d[1], d[0]), complex(d[1], -d[0])])
        reach = w / 2 * np.abs(sides.real) + np.where(sides.imag > 0, h / 2 + drop, h / 2) * np.abs(
            sides.imag
        )
        anchors = a + np.array(along)[:, None] * (b - a)
        ring = (distance + self.rings)[:, None, None]
        cx = (anchors[:, 0][:, None] + sides.real * (ring + reach)).ravel()
        cy = (anchors[:, 1][:, None] + sides.imag * (ring + reach)).ravel()
        return cx, cy

    def place_along(
        self,
        start: PointLike,
        end: PointLike,
        markup: str,
        *,
        distance: float = 1.0,
        group: str | None = None,
        around: bool = False,
        along: Sequence[float] | None = None,
    ) -> BaseGeometry:
        """Write `markup` `distance` mm beside the segment start–end (a link's
        number): at its middle if that is free, else further along (at the
        fractions `along` of it, in turn), either side; with `around`, else
        round the middle further out (an arm h among others)."""
        a, b = np.asarray(start, dtype=float), np.asarray(end, dtype=float)
        d = (b - a) / max(float(np.hypot(*(b - a))), 1e-12)
        sides = np.array([complex(-d[1], d[0]), complex(d[1], -d[0])])
        anchors = a + np.array(_ALONG if along is None else along)[:, None] * (b - a)
        mx, my = (a + b) / 2
        leader = ((float(mx), float(my)), (float(sides[0].real), float(sides[0].imag)), distance)
        names: tuple[NamingKind, PointLike, PointLike | None] = ("segment", a, b)

        def write(settle: bool) -> BaseGeometry | None:
            w, h, drop = self._extent(markup)
            # how far the box reaches back towards the segment from its centre (an index hangs below)
            reach = w / 2 * np.abs(sides.real) + np.where(
                sides.imag > 0, h / 2 + drop, h / 2
            ) * np.abs(sides.imag)
            # nearest ring first, then along the segment, then the side
            ring = (distance + self.rings)[:, None, None]
            cx = (anchors[:, 0][:, None] + sides.real * (ring + reach)).ravel()
            cy = (anchors[:, 1][:, None] + sides.imag * (ring + reach)).ravel()
            if around:
                # where the segment's sides are taken: round its middle, further out
                dirs = np.array(_COMPASS)
                far = distance + np.concatenate(
                    [self.rings, self.rings[-1] + np.array([6.0, 12.0])]
                )
                far = far[:, None]
                cx = np.concatenate(
                    [cx, (mx + dirs.real * (far + w / 2 * np.abs(dirs.real))).ravel()]
                )
                cy = np.concatenate(
                    [cy, (my + dirs.imag * (far + h / 2 * np.abs(dirs.imag))).ravel()]
                )
            return self._write_first_free(
                cx, cy, w, h, drop, markup, group, leader=leader, settle=settle, names=names
            )

        return self._at_sizes(write)

    def _extent(self, markup: str) -> tuple[float, float, float]:
        """Width and height of the box a label keeps free, and how far its index drops."""
        # an index drops 0.3 of the letter height under the (last) line
        lines = markup.split("\n")
        drop = 0.3 * self.size if "_{" in lines[-1] else 0.0
        return self.width(markup) + 0.4, self.size + 0.4 + (len(lines) - 1) * self._pitch, drop

    @property
    def _pitch(self) -> float:
        """From line to line of a label of several lines, mm."""
        return 1.3 * self.size

    def _obstacle_cost(
        self, x0: np.ndarray, y0: np.ndarray, x1: np.ndarray, y1: np.ndarray
    ) -> np.ndarray:
        """0.25 for each avoided thing a candidate box comes within its clearance of."""
        cost = np.zeros(x0.size)
        if not self._obstacles or not x0.size:
            return cost
        box_, _ = self._index().boxes_near(x0, y0, x1, y1)
        if box_.size:
            cost += 0.25 * np.bincount(box_, minlength=x0.size)
        return cost

    def _clear(self, x0: np.ndarray, y0: np.ndarray, x1: np.ndarray, y1: np.ndarray) -> np.ndarray:
        """Which candidate boxes come within the clearance of no avoided thing
        (`_obstacle_cost` zero), asked as that: a box met once is not asked again."""
        if not self._obstacles or not x0.size:
            return np.ones(x0.size, dtype=bool)
        return self._index().boxes_clear(x0, y0, x1, y1)

    def _index(self) -> _ObstacleIndex:
        """The obstacles as segments and solids in a tree (built again after a
        change; the last few built kept: one built before a trial serves again
        once the trial is undone, the same obstacles by their serials)."""
        if self._tree is None:
            key = (len(self._obstacles), self._serials[-1] if self._serials else -1)
            built = self._indexes.pop(key, None)  # (kept again as the newest)
            if built is None:
                built = (
                    _ObstacleIndex(self._obstacles, self._clearance, self._heavy),
                    np.array(self._clearance),
                )
            self._indexes[key] = built
            while len(self._indexes) > _INDEXES_KEPT:
                del self._indexes[next(iter(self._indexes))]
            self._tree, self._reach = built
        return cast(_ObstacleIndex, self._tree)

    def _label_cost(
        self, x0: np.ndarray, y0: np.ndarray, x1: np.ndarray, y1: np.ndarray
    ) -> np.ndarray:
        """The area (mm²) candidate boxes share with the labels written, these
        widened by `spacing` each side: two labels on one line never run into
        each other as if they were one."""
        if not self.boxes:
            return np.zeros(x0.size)
        b = self._written_bounds()
        sp = self.spacing
        dx = np.minimum(x1[:, None], b[:, 2] + sp) - np.maximum(x0[:, None], b[:, 0] - sp)
        dy = np.minimum(y1[:, None], b[:, 3]) - np.maximum(y0[:, None], b[:, 1])
        return (np.maximum(dx, 0) * np.maximum(dy, 0)).sum(axis=1)

    def _lookalike_cost(
        self, markup: str, x0: np.ndarray, y0: np.ndarray, x1: np.ndarray, y1: np.ndarray
    ) -> np.ndarray:
        """1 for each label written that reads like `markup` (O and 0, l and 1)
        within LOOKALIKE_MM of a candidate box: a reader takes one for the other."""
        cost = np.zeros(x0.size)
        alike = [g.bounds for g, t in zip(self.boxes, self._texts) if {t, markup} in LOOKALIKE]
        if not alike or not x0.size:
            return cost
        candidates = np.stack([x0, y0, x1, y1], axis=-1)[:, None, :]
        gap = _box_box(candidates, np.array(alike)[None, :, :])
        return (gap < LOOKALIKE_MM + 0.5).sum(axis=1).astype(float)

    def _write(self, *args: Any, **kwargs: Any) -> BaseGeometry:
        """`_write_first_free` that always writes."""
        footprint = self._write_first_free(*args, **kwargs)
        assert footprint is not None
        return footprint

    def _write_first_free(
        self,
        cx: np.ndarray,
        cy: np.ndarray,
        w: float,
        h: float,
        drop: float,
        markup: str,
        group: str | None,
        leader: tuple[PointLike, PointLike | None, float] | None = None,
        settle: bool = True,
        names: tuple[NamingKind, PointLike, PointLike | None] | None = None,
    ) -> BaseGeometry | None:
        """Write `markup` centred at the first free candidate; else, with
        `leader` (the anchor, the preferred side, the distance), further out
        at the first free place a leader line can reach from the anchor; else
        (with `settle`; without it write nothing and return None) at the
        candidate that covers least."""
        self._sync()
        leader = leader if self.leaders else None
        x0, x1, y0, y1 = cx - w / 2, cx + w / 2, cy - h / 2 - drop, cy + h / 2
        cost = self._label_cost(x0, y0, x1, y1) + self._lookalike_cost(markup, x0, y0, x1, y1)
        # a point inside a block is named beside the block
        outline = enclosing(names[1], self._outlines) if names and names[2] is None else None
        # the one rule: written within NEAR_MM of what it names, or led to it
        # (measured of those off the lettering: the others only where no place is free)
        off = np.flatnonzero(cost <= 1e-9)
        off_near = (
            self._near(
                names, markup, cx[off], cy[off], (x0[off], y0[off], x1[off], y1[off]), outline
            )
            if names is not None
            else np.ones(off.size, dtype=bool)
        )
        # The obstacles are asked about the first ring of candidates with any
        # to ask, then about all the rest at once: most labels find room in the
        # first ring (the same pick as asking about all of them, since the
        # candidates are in order of preference; a query costs more than its boxes).
        per_ring = max(1, cx.size // len(self.rings))
        # (only those near and off the lettering are asked, and only whether any is met)
        asked = off[off_near]
        k = -1
        if asked.size:
            first_ring = np.searchsorted(asked, (asked[0] // per_ring + 1) * per_ring)
            for part in (asked[:first_ring], asked[first_ring:]):
                free = part[self._clear(x0[part], y0[part], x1[part], y1[part])]
                if free.size:
                    k = int(free[0])
                    break
        # what the place hangs on: the candidates up to it (all where none is free)
        upto = cx.size if k < 0 else k + 1
        self._read(x0[:upto], y0[:upto], x1[:upto], y1[:upto])
        line: tuple[tuple[float, float], tuple[float, float]] | None = None
        if k < 0 and names is not None and self.fine:
            # between the compass's places: every place near it on a fine grid,
            # nearest first (a gap between lines narrower than a ring apart)
            found_near = self._fine_near(names, outline, w, h, drop, markup)
            if found_near is not None:
                cx, cy, x0, x1, y0, y1 = _one_box(found_near, w, h, drop)
                k = 0
        if k < 0 and leader is not None:
            # nothing near is free: further out, tied to it by a leader that
            # crosses nothing, else only thin lines
            found = self._leader_place(leader, w, h, drop, names, outline, markup)
            if found is None and self.wide_leaders:
                found = self._wide_leader_place(leader, w, h, drop, names, outline, markup)
            if found is not None:
                (lx, ly), line = found
                cx, cy, x0, x1, y0, y1 = _one_box((lx, ly), w, h, drop)
                k = 0
        if k < 0 and names is not None and self.fine:
            # the last resort before a place far off: the fine grid again, the
            # box kept _TIGHT mm nearer the lines (still clear of them)
            found_near = self._fine_near(
                names, outline, w - 2 * _TIGHT, h - 2 * _TIGHT, drop, markup
            )
            if found_near is not None:
                cx, cy, x0, x1, y0, y1 = _one_box(found_near, w, h, drop)
                k = 0
        if k < 0 and leader is not None and names is not None and self.fine:
            # and before that: a leader further out, from anywhere along what it names
            found = self._leader_place(leader, w, h, drop, names, outline, markup, wide=True)
            if found is not None:
                (lx, ly), line = found
                cx, cy, x0, x1, y0, y1 = _one_box((lx, ly), w, h, drop)
                k = 0
        if k < 0 and names is not None and self.fine and self.shortest_leaders:
            found = self._shortest_leader_place(names, outline, w, h, drop, markup)
            if found is not None:
                (lx, ly), line = found
                cx, cy, x0, x1, y0, y1 = _one_box((lx, ly), w, h, drop)
                k = 0
        if k < 0 and settle and self.across_main and names is not None and self.fine:
            self._across = True
            try:
                found = self._shortest_leader_place(names, outline, w, h, drop, markup)
            finally:
                self._across = False
            if found is not None:
                (lx, ly), line = found
                cx, cy, x0, x1, y0, y1 = _one_box((lx, ly), w, h, drop)
                k = 0
                # led across a main line (not only thin ones, on the grid of
                # this last resort): a drawing that needs none is preferred
                self.far += self._across_main_line(line)
        if k < 0 and not settle:
            return None
        if k < 0:
            # No place near it and none a leader reaches: a free place further
            # out (a label on a line or a label reads as neither), else the
            # place near it that covers least, lettering first. (The first
            # free: of those off the lettering and not near, the near ones
            # were asked above and met something.)
            further = off[~off_near]
            first = self._first_clear(
                x0[further], y0[further], x1[further], y1[further], _FINE_BLOCK
            )
            if first is not None:
                k = int(further[first])
            else:
                near = (
                    self._near(names, markup, cx, cy, (x0, y0, x1, y1), outline)
                    if names is not None
                    else cost >= 0.0
                )
                cost += self._obstacle_cost(x0, y0, x1, y1)
                cost += 100.0 * self._label_cost(x0, y0, x1, y1)
                k = int(np.argmin(np.where(near, cost, np.inf) if near.any() else cost))
                self.unsettled += 1
            self.far += 1
        footprint = box(x0[k], y0[k], x1[k], y1[k])
        lines = self._say(markup).split("\n")
        # the recording keeps what the label names, for the sheet linter
        naming = self.sketch.naming(markup, *names) if names is not None else nullcontext()
        with self.sketch.group(group, "label") if group is not None else nullcontext(), naming:
            if line is not None:
                self.sketch.line(line[0], line[1], "thin")
            for i, text in enumerate(lines):
                y = float(cy[k]) + ((len(lines) - 1) / 2 - i) * self._pitch
                self.sketch.rich_text(
                    (float(cx[k]), y), text, self.size, anchor="center", valign="middle"
                )
        if self.follow:  # its own lettering is among `boxes`, not the obstacles
            self._seen = len(self.sketch.calls)
        if line is not None:
            self._leaders.add(len(self._obstacles))
            self.avoid(LineString(line), self.clearance)
        self.boxes.append(footprint)
        self._boxes_changed()
        self._texts.append(markup)
        return footprint

    def _fine_near(
        self,
        names: tuple[NamingKind, PointLike, PointLike | None],
        outline: BaseGeometry | None,
        w: float,
        h: float,
        drop: float,
        markup: str,
    ) -> tuple[float, float] | None:
        """The centre of the free box nearest what the label names on a grid
        _FINE_STEP mm apart over every place within NEAR_MM of it; None where
        none is free."""
        _, a, b = names
        pts = np.array([a, a if b is None else b], dtype=float)
        if outline is not None:
            pts = np.concatenate([pts, shapely.get_coordinates(outline)])
        reach = _NEAR_KEPT + max(w, h + drop) / 2
        lo, hi = pts.min(axis=0) - reach, pts.max(axis=0) + reach
        nx = int((hi[0] - lo[0]) / _FINE_STEP) + 1
        ny = int((hi[1] - lo[1]) / _FINE_STEP) + 1
        if nx * ny > _FINE_MOST:
            return None
        gx, gy = np.meshgrid(lo[0] + _FINE_STEP * np.arange(nx), lo[1] + _FINE_STEP * np.arange(ny))
        cx, cy = gx.ravel(), gy.ravel()
        x0, x1, y0, y1 = cx - w / 2, cx + w / 2, cy - h / 2 - drop, cy + h / 2
        gap = _gap(names, x0, y0, x1, y1, outline)
        # not on what it names: as far off it as the compass's nearest ring
        near = self._near(names, markup, cx, cy, (x0, y0, x1, y1), outline)
        keep = np.flatnonzero(near & (gap >= _FINE_OFF))
        keep = keep[np.argsort(gap[keep], kind="stable")]
        if not keep.size:
            return None
        x0, x1, y0, y1 = x0[keep], x1[keep], y0[keep], y1[keep]
        cost = self._label_cost(x0, y0, x1, y1) + self._lookalike_cost(markup, x0, y0, x1, y1)
        ok = np.flatnonzero(cost <= 1e-9)
        # asked about in blocks, nearest first: the first free one ends it
        first = self._first_clear(x0[ok], y0[ok], x1[ok], y1[ok], _FINE_BLOCK) if ok.size else None
        # what the place hangs on: the boxes up to it (all where none is free)
        upto = keep.size if first is None else int(ok[first]) + 1
        self._read(x0[:upto], y0[:upto], x1[:upto], y1[:upto])
        if first is None:
            return None
        k = keep[ok[first]]
        return float(cx[k]), float(cy[k])

    def _leader_place(
        self,
        leader: tuple[PointLike, PointLike | None, float],
        w: float,
        h: float,
        drop: float,
        names: tuple[NamingKind, PointLike, PointLike | None] | None = None,
        outline: BaseGeometry | None = None,
        markup: str = "",
        wide: bool = False,
    ) -> tuple[tuple[float, float], tuple[tuple[float, float], tuple[float, float]]] | None:
        """The centre of the first free box further out round the anchor that a
        straight leader from the anchor reaches without touching anything but
        what meets at the anchor (a leader that crosses no line first, else one
        that crosses a few thin lines); with the leader (its start, its end).
        A segment's or an arrow's label may be led from along it too; a point's
        inside a block (`outline`), from the block's corners and edges. None if
        no place is free. With `wide` (the last resort before a place far
        off), the rings go on to _WIDE_RINGS and a segment's leader may start
        anywhere along it (_WIDE_ALONG)."""
        (ax0, ay0), towards, distance = (float(leader[0][0]), float(leader[0][1])), *leader[1:]
        starts = [(ax0, ay0)]
        if outline is not None:
            ring = shapely.get_coordinates(outline.exterior)[:-1]
            mids = (ring + np.roll(ring, -1, axis=0)) / 2
            starts = [(float(x), float(y)) for x, y in np.concatenate([mids, ring])]
        if names is not None and names[2] is not None:
            p, q = np.asarray(names[1], dtype=float), np.asarray(names[2], dtype=float)
            if float(np.hypot(*(q - p))) > 2.0 * _LEADER_START:
                starts += [tuple(p + t * (q - p)) for t in (_WIDE_ALONG if wide else _ALONG)]
            elif wide and self.short_ends:
                starts += [tuple(p), tuple(q)]
        dirs = self._leader_dirs
        if towards is not None and math.hypot(*towards) > 1e-12:
            t = complex(towards[0], towards[1]) / math.hypot(*towards)
            dirs = dirs[np.argsort(-(dirs.real * t.real + dirs.imag * t.imag), kind="stable")]
        # the box's edge `ring` mm from the anchor along the direction
        half = np.minimum(
            (w / 2) / np.maximum(np.abs(dirs.real), 1e-9),
            (h / 2 + drop / 2) / np.maximum(np.abs(dirs.imag), 1e-9),
        )
        rings = self.leader_rings
        if wide:  # (led from the anchor alone, the rings already tried are not asked again)
            rings = (
                np.concatenate([rings, _WIDE_RINGS]) if len(starts) > 1 else np.array(_WIDE_RINGS)
            )
        ring = (distance + rings)[:, None]
        st = np.asarray(starts, dtype=float)
        # nearest ring first, then each start in turn, then the direction
        ox = (dirs.real * (ring + half)).ravel()
        oy = (dirs.imag * (ring + half) + drop / 2).ravel()
        n_rings = len(rings)
        shape = (n_rings, len(st), len(dirs))
        ax = np.broadcast_to(st[None, :, 0, None], shape).ravel()
        ay = np.broadcast_to(st[None, :, 1, None], shape).ravel()
        cx = ax + np.broadcast_to(ox.reshape(n_rings, 1, -1), shape).ravel()
        cy = ay + np.broadcast_to(oy.reshape(n_rings, 1, -1), shape).ravel()
        per_ring = len(st) * len(dirs)
        for r0 in range(0, n_rings, self.leader_group):
            part = slice(r0 * per_ring, (r0 + self.leader_group) * per_ring)
            found = self._leader_among(cx[part], cy[part], ax[part], ay[part], w, h, drop, markup)
            if found is not None:
                return found
        return None

    def _shortest_leader_place(
        self,
        names: tuple[NamingKind, PointLike, PointLike | None],
        outline: BaseGeometry | None,
        w: float,
        h: float,
        drop: float,
        markup: str,
    ) -> tuple[tuple[float, float], tuple[tuple[float, float], tuple[float, float]]] | None:
        """`shortest_leaders`: the centre of the free box, on a grid
        _SHORTEST_STEP mm apart (coarser where that would hold more than
        _SHORTEST_MOST places) up to _SHORTEST_REACH mm from what the label
        names, that a leader from the nearest point of it (snapped to every
        _SHORTEST_STEP mm along it) reaches crossing nothing, else the fewest
        thin lines (`_leader_among`), nearest first; with the leader. None
        where none is."""
        _, a, b = names
        if outline is not None:
            target: BaseGeometry = outline.exterior
        elif b is None or math.dist(a, b) < 1e-9:
            target = Point(a)
        else:
            target = LineString([a, b])
        reach = _SHORTEST_REACH + max(w, h + drop) / 2
        x_lo, y_lo, x_hi, y_hi = target.bounds
        wide, high = x_hi - x_lo + 2 * reach, y_hi - y_lo + 2 * reach
        step = _SHORTEST_STEP
        while (wide / step + 1) * (high / step + 1) > _SHORTEST_MOST:
            step *= 1.05
        gx, gy = np.meshgrid(
            np.arange(x_lo - reach, x_hi + reach, step),
            np.arange(y_lo - reach, y_hi + reach, step),
        )
        cx, cy = gx.ravel(), gy.ravel()
        x0, x1, y0, y1 = cx - w / 2, cx + w / 2, cy - h / 2 - drop, cy + h / 2
        gap = _gap(names, x0, y0, x1, y1, outline)
        keep = np.flatnonzero((gap > _LEADER_START + 0.5) & (gap <= _SHORTEST_REACH))
        if not keep.size:
            return None
        keep = keep[np.argsort(gap[keep], kind="stable")]
        cx, cy = cx[keep], cy[keep]
        if target.geom_type == "Point":
            ax, ay = np.full(cx.size, float(a[0])), np.full(cx.size, float(a[1]))
        else:
            boxes = shapely.box(x0[keep], y0[keep], x1[keep], y1[keep])
            foot = shapely.get_coordinates(shapely.shortest_line(target, boxes))[0::2]
            along = shapely.line_locate_point(target, shapely.points(foot))
            along = np.round(along / _SHORTEST_STEP) * _SHORTEST_STEP
            feet = shapely.get_coordinates(shapely.line_interpolate_point(target, along))
            ax, ay = feet[:, 0], feet[:, 1]
        return self._leader_among(cx, cy, ax, ay, w, h, drop, markup)

    def _wide_leader_place(self, *args: Any) -> Any:
        """`_leader_place` on the fine rings, every FINE_LEADER_DIRS directions."""
        kept = self.leader_rings, self._leader_dirs, self.leader_group
        self.leader_rings = np.array(FINE_LEADER_RINGS, dtype=float)
        self._leader_dirs = np.exp(
            1j * np.radians(360.0 / FINE_LEADER_DIRS * np.arange(FINE_LEADER_DIRS))
        )
        self.leader_group = FINE_LEADER_GROUP
        try:
            return self._leader_place(*args)
        finally:
            self.leader_rings, self._leader_dirs, self.leader_group = kept

    def _leader_among(
        self,
        cx: np.ndarray,
        cy: np.ndarray,
        ax: np.ndarray,
        ay: np.ndarray,
        w: float,
        h: float,
        drop: float,
        markup: str,
    ) -> tuple[tuple[float, float], tuple[tuple[float, float], tuple[float, float]]] | None:
        """Of the boxes centred at cx, cy, each led from ax, ay: the first free
        one whose leader crosses nothing, else the first whose leader crosses a
        few thin lines; None if none is free or reachable. (Asked about in
        blocks of boxes, nearest first, 4 times as many each time: a block
        that holds a leader crossing nothing ends it; else each block's
        leaders are kept for the few thin lines. Each box is measured alone,
        so the pick is the one asking about all at once gives.)"""
        kept: list[_Leaders] = []
        start, size = 0, _LEADER_BLOCK
        while start < cx.size:
            part = slice(start, start + size)
            led = self._leaders_of(cx[part], cy[part], ax[part], ay[part], w, h, drop, markup)
            if led is not None:
                found = led.first(0, self._runs_along)
                if found is not None:
                    # what the pick hangs on: the boxes up to it (the first
                    # such box and foot: one the same before it is picked as well)
                    (fx, fy), ((sx, sy), _) = found
                    at = (cx[part] == fx) & (cy[part] == fy) & (ax[part] == sx) & (ay[part] == sy)
                    upto = slice(start, start + int(np.flatnonzero(at)[0]) + 1)
                    self._read_led(cx[upto], cy[upto], ax[upto], ay[upto], w, h, drop)
                    return found
                kept.append(led)
            self._read_led(cx[part], cy[part], ax[part], ay[part], w, h, drop)
            start, size = start + size, 4 * size
        # the first that crosses a few thin lines
        for most in _LEADER_CROSSINGS:
            for led in kept:
                found = led.first(most, self._runs_along)
                if found is not None:
                    return found
        return None

    def _leaders_of(
        self,
        cx: np.ndarray,
        cy: np.ndarray,
        ax: np.ndarray,
        ay: np.ndarray,
        w: float,
        h: float,
        drop: float,
        markup: str,
    ) -> _Leaders | None:
        """The free boxes of those centred at cx, cy (led from ax, ay) that a
        leader reaches, with what each leader crosses; None if none is."""
        x0, x1, y0, y1 = cx - w / 2, cx + w / 2, cy - h / 2 - drop, cy + h / 2
        cost = self._label_cost(x0, y0, x1, y1) + self._lookalike_cost(markup, x0, y0, x1, y1)
        free = np.flatnonzero(cost <= 1e-9)
        free = free[self._clear(x0[free], y0[free], x1[free], y1[free])]  # and off the obstacles
        # each leader ends 0.4 mm short of its box's nearest point
        ax, ay = ax[free], ay[free]
        px, py = np.clip(ax, x0[free], x1[free]), np.clip(ay, y0[free], y1[free])
        length = np.hypot(px - ax, py - ay)
        keep = length > _LEADER_START + 0.5
        free, px, py, length, ax, ay = (v[keep] for v in (free, px, py, length, ax, ay))
        if not free.size:
            return None
        ux, uy = (px - ax) / length, (py - ay) / length
        ex, ey = px - 0.4 * ux, py - 0.4 * uy
        clear = shapely.linestrings(
            np.stack(
                [
                    np.column_stack([ax + _LEADER_START * ux, ay + _LEADER_START * uy]),
                    np.column_stack([ex, ey]),
                ],
                axis=1,
            )
        )
        if self.boxes:  # never through lettering (passing it by a hair is not through)
            # (no leader is taken there: what the others cross is measured alone)
            off = ~self._near_written(
                clear, ax + _LEADER_START * ux, ay + _LEADER_START * uy, ex, ey
            )
            if not off.all():
                free, ax, ay, ex, ey, clear = (v[off] for v in (free, ax, ay, ex, ey, clear))
                if not free.size:
                    return None
        # (a leader that crosses more than any of _LEADER_CROSSINGS allows is
        # never picked: what meets at its foot is not measured)
        crossed = self._met_at_feet(
            clear, self._crossings(clear), ax, ay, most=_LEADER_CROSSINGS[-1]
        )
        return _Leaders(cx[free], cy[free], ax, ay, ex, ey, clear, crossed)

    def _crossings(self, lines: np.ndarray) -> np.ndarray:
        """For each of `lines`, how many avoided lines it comes within the
        clearance of (a solid shape, an arrowhead or a dot, or another leader,
        counts as very many)."""
        out = np.zeros(len(lines), dtype=np.int64)
        if not self._obstacles or not len(lines):
            return out
        index = self._index()
        line, owner = index.lines_near(lines)
        if not line.size:
            return out
        # a polygon (arrowhead, dot) or another leader: never
        np.add.at(out, line, self._weights(index)[owner])
        return out

    def _across_main_line(self, line: tuple[PointLike, PointLike]) -> bool:
        """Whether the leader `line` (from its foot) crosses a main line, as
        `_leader_among` measures it with none crossable."""
        (ax, ay), (ex, ey) = line
        u = np.array([ex - ax, ey - ay]) / math.hypot(ex - ax, ey - ay)
        led = shapely.linestrings(
            [[(ax + _LEADER_START * u[0], ay + _LEADER_START * u[1]), (ex, ey)]]
        )
        crossed = self._met_at_feet(led, self._crossings(led), np.array([ax]), np.array([ay]))
        return bool(crossed[0] >= 10**6)

    def _weights(self, index: _ObstacleIndex) -> np.ndarray:
        """What crossing each obstacle of `index` counts: very many for those
        no leader crosses (its uncrossable ones and the leaders), 1 for a thin
        line; while `_across` (the last resort of `across_main`) a main line
        counts _MAIN_CROSSED."""
        weight = np.where(index.uncrossable, 10**6, 1)
        if self._across:
            weight[index.heavy & ~index.solid] = _MAIN_CROSSED
        weight[list(self._leaders)] = 10**6
        return weight

    def _met_at_feet(
        self,
        clear: np.ndarray,
        crossed: np.ndarray,
        ax: np.ndarray,
        ay: np.ndarray,
        most: int | None = None,
    ) -> np.ndarray:
        """`crossed` (`_crossings` of the leaders `clear`, whose feet are ax, ay)
        with what touches a leader's foot (the arc and the arrowhead of the ω
        it names, the links meeting at a joint) counted only where the leader
        comes within _FOOT_CLEAR of it: it leaves them there, and only a leader
        that runs over one of them crosses it. With `most`, a leader that would
        cross more than `most` even if all at its foot were left keeps its
        count (more than `most` too), not measured."""
        if not self._obstacles or not len(clear):
            return crossed
        index = self._index()
        shapes, lines, lb = index.shapes, *index.lines_bounds  # a point keeps its clearance
        crossed = crossed.copy()
        weights = self._weights(index)
        for fx, fy in set(zip(ax.tolist(), ay.tolist())):  # each foot once (in any order)
            at = index.at_foot.get((fx, fy))
            if at is None:
                # (only those whose box comes within 0.05 mm of the foot are measured)
                by = np.flatnonzero(
                    (lb[:, 0] <= fx + _AT_FOOT)
                    & (lb[:, 2] >= fx - _AT_FOOT)
                    & (lb[:, 1] <= fy + _AT_FOOT)
                    & (lb[:, 3] >= fy - _AT_FOOT)
                )
                at = lines[by[shapely.dwithin(shapes[lines[by]], Point(fx, fy), 0.05)]]
                index.at_foot[(fx, fy)] = at
            if not at.size:
                continue
            mine = np.flatnonzero((ax == fx) & (ay == fy))
            weight = weights[at]
            if most is not None:  # (no count falls by more than all at the foot weigh)
                mine = mine[crossed[mine] - int(weight.sum()) <= most]
                if not mine.size:
                    continue
            gap = shapely.distance(clear[mine][:, None], shapes[at][None, :])
            reach = index.reach[at]
            kept = ((gap < reach) * weight).sum(axis=1)
            hair = np.minimum(reach, _FOOT_CLEAR)
            crossed[mine] = np.maximum(crossed[mine] - kept, 0) + ((gap < hair) * weight).sum(
                axis=1
            )
        return crossed

    def _runs_along(self, line: BaseGeometry) -> bool:
        """True when a leader runs along a drawn segment (more than 8 mm of it
        within 1.5 mm of the segment: they meet at under about 10°): it would
        read as part of it. Measured at points 0.5 mm apart on the leader."""
        if not self._obstacles:
            return False
        index = self._index()
        reach, most = _LEADER_ALONG
        (x0, y0), (x1, y1) = shapely.get_coordinates(line)
        n = max(2, int(math.hypot(x1 - x0, y1 - y0) / 0.5) + 1)
        if (n - 1) * 0.5 <= most:
            return False
        lo, hi = (
            (min(x0, x1) - reach, min(y0, y1) - reach),
            (max(x0, x1) + reach, max(y0, y1) + reach),
        )
        near = index.tree.query(box(*lo, *hi))
        segs = index.segs[near[near < index.n_segs]]
        if not len(segs):
            return False
        t = np.linspace(0.0, 1.0, n)
        px, py = np.repeat(x0 + t * (x1 - x0), len(segs)), np.repeat(y0 + t * (y1 - y0), len(segs))
        d = _point_segment(px, py, np.tile(segs, (n, 1))).reshape(n, len(segs))
        step = math.hypot(x1 - x0, y1 - y0) / (n - 1)
        return bool((((d <= reach).sum(axis=0) - 1) * step > most).any())


def unique_ints(keys: np.ndarray) -> np.ndarray:
    """np.unique of a 1-D integer array (its values sorted, each once), found
    by sorting: numpy's own hashes the values first, several times slower on
    the few thousand (query, obstacle) keys a query gives."""
    if not keys.size:
        return keys.copy()
    ordered = np.sort(keys)
    first = np.empty(ordered.size, dtype=bool)
    first[0] = True
    np.not_equal(ordered[1:], ordered[:-1], out=first[1:])
    return ordered[first]


def _within(bounds: np.ndarray, slot: np.ndarray) -> bool:
    """Whether the box `bounds` (x0, y0, x1, y1) lies in the box `slot` (1e-6 mm kept for rounding)."""
    return bool(
        bounds[0] >= slot[0] - 1e-6
        and bounds[1] >= slot[1] - 1e-6
        and bounds[2] <= slot[2] + 1e-6
        and bounds[3] <= slot[3] + 1e-6
    )


def _point_box(px: np.ndarray, py: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Distance from points to boxes (x0, y0, x1, y1 columns of `b`), 0 inside."""
    dx = np.maximum(np.maximum(b[:, 0] - px, px - b[:, 2]), 0.0)
    dy = np.maximum(np.maximum(b[:, 1] - py, py - b[:, 3]), 0.0)
    return np.hypot(dx, dy)


def _box_box(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Distance between upright boxes (x0, y0, x1, y1 in the last axis), row by
    row or as the two broadcast, 0 where they meet."""
    dx = np.maximum(np.maximum(b[..., 0] - a[..., 2], a[..., 0] - b[..., 2]), 0.0)
    dy = np.maximum(np.maximum(b[..., 1] - a[..., 3], a[..., 1] - b[..., 3]), 0.0)
    return np.hypot(dx, dy)


def _point_segment(px: np.ndarray, py: np.ndarray, s: np.ndarray) -> np.ndarray:
    """Distance from points to segments (x0, y0, x1, y1 columns of `s`)."""
    vx, vy = s[:, 2] - s[:, 0], s[:, 3] - s[:, 1]
    n2 = vx * vx + vy * vy
    # (t 0 on a segment of no length; its sign of zero changes no distance)
    along = (px - s[:, 0]) * vx + (py - s[:, 1]) * vy
    t = np.divide(along, n2, out=np.zeros(np.broadcast(along, n2).shape), where=n2 > 0.0)
    t = np.minimum(np.maximum(t, 0.0), 1.0)
    return np.hypot(px - (s[:, 0] + t * vx), py - (s[:, 1] + t * vy))


def segments_meet_boxes(s: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Row by row, whether the segment (x0, y0, x1, y1) meets the box (xmin,
    ymin, xmax, ymax): Liang-Barsky clipping of the segment to the box (the
    four edges at once: t0 the largest entering fraction, t1 the least leaving)."""
    x0, y0 = s[:, 0], s[:, 1]
    dx, dy = s[:, 2] - x0, s[:, 3] - y0
    p = np.stack([-dx, dx, -dy, dy])
    q = np.stack([x0 - b[:, 0], b[:, 2] - x0, y0 - b[:, 1], b[:, 3] - y0])
    flat = p == 0.0
    r = q / np.where(flat, 1.0, p)
    t0 = np.maximum(np.where(~flat & (p < 0.0), r, 0.0).max(axis=0), 0.0)
    t1 = np.minimum(np.where(~flat & (p > 0.0), r, 1.0).min(axis=0), 1.0)
    return ~(flat & (q < 0.0)).any(axis=0) & (t0 <= t1)


def _segment_box(s: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Distance from segments to boxes, row by row: 0 where the segment
    meets the box (Liang-Barsky clipping), else the least of its ends' to the
    box and the box's corners' to it (the two ends, the four corners, each
    measured as `_point_box` and `_point_segment` do, in one pass)."""
    meets = segments_meet_boxes(s, b)
    ex, ey = s[:, [0, 2]].T, s[:, [1, 3]].T
    dx = np.maximum(np.maximum(b[:, 0] - ex, ex - b[:, 2]), 0.0)
    dy = np.maximum(np.maximum(b[:, 1] - ey, ey - b[:, 3]), 0.0)
    ends = np.hypot(dx, dy).min(axis=0)
    cx, cy = b[:, [0, 2, 2, 0]].T, b[:, [1, 1, 3, 3]].T
    corners = _point_segment(cx, cy, s).min(axis=0)
    return np.where(meets, 0.0, np.minimum(ends, corners))


def _segment_segment(s: np.ndarray, t: np.ndarray) -> np.ndarray:
    """Distance between segments, row by row: 0 where they cross, else the
    least of each one's ends' to the other."""

    def cross(ax, ay, bx, by, cx, cy):  # noqa: ANN001, ANN202
        return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)

    o1 = cross(s[:, 0], s[:, 1], s[:, 2], s[:, 3], t[:, 0], t[:, 1])
    o2 = cross(s[:, 0], s[:, 1], s[:, 2], s[:, 3], t[:, 2], t[:, 3])
    o3 = cross(t[:, 0], t[:, 1], t[:, 2], t[:, 3], s[:, 0], s[:, 1])
    o4 = cross(t[:, 0], t[:, 1], t[:, 2], t[:, 3], s[:, 2], s[:, 3])
    crossing = (o1 * o2 < 0.0) & (o3 * o4 < 0.0)
    d = np.minimum(
        np.minimum(_point_segment(t[:, 0], t[:, 1], s), _point_segment(t[:, 2], t[:, 3], s)),
        np.minimum(_point_segment(s[:, 0], s[:, 1], t), _point_segment(s[:, 2], s[:, 3], t)),
    )
    return np.where(crossing, 0.0, d)


@dataclass(frozen=True)
class _Memo:
    """What a label wrote in one of `write_later`'s orders (`_memo_write`):
    the region its writing asked about (x0, y0, x1, y1), what stood within
    reach of it then (`_standing`), what it added to the sketch and the
    placer's lists (its leaders by their places past the obstacles before
    it), and by how much the counts grew."""

    region: tuple[float, ...]
    standing: tuple[Any, ...]
    calls: tuple[Call, ...]
    boxes: tuple[BaseGeometry, ...]
    texts: tuple[str, ...]
    obstacles: tuple[BaseGeometry, ...]
    clearance: tuple[float, ...]
    heavy: tuple[bool, ...]
    outlines: tuple[BaseGeometry, ...]
    leaders: tuple[int, ...]
    unsettled: int
    far: int
    unseen: int  # of its calls, how many the placer had not yet looked at (the last)


@dataclass(frozen=True)
class _Leaders:
    """Free boxes a leader reaches (centres cx, cy), each leader's foot (ax,
    ay), end (ex, ey), line and how many lines it crosses (`crossed`)."""

    cx: np.ndarray
    cy: np.ndarray
    ax: np.ndarray
    ay: np.ndarray
    ex: np.ndarray
    ey: np.ndarray
    lines: np.ndarray
    crossed: np.ndarray

    def first(
        self, most: int, runs_along: Callable[[BaseGeometry], bool]
    ) -> tuple[tuple[float, float], tuple[tuple[float, float], tuple[float, float]]] | None:
        """The first box whose leader crosses at most `most` lines and runs
        along none (`runs_along`): its centre and the leader; else None."""
        for i in np.flatnonzero(self.crossed <= most):
            if runs_along(self.lines[i]):
                continue
            start = (float(self.ax[i]), float(self.ay[i]))
            return (float(self.cx[i]), float(self.cy[i])), (
                start,
                (float(self.ex[i]), float(self.ey[i])),
            )
        return None


# below this many (query, piece) pairs an index compares boxes in numpy
# rather than asking its tree (the same pairs: a tree pays its building and
# a geometry per query box)
_BRUTE_PAIRS = 20_000


class _ObstacleIndex:
    """What labels avoid, cut into pieces a query measures cheaply: every line,
    polyline and ring as its segments, a point as a segment of no length,
    solids (filled polygons, text boxes, arrowheads) whole; a tree of the
    pieces' boxes, each grown by its own clearance. A query asks the tree for
    the pieces whose grown boxes it meets, measures exactly (numpy for segments, shapely for
    solids) and returns each (query, obstacle) pair once."""

    def __init__(
        self,
        obstacles: Sequence[BaseGeometry],
        clearance: Sequence[float],
        heavy: Sequence[bool] = (),
    ) -> None:
        shapes = np.asarray(obstacles, dtype=object)
        kind = shapely.get_type_id(shapes)
        self.shapes, self.kind = shapes, kind
        self._lines_bounds: tuple[np.ndarray, np.ndarray] | None = None
        # the obstacles (other than points) at each leader's foot asked, by the foot
        self.at_foot: dict[tuple[float, float], np.ndarray] = {}
        self.reach = np.asarray(clearance, dtype=float)
        # a polygon (measured whole) or a main line: never crossed by a leader
        self.solid = kind == 3
        self.heavy = np.asarray(heavy, dtype=bool) if len(heavy) else np.zeros(len(shapes), bool)
        self.uncrossable = self.solid | self.heavy
        lines = np.flatnonzero((kind == 1) | (kind == 2))
        points = np.flatnonzero(kind == 0)
        xy, of = shapely.get_coordinates(shapes[lines], return_index=True)
        same = of[:-1] == of[1:]
        segs = np.c_[xy[:-1][same], xy[1:][same]]
        pxy = shapely.get_coordinates(shapes[points])
        self.segs = np.concatenate([segs, np.c_[pxy, pxy]]).reshape(-1, 4)
        whole = np.flatnonzero(~np.isin(kind, (0, 1, 2)))  # solids and anything else
        self.whole = shapes[whole]
        self.owner = np.concatenate([lines[of[:-1][same]], points, whole]).astype(int)
        self.n_segs = len(self.segs)
        bounds = np.concatenate(
            [
                np.c_[
                    np.minimum(self.segs[:, 0], self.segs[:, 2]),
                    np.minimum(self.segs[:, 1], self.segs[:, 3]),
                    np.maximum(self.segs[:, 0], self.segs[:, 2]),
                    np.maximum(self.segs[:, 1], self.segs[:, 3]),
                ],
                shapely.bounds(self.whole).reshape(-1, 4),
            ]
        )
        # the solids that are upright rectangles (text boxes mostly): a box's
        # distance to one is measured in numpy, box to box
        self.whole_bounds = bounds[self.n_segs :]
        wb = self.whole_bounds
        self.upright = (shapely.get_type_id(self.whole) == 3) & (
            shapely.get_num_coordinates(self.whole) == 5
        )
        self.upright &= np.isclose(
            shapely.area(self.whole), (wb[:, 2] - wb[:, 0]) * (wb[:, 3] - wb[:, 1]), rtol=1e-12
        )
        # each piece's box grown by its own clearance: a query box meets it
        # wherever the piece may come within that clearance (a large one, a
        # circle's radius, does not widen every query)
        g = self.reach[self.owner][:, None] if len(self.owner) else np.zeros((0, 1))
        self.grown = bounds + np.c_[-g, -g, g, g]
        self._tree: STRtree | None = None
        self.n = len(shapes)
        # each piece's clearance and whether it is an upright solid, and the
        # grown boxes' columns: read by every query
        self.piece_reach = self.reach[self.owner] if len(self.owner) else np.zeros(0)
        self.piece_upright = np.concatenate([np.zeros(self.n_segs, dtype=bool), self.upright])
        self._grown_columns = tuple(np.ascontiguousarray(c) for c in self.grown.T)
        # the segments' ends as columns ((x0, y0), (x1, y1)): gathered by `_segments_clear`
        cols = [np.ascontiguousarray(c) for c in self.segs.T]
        self._seg_ends = ((cols[0], cols[1]), (cols[2], cols[3]))

    @property
    def lines_bounds(self) -> tuple[np.ndarray, np.ndarray]:
        """The obstacles other than points (their indices) and their boxes
        (x0, y0, x1, y1 rows), made at the first call."""
        if self._lines_bounds is None:
            lines = np.flatnonzero(self.kind != 0)
            self._lines_bounds = lines, shapely.bounds(self.shapes[lines]).reshape(-1, 4)
        return self._lines_bounds

    @property
    def tree(self) -> STRtree:
        """The tree of the pieces' grown boxes (built at the first query that needs it)."""
        if self._tree is None:
            g = self.grown
            self._tree = STRtree(shapely.box(g[:, 0], g[:, 1], g[:, 2], g[:, 3]))
        return self._tree

    def _query(self, lo: np.ndarray, hi: np.ndarray) -> np.ndarray:
        """(query, piece) pairs whose boxes meet (edges touching count), for
        query boxes from `lo` (x, y rows) to `hi`, as the tree gives them:
        few pieces and queries are compared all at once, many asked of the tree."""
        if not len(lo):
            return np.zeros((2, 0), dtype=np.intp)
        g0, g1, g2, g3 = self._grown_columns
        # (only the pieces near all the queries compared: the others meet none)
        (near,) = np.nonzero(
            (g2 >= lo[:, 0].min())
            & (g0 <= hi[:, 0].max())
            & (g3 >= lo[:, 1].min())
            & (g1 <= hi[:, 1].max())
        )
        if len(lo) * near.size > _BRUTE_PAIRS:
            return np.asarray(self.tree.query(shapely.box(lo[:, 0], lo[:, 1], hi[:, 0], hi[:, 1])))
        qi, k = np.nonzero(
            (lo[:, 0, None] <= g2[near])
            & (hi[:, 0, None] >= g0[near])
            & (lo[:, 1, None] <= g3[near])
            & (hi[:, 1, None] >= g1[near])
        )
        return np.array([qi, near[k]], dtype=np.intp).reshape(2, -1)

    def _pairs(self, near: np.ndarray, gap: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        owner = self.owner[near[1]]
        hit = gap < self.reach[owner]
        keyed = unique_ints(near[0][hit] * self.n + owner[hit])
        return keyed // self.n, keyed % self.n

    def boxes_near(
        self, x0: np.ndarray, y0: np.ndarray, x1: np.ndarray, y1: np.ndarray
    ) -> tuple[np.ndarray, np.ndarray]:
        """(box, obstacle) pairs: the boxes within each obstacle's clearance."""
        near = self._query(
            np.column_stack([np.minimum(x0, x1), np.minimum(y0, y1)]),
            np.column_stack([np.maximum(x0, x1), np.maximum(y0, y1)]),
        )
        if not near.shape[1]:
            return near[0], near[1]
        b = np.stack([x0, y0, x1, y1], axis=1)[near[0]]
        gap = np.empty(near.shape[1])
        seg = near[1] < self.n_segs
        gap[seg] = _segment_box(self.segs[near[1][seg]], b[seg])
        if (~seg).any():
            solid = near[1] - self.n_segs
            upright = ~seg & self.upright[np.where(seg, 0, solid)]
            if upright.any():
                gap[upright] = _box_box(b[upright], self.whole_bounds[solid[upright]])
            other = ~seg & ~upright
            if other.any():
                rest = near[:, other]
                gap[other] = self._far_or(
                    rest,
                    _box_box(b[other], self.whole_bounds[rest[1] - self.n_segs]),
                    lambda ask: shapely.box(x0[ask], y0[ask], x1[ask], y1[ask]),
                )
        return self._pairs(near, gap)

    def _far_or(
        self, pairs: np.ndarray, lower: np.ndarray, shapes: Callable[[np.ndarray], Any]
    ) -> np.ndarray:
        """The distances of (query, solid) `pairs` as `_pairs` reads them:
        `lower` (each query's distance to its solid's box, no more than to
        the solid) where that is past the solid's clearance by more than
        rounding, else the exact distance of the query's shape (`shapes` of
        the queries' indices) from the solid, asked of shapely."""
        ask = lower < self.reach[self.owner[pairs[1]]] + 1e-9
        out = lower.copy()
        if ask.any():
            out[ask] = shapely.distance(
                shapes(pairs[0][ask]), self.whole[pairs[1][ask] - self.n_segs]
            )
        return out

    def boxes_clear(
        self, x0: np.ndarray, y0: np.ndarray, x1: np.ndarray, y1: np.ndarray
    ) -> np.ndarray:
        """Which boxes are within no obstacle's clearance (no pair of `boxes_near`):
        the upright solids asked first, then the segments and the other solids
        about the boxes still clear. (The pieces' boxes met are found by the
        grown boxes' columns, without stacking the queries; one box as one row.)"""
        clear = np.ones(x0.size, dtype=bool)
        lx, hx = np.minimum(x0, x1), np.maximum(x0, x1)
        ly, hy = np.minimum(y0, y1), np.maximum(y0, y1)
        g0, g1, g2, g3 = self._grown_columns
        # the pieces whose grown boxes meet the box round all the queries (a
        # label's candidates lie round one anchor): the others meet none
        (near,) = np.nonzero(
            (g2 >= lx.min()) & (g0 <= hx.max()) & (g3 >= ly.min()) & (g1 <= hy.max())
        )
        if lx.size * near.size > _BRUTE_PAIRS:
            qi, pi = np.asarray(self.tree.query(shapely.box(lx, ly, hx, hy)))
        elif lx.size == 1:  # one box: the pieces it meets, as one row
            pi, qi = near, np.zeros(near.size, dtype=np.intp)
        else:
            qi, k = np.nonzero(
                (lx[:, None] <= g2[near])
                & (hx[:, None] >= g0[near])
                & (ly[:, None] <= g3[near])
                & (hy[:, None] >= g1[near])
            )
            pi = near[k]
        if not qi.size:
            return clear
        reach = self.piece_reach[pi]
        seg = pi < self.n_segs
        solid = pi - self.n_segs
        upright = self.piece_upright[pi]
        if upright.any():
            b = np.stack([x0, y0, x1, y1], axis=1)[qi[upright]]
            gap = _box_box(b, self.whole_bounds[solid[upright]])
            clear[qi[upright][gap < reach[upright]]] = False
        if seg.any():
            self._segments_clear(clear, qi[seg], pi[seg], reach[seg], x0, y0, x1, y1)
        ask = ~seg & ~upright & clear[qi]
        if ask.any():
            rq = qi[ask]
            gap = shapely.distance(
                shapely.box(x0[rq], y0[rq], x1[rq], y1[rq]), self.whole[solid[ask]]
            )
            clear[rq[gap < reach[ask]]] = False
        return clear

    def _segments_clear(
        self,
        clear: np.ndarray,
        qi: np.ndarray,
        pi: np.ndarray,
        reach: np.ndarray,
        x0: np.ndarray,
        y0: np.ndarray,
        x1: np.ndarray,
        y1: np.ndarray,
    ) -> None:
        """`clear` False for the boxes (qi) still clear that a segment (pi)
        comes within `reach` of, as `_segment_box` measures it: an end of the
        segment within reach first (the distance is no more than an end's:
        those pairs are not measured whole), then the rest measured."""
        ask = clear[qi]
        if not ask.all():
            qi, pi, reach = qi[ask], pi[ask], reach[ask]
        bx0, by0, bx1, by1 = x0[qi], y0[qi], x1[qi], y1[qi]
        end = None
        for ex, ey in ((c[pi] for c in pair) for pair in self._seg_ends):
            dx = np.maximum(np.maximum(bx0 - ex, ex - bx1), 0.0)
            dy = np.maximum(np.maximum(by0 - ey, ey - by1), 0.0)
            end = np.hypot(dx, dy) if end is None else np.minimum(end, np.hypot(dx, dy))
        hit = end < reach
        clear[qi[hit]] = False
        rest = ~hit & clear[qi]
        if not rest.any():
            return
        # (the ends are out of reach here: met, else a corner within reach)
        qi, pi, reach = qi[rest], pi[rest], reach[rest]
        s = self.segs[pi]
        b = np.stack([x0[qi], y0[qi], x1[qi], y1[qi]], axis=1)
        meets = segments_meet_boxes(s, b) & (reach > 0.0)  # (at a distance of 0)
        clear[qi[meets]] = False
        rest = ~meets & clear[qi]  # (the corners measured only where still asked)
        if rest.any():
            qi, reach, s, b = qi[rest], reach[rest], s[rest], b[rest]
            corners = _point_segment(b[:, [0, 2, 2, 0]].T, b[:, [1, 1, 3, 3]].T, s).min(axis=0)
            clear[qi[corners < reach]] = False

    def lines_near(self, lines: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """(line, obstacle) pairs for two-point `lines`: those within each
        obstacle's clearance."""
        xy = shapely.get_coordinates(lines).reshape(-1, 4)
        lo = np.minimum(xy[:, :2], xy[:, 2:])
        hi = np.maximum(xy[:, :2], xy[:, 2:])
        near = self._query(lo, hi)
        if not near.shape[1]:
            return near[0], near[1]
        gap = np.empty(near.shape[1])
        seg = near[1] < self.n_segs
        gap[seg] = _segment_segment(self.segs[near[1][seg]], xy[near[0][seg]])
        if (~seg).any():
            rest = near[:, ~seg]
            lower = _segment_box(xy[rest[0]], self.whole_bounds[rest[1] - self.n_segs])
            gap[~seg] = self._far_or(rest, lower, lambda ask: lines[ask])
        return self._pairs(near, gap)


def drawn_shapes(call: Call, backend: RecordingBackend) -> list[BaseGeometry]:
    """What one recorded call covers on the paper: a line or polyline, an arrow's
    shaft and head, a polygon's edges (its inside too when filled), a circle's
    rim (the whole disc when filled or small), an arc, the box of a text."""
    name, a = call.name, call.args
    if name in ("line", "polyline"):
        pts = call.points()
        if len(pts) >= 2 and any(math.dist(pts[0], q) > 1e-9 for q in pts[1:]):
            return [LineString(pts)]
        return [Point(pts[0])] if pts else []
    if name == "arrow":
        s, e = np.asarray(a["start"], float), np.asarray(a["end"], float)
        length = float(np.hypot(*(e - s)))
        if length < 1e-9:
            return [Point(tuple(s))]
        u = (e - s) / length
        n = np.array([-u[1], u[0]])
        back = e - min(a["head_length"], length) * u
        half = a["head_width"] / 2
        head = Polygon([tuple(e), tuple(back + half * n), tuple(back - half * n)])
        return [LineString([tuple(s), tuple(e)]), head]
    if name == "polygon":
        if len(a["points"]) < 3:
            return [LineString(a["points"])] if len(a["points"]) == 2 else []
        ring = Polygon(a["points"])
        if a["fill"] != "none" and ring.is_valid:
            return [ring]
        return [ring.exterior]
    if name == "circle":
        disc = Point(a["center"]).buffer(a["radius"], 16)
        return [disc if a["fill"] != "none" or a["radius"] <= 2.0 else disc.exterior]
    if name == "arc":
        return [arc_line(a["center"], a["radius"], a["start_deg"], a["end_deg"])]
    if name == "text" and a["rotation"] % 360.0 == 0.0:
        return [box(*backend.text_box(call))]
    return []


def drawn_shapes_of(calls: Sequence[Call], backend: RecordingBackend) -> list[list[BaseGeometry]]:
    """`drawn_shapes` of each of `calls`, their lines and polylines made in one
    shapely call (the same geometries: a sketch's lines are most of its calls)."""
    out: list[list[BaseGeometry]] = []
    flat: list[Any] = []
    index: list[int] = []
    slots: list[int] = []
    for c in calls:
        if c.name in ("line", "polyline"):
            pts = c.points()
            if len(pts) >= 2 and any(math.dist(pts[0], q) > 1e-9 for q in pts[1:]):
                index += [len(slots)] * len(pts)
                flat += pts
                slots.append(len(out))
                out.append([])
                continue
        out.append(drawn_shapes(c, backend))
    if slots:
        made = shapely.linestrings(np.array(flat, dtype=float), indices=np.array(index))
        for k, line in zip(slots, made):
            out[k] = [line]
    return out


def arc_line(centre: PointLike, radius: float, start_deg: float, end_deg: float) -> LineString:
    """An arc drawn counter-clockwise from start_deg to end_deg, as a polyline."""
    span = (end_deg - start_deg) % 360.0 or 360.0
    t = np.radians(start_deg + np.linspace(0.0, span, 24))
    return LineString(np.c_[centre[0] + radius * np.cos(t), centre[1] + radius * np.sin(t)])


def enclosing(point: PointLike, outlines: Iterable[BaseGeometry]) -> BaseGeometry | None:
    """The smallest of the filled `outlines` no wider or taller than BLOCK_MM
    that holds `point` (a slider's block round its pin or mass centre), or
    None: a point drawn there is named beside the outline. Of two blocks as
    large (a link's two sliders over its mass centre), the one whose middle
    is nearest the point, and of two as near (two blocks crossed over it, gen
    104's S5) the one whose corners come first, taken from the point: the
    placer and the sheet linter, which see the outlines in different orders
    and moved by the sheet's layout, take the same one (a leader started on
    the other block's edge does not reach the block the linter sees)."""
    x, y = float(point[0]), float(point[1])
    p = Point(x, y)
    held = [
        g
        for g in outlines
        if g.geom_type == "Polygon"
        and max(g.bounds[2] - g.bounds[0], g.bounds[3] - g.bounds[1]) <= BLOCK_MM
        and g.contains(p)
    ]

    def order(g: BaseGeometry) -> tuple[Any, ...]:
        # every measure taken from the point and rounded: the same wherever the drawing stands
        corners = sorted(
            (round(cx - x, 6), round(cy - y, 6)) for cx, cy in shapely.get_coordinates(g)[:-1]
        )
        return (round(g.area, 6), round(g.centroid.distance(p), 6), corners)

    return min(held, key=order) if held else None


def _one_box(
    at: tuple[float, float], w: float, h: float, drop: float
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """One candidate centred `at`, as `_write_first_free` holds its candidates:
    the centre's x and y and the box's x0, x1, y0, y1 (an index hangs `drop` below)."""
    cx, cy = np.array([at[0]]), np.array([at[1]])
    return cx, cy, cx - w / 2, cx + w / 2, cy - h / 2 - drop, cy + h / 2


def _gap(
    names: tuple[NamingKind, PointLike, PointLike | None],
    x0: np.ndarray,
    y0: np.ndarray,
    x1: np.ndarray,
    y1: np.ndarray,
    outline: BaseGeometry | None = None,
) -> np.ndarray:
    """Distance (mm) from each candidate box to what its label names: the
    point (the block round it, `outline`), or the segment of an arrow or a
    link (as the linter measures it)."""
    _, a, b = names
    b_ = np.column_stack([x0, y0, x1, y1])
    if outline is not None:
        return np.asarray(shapely.distance(shapely.box(x0, y0, x1, y1), outline), dtype=float)
    if b is None or math.dist(a, b) < 1e-9:
        return _point_box(np.full(len(b_), float(a[0])), np.full(len(b_), float(a[1])), b_)
    seg = np.tile([float(a[0]), float(a[1]), float(b[0]), float(b[1])], (len(b_), 1))
    return _segment_box(seg, b_)
