"""The A4 calculation and explanatory note (seed 003 §III-§IV; seed 002's way
of writing each step: formula = numbers = result).

    >>> import mmt_plans
    >>> from mmt_plans.note import note_content, write_note
    >>> a = mmt_plans.solve(mmt_plans.load("samples/six_link_press.toml"))
    >>> note_content(a).steps[:3]
    ['sheet1', '1.1', '1.2']
    >>> write_note(a, "out/note.pdf", lang="uk")          # doctest: +SKIP

`content` writes the calculation's blocks from the solver's data, `front`
the title page, task sheet, abstract, contents and references around them
(`note_document`), `pages` sets them on A4 pages through the drawing
interface (two passes: the contents and the abstract quote the first pass's
pages and counts); `write_note` draws them straight onto the pages of one
Cairo PDF (`pdf.PdfDocument`: no recording to replay), `draw_note` onto any
backend (a RecordingBackend for tests and `note_svgs`).
"""

from __future__ import annotations

import os
from dataclasses import dataclass, replace
from pathlib import Path
from typing import TYPE_CHECKING, Any

from ..i18n import Language, check_language
from ..render.output import render
from ..render.recording import RecordingBackend
from .content import Block, NoteContent, note_content, number, plain
from .front import (
    Counts,
    abstract,
    contents,
    reference_items,
    references,
    stamp_fields,
    task_sheet,
    title_info,
    title_page,
)
from .pages import (
    FORM5,
    NotePage,
    Stamp,
    draw_note_page,
    heading_pages,
    layout_note,
    note_look,
    note_page,
)

if TYPE_CHECKING:  # pragma: no cover
    from ..sheets.compose import ComposedSheets
    from ..solution import Solution

__all__ = [
    "Block",
    "NoteContent",
    "NotePage",
    "NoteDocument",
    "draw_note",
    "layout_note",
    "note_content",
    "note_document",
    "note_form",
    "note_pdf",
    "note_svgs",
    "number",
    "plain",
    "write_note",
]


@dataclass(frozen=True)
class NoteDocument:
    """The whole note: its blocks, its pages, and what the abstract counts."""

    content: NoteContent
    pages: tuple[NotePage, ...]
    counts: Counts
    stamp: Stamp
    # the sheets the note's scales and figures are read from (sheets.compose)
    composed: ComposedSheets | None = None


def _count(content: NoteContent, pages: int, refs: int) -> Counts:
    return Counts(
        pages=pages,
        figures=sum(b.kind == "figure" for b in content.blocks),
        tables=sum(b.kind == "table" for b in content.blocks),
        references=refs,
    )


NOTE_FORMS = ("2", "5")


def note_form(analysis: Solution, form: str | None = None) -> str:
    """The forms of the note's pages: "2" (GOST 2.104 forms 2 and 2a, seed
    003) or "5" (GOST 2.106 forms 5 and 5a, seed 002); `form`, else the
    file's [sheet] note_form, else "2"."""
    mech = analysis.mechanism
    chosen = form or str(dict(mech.sheet or {}).get("note_form", "") or "2")
    if chosen not in NOTE_FORMS:
        from ..errors import SpecError

        raise SpecError(
            mech.path,
            "[sheet] note_form",
            f"{chosen!r} is not a form of the note",
            'write note_form = "2" (forms 2 and 2a, GOST 2.104) or "5" (forms 5 and 5a, GOST 2.106)',
        )
    return chosen


