"""Composing the A1 sheets of a Solution once, and writing them to files in
every format of render.output.

`compose(solution, lang)` draws each sheet once on a RecordingBackend and
keeps what was drawn (`ComposedSheets`): the recorded calls of each sheet,
where each drawing went and the scales each drawing uses. The sheet writer
(`write_composed`), the note (note/: its millimetres at these scales, its
figures replayed from these calls) and batch read that one object, so a
number in the note never depends on a second, separate layout.

Each file is written atomically (files.py): an interrupted run leaves no
half-written sheet. PDFs carry a fixed date, so two runs give the same bytes."""

from __future__ import annotations

import os
from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass, field, replace
from functools import partial
from pathlib import Path
from types import MappingProxyType
from typing import Any

from ..drawing.page import Page
from ..errors import MmtError
from ..files import ensure_dir, write_bytes_atomic
from ..forked import fewer_collections, on_two_cores
from ..i18n import Language, catalogue
from ..render.look import Look
from ..render.output import FORMATS, render
from ..render.recording import Call, RecordingBackend
from ..solution import Solution
from .common import sheet_count
from .scales_record import Sheet1Scales, Sheet2Scales
from .sheet1 import compose_sheet1
from .sheet2 import compose_sheet2
from .sheet2_further import compose_sheet2_further

__all__ = [
    "FORMATS",
    "ComposedSheet",
    "ComposedSheets",
    "SheetNotAvailable",
    "available_sheets",
    "compose",
    "rendered_composed",
    "write_composed",
    "write_sheets",
]


class SheetNotAvailable(MmtError, ValueError):
    """A sheet this version cannot compose yet."""


def available_sheets(solution: Solution | None = None) -> dict[int, Callable[..., Any]]:
    """Sheet number → compose function: sheets 1 and 2, and for `solution`
    the further sheets of a force analysis too large for sheet 2 (3, 4 …:
    common.further_groups; their number is the title blocks' "sheets")."""
    out: dict[int, Callable[..., Any]] = {1: compose_sheet1, 2: compose_sheet2}
    for n in range(3, sheet_count(solution) + 1 if solution is not None else 3):
        out[n] = partial(compose_sheet2_further, number=n)
    return out


@dataclass(frozen=True)
class ComposedSheet:
    """One sheet as drawn: its recorded calls (each inside the group of its
    drawing: "mechanism", "velocity-plan-2", "group-4-5", "force-polygon-1",
    "zhukovsky-lever" ...), the page size and look it was drawn in, the
    rectangle each drawing was placed in and the scales it drew at."""

    number: int
    calls: tuple[Call, ...]
    width: float
    height: float
    look: Look
    placed: Mapping[str, Any]
    scales: Sheet1Scales | Sheet2Scales

    def recording(self) -> RecordingBackend:
        """A RecordingBackend holding the sheet's calls, to replay or write."""
        rec = RecordingBackend(self.width, self.height, self.look)
        rec.calls = list(self.calls)
        return rec

    def group(self, group_id: str) -> tuple[Call, ...]:
        """The calls of one drawing (group `group_id`, at any depth)."""
        return tuple(c for c in self.calls if group_id in c.groups and not c.name.endswith("group"))

    @property
    def drawings(self) -> tuple[str, ...]:
        """The ids of the sheet's drawings (its outermost groups), in drawing order."""
        return tuple(c.args["id"] for c in self.calls if c.name == "begin_group" and not c.groups)


@dataclass(frozen=True)
class ComposedSheets:
    """Sheets 1 and 2 of one Solution in one language, each composed once,
    and the further sheets (3, 4 …) of a force analysis too large for sheet
    2. A sheet not asked for, or one that cannot be composed (no plans, no
    force analysis, a layout that does not fit), is None (not in `further`)
    with its error in `errors`."""

    lang: Language
    first: ComposedSheet | None
    second: ComposedSheet | None
    errors: Mapping[int, MmtError] = field(default_factory=lambda: MappingProxyType({}))
    further: tuple[ComposedSheet, ...] = ()

    def sheet(self, n: int) -> ComposedSheet:
        """Sheet `n`, or the error that kept it from being composed."""
        got = {1: self.first, 2: self.second, **{s.number: s for s in self.further}}.get(n)
        if got is None:
            raise self.errors.get(n) or SheetNotAvailable(f"sheet {n} was not composed")
        return got

    def holding(self, drawing: str, default: int = 2) -> int:
        """The number of the composed sheet that holds `drawing` ("group-4-5"
        on a further sheet of a large force analysis), else `default`."""
        sheets = [self.first, self.second, *self.further]
        return next((s.number for s in sheets if s and drawing in s.drawings), default)

    @property
    def scales(self) -> tuple[Sheet1Scales | None, Sheet2Scales | None]:
        """The scales of sheets 1 and 2 (None for a sheet not composed); sheet
        2's with those of the groups drawn on the further sheets."""
        first = self.first.scales if self.first is not None else None
        second = self.second.scales if self.second is not None else None
        assert first is None or isinstance(first, Sheet1Scales)
        assert second is None or isinstance(second, Sheet2Scales)
        for sheet in self.further:
            more = sheet.scales
            assert isinstance(more, Sheet2Scales)
            if second is None:
                break
            second = replace(
                second,
                mu_l_group=MappingProxyType({**second.mu_l_group, **more.mu_l_group}),
                mu_F=MappingProxyType({**second.mu_F, **more.mu_F}),
            )
        return first, second


