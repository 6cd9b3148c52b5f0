"""Sheet 2 draws each view of Zhukovsky's lever once while it is composed:
the detail views are chosen by weighing the lever drawn with each choice
(lever_crowding), and the composers then draw the chosen ones again (gen
176: 10 of its 60 views, 1.2 s). The sheet is the one drawn without."""

from __future__ import annotations

from collections import Counter
from functools import cache

import mmt_plans
from mmt_plans.generate import generate_one
from mmt_plans.render.recording import RecordingBackend
from mmt_plans.sheets import sheet2 as sheet2_module
from mmt_plans.sheets.sheet2 import compose_sheet2
from mmt_plans.solution import Solution
from mmt_plans.spec import loads

# the lever's view as drawn without keeping (_view_kept's)
_RAW = sheet2_module._lever_view.__wrapped__


@cache
def _solution() -> Solution:
    made = generate_one(176)
    return mmt_plans.solve(loads(made.toml, made.name))


def _drawn(monkeypatch, kept: bool) -> tuple[RecordingBackend, Counter[tuple]]:
    """gen 176's sheet 2 (its lever's detail views chosen at two scales), with
    the views kept or each drawn whenever asked; how often each was drawn."""
    solution = _solution()
    drawn: Counter[tuple] = Counter()

    def counting(
        fa,
        mu_V,
        look,
        lang,
        arms,
        details,
        detail,
        *,
        merge_arms=False,
        lines=None,
        again=None,
        orders=None,
    ):
        orders = sheet2_module._RETRY_ORDERS if orders is None else orders
        drawn[(mu_V, lang, tuple(details), detail, merge_arms, again, orders, len(arms))] += 1
        kw = dict(merge_arms=merge_arms, lines=lines, again=again, orders=orders)
        return _RAW(fa, mu_V, look, lang, arms, details, detail, **kw)

    view = sheet2_module._view_kept(counting) if kept else counting
    monkeypatch.setattr(sheet2_module, "_lever_view", view)
    backend = RecordingBackend()
    compose_sheet2(solution, backend, "en")
    return backend, drawn


def test_each_view_of_the_lever_is_drawn_once_and_the_sheet_is_the_same(monkeypatch):
    kept, drawn = _drawn(monkeypatch, kept=True)
    again, drawn_again = _drawn(monkeypatch, kept=False)
    assert max(drawn.values()) == 1
    assert max(drawn_again.values()) > 1, "some view is asked for more than once"
    assert set(drawn) == set(drawn_again)
    assert [(c.name, c.args) for c in kept.calls] == [(c.name, c.args) for c in again.calls]
