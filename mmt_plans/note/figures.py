"""The note's figures: a key of a "figure" block → what draws it into its
rectangle on the page. "scheme" is the kinematic scheme of the mechanism at
position 0 as sheets/schematic.py draws it."""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING

from ..drawing.page import Rect
from ..i18n import check_language
from ..render.backend import Backend

if TYPE_CHECKING:  # pragma: no cover
    from ..solution import Solution

__all__ = ["FIGURES", "figure_drawers"]

Drawer = Callable[["Solution", Backend, Rect, str], None]


def _scheme(solution: Solution, backend: Backend, rect: Rect, lang: str) -> None:
    from ..sheets.schematic import sketch_schematic

    sketch = sketch_schematic(
        solution, backend.look, check_language(lang), width_mm=rect.width, height_mm=rect.height
    )
    sketch.replay(backend, rect.x, rect.y)


FIGURES: dict[str, Drawer] = {"scheme": _scheme}


def figure_drawers(solution: Solution) -> dict[str, Callable[[Backend, Rect, str], None]]:
    """The drawers of `FIGURES` bound to `solution`."""

    def bind(fn: Drawer) -> Callable[[Backend, Rect, str], None]:
        return lambda backend, rect, lang: fn(solution, backend, rect, lang)

    return {key: bind(fn) for key, fn in FIGURES.items()}
