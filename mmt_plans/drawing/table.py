"""A table drawn on a sheet: velocities, accelerations, reactions.

Placed by its top-left corner (tables grow downwards); `draw` returns the
bounding box so the layout can register the table's footprint. Lines as on
the main inscription: the outline, the column lines and the line under the
header main, the lines between rows thin. Rows at least 8 mm (GOST 2.105).
"""

from __future__ import annotations

import math
import re
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

from ..i18n import Language, catalogue
from ..render.backend import Backend, HAlign, PointLike, as_point
from ..render.look import Lettering, load_look
from .page import Rect
from .sketch import PAD, Sketch

__all__ = ["TABLE_PART_MM", "Table", "rows_per_part", "table_sketch"]

_PAD = 1.0  # clearance between lettering and cell lines, mm
_TITLE_GAP = 3.0  # between the title's baseline and the table's top line, mm


@dataclass(frozen=True, init=False)
class Table:
    """A grid of text cells with one header row.

    `header_height` None fits the (possibly multi-line, "\\n") header texts.
    `align` gives each column's alignment (default centred).
    """

    header: tuple[str, ...]
    rows: tuple[tuple[str, ...], ...]
    column_widths: tuple[float, ...]
    text_size: float = 3.5
    row_height: float = 8.0
    header_height: float | None = None
    title: str | None = None
    title_size: float = 5.0
    align: tuple[HAlign, ...] | None = None
    lettering: Lettering | None = None

    def __init__(
        self,
        header: Sequence[Any],
        rows: Sequence[Sequence[Any]],
        column_widths: Sequence[float],
        text_size: float = 3.5,
        row_height: float = 8.0,
        header_height: float | None = None,
        title: str | None = None,
        title_size: float = 5.0,
        align: Sequence[HAlign] | None = None,
        lettering: Lettering | None = None,
    ) -> None:
        n = len(column_widths)
        if n == 0:
            raise ValueError("a table needs at least one column")
        if len(header) != n:
            raise ValueError(f"header has {len(header)} cells for {n} columns")
        for i, row in enumerate(rows):
            if len(row) != n:
                raise ValueError(f"row {i + 1} has {len(row)} cells for {n} columns")
        if any(not w > 0 for w in column_widths):
            raise ValueError("column widths must be positive")
        if align is not None and len(align) != n:
            raise ValueError(f"align has {len(align)} entries for {n} columns")
        set_ = object.__setattr__
        set_(self, "header", tuple(str(h) for h in header))
        set_(self, "rows", tuple(tuple(str(c) for c in row) for row in rows))
        set_(self, "column_widths", tuple(float(w) for w in column_widths))
        set_(self, "text_size", float(text_size))
        set_(self, "row_height", float(row_height))
        set_(self, "header_height", None if header_height is None else float(header_height))
        set_(self, "title", title)
        set_(self, "title_size", float(title_size))
        set_(self, "align", None if align is None else tuple(align))
        set_(self, "lettering", lettering)

    # --- geometry -------------------------------------------------------------

    def _lettering(self, backend: Backend | None = None) -> Lettering:
        if self.lettering is not None:
            return self.lettering
        return backend.look.lettering if backend is not None else load_look().lettering

    def _header_h(self, let: Lettering) -> float:
        if self.header_height is not None:
            return self.header_height
        lines = max(len(self._header_lines(i, let)[1]) for i in range(len(self.header)))
        return max(self.row_height, let.block_height(lines, self.text_size) + 2 * _PAD + 2.0)

    def _header_lines(self, col: int, let: Lettering) -> tuple[float, list[str]]:
        width = self.column_widths[col] - 2 * _PAD
        sizes = tuple(s for s in let.sizes if s <= self.text_size) or (self.text_size,)
        if self.header_height is None:
            # Shrink only when a single word is wider than the column.
            size = self.text_size
            lines = let.wrap(self.header[col], size, width)
            if all(let.width(line, size) <= width for line in lines):
                return size, lines
        box_h = (self.header_height or self.row_height) - 2 * _PAD
        return let.fit(self.header[col], width, box_h, sizes)

    @property
    def width(self) -> float:
        return sum(self.column_widths)

    def height(self, lettering: Lettering | None = None) -> float:
        """Height of the grid plus the title line above it, mm."""
        let = lettering or self._lettering()
        h = self._header_h(let) + self.row_height * len(self.rows)
        if self.title:
            h += self.title_size + _TITLE_GAP
        return h

    def bbox(self, top_left: PointLike, lettering: Lettering | None = None) -> Rect:
        """Footprint of the table placed with its top-left corner at top_left."""
        x, top = as_point(top_left)
        let = lettering or self._lettering()
        width = self.width
        if self.title:
            width = max(width, let.width(self.title, self.title_size))
        h = self.height(let)
        return Rect(x, top - h, width, h)

    # --- drawing -------------------------------------------------------------

    def draw(self, backend: Backend, top_left: PointLike, id: str = "table") -> Rect:
        """Draw the table with the top-left corner of its footprint at top_left."""
        let = self._lettering(backend)
        x0, top = as_point(top_left)
        box = self.bbox((x0, top), let)
        with backend.group(id, "table"):
            if self.title:
                backend.text((x0, top - self.title_size), self.title, self.title_size)
                top -= self.title_size + _TITLE_GAP
            header_h = self._header_h(let)
            bottom = top - header_h - self.row_height * len(self.rows)
            xs = [x0]
            for w in self.column_widths:
                xs.append(xs[-1] + w)
            # Row lines between body rows thin; header line and outline main.
            for i in range(1, len(self.rows)):
                y = top - header_h - i * self.row_height
                backend.line((xs[0], y), (xs[-1], y), "thin")
            if self.rows:
                backend.line((xs[0], top - header_h), (xs[-1], top - header_h), "main")
            for x in xs[1:-1]:
                backend.line((x, top), (x, bottom), "main")
            backend.rectangle((xs[0], bottom), xs[-1] - xs[0], top - bottom, "main")

            for col in range(len(self.header)):
                size, lines = self._header_lines(col, let)
                cx = (xs[col] + xs[col + 1]) / 2.0
                pitch = let.line_pitch * size
                first = top - header_h / 2.0 + pitch * (len(lines) - 1) / 2.0
                for k, line in enumerate(lines):
                    backend.text(
                        (cx, first - k * pitch),
                        line,
                        size,
                        anchor="center",
                        valign="middle",
                        max_width=self.column_widths[col] - 2 * _PAD,
                    )

            sizes = tuple(s for s in let.sizes if s <= self.text_size) or (self.text_size,)
            for r, row in enumerate(self.rows):
                cy = top - header_h - (r + 0.5) * self.row_height
                for col, content in enumerate(row):
                    if not content:
                        continue
                    width = self.column_widths[col] - 2 * _PAD
                    size = let.fit_line(content, width, self.row_height - 2 * _PAD, sizes)
                    anchor: HAlign = self.align[col] if self.align else "center"
                    x = {
                        "left": xs[col] + _PAD,
                        "center": (xs[col] + xs[col + 1]) / 2.0,
                        "right": xs[col + 1] - _PAD,
                    }[anchor]
                    backend.text(
                        (x, cy), content, size, anchor=anchor, valign="middle", max_width=width
                    )
        return box


