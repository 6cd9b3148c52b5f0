"""The note's A4 pages: the blocks set in lines, paginated, and drawn through
the drawing interface (`render.backend.Backend`).

Page geometry and type follow seed 003 §III (DSTU 3008:2015, GOST 2.104):
A4 portrait with the GOST frame (20 mm binding margin, 5 mm elsewhere); the
text keeps margins of 25 mm on the left, 15 mm on the right, 25 mm at the top
and the bottom, at least 5 mm inside the frame and 10 mm above its stamp. The
first page of the text carries form 2 (185 × 40 mm), the following pages form
2a (185 × 15 mm); the title page and the task sheet have no frame. The main
font is a serif at 14 pt (Liberation Serif, metric-compatible with Times New
Roman: templates/note_look.toml) with 1.5 line spacing and a 12.5 mm
paragraph indent; tables are set at 12 pt with single spacing. Tables are
numbered above them, figures below them, in the order they come.
"""

from __future__ import annotations

import functools
import re
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, replace
from typing import Any, Literal

from ..drawing.page import Page, Rect, draw_frame
from ..i18n import Language, catalogue
from ..render.backend import Backend, parse_markup
from ..render.look import Lettering, LineType, Look, note_look
from .content import Block, NoteContent

__all__ = [
    "NotePage",
    "Line",
    "layout_note",
    "draw_note_page",
    "note_look",
    "note_page",
    "heading_pages",
    "text_box",
    "FORM2_HEIGHT",
    "FORM2A_HEIGHT",
    "Form",
]

Form = Literal["none", "2", "2a", "5", "5a"]
FORMS: tuple[str, ...] = ("none", "2", "2a", "5", "5a")
# GOST 2.106's forms 5 and 5a of a text document: forms 2 and 2a of GOST 2.104
# with the additional columns 19-25 in the binding margin (seed 002)
FORM5 = {"2": "5", "2a": "5a"}

PT = 25.4 / 72.0  # mm per point
SINGLE = 1.149  # single line spacing of Times New Roman / Liberation Serif, em
BODY_PT = 14.0
TABLE_PT = 12.0
CAPTION_PT = 12.0
FORM_PT = 10.0  # the filled cells of forms 2 and 2a
CAPTION_FORM_PT = 8.0  # their printed captions
SPACING = 1.5  # of the main text
PARAGRAPH = 12.5  # paragraph indent, mm (five characters)
INDENT = PARAGRAPH  # of equations
CONTINUATION = 2 * PARAGRAPH  # of an equation's continuation lines
CELL_PAD = 1.0  # text to the lines of a table cell, mm
NUMBER_ROOM = 20.0  # kept free right of a formula for its number "(2.147)", mm
WORDY = 60.0  # a table column this wide (mm) holds words: set from the left
FORM2_HEIGHT = 40.0
FORM2A_HEIGHT = 15.0
FORM_WIDTH = 185.0
# distances of the text from the paper's edges (seed 003 §III)
MARGIN_LEFT, MARGIN_RIGHT, MARGIN_TOP, MARGIN_BOTTOM = 25.0, 15.0, 25.0, 25.0
STAMP_GAP = 10.0  # text to the top of form 2 or 2a

# Glyphs that Liberation Serif lacks: drawn as lines (_draw_symbol).
SYMBOLS = frozenset("⊥∥⇒")
# a vector's mark after its letter (writer.vec): an arrow drawn over the letter
VECTOR = "\u20d7"
# the characters draw_markup draws itself (a symbol the font lacks, a vector's arrow)
_DRAWN_APART = SYMBOLS | {VECTOR}


def note_page() -> Page:
    return Page.of("A4")


def cap(pt: float, let: Lettering) -> float:
    """The lettering size (capital height, mm) of a font of `pt` points."""
    return pt * PT * let.cap_height


def pitch(pt: float, spacing: float = 1.0) -> float:
    """Baseline to baseline of lines of `pt` points at `spacing`, mm."""
    return spacing * SINGLE * pt * PT


@dataclass(frozen=True)
class Line:
    """One line of the note placed on a page: `y` is its baseline (mm, y up).
    A table row has `cells` and `widths` and fills `height` mm above `y`; a
    figure fills the rectangle (x, y, sum(widths), height); a contents line
    has its page number in `cells`. `anchor` names the heading a line starts."""

    y: float
    x: float
    text: str
    size: float
    kind: str
    cells: tuple[str, ...] = ()
    widths: tuple[float, ...] = ()
    header: bool = False
    align: str = "left"
    anchor: str = ""
    figure: str = ""
    height: float = 0.0
    sizes: tuple[float, ...] = ()  # of a table row's cells


@dataclass(frozen=True)
class NotePage:
    number: int  # from 1
    lines: tuple[Line, ...]
    form: Form = "2a"


# measured widths by (lettering, markup, size): a note measures the same words
# again and again (each layout pass, each justified line); the letterings are
# kept so that their ids stay theirs
_WIDTHS: dict[tuple[int, str, float], float] = {}
_LETTERINGS: dict[int, Lettering] = {}


def markup_width(let: Lettering, text: str, size: float) -> float:
    """Width of a markup line as `_draw_markup` sets it."""
    key = (id(let), text, size)
    hit = _WIDTHS.get(key)
    if hit is not None and _LETTERINGS.get(id(let)) is let:
        return hit
    small = let.index_size(size)
    width = sum(
        let.advance_width(t, size if kind == "normal" else small)
        for t, kind in parse_markup(text.replace(VECTOR, ""))
    )
    if len(_WIDTHS) > 200_000:
        _WIDTHS.clear()
    _LETTERINGS.setdefault(id(let), let)
    if _LETTERINGS[id(let)] is let:
        _WIDTHS[key] = width
    return width


