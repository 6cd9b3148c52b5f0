"""The same input gives the same bytes: SVG, PNG, and PDFs (sheets and the
note) whose dates are fixed (SOURCE_DATE_EPOCH, else 2000-01-01)."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

import mmt_plans

ROOT = Path(__file__).resolve().parents[1]
SMALL = ROOT / "samples" / "offset_slider_crank.toml"


@pytest.fixture(scope="module")
def analysis():
    return mmt_plans.solve(mmt_plans.load(SMALL))


def write_all(analysis, folder: Path) -> dict[str, bytes]:
    from mmt_plans.note import write_note
    from mmt_plans.sheets.compose import write_sheets

    paths = write_sheets(analysis, folder, formats=("svg", "pdf", "png"), sheets=[1])
    paths.append(write_note(analysis, folder / "note.pdf"))
    return {p.name: p.read_bytes() for p in paths}


def test_two_runs_give_identical_bytes(analysis, tmp_path, monkeypatch):
    monkeypatch.delenv("SOURCE_DATE_EPOCH", raising=False)
    first = write_all(analysis, tmp_path / "a")
    second = write_all(analysis, tmp_path / "b")
    assert first.keys() == {"sheet1.svg", "sheet1.pdf", "sheet1.png", "note.pdf"}
    for name in first:
        assert first[name] == second[name], name
    for name in ("sheet1.pdf", "note.pdf"):
        assert re.search(rb"/CreationDate \((D:)?20000101000000Z\)", first[name]), name
        assert re.search(rb"/ModDate \((D:)?20000101000000Z\)", first[name]), name


def test_source_date_epoch_sets_the_pdf_dates(analysis, tmp_path, monkeypatch):
    from mmt_plans.render.export import svg_to_pdf
    from mmt_plans.render.svg import SvgBackend

    monkeypatch.setenv("SOURCE_DATE_EPOCH", "1700000000")
    backend = SvgBackend(210, 297, title="page")
    backend.line((10, 10), (100, 100))
    data = svg_to_pdf(backend.to_string(), tmp_path / "p.pdf").read_bytes()
    assert re.search(rb"/CreationDate \((D:)?20231114221320Z\)", data)
