"""The note's figure of the loaded mechanism shows its detail view (#21):
where sheet 2 draws the mechanism's crowd again at a larger scale (generated
seed 63), the figure has it as its part b), the caption says what b) is and
the text why."""

from __future__ import annotations

import mmt_plans
from mmt_plans.generate import generate_one
from mmt_plans.i18n import catalogue
from mmt_plans.note import note_document
from mmt_plans.sheets.compose import compose
from mmt_plans.spec import loads

NBSP = "\u00a0"


def _flat(text: str) -> str:
    return text.replace("{", "").replace("}", "").replace(NBSP, " ").replace("\u2212", "-")


def test_the_loaded_mechanisms_figure_shows_its_detail_view():
    lang = "en"
    w = catalogue(lang).words("note")
    g = generate_one(63)
    solution = mmt_plans.solve(loads(g.toml, f"{g.name}.toml"))
    c = compose(solution, lang)
    details = [d for d in c.sheet(2).drawings if d.startswith("force-mechanism-detail")]
    assert details, "the crowded loaded mechanism has no detail view on sheet 2"
    doc = note_document(solution, lang, composed=c)
    figures = [
        f for f in doc.content.figures.values() if any("force-mechanism" in p.groups for p in f.parts)
    ]
    assert len(figures) == 1
    assert [p.groups for p in figures[0].parts] == [("force-mechanism",)] + [(d,) for d in details]
    text = " ".join(_flat(ln.text) for p in doc.pages for ln in p.lines if ln.text)
    assert _flat(str(w["loads_details_drawn"]))[:40] in text
    letters = str(w["part_letters"])
    assert _flat(str(w["fig_loads_parts"]).format(parts=letters[1]))[:30] in text
