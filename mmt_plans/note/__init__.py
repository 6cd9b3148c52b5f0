"""The A4 calculation and explanatory note (seed 003 §IV; seed 002's way of
writing each step: formula = numbers = result).

    >>> import mmt_plans
    >>> from mmt_plans.note import note_content, write_note
    >>> a = mmt_plans.solve(mmt_plans.load("samples/six_link_press.toml"))
    >>> note_content(a).steps[:3]
    ['sheet1', '1.1', '1.2']
    >>> write_note(a, "out/note.pdf", lang="uk")          # doctest: +SKIP

`content` writes the blocks from the solver's data, `pages` sets them on A4
pages through the drawing interface, `pdf` joins the pages' SVG into one PDF.
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import TYPE_CHECKING, Any

from ..i18n import Language
from ..render.output import render
from ..render.recording import RecordingBackend
from .content import Block, NoteContent, note_content, number, plain
from .pages import NotePage, draw_note_page, layout_note, note_page

if TYPE_CHECKING:  # pragma: no cover
    from ..solution import Solution

__all__ = [
    "Block",
    "NoteContent",
    "NotePage",
    "draw_note",
    "layout_note",
    "note_content",
    "note_svgs",
    "number",
    "plain",
    "write_note",
]


def draw_note(analysis: Solution, backend_factory: Any, lang: Language = "en") -> list[Any]:
    """Draw every page of the note on a new backend from `backend_factory(width,
    height, title)`; returns the backends (SvgBackend, RecordingBackend ...)."""
    content = note_content(analysis, lang)
    page = note_page()
    look = None
    backends = []
    pages = None
    for i in range(10**6):
        backend = backend_factory(page.width, page.height, f"{content.title}, page {i + 1}")
        if pages is None:
            look = backend.look
            pages = layout_note(content, look, page)
        draw_note_page(backend, pages[i], len(pages), content, analysis.mechanism, page)
        backends.append(backend)
        if i + 1 == len(pages):
            break
    return backends


def note_svgs(analysis: Solution, lang: Language = "en") -> list[str]:
    """The pages of the note as SVG documents (render's factory by format)."""
    titles: list[str] = []

    def factory(width: float, height: float, title: str) -> RecordingBackend:
        titles.append(title)
        return RecordingBackend(width, height)

    pages = draw_note(analysis, factory, lang)
    return [render(page, "svg", title).decode("utf-8") for page, title in zip(pages, titles)]


def write_note(analysis: Solution, target: str | os.PathLike[str], lang: Language = "en") -> Path:
    """Write the note as one multi-page A4 PDF at `target` (atomically, with
    fixed dates: note/pdf.py)."""
    from .pdf import svgs_to_pdf

    return svgs_to_pdf(note_svgs(analysis, lang), Path(target))
