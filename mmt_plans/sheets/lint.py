"""The sheet linter: the draughting rules of a composed sheet, checked on its
recording (typed records, `render.recording`), never on SVG text.

Each rule is a function of one sheet (`SheetView`) that yields `Finding`s
with a place on the sheet (mm from its bottom-left corner). The thresholds:

- ``label-near``: a label's box is within NEAR_MM = 6 mm of what it names (a
  point, or the segment of an arrow or a link), or a leader line of its own
  joins the two and crosses no main (heavy) line. A leader may cross main
  lines where no place within NEAR_MM is clear (on a ROOM_STEP = 0.5 mm
  grid, a box of the name's size ROOM_CLEAR = 0.25 mm off every line and
  name): GOST 2.316 keeps a leader off the drawing's lines where it can be,
  and a pivot in the fan of its positions' links has no free side.
  A point drawn inside a filled outline at most BLOCK_MM = 15 mm across (a
  slider's block round its pin or mass centre) is measured from the outline:
  its name stands beside the block, where a draughtsman writes it.
- ``label-clear``: a label's box (shrunk by 0.25 mm) touches no drawn line,
  arc, circle or arrowhead of a drawing but its own leader, and overlaps no
  other label by more than 0.5 mm² (tables, the frame and the title block
  have their own grid).
- ``leader-clear``: a leader crosses no other name (its box shrunk by
  0.25 mm). Apart from label-near, which the composers ask where names
  crowd: this rule judges the sheet only.
- ``vectors-apart``: no two arrows of one force polygon or lever lie along
  one line (within 1° and 0.4 mm) overlapping by more than 1 mm (a plan's
  images of one link's points lie on one line by similarity, as drawn).
- ``names-unique``: no name written twice for different things in one
  drawing (two labels of the same text more than 1 mm apart that name
  different places: a point P's image "p" and the pole p), no pair of
  look-alike names (O and 0, o and 0, l and 1) within 15 mm of each other,
  and no letter of a detail view ("H (2:1)") given to two views of the sheet.
- ``arrows-named``: every arrow of a plan, force polygon or lever has
  lettering within 8 mm of its shaft.
- ``letter-height``: every letter, indices included, at least 2.5 mm high
  (GOST 2.304).
- ``table-format``: the numbers of one table column all have the same number
  of decimals; a column of non-integer numbers has its unit in its header or
  in the table's title (", m/s", "(м/с)", "%", "°"…).
- ``language``: a Ukrainian sheet writes no decimal point, no Latin unit
  (m/s, 1/s, N, mm, rad) and a title with Cyrillic letters; an English sheet
  no decimal comma and no Cyrillic.
- ``designation``: the designation in the title block reads like GOST 2.201
  (capital letters or digits in groups joined by dots, no underscores), and is
  the same on the sheet's en and uk versions (`lint_pair`).
- ``guide-sizes``: velocity and acceleration plans between 100 and 200 mm
  (their longest vector from the pole, pa and πa), force polygons between
  150 and 300 mm (their longest side); a drawing below that passes where the
  sheet says why it is reduced (a text with "reduced"/"зменшено").
- ``no-dev-prose``: no lettering written for developers (the calculation's μ,
  "drawn at the μ", "fills its field", TODO, fallback …).
- ``field-filled``: at most EMPTY_MAX = 50 % of the field inside the frame,
  above the title block, is outside the boxes of the drawings and tables.
"""

from __future__ import annotations

import collections
import itertools
import math
import re
from collections.abc import Callable, Iterable, Iterator, Sequence
from dataclasses import dataclass, field
from typing import Literal

import numpy as np
import shapely
from shapely import STRtree
from shapely.geometry import LineString, Point, box
from shapely.geometry.base import BaseGeometry

from ..drawing.labels import LOOKALIKE, LOOKALIKE_MM, NEAR_MM, drawn_shapes, enclosing
from ..render.look import load_look
from ..render.recording import Arrow, BeginGroup, Call, Line, Naming, RecordingBackend, Text
from .common import EMPTY_MAX, empty_share

__all__ = [
    "EMPTY_MAX",
    "Finding",
    "NEAR_MM",
    "RULES",
    "SheetView",
    "lint",
    "lint_pair",
]

Language = Literal["en", "uk"]