def words(text: str) -> list[str]:
    """A markup line's words: split at spaces outside index braces."""
    out: list[str] = []
    current, depth = "", 0
    for ch in text:
        depth += {"{": 1, "}": -1}.get(ch, 0)
        if ch == " " and depth <= 0:
            if current:
                out.append(current)
            current = ""
        else:
            current += ch
    if current:
        out.append(current)
    return out


def _wrap(let: Lettering, text: str, size: float, width: float, first: float = 0.0) -> list[str]:
    """Break at spaces into lines no wider than `width`, the first `first` mm
    narrower (Lettering.wrap's rule: a word wider than a line stays alone on
    its line). A line's width is the sum of its words' and spaces' widths
    (an index never holds a breaking space: typeset()), each word measured once."""
    space = let.advance_width(" ", size)
    lines: list[str] = []
    for paragraph in text.split("\n"):
        current: list[str] = []
        used = 0.0
        for word in paragraph.split(" "):
            w = markup_width(let, word, size)
            room = width - (first if not lines else 0.0)
            trial = used + (space if current else 0.0) + w
            if current and trial > room + 1e-9:
                lines.append(" ".join(current))
                current, used = [word], w
            else:
                current.append(word)
                used = trial
        lines.append(" ".join(current))
    return lines


# a block's lines by (lettering, kind, text, size, width, first): the layout
# asks for them again and again (a heading's lead asks for the next block's,
# and the contents' second pass sets every block again)
_LINES: dict[tuple[int, str, str, float, float, float], tuple[Any, ...]] = {}


def _kept_lines(
    let: Lettering,
    key: tuple[str, str, float, float, float],
    make: Callable[[], Sequence[Any]],
) -> tuple[Any, ...]:
    """What `make()` gives for `key` set in `let`, made once (as markup_width
    keeps its widths: by the lettering's id while that lettering lives)."""
    full = (id(let), *key)
    hit = _LINES.get(full)
    if hit is not None and _LETTERINGS.get(id(let)) is let:
        return hit
    made = tuple(make())
    if len(_LINES) > 50_000:
        _LINES.clear()
    _LETTERINGS.setdefault(id(let), let)
    if _LETTERINGS[id(let)] is let:
        _LINES[full] = made
    return made


def _text_lines(
    let: Lettering, text: str, size: float, width: float, first: float
) -> tuple[str, ...]:
    """A paragraph typeset and broken into lines; where a formula run kept
    whole would be wider than a line, its "=" may break after all."""

    def make() -> list[str]:
        lines = _wrap(let, typeset(text), size, width, first)
        if any(markup_width(let, t, size) > width + 1e-6 for t in lines):
            lines = _wrap(let, typeset(text, False), size, width, first)
        return lines

    return _kept_lines(let, ("text", text, size, width, first), make)


def _equation_lines(
    let: Lettering, text: str, size: float, width: float
) -> tuple[tuple[str, float], ...]:
    """An equation as (line, indent): split at "; ", then at " = " with the
    continuation starting "= ", then at spaces."""
    return _kept_lines(
        let, ("equation", text, size, width, 0.0), lambda: _split_equation(let, text, size, width)
    )


def _split_equation(
    let: Lettering, text: str, size: float, width: float
) -> list[tuple[str, float]]:
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


FORM5_OF = {v: k for k, v in FORM5.items()}

NBSP = "\u00a0"
MINUS = "\u2212"
# a hyphen that is a minus: after a space, a bracket, an operator or the start,
# before a number, a symbol or a bracket ("4-5", "counter-clockwise" keep theirs)
_MINUS = re.compile(r"(?:(?<=^)|(?<=[\s(\[{=/·;,]))-(?=[\d(\[{A-Za-zΑ-Ωα-ωА-Яа-яІіЇїЄєҐґ√πΣΔ])")
# a number and what it counts or measures: "12403 N", "5 %", "58.8 °"
_NUMBER_UNIT = re.compile(r"(?<=\d) (?=[^\s=+\-−·/;:,.)\d])")
# a figure's, a table's, a formula's number stays with its word
_NUMBERED = re.compile(
    r"(?i)\b(figure|fig\.|table|position|positions|link|links|рисунок|рис\.|таблиця|"
    r"положення|ланка|ланки|group|група) (?=\d)"
)


_CITATION = re.compile(r"\[\d+, [^\]]*\]")


def _inside_braces(text: str) -> str:
    """Spaces inside index braces become non-breaking: a subscript stays whole."""
    out, depth = [], 0
    for ch in text:
        depth += {"{": 1, "}": -1}.get(ch, 0)
        out.append(NBSP if ch == " " and depth > 0 else ch)
    return "".join(out)


@functools.lru_cache(maxsize=8192)
def typeset(text: str, formula_runs: bool = True) -> str:
    """The note's typography of a line of markup before it is broken into
    lines: a true minus (U+2212) for a hyphen that is one, a non-breaking
    space between a number and its unit, in an index, in a citation, after
    "figure" and the like, the structural formula's arrows kept with the group they point to,
    and (`formula_runs`) round "=" so that "φ_1 = 58.83°" is never broken."""
    text = _MINUS.sub(MINUS, text)
    text = _inside_braces(text)
    text = _NUMBER_UNIT.sub(NBSP, text)
    text = _NUMBERED.sub(lambda m: m.group(1) + NBSP, text)
    text = text.replace(" <- ", " ←" + NBSP).replace(" <-", " ←")
    # a citation stays whole: "[2, formula (5)]"
    text = _CITATION.sub(lambda m: m.group(0).replace(" ", NBSP), text)
    if formula_runs:
        text = re.sub(r" (=|≤|≥|>|<|≈) ", lambda m: NBSP + m.group(1) + NBSP, text)
    return text


