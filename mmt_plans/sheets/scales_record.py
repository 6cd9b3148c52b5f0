"""The drawing scales each sheet chose, as a typed record other outputs read.

Sheet 1 draws the mechanism at a standard μ_l that fills its field and picks
μV, μa for its plans; sheet 2 picks a standard μ_l per drawing (the loaded
mechanism, each group, the driving link), μF per force polygon and μV of
Zhukovsky's lever. The note (note/) writes its millimetres at these scales,
so that they are the lengths on the sheets; `sheets.compose.compose`
composes the sheets once onto a RecordingBackend and keeps them with the
recorded drawings (`ComposedSheets.scales`).

    >>> import mmt_plans
    >>> from mmt_plans.sheets.compose import compose
    >>> a = mmt_plans.solve(mmt_plans.load("samples/six_link_press.toml"))
    >>> s1, s2 = compose(a, "en").scales
    >>> s1.mu_l, s2.mu_F["group 4-5"]                      # doctest: +SKIP
    (0.005, 40.0)
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from types import MappingProxyType

__all__ = ["DiagramScales", "Sheet1Scales", "Sheet2Scales"]


@dataclass(frozen=True)
class DiagramScales:
    """The S, V, a diagrams as sheet 1 draws them: the time axis L (mm) of one
    turn at μ_t (s/mm), μ_S (m/mm), the poles OH_1, OH_2 (mm) and the μ_V,
    μ_a they give. Sheet 1 may draw them larger than the calculation's
    construction (the room the sheet leaves them); the values read from them
    are the same."""

    L: float
    mu_t: float
    mu_S: float
    mu_V: float
    mu_a: float
    H1: float
    H2: float


@dataclass(frozen=True)
class Sheet1Scales:
    """Sheet 1: μ_l of the mechanism (m/mm); μV (m/s per mm) and μa (m/s² per
    mm) of the plans, by plan position; the diagrams' scales when it draws
    them."""

    mu_l: float
    mu_V: Mapping[int, float]
    mu_a: Mapping[int, float]
    diagrams: DiagramScales | None = None

    @classmethod
    def of(cls, s: Mapping[str, float], positions: Sequence[int]) -> Sheet1Scales:
        """From sheet 1's scales by name ("mu_l"; "mu_V 3", "mu_a 3" of the plans
        of position 3, or "mu_V", "mu_a" serving every position; the
        diagrams' "L", "mu_t", "mu_S", "mu_V_diagram", "mu_a_diagram", "H1",
        "H2")."""
        names = ("L", "mu_t", "mu_S", "mu_V_diagram", "mu_a_diagram", "H1", "H2")
        diagrams = (
            DiagramScales(*(float(s[k]) for k in names)) if all(k in s for k in names) else None
        )
        return cls(
            float(s["mu_l"]),
            MappingProxyType({i: float(s.get(f"mu_V {i}", s["mu_V"])) for i in positions}),
            MappingProxyType({i: float(s.get(f"mu_a {i}", s["mu_a"])) for i in positions}),
            diagrams,
        )


@dataclass(frozen=True)
class Sheet2Scales:
    """Sheet 2: μ_l of the loaded mechanism, of each group (by its name, "4-5")
    and of the driving link; μF of each force polygon drawing, by its title
    ("group 4-5", "link 1"); μV of Zhukovsky's lever."""

    mu_l: float
    mu_l_group: Mapping[str, float]
    mu_l_driving: float
    mu_F: Mapping[str, float]
    mu_V: float

    @classmethod
    def of(cls, s: Mapping[str, float], groups: Sequence[str], d: int) -> Sheet2Scales:
        """From sheet 2's scales by name ("mu_l", "mu_l 4-5", "mu_F 4-5", "mu_F 1",
        "mu_V"), the groups' names and the driving link's number."""
        force = {f"group {g}": float(s[f"mu_F {g}"]) for g in groups}
        force[f"link {d}"] = float(s[f"mu_F {d}"])
        return cls(
            mu_l=float(s["mu_l"]),
            mu_l_group=MappingProxyType({g: float(s[f"mu_l {g}"]) for g in groups}),
            mu_l_driving=float(s[f"mu_l {d}"]),
            mu_F=MappingProxyType(force),
            mu_V=float(s["mu_V"]),
        )

    @classmethod
    def further(cls, s: Mapping[str, float], groups: Sequence[str]) -> Sheet2Scales:
        """A further sheet's (sheet2_further.py): μ_l its groups share ("mu_l")
        and μF of their polygons; no driving link, no lever (NaN)."""
        return cls(
            mu_l=float(s["mu_l"]),
            mu_l_group=MappingProxyType({g: float(s[f"mu_l {g}"]) for g in groups}),
            mu_l_driving=math.nan,
            mu_F=MappingProxyType({f"group {g}": float(s[f"mu_F {g}"]) for g in groups}),
            mu_V=math.nan,
        )
