"""A group's drawing lettered again on the laid-out sheet (#21,
`_Composer.given_room`): where a name stands far, the group and the driving
link are lettered in the order that letters them best with their names
tried at GOST's 2.5 mm too, as the loaded mechanism and the lever are; the
drawing then goes where it was, else moved by as much as it grew, else into
the room nearest it (`SheetLayout.room_near`). Gen 240 en: group 2-3 at
1:100 has arms 2.8 mm long in a knot of reactions; h'6 stood 11.7 mm off
with no leader. Lettered again it is 9 mm taller, finds no room under the
table above it, and goes into the empty column below the driving link."""

from __future__ import annotations

from lettering import composed_sheet2

SMALL_GROUP = 240  # gen 240 (RRR-RRR-RRR-RRR): its group 2-3 drawn small


def test_the_small_groups_arm_names_stand_by_their_arms():
    result, view, findings = composed_sheet2(SMALL_GROUP, "en")
    group = result.placed["group-2-3"]
    arms = [lab for lab in view.labels if "group-2-3" in lab.groups and lab.text.startswith("h'")]
    assert arms  # its arms are named
    inside = [
        f
        for f in findings
        if group.x - 1 <= f.where[0] <= group.right + 1 and group.y - 1 <= f.where[1] <= group.top + 1
    ]
    assert inside == []
    # every drawing and table keeps the layout's gap and stays in the frame
    assert result.layout.problems(clearance=result.layout.gap - 1e-6) == []