def text_box(page: Page, form: str) -> Rect:
    """Where text may go on a page of `form` (capitals' tops at most at its top)."""
    f = page.frame
    left = max(MARGIN_LEFT, f.left + 5.0)
    right = min(page.width - MARGIN_RIGHT, f.right - 5.0)
    top = min(page.height - MARGIN_TOP, f.top - 10.0)
    stamp = {"none": 0.0, "2": FORM2_HEIGHT, "2a": FORM2A_HEIGHT}[FORM5_OF.get(form, form)]
    bottom = MARGIN_BOTTOM if form == "none" else max(MARGIN_BOTTOM, f.bottom + stamp + STAMP_GAP)
    return Rect.from_bounds(left, bottom, right, top)


class _Layout:
    """Sets blocks in lines, page by page."""

    def __init__(self, look: Look, page: Page, lang: Language, first_form: str) -> None:
        self.let = look.lettering
        self.page = page
        self.w = catalogue(lang).words("note_front")
        self.pages: list[list[Line]] = [[]]
        self.forms: list[str] = [first_form]
        self.box = text_box(page, first_form)
        self.y = self.box.top
        self.body = cap(BODY_PT, self.let)
        self.pitch = pitch(BODY_PT, SPACING)
        self.tables = 0
        self.figures = 0
        self.next: Block | None = None  # the block after the one being set
        self.after: Block | None = None  # and the one after that

    # --- placing --------------------------------------------------------------------
    def new_page(self, form: str = "2a") -> None:
        """Start a page of `form`; headings that would end the page left go
        with what follows them (a heading never ends a page)."""
        last = self.pages[-1]
        k = len(last)
        while k > 0 and last[k - 1].kind in ("section", "subsection"):
            k -= 1
        carried = last[k:] if 0 < k < len(last) else []
        if carried:
            del last[k:]
        self.pages.append([])
        self.forms.append(form)
        self.box = text_box(self.page, form)
        if carried:
            shift = (self.box.top - self.body) - carried[0].y
            self.pages[-1] = [replace(ln, y=ln.y + shift) for ln in carried]
            self.y += shift
        else:
            self.y = self.box.top

    @property
    def next_form(self) -> str:
        """The form of a page the text runs on to: 2a after form 2."""
        return "2a" if self.forms[-1] == "2" else self.forms[-1]

    @property
    def empty(self) -> bool:
        return not self.pages[-1]

    def room(self, height: float) -> bool:
        return self.y - height >= self.box.bottom - 1e-9

    def advance(self, height: float, keep: float = 0.0, before: float = 0.0) -> None:
        """Move down by `height` to the next baseline, on a new page if it and
        `keep` more mm do not fit; `before` is dropped at a page's top, where
        the first line's capitals touch the text's top."""
        if not self.empty and not self.room(before + height + keep):
            self.new_page(self.next_form)
        if self.empty:
            self.y = self.box.top - self.body
        else:
            self.y -= before + height

    def put(self, line: Line) -> None:
        self.pages[-1].append(line)

    def text_line(
        self,
        text: str,
        x: float = 0.0,
        kind: str = "text",
        *,
        align: str = "left",
        keep: float = 0.0,
        before: float = 0.0,
        anchor: str = "",
        size: float | None = None,
        step: float | None = None,
    ) -> None:
        size = size or self.body
        self.advance(step or self.pitch, keep, before)
        widths = (self.box.width - x,) if align == "justify" else ()
        self.put(
            Line(
                self.y,
                self.box.left + x,
                text,
                size,
                kind,
                widths=widths,
                align=align,
                anchor=anchor,
            )
        )

    # --- keeping lines together ------------------------------------------------------
    def fits(self) -> int:
        """How many more lines of the main text this page holds."""
        if self.empty:
            return int((self.box.height - self.body) / self.pitch + 1e-9) + 1
        return int((self.y - self.box.bottom) / self.pitch + 1e-9)

    def break_at(self, n: int, tail: float = 0.0) -> int:
        """Where a paragraph of `n` lines goes on to the next page (n: it does
        not): never one line alone at a page's foot or head; `tail` mm of the
        next block stay with the last line (a lead-in ending in ':')."""
        k = self.fits()
        if n <= k and (not tail or self.y - n * self.pitch - tail >= self.box.bottom - 1e-9):
            return n
        b = min(k, n - 1) if n > k else n - 1
        if n - b < 2:
            b = n - 2
        return b if b >= 2 else 0

    def lead(self, block: Block | None, following: Block | None = None) -> float:
        """The height of what must stay with a heading above `block`: its
        first two lines (three of a three-line paragraph, which does not
        break), a table's caption, header and first row, a whole figure; a
        lead-in ending in ':' with what it introduces, `following` (three
        lines when that is not known)."""
        if block is None:
            return 0.0
        width = self.box.width
        if block.kind in ("text", "problem"):
            first = PARAGRAPH if not block.indent else 0.0
            n = len(_text_lines(self.let, block.text, self.body, width - block.indent, first))
        elif block.kind == "equation":
            n = len(
                _equation_lines(
                    self.let, typeset(block.text, False), self.body, width - NUMBER_ROOM
                )
            )
        elif block.kind == "table":
            head = self.caption_lines(block.text, self.body, width)
            return self.pitch + (len(head) - 1) * pitch(BODY_PT) + 2 * (pitch(TABLE_PT) + CELL_PAD)
        elif block.kind == "figure":
            return block.height + 2 * pitch(CAPTION_PT) + self.pitch
        elif block.kind in ("toc", "subsection"):
            n = 1
        else:
            return 0.0
        # a lead-in ending in ':' keeps what it introduces (paragraph(): up to
        # three lines of an equation) and, with it, the heading above it
        if block.kind in ("text", "problem") and block.text.endswith(":"):
            if following is None or following.kind in ("text", "problem"):
                return (min(n, 3) + 3) * self.pitch
            return min(n, 3) * self.pitch + (self.lead(following) or 3 * self.pitch)
        n = n if n <= 3 else 2
        return (n + (block.text.endswith(":") and n == 1)) * self.pitch

    def paragraph(self, lines: Sequence[tuple[str, float]], kind: str, justify: bool) -> None:
        """Lines of one paragraph (text, indent), kept as break_at says; all
        but the last set flush left and right when `justify`."""
        # a lead-in (ending in ':', or one line before an equation) keeps what it introduces
        nxt = self.next
        lead_in = bool(lines) and nxt is not None
        if lead_in and not lines[-1][0].endswith(":"):
            lead_in = kind != "equation" and len(lines) == 1 and nxt.kind == "equation"  # type: ignore[union-attr]
        tail = self.lead(self.next, self.after) if self.next and lead_in else 0.0
        b = self.break_at(len(lines), tail)
        for j, (t, x) in enumerate(lines):
            if j == b and not self.empty:
                self.new_page(self.next_form)
            last = j == len(lines) - 1
            self.text_line(t, x, kind, align="justify" if justify and not last else "left")

    # --- blocks ---------------------------------------------------------------------
    def block(self, block: Block, toc: Mapping[str, int]) -> None:
        kind = block.kind
        width = self.box.width
        let = self.let
        if kind == "pagebreak":
            form = block.text if block.text in FORMS else "2a"
            if self.empty and len(self.pages) == 1:
                self.forms[0] = form
                self.box = text_box(self.page, form)
                self.y = self.box.top
            else:
                self.new_page(form)
        elif kind == "space":
            # a negative height: down to where -height lines are left on the page
            if block.height < 0:
                self.y = min(self.y, self.box.bottom - block.height * self.pitch)
            elif not self.empty:
                self.y -= block.height
        elif kind in ("title", "heading", "center"):
            if kind == "heading" and not self.empty:
                self.new_page("2a" if self.forms[-1] != "none" else "none")
            lines = _wrap(let, block.text, self.body, width - 2 * PARAGRAPH)
            for j, t in enumerate(lines):
                self.text_line(
                    t,
                    width / 2 + block.indent,
                    kind,
                    align="center",
                    keep=(len(lines) - 1 - j) * self.pitch
                    + (self.lead(self.next, self.after) if kind != "center" else 0),
                    anchor=block.step if j == 0 else "",
                )
            if kind != "center":
                self.y -= self.pitch / 2
        elif kind in ("section", "subsection"):
            if kind == "section" and not self.empty and block.step:
                self.new_page("2a" if self.forms[-1] != "none" else "none")
            text = block.text.upper() if kind == "section" else block.text
            lines = _wrap(let, text, self.body, width, PARAGRAPH)
            for j, t in enumerate(lines):
                self.text_line(
                    t,
                    PARAGRAPH if j == 0 else 0.0,
                    kind,
                    before=self.pitch / 2 if j == 0 else 0.0,
                    keep=(len(lines) - 1 - j) * self.pitch + self.lead(self.next, self.after),
                    anchor=block.step if j == 0 else "",
                )
            self.y -= self.pitch / 4
        elif kind in ("text", "problem"):
            first = PARAGRAPH if not block.indent else 0.0
            broken = _text_lines(let, block.text, self.body, width - block.indent, first)
            placed = [(t, block.indent + (first if j == 0 else 0.0)) for j, t in enumerate(broken)]
            self.paragraph(placed, kind, justify=True)
        elif kind == "equation":
            self.paragraph(
                _equation_lines(let, typeset(block.text, False), self.body, width - NUMBER_ROOM),
                kind,
                justify=False,
            )
            if block.number:
                # the formula's number at the right margin of its last line
                last = self.pages[-1].pop()
                self.put(
                    replace(
                        last,
                        cells=(f"({block.number})",),
                        widths=(self.box.right - last.x,),
                    )
                )
        elif kind == "toc":
            self.toc_line(block, toc.get(block.step))
        elif kind == "table":
            self.table(block)
        elif kind == "figure":
            self.figure(block)
        else:  # pragma: no cover - a new block kind must be set here
            raise ValueError(f"cannot set a block of kind {block.kind!r}")

    def toc_line(self, block: Block, number: int | None) -> None:
        page_col = 12.0
        indent = block.indent
        lines = _wrap(self.let, block.text, self.body, self.box.width - page_col - 4.0 - indent)
        for j, t in enumerate(lines):
            last = j == len(lines) - 1
            self.text_line(t, indent + (0.0 if j == 0 else 5.0), "toc")
            if last:
                line = self.pages[-1].pop()
                self.put(
                    Line(
                        line.y,
                        line.x,
                        line.text,
                        line.size,
                        "toc",
                        cells=(str(number) if number else "",),
                        widths=(self.box.right - line.x,),
                        anchor=block.step,
                    )
                )

    def caption_lines(self, text: str, size: float, width: float) -> list[str]:
        return _wrap(self.let, text, size, width)

    def table(self, block: Block) -> None:
        let = self.let
        self.tables += 1
        n = self.tables
        size = cap(TABLE_PT, let)
        row_h = pitch(TABLE_PT) + CELL_PAD
        scale = min(1.0, self.box.width / sum(block.widths)) if block.widths else 1.0
        widths = tuple(w * scale for w in block.widths)
        sizes = tuple(s for s in let.sizes if s >= cap(7.0, let) - 1e-9 and s <= size + 1e-9)
        title = typeset(self.w["table"].format(n=n) + (f" – {block.text}" if block.text else ""))
        head = self.caption_lines(title, self.body, self.box.width)
        # a cell is not broken into lines: only its minus signs are set
        rows = [tuple(_MINUS.sub(MINUS, c) for c in r) for r in block.rows]
        header, body = rows[0], rows[1:]

        def cells(row: Sequence[str]) -> tuple[float, ...]:
            return tuple(
                max([s for s in sizes if markup_width(let, c, s) <= w - 2 * CELL_PAD] or [sizes[0]])
                for c, w in zip(row, widths)
            )

        # the title keeps the header and the first row with it
        keep = 2 * row_h + (len(head) - 1) * pitch(BODY_PT)
        for j, t in enumerate(head):
            self.text_line(
                t,
                0.0,
                "caption",
                before=self.pitch / 4 if j == 0 else 0.0,
                keep=keep - j * pitch(BODY_PT),
                step=self.pitch if j == 0 else pitch(BODY_PT),
            )
        top = self.y - 0.4 * self.body

        def row(cells_: Sequence[str], is_header: bool) -> None:
            nonlocal top
            if top - row_h < self.box.bottom:
                self.new_page(self.next_form)
                self.y = self.box.top - self.body
                self.put(
                    Line(
                        self.y,
                        self.box.left,
                        self.w["table_continued"].format(n=n),
                        self.body,
                        "caption",
                    )
                )
                top = self.y - 0.4 * self.body
                if not is_header:
                    row(header, True)
            self.put(
                Line(
                    top - row_h,
                    self.box.left,
                    "",
                    size,
                    "table",
                    tuple(cells_),
                    widths,
                    is_header,
                    height=row_h,
                    sizes=cells(cells_),
                )
            )
            top -= row_h

        row(header, True)
        for r in body:
            row(r, False)
        self.y = top - 0.5 * self.pitch

    def figure(self, block: Block) -> None:
        self.figures += 1
        size = cap(CAPTION_PT, self.let)
        text = typeset(
            self.w["figure"].format(n=self.figures) + (f" – {block.text}" if block.text else "")
        )
        lines = self.caption_lines(text, size, self.box.width - 2 * PARAGRAPH)
        cap_h = len(lines) * pitch(CAPTION_PT)
        height = min(block.height, self.box.height - cap_h - self.pitch)
        need = height + cap_h + self.pitch / 2
        if not self.empty and not self.room(need):
            self.new_page(self.next_form)
        top = self.y if not self.empty else self.box.top
        if not self.empty:
            top -= self.pitch / 2
        self.put(
            Line(
                top - height,
                self.box.left,
                "",
                0.0,
                "figure",
                widths=(self.box.width,),
                figure=block.figure,
                height=height,
            )
        )
        self.y = top - height - 1.0
        for t in lines:
            self.y -= pitch(CAPTION_PT)
            self.put(
                Line(self.y, self.box.left + self.box.width / 2, t, size, "caption", align="center")
            )
        self.y -= self.pitch / 4


