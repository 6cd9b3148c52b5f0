"""Every dyad kind has its kinematics and its force equations, found by kind."""

from mmt_plans.forces.groups import GROUPS
from mmt_plans.kinematics.dyads import DYADS
from mmt_plans.structure import DYAD_KINDS


def test_both_registries_cover_the_five_kinds():
    assert set(DYADS) == set(GROUPS) == set(DYAD_KINDS) == {"RRR", "RRP", "RPR", "PRP", "RPP"}
    for kind in DYAD_KINDS:
        assert DYADS[kind].__name__ == GROUPS[kind].__name__ == kind
        assert DYADS[kind].__module__.endswith(f"dyads.{kind.lower()}")
        assert GROUPS[kind].__module__.endswith(f"groups.{kind.lower()}")
