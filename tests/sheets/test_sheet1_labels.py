"""Sheet 1's lettering judged by the sheet linter's own rules (issue 21):
generated mechanisms whose sheet 1 broke label-near before ω1's arc was put
where its label finds room beside the arrowhead (seeds 13, 24: "ω1" 14-15 mm
from its arc), before a label found the places between the compass's (the
fine grid) and before a plan's crowded images were named first (seed 23:
"a33" 9.6 mm off; "ω1" on a line)."""

from __future__ import annotations

import pytest

from mmt_plans.generate import generate_one
from mmt_plans.render.recording import RecordingBackend
from mmt_plans.sheets.lint import SheetView, lint
from mmt_plans.sheets.sheet1 import compose_sheet1
from mmt_plans.solution import solve
from mmt_plans.spec import loads

RULES = ["label-near", "label-clear", "names-unique", "arrows-named"]


@pytest.mark.parametrize("seed", [13, 23, 24])
def test_every_label_of_sheet1_near_what_it_names(seed):
    g = generate_one(seed)
    solution = solve(loads(g.toml, f"{g.name}.toml"))
    backend = RecordingBackend(841.0, 594.0)
    compose_sheet1(solution, backend, "en")
    found = lint(SheetView.of(backend, "en", g.name), RULES)
    assert [str(f) for f in found] == []
