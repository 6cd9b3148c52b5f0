"""Issue 22, the note as the textbooks write it: every displayed formula
numbered (section.n) at the right margin and cited only by numbers that
exist; the guide's own formulas cited with the reference list; vectors marked
with an arrow in vector equations; the structural scheme and the gear train
as figures of their own, cited in the text."""

from __future__ import annotations

import functools
import math
import re
from pathlib import Path

import pytest

import mmt_plans
from mmt_plans.drawing.page import Rect
from mmt_plans.i18n import catalogue
from mmt_plans.note import draw_note, note_document
from mmt_plans.note.figures import figure_drawers
from mmt_plans.note.literature import LITERATURE
from mmt_plans.note.pages import draw_markup, note_look, note_page, text_box
from mmt_plans.render.recording import RecordingBackend

ROOT = Path(__file__).resolve().parents[2]
GEARS = ROOT / "samples/tasks/seed002/task1_v00.toml"
PRESS = ROOT / "samples/six_link_press.toml"
CASES = [(p, lang) for p in (GEARS, PRESS) for lang in ("en", "uk")]
VECTOR = "\u20d7"
NBSP = "\u00a0"


@functools.cache
def solved(path: Path):
    return mmt_plans.solve(mmt_plans.load(path))


@functools.cache
def document(path: Path, lang: str):
    return note_document(solved(path), lang)  # type: ignore[arg-type]


@pytest.fixture(params=CASES, ids=[f"{p.stem}-{lang}" for p, lang in CASES], scope="module")
def case(request):
    return request.param


def _blocks(path, lang):
    return document(path, lang).content.blocks


# --- formulas numbered -------------------------------------------------------------------
def test_every_formula_numbered_in_order_within_its_section(case):
    blocks = _blocks(*case)
    equations = [b for b in blocks if b.kind == "equation"]
    assert len(equations) > 50
    numbers = [b.number for b in equations]
    assert all(re.fullmatch(r"[12]\.\d+", n) for n in numbers), numbers[:5]
    # section 1 (with the gear train before it), then section 2, each 1, 2, 3 ...
    for chapter in ("1", "2"):
        mine = [int(n.split(".")[1]) for n in numbers if n.split(".")[0] == chapter]
        assert mine == list(range(1, len(mine) + 1)), chapter
    assert numbers.index("2.1") > max(i for i, n in enumerate(numbers) if n.startswith("1."))


def test_formula_numbers_cited_exist_and_come_before(case):
    """A reference "(s.n)" in the text names a formula displayed before it;
    the guide's formulas are cited as [k, formula (7)] with k the guide's
    place in the reference list, never as a bare "(7)"."""
    path, lang = case
    blocks = _blocks(path, lang)
    shown: set[str] = set()
    cited: set[str] = set()
    guide = [w.key for w in LITERATURE].index("dovbush2018") + 1
    word = {"en": "formula", "uk": "формул"}[lang]
    guide_cites = 0
    for b in blocks:
        if b.kind in ("text", "problem"):
            for n in re.findall(r"\((\d+\.\d+)\)", b.text):
                assert n in shown, (n, b.text)
                cited.add(n)
            text = b.text
            for m in re.finditer(r"\[(\d+), ([^\]\d][^\]]*)\]", text):
                assert int(m.group(1)) == guide and m.group(2).startswith(word), m.group(0)
                guide_cites += 1
            bare = re.sub(r"\[\d+, [^\]]*\]", "", text)
            assert not re.search(r"(?<![\w.])\(\d{1,2}\)", bare), text  # "(7)" uncited
            assert "@guide" not in text
        if b.kind == "equation":
            shown.add(b.number)
    assert guide_cites >= 8
    assert len(cited) >= 4  # the vector equations are referred to by their numbers


def test_formula_number_drawn_at_the_right_margin():
    path, lang = PRESS, "en"
    doc = document(path, lang)
    right = text_box(note_page(), "2a").right
    numbered = {f"({b.number})" for b in doc.content.blocks if b.kind == "equation"}
    pages = draw_note(solved(path), lambda w, h, title: RecordingBackend(w, h), lang)
    drawn = [
        c
        for b in pages
        for c in b.named("text")
        if re.fullmatch(r"\(\d\.\d+\)", c["content"]) and c["anchor"] == "right"
    ]
    assert {c["content"] for c in drawn} == numbered
    assert all(c["pos"][0] == pytest.approx(right) for c in drawn)


