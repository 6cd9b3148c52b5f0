"""The note as a department's reviewer reads it (issue 22): its figures are
the sheets' drawings, numbered, captioned and cited in the text; every scale
a drawing uses is stated; and a number never parts from its unit, nor a
formula from its value, at a line's end.

The laid-out lines (note_document(...).pages) are read, not the blocks: what
is tested is what the PDF prints. The scales are read from the composed
sheets here (sheets.compose.compose), the figures' groups from their
recordings, the units from the catalogue."""

from __future__ import annotations

import functools
import re
from pathlib import Path

import pytest

import mmt_plans
from mmt_plans.i18n import catalogue
from mmt_plans.note import note_document
from mmt_plans.note.figures import draw_figure
from mmt_plans.render.recording import RecordingBackend
from mmt_plans.sheets.compose import compose
from mmt_plans.drawing.page import Rect

ROOT = Path(__file__).resolve().parents[2]
FILES = sorted((ROOT / "samples").glob("*.toml")) + [
    ROOT / "samples/tasks/seed002/task1_v00.toml"
]
CASES = [(p, lang) for p in FILES for lang in ("en", "uk")]
NBSP = "\u00a0"


def _id(case) -> str:
    return f"{case[0].stem}-{case[1]}"


@functools.cache
def solved(path: Path):
    return mmt_plans.solve(mmt_plans.load(path))


@functools.cache
def composed(path: Path, lang: str):
    return compose(solved(path), lang)  # type: ignore[arg-type]


@functools.cache
def document(path: Path, lang: str):
    return note_document(solved(path), lang, composed=composed(path, lang))  # type: ignore[arg-type]


def _lines(doc) -> list[tuple[int, str, str]]:
    """(page, kind, text) of every line of text the note prints, in order."""
    return [(p.number, ln.kind, ln.text) for p in doc.pages for ln in p.lines if ln.text]


def _flat(text: str) -> str:
    return text.replace("{", "").replace("}", "").replace(NBSP, " ").replace("\u2212", "-")


def _units(lang: str) -> set[str]:
    cat = catalogue(lang)  # type: ignore[arg-type]
    units = {str(v) for v in dict(cat.words("units")).values()}
    return units | {"%", "°"}


@pytest.fixture(params=CASES, ids=[_id(c) for c in CASES], scope="module")
def case(request):
    return request.param


# --- figures ---------------------------------------------------------------------------------
def test_at_least_eight_numbered_figures_each_cited(case):
    path, lang = case
    doc = document(path, lang)
    w = catalogue(lang).words("note_front")  # type: ignore[arg-type]
    word = str(w["figure"]).split(" ")[0]  # "Figure" / "Рисунок"
    captions = [
        int(m.group(1))
        for _, kind, text in _lines(doc)
        if kind == "caption"
        for m in [re.match(rf"{word}[ {NBSP}](\d+)[ {NBSP}]–", text)]
        if m
    ]
    figures = [ln for p in doc.pages for ln in p.lines if ln.kind == "figure"]
    assert len(figures) >= 8
    # numbered 1, 2, ... in the order they come, one caption each
    assert captions == list(range(1, len(figures) + 1))
    body = " ".join(_flat(t) for _, kind, t in _lines(doc) if kind in ("text", "equation"))
    cite = str(catalogue(lang).words("note")["cite_figure"])  # type: ignore[arg-type]
    for n in captions:
        assert cite.format(n=n) in body, (n, cite)


