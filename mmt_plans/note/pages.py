"""The note's A4 pages: the blocks of `content` set in lines, paginated, and
drawn through the drawing interface (`render.backend.Backend`).

Page geometry follows seed 003 §III: A4 portrait with the GOST frame (20 mm
binding margin, 5 mm elsewhere), text 5 mm inside the frame on the left and
right and 10 mm below its top; the first page carries the main inscription
(form 1 of `sheets.page`, the one this package draws), the others a
15 mm strip after GOST 2.104 form 2a (changes, designation, page number),
with the text stopping 10 mm above either.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Any

from ..drawing.page import FIELDS, Page, Rect, draw_frame, draw_title_block, load_title_block_look
from ..i18n import Language
from ..render.backend import Backend, parse_markup
from ..render.look import Lettering, LineType, Look, load_look
from .content import Block, NoteContent

__all__ = ["NotePage", "Line", "layout_note", "draw_note_page", "FORM2A_HEIGHT", "note_page"]

BODY = 3.5  # lettering size of the text, mm
SMALL = 2.5  # of tables
HEADING = 5.0
PITCH = 1.7  # line pitch in lettering sizes (GOST 2.304: at least 1.7 h)
INDENT = 10.0  # of equations
CONTINUATION = 20.0  # of an equation's continuation lines
ROW = 6.0  # table row height, mm
FORM1_HEIGHT = 55.0
FORM2A_HEIGHT = 15.0


def note_page() -> Page:
    return Page.of("A4")


@dataclass(frozen=True)
class Line:
    """One line of the note placed on a page: `y` is its baseline (mm, y up);
    a table row has `cells` and `widths` instead of `text`."""

    y: float
    x: float
    text: str
    size: float
    kind: str
    cells: tuple[str, ...] = ()
    widths: tuple[float, ...] = ()
    header: bool = False


@dataclass(frozen=True)
class NotePage:
    number: int  # from 1
    lines: tuple[Line, ...]


def markup_width(let: Lettering, text: str, size: float) -> float:
    """Width of a markup line as `Backend.rich_text` sets it."""
    small = let.index_size(size)
    return sum(
        let.advance_width(t, size if kind == "normal" else small) for t, kind in parse_markup(text)
    ) + (0.3 * size if text else 0.0)


def _wrap(let: Lettering, text: str, size: float, width: float) -> list[str]:
    return let.wrap(text, size, width, measure=lambda line, at: markup_width(let, line, at))


def _equation_lines(
    let: Lettering, text: str, size: float, width: float
) -> list[tuple[str, float]]:
    """An equation as (line, indent): split at "; ", then at " = " with the
    continuation starting "= ", then at spaces."""
    out: list[tuple[str, float]] = []
    for part in text.split("; "):
        if markup_width(let, part, size) <= width - INDENT:
            out.append((part, INDENT))
            continue
        chunks = part.split(" = ")
        line, indent = chunks[0], INDENT
        for chunk in chunks[1:]:
            trial = f"{line} = {chunk}"
            if markup_width(let, trial, size) <= width - indent:
                line = trial
            else:
                out += [(w, indent) for w in _wrap(let, line, size, width - indent)]
                line, indent = f"= {chunk}", CONTINUATION
        out += [(w, indent) for w in _wrap(let, line, size, width - indent)]
    return out


def _frame_box(page: Page, first: bool) -> Rect:
    """Where text may go on a page."""
    f = page.frame
    bottom = f.bottom + (FORM1_HEIGHT if first else FORM2A_HEIGHT) + 10.0
    return Rect.from_bounds(f.left + 5.0, bottom, f.right - 5.0, f.top - 10.0)


def layout_note(
    content: NoteContent, look: Look | None = None, page: Page | None = None
) -> list[NotePage]:
    """Set the blocks in lines and break them into pages."""
    look = look or load_look()
    let = look.lettering
    page = page or note_page()
    pages: list[list[Line]] = [[]]
    box = _frame_box(page, True)
    y = box.top

    def new_page() -> None:
        nonlocal box, y
        pages.append([])
        box = _frame_box(page, False)
        y = box.top

    def room(height: float) -> bool:
        return y - height >= box.bottom - 1e-9

    def put(
        text: str, size: float, kind: str, x: float, before: float = 0.0, keep: float = 0.0
    ) -> None:
        """A line of `size`; `keep` more mm must fit below it (a heading keeps its next line)."""
        nonlocal y
        pitch = PITCH * size
        if pages[-1] and not room(before + pitch + keep):
            new_page()
        elif pages[-1]:
            y -= before
        y -= pitch if pages[-1] else size + 1.0
        pages[-1].append(Line(y, box.left + x, text, size, kind))

    for block in content.blocks:
        width = box.width
        if block.kind == "title":
            for t in _wrap(let, block.text, HEADING, width):
                put(t, HEADING, "title", 0.0, keep=PITCH * BODY)
            y -= 3.0
        elif block.kind in ("section", "subsection"):
            size = HEADING if block.kind == "section" else BODY
            lines = _wrap(let, block.text, size, width)
            for j, t in enumerate(lines):
                # the heading's first line brings the space above it and keeps
                # the heading together with the first lines under it
                put(
                    t,
                    size,
                    block.kind,
                    0.0,
                    before=(4.0 if size == HEADING else 3.0) if j == 0 else 0.0,
                    keep=(len(lines) - 1 - j) * PITCH * size + 2 * PITCH * BODY,
                )
        elif block.kind in ("text", "problem"):
            lines = _wrap(let, block.text, BODY, width)
            for t in lines:
                put(t, BODY, block.kind, 0.0)
        elif block.kind == "equation":
            for t, indent in _equation_lines(let, block.text, BODY, width):
                put(t, BODY, "equation", indent)
        elif block.kind == "table":
            putter = _RowPutter(lambda: (box, y), new_page)
            putter.rows(block, pages)
            y = putter.y
        else:  # pragma: no cover - a new block kind must be set here
            raise ValueError(f"cannot set a block of kind {block.kind!r}")
    return [NotePage(i + 1, tuple(lines)) for i, lines in enumerate(pages)]


class _RowPutter:
    """Places table rows, repeating the header row on a new page."""

    def __init__(self, state, new_page) -> None:
        self.state = state
        self.new_page = new_page
        self.y = state()[1]

    def rows(self, block: Block, pages: list[list[Line]]) -> None:
        header, body = block.rows[0], block.rows[1:]
        box, y = self.state()
        y -= 2.0
        scale = min(1.0, box.width / sum(block.widths))
        widths = tuple(w * scale for w in block.widths)
        if y - 2 * ROW < box.bottom:
            self.new_page()
            box, y = self.state()
        pages[-1].append(Line(y - ROW, box.left, "", SMALL, "table", header, widths, True))
        y -= ROW
        for row in body:
            if y - ROW < box.bottom:
                self.new_page()
                box, y = self.state()
                pages[-1].append(Line(y - ROW, box.left, "", SMALL, "table", header, widths, True))
                y -= ROW
            pages[-1].append(Line(y - ROW, box.left, "", SMALL, "table", row, widths))
            y -= ROW
        self.y = y - 2.0


# --- drawing -------------------------------------------------------------------------------


def _fields(mech: Any, title: str, pages: int, lang: Language) -> dict[str, str]:
    fields = {k: str(v) for k, v in dict(getattr(mech, "sheet", None) or {}).items() if k in FIELDS}
    fields["title"] = title
    fields["sheet"] = "1"
    fields["sheets"] = str(pages)
    if "drawing_number" in fields:
        fields["drawing_number"] += " ПЗ" if lang == "uk" else " EN"
    return fields


def draw_form2a(
    backend: Backend, page: Page, number: int, designation: str, lang: Language
) -> None:
    """GOST 2.104 form 2a: 185 × 15 mm at the frame's bottom right; columns
    7, 10, 23, 15, 10 | 110 | 10 mm; three 5 mm rows on the left, the lowest
    holding the captions; the page number in the right cell."""
    tb = load_title_block_look()
    f = page.frame
    x0, y0 = f.right - 185.0, f.bottom
    xs = [x0 + d for d in (0.0, 7.0, 17.0, 40.0, 55.0, 65.0, 175.0, 185.0)]
    with backend.group("form-2a", "title-block"):
        for y in (y0 + 5.0, y0 + 10.0):
            backend.line((xs[0], y), (xs[5], y), "thin")
        backend.line((xs[0], y0 + 5.0), (xs[5], y0 + 5.0), "main")
        backend.line((xs[0], y0 + 15.0), (xs[7], y0 + 15.0), "main")
        for x in xs[:7]:
            backend.line((x, y0), (x, y0 + 15.0), "main")
        backend.line((xs[6], y0 + 8.0), (xs[7], y0 + 8.0), "main")
        keys = ("change", "change_sheet", "document", "signature", "date")
        for i, key in enumerate(keys):
            backend.text(
                ((xs[i] + xs[i + 1]) / 2, y0 + 2.5),
                tb.caption_text(lang, key),
                SMALL,
                anchor="center",
                valign="middle",
                max_width=xs[i + 1] - xs[i] - 1.0,
            )
        backend.text(
            ((xs[6] + xs[7]) / 2, y0 + 11.5),
            tb.caption_text(lang, "sheet"),
            SMALL,
            anchor="center",
            valign="middle",
            max_width=9.0,
        )
        backend.text(
            ((xs[6] + xs[7]) / 2, y0 + 4.0),
            str(number),
            BODY,
            anchor="center",
            valign="middle",
            max_width=9.0,
        )
        if designation:
            backend.text(
                ((xs[5] + xs[6]) / 2, y0 + 7.5),
                designation,
                HEADING,
                anchor="center",
                valign="middle",
                max_width=105.0,
            )


def draw_note_page(
    backend: Backend,
    note_page_: NotePage,
    pages: int,
    content: NoteContent,
    mech: Any = None,
    page: Page | None = None,
) -> None:
    """One page: its lines, the frame and the main inscription or form 2a."""
    page = page or note_page()
    with backend.group(f"page-{note_page_.number}", "note-page"):
        for line in note_page_.lines:
            if line.kind == "table":
                _draw_row(backend, line)
            else:
                backend.rich_text((line.x, line.y), line.text, line.size)
    draw_frame(backend, page)
    fields = _fields(mech, content.title, pages, content.lang)
    if note_page_.number == 1:
        draw_title_block(backend, page, fields, content.lang)
    else:
        draw_form2a(
            backend, page, note_page_.number, fields.get("drawing_number", ""), content.lang
        )


def _draw_row(backend: Backend, line: Line) -> None:
    x = line.x
    bottom, top = line.y, line.y + ROW
    kind: LineType = "main" if line.header else "thin"
    backend.line((x, top), (x + sum(line.widths), top), "main" if line.header else "thin")
    backend.line((x, bottom), (x + sum(line.widths), bottom), kind)
    backend.line((x, bottom), (x, top), "main")
    for w, cell in zip(line.widths, line.cells):
        backend.line((x + w, bottom), (x + w, top), "main")
        if cell:
            backend.rich_text(
                (x + w / 2, bottom + ROW / 2), cell, line.size, anchor="center", valign="middle"
            )
        x += w


def page_fields(mech: Any, content: NoteContent, pages: int) -> Mapping[str, str]:
    return _fields(mech, content.title, pages, content.lang)


def all_lines(pages: Sequence[NotePage]) -> list[Line]:
    return [line for p in pages for line in p.lines]
