"""Several SVG pages as one PDF through cairosvg, without another dependency.

cairosvg converts one SVG document to one page: its `Surface` creates the
Cairo surface in `_create_surface` and draws the tree into it. A subclass of
its `PDFSurface` that hands out one shared `cairocffi.PDFSurface` instead
draws every page into the same PDF document; `show_page()` ends each page
(cairo's multi-page PDF), `set_size()` sizes the next one.
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

    from ..render.export import prefer_installed_font

    target = Path(target)
    document = cairocffi.PDFSurface(str(target), 1, 1)

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
