"""Where a drawing's names crowd: the names the sheet linter finds far from
what they name, or on a line or another name, and what they name (the points
a detail view, `drawing.detail`, is drawn round)."""

from __future__ import annotations

from collections.abc import Iterable, Iterator

import numpy as np

from ..drawing.sketch import Sketch
from ..i18n import Language
from ..render.recording import Naming
from .lint import SheetView, label_clear, label_near

__all__ = ["crowded", "crowded_ends", "crowded_names", "stand_for"]


def crowded(sketch: Sketch, lang: Language) -> Iterator[Naming]:
    """What the names of a drawing that the sheet linter finds far from what
    they name, or on a line or another name, name."""
    view = SheetView(list(sketch.calls), 841.0, 594.0, lang)
    found = {f.where for f in (*label_near(view), *label_clear(view))}
    for lab in view.labels:
        c = lab.box.centroid
        if lab.naming is not None and (round(float(c.x), 1), round(float(c.y), 1)) in found:
            yield lab.naming


def crowded_names(sketch: Sketch, lang: Language, anchors: bool = False) -> np.ndarray:
    """Where the names of a drawing that the sheet linter finds far from what
    they name, or on a line or another name, stand for (mm, one row each: the
    point, or the middle of the segment, they name; with `anchors`, the
    segment's start: where a force is applied)."""
    return stand_for(crowded(sketch, lang), anchors)


def stand_for(namings: Iterable[Naming], anchors: bool = False) -> np.ndarray:
    """Where `namings` stand for, as `crowded_names`."""
    out = []
    for n in namings:
        end = n.anchor if n.end is None or anchors else n.end
        out.append(((n.anchor[0] + end[0]) / 2.0, (n.anchor[1] + end[1]) / 2.0))
    return np.array(out, dtype=float).reshape(-1, 2)


def crowded_ends(sketch: Sketch, lang: Language) -> np.ndarray:
    """What the crowded names of a drawing (as `crowded_names`) stand for,
    both ends (mm, one row each, x0, y0, x1, y1): the point, or the arrow's
    start, twice; the segment's ends."""
    out = []
    for n in crowded(sketch, lang):
        end = n.end if n.kind == "segment" and n.end is not None else n.anchor
        out.append((n.anchor[0], n.anchor[1], end[0], end[1]))
    return np.array(out, dtype=float).reshape(-1, 4)
