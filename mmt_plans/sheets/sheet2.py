"""Sheet 2: force (kinetostatic) solution (seed 003, Sheet 2 §2.1–2.10, Appendix B).

At the force position only: the mechanism with every load (G, F_IN shifted by
h, F_PR, F_bal), each Assur group drawn apart to μ_l with its loads, the
reactions of its outer pairs (R^n, R^t dashed) and the arms of the moment
equation that gives R^t, its force polygon to μF (the inner reaction closing
the polygon of one link), the driving link with F_bal and its polygon,
Zhukovsky's lever (the velocity plan turned by 90° with the forces at the
images of their points and their arms about the pole), and the tables of
loads, reactions, the lever's moments and the balancing force by both methods.

Forces on the mechanism, the groups and the lever are drawn to direction, not
to scale (their lengths grow with the square root of the magnitude); the
force polygons are to scale.

Every drawing has its own scale from the standard series: first the finest
at which all of them fit, then each enlarged a step at a time (the mechanism
with its groups, the lever, each group, the polygons within their 150 …
300 mm guide) while the sheet still packs and the lettering still finds room.
"""

from __future__ import annotations

import dataclasses
import functools
import math
import random
import re
from collections.abc import Callable, Iterable, Iterator, Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any, Literal, ParamSpec, TypeVar

import numpy as np
import shapely

from ..drawing.detail import (
    ARM_NAMED_MM,
    DETAIL_LETTERS,
    DETAIL_MM,
    DETAIL_RATIOS,
    NAME_SHARE,
    Detail,
    Name,
    choose_details,
    clipped,
    cut_to_disc,
    name_area,
    rim_anchors,
    roomy_ratio,
)
from ..drawing.labels import NEAR_MM, LabelCounts, Labels, arc_line
from ..drawing.layout import LayoutError, SheetLayout, pack
from ..drawing.markup import equation_markup as _equation_markup
from ..drawing.markup import force_markup, image_markup, point_markup
from ..drawing.page import Page, Rect, draw_page
from ..drawing.pose import Block, Guide, Pose, draw_poses
from ..drawing.sketch import PAD, Sketch
from ..drawing.symbols import sense_arc, unit_vector
from ..drawing.table import TABLE_PART_MM, table_sketch
from ..errors import shown
from ..forces import ForceAnalysis, ForcePolygon, GroupForces
from ..forces.state import PositionState
from ..i18n import Language, catalogue, check_language
from ..model import FRAME
from ..render.backend import Backend
from ..render.look import LineType
from ..scales import FORCE_PLAN, VELOCITY_PLAN, scale_for, scale_label, series
from ..solution import Solution
from .common import (
    EMPTY_MAX,
    further_groups,
    laid_out_empty_share,
    length_scale_step,
    scale_step,
    title_fields,
)
from .crowd import crowded, crowded_ends, crowded_names, far_names_again, written_again
from .scales_record import Sheet2Scales

__all__ = ["Sheet2", "compose_sheet2", "force_markup", "guide_side", "GROUPS"]

_P = ParamSpec("_P")
_R = TypeVar("_R")

_TEXT = 3.5
_TITLE = 5.0
_PAD = 2.0
_ARROW = dict(head_length=3.5, head_width=1.2)
# a force polygon's side shorter than this (mm: its arrowhead) whose name
# finds no place by it is drawn as a plain line, named under the polygon
_UNNAMED_BELOW = _ARROW["head_length"]
_FAR_MM = 40.0  # a reaction applied farther than this from its group's points moves to them
# where along an arm h its name is tried, in turn: the middle first, then out to
# both ends (the arms of a lever all leave the pole, where their names crowd)
_ARM_ALONG = (0.5, 0.65, 0.35, 0.8, 0.2, 0.9, 0.1, 0.75, 0.25, 0.95, 0.05, 0.55, 0.45)
# how every drawing of sheet 2 letters: a word space between labels, leaders;
# the fine grid of places only for the labels that found no place near at first
# (all of them on it wrote five_dyads' 'Fin4' and task09_v5's 's1, k1' on a
# line), the fine rings of leaders before a label stands far
_LABELLING: dict[str, Any] = dict(
    spacing=None, leaders=True, fine=False, fine_far=True, wide_leaders=True
)
# the force polygons and the groups: a name that stood far in any order on the
# fine grid in every order after (Labels.fine_kept): the names of a polygon's
# short sides along one column go far in turn (task09_v2's G5 and F_in5)
_FORCE_LABELLING: dict[str, Any] = dict(_LABELLING, fine_kept=True)
# the loaded mechanism and its detail views lettered again on the laid-out
# sheet (`_Composer.given_room`): a name that finds no place near nor a
# leader at _TEXT is tried once more at GOST's 2.5 mm before it stands far,
# as on sheet 1's mechanism (the forces' names at a slider's block, where G,
# F_in and F_PR stand side by side: gen 3's 'Fin9' stood 15.7 mm off). Not
# while the sheet is laid out: its scales and detail views are chosen on
# names at _TEXT (five_dyads: lettered so, the mechanism went a step coarser)
_LOADED_AGAIN: dict[str, Any] = dict(_LABELLING, smaller=2.5)
# the lever and its detail views lettered so again on the laid-out sheet
# (`_Composer.given_room`): the names walled in round p by the lines that
# leave it (gen 30 uk, view A at 40:1: 'k10' and 'G9' go between the images'
# lines 3 mm apart at 2.5 mm, 14 mm off at 3.5 mm)
_LEVER_AGAIN: dict[str, Any] = dict(_LABELLING, smaller=2.5)
# the groups and the driving link lettered so again on the laid-out sheet: a
# short arm's name in a knot of forces (gen 240's group 2-3 at 1:100, h'6 of a
# 2.8 mm arm 11.7 mm off at 3.5 mm, beside it at 2.5 mm)
_FORCE_AGAIN: dict[str, Any] = dict(_FORCE_LABELLING, smaller=2.5)
# a name that stands far on the laid-out sheet, written again alone (`_far_names_again`),
# led on the shortest line to a free place where no place near and no ring's leader is
_FAR_AGAIN: dict[str, Any] = dict(_LABELLING, fine=True, smaller=2.5, shortest_leaders=True)
# how the lever is lettered so: in the order that letters it best whatever box
# that takes, or in those that keep its box (where the sheet has no more room)
Again = Literal["grow", "box"]
# how many times a drawing's labels are written again, those that stood far
# in the last order first (Labels.write_later); an order kept only where it
# letters the drawing within the box the first order did (its leaders no
# further out), so the drawing's size is the first order's: chain_25_links's
# sheet 2 fits at the coarsest scales as with one order
_RETRY_ORDERS = 6
# the orders the lever at its textbook scale is lettered in to find where its
# names crowd (the detail views chosen round them): past the third, an order
# seldom moves a crowd (eleven links: 0.15 s of the lever's 0.36 s, the same
# views; with two, gen 212's crowd of one name the third order clears)
_CROWD_ORDERS = 3
# where along a force's arrow its name is tried beside the shaft (after round
# its head), in turn: out to near both ends, where other arrows leave room
_SHAFT_ALONG = (0.5, 0.35, 0.65, 0.2, 0.8, 0.1)
# the side a joint's name and a mass centre's are tried on first
_PIN_SIDE = np.array([-0.6, 0.8])
_S_SIDE = np.array([-0.8, -0.6])
# a couple's arc: 230° of a circle, started at the first of these angles that
# leaves room for its label and for the name of the point it turns round
_ARC_SPAN = 230.0
_ARC_STARTS = tuple(20.0 + 45.0 * k for k in range(8))

GROUPS = (
    "force-mechanism",
    "driving-link",
    "force-polygon-1",
    "zhukovsky-lever",
    "table-loads",
    "table-reactions",
    "table-lever",
    "table-balancing",
)


@dataclass
class Sheet2:
    """What compose_sheet2 drew: the force solution, layout, scales, placements."""

    forces: ForceAnalysis
    layout: SheetLayout
    scales: dict[str, float] = field(default_factory=dict)
    origins: dict[str, tuple[float, float]] = field(default_factory=dict)
    placed: dict[str, Rect] = field(default_factory=dict)
    arms: dict[str, list[tuple[str, float]]] = field(default_factory=dict)  # lever: label, h mm
    # the most series steps any drawing is coarser than its textbook scale
    # (negative: every drawing finer, enlarged to fill the sheet)
    shrink: int = 0
    # the lever's detail views (drawings "zhukovsky-lever-detail", "…-detail-2")
    details: tuple[LeverDetail, ...] = ()
    # the loaded mechanism's (drawings "force-mechanism-detail", "…-detail-2")
    mechanism_details: tuple[Detail, ...] = ()
    # the groups drawn here (None: every one; none where they continue on further sheets)
    groups: tuple[str, ...] | None = None

    @property
    def record(self) -> Sheet2Scales:
        """The scales drawn, as a typed record (scales_record.py)."""
        fa = self.forces
        names = [g.name for g in fa.groups] if self.groups is None else list(self.groups)
        if "mu_V" not in self.scales:  # a further sheet: its groups alone
            return Sheet2Scales.further(self.scales, names)
        return Sheet2Scales.of(self.scales, names, fa.driving_link.link)


def _words(lang: Language):
    return catalogue(lang).words("sheet2")


# --- lettering ------------------------------------------------------------------------

# --- primitives -------------------------------------------------------------------------


def _c(v: Any) -> complex:
    return v if isinstance(v, complex) else complex(float(v[0]), float(v[1]))


def _xy(z: complex) -> np.ndarray:
    return np.array([z.real, z.imag])


def _num(x: float, digits: int = 4) -> str:
    """A table value to `digits` significant figures, never in exponent form: 12970, 0.0523."""
    x = float(x)
    if not math.isfinite(x):
        return "—"
    if abs(x) < 1e-9:
        return "0"
    decimals = max(0, digits - 1 - math.floor(math.log10(abs(x))))
    return f"{round(x, decimals):.{decimals}f}"


def _coincident(s1: np.ndarray, e1: np.ndarray, s2: Any, e2: Any, tol: float = 0.8) -> bool:
    """True when the arrows s1→e1 and s2→e2 lie on one line and share more
    than half a millimetre of it, either sense: drawn on top of each other."""
    d1, d2 = np.asarray(e1, float) - s1, np.asarray(e2, float) - np.asarray(s2, float)
    l1, l2 = float(np.hypot(*d1)), float(np.hypot(*d2))
    if l1 < 1e-9 or l2 < 1e-9:
        return False
    u = d1 / l1
    if abs(float(np.dot(u, d2 / l2))) < 0.999:
        return False
    r = np.asarray(s2, float) - s1
    if abs(float(u[0] * r[1] - u[1] * r[0])) > tol:
        return False
    a, b = sorted((float(np.dot(r, u)), float(np.dot(r + d2, u))))
    return min(l1, b) - max(0.0, a) > 0.5


# a polygon's vector along a line another of its vectors already runs on is
# drawn this far beside it, as the textbook draws collinear forces side by side
_SIDE_BY_SIDE = 1.8  # mm


def _along(s1: np.ndarray, e1: np.ndarray, s2: np.ndarray, e2: np.ndarray) -> bool:
    """True when the arrows s1→e1 and s2→e2 run along each other: coincident
    seen from either (a long arrow a little off parallel), or parallel within
    3° and within 0.8 mm of each other over more than half a millimetre."""
    if _coincident(s1, e1, s2, e2) or _coincident(s2, e2, s1, e1):
        return True
    d1, d2 = e1 - s1, e2 - s2
    l1, l2 = float(np.hypot(*d1)), float(np.hypot(*d2))
    if l1 < 1e-9 or l2 < 1e-9:
        return False
    u = d1 / l1
    if abs(float(u[0] * d2[1] - u[1] * d2[0])) > math.sin(math.radians(3.0)) * l2:
        return False
    # b along a's axis from t0 to t1, h0 … h1 to one side of it
    t0, t1 = float(np.dot(s2 - s1, u)), float(np.dot(e2 - s1, u))
    h0 = float(u[0] * (s2 - s1)[1] - u[1] * (s2 - s1)[0])
    h1 = float(u[0] * (e2 - s1)[1] - u[1] * (e2 - s1)[0])
    if t1 < t0:
        t0, t1, h0, h1 = t1, t0, h1, h0
    lo, hi = max(0.0, t0), min(l1, t1)
    if hi - lo <= 0.5:
        return False
    if abs(h1 - h0) < 1e-12:
        return abs(h0) <= 0.8
    # where |h| ≤ 0.8 on b, as t: h is linear in t
    ta = t0 + (-0.8 - h0) * (t1 - t0) / (h1 - h0)
    tb = t0 + (0.8 - h0) * (t1 - t0) / (h1 - h0)
    near_lo, near_hi = max(lo, min(ta, tb)), min(hi, max(ta, tb))
    return near_hi - near_lo > 0.5


def _beside(
    s: np.ndarray, e: np.ndarray, drawn: Sequence[tuple[np.ndarray, np.ndarray]]
) -> np.ndarray:
    """The sideways shift (mm) that keeps the arrow s→e off every drawn arrow it
    would run along: zero when it overlaps none, else the nearest multiple of
    _SIDE_BY_SIDE perpendicular to it, either side, that overlaps none."""
    d = e - s
    n = np.array([-d[1], d[0]]) / float(np.hypot(*d))
    for k in (0, 1, -1, 2, -2, 3, -3, 4, -4):
        shift = k * _SIDE_BY_SIDE * n
        if not any(_along(s + shift, e + shift, a, b) for a, b in drawn):
            return shift
    return 5 * _SIDE_BY_SIDE * n


def _arrow_length(magnitude: float, largest: float) -> float:
    """Drawn length of a force shown to direction only: 8 … 26 mm by √|F|."""
    if largest <= 0.0:
        return 8.0
    return 8.0 + 18.0 * math.sqrt(max(0.0, magnitude) / largest)


