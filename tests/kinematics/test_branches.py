"""Assembly branches (kinematics/branches.py, SPEC_FORMAT "Assembly branch").

Each dyad kind with branches is built on both branches and checked against
the meaning of its sign; a three-group mechanism where only one combination
of the first two groups turns fully is solved and compared point by point
with an independent solver written here (plain complex arithmetic); random
Grashof four-bars extended by random dyads either turn fully on the chosen
combination at every angle of a grid, or are refused with their range.
"""

from __future__ import annotations

import cmath
import glob
import math
from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, event, given, settings
from hypothesis import strategies as st

import mmt_plans
from mmt_plans.kinematics.branches import build_chain
from mmt_plans.results_json import results as results_json
from mmt_plans.errors import PartialTurnError
from mechanisms import four_bar_toml, slider_crank_toml

ROOT = Path(__file__).resolve().parents[2]
GRID = np.linspace(0.0, 360.0, 720, endpoint=False)


def cross(a: complex, b: complex) -> float:
    return a.real * b.imag - a.imag * b.real


# --- every kind on both branches ---------------------------------------------------

@pytest.mark.parametrize("sign", [1, -1])
def test_rrr_branch_sign_is_the_side_of_b(sign):
    # four-bar O(0,0), C(300,0), r = 100, l = 250, c = 200 (Grashof crank-rocker)
    phi = 60.0
    A = 100 * cmath.exp(1j * math.radians(phi))
    # the sketch puts B on the side the sign names: left of A->C for +1
    base = four_bar_toml(100, 300, 250, 200)
    mech0 = mmt_plans.loads(base)
    sw = mmt_plans.sweep(mech0, [phi])
    B = complex(*sw.points["B"][0]) * 1e3
    C = 300 + 0j
    # reflect B in the line A-C to get the other branch's B
    u = (C - A) / abs(C - A)
    B_other = A + u * ((B - A) / u).conjugate()
    wanted = B if build_chain(mech0).choice.signs["2-3"] == sign else B_other
    mech = mmt_plans.loads(base + f"\n[sketch]\nA = [{A.real}, {A.imag}]\n"
                           f"B = [{wanted.real}, {wanted.imag}]\n")
    assert build_chain(mech).choice.signs["2-3"] == sign and build_chain(mech).choice.rule == "sketch"
    sw = mmt_plans.sweep(mech, GRID).check()
    for k in range(len(GRID)):
        A_k, B_k = (complex(*sw.points[p][k]) for p in "AB")
        side = cross(C / 1e3 - A_k, B_k - A_k)
        assert side * sign > 0  # +1: B to the left of A->C, at every angle
        assert abs(abs(B_k - A_k) - 0.25) < 1e-14 and abs(abs(B_k - C / 1e3) - 0.2) < 1e-14


@pytest.mark.parametrize("sign", [1, -1])
def test_rrp_branch_sign_is_the_far_or_near_intersection(sign):
    r, l, e = 100.0, 300.0, 40.0
    base = slider_crank_toml(r, l, e)
    x_far = r + math.sqrt(l * l - e * e)
    x = x_far if sign > 0 else r - math.sqrt(l * l - e * e)
    mech = mmt_plans.loads(base + f"\n[sketch]\nA = [{r}, 0]\nB = [{x}, {e}]\n")
    assert build_chain(mech).choice.signs["2-3"] == sign
    sw = mmt_plans.sweep(mech, GRID).check()
    for k, phi in enumerate(np.radians(GRID)):
        A = r * cmath.exp(1j * phi) / 1e3
        foot = A.real
        B = complex(*sw.points["B"][k])
        assert abs(B.imag - e / 1e3) < 1e-15
        assert (B.real - foot) * sign > 0  # +1: the larger x along the guide's direction
        assert abs(abs(B - A) - l / 1e3) < 1e-14


