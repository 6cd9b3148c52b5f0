"""The SVG renderer: the only module that imports svgwrite.

The document is sized in millimetres (width="841mm" height="594mm") with a
viewBox in millimetres, so one user unit is one millimetre of paper. The
drawing interface has y up; `_xy` is the one place where it becomes SVG's
y down. Output is repeatable: numbers at a fixed precision, ids counted per
document, nothing taken from the clock.
"""

from __future__ import annotations

import math
import os
import re
from collections import Counter
from collections.abc import Sequence
from pathlib import Path
from typing import Any

import svgwrite
from svgwrite.etree import etree

from .backend import (
    Backend,
    Fill,
    HAlign,
    LineType,
    PointLike,
    VAlign,
    as_point,
    slant_offsets,
    turned,
)
from .look import Look

__all__ = ["SvgBackend"]

_ID_START = re.compile(r"[A-Za-z_]")
_ID_BAD = re.compile(r"[^A-Za-z0-9_.-]+")


class SvgBackend(Backend):
    """Draws into an svgwrite.Drawing; `to_string()` / `save()` give the SVG."""

    def __init__(
        self,
        width: float = 841.0,
        height: float = 594.0,
        look: Look | None = None,
        *,
        precision: int = 3,
        title: str | None = None,
    ) -> None:
        super().__init__(width, height, look)
        self.precision = int(precision)
        # Ids this document uses itself, so that groups cannot take them.
        self._ids: Counter[str] = Counter({"paper": 1, "sheet": 1})
        w, h = self._num(self.width), self._num(self.height)
        self._dwg = svgwrite.Drawing(
            size=(f"{w}mm", f"{h}mm"), viewBox=f"0 0 {w} {h}", profile="full", debug=False
        )
        if title:
            self._dwg.set_desc(title=title)
        self._dwg.add(
            self._dwg.rect(insert=("0", "0"), size=(w, h), fill=self.look.background, id="paper")
        )
        lettering = self.look.lettering
        root = self._dwg.g(
            id="sheet",
            fill="none",
            stroke=self.look.ink,
            stroke_linecap="round",
            stroke_linejoin="round",
            font_family=", ".join(_quote_family(f) for f in lettering.families),
        )
        self._dwg.add(root)
        self._stack: list[Any] = [root]
        self._families = lettering.families  # the document's; a text in another names its own

    # --- output --------------------------------------------------------------

    def to_string(self) -> str:
        self.close()
        # svgwrite's tostring() less its Python 2 detour (its own comment says
        # so): ElementTree writes the same text as unicode, not as UTF-8 bytes
        # through a codec, write by write, decoded again
        text = etree.tostring(self._dwg.get_xml(), encoding="unicode")
        return '<?xml version="1.0" encoding="utf-8" ?>\n' + text + "\n"

    def save(self, path: str | os.PathLike[str]) -> Path:
        """Write the SVG to `path` atomically (files.write_text_atomic)."""
        from ..files import write_text_atomic

        return write_text_atomic(path, self.to_string())

    # --- number formatting and the one y flip --------------------------------

    def _num(self, value: float) -> str:
        text = f"{value:.{self.precision}f}"
        if "." in text:
            text = text.rstrip("0").rstrip(".")
        return "0" if text in ("-0", "") else text

    def _xy(self, p: PointLike) -> tuple[str, str]:
        x, y = as_point(p)
        return self._num(x), self._num(self.height - y)

    def _path_points(self, points: Sequence[PointLike]) -> str:
        pts = [" ".join(self._xy(p)) for p in points]
        if not pts:
            raise ValueError("a polyline needs at least one point")
        return "M " + " L ".join(pts)

    # --- styles --------------------------------------------------------------

    def _stroke(self, line: LineType | None) -> dict[str, str]:
        if line is None:
            return {"stroke": "none"}
        style = self.look.line(line)
        attrs = {"stroke_width": self._num(style.width), "class_": line}
        if style.dash:
            attrs["stroke_dasharray"] = " ".join(self._num(d) for d in style.dash)
        return attrs

    def _fill(self, fill: Fill) -> dict[str, str]:
        self._check_fill(fill)
        if fill == "none":
            return {}
        colour = self.look.ink if fill == "black" else self.look.background
        return {"fill": colour}

    def _add(self, element: Any) -> None:
        self._stack[-1].add(element)

    # --- the interface -------------------------------------------------------

    def line(self, start: PointLike, end: PointLike, line: LineType = "main") -> None:
        self._check_line(line)
        (x1, y1), (x2, y2) = self._xy(start), self._xy(end)
        self._add(self._dwg.line(start=(x1, y1), end=(x2, y2), **self._stroke(line)))

    def polyline(self, points: Sequence[PointLike], line: LineType = "main") -> None:
        self._check_line(line)
        self._add(self._dwg.path(d=self._path_points(points), **self._stroke(line)))

    def polygon(
        self, points: Sequence[PointLike], line: LineType | None = "main", fill: Fill = "none"
    ) -> None:
        self._check_line(line, allow_none=True)
        d = self._path_points(points) + " Z"
        self._add(self._dwg.path(d=d, **self._stroke(line), **self._fill(fill)))

    def circle(
        self, center: PointLike, radius: float, line: LineType | None = "main", fill: Fill = "none"
    ) -> None:
        self._check_line(line, allow_none=True)
        if not radius > 0:
            raise ValueError(f"circle radius must be positive, got {radius}")
        self._add(
            self._dwg.circle(
                center=self._xy(center),
                r=self._num(radius),
                **self._stroke(line),
                **self._fill(fill),
            )
        )

    def arc(
        self,
        center: PointLike,
        radius: float,
        start_deg: float,
        end_deg: float,
        line: LineType = "main",
    ) -> None:
        self._check_line(line)
        if not radius > 0:
            raise ValueError(f"arc radius must be positive, got {radius}")
        span = (end_deg - start_deg) % 360.0
        if span == 0.0:
            if end_deg == start_deg:
                return
            span = 360.0
        cx, cy = as_point(center)
        if span >= 360.0:
            self.circle((cx, cy), radius, line)
            return

        def at(deg: float) -> tuple[float, float]:
            a = math.radians(deg)
            return cx + radius * math.cos(a), cy + radius * math.sin(a)

        r = self._num(radius)
        large = "1" if span > 180.0 else "0"
        # Counter-clockwise with y up is counter-clockwise on paper too, which
        # in SVG's y-down frame is the negative sweep: sweep-flag 0.
        d = "M {} {} A {} {} 0 {} 0 {} {}".format(
            *self._xy(at(start_deg)), r, r, large, *self._xy(at(start_deg + span))
        )
        self._add(self._dwg.path(d=d, **self._stroke(line)))

    def text(
        self,
        pos: PointLike,
        content: str,
        size: float = 3.5,
        *,
        anchor: HAlign = "left",
        valign: VAlign = "baseline",
        rotation: float = 0.0,
        max_width: float | None = None,
    ) -> None:
        self._check_text(size, anchor, valign, max_width)
        lettering = self.look.lettering
        squeeze = lettering.squeeze(str(content), size, max_width)
        lean = lettering.lean  # tan of the slant, worked out once per lettering
        # where SVG puts the text: the baseline under the anchor
        along, across = slant_offsets(anchor, valign, size, lean, squeeze)
        ca, sa = turned(rotation)
        x, y = as_point(pos)
        bx = x + along * ca - across * sa
        by = y + along * sa + across * ca
        sx, sy = self._xy((bx, by))
        transform = f"translate({sx} {sy})"
        if rotation % 360.0:
            transform += f" rotate({self._num(-rotation)})"
        if squeeze != 1.0:
            transform += f" scale({self._num(squeeze)} 1)"
        if lettering.slant_deg:
            transform += f" skewX({self._num(-lettering.slant_deg)})"
        self._add(
            self._dwg.text(
                str(content),
                transform=transform,
                font_size=self._num(lettering.font_size(size)),
                text_anchor={"left": "start", "center": "middle", "right": "end"}[anchor],
                fill=self.look.ink,
                stroke="none",
                class_="lettering",
                **(
                    {}
                    if lettering.families == self._families
                    else {"font_family": ", ".join(_quote_family(f) for f in lettering.families)}
                ),
            )
        )

    def _begin_group(self, id: str, cls: str | None) -> None:
        attrs = {"id": self._unique_id(id)}
        if cls:
            attrs["class_"] = cls
        group = self._dwg.g(**attrs)
        self._add(group)
        self._stack.append(group)

    def _end_group(self) -> None:
        self._stack.pop()

    def _unique_id(self, wanted: str) -> str:
        """An XML id from `wanted`, made unique by a counter of this document."""
        base = _ID_BAD.sub("-", wanted).strip("-") or "g"
        if not _ID_START.match(base):
            base = "g-" + base
        self._ids[base] += 1
        n = self._ids[base]
        return base if n == 1 else f"{base}-{n}"


def _quote_family(name: str) -> str:
    return f"'{name}'" if " " in name else name
