"""The layout trials' short cuts: a trial rejected without sketching must be one
the sketches would reject as well, and the packer's grid search must pick the
candidate the first-in-order rule names."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from shapely.geometry import LineString

import mmt_plans
from mmt_plans.drawing.layout import first_free
from mmt_plans.drawing.page import Page, Rect
from mmt_plans.render.recording import RecordingBackend
from mmt_plans.sheets.sheet2 import _Composer

ROOT = Path(__file__).resolve().parents[2]


@pytest.mark.parametrize("name", ["six_link_press", "shaper", "forces_scotch_yoke"])
def test_least_area_never_exceeds_the_sketched_area(name: str) -> None:
    sol = mmt_plans.solve(mmt_plans.load(ROOT / "samples" / f"{name}.toml"))
    page = Page.of("A1")
    composer = _Composer(sol.require_forces(), sol, RecordingBackend(1, 1).look, "en", page)
    for shrink in (-2, -1, 0, 2):
        steps = composer._steps(shrink, shrink - 1)
        scales = composer.scales(steps)
        sketches = composer.sketches(scales)[0]
        drawn = sum(
            composer.extent(sketches[n]).width * composer.extent(sketches[n]).height
            for n in (*composer.tables, *composer.drawings)
        )
        least = composer.least_area(scales)
        assert 0.0 < least <= drawn


def test_first_free_is_the_first_free_candidate_in_order() -> None:
    # region 100 x 50 from (0, 0); one box in the top-left corner
    region = Rect(0.0, 0.0, 100.0, 50.0)
    boxes = np.array([[0.0, 30.0, 40.0, 50.0]])
    # top-left: the top row is taken by the box up to x = 40; with a gap of 5 the
    # first column clear of it is x = 45, at the top (y = 50 - 10)
    assert first_free(region, boxes, 20.0, 10.0, 5.0, "top-left") == (45.0, 40.0)
    # bottom-left: the corner itself is free
    assert first_free(region, boxes, 20.0, 10.0, 5.0, "bottom-left") == (0.0, 0.0)
    # top-right: flush with the right edge at the top
    assert first_free(region, boxes, 20.0, 10.0, 5.0, "top-right") == (80.0, 40.0)
    # wider than the room beside the box and taller than the room under it
    assert first_free(region, boxes, 70.0, 30.0, 5.0, "top-left") is None
    # no box: the corner
    assert first_free(region, np.zeros((0, 4)), 20.0, 10.0, 0.0, "top-right") == (80.0, 40.0)


@pytest.mark.parametrize("name", ["six_link_press", "shaper", "five_dyads"])
@pytest.mark.parametrize("lang", ["en", "uk"])
def test_unlettered_mechanism_is_never_larger_than_the_drawing(name: str, lang: str) -> None:
    # sheet 1 rejects a μ_l by the mechanism's lines and captions alone (no
    # lettering) only if the lettered drawing would be at least as large
    from mmt_plans.sheets.sheet1 import _unlettered_mechanism, sketch_mechanism

    sol = mmt_plans.solve(mmt_plans.load(ROOT / "samples" / f"{name}.toml"))
    look = RecordingBackend(1, 1).look
    for mu_l in (float(sol.mu_l), 2.0 * float(sol.mu_l)):
        stand_in = _unlettered_mechanism(sol, mu_l, look, lang).extent()  # type: ignore[arg-type]
        drawn = sketch_mechanism(sol, mu_l, look, lang).extent()  # type: ignore[arg-type]
        # its lettering only adds to the drawing: strictly larger somewhere
        assert stand_in.width <= drawn.width + 1e-9
        assert stand_in.height <= drawn.height + 1e-9
        assert stand_in.width * stand_in.height < drawn.width * drawn.height


def _first_free_by_shapely(
    region: Rect, boxes: np.ndarray, w: float, h: float, gap: float, corner: str
) -> tuple[float, float] | None:
    """first_free's rule asked one candidate at a time of shapely (an independent route)."""
    import shapely

    from mmt_plans.drawing.layout import _EPS, _candidates

    for x, y in _candidates(region, boxes, w, h, gap, corner):
        me = shapely.box(x, y, x + w, y + h)
        if gap > 0:
            hit = any(me.distance(shapely.box(*b)) < gap - _EPS for b in boxes)
        else:
            hit = any(me.intersection(shapely.box(*b)).area > 0 for b in boxes)
        if not hit:
            return float(x), float(y)
    return None