def test_figures_replay_the_sheets_drawings(case):
    """Every figure of the calculation is drawn from the composed sheets'
    own records: its lines are those of the sheet's groups, scaled by one
    factor (the ratio of any two lengths is the sheet's)."""
    path, lang = case
    doc = document(path, lang)
    c = composed(path, lang)
    specs = doc.content.figures
    assert specs, "no figure from the sheets"
    for key, spec in specs.items():
        if not spec.parts:  # the note's own drawings (structure, gears): test_formulas_and_figures
            continue
        sheet_lines = [
            call
            for part in spec.parts
            for g in part.groups
            for call in c.sheet(part.sheet).group(g)
            if call.name == "line"
        ]
        rec = RecordingBackend(210.0, 297.0)
        draw_figure(c, spec, rec, Rect(25.0, 30.0, 170.0, 200.0))
        page_lines = rec.named("line")
        assert len(page_lines) == len(sheet_lines), key
        if len(spec.parts) == 1 and len(sheet_lines) >= 2:
            import math

            def length(call):
                return math.dist(call["start"], call["end"])

            ratios = {
                round(length(q) / length(p), 6)
                for p, q in zip(sheet_lines, page_lines)
                if length(p) > 1.0
            }
            assert len(ratios) == 1, (key, sorted(ratios)[:5])
            assert 0.05 < ratios.pop() <= 1.0 + 1e-9


class _LetteringSeen(RecordingBackend):
    """A recording backend that keeps the lettering each text was drawn in."""

    def __init__(self, *args, **kwargs) -> None:
        super().__init__(*args, **kwargs)
        self.seen: list[tuple[str, object]] = []

    def text(self, pos, content, size=3.5, **kwargs) -> None:
        self.seen.append((str(content), self.look.lettering))
        super().text(pos, content, size, **kwargs)


def test_figures_keep_the_sheets_lettering(case):
    """A figure's texts are drawn in its sheet's lettering, not the note's:
    the sheet put a name's index where the sheet's letter widths end the name
    (rich_text's runs), so in the note's narrower serif "(μ" and its index
    "l" stood 6 mm apart. After the figure the page letters as the note."""
    from mmt_plans.render.look import note_look

    path, lang = case
    doc = document(path, lang)
    c = composed(path, lang)
    note = note_look()
    for key, spec in doc.content.figures.items():
        if not spec.parts:
            continue
        rec = _LetteringSeen(210.0, 297.0, note)
        draw_figure(c, spec, rec, Rect(25.0, 30.0, 170.0, 200.0))
        sheet = c.sheet(spec.parts[0].sheet).look.lettering
        assert sheet != note.lettering
        drawn = [let for text, let in rec.seen if text not in {p.label for p in spec.parts}]
        assert drawn, key
        assert all(let == sheet for let in drawn), key
        assert rec.look.lettering == note.lettering


def test_every_scale_of_the_sheets_is_stated(case):
    """μ_l of each drawing, μ_V and μ_a of each plan, μ_F of each polygon and
    μ_V of the lever: each is written in the note as "μ_x = value"."""
    path, lang = case
    doc = document(path, lang)
    cat = catalogue(lang)  # type: ignore[arg-type]
    text = " ".join(_flat(t) for _, _, t in _lines(doc))
    first, second = composed(path, lang).scales

    def stated(symbol: str, value: float) -> bool:
        return re.search(rf"{symbol} = {re.escape(cat.number(value))}(?![\d.,])", text) is not None

    if first is not None:
        assert stated("μ_l", first.mu_l)
        for i in first.mu_V:
            assert stated("μ_V", first.mu_V[i]), ("μ_V", i)
            assert stated("μ_a", first.mu_a[i]), ("μ_a", i)
        if first.diagrams is not None:  # the S, V, a diagrams as sheet 1 draws them
            d = first.diagrams
            for symbol, mu in (("μ_t", d.mu_t), ("μ_S", d.mu_S), ("μ_V", d.mu_V), ("μ_a", d.mu_a)):
                # "μ_t = 0.001" or the construction's "μ_t = 60/(n_1·L) = … = 0.004"
                value = re.escape(cat.number(mu))
                pattern = rf"{symbol} = (?:[^=;]*= )*{value}(?![\d.,])"
                assert re.search(pattern, text), (symbol, "diagrams")
    if second is not None:
        assert stated("μ_l", second.mu_l)
        assert stated("μ_l", second.mu_l_driving)
        for g, mu in second.mu_l_group.items():
            assert stated("μ_l", mu), g
        for title, mu in second.mu_F.items():
            assert stated("μ_F", mu), title
        assert stated("μ_V", second.mu_V)