def test_rpr_branches_are_the_slot_turned_by_plus_and_minus_arcsin():
    # the shaper's block in the slotted link: the slot line passes through the
    # block's point on both branches, and the two slot angles differ
    mech = mmt_plans.load(ROOT / "samples" / "shaper.toml").with_changes(sketch={})
    chain = build_chain(mech)
    solver = next(sv for sv in chain.solvers if sv.group.kind == "RPR")
    group, pair = solver.group.name, solver.inner
    phi = np.radians(GRID)
    slots = {}
    for sign in (1, -1):
        m = chain.place(phi, {**chain.branches, group: sign})
        guide, block = m[pair.guide], m[pair.slider]
        u = np.asarray(guide.e * np.ones(len(GRID))) * complex(*pair.direction)
        P = np.asarray(guide.at(complex(*pair.through)) * np.ones(len(GRID)))
        Q = np.asarray(block.at(complex(*mech.links[pair.slider].points[pair.slider_point]))
                       * np.ones(len(GRID)))
        assert np.all(np.isfinite(u)) and np.all(np.isfinite(Q))
        # the block's point lies on the slot's line
        assert np.max(np.abs((Q - P).real * u.imag - (Q - P).imag * u.real)) < 1e-14
        slots[sign] = u
    assert np.min(np.abs(slots[1] - slots[-1])) > 1e-3


def test_every_sample_turns_fully_without_its_sketch():
    """The seed-003 and seed-002 shapes written without a sketch: the search
    finds a combination that turns fully for every one of them."""
    files = sorted(glob.glob(str(ROOT / "samples" / "*.toml"))) + sorted(
        glob.glob(str(ROOT / "samples" / "tasks" / "*" / "*.toml")))
    assert len(files) > 100
    for f in files:
        kept = []
        skip = False
        for line in Path(f).read_text().splitlines():
            if line.startswith("["):
                skip = line.strip() == "[sketch]"
            if not skip:
                kept.append(line)
        mech = mmt_plans.loads("\n".join(kept), f)
        choice = build_chain(mech).choice
        assert choice.whole_turn and choice.rule != "sketch", f
        assert dict(choice.signs) in [dict(c) for c in choice.full_turn]
        assert mmt_plans.sweep(mech, GRID).ok.all(), f


# --- three groups, one combination of the first two ---------------------------------

THREE = """
title = "three groups: only one branch pair of groups 2-3 and 4-5 turns fully"
[drive]
rpm = 60
[study]
output = "H"
[frame]
O = [0, 0]
C = [373, 55]
F = [180, 223]
[[link]]
id = 1
points = { O = [0, 0], A = [100, 0] }
[[link]]
id = 2
points = { A = [0, 0], B = [391, 0] }
[[link]]
id = 3
points = { C = [0, 0], B = [232, 0], D = [252, 64] }
[[link]]
id = 4
points = { D = [0, 0], E = [488, 0] }
[[link]]
id = 5
points = { F = [0, 0], E = [292, 0], G = [280, 49] }
[[link]]
id = 6
points = { G = [0, 0], H = [354, 0] }
[[link]]
id = 7
points = { H = [0, 0] }
[[slider]]
link = 7
through = [0, -14]
angle = 0
"""


def _circles(P: complex, r1: float, Q: complex, r2: float, sign: int) -> complex | None:
    """B with |PB| = r1, |QB| = r2, sign +1: left of P->Q."""
    d = abs(Q - P)
    if not abs(r1 - r2) <= d <= r1 + r2:
        return None
    along = (r1 * r1 - r2 * r2 + d * d) / (2 * d)
    h = math.sqrt(max(r1 * r1 - along * along, 0.0))
    u = (Q - P) / d
    return P + u * (along + 1j * sign * h)


def independent(phi_deg: float, s1: int, s2: int, s3: int) -> dict[str, complex] | None:
    """The THREE mechanism in mm by hand: circle-circle, rigid links, circle-line."""
    A = 100 * cmath.exp(1j * math.radians(phi_deg))
    C, F = 373 + 55j, 180 + 223j
    B = _circles(A, 391, C, 232, s1)
    if B is None:
        return None
    D = C + (B - C) / 232 * (252 + 64j)  # the rocker turned as B - C turned from (232, 0)
    E = _circles(D, 488, F, 292, s2)
    if E is None:
        return None
    G = F + (E - F) / 292 * (280 + 49j)
    dy = -14 - G.imag
    if abs(dy) > 354:
        return None
    H = complex(G.real + s3 * math.sqrt(354 ** 2 - dy ** 2), -14)
    return {"A": A, "B": B, "D": D, "E": E, "G": G, "H": H}