class _Drawing:
    """One drawing of sheet 2 in progress: a sketch, its labels, the state."""

    def __init__(
        self,
        look: Any,
        state: PositionState,
        mu_l: float,
        lang: Language = "en",
        *,
        turn_arcs: bool = True,
        grow: bool = False,
        details: Sequence[Detail] = (),
        detail: Detail | None = None,
        labelling: dict[str, Any] = _LABELLING,
        longer: Mapping[str, float] | None = None,
    ) -> None:
        self.sk = Sketch(look)
        # the forces whose arrows are drawn longer (mm, by their names'
        # markup): a name walled in by its head (`_loaded_view`)
        self.longer = longer or {}
        # `details` (their discs in m): what stands in a disc is drawn but
        # lettered only in its detail view; with `detail`, this drawing is that
        # view (its lines cut at the disc's edge), else the disc is marked
        self.discs = [(np.asarray(d.centre, float) / mu_l, d.radius / mu_l) for d in details]
        self.in_detail = detail is not None
        # with `grow`, its labels written in the order that letters them best
        # whatever box it takes (Labels.write_later): the drawing given the
        # room round it on the laid-out sheet (_Composer.regrown)
        self.grow = grow
        self.labels = Labels(self.sk, _TEXT, **labelling, words=_index_words(lang))
        self.state = state
        self.mu_l = mu_l
        self._arrows: list[tuple[np.ndarray, np.ndarray]] = []  # (start, end) drawn
        # the names written near a point so far (its anchor, markup, side): a
        # couple's arc may wall in those round the point it turns round
        self._named: list[tuple[np.ndarray, str, np.ndarray | None]] = []
        # whether a couple's arc turned for the names inside its circle
        # (`moment`, `enclosed`) starts elsewhere than turned for its own and its point's
        self.turned_for_enclosed = False
        # couples' arcs turned to leave their names room (`moment`); a compact
        # sheet's loaded mechanism keeps them at the first start
        self.turn_arcs = turn_arcs

    def mm(self, P: Any) -> np.ndarray:
        return _xy(_c(P)) / self.mu_l

    def here(self, at: np.ndarray) -> bool:
        """Whether what stands at `at` is lettered in this drawing: in its
        disc for a detail view, in no detail's disc otherwise."""
        inside = any(float(np.hypot(*(at - c))) <= r for c, r in self.discs)
        return inside if self.in_detail else not inside

    def drawn_part(self, a: np.ndarray, b: np.ndarray) -> tuple[np.ndarray, np.ndarray] | None:
        """The part of the segment a–b this drawing draws: all of it, or in a
        detail view the part inside its disc (None where none is)."""
        a, b = np.asarray(a, float), np.asarray(b, float)
        return clipped(a, b, *self.discs[0]) if self.in_detail else (a, b)

    def line(self, a: np.ndarray, b: np.ndarray, kind: LineType = "main") -> None:
        part = self.drawn_part(a, b)
        if part is not None:
            self.sk.line(part[0], part[1], kind)

    def _cut(self, first: int) -> None:
        """A detail view's calls from `first` on cut at its disc's edge
        (`cut_to_disc`; its loads' arrows kept whole)."""
        if not self.in_detail:
            return
        self.sk.calls[first:] = cut_to_disc(self.sk.calls[first:], *self.discs[0], arrows=False)

    def marks(self, details: Sequence[Detail], lang: Language) -> None:
        """The discs of `details` as thin circles, each with its letter."""
        for d, (c, r) in zip(details, self.discs):
            self.sk.circle(c, r, "thin")
            rim, towards = rim_anchors(c, r)[0]  # up and right
            self.labels.later(rim, d.letter, towards)

    def later(self, anchor: np.ndarray, markup: str, towards: np.ndarray | None = None) -> None:
        """A label written after every line, so that it can avoid them all
        (where it is this drawing's: `here`)."""
        if self.here(anchor):
            self.labels.later(anchor, markup, towards)
            self._named.append((np.asarray(anchor, float), markup, towards))

    def later_along(
        self, start: np.ndarray, end: np.ndarray, markup: str, along: Sequence[float] | None = None
    ) -> None:
        self.labels.later_along(start, end, markup, along)

    def force(
        self, at: np.ndarray, F: np.ndarray, label: str, largest: float, line: str = "main"
    ) -> None:
        size = float(np.hypot(*F))
        if size <= 1e-9 * max(largest, 1e-300) or not self.here(at):
            return
        u = np.asarray(F, float) / size
        end = at + (_arrow_length(size, largest) + self.longer.get(force_markup(label), 0.0)) * u
        # forces along one line of action (F_PR, F_in and G on a slider) side by side
        for _ in range(6):
            if not any(_coincident(at, end, s, e) for s, e in self._arrows):
                break
            at, end = at + 2.5 * np.array([-u[1], u[0]]), end + 2.5 * np.array([-u[1], u[0]])
        self._arrows.append((at, end))
        self.sk.arrow(at, end, line, **_ARROW)  # type: ignore[arg-type]
        self.labels.later_arrow(at, end, force_markup(label), _SHAFT_ALONG)

    def moment(
        self,
        centre: np.ndarray,
        M: float,
        label: str,
        radius: float = 6.0,
        name: tuple[str, np.ndarray] | None = None,
        enclosed: bool = False,
    ) -> None:
        """A couple as an arc with its arrowhead in the sense of M (ccw
        positive), turned where it leaves room for its label by the arrowhead
        and for `name` (the name of the point at `centre`, the side it is
        written first), with `enclosed` for every name written so far inside
        its circle too, and crosses least."""
        if M == 0.0 or not self.here(centre):
            return
        # the arc is avoided as drawn (the labels follow the sketch), not as a
        # disc: the points inside it (the pivot it turns round) are named there
        start = _ARC_STARTS[0]
        if self.turn_arcs:
            start = self._arc_start(centre, M, force_markup(label), radius, name, enclosed)
            if enclosed and start != self._arc_start(centre, M, force_markup(label), radius, name):
                self.turned_for_enclosed = True
        tip = sense_arc(self.sk, centre, radius, M, start, start + _ARC_SPAN)
        self.later(tip, force_markup(label), unit_vector(tip - centre))

    def _arc_start(
        self,
        centre: np.ndarray,
        M: float,
        markup: str,
        radius: float,
        name: tuple[str, np.ndarray] | None,
        enclosed: bool = False,
    ) -> float:
        """Where a couple's arc starts, degrees: the first of _ARC_STARTS that
        leaves room near `centre` for `name` and by the arrowhead for `markup`
        (with `enclosed`, near its point for each name inside the arc's circle:
        a short crank's centre of mass, its pin), else the one that leaves most
        of that room and covers least."""
        inside = [
            (at, markup_, side)
            for at, markup_, side in self._named
            if enclosed
            and float(np.hypot(*(at - centre))) <= radius
            and (name is None or markup_ != name[0] or float(np.hypot(*(at - centre))) > 1e-6)
        ]
        best: tuple[tuple[int, float], float] | None = None
        for start in _ARC_STARTS:
            arc = arc_line(centre, radius, start, start + _ARC_SPAN)
            t = math.radians(start + _ARC_SPAN if M > 0 else start)
            tip = centre + radius * np.array([math.cos(t), math.sin(t)])
            lost = int(not len(self.labels.rooms(tip, markup, towards=tip - centre, keep_off=arc)))
            if name is not None:
                rooms = self.labels.rooms(centre, name[0], towards=name[1], keep_off=arc)
                lost += 2 * int(not len(rooms))
            for at, inner, side in inside:
                lost += int(not len(self.labels.rooms(at, inner, towards=side, keep_off=arc)))
            if not lost:  # room for both: the first such start
                return start
            score = (lost, round(self.labels.covered(arc.buffer(0.3)), 1))
            if best is None or score < best[0]:
                best = (score, start)
        assert best is not None
        return best[1]

    def arm(self, pivot: np.ndarray, at: np.ndarray, F: np.ndarray) -> np.ndarray | None:
        """The perpendicular from `pivot` to the force's line of action, drawn
        thin where it is 1 mm long at least: its foot (None where it is not)."""
        u = unit_vector(np.asarray(F, float))
        r = at - pivot
        foot = pivot + r - float(np.dot(r, u)) * u
        if float(np.hypot(*(foot - pivot))) < 1.0:
            return None
        self.line(pivot, foot, "thin")
        # the line of action carried on to the foot, thin
        self.line(at, foot, "thin")
        return foot

    # the mechanism's links -----------------------------------------------------------

    def _pose(self, lids: set[int], frame: bool) -> Pose:
        """The links `lids` at the state's position in mm: their pins, their
        sliders' blocks and guides; with `frame`, the frame's pivots and guides."""
        state, mech = self.state, self.state.mech
        points: dict[str, np.ndarray] = {}
        for lid in sorted(lids):
            for name in mech.links[lid].points:
                points.setdefault(name, self.mm(state.point(lid, name)))
        pins: list[str] = []
        pivots: list[str] = []
        for pin in mech.revolutes:
            moving = [lk for lk in pin.links if lk != FRAME]
            if any(lk in lids for lk in moving):
                points[pin.point] = self.mm(state.point(moving[0], pin.point))
                at_frame = pivots if FRAME in pin.links and frame else pins
                if pin.point not in pins + pivots:
                    at_frame.append(pin.point)
        guides: list[Guide] = []
        blocks: list[Block] = []
        for pair in mech.sliders:
            if pair.slider not in lids and pair.guide not in lids:
                continue
            u_c, Q_c = state.guide(pair)
            u, Q = _xy(u_c), self.mm(Q_c)
            if pair.guide == FRAME:
                if frame:
                    guides.append(Guide(Q - 22.0 * u, Q + 22.0 * u, u, "frame", 3.5))
            elif pair.guide in lids:
                # the slot runs from the block along the guide link, as far as its points reach
                ts = [
                    float(np.dot(self.mm(state.point(pair.guide, n)) - Q, u))
                    for n in mech.links[pair.guide].points
                ]
                guides.append(Guide(Q + min(-16.0, *ts) * u, Q + max(16.0, *ts) * u, u, "slot"))
            if pair.slider in lids:
                blocks.append(Block((pair.slider, pair.guide), Q, u, (6.0, 3.5)))
        return Pose(
            points,
            [mech.links[lid].points for lid in sorted(lids)],
            pins=pins,
            pivots=pivots,
            guides=guides,
            blocks=blocks,
        )

    def links(self, lids: Iterable[int], *, frame: bool) -> None:
        """The links `lids` at the state's position; with `frame`, the frame's
        pivots and guides hatched as on the kinematic diagram."""
        lids = set(lids)
        state, mech = self.state, self.state.mech
        # the lines and blocks drawn are avoided as the labels follow the sketch
        # (once: a line listed twice would count twice when a leader crosses it)
        first = len(self.sk.calls)
        drawn = draw_poses(self.sk, [self._pose(lids, frame)])
        self._cut(first)
        for P in drawn.pivots:
            if not self.in_detail or self.here(P):
                self.labels.avoid_line(P, P - np.array([0.0, 6.0]), 4.5)
        for P in [*drawn.pivots, *(c for c, _ in drawn.pins)]:
            if not self.in_detail or self.here(P):
                self.labels.avoid_circle(P, 1.6)
        written: set[str] = set()
        for pin in mech.revolutes:
            moving = [lk for lk in pin.links if lk != FRAME]
            if not any(lk in lids for lk in moving):
                continue
            P = self.mm(state.point(moving[0], pin.point))
            if pin.point not in written:
                written.add(pin.point)
                self.later(P, point_markup(pin.point), _PIN_SIDE)
        for pair in mech.sliders:
            if pair.slider in lids and pair.slider_point not in written:
                written.add(pair.slider_point)
                self.later(
                    self.mm(state.point(pair.slider, pair.slider_point)),
                    point_markup(pair.slider_point),
                    np.array([0.0, 1.0]),
                )
        for lid in sorted(lids):  # the output point and other named points
            for name in mech.links[lid].points:
                if name not in written and len(mech.point_owners[name]) == 1:
                    written.add(name)
                    self.later(
                        self.mm(state.point(lid, name)), point_markup(name), np.array([0.6, 0.8])
                    )

    def loads(self, fa: ForceAnalysis, lids: Iterable[int], largest: float) -> None:
        """G at S, F_IN shifted to K (or at S with M_IN as a couple), h, F_PR."""
        for lid in lids:
            ll = fa.loads.links[lid]
            S = self.mm(ll.centre_of_mass)
            if ll.mass and (not self.in_detail or self.here(S)):
                self.sk.circle(S, 0.8, "main", "black")
                self.labels.avoid_circle(S, 1.2)
                self.later(S, f"S_{{{lid}}}", _S_SIDE)
                self.force(S, ll.weight, f"G{lid}", largest)
            sh = ll.shifted_inertia_force
            if sh is not None and ll.mass:
                K = self.mm(sh.point)
                if float(np.hypot(*(K - S))) >= 1.0 and self.here(S):
                    self.line(S, K, "thin")
                    # named along the part drawn: a detail view cuts the arm
                    # at its disc's edge (gen 240's h6, 4:1, stood 12 mm past it)
                    part = self.drawn_part(S, K)
                    if part is not None and float(np.hypot(*(part[1] - part[0]))) >= 1.0:
                        self.later_along(part[0], part[1], f"h_{{{lid}}}", _ARM_ALONG)
                self.force(K, ll.inertia_force, f"F_in{lid}", largest)
            elif ll.mass:
                self.force(S, ll.inertia_force, f"F_in{lid}", largest)
                self.moment(S, ll.inertia_moment, f"M_in{lid}", name=(f"S_{{{lid}}}", _S_SIDE))
        for f in fa.loads.production_resistance:
            if f.link in lids and f.acting:
                self.force(self.mm(f.point), f.force, f.name, largest)
            elif f.link in lids and f.at_rest:
                # acts = "always" on a point at rest: the resistance is zero here
                self.later(self.mm(f.point), f"{force_markup(f.name)} = 0", np.array([0.0, 1.0]))

    def finish(self, title: str, notes: Sequence[str] = ()) -> Sketch:
        self.labels.write_later(retry=_RETRY_ORDERS, grow=self.grow)
        self.sk.label_counts = self.labels.counts()
        ext = self.sk.extent()
        y = ext.bottom - 5.0
        for note in notes:
            self.sk.rich_text((ext.left + _PAD, y), note, _TEXT)
            y -= 6.0
        self.sk.text((ext.left + _PAD, ext.top + 3.0), title, _TITLE)
        return self.sk


def _largest_load(
    fa: ForceAnalysis, lids: Iterable[int], extra: Iterable[np.ndarray] = ()
) -> float:
    sizes = [0.0]
    for lid in lids:
        ll = fa.loads.links[lid]
        sizes += [float(np.hypot(*ll.weight)), float(np.hypot(*ll.inertia_force))]
    sizes += [
        float(np.hypot(*f.force)) for f in fa.loads.production_resistance if f.link in set(lids)
    ]
    sizes += [float(np.hypot(*v)) for v in extra]
    return max(sizes)


# --- the drawings -----------------------------------------------------------------------


def sketch_loaded_mechanism(
    fa: ForceAnalysis,
    mu_l: float,
    look: Any,
    lang: Language,
    compact: bool = False,
    grow: bool = False,
    details: Sequence[Detail] = (),
    laid_out: Sketch | None = None,
) -> Sketch:
    """The mechanism with every load, F_bal and ω1 at `mu_l`; on a compact sheet
    (`_Composer`, many groups: every drawing near its coarsest scale) its
    couples' arcs at their first start, not turned to leave their names room
    (a turned arc's name may stand where such a sheet has no room left);
    `grow` as _Drawing's, its names tried at 2.5 mm too (_LOADED_AGAIN).
    With `details`, what stands in a detail's disc (its
    points' names, the loads applied there) is drawn only in its detail view
    (`sketch_loaded_detail`); the disc is marked by a thin circle and its letter.
    With `grow`, `laid_out` is the drawing as the sheet was laid out with it
    (these arguments without `grow`: the composer's), drawn here if not given."""
    return _loaded_view(fa, mu_l, look, lang, compact, grow, details, None, laid_out)


def sketch_loaded_detail(
    fa: ForceAnalysis,
    mu_l: float,
    look: Any,
    lang: Language,
    detail: Detail,
    compact: bool = False,
    grow: bool = False,
    laid_out: Sketch | None = None,
) -> Sketch:
    """The detail view `detail` of the loaded mechanism drawn at `mu_l`: its
    disc at μl / ratio, titled "A (4:1)", the links cut at the disc's edge, the
    loads applied inside it (to direction, as on the mechanism) and every name
    there; `grow` and `laid_out` as `sketch_loaded_mechanism`'s."""
    return _loaded_view(fa, mu_l, look, lang, compact, grow, (detail,), detail, laid_out)


def _loaded_view(
    fa: ForceAnalysis,
    mu_l: float,
    look: Any,
    lang: Language,
    compact: bool,
    grow: bool,
    details: Sequence[Detail],
    detail: Detail | None,
    laid_out: Sketch | None = None,
) -> Sketch:
    """The loaded mechanism with `details` marked (`detail` None), or the detail
    view `detail`: ω1's arc turned where it leaves room for the names inside its
    circle too (a short crank's S1 and pin, gen 141), kept so where that
    letters the drawing better than the arc turned for ω1 and the pivot's name
    alone (gen 165's detail: S3, ω1 and h5 then went far). With `grow`
    (lettered again on the laid-out sheet), where names of forces crowd on
    the drawing as the sheet was laid out with it (the sheet linter finds
    them far or on something), those forces' arrows drawn longer too
    (_LONGER_MM, in turn): kept where fewer names crowd, or as few and the
    drawing reaches less past the box it was laid out with (gen 97 uk: 'G8'
    10.4 mm off its arrow, its head on a guide; lettered again, the drawing
    grew 9 mm taller and found no room; its arrow 8 mm longer, 'G8' is
    written by its head within the box). `laid_out`, the drawing without
    `grow` where the caller has it (the composer's), is not drawn again."""

    def drawn(longer: Mapping[str, float], grow: bool) -> Sketch:
        sk, turned = _loaded_drawing(
            fa, mu_l, look, lang, compact, grow, details, detail, True, longer
        )
        if not turned:
            return sk
        plain, _ = _loaded_drawing(
            fa, mu_l, look, lang, compact, grow, details, detail, False, longer
        )
        assert sk.label_counts is not None and plain.label_counts is not None
        counts, plain_counts = sk.label_counts, plain.label_counts
        better = (counts.unsettled, counts.far) < (plain_counts.unsettled, plain_counts.far)
        return sk if better else plain

    sk = drawn({}, grow)
    if not grow:
        return sk
    if laid_out is None:
        laid_out = drawn({}, False)
    walled = {n.markup for n in crowded(laid_out, lang) if n.kind == "arrow"}
    if not walled:
        return sk
    box = laid_out.extent()

    def weighed(sk: Sketch) -> tuple[int, float]:
        ext = sk.extent()
        past = max(0.0, box.x - ext.x) + max(0.0, ext.right - box.right)
        past += max(0.0, box.y - ext.y) + max(0.0, ext.top - box.top)
        return len(list(crowded(sk, lang))), round(past, 3)

    # the points a longer arrow's head must not end on (a pin, a centre of
    # mass drawn as a dot would hide it: eleven links' G9 in a block's S)
    state = fa.loads.state
    mu = mu_l / detail.ratio if detail is not None else mu_l
    points = [
        _xy(_c(state.point(next(iter(o)), n))) / mu for n, o in state.mech.point_owners.items()
    ]
    points += [_xy(_c(ll.centre_of_mass)) / mu for ll in fa.loads.links.values() if ll.mass]
    dots = np.array(points, dtype=float).reshape(-1, 2)

    def clear(sk: Sketch) -> bool:
        heads = [
            c.naming.end
            for c in sk.calls
            if c.naming is not None and c.naming.kind == "arrow" and c.naming.markup in walled
        ]
        return all(
            not len(dots) or float(np.min(np.hypot(*(dots - head).T))) > _HEAD_CLEAR_MM
            for head in heads
            if head is not None
        )

    best = weighed(sk)
    for by in _LONGER_MM:
        longer = drawn(dict.fromkeys(walled, by), True)
        if clear(longer):
            weight = weighed(longer)
            if weight < best:
                sk, best = longer, weight
    return sk


def _loaded_drawing(
    fa: ForceAnalysis,
    mu_l: float,
    look: Any,
    lang: Language,
    compact: bool,
    grow: bool,
    details: Sequence[Detail],
    detail: Detail | None,
    enclosed: bool,
    longer: Mapping[str, float],
) -> tuple[Sketch, bool]:
    """`_loaded_view`'s drawing, ω1's arc turned with `enclosed` as
    _Drawing.moment's, the arrows of `longer` drawn longer (_Drawing's);
    and whether `enclosed` turned it elsewhere."""
    state = fa.loads.state
    mech = state.mech
    mu = mu_l / detail.ratio if detail is not None else mu_l
    d = _Drawing(
        look,
        state,
        mu,
        lang,
        turn_arcs=not compact,
        grow=grow,
        details=details,
        detail=detail,
        labelling=_LOADED_AGAIN if grow else _LABELLING,
        longer=longer,
    )
    gid = loaded_detail_gid(details, detail) if detail is not None else "force-mechanism"
    with d.sk.group(gid, "mechanism"):
        d.links(mech.links, frame=True)
        largest = _largest_load(fa, mech.links, [fa.driving_link.balancing_vector])
        d.loads(fa, mech.links, largest)
        A = d.mm(state.point(mech.drive.link, mech.crank_pin))
        d.force(A, fa.driving_link.balancing_vector, "F_bal", largest)
        O = d.mm(state.point(mech.drive.link, mech.crank_pivot))
        name = (point_markup(mech.crank_pivot), _PIN_SIDE)
        d.moment(O, state.omega1, "ω_{1}", radius=9.0, name=name, enclosed=enclosed)
        if detail is not None:
            ratio = catalogue(lang).plain_number(detail.ratio)
            title = _words(lang)["lever_detail"].format(letter=detail.letter, ratio=ratio)
            return d.finish(title), d.turned_for_enclosed
        d.marks(details, lang)
        label = scale_label(mu_l, "length", lang).markup()
        sk = d.finish(
            _words(lang)["mechanism"].format(i=fa.index), [label, _words(lang)["not_to_scale"]]
        )
    return sk, d.turned_for_enclosed


# how much longer (mm) a force's arrow on the loaded mechanism is tried,
# in turn, where its name found no place: drawn to direction only, it
# may reach out of the knot its head ends in
_LONGER_MM = (8.0, 16.0)
_HEAD_CLEAR_MM = 2.5  # and its head kept this far from every point drawn (mm)
_LOADED_DETAILS = 2  # the most detail views of the loaded mechanism
# a second detail view only for a crowd of its own: this many names far or on
# something that the first leaves at least (gen 5 uk: six round its crank; gen
# 63's two left over get none, a leader serves them)
_SECOND_CROWD = 3
# or for a pair of them, weighed on the sheet against the first alone: kept
# where fewer names stand far (five_dyads uk: 'S5', 'Fi5' in the knot at G where
# blocks 5 and 6 sit on guide T, 9-11 mm off, beside the first detail's L)
_SECOND_PAIR = 2
# or, on the laid-out sheet (`_loaded_details_again`), for a single name left
# far: weighed there like the others (gen 128 en: 'h7' 10.4 mm off in the knot
# at S7, outside the first view's disc, gets a view of its own)
_SECOND_ONE = 1
_POINTS_APART_MM = 7.0  # a detail of the loaded mechanism sets its points this far apart
_LOADED_DETAIL_MM = 45.0  # the largest radius of its disc, mm
_LOADED_RADII = (4.0, 6.0, 8.0, 12.0, 16.0)  # the radii of its discs tried, mm
_CORE_SHARE = 0.7  # its disc: the smallest that holds this share of the most any holds


def _loaded_names(fa: ForceAnalysis, mu_l: float) -> tuple[list[Name], np.ndarray]:
    """The names the loaded mechanism writes at `mu_l`: its points', the
    centres of mass', the loads' by their arrows and the arms' (`Name`); and
    the places (mm) of the points and centres of mass named."""
    state = fa.loads.state
    mech = state.mech
    out: list[Name] = []
    for name, owners in mech.point_owners.items():
        at = _xy(_c(state.point(next(iter(owners)), name))) / mu_l
        out.append(Name(at, name_area(name)))
    forces: list[tuple[np.ndarray, np.ndarray, str]] = []
    for lid in mech.links:
        ll = fa.loads.links[lid]
        if not ll.mass:
            continue
        S = _xy(_c(ll.centre_of_mass)) / mu_l
        out.append(Name(S, name_area(f"S_{{{lid}}}")))
        forces.append((S, np.asarray(ll.weight, float), f"G{lid}"))
        sh = ll.shifted_inertia_force
        K = S if sh is None else _xy(_c(sh.point)) / mu_l
        forces.append((K, np.asarray(ll.inertia_force, float), f"F_in{lid}"))
        h = float(np.hypot(*(K - S)))
        if h >= 1.0:
            out.append(Name((S + K) / 2.0, name_area(f"h_{{{lid}}}"), h))
    for f in fa.loads.production_resistance:
        if f.acting:
            forces.append((_xy(_c(f.point)) / mu_l, np.asarray(f.force, float), f.name))
    A = _xy(_c(state.point(mech.drive.link, mech.crank_pin))) / mu_l
    forces.append((A, np.asarray(fa.driving_link.balancing_vector, float), "F_bal"))
    largest = max([float(np.hypot(*F)) for _, F, _ in forces] + [0.0])
    for at, F, label in forces:
        size = float(np.hypot(*F))
        if size > 1e-9 * max(largest, 1e-300):
            u = F / size
            mid = at + 0.5 * _arrow_length(size, largest) * u
            out.append(Name(mid, name_area(label) + 8.0))
    points = [n.at for n in out[: len(mech.point_owners)]]
    points += [at for at, _, label in forces if label.startswith("G")]
    return out, np.array(points, dtype=float).reshape(-1, 2)


def loaded_details(
    fa: ForceAnalysis,
    mu_l: float,
    crowded: np.ndarray,
    taken: Iterable[str] = (),
    fewest: int = _SECOND_CROWD,
) -> tuple[Detail, ...]:
    """The detail views the loaded mechanism at `mu_l` needs where the names
    standing for the points `crowded` (mm, `crowded_names` of the mechanism
    drawn without details) found no place near (`choose_details`): at most
    _LOADED_DETAILS discs apart round a point of the mechanism or such a
    point, one past the first only for a crowd of `fewest` names or more,
    lettered by capitals that name no point and are not in `taken` (the
    lever's details' letters)."""
    names, points = _loaded_names(fa, mu_l)
    used = {n[:1].upper() for n in fa.loads.state.mech.point_owners} | set(taken)
    letters = [x for x in DETAIL_LETTERS if x not in used]
    return choose_details(
        names,
        crowded,
        list(points),
        mu_l,
        letters,
        _LOADED_DETAILS,
        points=points,
        spacing=_POINTS_APART_MM,
        widest=_LOADED_DETAIL_MM,
        tightest=_CORE_SHARE,
        radii=_LOADED_RADII,
        fewest=fewest,
    )


