"""The kinematic chain: the driving link, then the Assur groups in the order
they are attached, each solved in closed form over all crank angles at once.
"""

from __future__ import annotations

import cmath
import math
from collections.abc import Iterable
from dataclasses import dataclass, field
from functools import cached_property, lru_cache
from typing import Any

import numpy as np

from ..errors import AssemblyError, SingularPlanError, UnsupportedError, shown
from ..model import FRAME, Mechanism
from ..structure import Structure, analyse_structure
from .dyads import DYADS, DyadSolver, GroupPlan, Motion
from .geometry import quiet

# a plan whose direction lines meet at an angle with a sine below this is
# reported as singular rather than solved (see tests/kinematics/test_hard_cases.py)
SINGULAR_SIN = 1e-12
BRANCH_GRID = 720
# a long sweep is solved at most this many angles at a time (working arrays of
# 2 MB). Below it one pass: measured in a steady allocator (bench/sweeps.py),
# copying chunks into one block cost more than the cache saved (36,000 angles:
# 1.37× numpy in chunks of 16,384, 1.00× in one pass).
CHUNK = 131072


@dataclass(frozen=True)
class LinkState:
    """Pose and motion of one link over the angles (read-only arrays)."""

    e: np.ndarray
    o: np.ndarray
    omega: np.ndarray
    v: np.ndarray
    eps: np.ndarray
    a: np.ndarray
    # iω·e and (iε - ω²)·e: velocity and acceleration per unit of local coordinate
    spin: np.ndarray | None = field(repr=False, default=None)
    spin_acc: np.ndarray | None = field(repr=False, default=None)

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
    """x as a read-only (n,) array; a number (the frame's, a constant ω) is
    spread out without a copy."""
    if not isinstance(x, np.ndarray):
        return _spread(x, n, dtype)
    if x.dtype != dtype:
        x = x.astype(dtype)
    x.setflags(write=False)
    return x


def _link_xy(z: np.ndarray, n: int) -> np.ndarray:
    """`_xy` of a link state's complex array (read-only, so is the view):
    seen as pairs at once where it is contiguous, as it is but for a spread
    number (which `_recipe` does not ask for) or a strided one."""
    try:
        return z.view(np.float64).reshape(n, 2)
    except ValueError:
        return _xy(z)


@lru_cache(maxsize=512)
def _spread(x, n: int, dtype) -> np.ndarray:
    """A number seen at n angles: one value, stride 0, read-only (so shared by
    every sweep of that many angles: the frame's, a crank's constant ω)."""
    out = np.ndarray((n,), dtype=dtype, buffer=np.array([x], dtype=dtype), strides=(0,))
    out.setflags(write=False)
    return out


@lru_cache(maxsize=512)
def _still(z: complex, n: int) -> np.ndarray:
    """A frame point's [x, y] at every angle (one pair, not copied, read-only)."""
    pair = np.array([z.real, z.imag])
    out = np.ndarray((n, 2), dtype=np.float64, buffer=pair, strides=(0, pair.itemsize))
    out.setflags(write=False)
    return out


_STATE = (
    ("e", "e", complex),
    ("o", "o", complex),
    ("omega", "w", float),
    ("v", "v", complex),
    ("eps", "eps", float),
    ("a", "a", complex),
    ("spin", "spin", complex),
    ("spin_acc", "spin_acc", complex),
)


_ATTR = {name: attr for name, attr, _ in _STATE}
# what a long sweep keeps of each link: not the products iω·e and (iε - ω²)·e,
# which served the points' fields (worked out chunk by chunk) and are cheaply
# made again from the rest (`Motion.of`)
_KEPT = _STATE[:6]


# the kinds as numpy's own dtypes: an array's dtype is compared with one
# without converting a Python type at every field of every link of a sweep
_C, _F = np.dtype(complex), np.dtype(float)


def _state(mo: Motion, n: int) -> LinkState:
    # _STATE's fields in order, written out: a sweep makes one per link
    return LinkState(
        _full(mo.e, n, _C),
        _full(mo.o, n, _C),
        _full(mo.w, n, _F),
        _full(mo.v, n, _C),
        _full(mo.eps, n, _F),
        _full(mo.a, n, _C),
        _full(mo.spin, n, _C),
        _full(mo.spin_acc, n, _C),
    )


