"""Recorded pages as one vector PDF, drawn straight onto a Cairo PDF surface.

The pages are recorded once (render.recording.RecordingBackend) and replayed
here through the drawing interface onto one `cairocffi.PDFSurface`, a page
each: the same calls the SVG renderer gets, with the same line widths,
dashes, arrow heads and text placement (render/svg.py), but a text call is
one `show_text` instead of cairosvg's glyph-by-glyph layout of an SVG
document, which made the PDF most of a sheet's and the note's cost. The
creation and modification dates are files.document_date(), so the same
pages give the same bytes. The PDF is made in memory and written by
files.write_bytes_atomic, so a full disk or a read-only folder is reported
in words, never as Cairo's status code."""

from __future__ import annotations

import functools
import math
import os
from collections.abc import Sequence
from pathlib import Path
from typing import Any

from .backend import Backend, Fill, HAlign, PointLike, VAlign, as_point
from .look import LineType, Look
from .recording import RecordingBackend

__all__ = ["CairoPage", "pages_to_pdf", "pages_to_pdf_bytes"]

PT_PER_MM = 72.0 / 25.4


@functools.cache
def _family(families: tuple[str, ...]) -> str:
    """The first of `families` fontconfig knows (the SVG path's choice too)."""
    from .export import installed_families

    installed = installed_families()
    if installed is None:
        return families[0]
    return next((f for f in families if f.lower() in installed), families[0])


class CairoPage(Backend):
    """A drawing backend onto the current page of a Cairo surface: page mm,
    y up, as every backend; lines round-capped and round-joined as the SVG."""

    def __init__(self, context: Any, width: float, height: float, look: Look) -> None:
        super().__init__(width, height, look)
        import cairocffi

        self._cairo = cairocffi
        self.ctx = context
        self.ctx.set_line_cap(cairocffi.LINE_CAP_ROUND)
        self.ctx.set_line_join(cairocffi.LINE_JOIN_ROUND)
        self.ctx.select_font_face(_family(tuple(look.lettering.families)))

    def _xy(self, p: PointLike) -> tuple[float, float]:
        x, y = as_point(p)
        return x, self.height - y

    def _path(self, points: Sequence[PointLike], close: bool) -> None:
        pts = [self._xy(p) for p in points]
        self.ctx.new_path()
        self.ctx.move_to(*pts[0])
        for p in pts[1:]:
            self.ctx.line_to(*p)
        if close:
            self.ctx.close_path()

    def _finish(self, line: LineType | None, fill: Fill = "none") -> None:
        ctx = self.ctx
        if fill != "none":
            ctx.set_source_rgb(*((0.0, 0.0, 0.0) if fill == "black" else (1.0, 1.0, 1.0)))
            if line is None:
                ctx.fill()
                return
            ctx.fill_preserve()
        if line is None:
            ctx.new_path()
            return
        style = self.look.line(line)
        ctx.set_source_rgb(0.0, 0.0, 0.0)
        ctx.set_line_width(style.width)
        ctx.set_dash(list(style.dash) if style.dash else [])
        ctx.stroke()

    def line(self, start: PointLike, end: PointLike, line: LineType = "main") -> None:
        self._path([start, end], False)
        self._finish(line)

    def polyline(self, points: Sequence[PointLike], line: LineType = "main") -> None:
        self._path(points, False)
        self._finish(line)

    def polygon(
        self, points: Sequence[PointLike], line: LineType | None = "main", fill: Fill = "none"
    ) -> None:
        self._path(points, True)
        self._finish(line, fill)

    def circle(
        self, center: PointLike, radius: float, line: LineType | None = "main", fill: Fill = "none"
    ) -> None:
        x, y = self._xy(center)
        self.ctx.new_path()
        self.ctx.arc(x, y, radius, 0.0, 2 * math.pi)
        self.ctx.close_path()
        self._finish(line, fill)

    def arc(
        self,
        center: PointLike,
        radius: float,
        start_deg: float,
        end_deg: float,
        line: LineType = "main",
    ) -> None:
        span = (end_deg - start_deg) % 360.0
        if span == 0.0:
            if end_deg == start_deg:
                return
            span = 360.0
        x, y = self._xy(center)
        self.ctx.new_path()
        # counter-clockwise with y up is a negative angle with Cairo's y down
        a0 = -math.radians(start_deg)
        self.ctx.arc_negative(x, y, radius, a0, a0 - math.radians(span))
        self._finish(line)

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
        let = self.look.lettering
        content = str(content)
        squeeze = let.squeeze(content, size, max_width)
        lean = math.tan(math.radians(let.slant_deg))
        # as render/svg.py: offsets along and across the baseline (y up)
        along = {"left": 0.0, "center": -lean * size / 2.0, "right": -lean * size}[anchor] * squeeze
        across = {"baseline": 0.0, "middle": -size / 2.0, "top": -size}[valign]
        a = math.radians(rotation)
        x, y = as_point(pos)
        bx = x + along * math.cos(a) - across * math.sin(a)
        by = y + along * math.sin(a) + across * math.cos(a)
        ctx = self.ctx
        ctx.save()
        ctx.translate(bx, self.height - by)
        if rotation % 360.0:
            ctx.rotate(-a)
        if squeeze != 1.0:
            ctx.scale(squeeze, 1.0)
        if let.slant_deg:
            ctx.transform(self._cairo.Matrix(1.0, 0.0, math.tan(-math.radians(let.slant_deg)), 1.0))
        ctx.set_font_size(let.font_size(size))
        width = ctx.text_extents(content)[4] if anchor != "left" else 0.0
        ctx.move_to({"left": 0.0, "center": -width / 2.0, "right": -width}[anchor], 0.0)
        ctx.set_source_rgb(0.0, 0.0, 0.0)
        ctx.show_text(content)
        ctx.new_path()
        ctx.restore()

    def _begin_group(self, id: str, cls: str | None) -> None:
        pass

    def _end_group(self) -> None:
        pass


def pages_to_pdf_bytes(pages: Sequence[RecordingBackend], title: str | None = None) -> bytes:
    """The recorded pages as the bytes of one vector PDF, a page each."""
    import io

    import cairocffi

    from ..files import document_date

    if not pages:
        raise ValueError("a PDF needs at least one page")
    buffer = io.BytesIO()
    surface = cairocffi.PDFSurface(buffer, 1, 1)
    date = document_date()
    for key in (cairocffi.PDF_METADATA_CREATE_DATE, cairocffi.PDF_METADATA_MOD_DATE):
        surface.set_metadata(key, date)
    if title:
        surface.set_metadata(cairocffi.PDF_METADATA_TITLE, title)
    try:
        for page in pages:
            surface.set_size(page.width * PT_PER_MM, page.height * PT_PER_MM)
            ctx = cairocffi.Context(surface)
            ctx.scale(PT_PER_MM, PT_PER_MM)
            ctx.set_source_rgb(1.0, 1.0, 1.0)
            ctx.rectangle(0, 0, page.width, page.height)
            ctx.fill()
            page.replay(CairoPage(ctx, page.width, page.height, page.look))
            surface.show_page()
    finally:
        surface.finish()
    return buffer.getvalue()


def pages_to_pdf(pages: Sequence[RecordingBackend], target: str | os.PathLike[str]) -> Path:
    """The recorded pages as the pages of one vector PDF at `target` (atomically)."""
    from ..files import write_bytes_atomic

    return write_bytes_atomic(Path(target), pages_to_pdf_bytes(pages))
