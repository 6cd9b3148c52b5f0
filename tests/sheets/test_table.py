import pytest

from mmt_plans.render import RecordingBackend
from mmt_plans.sheets import Rect, Table

HEADER = ["Point", "V, m/s", "a, m/s²"]
ROWS = [["A", "1.885", "35.53"], ["B", "1.214", "22.10"], ["C", "0.603", "14.87"]]


def test_size_from_columns_and_rows():
    t = Table(HEADER, ROWS, [20, 30, 30])
    assert t.width == 80
    # Header row and three body rows of 8 mm (GOST 2.105 minimum).
    assert t.height() == 32
    assert t.bbox((100, 200)) == Rect(100, 168, 80, 32)


def test_draw_returns_its_bounding_box_and_keeps_inside_it():
    b = RecordingBackend()
    t = Table(HEADER, ROWS, [20, 30, 30], title="Table 1 – Velocities")
    box = t.draw(b, (100, 200), id="velocities")
    assert box == t.bbox((100, 200))
    assert box.top == 200 and box.left == 100
    calls = b.in_group("velocities")
    assert calls, "the table draws inside its own group"
    for c in calls:
        for x, y in c.points():
            assert box.left - 1e-9 <= x <= box.right + 1e-9
            assert box.bottom - 1e-9 <= y <= box.top + 1e-9
    for c in b.named("text"):
        x0, y0, x1, y1 = b.text_box(c)
        assert box.contains(Rect.from_bounds(x0, y0, x1, y1), tol=0.05), c["content"]


def test_grid_lines_and_cell_texts():
    b = RecordingBackend()
    t = Table(HEADER, ROWS, [20, 30, 30])
    box = t.draw(b, (0, 100))
    (outline,) = b.named("polygon")
    assert set(outline["points"]) == {(0, 68), (80, 68), (80, 100), (0, 100)}
    assert outline["line"] == "main"
    lines = b.named("line")
    assert sum(c["line"] == "thin" for c in lines) == len(ROWS) - 1
    # Header line and two column lines are main.
    assert sum(c["line"] == "main" for c in lines) == 1 + 2
    texts = b.named("text")
    assert [c["content"] for c in texts] == HEADER + [v for row in ROWS for v in row]
    # Body texts centred in their cells.
    a_cell = texts[3]
    assert a_cell["pos"] == pytest.approx((10, 100 - 8 - 4))
    assert a_cell["anchor"] == "center" and a_cell["valign"] == "middle"
    assert box.height == 32


def test_multi_line_header_grows():
    t = Table(["Reaction\nforce", "Value, N"], [["R12", "1520"]], [30, 30])
    assert t.height() > 16


def test_bad_tables_are_refused():
    with pytest.raises(ValueError):
        Table(HEADER, [["A", "1"]], [20, 30, 30])
    with pytest.raises(ValueError):
        Table(HEADER, ROWS, [20, 30])
    with pytest.raises(ValueError):
        Table(HEADER, ROWS, [20, 0, 30])
