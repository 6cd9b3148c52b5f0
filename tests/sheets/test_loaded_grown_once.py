"""The loaded mechanism lettered again on the laid-out sheet (`grow`, #21)
finds the forces whose names crowd on the drawing as the sheet was laid out
with it: given that drawing (the composer's, `laid_out`), it does not draw it
again, and letters the same."""

from __future__ import annotations

from lettering import solved_seed

import mmt_plans.sheets.sheet2 as sheet2
from mmt_plans.render.look import load_look
from mmt_plans.sheets.common import length_scale_step
from mmt_plans.sheets.sheet2 import (
    crowded_names,
    loaded_details,
    sketch_loaded_detail,
    sketch_loaded_mechanism,
)

CROWDED = 63  # gen 63: its forces' names crowd round its core (test_loaded_detail)


def _counted(monkeypatch) -> list[int]:
    """How many drawings `_loaded_view` makes from here on."""
    made = [0]
    drawing = sheet2._loaded_drawing

    def counted(*args, **kwargs):
        made[0] += 1
        return drawing(*args, **kwargs)

    monkeypatch.setattr(sheet2, "_loaded_drawing", counted)
    return made


def test_the_grown_loaded_mechanism_letters_the_same_without_drawing_it_again(monkeypatch):
    solution = solved_seed(CROWDED)
    fa = solution.require_forces()
    mu = length_scale_step(float(solution.mu_l), 2)
    look = load_look()
    plain = sketch_loaded_mechanism(fa, mu, look, "en")
    details = loaded_details(fa, mu, crowded_names(plain, "en", anchors=True))
    assert details
    made = _counted(monkeypatch)
    for draw in (
        lambda **kw: sketch_loaded_mechanism(fa, mu, look, "en", details=details, **kw),
        lambda **kw: sketch_loaded_detail(fa, mu, look, "en", details[0], **kw),
    ):
        laid_out = draw()
        made[0] = 0
        alone = draw(grow=True)
        drew_alone = made[0]
        made[0] = 0
        given = draw(grow=True, laid_out=laid_out)
        assert made[0] < drew_alone  # the laid-out drawing not drawn again
        assert _drawn(given) == _drawn(alone)  # and lettered the same


def _drawn(sketch) -> list[tuple]:
    """A drawing's calls as drawn: what each is, where, and what its label names
    (not the label's number, counted on through the recordings)."""
    return [
        (
            c.name,
            dict(c.args),
            c.groups,
            None if c.naming is None else (c.naming.markup, c.naming.kind, c.naming.anchor),
        )
        for c in sketch.calls
    ]
