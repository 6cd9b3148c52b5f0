"""SVG to PDF (vector) and PNG through cairosvg.

cairosvg (and Cairo under it) is imported inside the functions, so that the
rest of mmt_plans works on a machine without Cairo. Pages are rendered in
memory and written atomically (files.write_bytes_atomic); a PDF goes through note/pdf.py's writer,
which fixes the document's dates, so that two runs give the same bytes.
"""

from __future__ import annotations

import functools
import io
import os
import re
import shutil
import subprocess
from collections.abc import Iterable
from pathlib import Path
from typing import Any

__all__ = [
    "svg_to_pdf",
    "svg_to_png",
    "svg_to_pdf_bytes",
    "svg_to_png_bytes",
    "svgs_to_pdf",
    "installed_families",
    "prefer_installed_font",
]

SvgSource = str | bytes | os.PathLike[str]

_FONT_FAMILY = re.compile(r'font-family="([^"]*)"')


@functools.cache
@functools.cache
def installed_families() -> frozenset[str] | None:
    """Font families fontconfig knows (lower case), or None without fc-list;
    asked once a process (fc-list takes ~50 ms; every PNG and each lettering
    of a PDF asks)."""
    fc_list = shutil.which("fc-list")
    if fc_list is None:
        return None
    try:
        out = subprocess.run(
            [fc_list, ":", "family"], capture_output=True, text=True, check=True, timeout=30
        ).stdout
    except (OSError, subprocess.SubprocessError):
        return None
    families: set[str] = set()
    for line in out.splitlines():
        families.update(name.strip().lower() for name in line.split(",") if name.strip())
    return frozenset(families)


def prefer_installed_font(svg: str) -> str:
    """Move the first installed family of every font-family list to its front.

    cairosvg looks at the first family only and lets fontconfig substitute
    any font for it when it is missing, so an SVG asking for "osifont,
    'DejaVu Sans Condensed'" on a machine without osifont would not get the
    fallback we chose. Browsers read the whole list, so the SVG file itself
    keeps it as written.
    """
    installed = installed_families()
    if installed is None:
        return svg

    def reorder(match: re.Match[str]) -> str:
        names = [n.strip() for n in match.group(1).split(",") if n.strip()]
        for i, name in enumerate(names):
            if name.strip("'\"").lower() in installed:
                names.insert(0, names.pop(i))
                break
        return 'font-family="' + ", ".join(names) + '"'

    return _FONT_FAMILY.sub(reorder, svg)


def _svg_bytes(svg: SvgSource) -> bytes:
    if isinstance(svg, bytes):
        text = svg.decode("utf-8")
    elif isinstance(svg, str):
        text = svg
    else:
        text = Path(svg).read_text(encoding="utf-8")
    return prefer_installed_font(text).encode("utf-8")


def svg_to_pdf(svg: SvgSource, target: str | os.PathLike[str]) -> Path:
    """Write a vector PDF of the page. `svg` is SVG text (str/bytes) or a file path."""
    return svgs_to_pdf([_svg_bytes(svg).decode("utf-8")], target)


def svg_to_png(svg: SvgSource, target: str | os.PathLike[str], dpi: float = 96.0) -> Path:
    """Write a PNG of the page at `dpi` (the SVG is sized in mm, so dpi sets pixels)."""
    from ..files import write_bytes_atomic

    return write_bytes_atomic(Path(target), svg_to_png_bytes(svg, dpi))


def svg_to_pdf_bytes(svg: SvgSource) -> bytes:
    """A vector PDF of the page, as bytes (the same bytes svg_to_pdf writes)."""
    out = io.BytesIO()
    _pdf([_svg_bytes(svg).decode("utf-8")], out)
    return out.getvalue()


def svg_to_png_bytes(svg: SvgSource, dpi: float = 96.0) -> bytes:
    """A PNG of the page at `dpi`, as bytes."""
    from .cairo_lib import import_cairo

    import_cairo()  # before cairosvg imports it: without the library search
    import cairosvg

    return cairosvg.svg2png(bytestring=_svg_bytes(svg), dpi=dpi)


def svgs_to_pdf(svgs: Iterable[str], target: str | os.PathLike[str]) -> Path:
    """Write the SVG documents `svgs` (text) as the pages of one vector PDF,
    atomically (files.write_bytes_atomic).

    Cairo renders into memory and our own write puts the bytes on the disk:
    a full or read-only disk is then an OSError with its errno, said in words,
    not Cairo's bare status code ("cannot be written: 11")."""
    from ..files import write_bytes_atomic

    out = io.BytesIO()
    _pdf(svgs, out)
    return write_bytes_atomic(Path(target), out.getvalue())


def _pdf(svgs: Iterable[str], target: Any) -> None:
    """The pages into one PDF at `target` (a file name or a binary file object).

    cairosvg converts one SVG document to one page: its `Surface` creates the
    Cairo surface in `_create_surface` and draws the tree into it. A subclass
    of its `PDFSurface` that hands out one shared `cairocffi.PDFSurface`
    instead draws every page into the same PDF document; `show_page()` ends
    each page, `set_size()` sizes the next one. The creation and modification
    dates are files.document_date() (SOURCE_DATE_EPOCH, else a fixed date),
    not the clock, so the same pages give the same bytes."""
    from .cairo_lib import import_cairo

    cairocffi = import_cairo()
    from cairosvg.parser import Tree
    from cairosvg.surface import PDFSurface

    from ..files import document_date

    document = cairocffi.PDFSurface(target, 1, 1)
    date = document_date()
    for key in (cairocffi.PDF_METADATA_CREATE_DATE, cairocffi.PDF_METADATA_MOD_DATE):
        document.set_metadata(key, date)

    class PageOfDocument(PDFSurface):
        def _create_surface(self, width: float, height: float):
            document.set_size(width, height)
            return document, width, height

    pages = 0
    try:
        for svg in svgs:
            tree = Tree(bytestring=prefer_installed_font(svg).encode("utf-8"))
            PageOfDocument(tree, None, 96)
            document.show_page()
            pages += 1
        if pages == 0:
            raise ValueError("a PDF needs at least one page")
    finally:
        document.finish()