def _state_part(mo: Motion, part: slice, n: int) -> LinkState:
    """`_state` of the link's motion at the angles `part` of a pass (its arrays
    cut, its plain numbers spread out), without a Motion in between."""

    return LinkState(
        _cut(mo.e, part, n, _C),
        _cut(mo.o, part, n, _C),
        _cut(mo.w, part, n, _F),
        _cut(mo.v, part, n, _C),
        _cut(mo.eps, part, n, _F),
        _cut(mo.a, part, n, _C),
        _cut(mo.spin, part, n, _C),
        _cut(mo.spin_acc, part, n, _C),
    )


def _cut(x, part: slice, n: int, dtype) -> np.ndarray:
    """`_full` of an array's angles `part` (a view, read-only), or of a
    number spread out: what `_full(x[part], ...)` gives, in one call."""
    if x.__class__ is np.ndarray and x.ndim:
        x = x[part]
        if x.dtype != dtype:
            x = x.astype(dtype)
        x.setflags(write=False)
        return x
    return _full(x, n, dtype)


def motion_part(mo: Motion, part: slice) -> Motion:
    """The motion of a link at the angles `part` of a pass: its arrays cut
    (views), its plain numbers (the frame's, a constant ω) as they are."""
    out = Motion.__new__(Motion)
    for name in Motion.__slots__:
        x = getattr(mo, name)
        setattr(out, name, x[part] if isinstance(x, np.ndarray) and x.ndim else x)
    return out


@lru_cache(maxsize=64)
def _frame_state(n: int) -> LinkState:
    """The frame's state over n angles: plain numbers spread out, the same for
    every sweep of that many angles."""
    return _state(Motion(1 + 0j, 0j), n)


class _Arena:
    """One block of memory for everything a long sweep keeps: the arrays of
    every link's motion, the failure masks and the points' fields.
    A quantity that is a plain number in the first chunk (the frame's, the
    crank's ω) stays one."""

    def __init__(self, chain: Chain, m: dict, failed: dict, n: int) -> None:
        self.chain, self.n = chain, n
        wanted = [
            (lid, name, dtype)
            for lid, mo in m.items()
            if lid != FRAME
            for name, attr, dtype in _KEPT
            if np.ndim(getattr(mo, attr))
        ]
        sizes = [n * np.dtype(dtype).itemsize for _, _, dtype in wanted]
        masks = 2 * len(failed) * n
        fields = 3 * sum(1 for lid, _ in chain.locate.values() if lid != FRAME) * n * 16
        memory = np.empty(sum(sizes) + fields + masks, dtype=np.uint8)
        self.arrays: dict[tuple[int, str], np.ndarray] = {}
        at = 0
        for (lid, name, dtype), size in zip(wanted, sizes):
            self.arrays[lid, name] = memory[at : at + size].view(dtype)
            at += size
        self.fields = memory[at : at + fields].view(complex)
        at += fields
        self.failed = {
            g: memory[at + 2 * k * n : at + (2 * k + 1) * n].view(bool)
            for k, g in enumerate(failed)
        }
        self.singular = {
            g: memory[at + (2 * k + 1) * n : at + (2 * k + 2) * n].view(bool)
            for k, g in enumerate(failed)
        }
        # the first chunk's plain numbers (not its arrays, whose memory the next chunk reuses)
        self.numbers = {
            lid: {attr: getattr(mo, attr) for _, attr, _ in _KEPT if not np.ndim(getattr(mo, attr))}
            for lid, mo in m.items()
        }

    def put(self, part: slice, m: dict, failed: dict, singular: dict) -> None:
        """Keep one chunk: its links' motion, its masks, and the fields of its
        points, worked out while the chunk is still in the cache."""
        for (lid, name), arr in self.arrays.items():
            arr[part] = getattr(m[lid], _ATTR[name])
        for g in failed:
            self.failed[g][part] = failed[g]
            self.singular[g][part] = singular[g]
        block = self.fields.reshape(3, -1, self.n)[:, :, part]
        _work_out_fields(block, m, self.chain)

    def sweep(self, phi1_deg: np.ndarray) -> Sweep:
        states = {}
        for lid, numbers in self.numbers.items():
            parts = {}
            for name, attr, dtype in _KEPT:
                arr = self.arrays.get((lid, name))
                parts[name] = _ro(arr) if arr is not None else _full(numbers[attr], self.n, dtype)
            states[lid] = LinkState(**parts)
        return Sweep(
            self.chain,
            _ro(phi1_deg.copy()),
            states,
            {g: _ro(x) for g, x in self.failed.items()},
            {g: _ro(x) for g, x in self.singular.items()},
            worked_out=self.fields,
        )


