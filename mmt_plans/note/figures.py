"""The note's figures: the sheets' own drawings, replayed onto the A4 page.

A figure of the calculation is one or more drawings of the composed sheets
(sheets.compose.ComposedSheets): the recorded calls of a drawing's group
("velocity-plan-2", "group-4-5", "force-polygon-4-5", "zhukovsky-lever" ...)
cropped to their bounding box, scaled by one factor to the page's text width
(never enlarged) and replayed through the same drawing interface. There is no
second drawing code: what the note shows is what the sheet draws.

"scheme" is the kinematic scheme of the mechanism at position 0 as
sheets/schematic.py draws it (the task sheet's figure); "structure" the
structural scheme (seed 003 Fig. 1b): the driving link and each Assur group
apart, drawn by sheet 2's own link drawing; "gears" the gear train's scheme
(drawing/gears_scheme.py).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Literal

from ..drawing.page import Rect
from ..i18n import check_language
from ..render.backend import Backend
from ..render.recording import (
    Arc,
    Arrow,
    BeginGroup,
    Call,
    Circle,
    EndGroup,
    Line,
    Polygon,
    Polyline,
    Text,
)

if TYPE_CHECKING:  # pragma: no cover
    from ..drawing.sketch import Sketch

if TYPE_CHECKING:  # pragma: no cover
    from ..sheets.compose import ComposedSheets
    from ..solution import Solution

__all__ = [
    "FigurePart",
    "FigureSpec",
    "figure_drawers",
    "figure_height",
    "replay_scaled",
    "gear_sketch",
    "structure_sketches",
    "sketches_height",
]

Drawer = Callable[[Backend, Rect, str], None]
Arrangement = Literal["row", "column"]

GAP = 8.0  # between the parts of a figure, mm
PART_LABEL = 2.8  # the height of a part's letter "a)" under it, mm
MAX_HEIGHT = 190.0  # the tallest a figure is set on an A4 page, mm
# capital heights of the sheets' drawings are 2.5-5 mm: a part smaller than this
# share of the sheet is turned round (a row → a column) if that draws it larger
MIN_SCALE = 0.55


@dataclass(frozen=True)
class FigurePart:
    """One drawing of a sheet: the groups `groups` of sheet `sheet` (their
    union), lettered `label` ("a)") under it when the figure has parts."""

    sheet: int
    groups: tuple[str, ...]
    label: str = ""


@dataclass(frozen=True)
class FigureSpec:
    """A figure: its parts, side by side or one above the other."""

    key: str
    parts: tuple[FigurePart, ...]
    # each part's bounds on its sheet (bounds()), measured once when the figure
    # is chosen: the layout and the drawing ask again
    boxes: tuple[tuple[float, float, float, float], ...] = ()
    # a figure of the note's own drawing (no parts): its sketches, named, as
    # the text measured them ("structure": structure_sketches), drawn as they are
    sketches: tuple[tuple[str, Sketch], ...] = ()


def _calls(composed: ComposedSheets, part: FigurePart) -> tuple[Call, ...]:
    sheet = composed.sheet(part.sheet)
    out: list[Call] = []
    for g in part.groups:
        out += sheet.group(g)
    return tuple(out)


def _text_box(
    c: Text, width_of: Callable[[str, float, float | None], float]
) -> list[tuple[float, float]]:
    x, y = c.pos
    size = c.size
    w = width_of(c.content, size, c.max_width)
    x0 = {"left": 0.0, "center": -w / 2, "right": -w}[c.anchor]
    y0 = {"baseline": 0.0, "middle": -size / 2, "top": -size}[c.valign]
    a = math.radians(c.rotation)
    ca, sa = math.cos(a), math.sin(a)
    corners = [
        (x0, y0 - 0.3 * size),
        (x0 + w, y0 - 0.3 * size),
        (x0, y0 + size),
        (x0 + w, y0 + size),
    ]
    return [(x + u * ca - v * sa, y + u * sa + v * ca) for u, v in corners]


def bounds(composed: ComposedSheets, part: FigurePart) -> tuple[float, float, float, float]:
    """(xmin, ymin, xmax, ymax) of a part's calls on its sheet, text included, mm."""
    look = composed.sheet(part.sheet).look
    xs: list[float] = []
    ys: list[float] = []
    for c in _calls(composed, part):
        if isinstance(c, Text):
            pts = _text_box(c, look.lettering.width)
        elif isinstance(c, Arrow):
            pts = [c.start, c.end]
        else:
            pts = c.points()
        for x, y in pts:
            xs.append(x)
            ys.append(y)
    if not xs:
        return (0.0, 0.0, 1.0, 1.0)
    return (min(xs), min(ys), max(xs), max(ys))


