"""One factory by format: a drawing recorded once (`RecordingBackend`) is
written as SVG, PDF, PNG or DXF. The only place that chooses a renderer.

SVG through svgwrite (render/svg.py), PDF replayed onto a Cairo surface
(render/cairo_pdf.py), PNG from the SVG through cairosvg (render/export.py), DXF through ezdxf (render/dxf.py); each renderer
is imported when its format is asked for, so that a command that draws no
sheet loads none of them.
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import Literal, get_args

from .recording import RecordingBackend

__all__ = ["Format", "FORMATS", "render", "write_drawing"]

Format = Literal["svg", "pdf", "png", "dxf"]
FORMATS: tuple[Format, ...] = get_args(Format)


def _svg(recording: RecordingBackend, title: str | None) -> str:
    from .svg import SvgBackend

    backend = SvgBackend(recording.width, recording.height, recording.look, title=title)
    recording.replay(backend)
    return backend.to_string()


def render(recording: RecordingBackend, fmt: str, title: str | None = None) -> bytes:
    """The recorded drawing as the bytes of a file of format `fmt`."""
    if fmt not in FORMATS:
        raise ValueError(f"unknown format {fmt!r}; expected one of {', '.join(FORMATS)}")
    if fmt == "svg":
        return _svg(recording, title).encode("utf-8")
    if fmt == "dxf":
        from .dxf import DxfBackend

        backend = DxfBackend(recording.width, recording.height, recording.look, title=title)
        recording.replay(backend)
        return backend.to_bytes()
    if fmt == "pdf":
        from .cairo_pdf import pages_to_pdf_bytes

        return pages_to_pdf_bytes([recording], title)
    from .export import svg_to_png_bytes

    return svg_to_png_bytes(_svg(recording, title))


def write_drawing(
    recording: RecordingBackend, target: str | os.PathLike[str], fmt: str, title: str | None = None
) -> Path:
    """Write the recorded drawing to `target` in format `fmt`, atomically (a
    temporary name in the same folder, renamed when complete); returns the path."""
    from ..files import write_bytes_atomic

    return write_bytes_atomic(Path(target), render(recording, fmt, title))