# a point's position, velocity and acceleration: the link's origin quantity
# plus its quantity per unit of local coordinate times p
_FIELD_PARTS = (("o", "e"), ("v", "spin"), ("a", "spin_acc"))


def _moving_points(chain: Chain) -> list[tuple[str, int, complex]]:
    """The points on moving links, link by link (each link's points next to
    each other in the block of fields, so one product and one sum fill them)."""
    found = chain.__dict__.get("_moving")
    if found is None:
        points = [(name, lid, p) for name, (lid, p) in chain.locate.items() if lid != FRAME]
        found = chain.__dict__["_moving"] = sorted(points, key=lambda point: point[1])
    return found  # type: ignore[no-any-return]


def _link_rows(chain: Chain) -> list[tuple[int, slice, np.ndarray]]:
    """For each moving link: its rows in the block of fields and its points'
    local coordinates as a column."""
    found = chain.__dict__.get("_rows")
    if found is None:
        points = _moving_points(chain)
        found = []
        start = 0
        while start < len(points):
            lid = points[start][1]
            end = start
            while end < len(points) and points[end][1] == lid:
                end += 1
            column = np.array([p for _, _, p in points[start:end]], dtype=complex)[:, None]
            found.append((lid, slice(start, end), column))
            start = end
        chain.__dict__["_rows"] = found
    return found  # type: ignore[no-any-return]


def _is_origin(p: complex, origin) -> bool:
    """A point at its link's origin, when that moves: its field is the link's own array."""
    return not p and isinstance(origin, np.ndarray) and bool(origin.strides[0])


def _known(links: dict, carried: dict, base: str, name: str, lid: int, p: complex):
    """Which link's array a point's row would repeat, if one does: the origin
    quantity of its link (a point at the origin), or the velocity or
    acceleration of a link whose origin sits on the point (`DyadSolver.carried`)."""
    if _is_origin(p, getattr(links[lid], base)):
        return lid
    if base != "o" and name in carried:
        if _is_origin(0j, getattr(links[carried[name]], base)):
            return carried[name]
    return None


def _all_known(links: dict, carried: dict, points: list, chain: Chain | None = None) -> list[list]:
    """For every quantity and point, the link array its row repeats (or None).
    Which rows repeat which arrays follows from the chain's structure alone,
    so a chain works it out once."""
    sources = getattr(chain, "_known_sources", None)
    if sources is None:
        sources = [
            [_known(links, carried, base, name, lid, p) for name, lid, p in points]
            for base, _ in _FIELD_PARTS
        ]
        if chain is not None:
            chain._known_sources = sources  # type: ignore[attr-defined]
    return [
        [None if src is None else getattr(links[src], base) for src in row]
        for (base, _), row in zip(_FIELD_PARTS, sources)
    ]


def _rows_to_fill(chain: Chain, links: dict) -> list[list[tuple[int, slice, np.ndarray]]]:
    """`_link_rows` for each quantity, without the links all of whose rows
    repeat a link's array (`_all_known`): nothing of theirs is read."""
    found = chain.__dict__.get("_to_fill")
    if found is None:
        points = _moving_points(chain)
        _all_known(links, chain.carried, points, chain)
        sources = chain._known_sources  # type: ignore[attr-defined]
        found = [
            [
                (lid, where, column)
                for lid, where, column in _link_rows(chain)
                if any(src is None for src in held[where])
            ]
            for held in sources
        ]
        chain.__dict__["_to_fill"] = found
    return found  # type: ignore[no-any-return]


def _recipe(chain: Chain, links: dict) -> list[list[tuple[str, str, Any]]]:
    """For each quantity, every point of the chain in `locate`'s order with
    where its [x, y] rows come from: ("row", k) its row of the block, ("link",
    lid) the array of the link it repeats (`_all_known`), ("frame", z) a
    frame point's still pair. It follows from the chain's structure alone,
    so a chain works it out once."""
    found = chain.__dict__.get("_recipe")
    if found is None:
        points = _moving_points(chain)
        known = _all_known(links, chain.carried, points, chain)
        sources = chain._known_sources  # type: ignore[attr-defined]
        row = {name: k for k, (name, _, _) in enumerate(points)}
        found = []
        for (base, _), held in zip(_FIELD_PARTS, sources):
            by_name = {name: src for (name, _, _), src in zip(points, held)}
            steps: list[tuple[str, str, Any]] = []
            for name, (lid, p) in chain.locate.items():
                if lid == FRAME:
                    steps.append((name, "frame", p if base == "o" else 0j))
                elif by_name[name] is None:
                    steps.append((name, "row", row[name]))
                else:
                    steps.append((name, "link", by_name[name]))
            found.append(steps)
        del known
        chain.__dict__["_recipe"] = found
    return found  # type: ignore[no-any-return]


