"""Reduction to the crank (seed 002 tasks 5 and 6), at every position at once.

Reduced moment of the production resistance, by equal instantaneous powers:

    M_red·ω1 = Σ F_PR·V·cos(F_PR, V)            (task 5: M = −F_KO·v_S5/ω1)

signed like the balancing moment: positive in the sense of the crank's
rotation (driving), negative when it resists. Reduced moment of inertia, by
equal kinetic energies:

    J_red = Σ (m_i·V_Si² + J_Si·ω_i²) / ω1²     (task 6)

the crank's own m_1·V_S1² + J_S1·ω1² included.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from ..model import Force, Mechanism, Stroke, frozen_array

if TYPE_CHECKING:  # pragma: no cover
    from ..kinematics.chain import Sweep


@dataclass(frozen=True)
class Reduction:
    """M_red and J_red at each angle of a sweep (NaN where the mechanism does not move)."""

    phi1_deg: np.ndarray
    index: tuple[int | None, ...]  # the position numbers (None for other angles)
    stroke: tuple[Stroke, ...]
    omega1: float  # |ω1|, rad/s
    reduced_moment: np.ndarray  # M_red of every [[force]], N·m
    reduced_moment_of: Mapping[str, np.ndarray]  # per force
    reduced_inertia: np.ndarray  # J_red, kg·m²


def reduce_sweep(
    mech: Mechanism, sweep: Sweep, index: tuple[int | None, ...], stroke: tuple[Stroke, ...]
) -> Reduction:
    w1 = mech.drive.omega
    working = np.array([s == "working" for s in stroke], dtype=bool)
    ok = sweep.ok
    per_force = {}
    total = np.zeros(len(sweep.phi1_deg))
    for f in mech.forces:
        power = np.where(ok, production_power(mech, sweep, f, working), np.nan)
        m = power / w1
        per_force[f.name] = frozen_array(m)
        total = total + m
    energy = np.zeros(len(sweep.phi1_deg))
    for lid, link in mech.links.items():
        state = sweep.links[lid]
        cm = complex(link.cm[0], link.cm[1])
        V_S = state.vel(state.at(cm))
        energy = energy + link.mass * np.abs(V_S) ** 2 + link.J * state.omega**2
    J_red = np.where(ok, energy / (w1 * w1), np.nan)
    return Reduction(
        frozen_array(sweep.phi1_deg),
        index,
        stroke,
        w1,
        frozen_array(total),
        per_force,
        frozen_array(J_red),
    )


def production_power(mech: Mechanism, sweep: Sweep, f: Force, working: np.ndarray) -> np.ndarray:
    """F·V of a `[[force]]` at every angle (SPEC_FORMAT's acts rules)."""
    state = sweep.links[f.link]
    p = mech.links[f.link].points[f.at]
    V = state.vel(state.at(complex(p[0], p[1])))
    if f.direction is None and f.acts == "always":
        return -f.magnitude * np.abs(V)  # opposes V: power −F·|V|
    if f.direction is not None:
        d = complex(f.direction[0], f.direction[1])
        acting = np.ones_like(working) if f.acts == "always" else working
    else:
        wd = mech.study.working_direction
        d = -complex(wd[0], wd[1])
        acting = working
    power = f.magnitude * (d.real * V.real + d.imag * V.imag)
    return np.where(acting, power, 0.0)
