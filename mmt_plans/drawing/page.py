"""The sheet as data: page sizes, margins, the frame and the main inscription.

Modelled on ezdxf's `addons/drawing/layout.py` (`PAGE_SIZES`, `Margins`,
`Page`). Everything here is geometry in page millimetres, origin at the
bottom-left corner of the sheet, y up. How it looks (line weights, lettering,
captions) comes from templates/.

Main inscription: GOST 2.104-2006, form 1, 185 × 55 mm, in the bottom-right
corner of the frame. Columns of the left part 7, 10, 23, 15, 10 mm, then 70
and 50 mm; eleven rows of 5 mm on the left: four rows of changes, the header
row (Змн., Арк., № докум., Підпис, Дата), six rows of signatures (Розроб.,
Перев., Т.контр., a blank one, Н.контр., Затв.). On the right: designation
(graph 2) 120 × 15 at the top; below it the name of the drawing (graph 1,
70 × 25) beside Літ. (3 × 5 mm), Маса (17 mm), Масштаб (18 mm) with a 5 mm
caption row and a 15 mm value row, then Арк. (20 mm) and Аркушів (30 mm) in a
5 mm row; at the bottom graph 3 (70 × 15) and the organisation (graph 9,
50 × 15). Line weights as in GOST 2.104: the outline and the column lines
main, the row lines of changes and signatures thin. Cell positions were
checked against KiCad's GOST title block (common/title_block_shapes_gost.cpp).
"""

from __future__ import annotations

import dataclasses
import functools
from collections.abc import Iterator, Mapping
from dataclasses import dataclass
from types import MappingProxyType
from typing import Any, Literal, NamedTuple

from ..i18n import Language, catalogue, check_language
from ..render.backend import Backend, HAlign
from ..render.look import Look, load_look, load_template

__all__ = [
    "PAGE_SIZES",
    "Margins",
    "GOST_MARGINS",
    "Rect",
    "Page",
    "Cell",
    "TitleBlock",
    "FORM1_WIDTH",
    "FORM1_HEIGHT",
    "FORM1_COLUMNS",
    "FORM1_CELLS",
    "FORM1_MAIN_LINES",
    "FORM1_THIN_LINES",
    "FIELDS",
    "Language",
    "TitleBlockLook",
    "load_title_block_look",
    "PlacedText",
    "title_block_texts",
    "draw_frame",
    "draw_title_block",
    "draw_page",
]


# ISO 216 sizes in mm as this course uses them: the drawing sheets in
# landscape, the A4 of the explanatory note in portrait.
PAGE_SIZES: Mapping[str, tuple[float, float]] = MappingProxyType(
    {
        "A0": (1189.0, 841.0),
        "A1": (841.0, 594.0),
        "A2": (594.0, 420.0),
        "A3": (420.0, 297.0),
        "A4": (210.0, 297.0),
    }
)


class Margins(NamedTuple):
    """Distances from the sheet edge to the frame, in mm (ezdxf order)."""

    top: float
    right: float
    bottom: float
    left: float


# GOST 2.301 / 2.104: 20 mm on the binding side, 5 mm elsewhere.
GOST_MARGINS = Margins(top=5.0, right=5.0, bottom=5.0, left=20.0)


