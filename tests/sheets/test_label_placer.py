"""The one rule of the label placer (drawing/labels.py), judged by the sheet
linter's own measures (sheets/lint.py, shapely on the recording): every label
within NEAR_MM of what it names, or joined to it by a thin leader of its own
that crosses no main line and no lettering; and on no line and no label.
Crowded cases built by hand, each with a free place the rule can reach."""

from __future__ import annotations

import math

import numpy as np
import pytest
from shapely.geometry import LineString, Point, box

from mmt_plans.drawing.detail import rim_anchors
from mmt_plans.drawing.labels import NEAR_MM, Labels
from mmt_plans.drawing.sketch import Sketch
from mmt_plans.render.recording import Line, RecordingBackend, Text
from mmt_plans.sheets.lint import SheetView, lint


def _sketch() -> Sketch:
    return Sketch(RecordingBackend().look)


def _findings(sk: Sketch, rules: list[str]) -> list[str]:
    with_group = RecordingBackend(sk.width, sk.height)
    with with_group.group("d", "plan"):
        for c in sk.calls:
            with_group.calls.append(c.with_changes(groups=("d", *c.groups)))
    return [str(f) for f in lint(SheetView.of(with_group, "en", "t"), rules)]


def _leaders(sk: Sketch) -> list[Line]:
    return [c for c in sk.calls if isinstance(c, Line) and c.naming is not None]


def test_a_free_place_near_the_point_is_taken_without_a_leader():
    sk = _sketch()
    sk.line((-20.0, 0.0), (20.0, 0.0), "main")
    labels = Labels(sk, 3.5)
    footprint = labels.place((0.0, 0.0), "B", towards=(1.0, 1.0))
    assert footprint.distance(Point(0.0, 0.0)) <= NEAR_MM
    assert _leaders(sk) == []
    assert _findings(sk, ["label-near", "label-clear"]) == []


def test_a_point_in_a_fan_of_thin_lines_is_led_to_a_free_place():
    """Thin lines 3 mm apart fill the near places: the label goes further out
    with a leader that may cross the thin lines but no main line; the main
    lines of the fan (every fourth) are never crossed."""
    sk = _sketch()
    for k in range(16):
        u = np.array([math.cos(k * math.pi / 8 + 0.1), math.sin(k * math.pi / 8 + 0.1)])
        sk.line(tuple(1.5 * u), tuple(9.0 * u), "main" if k % 4 == 0 else "thin")
    for r in (3.0, 4.5, 6.0, 7.5):
        sk.circle((0.0, 0.0), r, "thin")
    labels = Labels(sk, 3.5)
    labels.place((0.0, 0.0), "O", towards=(-1.0, 1.0))
    assert len(_leaders(sk)) == 1
    assert _findings(sk, ["label-near", "label-clear"]) == []


def test_a_leader_never_crosses_a_main_line_or_lettering():
    """A main square round the point at 8 mm, crowded inside: no leader can
    leave it. The label is written clear of every line outside the square
    rather than on the lines near the point (a label on lines reads as
    neither), and counted as one that could not keep the rule."""
    sk = _sketch()
    sq = [(-8.0, -8.0), (8.0, -8.0), (8.0, 8.0), (-8.0, 8.0), (-8.0, -8.0)]
    for a, b in zip(sq, sq[1:]):
        sk.line(a, b, "main")
    for y in np.arange(-7.0, 7.5, 1.5):
        sk.line((-7.5, float(y)), (7.5, float(y)), "thin")
    sk.text((0.0, 12.0), "TEXT", 3.5, anchor="center", valign="middle")
    labels = Labels(sk, 3.5)
    labels.place((0.0, 0.0), "C", towards=(0.0, 1.0))
    assert _leaders(sk) == []
    assert labels.far == 1 and labels.unsettled == 0
    assert _findings(sk, ["label-clear"]) == []


def test_many_names_of_one_crowded_point_each_near_or_led():
    """Twelve forces from one point, each named by its head: every name near
    its arrow or led to it, none on a line or on another name."""
    sk = _sketch()
    labels = Labels(sk, 3.5, spacing=None)
    arrows = []
    for k in range(12):
        u = np.array([math.cos(k * math.pi / 6), math.sin(k * math.pi / 6)])
        end = tuple(12.0 * u)
        sk.arrow((0.0, 0.0), end, "main", head_length=3.0, head_width=1.0)
        arrows.append(((0.0, 0.0), end))
    for k, (s, e) in enumerate(arrows):
        labels.later_arrow(s, e, f"F_{{{k + 1}}}")
    labels.write_later()
    assert _findings(sk, ["label-near", "label-clear", "arrows-named"]) == []