def test_first_free_agrees_with_shapely_on_random_sheets() -> None:
    rng = np.random.default_rng(7)
    region = Rect(10.0, 10.0, 400.0, 250.0)
    for trial in range(150):
        n = int(rng.integers(0, 12))
        lo = rng.uniform([10.0, 10.0], [380.0, 240.0], size=(n, 2))
        size = rng.uniform(5.0, 120.0, size=(n, 2))
        boxes = np.c_[lo, lo + size].reshape(-1, 4)
        w, h = rng.uniform(5.0, 150.0, size=2)
        gap = [0.0, 3.0, 8.0][trial % 3]
        corner = ["top-left", "top-right", "bottom-left", "bottom-right"][trial % 4]
        want = _first_free_by_shapely(region, boxes, w, h, gap, corner)
        assert first_free(region, boxes, w, h, gap, corner) == want


def test_pack_remembering_places_each_item_as_without() -> None:
    from mmt_plans.drawing.layout import pack

    page = Page.of("A1")
    rng = np.random.default_rng(3)
    known: dict = {}
    for _ in range(30):
        items = [
            (f"d{i}", *map(float, rng.uniform(40.0, 220.0, size=2)), "top-left")
            for i in range(int(rng.integers(1, 9)))
        ]
        head = pack(page, items[:1], 5.0)
        assert head is not None
        for order in (items[1:], items[1:][::-1], items[1:]):
            assert pack(page, order, 5.0, head, known=known) == pack(page, order, 5.0, head)
    assert known  # it remembered


def test_obstacle_index_pairs_agree_with_shapely_for_solids() -> None:
    # boxes_near and lines_near skip shapely for a solid whose box is already
    # past its clearance: the pairs must be those shapely finds one by one
    import shapely

    from mmt_plans.drawing.labels import _ObstacleIndex

    rng = np.random.default_rng(11)
    solids = []
    for _ in range(40):
        x, y = rng.uniform(0.0, 100.0, size=2)
        if rng.random() < 0.5:  # an arrowhead
            p = rng.uniform(-4.0, 4.0, size=(3, 2)) + (x, y)
            solids.append(shapely.Polygon(p))
        else:  # a filled disc
            solids.append(shapely.Point(x, y).buffer(float(rng.uniform(0.5, 3.0)), 16))
    clearance = rng.uniform(0.2, 2.5, size=len(solids))
    index = _ObstacleIndex(solids, clearance)
    x0, y0 = rng.uniform(0.0, 100.0, size=(2, 300))
    x1, y1 = x0 + rng.uniform(1.0, 8.0, size=300), y0 + rng.uniform(1.0, 4.0, size=300)
    got = set(zip(*index.boxes_near(x0, y0, x1, y1)))
    boxes = shapely.box(x0, y0, x1, y1)
    want = {
        (i, j)
        for i in range(300)
        for j in range(len(solids))
        if shapely.distance(boxes[i], solids[j]) < clearance[j]
    }
    assert got == want and want
    ends = rng.uniform(0.0, 100.0, size=(200, 4))
    lines = np.array([shapely.LineString([(a, b), (c, d)]) for a, b, c, d in ends])
    got = set(zip(*index.lines_near(lines)))
    want = {
        (i, j)
        for i in range(200)
        for j in range(len(solids))
        if shapely.distance(lines[i], solids[j]) < clearance[j]
    }
    assert got == want and want


def test_boxes_clear_is_no_pair_of_boxes_near() -> None:
    # boxes_clear finds the pieces a box meets from the grown boxes' columns
    # (one box as one row) and asks the upright solids first: a box is clear
    # exactly where boxes_near gives it no pair, one box at a time or many,
    # with few pieces (compared in numpy) or many (asked of the tree)
    import shapely

    from mmt_plans.drawing.labels import _ObstacleIndex

    rng = np.random.default_rng(5)
    shapes, clearance = [], []
    for _ in range(120):
        x, y = rng.uniform(0.0, 100.0, size=2)
        kind = rng.integers(5)
        if kind == 0:  # a line of a few segments
            shapes.append(shapely.LineString(rng.uniform(-6.0, 6.0, size=(4, 2)) + (x, y)))
        elif kind == 1:  # a text box (an upright solid)
            shapes.append(shapely.box(x, y, x + rng.uniform(1.0, 6.0), y + 2.5))
        elif kind == 2:  # an arrowhead
            shapes.append(shapely.Polygon(rng.uniform(-3.0, 3.0, size=(3, 2)) + (x, y)))
        elif kind == 3:  # a point
            shapes.append(shapely.Point(x, y))
        else:  # a ring
            shapes.append(shapely.Point(x, y).buffer(float(rng.uniform(0.5, 3.0)), 16).exterior)
        clearance.append(float(rng.uniform(0.0, 2.0)))
    index = _ObstacleIndex(shapes, clearance)
    for n in (1, 1, 1, 16, 300):
        x0, y0 = rng.uniform(0.0, 100.0, size=(2, n))
        x1, y1 = x0 + rng.uniform(0.5, 8.0, size=n), y0 + rng.uniform(0.5, 4.0, size=n)
        met = np.zeros(n, dtype=bool)
        met[index.boxes_near(x0, y0, x1, y1)[0]] = True
        assert np.array_equal(index.boxes_clear(x0, y0, x1, y1), ~met)
    assert n * len(index.grown) > 20_000  # the last batch asked the tree