def layout_note(
    content: NoteContent,
    look: Look | None = None,
    page: Page | None = None,
    *,
    toc: Mapping[str, int] | None = None,
    first_form: str = "2",
) -> list[NotePage]:
    """Set the blocks in lines and break them into pages. `toc` gives the
    page of each heading named by a contents line (the second pass)."""
    look = look or note_look()
    page = page or note_page()
    lay = _Layout(look, page, content.lang, first_form)
    for k, block in enumerate(content.blocks):
        lay.next = content.blocks[k + 1] if k + 1 < len(content.blocks) else None
        lay.after = content.blocks[k + 2] if k + 2 < len(content.blocks) else None
        lay.block(block, toc or {})
    pages = [(lines, form) for lines, form in zip(lay.pages, lay.forms)]
    while len(pages) > 1 and not pages[-1][0]:
        pages.pop()
    return [NotePage(i + 1, tuple(lines), form) for i, (lines, form) in enumerate(pages)]  # type: ignore[arg-type]


def heading_pages(pages: Sequence[NotePage]) -> dict[str, int]:
    """The page each named heading starts on."""
    out: dict[str, int] = {}
    for p in pages:
        for line in p.lines:
            if line.anchor and line.kind != "toc" and line.kind != "table":
                out.setdefault(line.anchor, p.number)
    return out