def _arrangement(
    composed: ComposedSheets, spec: FigureSpec, width: float
) -> tuple[Arrangement, float, list[tuple[float, float, float, float]]]:
    """How the parts go (a row or a column), the one scale factor that fits
    them into `width` mm and MAX_HEIGHT, and each part's bounds."""
    boxes = list(spec.boxes) or [bounds(composed, p) for p in spec.parts]
    ws = [b[2] - b[0] for b in boxes]
    hs = [b[3] - b[1] for b in boxes]
    n = len(boxes)
    label = PART_LABEL + 2.0 if n > 1 else 0.0
    row = min(
        1.0,
        (width - GAP * (n - 1)) / max(sum(ws), 1e-9),
        (MAX_HEIGHT - label) / max(max(hs), 1e-9),
    )
    column = min(
        1.0,
        width / max(max(ws), 1e-9),
        (MAX_HEIGHT - (GAP + label) * (n - 1) - label) / max(sum(hs), 1e-9),
    )
    if n > 1 and row < MIN_SCALE and column > row:
        return "column", column, boxes
    return "row", row, boxes


def figure_height(composed: ComposedSheets, spec: FigureSpec, width: float) -> float:
    """The height (mm) the figure takes set `width` mm wide."""
    how, k, boxes = _arrangement(composed, spec, width)
    n = len(boxes)
    label = PART_LABEL + 2.0 if n > 1 else 0.0
    hs = [(b[3] - b[1]) * k for b in boxes]
    if how == "row":
        return max(hs) + label
    return sum(hs) + n * label + GAP * (n - 1)


def replay_scaled(calls: Sequence[Call], backend: Backend, k: float, dx: float, dy: float) -> None:
    """Draw `calls` again on `backend`, every length times `k`, then shifted
    by (dx, dy): x' = k·x + dx. Line types stay those of the page's look."""

    def t(p: Sequence[float]) -> tuple[float, float]:
        return (k * p[0] + dx, k * p[1] + dy)

    for c in calls:
        if isinstance(c, Line):
            backend.line(t(c.start), t(c.end), c.line)
        elif isinstance(c, Text):
            backend.text(
                t(c.pos),
                c.content,
                k * c.size,
                anchor=c.anchor,
                valign=c.valign,
                rotation=c.rotation,
                max_width=None if c.max_width is None else k * c.max_width,
            )
        elif isinstance(c, Polygon):
            backend.polygon([t(p) for p in c.vertices], c.line, c.fill)
        elif isinstance(c, Polyline):
            backend.polyline([t(p) for p in c.vertices], c.line)
        elif isinstance(c, Circle):
            backend.circle(t(c.center), k * c.radius, c.line, c.fill)
        elif isinstance(c, Arc):
            backend.arc(t(c.center), k * c.radius, c.start_deg, c.end_deg, c.line)
        elif isinstance(c, Arrow):
            backend.arrow(
                t(c.start),
                t(c.end),
                c.line,
                head_length=k * c.head_length,
                head_width=k * c.head_width,
            )
        elif isinstance(c, (BeginGroup, EndGroup)):
            continue
        else:  # pragma: no cover - a new primitive must be added here
            raise ValueError(f"cannot replay {c.name!r}")


