"""The drawing interface that sheets are composed through.

Modelled on ezdxf's `addons/drawing/backend.py`: sheet code calls only these
methods, a renderer implements them (`svg.SvgBackend`), and a recorder
(`recording.RecordingBackend`) keeps every call so tests can check what was
drawn without parsing SVG.

Coordinates are page millimetres with the origin at the bottom-left corner of
the sheet and y pointing up, as on the drawing board. Angles are degrees,
counter-clockwise.
"""

from __future__ import annotations

import abc
import contextlib
import dataclasses
import functools
import math
import re
from collections.abc import Iterator, Sequence
from typing import Literal, get_args

import numpy as np

from .look import LINE_TYPES, Lettering, LineType, Look, load_look

__all__ = [
    "LineType",
    "LINE_TYPES",
    "HAlign",
    "VAlign",
    "Fill",
    "RunKind",
    "TextRun",
    "parse_markup",
    "Point",
    "PointLike",
    "as_point",
    "slant_offsets",
    "turned",
    "arrow_geometry",
    "Backend",
]

HAlign = Literal["left", "center", "right"]
RunKind = Literal["normal", "sub", "sup"]
TextRun = tuple[str, RunKind]
VAlign = Literal["baseline", "middle", "top"]
Fill = Literal["none", "black", "white"]

Point = tuple[float, float]
PointLike = Sequence[float] | np.ndarray

_HALIGNS = get_args(HAlign)
_VALIGNS = get_args(VAlign)
_FILLS = get_args(Fill)


def slant_offsets(
    anchor: str, valign: str, size: float, lean: float, squeeze: float
) -> tuple[float, float]:
    """Offsets (mm) along and across a text's baseline (y up) from where it is
    asked for to where its baseline starts under the anchor: the slant leans
    the tops right (`lean`, its tan), so centred and right-aligned text moves
    left to keep its capitals, not just its baseline, where asked."""
    if anchor == "left":
        along = 0.0 * squeeze
    else:
        along = (-lean * size / 2.0 if anchor == "center" else -lean * size) * squeeze
    across = 0.0 if valign == "baseline" else -size / 2.0 if valign == "middle" else -size
    return along, across


def turned(degrees: float) -> tuple[float, float]:
    """cos and sin of a text's rotation (degrees): 1 and 0, exactly, unturned."""
    if not degrees:
        return 1.0, 0.0
    a = math.radians(degrees)
    return math.cos(a), math.sin(a)


def as_point(p: PointLike) -> Point:
    """A 2-d point as a tuple of two finite floats."""
    if type(p) is tuple and len(p) == 2:  # the common case, without a generator
        x, y = p
        if type(x) is float and type(y) is float:
            if x - x == 0.0 and y - y == 0.0:  # finite (inf - inf and nan are nan)
                return p
            raise ValueError(f"a drawn point must be finite, got ({x}, {y})")
    u, v = p  # raises on the wrong number of coordinates
    x, y = float(u), float(v)  # numpy's floats and rows of an array too
    if x - x == 0.0 and y - y == 0.0:
        return (x, y)
    raise ValueError(f"a drawn point must be finite, got ({x}, {y})")


_MARKUP = re.compile(r"([_^])(?:\{([^{}]*)\}|(.))", re.DOTALL)


def parse_markup(text: str) -> list[TextRun]:
    """Split "V_{BA} = 1,2 м/с^2" into runs: _x or _{...} a subscript, ^ a superscript."""
    return list(_runs(text))


@functools.lru_cache(maxsize=8192)
def _runs(text: str) -> tuple[TextRun, ...]:
    """`parse_markup`, split once per text (a sheet and a note write the same
    labels and numbers over and over)."""
    runs: list[TextRun] = []
    pos = 0
    for m in _MARKUP.finditer(text):
        if m.start() > pos:
            runs.append((text[pos : m.start()], "normal"))
        body = m.group(2) if m.group(2) is not None else m.group(3)
        runs.append((body, "sub" if m.group(1) == "_" else "sup"))
        pos = m.end()
    if pos < len(text):
        runs.append((text[pos:], "normal"))
    return tuple(r for r in runs if r[0])


