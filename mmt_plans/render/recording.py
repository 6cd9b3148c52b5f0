"""A backend that records every drawing call, for tests (ezdxf `debug_backend.py`)."""

from __future__ import annotations

import itertools
import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

from .backend import (
    Backend,
    Fill,
    HAlign,
    LineType,
    Point,
    PointLike,
    TextRun,
    VAlign,
    as_point,
    parse_markup,
)

__all__ = ["Call", "LabelRun", "RecordingBackend"]

_LABELS = itertools.count(1)  # label serials, unique across spliced sketches


@dataclass(frozen=True)
class LabelRun:
    """Marks a text call as one run of a label set by `rich_text`: the label's
    runs and the label's position relative to this run's, so that a backend
    that sets a label whole (`sets_labels_whole`, DXF: one MTEXT) gets the
    label back on replay. Every other reader sees the runs as texts."""

    serial: int
    index: int  # of this run in `runs`
    runs: tuple[TextRun, ...]
    offset: Point  # the label's pos less this run's pos
    size: float
    anchor: HAlign
    valign: VAlign
    rotation: float


@dataclass(frozen=True)
class Call:
    """One drawing call: its name, its arguments (points as float tuples) and
    the ids of the groups it was drawn in, outermost first."""

    name: str
    args: dict[str, Any]
    groups: tuple[str, ...] = ()

    def __getitem__(self, key: str) -> Any:
        return self.args[key]

    def points(self) -> list[Point]:
        """The defining points of the call (for bounds and containment checks)."""
        a = self.args
        if self.name == "line" or self.name == "arrow":
            return [a["start"], a["end"]]
        if self.name in ("polyline", "polygon"):
            return list(a["points"])
        if self.name in ("circle", "arc"):
            (cx, cy), r = a["center"], a["radius"]
            return [(cx - r, cy - r), (cx + r, cy + r)]
        if self.name == "text":
            return [a["pos"]]
        return []


