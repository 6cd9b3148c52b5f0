"""Sheet 2 through recorded drawing calls: groups, polygons to scale, the lever, layout."""

from __future__ import annotations

import math
from functools import cache
from pathlib import Path

import numpy as np
import pytest
from click.testing import CliRunner

import mmt_plans
from mmt_plans.render.recording import RecordingBackend
from mmt_plans.scales import is_standard
from mmt_plans.sheets.sheet2 import compose_sheet2, detail_gid, force_markup

from lettering import clashes

ROOT = Path(__file__).resolve().parents[2]
SAMPLES = sorted((ROOT / "samples").glob("*.toml"))
PRESS = ROOT / "samples" / "six_link_press.toml"


@cache  # one drawing per sample and language, shared by the tests that read it
def _draw(path: Path, lang: str = "en"):
    analysis = mmt_plans.solve(mmt_plans.load(path))
    backend = RecordingBackend()
    sheet = compose_sheet2(analysis, backend, lang)  # type: ignore[arg-type]
    backend.close()
    return analysis, backend, sheet


@pytest.fixture(scope="module")
def press():
    return _draw(PRESS)


@pytest.fixture(scope="module", params=[p.stem for p in SAMPLES])
def every_sample(request):
    return _draw(ROOT / "samples" / f"{request.param}.toml")


def test_every_required_group_is_drawn(every_sample):
    _, backend, sheet = every_sample
    fa = sheet.forces
    required = {"force-mechanism", "driving-link", f"force-polygon-{fa.driving_link.link}",
                "zhukovsky-lever", "table-loads", "table-reactions", "table-lever",
                "table-balancing", "frame", "title-block"}
    for g in fa.groups:
        required |= {f"group-{g.name}", f"force-polygon-{g.name}"}
    ids = {c["id"] for c in backend.named("begin_group")}
    assert required <= ids
    for gid in required:
        assert backend.in_group(gid), f"{gid} is empty"


def test_no_overlaps_and_inside_the_frame(every_sample):
    _, _, sheet = every_sample
    assert sheet.layout.problems() == []


def test_every_scale_is_from_the_standard_series(every_sample):
    _, _, sheet = every_sample
    assert sheet.scales
    for name, mu in sheet.scales.items():
        assert is_standard(mu), f"{name} = {mu}"


def test_no_two_labels_overlap(every_sample):
    """Lettering of sheet 2 never covers other lettering."""
    _, backend, _ = every_sample
    assert clashes(backend) == []


def _arrows(backend, gid):
    return [c for c in backend.in_group(gid) if c.name == "arrow"]


def _same_side_shifted(arrow, start, end, most=8.0):
    """The arrow is the side start→end: exactly, or shifted perpendicular to
    it by at most `most` mm, its length and direction kept."""
    shift = np.subtract(arrow["start"], start)
    if math.dist(np.add(end, shift), arrow["end"]) > 1e-6:
        return False
    u = np.subtract(end, start) / math.dist(start, end)
    return abs(float(np.dot(shift, u))) < 1e-6 and float(np.hypot(*shift)) <= most


def test_force_polygons_are_drawn_to_scale_and_close(every_sample):
    """Each side of a group's first polygon is an arrow from the drawn origin,
    |arrow|·μF = |F| within 0.1 %, and the drawn sides close: the measured
    sum of the arrows returns to the start."""
    _, backend, sheet = every_sample
    fa = sheet.forces
    groups = [(g.name, g.polygons[0]) for g in fa.groups]
    groups.append((str(fa.driving_link.link), fa.driving_link.polygon))
    for name, polygon in groups:
        gid = f"force-polygon-{name}"
        mu = sheet.scales[f"mu_F {name}"]
        origin = np.array(sheet.origins[gid])
        arrows = _arrows(backend, gid)
        drawn_sum = np.zeros(2)
        for v in polygon.vectors:
            start = origin + np.asarray(v.start) / mu
            end = origin + np.asarray(v.end) / mu
            if math.dist(start, end) < 1.0:  # listed as "shorter than 1 mm"
                drawn_sum += (end - start)
                assert any(force_markup(v.label).replace("{", "").replace("}", "")[0] in t
                           for t in backend.texts())
                continue
            # on its exact place, or (issue 21) drawn beside a vector it would run
            # along: the same length and direction, shifted sideways only
            match = [c for c in arrows if _same_side_shifted(c, start, end)]
            assert match, f"{gid}: side {v.label} is not drawn"
            assert match[0]["length"] * mu == pytest.approx(v.magnitude, rel=1e-3)
            drawn_sum += np.subtract(match[0]["end"], match[0]["start"])
        assert float(np.hypot(*drawn_sum)) < 0.01  # mm