def test_a_segments_name_may_be_led_from_along_it():
    """A link's name whose sides are full near the middle: led from a point
    along the link, the leader leaving it, crossing no main line."""
    sk = _sketch()
    sk.line((0.0, 0.0), (40.0, 0.0), "main")
    for x in np.arange(12.0, 28.5, 1.5):
        sk.line((float(x), -7.0), (float(x), 7.0), "thin")
    labels = Labels(sk, 3.5)
    footprint = labels.place_along((0.0, 0.0), (40.0, 0.0), "AB")
    seg = LineString([(0.0, 0.0), (40.0, 0.0)])
    assert footprint.distance(seg) <= NEAR_MM or len(_leaders(sk)) == 1
    assert _findings(sk, ["label-near", "label-clear"]) == []
    texts = [c for c in sk.calls if isinstance(c, Text)]
    assert texts and all(c.naming is not None and c.naming.kind == "segment" for c in texts)


def test_a_point_inside_a_block_is_named_beside_the_block():
    """A slider's pin inside its 12 x 7 mm block on a guide crowded above and
    below by lines 3 mm apart: the only free places are off the block's ends,
    more than NEAR_MM from the pin and out of a leader's reach (a leader from
    the pin would cross the block's outline). The name goes beside the block,
    within NEAR_MM of its outline, as the linter measures it."""
    sk = _sketch()
    for y in (4.5, 7.5, 10.5, 13.5):
        for s in (1.0, -1.0):
            sk.line((-40.0, s * y), (40.0, s * y), "thin")
    sk.polygon([(-6.0, -3.5), (6.0, -3.5), (6.0, 3.5), (-6.0, 3.5)], "main", "white")
    sk.circle((0.0, 0.0), 0.8, "main", "black")
    labels = Labels(sk, 3.5)
    footprint = labels.place((0.0, 0.0), "H", towards=(0.0, 1.0))
    assert footprint.distance(Point(0.0, 0.0)) > NEAR_MM  # beyond the block's end
    assert footprint.distance(box(-6.0, -3.5, 6.0, 3.5)) <= NEAR_MM
    assert _leaders(sk) == [] and labels.far == 0
    assert _findings(sk, ["label-near", "label-clear"]) == []


def test_a_point_ringed_by_many_thin_lines_is_led_across_them():
    """Eight thin circles 1.5 mm apart round a point (a lever's arms and lines
    of action round its pole): no place near it is free and every leader
    crosses eight thin lines. A leader across them still ties the name to the
    point; a name written beyond them untied would name nothing."""
    sk = _sketch()
    for k in range(8):
        sk.circle((0.0, 0.0), 2.5 + 1.5 * k, "thin")
    labels = Labels(sk, 3.5)
    labels.place((0.0, 0.0), "p", towards=(-1.0, 1.0))
    assert len(_leaders(sk)) == 1 and labels.far == 0
    assert _findings(sk, ["label-near", "label-clear"]) == []


def test_a_pocket_between_the_compass_places_is_found_before_a_leader():
    """A point on a main line over a filled base, thin lines 3 mm apart
    either side and a thin line 5.1 mm above: the only free place near it is
    a pocket 4.3 mm tall over the point, which no place of the compass fits.
    The fine grid finds it; the label stands in it with no leader."""
    sk = _sketch()
    sk.polygon([(-30.0, 0.0), (30.0, 0.0), (30.0, -20.0), (-30.0, -20.0)], "main", "black")
    sk.line((-30.0, 5.1), (30.0, 5.1), "thin")
    for x in 3.0 + 3.0 * np.arange(6):
        sk.line((-float(x), 0.0), (-float(x), 5.1), "thin")
        sk.line((float(x), 0.0), (float(x), 5.1), "thin")
    labels = Labels(sk, 3.5)
    footprint = labels.place((0.0, 0.0), "B", towards=(0.0, 1.0))
    assert footprint.distance(Point(0.0, 0.0)) <= NEAR_MM
    assert box(-3.0, 0.0, 3.0, 5.1).contains(footprint)
    assert _leaders(sk) == [] and labels.far == 0
    assert _findings(sk, ["label-near", "label-clear"]) == []


