"""Measuring the written SVG as an instructor measures the sheet with a ruler:
a vector's drawn length (from its start to the tip of its arrowhead, in the
file's own coordinates, mm) times the drawing's μ gives back the computed
value within 0.1 %."""

from __future__ import annotations

import math
import re
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
import pytest

import mmt_plans

from mmt_plans.render.svg import SvgBackend
from mmt_plans.drawing.page import Page
from mmt_plans.sheets.sheet1 import compose_sheet1
from mmt_plans.sheets.sheet2 import compose_sheet2

ROOT = Path(__file__).resolve().parents[2]
SVG = "{http://www.w3.org/2000/svg}"


def _svg(compose, analysis):
    page = Page.of("A1")
    backend = SvgBackend(page.width, page.height)
    sheet = compose(analysis, backend)
    return sheet, ET.fromstring(backend.to_string())


def _group(root, gid):
    found = [g for g in root.iter(f"{SVG}g") if g.get("id") == gid]
    assert found, gid
    return found[0]


def _arrows(group):
    """(start, tip) of every arrow in a group: a <line> followed by its filled head."""
    items = list(group.iter())
    out = []
    for a, b in zip(items, items[1:]):
        # a thin line is never an arrow's shaft (the ticks joining a force
        # polygon's side drawn beside its line to its exact ends are thin)
        if (a.tag == f"{SVG}line" and a.get("class") != "thin"
                and b.tag == f"{SVG}path" and b.get("fill") == "black"):
            start = np.array([float(a.get("x1")), float(a.get("y1"))])
            head = np.array([float(v) for v in re.findall(r"-?\d+(?:\.\d+)?", b.get("d"))]).reshape(-1, 2)
            tip = head[np.argmax(np.hypot(*(head - start).T))]
            out.append((a.get("class"), start, tip))
    return out


@pytest.mark.parametrize("stem", ["six_link_press", "shaper", "five_dyads"])
def test_plan_vectors_measured_in_the_svg(stem):
    analysis = mmt_plans.solve(mmt_plans.load(ROOT / "samples" / f"{stem}.toml"))
    sheet, root = _svg(compose_sheet1, analysis)
    for i in analysis.plan_positions:
        view = analysis.plan(i)
        # each position's plans at their own μ where one μ cannot hold both (issue 21)
        for kind, images, mu in (("velocity", view.velocity_images, sheet.record.mu_V[i]),
                                 ("acceleration", view.acceleration_images, sheet.record.mu_a[i])):
            values = [float(np.hypot(*v)) for v in images.values()]
            measured = [c for c in _arrows(_group(root, f"{kind}-plan-{i}")) if c[0] == "main"]
            assert measured
            for _, start, tip in measured:
                length = math.dist(start, tip) * mu
                assert min(abs(length - v) for v in values) <= 1e-3 * length, (kind, i, length)


@pytest.mark.parametrize("stem", ["six_link_press", "shaper", "five_dyads"])
def test_force_polygons_measured_in_the_svg(stem):
    analysis = mmt_plans.solve(mmt_plans.load(ROOT / "samples" / f"{stem}.toml"))
    fa = analysis.forces_at()
    sheet, root = _svg(lambda a, b: compose_sheet2(a, b, forces=fa), analysis)
    polys = [(g.name, g.polygons) for g in fa.groups]
    polys.append((str(fa.driving_link.link), (fa.driving_link.polygon,)))
    for name, polygons in polys:
        mu = sheet.scales[f"mu_F {name}"]
        sides = [v for p in polygons for v in p.vectors]
        values = [v.magnitude for v in sides]
        # R = R^n + R^t drawn as the resultant of its two components
        values += [float(np.hypot(*(np.asarray(a.vector) + np.asarray(b.vector))))
                   for a, b in zip(sides, sides[1:])
                   if {a.label[-2:], b.label[-2:]} == {"^n", "^t"} and a.label[:-2] == b.label[:-2]]
        measured = _arrows(_group(root, f"force-polygon-{name}"))
        assert measured
        for _, start, tip in measured:
            length = math.dist(start, tip) * mu
            assert min(abs(length - v) for v in values) <= 1e-3 * length, (name, length)