def _work_out_fields(block: np.ndarray, links: dict, chain: Chain) -> None:
    """o + e·p, v + iω·e·p and a + (iε - ω²)·e·p of every point into its row
    of block (one row per point and quantity), from the links' motion (`Motion`
    or `LinkState`): a link's rows at once, the products then the sums. (A
    row some link already holds, `_all_known`, is filled too, and not read,
    unless every row of its link is such.)"""
    for (base, per_unit), rows, parts in zip(_FIELD_PARTS, block, _rows_to_fill(chain, links)):
        for lid, where, column in parts:
            link = links[lid]
            out = rows[where]
            np.multiply(getattr(link, per_unit), column, out=out)
            origin = getattr(link, base)
            if not _nothing(origin):  # the crank's pivot, its V and a: zero, no pass
                np.add(origin, out, out=out)


def _nothing(x) -> bool:
    """Whether x is zero at every angle: a plain zero, or one spread out."""
    if isinstance(x, np.ndarray):
        return x.ndim == 1 and x.size > 0 and not x.strides[0] and not x[0]
    return not x


def _not_finite(values: tuple) -> Any:
    """Where any of the values is not finite. One sum is finite exactly where
    all its terms are (NaN and ±inf carry); a finite plain number (the
    frame's) adds nothing to it. A group fixed to the frame has only numbers."""
    arrays = [x for x in values if isinstance(x, np.ndarray)]
    if any(not cmath.isfinite(x) for x in values if not isinstance(x, np.ndarray)):
        return np.ones(np.broadcast_shapes(*(x.shape for x in arrays)), dtype=bool)
    if not arrays:
        return False
    total = arrays[0]
    for x in arrays[1:]:
        total = total + x
    return ~np.isfinite(total)


def _angles(phi1_deg) -> np.ndarray:
    """np.atleast_1d(np.asarray(phi1_deg, dtype=float)): a 1-d float array
    as it is (what those give back), anything else through them."""
    if phi1_deg.__class__ is np.ndarray and phi1_deg.ndim == 1 and phi1_deg.dtype == np.float64:
        return phi1_deg
    return np.atleast_1d(np.asarray(phi1_deg, dtype=float))