def test_reactions_measured_on_the_polygon(press):
    """|R| read off the drawn polygon (length × μF) equals the reaction of the
    pair, which the force tests check by the equilibrium of every link."""
    _, backend, sheet = press
    fa = sheet.forces
    for g in fa.groups:
        gid = f"force-polygon-{g.name}"
        mu = sheet.scales[f"mu_F {g.name}"]
        lengths = sorted(c["length"] * mu for c in _arrows(backend, gid))
        for r in g.reactions:
            assert min(abs(x - r.magnitude) for x in lengths) <= 1e-3 * r.magnitude, r.name


def test_drawn_lever_is_in_equilibrium_with_the_plans_balancing_force(every_sample):
    """Moments about the pole from the drawn lever: every arrow's start (the
    image of its point, measured) crossed with its drawn direction, times the
    load's magnitude — with F_bal from the force plans, not from the lever."""
    analysis, backend, sheet = every_sample
    fa = sheet.forces
    mu = sheet.scales["mu_V"]
    loads = [f for f in fa.lever.forces if np.hypot(*f.force) > 0]
    # the forces at the images in a detail's disc are drawn in the detail view,
    # at μV / ratio: each arrow with the origin and μ of its drawing
    views = [("zhukovsky-lever", mu)]
    for d in sheet.details:
        views.append((detail_gid(sheet.details, d), mu / d.ratio))
    arrows, origins, mus = [], [], []
    for gid, mu_view in views:
        for c in _arrows(backend, gid):
            arrows.append(c)
            origins.append(np.array(sheet.origins[gid]))
            mus.append(mu_view)
    # forces along one line of action in one sense share one arrow (F_PR, F_in5 at e)
    assert len(arrows) <= len(loads) + 1
    total, scale, used = 0.0, 0.0, set()
    for f in [*loads, fa.lever.balancing]:
        v = np.asarray(f.force, float) / np.hypot(*f.force)
        on_line = []
        for k, c in enumerate(arrows):
            u = np.subtract(c["end"], c["start"]) / c["length"]
            at = np.asarray(f.image, float) / mus[k] + origins[k]  # where the image should be, mm
            r = at - np.asarray(c["start"])
            if abs(float(u[0] * r[1] - u[1] * r[0])) < 1e-6 and float(u @ v) > 1 - 1e-9:
                on_line.append(k)
        assert on_line, f"no arrow on the line of {f.label}"
        # of several arrows on one line, the one that starts at (or runs through) the image
        def gap(k):
            c = arrows[k]
            at = np.asarray(f.image, float) / mus[k] + origins[k]
            u = np.subtract(c["end"], c["start"]) / c["length"]
            t = float(u @ (at - np.asarray(c["start"])))
            return max(0.0, -t, t - c["length"])

        k = min(on_line, key=gap)
        used.add(k)
        c = arrows[k]
        image = (np.subtract(c["start"], origins[k])) * mus[k]  # m/s, pole at the origin
        u = np.subtract(c["end"], c["start"]) / c["length"]
        size = abs(fa.balancing_force_plans) if f.label == "F_bal" else float(np.hypot(*f.force))
        m = size * float(image[0] * u[1] - image[1] * u[0])
        total += m
        scale = max(scale, abs(m))
    assert used == set(range(len(arrows)))
    assert abs(total) <= 1e-6 * scale


