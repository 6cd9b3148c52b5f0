"""Writing the A1 sheets of an solution to files: SVG, and PDF/PNG through Cairo."""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any, Callable, Iterable, Sequence

from ..drawing.page import Page
from ..errors import MmtError
from ..i18n import Language
from ..render.svg import SvgBackend
from ..solution import Solution

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
    solution: Solution,
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
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    written: list[Path] = []
    page = Page.of("A1")
    for n in wanted:
        backend = SvgBackend(page.width, page.height, title=f"{solution.mechanism.title}, sheet {n}")
        composers[n](solution, backend, lang)
        svg = backend.to_string()
        if "svg" in formats:
            path = out / f"sheet{n}.svg"
            path.write_text(svg, encoding="utf-8")
            written.append(path)
        if "pdf" in formats or "png" in formats:
            # Cairo is imported only when a raster or PDF is asked for.
            from ..render.export import svg_to_pdf, svg_to_png

            if "pdf" in formats:
                written.append(svg_to_pdf(svg, out / f"sheet{n}.pdf"))
            if "png" in formats:
                written.append(svg_to_png(svg, out / f"sheet{n}.png"))
    return written
