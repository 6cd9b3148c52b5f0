"""The lever's views lettered again on the laid-out sheet weighed by the
room the sheet has for them (#21, `_Composer._lever_again`): each with every
arm named on its own and with the arms along one line from p named by one
label, in the orders that letter it best whatever box that takes and in those
that keep its box; of those that find room, the one leaving fewest names
crowded. Gen 163 uk: detail view B (5:1) had the arms h13,15, h17,18,19,20 and
h21 left from p along its horizontal, each named on its own because one label
for them drew the view wider than its arms named each on its own: four names
stood 14-15 mm off, though the sheet has room right of the view."""

from __future__ import annotations

from lettering import composed_sheet2

CROWDED = 163  # gen 163 (RPP-RRR-RRP-RRP-RPR): view B of its lever, uk
VIEW = "zhukovsky-lever-detail"


def _in(rect, where) -> bool:
    x, y = where
    return rect.x - 1 <= x <= rect.right + 1 and rect.y - 1 <= y <= rect.top + 1


def test_regression_gen163_uk_lever_view_arms_along_one_line_one_label_where_room():
    result, view, found = composed_sheet2(CROWDED, "uk")
    rect = result.placed[VIEW]
    near = [f for f in found if f.rule in ("label-near", "label-clear") and _in(rect, f.where)]
    # four names far before (k11, Fi11, h14, h21)
    assert len(near) <= 3
    arms = [
        lab.text
        for lab in view.labels
        if lab.naming is not None
        and lab.naming.kind == "segment"
        and lab.groups
        and lab.groups[0] == VIEW
    ]
    # the arms left from p along its horizontal: one label
    assert any({"13", "15", "17", "21"} <= set(t[1:].split(",")) for t in arms)
    # the view keeps the layout's gap from every other drawing and table
    others = [r for name, r in result.placed.items() if name != VIEW]
    assert all(
        rect.right + 5.0 <= r.x + 1e-6
        or r.right + 5.0 <= rect.x + 1e-6
        or rect.top + 5.0 <= r.y + 1e-6
        or r.top + 5.0 <= rect.y + 1e-6
        for r in others
    )
