"""Sheet 1's table of ω and ε: one number format, the table's own letter
height, the language's decimal separator (issue 21: seed-002 task 1 printed
ε as "1529.1885" in a shrunken font beside "333")."""

from __future__ import annotations

import re
from functools import cache
from pathlib import Path

import pytest

import mmt_plans
from mmt_plans.render.recording import RecordingBackend
from mmt_plans.sheets.sheet1 import compose_sheet1

ROOT = Path(__file__).resolve().parents[2]
TASK = ROOT / "samples" / "tasks" / "seed002" / "task1_v00.toml"
NUMBER = {"en": re.compile(r"-?\d+(\.\d+)?"), "uk": re.compile(r"-?\d+(,\d+)?")}


@cache
def _solution():
    return mmt_plans.solve(mmt_plans.load(TASK))


@pytest.mark.parametrize("lang", ["en", "uk"])
def test_eps_cells_are_rounded_numbers_at_the_table_height(lang):
    solution = _solution()
    backend = RecordingBackend()
    compose_sheet1(solution, backend, lang)
    backend.close()
    texts = [c for c in backend.in_group("table-omega-eps") if c.name == "text"]
    cells = [c for c in texts if NUMBER[lang].fullmatch(c["content"])]
    assert cells
    for c in cells:
        # the body's 3.5 mm, never shrunk to fit a long number into its cell
        assert c["size"] >= 3.5, c["content"]
        digits = c["content"].lstrip("-").replace(",", "").replace(".", "").lstrip("0")
        assert len(digits) <= 4, c["content"]
    values = [float(c["content"].replace(",", ".")) for c in cells]
    # every ε of a moving link at each planned position is in the table,
    # correctly rounded to the decimals it is shown with
    sweep = solution.sweep
    eps = [
        float(sweep.eps[lid][solution.entry(i)])
        for i in solution.plan_positions
        for lid in sweep.eps
        if abs(float(sweep.eps[lid][solution.entry(i)])) > 100.0
    ]
    assert any(abs(e) > 1000.0 for e in eps), "the case has an ε of four digits"
    for e in eps:
        assert any(abs(v - e) <= 0.5 for v in values), e