def loaded_detail_gid(details: Sequence[Detail], detail: Detail) -> str:
    """The drawing of sheet 2 that holds the detail view `detail` of the loaded mechanism."""
    k = list(details).index(detail)
    return "force-mechanism-detail" + (f"-{k + 1}" if k else "")


def _group_forces(fa: ForceAnalysis, g: Any) -> list[tuple[str, np.ndarray, np.ndarray, str]]:
    """The reactions drawn on a group: (label, force, point, line) — the outer
    reactions as their components (dashed) where the plan split them, and the
    reactions of the groups attached after it; the inner reaction is internal."""
    inner = g.reactions[2]
    internal = {inner.name, inner.reversed().name}
    own = {r.name: r for r in g.reactions[:2]}
    out = []
    for lid in g.links:
        for f in g.free_bodies[lid]:
            if not f.label.startswith("R") or f.label in internal:
                continue
            r = own.get(f.label)
            if r is not None and len(r.components) > 1:
                for comp in r.components:
                    out.append((comp.label, comp.vector, r.point, "dashed"))
            out.append((f.label, f.force, f.point, "main"))
    return out


def sketch_group(
    fa: ForceAnalysis,
    g: Any,
    mu_l: float,
    look: Any,
    lang: Language,
    arm_names: list[str],
    grow: bool = False,
) -> Sketch:
    """A group's drawing, its arms h'_i numbered on from `arm_names` (which
    receives the forces they are the arms of). Every arm is named on its own;
    where some name then stands far or on something and arms from the inner
    pin run along one line (gen 15's h'_1 and h'_2 of group 10-11, 0.3 mm
    apart, their names crowding each other past the slider's block), drawn
    again with those named by one label, "h'_{1,2}", along the longest
    (`_one_per_line`), and kept where that leaves fewer crowded and its box
    is no wider nor taller (the sheet is laid out by it)."""
    own: list[str] = []
    lines: list[int] = []  # how many arms' labels one per line would save
    sk = _group_view(fa, g, mu_l, look, lang, len(arm_names), own, grow, lines=lines)
    arm_names += own
    counts = sk.label_counts
    if counts is None or not (counts.far or counts.unsettled) or not lines or not lines[0]:
        return sk
    merged = _group_view(fa, g, mu_l, look, lang, len(arm_names) - len(own), [], grow, True)
    grown, box = merged.extent(), sk.extent()
    if grown.width > box.width + 1e-6 or grown.height > box.height + 1e-6:
        return sk
    before = len(list(crowded(sk, lang)))
    return merged if len(list(crowded(merged, lang))) < before else sk


def _force_labelling(grow: bool) -> dict[str, Any]:
    """How a group or the driving link is lettered: as the force polygons
    (`_FORCE_LABELLING`); lettered again on the laid-out sheet (`grow`), at
    GOST's 2.5 mm too (`_FORCE_AGAIN`)."""
    return _FORCE_AGAIN if grow else _FORCE_LABELLING


def _group_view(
    fa: ForceAnalysis,
    g: Any,
    mu_l: float,
    look: Any,
    lang: Language,
    first: int,
    arm_names: list[str],
    grow: bool = False,
    merge_arms: bool = False,
    lines: list[int] | None = None,
) -> Sketch:
    """A group's drawing (`sketch_group`), its arms numbered on from `first`;
    with `merge_arms`, the arms along one line from the inner pin named by
    one label; `lines` receives how many labels that saves."""
    state = fa.loads.state
    mech = state.mech
    d = _Drawing(look, state, mu_l, lang, grow=grow, labelling=_force_labelling(grow))
    gid = f"group-{g.name}"
    with d.sk.group(gid, "assur-group"):
        d.links(g.links, frame=False)
        reactions = _group_forces(fa, g)
        largest = _largest_load(fa, g.links, [f for _, f, _, _ in reactions])
        d.loads(fa, g.links, largest)
        near = [d.mm(state.point(lid, n)) for lid in g.links for n in mech.links[lid].points]
        for label, F, P, line in reactions:
            at = d.mm(P)
            gap = [float(np.hypot(*(at - q))) for q in near]
            if min(gap) > _FAR_MM:
                # A guide's normal force whose line of action lies far off the
                # block: drawn at the block with the couple that carries it there.
                q = near[int(np.argmin(gap))]
                arm = (at - q) * mu_l
                if line == "main":
                    # named as the reaction it carries: M_{0,11} of R_{0,11} (not "M0_11")
                    couple = "M" + force_markup(label)[1:]
                    d.moment(q, float(arm[0] * F[1] - arm[1] * F[0]), couple, radius=8.0)
                at = q
            d.force(at, F, label, largest, line)
        # the arms of ΣM_B(L1) = 0, the equation of R^t: the groups whose first
        # outer reaction is split into R^n and R^t (RRR, RRP)
        if len(g.reactions[0].components) == 2:
            B = d.mm(state.point(g.links[0], g.reactions[2].pair))  # the inner pin
            L1 = g.links[0]
            ll = fa.loads.links[L1]
            moments = []
            if ll.mass:
                sh = ll.shifted_inertia_force
                moments.append((ll.weight, ll.centre_of_mass, f"G{L1}"))
                if sh is not None:
                    moments.append((ll.inertia_force, sh.point, f"F_in{L1}"))
            for label, F, P, line in reactions:
                if line == "main" and label in {f.label for f in g.free_bodies[L1]}:
                    if not any(r.name == label and r.components for r in g.reactions[:2]):
                        moments.append((F, P, label))
            feet: dict[int, tuple[np.ndarray, list[str]]] = {}  # (foot - B, numbers)
            for F, P, label in moments:
                if float(np.hypot(*F)) > 0.0:
                    foot = d.arm(B, d.mm(P), np.asarray(F, float))
                    if foot is not None:
                        arm_names.append(label)
                        # h_i is the shift of F_in.i: the arms are h'_i
                        feet[len(feet)] = (foot - B, [str(first + len(arm_names))])
            merged = _one_per_line(feet)
            if lines is not None:
                lines.append(len(feet) - len(merged))
            for foot, numbers in merged if merge_arms else feet.values():
                d.later_along(B, B + foot, f"h'_{{{','.join(numbers)}}}", _ARM_ALONG)
        title = _words(lang)["group"].format(name=g.name, kind=g.kind)
        sk = d.finish(title, [scale_label(mu_l, "length", lang).markup()])
    return sk


def sketch_driving_link(
    fa: ForceAnalysis, mu_l: float, look: Any, lang: Language, grow: bool = False
) -> Sketch:
    state = fa.loads.state
    dl = fa.driving_link
    d = _Drawing(look, state, mu_l, lang, grow=grow, labelling=_force_labelling(grow))
    with d.sk.group("driving-link", "driving-link"):
        d.links([dl.link], frame=False)
        forces = [
            (f.label, f.force, f.point) for f in dl.free_body if f.label.startswith(("R", "F_bal"))
        ]
        largest = _largest_load(fa, [dl.link], [f for _, f, _ in forces])
        d.loads(fa, [dl.link], largest)
        for label, F, P in forces:
            d.force(d.mm(P), F, label, largest)
        title = _words(lang)["driving"].format(link=dl.link)
        sk = d.finish(title, [scale_label(mu_l, "length", lang).markup()])
    return sk


def _polygon_title(title: str, lang: Language) -> str:
    for en, word in catalogue(lang).words("polygon_titles").items():
        title = title.replace(en, str(word))
    return title


def _reversed(label: str) -> str:
    """The reaction of the same pair the other way round: "R23" → "R32",
    "R10_11" → "R11_10"; "" for any other label."""
    m = re.fullmatch(r"R(\d)(\d)", label) or re.fullmatch(r"R(\d+)_(\d+)", label)
    if m is None:
        return ""
    sep = "_" if "_" in label else ""
    return f"R{m.group(2)}{sep}{m.group(1)}"


def _side_by_side(
    sk: Sketch,
    labels: Labels,
    arrows: list[tuple[np.ndarray, np.ndarray]],
    s: np.ndarray,
    e: np.ndarray,
) -> tuple[np.ndarray, np.ndarray]:
    """Where the polygon's arrow s→e is drawn: on its exact place, or shifted
    beside a drawn arrow it would run along, its length and direction kept,
    with thin ticks joining its ends to the exact ones so the chain reads
    closed. The arrow is added to `arrows`."""
    shift = _beside(s, e, arrows)
    if float(np.hypot(*shift)) > 0.0:
        for at in (s, e):
            sk.line(at, at + shift, "thin")
        s, e = s + shift, e + shift
    arrows.append((s, e))
    return s, e


def _wrapped(markup: str, width: float, look: Any) -> list[str]:
    """An equation's markup in lines no wider than `width` mm where its terms
    allow, broken before a "+" (the continued line opens with it)."""
    probe = Sketch(look)
    terms = markup.split(" + ")
    lines = [terms[0]]
    for term in terms[1:]:
        joined = f"{lines[-1]} + {term}"
        if probe.rich_text((0.0, 0.0), joined, _TEXT) <= width:
            lines[-1] = joined
        else:
            lines.append(f"+ {term}")
    return lines


def _distance_outside(region: Any, points: np.ndarray) -> np.ndarray:
    """The distance (mm) of `points` (x, y rows) outside `region` to it: of a
    polygon the least to its edges, measured in numpy (within rounding of
    shapely's measure, 1e-12 mm; _caption_place decides nothing closer than
    1e-6 mm by it); of another shape as shapely measures it."""
    if region.geom_type != "Polygon" or len(region.interiors):
        return np.asarray(shapely.distance(shapely.points(points), region), dtype=float)
    ring = shapely.get_coordinates(region.exterior)
    px, py = points[:, 0], points[:, 1]
    out = np.full(len(points), np.inf)
    for (ax, ay), (bx, by) in zip(ring[:-1], ring[1:]):
        vx, vy = bx - ax, by - ay
        n2 = vx * vx + vy * vy
        t = np.clip(((px - ax) * vx + (py - ay) * vy) / n2, 0.0, 1.0) if n2 > 0.0 else 0.0
        out = np.minimum(out, np.hypot(px - (ax + t * vx), py - (ay + t * vy)))
    return out


_CAPTION_REACH = NEAR_MM - 1.0  # a link polygon's caption walled in: this far from it at most


def _caption_place(
    labels: Labels, corners: np.ndarray, caption: str, reach: float = 3.0
) -> tuple[np.ndarray, np.ndarray | None]:
    """Where a link's polygon inside its group's is named ("link 4"): on the
    polygon or by it (the box within `reach` mm of it), at the free place nearest its centre
    (the anchor and the side the placer tries first put the box there); else
    beside the centre."""
    centre = corners.mean(axis=0)
    w, h = labels.width(caption) + 0.4, labels.size + 0.4
    region = shapely.convex_hull(shapely.multipoints(corners))
    lo, hi = corners.min(axis=0) - (w / 2 + reach), corners.max(axis=0) + (w / 2 + reach)
    xs, ys = np.meshgrid(np.arange(lo[0], hi[0], 1.0), np.arange(lo[1], hi[1], 1.0))
    q = np.c_[xs.ravel(), ys.ravel()]
    x0, y0, x1, y1 = q[:, 0] - w / 2, q[:, 1] - h / 2, q[:, 0] + w / 2, q[:, 1] + h / 2
    # a box whose centre is inside the polygon meets it; the others are measured
    on = shapely.contains_xy(region, q[:, 0], q[:, 1])
    ask = np.flatnonzero(~on)
    # the box holds the disc of radius min(w, h) / 2 round its centre and lies
    # within hypot(w, h) / 2 of it: where the centre's distance d says which
    # side of 3 mm the box is, by more than rounding, the box is not measured
    d = _distance_outside(region, q[ask])
    near = d <= reach + min(w, h) / 2 - 1e-6
    unsure = ~near & (d - math.hypot(w, h) / 2 <= reach + 1e-6)
    b = ask[unsure]
    near[unsure] = shapely.distance(shapely.box(x0[b], y0[b], x1[b], y1[b]), region) <= reach
    on[ask] = near
    taken = shapely.bounds(labels.boxes).reshape(-1, 4)
    gap = labels.spacing
    clash = (
        (taken[None, :, 0] - gap < x1[:, None])
        & (taken[None, :, 2] + gap > x0[:, None])
        & (taken[None, :, 1] < y1[:, None])
        & (taken[None, :, 3] > y0[:, None])
    ).any(axis=1)
    ok = np.flatnonzero(on & ~clash)
    tried = ok[np.argsort(np.hypot(*(q[ok] - centre).T), kind="stable")][:3000]
    first = labels.first_free(np.c_[x0[tried], y0[tried], x1[tried], y1[tried]])
    if first is not None:
        # the box centred on q: the placer's first place east of the anchor
        return q[tried[first]] - np.array([1.5 + w / 2, 0.0]), np.array([1.0, 0.0])
    return centre, None


def sketch_force_polygons(
    polygons: Sequence[ForcePolygon],
    mu_F: float,
    look: Any,
    lang: Language,
    gid: str,
    title: str,
    equation_width: float | None = None,
    grow: bool = False,
    captions_first: bool = False,
    unnamed: frozenset[str] = frozenset(),
) -> Sketch:
    """The polygons of one group (or of the driving link) to μF, head to tail
    from their origin. A polygon that starts with the sides of one already
    drawn (a link's polygon inside its group's) adds only its new sides, as
    the textbook closes R54 inside the polygon of group 4-5; one that shares
    nothing is drawn beside it. `grow` as _Drawing's. A link's polygon is
    named after the sides' names, by it; where the sides' names leave it no
    place by it (task5_v04's link 2, 2 mm across, walled in by arrows), the
    polygons are drawn again with the captions written first
    (`captions_first`), kept where that letters them better. A side shorter
    than its arrowhead whose name finds no place by it (gen 165's R^τ_{9,10},
    1.9 mm between two long sides) is drawn again as a plain line closing
    the chain, its name listed under the polygon (`unnamed`: their labels),
    kept where that letters the polygons better."""
    sk = Sketch(look)
    labels = Labels(sk, _TEXT, **_FORCE_LABELLING, words=_index_words(lang))
    drawn: dict[tuple[str, int, int], bool] = {}
    short: list[str] = []
    listed: list[str] = []  # the names of the sides in `unnamed`
    offset = np.zeros(2)
    sides: dict[str, tuple[np.ndarray, np.ndarray]] = {}  # label → exact start, end
    arrows: list[tuple[np.ndarray, np.ndarray]] = []  # as drawn, some beside their line
    names: dict[str, list[Any]] = {}  # label → [start, markup, end] of its side, written last
    captions: list[tuple[np.ndarray, str]] = []
    with sk.group(gid, "force-polygon"):
        for n, poly in enumerate(polygons):
            keys = [
                (
                    v.label,
                    round(float(v.start[0]) / mu_F * 100),
                    round(float(v.start[1]) / mu_F * 100),
                )
                for v in poly.vectors
            ]
            shares = any(k in drawn for k in keys)
            inner = None  # the side that is a drawn side reversed (R32 of R23)
            if n and not shares:
                inner = next((v for v in poly.vectors if _reversed(v.label) in sides), None)
                if inner is not None:
                    # one figure: the inner reaction closes this link's polygon
                    # inside the group's, on the side already drawn
                    offset = sides[_reversed(inner.label)][1] - np.asarray(inner.start) / mu_F
                else:
                    # beside what is drawn, clear of it whichever way its sides run
                    xs = [float(x) / mu_F for v in poly.vectors for x in (v.start[0], v.end[0])]
                    offset = np.array([sk.extent().right + 15.0 - min(xs), 0.0])
            corners = [offset + np.asarray(v.start, float) / mu_F for v in poly.vectors]
            if len(polygons) > 1 and poly.title != title:
                captions.append((np.array(corners), _polygon_title(poly.title, lang)))
            for key, v in zip(keys, poly.vectors):
                if key in drawn:
                    continue
                drawn[key] = True
                if v is inner:
                    entry = names.get(_reversed(v.label))
                    if entry is not None:  # (a side listed under the polygon has none)
                        entry[1] = f"{entry[1]} = -{force_markup(v.label)}"
                    continue
                s = offset + np.asarray(v.start, float) / mu_F
                e = s + np.asarray(v.vector, float) / mu_F
                length = float(np.hypot(*(e - s)))
                if length < 1.0:
                    short.append(force_markup(v.label))
                    continue
                component = "^" in v.label
                sides[v.label] = (s, e)
                s, e = _side_by_side(sk, labels, arrows, s, e)
                if v.label in unnamed:
                    sk.line(s, e, "dashed" if component else "main")
                    listed.append(force_markup(v.label))
                    continue
                sk.arrow(s, e, "dashed" if component else "main", **_ARROW)  # type: ignore[arg-type]
                # named beside its side, anywhere along it (as the textbook writes R12 by its side)
                names[v.label] = [s, force_markup(v.label), e]
            # R = R^n + R^t: the resultant of two consecutive components, main line
            for a, b in zip(poly.vectors, poly.vectors[1:]):
                if (
                    a.label.endswith("^n")
                    and b.label == a.label[:-2] + "^t"
                    or a.label.endswith("^t")
                    and b.label == a.label[:-2] + "^n"
                ):
                    s = offset + np.asarray(a.start, float) / mu_F
                    e = offset + np.asarray(b.end, float) / mu_F
                    key = (a.label[:-2], round(s[0] * 100), round(s[1] * 100))
                    if key in drawn or float(np.hypot(*(e - s))) < 1.0:
                        continue
                    drawn[key] = True
                    s, e = _side_by_side(sk, labels, arrows, s, e)
                    sk.arrow(s, e, "main", **_ARROW)  # type: ignore[arg-type]
                    labels.later_along(s, e, force_markup(a.label[:-2]))
        zero = not sides and guide_side(polygons) <= 0.0
        if zero:
            # an unloaded group (massless links, no force): every side is
            # zero, the polygon a single point, drawn as one
            sk.circle(offset, 0.8, "main", "black")
            labels.avoid_line(offset - 1.0, offset + 1.0)
        if captions_first:
            for corners_of, caption in captions:
                anchor, towards = _caption_place(labels, corners_of, caption)
                labels.place(anchor, caption, towards=towards)
        for start, markup, end in names.values():
            labels.later_along(start, end, markup)
        labels.write_later(retry=_RETRY_ORDERS, grow=grow)
        walled = False
        for corners_of, caption in captions if not captions_first else ():
            anchor, towards = _caption_place(labels, corners_of, caption)
            if towards is None:  # none by it: one within the linter's reach
                anchor, towards = _caption_place(labels, corners_of, caption, _CAPTION_REACH)
                walled |= towards is None
            # a polygon with no free place by it (a link's few short sides in
            # a corner of its group's): every place near its centre on the
            # fine grid before a leader
            labels.fine = towards is None
            labels.place(anchor, caption, towards=towards)
            labels.fine = False
        sk.label_counts = labels.counts()
        ext = sk.extent()
        y = ext.bottom - 5.0
        for poly in polygons:
            markup = _equation_markup(poly.equation)
            lines = [markup] if equation_width is None else _wrapped(markup, equation_width, look)
            for line in lines:
                sk.rich_text((ext.left + _PAD, y), line, _TEXT)
                y -= 6.0
        if short:
            note = _words(lang)["zero_polygon" if zero else "short"]
            sk.rich_text((ext.left + _PAD, y), note.format(names=", ".join(short)), _TEXT)
            y -= 6.0
        if listed:
            mm = catalogue(lang).plain_number(_UNNAMED_BELOW)
            note = _words(lang)["unnamed"].format(mm=mm, names=", ".join(listed))
            sk.rich_text((ext.left + _PAD, y), note, _TEXT)
            y -= 6.0
        sk.rich_text((ext.left + _PAD, y), scale_label(mu_F, "force", lang).markup(), _TEXT)
        sk.text(
            (ext.left + _PAD, ext.top + 3.0),
            _words(lang)["polygon"].format(title=_polygon_title(title, lang)),
            _TITLE,
        )
    if walled:
        again = sketch_force_polygons(
            polygons, mu_F, look, lang, gid, title, equation_width, grow, True, unnamed
        )
        if len(crowded_names(again, lang)) < len(crowded_names(sk, lang)):
            sk, captions_first = again, True
    tiny = {
        force_markup(label): label
        for label, (s, e) in sides.items()
        if float(np.hypot(*(e - s))) < _UNNAMED_BELOW and label not in unnamed
    }
    if tiny:
        # (the linter asked only where a side is that short: most polygons have none)
        far = [n.markup for n in crowded(sk, lang) if n.markup in tiny]
        if far:
            more = unnamed | {tiny[markup] for markup in far}
            again = sketch_force_polygons(
                polygons, mu_F, look, lang, gid, title, equation_width, grow, captions_first, more
            )
            if len(crowded_names(again, lang)) < len(crowded_names(sk, lang)):
                return again
    return sk