def draw_figure(composed: ComposedSheets, spec: FigureSpec, backend: Backend, rect: Rect) -> None:
    """The figure's parts in `rect`: scaled by one factor, centred, each
    lettered under it when there are several. A part keeps its sheet's
    lettering: its runs of text (a name and its index) stand where the
    sheet's letter widths put them, and in another font they would part."""
    how, k, boxes = _arrangement(composed, spec, rect.width)
    n = len(boxes)
    label = PART_LABEL + 2.0 if n > 1 else 0.0
    ws = [(b[2] - b[0]) * k for b in boxes]
    hs = [(b[3] - b[1]) * k for b in boxes]
    # the layout may have set the figure less tall than asked: shrink to it
    natural = figure_height(composed, spec, rect.width)
    if natural > rect.height + 1e-6:
        f = max((rect.height - n * label) / max(natural - n * label, 1e-9), 0.1)
        k *= f
        ws, hs = [w * f for w in ws], [h * f for h in hs]
    size = 2.8
    if how == "row":
        total = sum(ws) + GAP * (n - 1)
        x = rect.x + (rect.width - total) / 2
        top = rect.top
        for part, box, w, h in zip(spec.parts, boxes, ws, hs):
            y0 = top - max(hs) + (max(hs) - h) / 2
            with backend.lettered_as(composed.sheet(part.sheet).look.lettering):
                replay_scaled(_calls(composed, part), backend, k, x - k * box[0], y0 - k * box[1])
            if n > 1:
                backend.text(
                    (x + w / 2, top - max(hs) - label + 0.5), part.label, size, anchor="center"
                )
            x += w + GAP
    else:
        y = rect.top
        for part, box, w, h in zip(spec.parts, boxes, ws, hs):
            x0 = rect.x + (rect.width - w) / 2
            with backend.lettered_as(composed.sheet(part.sheet).look.lettering):
                replay_scaled(
                    _calls(composed, part), backend, k, x0 - k * box[0], y - h - k * box[1]
                )
            y -= h + label
            if n > 1:
                backend.text((rect.x + rect.width / 2, y + 0.5), part.label, size, anchor="center")
            y -= GAP


def _scheme(solution: Solution, backend: Backend, rect: Rect, lang: str) -> None:
    from ..sheets.schematic import sketch_schematic

    sketch = sketch_schematic(
        solution, backend.look, check_language(lang), width_mm=rect.width, height_mm=rect.height
    )
    sketch.replay(backend, rect.x, rect.y)


def gear_sketch(solution: Solution) -> Sketch | None:
    """The gear train's scheme in the note's lettering, None without [gears]."""
    train = solution.mechanism.drive.gear_train
    if train is None:
        return None
    from ..drawing.gears_scheme import sketch_gear_train
    from ..render.look import note_look

    return sketch_gear_train(train, note_look())


def structure_sketches(solution: Solution) -> list[tuple[str, Sketch]] | None:
    """The structural scheme at position 0: the driving link with the frame,
    then each Assur group in the order attached, as sheet 2 draws links (at
    the calculation's μ_l); (its structural name "I(0,1)", "II(2,3)", sketch)
    each; None where position 0 does not assemble."""
    from ..errors import MmtError
    from ..render.look import note_look
    from ..sheets.sheet2 import _Drawing

    try:
        state = solution.state(solution.positions[0].index or 0)
    except MmtError:
        return None
    st = solution.structure
    parts: list[tuple[str, tuple[int, ...]]] = [(f"I(0,{st.driver})", (st.driver,))]
    parts += [(g.label, tuple(g.links)) for g in st.groups]
    out: list[tuple[str, Sketch]] = []
    for name, links in parts:
        d = _Drawing(note_look(), state, float(solution.mu_l))
        d.links(links, frame=True)
        d.labels.write_later()
        out.append((name, d.sk))
    return out


