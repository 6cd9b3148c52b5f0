"""Mistake models recomputed through the construction (issue 23), each made
in corpus.py's independent construction: every downstream value is named."""

import math

import pytest

import mmt_plans
from mmt_plans.check import check, loads_answers

from .corpus import MECHANISMS, Method


@pytest.fixture(scope="module")
def shaper(tmp_path_factory):
    path = tmp_path_factory.mktemp("shaper") / "shaper.toml"
    path.write_text(MECHANISMS["shaper"].toml, encoding="utf-8")
    return mmt_plans.solve(mmt_plans.load(path))


def position(i: int, k, points=("B", "D", "S3")) -> str:
    v = ", ".join(f'"{p}" = {abs(k.V[p])!r}' for p in points)
    a = ", ".join(f'"{p}" = {abs(k.A[p])!r}' for p in points)
    w = ", ".join(f'"{lid}" = {k.w[lid]!r}' for lid in (3, 4))
    e = ", ".join(f'"{lid}" = {k.e[lid]!r}' for lid in (3, 4))
    return (
        f"[[position]]\nindex = {i}\nvelocity = {{ {v} }}\nacceleration = {{ {a} }}\n"
        f"omega = {{ {w} }}\neps = {{ {e} }}\n"
    )


def failures(solution, text):
    res = check(solution, loads_answers(text, solution))
    return {v.answer.label: v for v in res.values if not v.passed}


@pytest.mark.parametrize(
    "method,family",
    [
        (Method(coriolis=-1.0), "coriolis_reversed"),
        (Method(coriolis=0.0), "coriolis_left_out"),
        (Method(normal=0.0), "normal_left_out"),
        (Method(omega_factor=30 / math.pi), "rpm_as_rad"),
    ],
)
def test_a_construction_mistake_is_named_on_every_value_it_moves(shaper, method, family):
    """Regression: Coriolis reversed named 2 of 24 values (a^τ only), left
    out none, rpm as rad/s none; a_B, a_D, ε3, ε4 were "cause unknown"."""
    mech = MECHANISMS["shaper"]
    phi = shaper.positions[shaper.entry(2)].phi1_deg
    bad = failures(shaper, position(2, mech.kin(phi, method)))
    assert len(bad) >= 2
    for label, v in bad.items():
        assert v.group is not None and v.group.startswith(family), (label, v.cause)


def test_plans_copied_from_another_position(shaper):
    """Regression: ω and ε copied from position 1 were "sign swapped"."""
    mech = MECHANISMS["shaper"]
    phi1 = shaper.positions[shaper.entry(1)].phi1_deg
    bad = failures(shaper, position(2, mech.kin(phi1)))
    assert bad
    for label, v in bad.items():
        assert v.cause.startswith("the plans of position 2 drawn at position 1"), (label, v.cause)
