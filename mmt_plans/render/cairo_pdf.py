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
in words, never as Cairo's status code.

`PdfDocument` is the one surface, page by page: a document drawn straight
onto its pages (the note) skips the recording; the hot calls (paths,
strokes, texts) go to Cairo's own functions, checked once per primitive,
as cairocffi's methods would make them (the same bytes)."""

from __future__ import annotations

import functools
import math
import os
from collections.abc import Sequence
from pathlib import Path
from typing import Any

from .backend import Backend, Fill, HAlign, PointLike, VAlign, as_point, slant_offsets
from .cairo_lib import import_cairo
from .look import LineType, Look
from .recording import RecordingBackend

__all__ = ["CairoPage", "PdfDocument", "pages_to_pdf", "pages_to_pdf_bytes"]

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
        cairocffi = import_cairo()
        self._cairo = cairocffi
        self.ctx = context
        self.ctx.set_line_cap(cairocffi.LINE_CAP_ROUND)
        self.ctx.set_line_join(cairocffi.LINE_JOIN_ROUND)
        self._lettering_changed()
        # Cairo's own functions on the context, for the calls made thousands
        # of times a page (the same calls cairocffi's methods make)
        self._lib = cairocffi.cairo
        self._ptr = context._pointer
        self._dash_arrays: dict[tuple[float, ...], Any] = {}

    def _lettering_changed(self) -> None:
        let = self.look.lettering
        self.ctx.select_font_face(_family(tuple(let.families)))
        # the lettering's slant, worked out once per lettering rather than per text
        self._lean = math.tan(math.radians(let.slant_deg))
        self._shear = self._cairo.Matrix(1.0, 0.0, math.tan(-math.radians(let.slant_deg)), 1.0)

    def _xy(self, p: PointLike) -> tuple[float, float]:
        x, y = as_point(p)
        return x, self.height - y

    def _checked(self) -> None:
        """Raise Cairo's error, if a call since the last check made one (an
        error stays on the context: one check after a primitive's calls is
        as good as one after each, which cairocffi's methods make)."""
        status = self._lib.cairo_status(self._ptr)
        if status:
            self._cairo._check_status(status)

    def _dashes(self, dash: tuple[float, ...]) -> Any:
        """A line type's dash pattern as Cairo's array, made once per page."""
        found = self._dash_arrays.get(dash)
        if found is None:
            found = self._dash_arrays[dash] = self._cairo.ffi.new("double[]", list(dash))
        return found

    def _path(self, points: Sequence[PointLike], close: bool) -> None:
        pts = [self._xy(p) for p in points]
        lib, ptr = self._lib, self._ptr
        lib.cairo_new_path(ptr)
        lib.cairo_move_to(ptr, *pts[0])
        for x, y in pts[1:]:
            lib.cairo_line_to(ptr, x, y)
        if close:
            lib.cairo_close_path(ptr)

    def _finish(self, line: LineType | None, fill: Fill = "none") -> None:
        lib, ptr = self._lib, self._ptr
        if fill != "none":
            lib.cairo_set_source_rgb(
                ptr, *((0.0, 0.0, 0.0) if fill == "black" else (1.0, 1.0, 1.0))
            )
            if line is None:
                lib.cairo_fill(ptr)
                self._checked()
                return
            lib.cairo_fill_preserve(ptr)
        if line is None:
            lib.cairo_new_path(ptr)
            self._checked()
            return
        style = self.look.line(line)
        dash = tuple(style.dash) if style.dash else ()
        lib.cairo_set_source_rgb(ptr, 0.0, 0.0, 0.0)
        lib.cairo_set_line_width(ptr, style.width)
        lib.cairo_set_dash(ptr, self._dashes(dash), len(dash), 0)
        lib.cairo_stroke(ptr)
        self._checked()

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
        squeeze = 1.0 if max_width is None else let.squeeze(content, size, max_width)
        lean = self._lean
        # as render/svg.py: offsets along and across the baseline (y up)
        along, across = slant_offsets(anchor, valign, size, lean, squeeze)
        x, y = as_point(pos)
        if rotation:
            a = math.radians(rotation)
            ca, sa = math.cos(a), math.sin(a)
        else:  # cos 0 and sin 0, exactly
            a, ca, sa = 0.0, 1.0, 0.0
        bx = x + along * ca - across * sa
        by = y + along * sa + across * ca
        lib, ptr = self._lib, self._ptr
        lib.cairo_save(ptr)
        lib.cairo_translate(ptr, bx, self.height - by)
        if rotation % 360.0:
            lib.cairo_rotate(ptr, -a)
        if squeeze != 1.0:
            lib.cairo_scale(ptr, squeeze, 1.0)
        if let.slant_deg:
            lib.cairo_transform(ptr, self._shear._pointer)
        lib.cairo_set_font_size(ptr, size / let.cap_height)  # let.font_size(size)
        width = self.ctx.text_extents(content)[4] if anchor != "left" else 0.0
        lib.cairo_move_to(
            ptr, 0.0 if anchor == "left" else -width / 2.0 if anchor == "center" else -width, 0.0
        )
        lib.cairo_set_source_rgb(ptr, 0.0, 0.0, 0.0)
        lib.cairo_show_text(ptr, content.encode("utf-8"))  # bytes end in NUL: a C string
        lib.cairo_new_path(ptr)
        lib.cairo_restore(ptr)
        self._checked()

    def _begin_group(self, id: str, cls: str | None) -> None:
        pass

    def _end_group(self) -> None:
        pass