def test_free_spots_are_the_first_free_spot_each() -> None:
    # sheet 1's diagrams ask for every tick number's spots in one query: the
    # answer of each is the first spot Labels.free finds free, one by one
    from mmt_plans.drawing.labels import Labels
    from mmt_plans.drawing.sketch import Sketch
    from mmt_plans.sheets.sheet1 import _free_spots

    look = RecordingBackend(1, 1).look
    sk = Sketch(look)
    rng = np.random.default_rng(3)
    for _ in range(60):
        sk.line(tuple(rng.uniform(0.0, 60.0, size=2)), tuple(rng.uniform(0.0, 60.0, size=2)))
    free = Labels(sk, 2.5)
    asked = []
    for k in range(40):
        x, y = (float(v) for v in rng.uniform(0.0, 60.0, size=2))
        spots = [((x + d, y + e), "center", "top") for d in (-1.5, 0.0, 1.5) for e in (-1.2, 1.2)]
        asked.append((str(k), spots))
    got = _free_spots(sk, free, 2.5, asked)
    want = []
    for text, spots in asked:
        found = None
        for pos, anchor, valign in spots:
            probe = RecordingBackend(look=look)
            probe.text(pos, text, 2.5, anchor=anchor, valign=valign)  # type: ignore[arg-type]
            if free.free(probe.text_box(probe.calls[-1])):
                found = (pos, anchor, valign)
                break
        want.append(found)
    assert got == want
    assert any(w is None for w in want) and any(w is not None for w in want)


def test_drawn_shapes_of_are_drawn_shapes_each() -> None:
    # the placer takes in a sketch's lines in one shapely call: the same
    # geometries, in the same order, as drawn_shapes one call at a time
    import shapely

    from mmt_plans.drawing.labels import drawn_shapes, drawn_shapes_of
    from mmt_plans.render.recording import Line

    sol = mmt_plans.solve(mmt_plans.load(ROOT / "samples" / "six_link_press.toml"))
    from mmt_plans.sheets.compose import compose

    composed = compose(sol, "en", (1, 2))
    for n in (1, 2):
        rec = composed.sheet(n).recording()
        calls = list(rec.calls) + [Line((1.0, 1.0), (1.0, 1.0), "thin")]  # a point
        got = drawn_shapes_of(calls, rec)
        want = [drawn_shapes(c, rec) for c in calls]
        assert len(got) == len(want)
        for g, w in zip(got, want):
            assert len(g) == len(w)
            for a, b in zip(g, w):
                assert a.geom_type == b.geom_type
                assert shapely.equals_exact(a, b, tolerance=0.0)
                assert np.array_equal(shapely.get_coordinates(a), shapely.get_coordinates(b))


