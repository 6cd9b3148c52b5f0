"""Structural analysis: Chebyshev's formula and the Assur decomposition.

Seed 003 §1.1 and seed 004: W = 3n - 2p5 - p4 (1); the mechanism is taken
apart from the group farthest from the driving link, each group leaving W
unchanged, until the initial mechanism I(0,1) remains.
"""

from __future__ import annotations

from collections import deque
from dataclasses import dataclass
from itertools import combinations
from typing import Literal

from .errors import StructureError, shown
from .model import FRAME, Mechanism, Pair, Prismatic

DyadKind = Literal["RRR", "RRP", "RPR", "PRP", "RPP"]
DYAD_KINDS: tuple[str, ...] = ("RRR", "RRP", "RPR", "PRP", "RPP")
ROMAN = {1: "I", 2: "II", 3: "III", 4: "IV", 5: "V"}


@dataclass(frozen=True)
class AssurGroup:
    """A structural group of zero mobility attached to the links before it.

    For a dyad (class II) `pairs` is ordered outer–inner–outer and `links`
    as (L1, L2): L1 carries the first outer pair, L2 the last, so that `kind`
    reads as one of the five types RRR, RRP, RPR, PRP, RPP.
    """

    links: tuple[int, ...]
    pairs: tuple[Pair, ...]
    group_class: int
    order: int
    kind: str | None

    @property
    def label(self) -> str:
        return f"{ROMAN.get(self.group_class, str(self.group_class))}({','.join(map(str, sorted(self.links)))})"

    @property
    def name(self) -> str:
        return "-".join(map(str, sorted(self.links)))

    @property
    def is_dyad(self) -> bool:
        return self.group_class == 2


@dataclass(frozen=True)
class Structure:
    n: int
    p5: int
    p4: int
    W: int
    driver: int
    groups: tuple[AssurGroup, ...]  # in the order they are attached
    mechanism_class: int

    @property
    def formula(self) -> str:
        return " <- ".join([f"I(0,{self.driver})"] + [g.label for g in self.groups])

    def as_dict(self) -> dict:
        return {
            "n": self.n,
            "p5": self.p5,
            "p4": self.p4,
            "W": self.W,
            "groups": [
                {
                    "links": sorted(g.links),
                    "pairs": [p.name for p in g.pairs],
                    "class": g.group_class,
                    "order": g.order,
                    "kind": g.kind,
                }
                for g in self.groups
            ],
            "mechanism_class": self.mechanism_class,
            "formula": self.formula,
        }


def analyse_structure(mech: Mechanism) -> Structure:
    pairs = mech.pairs
    n = len(mech.links)
    p5 = len(pairs)
    p4 = len(mech.higher_pairs)
    W = 3 * n - 2 * p5 - p4
    driver = mech.drive.link
    distance = _distances_from(driver, mech)

    remaining = set(mech.links) - {driver}
    removed: list[AssurGroup] = []
    higher = list(mech.higher_pairs)
    while remaining:
        group = _farthest_group(remaining, driver, pairs, higher, distance)
        if group is None:
            raise StructureError(
                f"{shown(mech.path)}: links {sorted(remaining)} do not split into Assur groups "
                f"(W = {W}); check the pairs of these links"
            )
        removed.append(group)
        remaining -= set(group.links)
    groups = tuple(reversed(removed))
    _check_driven(groups, driver, mech.path)
    mclass = max([1] + [g.group_class for g in groups])
    return Structure(n=n, p5=p5, p4=p4, W=W, driver=driver, groups=groups, mechanism_class=mclass)


def _check_driven(groups: tuple[AssurGroup, ...], driver: int, path: str) -> None:
    """Every group, in the order of attachment, must hold by a pair to a link
    that moves (the driving link or a group before it): a group whose outer
    pairs all join the frame is a rigid truss, not a structural group of the
    mechanism (the decomposition would hang it on some other group)."""
    moving = {driver}
    for g in groups:
        outer = [p for p in g.pairs if not set(p.links) <= set(g.links)]
        joined = {other for p in outer for other in p.links if other not in g.links}
        if not joined & moving:
            where = ", ".join(p.name for p in outer)
            raise StructureError(
                f"{shown(path)}: group {g.label} (links {', '.join(map(str, g.links))}) has all its outer "
                f"pairs ({where}) on the frame and no pair to a moving link: it cannot move "
                f"(a rigid truss)\n  fix: join one of its outer pairs to a moving link, "
                f"or remove the links {', '.join(map(str, g.links))}"
            )
        moving |= set(g.links)


