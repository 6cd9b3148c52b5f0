"""The seeded generator of mechanisms the sheet linter runs over
(mmt_plans/generate.py): repeatable, every file assembles over the whole
turn, every dyad kind and the hard names turn up."""

from __future__ import annotations

import collections
import tomllib

import numpy as np

from mmt_plans.generate import generate_one
from mmt_plans.kinematics.branches import build_chain
from mmt_plans.spec import loads
from mmt_plans.structure import analyse_structure

SEEDS = range(30)


def test_a_seed_gives_the_same_file():
    assert generate_one(7).toml == generate_one(7).toml
    assert generate_one(7).toml != generate_one(8).toml


def test_every_generated_file_turns_fully_and_has_its_dyads():
    kinds = collections.Counter()
    names = set()
    for s in SEEDS:
        g = generate_one(s)
        mech = loads(g.toml, g.name)
        # the dyads the file was built of are the groups its structure finds
        assert sorted(str(x.kind) for x in analyse_structure(mech).groups) == sorted(g.kinds)
        assert 2 <= len(g.kinds) <= 5
        # an independent look at the turn: every one of 720 crank angles assembles
        sweep = build_chain(mech).sweep(np.linspace(0.0, 360.0, 720, endpoint=False))
        assert np.asarray(sweep.ok).all(), g.name
        kinds.update(g.kinds)
        data = tomllib.loads(g.toml)
        names |= set(data["frame"]) | {n for lk in data["link"] for n in lk["points"]}
    assert set(kinds) == {"RRR", "RRP", "RPR", "PRP", "RPP"}
    assert {"p", "P", "π", "O", "o"} <= names  # the poles' letters and position 0's look-alikes


def test_the_tool_solves_every_generated_file_forces_included():
    from mmt_plans.solution import solve

    for s in range(10):
        g = generate_one(s)
        solution = solve(loads(g.toml, g.name))
        assert solution.forces is not None, (g.name, solution.forces_problem)
