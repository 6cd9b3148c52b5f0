"""The lever's detail disc weighed on the drawing (#21): where a small disc
that spreads a tight crowd of images holds fewer of the crowded names than the
wide disc round them all, both are drawn and the one that leaves fewer names
far or on something is taken."""

from __future__ import annotations

from functools import cache

from mmt_plans.generate import generate_one
from mmt_plans.render.look import load_look
from mmt_plans.sheets.sheet2 import (
    _lever_scale,
    crowded_ends,
    lever_crowding,
    lever_details,
    sketch_lever,
)
from mmt_plans.solution import solve
from mmt_plans.spec import loads

TIGHT = 141  # gen 141 (RRR-RRR-PRP-RRR): ten images within 8 mm of p at the textbook's μV
WIDE = 91  # gen 91 (RRP-RRP-RRR-PRP-RRP): the small disc leaves long arms crowding round it


@cache
def _chosen(seed: int, lang: str = "en"):
    """The lever's crowding, and its details found without and with weighing."""
    g = generate_one(seed)
    fa = solve(loads(g.toml, f"{g.name}.toml")).require_forces()
    mu, look = _lever_scale(fa.lever), load_look()
    crowd = crowded_ends(sketch_lever(fa, mu, look, lang, []), lang)
    crowding = lever_crowding(fa, mu, look, lang)
    return crowding, lever_details(fa, mu, crowd), lever_details(fa, mu, crowd, crowding)


def test_a_tight_crowd_of_images_gets_the_small_disc_that_spreads_it():
    crowding, wide, weighed = _chosen(TIGHT)
    assert weighed[0].radius < wide[0].radius and weighed[0].ratio > wide[0].ratio
    # fewer names of the lever and its views stand far or on something
    assert crowding(weighed) < crowding(wide)


def test_the_wide_disc_is_kept_where_it_letters_better():
    crowding, wide, weighed = _chosen(WIDE)
    assert weighed == wide


SHRUNK = 6  # gen 6 (RPP-RPR-RPP-RPR): its lever reaches the sheet a step smaller


def test_of_discs_that_letter_it_alike_the_view_drawn_largest():
    """At the textbook's μV the wide disc (2.5:1) and tighter ones letter the
    lever alike; the one whose view is drawn largest is taken, and it still
    letters the lever a series step smaller, where the wide one crowds."""
    from mmt_plans.sheets.common import scale_step

    crowding, wide, weighed = _chosen(SHRUNK)
    assert weighed[0].ratio * weighed[0].radius > wide[0].ratio * wide[0].radius
    g = generate_one(SHRUNK)
    fa = solve(loads(g.toml, f"{g.name}.toml")).require_forces()
    smaller = lever_crowding(fa, scale_step(_lever_scale(fa.lever), 1), load_look(), "en")
    assert smaller(weighed) < smaller(wide)