# --- drawing -------------------------------------------------------------------------------

FigureDrawer = Callable[[Backend, Rect, str], None]


def _draw_symbol(backend: Backend, ch: str, x: float, y: float, w: float, size: float) -> None:
    """A glyph the font lacks, in lines of the lettering's weight."""
    if ch == "⊥":
        backend.line((x + 0.12 * w, y), (x + 0.88 * w, y), "thin")
        backend.line((x + w / 2, y), (x + w / 2, y + size), "thin")
    elif ch == "∥":
        for f in (0.35, 0.65):
            backend.line((x + f * w, y - 0.15 * size), (x + f * w, y + size), "thin")
    elif ch == "⇒":
        for f in (0.3, 0.7):
            backend.line((x + 0.1 * w, y + f * size), (x + 0.75 * w, y + f * size), "thin")
        backend.polyline(
            [(x + 0.6 * w, y + size), (x + 0.9 * w, y + 0.5 * size), (x + 0.6 * w, y)], "thin"
        )


def draw_markup(
    backend: Backend, pos: tuple[float, float], text: str, size: float, align: str = "left"
) -> float:
    """A line of markup at `pos` (its baseline), the glyphs the font lacks drawn
    as lines; returns its width."""
    let = backend.look.lettering
    total = markup_width(let, text, size)
    x = pos[0] - {"left": 0.0, "center": total / 2, "right": total}[align]
    y = pos[1]
    start = 0
    parts: list[str] = []
    if not _DRAWN_APART.isdisjoint(text):  # most lines have none: not read letter by letter
        for i, ch in enumerate(text):
            if ch in _DRAWN_APART:
                parts += [text[start:i], ch]
                start = i + 1
    parts.append(text[start:])
    letter = 0.0  # the width of the last letter drawn, which a vector's arrow spans
    for part in parts:
        if not part:
            continue
        if part == VECTOR:
            _draw_arrow_over(backend, x - letter, x, y + size, size)
            continue
        if part in SYMBOLS:
            w = let.advance_width(part, size)
            _draw_symbol(backend, part, x, y, w, size)
            x += w
            continue
        # spaces at the ends of a run are offsets (renderers drop them)
        lead = len(part) - len(part.lstrip(" "))
        if part.strip(" "):
            backend.rich_text((x + let.advance_width(" " * lead, size), y), part.lstrip(" "), size)
        x += markup_width(let, part, size)
        letter = let.advance_width(part[-1], size)
    return total