def arrow_geometry(
    start: PointLike, end: PointLike, head_length: float, head_width: float
) -> tuple[Point, list[Point]]:
    """Where the shaft of an arrow stops and the triangle of its head.

    The head's tip is `end`. The shaft stops at the base of the head so that a
    wide line does not poke out through the tip. A vector shorter than its head
    gets a head shortened to the vector's length.
    """
    sx, sy = as_point(start)
    ex, ey = as_point(end)
    dx, dy = ex - sx, ey - sy
    length = math.hypot(dx, dy)
    if length == 0.0:
        return (ex, ey), [(ex, ey)] * 3
    ux, uy = dx / length, dy / length
    hl = min(head_length, length)
    hw = head_width * hl / head_length / 2.0
    bx, by = ex - ux * hl, ey - uy * hl
    head = [(ex, ey), (bx - uy * hw, by + ux * hw), (bx + uy * hw, by - ux * hw)]
    return (bx, by), head


class Backend(abc.ABC):
    """Abstract drawing backend; page size and look are fixed per document."""

    def __init__(
        self, width: float = 841.0, height: float = 594.0, look: Look | None = None
    ) -> None:
        if not (width > 0 and height > 0):
            raise ValueError(f"page size must be positive, got {width} x {height}")
        self.width = float(width)
        self.height = float(height)
        self.look = look if look is not None else load_look()
        self._open_groups: list[str] = []

    # --- primitives every backend implements ---------------------------------

    @abc.abstractmethod
    def line(self, start: PointLike, end: PointLike, line: LineType = "main") -> None:
        """A straight segment."""

    @abc.abstractmethod
    def polyline(self, points: Sequence[PointLike], line: LineType = "main") -> None:
        """An open chain of segments."""

    @abc.abstractmethod
    def polygon(
        self, points: Sequence[PointLike], line: LineType | None = "main", fill: Fill = "none"
    ) -> None:
        """A closed outline; `line=None` draws the fill only."""

    @abc.abstractmethod
    def circle(
        self, center: PointLike, radius: float, line: LineType | None = "main", fill: Fill = "none"
    ) -> None:
        """A full circle."""

    @abc.abstractmethod
    def arc(
        self,
        center: PointLike,
        radius: float,
        start_deg: float,
        end_deg: float,
        line: LineType = "main",
    ) -> None:
        """A circular arc from start_deg counter-clockwise to end_deg."""

    @abc.abstractmethod
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
        """One line of lettering; `size` is the capital height in mm.

        `pos` is where the anchor point of the text goes: `anchor` picks the
        left end, centre or right end; `valign` the baseline, the middle of the
        capitals or their top. The text turns about `pos` by `rotation`.
        Lettering (by the look's metrics) wider than `max_width` mm is
        narrowed to fit, but not below the look's min_squeeze.
        """

    @abc.abstractmethod
    def _begin_group(self, id: str, cls: str | None) -> None: ...

    @abc.abstractmethod
    def _end_group(self) -> None: ...

    # --- composed from the primitives ----------------------------------------

    def begin_group(self, id: str, cls: str | None = None) -> None:
        """Start a group (an SVG <g> with this id and class) for what follows."""
        if not id:
            raise ValueError("a group needs an id")
        self._open_groups.append(id)
        self._begin_group(id, cls)

    def end_group(self) -> None:
        if not self._open_groups:
            raise RuntimeError("end_group() without begin_group()")
        self._open_groups.pop()
        self._end_group()

    @contextlib.contextmanager
    def group(self, id: str, cls: str | None = None) -> Iterator[None]:
        """`with backend.group("velocity-plan", "plan"): ...`"""
        self.begin_group(id, cls)
        try:
            yield
        finally:
            self.end_group()

    def arrow(
        self,
        start: PointLike,
        end: PointLike,
        line: LineType = "main",
        *,
        head_length: float | None = None,
        head_width: float | None = None,
    ) -> None:
        """A vector from start to end with a filled head at end."""
        hl = self.look.arrow_length if head_length is None else head_length
        hw = self.look.arrow_width if head_width is None else head_width
        shaft_end, head = arrow_geometry(start, end, hl, hw)
        if shaft_end != as_point(start):
            self.line(start, shaft_end, line)
        self.polygon(head, line="thin", fill="black")

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
        """Lettering with indices: "μ_{V} = 0.01 (m/s)/mm" or a list of runs.

        Indices take the next smaller standard size; a subscript's baseline
        drops by 0.3 h, a superscript's top meets the capitals' top. Returns
        the drawn width in mm.
        """
        runs = parse_markup(content) if isinstance(content, str) else list(content)
        self._check_text(size, anchor, valign)
        let = self.look.lettering
        small = let.index_size(size)
        advance = let.advance_width
        sized = [(t, kind, size if kind == "normal" else small) for t, kind in runs]
        advances = [advance(t, s) for t, _, s in sized]
        lean = let.lean * size if runs else 0.0
        total = sum(advances) + lean
        along = 0.0 if anchor == "left" else -total / 2.0 if anchor == "center" else -total
        across = 0.0 if valign == "baseline" else -size / 2.0 if valign == "middle" else -size
        ca, sa = turned(rotation)
        x, y = as_point(pos)
        offset = along
        for (text, kind, s), adv in zip(sized, advances):
            lift = (
                0.0 if kind == "normal" else -0.3 * size if kind == "sub" else size - s
            ) + across
            # Renderers drop spaces at the ends of a text element (SVG does),
            # so they become offsets here.
            body = text.strip(" ")
            if body:
                start = offset + advance(text[: len(text) - len(text.lstrip(" "))], s)
                self.text(
                    (x + start * ca - lift * sa, y + start * sa + lift * ca),
                    body,
                    s,
                    rotation=rotation,
                )
            offset += adv
        return total

    def rectangle(
        self,
        corner: PointLike,
        width: float,
        height: float,
        line: LineType | None = "main",
        fill: Fill = "none",
    ) -> None:
        """An axis-parallel rectangle from its bottom-left corner."""
        x, y = as_point(corner)
        self.polygon([(x, y), (x + width, y), (x + width, y + height), (x, y + height)], line, fill)

    @contextlib.contextmanager
    def lettered_as(self, lettering: Lettering) -> Iterator[None]:
        """Texts drawn within in `lettering`, lines still in the page's look:
        a figure copied from a sheet keeps the sheet's letters, so its
        indices stand where the sheet's widths put them."""
        kept = self.look
        self.look = dataclasses.replace(kept, lettering=lettering)
        self._lettering_changed()
        try:
            yield
        finally:
            self.look = kept
            self._lettering_changed()

    def _lettering_changed(self) -> None:
        """A backend that keeps something of its lettering sets it again here."""
        return None

    def close(self) -> None:
        """Check that every group was ended."""
        if self._open_groups:
            raise RuntimeError(f"groups left open: {', '.join(self._open_groups)}")

    # --- argument checks shared by the implementations -----------------------

    @staticmethod
    def _check_line(line: LineType | None, allow_none: bool = False) -> None:
        if line is None and allow_none:
            return
        if line not in LINE_TYPES:
            raise ValueError(f"unknown line type {line!r}; expected one of {', '.join(LINE_TYPES)}")

    @staticmethod
    def _check_text(size: float, anchor: str, valign: str, max_width: float | None = None) -> None:
        if not size > 0:
            raise ValueError(f"text size must be positive, got {size}")
        if max_width is not None and not max_width > 0:
            raise ValueError(f"max_width must be positive, got {max_width}")
        if anchor not in _HALIGNS:
            raise ValueError(f"unknown anchor {anchor!r}; expected one of {', '.join(_HALIGNS)}")
        if valign not in _VALIGNS:
            raise ValueError(f"unknown valign {valign!r}; expected one of {', '.join(_VALIGNS)}")

    @staticmethod
    def _check_fill(fill: str) -> None:
        if fill not in _FILLS:
            raise ValueError(f"unknown fill {fill!r}; expected one of {', '.join(_FILLS)}")
