"""A backend that records every drawing call as a typed record (ezdxf
`addons/drawing/recorder.py`), for layout, label placement, tests and the
sheet linter.

One frozen record type per primitive (`Line`, `Polyline`, `Polygon`,
`Circle`, `Arc`, `Arrow`, `Text`, and `BeginGroup`/`EndGroup`), each with its
bounding box and the ids of the groups it was drawn in. A label written
through `naming` carries what it names (`Naming`: the point, the arrow or the
segment, and the label's markup), so a check can measure a label against its
anchor. Records also answer the older dict-style reads (`c.name`, `c["key"]`,
`c.args`, `Call(name, args, groups)`), which code written before the typed
records still uses.
"""

from __future__ import annotations

import contextlib
import dataclasses
import itertools
import math
from collections.abc import Iterator, Sequence
from dataclasses import dataclass
from typing import Any, ClassVar, Literal, cast

from .backend import (
    Backend,
    Fill,
    HAlign,
    LineType,
    Point,
    PointLike,
    TextRun,
    VAlign,
    as_point,
    parse_markup,
)
from .look import Lettering

__all__ = [
    "Arc",
    "Arrow",
    "BBox",
    "BeginGroup",
    "Call",
    "Circle",
    "LabelRun",
    "EndGroup",
    "Line",
    "NamingKind",
    "Naming",
    "Polygon",
    "Polyline",
    "Record",
    "RecordingBackend",
    "Text",
]

BBox = tuple[float, float, float, float]  # xmin, ymin, xmax, ymax, mm
NamingKind = Literal["point", "arrow", "segment"]


@dataclass(frozen=True)
class Naming:
    """What a label names: a point (`anchor`), an arrow or a segment
    (`anchor`–`end`). `label` numbers the labels of one recording, so the
    runs of one label (a letter, then its index) and its leader line share it."""

    label: int
    markup: str
    kind: NamingKind
    anchor: Point
    end: Point | None = None

    def shifted(self, dx: float, dy: float) -> Naming:
        end = None if self.end is None else (self.end[0] + dx, self.end[1] + dy)
        return dataclasses.replace(self, anchor=(self.anchor[0] + dx, self.anchor[1] + dy), end=end)


@dataclass(frozen=True)
class LabelRun:
    """Marks a text record as one run of a label set by `rich_text`: the
    label's runs and the label's position relative to this run's, so that a
    backend that sets a label whole (`sets_labels_whole`, DXF: one MTEXT) gets
    the label back on replay. Every other reader sees the runs as texts."""

    serial: int
    index: int  # of this run in `runs`
    runs: tuple[TextRun, ...]
    offset: Point  # the label's pos less this run's pos
    size: float
    anchor: HAlign
    valign: VAlign
    rotation: float


_LABELS = itertools.count(1)  # label serials, unique across spliced sketches
_RECORDS: dict[str, type[Call]] = {}
_LABEL_IDS = itertools.count(1)  # labels are numbered across recordings


class _Args(dict[str, Any]):
    """A record's arguments as a dict, remembering the record (so that
    `type(c)(c.name, c.args, groups)` keeps what it names)."""

    record: Call | None = None


_FIELDS: dict[type, tuple[dataclasses.Field, ...]] = {}
_ARG_NAMES: dict[type, tuple[str, ...]] = {}  # the fields `Call.args` gives, by class


def _fields_of(cls: type) -> tuple[dataclasses.Field, ...]:
    """`dataclasses.fields` of a record class, looked up once per class (a
    sheet makes tens of thousands of records)."""
    found = _FIELDS.get(cls)
    if found is None:
        found = _FIELDS[cls] = dataclasses.fields(cls)  # type: ignore[arg-type]
    return found


