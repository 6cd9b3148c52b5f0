"""The mechanism-pose component: one pose's records, blocks on their guides,
a block drawn once, near-coincident blocks of two positions told apart."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

import mmt_plans
from mmt_plans.drawing.pose import Block, Guide, Pose, draw_poses
from mmt_plans.render.look import load_look
from mmt_plans.render.recording import Circle, Line, Polygon, RecordingBackend

ROOT = Path(__file__).resolve().parents[2]


def _slider_crank(x_b: float) -> Pose:
    """A central slider-crank drawn by hand: pivot O at the origin, pin A, the
    slider's point B on the x axis at x_b (mm)."""
    pts = {"O": np.array([0.0, 0.0]), "A": np.array([6.0, 8.0]), "B": np.array([x_b, 0.0])}
    u = np.array([1.0, 0.0])
    return Pose(
        pts,
        [("O", "A"), ("A", "B"), ("B",)],
        pins=["A", "B"],
        pivots=["O"],
        guides=[Guide(np.array([20.0, 0.0]), np.array([60.0, 0.0]), u, "frame", 3.5)],
        blocks=[Block((3, 0), pts["B"], u, (6.0, 3.5))],
    )


def _record(poses):
    rec = RecordingBackend(look=load_look())
    return rec, draw_poses(rec, poses)


def test_every_point_is_drawn_once_and_the_links_as_lines():
    rec, drawn = _record([_slider_crank(40.0)])
    circles = [c for c in rec.calls if isinstance(c, Circle)]
    # A and B: one white pin each; O: the pin of its base
    centres = sorted(c.center for c in circles)
    assert centres == [(0.0, 0.0), (6.0, 8.0), (40.0, 0.0)]
    links = {(c.start, c.end) for c in rec.calls if isinstance(c, Line) and c.line == "main"}
    assert ((0.0, 0.0), (6.0, 8.0)) in links and ((6.0, 8.0), (40.0, 0.0)) in links
    assert len(drawn.segments) == 2 and len(drawn.pins) == 2 and len(drawn.pivots) == 1


def test_a_block_lies_on_its_guide_and_covers_its_point():
    rec, drawn = _record([_slider_crank(40.0)])
    (block,) = [c for c in rec.calls if isinstance(c, Polygon)]
    xs = [p[0] for p in block.vertices]
    ys = [p[1] for p in block.vertices]
    # 12 × 7 mm, centred on B = (40, 0), its long sides along the guide
    assert (min(xs), max(xs), min(ys), max(ys)) == (34.0, 46.0, -3.5, 3.5)
    assert block.line == "main" and block.fill == "white"
    # the hatched guide's main line 3.5 mm under the path, the block's lower side on it
    guide = [c for c in rec.calls if isinstance(c, Line) and c.line == "main" and c.start[1] == -3.5]
    assert guide and guide[0].start == (20.0, -3.5) and guide[0].end == (60.0, -3.5)


def test_a_pivot_pin_is_drawn_over_its_legs():
    rec, _ = _record([_slider_crank(40.0)])
    order = [
        i for i, c in enumerate(rec.calls)
        if (isinstance(c, Line) and c.start == (0.0, 0.0) and c.end[1] < 0.0)
        or (isinstance(c, Circle) and c.center == (0.0, 0.0))
    ]
    kinds = [type(rec.calls[i]).__name__ for i in order]
    assert kinds == ["Line", "Line", "Circle"]


def test_blocks_of_one_place_are_drawn_once():
    rec, drawn = _record([_slider_crank(40.0), _slider_crank(40.0)])
    assert len([c for c in rec.calls if isinstance(c, Polygon)]) == 1
    assert len(drawn.blocks) == 1 and drawn.thin_blocks == 0


def test_near_coincident_blocks_of_two_positions_the_later_thin_in_outline():
    rec, drawn = _record([_slider_crank(40.0), _slider_crank(44.0)])
    blocks = [c for c in rec.calls if isinstance(c, Polygon)]
    assert [(b.line, b.fill) for b in blocks] == [("main", "white"), ("thin", "none")]
    assert drawn.thin_blocks == 1


def test_a_joint_of_two_positions_a_tenth_of_a_mm_apart_is_drawn_once():
    # two mirror positions of a crosshead put a pin 0.12 mm off itself: one
    # circle on paper (the main line is 0.7 mm wide), not two rings run together
    a, b = _slider_crank(40.0), _slider_crank(40.1)
    rec, drawn = _record([a, b])
    centres = [c.center for c in rec.calls if isinstance(c, Circle)]
    assert centres.count((40.0, 0.0)) == 1 and (40.1, 0.0) not in centres
    assert len([c for c in rec.calls if isinstance(c, Polygon)]) == 1


