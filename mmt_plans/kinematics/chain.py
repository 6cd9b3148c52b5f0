"""The kinematic chain: the driving link, then the Assur groups in the order
they are attached, each solved in closed form over all crank angles at once.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from functools import cached_property

import numpy as np

from ..errors import AssemblyError, SingularPlanError, UnsupportedError
from ..model import FRAME, Mechanism
from .dyads import SOLVERS, DyadSolver, GroupPlan, Motion

# a plan whose direction lines meet at an angle with a sine below this is
# reported as singular rather than solved (see tests/kinematics/test_hard_cases.py)
SINGULAR_SIN = 1e-12
BRANCH_GRID = 720


@dataclass(frozen=True)
class LinkState:
    """Pose and motion of one link over the angles (read-only arrays)."""

    e: np.ndarray
    o: np.ndarray
    omega: np.ndarray
    v: np.ndarray
    eps: np.ndarray
    a: np.ndarray

    @property
    def angle_deg(self) -> np.ndarray:
        return np.degrees(np.angle(self.e))

    def at(self, p_local: complex) -> np.ndarray:
        return self.o + self.e * p_local

    def vel(self, P: np.ndarray) -> np.ndarray:
        return self.v + 1j * self.omega * (P - self.o)

    def acc(self, P: np.ndarray) -> np.ndarray:
        return self.a + (1j * self.eps - self.omega**2) * (P - self.o)


def _xy(z: np.ndarray) -> np.ndarray:
    """The same numbers seen as [x, y] pairs (no copy)."""
    z = np.ascontiguousarray(z, dtype=complex)
    out = z.view(np.float64).reshape(z.shape + (2,))
    out.setflags(write=False)
    return out


def _full(x, n: int, dtype) -> np.ndarray:
    """x as a read-only (n,) array, copying only a scalar that must be spread out."""
    x = np.asarray(x)
    if x.shape != (n,) or x.dtype != dtype:
        x = np.full(n, x, dtype=dtype) if x.ndim == 0 else x.astype(dtype)
    x.setflags(write=False)
    return x


def _ro(a) -> np.ndarray:
    a = np.asarray(a)
    a.setflags(write=False)
    return a


@dataclass(frozen=True)
class Sweep:
    """Kinematics over many crank angles: complex arrays inside, [x, y] outside.

    `points`, `v`, `a` map every point name (and S1, S2, … for the centres of
    mass) to an (N, 2) array; `omega`, `eps` map link ids to (N,) arrays.
    Entries are NaN at angles where a group cannot assemble (`failed`) or its
    plan is singular (`singular`); `check()` turns those into errors.
    """

    chain: "Chain"
    phi1_deg: np.ndarray
    links: dict[int, LinkState]
    plans: tuple[GroupPlan, ...]
    failed: dict[str, np.ndarray]  # group name -> mask of angles where it cannot assemble
    singular: dict[str, np.ndarray]  # group name -> mask of singular plans
    where: dict[str, int] = field(repr=False, default_factory=dict)

    def position_of(self, name: str) -> np.ndarray:
        link, local = self.chain.locate[name]
        return self.links[link].at(local)

    def velocity_of(self, name: str) -> np.ndarray:
        link, local = self.chain.locate[name]
        state = self.links[link]
        return state.vel(state.at(local))

    def acceleration_of(self, name: str) -> np.ndarray:
        link, local = self.chain.locate[name]
        state = self.links[link]
        return state.acc(state.at(local))

    @cached_property
    def _positions(self) -> dict[str, np.ndarray]:
        return {name: self.position_of(name) for name in self.chain.locate}

    @cached_property
    def points(self) -> dict[str, np.ndarray]:
        return {name: _xy(P) for name, P in self._positions.items()}

    @cached_property
    def v(self) -> dict[str, np.ndarray]:
        return {name: _xy(self.links[self.chain.locate[name][0]].vel(P))
                for name, P in self._positions.items()}

    @cached_property
    def a(self) -> dict[str, np.ndarray]:
        return {name: _xy(self.links[self.chain.locate[name][0]].acc(P))
                for name, P in self._positions.items()}

    @property
    def omega(self) -> dict[int, np.ndarray]:
        return {lid: s.omega for lid, s in self.links.items() if lid != FRAME}

    @property
    def eps(self) -> dict[int, np.ndarray]:
        return {lid: s.eps for lid, s in self.links.items() if lid != FRAME}

    @property
    def ok(self) -> np.ndarray:
        bad = np.zeros(len(self.phi1_deg), dtype=bool)
        for mask in list(self.failed.values()) + list(self.singular.values()):
            bad |= mask
        return ~bad

    def problem(self, i: int) -> AssemblyError | SingularPlanError | None:
        """What went wrong at angle i, as the error a user reads (or None)."""
        for solver in self.chain.solvers:
            name = solver.group.name
            if self.failed[name][i]:
                return AssemblyError(float(self.phi1_deg[i]), name, self.chain.reason(solver, float(self.phi1_deg[i])))
        for solver in self.chain.solvers:
            name = solver.group.name
            if self.singular[name][i]:
                return SingularPlanError(
                    float(self.phi1_deg[i]), name,
                    "its two direction lines are parallel (the group is at a limit position)")
        return None

    def check(self) -> "Sweep":
        """Raise the first problem, if any."""
        bad = np.flatnonzero(~self.ok)
        if len(bad):
            raise self.problem(int(bad[0]))  # type: ignore[misc]
        return self


class Chain:
    """The driving link and the dyad solvers, with their assembly branches."""

    def __init__(self, mech: Mechanism, solvers: list[DyadSolver]) -> None:
        self.mech = mech
        self.solvers = solvers
        self.branches: dict[str, int] = {}
        self.branch_note = ""
        crank = mech.links[mech.drive.link]
        self.O = complex(*mech.frame[mech.crank_pivot])
        self.O_local = complex(*crank.points[mech.crank_pivot])
        A_local = complex(*crank.points[mech.crank_pin])
        self.crank_local_angle = math.atan2((A_local - self.O_local).imag, (A_local - self.O_local).real)
        self.locate: dict[str, tuple[int, complex]] = {}
        for name, p in mech.frame.items():
            self.locate[name] = (FRAME, complex(*p))
        for link in mech.links.values():
            for name, p in link.points.items():
                self.locate.setdefault(name, (link.id, complex(*p)))
        for link in mech.links.values():
            self.locate[link.cm_name] = (link.id, complex(*link.cm))

    @classmethod
    def build(cls, mech: Mechanism) -> "Chain":
        structure = mech.structure
        if mech.higher_pairs:
            raise UnsupportedError(
                f"{mech.path}: the mechanism has higher pairs; their kinematics is not solved: "
                "replace each higher pair by its lower-pair equivalent in the file")
        solvers = []
        for group in structure.groups:
            if not group.is_dyad:
                raise UnsupportedError(
                    f"{mech.path}: group {group.label} of links {group.name} is of class "
                    f"{group.group_class}; only class II groups (dyads) are solved. "
                    f"Structure: {structure.formula}")
            solvers.append(SOLVERS[group.kind](mech, group))
        chain = cls(mech, solvers)
        chain.choose_branches()
        return chain

    # --- one pass over the angles ----------------------------------------------------
    def crank(self, phi_rad: np.ndarray) -> Motion:
        w = self.mech.drive.signed_omega
        e = np.exp(1j * (phi_rad - self.crank_local_angle))
        o = self.O - e * self.O_local
        r = o - self.O
        return Motion(e, o, w, 1j * w * r, 0.0, -w * w * r)

    def frame(self, n: int) -> Motion:
        return Motion(np.ones(n, dtype=complex), np.zeros(n, dtype=complex), 0.0, 0j, 0.0, 0j)

    def place_all(self, phi_rad: np.ndarray, branches: dict[str, int]) -> dict[int, Motion]:
        m = {FRAME: self.frame(len(phi_rad)), self.mech.drive.link: self.crank(phi_rad)}
        for solver in self.solvers:
            solver.positions(m, branches.get(solver.group.name, 1))
        return m

    def sweep(self, phi1_deg: np.ndarray) -> Sweep:
        phi1_deg = np.atleast_1d(np.asarray(phi1_deg, dtype=float))
        n = len(phi1_deg)
        m = self.place_all(np.radians(phi1_deg), self.branches)
        failed, singular, plans = {}, {}, []
        for solver in self.solvers:
            name = solver.group.name
            L1, L2 = m[solver.L1], m[solver.L2]
            failed[name] = _ro(~(np.isfinite(L1.o) & np.isfinite(L2.o) & np.isfinite(L1.e)
                                 & np.isfinite(L2.e)))
            plan = solver.plan(m)
            singular[name] = _ro(~failed[name] & ~(plan.sin_angle > SINGULAR_SIN))
            plans.append(plan)
        states = {lid: LinkState(e=_full(mo.e, n, complex), o=_full(mo.o, n, complex),
                                 omega=_full(mo.w, n, float), v=_full(mo.v, n, complex),
                                 eps=_full(mo.eps, n, float), a=_full(mo.a, n, complex))
                  for lid, mo in m.items()}
        return Sweep(self, _ro(phi1_deg.copy()), states, tuple(plans), failed, singular)

    def reason(self, solver: DyadSolver, phi1_deg: float) -> str:
        m = self.place_all(np.radians(np.array([phi1_deg])), self.branches)
        return solver.failure(m, 0, phi1_deg)

    # --- assembly branches ------------------------------------------------------------
    def choose_branches(self) -> None:
        """Sketch first (least squares at the sketch's crank angle), else the
        documented rule: for each group in order, +1 then -1, the first branch
        that assembles over the whole turn; failing that, the one that
        assembles at more angles."""
        mech = self.mech
        notes = []
        sketch_phi = None
        if mech.crank_pin in mech.sketch:
            A = complex(*mech.sketch[mech.crank_pin])
            sketch_phi = np.array([math.atan2((A - self.O).imag, (A - self.O).real)])
        grid = np.linspace(0, 2 * np.pi, BRANCH_GRID, endpoint=False)
        for solver in self.solvers:
            name = solver.group.name
            if not solver.has_branches:
                continue
            choice = None
            if sketch_phi is not None:
                choice = self._branch_by_sketch(solver, sketch_phi)
                if choice is not None:
                    notes.append(f"group {name}: branch {choice:+d} (nearest to the sketch)")
            if choice is None:
                counts = {}
                for sign in (1, -1):
                    trial = dict(self.branches, **{name: sign})
                    m = self.place_all(grid, trial)
                    counts[sign] = int(np.sum(np.isfinite(m[solver.L1].o) & np.isfinite(m[solver.L2].o)))
                    if counts[sign] == len(grid):
                        break
                choice = max(counts, key=lambda s: (counts[s], s))
                whole = "assembles over the whole turn" if counts[choice] == len(grid) else (
                    f"assembles at {counts[choice]} of {len(grid)} angles")
                notes.append(f"group {name}: branch {choice:+d} ({_branch_meaning(solver, choice)}; "
                             f"{whole})")
            self.branches[name] = choice
        self.branch_note = "; ".join(notes)

    def _branch_by_sketch(self, solver: DyadSolver, phi: np.ndarray) -> int | None:
        mech = self.mech
        names = [p for lid in (solver.L1, solver.L2)
                 for p in mech.links[lid].points if p in mech.sketch]
        if not names:
            return None
        best = None
        for sign in (1, -1):
            m = self.place_all(phi, dict(self.branches, **{solver.group.name: sign}))
            err = 0.0
            for p in names:
                lid = solver.L1 if p in mech.links[solver.L1].points else solver.L2
                local = complex(*mech.links[lid].points[p])
                err += abs(m[lid].at(local)[0] - complex(*mech.sketch[p])) ** 2
            if np.isfinite(err) and (best is None or err < best[0]):
                best = (err, sign)
        return None if best is None else best[1]


def _branch_meaning(solver: DyadSolver, sign: int) -> str:
    side = "left" if sign > 0 else "right"
    if solver.kind == "RRR":
        a, b, c = solver.outer1.point, solver.inner.point, solver.outer2.point
        return f"{b} to the {side} of {a}->{c}"
    if solver.kind == "RRP":
        b = solver.inner.point
        return f"{b} at the {'far' if sign > 0 else 'near'} intersection along the guide"
    return f"guide of link {solver.inner.guide} turned {'+' if sign > 0 else '-'}"