class Call:
    """The base of the records: `name` says which primitive; `groups` are the
    ids of the groups it was drawn in, outermost first.

    `Call(name, args, groups)` (the older form) makes the record of that name
    from a dict of its arguments; so does `type(record)(name, args, groups)`.
    """

    name: ClassVar[str] = ""
    groups: tuple[str, ...]
    naming: Naming | None

    def __init_subclass__(cls, **kw: Any) -> None:
        super().__init_subclass__(**kw)
        if cls.name:
            _RECORDS[cls.name] = cls

    def __new__(cls, *args: Any, **kwargs: Any) -> Any:
        if cls is Call and args:
            try:
                cls = _RECORDS[args[0]]
            except KeyError:
                raise ValueError(f"no drawing record is named {args[0]!r}") from None
        return object.__new__(cls)

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        every = _fields_of(type(self))
        fields = [f.name for f in every]
        if len(args) >= 2 and isinstance(args[0], str) and isinstance(args[1], dict):
            values = dict(args[1])
            source = getattr(args[1], "record", None)
            if isinstance(source, type(self)):  # what a label names, a text's width
                for kept in ("naming", "width", "label"):
                    if hasattr(source, kept):
                        values.setdefault(kept, getattr(source, kept))
            values.pop("length", None)  # an arrow's length is derived
            if len(args) > 2:
                values["groups"] = args[2]
            values.update(kwargs)
        else:
            if len(args) > len(fields):
                raise TypeError(f"{type(self).__name__} takes at most {len(fields)} arguments")
            values = dict(zip(fields, args))
            values.update(kwargs)
        for f in every:
            if f.name in values:
                v = values.pop(f.name)
            elif f.default is not dataclasses.MISSING:
                v = f.default
            elif f.default_factory is not dataclasses.MISSING:
                v = f.default_factory()
            else:
                raise TypeError(f"{type(self).__name__} needs {f.name!r}")
            object.__setattr__(self, f.name, v)
        if values:
            raise TypeError(f"{type(self).__name__} has no {', '.join(values)}")
        object.__setattr__(self, "groups", tuple(self.groups))

    # --- the older, dict-style reads -------------------------------------------

    @property
    def args(self) -> dict[str, Any]:
        """The drawing call's arguments by name (without groups and naming)."""
        names = _ARG_NAMES.get(type(self))
        if names is None:
            skip = ("groups", "naming", "width", "label")
            names = _ARG_NAMES[type(self)] = tuple(
                f.name for f in _fields_of(type(self)) if f.name not in skip
            )
        values = self.__dict__
        out = _Args({name: values[name] for name in names})
        out.update(self._derived())
        out.record = self
        return out

    def _derived(self) -> dict[str, Any]:
        return {}

    def __getitem__(self, key: str) -> Any:
        return self.args[key]

    # --- geometry ---------------------------------------------------------------

    def points(self) -> list[Point]:
        """The defining points of the call (for bounds and containment checks)."""
        return []

    def bbox(self) -> BBox | None:
        """(xmin, ymin, xmax, ymax) of what the record covers; None if nothing."""
        pts = self.points()
        if not pts:
            return None
        xs, ys = [p[0] for p in pts], [p[1] for p in pts]
        return (min(xs), min(ys), max(xs), max(ys))

    def shifted(self, dx: float, dy: float) -> Call:
        """The same record moved by (dx, dy) mm."""
        return self

    def with_changes(self, **changes: Any) -> Call:
        """The same record with some fields changed (`content=`, `groups=` …)."""
        return dataclasses.replace(self, **changes)  # type: ignore[type-var]


def _t(p: Point, dx: float, dy: float) -> Point:
    return (p[0] + dx, p[1] + dy)


@dataclass(frozen=True, init=False, eq=True)
class BeginGroup(Call):
    name: ClassVar[str] = "begin_group"
    id: str
    cls: str | None = None
    groups: tuple[str, ...] = ()
    naming: Naming | None = None


@dataclass(frozen=True, init=False)
class EndGroup(Call):
    name: ClassVar[str] = "end_group"
    groups: tuple[str, ...] = ()
    naming: Naming | None = None


@dataclass(frozen=True, init=False)
class Line(Call):
    name: ClassVar[str] = "line"
    start: Point
    end: Point
    line: LineType = "main"
    groups: tuple[str, ...] = ()
    naming: Naming | None = None  # a label's leader line

    def points(self) -> list[Point]:
        return [self.start, self.end]

    def shifted(self, dx: float, dy: float) -> Line:
        naming = None if self.naming is None else self.naming.shifted(dx, dy)
        return dataclasses.replace(
            self, start=_t(self.start, dx, dy), end=_t(self.end, dx, dy), naming=naming
        )


