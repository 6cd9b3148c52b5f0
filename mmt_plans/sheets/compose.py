"""Writing the A1 sheets of an analysis to files: SVG, and PDF/PNG through Cairo.

Each file is written atomically (files.py): an interrupted run leaves no
half-written sheet. PDFs carry a fixed date (files.document_date), so two
runs give the same bytes."""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any, Callable, Iterable, Sequence

from ..errors import MmtError
from ..files import ensure_dir, write_text_atomic
from ..render.svg import SvgBackend
from .page import Language, Page

__all__ = ["FORMATS", "SheetNotAvailable", "available_sheets", "write_sheets"]

FORMATS = ("svg", "pdf", "png")


class SheetNotAvailable(MmtError, ValueError):
    """A sheet this version cannot compose yet."""


def available_sheets() -> dict[int, Callable[..., Any]]:
    """Sheet number → compose function, for the sheets this package can draw."""
    from .sheet1 import compose_sheet1

    sheets: dict[int, Callable[..., Any]] = {1: compose_sheet1}
    try:
        from .sheet2 import compose_sheet2  # type: ignore[import-not-found]
    except ImportError:
        pass
    else:
        sheets[2] = compose_sheet2
    return sheets


def write_sheets(
    analysis: Any,
    out_dir: str | os.PathLike[str],
    formats: Sequence[str] = FORMATS,
    lang: Language = "en",
    sheets: Iterable[int] = (1,),
) -> list[Path]:
    """Compose each sheet and write sheet<N>.<format> into out_dir; returns the paths."""
    formats = tuple(formats)
    unknown = [f for f in formats if f not in FORMATS]
    if unknown:
        raise ValueError(f"unknown format {', '.join(unknown)}; expected some of {', '.join(FORMATS)}")
    composers = available_sheets()
    wanted = list(sheets)
    missing = [n for n in wanted if n not in composers]
    if missing:
        raise SheetNotAvailable(
            f"sheet {', '.join(map(str, missing))} cannot be drawn yet; available: "
            f"{', '.join(map(str, sorted(composers)))}"
        )
    out = ensure_dir(out_dir)
    written: list[Path] = []
    page = Page.of("A1")
    for n in wanted:
        backend = SvgBackend(page.width, page.height, title=f"{analysis.mech.title}, sheet {n}")
        composers[n](analysis, backend, lang)
        svg = backend.to_string()
        if "svg" in formats:
            written.append(write_text_atomic(out / f"sheet{n}.svg", svg))
        if "pdf" in formats or "png" in formats:
            # Cairo is imported only when a raster or PDF is asked for.
            from ..render.export import svg_to_pdf, svg_to_png

            if "pdf" in formats:
                written.append(svg_to_pdf(svg, out / f"sheet{n}.pdf"))
            if "png" in formats:
                written.append(svg_to_png(svg, out / f"sheet{n}.png"))
    return written