# a lever's detail view (drawing/detail.py)
LeverDetail = Detail
_DETAILS = 2  # the most detail views of one lever
# arms whose feet lie this near one line from p are named by one label (mm)
_ON_LINE_MM = 0.5
# the series of a lever detail's scales (GOST 2.302's enlargements, 2:1 … 100:1)
# and the radii (mm at the lever's scale) of the discs tried round its crowd:
# a lever's images may crowd within a millimetre of p (gen 30)
_LEVER_RATIOS = (2.0, 2.5, 4.0, 5.0, 10.0, 20.0, 40.0, 50.0, 100.0)
_LEVER_RADII = (1.5, 2.0, 3.0, 5.0, 8.0, 12.0, 16.0, 20.0, 25.0)
# the least distance (mm, in a detail's view) of two spots where images are
# named: room for their names and the arrows of the forces at them
_SPOT_MM = 10.0
_MERGED_MM = 0.5  # images nearer (mm of the view) are written as one name
# a disc lettered at its ratio is taken if it holds this share of the crowded
# names the disc holding the most holds (gen 30: 6 of 7 round p at 40:1; gen 15's
# crowd strung along 15 mm of p's line, 8 of 23, goes in one wide disc)
_LETTERED_SHARE = 0.75


def _lever_names(fa: ForceAnalysis, mu_V: float) -> list[Name]:
    """The names the lever writes at `mu_V`: where each stands (mm), the area
    of its box (mm²), an arm's lettered along p–foot with its length."""
    lever = fa.lever
    owners = tuple(fa.loads.state.mech.point_owners)
    out: list[Name] = []
    spots: dict[tuple[int, int], tuple[np.ndarray, list[str]]] = {(0, 0): (np.zeros(2), ["p"])}
    for n, v in lever.images.items():
        at = np.asarray(v, float) / mu_V
        if float(np.hypot(*at)) >= 0.5:
            key = (round(float(at[0]) * 2), round(float(at[1]) * 2))
            spots.setdefault(key, (at, []))[1].append(image_markup(n, owners))
    out += [Name(at, name_area(", ".join(names))) for at, names in spots.values()]
    forces = [*lever.forces, lever.balancing]
    largest = max(float(np.hypot(*f.force)) for f in forces)
    for f in forces:
        size = float(np.hypot(*f.force))
        if size <= 1e-9 * largest:
            continue
        at = np.asarray(f.image, float) / mu_V
        u = np.asarray(f.force, float) / size
        out.append(Name(at + 0.5 * _arrow_length(size, largest) * u, name_area(f.label) + 8.0))
        if abs(f.arm) / mu_V >= 1.0:
            foot = at - float(np.dot(at, u)) * u
            h = float(np.hypot(*foot))
            out.append(Name(0.5 * foot, name_area("h_{10}"), h))
    return out


def _one_spot(a: np.ndarray, b: np.ndarray) -> bool:
    """Whether the lever writes the images at `a` and `b` (mm of the view
    drawn) as one name though they fall in two of its 0.5 mm cells: nearer
    than _MERGED_MM (task06_v5's s4 and k4, 0.13 mm apart, were two names
    crowding each other)."""
    return float(np.hypot(*(a - b))) < _MERGED_MM


def _spots(fa: ForceAnalysis, mu_V: float) -> np.ndarray:
    """Where the lever at `mu_V` writes a name of its images (mm): p and each
    image's spot, the images within 0.5 mm of one another in one."""
    spots: dict[tuple[int, int], np.ndarray] = {(0, 0): np.zeros(2)}
    for v in fa.lever.images.values():
        at = np.asarray(v, float) / mu_V
        spots.setdefault((round(float(at[0]) * 2), round(float(at[1]) * 2)), at)
    return np.array(list(spots.values()), dtype=float).reshape(-1, 2)


def _detail_ratio(
    where: np.ndarray, areas: np.ndarray, spots: np.ndarray, r: float
) -> float | None:
    """The first ratio of the series at which the disc of radius `r` (mm,
    `where`, `spots` relative to its centre) letters what it holds: its names
    NAME_SHARE of its room, its images' spots _SPOT_MM apart, and its view
    at most DETAIL_MM in radius (an arm shorter than ARM_NAMED_MM there is
    not drawn: the table of moments gives it); None if no ratio does."""
    inside = np.hypot(*where.T) <= r
    demand = float(areas[inside].sum())
    held = spots[np.hypot(*spots.T) <= r]
    gaps = np.hypot(*(held[:, None, :] - held[None, :, :]).transpose(2, 0, 1))
    closest = float(gaps[gaps > 0.0].min()) if (gaps > 0.0).any() else math.inf
    return next(
        (
            k
            for k in _LEVER_RATIOS
            if demand <= NAME_SHARE * math.pi * (k * r + NEAR_MM) ** 2
            and k * closest >= _SPOT_MM
            and k * r <= DETAIL_MM
        ),
        None,
    )


def lever_details(
    fa: ForceAnalysis,
    mu_V: float,
    crowded: np.ndarray,
    crowding: Callable[[tuple[LeverDetail, ...]], int] | None = None,
    *,
    enlarge: bool = False,
) -> tuple[LeverDetail, ...]:
    """The detail views the lever at `mu_V` needs where the names of what
    `crowded` names (mm, `crowded_ends` of the lever drawn without details)
    found no place near: at most _DETAILS discs apart, round p, an image or
    such a point, of a radius of _LEVER_RADII, each holding (drawing in its
    view) the most of those names left (of discs holding as many, the widest)
    among those lettered at a ratio of the series (`_detail_ratio`, the first
    such ratio), where one of them holds _LETTERED_SHARE of what the disc
    covering the most of their middles covers; else that disc (`choose_details`'
    rule), at the first ratio that leaves its names their room and names its
    shortest arm, or draws it DETAIL_MM wide; lettered by capitals that name
    no point of the mechanism. With `crowding` (how many names of the lever
    and its views stand far or on something, drawn with the details given),
    the wide disc is weighed against the disc lettered at its ratio (where
    that holds less than the share) and against itself made tighter, the
    widest whose view may be drawn at a larger ratio: all are drawn and the
    one leaving fewest names crowded taken, of as few the view drawn largest.
    The wide disc's low ratio may leave a tight crowd of images as tight as
    it was (gen 141: ten images within 2 mm of p, 4:1); the small disc's high
    ratio may leave the long arms round it crowding on the lever (gen 91).
    With `enlarge` (and `crowding`), each view taken is drawn at the next
    ratios of the series while that leaves fewer names crowded (`_enlarged`)."""
    names = _lever_names(fa, mu_V)
    where = np.array([n.at for n in names], dtype=float).reshape(-1, 2)
    areas = np.array([n.area for n in names])
    spots = _spots(fa, mu_V)
    crowded = np.asarray(crowded, dtype=float).reshape(-1, 4)
    centres = [np.zeros(2), *(n.at for n in names if n.arm_mm is None), *crowded[:, :2]]
    taken = {n[:1].upper() for n in fa.loads.state.mech.point_owners}
    letters = [x for x in DETAIL_LETTERS if x not in taken] or list(DETAIL_LETTERS)
    out: list[LeverDetail] = []
    left = np.ones(len(crowded), dtype=bool)  # the crowded names no disc taken holds

    def holds(c: np.ndarray, r: float) -> np.ndarray:
        """Which crowded names the disc draws: their points (both ends) in it."""
        a = np.hypot(*(crowded[:, :2] - c).T) <= r
        return a & (np.hypot(*(crowded[:, 2:] - c).T) <= r)

    def covers(c: np.ndarray, r: float) -> np.ndarray:
        """Which crowded names' middles the disc covers (a wide disc's measure)."""
        return np.hypot(*((crowded[:, :2] + crowded[:, 2:]) / 2.0 - c).T) <= r

    def disc(letter: str, c: np.ndarray, r: float, ratio: float | None) -> LeverDetail:
        """The detail view of the disc; with no ratio that letters it, at the
        first that leaves its names their room at least."""
        if ratio is None:
            inside = np.hypot(*(where - c).T) <= r
            demand = float(areas[inside].sum())
            shortest = min(
                (n.arm_mm for n, i in zip(names, inside) if i and n.arm_mm is not None),
                default=math.inf,
            )
            ratio = roomy_ratio(demand, r, shortest, ratios=_LEVER_RATIOS)
        return LeverDetail(letter, (float(c[0]) * mu_V, float(c[1]) * mu_V), r * mu_V, ratio)

    for letter in letters[:_DETAILS]:
        # the disc holding the most (of as many, the widest), and such a disc
        # of those lettered at a ratio: (held, radius), centre, ratio
        most: tuple[tuple[int, float], np.ndarray, float | None] | None = None
        lettered: tuple[tuple[int, float], np.ndarray, float | None] | None = None
        for c in centres:
            for r in _LEVER_RADII:
                if any(
                    math.dist(c, np.asarray(d.centre) / mu_V) < r + d.radius / mu_V for d in out
                ):
                    continue  # discs apart: a name is the lever's or one detail's
                covered = int((covers(c, r) & left).sum())
                held = int((holds(c, r) & left).sum())
                # a disc past the first holds an image at least, or its view
                # names nothing (gen 30: one round the middle of an arm from p,
                # p in the first: an arm is drawn in a view that holds it whole)
                empty = bool(out) and not (np.hypot(*(spots - c).T) <= r).any()
                if covered and not empty and (most is None or (covered, r) > most[0]):
                    most = ((covered, r), c, None)
                if not held:
                    continue
                ratio = _detail_ratio(where - c, areas, spots - c, r)
                if ratio is not None and (lettered is None or (held, r) > lettered[0]):
                    lettered = ((held, r), c, ratio)
        if most is None:
            break
        if lettered is not None and lettered[0][0] >= _LETTERED_SHARE * most[0][0]:
            options = [lettered]
        elif lettered is not None and crowding is not None:
            options = [most, lettered]  # both drawn: the one leaving fewer crowded
        else:
            options = [most]
        views = [disc(letter, c, r, ratio) for (_, r), c, ratio in options]
        (held, r), c, _ = options[0]
        # the wide disc made tighter, the widest whose view may be drawn at a
        # larger ratio than the wide one's (DETAIL_MM in radius at most)
        tighter = [
            (x, max(k for k in _LEVER_RATIOS if k * x <= DETAIL_MM))
            for x in sorted(_LEVER_RADII, reverse=True)
            if x < r and _LEVER_RATIOS[0] * x <= DETAIL_MM
        ]
        tighter = [(x, k) for x, k in tighter if k > views[0].ratio][:1]
        if crowding is not None and options[0] is most and tighter:
            options.append(((held, tighter[0][0]), c, tighter[0][1]))
            views.append(disc(letter, c, *tighter[0]))
        crowds = [crowding((*out, v)) for v in views] if crowding and len(views) > 1 else [0]
        # of as few, the view drawn largest: the lever reaches the sheet at its
        # textbook scale or smaller, and its views with it (gen 6: three discs
        # letter it at 1:0.004, the widest crowds at the 1:0.005 it reaches)
        k = min(range(len(views)), key=lambda i: (crowds[i], -views[i].ratio * views[i].radius))
        (_, r), c, _ = options[k]
        left &= ~(holds(c, r) | covers(c, r))
        view = views[k]
        if crowding is not None and enlarge:
            view = _enlarged(view, r, tuple(out), crowding, crowds[k] if len(views) > 1 else None)
        out.append(view)
    return tuple(out)


def _enlarged(
    view: LeverDetail,
    r: float,
    before: tuple[LeverDetail, ...],
    crowding: Callable[[tuple[LeverDetail, ...]], int],
    crowd: int | None = None,
) -> LeverDetail:
    """The detail view `view` (its disc `r` mm in radius on the lever, after
    the views `before`) drawn at the next ratios of the series, a step at a
    time while that leaves fewer names crowded (`crowding`; `crowd`: what it
    leaves as it is, where known) and the view stays DETAIL_MM in radius at
    most. A disc's ratio is chosen by the room its names take, as if they
    spread over it; a crowd packed in part of it (the images of points at
    rest round p, the arms along one line from p) wants more (gen 176: C at
    5:1 left 9 names crowded, at 10:1 3)."""
    larger = [k for k in _LEVER_RATIOS if k > view.ratio and k * r <= DETAIL_MM]
    if not larger:
        return view
    best = crowding((*before, view)) if crowd is None else crowd
    for ratio in larger:
        if not best:
            break
        bigger = dataclasses.replace(view, ratio=ratio)
        n = crowding((*before, bigger))
        if n >= best:
            break
        view, best = bigger, n
    return view


def lever_crowding(
    fa: ForceAnalysis, mu_V: float, look: Any, lang: Language
) -> Callable[[tuple[LeverDetail, ...]], int]:
    """How many names of the lever at `mu_V` and of its detail views the
    sheet linter finds far from what they name or on something, drawn with
    the detail views given (`lever_details`' weighing of two discs)."""

    def crowding(details: tuple[LeverDetail, ...]) -> int:
        views = [sketch_lever(fa, mu_V, look, lang, [], details, one_per_line=False)]
        views += [sketch_lever_detail(fa, mu_V, look, lang, d, one_per_line=False) for d in details]
        return sum(len(list(crowded(v, lang))) for v in views)

    return crowding


def detail_gid(details: Sequence[LeverDetail], detail: LeverDetail) -> str:
    """The drawing of sheet 2 that holds the detail view `detail` of `details`."""
    k = list(details).index(detail)
    return "zhukovsky-lever-detail" + (f"-{k + 1}" if k else "")


_clipped = clipped


def sketch_lever(
    fa: ForceAnalysis,
    mu_V: float,
    look: Any,
    lang: Language,
    arms: list[tuple[str, float]],
    details: Sequence[LeverDetail] = (),
    *,
    one_per_line: bool = True,
    again: Again | None = None,
    orders: int | None = None,
) -> Sketch:
    """The turned velocity plan to μV, every force at the image of its point
    and its arm about the pole p; `arms` receives (label, h mm) in order.
    With `details`, what lies in a detail's disc is drawn but lettered only in
    its detail view (`sketch_lever_detail`): there the forces at its images,
    their arms and the images' names; the disc is marked by a thin circle and
    its letter. Without `one_per_line`, every arm named on its own: the
    lever as its detail views are chosen by (`_lever_lettered`), its labels
    written again in `orders` orders at most (`Labels.write_later`; None:
    _RETRY_ORDERS). With
    `again`, lettered as on the laid-out sheet (_LEVER_AGAIN)."""
    if not one_per_line:
        return _lever_view(fa, mu_V, look, lang, arms, details, None, again=again, orders=orders)
    return _lever_lettered(fa, mu_V, look, lang, arms, details, None, again=again)


def sketch_lever_detail(
    fa: ForceAnalysis,
    mu_V: float,
    look: Any,
    lang: Language,
    detail: LeverDetail,
    *,
    one_per_line: bool = True,
    again: Again | None = None,
) -> Sketch:
    """The detail view `detail` of the lever drawn at `mu_V`: its disc at
    μV / ratio, titled "A (4:1)", the lines cut at the disc's edge, the forces
    at the images inside it with their arms, and every name there (without
    `one_per_line`, every arm named on its own; with `again`, as on the
    laid-out sheet: as `sketch_lever`)."""
    if not one_per_line:
        return _lever_view(fa, mu_V, look, lang, [], (detail,), detail, again=again)
    return _lever_lettered(fa, mu_V, look, lang, [], (detail,), detail, again=again)


def _lever_lettered(
    fa: ForceAnalysis,
    mu_V: float,
    look: Any,
    lang: Language,
    arms: list[tuple[str, float]],
    details: Sequence[LeverDetail],
    detail: LeverDetail | None,
    *,
    again: Again | None = None,
) -> Sketch:
    """The lever or its detail view (`_lever_view`), every arm named on its
    own; where some name then stands far or on something, drawn again with
    the arms along one line from p named by one label, "h_{3,13,15}", along
    the longest (`_one_per_line`), and kept where that leaves fewer crowded
    (gen 88: the arms of G_2, G_3, G_13 and G_15 all run left from p along
    the horizontal, their names stacked under it far from it), and where its
    box is no wider nor taller than the lever's drawn so: the sheet is laid
    out by it. Only the drawings the sheet draws: the detail views are chosen
    by the lever with every arm named on its own (gen 222: chosen by the
    lever so lettered, a view round other images crowded more)."""
    own: list[tuple[str, float]] = []
    lines: list[int] = []  # how many arms' labels one per line would save
    sk = _lever_view(fa, mu_V, look, lang, own, details, detail, lines=lines, again=again)
    arms += own
    counts = sk.label_counts
    if counts is None or not (counts.far or counts.unsettled) or not lines[0]:
        return sk
    merged = _lever_view(fa, mu_V, look, lang, [], details, detail, merge_arms=True, again=again)
    grown, box = merged.extent(), sk.extent()
    if grown.width > box.width + 1e-6 or grown.height > box.height + 1e-6:
        return sk  # a drawing is fitted on the sheet by its box (gen 153: 6 mm taller)
    before = len(list(crowded(sk, lang)))
    return merged if len(list(crowded(merged, lang))) < before else sk


def _one_per_line(
    feet: Mapping[Any, tuple[np.ndarray, list[str]]],
) -> list[tuple[np.ndarray, list[str]]]:
    """The arms' feet (mm from p) with their numbers, those along one line
    from p (each foot within _ON_LINE_MM of the line to the farthest) as
    one: the farthest foot with all their numbers, in order."""
    out: list[tuple[np.ndarray, list[str]]] = []
    for foot, numbers in sorted(feet.values(), key=lambda fn: -float(np.hypot(*fn[0]))):
        for far, names in out:
            u = far / float(np.hypot(*far))
            if (
                float(np.dot(foot, u)) > 0.0
                and abs(float(u[0] * foot[1] - u[1] * foot[0])) <= _ON_LINE_MM
            ):
                names += numbers
                break
        else:
            out.append((foot, list(numbers)))
    return [(foot, sorted(names, key=int)) for foot, names in out]


# the lever's views drawn while one sheet 2 is composed, by what they draw
# (None: no sheet being composed): lever_details weighs views (lever_crowding)
# that the composers then draw again, and the plain, compact and detailed
# composers draw the same ones (gen 176: 60 views, 10 of them again, 1.2 s)
_VIEWS: dict[tuple[Any, ...], tuple[Sketch, list[tuple[str, float]], list[int]]] | None = None


def _views_kept(compose: Callable[_P, _R]) -> Callable[_P, _R]:
    """`compose` with each view of the lever drawn once while it runs."""

    @functools.wraps(compose)
    def composing(*args: _P.args, **kwargs: _P.kwargs) -> _R:
        global _VIEWS
        outer = _VIEWS
        _VIEWS = {} if outer is None else outer
        try:
            return compose(*args, **kwargs)
        finally:
            _VIEWS = outer

    return composing