@dataclass(frozen=True, init=False)
class Polyline(Call):
    name: ClassVar[str] = "polyline"
    vertices: tuple[Point, ...]
    line: LineType = "main"
    groups: tuple[str, ...] = ()
    naming: Naming | None = None

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        if len(args) >= 2 and isinstance(args[1], dict) and "points" in args[1]:
            a = dict(args[1])
            a["vertices"] = a.pop("points")
            args = (args[0], a, *args[2:])
        if "points" in kwargs:
            kwargs["vertices"] = kwargs.pop("points")
        super().__init__(*args, **kwargs)

    @property
    def args(self) -> dict[str, Any]:
        out = _Args(points=self.vertices, line=self.line)
        out.record = self
        return out

    def points(self) -> list[Point]:
        return list(self.vertices)

    def shifted(self, dx: float, dy: float) -> Polyline:
        return dataclasses.replace(self, vertices=tuple(_t(p, dx, dy) for p in self.vertices))


@dataclass(frozen=True, init=False)
class Polygon(Polyline):
    name: ClassVar[str] = "polygon"
    vertices: tuple[Point, ...]
    line: LineType | None = "main"  # type: ignore[assignment]
    fill: Fill = "none"
    groups: tuple[str, ...] = ()
    naming: Naming | None = None

    @property
    def args(self) -> dict[str, Any]:
        out = _Args(points=self.vertices, line=self.line, fill=self.fill)
        out.record = self
        return out

    def shifted(self, dx: float, dy: float) -> Polygon:
        return dataclasses.replace(self, vertices=tuple(_t(p, dx, dy) for p in self.vertices))


@dataclass(frozen=True, init=False)
class Circle(Call):
    name: ClassVar[str] = "circle"
    center: Point
    radius: float
    line: LineType | None = "main"
    fill: Fill = "none"
    groups: tuple[str, ...] = ()
    naming: Naming | None = None

    def points(self) -> list[Point]:
        (cx, cy), r = self.center, self.radius
        return [(cx - r, cy - r), (cx + r, cy + r)]

    def shifted(self, dx: float, dy: float) -> Circle:
        return dataclasses.replace(self, center=_t(self.center, dx, dy))


@dataclass(frozen=True, init=False)
class Arc(Call):
    name: ClassVar[str] = "arc"
    center: Point
    radius: float
    start_deg: float
    end_deg: float
    line: LineType = "main"
    groups: tuple[str, ...] = ()
    naming: Naming | None = None

    def points(self) -> list[Point]:
        (cx, cy), r = self.center, self.radius
        return [(cx - r, cy - r), (cx + r, cy + r)]

    def bbox(self) -> BBox:
        (cx, cy), r = self.center, self.radius
        span = (self.end_deg - self.start_deg) % 360.0 or 360.0
        angles = [self.start_deg + span * k / 32 for k in range(33)]
        xs = [cx + r * math.cos(math.radians(a)) for a in angles]
        ys = [cy + r * math.sin(math.radians(a)) for a in angles]
        return (min(xs), min(ys), max(xs), max(ys))

    def shifted(self, dx: float, dy: float) -> Arc:
        return dataclasses.replace(self, center=_t(self.center, dx, dy))


@dataclass(frozen=True, init=False)
class Arrow(Call):
    name: ClassVar[str] = "arrow"
    start: Point
    end: Point
    line: LineType = "main"
    head_length: float = 2.5
    head_width: float = 0.9
    groups: tuple[str, ...] = ()
    naming: Naming | None = None

    @property
    def length(self) -> float:
        return math.dist(self.start, self.end)

    def _derived(self) -> dict[str, Any]:
        return {"length": self.length}

    def points(self) -> list[Point]:
        return [self.start, self.end]

    def shifted(self, dx: float, dy: float) -> Arrow:
        return dataclasses.replace(self, start=_t(self.start, dx, dy), end=_t(self.end, dx, dy))


