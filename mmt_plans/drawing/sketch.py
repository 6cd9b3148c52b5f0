"""A drawing sketched in its own millimetre coordinates: recorded, measured,
then replayed where the layout puts it."""

from __future__ import annotations

from collections.abc import Iterable
from typing import TYPE_CHECKING, Any

from ..render.recording import RecordingBackend
from .page import Rect

if TYPE_CHECKING:
    from .labels import LabelCounts

__all__ = ["Sketch", "PAD"]

PAD = 2.0  # clearance added round every sketch's drawn extent, mm


class Sketch(RecordingBackend):
    """A drawing recorded in local mm, measured, then replayed at an offset."""

    def __init__(self, look: Any) -> None:
        super().__init__(841.0, 594.0, look)
        # each call's bounds, measured once: the layout asks for extents often
        self._bounds: dict[int, tuple[Any, tuple[float, float, float, float] | None]] = {}
        # how well its labels found room, once they are written (Labels.counts):
        # what a composer weighs when it chooses the drawing's scale
        self.label_counts: LabelCounts | None = None
        # a detail view: where what it details stands in the drawing it
        # details (that drawing's local mm), which the layout keeps it near
        self.detail_of: tuple[float, float] | None = None

    def _call_bounds(self, c: Any) -> tuple[float, float, float, float] | None:
        hit = self._bounds.get(id(c))
        if hit is not None and hit[0] is c:
            return hit[1]
        if c.name == "text":
            pts = list(zip(*[iter(self.text_box(c))] * 2))
        else:
            pts = c.points()
        bounds = None
        if pts:
            xs, ys = [p[0] for p in pts], [p[1] for p in pts]
            bounds = (min(xs), min(ys), max(xs), max(ys))
        self._bounds[id(c)] = (c, bounds)  # the call is kept, so its id stays its own
        return bounds

    def bounds(self, start: int = 0) -> tuple[float, float, float, float] | None:
        """The bounds (x0, y0, x1, y1, no PAD) of the calls from `start` on;
        None: none of them draws anything."""
        return _union(map(self._call_bounds, self.calls[start:]))

    def extent(self) -> Rect:
        return self.extent_since(None, 0)

    def extent_since(self, before: tuple[float, float, float, float] | None, start: int) -> Rect:
        """`extent` where the calls before `start` are known to have the
        `bounds` `before` (and are unchanged since): only the calls drawn
        after them measured (a trial's symbol, drawn and undone many times)."""
        union = _union((before, self.bounds(start)))
        if union is None:
            return Rect(0.0, 0.0, 1.0, 1.0)
        x0, y0, x1, y1 = union
        return Rect.from_bounds(x0 - PAD, y0 - PAD, x1 + PAD, y1 + PAD)

    def group_extents(self) -> list[tuple[float, float, float, float]]:
        """The bounds of each group's calls (no PAD): what the sheet linter
        measures of the drawing (lint.field_filled)."""
        out: dict[str, list[float]] = {}
        for c in self.calls:
            b = self._call_bounds(c) if c.groups else None
            if b is None:
                continue
            for g in c.groups:
                o = out.setdefault(g, list(b))
                o[:] = [min(o[0], b[0]), min(o[1], b[1]), max(o[2], b[2]), max(o[3], b[3])]
        return [(o[0], o[1], o[2], o[3]) for o in out.values()]

    def add_to_last_group(self, other: Sketch, group_id: str) -> None:
        """Splice `other`'s calls into this sketch's last group `group_id`, before its end."""
        end = max(i for i, c in enumerate(self.calls) if c.name == "end_group")
        self.calls[end:end] = [type(c)(c.name, c.args, (group_id,)) for c in other.calls]


def _union(
    boxes: Iterable[tuple[float, float, float, float] | None],
) -> tuple[float, float, float, float] | None:
    """The bounds (x0, y0, x1, y1) holding every box of `boxes` (None: none)."""
    found = [b for b in boxes if b is not None]
    if not found:
        return None
    return (
        min(b[0] for b in found),
        min(b[1] for b in found),
        max(b[2] for b in found),
        max(b[3] for b in found),
    )
