"""mmt_plans: the graph-analytic workflow of the Theory of Machines and
Mechanisms course project, exact and drawn.

    >>> import mmt_plans
    >>> mech = mmt_plans.load("samples/six_link_press.toml")
    >>> solution = mmt_plans.solve(mech)
    >>> solution.structure.formula
    'I(0,1) <- II(2,3) <- II(4,5)'
    >>> sw = mmt_plans.kinematics(mech).sweep([0.0, 30.0])   # built once, swept often
"""

from .errors import (
    AssemblyError,
    MmtError,
    PartialTurnError,
    SingularPlanError,
    SpecError,
    StructureError,
)
from .kinematics.handle import Kinematics, kinematics
from .model import Mechanism
from .solution import Solution, solve, sweep
from .spec import load, loads

__all__ = [
    "load",
    "loads",
    "solve",
    "sweep",
    "kinematics",
    "Kinematics",
    "Mechanism",
    "Solution",
    "MmtError",
    "SpecError",
    "StructureError",
    "AssemblyError",
    "SingularPlanError",
    "PartialTurnError",
]
__version__ = "0.1.0"
