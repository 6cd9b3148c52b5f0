"""The drawing scales each sheet chose, as a typed record other outputs read.

Sheet 1 draws the mechanism at a standard μ_l that fills its field and picks
μV, μa for its plans; sheet 2 picks a standard μ_l per drawing (the loaded
mechanism, each group, the driving link), μF per force polygon and μV of
Zhukovsky's lever. The note (note/) writes its millimetres at these scales,
so that they are the lengths on the sheets; `sheet_scales` composes the
sheets once onto a RecordingBackend to learn them.

    >>> import mmt_plans
    >>> from mmt_plans.sheets.scales_record import sheet_scales
    >>> a = mmt_plans.solve(mmt_plans.load("samples/six_link_press.toml"))
    >>> s1, s2 = sheet_scales(a, "en")
    >>> s1.mu_l, s2.mu_F["group 4-5"]                      # doctest: +SKIP
    (0.005, 40.0)
"""

from __future__ import annotations

import weakref
from collections.abc import Mapping
from dataclasses import dataclass
from types import MappingProxyType
from typing import TYPE_CHECKING

from ..drawing.page import Page
from ..errors import MmtError
from ..i18n import Language
from ..render.recording import RecordingBackend

if TYPE_CHECKING:  # pragma: no cover
    from ..solution import Solution
    from .sheet1 import Sheet1
    from .sheet2 import Sheet2

__all__ = ["Sheet1Scales", "Sheet2Scales", "sheet_scales"]


@dataclass(frozen=True)
class Sheet1Scales:
    """Sheet 1: μ_l of the mechanism (m/mm); μV (m/s per mm) and μa (m/s² per
    mm) of the plans, by plan position."""

    mu_l: float
    mu_V: Mapping[int, float]
    mu_a: Mapping[int, float]

    @classmethod
    def of(cls, sheet: Sheet1, positions: tuple[int, ...]) -> Sheet1Scales:
        s = sheet.scales
        return cls(
            float(s["mu_l"]),
            MappingProxyType({i: float(s["mu_V"]) for i in positions}),
            MappingProxyType({i: float(s["mu_a"]) for i in positions}),
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
    def of(cls, sheet: Sheet2) -> Sheet2Scales:
        s, fa = sheet.scales, sheet.forces
        d = fa.driving_link.link
        force = {f"group {g.name}": float(s[f"mu_F {g.name}"]) for g in fa.groups}
        force[f"link {d}"] = float(s[f"mu_F {d}"])
        return cls(
            mu_l=float(s["mu_l"]),
            mu_l_group=MappingProxyType({g.name: float(s[f"mu_l {g.name}"]) for g in fa.groups}),
            mu_l_driving=float(s[f"mu_l {d}"]),
            mu_F=MappingProxyType(force),
            mu_V=float(s["mu_V"]),
        )


_Record = tuple[Sheet1Scales | None, Sheet2Scales | None]
# id of a live Solution → its records by language (a Solution is not hashable:
# kept by id, dropped when the Solution goes)
_CACHE: dict[int, dict[str, _Record]] = {}


def _cached(solution: Solution) -> dict[str, _Record]:
    key = id(solution)
    if key not in _CACHE:
        _CACHE[key] = {}
        weakref.finalize(solution, _CACHE.pop, key, None)
    return _CACHE[key]


def sheet_scales(solution: Solution, lang: Language = "en") -> _Record:
    """The scales sheets 1 and 2 of `solution` draw at in `lang` (composed once
    on a RecordingBackend, kept per Solution); None for a sheet that cannot be
    composed (no plans, no force analysis, a layout that does not fit)."""
    by_lang = _cached(solution)
    if lang not in by_lang:
        from .sheet1 import compose_sheet1
        from .sheet2 import compose_sheet2

        page = Page.of("A1")
        first: Sheet1Scales | None = None
        second: Sheet2Scales | None = None
        try:
            s1 = compose_sheet1(solution, RecordingBackend(page.width, page.height), lang)
            first = s1.record
        except MmtError:
            first = None
        if solution.forces is not None:
            try:
                s2 = compose_sheet2(solution, RecordingBackend(page.width, page.height), lang)
                second = s2.record
            except MmtError:
                second = None
        by_lang[lang] = (first, second)
    return by_lang[lang]