class PdfDocument:
    """One vector PDF made page by page on one Cairo surface: `page(width,
    height, look)` starts a page and gives the backend to draw it through;
    `finish()` the bytes. A document drawn straight onto its pages (the
    note) pays no recording and no replay; `pages_to_pdf_bytes` replays
    recorded pages through it, so both give the same bytes."""

    def __init__(self, title: str | None = None) -> None:
        import io

        from ..files import document_date

        cairocffi = import_cairo()

        self._cairo = cairocffi
        self._buffer = io.BytesIO()
        self._surface = cairocffi.PDFSurface(self._buffer, 1, 1)
        date = document_date()
        for key in (cairocffi.PDF_METADATA_CREATE_DATE, cairocffi.PDF_METADATA_MOD_DATE):
            self._surface.set_metadata(key, date)
        if title:
            self._surface.set_metadata(cairocffi.PDF_METADATA_TITLE, title)
        self._open = False
        self._done = False

    def page(self, width: float, height: float, look: Look) -> CairoPage:
        """A new page of `width` × `height` mm, white, to draw on in `look`."""
        if self._done:
            raise RuntimeError("the PDF is finished")
        if self._open:
            self._surface.show_page()
        self._surface.set_size(width * PT_PER_MM, height * PT_PER_MM)
        ctx = self._cairo.Context(self._surface)
        ctx.scale(PT_PER_MM, PT_PER_MM)
        ctx.set_source_rgb(1.0, 1.0, 1.0)
        ctx.rectangle(0, 0, width, height)
        ctx.fill()
        self._open = True
        return CairoPage(ctx, width, height, look)

    def finish(self) -> bytes:
        """The PDF's bytes (at least one page must have been started)."""
        if not self._done:
            self._done = True
            if self._open:
                self._surface.show_page()
            self._surface.finish()
            if not self._open:
                raise ValueError("a PDF needs at least one page")
        return self._buffer.getvalue()

    def close(self) -> None:
        """Let go of the surface, finished or not (after an error)."""
        if not self._done:
            self._done = True
            self._surface.finish()


def pages_to_pdf_bytes(pages: Sequence[RecordingBackend], title: str | None = None) -> bytes:
    """The recorded pages as the bytes of one vector PDF, a page each."""
    if not pages:
        raise ValueError("a PDF needs at least one page")
    document = PdfDocument(title)
    try:
        for page in pages:
            page.replay(document.page(page.width, page.height, page.look))
        return document.finish()
    finally:
        document.close()


def pages_to_pdf(pages: Sequence[RecordingBackend], target: str | os.PathLike[str]) -> Path:
    """The recorded pages as the pages of one vector PDF at `target` (atomically)."""
    from ..files import write_bytes_atomic

    return write_bytes_atomic(Path(target), pages_to_pdf_bytes(pages))