def test_three_groups_where_one_branch_pair_turns():
    mech = mmt_plans.loads(THREE)
    choice = build_chain(mech).choice
    pairs = {(c["2-3"], c["4-5"]) for c in choice.full_turn}
    assert pairs == {(-1, 1)}  # the greedy rule (+1 for group 2-3 first) cannot continue
    assert len(choice.full_turn) == 2  # the last group closes on either branch
    assert (choice.signs["2-3"], choice.signs["4-5"]) == (-1, 1)
    # the other pairs fail somewhere, by the independent solver too
    for s1, s2 in ((1, 1), (1, -1), (-1, -1)):
        assert any(independent(p, s1, s2, 1) is None for p in GRID)
    sw = mmt_plans.sweep(mech, GRID).check()
    for k, phi in enumerate(GRID):
        ref = independent(float(phi), -1, 1, choice.signs["6-7"])
        assert ref is not None
        for name, z in ref.items():
            got = complex(*sw.points[name][k]) * 1e3
            assert abs(got - z) < 1e-9 * 500, (phi, name)
    analysis = mmt_plans.solve(mech)
    assert analysis.branches.rule == "branch order"
    assert results_json(analysis)["branches"]["full_turn_combinations"] == 2


def test_three_groups_sketch_of_a_pair_that_does_not_turn_is_refused():
    # the sketch of branch pair (-1, -1) at phi1 = 90: it assembles there, not over the turn
    ref = independent(90.0, -1, -1, 1)
    assert ref is not None
    sketch = "\n[sketch]\n" + "\n".join(f"{n} = [{z.real}, {z.imag}]" for n, z in ref.items())
    mech = mmt_plans.loads(THREE + sketch)
    with pytest.raises(PartialTurnError) as err:
        mmt_plans.solve(mech).positions
    text = str(err.value)
    assert "sketched branches do not turn fully" in text and "group 2-3 -1, group 4-5 +1" in text
    assert "°…" in text and "fix:" in text


# --- extreme positions are zeros of the output's velocity ---------------------------

def _sample_files():
    return sorted(glob.glob(str(ROOT / "samples" / "*.toml"))) + sorted(
        glob.glob(str(ROOT / "samples" / "tasks" / "*" / "*.toml")))


def test_extreme_positions_are_zeros_of_the_output_velocity():
    for f in _sample_files():
        mech = mmt_plans.load(f)
        analysis = mmt_plans.solve(mech)
        assert analysis.extremes is not None, f
        wd = np.asarray(mech.study.working_direction)
        out = mech.study.output
        v_max = float(np.max(np.abs(mmt_plans.sweep(mech, GRID).v[out] @ wd)))
        sw = mmt_plans.sweep(mech, list(analysis.extremes)).check()
        v = sw.v[out] @ wd
        assert np.all(np.abs(v) <= 1e-12 * v_max), (f, v / v_max)
        s = sw.points[out] @ wd
        grid_s = mmt_plans.sweep(mech, GRID).points[out] @ wd
        assert s[0] <= grid_s.min() + 1e-12 and s[1] >= grid_s.max() - 1e-12, f
        if mech.study.zero is None:
            assert analysis.positions[0].phi1_deg == analysis.extremes[0]


# --- random Grashof four-bars extended by random dyads -------------------------------