CLEAR_SHRINK = 0.25
# the grid on which label-near asks whether a walled-in name had room near,
# and how far off every line and name that room is (mm): the placer's tightest
ROOM_STEP = 0.5
ROOM_CLEAR = 0.25
LABEL_OVERLAP = 0.5
COLLINEAR_DEG = 1.0
COLLINEAR_MM = 0.4
OVERLAP_MM = 1.0
ARROW_NAME_MM = 8.0
MIN_LETTER = 2.5
PLAN_MM = (100.0, 200.0)
POLYGON_MM = (150.0, 300.0)
_NOT_DRAWINGS = ("table", "title-block", "frame")


@dataclass(frozen=True)
class Finding:
    """One broken rule at one place of one sheet."""

    rule: str
    message: str
    where: tuple[float, float]
    sheet: str = ""

    def __str__(self) -> str:
        x, y = self.where
        return f"{self.sheet} {self.rule} at ({x:.0f}, {y:.0f}) mm: {self.message}"


@dataclass
class _Label:
    naming: Naming | None
    text: str
    box: BaseGeometry
    runs: list[Text]
    groups: tuple[str, ...]
    leader: Line | None = None


@dataclass
class SheetView:
    """A recorded sheet read for the rules: its labels (the runs of one label
    joined), its drawn shapes and its groups."""

    calls: Sequence[Call]
    width: float
    height: float
    lang: Language
    name: str = ""
    classes: dict[str, str] = field(default_factory=dict)

    @classmethod
    def of(cls, backend: RecordingBackend, lang: Language, name: str = "") -> SheetView:
        return cls(list(backend.calls), backend.width, backend.height, lang, name)

    def __post_init__(self) -> None:
        let = load_look().lettering
        # lettering changed after it was drawn is measured again
        self.calls = [
            c.with_changes(width=let.width(c.content, c.size, c.max_width))
            if isinstance(c, Text) and c.width is None
            else c
            for c in self.calls
        ]
        self.classes = {c.id: c.cls or "" for c in self.calls if isinstance(c, BeginGroup)}
        self.texts = [c for c in self.calls if isinstance(c, Text)]
        self.labels = self._labels()

    def cls_of(self, c: Call) -> set[str]:
        return {self.classes.get(g, "") for g in c.groups}

    def in_drawing(self, c: Call) -> bool:
        return bool(c.groups) and not (self.cls_of(c) & set(_NOT_DRAWINGS))

    def top_group(self, c: Call) -> str:
        return c.groups[0] if c.groups else ""

    def _labels(self) -> list[_Label]:
        out: list[_Label] = []
        by_id: dict[int, _Label] = {}
        prev: Text | None = None
        for c in self.calls:
            if isinstance(c, Line) and c.naming is not None:
                lab = by_id.get(c.naming.label)
                if lab is None:
                    lab = _Label(c.naming, "", box(0, 0, 0, 0), [], c.groups)
                    by_id[c.naming.label] = lab
                    out.append(lab)
                lab.leader = c
                continue
            if not isinstance(c, Text) or c.width is None or not c.content.strip():
                continue
            b = box(*c.box())
            if c.naming is not None:
                lab = by_id.get(c.naming.label)
                if lab is None:
                    lab = _Label(c.naming, "", b, [], c.groups)
                    by_id[c.naming.label] = lab
                    out.append(lab)
                lab.runs.append(c)
                lab.text += c.content
                lab.box = b if len(lab.runs) == 1 else lab.box.union(b).envelope
                prev = None
                continue
            # unnamed lettering: the runs of one rich text (letter, then index) are one
            if (
                prev is not None
                and out
                and out[-1].naming is None
                and prev.groups == c.groups
                and c.anchor == "left"
                and prev.width is not None
                and abs(c.pos[0] - (prev.box()[2])) < 1.0
                and abs(c.pos[1] - prev.pos[1]) < prev.size
            ):
                last = out[-1]
                last.runs.append(c)
                last.text += c.content
                last.box = last.box.union(b).envelope
            else:
                out.append(_Label(None, c.content, b, [c], c.groups))
            prev = c
        return [lab for lab in out if lab.runs]

    def shapes(self) -> list[tuple[Call, BaseGeometry]]:
        """Every drawn primitive but lettering, as it lies on the paper."""
        probe = RecordingBackend(self.width, self.height)
        return [
            (c, s)
            for c in self.calls
            if not isinstance(c, Text | BeginGroup) and c.name != "end_group"
            for s in drawn_shapes(c, probe)
        ]


