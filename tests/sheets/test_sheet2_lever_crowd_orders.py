"""Where the names of Zhukovsky's lever crowd at its textbook scale (the
detail views chosen round them) is asked of the lever lettered in
_CROWD_ORDERS orders, not in all _RETRY_ORDERS: the eleven-link lever's
last three orders cost 0.15 s of its 0.36 s and move no crowd. A lever lettered
so with no name far is the lever lettered in every order (no order is written
after one with none far): it is the one the sheet draws where no view is
chosen."""

from __future__ import annotations

from functools import cache
from pathlib import Path

import mmt_plans
from mmt_plans.generate import generate_one
from mmt_plans.render.recording import RecordingBackend
from mmt_plans.sheets import Page
from mmt_plans.sheets import sheet2 as sheet2_module
from mmt_plans.sheets.crowd import crowded_ends
from mmt_plans.sheets.sheet2 import (
    _CROWD_ORDERS,
    _RETRY_ORDERS,
    _lever_scale,
    compose_sheet2,
    lever_crowding,
    lever_details,
    sketch_lever,
)
from mmt_plans.solution import Solution
from mmt_plans.spec import loads

ROOT = Path(__file__).resolve().parents[2]
_RAW = sheet2_module._lever_view.__wrapped__


@cache
def _solution(path: str) -> Solution:
    return mmt_plans.solve(mmt_plans.load(ROOT / path))


def _plain(solution: Solution, orders: int):
    fa = solution.require_forces()
    look = RecordingBackend().look
    mu = _lever_scale(fa.lever)
    return sketch_lever(fa, mu, look, "en", [], one_per_line=False, orders=orders)


def test_a_lever_with_no_name_far_is_the_lever_in_every_order():
    solution = _solution("samples/six_link_press.toml")
    fewer, every = _plain(solution, _CROWD_ORDERS), _plain(solution, _RETRY_ORDERS)
    assert fewer.label_counts is not None and fewer.label_counts.far == 0
    assert [(c.name, c.args) for c in fewer.calls] == [(c.name, c.args) for c in every.calls]
    assert fewer.label_counts == every.label_counts


def test_eleven_links_views_are_those_of_the_lever_in_every_order(monkeypatch):
    solution = _solution("tests/data/hard/eleven_links_compound_hinge.toml")
    fa = solution.require_forces()
    look = RecordingBackend().look
    mu = _lever_scale(fa.lever)
    every = _plain(solution, _RETRY_ORDERS)
    assert (
        every.label_counts is not None and every.label_counts.far
    )  # crowded: orders past the third
    chosen = lever_details(fa, mu, crowded_ends(every, "en"), lever_crowding(fa, mu, look, "en"))
    assert chosen

    asked: list[tuple[tuple, int]] = []

    def counting(fa, mu_V, look, lang, arms, details, detail, **kw):
        asked.append((tuple(details), kw.get("orders", _RETRY_ORDERS)))
        return _RAW(fa, mu_V, look, lang, arms, details, detail, **kw)

    monkeypatch.setattr(sheet2_module, "_lever_view", sheet2_module._view_kept(counting))
    sheet = compose_sheet2(solution, RecordingBackend(), "en")
    assert sheet.details == chosen
    # the lever without views is lettered in the fewer orders only: never in every one
    plain = [orders for details, orders in asked if not details]
    assert plain == [_CROWD_ORDERS]


def test_gen212_lever_gets_no_view_its_third_order_clears():
    """gen 212: in two orders one name of the lever stands far (a view D round
    p was chosen for it, and its names crowded there: 6 findings); the third
    order letters it with none far, as all six do: no view."""
    made = generate_one(212)
    solution = mmt_plans.solve(loads(made.toml, made.name))
    fa = solution.require_forces()
    look = RecordingBackend().look
    mu = _lever_scale(fa.lever)
    two = sketch_lever(fa, mu, look, "en", [], one_per_line=False, orders=2)
    assert two.label_counts is not None and two.label_counts.far  # (why not two)
    composer = sheet2_module._Composer(fa, solution, look, "en", Page.of("A1"))
    assert composer.details == ()