def _distances_from(driver: int, mech: Mechanism) -> dict[int, int]:
    """Steps from the driving link through the moving links (the frame is no shortcut)."""
    neighbours: dict[int, set[int]] = {lid: set() for lid in mech.links}
    for pair in mech.pairs:
        a, b = pair.links
        if FRAME not in (a, b):
            neighbours[a].add(b)
            neighbours[b].add(a)
    dist = {driver: 0}
    queue = deque([driver])
    while queue:
        cur = queue.popleft()
        for nxt in neighbours[cur]:
            if nxt not in dist:
                dist[nxt] = dist[cur] + 1
                queue.append(nxt)
    return dist


def _farthest_group(
    remaining: set[int],
    driver: int,
    pairs: tuple[Pair, ...],
    higher: list[tuple[int, int]],
    distance: dict[int, int],
) -> AssurGroup | None:
    present = remaining | {driver, FRAME}
    live = [p for p in pairs if set(p.links) <= present]
    live_higher = [h for h in higher if set(h) <= present]
    # each pair's links as a set, made once for every combination tried
    live_sets = [(p, frozenset(p.links)) for p in live]
    for size in (2, 4, 6):
        found = []
        for links in combinations(sorted(remaining), size):
            group = _as_group(set(links), live_sets, live_higher)
            if group is not None:
                far = max(distance.get(lid, 10**6) for lid in links)
                found.append((far, max(links), group))
        if found:
            return max(found, key=lambda f: (f[0], f[1]))[2]
    return None


def _as_group(
    links: set[int],
    live_sets: list[tuple[Pair, frozenset[int]]],
    live_higher: list[tuple[int, int]],
) -> AssurGroup | None:
    """The Assur group of `links`, if they make one with the pairs left
    (`live_sets`: each pair with its links as a set) and the higher pairs."""
    touching_sets = [(p, ps) for p, ps in live_sets if ps & links]
    touching = [p for p, _ in touching_sets]
    touching_higher = [h for h in live_higher if set(h) & links]
    if 3 * len(links) - 2 * len(touching) - len(touching_higher) != 0:
        return None
    inner = [p for p, ps in touching_sets if ps <= links]
    outer = [p for p, ps in touching_sets if not ps <= links]
    if not outer:
        return None
    # every link of a group keeps at least two pairs, and the group is connected
    for lid in links:
        if sum(lid in p.links for p in touching) + sum(lid in h for h in touching_higher) < 2:
            return None
    if not _connected(links, inner):
        return None
    if len(links) == 2:
        return _dyad(links, inner, outer, touching_higher)
    four_contour = len(links) == 4 and len(inner) == 4
    return AssurGroup(
        links=tuple(sorted(links)),
        pairs=tuple(inner + outer),
        group_class=4 if four_contour else 3,
        order=len(outer) + len(touching_higher),
        kind=None,
    )


def _connected(links: set[int], inner: list[Pair]) -> bool:
    start = next(iter(links))
    seen = {start}
    stack = [start]
    while stack:
        cur = stack.pop()
        for p in inner:
            if cur in p.links:
                other = p.links[1] if p.links[0] == cur else p.links[0]
                if other not in seen:
                    seen.add(other)
                    stack.append(other)
    return seen == links


def _dyad(links: set[int], inner: list[Pair], outer: list[Pair], higher: list) -> AssurGroup | None:
    if higher or len(inner) != 1 or len(outer) != 2:
        return None
    a, b = sorted(links)
    outer_a = [p for p in outer if a in p.links]
    outer_b = [p for p in outer if b in p.links]
    if len(outer_a) != 1 or len(outer_b) != 1:
        return None
    kind = outer_a[0].kind + inner[0].kind + outer_b[0].kind
    order = (a, b)
    pairs = (outer_a[0], inner[0], outer_b[0])
    if kind not in DYAD_KINDS:
        kind = kind[::-1]
        order = (b, a)
        pairs = pairs[::-1]
    if kind not in DYAD_KINDS:  # PPP has no definite position
        return None
    return AssurGroup(links=order, pairs=pairs, group_class=2, order=2, kind=kind)


def other_link(pair: Pair, link: int) -> int:
    a, b = pair.links
    return b if a == link else a


def is_prismatic(pair: Pair) -> bool:
    return isinstance(pair, Prismatic)
