"""Several SVG pages as one PDF through cairosvg, without another dependency.

cairosvg converts one SVG document to one page: its `Surface` creates the
Cairo surface in `_create_surface` and draws the tree into it. A subclass of
its `PDFSurface` that hands out one shared `cairocffi.PDFSurface` instead
draws every page into the same PDF document; `show_page()` ends each page
(cairo's multi-page PDF), `set_size()` sizes the next one.

The document is written to a temporary file renamed onto the target when
complete (files.atomic_path), and its creation and modification dates are
files.document_date() (SOURCE_DATE_EPOCH, else a fixed date) rather than
the clock, so that the same pages give the same bytes. The sheets' PDFs
(render/export.svg_to_pdf) are written here too, as one-page documents.
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import Iterable

__all__ = ["svgs_to_pdf"]


def svgs_to_pdf(svgs: Iterable[str], target: str | os.PathLike[str]) -> Path:
    """Write the SVG documents `svgs` (text) as the pages of one vector PDF."""
    import cairocffi
    from cairosvg.parser import Tree
    from cairosvg.surface import PDFSurface

    from ..files import atomic_path, document_date
    from ..render.export import prefer_installed_font

    target = Path(target)
    with atomic_path(target) as tmp:
        document = cairocffi.PDFSurface(str(tmp), 1, 1)
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
    return target