Rule = Callable[[SheetView], Iterable[Finding]]


def _at(g: BaseGeometry) -> tuple[float, float]:
    c = g.centroid
    return (round(float(c.x), 1), round(float(c.y), 1))


def _named_shape(n: Naming) -> BaseGeometry:
    if n.end is None or math.dist(n.anchor, n.end) < 1e-9:
        return Point(n.anchor)
    if n.kind == "arrow":  # an arrow's name goes by its head
        return LineString([n.anchor, n.end])
    return LineString([n.anchor, n.end])


def label_near(v: SheetView, strict: bool = False) -> Iterator[Finding]:
    """label-near on `v`: a leader may cross main lines only where no place
    within NEAR_MM of what the label names is clear (`_Room.near`); with
    `strict` (the composers asking where names crowd: a drawing whose names
    need no such leader is better), never."""
    shapes = v.shapes()
    heavy = [s for c, s in shapes if getattr(c, "line", None) == "main" and v.in_drawing(c)]
    tree = STRtree(heavy) if heavy else None
    room: _Room | None = None
    blocks = [s for c, s in shapes if c.name == "polygon" and s.geom_type == "Polygon"]
    for lab in v.labels:
        if lab.naming is None:
            continue
        target = _named_shape(lab.naming)
        if target.geom_type == "Point":  # a point inside a block: named beside the block
            target = enclosing(lab.naming.anchor, blocks) or target
        gap = lab.box.distance(target)
        if gap <= NEAR_MM:
            continue
        if lab.leader is not None:
            ld = LineString([lab.leader.start, lab.leader.end])
            joined = ld.distance(target) < 1.0 and ld.distance(lab.box) < 2.0
            # past the pin and the lines that meet where the leader leaves what
            # it names (the anchor, or a point along a named segment)
            foot = min((lab.leader.start, lab.leader.end), key=lambda p: target.distance(Point(p)))
            far = ld.difference(Point(foot).buffer(1.8))
            crossed = (
                tree is not None
                and far.length > 0
                and len(tree.query(far, predicate="intersects")) > 0
            )
            if joined and not crossed:
                continue
            if joined and not strict:
                room = room or _Room(v, shapes)
                if not room.near(lab, target):
                    continue  # walled in: GOST 2.316's leader across the drawing's lines
            why = (
                "its leader crosses a main line, and a place near it is free"
                if joined
                else "its leader does not reach it"
            )
            yield Finding("label-near", f"{lab.text!r}: {why}", _at(lab.box), v.name)
            continue
        yield Finding(
            "label-near",
            f"{lab.text!r} stands {gap:.1f} mm from what it names (at most {NEAR_MM:g} mm, "
            "or a leader)",
            _at(lab.box),
            v.name,
        )


class _Room:
    """Where a label could stand instead: the drawn shapes of the sheet's
    drawings and the names written, as label-clear judges a place."""

    def __init__(self, v: SheetView, shapes: Sequence[tuple[Call, BaseGeometry]]) -> None:
        drawn = [(c, g) for c, g in shapes if v.in_drawing(c)]
        self.calls = [c for c, _ in drawn]
        self.shapes = STRtree([g for _, g in drawn]) if drawn else None
        self.labels = [lab for lab in v.labels if any(v.in_drawing(r) for r in lab.runs)]
        self.letters = STRtree([lab.box for lab in self.labels]) if self.labels else None

    def near(self, lab: _Label, target: BaseGeometry) -> bool:
        """Whether a box of `lab`'s size, on a grid ROOM_STEP mm fine, within
        NEAR_MM of `target` and off it, is clear: touches no drawn shape but
        `lab`'s own leader and no other name's box, ROOM_CLEAR mm off them.
        (Grown, not shrunk as label-clear shrinks a box written: a place where
        a line grazes the letters is not one a draughtsman leaves a walled-in
        name for.)"""
        x0, y0, x1, y1 = lab.box.bounds
        w, h = x1 - x0, y1 - y0
        tx0, ty0, tx1, ty1 = target.bounds
        reach = NEAR_MM + max(w, h)
        gx, gy = np.meshgrid(
            np.arange(tx0 - reach, tx1 + reach, ROOM_STEP),
            np.arange(ty0 - reach, ty1 + reach, ROOM_STEP),
        )
        cx, cy = gx.ravel(), gy.ravel()
        gap = shapely.distance(shapely.box(cx - w / 2, cy - h / 2, cx + w / 2, cy + h / 2), target)
        keep = np.flatnonzero((gap > 0.0) & (gap <= NEAR_MM))
        if not keep.size:
            return False
        cx, cy = cx[keep], cy[keep]
        e = ROOM_CLEAR
        inner = shapely.box(cx - w / 2 - e, cy - h / 2 - e, cx + w / 2 + e, cy + h / 2 + e)
        blocked = np.zeros(inner.size, dtype=bool)
        if self.shapes is not None:
            box_i, hit = self.shapes.query(inner, predicate="intersects")
            mine = np.array([self.calls[i] is lab.leader for i in hit], dtype=bool)
            blocked[box_i[~mine]] = True
        if self.letters is not None:
            box_i, hit = self.letters.query(inner, predicate="intersects")
            mine = np.array([self.labels[i] is lab for i in hit], dtype=bool)
            blocked[box_i[~mine]] = True
        return not blocked.all()