def _view_kept(draw: Callable[..., Sketch]) -> Callable[..., Sketch]:
    """`_lever_view` drawn once per sheet 2 for the same arguments (a view is
    a function of them; the arms and the labels saved it gives handed out
    again), where the arms start empty (their numbers go on from those given)."""

    @functools.wraps(draw)
    def view(
        fa: ForceAnalysis,
        mu_V: float,
        look: Any,
        lang: Language,
        arms: list[tuple[str, float]],
        details: Sequence[LeverDetail],
        detail: LeverDetail | None,
        *,
        merge_arms: bool = False,
        lines: list[int] | None = None,
        again: Again | None = None,
        orders: int | None = None,
    ) -> Sketch:
        orders = _RETRY_ORDERS if orders is None else orders
        kw = dict(merge_arms=merge_arms, again=again, orders=orders)
        if _VIEWS is None or arms:
            return draw(fa, mu_V, look, lang, arms, details, detail, lines=lines, **kw)
        key = (id(fa), id(look), lang, mu_V, tuple(details), detail, merge_arms, again, orders)
        if key not in _VIEWS:
            own: tuple[list[tuple[str, float]], list[int]] = ([], [])
            sketch = draw(fa, mu_V, look, lang, own[0], details, detail, lines=own[1], **kw)
            _VIEWS[key] = (sketch, *own)
            if not _counts(sketch).far:
                # lettered in fewer orders with none far: in every order the
                # same (Labels.write_later writes none after one with none far)
                _VIEWS.setdefault(key[:-1] + (_RETRY_ORDERS,), (sketch, *own))
        sketch, own_arms, own_lines = _VIEWS[key]
        arms += own_arms
        if lines is not None:
            lines += own_lines
        return sketch

    return view


@_view_kept
def _lever_view(
    fa: ForceAnalysis,
    mu_V: float,
    look: Any,
    lang: Language,
    arms: list[tuple[str, float]],
    details: Sequence[LeverDetail],
    detail: LeverDetail | None,
    *,
    merge_arms: bool = False,
    lines: list[int] | None = None,
    again: Again | None = None,
    orders: int = _RETRY_ORDERS,
) -> Sketch:
    """The lever with `details` marked (`detail` None), or the detail view
    `detail`; with `merge_arms`, the arms along one line from p named by
    one label (`_one_per_line`); `lines` receives how many labels that saves;
    with `again`, lettered as on the laid-out sheet (_LEVER_AGAIN); its
    labels written again in `orders` orders at most (`_view_kept` gives
    _RETRY_ORDERS for None)."""
    in_detail = detail is not None
    lever = fa.lever
    mech = fa.loads.state.mech
    sk = Sketch(look)
    labelling = _LEVER_AGAIN if again is not None else _LABELLING
    labels = Labels(sk, _TEXT, **labelling, words=_index_words(lang))
    mu = mu_V / detail.ratio if detail is not None else mu_V
    img = {n: np.asarray(v, float) / mu for n, v in lever.images.items()}
    discs = [(np.asarray(d.centre, float) / mu, d.radius / mu) for d in details]
    centre, radius = discs[0] if detail is not None else (np.zeros(2), 0.0)

    def inside(at: np.ndarray) -> bool:
        """Whether `at` lies in a detail's disc (in this view's own)."""
        return any(float(np.hypot(*(at - c))) <= r for c, r in discs)

    def here(at: np.ndarray) -> bool:
        """Whether what stands at `at` is drawn and named in this view."""
        return inside(at) if in_detail else not inside(at)

    def line(a: Any, b: Any, kind: LineType) -> None:
        a, b = np.asarray(a, float), np.asarray(b, float)
        part = _clipped(a, b, centre, radius) if in_detail else (a, b)
        if part is not None:
            sk.line(part[0], part[1], kind)

    dotted: set[str] = set()  # images of S_i and K_i marked with a dot
    gid = detail_gid(details, detail) if detail is not None else "zhukovsky-lever"
    with sk.group(gid, "lever"):
        joints = [n for n in img if not re.fullmatch(r"[SK]\d+", n)]
        for n in joints:
            if float(np.hypot(*img[n])) >= 0.5:
                line((0.0, 0.0), img[n], "thin")
        for link in mech.links.values():
            names = [p for p in link.points if p in img]
            for i in range(len(names)):
                for j in range(i + 1, len(names)):
                    line(img[names[i]], img[names[j]], "main")
        # the images named, those at one point in one label: "d, s_{5}, k_{5}"
        marks: dict[tuple[int, int], tuple[np.ndarray, list[str]]] = {}

        def mark(markup: str, at: np.ndarray) -> None:
            if not here(at):
                return
            key = (round(float(at[0]) * 2), round(float(at[1]) * 2))
            if key not in marks:  # nearer one in the next cell: one name all the same
                near = (k for k, (spot, _) in marks.items() if _one_spot(spot, at))
                key = next(near, key)
            marks.setdefault(key, (at, []))[1].append(markup)

        mark("p", np.zeros(2))  # the pole: no image is written p (image_markup)
        for n in joints:
            if float(np.hypot(*img[n])) >= 0.5:
                mark(image_markup(n, tuple(mech.point_owners)), img[n])
        if here(np.zeros(2)):
            sk.circle((0.0, 0.0), 0.8, "main", "black")
            labels.avoid_circle((0.0, 0.0), 1.2)
        forces = [*lever.forces, lever.balancing]
        feet: dict[tuple[int, int], tuple[np.ndarray, list[str]]] = {}
        largest = max(float(np.hypot(*f.force)) for f in forces)
        # (start, end, labels): forces along one line of action in one sense
        # (F_PR and F_in5 at e) are one arrow with both names
        drawn: list[tuple[np.ndarray, np.ndarray, list[str]]] = []
        for f in forces:
            size = float(np.hypot(*f.force))
            if size <= 1e-9 * largest:
                continue
            at = np.asarray(f.image, float) / mu
            u = np.asarray(f.force, float) / size
            end = at + _arrow_length(size, largest) * u
            if here(at):
                for k, (s0, e0, names) in enumerate(drawn):
                    if _coincident(s0, e0, at, end) and float(np.dot(e0 - s0, u)) > 0.0:
                        ts = [0.0, float(np.dot(e0 - s0, u)), float(np.dot(at - s0, u))]
                        ts.append(float(np.dot(end - s0, u)))
                        drawn[k] = (s0 + min(ts) * u, s0 + max(ts) * u, [*names, f.label])
                        break
                else:
                    drawn.append((at, end, [f.label]))
            if here(at) and re.fullmatch(r"[SK]\d+", f.point) and f.point not in dotted:
                dotted.add(f.point)
                sk.circle(at, 0.6, "thin", "black")
                mark(image_markup(f.point, tuple(mech.point_owners)), at)
            h = abs(f.arm) / mu
            arms.append((f.label, abs(f.arm) / mu_V))
            # an arm is drawn 1 mm long at least; in a detail view long enough
            # to be named along (a shorter one the table of moments gives)
            if h >= (ARM_NAMED_MM if in_detail and here(at) else 1.0):
                foot = at - float(np.dot(at, u)) * u
                # an arm is the detail's where all of it lies in the disc
                whole = any(
                    max(float(np.hypot(*(q - c))) for q in (at, foot, np.zeros(2))) <= r
                    for c, r in discs
                )
                if in_detail and not whole:
                    line((0.0, 0.0), foot, "thin")  # cut at the disc's edge, named on the lever
                    line(at, foot, "thin")
                    continue
                if not in_detail and whole:
                    continue
                sk.line((0.0, 0.0), foot, "thin")
                sk.line(at, foot, "thin")
                # forces on one line of action share their arm: one label, h_{10,11}
                key = (round(float(foot[0]) * 2), round(float(foot[1]) * 2))
                feet.setdefault(key, (foot, []))[1].append(str(len(arms)))
        for d, (c, r) in zip(details if not in_detail else (), discs):
            sk.circle(c, r, "thin")
            rim, towards = rim_anchors(c, r)[0]  # up and right
            labels.later(rim, d.letter, towards)
        for at, names in marks.values():
            pole = float(np.hypot(*at)) < 0.5
            labels.later(at, ", ".join(names), np.array([-1.0, -1.0]) if pole else at)
        # forces along one line in opposite senses: side by side, as in the polygons
        placed: list[tuple[np.ndarray, np.ndarray]] = []
        for start, end, names in drawn:
            shift = _beside(start, end, placed)
            start, end = start + shift, end + shift
            placed.append((start, end))
            sk.arrow(start, end, "main", **_ARROW)  # type: ignore[arg-type]
            markup = ", ".join(force_markup(n) for n in names)
            labels.later_arrow(start, end, markup, _SHAFT_ALONG)
        merged = _one_per_line(feet)
        if lines is not None:
            lines.append(len(feet) - len(merged))
        for foot, numbers in merged if merge_arms else feet.values():
            labels.later_along(np.zeros(2), foot, f"h_{{{','.join(numbers)}}}", _ARM_ALONG)
        labels.write_later(retry=orders, grow=again == "grow")
        sk.label_counts = labels.counts()
        ext = sk.extent()
        if detail is not None:
            ratio = catalogue(lang).plain_number(detail.ratio)
            title = _words(lang)["lever_detail"].format(letter=detail.letter, ratio=ratio)
            sk.text((ext.left + _PAD, ext.top + 3.0), title, _TITLE)
            return sk
        sk.rich_text((ext.left + _PAD, ext.bottom - 5.0), _words(lang)["equation"], _TEXT)
        sk.rich_text(
            (ext.left + _PAD, ext.bottom - 11.0),
            scale_label(mu_V, "velocity", lang).markup(),
            _TEXT,
        )
        sk.text((ext.left + _PAD, ext.top + 3.0), _words(lang)["lever"], _TITLE)
    return sk


# --- tables -----------------------------------------------------------------------------


def _table(
    look: Any,
    gid: str,
    title: str,
    header: Sequence[str],
    rows: Sequence[Sequence[str]],
    widths: Sequence[float],
    marks: Sequence[str],
    lang: Language,
    number: int | None = None,
) -> Sketch:
    """table_sketch with the header cells that carry indices (a_{S}, R^{n})
    lettered as rich text: split after the comma onto two lines if too wide.
    With a `number` (a compact sheet, _Composer), the table is titled "Table
    n – …" and continues in parts no taller than TABLE_PART_MM."""
    rich = [bool(re.search(r"[_^]", h)) for h in header]
    if number is not None:
        return _continued_table(look, gid, title, header, rows, widths, marks, lang, number)
    sk = table_sketch(
        look,
        gid,
        title,
        [("" if r else h) for h, r in zip(header, rich)],
        rows,
        widths,
        marks,
        lang,
    )
    extra = Sketch(look)
    probe = Sketch(look)
    mid_y = -(_TEXT + 3.0) - 6.0  # the middle of table_sketch's 12 mm header under its title
    x = 0.0
    for h, r, w in zip(header, rich, widths):
        if r:
            lines = _header_lines(probe, h, w)
            pitch = 4.8
            for k, line in enumerate(lines):
                y = mid_y + pitch * ((len(lines) - 1) / 2 - k)
                extra.rich_text((x + w / 2, y), line, _TEXT, anchor="center", valign="middle")
        x += w
    sk.add_to_last_group(extra, gid)
    return sk


def _header_lines(probe: Sketch, header: str, width: float) -> list[str]:
    """An indexed header cell's lettering: split after its comma onto two
    lines where it is wider than its column."""
    if probe.rich_text((0.0, 0.0), header, _TEXT) > width - 2.0 and ", " in header:
        head, unit = header.split(", ", 1)
        return [head + ",", unit]
    return [header]


# the tables of a compact sheet 2 numbered in the order the analysis makes them
_TABLE_NUMBERS = {"table-loads": 1, "table-reactions": 2, "table-lever": 3, "table-balancing": 4}


def _continued_table(
    look: Any,
    gid: str,
    title: str,
    header: Sequence[str],
    rows: Sequence[Sequence[str]],
    widths: Sequence[float],
    marks: Sequence[str],
    lang: Language,
    number: int,
) -> Sketch:
    """_table numbered, in parts no taller than TABLE_PART_MM side by side,
    each repeating the header (GOST 2.105): the indexed header cells given to
    table_sketch as markup so that every part letters them."""
    w = _words(lang)
    probe = Sketch(look)
    header_marks: list[str | None] = []
    for h, width in zip(header, widths):
        indexed = re.search(r"[_^]", h)
        header_marks.append("\n".join(_header_lines(probe, h, width)) if indexed else None)
    return table_sketch(
        look,
        gid,
        w["table_numbered"].format(n=number, title=title),
        header,
        rows,
        widths,
        marks,
        lang,
        header_markup=header_marks,
        max_height=TABLE_PART_MM,
        continued=w["table_continued"].format(n=number),
    )


def sketch_loads_table(
    fa: ForceAnalysis, mu_l: float, look: Any, lang: Language, compact: bool = False
) -> Sketch:
    """G, F_IN, M_IN and the arm h of every link; h in mm of the drawing at μ_l (19)."""
    w = _words(lang)
    rows, marks = [], []
    for lid, ll in fa.loads.links.items():
        sh = ll.shifted_inertia_force
        rows.append(
            [
                str(lid),
                _num(ll.mass),
                _num(float(np.hypot(*ll.weight))),
                _num(float(np.hypot(*ll.acceleration_cm))),
                _num(float(np.hypot(*ll.inertia_force))),
                _num(ll.J),
                _num(ll.eps),
                _num(ll.inertia_moment),
                "—" if sh is None else _num(sh.arm / mu_l),
            ]
        )
        marks.append(str(lid))
    header = [w["link"], *w["loads_header"]]
    return _table(
        look,
        "table-loads",
        w["loads"].format(i=fa.index),
        header,
        rows,
        [12.0, 14.0, 16.0, 16.0, 16.0, 16.0, 16.0, 16.0, 14.0],
        marks,
        lang,
        _TABLE_NUMBERS["table-loads"] if compact else None,
    )


def _sketch_tables(
    fa: ForceAnalysis,
    arms: Sequence[tuple[str, float]],
    look: Any,
    lang: Language,
    compact: bool = False,
) -> dict[str, Sketch]:
    w = _words(lang)
    out: dict[str, Sketch] = {}
    rows, marks = [], []
    for name, r in fa.reactions.items():
        comps = {c.label[-1]: c.value for c in r.components}
        rows.append(
            [
                name,
                _num(r.magnitude),
                _num(float(r.force[0])),
                _num(float(r.force[1])),
                _num(abs(comps["n"])) if "n" in comps else "—",
                _num(abs(comps["t"])) if "t" in comps else "—",
            ]
        )
        marks.append(force_markup(name))
    out["table-reactions"] = _table(
        look,
        "table-reactions",
        w["reactions"],
        [w["pair"], "|R|", "R_{x}", "R_{y}", "|R^{n}|", "|R^{τ}|"],
        rows,
        [16.0, 18.0, 18.0, 18.0, 18.0, 18.0],
        marks,
        lang,
        _TABLE_NUMBERS["table-reactions"] if compact else None,
    )
    rows, marks = [], []
    by_label = {f.label: f for f in (*fa.lever.forces, fa.lever.balancing)}
    for k, (label, h) in enumerate(arms, 1):
        f = by_label[label]
        rows.append(
            [
                label,
                str(k),
                _num(float(np.hypot(*f.force))),
                _num(h),
                _num(float(np.hypot(*f.force)) * h * math.copysign(1.0, f.moment)),
            ]
        )
        marks.append(force_markup(label))
    out["table-lever"] = _table(
        look,
        "table-lever",
        w["lever_table"],
        [w["force"], *w["lever_header"]],
        rows,
        [16.0, 12.0, 18.0, 16.0, 22.0],
        marks,
        lang,
        _TABLE_NUMBERS["table-lever"] if compact else None,
    )
    d = fa.discrepancy_percent
    rows = [
        ["", _num(fa.balancing_force_plans, 6)],
        ["", _num(fa.balancing_force_lever, 6)],
        ["", "—" if math.isnan(d) else f"{d:.2f}"],
        ["", _num(fa.balancing_moment, 6)],
    ]
    out["table-balancing"] = _table(
        look,
        "table-balancing",
        w["balancing"],
        [w["quantity"], w["value"]],
        rows,
        [66.0, 24.0],
        [w["plans"], w["by_lever"], w["delta"], w["moment"]],
        lang,
        _TABLE_NUMBERS["table-balancing"] if compact else None,
    )
    return out


# --- composing --------------------------------------------------------------------------


def guide_side(polygons: Sequence[ForcePolygon]) -> float:
    """The force the guide's 150 … 300 mm is for (seed 003 §2.6): |F_PR| where
    the polygons carry the production resistance, else their largest side, N."""
    resistance = [v.magnitude for p in polygons for v in p.vectors if v.label.startswith("F_PR")]
    largest = max((p.largest for p in polygons), default=0.0)
    # F_PR at 150 mm must leave the largest side within 300 mm
    if resistance and max(resistance) * FORCE_PLAN.high / FORCE_PLAN.low >= largest > 0.0:
        return max(resistance)
    return largest


def _force_scale(polygons: Sequence[ForcePolygon], steps: int = 0, held: bool = True) -> float:
    """μF so that the guide's side (guide_side) is 150 … 300 mm, `steps` series
    values coarser to fit the sheet (finer, negative, to fill it), but never so
    coarse that F_PR falls under 150 mm while `held` (compose_sheet2 lets it go
    only where the sheet has no arrangement with it held)."""
    side = guide_side(polygons)
    if side <= 0:
        return 1.0
    mu = scale_for(side, FORCE_PLAN)
    if not held or not any(v.label.startswith("F_PR") for p in polygons for v in p.vectors):
        # the guide is the production resistance's: the other groups' polygons
        # may go coarser with the rest of the sheet
        return scale_step(mu, steps)
    limit = side / FORCE_PLAN.low
    coarsest = max(series(mu, limit), default=mu) if limit >= mu else mu
    # no side past the guide's 300 mm where a series value keeps |F_PR| at
    # 150 mm or more too; where none does (the series' steps are coarse), the
    # guide's own rule, |F_PR| = 150 … 300 mm (seed 003, formula (20)), wins
    largest = max((p.largest for p in polygons), default=0.0)
    finest = next(iter(series(largest / FORCE_PLAN.high * (1 - 1e-9), largest)))
    return max(min(scale_step(mu, steps), coarsest), min(finest, coarsest))


def _polygon_note(polygons: Sequence[ForcePolygon], mu_F: float, lang: Language) -> str:
    """Why the force polygons are drawn below the guide's 150 mm: their
    guide side (guide_side: |F_PR| where the guide sizes by it, else the
    largest side) drawn shorter (empty when it is not)."""
    # the guide's measure: |F_PR| where it sizes the polygon (guide_side)
    drawn = guide_side(polygons) / mu_F
    if drawn <= 0.0 or drawn >= FORCE_PLAN.low * (1 - 1e-9):
        return ""
    return str(_words(lang)["polygon_reduced"]).format(
        mm=f"{drawn:.0f}", lo=f"{FORCE_PLAN.low:g}", hi=f"{FORCE_PLAN.high:g}"
    )


# indices of the textbook's symbols that differ by language


def _index_words(lang: Language) -> Callable[[str], str]:
    """A label's markup with the symbols' indices in `lang` ("F_{in4}" →
    "F_{i4}"), as the placer measures and writes it: the box it keeps free is
    the lettering's own."""
    runs = {k: str(v) for k, v in catalogue(lang).words("symbol_indices").items() if k != v}
    if not runs:
        return lambda markup: markup
    index = re.compile(f"_{{({'|'.join(map(re.escape, runs))})(\\d*)}}")
    return lambda markup: index.sub(lambda m: f"_{{{runs[m.group(1)]}{m.group(2)}}}", markup)


def _translated(sketch: Sketch, lang: Language) -> Sketch:
    """The sketch with its lettering runs in `lang`: F_bal is F_зр on a Ukrainian sheet."""
    runs = {k: str(v) for k, v in catalogue(lang).words("symbol_indices").items() if k != v}
    if not runs:
        return sketch
    # an index run: the symbol's index and the link's number ("in4" → "i4")
    index = re.compile(f"^({'|'.join(map(re.escape, runs))})(\\d*)$")
    for i, c in enumerate(sketch.calls):
        if c.name == "text" and (m := index.match(c["content"])) is not None:
            sketch.calls[i] = c.with_changes(content=runs[m.group(1)] + m.group(2))
    return sketch


def _with_note(sketch: Sketch, note: str) -> Sketch:
    """A copy of a drawing with one more line of lettering under its notes."""
    out = Sketch(sketch.look)
    out.calls = list(sketch.calls)
    ext = sketch.extent()
    extra = Sketch(sketch.look)
    extra.rich_text((ext.left + _PAD, ext.bottom - 3.0), note, _TEXT)
    gid = next(c["id"] for c in sketch.calls if c.name == "begin_group")
    out.add_to_last_group(extra, gid)
    # its labels as the drawing's: the composer counts them on the copy
    out.label_counts = sketch.label_counts
    return out