def note_document(
    analysis: Solution,
    lang: Language = "en",
    form: str | None = None,
    composed: ComposedSheets | None = None,
) -> NoteDocument:
    """The note with its front and back matter, laid out: title page, task
    sheet, abstract (form 2 or 5), contents, the calculation, references;
    `form` as note_form() chooses; `composed` the sheets of `analysis` in
    `lang` (sheets.compose.compose; composed here when not given)."""
    check_language(lang)
    chosen = note_form(analysis, form)
    if composed is None:
        from ..sheets.compose import compose

        composed = compose(analysis, lang)
    written = note_content(analysis, lang, composed)
    # the title page names the document: the calculation starts at its first section
    body = NoteContent(
        written.title,
        lang,
        tuple(b for b in written.blocks if b.kind != "title"),
        figures=written.figures,
    )
    info = title_info(analysis, lang)
    back = references(lang)
    refs = len(reference_items(lang))
    toc: dict[str, int] = {}
    counts = Counts()
    doc = body
    pages: list[NotePage] = []
    for _ in range(5):  # the contents and the abstract quote the last pass
        blocks = [
            *title_page(info, lang),
            *task_sheet(analysis, info, lang),
            *abstract(analysis, info, counts, lang),
            *contents([*body.blocks, *back], lang),
            Block("pagebreak", "2a"),
            *body.blocks,
            *back,
        ]
        doc = NoteContent(body.title, lang, tuple(blocks), figures=body.figures)
        pages = layout_note(doc, first_form="none", toc=toc)
        new_toc = heading_pages(pages)
        new_counts = _count(doc, len(pages), refs)
        if new_toc == toc and new_counts == counts:
            break
        toc, counts = new_toc, new_counts
    if chosen == "5":
        pages = [replace(p, form=FORM5.get(p.form, p.form)) for p in pages]  # type: ignore[arg-type]
    s = stamp_fields(info, lang)
    stamp = Stamp(pages=len(pages), **s)
    return NoteDocument(doc, tuple(pages), counts, stamp, composed)


def draw_note(
    analysis: Solution,
    backend_factory: Any,
    lang: Language = "en",
    form: str | None = None,
    composed: ComposedSheets | None = None,
) -> list[Any]:
    """Draw every page of the note on a new backend from `backend_factory(width,
    height, title)`; returns the backends (SvgBackend, RecordingBackend ...).
    The pages are drawn in the note's look (templates/note_look.toml)."""
    from .figures import figure_drawers

    document = note_document(analysis, lang, form, composed)
    page = note_page()
    look = note_look()
    figures = figure_drawers(analysis, document.composed, document.content.figures)
    backends = []
    for p in document.pages:
        backend = backend_factory(
            page.width, page.height, f"{document.content.title}, page {p.number}"
        )
        backend.look = look
        draw_note_page(
            backend,
            p,
            len(document.pages),
            document.content,
            analysis.mechanism,
            page,
            stamp=document.stamp,
            figures=figures,
        )
        backends.append(backend)
    return backends


def note_svgs(
    analysis: Solution,
    lang: Language = "en",
    form: str | None = None,
    composed: ComposedSheets | None = None,
) -> list[str]:
    """The pages of the note as SVG documents (render's factory by format)."""
    titles: list[str] = []

    def factory(width: float, height: float, title: str) -> RecordingBackend:
        titles.append(title)
        return RecordingBackend(width, height, note_look())

    pages = draw_note(analysis, factory, lang, form, composed)
    return [render(page, "svg", title).decode("utf-8") for page, title in zip(pages, titles)]


def write_note(
    analysis: Solution,
    target: str | os.PathLike[str],
    lang: Language = "en",
    form: str | None = None,
    composed: ComposedSheets | None = None,
) -> Path:
    """Write the note as one multi-page A4 PDF at `target` (atomically, with
    fixed dates: note/pdf.py), in forms 2/2a or 5/5a (note_form), from the
    sheets `composed` (composed here when not given)."""
    from ..files import write_bytes_atomic

    return write_bytes_atomic(Path(target), note_pdf(analysis, lang, form, composed))


def note_pdf(
    analysis: Solution,
    lang: Language = "en",
    form: str | None = None,
    composed: ComposedSheets | None = None,
) -> bytes:
    """The bytes write_note writes."""
    from ..forked import fewer_collections
    from .pdf import PdfDocument

    # drawn straight onto the PDF's pages: the same calls a recording of the
    # pages would replay there (pages_to_pdf), without recording them first
    look = note_look()
    document = PdfDocument()
    try:
        with fewer_collections():  # (its pages make many short-lived containers)
            draw_note(analysis, lambda w, h, title: document.page(w, h, look), lang, form, composed)
            return document.finish()
    finally:
        document.close()