def compose(
    solution: Solution, lang: Language = "en", sheets: Iterable[int] | None = None
) -> ComposedSheets:
    """Compose the sheets `sheets` of `solution` (all of them: None) once
    each, in `lang`. Sheet 2 is left out (without an error) where the
    Solution has no force analysis."""
    composers = available_sheets(solution)
    wanted = list(sheets) if sheets is not None else sorted(composers)
    missing = [n for n in wanted if n not in composers]
    if missing:
        raise SheetNotAvailable(
            f"sheet {', '.join(map(str, missing))} does not exist; the sheets are "
            f"{', '.join(map(str, sorted(composers)))}"
        )
    page = Page.of("A1")

    def one(n: int) -> ComposedSheet | MmtError:
        recording = RecordingBackend(page.width, page.height)
        try:
            drawn = composers[n](solution, recording, lang)
        except MmtError as err:
            return err
        recording.close()
        return ComposedSheet(
            n,
            tuple(recording.calls),
            recording.width,
            recording.height,
            recording.look,
            MappingProxyType(dict(drawn.placed)),
            drawn.record,
        )

    # the sheets are independent of each other: on two cores, half in a fork
    # (the catalogues read first, by this process: every sheet reads both,
    # for its words and the designation's prefix)
    catalogue("en"), catalogue("uk")
    with fewer_collections():
        made = dict(zip(wanted, on_two_cores(one, wanted), strict=True))
    done = {n: m for n, m in made.items() if isinstance(m, ComposedSheet)}
    errors = {n: m for n, m in made.items() if isinstance(m, MmtError)}
    further = tuple(done[n] for n in sorted(done) if n > 2)
    return ComposedSheets(lang, done.get(1), done.get(2), MappingProxyType(errors), further)


def write_composed(
    composed: ComposedSheets,
    solution: Solution,
    out_dir: str | os.PathLike[str],
    formats: Sequence[str] = ("svg", "pdf", "png"),
    sheets: Iterable[int] = (1,),
) -> list[Path]:
    """Write sheet<N>.<format> of the composed sheets `sheets` into out_dir
    (render's factory by format: svg, pdf, png, dxf); returns the paths. A
    sheet that could not be composed raises its error before any sheet is
    written, so a failed run leaves no sheet of it behind."""
    files = rendered_composed(composed, solution, formats, sheets)
    out = ensure_dir(out_dir)
    return [write_bytes_atomic(out / name, data) for name, data in files]


def rendered_composed(
    composed: ComposedSheets,
    solution: Solution,
    formats: Sequence[str] = ("svg", "pdf", "png"),
    sheets: Iterable[int] = (1,),
) -> list[tuple[str, bytes]]:
    """(file name, bytes) of sheet<N>.<format> for the composed sheets
    `sheets`, in the order write_composed writes them (a sheet's error
    raised before any is rendered); batch writes them while the note is drawn."""
    formats = tuple(formats)
    unknown = [f for f in formats if f not in FORMATS]
    if unknown:
        raise ValueError(
            f"unknown format {', '.join(unknown)}; expected some of {', '.join(FORMATS)}"
        )
    wanted = list(sheets)
    recordings = {n: composed.sheet(n).recording() for n in wanted}  # raises a sheet's error

    def one(n: int) -> list[tuple[str, bytes]]:
        title = f"{solution.mechanism.title_in(composed.lang)}, sheet {n}"
        return [(f"sheet{n}.{fmt}", render(recordings[n], fmt, title)) for fmt in formats]

    # each sheet's files apart from the others': on two cores, half in a fork
    # (SVG alone in turn: writing it takes less than a fork costs)
    with fewer_collections():
        made = on_two_cores(one, wanted) if set(formats) != {"svg"} else list(map(one, wanted))
    return [file for files in made for file in files]


def write_sheets(
    solution: Solution,
    out_dir: str | os.PathLike[str],
    formats: Sequence[str] = ("svg", "pdf", "png"),
    lang: Language = "en",
    sheets: Iterable[int] = (1,),
) -> list[Path]:
    """Compose each sheet once and write sheet<N>.<format> into out_dir;
    returns the paths (compose, then write_composed)."""
    wanted = list(sheets)
    formats = tuple(formats)
    unknown = [f for f in formats if f not in FORMATS]
    if unknown:
        raise ValueError(
            f"unknown format {', '.join(unknown)}; expected some of {', '.join(FORMATS)}"
        )
    return write_composed(compose(solution, lang, wanted), solution, out_dir, formats, wanted)