def test_caption_place_is_where_every_box_measured_puts_it() -> None:
    # _caption_place measures a box's distance to the link's polygon only
    # where its centre's distance leaves the answer open: the place must be
    # the one measuring every box gives
    import shapely

    from mmt_plans.drawing.labels import Labels
    from mmt_plans.drawing.sketch import Sketch
    from mmt_plans.sheets.sheet2 import _caption_place

    def every_box(labels: Labels, corners: np.ndarray, caption: str):  # the rule, plainly
        centre = corners.mean(axis=0)
        w, h = labels.width(caption) + 0.4, labels.size + 0.4
        region = shapely.convex_hull(shapely.multipoints(corners))
        lo, hi = corners.min(axis=0) - (w / 2 + 3.0), corners.max(axis=0) + (w / 2 + 3.0)
        xs, ys = np.meshgrid(np.arange(lo[0], hi[0], 1.0), np.arange(lo[1], hi[1], 1.0))
        q = np.c_[xs.ravel(), ys.ravel()]
        x0, y0, x1, y1 = q[:, 0] - w / 2, q[:, 1] - h / 2, q[:, 0] + w / 2, q[:, 1] + h / 2
        on = shapely.distance(shapely.box(x0, y0, x1, y1), region) <= 3.0
        taken = shapely.bounds(labels.boxes).reshape(-1, 4)
        gap = labels.spacing
        clash = (
            (taken[None, :, 0] - gap < x1[:, None])
            & (taken[None, :, 2] + gap > x0[:, None])
            & (taken[None, :, 1] < y1[:, None])
            & (taken[None, :, 3] > y0[:, None])
        ).any(axis=1)
        ok = np.flatnonzero(on & ~clash)
        tried = ok[np.argsort(np.hypot(*(q[ok] - centre).T), kind="stable")][:3000]
        first = labels.first_free(np.c_[x0[tried], y0[tried], x1[tried], y1[tried]])
        if first is not None:
            return q[tried[first]] - np.array([1.5 + w / 2, 0.0]), np.array([1.0, 0.0])
        return centre, None

    look = RecordingBackend(1, 1).look
    rng = np.random.default_rng(8)
    for trial in range(12):
        sk = Sketch(look)
        corners = rng.uniform(0.0, 40.0, size=(int(rng.integers(2, 6)), 2))
        for a, b in zip(corners, np.roll(corners, -1, axis=0)):
            sk.line(tuple(a), tuple(b))
        for _ in range(int(rng.integers(0, 40))):
            sk.line(tuple(rng.uniform(-5.0, 45.0, size=2)), tuple(rng.uniform(-5.0, 45.0, size=2)))
        labels = Labels(sk, 3.5)
        caption = ["link 4", "ланка 12", "3"][trial % 3]
        got, want = _caption_place(labels, corners, caption), every_box(labels, corners, caption)
        assert np.array_equal(got[0], want[0])
        assert (got[1] is None) == (want[1] is None)


def _crowded_labels(seed: int):  # noqa: ANN202
    """A placer over a random crowd of thin and main lines, rings, dots and
    names written: most anchors there find no free place near them."""
    from mmt_plans.drawing.labels import Labels
    from mmt_plans.drawing.sketch import Sketch

    rng = np.random.default_rng(seed)
    sk = Sketch(RecordingBackend().look)
    for _ in range(70):
        a = rng.uniform(0.0, 60.0, size=2)
        b = a + rng.uniform(-25.0, 25.0, size=2)
        sk.line(tuple(a), tuple(b), "main" if rng.random() < 0.3 else "thin")
    for _ in range(12):
        sk.circle(tuple(rng.uniform(0.0, 60.0, size=2)), float(rng.uniform(0.8, 4.0)), "thin")
    labels = Labels(sk, 3.5)
    for k in range(10):
        labels.place(tuple(rng.uniform(0.0, 60.0, size=2)), f"N_{{{k}}}")
    return labels, rng


