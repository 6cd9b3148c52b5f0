"""The velocity and acceleration plan at one position, as data for a drawing.

The pole (p for velocities, π for accelerations) is the origin; each point's
image is its absolute velocity or acceleration. Each group contributes the
components of its two vector equations in the order the textbook draws them.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Literal

import numpy as np

if TYPE_CHECKING:  # pragma: no cover
    from .chain import Sweep

ComponentKind = Literal["relative", "normal", "tangential", "coriolis", "slide"]


@dataclass(frozen=True)
class Component:
    """One vector of a plan drawn from `start` (a point of the plan, SI units)."""

    label: str
    kind: ComponentKind
    start: np.ndarray
    vector: np.ndarray

    @property
    def end(self) -> np.ndarray:
        return self.start + self.vector

    @property
    def magnitude(self) -> float:
        return float(np.hypot(*self.vector))


@dataclass(frozen=True)
class GroupPlanView:
    group: str
    kind: str
    point: str  # the point whose two equations the group's plan solves
    velocity: tuple[Component, ...]
    acceleration: tuple[Component, ...]
    sin_angle: float  # sine of the angle between the two direction lines


@dataclass(frozen=True)
class PlanView:
    index: int | None
    phi1_deg: float
    velocity_images: dict[str, np.ndarray]  # pole p at the origin
    acceleration_images: dict[str, np.ndarray]  # pole π at the origin
    groups: tuple[GroupPlanView, ...]
    omega: dict[int, float]
    eps: dict[int, float]


def _v(z: complex) -> np.ndarray:
    arr = np.array([z.real, z.imag])
    arr.setflags(write=False)
    return arr


def _entry(x, k: int):
    return x[k] if isinstance(x, np.ndarray) else x


def plan_view(sweep: Sweep, k: int, index: int | None = None) -> PlanView:
    """The plan at entry k of a sweep (position `index`)."""
    groups = []
    for plan in sweep.plans:
        vel, acc = [], []
        for leg in plan.legs:
            # a leg starting on the frame has V0 = a0 = 0 as plain numbers, a slide
            # along a guide on the frame its direction d and Coriolis component n
            V0, x, d = complex(_entry(leg.V0, k)), float(leg.x[k]), complex(_entry(leg.d, k))
            a0, n, y = complex(_entry(leg.a0, k)), complex(_entry(leg.n, k)), float(leg.y[k])
            rel = plan.X_name
            if leg.kind == "rotation":
                centre = leg.centre
                vel.append(Component(f"V_{rel}{centre}", "relative", _v(V0), _v(d * x)))
                acc.append(Component(f"a^n_{rel}{centre}", "normal", _v(a0), _v(n)))
                acc.append(Component(f"a^t_{rel}{centre}", "tangential", _v(a0 + n), _v(d * y)))
            else:
                vel.append(Component(f"V_{rel}/{leg.link}", "slide", _v(V0), _v(d * x)))
                acc.append(Component(f"a^k_{rel}/{leg.link}", "coriolis", _v(a0), _v(n)))
                acc.append(Component(f"a^r_{rel}/{leg.link}", "slide", _v(a0 + n), _v(d * y)))
        groups.append(
            GroupPlanView(
                plan.group.name,
                plan.group.kind or "",
                plan.X_name,
                tuple(vel),
                tuple(acc),
                float(plan.sin_angle[k]),
            )
        )
    v_img = {name: _v(complex(sweep.velocity_of(name)[k])) for name in sweep.chain.locate}
    a_img = {name: _v(complex(sweep.acceleration_of(name)[k])) for name in sweep.chain.locate}
    return PlanView(
        index=index,
        phi1_deg=float(sweep.phi1_deg[k]),
        velocity_images=v_img,
        acceleration_images=a_img,
        groups=tuple(groups),
        omega={lid: float(w[k]) for lid, w in sweep.omega.items()},
        eps={lid: float(e[k]) for lid, e in sweep.eps.items()},
    )
