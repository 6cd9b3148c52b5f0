"""What a trial undone leaves to reuse (issue 21, speed of crowded sheet 1s):
the label placer's obstacle index built before a trial serves again once the
trial is undone, and a trial's symbol is measured alone against the drawing's
bounds. Each must give what building and measuring afresh gives, to the bit,
so that the sheets stay byte-identical."""

from __future__ import annotations

import numpy as np
import shapely

from mmt_plans.drawing.labels import Labels, _ObstacleIndex
from mmt_plans.drawing.sketch import Sketch
from mmt_plans.drawing.symbols import sense_arc
from mmt_plans.render.recording import RecordingBackend


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


def _fresh_clear(labels: Labels, boxes: np.ndarray) -> np.ndarray:
    """`free_boxes` as an index built now of the obstacles as they stand answers it."""
    index = _ObstacleIndex(labels._obstacles, labels._clearance, labels._heavy)
    return index.boxes_clear(boxes[:, 0], boxes[:, 1], boxes[:, 2], boxes[:, 3])


def test_obstacle_index_before_a_trial_serves_again_once_it_is_undone() -> None:
    labels, rng = _crowd(5)
    xy = rng.uniform(0.0, 60.0, size=(400, 2))
    boxes = np.c_[xy, xy + rng.uniform(1.0, 6.0, size=(400, 2))]
    labels.place((30.0, 30.0), "A")
    before = labels.free_boxes(boxes)
    index = labels._index()
    with labels.trial():  # an arc drawn and a label written over it, undone
        sense_arc(labels.sketch, np.array([20.0, 20.0]), 9.0, 1.0, 0.0, 150.0)
        labels.place((26.0, 22.0), "ω_{3}")
        during = labels.free_boxes(boxes)
        assert labels._index() is not index
        assert np.array_equal(during, _fresh_clear(labels, boxes))
    # the same obstacles as before the trial: the same index, the same answers
    assert labels._index() is index
    assert np.array_equal(labels.free_boxes(boxes), before)
    assert np.array_equal(before, _fresh_clear(labels, boxes))
    assert not np.array_equal(before, during)  # (the trial did cover some)


def test_obstacles_cut_back_and_written_anew_are_indexed_anew() -> None:
    # as many obstacles as an index kept, but other ones: written after a
    # state undone to an earlier one (the serials tell them apart)
    labels, rng = _crowd(6)
    xy = rng.uniform(0.0, 60.0, size=(400, 2))
    boxes = np.c_[xy, xy + rng.uniform(1.0, 6.0, size=(400, 2))]
    start = labels._state()
    labels.sketch.line((10.0, 50.0), (30.0, 20.0), "main")
    labels.free_boxes(boxes)
    first = labels._index()
    count = len(labels._obstacles)
    labels._restore(start)
    labels.sketch.line((50.0, 10.0), (20.0, 40.0), "main")
    labels.free_boxes(boxes)
    assert len(labels._obstacles) == count
    assert labels._index() is not first
    assert np.array_equal(labels.free_boxes(boxes), _fresh_clear(labels, boxes))


def test_a_trial_symbol_measured_alone_gives_the_extent_measured_whole() -> None:
    labels, rng = _crowd(9)
    sk = labels.sketch
    whole_before = sk.extent()
    drawn, bounds = len(sk.calls), sk.bounds()
    for _ in range(40):
        centre = rng.uniform(-10.0, 70.0, size=2)
        with labels.trial():
            sense_arc(sk, centre, float(rng.uniform(3.0, 30.0)), 1.0, 10.0, 160.0)
            assert sk.extent_since(bounds, drawn) == sk.extent()
        assert sk.extent() == whole_before
    empty = Sketch(RecordingBackend().look)
    assert empty.extent_since(None, 0) == empty.extent()


def test_arcs_near_what_is_drawn_are_the_trees_own_pairs() -> None:
    # _ArcPlacer._near_arcs leaves the segments wholly inside or beyond an
    # arc unasked: the pairs are those of the tree's "dwithin" query, every
    # radius and sweep of a link's ω/ε arcs, round a crowd and inside it
    from mmt_plans.sheets.sheet1 import _ArcPlacer

    labels, rng = _crowd(4)
    placer = _ArcPlacer(labels.sketch)
    for radius, sweep in ((6.0, 150.0), (9.0, 100.0), (14.0, 120.0), (21.0, 70.0)):
        centres = rng.uniform(-5.0, 65.0, size=(80, 2))
        starts = rng.uniform(0.0, 360.0, size=80)
        ang = np.radians(starts[:, None] + np.linspace(0.0, sweep, 24)[None, :])
        xy = np.stack(
            [
                centres[:, :1] + radius * np.cos(ang),
                centres[:, 1:] + radius * np.sin(ang),
            ],
            -1,
        )
        lines = shapely.linestrings(xy)
        got = placer._near_arcs(lines, centres, radius, sweep, 0.6)
        want = placer._near_all(lines, 0.6)
        assert np.array_equal(got[0], want[0]) and np.array_equal(got[1], want[1])
        assert want[0].size and len(set(want[0].tolist())) < 80  # (some near, some not)
