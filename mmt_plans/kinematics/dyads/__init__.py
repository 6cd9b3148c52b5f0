"""The five dyads (class II Assur groups), one module per kind, found by kind.

A new kind is a subclass of `DyadSolver` (base.py) in a module of its own,
registered here, with its force equations in forces/groups/ (registered
there under the same name); a test checks that both registries cover
`structure.DYAD_KINDS`.
"""

from __future__ import annotations

from .base import DyadSolver, GroupPlan, Leg, Motion, solve_two_lines
from .prp import PRP
from .rpp import RPP
from .rpr import RPR
from .rrp import RRP
from .rrr import RRR

__all__ = ["DYADS", "DyadSolver", "GroupPlan", "Leg", "Motion", "solve_two_lines"]

DYADS: dict[str, type[DyadSolver]] = {"RRR": RRR, "RRP": RRP, "RPR": RPR, "PRP": PRP, "RPP": RPP}