# --- vectors ------------------------------------------------------------------------------
def test_vector_equations_carry_the_arrow(case):
    path, lang = case
    blocks = _blocks(path, lang)
    eqs = [b.text for b in blocks if b.kind == "equation"]
    velocity = [t for t in eqs if re.match(r"V.?_\{\w+\} = ", t) and " + " in t]
    accel = [t for t in eqs if re.match(r"a.?_\{\w+\} = ", t) and "^n" in t]
    # a polygon's equation: forces summed to zero (not "n = 5, p_5 = 7, p_4 = 0")
    forces = [t for t in eqs if t.endswith(" = 0") and " + " in t and re.match(r"[GFRM]", t)]
    assert velocity and accel and forces
    for text in velocity + accel:
        for part in text.split("; "):
            # every term of V_B = V_A + V_BA, a_B = a_A + a^n_BA + a^τ_BA is a vector
            terms = re.split(r" = | \+ ", part)
            assert all(t[1] == VECTOR for t in terms), part
    for text in forces:
        terms = text[: -len(" = 0")].split(" + ")
        assert all(t[1] == VECTOR for t in terms), text
    # a magnitude is no vector: "V_BA/μ_V" carries no arrow
    segments = [b.text for b in blocks if b.kind == "equation" and "/μ_V = " in b.text]
    assert segments and not any(VECTOR in t for t in segments)


def test_the_arrow_is_drawn_over_the_letter():
    rec = RecordingBackend(210.0, 297.0, note_look())
    size = 4.0
    draw_markup(rec, (50.0, 100.0), f"V{VECTOR}_{{B}} = V{VECTOR}_{{A}}", size)
    assert not any(VECTOR in c["content"] for c in rec.named("text"))
    let = note_look().lettering
    v = let.advance_width("V", size)
    over = [c for c in rec.named("line") if min(c["start"][1], c["end"][1]) > 100.0 + size]
    # two shafts, each spanning about its letter's width, above the capitals
    shafts = [c for c in over if c["start"][1] == c["end"][1]]
    assert len(shafts) == 2
    assert all(0.8 * v < math.dist(c["start"], c["end"]) < 1.4 * v for c in shafts)
    assert shafts[0]["start"][0] == pytest.approx(50.0, abs=0.2 * v)
    heads = rec.named("polyline")
    assert len(heads) == 2


# --- figures ------------------------------------------------------------------------------
def _cited_figure(doc, key: str, lang: str) -> int:
    """The number of figure `key` (figures are numbered in the order they
    come, the task sheet's first) and that the text cites it."""
    figures = [b for b in doc.content.blocks if b.kind == "figure"]
    number = next(i for i, b in enumerate(figures) if b.figure == key) + 1
    cite = str(catalogue(lang).words("note")["cite_figure"]).format(n=number)  # type: ignore[arg-type]
    texts = [b.text.replace(NBSP, " ") for b in doc.content.blocks if b.kind == "text"]
    assert any(cite.replace(NBSP, " ") in t for t in texts), (key, cite)
    return number


@pytest.mark.parametrize("lang", ["en", "uk"])
def test_gear_train_figure_drawn_and_cited(lang):
    doc = document(GEARS, lang)
    _cited_figure(doc, "gears", lang)
    train = solved(GEARS).mechanism.drive.gear_train
    drawers = figure_drawers(solved(GEARS), doc.composed, doc.content.figures)
    rec = RecordingBackend(210.0, 297.0, note_look())
    drawers["gears"](rec, Rect(20.0, 50.0, 170.0, 120.0), lang)
    texts = [c["content"] for c in rec.named("text")]
    # every gear named by its number: z, then the index
    names = {n for stage in train.gear_labels for n in stage}
    assert names <= set(texts), (names, texts)
    assert "H" in texts  # the planetary stage's carrier
    # the first stage, an external pair z1 = 20, z2 = 80: the gears' lines across
    # their shafts in the ratio of their teeth, their shafts the sum of radii apart
    z1, z2 = train.stages[0].z
    across = sorted(
        (c for c in rec.named("line") if c["start"][0] == c["end"][0] and c["line"] == "main"),
        key=lambda c: c["start"][0],
    )
    first, second = across[0], across[1]
    l1 = abs(first["end"][1] - first["start"][1])
    l2 = abs(second["end"][1] - second["start"][1])
    assert l2 / l1 == pytest.approx(z2 / z1, rel=1e-6)
    c1 = (first["start"][1] + first["end"][1]) / 2
    c2 = (second["start"][1] + second["end"][1]) / 2
    assert abs(c2 - c1) == pytest.approx((l1 + l2) / 2, rel=1e-6)