def _draw_arrow_over(backend: Backend, x0: float, x1: float, top: float, size: float) -> None:
    """The arrow of a vector over a letter from x0 to x1 whose capitals reach `top`."""
    y = top + 0.3 * size
    x0, x1 = x0 + 0.05 * (x1 - x0), x1 + 0.1 * (x1 - x0)
    head = 0.25 * size
    backend.line((x0, y), (x1, y), "thin")
    backend.polyline([(x1 - head, y + head / 2), (x1, y), (x1 - head, y - head / 2)], "thin")


def draw_justified(
    backend: Backend, pos: tuple[float, float], text: str, size: float, width: float
) -> float:
    """A line of markup set flush left and right over `width` mm: its words
    drawn one by one, the spaces between them widened alike (never narrowed)."""
    let = backend.look.lettering
    parts = words(text)
    natural = [markup_width(let, p, size) for p in parts]
    space = let.advance_width(" ", size)
    gap = (width - sum(natural)) / (len(parts) - 1) if len(parts) > 1 else 0.0
    if len(parts) < 2 or gap < space - 1e-6:
        return draw_markup(backend, pos, text, size)
    x = pos[0]
    for part, w in zip(parts, natural):
        draw_markup(backend, (x, pos[1]), part, size)
        x += w + gap
    return width


def _draw_row(backend: Backend, line: Line) -> None:
    x = line.x
    bottom, top = line.y, line.y + line.height
    kind: LineType = "thin"
    backend.line((x, top), (x + sum(line.widths), top), kind)
    backend.line((x, bottom), (x + sum(line.widths), bottom), kind)
    backend.line((x, bottom), (x, top), kind)
    sizes = line.sizes
    for i, (w, cell) in enumerate(zip(line.widths, line.cells)):
        backend.line((x + w, bottom), (x + w, top), kind)
        if cell:
            size = sizes[i] if i < len(sizes) else line.size
            y = (bottom + top) / 2 - size / 2
            if w >= WORDY and not line.header:  # a column of words reads from the left
                draw_markup(backend, (x + CELL_PAD + 0.5, y), cell, size, "left")
            else:
                draw_markup(backend, (x + w / 2, y), cell, size, "center")
        x += w


@dataclass(frozen=True)
class Stamp:
    """What forms 2 and 2a print: the designation, the document's name, the
    student and the supervisor, the organisation, the page count."""

    designation: str = ""
    title: str = ""
    author: str = ""
    checked_by: str = ""
    organisation: str = ""
    pages: int = 0


def _cell_text(
    backend: Backend,
    rect: tuple[float, float, float, float],
    text: str,
    pt: float,
    align: str = "center",
) -> None:
    """One line centred on a cell's middle, narrowed to fit it."""
    x0, y0, x1, y1 = rect
    let = backend.look.lettering
    size = cap(pt, let)
    x = {"left": x0 + 1.0, "center": (x0 + x1) / 2, "right": x1 - 1.0}[align]
    backend.text(
        (x, (y0 + y1) / 2),
        text,
        size,
        anchor=align,  # type: ignore[arg-type]
        valign="middle",
        max_width=x1 - x0 - 2.0,
    )