def test_rooms_are_the_free_places_near_a_point_clear_of_a_shape_to_come():
    """`rooms` writes nothing and names only places the rule allows: within
    NEAR_MM of the point, on no line drawn, and off the shape still to be
    drawn (an arc) by the clearance."""
    sk = _sketch()
    sk.line((-20.0, 0.0), (20.0, 0.0), "main")
    labels = Labels(sk, 3.5)
    arc = LineString([(-10.0, 3.0), (10.0, 3.0)])
    free = labels.rooms((0.0, 0.0), "ω_{1}", towards=(0.0, 1.0), keep_off=arc)
    assert len(free) > 0
    assert len(sk.calls) == 1 and labels.boxes == []
    w, h, drop = labels._extent("ω_{1}")
    for x, y in free:
        b = box(x - w / 2, y - h / 2 - drop, x + w / 2, y + h / 2)
        assert b.distance(Point(0.0, 0.0)) <= NEAR_MM
        assert b.distance(LineString([(-20.0, 0.0), (20.0, 0.0)])) >= labels.clearance
        assert b.distance(arc) >= labels.clearance


def test_a_segments_name_tried_at_the_fractions_given():
    """An arm whose middle is crowded with thin lines and whose far end is
    free: named beside the end when the fractions tried along it reach there
    (`along`), with no leader."""
    sk = _sketch()
    sk.line((0.0, 0.0), (60.0, 0.0), "thin")
    for x in np.arange(3.0, 49.0, 1.5):
        sk.line((float(x), -14.0), (float(x), 14.0), "thin")
    labels = Labels(sk, 3.5, leaders=False)
    footprint = labels.place_along((0.0, 0.0), (60.0, 0.0), "h_{1}", along=(0.5, 0.9))
    assert footprint.distance(LineString([(0.0, 0.0), (60.0, 0.0)])) <= NEAR_MM
    assert footprint.bounds[0] > 48.0 and labels.far == 0 and _leaders(sk) == []
    assert _findings(sk, ["label-near", "label-clear"]) == []


def _walled_in(smaller: float | None) -> tuple[Sketch, Labels]:
    """A point in a corridor 3.8 mm high between two main lines, closed 5 mm
    either side of it, in a grid of thin lines: a 3.5 mm label (its box 3.9 mm high, kept 0.4 mm off
    the lines, 0.35 mm less at the last resort) fits nowhere near it, and no leader crossing only thin lines
    reaches out; a 2.5 mm one fits beside it."""
    sk = _sketch()
    sk.line((-5.0, 1.9), (5.0, 1.9), "main")
    sk.line((-5.0, -1.9), (5.0, -1.9), "main")
    sk.line((-5.0, -1.9), (-5.0, 1.9), "main")
    sk.line((5.0, -1.9), (5.0, 1.9), "main")
    # round it, thin lines 2 mm apart out to 15 mm: no label fits between them
    for k in range(-7, 8):
        if k:
            sk.line((-15.0, 2.0 * k + 0.05), (15.0, 2.0 * k + 0.05), "thin")
        sk.line((2.0 * k + 0.05, -15.0), (2.0 * k + 0.05, -1.95), "thin")
        sk.line((2.0 * k + 0.05, 1.95), (2.0 * k + 0.05, 15.0), "thin")
    labels = Labels(sk, 3.5, smaller=smaller)
    labels.place((-3.0, 0.0), "B", towards=(1.0, 0.0))
    return sk, labels


def test_a_name_walled_in_is_written_in_the_smaller_figures_near_it():
    sk, labels = _walled_in(None)
    assert labels.far == 1  # without them: far, with no leader
    assert _findings(sk, ["label-near"]) != []
    sk, labels = _walled_in(2.5)
    assert labels.far == 0
    written = [c for c in sk.calls if isinstance(c, Text)]
    assert [c.size for c in written] == [2.5]
    assert labels.size == 3.5  # the next label at the usual height
    assert _findings(sk, ["label-near", "label-clear", "letter-height"]) == []


def _walled_and_free() -> Sketch:
    """The corridor of `_walled_in`, no label written, and 40 mm to its right
    a pin in the open (the same point drawn at another position)."""
    sk, _ = _walled_in(None)
    sk.calls[:] = [c for c in sk.calls if c.naming is None and not isinstance(c, Text)]
    sk.circle((37.0, 0.0), 1.0, "main")
    return sk