COMPACT_EQUATION_MM = 90.0  # a compact sheet's equations under the polygons, at most
_LEVER_MAX = 250.0  # mm: the longest pa the lever is enlarged to
# the lever's textbook scale draws pa 100–200 mm (the velocity plan's); where
# its longest image would run past this even _COARSEST steps coarser (a point
# far faster than the crank's, a 10:1 link), the scale that draws that image
# 100–200 mm
_LEVER_REACH_MM = 400.0
_ORDERS = 16  # orders of the drawings tried beyond the textbook's and by size
_PARTS_FINER = 1  # series steps a group may be drawn larger or smaller than the loaded mechanism
_COARSEST = 5  # series steps coarser than its textbook scale a drawing may go
_FINEST = -6  # series steps finer than its textbook scale a drawing may go
# first_fit asks whether the coarsest scales fit once this shrink fits nowhere:
# a step past the textbook's (asked at the textbook's, the question took 30-58 %
# of a generated sheet 2 of four or five groups, every one of which held them)
_COARSEST_CHECK = 1
# first_fit asks about the coarsest scales at once where the first scales
# tried take this many times the field by their least area
_HOPELESS = 1.5
_FILL_PASSES = 2 * (12 - _FINEST)  # a bound on fill's passes (each a step of some kind)
_UNWALL_PASSES = 4  # drawings enlarged at most this many times for their far names (unwall)


def _counts(sketch: Sketch) -> LabelCounts:
    """How well a drawing's labels found room (none written: nothing missed)."""
    return sketch.label_counts or LabelCounts(0, 0)


def _lever_scale(lever: Any) -> float:
    """The lever's μV at its textbook scale (_LEVER_REACH_MM)."""
    mu = scale_for(lever.pa, VELOCITY_PLAN)
    reach = max((float(np.hypot(*v)) for v in lever.images.values()), default=0.0)
    if reach / scale_step(mu, _COARSEST) > _LEVER_REACH_MM:
        return scale_for(reach, VELOCITY_PLAN)
    return mu


