"""The kinematic handle: the chain built once per Mechanism, swept many times,
the same numbers as a chain built afresh."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import mmt_plans
from mmt_plans.kinematics.branches import build_chain

ROOT = Path(__file__).resolve().parents[2]
PRESS = ROOT / "samples" / "six_link_press.toml"


def test_the_handle_is_built_once_and_kept_with_its_mechanism():
    mech = mmt_plans.load(PRESS)
    k = mmt_plans.kinematics(mech)
    assert mmt_plans.kinematics(mech) is k
    chain = k.chain
    mmt_plans.sweep(mech, [0.0, 10.0])
    assert mmt_plans.kinematics(mech).chain is chain
    sol = mmt_plans.solve(mech)
    assert sol.kinematics is k and sol.chain is chain
    # a changed copy is another mechanism: its own handle
    other = mech.with_changes(title="copy")
    assert mmt_plans.kinematics(other) is not k
    # another load of the same file is another object, so another handle
    assert mmt_plans.kinematics(mmt_plans.load(PRESS)) is not k


def test_the_handle_sweeps_as_a_chain_built_afresh():
    mech = mmt_plans.load(PRESS)
    phi = np.linspace(0.0, 360.0, 37)
    fresh = build_chain(mmt_plans.load(PRESS)).sweep(phi)
    k = mmt_plans.kinematics(mech)
    for sw in (k.sweep(phi), mmt_plans.sweep(mech, phi), k.sweep(list(phi))):
        for name in fresh.points:
            assert np.array_equal(sw.points[name], fresh.points[name])
            assert np.array_equal(sw.v[name], fresh.v[name])
            assert np.array_equal(sw.a[name], fresh.a[name])
        for lid in fresh.omega:
            assert np.array_equal(sw.omega[lid], fresh.omega[lid])
            assert np.array_equal(sw.eps[lid], fresh.eps[lid])
    assert k.branches.signs == fresh.chain.choice.signs
    one = k.at(37.5)
    assert one.points["E"].shape == (1, 2)
    assert np.array_equal(one.points["E"][0], fresh.chain.sweep(np.array([37.5])).points["E"][0])
    sol = mmt_plans.solve(mech)
    assert np.array_equal(sol.at(37.5).v["E"], one.v["E"])


def test_at_names_the_angle_where_it_cannot_assemble(tmp_path):
    text = (ROOT / "samples" / "offset_slider_crank.toml").read_text()
    path = tmp_path / "short.toml"
    # a rod of 110 mm, shorter than crank 100 + offset 30: at 270° the pin is
    # 130 mm from the guide and the group cannot close; at 90°, 70 mm, it can
    path.write_text(text.replace("B = [400, 0]", "B = [110, 0]").replace("B = [390, 30]", "B = [60, 30]"))
    k = mmt_plans.kinematics(mmt_plans.load(path))
    with pytest.raises(mmt_plans.AssemblyError) as err:
        k.at(270.0)
    assert "270" in str(err.value)
    k.at(90.0)
