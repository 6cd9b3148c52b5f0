"""The note as a document (DSTU 3008:2015, seed 003 §III): title page, task
sheet with the scheme and the file's initial data, abstract with its counts,
contents with page numbers, references, forms 2 and 2a, real text in the PDF.

The pages are read back from what was drawn (the recorded text calls, and
the PDF through pdftotext where it is installed), not from the layout's own
bookkeeping; the initial data are read from the TOML file itself.
"""

from __future__ import annotations

import math
import re
import shutil
import subprocess
import tomllib
from pathlib import Path

import pytest

import mmt_plans
from mmt_plans.cli.fields import with_fields
from mmt_plans.i18n import catalogue
from mmt_plans.note import draw_note, note_document, write_note
from mmt_plans.note.pages import FORM2_HEIGHT, FORM2A_HEIGHT, note_page
from mmt_plans.render.recording import RecordingBackend

ROOT = Path(__file__).resolve().parents[2]
PLANETARY = ROOT / "samples" / "tasks" / "seed002" / "task1_v00.toml"
SEED003 = ROOT / "samples" / "tasks" / "seed003" / "task01_v1.toml"
CASES = [(PLANETARY, "en"), (PLANETARY, "uk"), (SEED003, "en"), (SEED003, "uk")]
FIELDS = {
    "author": "I. Petrenko",
    "group": "TM-21",
    "supervisor": "O. Strilets",
    "university": "Rivne Water University",
    "department": "Department of Mechanics",
    "discipline": "Machine Theory",
    "variant": "17",
    "city": "Rivne",
    "year": "2031",
    "drawing_number": "TMM.KP.17.00.00",
}


def _words(lang: str):
    return catalogue(lang).words("note_front")  # type: ignore[arg-type]


def _page_texts(backend: RecordingBackend) -> list[tuple[float, float, str]]:
    """The text of the page itself: not the stamp's, not the page number."""
    skip = {"title-block", "form-2a", "page-number"}
    return [
        (c["pos"][1], c["pos"][0], c["content"])
        for c in backend.named("text")
        if not skip & set(c.groups)
    ]


def _lines(backend: RecordingBackend) -> list[str]:
    """The drawn text calls grouped into lines by their baseline (to 1.5 mm,
    so that indices stay on their line), left to right, joined by spaces."""
    calls = sorted(_page_texts(backend), key=lambda t: (-t[0], t[1]))
    lines: list[list[tuple[float, float, str]]] = []
    for t in calls:
        if lines and abs(lines[-1][0][0] - t[0]) <= 1.5:
            lines[-1].append(t)
        else:
            lines.append([t])
    return [" ".join(c for _, _, c in sorted(line, key=lambda t: t[1])) for line in lines]


def _norm(text: str) -> str:
    return re.sub(r"\s+", " ", text).strip().casefold()


@pytest.fixture(scope="module", params=CASES, ids=lambda c: f"{c[0].stem}-{c[1]}")
def case(request):
    path, lang = request.param
    solution = mmt_plans.solve(with_fields(mmt_plans.load(path), FIELDS))
    backends = draw_note(solution, lambda w, h, title: RecordingBackend(w, h), lang)
    return path, lang, solution, backends


def test_at_least_twelve_pages_with_the_forms(case):
    _, lang, solution, backends = case
    assert len(backends) >= 12
    groups = [{c["id"] for c in b.named("begin_group")} for b in backends]
    # title page and task sheet: no frame; then one page of form 2, the rest 2a
    framed = [i for i, g in enumerate(groups) if "frame" in g]
    assert framed == list(range(framed[0], len(backends))) and framed[0] >= 2
    assert "title-block" in groups[framed[0]]
    assert all("form-2a" in groups[i] and "title-block" not in groups[i] for i in framed[1:])
    # the page number in form 2a's cell is the page's own
    for i in framed[1:]:
        numbers = [c["content"] for c in backends[i].in_group("form-2a") if c.name == "text"]
        assert str(i + 1) in numbers