def _over(x, shape: tuple[int, ...]) -> np.ndarray:
    """x over the angles: an array of that shape as it is (no call into numpy's
    broadcasting machinery), a number or a smaller array spread out (a copy)."""
    if isinstance(x, np.ndarray) and x.shape == shape:
        return x
    return np.broadcast_to(x, shape).copy()


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

    chain: Chain
    phi1_deg: np.ndarray
    links: dict[int, LinkState]
    failed: dict[str, np.ndarray]  # group name -> mask of angles where it cannot assemble
    singular: dict[str, np.ndarray]  # group name -> mask of singular plans
    where: dict[str, int] = field(repr=False, default_factory=dict)
    worked_out: np.ndarray | None = field(repr=False, default=None)  # the fields, if already
    solved_plans: tuple[GroupPlan, ...] | None = field(repr=False, default=None)

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

    @property
    def _fields(self) -> tuple[dict[str, np.ndarray], ...]:
        # kept in the instance's dictionary, as `cached_property` would (whose
        # lock costs more than the lookup): read at every points, v, a
        found = self.__dict__.get("_worked_out")
        if found is None:
            found = self.__dict__["_worked_out"] = self._work_out()
        return found  # type: ignore[no-any-return]

    def _work_out(self) -> tuple[dict[str, np.ndarray], ...]:
        """o + e·p, v + iω·e·p and a + (iε - ω²)·e·p for every point p of
        every link, as [x, y] pairs. The products share one block of memory
        (one allocation instead of three per point; a long sweep filled it
        chunk by chunk); a point at a link's origin is the link's own array, a
        frame point one pair seen at every angle."""
        n = len(self.phi1_deg)
        chain = self.chain
        points = _moving_points(chain)
        shape = (len(_FIELD_PARTS), len(points), n)
        recipe = _recipe(chain, self.links)
        if self.worked_out is not None:
            block = self.worked_out.reshape(shape)
        else:
            block = np.empty(shape, dtype=complex)
            _work_out_fields(block, self.links, chain)
        # the whole block seen as [x, y] pairs once (its rows are then views)
        pairs = block.view(np.float64).reshape(shape + (2,))
        pairs.setflags(write=False)
        links = self.links
        fields = []
        for (base, _), rows, steps in zip(_FIELD_PARTS, pairs, recipe):
            fields.append(
                {
                    name: (
                        rows[at]
                        if how == "row"
                        else _link_xy(getattr(links[at], base), n)
                        if how == "link"
                        else _still(at, n)
                    )
                    for name, how, at in steps
                }
            )
        return tuple(fields)
        return tuple(fields)

    @property
    def points(self) -> dict[str, np.ndarray]:
        return self._fields[0]

    @property
    def v(self) -> dict[str, np.ndarray]:
        return self._fields[1]

    @property
    def a(self) -> dict[str, np.ndarray]:
        return self._fields[2]

    @property
    def omega(self) -> dict[int, np.ndarray]:
        return {lid: s.omega for lid, s in self.links.items() if lid != FRAME}

    @property
    def eps(self) -> dict[int, np.ndarray]:
        return {lid: s.eps for lid, s in self.links.items() if lid != FRAME}

    @cached_property
    def plans(self) -> tuple[GroupPlan, ...]:
        """The velocity and acceleration plan of every group. A sweep keeps
        only the links' motion (`DyadSolver.motion`); the plans are solved
        again from it when asked for (the drawings of the plans), leg by leg."""
        if self.solved_plans is not None:
            return self.solved_plans
        m = {lid: Motion.of(state) for lid, state in self.links.items()}
        with quiet():
            return tuple(solver.plan(m, place=False) for solver in self.chain.solvers)

    @property
    def ok(self) -> np.ndarray:
        """Where every group assembles and its plan is regular (read-only; worked
        out once and kept in the instance's dictionary, as `_fields`)."""
        found = self.__dict__.get("_ok")
        if found is None:
            bad = np.zeros(len(self.phi1_deg), dtype=bool)
            for mask in list(self.failed.values()) + list(self.singular.values()):
                bad |= mask
            found = self.__dict__["_ok"] = _ro(~bad)
        return found  # type: ignore[no-any-return]

    def problem(self, i: int) -> AssemblyError | SingularPlanError | None:
        """What went wrong at angle i, as the error a user reads (or None)."""
        for solver in self.chain.solvers:
            name = solver.group.name
            if self.failed[name][i]:
                return AssemblyError(
                    float(self.phi1_deg[i]),
                    name,
                    self.chain.reason(solver, float(self.phi1_deg[i])),
                )
        for solver in self.chain.solvers:
            name = solver.group.name
            if self.singular[name][i]:
                return SingularPlanError(
                    float(self.phi1_deg[i]),
                    name,
                    "its two direction lines are parallel (the group is at a limit position)",
                )
        return None

    def check(self) -> Sweep:
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
        self.branches: dict[str, int] = {}  # group -> branch sign (kinematics/branches.py)
        self.choice: Any = None  # the Branches record that chose them
        crank = mech.links[mech.drive.link]
        self.O = complex(*mech.frame[mech.crank_pivot])
        self.O_local = complex(*crank.points[mech.crank_pivot])
        A_local = complex(*crank.points[mech.crank_pin])
        self.crank_local_angle = math.atan2(
            (A_local - self.O_local).imag, (A_local - self.O_local).real
        )
        self.locate: dict[str, tuple[int, complex]] = {}
        for name, p in mech.frame.items():
            self.locate[name] = (FRAME, complex(*p))
        for link in mech.links.values():
            for name, p in link.points.items():
                self.locate.setdefault(name, (link.id, complex(*p)))
        for link in mech.links.values():
            self.locate[link.cm_name] = (link.id, complex(*link.cm))
        # point -> a link whose origin sits on it and so moves as it does
        self.carried: dict[str, int] = {}
        for solver in solvers:
            for L, K, name in solver.carried():
                if self.locate[name][0] == K != FRAME:
                    self.carried.setdefault(name, L)

    @classmethod
    def build(cls, mech: Mechanism, structure: Structure | None = None) -> Chain:
        structure = structure if structure is not None else analyse_structure(mech)
        if mech.higher_pairs:
            raise UnsupportedError(
                f"{shown(mech.path)}: the mechanism has higher pairs; their kinematics is not solved: "
                "replace each higher pair by its lower-pair equivalent in the file"
            )
        solvers = []
        for group in structure.groups:
            if not group.is_dyad:
                raise UnsupportedError(
                    f"{shown(mech.path)}: group {group.label} of links {group.name} is of class "
                    f"{group.group_class}; only class II groups (dyads) are solved. "
                    f"Structure: {structure.formula}"
                )
            assert group.kind is not None  # a dyad has a kind
            solvers.append(DYADS[group.kind](mech, group))
        return cls(mech, solvers)

    # --- one pass over the angles ----------------------------------------------------
    def crank(self, phi_rad: np.ndarray) -> Motion:
        w = self.mech.drive.signed_omega
        turn = phi_rad - self.crank_local_angle if self.crank_local_angle else phi_rad
        e = np.empty(turn.shape, dtype=complex)  # e^{i·turn}
        np.cos(turn, out=e.real)
        np.sin(turn, out=e.imag)
        if not self.O_local:  # the crank's local origin is its pivot
            return Motion(e, self.O, w, 0j, 0.0, 0j)
        r = -e * self.O_local
        return Motion(e, self.O + r, w, 1j * w * r, 0.0, -w * w * r)

    def frame(self) -> Motion:
        # placed and still: ω = ε = 0, V = a = 0 (the same values as given one by one)
        return Motion(1 + 0j, 0j)

    def place_all(self, phi_rad: np.ndarray, branches: dict[str, int]) -> dict[int, Motion]:
        return self.place(phi_rad, branches)

    def place(
        self,
        phi_rad: np.ndarray,
        branches: dict[str, int],
        upto: int | None = None,
        margins: list | None = None,
    ) -> dict[int, Motion]:
        """Positions of the first `upto` groups (all by default) with their
        branches; `margins` receives each group's `margin` before it is placed."""
        m = {FRAME: self.frame(), self.mech.drive.link: self.crank(phi_rad)}
        with quiet():
            for solver in self.solvers[:upto]:
                if margins is not None:
                    margins.append(solver.margin(m))
                solver.positions(m, branches.get(solver.name, 1))
        return m

    def sweep(self, phi1_deg: float | Iterable[float] | np.ndarray) -> Sweep:
        """Every point's position, V and a, every link's ω and ε, at the crank
        angles given (deg)."""
        if not (phi1_deg.__class__ is np.ndarray and phi1_deg.ndim == 1):
            phi1_deg = np.atleast_1d(np.asarray(phi1_deg, dtype=float))
        elif phi1_deg.dtype != np.float64:
            phi1_deg = phi1_deg.astype(np.float64)
        n = len(phi1_deg)
        if n <= CHUNK:
            m, failed, singular = self._solve(np.radians(phi1_deg))
            states = {
                lid: _state(mo, n) if lid != FRAME else _frame_state(n) for lid, mo in m.items()
            }
            return Sweep(self, _ro(phi1_deg.copy()), states, failed, singular)
        # Many angles: solve about CHUNK at a time, so the working arrays stay
        # bounded (the same memory again for every chunk), and write
        # the results into one block of memory for the whole sweep. The angles
        # are shared out evenly, in as many chunks as CHUNK goes into them
        # (rounded): a short last chunk would pay the per-chunk overhead in full.
        size = -(-n // max(1, round(n / CHUNK)))
        arena = None
        for start in range(0, n, size):
            part = slice(start, min(start + size, n))
            m, failed, singular = self._solve(np.radians(phi1_deg[part]))
            if arena is None:
                arena = _Arena(self, m, failed, n)
            arena.put(part, m, failed, singular)
            # let the chunk go before the next is solved, which then reuses its
            # memory, still in the cache
            del m, failed, singular
        assert arena is not None
        return arena.sweep(phi1_deg)

    def sweeps(self, *phi1_deg: np.ndarray) -> tuple[Sweep, ...]:
        """`sweep` at each of several sets of crank angles (deg, 1-d arrays),
        solved in one pass over all of them (the kernels work angle by angle,
        so each sweep holds the numbers its own `sweep` would) and handed out
        as a Sweep each: one pass's fixed cost instead of one for every set."""
        parts = [np.asarray(p, dtype=np.float64) for p in phi1_deg]
        sizes = [p.size for p in parts]
        total = sum(sizes)
        if total > CHUNK or any(p.ndim != 1 for p in parts):
            return tuple(self.sweep(p) for p in parts)
        m, failed, singular = self._solve(np.radians(np.concatenate(parts)))
        out = []
        start = 0
        for phi, n in zip(parts, sizes):
            part = slice(start, start + n)
            start += n
            states = {
                lid: _state_part(mo, part, n) if lid != FRAME else _frame_state(n)
                for lid, mo in m.items()
            }
            out.append(
                Sweep(
                    self,
                    _ro(phi.copy()),
                    states,
                    {g: _ro(x[part]) for g, x in failed.items()},
                    {g: _ro(x[part]) for g, x in singular.items()},
                )
            )
        return tuple(out)

    def point_motion(
        self, phi1_deg: np.ndarray, name: str
    ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """Where the chain is solved (every group assembled, its plan regular)
        and the position, velocity and acceleration of one point (complex) over
        the angles: the same kernels as `sweep`, without its records, for the
        searches over many angles that read one point (the extreme positions,
        the diagrams' grids). NaN where `ok` is False."""
        phi1_deg = _angles(phi1_deg)
        m, failed, singular = self._solve(np.radians(phi1_deg))
        bad = np.zeros(phi1_deg.shape, dtype=bool)
        for mask in (*failed.values(), *singular.values()):
            bad |= mask
        lid, p = self.locate[name]
        mo = m[lid]
        shape = phi1_deg.shape
        return ~bad, _over(mo.at(p), shape), _over(mo.vel_at(p), shape), _over(mo.acc_at(p), shape)

    def point_motion_only(
        self, phi1_deg: np.ndarray, name: str
    ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """`point_motion` without where the chain is solved: the position,
        velocity and acceleration of one point (NaN where it is not solved),
        by the same kernels, for a search that already knows its angles are
        solved (the Newton steps of the extreme positions)."""
        phi1_deg = _angles(phi1_deg)
        with quiet():
            m = self.place_all(np.radians(phi1_deg), self.branches)
            for solver in self.solvers:
                solver.motion(m, None)  # the links' motion alone (not where it is regular)
        lid, p = self.locate[name]
        mo = m[lid]
        shape = phi1_deg.shape
        return _over(mo.at(p), shape), _over(mo.vel_at(p), shape), _over(mo.acc_at(p), shape)

    def point_position(self, phi1_deg: np.ndarray, name: str) -> np.ndarray:
        """The position of one point (complex) over the angles, from the
        groups' positions alone (no plans): the same numbers as
        `point_motion`'s, for the searches that read where a point is, not how
        it moves (the displacements). NaN where a group cannot assemble."""
        phi1_deg = _angles(phi1_deg)
        m = self.place_all(np.radians(phi1_deg), self.branches)
        lid, p = self.locate[name]
        return _over(m[lid].at(p), phi1_deg.shape)

    def _solve(self, phi_rad: np.ndarray):
        """Positions, then the motion group by group (the plans, without their
        records): the links' motion, and where each group fails to assemble
        or its plan is singular."""
        with quiet():
            return self._solve_quietly(phi_rad)

    def _solve_quietly(self, phi_rad: np.ndarray):
        m = self.place_all(phi_rad, self.branches)
        failed, singular = {}, {}
        shape = phi_rad.shape
        for solver in self.solvers:
            name = solver.name
            L1, L2 = m[solver.L1], m[solver.L2]
            failed[name] = _ro(_over(_not_finite((L1.o, L2.o, L1.e, L2.e)), shape))
            # the links' motion, not the plan's records (`Sweep.plans` solves
            # them again when asked for)
            regular = solver.motion(m, SINGULAR_SIN)
            # not failed and not regular
            singular[name] = _ro(_over(np.logical_not(np.logical_or(failed[name], regular)), shape))
        return m, failed, singular

    def reason(self, solver: DyadSolver, phi1_deg: float) -> str:
        m = self.place_all(np.radians(np.array([phi1_deg])), self.branches)
        return solver.failure(m, 0, phi1_deg)