@dataclass(frozen=True)
class Rect:
    """An axis-parallel rectangle: bottom-left corner (x, y), width, height."""

    x: float
    y: float
    width: float
    height: float

    def __post_init__(self) -> None:
        if self.width < 0 or self.height < 0:
            raise ValueError(
                f"a rectangle needs width, height >= 0, got {self.width}, {self.height}"
            )

    @classmethod
    def from_bounds(cls, left: float, bottom: float, right: float, top: float) -> Rect:
        return cls(left, bottom, right - left, top - bottom)

    @property
    def left(self) -> float:
        return self.x

    @property
    def right(self) -> float:
        return self.x + self.width

    @property
    def bottom(self) -> float:
        return self.y

    @property
    def top(self) -> float:
        return self.y + self.height

    @property
    def center(self) -> tuple[float, float]:
        return (self.x + self.width / 2.0, self.y + self.height / 2.0)

    @property
    def bounds(self) -> tuple[float, float, float, float]:
        """(left, bottom, right, top), the order shapely uses."""
        return (self.left, self.bottom, self.right, self.top)

    def corners(self) -> list[tuple[float, float]]:
        """Counter-clockwise from the bottom-left corner."""
        return [
            (self.left, self.bottom),
            (self.right, self.bottom),
            (self.right, self.top),
            (self.left, self.top),
        ]

    def contains(self, other: Rect, tol: float = 1e-9) -> bool:
        return (
            other.left >= self.left - tol
            and other.right <= self.right + tol
            and other.bottom >= self.bottom - tol
            and other.top <= self.top + tol
        )

    def overlaps(self, other: Rect) -> bool:
        """True if the interiors share some area (touching edges do not count)."""
        return min(self.right, other.right) > max(self.left, other.left) and min(
            self.top, other.top
        ) > max(self.bottom, other.bottom)

    def moved(self, dx: float, dy: float) -> Rect:
        return Rect(self.x + dx, self.y + dy, self.width, self.height)

    def inset(self, d: float) -> Rect:
        """Shrunk by d on every side (grown for negative d)."""
        return Rect(
            self.x + d, self.y + d, max(self.width - 2 * d, 0.0), max(self.height - 2 * d, 0.0)
        )


# --- GOST 2.104 form 1 ------------------------------------------------------

FORM1_WIDTH = 185.0
FORM1_HEIGHT = 55.0
FORM1_COLUMNS: tuple[float, ...] = (7.0, 10.0, 23.0, 15.0, 10.0, 70.0, 50.0)

# Column edges of the left part and the right part, from the block's left edge.
_L = (0.0, 7.0, 17.0, 40.0, 55.0, 65.0)  # Змн. | Арк. | № докум. | Підпис | Дата
_T = 65.0  # graph 1 and graph 3 start
_R = 135.0  # the 50 mm right part starts


def _r(left: float, right: float, bottom: float, top: float) -> Rect:
    return Rect.from_bounds(left, bottom, right, top)


def _form1_cells() -> dict[str, Rect]:
    cells: dict[str, Rect] = {}
    change_cols = ("change", "change_sheet", "document", "signature", "date")
    # Four rows of changes above the header row, numbered from the top.
    for row in range(4):
        top = FORM1_HEIGHT - 5.0 * row
        for i, col in enumerate(change_cols):
            cells[f"change{row + 1}_{col}"] = _r(_L[i], _L[i + 1], top - 5.0, top)
    for i, col in enumerate(change_cols):
        cells[f"header_{col}"] = _r(_L[i], _L[i + 1], 30.0, 35.0)
    # Signature rows; the role caption spans the first two columns (7 + 10).
    roles = ("developed", "checked", "tech_control", "blank", "norm_control", "approved")
    for row, role in enumerate(roles):
        top = 30.0 - 5.0 * row
        cells[f"{role}_role"] = _r(_L[0], _L[2], top - 5.0, top)
        cells[f"{role}_name"] = _r(_L[2], _L[3], top - 5.0, top)
        cells[f"{role}_signature"] = _r(_L[3], _L[4], top - 5.0, top)
        cells[f"{role}_date"] = _r(_L[4], _L[5], top - 5.0, top)
    cells["designation"] = _r(_T, FORM1_WIDTH, 40.0, 55.0)  # graph 2
    cells["title"] = _r(_T, _R, 15.0, 40.0)  # graph 1
    cells["material"] = _r(_T, _R, 0.0, 15.0)  # graph 3
    cells["letter_caption"] = _r(_R, 150.0, 35.0, 40.0)
    cells["mass_caption"] = _r(150.0, 167.0, 35.0, 40.0)
    cells["scale_caption"] = _r(167.0, FORM1_WIDTH, 35.0, 40.0)
    for i in range(3):  # graph 4, three letter cells of 5 mm
        cells[f"letter{i + 1}"] = _r(_R + 5.0 * i, _R + 5.0 * (i + 1), 20.0, 35.0)
    cells["mass"] = _r(150.0, 167.0, 20.0, 35.0)  # graph 5
    cells["scale"] = _r(167.0, FORM1_WIDTH, 20.0, 35.0)  # graph 6
    cells["sheet"] = _r(_R, 155.0, 15.0, 20.0)  # graph 7
    cells["sheets"] = _r(155.0, FORM1_WIDTH, 15.0, 20.0)  # graph 8
    cells["organisation"] = _r(_R, FORM1_WIDTH, 0.0, 15.0)  # graph 9
    return cells


