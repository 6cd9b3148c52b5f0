"""The label placer's and sheet 2's short cuts for speed (issue 21, item 4):
each must give what the plain form gives, to the bit, so that the sheets
stay byte-identical: the distance kernels, the written boxes' index kept
between labels, the candidates asked in two batches, the lever sketched once
at the scale it reaches."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
import shapely

import mmt_plans
from mmt_plans.drawing import labels as mod
from mmt_plans.drawing.labels import Labels
from mmt_plans.drawing.sketch import Sketch
from mmt_plans.render.recording import RecordingBackend

ROOT = Path(__file__).resolve().parents[2]


def _point_segment_plain(px: np.ndarray, py: np.ndarray, s: np.ndarray) -> np.ndarray:
    """_point_segment as it read with np.where and np.clip."""
    vx, vy = s[:, 2] - s[:, 0], s[:, 3] - s[:, 1]
    n2 = vx * vx + vy * vy
    with np.errstate(divide="ignore", invalid="ignore"):
        t = np.where(n2 > 0.0, ((px - s[:, 0]) * vx + (py - s[:, 1]) * vy) / n2, 0.0)
    t = np.clip(t, 0.0, 1.0)
    return np.hypot(px - (s[:, 0] + t * vx), py - (s[:, 1] + t * vy))


def test_point_segment_is_its_plain_form_to_the_bit() -> None:
    # segments of no length among them, points on the segments' lines and
    # ends, rows of points (a box's four corners) at once
    rng = np.random.default_rng(3)
    for _ in range(300):
        n = int(rng.integers(1, 40))
        s = np.round(rng.normal(size=(n, 4)) * 10.0, int(rng.integers(0, 3)))
        flat = rng.random(n) < 0.2
        s[flat, 2:] = s[flat, :2]
        px, py = np.round(rng.normal(size=(2, n)) * 10.0, int(rng.integers(0, 3)))
        px[: n // 3], py[: n // 3] = s[: n // 3, 2], s[: n // 3, 3]
        assert np.array_equal(mod._point_segment(px, py, s), _point_segment_plain(px, py, s))
        corners = np.stack([px, px + 1.0, px, px - 2.5]), np.stack([py, py, py + 3.0, py])
        assert np.array_equal(mod._point_segment(*corners, s), _point_segment_plain(*corners, s))


def _crowd(seed: int) -> tuple[Labels, np.random.Generator]:
    """A placer over a random crowd of thin and main lines and rings."""
    rng = np.random.default_rng(seed)
    sk = Sketch(RecordingBackend().look)
    for _ in range(60):
        a = rng.uniform(0.0, 60.0, size=2)
        sk.line(tuple(a), tuple(a + rng.uniform(-25.0, 25.0, size=2)), "thin")
    for _ in range(10):
        sk.circle(tuple(rng.uniform(0.0, 60.0, size=2)), float(rng.uniform(0.8, 4.0)), "thin")
    return Labels(sk, 3.5), rng


def test_written_boxes_index_follows_every_change_of_them() -> None:
    # the bounds and tree of the labels written are kept between labels: after
    # a label written, undone (_restore) and written again (_put_back) they
    # are those of the boxes as they stand
    labels, rng = _crowd(7)

    probes = np.random.default_rng(8)

    def agrees() -> None:
        assert np.array_equal(labels._written_bounds(), shapely.bounds(labels.boxes).reshape(-1, 4))
        assert list(labels._written_boxes()) == labels.boxes
        # leaders from round the middle out: near a label written exactly
        # where one of the boxes is within 0.15 mm of it (as a tree asks it)
        x0, y0 = probes.uniform(20.0, 40.0, size=(2, 60))
        x1, y1 = probes.uniform(0.0, 60.0, size=(2, 60))
        lines = shapely.linestrings(np.stack([np.c_[x0, y0], np.c_[x1, y1]], axis=1))
        got = labels._near_written(lines, x0, y0, x1, y1)
        tree = shapely.STRtree(labels.boxes)
        want = np.zeros(len(lines), dtype=bool)
        want[tree.query(lines, predicate="dwithin", distance=0.15)[0]] = True
        assert np.array_equal(got, want) and want.any() and not want.all()

    for k in range(4):
        labels.place(tuple(rng.uniform(0.0, 60.0, size=2)), f"A_{{{k}}}")
    agrees()
    saved = labels._state()
    for k in range(3):
        labels.place(tuple(rng.uniform(0.0, 60.0, size=2)), f"B_{{{k}}}")
    agrees()
    written = labels._written(saved)
    labels._restore(saved)
    assert len(labels.boxes) == 4
    agrees()
    labels._put_back(written)
    assert len(labels.boxes) == 7
    agrees()


@pytest.mark.parametrize("seed", [11, 12, 13])
def test_a_label_takes_the_first_free_place_near_in_order(seed: int) -> None:
    # _write_first_free asks about its first ring of candidates, then about
    # all the rest at once: the place is the first of `rooms` (each candidate
    # near and free, in order) wherever there is one
    labels, rng = _crowd(seed)
    seen = set()
    for k in range(25):
        anchor = tuple(float(v) for v in rng.uniform(0.0, 60.0, size=2))
        towards = tuple(float(v) for v in rng.uniform(-1.0, 1.0, size=2))
        markup = f"C_{{{k}}}"
        rooms = labels.rooms(anchor, markup, towards=towards)
        before = len(labels.sketch.calls)
        footprint = labels.place(anchor, markup, towards=towards)
        if len(rooms):
            w, h, drop = labels._extent(markup)
            x0, _, x1, y1 = footprint.bounds  # (an index drops under the centre's box)
            assert ((x0 + x1) / 2, y1 - h / 2) == pytest.approx(tuple(rooms[0]), abs=1e-9)
            first_ring = len(mod._COMPASS)
            cx, cy, *_ = labels._around(np.array(anchor), markup, towards, 1.5)
            at = int(np.argmin(np.hypot(cx - rooms[0][0], cy - rooms[0][1])))
            seen.add(at >= first_ring)
        else:
            seen.add(None)
        assert len(labels.sketch.calls) > before
    assert {False, True} <= seen  # places in the first ring and past it


def test_the_lever_at_the_scale_it_reached_is_sketched_once(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    # five_dyads' lever reaches the sheet 3 steps smaller than its textbook
    # scale, its names crowded there: the detail views are found on the lever
    # the composer drew at that scale, not on a second sketch of it
    from mmt_plans.render.recording import RecordingBackend as Backend
    from mmt_plans.sheets import sheet2

    drawn: list[tuple[float, tuple[object, ...]]] = []
    sketch_lever = sheet2.sketch_lever

    def counted(fa, mu_V, look, lang, arms, details=(), **kw):  # noqa: ANN001, ANN003, ANN202
        drawn.append((mu_V, tuple(details)))
        return sketch_lever(fa, mu_V, look, lang, arms, details, **kw)

    monkeypatch.setattr(sheet2, "sketch_lever", counted)
    sol = mmt_plans.solve(mmt_plans.load(ROOT / "samples" / "five_dyads.toml"))
    result = sheet2.compose_sheet2(sol, Backend(841.0, 594.0), "en")
    assert result.details  # found at the scale reached
    assert len(drawn) == len(set(drawn))


def test_a_sheet_fitted_again_draws_no_polygon_or_loaded_mechanism_twice(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    # five_dyads' sheet 2 is fitted again with the lever's detail views found
    # at the scale it reached (_refitted): the force polygons and the loaded
    # mechanism already drawn at a scale are taken from the first composer
    # (as compact as it), each drawn once
    from mmt_plans.render.recording import RecordingBackend as Backend
    from mmt_plans.sheets import sheet2

    polygons: list[tuple[str, float, bool]] = []
    loaded: list[tuple[float, tuple[object, ...], bool]] = []
    refitted: list[bool] = []
    sketch_force_polygons = sheet2.sketch_force_polygons
    sketch_loaded_mechanism = sheet2.sketch_loaded_mechanism
    refit = sheet2._refitted

    def counted_polygons(polys, mu_F, look, lang, gid, *args, **kw):  # noqa: ANN001, ANN002, ANN003, ANN202
        polygons.append((gid, mu_F, kw.get("grow", False)))  # (lettered again to grow)
        return sketch_force_polygons(polys, mu_F, look, lang, gid, *args, **kw)

    def counted_loaded(fa, mu_l, look, lang, compact=False, **kw):  # noqa: ANN001, ANN003, ANN202
        loaded.append((mu_l, tuple(kw.get("details", ())), kw.get("grow", False)))
        return sketch_loaded_mechanism(fa, mu_l, look, lang, compact, **kw)

    def counted_refit(*args):  # noqa: ANN002, ANN202
        refitted.append(True)
        return refit(*args)

    monkeypatch.setattr(sheet2, "sketch_force_polygons", counted_polygons)
    monkeypatch.setattr(sheet2, "sketch_loaded_mechanism", counted_loaded)
    monkeypatch.setattr(sheet2, "_refitted", counted_refit)
    sol = mmt_plans.solve(mmt_plans.load(ROOT / "samples" / "five_dyads.toml"))
    sheet2.compose_sheet2(sol, Backend(841.0, 594.0), "en")
    assert refitted
    assert polygons and len(polygons) == len(set(polygons))
    assert loaded and len(loaded) == len(set(loaded))


def _boxes_clear_plain(index: mod._ObstacleIndex, x0, y0, x1, y1) -> np.ndarray:  # noqa: ANN001
    """boxes_clear as it read: every piece's grown box compared with every
    query (or the tree asked), the segments' ends measured as one 2-row
    array, the rest by their corners and Liang-Barsky at once."""
    clear = np.ones(x0.size, dtype=bool)
    lx, hx, ly, hy = np.minimum(x0, x1), np.maximum(x0, x1), np.minimum(y0, y1), np.maximum(y0, y1)
    g = index.grown
    if lx.size * len(g) > mod._BRUTE_PAIRS:
        qi, pi = np.asarray(index.tree.query(shapely.box(lx, ly, hx, hy)))
    else:
        qi, pi = np.nonzero(
            (lx[:, None] <= g[:, 2])
            & (hx[:, None] >= g[:, 0])
            & (ly[:, None] <= g[:, 3])
            & (hy[:, None] >= g[:, 1])
        )
    reach = index.piece_reach[pi]
    seg, solid, upright = pi < index.n_segs, pi - index.n_segs, index.piece_upright[pi]
    b = np.stack([x0, y0, x1, y1], axis=1)[qi[upright]]
    gap = mod._box_box(b, index.whole_bounds[solid[upright]])
    clear[qi[upright][gap < reach[upright]]] = False
    sq, sp, sr = qi[seg], pi[seg], reach[seg]
    ask = clear[sq]
    sq, sp, sr = sq[ask], sp[ask], sr[ask]
    s = index.segs[sp]
    ex, ey = s[:, [0, 2]].T, s[:, [1, 3]].T
    dx = np.maximum(np.maximum(x0[sq] - ex, ex - x1[sq]), 0.0)
    dy = np.maximum(np.maximum(y0[sq] - ey, ey - y1[sq]), 0.0)
    hit = np.hypot(dx, dy).min(axis=0) < sr
    clear[sq[hit]] = False
    rest = ~hit & clear[sq]
    sq, sr, s = sq[rest], sr[rest], s[rest]
    bb = np.stack([x0[sq], y0[sq], x1[sq], y1[sq]], axis=1)
    corners = mod._point_segment(bb[:, [0, 2, 2, 0]].T, bb[:, [1, 1, 3, 3]].T, s).min(axis=0)
    gap = np.where(mod.segments_meet_boxes(s, bb), 0.0, corners)
    clear[sq[gap < sr]] = False
    ask = ~seg & ~upright & clear[qi]
    rq = qi[ask]
    gap = shapely.distance(shapely.box(x0[rq], y0[rq], x1[rq], y1[rq]), index.whole[solid[ask]])
    clear[rq[gap < reach[ask]]] = False
    return clear


@pytest.mark.parametrize("seed", range(6))
def test_boxes_clear_is_its_plain_form(seed: int) -> None:
    # the pieces first cut to those near all the queries, the segments' ends
    # gathered by column, the corners measured only for boxes no segment
    # runs through: the same boxes clear as the plain form, on crowds of
    # lines, points, rings, text boxes and arrowheads (clearances of 0 and
    # coordinates rounded, so that boxes touch lines), one box, a few, many
    rng = np.random.default_rng(seed)
    shapes, clearance = [], []
    for _ in range(int(rng.integers(20, 160))):
        x, y = np.round(rng.uniform(0.0, 80.0, size=2), 1)
        kind = rng.integers(5)
        if kind == 0:
            shapes.append(
                shapely.LineString(np.round(rng.uniform(-9.0, 9.0, size=(3, 2)), 1) + (x, y))
            )
        elif kind == 1:
            shapes.append(shapely.box(x, y, x + 4.0, y + 2.5))
        elif kind == 2:
            shapes.append(shapely.Polygon(rng.uniform(-3.0, 3.0, size=(3, 2)) + (x, y)))
        elif kind == 3:
            shapes.append(shapely.Point(x, y))
        else:
            shapes.append(shapely.Point(x, y).buffer(float(rng.uniform(0.5, 5.0)), 16).exterior)
        clearance.append(float(rng.choice([0.0, 0.3, 0.4, rng.uniform(0.0, 2.0)])))
    index = mod._ObstacleIndex(shapes, clearance)
    for n in (1, 1, 5, 16, 120, 600):
        cx, cy = np.round(rng.uniform(0.0, 80.0, size=2), 1)
        x0 = np.round(cx + rng.uniform(-15.0, 15.0, size=n), 1)
        y0 = np.round(cy + rng.uniform(-15.0, 15.0, size=n), 1)
        x1, y1 = x0 + rng.uniform(0.5, 8.0, size=n), y0 + rng.uniform(0.5, 4.0, size=n)
        got = index.boxes_clear(x0, y0, x1, y1)
        assert np.array_equal(got, _boxes_clear_plain(index, x0, y0, x1, y1))
