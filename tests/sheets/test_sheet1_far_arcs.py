"""Sheet 1's ω and ε names among crowded links (issue 21): where no arc of a
link at the usual radii, 3 or 6 mm larger, or shorter leaves its names a free
place near their arrowheads and a name stands far, the mechanism is lettered
once more with such arcs tried larger still (_FAR_WIDER), their arrowheads
out of the wide bundle of the positions' lines (never over a name written,
a block or a pin at little cost), and the better lettering is kept. Seed 178
(five groups, RPP-RRR-RRR-RRR-RPP): "ε9" stood 9.8 mm from its arc."""

from __future__ import annotations

import pytest

from mmt_plans.generate import generate_one
from mmt_plans.render.recording import RecordingBackend
from mmt_plans.sheets.lint import SheetView, lint
from mmt_plans.sheets.sheet1 import compose_sheet1
from mmt_plans.solution import solve
from mmt_plans.spec import loads


@pytest.mark.parametrize("lang", ["en", "uk"])
def test_every_omega_and_epsilon_name_stands_near_its_arc(lang):
    g = generate_one(178)
    solution = solve(loads(g.toml, f"{g.name}.toml"))
    backend = RecordingBackend(841.0, 594.0)
    compose_sheet1(solution, backend, lang)
    view = SheetView.of(backend, lang, g.name)
    named = [lab.text for lab in view.labels if lab.text[:1] in "ωε"]
    assert len(named) >= 8  # every moving link's at both plan positions
    far = [str(f) for f in lint(view, ["label-near"]) if f.message[1:2] in "ωε"]
    assert far == []
