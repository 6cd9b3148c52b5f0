"""Sheet 1: structural and kinematic solution (seed 003, Sheet 1, Appendix A).

Each drawing is first sketched in its own millimetre coordinates into a
recording, so that its footprint is known before it is placed; the layout
then finds free room on the sheet and the recording is replayed there.
"""

from __future__ import annotations

import dataclasses
import itertools
import math
import re
from collections.abc import Callable, Iterator, Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any, Literal, cast

import numpy as np
import shapely

from ..diagrams import (
    DIAGRAM_HEIGHT_MM,
    ILL_CONDITIONED,
    ROUND_POLE_DISTANCES_MM,
    KinematicDiagrams,
    graphical_differentiation,
)
from ..drawing.detail import (
    DETAIL_LETTERS,
    DETAIL_RATIOS,
    Detail,
    Name,
    choose_details,
    clipped,
    cut_to_disc,
    heads_outside,
    name_area,
    rim_anchors,
    spread,
)
from ..drawing.labels import (
    FINE_LEADER_DIRS,
    FINE_LEADER_GROUP,
    FINE_LEADER_RINGS,
    NEAR_MM,
    LabelCounts,
    Labels,
    _point_segment,
    arc_line,
    drawn_shapes,
    segments_meet_boxes,
    unique_ints,
)
from ..drawing.layout import LayoutError, SheetLayout
from ..drawing.markup import component_markup, image_markup, point_markup
from ..drawing.page import Page, Rect, draw_page
from ..drawing.pose import Block, Guide, Pose, draw_poses
from ..drawing.sketch import PAD as _PAD
from ..drawing.sketch import Sketch
from ..drawing.symbols import sense_arc, unit_vector
from ..drawing.table import DECIMALS_MAX, TABLE_PART_MM, rows_per_part, table_sketch
from ..errors import shown
from ..i18n import Language, catalogue, check_language
from ..render.backend import Backend
from ..render.look import LineType
from ..render.recording import Naming, RecordingBackend, Text
from ..scales import (
    LENGTH_MANTISSA_TEXT,
    Quantity,
    is_standard,
    scale_label,
    series,
)
from ..solution import Solution
from .common import EMPTY_MAX, laid_out_empty_share, length_scale_step, title_fields
from .common import next_scale as _next_scale
from .crowd import crowded, crowded_ends, crowded_names, far_names_again, stand_for
from .scales_record import Sheet1Scales

__all__ = ["Sheet1", "compose_sheet1", "GROUPS"]

GROUPS = (
    "mechanism",
    "structural-formula",
    "diagram-s",
    "diagram-v",
    "diagram-a",
    "table-velocities",
    "table-accelerations",
    "table-omega-eps",
    "table-check",
)

_TEXT = 3.5
_SMALL = 2.5
_TITLE = 5.0
_DENSE = 181
_NUMBER = re.compile(
    r"[-−]?\d+\.\d+(e[-+]?\d+)?"
)  # positions of the dense sweep for the trajectories


def _words(lang: Language):
    return catalogue(lang).words("sheet1")


# --- sketches: drawings in their own coordinates ---------------------------------


@dataclass
class Sheet1:
    """What compose_sheet1 drew: the layout, the scales, where each local origin went."""

    layout: SheetLayout
    scales: dict[str, float] = field(default_factory=dict)
    origins: dict[str, tuple[float, float]] = field(default_factory=dict)
    placed: dict[str, Rect] = field(default_factory=dict)
    shrink: int = 0  # series steps the acceleration plans' scale was raised by to make room
    field: Rect | None = None  # the mechanism's field (None: a crowded sheet's fallback)
    diagrams: KinematicDiagrams | None = None  # the S, V, a construction as drawn
    positions: tuple[int, ...] = ()  # the plan positions drawn

    @property
    def record(self) -> Sheet1Scales:
        """The scales drawn, as a typed record (scales_record.py)."""
        return Sheet1Scales.of(self.scales, self.positions)

    def fill(self) -> float:
        """How much of its field the mechanism's drawing fills: the larger of its
        width and height shares (1: it touches two opposite sides)."""
        if self.field is None or "mechanism" not in self.placed:
            return 0.0
        r = self.placed["mechanism"]
        return max(r.width / self.field.width, r.height / self.field.height)


def _fmt(x: float, digits: int = 3) -> str:
    """`digits` significant figures, never in exponent form, whole numbers kept
    whole: 333, 45.3, 0.0523, 1529 (not "1.53e+03", nor "1529.1885")."""
    if x is None or not math.isfinite(x):
        return "—"
    if abs(x) < 1e-12:
        return "0"
    text = f"{x:.{digits}g}"
    if "e" in text:
        decimals = max(0, digits - 1 - math.floor(math.log10(abs(x))))
        text = f"{x:.{decimals}f}"
    return text


def _tidy(mu: float) -> float:
    """0.7999999999999999 → 0.8: a scale computed as a product, shown as its series value."""
    return float(f"{float(mu):.9g}")


# --- the mechanism -----------------------------------------------------------------

_OMEGA_R, _EPS_R, _CRANK_R = 5.0, 8.0, 8.0  # radii of the ω, ε arcs and of ω1's, mm
# a label among many lines may go this much further out, mm, tried in turn
_MECHANISM_RINGS = (0.0, 1.2, 2.5, 3.5, 4.2, 5.0, 9.0, 14.0, 20.0)
# how the mechanism's names are placed (`_lettered_mechanism`)
_MECHANISM_LABELLING: dict[str, Any] = dict(
    rings=_MECHANISM_RINGS,
    leader_rings=FINE_LEADER_RINGS,
    leader_dirs=FINE_LEADER_DIRS,
    leader_group=FINE_LEADER_GROUP,
)
# a name that stands far on the laid-out mechanism, written again alone
# (_far_names_led), at 2.5 mm too
_MECHANISM_AGAIN: dict[str, Any] = dict(_MECHANISM_LABELLING, smaller=_SMALL)
_SPAN = 150.0
# the rooms kept for an ω/ε label round its arrowhead: near enough that the
# label written there is within NEAR_MM of it (its box's edge 1.9–4.9 mm off)
_ARC_LABEL_RINGS = (0.0, 1.5, 3.0)
_NEAR_RINGS = 2  # the rings of a label's boxes tried first, for all candidates at once
_MAX_SEGMENTS = 6  # a link of many points: its arcs are tried beside its longest segments
# what an arc whose label finds no free place near its arrowhead costs (as
# much as crossing 20 main lines: its label would stand far or on a line)
_NO_ROOM = 20.0
# the disc (radius, mm) round the arrowhead of a label with no room near it
# that later arcs keep off (as off a room kept for a label)
_WALLED = 8.0
# how much larger (mm) the ω and ε arcs of a link are tried, in turn, where a
# label finds no room near its arrowhead at the usual radii
_WIDER = (3.0, 6.0)
# and where none of those leaves it room: the arcs shorter, spanning this
# much (deg), their arrowheads 30° off the link instead of 15° (out of the
# bundle of its other positions' lines, nearly parallel to it), tried
# further along the link too (_ALONG_SHORT), at the usual radii and larger
_SHORT_SPAN = 120.0
_SHORT_WIDER = (0.0, 3.0)
# and where none of those leaves it room either (a link among the wide bundle
# of the positions' lines round a crowded crank), in a second lettering of
# the drawing, kept where it letters it better (sketch_mechanism): the usual
# arcs larger still, their arrowheads out of that bundle
_FAR_WIDER = (9.0, 12.0)
# and where none of those leaves it room either (a link in a dense bundle of
# its positions' lines, its arrowheads 15° off the link in that bundle):
# the usual arcs turned round their centre by these angles (deg), so that an
# arrowhead stands further out of the bundle, at the usual radii and _WIDER
_TURNS = (-30.0, 30.0, -60.0, 60.0, -90.0, 90.0)
_TURNED_WIDER = (0.0, *_WIDER)
# a mechanism of more links than this (a long chain, every drawing of it
# crowded) keeps the usual arcs and letter heights: the shorter arcs and the
# smaller figures are not tried (their cost, a pass more for each link and
# each label far, is then spent where they seldom help)
_SHORT_LINKS = 12
# a plan where more labels than this find no place near in the usual order
# keeps it (too crowded for another order to help; the acceleration plans of
# chains of 4 and 5 dyads, with 5 to 12 far at first, are helped by another)
_REORDER_MOST = 12
# how many of a link's candidate arcs, best scored first, are asked whether
# their labels find room (a long link of many positions has up to 84)
_ROOM_TRIES = 16
# the box an ω/ε label keeps free round its centre, mm: left/right, down, up (the
# placer's box of "ω_{10}" at _TEXT, its index hanging below, and its 0.4 mm clearance)
_ROOM_X, _ROOM_DOWN, _ROOM_UP = 3.7, 3.45, 2.4
# where a link's best arcs leave a label no room near its arrowhead: how many
# of the arcs tried, cheapest first, are drawn for a trial of whether that
# label finds a place all the same (on the fine grid, or led past the lines):
# all of them, mostly (up to 45 are asked in a link's tries; of a link round
# nearly one place at both plan positions, the 6 cheapest may all fail where
# the 9th or the 31st does)
_LED_TRIES = 48
# a segment farther than a query's distance by this much (mm) is apart from an
# arc however the distance is rounded (`_ArcPlacer._near_arcs`)
_APART_MARGIN = 1e-6
# the points of a candidate ω/ε arc's polyline (`_ArcPlacer._beside`, `_near_arcs`)
_ARC_POINTS = 24
# how far (mm) from a link's arcs the ω/ε labels written before its own may
# stand and take their places: a leader reaches 36 mm out (FINE_LEADER_RINGS)
_BEFORE_MM = 50.0
# a link's arcs as `_ArcPlacer.beside` tries them: their cost, centre, start
# angle (deg), the labels' rooms (None: none near), mm larger and span (deg)
_Arcs = tuple[float, np.ndarray, float, list["np.ndarray | None"], float, float]


def _arc_tip(
    centre: np.ndarray, radius: float, sense: float, start: float, span: float, inset: float
) -> np.ndarray:
    """The arrowhead of an arc of `span` deg from `start` (deg), `inset` deg
    short at each end, in the sense of `sense` (as sense_arc draws it)."""
    t = math.radians(start + span - inset if sense > 0 else start + inset)
    return np.asarray(centre, dtype=float) + radius * np.array([math.cos(t), math.sin(t)])


def _room_box(x: float, y: float) -> Any:
    """The room kept for an ω or ε label whose box is centred at (x, y)."""
    return shapely.box(x - _ROOM_X, y - _ROOM_DOWN, x + _ROOM_X, y + _ROOM_UP)


# a diagram's number or pole letter goes no further than this from its point, mm
_TICK_RINGS = (
    0.0,
    1.0,
    2.0,
    3.5,
    5.0,
    7.0,
)  # an arc beside a link spans this much of the half-plane on its side, deg
# where along a link its arcs are tried, the middle first
_ALONG_LINK = tuple(sorted(np.arange(0.2, 0.81, 0.1), key=lambda t: abs(t - 0.5)))
_ALONG_SHORT = tuple(sorted(np.arange(0.1, 0.91, 0.1), key=lambda t: abs(t - 0.5)))


def _inset(radius: float, inner: float = _OMEGA_R) -> float:
    """Degrees the outer (ε) arc stops short of the inner (ω, radius `inner`)
    one at each end, so that the inner arc's arrowhead and label stand clear of it."""
    return 0.0 if radius <= inner else 25.0


def _between_spokes(
    centre: np.ndarray, tip: np.ndarray, spokes: Sequence[np.ndarray], width: float
) -> np.ndarray:
    """Where a label `width` mm wide fits between the crank's lines (spokes
    from `centre`) nearest the arrowhead `tip`: on the bisector of a gap, as
    far out as the gap is wide enough; `tip` itself when no gap will do."""
    angles = sorted(
        {
            # rounded before the wrap, so that 359.9999999 and 0 are one spoke
            round(math.degrees(math.atan2(v[1], v[0])), 6) % 360.0
            for v in spokes
            if np.hypot(*v) > 1e-9
        }
    )
    reach = min((float(np.hypot(*v)) for v in spokes), default=0.0)
    if len(angles) < 2:
        return tip
    at_tip = math.degrees(math.atan2(*(tip - centre)[::-1])) % 360.0
    best: tuple[float, np.ndarray] | None = None
    for a, b in zip(angles, angles[1:] + [angles[0] + 360.0]):
        half = math.radians(b - a) / 2
        if half < 1e-6:
            continue  # spokes that coincide leave no gap
        if half >= math.pi / 2:
            r = float(np.hypot(*(tip - centre)))
        else:
            r = (width / 2 + 1.0) / math.sin(half) + 2.5
        if r > reach - 2.0:
            continue
        mid = (a + b) / 2
        off = abs((mid - at_tip + 180.0) % 360.0 - 180.0)
        u = np.array([math.cos(math.radians(mid)), math.sin(math.radians(mid))])
        if best is None or off < best[0]:
            best = (off, centre + u * max(r - 2.5, 0.0))
    return tip if best is None else best[1]


