"""A drawing sketched in its own millimetre coordinates: recorded, measured,
then replayed where the layout puts it."""

from __future__ import annotations

from typing import Any

from ..render.recording import RecordingBackend
from .page import Rect

__all__ = ["Sketch", "PAD"]

PAD = 2.0  # clearance added round every sketch's drawn extent, mm


class Sketch(RecordingBackend):
    """A drawing recorded in local mm, measured, then replayed at an offset."""

    def __init__(self, look: Any) -> None:
        super().__init__(841.0, 594.0, look)

    def extent(self) -> Rect:
        xs: list[float] = []
        ys: list[float] = []
        for c in self.calls:
            if c.name == "text":
                x0, y0, x1, y1 = self.text_box(c)
                pts = [(x0, y0), (x1, y1)]
            else:
                pts = c.points()
            for x, y in pts:
                xs.append(x)
                ys.append(y)
        if not xs:
            return Rect(0.0, 0.0, 1.0, 1.0)
        return Rect.from_bounds(min(xs) - PAD, min(ys) - PAD, max(xs) + PAD, max(ys) + PAD)

    def add_to_last_group(self, other: Sketch, group_id: str) -> None:
        """Splice `other`'s calls into this sketch's last group `group_id`, before its end."""
        end = max(i for i, c in enumerate(self.calls) if c.name == "end_group")
        self.calls[end:end] = [type(c)(c.name, c.args, (group_id,)) for c in other.calls]
