"""The small scheme of every task file, through recorded drawing calls."""

from __future__ import annotations

import importlib.util
import math
from pathlib import Path

import numpy as np
import pytest
from shapely.geometry import box

import mmt_plans
from mmt_plans.render.look import load_look
from mmt_plans.drawing.layout import find_overlaps
from mmt_plans.sheets.schematic import (
    LABEL_GROUP,
    NUMBER_GROUP,
    sketch_schematic,
    task_of,
)

ROOT = Path(__file__).resolve().parents[2]
TASKS = ROOT / "samples" / "tasks"
SEEDS = ("seed003", "seed002")
FILES = sorted(p for seed in SEEDS for p in (TASKS / seed).glob("*.toml"))
W, H = 75.0, 45.0  # about a cell of the contact sheets


@pytest.fixture(scope="module")
def look():
    return load_look()


def _label_boxes(sk) -> dict[str, object]:
    """Group id → the envelope of its lettering (a rich text is several text calls)."""
    boxes: dict[str, list] = {}
    for c in sk.named("text"):
        gid = next((g for g in c.groups if g.startswith((LABEL_GROUP, NUMBER_GROUP, "omega"))), None)
        if gid is not None:
            boxes.setdefault(gid, []).append(box(*sk.text_box(c)))
    out = {}
    for gid, parts in boxes.items():
        x0 = min(b.bounds[0] for b in parts)
        y0 = min(b.bounds[1] for b in parts)
        x1 = max(b.bounds[2] for b in parts)
        y1 = max(b.bounds[3] for b in parts)
        out[gid] = box(x0, y0, x1, y1)
    return out


def _text_of(sk, gid: str) -> str:
    return "".join(c["content"] for c in sk.in_group(gid) if c.name == "text")


def test_every_seed_task_is_here():
    assert len(list((TASKS / "seed003").glob("*.toml"))) == 55
    assert len(list((TASKS / "seed002").glob("*.toml"))) == 60
    assert task_of("task03_v2.toml") == (3, 2) and task_of("task6_v09.toml") == (6, 9)


@pytest.mark.parametrize("path", FILES, ids=lambda p: f"{p.parent.name}/{p.stem}")
def test_schematic_of_every_task(path, look):
    analysis = mmt_plans.solve(mmt_plans.load(path))
    mech = analysis.mechanism
    sk = sketch_schematic(analysis, look, "en", width_mm=W, height_mm=H)

    # Every point letter and every link number, each in its own group.
    for name in mech.point_owners:
        assert _text_of(sk, f"{LABEL_GROUP}{name}") == name
    for lid in mech.links:
        assert _text_of(sk, f"{NUMBER_GROUP}{lid}") == str(lid)

    # Within the box: the extent (text boxes included) and every defining point.
    ext = sk.extent()
    assert ext.left >= -1e-6 and ext.bottom >= -1e-6
    assert ext.right <= W + 1e-6 and ext.top <= H + 1e-6

    # No two labels share area.
    boxes = _label_boxes(sk)
    assert len(boxes) == len(mech.point_owners) + len(mech.links) + 1
    assert find_overlaps(boxes) == []

    # A circle at every joint.
    circles = [c for c in sk.named("circle") if c["fill"] == "white"]
    assert len(circles) >= sum(len(o) > 1 for o in mech.point_owners.values())


@pytest.mark.parametrize("name", ["seed003/task01_v1", "seed002/task3_v00", "seed002/task6_v00"])
def test_crank_arrow_turns_with_the_drive_and_output_arrow_points_the_working_way(name, look):
    analysis = mmt_plans.solve(mmt_plans.load(TASKS / f"{name}.toml"))
    mech = analysis.mechanism
    sk = sketch_schematic(analysis, look, "en", width_mm=W, height_mm=H)
    arc = sk.named("arc")[0]
    centre = np.array(arc["center"])
    arrows = sk.named("arrow")
    omega, output = arrows[0], arrows[1]
    tail, tip = np.array(omega["start"]) - centre, np.array(omega["end"]) - centre
    turn = float(tail[0] * tip[1] - tail[1] * tip[0])
    assert (turn > 0) == (mech.drive.sense == "ccw")
    d = np.array(output["end"]) - np.array(output["start"])
    w = np.asarray(mech.study.working_direction, dtype=float)
    assert math.isclose(float(np.dot(d, w)) / float(np.hypot(*d)), 1.0, abs_tol=1e-9)


def test_drawn_to_one_scale(look):
    """Joints lie where the solution puts them, all to one scale (press of seed 003)."""
    analysis = mmt_plans.solve(mmt_plans.load(TASKS / "seed003" / "task01_v1.toml"))
    sk = sketch_schematic(analysis, look, "en", width_mm=W, height_mm=H)
    k = analysis.entry(0)
    true = {n: np.asarray(analysis.sweep.points[n][k]) for n in analysis.mechanism.point_owners}
    drawn = {c["center"] for c in sk.named("circle")}
    a, b = true["O1"], true["O2"]
    # find the scale from the two pivots' circles (the biggest white ones)
    pins = sorted((c for c in sk.named("circle") if c["radius"] > 1.0), key=lambda c: c["center"][0])
    p1, p2 = np.array(pins[0]["center"]), np.array(pins[-1]["center"])
    scale = float(np.hypot(*(p2 - p1))) / float(np.hypot(*(b - a)))
    for n, p in true.items():
        q = p1 + (p - a) * scale
        assert min(math.dist(q, c) for c in drawn) < 1e-6, n


def _make_schematics():
    spec = importlib.util.spec_from_file_location("make_schematics", TASKS / "make_schematics.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


@pytest.mark.parametrize("seed", SEEDS)
def test_shipped_schematics_are_up_to_date(seed):
    make = _make_schematics()
    shipped = TASKS / seed / "schematics"
    assert (shipped / make.CONTACT_SHEET).is_file()
    assert (shipped / "contact_sheet.png").is_file()
    tasks = {task_of(p)[0] for p in (TASKS / seed).glob("*.toml")}
    assert {p.name for p in shipped.glob("task_*.svg")} == {f"task_{t:02d}.svg" for t in tasks}
    assert make.stale(TASKS / seed, shipped) == [], "rerun samples/tasks/make_schematics.py"


def test_up_to_date_check_forgives_only_the_last_rounding():
    make = _make_schematics()
    assert make.same_drawing('<line x1="1.234" y1="5"/>', '<line x1="1.235" y1="5"/>')
    assert not make.same_drawing('<line x1="1.234" y1="5"/>', '<line x1="1.334" y1="5"/>')
    assert not make.same_drawing('<text>A</text>', '<text>B</text>')
    assert not make.same_drawing("<svg/>", None)