FORM1_CELLS: Mapping[str, Rect] = MappingProxyType(_form1_cells())

Segment = tuple[tuple[float, float], tuple[float, float]]


def _h(y: float, x0: float, x1: float) -> Segment:
    return ((x0, y), (x1, y))


def _v(x: float, y0: float, y1: float) -> Segment:
    return ((x, y0), (x, y1))


FORM1_MAIN_LINES: tuple[Segment, ...] = (
    _h(55.0, 0.0, FORM1_WIDTH),  # top edge; the other edges lie on the frame
    _v(0.0, 0.0, 55.0),  # left edge
    _h(40.0, _T, FORM1_WIDTH),
    _h(35.0, 0.0, _T),
    _h(30.0, 0.0, _T),
    _h(35.0, _R, FORM1_WIDTH),
    _h(20.0, _R, FORM1_WIDTH),
    _h(15.0, _T, FORM1_WIDTH),
    _v(7.0, 30.0, 55.0),
    _v(17.0, 0.0, 55.0),
    _v(40.0, 0.0, 55.0),
    _v(55.0, 0.0, 55.0),
    _v(_T, 0.0, 55.0),
    _v(_R, 0.0, 40.0),
    _v(150.0, 20.0, 40.0),
    _v(155.0, 15.0, 20.0),
    _v(167.0, 20.0, 40.0),
)

FORM1_THIN_LINES: tuple[Segment, ...] = (
    *(_h(y, 0.0, _T) for y in (50.0, 45.0, 40.0)),
    *(_h(y, 0.0, _T) for y in (25.0, 20.0, 15.0, 10.0, 5.0)),
    _v(140.0, 20.0, 35.0),
    _v(145.0, 20.0, 35.0),
)


@dataclass(frozen=True)
class Cell:
    """A cell of the main inscription, placed on the page."""

    name: str
    rect: Rect


@dataclass(frozen=True)
class TitleBlock:
    """GOST 2.104 form 1 with its bottom-left corner at `origin` (page mm)."""

    origin: tuple[float, float]

    @property
    def rect(self) -> Rect:
        return Rect(self.origin[0], self.origin[1], FORM1_WIDTH, FORM1_HEIGHT)

    def cell(self, name: str) -> Rect:
        try:
            local = FORM1_CELLS[name]
        except KeyError:
            raise KeyError(f"form 1 has no cell {name!r}") from None
        return local.moved(*self.origin)

    def cells(self) -> Iterator[Cell]:
        for name in FORM1_CELLS:
            yield Cell(name, self.cell(name))

    def lines(self, kind: Literal["main", "thin"]) -> list[Segment]:
        ox, oy = self.origin
        segments = FORM1_MAIN_LINES if kind == "main" else FORM1_THIN_LINES
        return [((x0 + ox, y0 + oy), (x1 + ox, y1 + oy)) for (x0, y0), (x1, y1) in segments]