def _leader_among_at_once(self, cx, cy, ax, ay, w, h, drop, markup):  # noqa: ANN001, ANN202
    """Labels._leader_among as it read before it asked in blocks: every box at once."""
    import shapely
    from shapely import STRtree

    from mmt_plans.drawing.labels import _FOOT_CLEAR, _LEADER_CROSSINGS, _LEADER_START

    x0, x1, y0, y1 = cx - w / 2, cx + w / 2, cy - h / 2 - drop, cy + h / 2
    cost = self._label_cost(x0, y0, x1, y1) + self._lookalike_cost(markup, x0, y0, x1, y1)
    free = np.flatnonzero(cost <= 1e-9)
    free = free[self._clear(x0[free], y0[free], x1[free], y1[free])]
    ax, ay = ax[free], ay[free]
    px, py = np.clip(ax, x0[free], x1[free]), np.clip(ay, y0[free], y1[free])
    length = np.hypot(px - ax, py - ay)
    keep = length > _LEADER_START + 0.5
    free, px, py, length, ax, ay = (v[keep] for v in (free, px, py, length, ax, ay))
    if not free.size:
        return None
    ux, uy = (px - ax) / length, (py - ay) / length
    ex, ey = px - 0.4 * ux, py - 0.4 * uy
    starts = np.c_[ax + _LEADER_START * ux, ay + _LEADER_START * uy]
    clear = shapely.linestrings(np.stack([starts, np.c_[ex, ey]], axis=1))
    crossed = self._met_at_feet(clear, self._crossings(clear), ax, ay)
    if self.boxes:
        written = np.asarray(self.boxes, dtype=object)
        near = STRtree(written).query(clear, predicate="dwithin", distance=_FOOT_CLEAR)
        crossed[np.unique(near[0])] = np.iinfo(np.int64).max
    for most in (0, *_LEADER_CROSSINGS):
        for i in np.flatnonzero(crossed <= most):
            if self._runs_along(clear[i]):
                continue
            k = free[i]
            start = (float(ax[i]), float(ay[i]))
            return (float(cx[k]), float(cy[k])), (start, (float(ex[i]), float(ey[i])))
    return None


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_leaders_asked_in_blocks_pick_what_all_at_once_picks(
    seed: int, monkeypatch: pytest.MonkeyPatch
) -> None:
    # _leader_among asks about a leader's boxes in blocks, nearest first, and
    # stops at the first block holding a leader that crosses nothing: the
    # place and the leader are those asking about every box at once gives
    from mmt_plans.drawing import labels as mod

    labels, rng = _crowded_labels(seed)
    blocked, block = mod.Labels._leader_among, mod._LEADER_BLOCK
    levels = set()
    for _ in range(12):
        anchor = tuple(rng.uniform(0.0, 60.0, size=2))
        towards = tuple(rng.uniform(-1.0, 1.0, size=2))
        w, h = float(rng.uniform(3.0, 12.0)), 3.5
        got = []
        for among, size in ((blocked, block), (blocked, 1), (_leader_among_at_once, block)):
            monkeypatch.setattr(mod, "_LEADER_BLOCK", size)
            monkeypatch.setattr(mod.Labels, "_leader_among", among)
            got.append(labels._leader_place((anchor, towards, 1.5), w, h, 1.0))
            got.append(labels._wide_leader_place((anchor, towards, 1.5), w, h, 1.0))
        assert got[0::2] == [got[0]] * 3 and got[1::2] == [got[1]] * 3
        for found in got[:2]:
            if found is not None:
                led = labels._crossings(np.array([LineString(found[1])]))[0]
                levels.add(min(led, 1))
            else:
                levels.add(-1)
    assert levels == {-1, 0, 1}  # none found, one crossing nothing, one crossing a few


@pytest.mark.parametrize("seed", [4, 5])
def test_what_touches_a_leaders_foot_is_found_by_its_box_first(seed: int) -> None:
    # _met_at_feet measures only the lines whose boxes come within 0.05 mm
    # of a foot: the counts are those of measuring every line at every foot
    import shapely

    labels, rng = _crowded_labels(seed)
    index = labels._index()
    shapes = np.asarray(labels._obstacles, dtype=object)
    lines = np.flatnonzero(shapely.get_type_id(shapes) != 0)
    # feet on the lines' ends and corners, where lines meet, and anywhere
    ends = shapely.get_coordinates(shapes[lines])
    feet = np.concatenate([ends[rng.integers(len(ends), size=30)], rng.uniform(0, 60, (10, 2))])
    ax, ay = np.repeat(feet[:, 0], 8), np.repeat(feet[:, 1], 8)
    turn = np.tile(np.radians(45.0 * np.arange(8)), len(feet))
    leaders = shapely.linestrings(
        np.stack(
            [
                np.c_[ax, ay] + 1.8 * np.c_[np.cos(turn), np.sin(turn)],
                np.c_[ax, ay] + 9.0 * np.c_[np.cos(turn), np.sin(turn)],
            ],
            axis=1,
        )
    )
    crossed = labels._crossings(leaders)
    want = crossed.copy()
    for fx, fy in np.unique(np.c_[ax, ay], axis=0):  # every line measured at every foot
        at = lines[shapely.dwithin(shapes[lines], shapely.Point(fx, fy), 0.05)]
        if not at.size:
            continue
        mine = np.flatnonzero((ax == fx) & (ay == fy))
        weight = np.where(index.uncrossable[at] | np.isin(at, list(labels._leaders)), 10**6, 1)
        gap = shapely.distance(leaders[mine][:, None], shapes[at][None, :])
        reach = np.asarray(labels._clearance)[at]
        kept = ((gap < reach) * weight).sum(axis=1)
        hair = np.minimum(reach, 0.15)
        want[mine] = np.maximum(want[mine] - kept, 0) + ((gap < hair) * weight).sum(axis=1)
    got = labels._met_at_feet(leaders, crossed, ax, ay)
    assert np.array_equal(got, want) and not np.array_equal(want, crossed)


