import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from shapely.geometry import Polygon

from mmt_plans.errors import MmtError
from mmt_plans.sheets import LayoutError, Page, Rect, SheetLayout, find_overlaps


@pytest.fixture
def layout() -> SheetLayout:
    return SheetLayout(Page.of("A1"))


def test_planted_overlap_is_found(layout):
    layout.register("kinematic-scheme", Rect(50, 300, 200, 200))
    layout.register("velocity-plan", Rect(300, 300, 150, 150))
    layout.register("label-muV", Rect(440, 440, 40, 8), "label")  # pokes into the plan
    layout.register("table-1", Rect(600, 100, 80, 40), "table")
    assert layout.overlaps() == [("velocity-plan", "label-muV")]
    assert layout.problems() == ["velocity-plan overlaps label-muV"]


def test_clean_layout_passes(layout):
    layout.register("kinematic-scheme", Rect(50, 300, 200, 200))
    layout.register("velocity-plan", Rect(300, 300, 150, 150))
    layout.register("table-1", Rect(600, 100, 80, 40), "table")
    assert layout.overlaps() == []
    assert layout.outside() == []


def test_touching_is_not_overlapping_but_clearance_counts():
    shapes = {"a": Rect(0, 0, 10, 10), "b": Rect(10, 0, 10, 10), "c": Rect(25, 0, 5, 5)}
    assert find_overlaps(shapes) == []
    assert find_overlaps(shapes, clearance=1.0) == [("a", "b")]
    assert find_overlaps(shapes, clearance=6.0) == [("a", "b"), ("b", "c")]


def test_polygon_footprints():
    # A label rotated 45 degrees whose bounding boxes meet but outlines do not.
    diamond = Polygon([(10, 0), (20, 10), (10, 20), (0, 10)])
    corner = Rect(17, 17, 5, 5)
    assert find_overlaps({"diamond": diamond, "corner": corner}) == []
    assert find_overlaps({"diamond": diamond, "box": [(5, 5), (12, 5), (12, 12), (5, 12)]}) == [
        ("diamond", "box")
    ]


def test_title_block_is_an_element(layout):
    layout.register("stray", Rect(700, 20, 30, 20))
    assert layout.overlaps() == [("title-block", "stray")]


def test_element_leaving_the_frame(layout):
    layout.register("too-far-left", Rect(10, 300, 30, 30))
    assert layout.outside() == ["too-far-left"]


def test_place_fills_from_the_top_left(layout):
    region = layout.region
    first = layout.place("scheme", 250, 200)
    assert (first.left, first.top) == (region.left, region.top)
    second = layout.place("velocity-plan", 150, 150)
    assert second.top == region.top and second.left == pytest.approx(first.right + layout.gap)
    assert layout.overlaps(clearance=layout.gap - 1e-6) == []


def test_place_avoids_the_title_block(layout):
    r = layout.place("table", 150, 60, corner="bottom-right")
    tb = layout.page.title_block.rect
    assert not r.overlaps(tb)
    assert r.bottom == layout.region.bottom  # beside it, not above it
    assert r.right == pytest.approx(tb.left - layout.gap)


def test_place_raises_when_full(layout):
    with pytest.raises(LayoutError) as err:
        layout.place("huge", 900, 100)
    assert isinstance(err.value, MmtError)
    with pytest.raises(ValueError):
        layout.register("title-block", Rect(0, 0, 1, 1))


@settings(max_examples=60, deadline=None)
@given(st.lists(st.tuples(st.floats(20, 300), st.floats(20, 250)), min_size=1, max_size=8),
       st.sampled_from(["top-left", "top-right", "bottom-left", "bottom-right"]))
def test_placed_drawings_never_overlap(sizes, corner):
    layout = SheetLayout(Page.of("A1"))
    for i, (w, h) in enumerate(sizes):
        try:
            r = layout.place(f"d{i}", w, h, corner=corner)
        except LayoutError:
            continue
        assert layout.region.contains(r, tol=1e-6)
    assert layout.overlaps() == []
    assert layout.outside() == []


def test_place_near_puts_a_detail_beside_its_drawing(layout):
    # a plan in the middle of the sheet: its detail view goes beside it, one
    # gap away, not to the top-left corner the packer fills first
    plan = layout.place("plan", 200, 150)
    layout.register("middle-plan", Rect(400, 250, 180, 120))
    layout.place("tables", 150, 300, corner="top-right")
    middle = layout["middle-plan"].bounds
    detail = layout.place("detail", 60, 60, near=middle)
    gap_x = max(detail.left - middle.right, middle.left - detail.right, 0.0)
    gap_y = max(detail.bottom - middle.top, middle.bottom - detail.top, 0.0)
    assert max(gap_x, gap_y) == pytest.approx(layout.gap)
    assert detail.left > plan.right
    assert layout.overlaps(clearance=layout.gap - 1e-6) == []


# drawings placed from the top left, then a detail of w x h near the last
_DRAWINGS_AND_DETAIL = (
    st.lists(st.tuples(st.floats(20, 300), st.floats(20, 250)), min_size=1, max_size=8),
    st.floats(20, 120),
    st.floats(20, 120),
)


def _filled(sizes) -> SheetLayout:
    """An A1 layout with drawings of `sizes` placed from the top left (those
    that find no room left out)."""
    layout = SheetLayout(Page.of("A1"))
    for i, (a, b) in enumerate(sizes):
        try:
            layout.place(f"d{i}", a, b)
        except LayoutError:
            continue
    return layout


@settings(max_examples=40, deadline=None)
@given(*_DRAWINGS_AND_DETAIL)
def test_placed_near_never_overlaps(sizes, w, h):
    layout = _filled(sizes)
    target = layout.elements[-1].bounds
    try:
        r = layout.place("detail", w, h, near=target)
    except LayoutError:
        return
    assert layout.region.contains(r, tol=1e-6)
    assert layout.overlaps(clearance=layout.gap - 1e-6) == []


@settings(max_examples=40, deadline=None)
@given(*_DRAWINGS_AND_DETAIL)
def test_room_near_is_where_place_near_puts_it_and_registers_nothing(sizes, w, h):
    layout = _filled(sizes)
    target = layout.elements[-1].bounds
    before = layout.elements
    room = layout.room_near(w, h, target)
    assert layout.elements == before
    try:
        placed = layout.place("detail", w, h, near=target)
    except LayoutError:
        assert room is None
        return
    assert room == placed