@dataclass(frozen=True)
class Page:
    """A sheet: its size, the margins to the frame, and what follows from them."""

    width: float
    height: float
    margins: Margins = GOST_MARGINS
    name: str = ""

    def __post_init__(self) -> None:
        m = self.margins
        if (
            self.width - m.left - m.right < FORM1_WIDTH
            or self.height - m.top - m.bottom < FORM1_HEIGHT
        ):
            raise ValueError(f"page {self.width} x {self.height} mm is too small for a frame")

    @classmethod
    def of(cls, name: str, margins: Margins = GOST_MARGINS) -> Page:
        """Page.of("A1"): 841 × 594 mm with the GOST margins."""
        try:
            w, h = PAGE_SIZES[name.upper()]
        except KeyError:
            raise ValueError(
                f"unknown page size {name!r}; expected one of {', '.join(PAGE_SIZES)}"
            ) from None
        return cls(w, h, margins, name.upper())

    @property
    def is_landscape(self) -> bool:
        return self.width > self.height

    def landscape(self) -> Page:
        return (
            self
            if self.is_landscape
            else dataclasses.replace(self, width=self.height, height=self.width)
        )

    def portrait(self) -> Page:
        return (
            self
            if not self.is_landscape
            else dataclasses.replace(self, width=self.height, height=self.width)
        )

    @property
    def rect(self) -> Rect:
        return Rect(0.0, 0.0, self.width, self.height)

    @property
    def frame(self) -> Rect:
        m = self.margins
        return Rect.from_bounds(m.left, m.bottom, self.width - m.right, self.height - m.top)

    @property
    def title_block(self) -> TitleBlock:
        f = self.frame
        return TitleBlock((f.right - FORM1_WIDTH, f.bottom))


# --- filling the main inscription ---------------------------------------------

# Field name → the cell it fills.
FIELDS: Mapping[str, str] = MappingProxyType(
    {
        "title": "title",
        "drawing_number": "designation",
        "author": "developed_name",
        "date": "developed_date",
        "checked_by": "checked_name",
        "checked_date": "checked_date",
        "tech_control": "tech_control_name",
        "norm_control": "norm_control_name",
        "approved_by": "approved_name",
        "material": "material",
        "letter": "letter1",
        "mass": "mass",
        "scale": "scale",
        "sheet": "sheet",
        "sheets": "sheets",
        "organisation": "organisation",
        "school": "organisation",
        "group": "organisation",
        "sheet_name": "title",  # the document's name, under the title in graph 1
        # the designation without the sheet's number ("ТММ.КП.PRESS"): completed
        # with it (".01") where no drawing_number is given
        "designation_base": "designation",
    }
)

# Caption key (templates/title_block.toml) → the cell that prints it.
_CAPTION_CELLS: Mapping[str, str] = MappingProxyType(
    {
        "change": "header_change",
        "change_sheet": "header_change_sheet",
        "document": "header_document",
        "signature": "header_signature",
        "date": "header_date",
        "developed": "developed_role",
        "checked": "checked_role",
        "tech_control": "tech_control_role",
        "norm_control": "norm_control_role",
        "approved": "approved_role",
        "letter": "letter_caption",
        "mass": "mass_caption",
        "scale": "scale_caption",
        "sheet": "sheet",
        "sheets": "sheets",
    }
)


@dataclass(frozen=True)
class TitleBlockLook:
    """Lettering sizes of the main inscription (templates/title_block.toml); its
    captions come from the language's catalogue."""

    caption: float
    field: float
    title: float
    designation: float
    organisation: float
    padding: float
    block_padding: float

    def caption_text(self, lang: Language, key: str) -> str:
        """A printed caption in `lang` (the catalogue's [title_block])."""
        try:
            return str(catalogue(lang).words("title_block")[key])
        except KeyError:
            raise ValueError(f"no caption {key!r} for language {lang!r}") from None


@functools.cache
def load_title_block_look() -> TitleBlockLook:
    data = load_template("title_block.toml")
    sizes = data["sizes"]
    return TitleBlockLook(
        caption=float(sizes["caption"]),
        field=float(sizes["field"]),
        title=float(sizes["title"]),
        designation=float(sizes["designation"]),
        organisation=float(sizes["organisation"]),
        padding=float(sizes["padding"]),
        block_padding=float(sizes["block_padding"]),
    )


@dataclass(frozen=True)
class PlacedText:
    """One line of lettering the title block will draw."""

    cell: str
    content: str
    pos: tuple[float, float]
    size: float
    anchor: HAlign
    max_width: float | None = None


def _check_fields(fields: Mapping[str, Any]) -> dict[str, str]:
    unknown = set(fields) - set(FIELDS)
    if unknown:
        raise ValueError(
            f"unknown title-block fields: {', '.join(sorted(unknown))}; "
            f"expected some of {', '.join(FIELDS)}"
        )
    return {k: str(v) for k, v in fields.items() if v is not None and str(v) != ""}


