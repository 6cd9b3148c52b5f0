"""The note's writer: blocks of text whose every number says where it came from.

A section module writes a line as markup with its numbers put in through
`Writer.v` (a value, the source it was read from, significant digits). The
number is formatted in the note's language (the catalogue's number format: 3–4
significant figures, the decimal comma in Ukrainian, no negative zero) and
recorded as a `Printed`: where it sits in the block and its `source`, a Python
expression over the solved mechanism that a reader (tests/note) evaluates on
its own to check the number:

    J      the results JSON of the solution (results_json.results)
    S, M   the Solution and its Mechanism (inputs: masses, lengths, teeth)
    plan(i), F   the plan at position i, the force analysis at the force position
    sheet1, sheet2   the scales the sheets draw at (sheets/scales_record.py: mu_l,
                 mu_V[i], mu_a[i]; mu_l, mu_l_group['4-5'], mu_l_driving,
                 mu_F['group 4-5'], mu_V): a millimetre in the note is one on a sheet
    hyp, dist, cross, moment, scale_for, VELOCITY_PLAN ...   small helpers

so a number in the note is never taken on the writer's word.
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import dataclass, field
from functools import cached_property
from typing import TYPE_CHECKING, Any

from ..i18n import Language, catalogue, check_language

if TYPE_CHECKING:  # pragma: no cover
    from ..drawing.sketch import Sketch
    from ..sheets.compose import ComposedSheets
    from ..solution import Solution
    from .drawn import Drawn
    from .figures import FigureSpec

__all__ = ["Printed", "Writer", "and_list", "plural", "sub", "paren_markup", "vec", "VECTOR"]

# a vector's mark: the combining arrow over the symbol's letter before it,
# drawn as a line by the note's pages (pages.draw_markup): V⃗_{B} = V⃗_{A} + V⃗_{BA}
VECTOR = "\u20d7"
# the catalogue's citation of the course-project guide (seed 003) by its
# formulas: "[@guide, formula (7)]" becomes "[2, formula (7)]" (literature.py)
GUIDE = "@guide"

_OPEN, _CLOSE = "\ue000", "\ue001"
_MARK = re.compile(_OPEN + r"(\d+)" + _CLOSE)


@dataclass(frozen=True)
class Printed:
    """One number printed in the note: in block `block` (in a table: cell
    `row`, `col`; else -1, -1), at text[start:end]; `sig` significant figures
    (0: a whole number written exactly); `source` an expression of its value."""

    block: int
    row: int
    col: int
    start: int
    end: int
    text: str
    value: float
    sig: int
    source: str


@dataclass
class RawBlock:
    kind: str
    text: str = ""
    step: str = ""
    rows: tuple[tuple[str, ...], ...] = ()
    widths: tuple[float, ...] = ()
    figure: str = ""
    height: float = 0.0
    number: str = ""  # a displayed formula's number, "1.3"


# figures before the calculation: the task sheet's kinematic scheme (front.py)
FRONT_FIGURES = 1
# the width a figure is set at: the text's width on an A4 page (pages.text_box)
FIGURE_WIDTH = 170.0


@dataclass
class _Pending:
    text: str
    value: float
    sig: int
    source: str


def plural(lang: str, n: int, forms: Sequence[str]) -> str:
    """The form of a noun after the number n: English (one, many); Ukrainian
    (one, few, many): 1 рисунок, 2 рисунки, 5 рисунків, 21 рисунок."""
    if lang == "uk" and len(forms) >= 3:
        if n % 10 == 1 and n % 100 != 11:
            return forms[0]
        if 2 <= n % 10 <= 4 and not 12 <= n % 100 <= 14:
            return forms[1]
        return forms[2]
    return forms[0] if n == 1 else forms[-1]


def and_list(items: Sequence[str], conj: str) -> str:
    """ "4", "4 and 5", "2, 4 and 5" (`conj` the language's "and")."""
    items = list(items)
    if len(items) < 2:
        return "".join(items)
    return f"{', '.join(items[:-1])} {conj} {items[-1]}"


def sub(name: str) -> str:
    """A point or link name as a subscript group: "S2" → "{S2}"."""
    return "{" + name + "}"


def vec(markup: str) -> str:
    """A vector's symbol: the arrow over its letter, "V_{BA}" → "V⃗_{BA}"."""
    return markup[:1] + VECTOR + markup[1:] if markup else markup


def paren_markup(text: str) -> str:
    return f"({text})" if text.startswith("-") else text


@dataclass
class Writer:
    """Blocks and their printed numbers, in one language."""

    solution: Solution
    lang: Language
    composed: ComposedSheets
    blocks: list[RawBlock] = field(default_factory=list)
    printed: list[Printed] = field(default_factory=list)
    figures: dict[str, FigureSpec] = field(default_factory=dict)
    _pending: dict[int, _Pending] = field(default_factory=dict)
    # displayed formulas are numbered "section.n": the numbered section they
    # stand in (an unnumbered one continues the section before it; the gear
    # train, before section 1, opens section 1's numbers)
    _chapter: str = "1"
    _formulas: int = 0

    def __post_init__(self) -> None:
        check_language(self.lang)
        cat = catalogue(self.lang)
        self.cat = cat
        self.w = cat.words("note")
        self.u = cat.words("units")
        # the language's indices of the textbook's symbols: F_{bal.pl} is F_{зр.пл} in Ukrainian
        self.symbols = tuple(dict(self.w["symbols"]).items())
        self.mech = self.solution.mechanism
        from .literature import cite

        self._guide = cite("dovbush2018")[1:-1]

    @cached_property
    def drawn(self) -> Drawn:
        """The scales the sheets draw at (drawn.py): the note's mm are the sheets'."""
        from .drawn import Drawn

        return Drawn(self.solution, self.composed)

    # --- numbers ------------------------------------------------------------------------
    def v(self, x: float, source: str, sig: int = 4) -> str:
        """A number read from `source`, formatted, as a marker the block resolves."""
        text = self.cat.number(float(x), sig)
        key = len(self._pending)
        self._pending[key] = _Pending(text, float(x), sig, source)
        return f"{_OPEN}{key}{_CLOSE}"

    def vp(self, x: float, source: str, sig: int = 4) -> str:
        """A number substituted into a formula: a negative one in parentheses."""
        mark = self.v(x, source, sig)
        return f"({mark})" if self.cat.number(float(x), sig).startswith("-") else mark

    def neg(self, x: float, source: str, sig: int = 4) -> str:
        """-x substituted into a formula: "-" before the number (in parentheses
        when negative); no sign before a number that prints as 0 (no "-0")."""
        mark = self.vp(x, source, sig)
        return mark if self.cat.number(float(x), sig) == "0" else f"-{mark}"

    def i(self, k: int, source: str) -> str:
        """A whole number (a count, a position) written exactly."""
        key = len(self._pending)
        self._pending[key] = _Pending(str(int(k)), float(k), 0, source)
        return f"{_OPEN}{key}{_CLOSE}"

    def _resolve(self, text: str, block: int, row: int, col: int) -> str:
        out, pos = [], 0
        for m in _MARK.finditer(text):
            out.append(text[pos : m.start()])
            p = self._pending[int(m.group(1))]
            start = sum(len(s) for s in out)
            self.printed.append(
                Printed(
                    block, row, col, start, start + len(p.text), p.text, p.value, p.sig, p.source
                )
            )
            out.append(p.text)
            pos = m.end()
        out.append(text[pos:])
        return "".join(out)

    def symbol(self, markup: str) -> str:
        markup = markup.replace(GUIDE, self._guide)
        for en, local in self.symbols:
            markup = markup.replace(en, local)
        return markup

    # --- blocks -------------------------------------------------------------------------
    def add(
        self,
        kind: str,
        text: str = "",
        step: str = "",
        rows: Any = (),
        widths: Any = (),
    ) -> None:
        b = len(self.blocks)
        text = self._resolve(self.symbol(text), b, -1, -1)
        cells = tuple(
            tuple(self._resolve(self.symbol(str(c)), b, r, k) for k, c in enumerate(row))
            for r, row in enumerate(rows)
        )
        number = ""
        if kind == "section" and step[-1:].isdigit() and step[-1:] != self._chapter:
            self._chapter, self._formulas = step[-1:], 0
        elif kind == "equation":
            self._formulas += 1
            number = f"{self._chapter}.{self._formulas}"
        self.blocks.append(RawBlock(kind, text, step, cells, tuple(widths), number=number))

    def text(self, t: str) -> None:
        self.add("text", t)

    def eq(self, t: str) -> str:
        """A displayed formula, numbered; returns its number as the text cites it: "(1.3)"."""
        self.add("equation", t)
        return f"({self.blocks[-1].number})"

    def heading(self, step: str) -> None:
        """A seed 003 item's heading: "1.3. Velocity plans"."""
        self.add("subsection", f"{step}. {self.w[step]}", step)

    def sub_heading(self, text: str) -> None:
        self.add("subsection", text)

    @property
    def next_figure(self) -> int:
        """The number the next figure gets in the note."""
        return FRONT_FIGURES + sum(1 for x in self.blocks if x.kind == "figure") + 1

    def has_figure(self, parts: Sequence[tuple[int, Sequence[str]]]) -> bool:
        """Whether every drawing of `parts` is on the composed sheets."""
        for n, groups in parts:
            try:
                sheet = self.composed.sheet(n)
            except Exception:
                return False
            if not all(g in sheet.drawings for g in groups):
                return False
        return True

    def drawings_named(self, n: int, prefix: str) -> tuple[str, ...]:
        """The drawings of composed sheet `n` whose ids start with `prefix`, in
        drawing order (none where the sheet was not composed)."""
        try:
            sheet = self.composed.sheet(n)
        except Exception:
            return ()
        return tuple(g for g in sheet.drawings if g.startswith(prefix))

    def figure(self, parts: Sequence[tuple[int, Sequence[str]]], caption: str) -> int | None:
        """A figure of the drawings `parts` ((sheet, group ids) each, lettered
        a), b) ... when more than one) of the composed sheets, with its
        caption; returns its number in the note (None where a drawing is not
        on the composed sheets: no figure)."""
        from .figures import FigurePart, FigureSpec, bounds, figure_height

        composed = self.composed
        if not self.has_figure(parts):
            return None
        chosen: list[FigurePart] = []
        for k, (n, groups) in enumerate(parts):
            letter = (
                self.w["part"].format(p=str(self.w["part_letters"])[k]) if len(parts) > 1 else ""
            )
            chosen.append(FigurePart(n, tuple(groups), letter))
        key = "+".join(f"{p.sheet}:{','.join(p.groups)}" for p in chosen)
        spec = FigureSpec(key, tuple(chosen), tuple(bounds(composed, p) for p in chosen))
        self.figures[key] = spec
        height = figure_height(composed, spec, FIGURE_WIDTH)
        b = len(self.blocks)
        self.blocks.append(
            RawBlock(
                "figure", self._resolve(self.symbol(caption), b, -1, -1), figure=key, height=height
            )
        )
        return FRONT_FIGURES + sum(1 for x in self.blocks if x.kind == "figure")

    def drawing(
        self,
        key: str,
        height: float,
        caption: str,
        sketches: Sequence[tuple[str, Sketch]] = (),
    ) -> int:
        """A figure of the note's own drawing `key` (figures.figure_drawers:
        "structure", "gears") `height` mm tall, of `sketches` (named) where
        they are drawn already; returns its number."""
        from .figures import FigureSpec

        self.figures[key] = FigureSpec(key, (), sketches=tuple(sketches))
        b = len(self.blocks)
        self.blocks.append(
            RawBlock(
                "figure", self._resolve(self.symbol(caption), b, -1, -1), figure=key, height=height
            )
        )
        return FRONT_FIGURES + sum(1 for x in self.blocks if x.kind == "figure")

    def cite(self, n: int | None) -> str:
        """ " (Fig. n)" after a sentence's words, "" where there is no figure."""
        return "" if n is None else "\u00a0" + self.w["cite_figure"].format(n=n)

    def problem(self, err: Exception | str) -> None:
        self.add("problem", self.w["problem"].format(msg=str(err)))

    def unit(self, key: str) -> str:
        return str(self.u[key])
