import math

import numpy as np
import pytest

from mmt_plans.render import RecordingBackend, arrow_geometry, load_look
from mmt_plans.render.backend import parse_markup


def test_arrow_head_tip_base_and_width():
    shaft_end, head = arrow_geometry((0, 0), (30, 40), head_length=5.0, head_width=1.6)
    tip, left, right = head
    assert tip == (30.0, 40.0)
    # The shaft stops at the base of the head, 5 mm back along the vector (3-4-5).
    assert shaft_end == pytest.approx((27.0, 36.0))
    assert math.dist(left, right) == pytest.approx(1.6)
    assert ((left[0] + right[0]) / 2, (left[1] + right[1]) / 2) == pytest.approx(shaft_end)


def test_short_vector_gets_a_shorter_head():
    shaft_end, head = arrow_geometry((0, 0), (2, 0), head_length=5.0, head_width=1.6)
    assert shaft_end == pytest.approx((0.0, 0.0))
    assert math.dist(head[1], head[2]) == pytest.approx(1.6 * 2 / 5)


def test_look_arrow_is_sized_for_a1():
    look = load_look()
    assert look.arrow_length == pytest.approx(5.0)
    assert look.line("main").width == pytest.approx(0.7)
    assert look.line("thin").width == pytest.approx(0.35)
    assert look.line("dashed").dash and look.line("dashdot").dash
    assert look.line("main").dash == ()


def test_calls_are_recorded_with_groups():
    b = RecordingBackend()
    with b.group("velocity-plan", "plan"):
        b.line((0, 0), np.array([10.0, 0.0]), "thin")
        with b.group("pole"):
            b.circle((0, 0), 1.0, fill="black")
        b.arrow((0, 0), (0, 100))
    b.text((5, 5), "pa", 3.5)
    names = [c.name for c in b.calls]
    assert names == [
        "begin_group", "line", "begin_group", "circle", "end_group", "arrow", "end_group", "text"
    ]
    line = b.named("line")[0]
    assert line["start"] == (0.0, 0.0) and line["end"] == (10.0, 0.0)
    assert line.groups == ("velocity-plan",)
    assert b.named("circle")[0].groups == ("velocity-plan", "pole")
    arrow = b.named("arrow")[0]
    assert arrow["length"] == pytest.approx(100.0) and arrow["head_length"] == pytest.approx(5.0)
    assert b.named("text")[0].groups == ()
    assert len(b.in_group("velocity-plan")) == 3


def test_bad_arguments_are_refused():
    b = RecordingBackend()
    with pytest.raises(ValueError):
        b.line((0, 0), (1, 1), "bold")  # type: ignore[arg-type]
    with pytest.raises(ValueError):
        b.text((0, 0), "x", 3.5, anchor="middle")  # type: ignore[arg-type]
    with pytest.raises(ValueError):
        b.line((0, 0), (math.nan, 1))
    with pytest.raises(RuntimeError):
        b.end_group()
    b.begin_group("open")
    with pytest.raises(RuntimeError):
        b.close()


def test_markup_runs():
    assert parse_markup("μ_{V} = 0.01") == [("μ", "normal"), ("V", "sub"), (" = 0.01", "normal")]
    assert parse_markup("a_B^n") == [("a", "normal"), ("B", "sub"), ("n", "sup")]
    assert parse_markup("R_{12}") == [("R", "normal"), ("12", "sub")]


def test_rich_text_sets_indices_smaller_and_lower():
    b = RecordingBackend()
    width = b.rich_text((100, 50), "V_{BA} = 1", 5.0)
    main, index, rest = b.named("text")
    assert (main["content"], index["content"], rest["content"]) == ("V", "BA", "= 1")
    assert main["size"] == 5.0 and index["size"] == 3.5
    assert index["pos"][1] == pytest.approx(50 - 0.3 * 5.0)
    assert main["pos"][0] < index["pos"][0] < rest["pos"][0]
    assert rest["pos"][0] + b.look.lettering.natural_width("= 1", 5.0) == pytest.approx(
        100 + width, abs=1e-6
    )


def test_rich_text_centred_and_rotated():
    b = RecordingBackend()
    width = b.rich_text((0, 0), "ω_2", 5.0, anchor="center", rotation=90.0)
    first = b.named("text")[0]
    # Rotated a quarter turn, the line runs up the y axis from -width/2.
    assert first["pos"] == pytest.approx((0.0, -width / 2))
    assert first["rotation"] == 90.0


def test_text_box_estimate():
    b = RecordingBackend()
    b.text((10, 20), "Масштаб", 2.5, anchor="center", valign="middle")
    x0, y0, x1, y1 = b.text_box(b.named("text")[0])
    assert (x0 + x1) / 2 == pytest.approx(10)
    assert (y0, y1) == pytest.approx((18.75, 21.25))
    assert x1 - x0 == pytest.approx(b.look.lettering.natural_width("Масштаб", 2.5))


