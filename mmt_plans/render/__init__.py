"""Drawing interface and renderers.

`Backend` is the interface sheets draw through; `RecordingBackend` keeps the
calls for tests; `SvgBackend` (render/svg.py, the only user of svgwrite)
writes SVG; `export` turns SVG into PDF and PNG with cairosvg.
"""

from __future__ import annotations

from typing import Any

from .backend import (
    LINE_TYPES,
    Backend,
    Fill,
    HAlign,
    LineType,
    Point,
    PointLike,
    VAlign,
    arrow_geometry,
    as_point,
)
from .look import Lettering, LineStyle, Look, load_look, load_template, templates_dir
from .recording import Call, RecordingBackend

__all__ = [
    "LINE_TYPES",
    "Backend",
    "Call",
    "Fill",
    "HAlign",
    "Lettering",
    "LineStyle",
    "LineType",
    "Look",
    "Point",
    "PointLike",
    "RecordingBackend",
    "SvgBackend",
    "VAlign",
    "arrow_geometry",
    "as_point",
    "load_look",
    "load_template",
    "svg_to_pdf",
    "svg_to_png",
    "templates_dir",
]


def __getattr__(name: str) -> Any:
    # svgwrite and cairosvg load only when a renderer is asked for.
    if name == "SvgBackend":
        from .svg import SvgBackend

        return SvgBackend
    if name in ("svg_to_pdf", "svg_to_png"):
        from . import export

        return getattr(export, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
