"""A mechanism's kinematics, built once and swept many times.

    >>> import mmt_plans
    >>> k = mmt_plans.kinematics(mmt_plans.load("samples/six_link_press.toml"))
    >>> k.branches.whole_turn
    True
    >>> sw = k.sweep(range(0, 360, 30))      # every point, ω and ε, 12 angles

The structure (seed 003 §1.1) and the search for the assembly branches run
once, when the handle is made; each sweep is then the closed forms of the
groups over the angles asked for. `kinematics(mech)` keeps the handle on the
Mechanism itself (as `functools.cached_property` keeps its values: in the
instance's own dictionary), so it lives and dies with that Mechanism and a
copy made by `with_changes` builds its own.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from typing import Any, TypeVar

import numpy as np

from ..model import Mechanism
from ..structure import Structure, analyse_structure
from .branches import Branches, build_chain
from .chain import Chain, Sweep

__all__ = ["Kinematics", "kinematics"]

# the handle's slot in a Mechanism's instance dictionary (where cached_property
# keeps the Mechanism's own derived values)
_SLOT = "_kinematics"

T = TypeVar("T")


class Kinematics:
    """The kinematic chain of one Mechanism on its assembly branches."""

    def __init__(self, mechanism: Mechanism, structure: Structure | None = None) -> None:
        self.mechanism = mechanism
        self.structure = structure if structure is not None else analyse_structure(mechanism)
        self.chain: Chain = build_chain(mechanism, self.structure)
        # what is worked out from this chain alone, made once (`kept`)
        self._kept: dict[str, Any] = {}

    def kept(self, name: str, make: Callable[[], T]) -> T:
        """The value `make()` gives, made on the first call and kept with the
        handle: for what follows from the mechanism's kinematics alone and is
        read again at every solve (the output's extreme positions and
        displacements, `solution._Turn`). A `make()` that raises keeps nothing."""
        found = self._kept.get(name)
        if found is None:
            found = self._kept[name] = make()
        return found  # type: ignore[no-any-return]

    @property
    def branches(self) -> Branches:
        """The record of the branch search: the signs chosen, why, where it assembles."""
        return self.chain.choice  # type: ignore[no-any-return]

    def sweep(self, phi1_deg: float | Iterable[float] | np.ndarray) -> Sweep:
        """Positions, velocities and accelerations of every point, ω and ε of
        every link, at the crank angles given (deg); NaN where a group cannot
        assemble (`Sweep.check()` raises it)."""
        return self.chain.sweep(phi1_deg)

    def at(self, phi1_deg: float) -> Sweep:
        """The kinematics at one crank angle; AssemblyError (naming the angle
        and the group) where the mechanism cannot assemble."""
        return self.chain.sweep(np.array([float(phi1_deg)])).check()


def kinematics(mechanism: Mechanism, structure: Structure | None = None) -> Kinematics:
    """The handle of `mechanism`, built on the first call and kept with it."""
    found = mechanism.__dict__.get(_SLOT)
    if found is None:
        found = Kinematics(mechanism, structure)
        mechanism.__dict__[_SLOT] = found
    return found  # type: ignore[no-any-return]
