"""One test per group kind: the directions and the moment equations of the
textbook's force plans (seed 003 §2.6–2.7), checked on the group's own terms."""

from __future__ import annotations

import math

import numpy as np
import pytest
from force_checks import ROOT, c, cross, own_loads

import mmt_plans



def analysed(name: str):
    a = mmt_plans.solve(mmt_plans.load(ROOT / "samples" / f"{name}.toml"))
    return a, a.forces_at()


def entry(a, fa) -> int:
    return a.entry(fa.index)


def group(fa, name):
    return next(g for g in fa.groups if g.name == name)


def sums(loads, P):
    F = sum((ld.force for ld in loads), 0j)
    M = sum((cross(ld.point - P, ld.force) + ld.couple for ld in loads), 0.0)
    return F, M


def test_groups_are_solved_last_first():
    a, fa = analysed("five_dyads")
    assert [g.name for g in fa.groups] == [g.name for g in reversed(a.structure.groups)]
    assert [g.kind for g in fa.groups] == ["RPP", "PRP", "RPR", "RRP", "RRR"]


def test_rrr_four_bar():
    """R12^t = M_B(loads of 2)/AB, R03^t = M_B(loads of 3)/CB (seed 000 (1.32), (1.33),
    with the sign of t = i·n, n from the outer pin to B); normals along the links."""
    a, fa = analysed("four_bar_coupler")
    k, sw = entry(a, fa), a.sweep
    own = own_loads(a.mechanism, sw, k, a.positions[k].stroke)
    A, B, C = (c(sw.points[p][k]) for p in "ABC")
    g = group(fa, "2-3")
    R12, R03, R32 = g.reactions
    assert (R12.name, R03.name, R32.name) == ("R12", "R03", "R32")
    for r, P, link in ((R12, A, 2), (R03, C, 3)):
        n = (B - P) / abs(B - P)
        comp = {x.label[-1]: x for x in r.components}
        assert abs(c(comp["n"].direction) - n) < 1e-15
        assert abs(c(comp["t"].direction) - 1j * n) < 1e-15
        _, MB = sums(own[link], B)
        assert math.isclose(comp["t"].value, MB / abs(B - P), rel_tol=1e-12)
        assert abs(c(comp["n"].vector) + c(comp["t"].vector) - c(r.force)) < 1e-9
        assert abs(c(r.point) - P) < 1e-15
    F2, _ = sums(own[2], B)
    assert abs(c(R32.force) + c(R12.force) + F2) < 1e-9 * abs(c(R12.force))  # link 2's polygon


def test_rrr_receives_the_later_groups_reaction():
    """Group 2-3 of the press carries R43 = −R34 at D in its moment equation about B."""
    a, fa = analysed("six_link_press")
    k, sw = entry(a, fa), a.sweep
    own = own_loads(a.mechanism, sw, k, a.positions[k].stroke)
    B, C, D = (c(sw.points[p][k]) for p in "BCD")
    R34 = fa.reactions["R34"]
    R03 = fa.reactions["R03"]
    _, MB = sums(own[3], B)
    MB += cross(D - B, -c(R34.force))
    Rt = next(x for x in R03.components if x.label == "R03^t").value
    assert math.isclose(Rt, MB / abs(B - C), rel_tol=1e-12)
    on3 = [f for f in fa.free_body(3) if f.label == "R43"]
    assert len(on3) == 1 and abs(c(on3[0].point) - D) < 1e-15


def test_rrp_slider_crank():
    """R03 is normal to the guide and passes through B (all loads of the slider act at B)."""
    a, fa = analysed("offset_slider_crank")
    k, sw = entry(a, fa), a.sweep
    B = c(sw.points["B"][k])
    R03 = fa.reactions["R03"]
    assert R03.kind == "P" and abs(R03.force[0]) <= 1e-12 * R03.magnitude
    assert abs(c(R03.point) - B) < 1e-12
    assert R03.couple == 0.0
    assert abs(c(fa.reactions["R32"].point) - B) < 1e-15


def test_rpr_shaper_block_on_a_moving_guide():
    """The block 2 slides in the rocker 3: R23 is normal to the slot, acts at A
    (the block's loads act at A), and loads the rocker too; ΣM_C(3) = 0."""
    a, fa = analysed("shaper")
    mech, sw = a.mechanism, a.sweep
    k = entry(a, fa)
    own = own_loads(mech, sw, k, a.positions[k].stroke)
    A, B, C = (c(sw.points[p][k]) for p in "ABC")
    u = complex(sw.links[3].e[k])  # the slot runs along the rocker's own x axis
    R23 = fa.reactions["R23"]
    assert R23.kind == "P"
    assert abs(c(R23.force).real * u.real + c(R23.force).imag * u.imag) <= 1e-12 * R23.magnitude
    assert abs(c(R23.point) - A) < 1e-12
    on3 = [f for f in fa.free_body(3) if f.label == "R23"]
    on2 = [f for f in fa.free_body(2) if f.label == "R32"]
    assert len(on3) == 1 and len(on2) == 1
    assert abs(c(on3[0].force) - c(R23.force)) == 0 and abs(c(on2[0].force) + c(R23.force)) == 0
    # ΣM_C(3): own loads, R43 at B, R23 at A, R03 through C
    _, MC = sums(own[3], C)
    MC += cross(B - C, -c(fa.reactions["R34"].force)) + cross(A - C, c(R23.force))
    assert abs(MC) <= 1e-9 * R23.magnitude * abs(A - C)
    # the slot turns while the block slides: Coriolis in the kinematics, and the
    # block's inertia force is −m2·a_A
    assert abs(c(fa.loads.links[2].inertia_force) + 2.0 * c(sw.a["A"][k])) < 1e-12