def label_clear(v: SheetView) -> Iterator[Finding]:
    # leaders are checked by label-near
    drawn = [(c, s) for c, s in v.shapes() if v.in_drawing(c) and c.naming is None]
    shapes = [s for _, s in drawn]
    tree = STRtree(shapes) if shapes else None
    labels = [lab for lab in v.labels if any(v.in_drawing(r) for r in lab.runs)]
    for lab in labels:
        inner = lab.box.buffer(-CLEAR_SHRINK)
        if inner.is_empty or tree is None:
            continue
        hits = tree.query(inner, predicate="intersects")
        own = lab.leader
        hits = [i for i in hits if drawn[i][0] is not own]
        if hits:
            what = sorted({drawn[i][0].name for i in hits})
            yield Finding(
                "label-clear", f"{lab.text!r} lies on a {', '.join(what)}", _at(lab.box), v.name
            )
    boxes = [lab.box for lab in labels]
    if not boxes:
        return
    pairs = STRtree(boxes).query(boxes, predicate="intersects")
    for i, j in pairs.T:
        if i < j:
            area = boxes[i].intersection(boxes[j]).area
            if area > LABEL_OVERLAP:
                yield Finding(
                    "label-clear",
                    f"{labels[i].text!r} and {labels[j].text!r} overlap ({area:.1f} mm²)",
                    _at(boxes[i]),
                    v.name,
                )


def leader_clear(v: SheetView) -> Iterator[Finding]:
    """A leader crosses no other name: the reader following it would run
    into another name's letters (each label's box shrunk as label-clear
    does). A rule apart from label-near, which the composers ask where names
    crowd (crowd.py): this one judges the sheet only."""
    led = [lab for lab in v.labels if lab.leader is not None]
    if not led:
        return
    inner = [lab.box.buffer(-CLEAR_SHRINK) for lab in v.labels]
    letters = STRtree(inner)
    for lab in led:
        assert lab.leader is not None
        ld = LineString([lab.leader.start, lab.leader.end])
        through = [
            v.labels[i].text
            for i in letters.query(ld, predicate="intersects")
            if v.labels[i] is not lab and not inner[i].is_empty
        ]
        if through:
            yield Finding(
                "leader-clear",
                f"{lab.text!r}: its leader crosses the name {through[0]!r}",
                _at(lab.box),
                v.name,
            )


