"""The kinematics of the mechanism at the one position a force analysis is made for.

Plane vectors are complex numbers, as in `kinematics/`: the perpendicular
k × r is i·r, the z-component of a × b is Im(conj(a)·b).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from ..model import FRAME, Mechanism, Prismatic, Stroke
from ..structure import AssurGroup

if TYPE_CHECKING:  # pragma: no cover
    from ..kinematics.chain import Sweep


def cross(a: complex, b: complex) -> float:
    """z-component of a × b (the moment of force b applied at arm a)."""
    return a.real * b.imag - a.imag * b.real


def _complex(p) -> complex:
    """A point [x, y] as a complex number, an array's through Python floats
    (no numpy scalars): the same values."""
    return complex(*p.tolist()) if p.__class__ is np.ndarray else complex(p[0], p[1])


def xy(z: complex) -> np.ndarray:
    """A complex plane vector as a read-only [x, y] array (`frozen_array`'s
    float array: the parts of a complex number are floats already)."""
    arr = np.array((z.real, z.imag))
    arr.setflags(write=False)
    return arr


def xy_rows(zs: list[complex]) -> list[np.ndarray]:
    """`xy` of each of several vectors: the rows of one read-only array (made
    at once, the same numbers)."""
    flat: list[float] = []
    for z in zs:  # one flat list of floats: numpy reads it faster than pairs
        flat += (z.real, z.imag)
    arr = np.array(flat, dtype=float).reshape(-1, 2)
    arr.setflags(write=False)
    return list(arr)


@dataclass(frozen=True)
class LinkPose:
    """Pose and motion of one link at one position: e^{iθ}, origin o, ω, V_o, ε, a_o."""

    e: complex
    o: complex
    omega: float
    v: complex
    eps: float
    a: complex

    def at(self, local: complex) -> complex:
        return self.o + self.e * local

    def vel(self, P: complex) -> complex:
        return self.v + 1j * self.omega * (P - self.o)

    def acc(self, P: complex) -> complex:
        return self.a + (1j * self.eps - self.omega * self.omega) * (P - self.o)


@dataclass(frozen=True)
class PositionState:
    """Where every link is and how it moves at one crank angle."""

    mech: Mechanism
    index: int | None  # the position's number, None for another angle
    phi1_deg: float
    stroke: Stroke
    links: dict[int, LinkPose]
    groups: tuple[AssurGroup, ...] = ()  # the Assur groups in the order they are attached

    def local(self, link: int, name: str) -> complex:
        pts = self.mech.frame if link == FRAME else self.mech.links[link].points
        return _complex(pts[name])

    def point(self, link: int, name: str) -> complex:
        """Global position of point `name` of `link` (m)."""
        return self.links[link].at(self.local(link, name))

    def centre_of_mass(self, link: int) -> complex:
        return self.links[link].at(_complex(self.mech.links[link].cm))

    def guide(self, pair: Prismatic) -> tuple[complex, complex]:
        """The sliding line of a prismatic pair: its unit direction u (global) and
        the slider's point on it, the reference point of the pair's reaction."""
        u = self.links[pair.guide].e * complex(pair.direction[0], pair.direction[1])
        return u, self.point(pair.slider, pair.slider_point)

    @property
    def omega1(self) -> float:
        return self.links[self.mech.drive.link].omega


def from_sweep(
    mech: Mechanism, sweep: Sweep, k: int, index: int | None, stroke: Stroke
) -> PositionState:
    """The state at entry k of a sweep; a position whose kinematics failed
    raises the kinematics' own error."""
    problem = sweep.problem(k)
    if problem is not None:
        raise problem
    # .item(k): entry k as a Python number (the same value, without a numpy scalar)
    links = {
        lid: LinkPose(
            complex(s.e.item(k)),
            complex(s.o.item(k)),
            float(s.omega.item(k)),
            complex(s.v.item(k)),
            float(s.eps.item(k)),
            complex(s.a.item(k)),
        )
        for lid, s in sweep.links.items()
    }
    groups = tuple(solver.group for solver in sweep.chain.solvers)
    return PositionState(mech, index, float(sweep.phi1_deg[k]), stroke, links, groups)
