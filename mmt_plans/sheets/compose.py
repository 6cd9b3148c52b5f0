"""Writing the A1 sheets of a Solution to files, in every format of render.output.

Each file is written atomically (files.py): an interrupted run leaves no
half-written sheet. PDFs carry a fixed date, so two runs give the same bytes."""

from __future__ import annotations

import os
import weakref
from collections.abc import Callable, Iterable, Sequence
from pathlib import Path
from typing import Any

from ..drawing.page import Page
from ..errors import MmtError
from ..files import ensure_dir
from ..i18n import Language
from ..render.output import FORMATS, write_drawing
from ..render.recording import RecordingBackend
from ..solution import Solution
from .scales_record import Sheet1Scales, Sheet2Scales
from .sheet1 import compose_sheet1
from .sheet2 import compose_sheet2

__all__ = [
    "FORMATS",
    "SheetNotAvailable",
    "available_sheets",
    "sheet_scales",
    "write_sheets",
]


class SheetNotAvailable(MmtError, ValueError):
    """A sheet this version cannot compose yet."""


def available_sheets() -> dict[int, Callable[..., Any]]:
    """Sheet number → compose function."""
    return {1: compose_sheet1, 2: compose_sheet2}


def write_sheets(
    solution: Solution,
    out_dir: str | os.PathLike[str],
    formats: Sequence[str] = ("svg", "pdf", "png"),
    lang: Language = "en",
    sheets: Iterable[int] = (1,),
) -> list[Path]:
    """Compose each sheet once and write sheet<N>.<format> into out_dir (render's
    factory by format: svg, pdf, png, dxf); returns the paths."""
    formats = tuple(formats)
    unknown = [f for f in formats if f not in FORMATS]
    if unknown:
        raise ValueError(
            f"unknown format {', '.join(unknown)}; expected some of {', '.join(FORMATS)}"
        )
    composers = available_sheets()
    wanted = list(sheets)
    missing = [n for n in wanted if n not in composers]
    if missing:
        raise SheetNotAvailable(
            f"sheet {', '.join(map(str, missing))} does not exist; the sheets are "
            f"{', '.join(map(str, sorted(composers)))}"
        )
    out = ensure_dir(out_dir)
    written: list[Path] = []
    page = Page.of("A1")
    records: dict[int, Any] = {}
    recordings: dict[int, RecordingBackend] = {}
    # every sheet composed before any is written: a sheet that cannot be laid
    # out leaves no file of the others behind
    for n in wanted:
        recording = RecordingBackend(page.width, page.height)
        records[n] = composers[n](solution, recording, lang).record
        recording.close()
        recordings[n] = recording
    for n, recording in recordings.items():
        title = f"{solution.mechanism.title_in(lang)}, sheet {n}"
        for fmt in formats:
            written.append(write_drawing(recording, out / f"sheet{n}.{fmt}", fmt, title))
    if set(records) == {1, 2}:  # the note of the same Solution composes them no more
        _cached(solution).setdefault(lang, (records[1], records[2]))
    return written


_Record = tuple[Sheet1Scales | None, Sheet2Scales | None]
# id of a live Solution → its records by language (a Solution is not hashable:
# kept by id, dropped when the Solution goes)
_CACHE: dict[int, dict[str, _Record]] = {}


def _cached(solution: Solution) -> dict[str, _Record]:
    key = id(solution)
    if key not in _CACHE:
        _CACHE[key] = {}
        weakref.finalize(solution, _CACHE.pop, key, None)
    return _CACHE[key]


def sheet_scales(solution: Solution, lang: Language = "en") -> _Record:
    """The scales sheets 1 and 2 of `solution` draw at in `lang` (composed once
    on a RecordingBackend, kept per Solution); None for a sheet that cannot be
    composed (no plans, no force analysis, a layout that does not fit)."""
    by_lang = _cached(solution)
    if lang not in by_lang:
        page = Page.of("A1")
        first: Sheet1Scales | None = None
        second: Sheet2Scales | None = None
        try:
            s1 = compose_sheet1(solution, RecordingBackend(page.width, page.height), lang)
            first = s1.record
        except MmtError:
            first = None
        if solution.forces is not None:
            try:
                s2 = compose_sheet2(solution, RecordingBackend(page.width, page.height), lang)
                second = s2.record
            except MmtError:
                second = None
        by_lang[lang] = (first, second)
    return by_lang[lang]