class _ArcPlacer:
    """Where the ω/ε arcs of a link go: round a point of the link, on one side
    of it, crossing as little of what is drawn as it can (a main line of a link
    or block counts 1, a thin line of another position or a trajectory 0.2, an
    arc 3, the room kept for a link's ω/ε label 50: an arc over it leaves that
    label on a line or far from its own arc, unless it finds another place; a
    label or its leader written 100: an arc over it puts that label on a line;
    made `far`, a block's outline or a pin 10), with a free box for each label
    next to its arrowhead."""

    _WEIGHT = {
        "main": 1.0,
        "thin": 0.2,
        "arc": 3.0,
        "room": 50.0,
        "label": 100.0,
        "symbol": 10.0,
    }

    def __init__(self, sk: Sketch, far: bool = False, walled: bool = True) -> None:
        self.sk = sk
        # with `walled`, the arrowhead of an arc whose label finds no room is
        # kept free of later arcs (_WALLED): where arcs of the same link at
        # another plan position are drawn round the same place
        self.walled = walled
        # with `far`, the arcs of a link whose names find no room at the usual
        # radii are tried larger still (_FAR_WIDER), and every arc keeps off
        # the blocks and the pins (an outline or a circle counts 10: a large
        # arc is not drawn over a slider); `lacking`: some found no room
        self.far = far
        self.lacking = False
        # the ω/ε labels of the links placed so far, as the drawing will write
        # them (tip, label, towards, the room kept for it): `_led`'s trial
        # writes those near first, as the final lettering does
        self.queued: list[tuple[np.ndarray, str, np.ndarray, np.ndarray | None]] = []
        self._seen = 0
        self._shapes: list[Any] = []
        self._weights: list[float] = []
        self._tree: Any = None

    def _add(self, shapes: Sequence[Any], kind: str) -> None:
        self._shapes += list(shapes)
        self._weights += [self._WEIGHT[kind]] * len(shapes)
        self._tree = None

    def reserve(self, shapes: Sequence[Any]) -> None:
        """Keep later arcs and labels' boxes off these (the room of labels to come)."""
        self._add(shapes, "arc")

    def _sync(self) -> bool:
        """Take in what was drawn since the last query; False: nothing is drawn."""
        calls = self.sk.calls
        for c in calls[self._seen :]:
            arc = c.name == "arc" or (c.name == "arrow" and c.args.get("head_length") == 2.5)
            kind = "arc" if arc else ("main" if c.args.get("line") == "main" else "thin")
            # lettering, and a label's leader (it names something), are kept clear
            kind = "label" if c.name == "text" or c.naming is not None else kind
            kind = "symbol" if self.far and c.name in ("polygon", "circle") else kind
            self._add(drawn_shapes(c, self.sk), kind)
        self._seen = len(calls)
        if not self._shapes:
            return False
        if self._tree is None:
            # long polylines (trajectories, arcs) go in as their segments, so
            # that a query measures distances to a few short pieces, not to
            # whole curves whose boxes cover half the drawing
            shapes = np.asarray(self._shapes, dtype=object)
            n = shapely.get_num_coordinates(shapes)
            long = (shapely.get_type_id(shapes) == 1) & (n >= 2)
            whole = np.flatnonzero(~long)
            xy, of = shapely.get_coordinates(shapes[long], return_index=True)
            same = of[:-1] == of[1:]  # consecutive points of one polyline
            ends = np.stack([xy[:-1][same], xy[1:][same]], axis=1)
            parts = np.concatenate([shapes[whole], shapely.linestrings(ends)])
            owner = np.concatenate([whole, np.flatnonzero(long)[of[:-1][same]]])
            segs = [np.full((len(whole), 4), np.nan), ends.reshape(-1, 4)]
            self._tree = shapely.STRtree(parts)
            self._parts = parts
            self._segs = np.concatenate(segs)  # x0 y0 x1 y1 of a segment part, else NaN
            self._owner = np.asarray(owner, dtype=int)
            self._w = np.asarray(self._weights)
        return True

    def _query(self, geoms: Any, distance: float) -> np.ndarray:
        """(index of the query shape, index of the drawn shape) pairs, each once;
        distance 0: the shapes that touch (a cheaper, prepared test)."""
        if distance > 0.0:
            pairs = np.asarray(self._tree.query(geoms, predicate="dwithin", distance=distance))
        else:
            pairs = self._touching(geoms)
        if pairs.ndim == 1:
            return unique_ints(self._owner[pairs])
        return self._owned(pairs)

    def _owned(self, pairs: np.ndarray) -> np.ndarray:
        """(query, part) pairs as (query, drawn shape) pairs, each once, sorted."""
        if pairs.shape[1] == 0:
            return pairs
        keyed = unique_ints(pairs[0] * len(self._shapes) + self._owner[pairs[1]])
        return np.stack([keyed // len(self._shapes), keyed % len(self._shapes)])

    def _near_arcs(
        self, lines: np.ndarray, centres: np.ndarray, radius: float, sweep: float, distance: float
    ) -> tuple[np.ndarray, np.ndarray]:
        """`_near_all(lines, distance)` of arcs drawn as polylines of _ARC_POINTS points
        `radius` mm from their `centres`, spanning `sweep` deg: the same pairs,
        found cheaper. The tree's boxes near each arc's box first; of those a
        segment that lies wholly inside the circle its chords keep out of, or
        wholly beyond the arc's radius, by more than `distance` (and a margin
        for rounding far above it) is left without asking; the rest asked as
        the tree's query asks them (the arc prepared, within `distance`)."""
        if not self._sync() or len(lines) == 0:
            return np.zeros(0, dtype=int), np.zeros(0, dtype=int)
        reach = distance + _APART_MARGIN
        b = shapely.bounds(lines)
        grown = shapely.box(b[:, 0] - reach, b[:, 1] - reach, b[:, 2] + reach, b[:, 3] + reach)
        qi, pj = np.asarray(self._tree.query(grown)).reshape(2, -1)
        sg = self._segs[pj]
        seg = np.flatnonzero(~np.isnan(sg[:, 0]))
        c, s = centres[qi[seg]], sg[seg]
        farthest = np.maximum(
            np.hypot(s[:, 0] - c[:, 0], s[:, 1] - c[:, 1]),
            np.hypot(s[:, 2] - c[:, 0], s[:, 3] - c[:, 1]),
        )
        nearest = _point_segment(c[:, 0], c[:, 1], s)
        # (a chord of the polyline comes no nearer its centre than this)
        inner = radius * math.cos(math.radians(sweep / (_ARC_POINTS - 1) / 2.0))
        apart = (farthest < inner - reach) | (nearest > radius + reach)
        keep = np.ones(len(qi), dtype=bool)
        keep[seg[apart]] = False
        qi, pj = qi[keep], pj[keep]
        shapely.prepare(lines)
        hit = np.asarray(shapely.dwithin(lines[qi], self._parts[pj], distance), dtype=bool)
        pairs = self._owned(np.stack([qi[hit], pj[hit]]))
        return pairs[0], pairs[1]

    def _touching(self, boxes: np.ndarray) -> np.ndarray:
        """(box, part) pairs of axis-parallel `boxes` and the drawn parts they
        touch: the tree's bounding boxes, then the exact test in numpy for a
        segment (Liang-Barsky clipping), shapely's for anything else."""
        pairs = np.asarray(self._tree.query(boxes))
        if pairs.shape[-1] == 0:
            return pairs.reshape(2, 0)
        boxes = np.asarray(boxes, dtype=object)
        bx = shapely.bounds(boxes)[pairs[0]]  # (each box's once)
        sg = self._segs[pairs[1]]
        seg = ~np.isnan(sg[:, 0])
        keep = np.zeros(len(sg), dtype=bool)
        keep[seg] = segments_meet_boxes(sg[seg], bx[seg])
        other = ~seg
        if other.any():
            keep[other] = shapely.intersects(boxes[pairs[0][other]], self._parts[pairs[1][other]])
        return pairs[:, keep]

    def _near(self, geom: Any, distance: float) -> np.ndarray:
        if not self._sync():
            return np.zeros(0, dtype=int)
        return self._query(geom, distance)

    def _near_all(self, geoms: np.ndarray, distance: float) -> tuple[np.ndarray, np.ndarray]:
        """One vectorised query for many shapes: (index of the shape, index of
        what it comes within `distance` of) pairs."""
        if not self._sync() or len(geoms) == 0:
            return np.zeros(0, dtype=int), np.zeros(0, dtype=int)
        pairs = self._query(geoms, distance)
        return pairs[0], pairs[1]

    def cost(self, arc: Any) -> float:
        """What `arc` crosses, weighted."""
        near = self._near(arc, 0.6)
        return float(self._w[near].sum()) if near.size else 0.0

    def costs(self, arcs: Sequence[Any]) -> np.ndarray:
        """`cost` of each of `arcs`, in one query."""
        i, j = self._near_all(np.asarray(arcs, dtype=object), 0.6)
        out = np.zeros(len(arcs))
        if i.size:
            out += np.bincount(i, weights=self._w[j], minlength=len(arcs))
        return out

    def kept_near(self, centre: np.ndarray) -> bool:
        """Whether a label's box centred at `centre` touches a room kept for
        another label (or an arc)."""
        x, y = float(centre[0]), float(centre[1])
        room = _room_box(x, y)
        _, near = self._near_all(np.array([room], dtype=object), 0.0)
        return bool(near.size and (self._w[near] >= self._WEIGHT["arc"]).any())

    def _covered(self, box: Any) -> int:
        return int(self._near(box, 0.3).size)

    def beside(
        self,
        segments: Sequence[tuple[np.ndarray, np.ndarray]],
        spins: Sequence[tuple[float, float]],
        labels: Labels | None = None,
        markups: Sequence[str] = (),
        short: bool = True,
        lines: Sequence[LineType] = (),
    ) -> tuple[np.ndarray, float, list[np.ndarray | None], float, float]:
        """`_beside` at the usual radii; with `labels`, where a label finds
        no room near its arrowhead there, at radii _WIDER mm larger in turn
        (an arrowhead out of a bundle of lines), then (with `short`) the arcs
        shorter (_SHORT_SPAN, tried further along the link, at the usual radii
        and 3 mm larger), then turned round their centres (_TURNS, at the
        usual radii and _WIDER: an arrowhead further out of a bundle of the
        positions' lines, the arc over the link where it must), then (a
        placer made `far`) _FAR_WIDER mm larger: the arcs whose labels find
        room, crossing least; where none leaves a label room, the first of
        the cheapest where it finds a place all the same (`_led`). The
        centre, start angle, the labels' places, how much larger the radii
        are, mm, and the span, deg."""
        # (span, fractions along, mm larger, turns)
        tries: list[tuple[float, Sequence[float], float, Sequence[float]]]
        tries = [(_SPAN, _ALONG_LINK, 0.0, (0.0,))]
        if labels is not None:
            tries += [(_SPAN, _ALONG_LINK, w, (0.0,)) for w in _WIDER]
            tries += [(_SHORT_SPAN, _ALONG_SHORT, w, (0.0,)) for w in _SHORT_WIDER if short]
            tries += [(_SPAN, _ALONG_LINK, w, _TURNS) for w in _TURNED_WIDER if short]
            tries += [(_SPAN, _ALONG_LINK, w, (0.0,)) for w in _FAR_WIDER if self.far]
        tried: list[_Arcs] = []  # every candidate asked, in the order asked
        for span, along, wider, turns in tries:
            wide = [(radius + wider, sense) for radius, sense in spins]
            _, _, picked, _, asked = self._beside(
                segments, wide, labels, markups, wider, span, along, turns
            )
            tried += [(c, cs, st, rooms, wider, span) for c, cs, st, rooms in asked]
            if all(p is not None for p in picked):
                break
        best = min(tried, key=lambda a: a[0])  # (the first of equal cost)
        if labels is not None and any(p is None for p in best[3]):
            best = self._led(best, tried, spins, labels, markups, lines)
        _, centre, start, picked, wider, span = best
        self.lacking |= any(p is None for p in picked)
        # (another position's arcs of the link, drawn round the same place, go
        # round these rooms: the label is written in its room later)
        self._add([_room_box(*p) for p in picked if p is not None], "room")
        # and round the arrowhead of a label with no room near it: a later arc
        # drawn round it (another position's of the link, at the same place)
        # walls it in, and no leader reaches it past that arc's main line
        tips = [
            _arc_tip(
                centre, radius + wider, sense, start, span, _inset(radius + wider, _OMEGA_R + wider)
            )
            for (radius, sense), p in zip(spins, picked)
            if p is None and self.walled
        ]
        self._add([shapely.Point(*tip).buffer(_WALLED) for tip in tips], "room")
        return centre, start, picked, wider, span

    def _led(
        self,
        best: _Arcs,
        tried: Sequence[_Arcs],
        spins: Sequence[tuple[float, float]],
        labels: Labels,
        markups: Sequence[str],
        lines: Sequence[LineType],
    ) -> _Arcs:
        """Where the `best` arcs of a link leave a label no room near its
        arrowhead: of the arcs `tried` (every candidate asked in each try of
        `beside`), the cheapest _LED_TRIES drawn in turn for a trial, the
        first where every such label finds a place all the same (on the
        placer's fine grid near it, or led to it past the lines round it:
        `Labels.finds_place`) once the labels the drawing writes before it
        stand written (`_written_before`: else it may find only a place
        another takes first); `best` where none does (its label then stands
        far). Arcs other than `best` keep their labels' places (box and
        leader) free of the arcs drawn after them."""
        # (a place out of the drawing's box would grow it: a drawing is fitted
        # on its sheet by its box)
        ext = self.sk.extent()
        inside = shapely.box(ext.left, ext.bottom, ext.right, ext.top)
        # (each trial measures only the arcs it draws against what stood before)
        drawn, bounds = len(self.sk.calls), self.sk.bounds()
        for arcs in sorted(tried, key=lambda a: a[0])[:_LED_TRIES]:
            _, centre, start, picked, wider, span = arcs
            kept: list[Any] = []  # the places its labels find
            with labels.trial():  # (the arcs drawn by the caller once chosen)
                tips = [
                    sense_arc(
                        self.sk,
                        centre,
                        radius + wider,
                        sense,
                        start + _inset(radius + wider, _OMEGA_R + wider),
                        start + span - _inset(radius + wider, _OMEGA_R + wider),
                        line,
                    )
                    for (radius, sense), line in zip(spins, lines)
                ]
                # (arcs other than the best, drawn anyway, do not grow it either)
                fits = arcs is best or self.sk.extent_since(bounds, drawn) == ext
                if fits:
                    self._written_before(labels, centre, tips, markups, picked)
                for tip, markup, room in zip(tips, markups, picked):
                    if fits and room is None:
                        found = labels.finds_place(tip, markup, towards=tip - centre)
                        fits = found is not None and all(inside.covers(f) for f in found)
                        kept += found or []
                        if fits:  # (written: the link's next label keeps off it)
                            labels.place(tip, markup, towards=tip - centre)
            if fits:
                if arcs is not best:
                    self._add(kept, "room")
                return arcs
        return best

    def _written_before(
        self,
        labels: Labels,
        centre: np.ndarray,
        tips: Sequence[np.ndarray],
        markups: Sequence[str],
        picked: Sequence[np.ndarray | None],
    ) -> None:
        """For `_led`'s trial of a link's arcs (their arrowheads `tips`):
        written as the drawing's lettering will write them before the link's
        labels without room, the labels with a room kept (the `queued` of
        the links before within _BEFORE_MM of the arcs' centre: no further
        one reaches a place near them; then the link's own). (Those without
        room, written after them, are left out: each a leader search, they
        cost more than half the trials.)"""
        mine = [
            (tip, markup, room - tip, room)
            for tip, markup, room in zip(tips, markups, picked)
            if room is not None
        ]
        near = [
            q
            for q in self.queued
            if q[3] is not None and float(np.hypot(*(q[0] - centre))) <= _BEFORE_MM
        ]
        for tip, markup, towards, room in near + mine:
            labels.place(tip, markup, towards=towards, first=room)

    def _beside(
        self,
        segments: Sequence[tuple[np.ndarray, np.ndarray]],
        spins: Sequence[tuple[float, float]],
        labels: Labels | None,
        markups: Sequence[str],
        wider: float,
        span: float = _SPAN,
        along: Sequence[float] = _ALONG_LINK,
        turns: Sequence[float] = (0.0,),
    ) -> tuple[
        np.ndarray,
        float,
        list[np.ndarray | None],
        float,
        list[tuple[float, np.ndarray, float, list[np.ndarray | None]]],
    ]:
        """Centre and start angle (deg) of the arcs (radius, sense) of a link
        beside one of its segments (at the fractions `along` of it), spanning
        `span` degrees on one side of it (turned by each of `turns`, deg),
        and the free place of each one's label (its box's centre; None: asked
        of `labels`, none is free near its arrowhead).

        Every candidate (a point along a segment, a side) is scored at once:
        the arcs' crossings in one vectorised query, the label boxes' cover in
        another; for each label the nearest box clear of the drawing and of the
        link's other label, else the least covered (10 for each thing a box
        touches, and how far out it is, mm). With `labels` (the placer that
        writes them) and the labels' `markups`, the candidates are then asked
        in that order whether each label finds a free place near its
        arrowhead (`_label_rooms`): the first where all do wins, unless one
        scored better by more than a label without room costs. Last, every
        candidate so asked: its cost, centre, start angle and labels' places."""
        centres: list[np.ndarray] = []
        starts: list[float] = []
        # the cost bounded for a link of many points: its longest segments only
        lengths = [float(np.hypot(*(b - a))) for a, b in segments]
        if len(segments) > _MAX_SEGMENTS:
            cut = sorted(lengths, reverse=True)[_MAX_SEGMENTS - 1]
            segments = [sg for sg, ln in zip(segments, lengths) if ln >= cut][:_MAX_SEGMENTS]
        for a, b in segments:
            if float(np.hypot(*(b - a))) < 1e-9:
                continue
            theta = math.degrees(math.atan2(*(b - a)[::-1]))
            for t in along:
                for side in (0.0, 180.0):
                    for turn in turns:
                        centres.append(a + t * (b - a))
                        starts.append(theta + side + (180.0 - span) / 2 + turn)
        assert centres, "a link with no segment of length"
        cs = np.asarray(centres, dtype=float)
        st = np.asarray(starts, dtype=float)
        m, n_spins = len(cs), len(spins)
        score = 0.01 * np.arange(m, dtype=float)
        own: list[np.ndarray] = []  # points of each candidate's own arcs, 0.5 mm apart or less
        # the arcs: the same polylines as arc_line draws
        for radius, _ in spins:
            inset = _inset(radius, _OMEGA_R + wider)
            sweep = (span - 2.0 * inset) % 360.0 or 360.0
            ang = np.radians((st + inset)[:, None] + np.linspace(0.0, sweep, _ARC_POINTS)[None, :])
            xy = np.stack([cs[:, :1] + radius * np.cos(ang), cs[:, 1:] + radius * np.sin(ang)], -1)
            i, j = self._near_arcs(shapely.linestrings(xy), cs, radius, sweep, 0.6)
            if i.size:
                score += np.bincount(i, weights=self._w[j], minlength=m)
                if wider in _FAR_WIDER:  # an arc that large never over a name written
                    score[i[self._w[j] >= self._WEIGHT["label"]]] = np.inf
            fine = np.radians(
                (st + inset)[:, None] + np.linspace(0.0, sweep, int(sweep * radius / 25.0) + 2)
            )
            own.append(
                np.stack([cs[:, :1] + radius * np.cos(fine), cs[:, 1:] + radius * np.sin(fine)], -1)
            )
        # the label boxes: 8 directions × the rings round each arrowhead
        rings = 1.5 + np.asarray(_ARC_LABEL_RINGS)
        dirs = 45.0 * np.arange(8)
        boxes_xy = np.empty((m, n_spins, len(rings) * 8, 2))
        for s, (radius, sense) in enumerate(spins):
            inset = _inset(radius, _OMEGA_R + wider)
            tip_deg = st + span - inset if sense > 0 else st + inset
            tr = np.radians(tip_deg)
            tip = cs + radius * np.stack([np.cos(tr), np.sin(tr)], -1)
            d = np.radians(tip_deg[:, None] + dirs[None, :])  # (m, 8)
            reach = (rings + 3.0)[None, :, None]  # (1, rings, 1)
            boxes_xy[:, s, :, 0] = (tip[:, 0, None, None] + np.cos(d)[:, None, :] * reach).reshape(
                m, -1
            )
            boxes_xy[:, s, :, 1] = (tip[:, 1, None, None] + np.sin(d)[:, None, :] * reach).reshape(
                m, -1
            )
        # How many drawn things each box touches (a box 0.3 mm larger each way
        # stands for "within 0.3 mm"): the two inner rings of every candidate
        # at once; the outer rings only of a candidate whose label found no
        # free box there (a free inner box beats any outer one).
        near = 8 * _NEAR_RINGS
        covered = np.full(boxes_xy.shape[:3], -1, dtype=int)
        # a label's room is not on the link's own arcs (drawn after this choice),
        # their arrowheads included: the label's box and its clearance
        arcs_xy = np.concatenate(own, axis=1)  # (m, points, 2)
        on_own = np.zeros(boxes_xy.shape[:3], dtype=int)
        for s_ in range(n_spins):
            dx = np.abs(boxes_xy[:, s_, :, None, 0] - arcs_xy[:, None, :, 0])
            dy = arcs_xy[:, None, :, 1] - boxes_xy[:, s_, :, None, 1]
            inside = (dx <= _ROOM_X + 0.3) & (dy >= -_ROOM_DOWN - 0.3) & (dy <= _ROOM_UP + 0.3)
            on_own[:, s_] = np.any(inside, axis=2)

        def count(xy: np.ndarray) -> np.ndarray:
            flat = xy.reshape(-1, 2)
            geoms = shapely.box(
                flat[:, 0] - _ROOM_X,
                flat[:, 1] - _ROOM_DOWN,
                flat[:, 0] + _ROOM_X,
                flat[:, 1] + _ROOM_UP,
            )
            i, _ = self._near_all(geoms, 0.0)
            return np.bincount(i, minlength=len(flat)).reshape(xy.shape[:-1])

        covered[:, :, :near] = count(boxes_xy[:, :, :near]) + on_own[:, :, :near]
        # the candidates with a label that has no free inner box: their outer
        # rings in one query too
        full = np.all(covered[:, :, :near] > 0, axis=2)
        lacking = np.flatnonzero(np.any(full, axis=1))
        if lacking.size:
            covered[lacking, :, near:] = (
                count(boxes_xy[lacking, :, near:]) + on_own[lacking, :, near:]
            )
        ring_of = 0.5 * np.repeat(np.asarray(_ARC_LABEL_RINGS), 8)
        chosen_all: list[list[int]] = []
        for c in range(m):
            chosen: list[int] = []
            for s in range(n_spins):
                ok = np.ones(covered.shape[2], dtype=bool)
                for k in chosen:  # not on the link's other label (boxes that touch)
                    dx = np.abs(boxes_xy[c, s, :, 0] - boxes_xy[c, k // 10_000, k % 10_000, 0])
                    dy = np.abs(boxes_xy[c, s, :, 1] - boxes_xy[c, k // 10_000, k % 10_000, 1])
                    ok &= ~((dx <= 2 * _ROOM_X) & (dy <= _ROOM_DOWN + _ROOM_UP))
                if not ok.any():
                    chosen.append(s * 10_000)
                    continue
                if not (ok[:near] & (covered[c, s, :near] == 0)).any() and covered[c, s, near] < 0:
                    covered[c, :, near:] = count(boxes_xy[c, :, near:]) + on_own[c, :, near:]
                sc = np.where(ok, 10.0 * covered[c, s] + ring_of, np.inf)
                sc[covered[c, s] < 0] = np.inf
                k = int(np.argmin(sc))
                score[c] += sc[k]
                chosen.append(s * 10_000 + k)
            chosen_all.append(chosen)
        best = int(np.argmin(score))
        picked: list[np.ndarray | None] = [
            np.asarray(boxes_xy[best, k // 10_000, k % 10_000], dtype=float)
            for k in chosen_all[best]
        ]
        cost = float(score[best])
        # where each label's box at the best touches nothing drawn, it is taken
        # as it is; else the candidates are asked of the placer that writes them
        bare = all(covered[best, k // 10_000, k % 10_000] == 0 for k in chosen_all[best])
        if labels is not None and not bare:
            kept = [
                [boxes_xy[c, k // 10_000, k % 10_000] for k in ks]
                for c, ks in enumerate(chosen_all)
            ]
            best, picked, cost, options = self._label_rooms(
                cs, st, spins, markups, labels, score, wider, kept, span
            )
            asked = [(o[0], cs[o[1]], float(st[o[1]]), o[2]) for o in options]
            return cs[best], float(st[best]), picked, cost, asked
        return cs[best], float(st[best]), picked, cost, [(cost, cs[best], float(st[best]), picked)]

    def _label_rooms(
        self,
        cs: np.ndarray,
        st: np.ndarray,
        spins: Sequence[tuple[float, float]],
        markups: Sequence[str],
        labels: Labels,
        score: np.ndarray,
        wider: float,
        kept: Sequence[Sequence[np.ndarray]],
        span: float = _SPAN,
    ) -> tuple[
        int, list[np.ndarray | None], float, list[tuple[float, int, list[np.ndarray | None]]]
    ]:
        """Of the arcs centred at `cs` starting at `st` (deg), asked best
        `score` first: the first whose every label finds a free place near
        its arrowhead (`Labels.rooms`, the link's arcs kept clear; the place
        `kept` for it by `_beside` first, where free), out of the
        rooms kept for other labels and apart from each other; a label without
        room costs _NO_ROOM; the best _ROOM_TRIES are asked. The candidate, its
        labels' places (None: no room near), its cost, and every candidate
        asked (cost, index, labels' places)."""
        options: list[tuple[float, int, list[np.ndarray | None]]] = []
        for c in np.argsort(score, kind="stable")[:_ROOM_TRIES]:
            if options and score[c] >= min(o[0] for o in options):
                break
            arcs = []
            for radius, _ in spins:
                inset = _inset(radius, _OMEGA_R + wider)
                arcs.append(arc_line(cs[c], radius, st[c] + inset, st[c] + span - inset))
            own = shapely.union_all(arcs)
            rooms: list[np.ndarray | None] = []
            for (radius, sense), markup, mine in zip(spins, markups, kept[c]):
                inset = _inset(radius, _OMEGA_R + wider)
                tip_deg = math.radians(st[c] + span - inset if sense > 0 else st[c] + inset)
                u = np.array([math.cos(tip_deg), math.sin(tip_deg)])
                tip = cs[c] + radius * u

                # the place kept by `_beside` asked alone first (mostly it
                # will do), then every place near, away from the arc's centre first
                def free(
                    tip: np.ndarray = tip, markup: str = markup, mine: np.ndarray = mine
                ) -> Iterator[np.ndarray]:
                    if labels.is_room(tip, markup, mine, keep_off=own):
                        yield mine
                    yield from labels.rooms(tip, markup, towards=u, keep_off=own)

                room = None
                for xy in free():
                    taken = any(
                        abs(xy[0] - r[0]) <= 2 * _ROOM_X
                        and abs(xy[1] - r[1]) <= _ROOM_DOWN + _ROOM_UP
                        for r in rooms
                        if r is not None
                    )
                    if not taken and not self.kept_near(xy):
                        room = np.asarray(xy, dtype=float)
                        break
                rooms.append(room)
            lacking = sum(r is None for r in rooms)
            options.append((float(score[c]) + _NO_ROOM * lacking, int(c), rooms))
        cost, c, rooms = min(options, key=lambda o: o[0])
        return c, rooms, cost, options

    def round_pivot(self, centre: np.ndarray, radius: float, sense: float) -> float:
        """Start angle (deg) of a 120° arc round a frame pivot crossing least,
        with room for its label at the arrowhead."""
        options = []
        for a in np.arange(0.0, 360.0, 15.0):
            tip = math.radians(a + 120.0 if sense > 0 else a)
            u = np.array([math.cos(tip), math.sin(tip)])
            x, y = centre + u * (radius + 4.0)
            room = [shapely.box(x - 2.5, y - 2.2, x + 2.5, y + 2.2)]
            score = self.cost(arc_line(centre, radius, a, a + 120.0)) + self._covered(room[0])
            options.append((score + 1e-3 * abs(a - 30.0), float(a), room))
        best = min(options, key=lambda o: (o[0], o[1]))
        self.reserve(best[2])
        return best[1]


# a plan's component shorter than this (mm) is named before the images
_SHORT_COMPONENT = 6.0
# the radii tried for ω1's arc round the crank's pivot, mm, the usual first
_CRANK_RADII = (_CRANK_R, 6.5, 10.0, 12.0, 5.0, 14.0)
# the positions' numbers stand about this far out of the crank pin's circle,
# mm, give or take the second
_NUMBER_BAND = (5.0, 4.5)
# where no arc at _CRANK_RADII leaves ω1's name room (every one inside a
# crank's circle crossed by its positions' spokes): round the pivot outside
# the circle, this much (mm) beyond the crank pin's reach, out of the spokes
_CRANK_OUTSIDE = (4.0, 8.0, 12.0)


def _crank_arc(
    arcs: _ArcPlacer,
    labels: Labels,
    centre: np.ndarray,
    sense: float,
    crank: float,
    radii: Sequence[float] = _CRANK_RADII,
) -> tuple[float, float, np.ndarray] | None:
    """Radius and start angle (deg) of ω1's 120° arc round the crank's pivot,
    and the centre of its label's box: of the arcs whose label finds a free
    place within NEAR_MM of the arrowhead (asked of the placer that will write
    it, the arc itself kept clear), the one that crosses least, the usual
    radius first; a place out of the rooms kept for the links' ω and ε labels
    and of the band just outside the crank pin's circle (radius `crank`, mm),
    where the positions' numbers are written next, first; the `radii`
    tried in turn. None where no arc leaves its label room."""
    starts = np.arange(0.0, 360.0, 15.0)
    tries = [(r, float(a)) for r in radii for a in starts]
    # what each arc crosses, all in one query; then the arcs asked about their
    # labels' room in that order, until none left can beat the best found
    arcs_drawn = [arc_line(centre, r, a, a + 120.0) for r, a in tries]
    score = np.array(
        [0.5 * list(radii).index(r) + 1e-3 * abs(a - 30.0) for r, a in tries]
    ) + arcs.costs(arcs_drawn)
    # never over a label written (a joint's name): the arc and its arrowhead
    written = shapely.STRtree(labels.boxes) if labels.boxes else None
    options: list[tuple[float, float, float, np.ndarray]] = []
    for i in np.argsort(score, kind="stable"):
        if options and score[i] >= min(o[0] for o in options):
            break
        if written is not None and written.query(arcs_drawn[i], "dwithin", 1.2).size:
            continue
        radius, a = tries[i]
        tip_deg = math.radians(a + 120.0 if sense > 0 else a)
        u = np.array([math.cos(tip_deg), math.sin(tip_deg)])
        free = labels.rooms(centre + radius * u, "ω_{1}", towards=u, keep_off=arcs_drawn[i])
        if len(free):
            # a room another label keeps costs as much as crossing a main
            # line, one where the positions' numbers go a little less
            band = np.abs(np.hypot(*(free - centre).T) - crank - _NUMBER_BAND[0])
            extra = [
                (1.0 if arcs.kept_near(room) else 0.0) + (0.8 if b < _NUMBER_BAND[1] else 0.0)
                for room, b in zip(free, band)
            ]
            k = int(np.argmin(extra))
            options.append((float(score[i]) + extra[k], radius, a, free[k]))
    if not options:
        return None
    _, radius, start, room = min(options, key=lambda o: o[0])
    x, y = room
    arcs.reserve([_room_box(x, y)])
    return radius, start, room


def _trajectories(sk: Sketch, solution: Solution, mu_l: float) -> None:
    """The paths of the moving points and of the centres of mass of the links off
    the frame, from a dense sweep: thin polylines."""
    mech = solution.mechanism
    pts = solution.sweep.points
    owners = {p: (0 if 0 in o else o[0], o) for p, o in mech.point_owners.items()}
    dense = solution.dense
    ok = np.asarray(dense.ok, dtype=bool)
    frame_links = {
        lid
        for lid, link in mech.links.items()
        if any(owners.get(p, (None,))[0] == 0 for p in link.points)
    }
    traced = [p for p, (l0, _) in owners.items() if l0 != 0]
    for lid, link in mech.links.items():
        s = f"S{lid}"
        if s in pts and lid not in frame_links and len(link.points) > 1:
            traced.append(s)
    for name in traced:
        if name not in dense.points:
            continue
        arr = np.asarray(dense.points[name], dtype=float)[ok] / mu_l
        arr = arr[np.all(np.isfinite(arr), axis=1)]
        if len(arr) > 1 and float(np.ptp(arr, axis=0).max()) > 0.5:
            sk.polyline([tuple(p) for p in arr], "thin")


def _position(solution: Solution, k: int, mu_l: float, main: set[int]) -> Pose:
    """Entry k of the sweep in mm: its links, and at a planned position its joints
    (and at position 0 the frame's pivots)."""
    mech = solution.mechanism
    pts = solution.sweep.points
    points = {name: np.asarray(pts[name][k], dtype=float) / mu_l for name in pts}
    frame = [p for p, o in mech.point_owners.items() if 0 in o]
    moving = [p for p, o in mech.point_owners.items() if 0 not in o and p in pts]
    return Pose(
        points,
        [link.points for link in mech.links.values()],
        "main" if k in main else "thin",
        pins=moving if k in main else (),
        pin_radius=1.0,
        pivots=frame if k == 0 else (),
    )


def _sliders(
    solution: Solution, mu_l: float, main: set[int], at: Callable[[str, int], np.ndarray]
) -> tuple[dict[int | None, tuple[Guide, ...]], dict[int, tuple[Block, ...]]]:
    """The guides (None: the frame's, drawn once) and the blocks of each planned
    position. The blocks on a frame's guide are shorter where positions crowd."""
    mech = solution.mechanism
    pts = solution.sweep.points
    n = len(solution.positions)
    guides: dict[int | None, list[Guide]] = {None: [], **{k: [] for k in main}}
    blocks: dict[int, list[Block]] = {k: [] for k in main}
    for slider in mech.sliders:
        name = slider.slider_point
        if slider.guide != 0:
            for k in sorted(main):
                d = complex(solution.sweep.links[slider.guide].e[k]) * complex(*slider.direction)
                u = unit_vector(np.array([d.real, d.imag]))
                c = at(name, k)
                ts = [
                    float(np.dot(at(p, k) - c, u))
                    for p in mech.links[slider.guide].points
                    if p in pts
                ]
                guides[k].append(Guide(c + min(-12.0, *ts) * u, c + max(12.0, *ts) * u, u, "slot"))
                blocks[k].append(Block((slider.slider, slider.guide), c, u, (6.0, 3.5)))
            continue
        u = unit_vector(np.asarray(slider.direction, dtype=float))
        along = [float(np.dot(at(name, k), u)) for k in range(n)]
        base = np.asarray(slider.through, dtype=float) / mu_l
        base = base - np.dot(base, u) * u
        a, b = base + (min(along) - 12.0) * u, base + (max(along) + 12.0) * u
        guides[None].append(Guide(a, b, u, "frame", 3.5))
        # blocks of neighbouring positions kept apart: shorter where they crowd
        ends = sorted(along[k] for k in main)
        gaps = [b - a for a, b in zip(ends, ends[1:]) if b - a > 1e-6]
        half = max(3.0, min([6.0, *(g / 2.0 - 0.5 for g in gaps)]))
        for k in sorted(main):
            blocks[k].append(Block((slider.slider, 0), at(name, k), u, (half, 3.5)))
    return (
        {k: tuple(v) for k, v in guides.items()},
        {k: tuple(v) for k, v in blocks.items()},
    )


def _mechanism_lines(sk: Sketch, solution: Solution, mu_l: float) -> None:
    """The mechanism's line work, no lettering: the trajectories, every
    position's links, thin but for the planned ones; those drawn whole:
    sliders on their guides (a frame's guide hatched once under the stroke, a
    slot drawn from the block along its link), the joints, and at position 0
    the frame's pivots."""
    pts = solution.sweep.points
    n = len(solution.positions)
    main = {0, *(solution.entry(i) for i in solution.plan_positions)}

    def at(name: str, k: int) -> np.ndarray:
        return np.asarray(pts[name][k], dtype=float) / mu_l

    _trajectories(sk, solution, mu_l)
    poses = [_position(solution, k, mu_l, main) for k in range(n)]
    guides, blocks = _sliders(solution, mu_l, main, at)
    for k in sorted(main):
        own = (*(guides[None] if k == 0 else ()), *guides[k])
        poses[k] = dataclasses.replace(poses[k], guides=own, blocks=blocks[k])
    draw_poses(sk, poses)


def _pose_lines(sk: Sketch, solution: Solution, mu_l: float, k: int) -> None:
    """The line work of entry `k` of the sweep alone (a plan position's view,
    `sketch_mechanism` with `alone`): its links in main lines, its joints,
    sliders and guides, and the frame's pivots; no other position, no trajectory."""
    pts = solution.sweep.points

    def at(name: str, j: int) -> np.ndarray:
        return np.asarray(pts[name][j], dtype=float) / mu_l

    pose = _position(solution, k, mu_l, {k})
    frame = [p for p, o in solution.mechanism.point_owners.items() if 0 in o and p in pts]
    guides, blocks = _sliders(solution, mu_l, {k}, at)
    own = (*guides[None], *guides[k])
    draw_poses(sk, [dataclasses.replace(pose, pivots=frame, guides=own, blocks=blocks[k])])


# the paper (mm²) round a link (within _ARC_REACH of its lines) that its ω
# and ε arcs at one position take with their names. Where the plan positions'
# links drawn in all the positions have less than _ARC_CROWD of it each, the
# n-position drawing cannot hold their arcs (chain_25 at 1:20, its 12
# rockers' arcs: 321 mm², 35 findings, ω/ε names 9–20 mm off; the samples,
# 1380 mm² and more; the generated seeds 0–299 at the scale that fills the
# field, 500 and more): each plan position is drawn in a view of its own, at
# the coarsest scale of the series that leaves its links _ARC_VIEW each
# (chain_25: 1:20, 625 mm²)
_ARC_CROWD = 400.0
_ARC_VIEW = 600.0
_ARC_REACH = 12.0  # how far from a link its arcs and their names go, mm


def _spins(solution: Solution, lid: int, k: int) -> list[tuple[float, float, str, LineType]]:
    """The arcs link `lid` is drawn with at entry `k` of the sweep: (value,
    radius, symbol, line) of its ω and of its ε where Table 3 writes that
    value other than 0 (at DECIMALS_MAX decimals). A link at rest for an
    instant (ω = 0 at an extreme position) still has its ε; one that moves
    without turning (the coupler of a parallelogram: chain_25's, ω ~ 2e-6
    1/s, written 0.0000) has neither: no sense to show."""
    sw = solution.sweep
    w, e = float(sw.omega[lid][k]), float(sw.eps[lid][k])
    spins: list[tuple[float, float, str, LineType]] = []
    if _written(w):
        spins.append((w, _OMEGA_R, "ω", "main"))
    if _written(e):
        spins.append((e, _EPS_R, "ε", "thin"))
    return spins


def _written(value: float) -> bool:
    """Whether Table 3 writes `value` other than 0 (table.py: at most DECIMALS_MAX decimals)."""
    return math.isfinite(value) and float(f"{abs(value):.{DECIMALS_MAX}f}") != 0.0


def _arc_room(solution: Solution, mu_l: float, entries: Sequence[int]) -> float:
    """The paper (mm²) within _ARC_REACH of the links drawn at the sweep's
    `entries` at `mu_l`, for each of the links at the plan positions among
    them whose ω or ε is drawn (inf where none is)."""
    mech = solution.mechanism
    pts = solution.sweep.points
    planned = {solution.entry(i) for i in solution.plan_positions}
    lines = []
    spinning = 0
    for k in sorted(set(entries)):
        for lid, link in mech.links.items():
            ends = [np.asarray(pts[p][k], dtype=float) / mu_l for p in link.points if p in pts]
            ends = [e for e in ends if np.all(np.isfinite(e))]
            if len(ends) < 2:
                continue
            lines += [shapely.LineString([a, b]) for a, b in itertools.combinations(ends, 2)]
            if lid != mech.drive.link and k in planned:
                spinning += bool(_spins(solution, lid, k))
    if not spinning or not lines:
        return math.inf
    return float(shapely.union_all([g.buffer(_ARC_REACH, 8) for g in lines]).area) / spinning


def _arcs_crowd(solution: Solution, mu_l: float) -> bool:
    """Whether the mechanism drawn at `mu_l` in all its positions has too little
    room for its links' ω/ε arcs at the plan positions (_ARC_CROWD)."""
    entries = [0, *(solution.entry(i) for i in solution.plan_positions)]
    return _arc_room(solution, mu_l, entries) < _ARC_CROWD


def _view_scales(solution: Solution, mu_l: float) -> list[float]:
    """The scales the plan positions' views of a mechanism drawn at `mu_l` are
    tried at, in turn: from the coarsest of the series (at most 4 steps finer
    than `mu_l`) at which every plan position alone leaves its links
    _ARC_VIEW each, up to `mu_l` itself (where the sheet has no room for them larger)."""
    finer = list(series(mu_l * 1e-4, mu_l * (1 + 1e-6), LENGTH_MANTISSA_TEXT))[::-1][:5]
    for n, mu in enumerate(finer):
        alone = [_arc_room(solution, mu, [solution.entry(i)]) for i in solution.plan_positions]
        if min(alone) >= _ARC_VIEW:
            return finer[: n + 1][::-1]
    return finer[::-1]


# how sketch_mechanism draws the mechanism: None, in all its positions with
# every arc; "apart", so but for the links' ω/ε arcs, drawn in the plan
# positions' views; a plan position (its index), that position's view
Views = int | Literal["apart"] | None


def _view_name(index: int) -> str:
    """The drawing of sheet 1 that holds plan position `index` alone."""
    return f"mechanism-position-{index}"


def _unlettered_view(
    solution: Solution, mu_l: float, look: Any, lang: Language, index: int
) -> Sketch:
    """A stand-in for plan position `index`'s view, about as large as it: its
    lines, the room its arcs and names take round them (_ARC_REACH) and its
    captions, no lettering (the view is lettered only where this fits the sheet)."""
    sk = Sketch(look)
    _pose_lines(sk, solution, mu_l, solution.entry(index))
    ext = sk.extent()
    r = _ARC_REACH
    corners = [(ext.left - r, ext.bottom - r), (ext.right + r, ext.bottom - r)]
    sk.polygon([*corners, (ext.right + r, ext.top + r), (ext.left - r, ext.top + r)], "thin")
    _view_captions(sk, mu_l, lang, index)
    return sk


def _view_captions(sk: Sketch, mu_l: float, lang: Language, index: int) -> None:
    """A plan position's view: its title over it, its scale under it."""
    ext = sk.extent()
    label = scale_label(mu_l, "length", lang)
    sk.rich_text((ext.x + _PAD, ext.bottom - 6.0), label.markup(), _TEXT)
    sk.text((ext.x + _PAD, ext.top + 3.0), _words(lang)["position_view"].format(i=index), _TITLE)


def _apart_note(sk: Sketch, solution: Solution, lang: Language) -> None:
    """Under the drawing whose links' ω/ε arcs are drawn in the plan positions' views: where."""
    ext = sk.extent()
    listed = ", ".join(str(i) for i in solution.plan_positions)
    sk.text((ext.x + _PAD, ext.bottom - 5.0), _words(lang)["arcs_apart"].format(i=listed), _SMALL)


def _mechanism_captions(sk: Sketch, mu_l: float, lang: Language) -> None:
    """The scale under the drawn mechanism, its title over it."""
    ext = sk.extent()
    label = scale_label(mu_l, "length", lang)
    sk.rich_text((ext.x + _PAD, ext.bottom - 6.0), label.markup(), _TEXT)
    sk.text((ext.x + _PAD, ext.top + 3.0), _words(lang)["mechanism"], _TITLE)


def _unlettered_mechanism(solution: Solution, mu_l: float, look: Any, lang: Language) -> Sketch:
    """A stand-in for the mechanism's drawing no larger than it in width and in
    height: its lines and its captions without the lettering (the drawing
    adds names, arcs and numbers round the same lines and puts the same
    captions round all of it)."""
    sk = Sketch(look)
    _mechanism_lines(sk, solution, mu_l)
    _mechanism_captions(sk, mu_l, lang)
    return sk


def _position_numbers(
    labels: Labels,
    solution: Solution,
    mu_l: float,
    here: Callable[[np.ndarray], bool] | None = None,
    in_no_disc: Callable[[np.ndarray], bool] | None = None,
) -> None:
    """Numbered positions of the crank pin, in smaller figures and out beyond
    the pin's circle, so that "0" is not read as a pivot's "O"; an entry of the
    sweep that is no numbered position (an extreme) gets none. A number walled
    in on the crank's circle by the bundle of the positions' links is written
    where the textbook numbers the positions too (seed 000 §1.3: A_i on the
    crank's circle, B_i on the output's trail): at the output point's place
    in that position, out of its trail (Labels.place_first). Written last
    (before the ω and ε labels, a number takes the room kept for one), and
    where some stand far, all once more with those first (Labels.write_each).
    With `here` (a drawing with detail views: whether this view letters
    what stands at a place) and `in_no_disc` (whether a place is in no
    detail's disc), a number is written by its places out of every disc, in the
    drawing (the output's, where the crank pin's is in a disc), else by those
    in the detail view's."""
    mech = solution.mechanism
    pts = solution.sweep.points
    pivot = np.asarray(pts[mech.crank_pivot][0], dtype=float) / mu_l
    output = mech.study.output
    trail = (
        np.asarray(pts[output], dtype=float) / mu_l
        if output in pts and output != mech.crank_pin
        else None
    )
    # the output's trail is numbered on the side away from the mechanism's middle
    middle = (
        np.nanmean(np.concatenate([np.asarray(pts[name], dtype=float) for name in pts]), axis=0)
        / mu_l
    )
    kept = labels.size
    labels.size = _SMALL
    writes = []
    for k, position in enumerate(solution.positions):
        if position.index is None:
            continue
        p = np.asarray(pts[mech.crank_pin][k], dtype=float) / mu_l
        anchors: list[tuple[np.ndarray, np.ndarray]] = [(p, unit_vector(p - pivot))]
        if trail is not None and np.all(np.isfinite(trail[k])):
            anchors.append((trail[k], unit_vector(trail[k] - middle)))
        if here is not None and in_no_disc is not None:
            mine = [(at, u) for at, u in anchors if here(at)]
            out_of_discs = any(in_no_disc(at) for at, _ in anchors)
            if not mine or (out_of_discs and not any(in_no_disc(at) for at, _ in mine)):
                continue  # another view numbers it (the drawing, where it can)
            anchors = mine

        def write(
            anchors: list[tuple[np.ndarray, np.ndarray]] = anchors,
            number: str = str(position.index),
        ) -> object:
            return labels.place_first(anchors, number, distance=3.0)

        writes.append(write)
    if len(mech.links) <= _SHORT_LINKS:
        # where some stand far, all once more with those first: a number
        # walled in by one written before it (or its leader) goes first
        labels.write_each(writes)
    else:  # a long chain: the usual order alone (see _SHORT_LINKS)
        for write in writes:
            write()
    labels.size = kept


def sketch_mechanism(
    solution: Solution,
    mu_l: float,
    look: Any,
    lang: Language,
    details: Sequence[Detail] = (),
    detail: Detail | None = None,
    views: Views = None,
) -> Sketch:
    """The mechanism in all its positions, lettered; where some link's ω/ε
    names found no room near their arcs and some name stands far or on
    something (a mechanism of _SHORT_LINKS links at most), lettered once
    more with such a link's arcs tried larger still
    (_FAR_WIDER), the better of the two kept (fewer names on something, then
    fewer far; the first on a tie: a drawing not crowded is drawn as before).
    With `details`, what stands in a detail's disc is drawn but lettered only
    in its detail view, the disc marked by a thin circle and its letter; with
    `detail` too, the drawing is that view (`_lettered_mechanism`). With
    `views` (`Views`), the drawing without its links' ω/ε arcs, or one plan
    position's view."""
    sk, counts, lacking = _lettered_mechanism(
        solution, mu_l, look, lang, False, details, detail, views
    )
    # (a long chain keeps the one lettering: see _SHORT_LINKS)
    short = len(solution.mechanism.links) <= _SHORT_LINKS or isinstance(views, int)
    if short and lacking and (counts.unsettled or counts.far):
        again, counts_again, _ = _lettered_mechanism(
            solution, mu_l, look, lang, True, details, detail, views
        )
        if (counts_again.unsettled, counts_again.far) < (counts.unsettled, counts.far):
            return again
    return sk


def _lettered_mechanism(
    solution: Solution,
    mu_l: float,
    look: Any,
    lang: Language,
    far: bool,
    details: Sequence[Detail] = (),
    detail: Detail | None = None,
    views: Views = None,
) -> tuple[Sketch, LabelCounts, bool]:
    """The mechanism lettered, its links' ω/ε arcs tried `far` (_ArcPlacer):
    the drawing, how well its labels found room, and whether some link's
    ω/ε names found none near their arcs. With `details` (their discs in m),
    a point is named, a position numbered and a link's arcs drawn in the view
    that holds its place (`_arc_parts`): this drawing, its discs marked, or
    with `detail` that detail view, its disc at μl / ratio, the lines cut at
    the disc's edge. With `views` (`Views`): "apart", the drawing whose
    plan positions' ω/ε arcs are drawn in views of their own (it says so
    under it); a plan position, that position's view (`_view_of`)."""
    mech = solution.mechanism
    pts = solution.sweep.points
    owners = {p: (0 if 0 in o else o[0], o) for p, o in mech.point_owners.items()}
    n = len(solution.positions)
    alone = solution.entry(views) if isinstance(views, int) else None
    arcs_at: Sequence[int] = (
        [views] if isinstance(views, int) else [] if views == "apart" else solution.plan_positions
    )
    shown = [alone] if alone is not None else list(range(n))
    # a position's view, one pose, is lettered as a short mechanism's drawing
    short = len(mech.links) <= _SHORT_LINKS or alone is not None
    sk = Sketch(look)
    ratio = detail.ratio if detail is not None else 1.0
    mu_l = mu_l / ratio
    discs = [(np.asarray(d.centre, float) / mu_l, d.radius / mu_l) for d in details]
    own = discs[list(details).index(detail)] if detail is not None else None

    def at(name: str, k: int) -> np.ndarray:
        return np.asarray(pts[name][k], dtype=float) / mu_l

    def in_no_disc(p: np.ndarray) -> bool:
        """Whether `p` is in no detail's disc."""
        return all(float(np.hypot(*(p - c))) > r for c, r in discs)

    def here(p: np.ndarray) -> bool:
        """Whether what stands at `p` is lettered in this view."""
        if own is not None:
            return float(np.hypot(*(p - own[0]))) <= own[1]
        return in_no_disc(p)

    gid = "mechanism" if detail is None else _mechanism_detail_name(details, detail)
    gid = gid if alone is None else _view_name(cast(int, views))
    with sk.group(gid, "mechanism"):
        begun = len(sk.calls)
        if alone is None:
            _mechanism_lines(sk, solution, mu_l)
        else:
            _pose_lines(sk, solution, mu_l, alone)
        if own is not None:
            sk.calls[begun:] = cut_to_disc(sk.calls[begun:], *own)
        for middle, r in [own] if own is not None else discs:
            sk.circle(middle, r, "thin")  # the view's edge, or the disc marked
        # Lettering goes where it covers no line, no arc and no other letter:
        # the joints' names first (the arcs are then drawn clear of them), then
        # ω and ε once every arc is drawn, then the positions' numbers. A plan
        # position's view (one pose: no other position's lines wall a joint
        # in) names its joints with ω and ε, round the arcs drawn: named
        # first, they left a link's arcs no side but over a name (chain_25's
        # rockers, their joints' names on both sides, 9 a view)
        pivot = at(mech.crank_pivot, 0)
        labels = Labels(
            sk,
            _TEXT,
            **_MECHANISM_LABELLING,
            smaller=_SMALL if short else None,
            # led across the lines as the last resort in a drawing with
            # detail views and in each view, not in the plain drawing: there
            # a name walled in stands far, and a view is drawn round it
            across_main=bool(details),
        )
        labels.avoid_drawn(sk.calls)
        for d, (middle, r) in zip(details, discs) if detail is None else ():
            # by the disc's rim, up and right first, where the letter stands near it
            rims = [middle + r * np.array([math.cos(a), math.sin(a)]) for a in _RIM]
            labels.place_first([(rim, rim - middle) for rim in rims], d.letter)
        # the crank's pivot named on the side away from the pin at position 0,
        # so that its "O" stands far from the position number "0"
        opposite = -unit_vector(at(mech.crank_pin, shown[0]) - pivot)
        # each joint named at position 0, else (walled in there by the lines
        # of the other positions) at the first plan position where its name
        # stands near it: a point drawn in main lines there too (a long chain
        # at position 0 alone: see _SHORT_LINKS)
        drawn_at = [0, *sorted({solution.entry(i) for i in solution.plan_positions} - {0})]
        drawn_at = drawn_at if len(mech.links) <= _SHORT_LINKS else [0]
        drawn_at = drawn_at if alone is None else [alone]
        # a view's joints: (anchor, name, towards), named with ω and ε
        named_later: list[tuple[np.ndarray, str, np.ndarray]] = []
        for name in owners:
            # (named in the view that holds its place at position 0)
            if name in pts and here(at(name, shown[0])):
                anchors: list[tuple[np.ndarray, np.ndarray]] = []
                for k in drawn_at:
                    p = at(name, k)
                    if not here(p):
                        continue
                    if any(float(np.hypot(*(p - q))) < 1e-6 for q, _ in anchors):
                        continue  # a frame point: the same place at every position
                    if name == mech.crank_pivot:
                        towards = opposite
                    else:
                        towards = unit_vector(unit_vector(p - pivot) + np.array([0.3, 0.6]))
                    anchors.append((p, towards))
                if alone is not None and anchors:
                    named_later += [(p, point_markup(name), towards) for p, towards in anchors]
                else:
                    labels.place_first(anchors, point_markup(name), distance=2.0)
        # ω and ε of every rotating link at the planned positions (seed 003
        # §1.6), each beside its own link on the side freest of the others and
        # of the joints' names; all drawn before their labels are written.
        # (one position's arcs alone: no other position's arcs of a link to wall them in)
        arcs = _ArcPlacer(sk, far, walled=len(arcs_at) > 1)
        # the frame's pivots: no arc over a hatched base
        arcs.reserve(
            [
                shapely.box(x - 5.0, y - 6.5, x + 5.0, y - 1.0)
                for x, y in (at(p, 0) for p, (l0, _) in owners.items() if l0 == 0 and p in pts)
            ]
        )
        # (tip, label, towards, the room kept for it)
        queued = arcs.queued
        for i in arcs_at:
            k = solution.entry(i)
            for lid, link in mech.links.items():
                names = [p for p in link.points if p in pts]
                if lid == mech.drive.link or len(names) < 2:
                    continue
                spins = _spins(solution, lid, k)
                if not spins:
                    continue
                segments = [(at(a, k), at(b, k)) for a, b in itertools.combinations(names, 2)]
                segments = _arc_parts(segments, discs, own, ratio)
                if not segments:
                    continue  # the link lies in a detail's disc: its arcs are drawn there
                centre, start_deg, rooms, wider, span = arcs.beside(
                    segments,
                    [(r, v) for v, r, _, _ in spins],
                    labels,
                    [f"{sym}_{{{lid}}}" for _, _, sym, _ in spins],
                    short,  # the shorter arcs tried
                    [line for _, _, _, line in spins],
                )
                for (value, radius, sym, line), room in zip(spins, rooms):
                    inset = _inset(radius + wider, _OMEGA_R + wider)
                    tip = sense_arc(
                        sk,
                        centre,
                        radius + wider,
                        value,
                        start_deg + inset,
                        start_deg + span - inset,
                        line,
                    )
                    towards = tip - centre if room is None else room - tip
                    queued.append((tip, f"{sym}_{{{lid}}}", towards, room))
        centre = pivot
        sense = float(mech.drive.signed_omega)
        crank = [at(mech.crank_pin, k) - centre for k in shown]
        reach = max(float(np.hypot(*v)) for v in crank)
        found = _crank_arc(arcs, labels, centre, sense, reach) if here(centre) else None
        if found is None and here(centre):  # walled in by the spokes: outside the crank's circle
            # (in a detail view, only within its disc: the crank's circle at the
            # view's ratio may be far larger than the view, gen 81's 10:1 of a
            # pivot 19 mm off its pin, an arc of 386 mm)
            outside = [
                reach + d for d in _CRANK_OUTSIDE if own is None or reach + d + _TEXT <= own[1]
            ]
            found = _crank_arc(arcs, labels, centre, sense, reach, outside) if outside else None
        if found is not None:
            # the arc where its label finds room beside its arrowhead
            radius, start_deg, room = found
            tip = sense_arc(sk, centre, radius, sense, start_deg, start_deg + 120.0)
            queued.insert(0, (tip, "ω_{1}", room - tip, room))
        elif here(centre):
            start_deg = arcs.round_pivot(centre, _CRANK_R, sense)
            tip = sense_arc(sk, centre, _CRANK_R, sense, start_deg, start_deg + 120.0)
            # ω1 names its arc's arrowhead, written towards the gap between the spokes
            anchor = _between_spokes(centre, tip, crank, 7.0)
            queued.append((tip, "ω_{1}", anchor - tip, None))
        for p, markup, towards in named_later:
            labels.later(p, markup, towards)
        # those with a room kept first: one with none (no free place near its
        # arrowhead) would take another's
        for tip, markup, towards, kept in sorted(queued, key=lambda q: q[3] is None):
            labels.later(tip, markup, towards, first=kept)
        # where some stand far, all once more with those first (Labels.write_later;
        # a long chain keeps the one order: see _SHORT_LINKS)
        labels.write_later(retry=short)
        if alone is None:
            _position_numbers(labels, solution, mu_l, here if discs else None, in_no_disc)
        if alone is not None:
            _view_captions(sk, mu_l, lang, cast(int, views))
        elif detail is None:
            _mechanism_captions(sk, mu_l, lang)
            if views == "apart":
                _apart_note(sk, solution, lang)
        else:
            ext = sk.extent()
            number = catalogue(lang).plain_number(detail.ratio)
            title = _words(lang)["plan_detail"].format(letter=detail.letter, ratio=number)
            sk.text(((ext.left + ext.right) / 2, ext.top + 3.0), title, _TEXT, anchor="center")
    return sk, labels.counts(), arcs.lacking


# where round a detail's disc its letter is tried, in turn (rad)
_RIM = tuple(math.radians(a) for a in (45.0, 135.0, -45.0, -135.0, 90.0, 0.0, 180.0, -90.0))
# a link's part out of every detail's disc at least this long (mm at the
# drawing's scale) carries its ω/ε arcs in the drawing; else its detail view does
_ARC_ROOM_MM = 3.0


def _arc_parts(
    segments: Sequence[tuple[np.ndarray, np.ndarray]],
    discs: Sequence[tuple[np.ndarray, float]],
    own: tuple[np.ndarray, float] | None,
    ratio: float,
) -> list[tuple[np.ndarray, np.ndarray]]:
    """The parts of a link's `segments` (mm) along which a view draws its
    ω/ε arcs: all of them where no detail's disc is drawn; the parts out of
    every one of `discs` at least _ARC_ROOM_MM long in the drawing; in the
    detail view of the disc `own` (drawn `ratio` times larger), the parts in
    it of a link that has none such."""
    if not discs:
        return list(segments)
    holes = shapely.union_all([shapely.Point(*map(float, c)).buffer(r, 64) for c, r in discs])
    out: list[tuple[np.ndarray, np.ndarray]] = []
    for a, b in segments:
        if float(np.hypot(*(b - a))) < 1e-9:
            continue
        rest = shapely.LineString([a, b]).difference(holes)
        for g in getattr(rest, "geoms", [rest]):
            if not g.is_empty and g.length >= _ARC_ROOM_MM * ratio:
                xy = shapely.get_coordinates(g)
                out.append((xy[0], xy[-1]))
    if own is None:
        return out
    if out:
        return []
    inside = [clipped(a, b, *own) for a, b in segments]
    return [p for p in inside if p is not None and float(np.hypot(*(p[1] - p[0]))) > 1e-6]


def _mechanism_detail_name(details: Sequence[Detail], detail: Detail) -> str:
    """The drawing of sheet 1 that holds the mechanism's detail view `detail`."""
    k = list(details).index(detail)
    return "mechanism-detail" + (f"-{k + 1}" if k else "")


def sketch_mechanism_details(
    solution: Solution,
    mu_l: float,
    look: Any,
    lang: Language,
    letters: str,
    plain: Sketch,
    views: Views = None,
) -> tuple[Sketch, list[Sketch]] | None:
    """The mechanism (`plain`: as `sketch_mechanism` drew it at `mu_l`) whose
    names crowd, with its crowd marked by a circle and a letter, and its
    detail views (a sketch each): the first of `mechanism_detail_options`,
    the one leaving fewest names crowded. None where no name crowds so, or
    where no detail view letters the drawing better."""
    options = mechanism_detail_options(solution, mu_l, look, lang, letters, plain, views)
    return options[0] if options else None


def mechanism_detail_options(
    solution: Solution,
    mu_l: float,
    look: Any,
    lang: Language,
    letters: str,
    plain: Sketch,
    views: Views = None,
) -> list[tuple[Sketch, list[Sketch]]]:
    """The mechanism (`plain`: as `sketch_mechanism` drew it at `mu_l`) whose
    names crowd, with its crowd marked by a circle and a letter, and its
    detail views (a sketch each): the crowd drawn again at a larger scale of
    the standard series, lettered there (`mechanism_details`, by the first of
    `letters`), where _MECHANISM_CROWD of its names at least stand far or
    on something (`crowded_names`); else, or where that view letters the
    drawing no better, round the joints' names among them alone
    (`_crowded_joints`: a joint walled in by lines, the crank's pivot in the
    fan of its positions, that no leader reaches without crossing a main
    line). Where a view so chosen leaves names crowded and a knot of pivots
    nearer than _MECHANISM_APART_MM in it, its discs are chosen again at the
    enlargements past 10:1 (`_knot_details`), and the next crowd tried too.
    Every choice that letters the drawing better than `plain`, those leaving
    fewest names crowded first (the order tried on a tie): the sheet takes
    the first whose views find room on it, as a draughtsman takes the
    enlargement that fits (gen 81: the 10:1 view of its knot where the
    20:1 one finds none). After them, those that letter it better only as
    the finished sheet is judged: a name walled in in a view (no place
    within 6 mm free) led across main lines there (`label_near`, not
    strict). Empty where no name crowds so, or where no detail view letters
    the drawing better."""
    namings = list(crowded(plain, lang))
    crowd = stand_for(namings)
    lettered_badly = len(crowd)

    def crowds() -> Iterator[tuple[np.ndarray, int]]:
        if lettered_badly >= _MECHANISM_CROWD:
            yield crowd, 1
        joints = _crowded_joints(solution, namings)
        if len(joints) and (lettered_badly < _MECHANISM_CROWD or len(joints) < lettered_badly):
            # (not the whole crowd again) a view round each walled-in joint
            # apart: no leader reaches it, however few they are
            yield joints, _MECHANISM_DETAILS

    # ((left crowded, as the finished sheet judges it), the drawing, its views)
    # of every choice lettering better
    better: list[tuple[tuple[int, int], Sketch, list[Sketch]]] = []
    fewest: int | None = None  # the fewest left crowded by a choice (strictly)
    knotted = False  # whether the best so far leaves a view's points too near
    # (each choice drawn and measured once, however many crowds choose it)
    drawn_once: dict[tuple[Detail, ...], tuple[Sketch, list[Sketch], set[str], int, int]] = {}
    for knot, most in crowds():
        chosen = mechanism_details(solution, mu_l, knot, letters, most)
        variants = [chosen]
        for details in variants:  # (the chosen's variants appended once it is drawn)
            if not details:
                continue
            again = details in drawn_once
            if not again:
                sk = sketch_mechanism(solution, mu_l, look, lang, details, views=views)
                drawn = [
                    sketch_mechanism(solution, mu_l, look, lang, details, d, views) for d in details
                ]
                for view, d in zip(drawn, details):
                    view.detail_of = (d.centre[0] / mu_l, d.centre[1] / mu_l)
                # (the drawing's crowd measured once: its count, and its discs' letters)
                namings_left = list(crowded(sk, lang))
                marked = {n.markup for n in namings_left}
                left = len(namings_left) + sum(len(crowded_names(v, lang)) for v in drawn)
                # where that letters it no better, as the finished sheet is
                # judged: a view's name walled in (no place within 6 mm free),
                # led across main lines, lettered (asked only then: it costs a
                # search for room round each name led so)
                led = (
                    left
                    if left < lettered_badly
                    else len(namings_left)
                    + sum(len(crowded_names(v, lang, strict=False)) for v in drawn)
                )
                drawn_once[details] = (sk, drawn, marked, left, led)
            sk, drawn, marked, left, led = drawn_once[details]
            if left < lettered_badly and not again:
                if fewest is None or left < fewest:
                    fewest = left
                    knotted = left > 0 and _knotted(solution, mu_l, details)
                better.append(((left, led), sk, drawn))
            elif led < lettered_badly and not again:
                # better only so: after every choice better strictly (held-out
                # gen 456: the crank's pivot 'p' in the fan of its positions, 21
                # mm off on the drawing, led out between the spokes in C (4:1))
                better.append(((left, led), sk, drawn))
            if details is chosen and left:
                if fewest is None or knotted:
                    variants.append(_knot_details(solution, mu_l, knot, letters, most, chosen))
                variants.append(_grown_details(solution, mu_l, knot, letters, most, chosen, marked))
        if fewest is not None and not knotted:
            break
    # (none where no detail view letters the drawing better)
    # (stable: the order tried on a tie; those better only as judged after
    # every other, by that)
    better.sort(key=lambda b: b[0])
    return [(sk, drawn) for _, sk, drawn in better]


def _grown_details(
    solution: Solution,
    mu_l: float,
    knot: np.ndarray,
    letters: str,
    most: int,
    chosen: Sequence[Detail],
    lettered: set[str],
) -> tuple[Detail, ...]:
    """Where the letter of a disc of `chosen` (`mechanism_details` of the
    names standing for `knot`) stands far or on something in the drawing
    marked with them (`lettered`: the markups of its names crowded there;
    its rim walled in: gen 265's crank pivot amid its blocks): the details
    chosen again on the larger discs only (else none)."""
    walled = [d.radius / mu_l for d in chosen if d.letter in lettered]
    radii = [r for r in _MECHANISM_RADII if walled and r > min(walled) + 1e-9]
    if not radii:
        return ()
    return mechanism_details(solution, mu_l, knot, letters, most, radii=radii)


def _knotted(solution: Solution, mu_l: float, details: Sequence[Detail]) -> bool:
    """Whether some of `details` (the mechanism's at `mu_l`) leaves the points
    in its disc nearer than _MECHANISM_APART_MM in its view (`spread`)."""
    _, points = _mechanism_names(solution, mu_l)
    for d in details:
        c, r = np.asarray(d.centre, float) / mu_l, d.radius / mu_l
        if spread(points[np.hypot(*(points - c).T) <= r]) * d.ratio < _MECHANISM_APART_MM:
            return True
    return False


def _knot_details(
    solution: Solution,
    mu_l: float,
    crowded: np.ndarray,
    letters: str,
    most: int,
    chosen: Sequence[Detail],
) -> tuple[Detail, ...]:
    """Where `chosen` (`mechanism_details` of the names standing for
    `crowded`) leaves a knot of pivots nearer than _MECHANISM_APART_MM in its
    view: the details chosen again on smaller discs at GOST 2.302's
    enlargements past 10:1 (_KNOT_RADII, _KNOT_RATIOS; else none)."""
    if not chosen or not _knotted(solution, mu_l, chosen):
        return ()
    again = mechanism_details(
        solution, mu_l, crowded, letters, most, radii=_KNOT_RADII, ratios=_KNOT_RATIOS
    )
    return () if again == tuple(chosen) else again


def _crowded_joints(solution: Solution, namings: Sequence[Naming]) -> np.ndarray:
    """Where the joints' names among `namings` (those of the mechanism that
    stand far or on something, `crowded`) stand for (mm, one row each: the joint)."""
    joints = {point_markup(p) for p in solution.mechanism.point_owners}
    return stand_for((n for n in namings if n.markup in joints), anchors=True)


_MECHANISM_CROWD = 3  # the mechanism's names far or on something: this many make a crowd
_MECHANISM_DETAILS = 2  # the most detail views of the mechanism (round its walled-in joints)
_MECHANISM_DETAIL_MM = 45.0  # the largest radius of its detail's disc, mm
_MECHANISM_APART_MM = 7.0  # its detail sets the points this far apart
_MECHANISM_RADII = (4.0, 6.0, 8.0, 12.0, 16.0)  # the radii of its discs tried, mm
_MECHANISM_CORE = 0.7  # its disc: the smallest that holds this share of the most any holds
# a knot of pivots that 10:1 leaves nearer than _MECHANISM_APART_MM (gen 70's
# P, W, G: 0.4 mm apart at 1:100, their names walled in by the links' main
# lines at 10:1): a disc of 2 mm too, at GOST 2.302's 20:1 and 40:1
_KNOT_RADII = (2.0, *_MECHANISM_RADII)
_KNOT_RATIOS = (*DETAIL_RATIOS, 20.0, 40.0)


def _mechanism_names(solution: Solution, mu_l: float) -> tuple[list[Name], np.ndarray]:
    """The names the mechanism at `mu_l` writes (`Name`: its points' at
    position 0, ω and ε of each link at the planned positions by the link's
    middle, ω1 and the positions' numbers by the crank), and the places
    (mm) of its points at position 0 and at the planned positions."""
    mech = solution.mechanism
    pts = solution.sweep.points

    def at(name: str, k: int) -> np.ndarray:
        return np.asarray(pts[name][k], dtype=float) / mu_l

    drawn = sorted({0, *(solution.entry(i) for i in solution.plan_positions)})
    named = [p for p in mech.point_owners if p in pts]
    out = [Name(at(p, 0), name_area(point_markup(p))) for p in named]
    for k in drawn[1:] if solution.plan_positions else ():
        for lid, link in mech.links.items():
            ends = [at(p, k) for p in link.points if p in pts]
            if lid != mech.drive.link and len(ends) > 1:
                middle = np.mean(ends, axis=0)
                out += [Name(middle, name_area(f"{sym}_{{{lid}}}")) for sym in "ωε"]
    out.append(Name(at(mech.crank_pivot, 0), name_area("ω_{1}")))
    digit = (_SMALL * 0.7 + 1.5) * (_SMALL + 1.5)
    out += [
        Name(at(mech.crank_pin, k), digit)
        for k, position in enumerate(solution.positions)
        if position.index is not None
    ]
    places = np.array([at(p, k) for p in named for k in drawn], dtype=float).reshape(-1, 2)
    return out, places[np.all(np.isfinite(places), axis=1)]


def mechanism_details(
    solution: Solution,
    mu_l: float,
    crowded: np.ndarray,
    letters: str,
    most: int = 1,
    *,
    radii: Sequence[float] = _MECHANISM_RADII,
    ratios: Sequence[float] = DETAIL_RATIOS,
) -> tuple[Detail, ...]:
    """The detail views the mechanism at `mu_l` needs where the names standing
    for `crowded` (mm, `crowded_names` of the mechanism drawn without details)
    found no place near (`choose_details`): at most `most` discs apart, each
    round a point of the mechanism or such a point, the smallest that holds
    most of the crowd left, drawn at the ratio of the series that sets its
    points _MECHANISM_APART_MM apart and leaves its names room, lettered by
    `letters` (a disc past the first may hold one name: a walled-in joint's,
    which no leader reaches); its discs' radii of `radii`, its ratios of `ratios`.
    Each crowded name stands for the point of the mechanism nearest what it
    names (an ω or ε for a joint of its link, beside which its arc is drawn):
    the disc goes round the knot of joints, not round the arcs' heads."""
    names, points = _mechanism_names(solution, mu_l)
    if not len(points):
        return ()
    gap = np.hypot(*(crowded[:, None, :] - points[None, :, :]).transpose(2, 0, 1))
    knot = points[np.argmin(gap, axis=1)] if len(crowded) else crowded
    return choose_details(
        names,
        knot,
        list(points),
        mu_l,
        letters,
        most,
        points=points,
        spacing=_MECHANISM_APART_MM,
        widest=_MECHANISM_DETAIL_MM,
        tightest=_MECHANISM_CORE,
        radii=radii,
        fewest=1,
        ratios=ratios,
    )


def sketch_formula(solution: Solution, look: Any, lang: Language) -> Sketch:
    st = solution.structure
    sk = Sketch(look)
    with sk.group("structural-formula", "structural-formula"):
        sk.text((0.0, 14.0), _words(lang)["structure"], _TITLE)
        mobility = f"W = 3n - 2p_{{5}} - p_{{4}} = 3·{st.n} - 2·{st.p5} - {st.p4} = {st.W}"
        sk.rich_text((0.0, 6.0), mobility, _TEXT)
        # osifont has no arrow glyph: the arrows between groups are drawn.
        x = 0.0
        for i, part in enumerate(str(st.formula).split("<-")):
            if i:
                sk.arrow((x + 6.0, 1.2), (x + 1.0, 1.2), "thin", head_length=2.0, head_width=1.2)
                x += 8.0
            part = part.strip()
            x += sk.rich_text((x, 0.0), part, _TEXT)
    return sk


# --- plans -------------------------------------------------------------------------


def _moving_points(solution: Solution) -> list[str]:
    owners = solution.mechanism.point_owners
    names = [p for p, o in owners.items() if 0 not in o]
    names += [p for p in solution.sweep.points if p not in owners]
    return names


def sketch_plan(
    solution: Solution,
    index: int,
    mu: float,
    kind: str,
    look: Any,
    lang: Language,
    note: str = "",
) -> tuple[Sketch, dict[str, np.ndarray]]:
    """A velocity ("velocity") or acceleration ("acceleration") plan at `index`.

    The pole is at the local origin; returns the sketch and the images in mm;
    `note` (a plan drawn below the guide's size: why) goes under its scale.
    """
    return _plan_view(solution, index, mu, kind, look, lang, note)


def sketch_plan_details(
    solution: Solution,
    index: int,
    mu: float,
    kind: str,
    look: Any,
    lang: Language,
    note: str = "",
    letters: str = DETAIL_LETTERS,
    plain: Sketch | None = None,
) -> tuple[Sketch, list[Sketch], str] | None:
    """The plan (`sketch_plan`) whose names crowd, with its crowd marked by a
    circle and a letter, its detail views (a sketch each): the crowd drawn
    again at a larger scale of the standard series, lettered there
    (`plan_details`, by the first of `letters` that name no point), and the
    letters it took. Where the plan with its crowd marked leaves other names
    crowded (a name it moved), the details are chosen again for both, up to
    _PLAN_ROUNDS times: those that leave fewest crowded kept.
    None where none of its names is crowded (`crowded_names`: far from what
    they name, or on something), or where the detail views letter them no better.
    `plain`: the plan as `sketch_plan` drew it, where it was."""
    if plain is None:
        plain, _ = _plan_view(solution, index, mu, kind, look, lang, note)
    crowd = crowded_names(plain, lang)
    first = len(crowd)
    best: tuple[int, Sketch, list[Sketch], str] | None = None
    for _ in range(_PLAN_ROUNDS if first else 0):
        details = plan_details(solution, index, mu, kind, crowd, letters)
        if not details:
            break
        sk, _ = _plan_view(solution, index, mu, kind, look, lang, note, details)
        views = [
            _plan_detail_view(solution, index, mu, kind, look, lang, note, details, d)
            for d in details
        ]
        # (a component is named in the view whose disc holds its head)
        moved = crowded_ends(sk, lang)[:, 2:]
        left = len(moved) + sum(len(crowded_names(v, lang)) for v in views)
        if best is None or left < best[0]:
            best = (left, sk, views, "".join(d.letter for d in details))
        if not len(moved):
            break
        crowd = np.vstack([crowd, moved])
    if best is None or best[0] >= first:
        return None  # the details letter the crowd no better
    return best[1], best[2], best[3]


def _plan_detail_view(
    solution: Solution,
    index: int,
    mu: float,
    kind: str,
    look: Any,
    lang: Language,
    note: str,
    details: Sequence[Detail],
    detail: Detail,
) -> Sketch:
    """The detail view `detail` of the plan (`_plan_view`) at its ratio; where
    its names crowd there (`crowded_names`), at the other ratios of the
    series, the nearest first, as a draughtsman takes another enlargement:
    the first that leaves none crowded, else the one leaving fewest (gen 20's
    acceleration plan 4: s5 walled in at 4:1, free at 2.5:1 and 5:1)."""
    view = _plan_view(solution, index, mu, kind, look, lang, note, details, detail)[0]
    left = len(crowded_names(view, lang))
    if not left:
        return view
    k = DETAIL_RATIOS.index(detail.ratio) if detail.ratio in DETAIL_RATIOS else 0
    others = sorted(
        (r for r in DETAIL_RATIOS if r != detail.ratio),
        key=lambda r: (abs(DETAIL_RATIOS.index(r) - k), -r),
    )
    for ratio in others:
        d = dataclasses.replace(detail, ratio=ratio)
        again = tuple(d if x is detail else x for x in details)
        other = _plan_view(solution, index, mu, kind, look, lang, note, again, d)[0]
        crowd = len(crowded_names(other, lang))
        if crowd < left:
            view, left = other, crowd
            if not left:
                break
    return view


_PLAN_CROWD = 3  # a plan's detail past its first holds this many crowded names (a crowd of its own)
_PLAN_ROUNDS = 2  # how many times a plan's details are chosen (sketch_plan_details)
_PLAN_DETAILS = 2  # the most detail views of one plan
_PLAN_DETAIL_MM = 30.0  # the largest radius of a plan detail's disc, mm
_PLAN_APART_MM = 7.0  # a plan's detail sets its images this far apart
_PLAN_RADII = (3.0, 4.0, 6.0, 8.0, 12.0)  # the radii of its discs tried, mm (a knot round the pole)
_PLAN_CORE = 0.7  # a plan detail's disc: the smallest that holds this share of the most any holds


def _plan_names(
    solution: Solution, index: int, mu: float, kind: str
) -> tuple[list[Name], np.ndarray]:
    """The names a plan at `mu` writes (`Name`: its images' and its
    components', where each stands, mm) and its images (mm)."""
    view = solution.plan(index)
    images_si = view.velocity_images if kind == "velocity" else view.acceleration_images
    owners = tuple(solution.mechanism.point_owners)
    spots: dict[tuple[int, int], tuple[np.ndarray, list[str]]] = {}
    for n, v in images_si.items():
        at = np.asarray(v, float) / mu
        key = (round(float(at[0]) * 2), round(float(at[1]) * 2))
        spots.setdefault(key, (at, []))[1].append(image_markup(n, owners))
    out = [Name(at, name_area(", ".join(names))) for at, names in spots.values()]
    for g in view.groups:
        for c in g.velocity if kind == "velocity" else g.acceleration:
            s = np.asarray(c.start, float) / mu
            e = s + np.asarray(c.vector, float) / mu
            if kind == "acceleration" and float(np.hypot(*(e - s))) >= 0.5:
                name = f"a^{{n}}_{{{c.label.split('_', 1)[-1]}}}"
                out.append(Name((s + e) / 2.0, name_area(name)))
    points = np.array([at for at, _ in spots.values()], dtype=float).reshape(-1, 2)
    return out, points


def plan_details(
    solution: Solution, index: int, mu: float, kind: str, crowded: np.ndarray, letters: str
) -> tuple[Detail, ...]:
    """The detail views a plan at `mu` needs where the names standing for
    `crowded` (mm, `crowded_names` of the plan drawn without details) found no
    place near (`choose_details`): at most _PLAN_DETAILS discs apart round the
    pole, an image or such a point, one past the first only for a crowd of its
    own (_PLAN_CROWD), lettered by `letters` that name no point."""
    names, points = _plan_names(solution, index, mu, kind)
    used = {n[:1].upper() for n in solution.mechanism.point_owners}
    return choose_details(
        names,
        crowded,
        [np.zeros(2), *points],
        mu,
        [x for x in letters if x not in used],
        _PLAN_DETAILS,
        points=np.vstack([np.zeros((1, 2)), points]),
        spacing=_PLAN_APART_MM,
        widest=_PLAN_DETAIL_MM,
        tightest=_PLAN_CORE,
        radii=_PLAN_RADII,
        fewest=_PLAN_CROWD,
    )


def _plan_view(
    solution: Solution,
    index: int,
    mu: float,
    kind: str,
    look: Any,
    lang: Language,
    note: str = "",
    details: Sequence[Detail] = (),
    detail: Detail | None = None,
) -> tuple[Sketch, dict[str, np.ndarray]]:
    """The plan with `details` marked (`detail` None), or the detail view
    `detail`: its disc at μ / ratio, its lines cut at the disc's edge, every
    name there, titled "A (4:1)"."""
    gid = f"{kind}-plan-{index}"
    if detail is not None:
        k = list(details).index(detail)
        gid += "-detail" + (f"-{k + 1}" if k else "")
        mu = mu / detail.ratio
        details = [detail]  # its own disc
    discs = [(np.asarray(d.centre, float) / mu, d.radius / mu) for d in details]

    def here(at: np.ndarray) -> bool:
        """Whether what stands at `at` is lettered in this view: in its disc
        for a detail view, in no detail's disc otherwise."""
        inside = any(float(np.hypot(*(np.asarray(at) - c))) <= r for c, r in discs)
        return inside if detail is not None else not inside

    view = solution.plan(index)
    images_si = view.velocity_images if kind == "velocity" else view.acceleration_images
    images = {n: np.asarray(v, dtype=float) / mu for n, v in images_si.items()}
    # The point a group's plan solves for and that is no joint of the
    # mechanism (A3 of a slotted link, on the link beside the block's A): its
    # image is where the group's last component ends, and it is named too.
    solved: list[str] = []
    for g in view.groups:
        comps = g.velocity if kind == "velocity" else g.acceleration
        if g.point not in images and comps:
            last = comps[-1]
            images[g.point] = (np.asarray(last.start, float) + np.asarray(last.vector, float)) / mu
            solved.append(g.point)
    sk = Sketch(look)
    pole = "p" if kind == "velocity" else "π"
    moving = _moving_points(solution)
    # the components' labels are written last, at _SMALL
    placer = Labels(
        sk,
        _TEXT,
        leader_rings=FINE_LEADER_RINGS,
        leader_dirs=FINE_LEADER_DIRS,
        leader_group=FINE_LEADER_GROUP,
        smaller=_SMALL if len(solution.mechanism.links) <= _SHORT_LINKS else None,
        short_ends=len(solution.mechanism.links) <= _SHORT_LINKS,
        across_main=bool(details),  # (see the mechanism's)
    )
    # the acceleration components to name: start, end, name, by the head
    components: list[tuple[np.ndarray, np.ndarray, str, bool]] = []
    with sk.group(gid, "plan" if detail is None else "plan-detail"):
        begun = len(sk.calls)
        # Components of the vector equations, dashed.
        for g in view.groups:
            comps = g.velocity if kind == "velocity" else g.acceleration
            for c in comps:
                s = np.asarray(c.start, dtype=float) / mu
                e = s + np.asarray(c.vector, dtype=float) / mu
                if float(np.hypot(*(e - s))) < 0.5:
                    continue
                at_pole = float(np.hypot(*s)) < 1e-6
                if at_pole and any(
                    float(np.hypot(*(e - images[p]))) < 1e-6 for p in moving if p in images
                ):
                    continue  # coincides with an absolute vector
                sk.arrow(s, e, "dashed", head_length=3.0, head_width=1.0)
                # every component of the acceleration plan named as the textbook
                # names it: a^n, a^τ, a^k (Coriolis), a^r (relative)
                tags = {"normal": "n", "coriolis": "k", "tangential": "τ", "slide": "r"}
                # (by the head of a normal or Coriolis one, beside a tangential or
                # relative one), each naming its arrow
                if kind == "acceleration" and c.kind in tags:
                    name = f"a^{{{tags[c.kind]}}}_{{{c.label.split('_', 1)[-1]}}}"
                    # named where its head is drawn: by a detail whose disc holds it
                    if here(e):
                        inside = clipped(s, e, *discs[0]) if detail is not None else None
                        start = inside[0] if inside is not None else s
                        components.append((start, e, name, c.kind in ("normal", "coriolis")))
        # The image of each link: its joints' images joined by thin lines (the
        # relative vectors ab, de, and the similarity triangles of three-point links).
        owners = solution.mechanism.point_owners
        for link in solution.mechanism.links.values():
            joints = [p for p in link.points if p in images and len(owners.get(p, ())) > 1]
            for i in range(len(joints)):
                for j in range(i + 1, len(joints)):
                    a, b = images[joints[i]], images[joints[j]]
                    if float(np.hypot(*(b - a))) >= 0.5:
                        sk.line(a, b, "thin")
        # Absolute vectors from the pole, main lines.
        labels: dict[tuple[int, int], list[str]] = {}
        for name in moving:
            if name not in images:
                continue
            v = images[name]
            if float(np.hypot(*v)) >= 0.5 and not name.startswith("S"):
                sk.arrow((0.0, 0.0), v)
            elif float(np.hypot(*v)) >= 0.5:
                sk.circle(v, 0.6, "thin", "black")
            key = (round(float(v[0]) * 2), round(float(v[1]) * 2))
            labels.setdefault(key, []).append(name)
        for name in solved:
            v = images[name]
            if float(np.hypot(*v)) >= 0.5:
                sk.circle(v, 0.6, "thin", "black")
            key = (round(float(v[0]) * 2), round(float(v[1]) * 2))
            labels.setdefault(key, []).append(name)
        sk.circle((0.0, 0.0), 0.8, "main", "black")
        if detail is not None:
            sk.calls[begun:] = cut_to_disc(sk.calls[begun:], *discs[0])
            sk.circle(discs[0][0], discs[0][1], "thin")  # the view's edge
        else:
            sk.calls[begun:] = heads_outside(sk.calls[begun:], discs)
        for middle, r in discs if detail is None else ():
            sk.circle(middle, r, "thin")
        placer.avoid_drawn(sk.calls)
        if here(np.zeros(2)):
            placer.place((0.0, 0.0), pole, towards=(-1.0, -1.0))
        for d, (middle, r) in zip(details, discs) if detail is None else ():
            rim, towards = rim_anchors(middle, r)[0]  # up and right
            placer.place(rim, d.letter, towards=towards)
        # the images among most lines first (they have the fewest places near
        # them), then the components; where some find no place near: the
        # components shorter than _SHORT_COMPONENT (amid the pole's or an
        # image's arrowheads) among the images, crowded first, then the rest
        named: list[Any] = [
            names
            for names in labels.values()
            if float(np.hypot(*images[names[0]])) >= 0.5 and here(images[names[0]])
        ]
        items = [*_crowded_first(placer, [images[n[0]] for n in named], named), *components]
        short = [
            k
            for k, c in enumerate(items)
            if not isinstance(c, list) and float(np.hypot(*(c[1] - c[0]))) < _SHORT_COMPONENT
        ]
        first = [k for k, c in enumerate(items) if isinstance(c, list)] + short
        anchors = [
            images[items[k][0]] if isinstance(items[k], list) else (items[k][0] + items[k][1]) / 2
            for k in first
        ]
        crowded = _crowded_first(placer, anchors, first)
        crowded += [k for k in range(len(items)) if k not in first]

        everyone = tuple(solution.mechanism.point_owners)

        def write(item: Any) -> Callable[[], object]:
            if isinstance(item, list):
                v = images[item[0]]
                markup = ", ".join(image_markup(n, everyone) for n in item)
                return lambda: _at_size(
                    placer, _TEXT, lambda: placer.place(v, markup, towards=unit_vector(v))
                )
            s, e, name, by_head = item
            if by_head:
                return lambda: _at_size(placer, _SMALL, lambda: placer.place_arrow(s, e, name))
            return lambda: _at_size(
                placer, _SMALL, lambda: placer.place_along(s, e, name, around=True)
            )

        # (a long chain's plans keep the usual order: see _SHORT_LINKS)
        chain = len(solution.mechanism.links) > _SHORT_LINKS
        # the components before the images too: a component's name has a
        # place near it only along its short shaft, an image's all round it
        parts = [k for k in crowded if not isinstance(items[k], list)]
        parts += [k for k in crowded if isinstance(items[k], list)]
        placer.write_each(
            [write(item) for item in items],
            [crowded, parts] if short and not chain else [],
            most=0 if chain else _REORDER_MOST,
        )
        ext = sk.extent()
        if detail is not None:
            ratio = catalogue(lang).plain_number(detail.ratio)
            title = _words(lang)["plan_detail"].format(letter=detail.letter, ratio=ratio)
            sk.text(((ext.left + ext.right) / 2, ext.top + 3.0), title, _TEXT, anchor="center")
            return sk, images
        q: Quantity = "velocity" if kind == "velocity" else "acceleration"
        sk.rich_text(
            ((ext.left + ext.right) / 2, ext.bottom - 5.0),
            scale_label(mu, q, lang).markup(),
            _TEXT,
            anchor="center",
        )
        if note:
            sk.text(((ext.left + ext.right) / 2, ext.bottom - 10.0), note, _SMALL, anchor="center")
        title = _words(lang)[f"{kind}_plan"].format(i=index)
        sk.text(((ext.left + ext.right) / 2, ext.top + 3.0), title, _TEXT, anchor="center")
    return sk, images


def _at_size(placer: Labels, size: float, write: Callable[[], object]) -> object:
    """`write()` with the placer's letter height `size`."""
    kept = placer.size
    placer.size = size
    try:
        return write()
    finally:
        placer.size = kept


def _crowded_first(
    placer: Labels, anchors: Sequence[np.ndarray], items: Sequence[Any]
) -> list[Any]:
    """`items` (one for each of `anchors`) in the order their labels are best
    written: the anchor with most drawn round it (within NEAR_MM) first, for
    it has the fewest free places near it and one written before would take them."""
    crowd = [placer.covered(shapely.Point(*map(float, a)).buffer(NEAR_MM)) for a in anchors]
    order = sorted(range(len(items)), key=lambda i: -crowd[i])
    return [items[i] for i in order]


# --- diagrams ----------------------------------------------------------------------


def _free_spot(
    sk: Sketch, free: Labels, text: str, size: float, spots: Sequence[tuple[Any, str, str]]
) -> tuple[Any, str, str] | None:
    """The first of `spots` (position, anchor, valign) where `text` covers no line
    (every spot's box asked of the placer in one query, Labels.first_free)."""
    return _free_spots(sk, free, size, [(text, spots)])[0]


def _free_spots(
    sk: Sketch,
    free: Labels,
    size: float,
    asked: Sequence[tuple[str, Sequence[tuple[Any, str, str]]]],
) -> list[tuple[Any, str, str] | None]:
    """_free_spot of each (text, spots) of `asked`, every box in one query
    (whether a box is free depends on it alone: the same answers)."""
    probe = RecordingBackend(look=sk.look)
    for text, spots in asked:
        for pos, anchor, valign in spots:
            probe.text(pos, text, size, anchor=anchor, valign=valign)  # type: ignore[arg-type]
    if not probe.calls:
        return [None for _ in asked]
    ok = free.free_boxes(np.array([probe.text_box(c) for c in probe.calls], dtype=float))
    out: list[tuple[Any, str, str] | None] = []
    start = 0
    for _, spots in asked:
        hits = np.flatnonzero(ok[start : start + len(spots)])
        out.append(spots[int(hits[0])] if hits.size else None)
        start += len(spots)
    return out


def _axes(sk: Sketch, x0: float, x1: float, y0: float, y1: float, ylabel: str, xlabel: str) -> None:
    sk.arrow((x0, 0.0), (x1, 0.0), "main", head_length=3.0, head_width=1.2)
    sk.arrow((0.0, y0), (0.0, y1), "main", head_length=3.0, head_width=1.2)
    sk.rich_text((2.0, y1 - 3.0), ylabel, _TEXT)
    sk.text((x1, -5.0), xlabel, _TEXT, anchor="right", valign="top")


def sketch_diagram(
    construction: Any,
    which: str,
    look: Any,
    lang: Language,
    s_dense: np.ndarray | None = None,
    refinement: int = 1,
    mu_l: float | None = None,
    mu_l_solution: float | None = None,
    filling: bool = False,
) -> Sketch:
    """One of the S, V, a diagrams with its construction. `s_dense` (m, at equal
    crank steps from position 0) draws S as the smooth curve through the
    positions' ordinates, as a draughtsman draws it with a French curve.
    `mu_l` (the mechanism's drawing on this sheet): μ_S other than it is
    explained under S, by the diagrams' height when μ_l is the calculation's
    `mu_l_solution` (the one μ_S was chosen from), else by the field; with
    `filling` (μ_S chosen to fill the field: _grown_scales), a coarser μ_S by
    the room it leaves V and a."""
    c = construction
    sk = Sketch(look)
    axes = catalogue(lang).words("diagram_axes")
    L = float(c.s_points[-1][0])
    with sk.group(f"diagram-{which}", "diagram"):
        if which == "s":
            pts = np.asarray(c.s_points, dtype=float)
            curve = pts
            if s_dense is not None:
                y = np.append(s_dense, s_dense[0]) / c.mu_S
                curve = np.column_stack([np.linspace(0.0, L, len(y)), y])
            deriv = c.velocity
            label = axes["s"]
            scales = [
                scale_label(_tidy(c.mu_S), "displacement", lang),
                scale_label(_tidy(c.mu_t), "time", lang),
            ]
        elif which == "v":
            deriv = c.velocity
            pts = np.asarray(deriv.mid_points, dtype=float)
            curve = np.asarray(deriv.curve, dtype=float)
            label = axes["v"]
            scales = [scale_label(_tidy(c.mu_V), "velocity", lang)]
        else:
            deriv = c.acceleration
            pts = np.asarray(deriv.mid_points, dtype=float)
            curve = np.asarray(deriv.curve, dtype=float)
            label = axes["a"]
            scales = [scale_label(_tidy(c.mu_a), "acceleration", lang)]
        ymin = min(0.0, float(curve[:, 1].min()))
        ymax = max(0.0, float(curve[:, 1].max()))
        x_lo = float(deriv.pole[0]) - 4.0 if which != "s" else -4.0
        _axes(sk, x_lo, L + 12.0, ymin - 4.0, ymax + 10.0, str(label), str(axes["t"]))
        # Ordinates at the positions, numbered under the axis.
        grid = np.asarray(c.abscissae, dtype=float).tolist() + [L]
        ticks = []  # numbered once every line is drawn, where they cover none
        for i, x in enumerate(grid):
            if i % refinement == 0:  # the positions are numbered, the finer grid is not
                ticks.append((x, str((i // refinement) % ((len(grid) - 1) // refinement))))
            if which == "s":
                y = float(c.s_points[i][1])
                if abs(y) > 0.5:
                    sk.line((x, 0.0), (x, y), "thin")
        sk.polyline([tuple(p) for p in curve], "main")
        if which != "s":
            # The construction: pole H, rays H–K_i, K_i carried to the mid points.
            H = np.asarray(deriv.pole, dtype=float)
            sk.circle(H, 0.8, "main", "black")
            for s, e in np.asarray(deriv.rays, dtype=float):
                sk.line(s, e, "thin")
            for kp, mp in zip(np.asarray(deriv.k_points, dtype=float), pts):
                sk.line(kp, (mp[0], kp[1]), "thin")
                sk.circle(mp, 0.6, "thin", "black")
        # Chords of the graphical differentiation drawn on the source diagram.
        chords = None
        if which == "s":
            chords = c.velocity.chords
        elif which == "v":
            chords = c.acceleration.chords
        if chords is not None:
            for s, e in np.asarray(chords, dtype=float):
                sk.line(s, e, "dashed")
        # The lettering of the construction, clear of every line: the pole's
        # letter beside the pole away from its rays, the positions' numbers
        # under the time axis (above it where the curve or a line is below),
        # the first "0" left of the ordinate axis.
        free = Labels(sk, _TEXT)  # asked only what is covered: it follows every line drawn
        if which != "s":
            hx = float(deriv.pole[0])
            spot = _free_spot(
                sk,
                free,
                "H",
                _TEXT,
                [
                    ((hx - 1.0, -1.2), "right", "top"),
                    ((hx - 1.0, 1.2), "right", "baseline"),
                    ((hx, -1.5), "center", "top"),
                    ((hx, 1.5), "center", "baseline"),
                ],
            )
            pos, anchor, valign = spot or ((hx - 5.0, 0.0), "right", "middle")
            sk.text(pos, "H", _TEXT, anchor=anchor, valign=valign)  # type: ignore[arg-type]
        # the numbers at the time axis, under it or over it where a line is in
        # the way; where no place by the axis is free for one of them, all in a
        # row under the whole diagram (one rule for the diagram)
        asked = []
        for j, (x, number) in enumerate(ticks):
            if j == 0:  # the first "0" left of the ordinate axis
                near = [((x - 1.2, -1.2), "right", "top"), ((x - 1.2, 1.2), "right", "baseline")]
            else:
                near = [((x, -1.2), "center", "top"), ((x, 1.2), "center", "baseline")]
                near += [((x + d, -1.2), "center", "top") for d in (-1.5, 1.5)]
                near += [((x + d, 1.2), "center", "baseline") for d in (-1.5, 1.5)]
            asked.append((number, near))
        spots = _free_spots(sk, free, _SMALL, asked)
        for (x, number), spot in zip(ticks, spots):
            if any(sp is None for sp in spots):
                spot = ((x, ymin - 5.0), "center", "top")
            assert spot is not None
            pos, anchor, valign = spot
            sk.text(pos, number, _SMALL, anchor=anchor, valign=valign)  # type: ignore[arg-type]
        ext = sk.extent()
        y = ext.bottom - 5.0
        x = ext.x + _PAD
        for lab in scales:
            x += sk.rich_text((x, y), lab.markup(), _TEXT) + 8.0
        if which != "s":
            pole = f"{float(-deriv.pole[0]):.2f}".rstrip("0").rstrip(".")
            sk.rich_text((x, y), str(axes["pole"]).format(H=catalogue(lang).localise(pole)), _TEXT)
        elif mu_l is not None and abs(c.mu_S / mu_l - 1.0) > 1e-9:
            # seed 003 §1.7 draws S at μ_S = μ_l: another μ_S says why
            cat = catalogue(lang)
            k = cat.plain_number(float(f"{c.mu_S / mu_l:.6g}"))
            same = mu_l_solution is None or abs(mu_l / mu_l_solution - 1.0) <= 1e-9
            reason = (
                _words(lang)["mu_S_reason_finer"].format(k=k)
                if c.mu_S < mu_l
                else _words(lang)["mu_S_reason_fill"].format(k=k)
                if filling
                else _words(lang)["mu_S_reason"].format(k=k)
                if same
                else _words(lang)["mu_S_reason_field"].format(
                    k=k,
                    mu_S=cat.plain_number(_tidy(c.mu_S)),
                    unit=cat.unit("m/mm"),
                )
            )
            sk.rich_text((ext.x + _PAD, y - _TEXT - 2.0), reason, _TEXT)
        sk.text((ext.x + _PAD, ext.top + 3.0), _words(lang)[f"diagram_{which}"], _TEXT)
    return sk


def _stack(parts: Sequence[Sketch], look: Any, gap: float = 6.0) -> Sketch:
    """One sketch of several, top to bottom, their local origins on one vertical line."""
    out = Sketch(look)
    y = 0.0
    for part in parts:
        ext = part.extent()
        dy = y - ext.top
        part.replay(out, 0.0, dy)  # each call with its groups, shifted down
        y = ext.bottom + dy - gap
    return out


# --- tables ------------------------------------------------------------------------


@dataclass(frozen=True)
class _TableSpec:
    """What table_sketch draws of one of sheet 1's tables."""

    gid: str
    title: str
    header: Sequence[str]
    rows: Sequence[Sequence[str]]
    widths: Sequence[float]
    marks: Sequence[str]
    header_markup: Sequence[str | None] | None = None


def _continued_tables(specs: Sequence[_TableSpec], look: Any, lang: Language) -> dict[str, Sketch]:
    """The tables; where one is taller than TABLE_PART_MM, every table of the
    sheet numbered ("Table 1 – Velocities, m/s") and the long one in parts
    ("Continuation of Table 1")."""
    w = _words(lang)
    numbered = any(rows_per_part(len(t.rows), TABLE_PART_MM) < len(t.rows) for t in specs)
    out: dict[str, Sketch] = {}
    for n, t in enumerate(specs, start=1):
        title = w["table_numbered"].format(n=n, title=t.title) if numbered else t.title
        out[t.gid] = table_sketch(
            look,
            t.gid,
            title,
            t.header,
            t.rows,
            t.widths,
            t.marks,
            lang,
            header_markup=t.header_markup,
            max_height=TABLE_PART_MM,
            continued=w["table_continued"].format(n=n),
        )
    return out


def _sketch_tables(solution: Solution, look: Any, lang: Language) -> dict[str, Sketch]:
    w = _words(lang)
    idx = list(solution.plan_positions)
    views = [solution.plan(i) for i in idx]
    moving = _moving_points(solution)
    out: dict[str, Sketch] = {}
    specs: list[_TableSpec] = []

    for kind, gid, title, sym in (
        ("velocity", "table-velocities", w["velocities"], "V"),
        ("acceleration", "table-accelerations", w["accelerations"], "a"),
    ):
        rows: list[list[str]] = []
        marks: list[str] = []
        for name in moving:
            vals = []
            for v in views:
                img = (v.velocity_images if kind == "velocity" else v.acceleration_images).get(name)
                vals.append(_fmt(float(np.hypot(*img))) if img is not None else "—")
            rows.append([name, *vals])
            marks.append(f"{sym}_{{{name}}}")
        labels: list[str] = []
        for g in views[0].groups:
            for c in g.velocity if kind == "velocity" else g.acceleration:
                if c.kind in ("slide",) or c.label in labels:
                    continue
                labels.append(c.label)
        for lab in labels:
            vals = []
            for v in views:
                found = [
                    c
                    for g in v.groups
                    for c in (g.velocity if kind == "velocity" else g.acceleration)
                    if c.label == lab
                ]
                vals.append(_fmt(float(np.hypot(*found[0].vector))) if found else "—")
            if all(x in ("0", "—") for x in vals):
                continue  # a component that vanishes at every planned position (Coriolis on a still guide)
            rows.append([lab, *vals])
            marks.append(component_markup(lab))
        header = [w["quantity"], *(f"{w['position']} {i}" for i in idx)]
        specs.append(_TableSpec(gid, title, header, rows, [22.0] + [20.0] * len(idx), marks))

    rows = []
    marks = []
    links = sorted(views[0].omega)
    for lid in links:
        vals = []
        for v in views:
            vals += [
                _fmt(float(v.omega.get(lid, float("nan")))),
                _fmt(float(v.eps.get(lid, float("nan")))),
            ]
        rows.append([str(lid), *vals])
        marks.append(str(lid))
    header = [w["link"]]
    units = catalogue(lang)
    for i in idx:
        header += [f"ω, {units.unit('1/s')} ({i})", f"ε, {units.unit('1/s2')} ({i})"]
    specs.append(
        _TableSpec(
            "table-omega-eps", w["omega_eps"], header, rows, [14.0] + [20.0] * (2 * len(idx)), marks
        )
    )

    dg = solution.require_diagrams()
    sc = dg.sheet_check
    rows = []
    marks = []
    # Seed 003 §1.8, formulas (12) and (13), at the investigated positions on
    # the diagrams drawn; an ill-conditioned one shows its absolute error.
    for i in idx:
        row = [str(i)]
        for q in ("v", "a"):
            val = next(x for x in sc.values if x.index == i and x.quantity == q)
            err = (
                catalogue(lang).localise(f"±{_fmt(val.absolute_error, 2)}*")
                if val.ill_conditioned
                else f"{val.error_percent:.1f}"
            )
            row += [_fmt(val.plan), _fmt(val.diagram), err]
        rows.append(row)
        marks.append(str(i))
    header = [
        w["position"],
        f"V {w['plan']}",
        f"V {w['diagram']}",
        "δV, %",
        f"a {w['plan']}",
        f"a {w['diagram']}",
        "δa, %",
    ]
    # formulas (12) and (13): Δ_V, Δ_a of V_plan and V_diagram (a likewise)
    header_marks: list[str | None] = [None]
    for q, unit in (("V", "m/s"), ("a", "m/s2")):
        u = catalogue(lang).unit(unit)
        header_marks += [
            f"{q}_{{{w['plan']}}}\n{u}",
            f"{q}_{{{w['diagram']}}}\n{u}",
            f"Δ_{{{q}}}, %",
        ]
    specs.append(
        _TableSpec(
            "table-check", w["check"], header, rows, [12.0] + [18.0] * 6, marks, header_marks
        )
    )
    out.update(_continued_tables(specs, look, lang))
    sk = out["table-check"]
    step = 360.0 / sc.intervals
    notes = [w["grid"].format(n=sc.intervals, step=f"{step:g}")]
    for val in sc.values:
        if val.ill_conditioned:
            sym = "V" if val.quantity == "v" else "a"
            notes.append(
                w["ill_conditioned"].format(
                    q=sym,
                    i=val.index,
                    share=f"{ILL_CONDITIONED * 100:g}",
                    abs=_fmt(val.absolute_error, 2),
                    unit=catalogue(lang).unit("m/s" if val.quantity == "v" else "m/s2"),
                )
            )
    for val in sc.values:
        if not val.passed:
            sym = "V" if val.quantity == "v" else "a"
            notes.append(
                w["over_plain"].format(
                    q=sym,
                    i=val.index,
                    e=f"{abs(val.error_percent):.1f}",
                    lim=f"{sc.limit_percent:g}",
                )
            )
    notes.append(
        w["verdict_passed" if sc.passed else "verdict_failed"].format(lim=f"{sc.limit_percent:g}")
    )
    notes = [catalogue(lang).localise(n) if lang != "en" else n for n in notes]
    extra = Sketch(look)
    y = sk.extent().bottom - 2.0
    for note in notes:
        extra.text((0.0, y), note, _SMALL, valign="top")
        y -= _SMALL + 1.5
    sk.add_to_last_group(extra, "table-check")
    out["table-check"] = sk
    return out


# --- composing ---------------------------------------------------------------------


_PLACEMENT: Mapping[str, str] = {
    "mechanism": "top-left",
    "structural-formula": "top-left",
    "diagrams": "bottom-left",
    "diagram-s": "bottom-left",
    "diagram-v": "bottom-left",
    "diagram-a": "bottom-left",
    "table-velocities": "top-right",
    "table-accelerations": "top-right",
    "table-omega-eps": "top-right",
    "table-check": "top-right",
}

# The plans' size (seed 003 §1.3: pa "not less than 100 … 150 mm"; §1.5: πa ≈
# 100 … 200 mm), as one rule for both kinds: each plan's longest vector from
# its pole is drawn 100 … 200 mm long.
PLAN_GUIDE_MM = (100.0, 200.0)
# series steps a plan may be drawn coarser than its guide scale to make room
PLAN_SHRINK = 4


def _pole_longest(solution: Solution, index: int, kind: str) -> float:
    """The longest vector drawn from the pole of a plan (an absolute vector, or a
    component that starts at the pole), m/s or m/s²."""
    view = solution.plan(index)
    images = view.velocity_images if kind == "velocity" else view.acceleration_images
    longest = 0.0
    for name in _moving_points(solution):
        if name in images and not name.startswith("S"):
            longest = max(longest, float(np.hypot(*images[name])))
    for g in view.groups:
        for c in g.velocity if kind == "velocity" else g.acceleration:
            if float(np.hypot(*c.start)) <= 1e-9 * max(longest, 1.0):
                longest = max(longest, float(np.hypot(*c.vector)))
    return longest if math.isfinite(longest) else 0.0


def _guide_scale(longest: float) -> float:
    """The finest series μ that draws `longest` no longer than 200 mm (the series
    steps by at most 1.6, so it draws it 125 mm long at least)."""
    hi = PLAN_GUIDE_MM[1]
    return next(iter(series(longest / hi * (1 - 1e-9), longest / hi * 100.0)))


def _plan_scales(solution: Solution, shrink: int = 0) -> dict[str, float]:
    """μ of every plan, "velocity 3" / "acceleration 3": the finest series value
    drawing the longest vector from the pole of all positions within 200 mm,
    one μ for all positions of a kind where that draws each plan's own longest
    vector 100 mm at least, else each plan at its own finest μ; `shrink`
    series steps coarser where the sheet cannot hold them."""
    lo = PLAN_GUIDE_MM[0]
    out: dict[str, float] = {}
    for kind in ("velocity", "acceleration"):
        longest = {i: _pole_longest(solution, i, kind) for i in solution.plan_positions}
        top = max(longest.values(), default=0.0)
        if not top > 0.0:
            out.update({f"{kind} {i}": 1.0 for i in longest})
            continue
        common = _guide_scale(top)
        one = all(v == 0.0 or v / common >= lo * (1 - 1e-9) for v in longest.values())
        for i, v in longest.items():
            mu = common if one or v == 0.0 else _guide_scale(v)
            out[f"{kind} {i}"] = _next_scale(mu, shrink)
    return out


def _reduced_note(solution: Solution, index: int, kind: str, mu: float, lang: Language) -> str:
    """The note under a plan drawn below the guide's 100 mm (empty when it is not)."""
    lo, hi = PLAN_GUIDE_MM
    drawn = _pole_longest(solution, index, kind) / mu
    if drawn <= 0.0 or drawn >= lo * (1 - 1e-9):
        return ""
    return str(_words(lang)["plan_reduced"]).format(mm=f"{drawn:.0f}", lo=f"{lo:g}", hi=f"{hi:g}")


def _sketch_all(
    solution: Solution,
    look: Any,
    lang: Language,
    plan_mu: Mapping[str, float],
    mu_l: float,
    stacked: bool,
    cache: dict[tuple[str, float], Any],
    details: bool = False,
) -> tuple[dict[str, Sketch], dict[str, float], KinematicDiagrams]:
    """Every drawing but the mechanism: the plans at `plan_mu` (_plan_scales), the diagrams
    as the Solution constructed them (its μ_S and poles, the ones the note and
    the results JSON give); `cache` keeps what was drawn at a scale. With
    `details`, a plan whose names crowd is drawn with its crowd marked, and
    its detail views apart ("…-plan-3-detail", `sketch_plan_details`), each
    plan's lettered by letters of its own."""

    def memo(name: str, mu: float, make: Callable[[], Any]) -> Any:
        if (name, mu) not in cache:
            cache[(name, mu)] = make()
        return cache[(name, mu)]

    sketches: dict[str, Sketch] = {}
    sketches["structural-formula"] = memo(
        "structural-formula", 0.0, lambda: sketch_formula(solution, look, lang)
    )
    used = {n[:1].upper() for n in solution.mechanism.point_owners}
    letters = "".join(x for x in DETAIL_LETTERS if x not in used)
    for i, kind in itertools.product(solution.plan_positions, ("velocity", "acceleration")):
        mu = plan_mu[f"{kind} {i}"]
        note = _reduced_note(solution, i, kind, mu, lang)
        sketches[f"{kind}-plan-{i}"] = memo(
            f"{kind}-plan-{i}",
            mu,
            lambda: sketch_plan(solution, i, mu, kind, look, lang, note)[0],
        )
        crowd = (
            memo(
                f"{kind}-plan-{i}-details {letters}",
                mu,
                lambda: sketch_plan_details(
                    solution, i, mu, kind, look, lang, note, letters, sketches[f"{kind}-plan-{i}"]
                ),
            )
            if details and letters
            else None
        )
        if crowd is not None:
            sketches[f"{kind}-plan-{i}"], views, taken = crowd
            for k, view in enumerate(views):
                sketches[f"{kind}-plan-{i}-detail" + (f"-{k + 1}" if k else "")] = view
            letters = "".join(x for x in letters if x not in taken)

    dg = solution.require_diagrams()
    drawn = dg.construction

    def diagram(which: str) -> Sketch:
        return _diagram_sketch(solution, drawn, which, look, lang, mu_l)

    # V and a do not depend on the mechanism's μ_l: drawn once
    parts = [
        memo(f"diagram-{which}", mu_l if which == "s" else 0.0, lambda: diagram(which))
        for which in ("s", "v", "a")
    ]
    if stacked:
        sketches["diagrams"] = memo("diagrams-stacked", mu_l, lambda: _stack(parts, look))
    else:
        for which, sk in zip("sva", parts):
            sketches[f"diagram-{which}"] = sk
    sketches.update(memo("tables", 0.0, lambda: _sketch_tables(solution, look, lang)))
    first = solution.plan_positions[0]
    scales = {
        "mu_V": plan_mu[f"velocity {first}"],
        "mu_a": plan_mu[f"acceleration {first}"],
        **{f"mu_V {i}": plan_mu[f"velocity {i}"] for i in solution.plan_positions},
        **{f"mu_a {i}": plan_mu[f"acceleration {i}"] for i in solution.plan_positions},
        **_diagram_scales(drawn),
    }
    return sketches, scales, drawn


def _with_details(
    solution: Solution,
    look: Any,
    lang: Language,
    mu_l: float,
    cache: dict[tuple[str, float], Any],
) -> Iterator[tuple[int, dict[str, Sketch], dict[str, float], KinematicDiagrams]]:
    """The drawings of the sheet (`_sketch_all`) as compose_sheet1 tries them,
    the plans 0, 1, 2 series steps coarser than their guide's (`_plan_scales`);
    at each, first with the detail views of every plan whose names crowd,
    then (where more than one plan has them: they take room the sheet may not
    have) with those of one plan alone, the plan whose details letter most
    names first; then with none."""
    for shrink in range(3):
        plan_mu = _plan_scales(solution, shrink)
        full, scales, drawn = _sketch_all(solution, look, lang, plan_mu, mu_l, True, cache, True)
        crowded = {n.split("-detail")[0] for n in full if "-detail" in n}
        if not crowded:
            yield shrink, full, scales, drawn
            continue
        plain, _, _ = _sketch_all(solution, look, lang, plan_mu, mu_l, True, cache)

        def lettered(plan: str) -> int:
            views = [v for n, v in full.items() if n.startswith(plan + "-detail")]
            return sum(c.naming is not None for v in views for c in v.calls)

        alone = sorted(crowded, key=lambda p: (-lettered(p), list(full).index(p)))
        tried = [set(crowded), *({p} for p in alone)] if len(crowded) > 1 else [set(crowded)]
        for kept in [*tried, set()]:
            sketches = dict(plain)
            for n, v in full.items():
                if n.split("-detail")[0] in kept:
                    sketches[n] = v
            yield shrink, sketches, scales, drawn


def _diagram_sketch(
    solution: Solution,
    construction: KinematicDiagrams,
    which: str,
    look: Any,
    lang: Language,
    mu_l: float,
    filling: bool = False,
) -> Sketch:
    """The diagram `which` ("s", "v", "a") of `construction`; S beside a
    mechanism drawn at μ_l `mu_l`, its μ_S chosen from the calculation's μ_l
    where it is the calculation's μ_S, else from `mu_l` (with `filling`: to
    fill the field, sketch_diagram)."""
    calculated = solution.require_diagrams()
    same = abs(construction.mu_S / calculated.construction.mu_S - 1.0) <= 1e-9
    return sketch_diagram(
        construction,
        which,
        look,
        lang,
        solution.s_dense,
        calculated.refinement,
        mu_l=mu_l if which == "s" else None,
        mu_l_solution=float(solution.mu_l) if same else mu_l,
        filling=filling,
    )


def _diagram_scales(drawn: KinematicDiagrams) -> dict[str, float]:
    """The scales record's entries of the diagrams as drawn."""
    return {
        "L": drawn.L,
        "mu_S": drawn.mu_S,
        "mu_t": drawn.mu_t,
        "mu_V_diagram": drawn.mu_V,
        "mu_a_diagram": drawn.mu_a,
        "H1": drawn.H1,
        "H2": drawn.H2,
    }


def _geometric_extent(solution: Solution) -> tuple[float, float]:
    """Width and height (m) of the mechanism in every position with its trajectories."""
    xs: list[float] = []
    ys: list[float] = []
    for source in (solution.sweep.points, solution.dense.points):
        for arr in source.values():
            a = np.asarray(arr, dtype=float).reshape(-1, 2)
            a = a[np.all(np.isfinite(a), axis=1)]
            if len(a):
                xs += [float(a[:, 0].min()), float(a[:, 0].max())]
                ys += [float(a[:, 1].min()), float(a[:, 1].max())]
    if not xs:
        return (1.0, 1.0)
    return (max(xs) - min(xs), max(ys) - min(ys))


def _order(sketches: Mapping[str, Sketch], stacked: bool) -> list[str]:
    # Big fixed pieces first: the column of diagrams bottom left, the tables
    # from the top right, the mechanism in the field left of the tables and
    # above the diagrams; the plans then take the free middle.
    columns = ["diagrams"] if stacked else ["diagram-s", "diagram-v", "diagram-a"]
    return [
        *columns,
        "table-velocities",
        "table-accelerations",
        "table-omega-eps",
        "table-check",
        "mechanism",
        "structural-formula",
        *(n for n in sketches if n.startswith("mechanism-detail")),
        *(n for n in sketches if n.startswith("mechanism-position")),
    ] + [n for n in sketches if n.startswith("velocity-plan") or n.startswith("acceleration-plan")]


def mechanism_field(
    layout: SheetLayout, gap: float, size: tuple[float, float] | None = None
) -> Rect:
    """The field of the mechanism's drawing (Appendix A: top left): a rectangle
    from the free region's top-left corner, clear (by `gap`) of what was placed
    before it (the diagrams, the tables). Of the right edges it may take (the
    region's, or `gap` left of a placed element) the one in which a `size`
    (width, height) drawing grows largest; without `size`, the largest field."""
    region = layout.region
    boxes = [e.bounds for e in layout.elements]
    rights = {region.right, *(b.left - gap for b in boxes if b.left - gap > region.left + 1.0)}
    best: tuple[float, Rect] | None = None
    for right in sorted(rights):
        bottom = max(
            [region.bottom]
            + [b.top + gap for b in boxes if b.left < right + gap and b.right > region.left]
        )
        if bottom > region.top - 1.0:
            continue
        rect = Rect.from_bounds(region.left, bottom, right, region.top)
        w, h = size if size is not None else (1.0, 1.0)
        score = (
            min(rect.width / max(w, 1e-9), rect.height / max(h, 1e-9))
            if size is not None
            else rect.width * rect.height
        )
        if best is None or score > best[0] + 1e-9:
            best = (score, rect)
    if best is None:
        return Rect.from_bounds(region.left, region.top - 1.0, region.left + 1.0, region.top)
    return best[1]


class _Extents:
    """Each sketch's extent, measured once within one compose_sheet1 call (the
    layout trials ask for the same drawings' extents again and again); a
    sketch is kept here with its extent, so its id stays its own."""

    def __init__(self) -> None:
        self._seen: dict[int, tuple[Sketch, Rect]] = {}

    def __call__(self, sketch: Sketch) -> Rect:
        hit = self._seen.get(id(sketch))
        if hit is None or hit[0] is not sketch:
            hit = (sketch, sketch.extent())
            self._seen[id(sketch)] = hit
        return hit[1]


def _try_layout(
    page: Page,
    sketches: Mapping[str, Sketch],
    order: Sequence[str],
    gap: float,
    with_field: bool,
    tables_width: float | None = None,
    diagrams: str = "bottom-left",
    extents: _Extents | None = None,
    reserved: Mapping[str, tuple[float, float]] | None = None,
) -> tuple[SheetLayout, dict[str, Rect], Rect | None]:
    """Place every sketch in `order` (a `reserved` one in a box of that width
    and height, its sketch at the box's bottom left); the mechanism inside its field when
    `with_field` (LayoutError if it does not fit there); the tables within
    `tables_width` mm of the right edge when given (a block, not a row); the
    diagrams from the `diagrams` corner (bottom left, under the mechanism, as
    Appendix A draws them, or bottom right, beside the title block, so that a
    tall mechanism takes the sheet's height). The mechanism's detail views in
    its field nearest the knots they detail; where the sheet then has no
    room for the rest, in the field's lowest free place instead (held-out gen
    441: the view by its knot took the room beside the drawing that a tall
    velocity plan needs, under the drawing the field was empty)."""
    args = (page, sketches, order, gap, with_field, tables_width, diagrams, extents, reserved)
    try:
        return _layout_once(*args)
    except LayoutError as err:
        if str(err).startswith("mechanism:") or not any(
            n.startswith("mechanism-detail") for n in order
        ):
            raise
        return _layout_once(*args, by_knot=False)


def _layout_once(
    page: Page,
    sketches: Mapping[str, Sketch],
    order: Sequence[str],
    gap: float,
    with_field: bool,
    tables_width: float | None,
    diagrams: str,
    extents: _Extents | None,
    reserved: Mapping[str, tuple[float, float]] | None,
    by_knot: bool = True,
) -> tuple[SheetLayout, dict[str, Rect], Rect | None]:
    """_try_layout's one trial: the mechanism's detail views nearest their
    knots (`by_knot`) or in the field's lowest free place."""
    extent = extents if extents is not None else _Extents()
    layout = SheetLayout(page, gap=gap)
    region = layout.region
    placed: dict[str, Rect] = {}
    field: Rect | None = None
    for name in order:
        ext = extent(sketches[name])
        if reserved is not None and name in reserved:
            ext = Rect(ext.x, ext.y, *reserved[name])
        corner = diagrams if name.startswith("diagram") else _PLACEMENT.get(name, "top-left")
        kind = "table" if name.startswith("table") else "drawing"
        within = None
        if kind == "table" and tables_width is not None:
            width = min(region.width, max(tables_width, ext.width))
            within = Rect(region.right - width, region.bottom, width, region.height)
        if name == "mechanism" and with_field:
            field = mechanism_field(layout, gap, (ext.width, ext.height))
            if ext.width > field.width + 1e-6 or ext.height > field.height + 1e-6:
                raise LayoutError(
                    f"mechanism: {ext.width:.0f} x {ext.height:.0f} mm is larger than "
                    f"its field {field.width:.0f} x {field.height:.0f} mm"
                )
            within = field
        # a plan's detail view beside its plan
        near = placed.get(name.split("-detail")[0]) if "-detail" in name else None
        if name.startswith("mechanism-detail") and field is not None:
            # the mechanism's detail view in its own field where the drawing
            # leaves room, nearest the knot it details: the sheet's middle,
            # beside the drawing, is the plans'
            knot = (
                _detail_place(sketches[name], extent(sketches["mechanism"]), placed["mechanism"])
                if by_knot
                else None
            )
            try:
                placed[name] = layout.place(
                    name, ext.width, ext.height, corner="bottom-left", within=field, near=knot
                )
                continue
            except LayoutError:
                pass  # no room there: beside the drawing, as a plan's detail view
        if name.startswith("mechanism-position") and field is not None:
            # a plan position's view in the mechanism's field, under its drawing
            try:
                placed[name] = layout.place(name, ext.width, ext.height, within=field)
                continue
            except LayoutError:
                pass  # no room there: where the plans go
        placed[name] = layout.place(
            name,
            ext.width,
            ext.height,
            kind=kind,  # type: ignore[arg-type]
            corner=corner,  # type: ignore[arg-type]
            within=within,
            near=near,
        )
    return layout, placed, field


def _detail_place(view: Sketch, drawn: Rect, placed: Rect) -> Rect | None:
    """Where on the sheet (a point, as a Rect) what the detail `view` details
    stands, its drawing `drawn` (its extent) placed at `placed`."""
    if view.detail_of is None:
        return None
    x, y = view.detail_of
    return Rect(x + placed.x - drawn.x, y + placed.y - drawn.y, 0.0, 0.0)


def _bare_mechanism(solution: Solution, mu_l: float, look: Any) -> Sketch:
    """A stand-in for the mechanism's drawing that is no larger than it: the
    box of the links' lines in every position (the drawing adds lettering,
    blocks, arcs round them)."""
    pts = solution.sweep.points
    names = {
        p
        for link in solution.mechanism.links.values()
        if len([q for q in link.points if q in pts]) > 1
        for p in link.points
        if p in pts
    }
    xy = np.concatenate([np.asarray(pts[p], dtype=float).reshape(-1, 2) for p in names or pts])
    xy = xy[np.all(np.isfinite(xy), axis=1)] / mu_l
    sk = Sketch(look)
    if len(xy):
        (x0, y0), (x1, y1) = xy.min(axis=0), xy.max(axis=0)
        sk.polygon([(x0, y0), (x1, y0), (x1, y1), (x0, y1)], "thin")
    return sk


def _may_fit(
    page: Page,
    sketches: Mapping[str, Sketch],
    order: Sequence[str],
    arrangements: Sequence[tuple[float | None, str]],
    extents: _Extents | None = None,
) -> tuple[bool, bool]:
    """Whether the sheet may fit with the stand-in mechanism in some
    arrangement _try_layout would try (the real drawing is at least as large,
    so where the stand-in fails the real one fails too), and whether the
    stand-in found its field in one that failed."""
    in_field = False
    for gap, (tables_width, corner) in itertools.product((8.0, 5.0), arrangements):
        try:
            _try_layout(page, sketches, order, gap, True, tables_width, corner, extents)
        except LayoutError as err:
            in_field = in_field or not str(err).startswith("mechanism:")
            continue
        return True, in_field
    return False, in_field


def _past_field(
    page: Page,
    sketches: Mapping[str, Sketch],
    order: Sequence[str],
    arrangements: Sequence[tuple[float | None, str]],
    extents: _Extents | None = None,
) -> bool:
    """Whether the stand-in mechanism is larger than its field in every
    arrangement _try_layout would try. What is placed before the mechanism is
    the same for the stand-in and the drawing, so is its field: where the
    stand-in is larger than the field, the drawing (no smaller) is too, and
    _try_layout fails at the mechanism for both."""
    for gap, (tables_width, corner) in itertools.product((8.0, 5.0), arrangements):
        try:
            _try_layout(page, sketches, order, gap, True, tables_width, corner, extents)
        except LayoutError as err:
            if str(err).startswith("mechanism") and "larger than its field" in str(err):
                continue
        return False
    return True


# --- the diagrams take the room that is left ------------------------------------------

_STACK_GAP = 6.0  # _stack's gap between the S, V and a diagrams
# where the field is left too empty, S may be drawn up to this many times
# larger than the mechanism (μ_S = μ_l/FINER_S): a short stroke then reads
FINER_S = 10.0
# where even that leaves the field too empty, the diagrams' scales from the
# whole series of seed 000 §2.2 (1, 1.25, 2, 2.5, 4, 5, 8 × 10^k; S is no
# drawing of the mechanism, so not only GOST 2.302's ratios), their poles
# also at 32 and 64 mm (2^k mm: with μ_t of mantissa 1.25 or 8 they keep μ_V
# and μ_a series values where the round poles cannot)
_FILL_S_MANTISSAS = ("1", "1.25", "2", "2.5", "4", "5", "8")
_FILL_POLES_MM = (*ROUND_POLE_DISTANCES_MM, 32.0, 64.0)


def _diagram_rooms(layout: SheetLayout, rect: Rect, gap: float, raised: bool = False) -> list[Rect]:
    """The free rectangles the diagrams' column at `rect` may be redrawn in:
    on its bottom edge, from the region's left edge or `gap` right of an
    element (the mechanism) to the region's right edge or `gap` short of one
    (the title block, a plan, a table), up to `gap` under the lowest element
    above that span; largest first. Each spans the column's width at least
    and three quarters of its height (a wider, lower room where plans come
    down beside the column). With `raised` (_grown_diagrams' last pass,
    `fill`: a field left too empty) also
    those standing `gap` above an element beside the column's foot (the
    title block): a column lifted clear of it may run on to the right."""
    region = layout.region
    others = [e.bounds for e in layout.elements if e.name != "diagrams"]
    bottoms = {rect.bottom}
    if raised:
        bottoms |= {b.top + gap for b in others if rect.bottom < b.top + gap < rect.top}
    lefts = {region.left, *(b.right + gap for b in others if b.right + gap <= rect.left + 1e-6)}
    rights = {region.right, *(b.left - gap for b in others if b.left - gap >= rect.right - 1e-6)}
    rooms = []
    for bottom, left, right in itertools.product(bottoms, lefts, rights):
        if right - left < rect.width - 1e-6:
            continue
        top = min(
            [region.top]
            + [
                b.bottom - gap
                for b in others
                if b.left < right + gap - 1e-6 and b.right > left - gap + 1e-6 and b.top > bottom
            ]
        )
        if top >= bottom + 0.75 * rect.height - 1e-6:
            rooms.append(Rect.from_bounds(left, bottom, right, top))
    return sorted(rooms, key=lambda r: -r.width * r.height)


def _grown_scales(
    s: np.ndarray,
    n1: float,
    L: float,
    mu_S_range: tuple[float, float],
    budget: float,
    longest_pole: float,
    fill: bool = False,
) -> tuple[float, float, float] | None:
    """μ_S, OH1, OH2 for diagrams over an `L` mm time axis sharing `budget` mm
    of height: μ_S the finest series value of `mu_S_range` (from μ_l, seed 003
    §1.7: μ_S = μ_l where it can) that draws S within a third of it (a fixed
    μ_S: within three fifths); V and a each within half of what S leaves, the
    poles whole millimetres of ROUND_POLE_DISTANCES_MM, at most
    `longest_pole`, making μ_V and μ_a series values, of those the tallest V
    and a (a long axis flattens them: the pole lengthens instead). The
    heights scale as 1/μ_S, OH1/μ_S and OH1·OH2/μ_S (the construction is
    linear in them); None where no choice keeps μ_V and μ_a series values.
    With `fill` (a field left too empty), μ_S from the whole series and the
    poles from _FILL_POLES_MM, and of every μ_S that draws S within its third
    the one whose three diagrams stand tallest (not the finest: the field
    wants the room covered, and a coarser S leaves V and a more of it)."""
    ref = graphical_differentiation(s, n1=n1, mu_S=mu_S_range[0], L=L, H1=40.0, H2=40.0)
    h_s, h_v, h_a = ref.heights_mm
    poles = [H for H in (_FILL_POLES_MM if fill else ROUND_POLE_DISTANCES_MM) if H <= longest_pole]
    lo, hi = mu_S_range
    share_s = budget / 3.0 if hi > lo else budget * 0.6
    # from μ_l/FINER_S up to 10·μ_l where the whole series is tried (7 a decade)
    mantissas, tried = (_FILL_S_MANTISSAS, 14) if fill else (LENGTH_MANTISSA_TEXT, 8)
    tallest: tuple[float, tuple[float, float, float]] | None = None
    for mu_S in itertools.islice(series(lo * (1 - 1e-9), hi, mantissas), tried):
        k = lo / mu_S
        if h_s * k > share_s * (1 + 1e-9):
            continue
        cap = (budget - h_s * k) / 2.0
        best: tuple[tuple[float, float], tuple[float, float, float]] | None = None
        for H1 in poles:
            tall_v = h_v * k * H1 / 40.0
            if tall_v > cap * (1 + 1e-9) or not is_standard(ref.mu_V * 40.0 / (k * H1)):
                continue
            for H2 in poles:
                tall_a = h_a * k * H1 * H2 / 1600.0
                mu_a = ref.mu_a * 1600.0 / (k * H1 * H2)
                if tall_a > cap * (1 + 1e-9) or not is_standard(mu_a):
                    continue
                key = (min(tall_v, tall_a), tall_v + tall_a)
                if best is None or key > best[0]:
                    best = (key, (mu_S, H1, H2))
        if best is not None and not fill:
            return best[1]
        if best is not None:
            tall = h_s * k + best[0][1]
            if tallest is None or tall > tallest[0]:
                tallest = (tall, best[1])
    return None if tallest is None else tallest[1]


def _grown_diagrams(
    solution: Solution,
    look: Any,
    lang: Language,
    layout: SheetLayout,
    sketches: Mapping[str, Sketch],
    placed: Mapping[str, Rect],
    drawn: KinematicDiagrams,
    mu_l: float,
    gap: float,
    extents: _Extents,
    finer: bool = False,
    fill: bool = False,
) -> tuple[Sketch, Rect, KinematicDiagrams] | None:
    """The diagrams' column redrawn into the room left beside and above it
    (_diagram_rooms), or None where it cannot grow. The rule: one turn of
    the crank on the time axis at the finest series μ_t whose axis (with the
    pole and the lettering) fits the room's width; each diagram at most a
    third of the room's height (less the lettering), at series μ_S, μ_V, μ_a
    (_grown_scales); of the rooms, the one the column then covers most of.
    μ_S is the sheet's μ_l (seed 003 §1.7: S read off the drawing of the
    mechanism) or the series step above that S needs (the line under S then
    says why, or names it the calculation's scale where it is that). The
    construction is the Solution's on the same grid (its V and a in SI do not
    depend on the scales: the 5 % check stands). With `finer` (a field the
    rule above leaves more than EMPTY_MAX empty), μ_S may also be finer than
    μ_l, down to μ_l/FINER_S: S drawn larger than the mechanism, so that a
    short stroke reads (the line under S says so). With `fill` (a field that
    too leaves more than EMPTY_MAX empty) as `finer`, the scales from the
    whole series (_grown_scales), and the rooms lifted clear of the title
    block too (_diagram_rooms' `raised`)."""
    if "diagrams" not in placed:
        return None
    rect = placed["diagrams"]
    base = extents(sketches["diagrams"])
    least = 1.15 * _drawn_area(sketches["diagrams"])  # worth redrawing: 15 % more covered
    s = np.asarray(drawn.s, dtype=float)
    T = 60.0 / drawn.n1
    over_w = base.width - drawn.L - max(drawn.H1, drawn.H2)
    over_h = base.height - sum(drawn.heights_mm)
    mu_S_range = (mu_l / FINER_S if finer or fill else mu_l, mu_l * 1e4)
    best: tuple[float, Sketch, Rect, KinematicDiagrams] | None = None
    drawn_parts: dict[tuple[Any, ...], Sketch] = {}
    for room in _diagram_rooms(layout, rect, gap, fill)[:3]:
        if room.width * room.height < max(least, best[0] if best else 0.0):
            continue
        budget = room.height - over_h  # the three diagrams' heights share it
        if room.height >= rect.height:  # not lower than the Solution's, where it can
            budget = max(budget, 3.0 * DIAGRAM_HEIGHT_MM)
        tried = 0
        for mu_t in series(T / max(room.width - over_w - 20.0, drawn.L), T / drawn.L):
            L = T / mu_t
            if tried >= 4 or (L <= drawn.L * (1 + 1e-9) and budget <= sum(drawn.heights_mm)):
                break
            for share in (1.0, 0.85, 0.7, 0.55):
                longest = room.width - over_w - L - 8.0  # the lettering's widths vary
                chosen = _grown_scales(s, drawn.n1, L, mu_S_range, budget * share, longest, fill)
                if chosen is None:
                    continue
                mu_S, H1, H2 = chosen
                c = graphical_differentiation(s, n1=drawn.n1, mu_S=mu_S, L=L, H1=H1, H2=H2)
                if sum(c.heights_mm) + over_h > room.height:
                    continue
                tried += 1
                parts = []
                for which, key in (
                    ("s", ("s", L, mu_S)),
                    ("v", ("v", L, mu_S, H1)),
                    ("a", ("a", L, mu_S, H1, H2)),
                ):
                    if key not in drawn_parts:  # the rooms try the same axes again
                        drawn_parts[key] = _diagram_sketch(
                            solution, c, which, look, lang, mu_l, fill
                        )
                    parts.append(drawn_parts[key])
                grown = _stack(parts, look, _STACK_GAP)
                ext = extents(grown)
                covered = _drawn_area(grown)
                if ext.width > room.width + 1e-6:
                    break  # too wide: a shorter axis
                if ext.height > room.height + 1e-6:
                    continue  # too tall: lower diagrams
                if covered >= max(least, best[0] if best else 0.0):
                    best = (covered, grown, Rect(room.left, room.bottom, ext.width, ext.height), c)
                break  # the tallest that fits this axis
            if best is not None and best[0] >= room.width * room.height * 0.8:
                break
    return None if best is None else best[1:]


def _drawn_area(sketch: Sketch) -> float:
    """The paper a drawing covers as the sheet linter counts it (field-filled):
    the union of its groups' boxes, so a flat curve on a long axis covers
    little, however long the column it stands in."""
    boxes = [shapely.box(*b) for b in sketch.group_extents()]
    return float(shapely.union_all(boxes).area) if boxes else 0.0


def _with_diagrams(layout: SheetLayout, page: Page, gap: float, rect: Rect) -> SheetLayout:
    """`layout` with the diagrams' footprint at `rect`."""
    out = SheetLayout(page, gap=gap)
    for e in layout.elements:
        if e.name == "title-block":
            continue
        out.register(e.name, rect if e.name == "diagrams" else e.footprint, e.kind)
    return out


def _mechanism_options(
    sketches: Mapping[str, Sketch],
    plain: Sketch,
    detailed: Sequence[tuple[Sketch, list[Sketch]]],
) -> Iterator[dict[str, Sketch]]:
    """The sheet's drawings with the mechanism lettered: with its detail
    views ("mechanism-detail", `mechanism_detail_options`) where it has
    them, each choice in turn (those lettering best first: the sheet takes
    the first whose views find room), then (where the sheet has room for
    none) as drawn plain."""
    for sk, views in detailed:
        out = {**sketches, "mechanism": sk}
        for k, view in enumerate(views):
            out["mechanism-detail" + (f"-{k + 1}" if k else "")] = view
        yield out
    yield {**sketches, "mechanism": plain}


def _detail_letters(sketches: Mapping[str, Sketch]) -> set[str]:
    """The letters the detail views among `sketches` take (their titles, "A (4:1)")."""
    return {
        c.content[0]
        for name, sk in sketches.items()
        if "-detail" in name
        for c in sk.calls
        if isinstance(c, Text) and re.match(r"[A-Z] \(", c.content)
    }


def compose_sheet1(
    solution: Solution, backend: Backend, lang: Language = "en", *, page: Page | None = None
) -> Sheet1:
    """Draw sheet 1 of `solution` on `backend`; returns the layout and scales used.

    The layout rule, in order: the mechanism at the series value μ_l (1, 2,
    2.5, 4, 5 × 10^k) that draws it in all its positions largest within its
    field (mechanism_field: top left, clear of the diagrams, placed bottom
    left or bottom right, and of the tables, top right); the plans at the
    guide's size (_plan_scales: each one's longest vector from the pole 100 …
    200 mm), up to two series steps coarser where the sheet needs it, a plan
    then drawn under 100 mm saying so; the diagrams at the Solution's μ_S (the
    line under S says why where μ_S ≠ μ_l), grown into the room left
    (_grown_diagrams), and the tables. Of the arrangements that fit, the
    first whose field the linter's field-filled rule finds filled
    (laid_out_empty_share ≤ EMPTY_MAX), where need be with the sheet laid out again
    round the grown diagrams (their column kept as high as it was), the
    diagrams' scales tried again (S finer than μ_l, then from the whole
    series) only where no arrangement fills it; else the one leaving least
    empty. Where nothing fits, _fallback draws the
    mechanism and the plans smaller still.
    """
    page = page if page is not None else Page.of("A1")
    check_language(lang)
    look = backend.look
    cache: dict[tuple[str, float], Any] = {}
    extents = _Extents()
    region = SheetLayout(page).region
    width_m, height_m = _geometric_extent(solution)
    # the largest the drawing could be: the region's width or height
    start = max(width_m / region.width, height_m / region.height, 1e-9)
    candidates = list(series(start * (1 - 1e-9), start * 1e4, LENGTH_MANTISSA_TEXT))[:16]

    def apart(mu_l: float) -> Views:
        # the links' ω/ε arcs in the plan positions' views where the drawing
        # has no room for them (measured once a scale: asked at every trial)
        if ("apart", mu_l) not in cache:
            cache[("apart", mu_l)] = "apart" if _arcs_crowd(solution, mu_l) else None
        return cast(Views, cache[("apart", mu_l)])

    def mechanism(mu_l: float) -> Sketch:
        if ("mechanism", mu_l) not in cache:
            cache[("mechanism", mu_l)] = sketch_mechanism(
                solution, mu_l, look, lang, views=apart(mu_l)
            )
        return cast(Sketch, cache[("mechanism", mu_l)])

    def position_views(mu_v: float, lettered: bool = True) -> dict[str, Sketch]:
        key = ("position views" if lettered else "unlettered views", mu_v)
        if key not in cache:
            cache[key] = {
                _view_name(i): sketch_mechanism(solution, mu_v, look, lang, views=i)
                if lettered
                else _unlettered_view(solution, mu_v, look, lang, i)
                for i in solution.plan_positions
            }
        return cast("dict[str, Sketch]", cache[key])

    def view_options(
        mu_l: float,
        sketches: Mapping[str, Sketch],
        arrangements: Sequence[tuple[float | None, str]],
    ) -> Iterator[dict[str, Sketch]]:
        # the plan positions' views where the drawing cannot hold their
        # links' arcs (none else), the largest first whose stand-ins fit the sheet
        if not apart(mu_l):
            yield {}
            return
        for mu_v in _view_scales(solution, mu_l):
            stand = {**sketches, **position_views(mu_v, lettered=False)}
            order = _order(stand, True)
            if _may_fit(page, stand, order, arrangements, extents)[0]:
                yield position_views(mu_v)

    used = {n[:1].upper() for n in solution.mechanism.point_owners}

    def detailed(mu_l: float, sketches: Mapping[str, Sketch]) -> list[tuple[Sketch, list[Sketch]]]:
        # lettered by the first letter that names no point and no plan's detail
        taken = _detail_letters(sketches)
        letters = "".join(x for x in DETAIL_LETTERS if x not in used and x not in taken)
        if not letters:
            return []
        key = ("mechanism-details " + letters, mu_l)
        if key not in cache:
            cache[key] = mechanism_detail_options(
                solution, mu_l, look, lang, letters, mechanism(mu_l), apart(mu_l)
            )
        return cast("list[tuple[Sketch, list[Sketch]]]", cache[key])

    def unlettered(mu_l: float) -> Sketch:
        if ("unlettered", mu_l) not in cache:
            cache[("unlettered", mu_l)] = _unlettered_mechanism(solution, mu_l, look, lang)
        return cast(Sketch, cache[("unlettered", mu_l)])

    last: Exception | None = None
    fitted = 0  # candidates whose mechanism fitted its field but whose sheet did not
    for mu_l in candidates:
        if width_m / mu_l > region.width or height_m / mu_l > region.height:
            continue
        placed_field = False
        for shrink, sketches, scales, drawn in _with_details(solution, look, lang, mu_l, cache):
            sketches["mechanism"] = _bare_mechanism(solution, mu_l, look)
            order = _order(sketches, True)
            tables = [extents(sketches[n]).width for n in order if n.startswith("table")]
            # the tables in a row across the top right, or in a block two rows high
            arrangements = [
                (width, corner)
                for corner in ("bottom-left", "bottom-right")
                for width in (None, max(max(tables), sum(tables) / 2.0 + 8.0))
            ]
            may, in_field = _may_fit(page, sketches, order, arrangements, extents)
            if not may:  # not even the links alone fit: no need to letter them
                placed_field = placed_field or in_field
                if not in_field:
                    break  # its field is set before the plans are placed: no shrink helps
                continue
            # the lines and captions alone larger than the mechanism's field in
            # every arrangement: so is the lettered drawing (no need to letter it)
            sketches["mechanism"] = unlettered(mu_l)
            if _past_field(page, sketches, order, arrangements, extents):
                break
            in_field = False
            # with the mechanism's detail views where its names crowd, then without
            base = sketches
            options = (
                option
                for views in view_options(mu_l, base, arrangements)
                for option in _mechanism_options(
                    {**base, **views}, mechanism(mu_l), detailed(mu_l, base)
                )
            )
            for sketches in options:
                order = _order(sketches, True)
                best: tuple[float, dict[str, Sketch], dict[str, Rect], Sheet1] | None = None
                # every arrangement with μ_S from μ_l; then, where none fills the
                # field, again with S drawn finer than μ_l, and again with the
                # diagrams' scales from the whole series (_grown_diagrams)
                passes = ((False, False), (True, False), (False, True))
                trials = itertools.product(passes, (8.0, 5.0), arrangements)
                for (finer, fill), gap, (tables_width, corner) in trials:
                    try:
                        layout, placed, field = _try_layout(
                            page, sketches, order, gap, True, tables_width, corner, extents
                        )
                    except LayoutError as err:
                        last = err
                        in_field = in_field or not str(err).startswith("mechanism:")
                        placed_field = placed_field or in_field
                        continue
                    done, done_drawn, done_scales = sketches, drawn, {**scales, "mu_l": mu_l}
                    for again in (False, True):
                        if again:
                            # the sheet laid out again round the grown diagrams, their
                            # column kept as high as it was: the plans then stay out
                            # of the room above it, which they may grow into
                            column, wide = extents(sketches["diagrams"]), extents(done["diagrams"])
                            keep = {"diagrams": (wide.width, max(wide.height, column.height))}
                            try:
                                layout, placed, field = _try_layout(
                                    page,
                                    done,
                                    order,
                                    gap,
                                    True,
                                    tables_width,
                                    corner,
                                    extents,
                                    keep,
                                )
                            except LayoutError:
                                break
                        # grown from the calculation's column (every time axis tried again)
                        grown = _grown_diagrams(
                            solution,
                            look,
                            lang,
                            layout,
                            sketches,
                            placed,
                            drawn,
                            mu_l,
                            gap,
                            extents,
                            finer,
                            fill,
                        )
                        if grown is not None:  # the diagrams take the room that is left
                            done, done_drawn = {**done, "diagrams": grown[0]}, grown[2]
                            placed = {**placed, "diagrams": grown[1]}
                            layout = _with_diagrams(layout, page, gap, grown[1])
                            done_scales = {**done_scales, **_diagram_scales(done_drawn)}
                        empty = laid_out_empty_share(page, done, placed, extents)
                        if best is None or empty < best[0] - 1e-9:
                            result = Sheet1(
                                layout, done_scales, shrink=shrink, field=field, diagrams=done_drawn
                            )
                            best = (empty, done, placed, result)
                        if empty <= EMPTY_MAX or grown is None:
                            break
                    if best is not None and best[0] <= EMPTY_MAX:
                        break  # the first arrangement that fills the field
                if best is not None:
                    # of the arrangements that fit, the first to fill the field
                    # (the linter's field-filled rule), else the one filling most
                    _, done, placed, result = best
                    return _draw(
                        solution, backend, page, lang, done, order, placed, result, extents
                    )
            if not in_field:
                # the mechanism larger than its field in every arrangement: the
                # field is set by the diagrams and the tables, placed before it
                # (_order), which no shrink of the plans changes
                break
        fitted += placed_field
        if fitted > 3:
            break
    return _fallback(solution, backend, page, lang, cache, last, extents)


def _draw(
    solution: Solution,
    backend: Backend,
    page: Page,
    lang: Language,
    sketches: Mapping[str, Sketch],
    order: Sequence[str],
    placed: Mapping[str, Rect],
    result: Sheet1,
    extents: _Extents,
) -> Sheet1:
    if "mechanism" in sketches:
        sketches = {**sketches, "mechanism": _far_names_led(sketches["mechanism"], lang, extents)}
    for name in order:
        ext, rect = extents(sketches[name]), placed[name]
        dx, dy = rect.x - ext.x, rect.y - ext.y
        sketches[name].replay(backend, dx, dy)
        result.origins[name] = (dx, dy)
        result.placed[name] = rect
    result.positions = tuple(solution.plan_positions)
    draw_page(backend, page, title_fields(solution, result.scales["mu_l"], lang, sheet=1), lang)
    return result


def _far_names_led(sk: Sketch, lang: Language, extents: _Extents) -> Sketch:
    """The laid-out mechanism with the names that stand far on it written
    again one by one among all else written there, then led across main
    lines where none is free near (`far_names_again`, as sheet 2 does last):
    a copy, kept in the drawing's box. A name walled in by the lines of the
    positions where no detail view was taken (held-out gen 386's K); the
    drawing itself where no name stands far."""
    out = Sketch(sk.look)
    out.calls = list(sk.calls)
    if far_names_again(out, lang, _MECHANISM_AGAIN, lambda m: m, extents(sk).contains):
        out.label_counts = sk.label_counts
        return out
    return sk


def _fallback(
    solution: Solution,
    backend: Backend,
    page: Page,
    lang: Language,
    cache: dict[tuple[str, float], Any],
    last: Exception | None,
    extents: _Extents,
) -> Sheet1:
    """A crowded sheet: the acceleration plans and the mechanism smaller, step
    by step from the file's μ_l, the diagrams apart if need be."""
    look = backend.look
    attempts = [
        (shrink, stacked, gap)
        for shrink in range(5)
        for stacked in (True, False)
        for gap in (8.0, 5.0)
    ]
    for shrink, stacked, gap in attempts:
        mu_l = length_scale_step(float(solution.mu_l), shrink)
        sketches, scales, drawn = _sketch_all(
            solution, look, lang, _plan_scales(solution, shrink), mu_l, stacked, cache
        )
        sketches["mechanism"] = _bare_mechanism(solution, mu_l, look)
        order = _order(sketches, stacked)
        try:  # the links alone first: no need to letter a drawing that cannot fit
            _try_layout(page, sketches, order, gap, False, extents=extents)
        except LayoutError as err:
            last = err
            continue
        if ("mechanism", mu_l) not in cache:
            cache[("mechanism", mu_l)] = sketch_mechanism(solution, mu_l, look, lang)
        sketches["mechanism"] = cache[("mechanism", mu_l)]
        try:
            layout, placed, _ = _try_layout(page, sketches, order, gap, False, extents=extents)
        except LayoutError as err:
            last = err
            continue
        scales["mu_l"] = mu_l
        return _draw(
            solution,
            backend,
            page,
            lang,
            sketches,
            order,
            placed,
            Sheet1(layout, scales, shrink=shrink, diagrams=drawn),
            extents,
        )
    raise LayoutError(
        f"{shown(solution.mechanism.path)}: sheet 1 does not fit on {page.name or 'the page'} "
        f"even with the mechanism and the acceleration plans 4 scale steps smaller and the "
        f"diagrams apart: {last}\n"
        "  fix: study fewer plan positions (study.plans) or a mechanism of fewer groups"
    )