class _Composer:
    """The drawings of sheet 2 at scales given as series steps from the
    textbook's, each drawing made once per scale, and their layout."""

    def __init__(
        self,
        fa: ForceAnalysis,
        solution: Solution,
        look: Any,
        lang: Language,
        page: Page,
        compact: bool = False,
        details: bool = True,
        mechanism_details: tuple[Detail, ...] = (),
        lever_views: tuple[LeverDetail, ...] | None = None,
        groups: Sequence[GroupForces] | None = None,
        held: bool = True,
    ) -> None:
        self.fa, self.look, self.lang, self.page = fa, look, lang, page
        # the polygon that carries F_PR kept at |F_PR| >= 150 mm (_force_scale)
        self.held = held
        # the groups drawn here with their polygons: every one, or none where
        # they continue on further sheets (further_groups)
        self.groups = tuple(fa.groups if groups is None else groups)
        # the loaded mechanism's detail views (compose_sheet2 finds them on
        # the mechanism that reached the sheet without)
        self.mechanism_details = mechanism_details
        # compact (compose_sheet2's reduction for a sheet of many groups): the
        # equations under the polygons in lines of COMPACT_EQUATION_MM, the
        # tables numbered and continued in parts (GOST 2.105)
        self.compact = compact
        self.mu0 = float(solution.mu_l)
        self.lever_mu = _lever_scale(fa.lever)
        self.cache: dict[tuple[Any, ...], Any] = {}
        self._extents: dict[int, Rect] = {}
        dl = fa.driving_link
        self.polygon_sets: list[tuple[str, Sequence[ForcePolygon], str]] = [
            *((g.name, g.polygons, f"group {g.name}") for g in self.groups),
            (str(dl.link), (dl.polygon,), f"link {dl.link}"),
        ]
        self.tables = ["table-balancing", "table-reactions", "table-loads", "table-lever"]
        self.drawings = ["force-mechanism", "zhukovsky-lever"]
        for g in self.groups:
            self.drawings += [f"group-{g.name}", f"force-polygon-{g.name}"]
        self.drawings += ["driving-link", f"force-polygon-{dl.link}"]
        # where the lever's names crowd at its textbook scale, a detail view of them
        # (or `lever_views`: those found on the lever as it reached the sheet,
        # where the lever at its textbook scale is not drawn at all)
        arms: list[tuple[str, float]] = []
        self.allows_details = details
        if lever_views:
            self.details = lever_views
        else:
            choose = details and lever_views is None
            # where its names crowd, asked of the lever lettered in fewer
            # orders (_CROWD_ORDERS): where none stands far it is the lever
            # lettered in all of them (no order after one with none far)
            orders = min(_CROWD_ORDERS, _RETRY_ORDERS) if choose else _RETRY_ORDERS
            plain = sketch_lever(
                fa, self.lever_mu, look, lang, arms, one_per_line=False, orders=orders
            )
            self.details = (
                lever_details(
                    fa,
                    self.lever_mu,
                    crowded_ends(plain, lang),
                    lever_crowding(fa, self.lever_mu, look, lang),
                )
                if choose
                else ()
            )
            if not self.details and _counts(plain).far and orders != _RETRY_ORDERS:
                # the lever drawn on the sheet as it is: lettered in every order
                arms.clear()
                plain = sketch_lever(fa, self.lever_mu, look, lang, arms, one_per_line=False)
        self.drawings += [detail_gid(self.details, d) for d in self.details]
        self.drawings += [loaded_detail_gid(mechanism_details, d) for d in mechanism_details]
        if not self.details:  # the lever at its textbook scale is drawn: kept
            tables = _sketch_tables(fa, arms, look, lang, compact)
            self.cache[("lever", self.lever_mu)] = (plain, arms, tables)
        self.last: Exception | None = None
        # where pack put each drawing after the same ones before it (arrange's
        # trials share the start of their orders)
        self.packed: dict[Any, tuple[float, float] | None] = {}
        # the pins each drawing of links draws, in m: its extent at μ_l holds
        # their box / μ_l (each pin a circle round its point) and PAD round it
        mech = fa.loads.state.mech
        self._pins: list[tuple[str, np.ndarray]] = [
            ("mu_l", self._pin_points(set(mech.links) - {FRAME})),
            *((f"mu_l {g.name}", self._pin_points(set(g.links))) for g in self.groups),
            (f"mu_l {dl.link}", self._pin_points({dl.link})),
        ]

    def again(self, solution: Solution, **changes: Any) -> _Composer:
        """A composer of the same sheet afresh with `changes` (the
        constructor's keywords), every other choice made so far kept: how
        compact, whether the lever may have detail views and which it has
        (those found on the lever as it reached the sheet are not found
        again at its textbook scale: gen 153 uk's A and B, lost when the
        sheet was composed again for the loaded mechanism's view, left k9
        9.8 mm off), the loaded mechanism's views, the groups drawn, whether
        F_PR's polygon is held."""
        kept: dict[str, Any] = dict(
            compact=self.compact,
            details=self.allows_details,
            lever_views=self.details or None,
            mechanism_details=self.mechanism_details,
            groups=self.groups,
            held=self.held,
        )
        return _Composer(self.fa, solution, self.look, self.lang, self.page, **{**kept, **changes})

    def with_mechanism_details(self, details: tuple[Detail, ...]) -> None:
        """The loaded mechanism drawn with `details` from now on: what the
        sheet's fits and packing found forgotten (the sketches are kept: their
        extents are known by id)."""
        self.drawings = [d for d in self.drawings if not d.startswith("force-mechanism-detail")]
        self.mechanism_details = details
        self.drawings += [loaded_detail_gid(details, d) for d in details]
        for key in [k for k in self.cache if k[0] in ("fits", "fits at", "bounded")]:
            del self.cache[key]
        self.packed = {}

    def shared_drawings(self, other: _Composer | None = None) -> dict[tuple[Any, ...], Any]:
        """The drawings of links made so far, which a compact sheet draws the
        same (its polygons, tables and the sketches holding them differ); for
        `other`, as compact as this one, the polygons, the table of loads and
        the loaded mechanism too (keyed by its details), and the lever with
        its tables and detail views where it has the same ones."""

        def same(k: tuple[Any, ...]) -> bool:
            if k[0] in ("group", "driving-link") or (k[0] == "noted" and isinstance(k[1], int)):
                return True
            if other is None or other.compact != self.compact:
                return False
            if k[0] in ("lever", "lever-detail"):
                return other.details == self.details
            return (
                k[0].startswith("force-polygon-")
                or k[0] in ("noted", "table-loads", "force-mechanism")
                or (k[0] == "head" and other.page is self.page)
            )

        return {k: v for k, v in self.cache.items() if same(k)}

    def _pin_points(self, lids: set[int]) -> np.ndarray:
        """The points (m) of the revolute pairs that _Drawing.links draws for `lids`."""
        state = self.fa.loads.state
        out = []
        for pin in state.mech.revolutes:
            moving = [lk for lk in pin.links if lk != FRAME]
            if any(lk in lids for lk in moving):
                out.append(_xy(_c(state.point(moving[0], pin.point))))
        return np.array(out, dtype=float).reshape(-1, 2)

    def least_area(self, scales: dict[str, float]) -> float:
        """A lower bound of the area (mm²) the drawings and tables take at
        `scales`, sketching none of the drawings of links: the loaded
        mechanism, the groups and the driving link each no smaller than the
        box of their pins; the lever with its tables and the polygons as
        sketched (without a polygon's note), the table of loads as nothing."""
        return sum(area for _, area in self._least_parts(scales))

    def lever(self, mu_V: float) -> tuple[Sketch, list[tuple[str, float]], dict[str, Sketch]]:
        """The lever at `mu_V`, its arms and the tables that read them."""

        def make() -> tuple[Sketch, list[tuple[str, float]], dict[str, Sketch]]:
            arms: list[tuple[str, float]] = []
            sketch = sketch_lever(self.fa, mu_V, self.look, self.lang, arms, self.details)
            return sketch, arms, _sketch_tables(self.fa, arms, self.look, self.lang, self.compact)

        return self.memo(("lever", mu_V), make)  # type: ignore[no-any-return]

    def lever_details(self, mu_V: float) -> list[tuple[str, Sketch]]:
        """The detail views of the lever at `mu_V` (drawing, sketch)."""
        return [
            (
                detail_gid(self.details, d),
                self.memo(
                    ("lever-detail", d.letter, mu_V),
                    lambda d=d: sketch_lever_detail(self.fa, mu_V, self.look, self.lang, d),
                ),
            )
            for d in self.details
        ]

    def polygons(
        self, name: str, polygons: Sequence[ForcePolygon], title: str, mu_F: float
    ) -> Sketch:
        """The force polygons `polygons` of `name` at `mu_F`, without a note."""
        gid = f"force-polygon-{name}"
        return self.memo(  # type: ignore[no-any-return]
            (gid, mu_F),
            lambda: sketch_force_polygons(
                polygons,
                mu_F,
                self.look,
                self.lang,
                gid,
                title,
                COMPACT_EQUATION_MM if self.compact else None,
            ),
        )

    def extent(self, sketch: Sketch) -> Rect:
        if id(sketch) not in self._extents:
            self._extents[id(sketch)] = sketch.extent()
        return self._extents[id(sketch)]

    def memo(self, key: tuple[Any, ...], make: Any) -> Any:
        if key not in self.cache:
            self.cache[key] = make()
        return self.cache[key]

    def scales(self, steps: dict[str, int]) -> dict[str, float]:
        """μ of every drawing at `steps` series steps from its textbook scale
        (negative: finer, the drawing larger)."""
        out: dict[str, float] = {}
        for g in self.groups:
            out[f"mu_l {g.name}"] = length_scale_step(self.mu0, steps[f"group {g.name}"])
        out[f"mu_l {self.fa.driving_link.link}"] = length_scale_step(self.mu0, steps["driving"])
        for name, polygons, _ in self.polygon_sets:
            out[f"mu_F {name}"] = _force_scale(polygons, steps[f"poly {name}"], self.held)
        out["mu_V"] = scale_step(self.lever_mu, steps["lever"])
        out["mu_l"] = length_scale_step(self.mu0, steps["mech"])
        return out

    def sketches(
        self, scales: dict[str, float]
    ) -> tuple[dict[str, Sketch], list[tuple[str, float]]]:
        arms: list[tuple[str, float]] = []
        return dict(self._sketched(scales, arms)), arms

    def _sketched(
        self, scales: dict[str, float], arms: list[tuple[str, float]], mechanism: bool = True
    ) -> Iterator[tuple[str, Sketch]]:
        """The drawings and tables at `scales` one at a time (name, sketch),
        the lever's arms into `arms`; the loaded mechanism last (not without `mechanism`)."""
        fa, look, lang = self.fa, self.look, self.lang
        mu_l, mu_V = scales["mu_l"], scales["mu_V"]

        group_mu = tuple(scales[f"mu_l {g.name}"] for g in self.groups)
        mu_d = scales[f"mu_l {fa.driving_link.link}"]

        def group_at(g: Any, mu: float, before: tuple[str, ...]) -> tuple[Sketch, tuple[str, ...]]:
            """A group's drawing, its arms numbered on from those of the groups before."""
            names = list(before)
            sketch = sketch_group(fa, g, mu, look, lang, names)
            return sketch, tuple(names)

        def noted(plain: Sketch, mu_g: float) -> Sketch:
            if math.isclose(mu_l, mu_g, rel_tol=1e-9):
                return plain
            other = _words(lang)["other_scale"].format(
                scale=scale_label(mu_l, "length", lang).markup()
            )
            return self.memo(("noted", id(plain), mu_l), lambda: _with_note(plain, other))

        arm_names: tuple[str, ...] = ()  # the arms are numbered on through the groups
        for g, mu in zip(self.groups, group_mu):
            before = arm_names
            plain, arm_names = self.memo(
                ("group", g.name, mu, before), lambda: group_at(g, mu, before)
            )
            yield f"group-{g.name}", noted(plain, mu)
        driving = self.memo(
            ("driving-link", mu_d), lambda: sketch_driving_link(fa, mu_d, look, lang)
        )
        yield "driving-link", noted(driving, mu_d)
        for name, polygons, title in self.polygon_sets:
            mu_F = scales[f"mu_F {name}"]
            gid = f"force-polygon-{name}"
            note = _polygon_note(polygons, mu_F, lang)
            drawn = self.polygons(name, polygons, title, mu_F)
            if note:
                drawn = self.memo(("noted", gid, mu_F), lambda: _with_note(drawn, note))
            yield gid, drawn

        lever, lever_arms, tables = self.lever(mu_V)
        arms.extend(lever_arms)
        yield "zhukovsky-lever", lever
        yield from self.lever_details(mu_V)
        yield from tables.items()
        yield (
            "table-loads",
            self.memo(
                ("table-loads", mu_l),
                lambda: sketch_loads_table(fa, mu_l, look, lang, self.compact),
            ),
        )
        # its details (drawn apart: `could_fit` sketches them)
        for d in self.mechanism_details:
            yield (
                loaded_detail_gid(self.mechanism_details, d),
                self.memo(
                    ("force-mechanism-detail", d, mu_l),
                    lambda d=d: sketch_loaded_detail(fa, mu_l, look, lang, d, self.compact),
                ),
            )
        if not mechanism:
            return  # the most lettering, last (`could_fit` takes it as a box)
        yield (
            "force-mechanism",
            self.memo(
                ("force-mechanism", mu_l, self.mechanism_details),
                lambda: sketch_loaded_mechanism(
                    fa, mu_l, look, lang, self.compact, details=self.mechanism_details
                ),
            ),
        )

    def given_room(
        self,
        sketches: dict[str, Sketch],
        layout: SheetLayout,
        placed: dict[str, Rect],
        scales: dict[str, float],
    ) -> tuple[SheetLayout, dict[str, Rect]]:
        """The laid-out sheet with each drawing whose names stand far
        lettered again in the order that letters them best
        whatever box that takes (`regrown`): kept where fewer names stand
        far, none more finds no free place, and its box, the drawing where it
        was placed, lies in the field and keeps the layout's gap from every
        other drawing and table; the lever and its detail views, where so
        lettered they find no room, lettered so within their box (gen 30 uk:
        view A's names far 10 -> 4, 4 mm taller grown). `sketches` takes the
        drawings kept."""
        placed = dict(placed)
        # the drawings of links lettered again at 2.5 mm too (_LOADED_AGAIN, _FORCE_AGAIN)
        drawn_again = ("force-mechanism", "group-", "driving-link")
        for name in self.drawings:
            was = _counts(sketches[name])
            # lettered again only where `grow` letters it otherwise (no order
            # was kept from it by its box or cut short, or the names of the
            # lever and the drawings of links tried at 2.5 mm): else the same drawing
            lever = name.startswith("zhukovsky-lever")
            again = was.grows or lever or name.startswith(drawn_again)
            hows: tuple[Again, ...] = ("grow", "box") if lever else ("grow",)
            chosen: tuple[Sketch, Rect] | None = None
            for how in hows if was.far and again and not lever else ():
                grown = self.regrown(name, scales, how)
                if grown is None:
                    break
                now = _counts(grown)
                if now.far >= was.far or now.unsettled > was.unsettled:
                    continue
                moved = self._room_for(name, sketches[name], grown, layout, placed[name])
                if moved is not None:
                    chosen = (grown, moved)
                    break
            if lever and was.far:
                chosen = self._lever_again(name, sketches[name], layout, placed[name], scales)
            if chosen is None:
                continue
            sketches[name], placed[name] = chosen
            kept = layout
            layout = SheetLayout(self.page, gap=kept.gap)
            for e in kept.elements:
                if e.name != "title-block":
                    layout.register(e.name, placed.get(e.name, e.footprint), e.kind)
        return layout, placed

    def _lever_again(
        self, name: str, sketch: Sketch, layout: SheetLayout, rect: Rect, scales: dict[str, float]
    ) -> tuple[Sketch, Rect] | None:
        """The lever's view `name` (`sketch`, placed at `rect`) lettered
        again (`regrown`: in the orders that letter it best whatever box that
        takes, then in those that keep its box), each with every arm named on
        its own and with the arms along one line from p named by one label
        (`_one_per_line`): of those with fewer names far than `sketch`, none
        more on something, that find room on the sheet, the one leaving
        fewest names crowded (of as many, the first), where it goes. A view
        lettered so is weighed by the room the laid-out sheet has for it, not
        by its box (gen 163 uk, view B: h_{13,15,17,18,19,20,21} along p's
        horizontal, 9 mm wider than its arms named each on its own, in the
        room right of it: names far 4 -> 3)."""
        was = _counts(sketch)
        best: tuple[int, Sketch, Rect] | None = None
        for how in ("grow", "box"):
            for grown in self._lever_letterings(name, scales, how):
                now = _counts(grown)
                if now.far >= was.far or now.unsettled > was.unsettled:
                    continue
                crowd = len(list(crowded(grown, self.lang)))
                if best is not None and crowd >= best[0]:
                    continue
                moved = self._room_for(name, sketch, grown, layout, rect)
                if moved is not None:
                    best = (crowd, grown, moved)
        return None if best is None else best[1:]

    def _lever_letterings(self, name: str, scales: dict[str, float], how: Again) -> list[Sketch]:
        """The lever's view `name` lettered again (`regrown`) as `sketch_lever`
        picks, then as it does not: every arm named on its own, or the arms
        along one line from p by one label (where that saves a label)."""
        picked = self.regrown(name, scales, how)
        if picked is None:
            return []
        mu_V = scales["mu_V"]
        detail = next((v for v in self.details if name == detail_gid(self.details, v)), None)
        details = self.details if detail is None else (detail,)
        lines: list[int] = []
        own = _lever_view(
            self.fa, mu_V, self.look, self.lang, [], details, detail, lines=lines, again=how
        )
        if not lines[0]:
            return [picked]
        merged = _lever_view(
            self.fa, mu_V, self.look, self.lang, [], details, detail, merge_arms=True, again=how
        )
        return [picked, merged if picked is own else own]

    def _room_for(
        self, name: str, sketch: Sketch, grown: Sketch, layout: SheetLayout, rect: Rect
    ) -> Rect | None:
        """Where the drawing `name`, `sketch` placed at `rect`, goes lettered
        again (`grown`): where it was, else moved by as much as it grew past
        a side (the title over a drawing rises with a name written above
        it), else in the room nearest it (gen 240's group 2-3 lettered at
        2.5 mm, 9 mm taller, under the table above it: into the empty
        column below the driving link), in the field and the layout's gap
        from the rest; None if not."""
        others = _without(layout, {name})
        ext = self.extent(grown)
        moved = _moved(self.extent(sketch), ext, rect, others)
        return moved if moved is not None else others.room_near(ext.width, ext.height, rect)

    def regrown(self, name: str, scales: dict[str, float], how: Again = "grow") -> Sketch | None:
        """The drawing `name` at `scales` with its labels written in the
        order that letters them best whatever box it takes (`grow`), noted as
        in `sketches`; the lever and its detail views with their names tried
        at 2.5 mm too (_LEVER_AGAIN), with `how` "box" in the orders that
        keep their box."""
        fa, look, lang = self.fa, self.look, self.lang
        mu_l, mu_V = scales["mu_l"], scales["mu_V"]
        if name == "zhukovsky-lever":
            return sketch_lever(fa, mu_V, look, lang, [], self.details, again=how)
        for v in self.details:
            if name == detail_gid(self.details, v):
                return sketch_lever_detail(fa, mu_V, look, lang, v, again=how)
        # the loaded mechanism and its views as laid out (`sketches`' own) are
        # not drawn again to find the names that crowd there
        if name == "force-mechanism":
            laid_out = self.cache.get(("force-mechanism", mu_l, self.mechanism_details))
            return sketch_loaded_mechanism(
                fa,
                mu_l,
                look,
                lang,
                self.compact,
                grow=True,
                details=self.mechanism_details,
                laid_out=laid_out,
            )
        for d in self.mechanism_details:
            if name == loaded_detail_gid(self.mechanism_details, d):
                laid_out = self.cache.get(("force-mechanism-detail", d, mu_l))
                return sketch_loaded_detail(
                    fa, mu_l, look, lang, d, self.compact, grow=True, laid_out=laid_out
                )
        if name == "driving-link":
            mu_d = scales[f"mu_l {fa.driving_link.link}"]
            return self._noted(sketch_driving_link(fa, mu_d, look, lang, grow=True), mu_d, mu_l)
        before: tuple[str, ...] = ()  # the arms are numbered on through the groups
        for g in self.groups:
            mu = scales[f"mu_l {g.name}"]
            if name == f"group-{g.name}":
                plain = sketch_group(fa, g, mu, look, lang, list(before), grow=True)
                return self._noted(plain, mu, mu_l)
            before = self.memo(("group", g.name, mu, before), lambda: None)[1]
        for key, polygons, title in self.polygon_sets:
            gid = f"force-polygon-{key}"
            if name == gid:
                mu_F = scales[f"mu_F {key}"]
                width = COMPACT_EQUATION_MM if self.compact else None
                drawn = sketch_force_polygons(
                    polygons, mu_F, look, lang, gid, title, width, grow=True
                )
                note = _polygon_note(polygons, mu_F, lang)
                return _with_note(drawn, note) if note else drawn
        return None

    def _noted(self, plain: Sketch, mu_g: float, mu_l: float) -> Sketch:
        """A drawing of links at `mu_g` noted with the mechanism's scale where that differs."""
        if math.isclose(mu_l, mu_g, rel_tol=1e-9):
            return plain
        other = _words(self.lang)["other_scale"].format(
            scale=scale_label(mu_l, "length", self.lang).markup()
        )
        return _with_note(plain, other)

    def arrange(
        self, sketches: dict[str, Sketch], boxes: dict[str, Rect] | None = None
    ) -> tuple[SheetLayout, dict[str, Rect]] | None:
        """The loaded mechanism top left, the tables top right, the drawings
        from the top left: in the textbook's order first, then the largest, tallest, widest first (which
        may pack tighter), then in other orders; None if nothing fits. A
        drawing of `boxes` is taken as that box (not sketched)."""
        drawings = self.drawings
        boxes = boxes or {}
        size = {n: boxes.get(n) or self.extent(sketches[n]) for n in (*self.tables, *drawings)}
        orders = [(8.0, drawings), (5.0, drawings)]
        for by in (
            lambda n: -size[n].width * size[n].height,
            lambda n: -size[n].height,
            lambda n: -size[n].width,
        ):
            orders.append((5.0, [drawings[0], *sorted(drawings[1:], key=by)]))
        # then other orders, the same on every run: a larger drawing may fit in one
        shuffle = random.Random(len(drawings))
        for _ in range(_ORDERS):
            orders.append((5.0, [drawings[0], *shuffle.sample(drawings[1:], len(drawings) - 1)]))
        field = self.page.frame.inset(5.0)
        area = sum(r.width * r.height for r in size.values())
        if area > field.width * field.height:
            self.last = LayoutError(
                f"the drawings and tables take {area / 1e4:.0f} dm², more than the "
                f"{field.width * field.height / 1e4:.0f} dm² of the sheet's field"
            )
            return None
        tables = [(n, size[n].width, size[n].height, "top-right") for n in self.tables]
        first = (drawings[0], size[drawings[0]].width, size[drawings[0]].height, "top-left")
        for gap, order in orders:
            rest = [(n, size[n].width, size[n].height, "top-left") for n in order[1:]]
            # the loaded mechanism top left, the tables top right beside it; else
            # the tables first (the same in every order) and the mechanism under them
            for head in ([first, *tables], [*tables, first]):
                placed = self.memo(("head", gap, *head), lambda: pack(self.page, head, gap))
                if placed is not None:
                    placed = pack(self.page, rest, gap, placed, known=self.packed)
                if placed is not None:
                    break
            if placed is None:
                continue
            layout = SheetLayout(self.page, gap=gap)
            for name in (*self.tables, *order):
                layout.register(name, placed[name], "table" if name in self.tables else "drawing")
            return layout, placed
        self.last = LayoutError(
            "no room for the drawings at their coarsest scales "
            + ", ".join(f"{n} {size[n].width:.0f} x {size[n].height:.0f} mm" for n in drawings)
        )
        return None

    def fits(self, steps: dict[str, int]) -> bool:
        key = ("fits", tuple(sorted(steps.items())))
        if key not in self.cache:
            scales = self.scales(steps)
            # steps that give the same scales (a polygon's μF held at its
            # limit) fit as those did: the same answer, reason and bound
            same = ("fits at", tuple(sorted(scales.items())))
            if same not in self.cache:
                ok, over = self._fits(scales)
                self.cache[same] = (ok, self.last, over)
            ok, last, over = self.cache[same]
            self.cache[key] = ok
            if not ok:
                self.last = last
            if over is not None:
                self.cache[("bounded", key)] = over
        return bool(self.cache[key])

    def _fits(self, scales: dict[str, float]) -> tuple[bool, float | None]:
        """Whether the drawings at `scales` fit the sheet; with how many times
        the field's area they take at least where that alone says no."""
        field = self.page.frame.inset(5.0)
        least = self.least_area(scales)
        if least > field.width * field.height:
            # arrange would find the drawings larger still: no need to sketch them
            self.last = LayoutError(
                f"the drawings take at least {least / 1e4:.0f} dm², more than the "
                f"{field.width * field.height / 1e4:.0f} dm² of the sheet's field"
            )
            return False, least / (field.width * field.height)
        return self._staged(scales) and self.arrange(self.sketches(scales)[0]) is not None, None

    def _staged(self, scales: dict[str, float]) -> bool:
        """False where the drawings at `scales`, sketched one at a time, take
        more than the field before all are sketched: each counted as its own
        extent once sketched, the rest by their least area (least_area's
        parts); arrange would find them larger still. True otherwise."""
        field = self.page.frame.inset(5.0)
        most = field.width * field.height * (1.0 + 1e-9)  # arrange decides the close ones
        area = dict(self._least_parts(scales))
        for name, sketch in self._sketched(scales, []):
            ext = self.extent(sketch)
            area[name] = ext.width * ext.height
            if sum(area.values()) > most:
                self.last = LayoutError(
                    f"the drawings and tables take at least {sum(area.values()) / 1e4:.0f} "
                    f"dm², more than the {field.width * field.height / 1e4:.0f} dm² of "
                    "the sheet's field"
                )
                return False
        return True

    def _least_parts(self, scales: dict[str, float]) -> Iterator[tuple[str, float]]:
        """least_area's parts by drawing (mm²): the drawings of links by the
        boxes of their pins, the lever, its tables and the polygons (without
        a note) as sketched."""
        for name, box in self._pin_boxes(scales):
            yield name, box.width * box.height
        lever, _, tables = self.lever(scales["mu_V"])
        for name, sketch in (
            ("zhukovsky-lever", lever),
            *self.lever_details(scales["mu_V"]),
            *tables.items(),
        ):
            yield name, self.extent(sketch).width * self.extent(sketch).height
        for name, polygons, title in self.polygon_sets:
            sketch = self.polygons(name, polygons, title, scales[f"mu_F {name}"])
            yield f"force-polygon-{name}", self.extent(sketch).width * self.extent(sketch).height

    def _bounded(self, steps: dict[str, int]) -> bool:
        """Whether `fits` found the drawings at `steps` far larger than the
        field by their least area alone (sketching none of the drawings of
        links): by more than _HOPELESS times its area."""
        over = self.cache.get(("bounded", ("fits", tuple(sorted(steps.items())))), 0.0)
        return bool(over > _HOPELESS)

    def unsettled(self, steps: dict[str, int]) -> int:
        """How many labels of the drawings at `steps` found no free place."""
        sketches = self.sketches(self.scales(steps))[0]
        return sum(_counts(sketches[n]).unsettled for n in self.drawings)

    def first_fit(self) -> dict[str, int] | None:
        """Scales from the finest that fits: every drawing `shrink` series
        steps from its textbook scale, the loaded mechanism up to two steps
        finer still (the groups then a step from it), the lever and the polygons never finer than the
        textbook's. Where some lettering then finds no free place, the next
        two coarser steps are tried as well for a sheet where more of it does."""
        found: list[dict[str, int]] = []
        coarsest_tried = False
        for shrink in range(-2, _COARSEST + 1):
            if found and shrink > max(v for k, v in found[0].items() if k != "mech") + 2:
                break
            hopeless = True  # every scale of this shrink larger than the field by its least area
            for bigger in range(max(2, shrink + 2), -1, -1):
                steps = self._steps(shrink, shrink - bigger)
                if self.fits(steps):
                    found.append(steps)
                    break
                hopeless &= self._bounded(steps)
            if not found and not coarsest_tried and (hopeless or shrink >= _COARSEST_CHECK):
                # once the scales a step past the textbook's fit nowhere (or
                # the first scales tried are larger than the sheet even by
                # their least area), the coarsest scales: if the sheet cannot
                # hold even those, no other will: stop now (not sooner:
                # drawing everything at the coarsest scales costs as much as
                # the trials up to there, and most sheets fit by then, those
                # of many groups a step coarser). Asked with the loaded
                # mechanism as the box of its pins (could_fit): lettered,
                # crowded at those scales, it costs more than the rest; where
                # it holds so, the scales between are tried
                coarsest_tried = True
                if not self.could_fit(self._steps(_COARSEST, _COARSEST)):
                    return None
            if found and self.unsettled(found[0]) == 0:
                break
        return min(found, key=self.unsettled) if found else None

    def could_fit(self, steps: dict[str, int]) -> bool:
        """Whether the drawings at `steps` may fit the sheet: first_fit's
        question whether even the coarsest scales fit, asked before the
        scales between. Asked first with the loaded mechanism taken as the
        box of its pins (`_pin_boxes`), not lettered (its lettering, crowded
        at a coarse scale, costs more than all the rest; the groups are
        lettered: taken as their pins' boxes too, chain_25's sheet of full
        size would pass and the scales between be tried in vain); where no
        arrangement holds them so, by `fits`, with it lettered: the packer
        is not monotone, a smaller box may find no place where a larger one
        does (gen 30: its mechanism lettered, 158 x 146 mm, packs at scales
        where the box of its pins, 115 x 95 mm, does not)."""
        scales = self.scales(steps)
        field = self.page.frame.inset(5.0)
        if self.least_area(scales) > field.width * field.height:
            return False
        sketches = dict(self._sketched(scales, [], mechanism=False))
        pins = dict(self._pin_boxes(scales, empty=True))
        boxes = {"force-mechanism": pins["force-mechanism"]}
        return self.arrange(sketches, boxes) is not None or self.fits(steps)

    def _pin_boxes(
        self, scales: dict[str, float], empty: bool = False
    ) -> Iterator[tuple[str, Rect]]:
        """The drawings of links at `scales`, each as the box (mm) of its pins
        with PAD round it, no larger than its extent; with `empty` those of no pin too."""
        owner = {"mu_l": "force-mechanism", f"mu_l {self.fa.driving_link.link}": "driving-link"}
        owner.update({f"mu_l {g.name}": f"group-{g.name}" for g in self.groups})
        for key, pts in self._pins:
            if len(pts) or empty:
                w, h = (np.ptp(pts, axis=0) / scales[key] if len(pts) else np.zeros(2)) + 2.0 * PAD
                yield owner[key], Rect(0.0, 0.0, float(w), float(h))

    def _steps(self, shrink: int, mech: int) -> dict[str, int]:
        """Every drawing `shrink` steps from its textbook scale, the loaded
        mechanism `mech`, the groups within _PARTS_FINER of it."""
        parts = min(shrink, mech + _PARTS_FINER)  # the groups near the mechanism's scale
        steps = {"mech": mech, "lever": max(0, shrink)}
        steps.update({f"group {g.name}": parts for g in self.groups})
        steps["driving"] = parts
        steps.update({f"poly {name}": max(0, shrink) for name, _, _ in self.polygon_sets})
        return steps

    def _fill_kinds(self) -> list[list[str]]:
        """The kinds of drawing `fill` and `filled` enlarge together, in
        turn: the mechanism with its groups, the groups, the lever, the
        mechanism, each group, the driving link, the polygons, each polygon."""
        polys = [f"poly {name}" for name, _, _ in self.polygon_sets]
        groups = [f"group {g.name}" for g in self.groups]
        return [
            ["mech", *groups, "driving"],
            [*groups, "driving"],
            ["lever"],
            ["mech"],
            *([k] for k in groups),
            ["driving"],
            polys,
            *([k] for k in polys),
        ]

    def fill(self, steps: dict[str, int]) -> dict[str, int]:
        """Enlarge the drawings a series step at a time while the sheet has
        room: the mechanism with its groups, the mechanism, the lever, the
        groups, each alone, the force polygons within their guide; a kind that
        no longer fits is not tried again."""
        kinds = self._fill_kinds()
        # every pass enlarges each kind left by a step or drops it, and no
        # scale goes past _FINEST: the passes are bounded
        for _ in range(_FILL_PASSES):
            if not kinds:
                break
            for kind in list(kinds):
                # larger only where it fits and its lettering finds room as well
                # as before (one step further where it does not, the next does)
                for by in (1, 2):
                    trial = dict(steps)
                    for k in kind:
                        trial[k] -= by
                    if not self._allowed(trial) or not self.fits(trial):
                        kinds.remove(kind)
                        break
                    if self.lettered(trial) <= self.lettered(steps):
                        steps = trial
                        break
                else:
                    kinds.remove(kind)
        return steps

    def lettered(self, steps: dict[str, int]) -> tuple[int, int]:
        """How well the drawings at `steps` are lettered, the less the better:
        how many labels found no free place, then how many stand far from
        what they name with no leader."""
        return self.unsettled(steps), sum(self.far(steps).values())

    def far(self, steps: dict[str, int]) -> dict[str, int]:
        """How many labels of each drawing at `steps` stand far from what
        they name with no leader (the drawings with any)."""
        sketches = self.sketches(self.scales(steps))[0]
        counts = {n: _counts(sketches[n]).far for n in self.drawings}
        return {n: k for n, k in counts.items() if k}

    def unwall(self, steps: dict[str, int]) -> dict[str, int]:
        """Where some drawing's names stand far from what they name (walled
        in by lines and other names), that drawing a series step or two
        larger (a group with the mechanism and the other parts where alone it
        would leave their scales), if the sheet holds it and no more
        lettering then finds no free place: kept where fewer names stand far."""
        groups = [f"group {g.name}" for g in self.groups]
        parts = ["mech", *groups, "driving"]
        keys: dict[str, list[list[str]]] = {
            "force-mechanism": [["mech"], parts],
            **{
                loaded_detail_gid(self.mechanism_details, d): [["mech"], parts]
                for d in self.mechanism_details
            },
            "zhukovsky-lever": [["lever"]],
            **{detail_gid(self.details, d): [["lever"]] for d in self.details},
            "driving-link": [["driving"], parts],
        }
        keys.update({f"group-{g.name}": [[f"group {g.name}"], parts] for g in self.groups})
        keys.update({f"force-polygon-{n}": [[f"poly {n}"]] for n, _, _ in self.polygon_sets})
        polys = [f"poly {n}" for n, _, _ in self.polygon_sets]
        for _ in range(_UNWALL_PASSES):
            far = self.far(steps)
            better = None
            for trial in self._unwalled(steps, far, keys, [parts, *([p] for p in polys)]):
                if not self._allowed(trial) or not self.fits(trial):
                    continue
                if self.unsettled(trial) > self.unsettled(steps):
                    continue
                if sum(self.far(trial).values()) < sum(far.values()):
                    better = trial
                    break
            if better is None:
                break
            steps = better
        return steps

    def _unwalled(
        self,
        steps: dict[str, int],
        far: dict[str, int],
        keys: dict[str, list[list[str]]],
        others: list[list[str]],
    ) -> Iterator[dict[str, int]]:
        """The trials of `unwall`, in turn: each drawing with far names (the
        most first) a step or two larger; then so with another kind a step
        smaller where it was enlarged (a polygon, the mechanism with its
        parts), to make room."""
        order = sorted(far, key=lambda n: -far[n])
        for give in (None, *others):
            for name in order:
                for kind in keys[name]:
                    if give is not None and (
                        set(give) & set(kind) or max(steps[k] for k in give) >= 0
                    ):
                        continue
                    for by in (1, 2):
                        trial = dict(steps)
                        for k in kind:
                            trial[k] -= by
                        for k in give or ():
                            trial[k] += 1
                        yield trial

    def filled(self, steps: dict[str, int]) -> dict[str, int]:
        """The empty-field rule, after `fill`: where the field is left more
        than EMPTY_MAX empty (common.empty_share, the linter's field-filled
        measure), the drawings one series step larger at a time, in fill's
        order, the lever past _LEVER_MAX too (no guide bounds its size): each
        step kept where it fits, leaves less empty and letters no worse
        (`lettered`: unwall's far names stay near), until the field is filled
        or no step does."""
        empty = self.empty(steps)
        kinds = self._fill_kinds()
        while empty > EMPTY_MAX:
            for kind in kinds:
                trial = {k: v - (k in kind) for k, v in steps.items()}
                if self._allowed(trial, lever_max=False) and self.fits(trial):
                    trial_empty = self.empty(trial)
                    if trial_empty < empty - 1e-9 and self.lettered(trial) <= self.lettered(steps):
                        steps, empty = trial, trial_empty
                        break
            else:
                break
        return steps

    def empty(self, steps: dict[str, int]) -> float:
        """The share of the field the drawings and tables at `steps` leave
        empty, as the linter's field-filled rule measures it."""
        sketches, _ = self.sketches(self.scales(steps))
        arranged = self.arrange(sketches)
        if arranged is None:
            return 1.0
        return laid_out_empty_share(self.page, sketches, arranged[1], self.extent)

    def _allowed(self, steps: dict[str, int], *, lever_max: bool = True) -> bool:
        if min(v for k, v in steps.items() if not k.startswith(("poly", "lever"))) < _FINEST:
            return False
        if min(steps.values()) < 2 * _FINEST:
            return False  # no drawing, the polygons and the lever too, enlarged without end
        parts = [v for k, v in steps.items() if k.startswith(("group", "driving"))]
        if (
            not steps["mech"] - _PARTS_FINER
            <= min(parts)
            <= max(parts)
            <= steps["mech"] + _PARTS_FINER
        ):
            return False
        for name, polygons, _ in self.polygon_sets:
            # a polygon enlarged no further than the guide's 300 mm
            if steps[f"poly {name}"] != 0 and guide_side(polygons) <= 0.0:
                return False  # an all-zero polygon is a point at any scale: never enlarged
            mu_F = _force_scale(polygons, steps[f"poly {name}"], self.held)
            if steps[f"poly {name}"] < 0 and guide_side(polygons) / mu_F > FORCE_PLAN.high:
                return False
        mu_V = scale_step(self.lever_mu, steps["lever"])
        return steps["lever"] >= 0 or not lever_max or self.fa.lever.pa / mu_V <= _LEVER_MAX