def vectors_apart(v: SheetView) -> Iterator[Finding]:
    by_group: dict[str, list[Arrow]] = {}
    for c in v.calls:
        # a plan's images of the points of one link lie on one line by similarity:
        # the force polygons and the lever are checked
        if isinstance(c, Arrow) and v.cls_of(c) & {"force-polygon", "lever"} and c.length > 1e-6:
            by_group.setdefault(v.top_group(c), []).append(c)
    for group, arrows in by_group.items():
        if len(arrows) < 2:
            continue
        s = np.array([a.start for a in arrows])
        e = np.array([a.end for a in arrows])
        d = e - s
        u = d / np.hypot(d[:, 0], d[:, 1])[:, None]
        for i, j in itertools.combinations(range(len(arrows)), 2):
            cross = abs(u[i, 0] * u[j, 1] - u[i, 1] * u[j, 0])
            if cross > math.sin(math.radians(COLLINEAR_DEG)):
                continue
            w = s[j] - s[i]
            off = abs(u[i, 0] * w[1] - u[i, 1] * w[0])
            if off > COLLINEAR_MM:
                continue
            ti = sorted((0.0, float(np.dot(d[i], u[i]))))
            tj = sorted((float(np.dot(s[j] - s[i], u[i])), float(np.dot(e[j] - s[i], u[i]))))
            overlap = min(ti[1], tj[1]) - max(ti[0], tj[0])
            if overlap > OVERLAP_MM:
                mid = (s[i] + e[i]) / 2
                yield Finding(
                    "vectors-apart",
                    f"two vectors of {group} lie on one line, {overlap:.1f} mm over each other",
                    (round(float(mid[0]), 1), round(float(mid[1]), 1)),
                    v.name,
                )


def names_unique(v: SheetView) -> Iterator[Finding]:
    yield from _detail_letters(v)
    named = [lab for lab in v.labels if lab.naming is not None]
    by_group: dict[str, list[_Label]] = {}
    for lab in named:
        by_group.setdefault(lab.groups[0] if lab.groups else "", []).append(lab)
    for group, labs in by_group.items():
        for a, b in itertools.combinations(labs, 2):
            assert a.naming is not None and b.naming is not None
            # ω, ε at each drawn position and the positions' numbers repeat by design
            repeats = a.text[:1] in ("ω", "ε") or a.text.isdigit()
            # a label of coincident images names each of them: "p, s5"
            shared = set(a.text.split(", ")) & set(b.text.split(", "))
            if shared and not repeats and math.dist(a.naming.anchor, b.naming.anchor) > 1.0:
                yield Finding(
                    "names-unique",
                    f"{', '.join(sorted(shared))!r} names two different things in {group}",
                    _at(b.box),
                    v.name,
                )
            elif {a.text, b.text} in LOOKALIKE and a.box.distance(b.box) < LOOKALIKE_MM:
                yield Finding(
                    "names-unique",
                    f"{a.text!r} and {b.text!r} read alike {a.box.distance(b.box):.0f} mm apart",
                    _at(b.box),
                    v.name,
                )


_DETAIL_TITLE = re.compile(r"^(\S+) \(\d+(?:[.,]\d+)?:1\)$")


def _detail_letters(v: SheetView) -> Iterator[Finding]:
    """A detail view's letter (its title "H (2:1)", GOST 2.305) names one
    view of the sheet: two views lettered alike read as one."""
    seen: dict[str, str] = {}
    for c in v.texts:
        m = _DETAIL_TITLE.match(c.content)
        top = v.top_group(c)
        if m is None or "detail" not in top:
            continue
        letter = m.group(1)
        if letter in seen and seen[letter] != top:
            yield Finding(
                "names-unique",
                f"two detail views are lettered {letter!r} ({seen[letter]} and {top})",
                (round(c.pos[0], 1), round(c.pos[1], 1)),
                v.name,
            )
        seen.setdefault(letter, top)


def arrows_named(v: SheetView) -> Iterator[Finding]:
    boxes = [lab.box for lab in v.labels]
    tree = STRtree(boxes) if boxes else None
    led = [lab for lab in v.labels if lab.leader is not None]
    for c in v.calls:
        if not isinstance(c, Arrow) or not (v.cls_of(c) & {"plan", "force-polygon", "lever"}):
            continue
        if c.length < 1.0:
            continue
        shaft = LineString([c.start, c.end])
        if tree is not None and len(tree.query(shaft, predicate="dwithin", distance=ARROW_NAME_MM)):
            continue
        if any(_led_to(lab, shaft) for lab in led):
            continue  # its name stands further out, joined to it by its own leader
        yield Finding("arrows-named", "a vector with no name near it", _at(shaft), v.name)


def _led_to(lab: _Label, shaft: LineString) -> bool:
    """Whether `lab` names the arrow `shaft` and its leader touches it."""
    n = lab.naming
    if n is None or n.end is None or lab.leader is None:
        return False
    named = LineString([n.anchor, n.end])
    if named.hausdorff_distance(shaft) > 0.5:
        return False
    return LineString([lab.leader.start, lab.leader.end]).distance(shaft) < 1.0