# --- typography ------------------------------------------------------------------------------
_NUMBER_END = re.compile(r"(?:^|[\s(=/·])[-−]?\d+(?:[.,]\d+)?$")


def test_number_unit_and_formula_runs_stay_on_one_line(case):
    path, lang = case
    doc = document(path, lang)
    units = _units(lang)
    lines = [(p, k, t) for p, k, t in _lines(doc) if k in ("text", "equation", "caption", "problem")]
    for (p, _, a), (q, kind, b) in zip(lines, lines[1:]):
        a_, b_ = a.rstrip(), b.lstrip()
        first = b_.replace(NBSP, " ").split(" ")[0].rstrip(".,;:)")
        # a number at a line's end, its unit at the next one's start
        assert not (_NUMBER_END.search(a_.replace(NBSP, " ")) and first in units), (p, a, b)
        # a formula broken after its "=" or before its value's sign
        assert not re.search(r"[=≤≥<>][\s]*$", a_), (p, a, b)
        assert not a_.endswith(("-", "−", "←", "<-")), (p, a, b)
        # a line never starts with a unit
        if kind != "equation":
            assert b_.split(" ")[0] not in units - {"°"}, (p, a, b)


def test_indices_whole_and_a_true_minus(case):
    path, lang = case
    doc = document(path, lang)
    for p, kind, t in _lines(doc):
        if kind not in ("text", "equation", "caption"):
            continue
        depth = 0
        for ch in t:
            depth += {"{": 1, "}": -1}.get(ch, 0)
            assert depth >= 0, (p, t)
        assert depth == 0, (p, t)  # an index is never split across lines
        # a minus before a number or a symbol is U+2212, not a hyphen
        assert not re.search(r"(?:^|[\s(=])-(?=[\d(A-Za-zα-ωΣ])", t), (p, t)


@pytest.mark.parametrize("lang", ["en", "uk"])
def test_the_levers_figure_shows_its_detail_views(lang):
    """Where sheet 2 draws the lever's crowd again as a detail view (generated
    seed 15: twenty forces, most images within 20 mm of p), the note's lever
    figure shows it too, as its part b), the caption says what b) is, and the
    text says why; the sheet's lever without a detail (six_link_press) keeps
    one part."""
    from mmt_plans.generate import generate_one
    from mmt_plans.spec import loads

    w = catalogue(lang).words("note")  # type: ignore[arg-type]
    g = generate_one(15)
    solution = mmt_plans.solve(loads(g.toml, f"{g.name}.toml"))
    c = compose(solution, lang)  # type: ignore[arg-type]
    details = [d for d in c.sheet(2).drawings if d.startswith("zhukovsky-lever-detail")]
    assert details, "the crowded lever has no detail view on sheet 2"
    doc = note_document(solution, lang, composed=c)  # type: ignore[arg-type]
    lever = [s for s in doc.content.figures.values() if any("zhukovsky-lever" in p.groups for p in s.parts)]
    assert len(lever) == 1
    assert [p.groups for p in lever[0].parts] == [("zhukovsky-lever",)] + [(d,) for d in details]
    text = " ".join(_flat(t) for _, _, t in _lines(doc))
    assert _flat(str(w["lever_details_drawn"]))[:40] in text
    letters = str(w["part_letters"])
    assert _flat(str(w["fig_lever_parts"]).format(parts=letters[1]))[:30] in text

    plain = document(ROOT / "samples/six_link_press.toml", lang)
    one = [s for s in plain.content.figures.values() if any("zhukovsky-lever" in p.groups for p in s.parts)]
    assert [p.groups for p in one[0].parts] == [("zhukovsky-lever",)]