def _with_lever_details(
    composer: _Composer, steps: dict[str, int], solution: Solution
) -> tuple[_Composer, dict[str, int]]:
    """Where the lever reached the sheet at another scale than its textbook
    one and names crowd there, with no detail view (none crowded at its
    textbook scale: five_dyads, 3 steps smaller, 'h15,…' 26 mm from its arm)
    or with those chosen at the textbook scale (gen 112: 'h…' 10–20 mm off),
    or where names crowd in those views drawn at their ratios of the lever at
    that scale (gen 176: C, 5:1, 9 names 8-15 mm off):
    its detail views found on the lever at the scale it reached, each drawn
    larger while that letters it better
    (`lever_details`), the sheet fitted again with them; kept where it fits
    and fewer labels of all its drawings stand far or found no free place;
    else as it was."""
    fa, lang = composer.fa, composer.lang
    scales = composer.scales(steps)
    if not composer.allows_details or scales["mu_V"] == composer.lever_mu:
        return composer, steps
    mu_V = scales["mu_V"]
    # the lever as the sheet draws it (the sketch the composer made at that
    # scale; nothing letters it again once made)
    drawn = composer.lever(mu_V)[0]
    crowd = crowded_ends(drawn, lang)
    # its detail views drawn at their ratios of the lever at that scale (gen
    # 176: C, 5:1 of the lever a step smaller, its names 8–15 mm off)
    views = composer.lever_details(mu_V)
    if not len(crowd) and not any(len(crowded_ends(v, lang)) for _, v in views):
        return composer, steps
    if composer.details:
        # its details, chosen at the textbook scale, leave names crowded at
        # this one (gen 68: 'h5' … 'h19' 10–23 mm off): chosen again here,
        # on the lever drawn without them
        plain = sketch_lever(fa, mu_V, composer.look, lang, [], one_per_line=False)
        crowd = crowded_ends(plain, lang)
    crowding = lever_crowding(fa, mu_V, composer.look, lang)
    found = lever_details(fa, mu_V, crowd, crowding, enlarge=True)
    if not found or found == composer.details:
        return composer, steps
    detailed = composer.again(solution, lever_views=found)
    return _refitted(composer, detailed, sum(composer.lettered(steps))) or (composer, steps)


def _with_mechanism_details(
    composer: _Composer, steps: dict[str, int], solution: Solution
) -> tuple[_Composer, dict[str, int]]:
    """Where names of the loaded mechanism as it reaches the sheet (at
    `steps`) stand far or on something, a detail view of their crowd
    (`loaded_details`), decided once on that drawing (`_detailed`); where a
    second disc would hold a pair of them left over (_SECOND_PAIR), those
    views with it weighed against those without: the one kept where fewer
    labels of all the sheet's drawings stand far or found no free place."""
    fa, lang = composer.fa, composer.lang
    scales = composer.scales(steps)
    mechanism = composer.sketches(scales)[0]["force-mechanism"]
    crowd = crowded_names(mechanism, lang, anchors=True)
    if not len(crowd):
        return composer, steps
    taken = [d.letter for d in composer.details]
    kept, was = (composer, steps), sum(composer.lettered(steps))
    tried: list[tuple[Detail, ...]] = []
    for fewest in (_SECOND_CROWD, _SECOND_PAIR):
        found = loaded_details(fa, scales["mu_l"], crowd, taken, fewest)
        if not found or found in tried:
            continue
        tried.append(found)
        better = _detailed(composer, steps, solution, found, was)
        if better is not None:
            kept, was = better[:2], better[2]
    return kept


def _detailed(
    composer: _Composer,
    steps: dict[str, int],
    solution: Solution,
    found: tuple[Detail, ...],
    was: int,
) -> tuple[_Composer, dict[str, int], int] | None:
    """The sheet with the loaded mechanism's detail views `found`: at the same
    steps, else with the mechanism a step or two smaller (the detail holds
    its crowd), else fitted again with them (the filled sheet has no room
    left); with how many labels of all its drawings stand far or found no
    free place, where fewer than `was`; else None, `composer` as it was."""
    before = composer.mechanism_details
    composer.with_mechanism_details(found)
    for by in (0, 1, 2):
        trial = {**steps, "mech": steps["mech"] + by}
        if composer.fits(trial):
            now = sum(composer.lettered(trial))
            if now < was:
                return composer, trial, now
    composer.with_mechanism_details(before)
    # the filled sheet has no room for it: the sheet fitted again with it
    detailed = composer.again(solution, details=bool(composer.details), mechanism_details=found)
    refit = _refitted(composer, detailed, was)
    return None if refit is None else (*refit, sum(refit[0].lettered(refit[1])))


def _refitted(
    composer: _Composer, detailed: _Composer, was: int
) -> tuple[_Composer, dict[str, int]] | None:
    """The sheet fitted again by `detailed` (sharing `composer`'s drawings of
    links), filled: kept where it fits and fewer than `was` labels of all its
    drawings stand far or found no free place."""
    detailed.cache.update(composer.shared_drawings(detailed))
    refit = detailed.first_fit()
    if refit is None:
        return None
    refit = detailed.filled(detailed.unwall(detailed.fill(refit)))
    return (detailed, refit) if sum(detailed.lettered(refit)) < was else None


def _without(layout: SheetLayout, names: set[str]) -> SheetLayout:
    """The drawings and tables of `layout` but `names` and the title block."""
    others = SheetLayout(layout.page, gap=layout.gap)
    for e in layout.elements:
        if e.name != "title-block" and e.name not in names:
            others.register(e.name, e.footprint, e.kind)
    return others


def _moved(old: Rect, ext: Rect, rect: Rect, others: SheetLayout) -> Rect | None:
    """Where a drawing placed at `rect` with the box `old` goes with the box
    `ext`: where it was, else moved by as much as it grew past a side (the
    title over a drawing rises with a name written above it), in the field
    and the layout's gap from `others`; None if it finds no room."""
    xs = (ext.x + rect.x - old.x, rect.x, rect.right - ext.width)
    ys = (ext.y + rect.y - old.y, rect.y, rect.top - ext.height)
    boxes = (Rect(x, y, ext.width, ext.height) for x in xs for y in ys)
    return next((at for at in boxes if others.fits(at)), None)


def _loaded_crowd(sketches: Mapping[str, Sketch], details: Sequence[Detail], lang: Language) -> int:
    """How many names of the loaded mechanism and of its detail views (drawn
    with `details`) in `sketches` the sheet linter finds far or on something."""
    views = ["force-mechanism", *(loaded_detail_gid(details, d) for d in details)]
    return sum(len(list(crowded(sketches[n], lang))) for n in views)


def _letters_by_rims(
    composer: _Composer, sketches: dict[str, Sketch], scales: dict[str, float]
) -> None:
    """On the laid-out sheet, each detail view's letter on the lever and on
    the loaded mechanism that stands further than NEAR_MM from its disc
    (written up and right of it, `_lever_view`, `_Drawing.marks`) moved to
    the first point of the rim where it stands near and covers nothing
    (`rim_anchors`, `Labels.place_first`), where that keeps the drawing's
    box: gen 90's lever view A, its up-right rim walled in by the images'
    names, had A 10 mm off. Done last, so that the views chosen, the scales
    and the layout are those of the letter as it was (tried while the
    views were chosen, the letter's place chose other views and scales:
    held-out gen 262 and 289 got other names far)."""
    owners = (
        ("zhukovsky-lever", composer.details, scales["mu_V"]),
        ("force-mechanism", composer.mechanism_details, scales["mu_l"]),
    )
    for name, details, mu in owners:
        for d in details if name in sketches else ():
            centre = np.asarray(d.centre, dtype=float) / mu
            _letter_by_rim(sketches[name], centre, d.radius / mu, d.letter, composer.lang)


def _far_names_again(composer: _Composer, sketches: dict[str, Sketch]) -> None:
    """On the laid-out sheet, each drawing's names that stand far written
    again one by one among all else written there (`far_names_again`), at
    GOST's 2.5 mm too and on the fine grid of places, where that keeps the
    drawing's box: done last, as `_letters_by_rims`, so that views, scales
    and layout stay as chosen (gen 30's lever view: Fin5 8.9 mm off its
    arrow, a place by it taken while the view was lettered, free on the
    laid-out sheet)."""
    words = _index_words(composer.lang)
    for name in composer.drawings:
        sk = sketches[name]
        far_names_again(sk, composer.lang, _FAR_AGAIN, words, composer.extent(sk).contains)


def _letter_by_rim(sk: Sketch, centre: np.ndarray, r: float, letter: str, lang: Language) -> None:
    """`_letters_by_rims` for one disc of `sk` (its centre and radius in the
    sketch's mm): the letter is found where the drawing wrote it, by the
    first of `rim_anchors`."""
    anchors = rim_anchors(centre, r)
    rim, _ = anchors[0]
    runs = [
        i
        for i, c in enumerate(sk.calls)
        if (n := getattr(c, "naming", None)) is not None
        and n.markup == letter
        and n.kind == "point"
        and math.dist(n.anchor, rim) < 1e-6
    ]
    boxes = [sk.text_box(sk.calls[i]) for i in runs if sk.calls[i].name == "text"]
    if not boxes:
        return
    written = shapely.union_all([shapely.box(*b) for b in boxes])
    if written.distance(shapely.Point(rim)) <= NEAR_MM:
        return
    box, before = sk.extent(), list(sk.calls)
    labels = written_again(
        sk,
        runs,
        lang,
        _TEXT,
        _LABELLING,
        _index_words(lang),
        lambda placer: placer.place_first(anchors, letter, clear=True),
    )
    if labels.far or labels.unsettled or not box.contains(sk.extent()):
        sk.calls[:] = before  # no rim point serves: as it was


def _loaded_details_again(
    composer: _Composer,
    sketches: dict[str, Sketch],
    layout: SheetLayout,
    placed: dict[str, Rect],
    scales: dict[str, float],
) -> tuple[SheetLayout, dict[str, Rect]]:
    """The laid-out sheet with the loaded mechanism's detail views chosen
    again where its names still stand far or on something: its details
    were chosen at the scale it had before the sheet was fitted again with
    them (gen 158: a disc of 6 mm at μl 0.01, the mechanism then drawn at
    0.025, the knot round the crank's pivot O lettered 10–15 mm off). Chosen
    again (`loaded_details`) on the mechanism at the scale it reached, drawn
    without details, and on the names that stand far on the sheet (a second
    disc for a crowd of _SECOND_CROWD, _SECOND_PAIR or even _SECOND_ONE
    names, in turn); the mechanism drawn with them at that scale where it
    was (`_loaded_placed`), each view in the room left nearest it: kept
    where fewer of their names stand far or on something, no other drawing
    moved. `sketches` takes the drawings kept, `composer` the details."""
    fa, lang = composer.fa, composer.lang
    mu_l, before = scales["mu_l"], composer.mechanism_details
    was = _loaded_crowd(sketches, before, lang)
    if not was:
        return layout, placed
    plain = composer.memo(
        ("force-mechanism", mu_l, ()),
        lambda: sketch_loaded_mechanism(fa, mu_l, composer.look, lang, composer.compact),
    )
    crowd = [crowded_names(plain, lang, anchors=True)]
    crowd.append(crowded_names(sketches["force-mechanism"], lang, anchors=True))
    for d in before:  # a detail view's mm are the mechanism's times its ratio
        view = sketches[loaded_detail_gid(before, d)]
        crowd.append(crowded_names(view, lang, anchors=True) / d.ratio)
    points = np.concatenate(crowd)
    taken = [d.letter for d in composer.details]
    tried = [before]
    best: tuple[int, tuple[Detail, ...], dict[str, Sketch], SheetLayout] | None = None
    for fewest in (_SECOND_CROWD, _SECOND_PAIR, _SECOND_ONE):
        found = loaded_details(fa, mu_l, points, taken, fewest)
        if not found or found in tried:
            continue
        tried.append(found)
        trial = _loaded_placed(composer, found, sketches, layout, placed, mu_l)
        while trial is None and found != _smaller(found):
            # no room on the sheet for a view at its ratio: a step smaller
            found = _smaller(found)
            trial = _loaded_placed(composer, found, sketches, layout, placed, mu_l)
        if trial is None:
            continue
        now = _loaded_crowd(trial[0], found, lang)
        if now < (was if best is None else best[0]):
            best = (now, found, *trial)
        if not now:
            break
    if best is None:
        return layout, placed
    _, found, drawn, layout = best
    for d in before:
        del sketches[loaded_detail_gid(before, d)]
    composer.with_mechanism_details(found)
    sketches.update(drawn)
    kept = {n: r for n, r in placed.items() if not n.startswith("force-mechanism")}
    return layout, {**kept, **{n: layout[n].bounds for n in drawn}}


def _smaller(details: tuple[Detail, ...]) -> tuple[Detail, ...]:
    """`details`, each drawn a ratio of the series smaller (none below its first)."""
    return tuple(
        dataclasses.replace(
            d, ratio=max([k for k in DETAIL_RATIOS if k < d.ratio], default=d.ratio)
        )
        for d in details
    )


def _loaded_placed(
    composer: _Composer,
    details: tuple[Detail, ...],
    sketches: Mapping[str, Sketch],
    layout: SheetLayout,
    placed: Mapping[str, Rect],
    mu_l: float,
) -> tuple[dict[str, Sketch], SheetLayout] | None:
    """The loaded mechanism at `mu_l` with `details` and their views, each
    lettered as `given_room` letters it where that letters it better
    (`regrown`), and the laid-out sheet with them: the mechanism where it
    was placed, else moved by as much as it grew past a side, each view in
    the room nearest it; None where they find no room (the other drawings stay)."""
    fa, look, lang, compact = composer.fa, composer.look, composer.lang, composer.compact
    # the mechanism marks its details' discs whatever their ratios
    discs = tuple(dataclasses.replace(d, ratio=1.0) for d in details)

    def lettered(
        draw: Callable[[bool, Sketch | None], Sketch],
        room: Callable[[Sketch], bool] | None = None,
    ) -> list[Sketch]:
        """The drawing lettered as it comes, and with `grow` where its names
        stand far (that drawing not drawn again to find them) and it finds
        `room` (a view that finds none is not lettered again: gen 63's view
        at 2:1 took 9 s to draw, 197 s more lettered again, and neither found
        room): the one that letters it better first."""
        sk = draw(False, None)
        if not _counts(sk).far or (room is not None and not room(sk)):
            return [sk]
        grown = draw(True, sk)
        better = len(list(crowded(grown, lang))) < len(list(crowded(sk, lang)))
        return [grown, sk] if better else [sk, grown]

    mechanisms = lettered(
        lambda grow, laid_out: composer.memo(
            ("force-mechanism", mu_l, discs) + (("grow",) if grow else ()),
            lambda: sketch_loaded_mechanism(
                fa, mu_l, look, lang, compact, grow=grow, details=details, laid_out=laid_out
            ),
        )
    )
    others = _without(layout, {n for n in placed if n.startswith("force-mechanism")})
    old, rect = composer.extent(sketches["force-mechanism"]), placed["force-mechanism"]
    for mechanism in mechanisms:  # the first that finds room
        at = _moved(old, mechanism.extent(), rect, others)
        if at is not None:
            break
    if at is None:
        return None
    others.register("force-mechanism", at)
    drawn = {"force-mechanism": mechanism}
    for d in details:

        def detail_view(grow: bool, laid_out: Sketch | None, d: Detail = d) -> Sketch:
            return composer.memo(
                ("force-mechanism-detail", d, mu_l) + (("grow",) if grow else ()),
                lambda: sketch_loaded_detail(
                    fa, mu_l, look, lang, d, compact, grow=grow, laid_out=laid_out
                ),
            )

        def room(view: Sketch) -> bool:
            box = view.extent()
            return others.room_near(box.width, box.height, at) is not None

        view = lettered(detail_view, room)[0]
        name, box = loaded_detail_gid(details, d), view.extent()
        try:
            others.place(name, box.width, box.height, near=at)
        except LayoutError:
            return None
        drawn[name] = view
    return drawn, others


@_views_kept
def compose_sheet2(
    solution: Solution,
    backend: Backend,
    lang: Language = "en",
    *,
    page: Page | None = None,
    forces: ForceAnalysis | None = None,
) -> Sheet2:
    """Draw sheet 2 of `solution` on `backend`: the force solution at its force
    position (computed here unless `forces` is given). The drawings take the
    finest scales at which they fit, then grow while the sheet has room."""
    page = page if page is not None else Page.of("A1")
    check_language(lang)
    fa = forces if forces is not None else solution.require_forces()
    # a mechanism of many groups: they go on further sheets (further_groups),
    # sheet 2 laid out compact (its tables of every pair, every force, long)
    further = further_groups(len(fa.groups))
    groups = () if further else fa.groups
    composer = _Composer(
        fa, solution, backend.look, lang, page, compact=bool(further), groups=groups
    )
    steps = composer.first_fit()
    if steps is None and not composer.compact:
        # many groups: the equations in short lines, the tables in parts
        plain = composer
        composer = _Composer(fa, solution, backend.look, lang, page, compact=True, groups=groups)
        composer.cache.update(plain.shared_drawings())
        steps = composer.first_fit()
    if steps is None and composer.details:
        # no room for the lever's detail views either: the lever alone
        plain = composer
        composer = _Composer(
            fa, solution, backend.look, lang, page, compact=True, details=False, groups=groups
        )
        composer.cache.update(plain.shared_drawings())
        steps = composer.first_fit()
    if steps is None:
        # a polygon of F_PR whose other sides run far past it (reactions
        # many times the resistance near a dead centre): it too goes coarser,
        # under 150 mm with the note that says so (_polygon_note)
        plain = composer
        composer = _Composer(
            fa,
            solution,
            backend.look,
            lang,
            page,
            compact=True,
            details=False,
            groups=groups,
            held=False,
        )
        composer.cache.update(plain.shared_drawings())
        steps = composer.first_fit()
    if steps is None:
        what = composer.last or (
            f"its {len(composer.drawings)} drawings ({', '.join(composer.drawings)}) and "
            "tables find no arrangement at any scale tried"
        )
        raise LayoutError(
            f"{shown(solution.mechanism.path)}: sheet 2 does not fit on "
            f"{page.name or 'the page'}: {what}, even with every drawing {_COARSEST} scale "
            "steps smaller than the textbook's\n"
            "  fix: draw sheet 1 alone (--sheet 1), or study a mechanism of fewer "
            "groups (up to five groups go on sheet 2 with the rest of the force analysis)"
        )
    steps = composer.filled(composer.unwall(composer.fill(steps)))
    composer, steps = _with_lever_details(composer, steps, solution)
    composer, steps = _with_mechanism_details(composer, steps, solution)
    scales = composer.scales(steps)
    sketches, arms = composer.sketches(scales)
    arranged = composer.arrange(sketches)
    assert arranged is not None  # it fitted before
    layout, placed = composer.given_room(sketches, *arranged, scales)
    layout, placed = _loaded_details_again(composer, sketches, layout, placed, scales)
    _letters_by_rims(composer, sketches, scales)
    _far_names_again(composer, sketches)
    result = Sheet2(
        fa,
        layout,
        dict(scales),
        shrink=max(steps.values()),
        arms={"lever": arms},
        details=composer.details,
        mechanism_details=composer.mechanism_details,
        groups=tuple(g.name for g in composer.groups) if further else None,
    )
    for name in composer.tables + composer.drawings:
        ext, rect = composer.extent(sketches[name]), placed[name]
        dx, dy = rect.x - ext.x, rect.y - ext.y
        _translated(sketches[name], lang).replay(backend, dx, dy)
        result.origins[name] = (dx, dy)
        result.placed[name] = rect
    fields = title_fields(solution, scales["mu_l"], lang)
    fields["sheet"] = "2"
    if further:  # the sheet says where its groups went
        fields.setdefault(
            "sheet_name",
            _words(lang)["groups_further"].format(first=3, last=2 + len(further)),
        )
    draw_page(backend, page, fields, lang)
    return result