def _default_sheet_name(lang: Language, sheet: str | None) -> str:
    """The catalogue's name of sheet `sheet` (sheet_name_1, sheet_name_2), or ""."""
    words = catalogue(lang).words("title_block")
    return str(words.get(f"sheet_name_{(sheet or '').strip()}", ""))


def _designation(values: Mapping[str, str]) -> str:
    """designation_base completed with the sheet's number: "ТММ.КП.PRESS.01"."""
    base = values.get("designation_base", "")
    sheet = values.get("sheet", "").strip()
    if not base:
        return ""
    return f"{base}.{int(sheet):02d}" if sheet.isdigit() else base


def title_block_texts(
    block: TitleBlock,
    fields: Mapping[str, Any],
    lang: Language = "uk",
    *,
    look: Look | None = None,
    tb_look: TitleBlockLook | None = None,
) -> list[PlacedText]:
    """Every caption and field text of the main inscription, placed in its cell.

    Positions are the anchor points of `Backend.text` with valign="middle":
    the middle of the capitals sits on the middle of its line.
    """
    look = look if look is not None else load_look()
    tb = tb_look if tb_look is not None else load_title_block_look()
    check_language(lang)
    values = _check_fields(fields)
    let = look.lettering
    pad = tb.padding
    out: list[PlacedText] = []

    def one_line(cell: str, text: str, size: float, anchor: HAlign, *, shrink: bool = True) -> None:
        r = block.cell(cell)
        if shrink:
            fitting = tuple(s for s in let.sizes if s <= size) or (size,)
            # Capitals may fill a 5 mm row up to 0.75 mm from its lines.
            size = let.fit_line(text, r.width - 2 * pad, r.height - 1.5, fitting)
        x = {"left": r.left + pad, "center": r.center[0], "right": r.right - pad}[anchor]
        out.append(PlacedText(cell, text, (x, r.center[1]), size, anchor, r.width - 2 * pad))

    def _name_size(name: str, rect: Rect) -> float:
        """The document's name in one size on every sheet: the size at which the
        longest of the catalogue's sheet names fits (a name of the file's own
        that needs less room is not set larger than they are)."""
        fitting = tuple(s for s in let.sizes if s <= tb.title) or (tb.title,)
        words = catalogue(lang).words("title_block")
        names = [str(v) for k, v in words.items() if k.startswith("sheet_name_")] + [name]
        room, height = rect.width - 2 * tb.block_padding, rect.height - 2 * pad
        return min(let.fit(n, room, height, fitting)[0] for n in names)

    def _fits(text: str, height: float) -> bool:
        """True when `text` fits the title cell's width and `height` at some size."""
        r = block.cell("title")
        room = r.width - 2 * tb.block_padding
        fitting = tuple(s for s in let.sizes if s <= tb.title) or (tb.title,)
        s, lines = let.fit(text, room, height - 2 * pad, fitting)
        return let.block_height(len(lines), s) <= height - 2 * pad

    def block_text(cell: str, text: str, size: float, rect: Rect | None = None) -> None:
        """Centred, wrapped, shrunk from `size` down until it fits the cell
        (or `rect`, a part of it); where even the smallest size does not, the
        lines are narrowed (down to the look's min_squeeze) so that fewer of
        them fit its height."""
        r = rect if rect is not None else block.cell(cell)
        fitting = tuple(s for s in let.sizes if s <= size) or (size,)
        room = r.width - 2 * tb.block_padding
        s, lines = let.fit(text, room, r.height - 2 * pad, fitting)
        if let.block_height(len(lines), s) > r.height - 2 * pad:
            lines = let.wrap(text, s, room / let.min_squeeze)
        pitch = let.line_pitch * s
        cx, cy = r.center
        # Middles of the lines, centred as a group on the cell's middle.
        first = cy + pitch * (len(lines) - 1) / 2.0
        for i, line in enumerate(lines):
            out.append(PlacedText(cell, line, (cx, first - i * pitch), s, "center", room))

    # Printed captions.
    for key, cell in _CAPTION_CELLS.items():
        text = tb.caption_text(lang, key)
        if key in ("sheet", "sheets"):
            continue  # share their cell with a number, placed below
        anchor: HAlign = "left" if cell.endswith("_role") else "center"
        one_line(cell, text, tb.caption, anchor)

    # Sheet i of n: the caption on the left of its cell, the number after it.
    for key in ("sheet", "sheets"):
        caption = tb.caption_text(lang, key)
        one_line(key, caption, tb.caption, "left", shrink=False)
        if key in values:
            r = block.cell(key)
            x = r.left + pad + let.width(caption, tb.caption) + 2.0
            room = r.right - pad - x
            out.append(PlacedText(key, values[key], (x, r.center[1]), tb.field, "left", room))

    # Graph 1: the product's name and, under it, the document's (the sheet's) name.
    sheet_name = values.get("sheet_name") or _default_sheet_name(lang, values.get("sheet"))
    title_cell = block.cell("title")
    if "title" in values and sheet_name:
        split = title_cell.top - title_cell.height * 0.62
        lower = Rect.from_bounds(title_cell.left, title_cell.bottom, title_cell.right, split)
        name_size = _name_size(sheet_name, lower)
        if not _fits(values["title"], title_cell.top - split):
            # a long title takes the room the document's name does not need
            room = lower.width - 2 * tb.block_padding
            lines = len(let.wrap(sheet_name, name_size, room))
            split = title_cell.bottom + let.block_height(lines, name_size) + 2 * pad + 1.0
            lower = Rect.from_bounds(title_cell.left, title_cell.bottom, title_cell.right, split)
        upper = Rect.from_bounds(title_cell.left, split, title_cell.right, title_cell.top)
        block_text("title", values["title"], tb.title, upper)
        block_text("title", sheet_name, name_size, lower)
    elif "title" in values or sheet_name:
        block_text("title", values.get("title") or sheet_name, tb.title)
    designation = values.get("drawing_number") or _designation(values)
    if designation:
        one_line("designation", designation, tb.designation, "center")
    if "material" in values:
        block_text("material", values["material"], tb.field)
    first = values.get("organisation") or values.get("school")
    first = first or str(catalogue(lang).words("title_block")["organisation_default"])
    organisation = "\n".join(v for v in (first, values.get("group")) if v)
    block_text("organisation", organisation, tb.organisation)
    for key in ("author", "checked_by", "tech_control", "norm_control", "approved_by"):
        if key in values:
            one_line(FIELDS[key], values[key], tb.field, "left")
    for key in ("date", "checked_date", "mass", "scale", "letter"):
        if key in values:
            one_line(FIELDS[key], values[key], tb.field, "center")
    return out