def test_text_keeps_the_margins_of_seed_003(case):
    _, _, _, backends = case
    page = note_page()
    for i, b in enumerate(backends):
        stamp = {"title-block": FORM2_HEIGHT, "form-2a": FORM2A_HEIGHT}
        groups = {c["id"] for c in b.named("begin_group")}
        bottom = 25.0
        for key, h in stamp.items():
            if key in groups:
                bottom = page.frame.bottom + h + 10.0
        for c in b.calls:
            if c.name != "text" or {"title-block", "form-2a", "page-number"} & set(c.groups):
                continue
            if any(g.startswith("figure-") for g in c.groups):
                continue
            x0, y0, x1, y1 = b.text_box(c)
            assert x0 >= 25.0 - 1e-6, c["content"]
            assert x1 <= 210.0 - 15.0 + 0.5, c["content"]
            assert y1 <= 297.0 - 25.0 + 1e-6, c["content"]
            # descenders and subscripts reach below the baseline
            assert y0 >= bottom - 2.0, c["content"]


def test_title_page_fields(case):
    path, lang, solution, backends = case
    text = " ".join(_lines(backends[0]))
    for key in ("university", "department", "author", "group", "supervisor", "city", "year"):
        assert FIELDS[key] in text, key
    assert f"«{FIELDS['discipline']}»" in text
    assert _words(lang)["variant"].format(variant="17") in text
    assert solution.mechanism.title_in(lang)[:20] in text
    # form 2 carries the designation, the student and the supervisor
    form2 = next(b for b in backends if "title-block" in {c["id"] for c in b.named("begin_group")})
    stamp = [c["content"] for c in form2.in_group("title-block") if c.name == "text"]
    assert FIELDS["drawing_number"] + (" ПЗ" if lang == "uk" else " EN") in stamp
    assert FIELDS["author"] in stamp and FIELDS["supervisor"] in stamp


def test_year_from_source_date_epoch(monkeypatch):
    monkeypatch.setenv("SOURCE_DATE_EPOCH", str(2_000_000_000))  # 2033-05-18
    solution = mmt_plans.solve(mmt_plans.load(SEED003))
    doc = note_document(solution, "uk")
    first = " ".join(line.text for line in doc.pages[0].lines)
    assert "– 2033" in first
    # blanks to fill in by hand where the file names nobody
    assert "____" in first


def _abstract_counts(backends, lang: str) -> tuple[int, int, int, int]:
    # a number and its noun never part (a non-breaking space); the noun agrees with it
    pattern = (
        r"(\d+)\spages?, (\d+)\sfigures?, (\d+)\stables?, (\d+)\sreferences?"
        if lang == "en"
        else r"(\d+)\sс\., (\d+)\sрисун(?:ок|ки|ків), (\d+)\sтаблиц(?:я|і|ь), (\d+)\sджерел[оа]?"
    )
    for b in backends:
        m = re.search(pattern, " ".join(_lines(b)))
        if m:
            return tuple(int(g) for g in m.groups())  # type: ignore[return-value]
    raise AssertionError("no counts in the abstract")


def test_abstract_counts_are_the_real_counts(case):
    _, lang, _, backends = case
    w = _words(lang)
    # "Figure 3 – ...": the spaces may be non-breaking ones
    fig = re.compile(re.escape(w["figure"]).replace(r"\{n\}", r"(\d+)").replace(r"\ ", r"\s") + r"(\s–|$)")
    tab = re.compile(
        "^" + re.escape(w["table"]).replace(r"\{n\}", r"(\d+)").replace(r"\ ", r"\s") + r"(\s–|$)"
    )
    figures, tables = set(), set()
    for b in backends:
        for line in _lines(b):
            m = fig.match(line)
            if m:
                figures.add(int(m.group(1)))
            m = tab.match(line)
            if m:
                tables.add(int(m.group(1)))
    refs_page = next(i for i, b in enumerate(backends) if w["references"] in _lines(b))
    refs: list[int] = []  # the numbers starting lines, 1, 2, 3 ... in order
    for b in backends[refs_page:]:
        for line in _lines(b):
            m = re.match(r"^(\d+)\. \S", line)
            if m and int(m.group(1)) == len(refs) + 1:
                refs.append(len(refs) + 1)
    pages, n_fig, n_tab, n_ref = _abstract_counts(backends, lang)
    assert pages == len(backends)
    assert n_fig == len(figures) >= 1 and sorted(figures) == list(range(1, n_fig + 1))
    assert n_tab == len(tables) >= 2 and sorted(tables) == list(range(1, n_tab + 1))
    assert n_ref == len(refs) >= 5