def test_a_name_of_a_point_drawn_twice_goes_where_it_stands_near():
    # walled in at its first place, free at its second: written by the second
    sk = _walled_and_free()
    labels = Labels(sk, 3.5)
    labels.place_first([((-3.0, 0.0), (1.0, 0.0)), ((37.0, 0.0), (1.0, 0.0))], "B")
    assert labels.far == 0
    (text,) = [c for c in sk.calls if isinstance(c, Text)]
    assert text.naming is not None and math.dist(text.naming.anchor, (37.0, 0.0)) < 1e-9
    assert _findings(sk, ["label-near", "label-clear"]) == []


def test_a_name_far_at_every_place_is_written_as_place_writes_it_at_the_first():
    # both places in the corridor: far at each, written as `place` alone
    # writes it at the first, once (what the second try wrote taken back)
    _, alone = _walled_in(None)
    sk = _walled_and_free()
    labels = Labels(sk, 3.5)
    labels.place_first([((-3.0, 0.0), (1.0, 0.0)), ((3.0, 0.0), (1.0, 0.0))], "B")
    assert labels.far == 1
    (text,) = [c for c in sk.calls if isinstance(c, Text)]
    assert text.naming is not None and math.dist(text.naming.anchor, (-3.0, 0.0)) < 1e-9
    (expected,) = [c for c in alone.sketch.calls if isinstance(c, Text)]
    assert text.bbox() == expected.bbox()
    assert labels.boxes == alone.boxes


def _block(angle: float) -> list[tuple[float, float]]:
    u = np.array([math.cos(angle), math.sin(angle)])
    n = np.array([-u[1], u[0]])
    return [tuple(a * 6.0 * u + b * 3.5 * n) for a, b in ((-1, -1), (1, -1), (1, 1), (-1, 1))]


@pytest.mark.parametrize("angle", [0.0, 0.3, 1.2])
@pytest.mark.parametrize("reverse", [False, True])
def test_regression_gen104_every_leader_ends_at_its_point_under_two_crossed_blocks(angle, reverse):
    """gen 104 sheet 2, 'S5': a mass centre under two blocks as large crossed
    over it, ringed by thin lines so that its name is led out. The leader
    starts on the edge of the block the linter measures to, wherever the
    sheet's layout moves the drawing (the placer and the linter chose
    between the two blocks by a float difference of 1e-13 mm; a leader from
    the other block's edge ended 2.4 mm off the one the linter sees)."""
    sk = _sketch()
    for r in np.arange(8.0, 20.0, 1.5):
        sk.circle((0.0, 0.0), float(r), "thin")
    blocks = [_block(angle), _block(angle + math.pi / 2)]
    for b in reversed(blocks) if reverse else blocks:
        sk.polygon(b, "main", "white")
    Labels(sk, 3.5).place((0.0, 0.0), "S_{5}", towards=(0.0, 1.0))
    assert len(_leaders(sk)) == 1
    for dx, dy in ((0.0, 0.0), (781.6022233122015, 474.8737977742024), (0.1, 1e-7), (333.3, 77.7)):
        moved = _sketch()
        moved.calls.extend(c.shifted(dx, dy) for c in sk.calls)
        assert _findings(moved, ["label-near", "label-clear"]) == []


def test_a_details_letter_walled_in_up_and_right_stands_by_another_point_of_its_rim():
    """A detail's disc whose rim up and right (the first place tried) lies
    in the walled corridor: its letter is written by another point of the
    rim, near it, not 10 mm out with no leader (gen 90's view A on sheet 2)."""
    r = 30.0
    centre = np.array([-3.0, 0.0]) - r * np.array([math.sqrt(0.5), math.sqrt(0.5)])
    anchors = rim_anchors(centre, r)
    assert np.allclose(anchors[0][0], (-3.0, 0.0))
    for a, towards in anchors:  # on the rim, pointing out
        assert math.isclose(math.dist(a, centre), r)
        assert np.allclose(towards, a - centre)
    sk = _walled_and_free()
    sk.circle(tuple(centre), r, "thin")
    labels = Labels(sk, 3.5)
    labels.place_first(anchors, "A", clear=True)
    assert labels.far == 0 and labels.unsettled == 0
    (text,) = [c for c in sk.calls if isinstance(c, Text)]
    assert text.naming is not None and math.dist(text.naming.anchor, (-3.0, 0.0)) > 1.0
    assert _findings(sk, ["label-near", "label-clear"]) == []