def test_lever_arms_in_the_table_are_the_drawn_ones(press):
    _, backend, sheet = press
    arms = sheet.arms["lever"]
    labels = [f.label for f in (*sheet.forces.lever.forces, sheet.forces.lever.balancing)
              if np.hypot(*f.force) > 0]
    assert [a for a, _ in arms] == labels
    mu = sheet.scales["mu_V"]
    for (label, h), f in zip(arms, [f for f in (*sheet.forces.lever.forces, sheet.forces.lever.balancing)
                                     if np.hypot(*f.force) > 0]):
        assert h * mu == pytest.approx(abs(f.arm), rel=1e-12, abs=1e-12)


def test_balancing_table_shows_both_methods(press):
    _, backend, sheet = press
    texts = [c["content"] for c in backend.in_group("table-balancing") if c.name == "text"]
    fa = sheet.forces
    assert f"{fa.balancing_force_plans:.1f}" in texts
    assert f"{fa.balancing_force_lever:.1f}" in texts


def test_ukrainian_sheet2():
    _, backend, _ = _draw(PRESS, "uk")
    texts = " ".join(backend.texts())
    assert "Важіль Жуковського" in texts and "Група Ассура" in texts


def test_force_markup():
    assert force_markup("R34^n") == "R^{n}_{34}"
    assert force_markup("R0_11") == "R_{0,11}"
    assert force_markup("F_in4") == "F_{in4}"
    assert force_markup("G2") == "G_{2}"
    assert force_markup("F_PR") == "F_{PR}"


def test_draw_sheet_1_runs_no_force_analysis(tmp_path, monkeypatch):
    """`draw --sheet 1` asks only for what sheet 1 shows."""
    import mmt_plans.solution

    def refuse(*args, **kwargs):
        raise AssertionError("the force analysis ran for sheet 1")

    monkeypatch.setattr(mmt_plans.solution, "force_analysis_at", refuse)
    from mmt_plans.cli import main

    result = CliRunner().invoke(main, ["draw", str(PRESS), "-o", str(tmp_path), "--format", "svg",
                                       "--sheet", "1"])
    assert result.exit_code == 0, result.output
    assert (tmp_path / "sheet1.svg").exists() and not (tmp_path / "sheet2.svg").exists()


def test_draw_both_sheets(tmp_path):
    from mmt_plans.cli import main

    result = CliRunner().invoke(main, ["draw", str(PRESS), "-o", str(tmp_path), "--format", "svg"])
    assert result.exit_code == 0, result.output
    svg = (tmp_path / "sheet2.svg").read_text(encoding="utf-8")
    assert 'width="841mm"' in svg and 'height="594mm"' in svg
    for gid in ("zhukovsky-lever", "force-polygon-4-5", "group-2-3", "table-reactions"):
        assert f'id="{gid}"' in svg



# The share of the field (inside the frame less 5 mm, the title block aside)
# that the drawings and tables cover, each as the box of its drawn primitives.
# Before the sheet grew its drawings to fill the field (issue 13): shaper 0.51,
# six_link_press 0.64, five_dyads 0.53, forces_scotch_yoke 0.31, offset
# 0.51, four_bar 0.66; after 0.64, 0.71, 0.71, 0.41, 0.62, 0.74.
# six_link_press reached 0.70 with the polygon of group 4-5 drawn 324 mm long,
# past the guide's 300 mm (issue 21): within the guide it covers 0.685.
FIELD_USED = {"shaper": 0.62, "six_link_press": 0.68, "five_dyads": 0.68}
FIELD_USED_ANY = 0.40


@pytest.mark.parametrize("path", SAMPLES, ids=[p.stem for p in SAMPLES])
def test_drawings_use_the_field(path):
    """Sheet 2 fills its field: the boxes of what each drawing and table
    drew, measured on the recorded page, cover at least the stated share."""
    import shapely
    from shapely.geometry import box

    _, backend, sheet = _draw(path)
    layout = sheet.layout
    field = box(*layout.region.bounds).difference(box(*layout["title-block"].footprint.bounds))
    drawn = []
    for name in sheet.placed:
        pts = [p for c in backend.in_group(name) for p in c.points()]
        drawn.append(box(min(x for x, _ in pts), min(y for _, y in pts),
                         max(x for x, _ in pts), max(y for _, y in pts)))
    used = shapely.unary_union(drawn).intersection(field).area / field.area
    assert used >= FIELD_USED.get(path.stem, FIELD_USED_ANY), used