def letter_height(v: SheetView) -> Iterator[Finding]:
    for c in v.texts:
        if c.content.strip() and c.size < MIN_LETTER - 1e-9:
            yield Finding(
                "letter-height",
                f"{c.content!r} is {c.size:g} mm high (at least {MIN_LETTER:g} mm, GOST 2.304)",
                c.pos,
                v.name,
            )


_NUMERIC = re.compile(r"^[-−]?\d+(?:[.,](\d+))?$")  # not ±0.049* (an absolute error)
_UNIT = re.compile(
    r"(,\s*\S+|\(\S+\)|%|°|\bm/s|м/с|1/s|1/с|\bN\b|\bН\b|мм|mm|rad|рад|kg|кг|W\b|Вт)"
)

_TITLE_UNIT = re.compile(r",\s*\S+$")  # "Reactions in the pairs, N": the unit of every column


def _table_title(v: SheetView, g: str) -> str:
    """The lettering above a table's outline: its title."""
    outline = [c.bbox() for c in v.calls if g in c.groups and c.name == "polygon"]
    top = max((b[3] for b in outline if b is not None), default=math.inf)
    return " ".join(c.content for c in v.texts if g in c.groups and c.pos[1] > top)


def table_format(v: SheetView) -> Iterator[Finding]:
    groups = [g for g, k in v.classes.items() if k == "table"]
    # a part of a continued table (drawing/table: gid-2, gid-3…, titled
    # "Continuation of Table n", GOST 2.105) has its unit in its table's title
    continued = {
        g: m.group(1)
        for g in groups
        if (m := re.fullmatch(r"(.+)-\d+", g)) is not None and m.group(1) in groups
    }
    for g in groups:
        texts = [c for c in v.texts if g in c.groups]
        lines = [c for c in v.calls if isinstance(c, Line) and g in c.groups and c.line == "main"]
        heads = [ln for ln in lines if abs(ln.start[1] - ln.end[1]) < 1e-6]
        if not heads:
            continue
        head_y = heads[0].start[1]
        outline = [c.bbox() for c in v.calls if g in c.groups and c.name == "polygon"]
        top = max((b[3] for b in outline if b is not None), default=math.inf)
        left_line = min(
            (ln.start[0] for ln in lines if abs(ln.start[0] - ln.end[0]) < 1e-6), default=-math.inf
        )
        columns: dict[float, list[Text]] = {}
        header: list[Text] = []
        title = [c for c in texts if c.pos[1] > top]
        row_labels = [c for c in texts if c.pos[1] < head_y and c.pos[0] < left_line]
        for c in texts:
            if c in title:
                continue
            if c.pos[1] > head_y:
                header.append(c)
            elif c.valign == "middle":
                columns.setdefault(round(c.pos[0], 1), []).append(c)
        title_text = " ".join(c.content for c in title)
        if g in continued:
            title_text += " " + _table_title(v, continued[g])
        for x, cells in columns.items():
            decimals = set()
            plain = True
            for c in cells:
                if c.content.strip() in ("—", "-"):
                    continue
                m = _NUMERIC.match(c.content.strip())
                if m is None:
                    plain = False
                    continue
                decimals.add(len(m.group(1) or ""))
            if len(decimals) > 1:
                yield Finding(
                    "table-format",
                    f"column of {g} mixes {sorted(decimals)} decimals",
                    (x, head_y),
                    v.name,
                )
            if plain and decimals - {0}:
                words = " ".join(
                    h.content
                    for h in header
                    if h.box()[0] <= x + 1.0 and h.box()[2] >= x - 1.0 and h not in title
                )
                # the unit in the column's header, the table's title, or every row's name
                rows_say = all(
                    any(
                        _UNIT.search(r.content) and abs(r.pos[1] - c.pos[1]) < 2.0
                        for r in row_labels
                    )
                    for c in cells
                )
                if not (_UNIT.search(words) or _TITLE_UNIT.search(title_text) or rows_say):
                    yield Finding(
                        "table-format",
                        f"column {words!r} of {g} has no unit in its header",
                        (x, head_y),
                        v.name,
                    )


