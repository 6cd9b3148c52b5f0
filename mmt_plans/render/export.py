"""SVG to PDF (vector) and PNG through cairosvg.

cairosvg (and Cairo under it) is imported inside the functions, so that the
rest of mmt_plans works on a machine without Cairo. Files are written
atomically (files.atomic_path); a PDF goes through note/pdf.py's writer,
which fixes the document's dates, so that two runs give the same bytes.
"""

from __future__ import annotations

import functools
import os
import re
import shutil
import subprocess
from pathlib import Path

__all__ = ["svg_to_pdf", "svg_to_png", "installed_families", "prefer_installed_font"]

SvgSource = str | bytes | os.PathLike[str]

_FONT_FAMILY = re.compile(r'font-family="([^"]*)"')


@functools.cache
def installed_families() -> frozenset[str] | None:
    """Font families fontconfig knows (lower case), or None without fc-list."""
    fc_list = shutil.which("fc-list")
    if fc_list is None:
        return None
    try:
        out = subprocess.run(
            [fc_list, ":", "family"], capture_output=True, text=True, check=True, timeout=30
        ).stdout
    except (OSError, subprocess.SubprocessError):
        return None
    families: set[str] = set()
    for line in out.splitlines():
        families.update(name.strip().lower() for name in line.split(",") if name.strip())
    return frozenset(families)


def prefer_installed_font(svg: str) -> str:
    """Move the first installed family of every font-family list to its front.

    cairosvg looks at the first family only and lets fontconfig substitute
    any font for it when it is missing, so an SVG asking for "osifont,
    'DejaVu Sans Condensed'" on a machine without osifont would not get the
    fallback we chose. Browsers read the whole list, so the SVG file itself
    keeps it as written.
    """
    installed = installed_families()
    if installed is None:
        return svg

    def reorder(match: re.Match[str]) -> str:
        names = [n.strip() for n in match.group(1).split(",") if n.strip()]
        for i, name in enumerate(names):
            if name.strip("'\"").lower() in installed:
                names.insert(0, names.pop(i))
                break
        return 'font-family="' + ", ".join(names) + '"'

    return _FONT_FAMILY.sub(reorder, svg)


def _svg_bytes(svg: SvgSource) -> bytes:
    if isinstance(svg, bytes):
        text = svg.decode("utf-8")
    elif isinstance(svg, str):
        text = svg
    else:
        text = Path(svg).read_text(encoding="utf-8")
    return prefer_installed_font(text).encode("utf-8")


def svg_to_pdf(svg: SvgSource, target: str | os.PathLike[str]) -> Path:
    """Write a vector PDF of the page. `svg` is SVG text (str/bytes) or a file path."""
    from ..note.pdf import svgs_to_pdf

    return svgs_to_pdf([_svg_bytes(svg).decode("utf-8")], target)


def svg_to_png(svg: SvgSource, target: str | os.PathLike[str], dpi: float = 96.0) -> Path:
    """Write a PNG of the page at `dpi` (the SVG is sized in mm, so dpi sets pixels)."""
    import cairosvg

    from ..files import atomic_path

    target = Path(target)
    data = _svg_bytes(svg)
    with atomic_path(target) as tmp:
        cairosvg.svg2png(bytestring=data, write_to=str(tmp), dpi=dpi)
    return target
