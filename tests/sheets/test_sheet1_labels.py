"""Sheet 1's lettering judged by the sheet linter's own rules (issue 21):
generated mechanisms whose sheet 1 broke label-near before ω1's arc was put
where its label finds room beside the arrowhead (seeds 13, 24: "ω1" 14-15 mm
from its arc), before a label found the places between the compass's (the
fine grid) and before a plan's crowded images were named first (seed 23:
"a33" 9.6 mm off; "ω1" on a line); and mechanisms whose sheet 1 broke it
before a link's ω/ε arcs were put where their labels find room and before the
placer's last resorts (a tighter fine grid, a leader from further out) came
ahead of a place far off; and seed tasks and hard cases, en and uk, whose
sheet 1 broke it before an ω arc with no room for its name was tried shorter,
a plan's short components were named among its images (crowded first) and a
walled-in joint's name was tried in the smaller figures, and a joint walled in at
position 0 named where it is drawn again (a plan position)."""

from __future__ import annotations

from pathlib import Path

import pytest

from mmt_plans.generate import generate_one
from mmt_plans.render.recording import RecordingBackend
from mmt_plans.sheets.lint import SheetView, lint
from mmt_plans.sheets.sheet1 import compose_sheet1
from mmt_plans.solution import solve
from mmt_plans.spec import loads

RULES = ["label-near", "label-clear", "names-unique", "arrows-named"]


def _findings(toml: str, name: str, lang: str) -> list[str]:
    """The linter's findings on sheet 1 of the mechanism file `toml`."""
    solution = solve(loads(toml, f"{name}.toml"))
    backend = RecordingBackend(841.0, 594.0)
    compose_sheet1(solution, backend, lang)
    return [str(f) for f in lint(SheetView.of(backend, lang, name), RULES)]


@pytest.mark.parametrize("seed", [13, 23, 24])
def test_every_label_of_sheet1_near_what_it_names(seed):
    g = generate_one(seed)
    assert _findings(g.toml, g.name, "en") == []


TASKS = Path(__file__).resolve().parents[2] / "samples" / "tasks"


@pytest.mark.parametrize(
    "task",
    [
        "seed003/task01_v5",  # "ω3" 8.5 mm from its arc
        "seed003/task08_v2",  # "C" 7.2 mm from its joint
        "seed002/task1_v05",  # "ω4" 14.6 mm from its arc
        "seed002/task5_v07",  # "ε4" 9.4 mm from its arc
    ],
)
def test_seed_tasks_sheet1_labels_near_what_they_name(task):
    path = TASKS / f"{task}.toml"
    solution = solve(loads(path.read_text(encoding="utf-8"), str(path)))
    backend = RecordingBackend(841.0, 594.0)
    compose_sheet1(solution, backend, "en")
    found = lint(SheetView.of(backend, "en", task), RULES)
    assert [str(f) for f in found] == []


@pytest.mark.parametrize("seed", [16, 21])  # "s5" 9.8 mm off its image; three far
def test_generated_sheet1_labels_near_what_they_name(seed):
    test_every_label_of_sheet1_near_what_it_names(seed)


HARD = Path(__file__).resolve().parents[1] / "data" / "hard"
LINT = Path(__file__).resolve().parents[1] / "data" / "lint"


@pytest.mark.parametrize("lang", ["en", "uk"])
@pytest.mark.parametrize(
    "path",
    [
        # an ω arc's name with no room beside its arrowhead, the arrowhead in
        # the bundle of the link's other positions: the arcs shorter (120°)
        TASKS / "seed003/task04_v1.toml",  # "ω4" 13.7 mm from its arc
        TASKS / "seed003/task04_v5.toml",  # "ω4" 8.8 mm
        TASKS / "seed002/task5_v04.toml",  # "ω4" 13.7 mm
        # a plan's short component amid the pole's arrowheads, named before the images
        TASKS / "seed003/task11_v4.toml",  # "aτBO2" 8.7 mm
        # a joint walled in by lines: its name in the positions' smaller figures
        HARD / "crosshead_mid_chain.toml",  # "B" 11.2 mm
        HARD / "six_points_10mm_apart.toml",  # "k" 10.4 mm, "l" 10.7 mm
        # joints 1.6 mm apart walled in at position 0 by the other positions'
        # main lines: named where they are drawn again, at a plan position
        LINT / "six_link_press_v01.toml",  # "B" 10.7 mm, "D" 11.0 mm
    ],
    ids=lambda p: p.stem,
)
def test_sheet1_labels_near_what_they_name_en_and_uk(path, lang):
    assert _findings(path.read_text(encoding="utf-8"), path.stem, lang) == []


@pytest.mark.parametrize(
    "seed",
    [
        130,  # "0" 6.5 mm, "11" 11.6 mm from the crank pin, walled in by the links
        140,  # "9" 7.4 mm, "10" 11.5 mm
        147,  # "11" 17.2 mm
    ],
)
@pytest.mark.parametrize("lang", ["en", "uk"])
def test_position_numbers_walled_in_on_the_crank_circle_near_the_output(seed, lang):
    """A position number with no room near the crank pin on its circle (the
    bundle of the positions' links all round it) is written where the
    textbook numbers the positions too, at the output point in that position:
    near it, as the linter's own rules judge."""
    g = generate_one(seed)
    assert _findings(g.toml, g.name, lang) == []


@pytest.mark.parametrize(
    "seed",
    [
        75,  # "ω1" 21.7 mm from its arc, written between the spokes
        162,  # "ω1" on a line, "10" 16.3 mm from the crank pin
    ],
)
def test_crank_arc_walled_in_by_spokes_drawn_outside_the_crank_circle(seed):
    """Where every arc inside the crank's circle is crossed by its positions'
    spokes so that ω1's name finds no room by its arrowhead, the arc goes round
    the pivot outside the circle: its name near it, as the linter judges."""
    test_every_label_of_sheet1_near_what_it_names(seed)


@pytest.mark.parametrize("lang", ["en", "uk"])
def test_acceleration_plan_components_named_first_where_many_stand_far(lang):
    """A chain of five dyads (generated seed 30) whose acceleration plan named
    "aτXB" 10.2 mm from its arrow in every order tried (the usual one, the
    crowded first): with the plan's components written before its images in
    one more order, every label of sheet 1 stands near what it names, as the
    linter's own rules judge."""
    g = generate_one(30)
    assert _findings(g.toml, g.name, lang) == []