@dataclass(frozen=True, init=False)
class Text(Call):
    """One run of lettering; `size` the capital height (mm), `width` its
    drawn width by the look's lettering metrics (narrowed to `max_width`)."""

    name: ClassVar[str] = "text"
    pos: Point
    content: str
    size: float = 3.5
    anchor: HAlign = "left"
    valign: VAlign = "baseline"
    rotation: float = 0.0
    max_width: float | None = None
    groups: tuple[str, ...] = ()
    naming: Naming | None = None  # what the label this run belongs to names
    width: float | None = None  # None: not measured (made without a look)
    label: LabelRun | None = None  # the rich-text label this run belongs to
    # drawn in this lettering, not the page's (a note's figure copied from a
    # sheet: Backend.lettered_as); None: the page's
    lettering: Lettering | None = None

    def points(self) -> list[Point]:
        return [self.pos]

    def box(self, width: float | None = None) -> BBox:
        """The box of the capitals (rotated text: the box round the turned one)."""
        w = self.width if width is None else width
        if w is None:
            raise ValueError("this text record was not measured; use RecordingBackend.text_box")
        size = self.size
        x0 = {"left": 0.0, "center": -w / 2, "right": -w}[self.anchor]
        y0 = {"baseline": 0.0, "middle": -size / 2, "top": -size}[self.valign]
        x, y = self.pos
        if self.rotation % 360.0 == 0.0:
            return (x + x0, y + y0, x + x0 + w, y + y0 + size)
        a = math.radians(self.rotation)
        ca, sa = math.cos(a), math.sin(a)
        corners = [(x0, y0), (x0 + w, y0), (x0 + w, y0 + size), (x0, y0 + size)]
        xs = [x + u * ca - v * sa for u, v in corners]
        ys = [y + u * sa + v * ca for u, v in corners]
        return (min(xs), min(ys), max(xs), max(ys))

    def bbox(self) -> BBox | None:
        return None if self.width is None else self.box()

    def with_changes(self, **changes: Any) -> Call:
        # new lettering is measured again (by whoever has the look)
        if {"content", "size", "max_width"} & set(changes) and "width" not in changes:
            changes["width"] = None
        return super().with_changes(**changes)

    def shifted(self, dx: float, dy: float) -> Text:
        naming = None if self.naming is None else self.naming.shifted(dx, dy)
        return dataclasses.replace(self, pos=_t(self.pos, dx, dy), naming=naming)


# Every record is a Call; `Record` is the name new code reads.
Record = Call


_RECORDING_METHODS: tuple[str, ...] = (
    *("line", "polygon", "polyline", "circle", "arc", "arrow", "text", "rich_text"),
    *("begin_group", "end_group", "_begin_group", "_end_group"),
)


def _plain_recording(backend: Any) -> bool:
    """Whether `backend` is a recording whose drawing methods are RecordingBackend's own."""
    kind = type(backend)
    return issubclass(kind, RecordingBackend) and all(
        getattr(kind, m) is getattr(RecordingBackend, m) for m in _RECORDING_METHODS
    )


def _made(cls: type[Any], values: dict[str, Any]) -> Any:
    """A record of `cls` from the values of all its fields, checked by the
    caller (RecordingBackend's methods): what `Call.__init__` makes, without
    its argument matching, which a sheet or a note pays tens of thousands of
    times (tests/render/test_recording.py holds the two alike)."""
    record = object.__new__(cls)
    record.__dict__.update(values)
    return record