_NUMBER = re.compile(r"[-−]?\d+\.\d+(e[-+]?\d+)?")
_PLAIN = re.compile(r"^([-−]?)(\d+)(?:\.(\d+))?$")
_TEXT = 3.5
DECIMALS_MAX = 4  # decimals a column is padded to at most


def _decimals(values: Sequence[float], given: Sequence[int]) -> int:
    """One number of decimals for a column: as many as its largest value was
    given with, or more where its smallest non-zero one needs them for two
    significant figures (never more than any was given with, nor DECIMALS_MAX)."""
    nonzero = [abs(v) for v in values if v != 0.0]
    if not nonzero:
        return min(max(given), DECIMALS_MAX)
    big = given[max(range(len(values)), key=lambda i: abs(values[i]))]
    small = max(0, 1 - math.floor(math.log10(min(nonzero))))
    return min(max(big, small), max(given), DECIMALS_MAX)


def _one_format_per_column(rows: Sequence[Sequence[str]]) -> list[list[str]]:
    """The rows with the plain numbers of each column written with one number of
    decimals (`_decimals`): 15140, 11977, 53 — never 15140, 11977, 52.88 in one
    column; 12403.1, 0.0, 2480.6 — never 12403.1, 0.00, 2480.62. Marked values
    (±0.049*) and words stay as they are."""
    out = [list(r) for r in rows]
    width = max((len(r) for r in out), default=0)
    for col in range(width):
        cells = [(r, m) for r in out if col < len(r) and (m := _PLAIN.match(r[col])) is not None]
        if not cells:
            continue
        values = [
            float(f"{m.group(1).replace('−', '-')}{m.group(2)}.{m.group(3) or '0'}")
            for _, m in cells
        ]
        d = _decimals(values, [len(m.group(3) or "") for _, m in cells])
        for (r, _), value in zip(cells, values):
            text = f"{value:.{d}f}"
            r[col] = text if float(text) != 0.0 else f"{0.0:.{d}f}"  # never -0.00
    return out


