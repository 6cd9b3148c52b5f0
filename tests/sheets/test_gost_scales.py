"""Every scale in a title block is a GOST 2.302 ratio (issue 13): the
mechanism's drawings take μ_l from 1, 2, 2.5, 4, 5 × 10^k, never 1.25 or 8."""

from __future__ import annotations

from pathlib import Path

import pytest

import mmt_plans
from mmt_plans.render.recording import RecordingBackend
from mmt_plans.sheets.sheet1 import compose_sheet1
from mmt_plans.sheets.sheet2 import compose_sheet2

ROOT = Path(__file__).resolve().parents[2]
SAMPLES = sorted((ROOT / "samples").glob("*.toml")) + [
    ROOT / "samples" / "tasks" / "seed003" / "task01_v1.toml"]

# GOST 2.302-68: reduction, natural size, enlargement
GOST = {"1:1", "1:2", "1:2.5", "1:4", "1:5", "1:10", "1:15", "1:20", "1:25", "1:40", "1:50",
        "1:75", "1:100", "1:200", "1:400", "1:500", "1:800", "1:1000", "2:1", "2.5:1", "4:1",
        "5:1", "10:1", "20:1", "40:1", "50:1", "100:1"}


@pytest.mark.parametrize("path", SAMPLES, ids=lambda p: p.stem)
def test_title_block_scales_are_gost(path):
    solution = mmt_plans.solve(mmt_plans.load(path))
    for compose in (compose_sheet1, compose_sheet2):
        backend = RecordingBackend()
        sheet = compose(solution, backend, "en")
        scale_texts = [c["content"] for c in backend.in_group("title-block")
                       if c.name == "text" and ":" in c["content"]
                       and c["content"].replace(".", "").replace(":", "").isdigit()]
        assert scale_texts, "no scale in the title block"
        assert set(scale_texts) <= GOST, scale_texts
        mu_l = sheet.scales["mu_l"]
        mantissa = mu_l * 1000 / 10 ** int(f"{mu_l * 1000:e}".split("e")[1])
        assert any(abs(mantissa - m) < 1e-9 for m in (1, 2, 2.5, 4, 5)), mu_l