def test_blocks_apart_are_both_drawn_whole():
    rec, drawn = _record([_slider_crank(40.0), _slider_crank(53.0)])
    blocks = [c for c in rec.calls if isinstance(c, Polygon)]
    assert [(b.line, b.fill) for b in blocks] == [("main", "white")] * 2


def test_the_extent_holds_every_record():
    rec, drawn = _record([_slider_crank(40.0)])
    x0, y0, x1, y1 = drawn.extent
    for c in rec.calls:
        bx0, by0, bx1, by1 = c.bbox()
        assert x0 - 2.01 <= bx0 and bx1 <= x1 + 2.01 and y0 - 1e-9 <= by0 and by1 <= y1 + 1e-9


# --- the sheets through the component ---------------------------------------------------


def _solve(path: str):
    return mmt_plans.solve(mmt_plans.load(ROOT / path))


def _blocks(calls):
    return [c for c in calls if isinstance(c, Polygon) and c.fill in ("white", "none")]


def test_seed003_task3_slider_blocks_of_positions_3_and_9_are_one_block():
    """Positions 3 and 9 of the opposed slider-cranks are mirror images: each
    slider stands at the same place in both. The block was drawn twice, one on
    the other (the doubled block of issue #21); it is drawn once."""
    from mmt_plans.sheets.sheet1 import sketch_mechanism

    sol = _solve("samples/tasks/seed003/task03_v3.toml")
    sk = sketch_mechanism(sol, 0.005, load_look(), "en")
    blocks = _blocks(sk.calls)
    centres = [tuple(np.round(np.mean(b.vertices, axis=0), 6)) for b in blocks]
    assert len(centres) == len(set(centres))
    # B and C each at one place in positions 0 (where both overlap) ... count by slider:
    # position 0 (φ1 = 0) has B and C at their own places, positions 3 and 9 share theirs
    assert len(blocks) == 4


def test_seed003_task3_rods_have_their_eps_arcs():
    """ε2 = ε4 = ±81.8 1/s² at positions 3 and 9 (ω2 = ω4 = 0 there): the rods
    carry an ε arc at each planned position."""
    from mmt_plans.sheets.sheet1 import sketch_mechanism

    sol = _solve("samples/tasks/seed003/task03_v3.toml")
    for i in sol.plan_positions:
        k = sol.entry(i)
        assert abs(abs(float(sol.sweep.eps[2][k])) - 81.765) < 1e-3
    sk = sketch_mechanism(sol, 0.005, load_look(), "en")
    labels = {c.naming for c in sk.calls if getattr(c, "naming", None) is not None}
    names = [n.markup for n in labels]  # one per label, its runs and leader sharing it
    assert names.count("ε_{2}") == 2 and names.count("ε_{4}") == 2


@pytest.mark.parametrize("sample", ["six_link_press", "shaper", "five_dyads", "offset_slider_crank"])
def test_loaded_mechanism_draws_each_joint_once(sample):
    from mmt_plans.sheets.sheet2 import sketch_loaded_mechanism

    sol = _solve(f"samples/{sample}.toml")
    fa = sol.require_forces()
    sk = sketch_loaded_mechanism(fa, 0.005, load_look(), "en")
    pins = [c.center for c in sk.calls if isinstance(c, Circle) and c.radius == 1.2]
    assert len(pins) == len(set(pins))
    mech = sol.mechanism
    assert len(pins) == len({p.point for p in mech.revolutes})
    blocks = _blocks(sk.calls)
    assert len(blocks) == len({(s.slider, s.guide) for s in mech.sliders})


@pytest.mark.parametrize("task", ["task02_v1", "task03_v1", "task07_v1", "task11_v1"])
def test_a_task_schematic_draws_each_point_once_and_each_block_on_its_guide(task):
    from mmt_plans.sheets.schematic import sketch_schematic

    sol = _solve(f"samples/tasks/seed003/{task}.toml")
    sk = sketch_schematic(sol, load_look(), "en")
    mech = sol.mechanism
    circles = [c for c in sk.calls if isinstance(c, Circle)]
    # every point of a moving link once (a pin or a dot), every frame pivot once
    moving = [p for p, o in mech.point_owners.items() if 0 not in o]
    pivots = [p for p, o in mech.point_owners.items() if 0 in o and len(o) > 1]
    assert len(circles) == len(moving) + len(pivots)
    assert len({c.center for c in circles}) == len(circles)
    blocks = _blocks(sk.calls)
    assert len(blocks) == len(mech.sliders)
    for b in blocks:
        # a block's centre is a drawn point: its slider's
        centre = np.mean(b.vertices, axis=0)
        assert min(math.dist(centre, c.center) for c in circles) < 1e-6