def _block_text(
    backend: Backend, rect: tuple[float, float, float, float], text: str, pt: float
) -> None:
    """Centred lines, wrapped and made smaller until they fit the cell."""
    x0, y0, x1, y1 = rect
    let = backend.look.lettering
    for p in (pt, pt - 2, pt - 4, 8.0, 7.0):
        size = cap(p, let)
        lines = [ln for part in text.split("\n") for ln in let.wrap(part, size, x1 - x0 - 4.0)]
        step = pitch(p)
        if len(lines) * step <= y1 - y0 - 1.0 and all(
            let.width(ln, size) <= x1 - x0 - 4.0 for ln in lines
        ):
            break
    first = (y0 + y1) / 2 + step * (len(lines) - 1) / 2
    for i, ln in enumerate(lines):
        backend.text(
            ((x0 + x1) / 2, first - i * step),
            ln,
            size,
            anchor="center",
            valign="middle",
            max_width=x1 - x0 - 2.0,
        )


def draw_form2(backend: Backend, page: Page, number: int, stamp: Stamp, lang: Language) -> None:
    """GOST 2.104 form 2, the first page of a text document: 185 × 40 mm;
    on the left two rows of changes, the caption row and five rows of
    signatures (5 mm each; columns 7, 10, 23, 15, 10 mm); on the right the
    designation (120 × 15), the document's name (70 × 25), Літ. / Арк. /
    Аркушів (15, 15, 20 mm; a caption row and a value row) and the
    organisation (50 × 15)."""
    w = catalogue(lang).words("title_block")
    f = page.frame
    x0, y0 = f.right - FORM_WIDTH, f.bottom
    L = [x0 + d for d in (0.0, 7.0, 17.0, 40.0, 55.0, 65.0)]
    R = x0 + 135.0
    right = f.right
    with backend.group("title-block", "title-block"):
        for y in (y0 + 5, y0 + 10, y0 + 15, y0 + 20, y0 + 35):
            backend.line((L[0], y), (L[5], y), "thin")
        backend.line((x0, y0 + 40), (right, y0 + 40), "main")
        backend.line((x0, y0), (x0, y0 + 40), "main")
        for y in (y0 + 25, y0 + 30):
            backend.line((L[0], y), (L[5], y), "main")
        backend.line((L[1], y0 + 25), (L[1], y0 + 40), "main")
        for x in L[2:]:
            backend.line((x, y0), (x, y0 + 40), "main")
        backend.line((L[5], y0 + 25), (right, y0 + 25), "main")
        backend.line((R, y0), (R, y0 + 25), "main")
        for y in (y0 + 20, y0 + 15):
            backend.line((R, y), (right, y), "main")
        for x in (R + 15, R + 30):
            backend.line((x, y0 + 15), (x, y0 + 25), "main")
        for x in (R + 5, R + 10):
            backend.line((x, y0 + 15), (x, y0 + 20), "thin")
        keys = ("change", "change_sheet", "document", "signature", "date")
        for i, key in enumerate(keys):
            _cell_text(backend, (L[i], y0 + 25, L[i + 1], y0 + 30), w[key], CAPTION_FORM_PT)
        roles = ("developed", "checked", "", "norm_control", "approved")
        names = (stamp.author, stamp.checked_by, "", "", "")
        for j, (role, name) in enumerate(zip(roles, names)):
            ya, yb = y0 + 20 - 5 * j, y0 + 25 - 5 * j
            if role:
                _cell_text(backend, (L[0], ya, L[2], yb), w[role], CAPTION_FORM_PT, "left")
            if name:
                _cell_text(backend, (L[2], ya, L[3], yb), name, FORM_PT, "left")
        for key, (xa, xb) in (
            ("letter", (R, R + 15)),
            ("sheet", (R + 15, R + 30)),
            ("sheets", (R + 30, right)),
        ):
            _cell_text(backend, (xa, y0 + 20, xb, y0 + 25), w[key], CAPTION_FORM_PT)
        _cell_text(backend, (R + 15, y0 + 15, R + 30, y0 + 20), str(number), FORM_PT)
        if stamp.pages:
            _cell_text(backend, (R + 30, y0 + 15, right, y0 + 20), str(stamp.pages), FORM_PT)
        if stamp.designation:
            _cell_text(backend, (L[5], y0 + 25, right, y0 + 40), stamp.designation, 16.0)
        if stamp.title:
            _block_text(backend, (L[5], y0, R, y0 + 25), stamp.title, 12.0)
        if stamp.organisation:
            _block_text(backend, (R, y0, right, y0 + 15), stamp.organisation, 12.0)


def draw_form2a(
    backend: Backend, page: Page, number: int, designation: str, lang: Language
) -> None:
    """GOST 2.104 form 2a: 185 × 15 mm at the frame's bottom right; columns
    7, 10, 23, 15, 10 | 110 | 10 mm; three 5 mm rows on the left, the lowest
    holding the captions; the page number in the right cell."""
    w = catalogue(lang).words("title_block")
    f = page.frame
    x0, y0 = f.right - FORM_WIDTH, f.bottom
    xs = [x0 + d for d in (0.0, 7.0, 17.0, 40.0, 55.0, 65.0, 175.0, 185.0)]
    with backend.group("form-2a", "title-block"):
        backend.line((xs[0], y0 + 10.0), (xs[5], y0 + 10.0), "thin")
        backend.line((xs[0], y0 + 5.0), (xs[5], y0 + 5.0), "main")
        backend.line((xs[0], y0 + 15.0), (xs[7], y0 + 15.0), "main")
        for x in xs[:7]:
            backend.line((x, y0), (x, y0 + 15.0), "main")
        backend.line((xs[6], y0 + 8.0), (xs[7], y0 + 8.0), "main")
        keys = ("change", "change_sheet", "document", "signature", "date")
        for i, key in enumerate(keys):
            _cell_text(backend, (xs[i], y0, xs[i + 1], y0 + 5.0), w[key], CAPTION_FORM_PT)
        _cell_text(backend, (xs[6], y0 + 8.0, xs[7], y0 + 15.0), w["sheet"], CAPTION_FORM_PT)
        _cell_text(backend, (xs[6], y0, xs[7], y0 + 8.0), str(number), 12.0)
        if designation:
            _cell_text(backend, (xs[5], y0, xs[6], y0 + 15.0), designation, 16.0)


