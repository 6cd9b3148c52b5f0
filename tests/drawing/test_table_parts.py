"""A table taller than the room continues in parts side by side (GOST 2.105
§4.4.9): each part no taller than asked, each with the header repeated, the
parts after the first titled as a continuation, every row once and in order."""

from __future__ import annotations

import math

import pytest

from mmt_plans.drawing.table import TABLE_PART_MM, rows_per_part, table_sketch
from mmt_plans.render.look import load_look


def test_rows_per_part_by_hand():
    # A part holds its title (3.5 mm letters + 3 mm gap), the 12 mm header and
    # 8 mm rows: in 280 mm, (280 - 6.5 - 12) / 8 = 32.7, so 32 rows. 74 rows
    # need ceil(74 / 32) = 3 parts, shared evenly: ceil(74 / 3) = 25 rows each.
    assert rows_per_part(74, 280.0) == 25
    assert rows_per_part(32, 280.0) == 32  # fits whole
    assert rows_per_part(33, 280.0) == 17  # two parts of 17 and 16
    assert rows_per_part(0, 280.0) == 1
    assert TABLE_PART_MM == 280.0


def _table(rows: int, max_height: float | None):
    look = load_look()
    body = [[f"r{k}", f"{k}.5", f"{2 * k}.25"] for k in range(rows)]
    return table_sketch(
        look,
        "table-t",
        "Velocities, m/s",
        ["Quantity", "Pos. 3", "Pos. 9"],
        body,
        [22.0, 20.0, 20.0],
        [f"V_{{{k}}}" for k in range(rows)],
        "en",
        max_height=max_height,
        continued="Continuation of Table 1",
    )


def _parts(sk):
    ids = []
    for c in sk.calls:
        if c.name == "begin_group" and c["id"] not in ids:
            ids.append(c["id"])
    return ids


def _box(sk, gid):
    boxes = [c.bbox() for c in sk.in_group(gid)]
    boxes = [b for b in boxes if b is not None]
    return (
        min(b[0] for b in boxes),
        min(b[1] for b in boxes),
        max(b[2] for b in boxes),
        max(b[3] for b in boxes),
    )


def test_a_short_table_is_one_part():
    sk = _table(10, 150.0)
    assert _parts(sk) == ["table-t"]
    assert "Continuation of Table 1" not in [c["content"] for c in sk.named("text")]


def test_a_tall_table_continues_in_parts_each_within_the_room():
    rows = 40
    sk = _table(rows, 150.0)
    parts = _parts(sk)
    # (150 - 6.5 - 12) / 8 = 16.4: 16 rows a part, ceil(40 / 16) = 3 parts
    assert parts == ["table-t", "table-t-2", "table-t-3"]
    seen: list[str] = []
    boxes = []
    for k, gid in enumerate(parts):
        texts = [c["content"] for c in sk.in_group(gid) if c.name == "text"]
        box = _box(sk, gid)
        boxes.append(box)
        assert box[3] - box[1] <= 150.0 + 1e-6, (gid, box)
        # the header repeated in every part, the title or the continuation's
        assert {"Quantity", "Pos. 3", "Pos. 9"} <= set(texts), gid
        assert ("Velocities, m/s" if k == 0 else "Continuation of Table 1") in texts
        seen += [t for t in texts if t.endswith(".5")]
    # every row once, in order across the parts; one number format throughout
    assert seen == [f"{k}.5" for k in range(rows)]
    # side by side, tops level, apart
    assert all(math.isclose(b[3], boxes[0][3], abs_tol=1e-6) for b in boxes)
    for left, right in zip(boxes, boxes[1:]):
        assert right[0] >= left[2] + 5.0


def test_a_table_in_parts_needs_a_continuation_title():
    look = load_look()
    with pytest.raises(ValueError, match="continued"):
        table_sketch(
            look, "t", "T", ["a", "b"], [["x", "1"]] * 40, [20.0, 20.0], ["x"] * 40,
            max_height=100.0,
        )
