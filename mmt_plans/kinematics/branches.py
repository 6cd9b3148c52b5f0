"""Assembly branches: which of its two closed-form solutions each group takes.

A dyad of kind RRR, RRP or RPR closes in two ways (B left or right of A→C,
the far or the near intersection with the guide, the slot turned by +arcsin
or −arcsin); its branch is a sign kept for the whole turn. A combination of
signs, one per group, assembles over the whole turn when every group's
margin (`DyadSolver.margin`: positive where it closes, zero at a toggle) stays
non-negative at every crank angle.

The search (SPEC_FORMAT, "Assembly branch"): depth first over the groups in
the order they are solved, +1 before −1, a branch pruned as soon as its group
fails at some angle of a 720-angle grid or at a local minimum of its margin
refined between the grid angles (so that a toggle passed between two grid
angles is not missed). Every combination that assembles over the whole turn
is found; one is chosen by

- the sketch, when the file gives one (least squares at the sketch's crank
  angle, group by group);
- otherwise, when the file's link coordinates are drawn in place (every
  pivot written with the frame's coordinates), the combination whose points
  at the crank angle of the drawing lie nearest to those coordinates;
- otherwise the first in branch order (+1 before −1, group by group).

When no combination turns fully, the one that assembles over the most of the
turn is kept (the sketched one, when there is a sketch), with its crank-angle
ranges; the caller refuses it or, when the file opts in, analyses one range.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Literal

import numpy as np

from ..model import FRAME, Mechanism
from ..structure import Structure
from .chain import Chain
from .dyads import Motion
from .geometry import quiet

GRID = 720
# a margin this far below zero (relative to the mechanism's size) is rounding
# at a toggle, not a failure to assemble
TOLERANCE = 1e-11
EDGE_DEG = 1e-10  # crank angles of the ends of an assembly range, to this

# the search's crank angles (rad), the same for every mechanism (read-only)
_GRID = np.linspace(0.0, 2 * np.pi, GRID, endpoint=False)
_GRID.setflags(write=False)

Rule = Literal["sketch", "as drawn", "branch order", "only one", "no branches"]
Signs = tuple[int, ...]


@dataclass(frozen=True)
class Branches:
    """The branch of every group and how it was chosen."""

    signs: Mapping[str, int]  # group name -> +1 / -1 (+1 for a group without branches)
    rule: Rule
    full_turn: tuple[Mapping[str, int], ...]  # every combination that turns fully
    ranges: tuple[tuple[float, float], ...]  # where the chosen combination assembles (deg, ccw)
    meanings: Mapping[str, str] = field(default_factory=dict)  # group -> what its sign means
    failing_group: str | None = None  # the group that stops a partial turn
    failing_reason: str = ""  # why, at an angle where it fails
    cure: str = ""  # what to change
    sketch_turns: bool | None = None  # with a sketch: does the sketched combination turn?

    @property
    def whole_turn(self) -> bool:
        return self.ranges == ((0.0, 360.0),)

    @property
    def note(self) -> str:
        """One line for the text output."""
        groups = "; ".join(
            f"group {g}: {s:+d} ({self.meanings.get(g, '')})"
            for g, s in self.signs.items()
            if g in self.meanings
        )
        count = len(self.full_turn)
        rule = {
            "sketch": "nearest to the sketch",
            "as drawn": "nearest to the file's coordinates as drawn",
            "branch order": "the first in branch order (+1 before -1, group by group)",
            "only one": "the only one",
            "no branches": "no group has branches",
        }[self.rule]
        turns = (
            f"{count} combination{'s' if count != 1 else ''} of branches assemble"
            f"{'s' if count == 1 else ''} over the whole turn"
        )
        out = f"{groups + '; ' if groups else ''}chosen: {rule}; {turns}"
        if self.rule == "sketch" and self.sketch_turns is False:
            out += "; the sketched combination does not turn fully"
        return out

    def to_json(self) -> dict:
        return {
            "groups": dict(self.signs),
            "meaning": dict(self.meanings),
            "rule": self.rule,
            "full_turn_combinations": len(self.full_turn),
            "full_turn": [dict(c) for c in self.full_turn],
            "whole_turn": self.whole_turn,
            "assembly_ranges_deg": [list(r) for r in self.ranges],
            "note": self.note,
        }


def choose(chain: Chain) -> Branches:
    """Search the combinations of branches and choose one (module docstring)."""
    # NaN is the search's data (a group that fails): one quiet context for
    # all of it (its kernels' own are then a counter, not numpy's machinery)
    with quiet():
        return _choose(chain)


def _choose(chain: Chain) -> Branches:
    search = _Search(chain)
    names = [s.group.name for s in chain.solvers]
    branchy = [s.group.name for s in chain.solvers if s.has_branches]
    full = search.full_turn()
    sketched = search.by_sketch()
    if sketched is not None:
        signs, rule = sketched, "sketch"
        turns = signs in full
    elif not branchy:
        signs, rule, turns = full[0] if full else (1,) * len(names), "no branches", bool(full)
    elif len(full) == 1:
        signs, rule, turns = full[0], "only one", True
    elif full and search.drawn_in_place():
        signs, rule, turns = search.nearest_drawing(full), "as drawn", True
    elif full:
        signs, rule, turns = full[0], "branch order", True
    else:
        signs, rule, turns = search.most_assembled(), "branch order", False
    ranges = ((0.0, 360.0),) if turns else search.ranges(signs)
    failing, reason, cure = (None, "", "") if turns else search.failure(signs)
    meanings = {
        s.group.name: s.branch_meaning(sign)
        for s, sign in zip(chain.solvers, signs)
        if s.has_branches
    }
    return Branches(
        signs=dict(zip(names, signs)),
        rule=rule,  # type: ignore[arg-type]
        full_turn=tuple(dict(zip(names, c)) for c in full),
        ranges=ranges,
        meanings=meanings,
        failing_group=failing,
        failing_reason=reason,
        cure=cure,
        sketch_turns=turns if rule == "sketch" else None,
    )


class _Search:
    def __init__(self, chain: Chain) -> None:
        self.chain = chain
        self.solvers = chain.solvers
        self.names = [s.group.name for s in chain.solvers]
        self.grid = _GRID
        mech = chain.mech
        # the distance of every point from the origin, in one pass
        points = [p for link in mech.links.values() for p in link.points.values()]
        points += list(mech.frame.values())
        xy = np.concatenate(points).astype(float, copy=False).reshape(-1, 2)
        sizes = np.hypot(xy[:, 0], xy[:, 1]).tolist()
        self.tol = TOLERANCE * max(sizes + [1e-3])
        # the links placed on the grid and the groups' margins there, by the
        # branches of the first groups: a trial of group k starts from the
        # placing of the groups before it (the same for both its branches),
        # and a group is placed only when a group after it is tried
        self._on_grid: dict[Signs, tuple[dict, list]] = {}
        self._grid_margins: dict[Signs, np.ndarray] = {}
        # the links placed at one crank angle (the sketch's, the drawing's), by
        # the angle and the branches of the first groups
        self._at_angle: dict[tuple[float, Signs], dict] = {}
        # whether group len(before) turns fully after the groups `before` (`group_turns`)
        self._turns: dict[Signs, bool] = {}
        # The sketch's and the drawing's crank angle ride along with the grid:
        # every placing on the grid places the links there too (the kernels
        # work angle by angle), and a trial of the choice reads them off it.
        extra = [a for a in (self._sketch_angle(), self._drawing_angle()) if a is not None]
        self._ext = np.concatenate((_GRID, extra)) if extra else _GRID
        self._extra_at = {a: GRID + i for i, a in enumerate(extra)}

    def _sketch_angle(self) -> float | None:
        """The crank angle (rad) of the sketch (None without a sketch of the crank pin)."""
        mech = self.chain.mech
        if mech.crank_pin not in mech.sketch:
            return None
        A = complex(*mech.sketch[mech.crank_pin])
        O = self.chain.O
        return math.atan2((A - O).imag, (A - O).real)

    def _drawing_angle(self) -> float:
        """The crank angle (rad) at which the links' coordinates draw the crank."""
        mech = self.chain.mech
        crank = mech.links[mech.drive.link]
        # through Python floats: the same subtractions as the arrays'
        (ax, ay), (ox, oy) = (crank.points[p].tolist() for p in (mech.crank_pin, mech.crank_pivot))
        return math.atan2(ay - oy, ax - ox)

    def _grid_placed(self, signs: Signs) -> tuple[dict, list]:
        """The links' motion after the first len(signs) groups are placed on
        the grid with `signs`, and each group's margin before it was placed
        (what `Chain.place` gives, by the same operations)."""
        found = self._on_grid.get(signs)
        if found is None:
            chain = self.chain
            if not signs:
                m = {FRAME: chain.frame(), chain.mech.drive.link: chain.crank(self._ext)}
                found = (m, [])
            else:
                before, margins = self._grid_placed(signs[:-1])
                margin = self._grid_margin(signs[:-1])
                m = dict(before)  # a group adds its own links, changing none before it
                with quiet():
                    self.solvers[len(signs) - 1].positions(m, signs[-1])
                found = (m, [*margins, margin])
            self._on_grid[signs] = found
        return found

    def _grid_margin(self, before: Signs) -> np.ndarray:
        """The margin on the grid of group len(before), the groups before it
        placed with the branches `before` (the same for both its own)."""
        found = self._grid_margins.get(before)
        if found is None:
            m, _ = self._grid_placed(before)
            with quiet():
                found = self.solvers[len(before)].margin(m)
            if found.__class__ is np.ndarray and found.ndim and self._ext is not _GRID:
                found = found[:GRID]  # the grid's, without the angles riding along
            self._grid_margins[before] = found
        return found

    def _placed_at(self, phi: np.ndarray, signs: Signs) -> dict:
        """The links' motion at the one crank angle `phi` (rad, an array of one)
        after the first len(signs) groups are placed with `signs` (what
        `Chain.place` gives, by the same operations), kept by the branches of
        the first groups: a trial of group k places that group alone."""
        key = (float(phi[0]), signs)
        found = self._at_angle.get(key)
        if found is None:
            at = self._extra_at.get(key[0])
            if at is not None and signs in self._on_grid:
                # placed on the grid already, this angle with it: where each
                # link is (a group's positions and a point's place read its
                # pose alone, e and o)
                part = slice(at, at + 1)
                found = {lid: _pose_part(mo, part) for lid, mo in self._on_grid[signs][0].items()}
            elif not signs:
                chain = self.chain
                found = {FRAME: chain.frame(), chain.mech.drive.link: chain.crank(phi)}
            else:
                found = dict(self._placed_at(phi, signs[:-1]))
                with quiet():
                    self.solvers[len(signs) - 1].positions(found, signs[-1])
            self._at_angle[key] = found
        return found

    # --- margins -------------------------------------------------------------------
    def margins(self, phi: np.ndarray, signs: Signs) -> list[np.ndarray]:
        """Each group's margin at the angles `phi` (rad) with the branches `signs`
        (the first len(signs) groups), NaN where an earlier group failed."""
        margins: list[np.ndarray] = []
        signs = tuple(signs)
        if not signs:
            return margins
        if phi is self.grid:
            margins = [*self._grid_placed(signs[:-1])[1], self._grid_margin(signs[:-1])]
        else:
            # the groups before the last placed, then the last one's margin (its
            # own placing is not read)
            k = len(signs) - 1
            m = self.chain.place(phi, dict(zip(self.names, signs)), upto=k, margins=margins)
            with quiet():
                margins.append(self.solvers[k].margin(m))
        return [_spread_over(g, phi.shape) for g in margins]

    def _refined_minima(
        self, k: int, signs: Signs, grid_margin: np.ndarray
    ) -> tuple[np.ndarray, np.ndarray]:
        """The angles (rad) and margins of group k's local minima between grid
        angles, found by golden-section search on each bracket [φ_i−1, φ_i+1]."""
        g = grid_margin
        # finite everywhere (NaN and ±inf carry into the least or the greatest)
        # and not flat
        lowest, highest = float(g.min()), float(g.max())
        if not (math.isfinite(lowest) and math.isfinite(highest)) or highest - lowest <= self.tol:
            return np.empty(0), np.empty(0)
        # the neighbours round the turn (np.roll's values, without its overhead)
        prev, nxt = np.concatenate((g[-1:], g[:-1])), np.concatenate((g[1:], g[:1]))
        # A smooth margin dips below its lowest grid value by about a quarter
        # of its second difference there: only minima that could reach zero
        # are refined.
        dip = np.abs(prev - 2 * g + nxt)
        if lowest > 2.0 * float(dip.max()) + self.tol:
            # no grid angle is within twice its dip of zero (g >= lowest there):
            # the test below would pick none
            return np.empty(0), np.empty(0)
        idx = np.flatnonzero(
            (g <= prev) & (g <= nxt) & ((g < prev) | (g < nxt)) & (g <= 2.0 * dip + self.tol)
        )
        if not idx.size:
            return np.empty(0), np.empty(0)
        step = self.grid[1] - self.grid[0]
        a, b = self.grid[idx] - step, self.grid[idx] + step
        r = (math.sqrt(5.0) - 1.0) / 2.0
        c, d = b - r * (b - a), a + r * (b - a)
        fc, fd = self.margins(c, signs)[k], self.margins(d, signs)[k]
        for _ in range(48):  # the bracket shrinks to 0.618^48 of 1° (1e-10°)
            if np.any(np.minimum(fc, fd) < -self.tol):
                break  # it fails: how far below zero does not matter
            left = ~(fc > fd)  # NaN (fails) at c counts as the lower value
            b = np.where(left, d, b)
            a = np.where(left, a, c)
            c, d = b - r * (b - a), a + r * (b - a)
            fc, fd = self.margins(c, signs)[k], self.margins(d, signs)[k]
        best = np.where(np.isnan(fc) | (fc <= fd), c, d)
        return best, self.margins(best, signs)[k]

    def group_turns(self, k: int, signs: Signs) -> bool:
        # Group k's margin is the groups' before it placed (its own branch
        # is not read): both its branches have one answer, worked out once.
        before = tuple(signs[:k])
        found = self._turns.get(before)
        if found is None:
            found = self._turns[before] = self._group_turns(k, signs)
        return found

    def _group_turns(self, k: int, signs: Signs) -> bool:
        # margins(self.grid, signs)[k], read straight from the grid's
        g = _spread_over(self._grid_margin(tuple(signs[:k])), self.grid.shape)
        if not g.min() >= -self.tol:  # NaN fails as well (the least is NaN)
            return False
        _, m = self._refined_minima(k, signs, g)
        return not m.size or bool(np.all(m >= -self.tol))

    # --- the search ----------------------------------------------------------------
    def full_turn(self) -> list[Signs]:
        found: list[Signs] = []

        def deeper(signs: Signs) -> None:
            k = len(signs)
            if k == len(self.solvers):
                found.append(signs)
                return
            for sign in (1, -1) if self.solvers[k].has_branches else (1,):
                trial = signs + (sign,)
                if self.group_turns(k, trial):
                    deeper(trial)

        deeper(())
        return found

    def all_combinations(self) -> list[Signs]:
        options = [(1, -1) if s.has_branches else (1,) for s in self.solvers]
        return list(itertools.product(*options))

    def most_assembled(self) -> Signs:
        """The combination that assembles at the most grid angles (the first on a tie)."""
        best: tuple[int, Signs] | None = None
        for signs in self.all_combinations():
            count = int(np.sum(self.ok(self.grid, signs)))
            if best is None or count > best[0]:
                best = (count, signs)
        assert best is not None
        return best[1]

    def ok(self, phi: np.ndarray, signs: Signs) -> np.ndarray:
        ok = np.ones(phi.shape, dtype=bool)
        for g in self.margins(phi, signs):
            ok &= g >= -self.tol
        return ok

    # --- choosing --------------------------------------------------------------------
    def by_sketch(self) -> Signs | None:
        """Group by group, the branch nearest to the sketch at its crank angle
        (None without a sketch of the crank pin)."""
        mech = self.chain.mech
        angle = self._sketch_angle()
        if angle is None:
            return None
        phi = np.array([angle])
        signs: Signs = ()
        for solver in self.solvers:
            names = [
                p
                for lid in (solver.L1, solver.L2)
                for p in mech.links[lid].points
                if p in mech.sketch
            ]
            choice = 1
            if solver.has_branches and names:
                best = None
                for sign in (1, -1):
                    err = self._distance(phi, signs + (sign,), names, mech.sketch)
                    if math.isfinite(err) and (best is None or err < best[0]):
                        best = (err, sign)
                choice = 1 if best is None else best[1]
            signs += (choice,)
        return signs

    def _distance(
        self, phi: np.ndarray, signs: Signs, names: list[str], target: Mapping[str, np.ndarray]
    ) -> float:
        m = self._placed_at(phi, signs)
        err = 0.0
        for p in names:
            lid, local = self.chain.locate[p]
            if lid not in m:
                continue
            at = m[lid].at(local)
            at = at[0] if at.__class__ is np.ndarray and at.shape == (1,) else np.ravel(at)[0]
            err += abs(complex(at) - complex(*target[p])) ** 2
        return err

    def drawn_in_place(self) -> bool:
        """Every point is written with the same coordinates in every link that
        has it and in [frame]: the links are drawn as they stand in one
        position, and their coordinates are a drawing of the mechanism."""
        mech = self.chain.mech
        seen: dict[str, np.ndarray] = dict(mech.frame)
        shared = 0
        for link in mech.links.values():
            for p, xy in link.points.items():
                if p in seen:
                    shared += 1
                    if float(np.hypot(*(xy - seen[p]))) > 1e-9:
                        return False
                else:
                    seen[p] = xy
        return shared > 0

    def nearest_drawing(self, candidates: list[Signs]) -> Signs:
        """The combination whose points, at the crank angle of the drawing, lie
        nearest (least squares) to the links' own coordinates."""
        mech = self.chain.mech
        phi = np.array([self._drawing_angle()])
        drawn = {
            p: xy
            for link in mech.links.values()
            for p, xy in link.points.items()
            if self.chain.locate[p][0] != FRAME
        }
        names = sorted(drawn)
        scored = [(self._distance(phi, c, names, drawn), i, c) for i, c in enumerate(candidates)]
        scale = min(s for s, _, _ in scored) if scored else 0.0
        # equal within rounding: the branch order decides
        return min(
            scored,
            key=lambda t: (
                round(t[0] / max(scale, 1e-300), 9) if math.isfinite(t[0]) else math.inf,
                t[1],
            ),
        )[2]

    # --- a partial turn --------------------------------------------------------------
    def ranges(self, signs: Signs) -> tuple[tuple[float, float], ...]:
        """Crank-angle intervals (deg, counter-clockwise from start to end) where
        every group assembles with `signs`, ends to EDGE_DEG by bisection."""
        margins = self.margins(self.grid, signs)
        phi = list(self.grid)
        ok = list(self.ok(self.grid, signs))
        for k, g in enumerate(margins):  # failures hidden between grid angles
            at, m = self._refined_minima(k, signs, np.where(np.isfinite(g), g, np.inf))
            for x, v in zip(at, m):
                if not v >= -self.tol:
                    phi.append(float(x) % (2 * np.pi))
                    ok.append(False)
        order = np.argsort(phi, kind="stable")
        phi_s = np.degrees(np.asarray(phi)[order])
        ok_s = np.asarray(ok)[order]
        if ok_s.all():
            return ((0.0, 360.0),)
        if not ok_s.any():
            return ()
        n = len(phi_s)
        out = []
        for i in range(n):
            if ok_s[i] and not ok_s[i - 1]:
                j = i
                while ok_s[(j + 1) % n]:
                    j += 1
                start = self._edge(phi_s[i - 1] - (360.0 if i == 0 else 0.0), phi_s[i], signs)
                jj = j % n
                after = phi_s[(jj + 1) % n] + (360.0 if jj + 1 >= n else 0.0)
                end = self._edge(after, phi_s[jj], signs)
                out.append((float(start % 360.0), float(end % 360.0)))
        return tuple(out)

    def _edge(self, bad: float, good: float, signs: Signs) -> float:
        for _ in range(80):
            if abs(good - bad) < EDGE_DEG:
                break
            mid = 0.5 * (bad + good)
            if self.ok(np.radians(np.array([mid])), signs)[0]:
                good = mid
            else:
                bad = mid
        return good

    def failure(self, signs: Signs) -> tuple[str, str, str]:
        """The first group that fails somewhere on the grid, why, and the cure."""
        margins = self.margins(self.grid, signs)
        for k, g in enumerate(margins):
            bad = ~(g >= -self.tol)
            prior_ok = np.ones(bad.shape, dtype=bool)
            for h in margins[:k]:
                prior_ok &= h >= -self.tol
            bad &= prior_ok
            if bad.any():
                solver = self.solvers[k]
                m = self.chain.place(self.grid, dict(zip(self.names, signs)), upto=k)
                i = int(np.flatnonzero(bad)[0])
                phi = float(np.degrees(self.grid[i]))
                return solver.group.name, solver.failure(m, i, phi), solver.cure(m, bad)
        # only between grid angles: name the group whose refined minimum fails
        for k in range(len(self.solvers)):
            _, m_min = self._refined_minima(k, signs, margins[k])
            if np.any(m_min < -self.tol):
                solver = self.solvers[k]
                return (
                    solver.group.name,
                    "it reaches a limit position between grid angles",
                    "change the lengths of the group's links",
                )
        return "", "", ""


