"""Source expressions of the note's numbers (see writer.py): where in the
results JSON (`J`), the Solution (`S`), its Mechanism (`M`), a plan
(`plan(i)`) or the force analysis (`F`) each printed number is read."""

from __future__ import annotations

import re
from typing import TYPE_CHECKING

if TYPE_CHECKING:  # pragma: no cover
    from ..solution import Solution


def json_points(solution: Solution) -> set[str]:
    """Names that the results JSON lists under points, v and a (results_json)."""
    mech = solution.mechanism
    cms = {lk.cm_name for lk in mech.links.values()} - set(mech.point_owners)
    return {n for n in solution.chain.locate if n not in cms}


def located(solution: Solution, name: str) -> str:
    """A name the kinematics knows: "G7", the point of link 7 under G, is where G is."""
    locate = solution.chain.locate
    if name not in locate:
        m = re.fullmatch(r"(.+?)(\d+)", name)
        if m and m.group(1) in locate:
            return m.group(1)
    return name


def point(solution: Solution, i: int, name: str, q: str) -> str:
    """V ("v"), a ("a") or the position ("points") of point `name` at position i, [x, y]."""
    k = solution.entry(i)
    if q == "points":
        name = located(solution, name)
    if name in json_points(solution):
        where = "positions" if q == "points" else "kinematics"
        return f"J[{where!r}][{k}][{q!r}][{name!r}]"
    of = {"v": "velocity_of", "a": "acceleration_of", "points": "position_of"}[q]
    return f"xy(S.sweep.{of}({name!r})[{k}])"


def rate(solution: Solution, i: int, lid: int, q: str) -> str:
    """ω ("omega") or ε ("eps") of link `lid` at position i, signed."""
    return f"J['kinematics'][{solution.entry(i)}][{q!r}]['{lid}']"


def diff(a: str, b: str) -> str:
    return f"dist({a}, {b})"