# a Latin unit after a number, a comma or a bracket
_LATIN_UNITS = re.compile(
    r"(?:\d\s+|,\s+|\()(m/s²?|m/mm|rad/s|mm|kN|N·m|N|rad|kg|m)(?![A-Za-z])|(?<![\w/])1/s"
)  # "G, N", "(m/s)", "1/s"; not a point N in R9N
_POINT = re.compile(r"(?<![\w.])\d+\.\d+(?![\w.])")
_COMMA = re.compile(r"[-−]?\d+,\d+")
_CYRILLIC = re.compile(r"[А-Яа-яІіЇїЄєҐґ]")


def language(v: SheetView) -> Iterator[Finding]:
    code = designation_of(v)
    for c in v.texts:
        t = c.content
        if c is code:  # one designation in both languages
            continue
        if v.lang == "uk":
            if _POINT.search(t):
                yield Finding("language", f"a decimal point in {t!r}", c.pos, v.name)
            m = _LATIN_UNITS.search(t) if c.naming is None else None  # "b, m" names images
            if m:
                yield Finding("language", f"a Latin unit {m.group(0)!r} in {t!r}", c.pos, v.name)
        else:
            # a number of a table or the title block, not an index (R_{0,11}, I(0,1))
            # (a cell's lettering is set in its middle; an index run on its baseline)
            numbers = bool(v.cls_of(c) & {"table", "title-block"}) and c.valign == "middle"
            if numbers and _COMMA.fullmatch(t.strip()):
                yield Finding("language", f"a decimal comma in {t!r}", c.pos, v.name)
            if _CYRILLIC.search(t):
                yield Finding("language", f"Cyrillic in {t!r}", c.pos, v.name)
    if v.lang == "uk":
        block = [c for c in v.texts if "title-block" in c.groups and c.size == 2.5]
        titled = [c for c in block if len(c.content) > 12]
        if titled and not any(_CYRILLIC.search(c.content) for c in titled[:1]):
            yield Finding(
                "language",
                f"the title {titled[0].content!r} is not Ukrainian",
                titled[0].pos,
                v.name,
            )


_DESIGNATION = re.compile(r"^[A-ZА-ЯІЇЄҐ0-9]+(\.[A-ZА-ЯІЇЄҐ0-9]+)+$")


def designation_of(v: SheetView) -> Text | None:
    block = [c for c in v.texts if "title-block" in c.groups]
    return max(block, key=lambda c: c.size, default=None)


def designation(v: SheetView) -> Iterator[Finding]:
    d = designation_of(v)
    if d is None:
        return
    if not _DESIGNATION.match(d.content):
        yield Finding(
            "designation",
            f"{d.content!r} is not a GOST 2.201 designation (capitals and digits in groups joined by dots)",
            d.pos,
            v.name,
        )


_REDUCED = re.compile(r"reduced|зменшено", re.IGNORECASE)


_RESISTANCE = re.compile(r"^F_\{?(PR|КО)\}?$")


def _resistance_arrows(v: SheetView, arrows: Sequence[Arrow]) -> list[Arrow]:
    """The arrows of `arrows` named as the production resistance F_PR (F_КО):
    by the arrow itself, or by the middle of its shaft (a polygon's sides)."""
    named = [
        lab.naming
        for lab in v.labels
        if lab.naming is not None and _RESISTANCE.match(lab.naming.markup)
    ]

    def names(n: Naming, a: Arrow) -> bool:
        if n.end is not None:
            return math.dist(n.anchor, a.start) < 0.05 and math.dist(n.end, a.end) < 0.05
        middle = ((a.start[0] + a.end[0]) / 2, (a.start[1] + a.end[1]) / 2)
        return math.dist(n.anchor, middle) < 0.05

    return [a for a in arrows if any(names(n, a) for n in named)]


