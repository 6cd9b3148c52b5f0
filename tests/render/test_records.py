"""Typed drawing records: one frozen type per primitive, with its box, its
groups and (for a label) what it names; the older dict-style reads still work."""

import math
import pickle

import pytest

from mmt_plans.drawing.labels import Labels
from mmt_plans.render.recording import (
    Arc,
    Arrow,
    Call,
    Line,
    Polygon,
    RecordingBackend,
    Text,
)


def test_each_primitive_is_its_own_frozen_type_with_a_box():
    b = RecordingBackend()
    with b.group("g", "plan"):
        b.line((0, 0), (10, 5), "thin")
        b.arrow((0, 0), (3, 4))
        b.polygon([(0, 0), (2, 0), (2, 2)], "main", "black")
        b.arc((0, 0), 2.0, 0.0, 90.0)
        b.text((10, 20), "AB", 5.0, anchor="right", valign="top")
    line, arrow, poly, arc, text = b.in_group("g")
    assert isinstance(line, Line) and line.line == "thin" and line.groups == ("g",)
    assert line.bbox() == (0.0, 0.0, 10.0, 5.0)
    assert isinstance(arrow, Arrow) and arrow.length == 5.0 and arrow["length"] == 5.0
    assert isinstance(poly, Polygon) and poly.fill == "black" and poly["points"][1] == (2.0, 0.0)
    # a quarter arc from 0° to 90° of radius 2 about the origin: its box is the quadrant
    x0, y0, x1, y1 = arc.bbox()
    assert (x0, y0) == pytest.approx((0.0, 0.0), abs=1e-12)
    assert (x1, y1) == pytest.approx((2.0, 2.0), abs=1e-12)
    # the text's box from the look's lettering width, right and top aligned at (10, 20)
    w = b.look.lettering.width("AB", 5.0)
    assert isinstance(text, Text) and text.bbox() == pytest.approx((10 - w, 15.0, 10.0, 20.0))
    assert b.text_box(text) == pytest.approx(text.bbox())
    with pytest.raises(dataclasses_error()):
        text.size = 1.0  # frozen


def dataclasses_error():
    import dataclasses

    return dataclasses.FrozenInstanceError


def test_the_older_reads_and_constructors_still_work():
    b = RecordingBackend()
    b.text((1, 2), "x", 3.5)
    c = b.calls[0]
    assert c.name == "text" and c["content"] == "x" and c.args["size"] == 3.5
    assert "groups" not in c.args and "naming" not in c.args
    again = type(c)(c.name, c.args, ("h",))
    assert isinstance(again, Text) and again.groups == ("h",) and again.pos == (1.0, 2.0)
    made = Call("line", {"start": (0.0, 0.0), "end": (1.0, 0.0), "line": "main"})
    assert isinstance(made, Line) and made.end == (1.0, 0.0)
    assert Call("begin_group", {"id": "a", "cls": None}).id == "a"
    assert pickle.loads(pickle.dumps(c)) == c


def test_a_label_carries_what_it_names_through_a_replay():
    sk = RecordingBackend()
    labels = Labels(sk, 3.5)
    labels.place((10.0, 10.0), "B")
    labels.place_arrow((0.0, 0.0), (30.0, 0.0), "F_{PR}")
    runs = [c for c in sk.calls if isinstance(c, Text)]
    point, *force = runs
    assert point.naming.kind == "point" and point.naming.anchor == (10.0, 10.0)
    assert {r.naming.label for r in force} == {force[0].naming.label}  # F and PR: one label
    assert force[0].naming.kind == "arrow" and force[0].naming.end == (30.0, 0.0)
    sheet = RecordingBackend()
    sk.replay(sheet, 100.0, 50.0)
    sk.replay(sheet, 200.0, 50.0)  # the same sketch twice: two labels each, numbered apart
    moved = [c for c in sheet.calls if isinstance(c, Text)]
    assert moved[0].naming.anchor == (110.0, 60.0)
    assert len({c.naming.label for c in moved}) == 4
    # the label is where the placer wrote it, next to what it names
    assert math.dist(moved[0].pos, moved[0].naming.anchor) < 8.0


def test_a_recorded_call_is_the_record_its_constructor_makes():
    """RecordingBackend makes its records without Call.__init__'s argument
    matching (render/recording.py `_made`): each must equal, field by field,
    the record the constructor makes from the same values, with every field
    set (a default the fast path forgot would be missing here)."""
    import dataclasses

    from mmt_plans.render.recording import BeginGroup, Circle, EndGroup, Polyline

    b = RecordingBackend()
    with b.group("g", "plan"):
        with b.naming("A", "point", (1.0, 2.0)):
            b.line((0, 0), (10, 5), "thin")
            b.text((10, 20), "AB", 5.0, anchor="right", valign="top", max_width=4.0)
        b.polyline([(0, 0), (1, 1), (2, 0)], "thin")
        b.polygon([(0, 0), (2, 0), (2, 2)], None, "black")
        b.circle((1, 1), 2, "main", "white")
        b.arc((0, 0), 2.0, 10.0, 90.0, "thin")
        b.arrow((0, 0), (3, 4), head_length=2.0, head_width=1.0)
        b.rich_text((0, 0), "V_{BA}", 3.5)
    kinds = [type(c) for c in b.calls]
    assert kinds[:8] == [BeginGroup, Line, Text, Polyline, Polygon, Circle, Arc, Arrow]
    assert kinds[-1] is EndGroup
    for c in b.calls:
        again = type(c)(*[getattr(c, f.name) for f in dataclasses.fields(c)])
        assert again == c and vars(again) == vars(c), c
        assert hash(again) == hash(c)
    # what a label names and a run's label mark are kept
    assert b.calls[1].naming is not None and b.calls[1].naming.markup == "A"
    assert b.calls[2].width == pytest.approx(b.look.lettering.width("AB", 5.0, 4.0))
    assert [c.label is not None for c in b.calls if isinstance(c, Text)] == [False, True, True]
