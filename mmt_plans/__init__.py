"""mmt_plans: the graph-analytic workflow of the Theory of Machines and
Mechanisms course project, exact and drawn.

    >>> import mmt_plans
    >>> mech = mmt_plans.load("samples/six_link_press.toml")
    >>> mech.structure.formula
    'I(0,1) <- II(2,3) <- II(4,5)'
"""

from .errors import AssemblyError, MmtError, SingularPlanError, SpecError, StructureError
from .model import Mechanism
from .spec import load, loads

__all__ = ["load", "loads", "Mechanism", "MmtError", "SpecError", "StructureError",
           "AssemblyError", "SingularPlanError"]
__version__ = "0.1.0"
