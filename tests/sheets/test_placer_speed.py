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

    def agrees() -> None:
        assert np.array_equal(labels._written_bounds(), shapely.bounds(labels.boxes).reshape(-1, 4))
        probe = shapely.box(0.0, 0.0, 30.0, 30.0)
        got = labels._written_tree().query(probe, predicate="dwithin", distance=0.15)
        want = [i for i, b in enumerate(labels.boxes) if shapely.dwithin(b, probe, 0.15)]
        assert sorted(got.tolist()) == want

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

    def counted(fa, mu_V, look, lang, arms, details=()):  # noqa: ANN001, ANN202
        drawn.append((mu_V, tuple(details)))
        return sketch_lever(fa, mu_V, look, lang, arms, details)

    monkeypatch.setattr(sheet2, "sketch_lever", counted)
    sol = mmt_plans.solve(mmt_plans.load(ROOT / "samples" / "five_dyads.toml"))
    result = sheet2.compose_sheet2(sol, Backend(841.0, 594.0), "en")
    assert result.details  # found at the scale reached
    assert len(drawn) == len(set(drawn))