@st.composite
def extended_four_bars(draw):
    r = 100
    d = draw(st.integers(250, 500))
    l = draw(st.integers(200, 500))
    c = draw(st.integers(150, 450))
    longest, others = max(d, l, c), sorted((d, l, c))[:2]
    if r + longest > sum(others):  # Grashof with the crank shortest: it turns fully
        c = others[0] + others[1] - r - longest + c - 1
    extra = ""
    kind = draw(st.sampled_from(["RRR", "RRP"]))
    dx, dy = draw(st.integers(-200, 300)), draw(st.integers(-150, 150))
    extra += f"\n[[link]]\nid = 4\npoints = {{ D = [0, 0], E = [{draw(st.integers(150, 600))}, 0] }}\n"
    if kind == "RRR":
        fx, fy = draw(st.integers(-300, 700)), draw(st.integers(-400, 400))
        extra += (f"[[link]]\nid = 5\npoints = {{ F = [0, 0], E = [{draw(st.integers(100, 500))}, 0] }}\n")
        frame = f"F = [{fx}, {fy}]\n"
    else:
        extra += "[[link]]\nid = 5\npoints = { E = [0, 0] }\n"
        extra += f"[[slider]]\nlink = 5\nthrough = [0, {draw(st.integers(-300, 300))}]\nangle = {draw(st.sampled_from([0, 30, 90]))}\n"
        frame = ""
    text = four_bar_toml(r, d, l, c).replace('output = "B"', 'output = "E"')
    text = text.replace(f"B = [{c}, 0] }}", f"B = [{c}, 0], D = [{dx}, {dy}] }}")
    text = text.replace("[[link]]\nid = 1", frame + "\n[[link]]\nid = 1", 1)
    return text + extra


@settings(max_examples=40, deadline=None, derandomize=True,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much])
@given(extended_four_bars())
def test_random_extended_four_bars_turn_fully_or_are_refused(text):
    try:
        mech = mmt_plans.loads(text)
    except mmt_plans.SpecError:
        return  # e.g. a drawn point that coincides with another
    choice = build_chain(mech).choice
    event("whole turn" if choice.whole_turn else "refused")
    if not choice.whole_turn:
        with pytest.raises(PartialTurnError) as err:
            mmt_plans.solve(mech).positions
        assert err.value.ranges == choice.ranges != ((0.0, 360.0),)
        assert "°…" in str(err.value) or "no crank angle" in str(err.value)
        assert not choice.full_turn
        return
    assert dict(choice.signs) in [dict(c) for c in choice.full_turn]
    sw = mmt_plans.sweep(mech, GRID)
    assert sw.ok.all() or all(e.__class__.__name__ == "SingularPlanError"
                              for e in (sw.problem(i) for i in np.flatnonzero(~sw.ok)))
    pts = sw.points
    # the links keep their lengths at every angle (an independent check of the placement)
    for link in mech.links.values():
        names = list(link.points)
        for i in range(len(names)):
            for j in range(i + 1, len(names)):
                want = float(np.hypot(*(link.points[names[i]] - link.points[names[j]])))
                got = np.hypot(*(pts[names[i]] - pts[names[j]]).T)
                assert np.all(np.abs(got - want) <= 1e-12 * max(1.0, want) + 1e-12)


# --- no sketch, links drawn in place: the branch of the drawing ----------------------

_DRAWN = """
title = "Four-bar drawn in place"
[drive]
link = 1
rpm = 120
[study]
positions = 12
output = "B"
working_direction = [1, 0]
[frame]
O = [0, 0]
C = [300, 0]
[[link]]
id = 1
points = {{ O = [0, 0], A = [50, 86.6025] }}
[[link]]
id = 2
points = {{ A = [50, 86.6025], B = [250, {y}] }}
[[link]]
id = 3
points = {{ C = [300, 0], B = [250, {y}] }}
"""


@pytest.mark.parametrize("y", [200, -200])
def test_links_drawn_in_place_choose_the_drawn_branch(y):
    """Both branches of this crank-rocker turn fully and there is no sketch:
    the links' own coordinates (every point written where it stands at a
    crank angle of 60°) decide. B drawn above the line A→C is to its left
    (+1 by the RRR convention), below it to its right (-1); checked here by
    the side of B itself, and by where the solved B stands at the drawing's
    crank angle."""
    mech = mmt_plans.loads(_DRAWN.format(y=y), "drawn.toml")
    k = mmt_plans.kinematics(mech)
    assert k.branches.rule == "as drawn"
    assert len(k.branches.full_turn) == 2
    A, B, C = complex(50, 86.6025), complex(250, y), complex(300, 0)
    side = 1 if cross(C - A, B - A) > 0 else -1
    assert k.branches.signs["2-3"] == side
    at = k.at(60.0)
    solved = complex(*at.points["B"][0])
    assert abs(solved - B / 1000.0) < 1e-7  # the drawing's B (mm -> m); A is drawn to 1e-4 mm