def test_no_gear_figure_without_gears():
    doc = document(PRESS, "en")
    assert not any(b.figure == "gears" for b in doc.content.blocks)


@pytest.mark.parametrize("path", [GEARS, PRESS])
def test_structural_scheme_figure_names_each_group(path):
    lang = "en"
    doc = document(path, lang)
    _cited_figure(doc, "structure", lang)
    st = solved(path).structure
    drawers = figure_drawers(solved(path), doc.composed, doc.content.figures)
    rec = RecordingBackend(210.0, 297.0, note_look())
    drawers["structure"](rec, Rect(20.0, 50.0, 170.0, 90.0), lang)
    drawn = "".join(c["content"] for c in rec.named("text"))
    for g in st.groups:
        assert g.label in drawn
    assert f"I(0,{st.driver})" in drawn
    # in section 1.1, after the structural formula
    steps = [b.step for b in doc.content.blocks if b.kind == "subsection" and b.step]
    kinds = [(b.kind, b.figure, b.step) for b in doc.content.blocks]
    at = next(i for i, k in enumerate(kinds) if k[1] == "structure")
    last_step = [k[2] for k in kinds[:at] if k[0] == "subsection" and k[2]][-1]
    assert last_step == "1.1" and "1.1" in steps


def test_the_structural_scheme_is_drawn_as_the_text_sketched_it():
    """The figure draws the sketches the text measured its height by (kept on
    its FigureSpec, not sketched a second time), and they draw what sketching
    them afresh draws."""
    from mmt_plans.drawing.page import Rect as Box
    from mmt_plans.note.figures import draw_row, structure_sketches

    doc = document(PRESS, "en")
    spec = doc.content.figures["structure"]
    fresh = structure_sketches(solved(PRESS))
    assert fresh is not None and [n for n, _ in spec.sketches] == [n for n, _ in fresh]
    box = Box(20.0, 50.0, 170.0, 90.0)
    kept, again = RecordingBackend(210.0, 297.0, note_look()), RecordingBackend(
        210.0, 297.0, note_look()
    )
    figure_drawers(solved(PRESS), doc.composed, doc.content.figures)["structure"](kept, box, "en")
    draw_row([sk for _, sk in fresh], [n for n, _ in fresh], again, box)
    assert [c.name for c in kept.calls] == [c.name for c in again.calls]
    assert [c.points() for c in kept.calls if c.name != "text"] == [
        c.points() for c in again.calls if c.name != "text"
    ]
    assert [c["content"] for c in kept.named("text")] == [c["content"] for c in again.named("text")]


def test_a_citation_is_never_broken_at_a_line_end(case):
    doc = document(*case)
    lines = [ln.text for p in doc.pages for ln in p.lines if ln.kind in ("text", "problem")]
    assert any("[" in t for t in lines)
    for t in lines:
        assert t.count("[") == t.count("]"), t


def test_structural_scheme_of_a_long_chain_in_rows_of_four():
    """tests/data/hard/chain_25_links: the driving link and twelve dyads, four
    a row, every part named under it, each row below the one before."""
    from mmt_plans.note.figures import PER_ROW, draw_row, sketches_height, structure_sketches

    solution = solved(ROOT / "tests/data/hard/chain_25_links.toml")
    parts = structure_sketches(solution)
    assert parts is not None and len(parts) == 1 + len(solution.structure.groups) == 13
    names = [n for n, _ in parts]
    sketches = [sk for _, sk in parts]
    height = sketches_height(sketches, 170.0, labelled=True)
    rec = RecordingBackend(210.0, 297.0, note_look())
    draw_row(sketches, names, rec, Rect(20.0, 280.0 - height, 170.0, height))
    labels = [c for c in rec.named("text") if c["content"] in names]
    assert [c["content"] for c in labels] == names
    rows = sorted({round(c["pos"][1], 3) for c in labels}, reverse=True)
    assert len(rows) == math.ceil(len(names) / PER_ROW) == 4
    # everything drawn inside the figure's rectangle
    ys = [y for c in rec.named("line") for _, y in c.points()]
    assert min(ys) >= 280.0 - height - 1e-6 and max(ys) <= 280.0 + 1e-6
