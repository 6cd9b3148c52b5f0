"""One language per sheet (issue 13): a Ukrainian sheet has no English word
or unit and no decimal point; no sheet prints None, nan or inf."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

import mmt_plans
from mmt_plans.i18n import catalogue
from mmt_plans.render.recording import RecordingBackend
from mmt_plans.sheets.sheet1 import compose_sheet1
from mmt_plans.sheets.sheet2 import compose_sheet2

ROOT = Path(__file__).resolve().parents[2]
SAMPLES = sorted((ROOT / "samples").glob("*.toml"))
ENGLISH = re.compile(r"\b(m/s|mm|N·m|kg|rpm|position|plan|link|group|force|scale|diagram|"
                     r"Pos|Quantity|Value|Sheet|Scale|Drawn|within|passed|divisions|turn|"
                     r"press|crank|slider|rocker|shaper)\b", re.IGNORECASE)


def texts(solution, lang):
    out = []
    for compose in (compose_sheet1, compose_sheet2):
        backend = RecordingBackend()
        compose(solution, backend, lang)
        out += [c["content"] for c in backend.named("text")]
    return out


@pytest.mark.parametrize("path", SAMPLES, ids=lambda p: p.stem)
def test_sheets_in_one_language(path):
    solution = mmt_plans.solve(mmt_plans.load(path))
    for lang in ("en", "uk"):
        for t in texts(solution, lang):
            assert not re.search(r"\b(None|nan|inf)\b", t), t
    prefix = catalogue("uk").words("title_block")["designation_prefix"]
    for t in texts(solution, "uk"):
        assert not ENGLISH.search(t), t
        if t.startswith(prefix + "."):  # the designation: dots part its codes, not decimals
            assert re.fullmatch(re.escape(prefix) + r"(\.[0-9А-ЯІЇЄҐ_-]+)+", t), t
            continue
        assert not re.search(r"\d\.\d", t), t  # the decimal comma
