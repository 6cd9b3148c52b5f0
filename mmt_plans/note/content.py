"""The calculation note as blocks of text, in the order of seed 003 §IV.

Every step is written as seed 002 writes it: formula = numbers substituted =
result unit, with the numbers taken from the Solution, never re-derived by
another method; a segment of a plan or a force polygon is the solver's
magnitude divided by the plan's scale, so "segment·μ" gives back the value.

The sections are written by writer.Writer (every printed number recorded with
its source, `NoteContent.numbers`): sections_kinematics (1.1–1.8),
sections_forces (2.1–2.11, one sign convention), sections_gears (the gear
train by Willis, the reduction to the crank, the conclusions).

Lines are `Backend.rich_text` markup: `_x` / `_{xy}` a subscript, `^x` a
superscript; `plain()` drops the braces for tests and text output.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from types import MappingProxyType
from typing import TYPE_CHECKING, Literal

from ..i18n import Language, catalogue, check_language
from ..titles import title_in
from .sections_forces import sheet2
from .sections_gears import conclusions, gear_train, reduction
from .sections_kinematics import sheet1
from .writer import Printed, Writer

if TYPE_CHECKING:  # pragma: no cover
    from ..sheets.compose import ComposedSheets
    from ..solution import Solution
    from .figures import FigureSpec

BlockKind = Literal[
    "title",
    "section",
    "subsection",
    "text",
    "equation",
    "table",
    "problem",
    # the document's frame (note/front.py, note/pages.py)
    "heading",  # a structural element's name, centred: CONTENTS, CONCLUSIONS, REFERENCES
    "figure",  # a drawing `figure` (note/figures.py) `height` mm tall, `text` its caption
    "pagebreak",  # the next block starts a page of form `text` ("none", "2", "2a")
    "center",  # a centred line of text
    "space",  # `height` mm of white space
    "toc",  # a line of the contents: `text` and the page of the heading `step`
]

__all__ = ["Block", "NoteContent", "Printed", "note_content", "plain", "Language"]


@dataclass(frozen=True)
class Block:
    """One piece of the note. `step` is seed 003's item number ("1.3") of a
    (sub)section heading; a table has `rows` (the header first) and `widths`
    (mm), and `text` is its caption (numbered "Table N - text" by the layout).
    A figure draws `figure` (a key of note/figures.py) `height` mm tall, with
    `text` as its caption; `indent` (mm) moves a text line right."""

    kind: BlockKind
    text: str = ""
    step: str = ""
    rows: tuple[tuple[str, ...], ...] = ()
    widths: tuple[float, ...] = ()
    figure: str = ""
    height: float = 0.0
    indent: float = 0.0
    number: str = ""  # a displayed formula's number ("1.3"), set at the right margin


@dataclass(frozen=True)
class NoteContent:
    title: str
    lang: Language
    blocks: tuple[Block, ...]
    # every number printed in the blocks, with its source (writer.Printed)
    numbers: tuple[Printed, ...] = ()
    # the figures of the calculation by their blocks' keys (note/figures.py)
    figures: Mapping[str, FigureSpec] = field(default_factory=dict)

    @property
    def steps(self) -> list[str]:
        """Seed 003 item numbers of the headings, in the order written."""
        return [b.step for b in self.blocks if b.step]

    def text(self) -> str:
        """The whole note as plain text (markup braces dropped)."""
        out = []
        for b in self.blocks:
            if b.kind in ("pagebreak", "space"):
                continue
            if b.kind == "table":
                out += [plain(b.text)] if b.text else []
                out += ["  ".join(plain(c) for c in row) for row in b.rows]
            else:
                out.append(plain(b.text))
        return "\n".join(out)


def plain(markup: str) -> str:
    """ "V_{BA} = ω_{1}·l_{OA}" → "V_BA = ω_1·l_OA"."""
    return markup.replace("{", "").replace("}", "")


def number(x: float, lang: Language = "en", sig: int = 4) -> str:
    """At least `sig` significant digits, no exponent, no trailing zeros; a
    decimal comma in Ukrainian: 10.47, 2.094, 0.2, 12403; "2,094"."""
    return catalogue(lang).number(x, sig)


def note_content(
    analysis: Solution, lang: Language = "en", composed: ComposedSheets | None = None
) -> NoteContent:
    """The calculation note of `analysis` as blocks, in seed 003 §IV order: the
    gear train (seed 002 task 1) where the file has one, sheet 1 (1.1–1.8),
    sheet 2 (2.1–2.11), the reduction to the crank (seed 002 tasks 5–6) and
    the conclusions; every number with its source.
    `composed`: the sheets of `analysis` in `lang` composed once (composed
    here when not given): the note's millimetres, scales and figures are theirs."""
    check_language(lang)
    if composed is None:
        from ..sheets.compose import compose

        composed = compose(analysis, lang)
    elif composed.lang != lang:
        raise ValueError(f"the sheets were composed in {composed.lang!r}, the note is in {lang!r}")
    wr = Writer(analysis, lang, composed)
    w = wr.w
    title = title_in(analysis.mechanism, lang)
    wr.add("title", f"{w['title']}: {title}")
    gear_train(wr)
    wr.add("section", w["sheet1"], "sheet1")
    sheet1(wr)
    wr.add("section", w["sheet2"], "sheet2")
    sheet2(wr)
    reduction(wr)
    conclusions(wr)
    blocks = tuple(
        Block(b.kind, b.text, b.step, b.rows, b.widths, b.figure, b.height, number=b.number)  # type: ignore[arg-type]
        for b in wr.blocks
    )
    return NoteContent(title, wr.lang, blocks, tuple(wr.printed), MappingProxyType(wr.figures))


def step_order() -> Sequence[str]:
    """Seed 003 §IV items of sheet 1, in order."""
    return ("1.1", "1.2", "1.3", "1.4", "1.5", "1.6", "1.7", "1.8")