def test_contents_page_numbers_are_where_the_headings_land(case):
    _, lang, _, backends = case
    w = _words(lang)
    start = next(i for i, b in enumerate(backends) if _lines(b) and _lines(b)[0] == w["contents"])
    entries: list[tuple[str, int]] = []
    i = start
    pending = ""
    while True:
        lines = _lines(backends[i])
        if i > start and not any(re.search(r"(\. ){3,}", ln) for ln in lines):
            break
        for ln in lines:
            m = re.match(r"^(.*?)\s*(?:\. ?)*\.\s+(\d+)$", ln)
            if m and "." in ln:
                entries.append(((pending + " " + m.group(1)).strip(), int(m.group(2))))
                pending = ""
            elif ln != w["contents"] and not re.fullmatch(r"\d+", ln):
                pending = (pending + " " + ln).strip()
        i += 1
    body_from = i
    assert len(entries) >= 20
    assert entries[-1][0].casefold() == w["references"].casefold()
    texts = [_norm(" ".join(_lines(b))) for b in backends]
    for title, number in entries:
        found = next(
            (k + 1 for k in range(body_from, len(texts)) if _norm(title) in texts[k]), None
        )
        assert found == number, (title, number, found)


def _file_numbers(path: Path):
    """(label of a row, a number) pairs from the file itself."""
    data = tomllib.loads(path.read_text(encoding="utf-8"))
    out = []
    for link in data["link"]:
        pts = list(link["points"].items())
        for name, xy in pts[1:]:
            (a, p0) = pts[0]
            out.append((f"{a}{name}", math.hypot(xy[0] - p0[0], xy[1] - p0[1])))
        if link.get("mass"):
            out.append((f"m{link['id']}", float(link["mass"])))
        if link.get("J"):
            out.append((f"J{link['id']}", float(link["J"])))
    for force in data.get("force", []):
        out.append((force["name"], float(force["magnitude"])))
    if "gears" in data:
        out.append(("motor", float(data["gears"]["motor_rpm"])))
    elif "rpm" in data["drive"]:
        out.append(("n1", float(data["drive"]["rpm"])))
    return data, out


def test_task_sheet_has_the_scheme_and_the_files_data(case):
    path, lang, solution, backends = case
    w = _words(lang)
    abstract = next(i for i, b in enumerate(backends) if w["abstract"] in _lines(b))
    task = list(range(1, abstract))
    assert 1 <= len(task) <= 2
    lines = [ln for i in task for ln in _lines(backends[i])]
    assert lines[0] == w["task"]
    # the scheme is drawn as a figure on the first page of the task
    figure = backends[task[0]].in_group("figure-scheme")
    assert len([c for c in figure if c.name in ("line", "circle", "polyline")]) > 10
    data, numbers = _file_numbers(path)
    cat = catalogue(lang)  # type: ignore[arg-type]
    joined = "\n".join(lines)
    for label, value in numbers:
        shown = cat.number(value, 4)
        if label.startswith("m") and label[1:].isdigit():
            row = w["mass"].format(link=label[1:])
        elif label.startswith("J") and label[1:].isdigit():
            row = w["inertia"].format(link=label[1:])
        elif label == "motor":
            row = w["motor"]
        elif label == "n1":
            row = w["rpm"]
        elif label.startswith("F"):
            row = label.split("_")[0]
        else:
            row = label
        assert any(row in ln and f" {shown} " in f" {ln} " for ln in lines), (row, shown)
    if "gears" in data:
        for stage in data["gears"]["stage"]:
            pairs = [m["z"] for m in stage.get("meshes", [stage])]
            assert "; ".join(f"{a}–{b}" for a, b in pairs) in joined
    for item in w["todo_items"]:
        assert item[:25] in joined.replace("\n", " ")


def test_references_at_the_end(case):
    _, lang, _, backends = case
    w = _words(lang)
    refs_page = next(i for i, b in enumerate(backends) if w["references"] in _lines(b))
    assert refs_page >= len(backends) - 2
    text = _norm(" ".join(ln for b in backends[refs_page:] for ln in _lines(b)))
    from mmt_plans.note.literature import entries

    items = entries(lang)
    for k, item in enumerate(items, 1):
        assert _norm(f"{k}. {item}")[:40] in text
    # after every section of the calculation
    last_section = max(
        i for i, b in enumerate(backends) if any(ln.startswith("2.") for ln in _lines(b))
    )
    assert refs_page >= last_section