def test_squeezed_width_never_below_min_squeeze():
    let = load_look().lettering
    natural = let.natural_width("Розроблено", 3.5)
    assert let.width("Розроблено", 3.5, natural / 2) == pytest.approx(natural * let.min_squeeze)
    assert let.width("Розроблено", 3.5, natural * 0.9) == pytest.approx(natural * 0.9)
    assert let.width("Розроблено", 3.5, natural * 2) == pytest.approx(natural)


def test_replay_onto_a_plain_recording_makes_the_records_the_methods_make():
    # replay onto a plain recording makes each record itself (no drawing
    # method called): the records must be those the drawing methods make, a
    # label's naming renumbered where the target has its number already
    from mmt_plans.render.recording import Text

    class Calling(RecordingBackend):  # a method of its own: replay calls the methods
        def line(self, start, end, line="main"):
            super().line(start, end, line)

    src = RecordingBackend()
    with src.group("outer", "drawing"):
        with src.naming("B", "point", (5.0, 6.0)):
            src.rich_text((5.0, 6.0), "V_{B}", 3.5)
            src.line((0.0, 0.0), (5.0, 6.0), "thin")
        src.polygon([(0.0, 0.0), (1.0, 0.0), (1.0, 1.0)], "main", "black")
        src.polyline([(0.0, 0.0), (2.0, 1.0), (3.0, 0.0)], "thin")
        src.circle((1.0, 1.0), 0.75, None, "white")
        src.arc((1.0, 1.0), 4.0, 10.0, 80.0, "thin")
        src.arrow((0.0, 0.0), (9.0, 3.0), "main", head_length=3.0, head_width=1.0)
        src.text((2.0, 2.0), "x", 5.0, anchor="right", valign="top", max_width=1.0)
    label = next(c.naming.label for c in src.calls if c.naming is not None)
    fast, slow = RecordingBackend(), Calling()
    for target in (fast, slow):
        target._label_ids.add(label)  # the label's number taken: renumbered
        with target.group("sheet"):
            src.replay(target, 10.0, np.float64(-2.5))
            src.replay(target, 0.0, 0.0)
    assert len(fast.calls) == len(slow.calls) == 2 * len(src.calls) + 2
    numbers: dict[int, int] = {}
    for a, b in zip(fast.calls, slow.calls):
        assert type(a) is type(b)
        got, want = dict(a.__dict__), dict(b.__dict__)
        if want["naming"] is not None:  # fresh numbers come from one counter
            assert numbers.setdefault(want["naming"].label, got["naming"].label) == (
                got["naming"].label
            )
            assert got["naming"].label != label
            got["naming"] = want["naming"] = None
        assert list(got.items()) == list(want.items())
        assert all(type(x) is float and type(y) is float for x, y in a.points())
    texts = [c for c in fast.calls if isinstance(c, Text)]
    assert texts[0].groups == ("sheet", "outer") and texts[0].pos[1] == 3.5


def test_a_text_in_another_lettering_keeps_it_through_a_recording():
    """Backend.lettered_as (a note's figure copied from a sheet): a text
    recorded within carries that lettering, its width measured in it, and a
    replay draws it so; the page's lettering is back after, and an SVG names
    the other font on that text alone."""
    from mmt_plans.render import SvgBackend
    from mmt_plans.render.look import load_look, note_look

    sheet, note = load_look(), note_look()
    assert sheet.lettering.families != note.lettering.families
    rec = RecordingBackend(210.0, 297.0, note)
    rec.text((10.0, 10.0), "note", 3.5)
    with rec.lettered_as(sheet.lettering):
        rec.text((10.0, 20.0), "figure", 3.5)
    rec.text((10.0, 30.0), "note again", 3.5)
    first, inside, after = rec.calls
    assert first.lettering is None and after.lettering is None
    assert inside.lettering == sheet.lettering
    assert inside.width == sheet.lettering.width("figure", 3.5, None)
    assert first.width == note.lettering.width("note", 3.5, None)
    assert rec.look is not None and rec.look.lettering == note.lettering

    again = RecordingBackend(210.0, 297.0, note)
    rec.replay(again)
    assert [c.lettering for c in again.calls] == [None, sheet.lettering, None]

    svg = SvgBackend(210.0, 297.0, look=note)
    rec.replay(svg)
    text = svg.to_string()
    family = sheet.lettering.families[0]
    assert text.count(family) == 1  # the figure's text only


def test_a_drawn_point_is_two_python_floats_whatever_it_came_as():
    from mmt_plans.render.backend import as_point

    row = np.array([[1.5, -2.25]])[0]
    for p in ((1.5, -2.25), (np.float64(1.5), np.float64(-2.25)), row, [1.5, -2.25], (1.5, -2.25)):
        got = as_point(p)
        assert got == (1.5, -2.25)
        assert type(got) is tuple and all(type(v) is float for v in got)
    assert as_point((3, 4)) == (3.0, 4.0) and type(as_point((3, 4))[0]) is float
    for bad in ((np.float64("nan"), 0.0), (0.0, float("inf")), np.array([-np.inf, 1.0])):
        with pytest.raises(ValueError, match="must be finite"):
            as_point(bad)
    for wrong in ((1.0,), (1.0, 2.0, 3.0), np.zeros(3)):
        with pytest.raises(ValueError):
            as_point(wrong)
