"""A sheet-1 plan with only one or two names crowded (far from what they name,
or on something) gets a detail view too, placed beside its plan; where the
plan with its crowd marked leaves another name crowded (a component whose
head the disc missed), the details are chosen again for both (#21)."""

from __future__ import annotations

from pathlib import Path

from lettering import near_findings, solved_seed

from mmt_plans.render.look import load_look
from mmt_plans.render.recording import RecordingBackend
from mmt_plans.sheets.crowd import crowded_names
from mmt_plans.sheets.lint import SheetView, label_clear, label_near
from mmt_plans.sheets.sheet1 import _plan_scales, compose_sheet1, sketch_plan, sketch_plan_details
from mmt_plans.solution import solve
from mmt_plans.spec import load

ROOT = Path(__file__).resolve().parents[2]


def _five_dyads():
    return solve(load(ROOT / "samples" / "five_dyads.toml"))


def test_five_dyads_sheet1_names_stand_near_in_en_and_uk():
    # main: 'g7' 6.5 mm from its image, beside the pole π of acceleration plan 3
    solution = _five_dyads()
    for lang in ("en", "uk"):
        backend = RecordingBackend(841.0, 594.0)
        compose_sheet1(solution, backend, lang)
        view = SheetView.of(backend, lang, f"five_dyads sheet 1 {lang}")
        assert [*label_near(view), *label_clear(view)] == []


def test_one_crowded_name_gets_a_detail_view_beside_its_plan():
    solution = _five_dyads()
    backend = RecordingBackend(841.0, 594.0)
    sheet = compose_sheet1(solution, backend, "en")
    plan, detail = sheet.placed["acceleration-plan-3"], sheet.placed["acceleration-plan-3-detail"]
    # the name crowded on the plan drawn alone: one
    look = load_look()
    mu = sheet.scales["mu_a 3"]
    plain, _ = sketch_plan(solution, 3, mu, "acceleration", look, "en")
    assert len(crowded_names(plain, "en")) == 1
    # the view beside its plan: one layout gap (5 or 8 mm) apart, no further
    gap_x = max(detail.left - plan.right, plan.left - detail.right, 0.0)
    gap_y = max(detail.bottom - plan.top, plan.bottom - detail.top, 0.0)
    assert max(gap_x, gap_y) <= 8.0 + 1e-6
    # nearer its own plan than any other plan
    for name, rect in sheet.placed.items():
        if "plan" in name and "detail" not in name and name != "acceleration-plan-3":
            far_x = max(detail.left - rect.right, rect.left - detail.right, 0.0)
            far_y = max(detail.bottom - rect.top, rect.bottom - detail.top, 0.0)
            assert max(far_x, far_y) > max(gap_x, gap_y)


def test_the_details_chosen_again_for_a_component_the_first_disc_left():
    # gen 65 (RRR-RRR-RRR-PRP-RRP), acceleration plan of position 10 one series
    # step coarse: 's7' crowded; the first disc letters it, but the plan then
    # names a^τ_MX (its head outside the disc) far from its arrow
    solution = solved_seed(65)
    mu = _plan_scales(solution, 1)["acceleration 10"]
    look = load_look()
    plain, _ = sketch_plan(solution, 10, mu, "acceleration", look, "en")
    assert len(crowded_names(plain, "en")) == 1
    made = sketch_plan_details(solution, 10, mu, "acceleration", look, "en")
    assert made is not None
    main, views, letters = made
    assert len(letters) == len(views) == 1
    assert near_findings(main, "en") == []
    assert near_findings(views[0], "en") == []