PER_ROW = 4  # parts of a figure of the note's own drawings side by side, at most


def _rows(sketches: Sequence[Sketch], width: float) -> tuple[float, list[list[Rect]]]:
    """The sketches' extents in rows of at most PER_ROW, and one factor
    (never enlarging) that fits every row into `width` mm and the figure
    into MAX_HEIGHT."""
    exts = [sk.extent() for sk in sketches]
    rows = [exts[i : i + PER_ROW] for i in range(0, len(exts), PER_ROW)]
    k = 1.0
    for row in rows:
        gaps = GAP * (len(row) - 1)
        k = min(k, (width - gaps) / max(sum(e.width for e in row), 1e-9))
    tall = sum(max(e.height for e in row) for row in rows)
    return min(k, (MAX_HEIGHT / 2) / max(tall, 1e-9)), rows


def sketches_height(sketches: Sequence[Sketch], width: float, labelled: bool) -> float:
    """The height (mm) of `sketches` set in rows `width` mm wide."""
    k, rows = _rows(sketches, width)
    label = PART_LABEL + 2.0 if labelled else 0.0
    return sum(k * max(e.height for e in row) + label for row in rows) + GAP * (len(rows) - 1)


def draw_row(
    sketches: Sequence[Sketch], labels: Sequence[str], backend: Backend, rect: Rect
) -> None:
    """`sketches` side by side in `rect` (in rows of at most PER_ROW), at one
    factor, each named under it."""
    k, rows = _rows(sketches, rect.width)
    label = PART_LABEL + 2.0 if any(labels) else 0.0
    natural = sketches_height(sketches, rect.width, bool(label))
    if natural > rect.height + 1e-6:
        fixed = len(rows) * label + GAP * (len(rows) - 1)
        k *= max((rect.height - fixed) / max(natural - fixed, 1e-9), 0.1)
    top = rect.top
    i = 0
    for row in rows:
        ws = [k * e.width for e in row]
        hs = [k * e.height for e in row]
        x = rect.x + (rect.width - sum(ws) - GAP * (len(ws) - 1)) / 2
        for e, w, h in zip(row, ws, hs):
            y0 = top - max(hs) + (max(hs) - h) / 2
            replay_scaled(sketches[i].calls, backend, k, x - k * e.x, y0 - k * e.y)
            if labels[i]:
                bottom = top - max(hs) - label + 0.5
                backend.text((x + w / 2, bottom), labels[i], 2.8, anchor="center")
            x += w + GAP
            i += 1
        top -= max(hs) + label + GAP


def figure_drawers(
    solution: Solution,
    composed: ComposedSheets | None = None,
    specs: Mapping[str, FigureSpec] | None = None,
) -> dict[str, Drawer]:
    """Key of a figure block → what draws it into its rectangle: "scheme",
    and every figure of `specs` from the composed sheets."""
    out: dict[str, Drawer] = {
        "scheme": lambda backend, rect, lang: _scheme(solution, backend, rect, lang)
    }
    gears = gear_sketch(solution)
    if gears is not None:
        out["gears"] = lambda backend, rect, lang: draw_row([gears], [""], backend, rect)
    structure: Sequence[tuple[str, Sketch]] | None = None
    if "structure" in (specs or {}):  # as the text sketched them, else sketched now
        structure = (specs or {})["structure"].sketches or structure_sketches(solution)
    if structure is not None:
        names = [name for name, _ in structure]
        sketches = [sk for _, sk in structure]
        out["structure"] = lambda backend, rect, lang: draw_row(sketches, names, backend, rect)
    if composed is not None:
        for key, spec in (specs or {}).items():
            if not spec.parts:  # a figure of the note's own drawing (above)
                continue
            out[key] = lambda backend, rect, lang, spec=spec: draw_figure(  # type: ignore[misc]
                composed, spec, backend, rect
            )
    return out
