"""The scales of the sheets' drawings, with their sources, for the note's millimetres.

A segment, a side or an arm the note gives in mm is the one drawn on the
sheet: value/μ with μ the sheet's (sheets/scales_record.py, read from the
sheets composed once: sheets.compose.compose). Each scale comes
with its source expression (writer.py): `sheet1.mu_l`, `sheet1.mu_V[2]`,
`sheet2.mu_F['group 4-5']` ..., the record a reader gets by composing the
sheets. Where a sheet cannot be composed, the calculation's scale stands in
(the Solution's μ_l, the textbook's μV, μa, μF), with its own source."""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from ..scales import ACCELERATION_PLAN, FORCE_PLAN, VELOCITY_PLAN, scale_for
from . import sources as src

if TYPE_CHECKING:  # pragma: no cover
    from ..forces import ForcePolygon
    from ..sheets.compose import ComposedSheets
    from ..sheets.scales_record import DiagramScales
    from ..solution import Solution

__all__ = ["Drawn"]

Scale = tuple[float, str]


class Drawn:
    """μ of every drawing of sheets 1 and 2, each with its source."""

    def __init__(self, solution: Solution, composed: ComposedSheets) -> None:
        self.solution = solution
        self.composed = composed
        self.first, self.second = composed.scales

    # sheet 1 ----------------------------------------------------------------------------
    def mechanism(self) -> Scale:
        if self.first is None:
            return float(self.solution.mu_l), "S.mu_l"
        return self.first.mu_l, "sheet1.mu_l"

    def velocity(self, i: int) -> Scale:
        if self.first is not None and i in self.first.mu_V:
            return self.first.mu_V[i], f"sheet1.mu_V[{i}]"
        return self._textbook(i, "v")

    def acceleration(self, i: int) -> Scale:
        if self.first is not None and i in self.first.mu_a:
            return self.first.mu_a[i], f"sheet1.mu_a[{i}]"
        return self._textbook(i, "a")

    def _textbook(self, i: int, q: str) -> Scale:
        """μV (seed 003 (5)) or μa ((9)) from the crank pin's V_A or a_A at position i."""
        a = self.solution
        pin = a.mechanism.crank_pin
        view = a.plan(i)
        images = view.velocity_images if q == "v" else view.acceleration_images
        x = float(np.hypot(*images[pin]))
        guide, name = (
            (VELOCITY_PLAN, "VELOCITY_PLAN")
            if q == "v"
            else (
                ACCELERATION_PLAN,
                "ACCELERATION_PLAN",
            )
        )
        if x <= 0:
            return 1.0, "1.0"
        return scale_for(x, guide), f"scale_for(hyp({src.point(a, i, pin, q)}), {name})"

    def diagrams(self) -> DiagramScales | None:
        """The S, V, a diagrams' scales as sheet 1 draws them (source
        "sheet1.diagrams.<name>"), or None without sheet 1."""
        return None if self.first is None else self.first.diagrams

    # sheet 2 ----------------------------------------------------------------------------
    def loaded(self) -> Scale:
        if self.second is None:
            return float(self.solution.mu_l), "S.mu_l"
        return self.second.mu_l, "sheet2.mu_l"

    def group(self, name: str) -> Scale:
        if self.second is None or name not in self.second.mu_l_group:
            return float(self.solution.mu_l), "S.mu_l"
        return self.second.mu_l_group[name], f"sheet2.mu_l_group[{name!r}]"

    def driving(self) -> Scale:
        if self.second is None:
            return float(self.solution.mu_l), "S.mu_l"
        return self.second.mu_l_driving, "sheet2.mu_l_driving"

    def force(self, title: str, polygons: tuple[ForcePolygon, ...], base: str) -> Scale:
        """μF of the drawing of `polygons` ("group 4-5", "link 1"); `base` the
        source of the polygons for the stand-in."""
        if self.second is not None and title in self.second.mu_F:
            return self.second.mu_F[title], f"sheet2.mu_F[{title!r}]"
        largest = max((p.largest for p in polygons), default=0.0)
        if largest <= 0:
            return 1.0, "1.0"
        return scale_for(largest, FORCE_PLAN), f"mu_F({base})"

    def lever(self, pa: float) -> Scale:
        if self.second is None:
            return scale_for(pa, VELOCITY_PLAN), "scale_for(F.lever.pa, VELOCITY_PLAN)"
        return self.second.mu_V, "sheet2.mu_V"