def guide_sizes(v: SheetView) -> Iterator[Finding]:
    reduced = any(_REDUCED.search(c.content) for c in v.texts)
    for g, k in v.classes.items():
        arrows = [c for c in v.calls if isinstance(c, Arrow) and g in c.groups]
        if not arrows:
            continue
        if k == "plan":
            # the pole: where most of the plan's vectors start
            starts = collections.Counter(
                (round(a.start[0], 2), round(a.start[1], 2)) for a in arrows
            )
            pole = starts.most_common(1)[0][0]
            rays = [a for a in arrows if math.dist(a.start, pole) < 0.02] or arrows
            size, (lo, hi) = max(a.length for a in rays), PLAN_MM
            what = "longest vector from the pole"
        elif k == "force-polygon":
            # the guide sizes a polygon by its production resistance, |F_PR| =
            # 150 … 300 mm (seed 003, formula (20)); one without it, or one
            # where |F_PR| at 150 mm would put a side past 300 mm, by its
            # longest side (as sheet 2's guide_side chooses)
            resistance = _resistance_arrows(v, arrows)
            (lo, hi), longest = POLYGON_MM, max(a.length for a in arrows)
            f_pr = max((a.length for a in resistance), default=0.0)
            if f_pr > 0 and (f_pr >= lo - 0.5 or longest * lo / f_pr <= hi + 0.5):
                size, what = f_pr, "|F_PR|"
            else:
                size, what = longest, "longest side"
        else:
            continue
        if size < lo - 0.5 and not reduced or size > hi + 0.5:
            a = max(arrows, key=lambda a: a.length)
            yield Finding(
                "guide-sizes",
                f"{g}: {what} {size:.0f} mm (guide {lo:g}–{hi:g} mm)",
                a.end,
                v.name,
            )


_DEV_PROSE = re.compile(
    r"the calculation's|drawn at the μ|fills its field|μ that fills|"
    r"TODO|FIXME|debug|fallback|the layout|the code|розрахунку μ|заповнює його поле",
    re.IGNORECASE,
)


def no_dev_prose(v: SheetView) -> Iterator[Finding]:
    for c in v.texts:
        if _DEV_PROSE.search(c.content):
            yield Finding("no-dev-prose", f"{c.content[:80]!r}", c.pos, v.name)


def field_filled(v: SheetView) -> Iterator[Finding]:
    frame = [c for c in v.calls if "frame" in c.groups and c.bbox() is not None]
    block = [c for c in v.calls if "title-block" in c.groups and c.bbox() is not None]
    if not frame:
        return
    fb = np.array([c.bbox() for c in frame])
    x0, y0, x1, y1 = fb[:, 0].min(), fb[:, 1].min(), fb[:, 2].max(), fb[:, 3].max()
    field_ = box(x0, y0, x1, y1)
    if block:
        bb = np.array([c.bbox() for c in block])
        field_ = field_.difference(box(bb[:, 0].min(), y0, x1, bb[:, 3].max()))
    parts = []
    for g in v.classes:
        if g in ("frame", "title-block"):
            continue
        bbs = [c.bbox() for c in v.calls if g in c.groups and c.bbox() is not None]
        if bbs:
            a = np.array(bbs)
            parts.append(box(a[:, 0].min(), a[:, 1].min(), a[:, 2].max(), a[:, 3].max()))
    empty = empty_share(field_, parts)
    if empty > EMPTY_MAX:
        yield Finding(
            "field-filled",
            f"{100 * empty:.0f} % of the field is empty (at most {100 * EMPTY_MAX:.0f} %)",
            _at(field_),
            v.name,
        )


RULES: dict[str, Rule] = {
    "label-near": label_near,
    "label-clear": label_clear,
    "leader-clear": leader_clear,
    "vectors-apart": vectors_apart,
    "names-unique": names_unique,
    "arrows-named": arrows_named,
    "letter-height": letter_height,
    "table-format": table_format,
    "language": language,
    "designation": designation,
    "guide-sizes": guide_sizes,
    "no-dev-prose": no_dev_prose,
    "field-filled": field_filled,
}


def lint(view: SheetView, rules: Sequence[str] | None = None) -> list[Finding]:
    """The findings of every rule (or of `rules`) on one sheet."""
    out: list[Finding] = []
    for name in rules or RULES:
        out.extend(RULES[name](view))
    return out


def lint_pair(en: SheetView, uk: SheetView) -> list[Finding]:
    """The rules across the two languages of one sheet: one designation."""
    a, b = designation_of(en), designation_of(uk)
    if a is None or b is None or a.content == b.content:
        return []
    return [
        Finding(
            "designation",
            f"en {a.content!r} and uk {b.content!r} differ",
            b.pos,
            uk.name,
        )
    ]