# --- drawing --------------------------------------------------------------------


def draw_frame(backend: Backend, page: Page) -> None:
    """The frame, a main line at the margins."""
    f = page.frame
    with backend.group("frame", "frame"):
        backend.rectangle((f.x, f.y), f.width, f.height, "main")


def draw_title_block(
    backend: Backend,
    page: Page,
    fields: Mapping[str, Any] | None = None,
    lang: Language = "uk",
) -> TitleBlock:
    """The main inscription, its lines and every caption and field text."""
    block = page.title_block
    tb = load_title_block_look()
    texts = title_block_texts(block, fields or {}, lang, look=backend.look, tb_look=tb)
    with backend.group("title-block", "title-block"):
        for start, end in block.lines("thin"):
            backend.line(start, end, "thin")
        for start, end in block.lines("main"):
            backend.line(start, end, "main")
        for t in texts:
            backend.text(
                t.pos, t.content, t.size, anchor=t.anchor, valign="middle", max_width=t.max_width
            )
    return block


def draw_page(
    backend: Backend,
    page: Page,
    fields: Mapping[str, Any] | None = None,
    lang: Language = "uk",
) -> TitleBlock:
    """Frame and filled main inscription of one sheet."""
    draw_frame(backend, page)
    return draw_title_block(backend, page, fields, lang)