UNITS_EN = r"\d\s(?:m|mm|m/s|m/s²|rad/s|rad/s²|N|N·m|kg|kg·m²|rpm)(?![\w/])"


@pytest.mark.skipif(shutil.which("pdftotext") is None, reason="needs pdftotext (poppler-utils)")
@pytest.mark.parametrize("lang", ["en", "uk"])
def test_pdf_text_is_real_and_in_one_language(tmp_path, lang):
    solution = mmt_plans.solve(mmt_plans.load(PLANETARY))
    target = write_note(solution, tmp_path / "note.pdf", lang=lang)  # type: ignore[arg-type]
    out = subprocess.run(
        ["pdftotext", "-enc", "UTF-8", str(target), "-"],
        capture_output=True,
        text=True,
        check=True,
        timeout=60,
    ).stdout
    pages = out.split("\f")
    assert len([p for p in pages if p.strip()]) >= 12
    w = _words(lang)
    for word in (w["abstract"], w["contents"], w["references"], w["task"]):
        assert word in out
    assert "W = 3n - 2p5 - p4" in out
    # the longest paragraph, set flush left and right, reads back word by word
    blocks = note_document(solution, lang).content.blocks  # type: ignore[arg-type]
    texts = [b.text for b in blocks if b.kind == "text" and not re.search(r"[_^{}]", b.text)]
    assert _norm(max(texts, key=len)) in _norm(out)
    if lang == "uk":
        assert not re.findall(UNITS_EN, out)
        assert "рад/с" in out and "Таблиця 1" in out and "Рисунок 1" in out
        for english in ("Table", "Figure", "Sheet", "Task", "Variant", "Abstract"):
            assert english not in out
    else:
        assert re.findall(UNITS_EN, out)


def test_glyphs_the_serif_lacks_are_drawn_as_lines():
    from mmt_plans.note.pages import draw_markup, note_look

    backend = RecordingBackend(210.0, 297.0, note_look())
    width = draw_markup(backend, (30.0, 100.0), "V_{BA} ⊥ AB, V_{B} ∥ x", 3.2)
    texts = backend.texts()
    assert texts and not any(ch in t for t in texts for ch in "⊥∥")
    assert "AB," in " ".join(texts)
    # the perpendicular's foot and stem, the parallel's two strokes
    assert len(backend.named("line")) == 4
    xs = [x for c in backend.named("line") for x, _ in c.points()]
    assert 30.0 < min(xs) and max(xs) < 30.0 + width


def test_one_list_of_references_for_both_languages():
    """The en and uk lists name the same works in the same order: each pair of
    entries has the same years and page counts (issue 22: Kinytskyi's 467 p.
    in one, 660 p. in the other; Rattan only in en, Hlad only in uk)."""
    from mmt_plans.note.literature import entries

    en, uk = entries("en"), entries("uk")
    assert len(en) == len(uk) >= 10
    for a, b in zip(en, uk):
        years = re.compile(r"\b(?:19|20)\d\d\b")
        assert years.findall(a) == years.findall(b), (a, b)
        pages = re.compile(r"(\d+) [pс]\.$")
        assert pages.findall(a.strip()) == pages.findall(b.strip()), (a, b)


def test_the_note_drawn_straight_onto_its_pdf_is_the_recorded_pages_replayed(tmp_path):
    """write_note draws its pages straight onto one Cairo PDF (no recording):
    the bytes are those of the pages recorded first and replayed onto the
    PDF (render.cairo_pdf.pages_to_pdf), the route the sheets' PDFs take."""
    from mmt_plans.note.pages import note_look
    from mmt_plans.render.cairo_pdf import pages_to_pdf_bytes
    from mmt_plans.sheets.compose import compose

    solution = mmt_plans.solve(mmt_plans.load(SEED003))
    sheets = compose(solution, "uk")
    look = note_look()
    recorded = draw_note(
        solution, lambda w, h, title: RecordingBackend(w, h, look), "uk", composed=sheets
    )
    assert len(recorded) >= 12 and all(page.calls for page in recorded)
    target = write_note(solution, tmp_path / "note.pdf", lang="uk", composed=sheets)
    assert target.read_bytes() == pages_to_pdf_bytes(recorded)
