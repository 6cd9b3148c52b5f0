"""The title block of both sheets (issue 13): designation, the sheet's name,
organisation, scale, sheet i of n, from the file, --field, or defaults; and
batch --field reaching the sheets and the resume manifest."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

import mmt_plans
from mmt_plans.drawing.page import Page
from mmt_plans.i18n import catalogue
from mmt_plans.render.recording import RecordingBackend
from mmt_plans.sheets.sheet1 import compose_sheet1
from mmt_plans.sheets.sheet2 import compose_sheet2

ROOT = Path(__file__).resolve().parents[2]
SLIDER = ROOT / "samples" / "offset_slider_crank.toml"


@pytest.fixture(scope="module")
def solution():
    return mmt_plans.solve(mmt_plans.load(SLIDER))


def cells(solution, compose, lang):
    backend = RecordingBackend()
    compose(solution, backend, lang)
    block = Page.of("A1").title_block
    out: dict[str, list[str]] = {}
    for c in backend.in_group("title-block"):
        if c.name != "text":
            continue
        for cell in ("designation", "title", "organisation", "sheet", "sheets", "scale"):
            r = block.cell(cell)
            if r.left <= c["pos"][0] <= r.right and r.bottom <= c["pos"][1] <= r.top:
                out.setdefault(cell, []).append(c["content"])
    return out


@pytest.mark.parametrize("lang", ["en", "uk"])
def test_defaults_on_both_sheets(solution, lang):
    words = catalogue(lang).words("title_block")
    for n, compose in ((1, compose_sheet1), (2, compose_sheet2)):
        got = cells(solution, compose, lang)
        designation = got["designation"][0]
        assert designation.startswith(words["designation_prefix"] + ".")
        assert designation.endswith(f".0{n}")
        assert words[f"sheet_name_{n}"] in " ".join(got["title"])
        assert got["organisation"] == [words["organisation_default"]]
        assert str(n) in got["sheet"] and "2" in got["sheets"]
        assert got["scale"] and ":" in got["scale"][0]
    # one document, one designation in both languages, no underscores (issue 21)
    other = "uk" if lang == "en" else "en"
    assert cells(solution, compose_sheet1, other)["designation"] == cells(
        solution, compose_sheet1, lang)["designation"]
    assert "_" not in cells(solution, compose_sheet1, lang)["designation"][0]


def test_fields_from_the_file_or_the_command_line(solution):
    sheet = {
        "drawing_number": "ТММ.КП.05.00.00",
        "sheet_name": "Кінематика",
        "organisation": "НТУ",
        "group": "МТ-21",
    }
    changed = solution.mechanism.with_changes(sheet=sheet)
    fielded = mmt_plans.solve(changed)
    for compose in (compose_sheet1, compose_sheet2):
        got = cells(fielded, compose, "uk")
        assert got["designation"] == ["ТММ.КП.05.00.00"]
        assert "Кінематика" in got["title"]
        assert got["organisation"] == ["НТУ", "МТ-21"]


def test_batch_passes_fields_through_and_records_them(tmp_path):
    from mmt_plans.batch import MANIFEST_NAME, process_file

    out = tmp_path / "item"
    fields = {"drawing_number": "KEY.42", "author": "I. Petrenko"}
    result = process_file(SLIDER, out, formats=("svg",), fields=fields)
    assert result.ok, result.message
    manifest = json.loads((out / MANIFEST_NAME).read_text(encoding="utf-8"))
    assert manifest["settings"]["fields"] == fields
    svg = (out / "sheet1.svg").read_text(encoding="utf-8")
    assert "KEY.42" in svg and "I. Petrenko" in svg
    # the same fields: kept; other fields: redone
    again = process_file(SLIDER, out, formats=("svg",), fields=fields, force=False)
    assert again.kept
    other = process_file(SLIDER, out, formats=("svg",), fields={"drawing_number": "KEY.43"}, force=False)
    assert not other.kept and other.ok
    assert "KEY.43" in (out / "sheet1.svg").read_text(encoding="utf-8")


def test_batch_command_takes_field(tmp_path):
    from click.testing import CliRunner

    from mmt_plans.cli.batch import batch

    runner = CliRunner()
    res = runner.invoke(
        batch, [str(SLIDER), "-o", str(tmp_path), "--format", "svg", "--jobs", "1", "--field", "group=MT-21"]
    )
    assert res.exit_code == 0, res.output
    assert "MT-21" in (tmp_path / "offset_slider_crank" / "sheet1.svg").read_text(encoding="utf-8")
    bad = runner.invoke(batch, [str(SLIDER), "-o", str(tmp_path), "--field", "nonsense=1"])
    assert bad.exit_code == 2
