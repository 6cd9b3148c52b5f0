"""The labels of a recorded sheet as boxes: the runs of one rich text joined."""

from __future__ import annotations

import itertools
import math

from shapely.geometry import box


def label_boxes(backend, group: str | None = None):
    """(text, box) per label. backend.rich_text writes a label as runs (a
    letter, then its index), each run starting where the previous one's
    advance ends; such runs are one label."""
    calls = backend.named("text") if group is None else [
        c for c in backend.in_group(group) if c.name == "text"]
    let = backend.look.lettering
    labels: list[tuple[str, object]] = []
    prev = None
    for c in calls:
        if c["rotation"] != 0:
            prev = None
            continue
        b = box(*backend.text_box(c))
        if prev is not None and prev.groups == c.groups and c["anchor"] == "left":
            end = prev["pos"][0] + let.advance_width(prev["content"], prev["size"])
            gap = c["pos"][0] - end
            if -1e-9 <= gap <= let.advance_width(" ", max(prev["size"], c["size"])) + 1e-9 \
                    and abs(c["pos"][1] - prev["pos"][1]) < prev["size"]:
                text, old = labels[-1]
                labels[-1] = (text + c["content"], old.union(b).envelope)
                prev = c
                continue
        labels.append((c["content"], b))
        prev = c
    return labels


def clashes(backend, group: str | None = None, area: float = 0.2):
    """Pairs of labels whose boxes overlap by more than `area` mm²."""
    labels = label_boxes(backend, group)
    return [(a[0], b[0]) for a, b in itertools.combinations(labels, 2)
            if a[1].intersects(b[1]) and a[1].intersection(b[1]).area > area]


__all__ = ["label_boxes", "clashes"]