class RecordingBackend(Backend):
    """Keeps `calls` (typed records) in order; `begin_group`/`end_group` are recorded too."""

    def __init__(self, width: float = 841.0, height: float = 594.0, look=None) -> None:
        super().__init__(width, height, look)
        self.calls: list[Call] = []
        self._naming: Naming | None = None
        self._label_ids: set[int] = set()
        self._page_look = self.look  # Backend.lettered_as swaps self.look for a while
        self._label: tuple[int, tuple[TextRun, ...], Point, list[int], dict[str, Any]] | None = None

    def rich_text(
        self,
        pos: PointLike,
        content: str | Sequence[TextRun],
        size: float = 3.5,
        *,
        anchor: HAlign = "left",
        valign: VAlign = "baseline",
        rotation: float = 0.0,
    ) -> float:
        runs = tuple(parse_markup(content) if isinstance(content, str) else content)
        # the runs base rich_text draws, in order: those with a non-blank body
        drawn = [i for i, (t, _) in enumerate(runs) if t.strip(" ")]
        style = {"size": float(size), "anchor": anchor, "valign": valign, "rotation": rotation}
        self._label = (next(_LABELS), runs, as_point(pos), drawn, style)
        try:
            return super().rich_text(
                pos, list(runs), size, anchor=anchor, valign=valign, rotation=rotation
            )
        finally:
            self._label = None

    def _add(self, record: Call) -> None:
        self.calls.append(record)
        if record.naming is not None:
            self._label_ids.add(record.naming.label)

    # --- what a label names ---------------------------------------------------

    @contextlib.contextmanager
    def naming(
        self,
        markup: str,
        kind: NamingKind,
        anchor: PointLike,
        end: PointLike | None = None,
    ) -> Iterator[Naming]:
        """Every text (and leader line) drawn inside is one label naming
        `anchor` (a point) or `anchor`–`end` (an arrow, a segment)."""
        outer = self._naming
        self._naming = Naming(
            next(_LABEL_IDS),
            markup,
            kind,
            as_point(anchor),
            None if end is None else as_point(end),
        )
        try:
            yield self._naming
        finally:
            self._naming = outer

    # --- queries -------------------------------------------------------------

    def named(self, *names: str) -> list[Call]:
        return [c for c in self.calls if c.name in names]

    def in_group(self, group_id: str) -> list[Call]:
        """Calls drawn inside the group `group_id` (at any depth)."""
        return [c for c in self.calls if group_id in c.groups and not c.name.endswith("group")]

    def texts(self) -> list[str]:
        return [c["content"] for c in self.named("text")]

    def text_box(self, call: Call) -> tuple[float, float, float, float]:
        """Estimated (xmin, ymin, xmax, ymax) of an unrotated text call's capitals."""
        if not isinstance(call, Text):
            raise ValueError("text_box needs a text call")
        if call.rotation % 360.0 != 0.0:
            raise ValueError("text_box handles unrotated text only")
        w = self.look.lettering.width(call.content, call.size, call.max_width)
        return call.box(w)

    # --- the interface -------------------------------------------------------

    def line(self, start: PointLike, end: PointLike, line: LineType = "main") -> None:
        self._check_line(line)
        naming = self._naming
        self.calls.append(
            _made(
                Line,
                {
                    "start": as_point(start),
                    "end": as_point(end),
                    "line": line,
                    "groups": tuple(self._open_groups),
                    "naming": naming,
                },
            )
        )
        if naming is not None:
            self._label_ids.add(naming.label)

    def polyline(self, points: Sequence[PointLike], line: LineType = "main") -> None:
        self._check_line(line)
        pts = tuple(as_point(p) for p in points)
        self.calls.append(
            _made(
                Polyline,
                {"vertices": pts, "line": line, "groups": tuple(self._open_groups), "naming": None},
            )
        )

    def polygon(
        self, points: Sequence[PointLike], line: LineType | None = "main", fill: Fill = "none"
    ) -> None:
        self._check_line(line, allow_none=True)
        self._check_fill(fill)
        pts = tuple(as_point(p) for p in points)
        self.calls.append(
            _made(
                Polygon,
                {
                    "vertices": pts,
                    "line": line,
                    "fill": fill,
                    "groups": tuple(self._open_groups),
                    "naming": None,
                },
            )
        )

    def circle(
        self, center: PointLike, radius: float, line: LineType | None = "main", fill: Fill = "none"
    ) -> None:
        self._check_line(line, allow_none=True)
        self._check_fill(fill)
        self.calls.append(
            _made(
                Circle,
                {
                    "center": as_point(center),
                    "radius": float(radius),
                    "line": line,
                    "fill": fill,
                    "groups": tuple(self._open_groups),
                    "naming": None,
                },
            )
        )

    def arc(
        self,
        center: PointLike,
        radius: float,
        start_deg: float,
        end_deg: float,
        line: LineType = "main",
    ) -> None:
        self._check_line(line)
        self._add(
            Arc(
                as_point(center),
                float(radius),
                float(start_deg),
                float(end_deg),
                line,
                groups=tuple(self._open_groups),
            )
        )

    def arrow(
        self,
        start: PointLike,
        end: PointLike,
        line: LineType = "main",
        *,
        head_length: float | None = None,
        head_width: float | None = None,
    ) -> None:
        self._check_line(line)
        hl = self.look.arrow_length if head_length is None else float(head_length)
        hw = self.look.arrow_width if head_width is None else float(head_width)
        self.calls.append(
            _made(
                Arrow,
                {
                    "start": as_point(start),
                    "end": as_point(end),
                    "line": line,
                    "head_length": hl,
                    "head_width": hw,
                    "groups": tuple(self._open_groups),
                    "naming": None,
                },
            )
        )

    def text(
        self,
        pos: PointLike,
        content: str,
        size: float = 3.5,
        *,
        anchor: HAlign = "left",
        valign: VAlign = "baseline",
        rotation: float = 0.0,
        max_width: float | None = None,
    ) -> None:
        self._check_text(size, anchor, valign, max_width)
        mw = None if max_width is None else float(max_width)
        p = as_point(pos)
        mark: LabelRun | None = None
        if self._label is not None and self._label[3]:
            serial, runs, at, drawn, style = self._label
            mark = LabelRun(serial, drawn.pop(0), runs, (at[0] - p[0], at[1] - p[1]), **style)
        text, h = str(content), float(size)
        naming = self._naming
        self.calls.append(
            _made(
                Text,
                {
                    "pos": p,
                    "content": text,
                    "size": h,
                    "anchor": anchor,
                    "valign": valign,
                    "rotation": float(rotation),
                    "max_width": mw,
                    "groups": tuple(self._open_groups),
                    "naming": naming,
                    "width": self.look.lettering.width(text, h, mw),
                    "label": mark,
                    "lettering": None if self.look is self._page_look else self.look.lettering,
                },
            )
        )
        if naming is not None:
            self._label_ids.add(naming.label)

    def _begin_group(self, id: str, cls: str | None) -> None:
        # Recorded with the groups as they were before this one opened.
        self.calls.append(
            _made(
                BeginGroup,
                {"id": id, "cls": cls, "groups": tuple(self._open_groups[:-1]), "naming": None},
            )
        )

    def _end_group(self) -> None:
        self.calls.append(_made(EndGroup, {"groups": tuple(self._open_groups), "naming": None}))

    def replay(self, backend: Backend, dx: float = 0.0, dy: float = 0.0) -> None:
        """Draw every recorded call again on `backend`, shifted by (dx, dy) mm;
        a recording backend keeps what each label names."""

        def t(p: Sequence[float]) -> tuple[float, float]:
            return (p[0] + dx, p[1] + dy)

        if _plain_recording(backend):
            self._replay_recorded(cast(RecordingBackend, backend), dx, dy)
            return
        into = isinstance(backend, RecordingBackend)  # a recording keeps what labels name
        target: Any = backend
        naming = target._naming if into else None
        whole = bool(getattr(backend, "sets_labels_whole", False))
        # each label's runs as recorded now (a sheet may have translated a run's text)
        labels: dict[int, list[TextRun]] = {}
        if whole:
            for c in self.calls:
                if isinstance(c, Text) and c.label is not None:
                    runs = labels.setdefault(c.label.serial, list(c.label.runs))
                    old, kind = runs[c.label.index]
                    lead = old[: len(old) - len(old.lstrip(" "))]
                    trail = old[len(old.rstrip(" ")) :]
                    runs[c.label.index] = (lead + c.content + trail, kind)
        # a label keeps its number, unless the target has one of that number
        # already (a sketch replayed twice): then it gets a new one
        renumbered: dict[int, Naming] = {}
        # the target's methods looked up once (a sheet replays thousands of records)
        line, polygon, polyline = backend.line, backend.polygon, backend.polyline
        circle, arc, arrow, text = backend.circle, backend.arc, backend.arrow, backend.text
        records: list[Any] = self.calls  # each read by its own type below
        for c in records:
            made = type(c)
            if into and c.naming is not None:
                target._naming = _renumbered(renumbered, c.naming, target, dx, dy)
            if made is Line:
                line(t(c.start), t(c.end), c.line)
            elif made is Text and not (whole and c.label is not None):
                with backend.lettered_as(c.lettering) if c.lettering else contextlib.nullcontext():
                    text(
                        t(c.pos),
                        c.content,
                        c.size,
                        anchor=c.anchor,
                        valign=c.valign,
                        rotation=c.rotation,
                        max_width=c.max_width,
                    )
                if into and c.label is not None:
                    # into another recording: the run keeps its label's mark
                    last = target.calls[-1]
                    target.calls[-1] = _made(Text, {**last.__dict__, "label": c.label})
            elif made is BeginGroup:
                backend.begin_group(c.id, c.cls)
            elif made is EndGroup:
                backend.end_group()
            elif made is Polygon:
                polygon([t(p) for p in c.vertices], c.line, c.fill)
            elif made is Polyline:
                polyline([t(p) for p in c.vertices], c.line)
            elif made is Circle:
                circle(t(c.center), c.radius, c.line, c.fill)
            elif made is Arc:
                arc(t(c.center), c.radius, c.start_deg, c.end_deg, c.line)
            elif made is Arrow:
                arrow(
                    t(c.start),
                    t(c.end),
                    c.line,
                    head_length=c.head_length,
                    head_width=c.head_width,
                )
            elif made is Text:  # a label's run onto a backend that sets labels whole
                whole_runs = labels.pop(c.label.serial, None)
                if whole_runs is not None:  # the label's first run: the whole label
                    x, y = t(c.pos)
                    mark = c.label
                    backend.rich_text(
                        (x + mark.offset[0], y + mark.offset[1]),
                        whole_runs,
                        mark.size,
                        anchor=mark.anchor,
                        valign=mark.valign,
                        rotation=mark.rotation,
                    )
            else:  # pragma: no cover - a new primitive must be added here
                raise ValueError(f"cannot replay {c.name!r}")
            if into:
                target._naming = naming

    def _replay_recorded(self, target: RecordingBackend, dx: float, dy: float) -> None:
        """`replay` onto a plain recording (no method of its own): each record
        made again as the target's drawing methods make it (shifted, in the
        target's open groups, a label's naming renumbered as `replay` does),
        without their checks and argument matching, already passed once."""
        naming = target._naming
        renumbered: dict[int, Naming] = {}
        out, ids = target.calls, target._label_ids
        width = target.look.lettering.width
        groups = tuple(target._open_groups)

        def t(p: Sequence[float]) -> tuple[float, float]:
            x, y = float(p[0] + dx), float(p[1] + dy)
            if x - x == 0.0 and y - y == 0.0:
                return (x, y)
            return as_point((x, y))  # raises as the drawing methods do

        records: list[Any] = self.calls  # each read by its own type below
        for c in records:
            made = type(c)
            if made is BeginGroup:
                target.begin_group(c.id, c.cls)
                groups = tuple(target._open_groups)
                continue
            if made is EndGroup:
                target.end_group()
                groups = tuple(target._open_groups)
                continue
            named = naming
            if c.naming is not None:
                named = _renumbered(renumbered, c.naming, target, dx, dy)
            values = dict(c.__dict__)
            values["groups"] = groups
            if made is Line:
                values["start"], values["end"] = t(c.start), t(c.end)
                values["naming"] = named
            elif made is Text:
                values["pos"] = t(c.pos)
                values["naming"] = named
                values["width"] = width(c.content, c.size, c.max_width)
            elif made is Polygon or made is Polyline:
                values["vertices"] = tuple(t(p) for p in c.vertices)
                values["naming"] = None
                named = None
            elif made is Circle or made is Arc:
                values["center"] = t(c.center)
                values["naming"] = None
                named = None
            elif made is Arrow:
                values["start"], values["end"] = t(c.start), t(c.end)
                values["naming"] = None
                named = None
            else:  # pragma: no cover - a new primitive must be added here
                raise ValueError(f"cannot replay {c.name!r}")
            out.append(_made(made, values))
            if named is not None:
                ids.add(named.label)


def _renumbered(
    renumbered: dict[int, Naming],
    naming: Naming,
    target: RecordingBackend,
    dx: float,
    dy: float,
) -> Naming:
    """`naming` moved by (dx, dy) for `target`, a new label id where the
    target already holds the label's (`renumbered` keeps what a replay gave)."""
    if naming.label not in renumbered:
        label = naming.label
        if label in target._label_ids:
            label = next(_LABEL_IDS)
        renumbered[naming.label] = dataclasses.replace(naming.shifted(dx, dy), label=label)
    return renumbered[naming.label]