@pytest.mark.parametrize("seed", [4, 5])
def test_leaders_past_what_a_pick_allows_keep_their_count_unmeasured_at_feet(seed: int) -> None:
    # _leaders_of asks _met_at_feet with most=_LEADER_CROSSINGS[-1]: a leader
    # whose count less all that meets its foot is still past it is left as it
    # was. Every count a pick reads (at most `most`) is the measured one, the
    # others stay past `most`, and some are left so
    import shapely

    from mmt_plans.drawing.labels import _LEADER_CROSSINGS

    labels, rng = _crowded_labels(seed)
    shapes = np.asarray(labels._obstacles, dtype=object)
    ends = shapely.get_coordinates(shapes[shapely.get_type_id(shapes) != 0])
    feet = np.concatenate([ends[rng.integers(len(ends), size=30)], rng.uniform(0, 60, (10, 2))])
    ax, ay = np.repeat(feet[:, 0], 8), np.repeat(feet[:, 1], 8)
    turn = np.tile(np.radians(45.0 * np.arange(8)), len(feet))
    leaders = shapely.linestrings(
        np.stack(
            [
                np.c_[ax, ay] + 1.8 * np.c_[np.cos(turn), np.sin(turn)],
                np.c_[ax, ay] + 9.0 * np.c_[np.cos(turn), np.sin(turn)],
            ],
            axis=1,
        )
    )
    most = _LEADER_CROSSINGS[-1]
    crossed = labels._crossings(leaders)
    want = labels._met_at_feet(leaders, crossed, ax, ay)
    got = labels._met_at_feet(leaders, crossed, ax, ay, most=most)
    picked = want <= most
    assert np.array_equal(got[picked], want[picked]) and (got[~picked] > most).all()
    assert picked.any() and not np.array_equal(got, want)


def test_distance_outside_a_polygon_is_shapelys_within_rounding() -> None:
    # _caption_place takes the distance of the grid's points outside a link's
    # polygon in numpy: shapely's own to 1e-9 mm (it decides nothing closer
    # than 1e-6 mm by it); a shape other than a polygon measured by shapely
    import shapely

    from mmt_plans.sheets.sheet2 import _distance_outside

    rng = np.random.default_rng(21)
    for n in (2, 3, 3, 4, 5, 8, 8):
        region = shapely.convex_hull(shapely.multipoints(rng.uniform(0.0, 300.0, size=(n, 2))))
        points = rng.uniform(-50.0, 350.0, size=(4000, 2))
        outside = points[~shapely.contains_xy(region, points[:, 0], points[:, 1])]
        want = shapely.distance(shapely.points(outside), region)
        got = _distance_outside(region, outside)
        assert np.abs(got - want).max() <= 1e-9 and want.max() > 10.0


def test_a_labels_width_kept_is_the_width_measured_at_its_size() -> None:
    # Labels.width keeps each markup's width at each letter height: asked
    # again, and at another height (the smaller figures), it is a fresh measure
    from mmt_plans.drawing.labels import Labels
    from mmt_plans.drawing.sketch import Sketch

    def fresh(markup: str, size: float) -> float:
        probe = RecordingBackend(look=RecordingBackend().look)
        return max(probe.rich_text((0.0, 0.0), line, size) for line in markup.split("\n"))

    labels = Labels(Sketch(RecordingBackend().look), 3.5)
    for markup in ("F_{in4}", "R_{12}^{n}", "d,\ns_{5}", "F_{in4}"):
        for size in (3.5, 2.5, 3.5):
            labels.size = size
            assert labels.width(markup) == fresh(markup, size)
    assert fresh("F_{in4}", 2.5) < fresh("F_{in4}", 3.5)


def test_unique_ints_is_numpys_unique() -> None:
    # the placers' queries key their (query, obstacle) pairs once each by
    # unique_ints: np.unique's answer (sorted, each once), empty and repeated too
    from mmt_plans.drawing.labels import unique_ints

    rng = np.random.default_rng(21)
    for n in (0, 1, 2, 7, 100, 5000):
        for high in (1, 3, 50, 10**9):
            keys = rng.integers(0, high, size=n)
            got = unique_ints(keys)
            assert got.dtype == np.unique(keys).dtype and np.array_equal(got, np.unique(keys))
