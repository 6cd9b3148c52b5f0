"""The `forces` object of the results JSON (SPEC_FORMAT.md) and the text tables."""

from __future__ import annotations

import json
import math

import pytest
from force_checks import ROOT, SAMPLES

import mmt_plans
from mmt_plans.results_json import force_analysis_json, forces_json
from mmt_plans.report import force_text as text

CONTRACT = {"index", "phi1_deg", "balancing_force_plans", "balancing_force_lever",
            "discrepancy_percent", "balancing_moment", "reactions"}


@pytest.mark.parametrize("path", SAMPLES, ids=lambda p: p.stem)
def test_contract_keys_and_types(path):
    a = mmt_plans.solve(mmt_plans.load(path))
    fa = a.forces_at()
    out = json.loads(json.dumps(forces_json(a), allow_nan=False))
    assert out == json.loads(json.dumps({**force_analysis_json(fa), "reduction": out["reduction"]}))
    assert CONTRACT <= set(out)
    assert out["index"] == a.force_position
    assert out["phi1_deg"] == a.positions[a.entry(a.force_position)].phi1_deg
    for key in ("balancing_force_plans", "balancing_force_lever", "discrepancy_percent",
                "balancing_moment"):
        assert isinstance(out[key], float) and math.isfinite(out[key])
    assert out["discrepancy_percent"] < 1e-6
    r = a.mechanism.crank_length
    assert out["balancing_moment"] == pytest.approx(out["balancing_force_plans"] * r, rel=1e-12)
    assert "R01" in out["reactions"]
    for name, v in out["reactions"].items():
        assert name.startswith("R") and len(v) == 2 and all(isinstance(x, float) for x in v)
    assert len(out["reactions"]) == len(a.mechanism.pairs)
    # additions: loads, details, the reduction
    assert set(out["loads"]) == {str(i) for i in a.mechanism.links}
    assert set(out["reaction_details"]) == set(out["reactions"])
    red = out["reduction"]
    assert len(red["reduced_moment"]) == len(red["reduced_inertia"]) == len(a.positions)


def test_two_digit_links_are_written_with_an_underscore():
    a = mmt_plans.solve(mmt_plans.load(ROOT / "samples" / "five_dyads.toml"))
    names = set(force_analysis_json(a.forces_at())["reactions"])
    assert {"R8_10", "R0_11", "R10_11", "R01", "R05", "R34"} <= names
    assert not any(n in names for n in ("R810", "R011", "R1011"))


def test_text_tables():
    a = mmt_plans.solve(mmt_plans.load(ROOT / "samples" / "six_link_press.toml"))
    fa = a.forces_at(2)
    out = text(fa)
    assert "Force analysis at position 2" in out
    for name in fa.reactions:
        assert f" {name} " in out
    assert f"{fa.balancing_force_plans:.6g}" in out and f"{fa.balancing_force_lever:.6g}" in out
    assert "discrepancy" in out and "M_bal" in out
    assert "Sum M_E(link 4) = 0" in out  # the textbook's first equation of group 4-5