def _pose_part(mo: Motion, part: slice) -> Motion:
    """Where a link is at the angles `part` of a pass (its e and o cut,
    plain numbers as they are), placed: what `motion_part` gives of its pose."""
    e, o = mo.e, mo.o
    return Motion(
        e[part] if e.__class__ is np.ndarray and e.ndim else e,
        o[part] if o.__class__ is np.ndarray and o.ndim else o,
    )


def _spread_over(g, shape: tuple[int, ...]) -> np.ndarray:
    """A margin as a float array over the angles: as it is when it already is
    one (not written to), a number (a group fixed to the frame) spread out."""
    if g.__class__ is np.ndarray and g.shape == shape and g.dtype == np.float64:
        return g
    return np.broadcast_to(np.asarray(g, dtype=float), shape)


def build_chain(mech: Mechanism, structure: Structure | None = None) -> Chain:
    """The kinematic chain of `mech` on the assembly branches chosen here."""
    chain = Chain.build(mech, structure)
    chain.choice = choose(chain)
    chain.branches = dict(chain.choice.signs)
    return chain


def turns_fully(chain: Chain, signs: Mapping[str, int]) -> bool:
    """Whether `chain` assembles over the whole turn with the branch `signs`
    (group name -> sign), by the search's own test."""
    search = _Search(chain)
    order = tuple(signs[s.group.name] for s in chain.solvers)
    return all(search.group_turns(k, order[: k + 1]) for k in range(len(order)))
