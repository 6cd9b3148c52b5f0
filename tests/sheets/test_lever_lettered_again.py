"""The lever's names lettered again on the laid-out sheet (#21): a view of
the lever whose names stand far is lettered again with those names tried at
GOST's 2.5 mm before they stand far (`_Composer.given_room`), in the order
that letters it best whatever box that takes, else (no room on the sheet for
the box grown) in those that keep its box. Gen 30 uk: detail view A (40:1),
its arms' names walled in round p by the lines that leave it, had ten names
standing 10-26 mm off; grown 4 mm taller it has no room, kept in its box."""

from __future__ import annotations

from lettering import composed_sheet2

CROWDED = 30  # gen 30 (RRR-RRR-RRR-RRP-RRR): view A of its lever, uk
VIEW = "zhukovsky-lever-detail"


def _in(rect, finding) -> bool:
    x, y = finding.where
    return rect.x - 1 <= x <= rect.right + 1 and rect.y - 1 <= y <= rect.top + 1


def test_regression_gen30_uk_lever_view_names_far_lettered_again_in_its_box():
    result, _, found = composed_sheet2(CROWDED, "uk")
    rect = result.placed[VIEW]
    near = [f for f in found if f.rule in ("label-near", "label-clear") and _in(rect, f)]
    # ten names far and one on a line before
    assert len(near) <= 5
    # the view drawn where it was laid out: its box as the sheet fitted it
    assert rect.height < 108.0