# the additional columns of GOST 2.104 in the binding margin, from the frame's
# bottom up (19-23) and from its top down (25, 24): (catalogue key, height mm)
MARGIN_COLUMNS = (
    ("inv_original", 25.0),
    ("sign_date", 35.0),
    ("inv_replaced", 25.0),
    ("inv_duplicate", 25.0),
    ("sign_date", 35.0),
)
MARGIN_TOP_COLUMNS = (("first_use", 60.0), ("reference_no", 60.0))
MARGIN_CAPTION, MARGIN_VALUE = 5.0, 7.0  # the columns' widths, mm


def draw_margin_columns(backend: Backend, page: Page, first: bool, lang: Language) -> None:
    """Columns 19-23 of GOST 2.104 left of the frame (12 mm: a 5 mm caption
    column and a 7 mm one to fill), and on the first page (form 5) columns
    24-25 at the top: GOST 2.106's forms 5 and 5a."""
    w = catalogue(lang).words("note_front")
    f = page.frame
    x1 = f.left
    x0, xm = x1 - MARGIN_CAPTION - MARGIN_VALUE, x1 - MARGIN_VALUE
    size = cap(CAPTION_FORM_PT, backend.look.lettering)

    def strip(y0: float, cells: Sequence[tuple[str, float]], down: bool) -> None:
        y = y0
        edges = [y]
        for key, h in cells:
            ya, yb = (y - h, y) if down else (y, y + h)
            backend.text(
                ((x0 + xm) / 2, (ya + yb) / 2),
                str(w[key]),
                size,
                anchor="center",
                valign="middle",
                rotation=90.0,
                max_width=h - 2.0,
            )
            y = ya if down else yb
            edges.append(y)
        backend.line((x0, min(edges)), (x0, max(edges)), "main")
        backend.line((xm, min(edges)), (xm, max(edges)), "main")
        for e in edges:
            backend.line((x0, e), (x1, e), "main")

    with backend.group("margin-columns", "title-block"):
        strip(f.bottom, MARGIN_COLUMNS, down=False)
        if first:
            strip(f.top, MARGIN_TOP_COLUMNS, down=True)


def draw_note_page(
    backend: Backend,
    note_page_: NotePage,
    pages: int,
    content: NoteContent,
    mech: Any = None,
    page: Page | None = None,
    *,
    stamp: Stamp | None = None,
    figures: Mapping[str, FigureDrawer] | None = None,
) -> None:
    """One page: its lines, the frame and form 2 or 2a (none on the title
    page and the task sheet, which show their number at the top right but
    for the first)."""
    page = page or note_page()
    stamp = stamp or Stamp(title=content.title, pages=pages)
    with backend.group(f"page-{note_page_.number}", "note-page"):
        for line in note_page_.lines:
            if line.kind == "table":
                _draw_row(backend, line)
            elif line.kind == "figure":
                drawer = (figures or {}).get(line.figure)
                if drawer is not None:
                    rect = Rect(line.x, line.y, sum(line.widths), line.height)
                    with backend.group(f"figure-{line.figure}", "figure"):
                        drawer(backend, rect, content.lang)
            elif line.align == "justify":
                draw_justified(backend, (line.x, line.y), line.text, line.size, line.widths[0])
            else:
                draw_markup(backend, (line.x, line.y), line.text, line.size, line.align)
                if line.kind == "equation" and line.cells:
                    end = line.x + line.widths[0]
                    backend.text((end, line.y), line.cells[0], line.size, anchor="right")
                if line.kind == "toc":
                    let = backend.look.lettering
                    end = line.x + line.widths[0]
                    number = line.cells[0] if line.cells else ""
                    num_w = let.advance_width(number, line.size)
                    text_end = line.x + markup_width(let, line.text, line.size)
                    dots_w = end - num_w - 1.5 - text_end - 1.5
                    dot = let.advance_width(" .", line.size)
                    if dots_w > dot:
                        backend.text(
                            (end - num_w - 1.5, line.y),
                            " ." * int(dots_w / dot),
                            line.size,
                            anchor="right",
                        )
                    if number:
                        backend.text((end, line.y), number, line.size, anchor="right")
    if note_page_.form == "none":
        if note_page_.number > 1:
            box = text_box(page, "none")
            size = cap(BODY_PT, backend.look.lettering)
            with backend.group("page-number", "page-number"):
                backend.text(
                    (box.right, page.height - 15.0), str(note_page_.number), size, anchor="right"
                )
        return
    draw_frame(backend, page)
    form = FORM5_OF.get(note_page_.form, note_page_.form)
    if form == "2":
        draw_form2(backend, page, note_page_.number, stamp, content.lang)
    else:
        draw_form2a(backend, page, note_page_.number, stamp.designation, content.lang)
    if note_page_.form in FORM5_OF:
        draw_margin_columns(backend, page, note_page_.form == "5", content.lang)


def all_lines(pages: Sequence[NotePage]) -> list[Line]:
    return [line for p in pages for line in p.lines]