class RecordingBackend(Backend):
    """Keeps `calls` in order; `begin_group`/`end_group` are recorded too."""

    def __init__(self, width: float = 841.0, height: float = 594.0, look=None) -> None:
        super().__init__(width, height, look)
        self.calls: list[Call] = []
        self._label: tuple[int, tuple[TextRun, ...], Point, list[int], dict[str, Any]] | None = None

    def rich_text(
        self,
        pos: PointLike,
        content: str | Sequence[TextRun],
        size: float = 3.5,
        *,
        anchor: HAlign = "left",
        valign: VAlign = "baseline",
        rotation: float = 0.0,
    ) -> float:
        runs = tuple(parse_markup(content) if isinstance(content, str) else content)
        # the runs base rich_text draws, in order: those with a non-blank body
        drawn = [i for i, (t, _) in enumerate(runs) if t.strip(" ")]
        style = {"size": float(size), "anchor": anchor, "valign": valign, "rotation": rotation}
        self._label = (next(_LABELS), runs, as_point(pos), drawn, style)
        try:
            return super().rich_text(
                pos, list(runs), size, anchor=anchor, valign=valign, rotation=rotation
            )
        finally:
            self._label = None

    def _record(self, name: str, **args: Any) -> None:
        self.calls.append(Call(name, args, tuple(self._open_groups)))

    # --- queries -------------------------------------------------------------

    def named(self, *names: str) -> list[Call]:
        return [c for c in self.calls if c.name in names]

    def in_group(self, group_id: str) -> list[Call]:
        """Calls drawn inside the group `group_id` (at any depth)."""
        return [c for c in self.calls if group_id in c.groups and not c.name.endswith("group")]

    def texts(self) -> list[str]:
        return [c["content"] for c in self.named("text")]

    def text_box(self, call: Call) -> tuple[float, float, float, float]:
        """Estimated (xmin, ymin, xmax, ymax) of an unrotated text call's capitals."""
        if call.name != "text":
            raise ValueError("text_box needs a text call")
        if call["rotation"] % 360.0 != 0.0:
            raise ValueError("text_box handles unrotated text only")
        x, y = call["pos"]
        size = call["size"]
        w = self.look.lettering.width(call["content"], size, call["max_width"])
        x0 = {"left": x, "center": x - w / 2, "right": x - w}[call["anchor"]]
        y0 = {"baseline": y, "middle": y - size / 2, "top": y - size}[call["valign"]]
        return (x0, y0, x0 + w, y0 + size)

    # --- the interface -------------------------------------------------------

    def line(self, start: PointLike, end: PointLike, line: LineType = "main") -> None:
        self._check_line(line)
        self._record("line", start=as_point(start), end=as_point(end), line=line)

    def polyline(self, points: Sequence[PointLike], line: LineType = "main") -> None:
        self._check_line(line)
        self._record("polyline", points=tuple(as_point(p) for p in points), line=line)

    def polygon(
        self, points: Sequence[PointLike], line: LineType | None = "main", fill: Fill = "none"
    ) -> None:
        self._check_line(line, allow_none=True)
        self._check_fill(fill)
        self._record("polygon", points=tuple(as_point(p) for p in points), line=line, fill=fill)

    def circle(
        self, center: PointLike, radius: float, line: LineType | None = "main", fill: Fill = "none"
    ) -> None:
        self._check_line(line, allow_none=True)
        self._check_fill(fill)
        self._record("circle", center=as_point(center), radius=float(radius), line=line, fill=fill)

    def arc(
        self,
        center: PointLike,
        radius: float,
        start_deg: float,
        end_deg: float,
        line: LineType = "main",
    ) -> None:
        self._check_line(line)
        self._record(
            "arc",
            center=as_point(center),
            radius=float(radius),
            start_deg=float(start_deg),
            end_deg=float(end_deg),
            line=line,
        )

    def arrow(
        self,
        start: PointLike,
        end: PointLike,
        line: LineType = "main",
        *,
        head_length: float | None = None,
        head_width: float | None = None,
    ) -> None:
        self._check_line(line)
        hl = self.look.arrow_length if head_length is None else float(head_length)
        hw = self.look.arrow_width if head_width is None else float(head_width)
        s, e = as_point(start), as_point(end)
        self._record(
            "arrow",
            start=s,
            end=e,
            line=line,
            head_length=hl,
            head_width=hw,
            length=math.dist(s, e),
        )

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
        extra: dict[str, Any] = {}
        p = as_point(pos)
        if self._label is not None and self._label[3]:
            serial, runs, at, drawn, style = self._label
            extra["label"] = LabelRun(
                serial, drawn.pop(0), runs, (at[0] - p[0], at[1] - p[1]), **style
            )
        self._record(
            "text",
            pos=p,
            content=str(content),
            size=float(size),
            anchor=anchor,
            valign=valign,
            rotation=float(rotation),
            max_width=None if max_width is None else float(max_width),
            **extra,
        )

    def _begin_group(self, id: str, cls: str | None) -> None:
        # Recorded with the groups as they were before this one opened.
        self.calls.append(
            Call("begin_group", {"id": id, "cls": cls}, tuple(self._open_groups[:-1]))
        )

    def _end_group(self) -> None:
        self._record("end_group")

    def replay(self, backend: Backend, dx: float = 0.0, dy: float = 0.0) -> None:
        """Draw every recorded call again on `backend`, shifted by (dx, dy) mm."""

        def t(p: Sequence[float]) -> tuple[float, float]:
            return (p[0] + dx, p[1] + dy)

        whole = bool(getattr(backend, "sets_labels_whole", False))
        # each label's runs as recorded now (a sheet may have translated a run's text)
        labels: dict[int, list[TextRun]] = {}
        for c in self.calls:
            mark = c.args.get("label") if c.name == "text" else None
            if whole and mark is not None:
                runs = labels.setdefault(mark.serial, list(mark.runs))
                old, kind = runs[mark.index]
                lead = old[: len(old) - len(old.lstrip(" "))]
                trail = old[len(old.rstrip(" ")) :]
                runs[mark.index] = (lead + c.args["content"] + trail, kind)
        for c in self.calls:
            a = c.args
            mark = a.get("label") if c.name == "text" else None
            if whole and mark is not None:
                whole_runs = labels.pop(mark.serial, None)
                if whole_runs is not None:  # the label's first run: the whole label
                    x, y = t(a["pos"])
                    backend.rich_text(
                        (x + mark.offset[0], y + mark.offset[1]),
                        whole_runs,
                        mark.size,
                        anchor=mark.anchor,
                        valign=mark.valign,
                        rotation=mark.rotation,
                    )
                continue
            if c.name == "begin_group":
                backend.begin_group(a["id"], a["cls"])
            elif c.name == "end_group":
                backend.end_group()
            elif c.name == "line":
                backend.line(t(a["start"]), t(a["end"]), a["line"])
            elif c.name == "polyline":
                backend.polyline([t(p) for p in a["points"]], a["line"])
            elif c.name == "polygon":
                backend.polygon([t(p) for p in a["points"]], a["line"], a["fill"])
            elif c.name == "circle":
                backend.circle(t(a["center"]), a["radius"], a["line"], a["fill"])
            elif c.name == "arc":
                backend.arc(t(a["center"]), a["radius"], a["start_deg"], a["end_deg"], a["line"])
            elif c.name == "arrow":
                backend.arrow(
                    t(a["start"]),
                    t(a["end"]),
                    a["line"],
                    head_length=a["head_length"],
                    head_width=a["head_width"],
                )
            elif c.name == "text" and mark is not None and isinstance(backend, RecordingBackend):
                # into another recording: the run keeps its label's mark
                backend._record("text", **{**a, "pos": t(a["pos"])})
            elif c.name == "text":
                backend.text(
                    t(a["pos"]),
                    a["content"],
                    a["size"],
                    anchor=a["anchor"],
                    valign=a["valign"],
                    rotation=a["rotation"],
                    max_width=a["max_width"],
                )
            else:  # pragma: no cover - a new primitive must be added here
                raise ValueError(f"cannot replay {c.name!r}")