def test_prp_five_dyads():
    a, fa = analysed("five_dyads")
    sw, k = a.sweep, entry(a, fa)
    g = group(fa, "8-9")
    assert g.kind == "PRP"
    R08, R79, R98 = g.reactions
    assert (R08.name, R79.name, R98.name) == ("R08", "R79", "R98")
    assert abs(R08.force[1]) <= 1e-12 * max(R08.magnitude, 1.0)  # normal to the vertical guide
    u7 = complex(sw.links[7].e[k])
    assert abs(c(R79.force).real * u7.real + c(R79.force).imag * u7.imag) <= 1e-12 * R79.magnitude
    assert abs(c(R98.point) - c(sw.points["J"][k])) < 1e-15
    # R79 acts on the slotted link 7 as well, in group 6-7
    assert any(f.label == "R97" for f in fa.free_body(7))


def test_rpp_five_dyads():
    a, fa = analysed("five_dyads")
    g = group(fa, "10-11")
    assert g.kind == "RPP"
    R8_10, R0_11, R10_11 = g.reactions
    assert (R8_10.name, R0_11.name, R10_11.name) == ("R8_10", "R0_11", "R10_11")
    assert abs(R0_11.force[0]) <= 1e-12 * R0_11.magnitude  # normal to the horizontal guide
    assert abs(R10_11.force[1]) <= 1e-12 * max(R10_11.magnitude, 1.0)  # normal to the slot


@pytest.mark.parametrize("kind, sample", [("RRR", "four_bar_coupler"), ("RRP", "six_link_press"),
                                          ("RPR", "shaper"), ("PRP", "five_dyads"),
                                          ("RPP", "forces_scotch_yoke")])
def test_each_kind_keeps_its_polygons(kind, sample):
    a, fa = analysed(sample)
    g = next(g for g in fa.groups if g.kind == kind)
    assert g.polygons and g.steps
    found = {v.label for p in g.polygons for v in p.vectors if not v.known}
    names = {r.name for r in g.reactions}
    assert {f.split("^")[0] for f in found} <= names
    for p in g.polygons:
        assert p.closure <= 1e-12 * p.largest
    for lid in g.links:  # each link's free body balances on its own
        body = g.free_bodies[lid]
        F = sum((c(f.force) for f in body), 0j)
        M = sum((cross(c(f.point), c(f.force)) + f.couple for f in body), 0.0)
        scale = max(np.hypot(*f.force) for f in body)
        assert abs(F) <= 1e-9 * scale and abs(M) <= 1e-9 * scale * 2.0


SWAPPED_SHAPER = (ROOT / "samples" / "shaper.toml").read_text() \
    .replace("id = 2                                  # the block at the crank pin",
             "id = 3                                  # the block at the crank pin") \
    .replace("id = 3                                  # the slotted link (rocker)",
             "id = 2                                  # the slotted link (rocker)") \
    .replace("link = 2\non = 3", "link = 3\non = 2")


def test_rpr_with_the_slotted_link_first():
    """The same shaper with the rocker numbered 2 and the block 3: the group
    reads RPR with L1 the guide; the answers do not depend on the numbering."""
    from force_checks import equilibrium_residuals, virtual_power_balancing_force

    assert "link = 3\non = 2" in SWAPPED_SHAPER
    a = mmt_plans.solve(mmt_plans.loads(SWAPPED_SHAPER))
    ref = mmt_plans.solve(mmt_plans.load(ROOT / "samples" / "shaper.toml"))
    g = next(g for g in a.structure.groups if g.kind == "RPR")
    assert g.links == (2, 3)
    for pos in a.positions:
        k = a.entry(pos.index)
        fa, fr = a.forces_at(pos.index), ref.forces_at(pos.index)
        for link, (F, M, scale) in equilibrium_residuals(a.mechanism, a.sweep, k, pos.stroke,
                                                         fa).items():
            assert F <= 1e-9 * scale and M <= 1e-9 * scale
        expected = virtual_power_balancing_force(a.mechanism, a.sweep, k, pos.stroke)
        assert fa.balancing_force_plans == pytest.approx(expected, rel=1e-9)
        assert fa.balancing_force_plans == pytest.approx(fr.balancing_force_plans, rel=1e-9)
        # R32 of the swapped numbering (block 3 on rocker 2) is R23 of the sample
        assert np.allclose(fa.reaction(3, 2).force, fr.reaction(2, 3).force, rtol=1e-9, atol=1e-9)
        assert np.allclose(fa.reaction(0, 2).force, fr.reaction(0, 3).force, rtol=1e-9, atol=1e-9)