_ROW_H, _HEAD_H = 8.0, 12.0  # table_sketch's body rows and header, mm
# A table part at most this tall on a sheet (about half the A1 field's 574 mm,
# so that the tables stand in two rows at most): a longer table continues in
# parts side by side, the header repeated (GOST 2.105 §4.4.9), and the sheet's
# tables are then numbered so that the continuation can name its table.
TABLE_PART_MM = 280.0
PART_GAP = 8.0  # between the parts of a table continued side by side, mm


def rows_per_part(rows: int, max_height: float, title: bool = True) -> int:
    """Body rows in each part of a table of `rows` rows of table_sketch's sizes
    that must be at most `max_height` tall: as few parts as hold them, the
    rows shared evenly among them (GOST 2.105 §4.4.9: a long table continues
    with its header repeated)."""
    room = max_height - (_TEXT + 3.0 if title else 0.0) - _HEAD_H
    fit = max(1, math.floor(room / _ROW_H + 1e-9))
    if rows <= fit:
        return max(rows, 1)
    parts = math.ceil(rows / fit)
    return math.ceil(rows / parts)


def table_sketch(
    look: Any,
    gid: str,
    title: str,
    header: Sequence[str],
    rows: Sequence[Sequence[str]],
    widths: Sequence[float],
    first_markup: Sequence[str],
    lang: Language = "en",
    header_markup: Sequence[str | None] | None = None,
    *,
    max_height: float | None = None,
    continued: str | None = None,
) -> Sketch:
    """A Table whose first column is set with indices (rich_text) over empty cells;
    so is each header cell given a markup in `header_markup` (V_{plan}, not
    "V plan"). Ukrainian tables write numbers with a decimal comma, as the
    scale labels do. A table taller than `max_height` is drawn in parts side
    by side, each no taller, each repeating the header; the parts after the
    first are titled `continued` ("Continuation of Table 1") and are groups
    `gid`-2, `gid`-3…"""

    def cell(text: str) -> str:
        return catalogue(lang).localise(text) if _NUMBER.fullmatch(text) else text

    # one number format per column over the whole table, then split
    body = [["", *(cell(t) for t in r[1:])] for r in _one_format_per_column(rows)]
    marks = list(header_markup or [None] * len(header))
    if len(marks) != len(header):
        raise ValueError(f"header_markup has {len(marks)} cells for {len(header)} columns")
    per = len(body) if max_height is None else rows_per_part(len(body), max_height)
    if per >= len(body):
        return _table_part(look, gid, title, header, body, widths, first_markup, marks)
    if continued is None:
        raise ValueError(f"{gid} is continued in parts but has no title for them")
    sk = Sketch(look)
    x = 0.0
    for k, start in enumerate(range(0, len(body), per)):
        part = _table_part(
            look,
            gid if k == 0 else f"{gid}-{k + 1}",
            title if k == 0 else continued,
            header,
            body[start : start + per],
            widths,
            first_markup[start : start + per],
            marks,
        )
        part.replay(sk, x, 0.0)
        x += part.extent().width - 2 * PAD + PART_GAP
    return sk


def _table_part(
    look: Any,
    gid: str,
    title: str,
    header: Sequence[str],
    body: Sequence[Sequence[str]],
    widths: Sequence[float],
    first_markup: Sequence[str],
    marks: Sequence[str | None],
) -> Sketch:
    """One table (or one part of a continued one) with its overlays, at (0, 0)."""
    sk = Sketch(look)
    row_h, head_h = _ROW_H, _HEAD_H
    table = Table(
        ["" if m is not None else h for h, m in zip(header, marks)],
        body,
        widths,
        text_size=3.5,
        row_height=row_h,
        header_height=head_h,
        title=title,
        title_size=_TEXT,
    )
    table.draw(sk, (0.0, 0.0), gid)
    # The overlay goes into the table's group: reopen it by replaying into it.
    top = -(_TEXT + 3.0) - head_h
    extra = Sketch(look)
    for r, text in enumerate(first_markup):
        extra.rich_text(
            (widths[0] / 2, top - (r + 0.5) * row_h), text, _TEXT, anchor="center", valign="middle"
        )
    x = 0.0
    pitch = 1.3 * _TEXT
    for width, mark in zip(widths, marks):
        if mark is not None:  # a mark of two lines ("V_{plan}\nm/s"): the unit under it
            lines = mark.split("\n")
            for k, line in enumerate(lines):
                y = top + head_h / 2 + ((len(lines) - 1) / 2 - k) * pitch
                extra.rich_text((x + width / 2, y), line, _TEXT, anchor="center", valign="middle")
        x += width
    sk.add_to_last_group(extra, gid)
    return sk
