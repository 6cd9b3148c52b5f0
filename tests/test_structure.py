import pytest

import mmt_plans
from mmt_plans.kinematics.branches import build_chain
from mmt_plans.structure import analyse_structure

EXPECTED = {
    # sample: (n, p5, formula, kinds) — counted by hand from the files
    "six_link_press": (5, 7, "I(0,1) <- II(2,3) <- II(4,5)", ["RRR", "RRP"]),
    "offset_slider_crank": (3, 4, "I(0,1) <- II(2,3)", ["RRP"]),
    "shaper": (5, 7, "I(0,1) <- II(2,3) <- II(4,5)", ["RPR", "RRP"]),
    "four_bar_coupler": (3, 4, "I(0,1) <- II(2,3)", ["RRR"]),
    "five_dyads": (11, 16, "I(0,1) <- II(2,3) <- II(4,5) <- II(6,7) <- II(8,9) <- II(10,11)",
                   ["RRR", "RRP", "RPR", "PRP", "RPP"]),
}


@pytest.mark.parametrize("name", EXPECTED)
def test_structure_of_samples(name):
    st = analyse_structure(mmt_plans.load(f"samples/{name}.toml"))
    n, p5, formula, kinds = EXPECTED[name]
    assert (st.n, st.p5, st.p4, st.W) == (n, p5, 0, 1)
    assert st.formula == formula
    assert [g.kind for g in st.groups] == kinds
    assert st.mechanism_class == 2
    assert all(g.order == 2 for g in st.groups)


def test_class_three_group_is_named_and_its_kinematics_refused():
    # a triad: a ternary link 3 (B, D, F) held by 2 (from the crank), 4 and 5 (from the frame)
    mech = mmt_plans.loads("""
[drive]
rpm = 60
[study]
output = "D"
[frame]
O = [0, 0]
P = [600, 0]
Q = [300, 500]
[[link]]
id = 1
points = { O = [0, 0], A = [100, 0] }
[[link]]
id = 2
points = { A = [0, 0], B = [300, 0] }
[[link]]
id = 3
points = { B = [0, 0], D = [200, 0], F = [100, 150] }
[[link]]
id = 4
points = { D = [0, 0], P = [300, 0] }
[[link]]
id = 5
points = { F = [0, 0], Q = [300, 0] }
""")
    st = analyse_structure(mech)
    assert st.W == 1 and st.formula == "I(0,1) <- III(2,3,4,5)"
    assert st.groups[0].order == 3 and st.mechanism_class == 3
    with pytest.raises(mmt_plans.MmtError, match="class 3; only class II"):
        build_chain(mech)
