"""Sheet 2 asks whether even the coarsest scales fit (`_Composer.could_fit`,
every drawing lettered at those scales) only once the scales a step past
the textbook's fit nowhere: most sheets fit by then, and asked at the
textbook's the question cost 30-45 % of their sheet 2 (issue 21: the
eleven-link hard case 3.6 s -> 2.8 s CPU)."""

from __future__ import annotations

from pathlib import Path

import mmt_plans
from mmt_plans.render.recording import RecordingBackend
from mmt_plans.sheets import sheet2 as sheet2_module
from mmt_plans.sheets.sheet2 import compose_sheet2

HARD = Path(__file__).resolve().parents[1] / "data" / "hard"


def _trials(monkeypatch) -> list[tuple[str, dict[str, int], bool]]:
    """What the composers ask, in order: ("fits" | "could_fit", steps, answer)."""
    asked: list[tuple[str, dict[str, int], bool]] = []
    for name in ("fits", "could_fit"):
        real = getattr(sheet2_module._Composer, name)

        def recording(self, steps, real=real, name=name):
            answer = real(self, steps)
            asked.append((name, dict(steps), answer))
            return answer

        monkeypatch.setattr(sheet2_module._Composer, name, recording)
    return asked


def test_a_sheet_that_fits_a_step_coarser_never_asks_about_the_coarsest(monkeypatch):
    # The eleven links' drawings fit nowhere at the textbook's scales and
    # finer; a series step coarser they do. The coarsest scales are not
    # drawn to ask whether they fit (they did, at the textbook's step).
    solution = mmt_plans.solve(mmt_plans.load(HARD / "eleven_links_compound_hinge.toml"))
    asked = _trials(monkeypatch)
    compose_sheet2(solution, RecordingBackend(), "en")
    assert not [a for a in asked if a[0] == "could_fit"]
    first = next(a for a in asked if a[0] == "fits" and a[2])
    assert first[1]["lever"] == 1, "the first scales that fit: a step past the textbook's"
    before = asked[: asked.index(first)]
    assert {a[1]["lever"] for a in before} == {0, 1}, "the textbook's step tried first"


def test_the_coarsest_are_asked_about_once_a_step_coarser_fits_nowhere(monkeypatch):
    # A sheet too small for the drawings a step past the textbook's scales
    # (A2 for six_link_press): the coarsest scales asked about once, after
    # every trial of that step, then the coarser steps tried.
    solution = mmt_plans.solve(mmt_plans.load(HARD.parents[2] / "samples" / "six_link_press.toml"))
    asked = _trials(monkeypatch)
    page = sheet2_module.Page.of("A2")
    compose_sheet2(solution, RecordingBackend(page.width, page.height), "en", page=page)
    questions = [k for k, a in enumerate(asked) if a[0] == "could_fit"]
    assert len(questions) == 1
    before, after = asked[: questions[0]], asked[questions[0] + 1 :]
    assert {a[1]["lever"] for a in before} == {0, 1}
    assert not any(a[2] for a in before)
    assert any(a[1]["lever"] >= 2 for a in after)


def test_a_no_with_the_mechanism_as_its_pins_box_is_asked_again_lettered(monkeypatch):
    # The packer is not monotone: gen 30's mechanism lettered (158 x 146 mm)
    # packs at scales where the box of its pins (115 x 95 mm) does not. Where
    # the pins' box finds no arrangement, `could_fit` asks `fits` with the
    # mechanism lettered before it says the coarsest scales cannot fit.
    from mmt_plans.generate import generate_one
    from mmt_plans.sheets.sheet2 import _COARSEST, _Composer

    g = generate_one(30)
    solution = mmt_plans.solve(mmt_plans.loads(g.toml, f"{g.name}.toml"))
    fa = solution.require_forces()
    backend = RecordingBackend(841.0, 594.0)
    page = sheet2_module.Page.of("A1")
    composer = _Composer(fa, solution, backend.look, "en", page)
    coarsest = composer._steps(_COARSEST, _COARSEST)
    scales = composer.scales(coarsest)
    sketches = dict(composer._sketched(scales, [], mechanism=False))
    pins = dict(composer._pin_boxes(scales, empty=True))["force-mechanism"]
    lettered = composer.extent(composer.sketches(scales)[0]["force-mechanism"])
    assert pins.width < lettered.width and pins.height < lettered.height
    assert composer.fits(coarsest), "the coarsest scales fit with the mechanism lettered"

    # a packer that finds no place for the pins' box (as gen 30's at a finer scale)
    real = _Composer.arrange

    def no_room_for_pins(self, sketches, boxes=None):
        return None if boxes else real(self, sketches, boxes)

    monkeypatch.setattr(_Composer, "arrange", no_room_for_pins)
    assert composer.arrange(sketches, {"force-mechanism": pins}) is None
    assert composer.could_fit(coarsest)
