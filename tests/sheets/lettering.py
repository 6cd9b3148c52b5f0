"""The labels of a recorded sheet as boxes: the runs of one rich text joined."""

from __future__ import annotations

import functools
import itertools
import math

from shapely.geometry import box


def label_boxes(backend, group: str | None = None, *, groups: bool = False):
    """(text, box) per label (with `groups`, (text, box, the groups of its first run)). backend.rich_text writes a label as runs (a
    letter, then its index), each run starting where the previous one's
    advance ends; such runs are one label (where the recording says what
    each names, runs of two labels side by side, naming different things,
    are two)."""
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
        same = prev is None or None in (prev.naming, c.naming) or prev.naming == c.naming
        if prev is not None and same and prev.groups == c.groups and c["anchor"] == "left":
            end = prev["pos"][0] + let.advance_width(prev["content"], prev["size"])
            gap = c["pos"][0] - end
            if -1e-9 <= gap <= let.advance_width(" ", max(prev["size"], c["size"])) + 1e-9 \
                    and abs(c["pos"][1] - prev["pos"][1]) < prev["size"]:
                text, old, g = labels[-1]
                labels[-1] = (text + c["content"], old.union(b).envelope, g)
                prev = c
                continue
        labels.append((c["content"], b, c.groups))
        prev = c
    return labels if groups else [(t, b) for t, b, _ in labels]


def clashes(backend, group: str | None = None, area: float = 0.2):
    """Pairs of labels whose boxes overlap by more than `area` mm²."""
    labels = label_boxes(backend, group)
    return [(a[0], b[0]) for a, b in itertools.combinations(labels, 2)
            if a[1].intersects(b[1]) and a[1].intersection(b[1]).area > area]


__all__ = ["label_boxes", "clashes"]


# --- lettering against the drawn primitives -----------------------------------------

_NOT_DRAWINGS = ("table", "title-block", "frame")  # lettering in cells is the table's


def _group_classes(backend) -> dict[str, str]:
    return {c["id"]: c["cls"] or "" for c in backend.named("begin_group")}


def _in_drawing(call, classes) -> bool:
    return not any(classes.get(g, "") in _NOT_DRAWINGS for g in call.groups)


def primitive_shapes(backend):
    """(name, shape) of every drawn primitive but lettering, as it lies on the
    paper: a line, each edge of a polyline or polygon (the whole of a filled
    one), an arrow's shaft and its head, a circle (the disc when filled), an arc."""
    from shapely.geometry import LineString, Point, Polygon

    out = []
    for c in backend.calls:
        a = c.args
        if c.name == "line":
            if math.dist(a["start"], a["end"]) > 1e-9:
                out.append(("line", LineString([a["start"], a["end"]])))
        elif c.name == "polyline":
            out.append(("polyline", LineString(a["points"])))
        elif c.name == "polygon":
            pts = list(a["points"])
            if a["fill"] != "none":
                out.append(("polygon", Polygon(pts)))
            else:
                out.append(("polygon", LineString(pts + pts[:1])))
        elif c.name == "arrow":
            (x0, y0), (x1, y1) = a["start"], a["end"]
            length = math.hypot(x1 - x0, y1 - y0)
            if length < 1e-9:
                continue
            ux, uy = (x1 - x0) / length, (y1 - y0) / length
            hl, hw = min(a["head_length"], length), a["head_width"] / 2
            bx, by = x1 - hl * ux, y1 - hl * uy
            out.append(("arrow", LineString([(x0, y0), (x1, y1)])))
            out.append(("arrowhead", Polygon(
                [(x1, y1), (bx - hw * uy, by + hw * ux), (bx + hw * uy, by - hw * ux)])))
        elif c.name == "circle":
            disc = Point(a["center"]).buffer(a["radius"], 32)
            out.append(("circle", disc if a["fill"] != "none" else disc.exterior))
        elif c.name == "arc":
            (cx, cy), r = a["center"], a["radius"]
            span = (a["end_deg"] - a["start_deg"]) % 360.0 or 360.0
            ts = [math.radians(a["start_deg"] + span * k / 48) for k in range(49)]
            out.append(("arc", LineString([(cx + r * math.cos(t), cy + r * math.sin(t))
                                           for t in ts])))
    return out


def label_hits(backend, shrink: float = 0.1):
    """(label, primitive name, a point of the overlap, the label's innermost
    group) for every label of a
    drawing (tables, the title block and the frame aside) that a drawn
    primitive crosses; a label's box is its capitals and indices, `shrink` mm in."""
    from shapely import STRtree

    classes = _group_classes(backend)
    keep = [c for c in backend.named("text") if _in_drawing(c, classes)]

    class _Only:  # label_boxes of the kept calls only
        look = backend.look
        text_box = backend.text_box

        @staticmethod
        def named(*names):
            return keep

    shapes = primitive_shapes(backend)
    tree = STRtree([s for _, s in shapes])
    hits = []
    for text, b, g in label_boxes(_Only, groups=True):
        inner = b.buffer(-shrink, join_style=2)
        if inner.is_empty:
            continue
        for k in tree.query(inner, predicate="intersects"):
            name, shape = shapes[int(k)]
            p = inner.intersection(shape).representative_point()
            hits.append((text, name, (round(p.x, 1), round(p.y, 1)), g[-1] if g else ""))
    return hits


def label_clashes_anywhere(backend, area: float = 0.2):
    """Pairs of labels of the drawings whose boxes overlap by more than `area` mm²."""
    classes = _group_classes(backend)
    keep = [c for c in backend.named("text") if _in_drawing(c, classes)]

    class _Only:
        look = backend.look
        text_box = backend.text_box

        @staticmethod
        def named(*names):
            return keep

    return clashes(_Only, None, area)


__all__ += ["primitive_shapes", "label_hits", "label_clashes_anywhere"]


@functools.cache
def solved_seed(seed: int):
    """The Solution of generated mechanism `seed` (mmt_plans.generate), solved once per run."""
    from mmt_plans.generate import generate_one
    from mmt_plans.solution import solve
    from mmt_plans.spec import loads

    g = generate_one(seed)
    return solve(loads(g.toml, f"{g.name}.toml"))


def near_findings(sketch, lang: str = "en") -> list:
    """The label-near and label-clear findings on `sketch` laid on an A1 sheet."""
    from mmt_plans.sheets.lint import SheetView, label_clear, label_near

    view = SheetView(list(sketch.calls), 841.0, 594.0, lang)
    return [*label_near(view), *label_clear(view)]


@functools.cache
def composed_sheet2(seed: int, lang: str):
    """Sheet 2 of generated mechanism `seed` recorded on A1, composed once
    per run: what compose_sheet2 returned, the recorded view and the
    linter's findings on it."""
    from mmt_plans.generate import generate_one
    from mmt_plans.render.recording import RecordingBackend
    from mmt_plans.sheets.lint import SheetView, lint
    from mmt_plans.sheets.sheet2 import compose_sheet2

    backend = RecordingBackend(841.0, 594.0)
    result = compose_sheet2(solved_seed(seed), backend, lang)
    view = SheetView.of(backend, lang, generate_one(seed).name)
    return result, view, list(lint(view))
