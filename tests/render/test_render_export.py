import io
import re
import zlib

import pytest

pytest.importorskip("cairosvg")
from PIL import Image  # noqa: E402  (pillow comes with cairosvg)

from mmt_plans.render import SvgBackend, svg_to_pdf, svg_to_png  # noqa: E402
from mmt_plans.render import export  # noqa: E402
from mmt_plans.sheets import Page, draw_page  # noqa: E402

MM_TO_PT = 72 / 25.4


@pytest.fixture(scope="module")
def sheet_svg() -> str:
    page = Page.of("A1")
    b = SvgBackend(page.width, page.height)
    draw_page(b, page, {"title": "Кінематичний аналіз", "author": "Коваленко", "sheet": 1, "sheets": 2})
    b.arrow((100, 100), (200, 300))
    return b.to_string()


def pdf_streams(data: bytes) -> list[bytes]:
    out = []
    for m in re.finditer(rb"stream\r?\n(.*?)\r?\nendstream", data, re.S):
        raw = m.group(1)
        try:
            out.append(zlib.decompress(raw))
        except zlib.error:
            out.append(raw)
    return out


def test_pdf_is_vector_and_a1(tmp_path, sheet_svg):
    path = svg_to_pdf(sheet_svg, tmp_path / "sheet.pdf")
    data = path.read_bytes()
    assert data.startswith(b"%PDF")
    streams = pdf_streams(data)
    everything = data + b"".join(streams)
    # No raster image anywhere, not even inside object streams.
    assert b"/Image" not in everything
    assert b"/DCTDecode" not in everything
    # Lines are drawn with path operators (moveto/lineto ... stroke).
    content = b"".join(streams)
    assert re.search(rb"\bm\b", content) and re.search(rb"\bl\b", content)
    assert re.search(rb"\bS\b", content)
    box = re.search(rb"/MediaBox\s*\[\s*([\d.\s-]+)\]", data)
    x0, y0, x1, y1 = (float(v) for v in box.group(1).split())
    assert x1 - x0 == pytest.approx(841 * MM_TO_PT, abs=0.5)
    assert y1 - y0 == pytest.approx(594 * MM_TO_PT, abs=0.5)


def test_png_decodes_with_the_sheet_aspect(tmp_path, sheet_svg):
    path = svg_to_png(sheet_svg, tmp_path / "sheet.png", dpi=50)
    image = Image.open(io.BytesIO(path.read_bytes()))
    image.load()
    w, h = image.size
    assert w == pytest.approx(841 / 25.4 * 50, abs=1)
    assert h == pytest.approx(594 / 25.4 * 50, abs=1)
    assert w / h == pytest.approx(841 / 594, rel=2e-3)
    grey = image.convert("L")
    k = 50 / 25.4
    # Paper is white; the frame's left line at x = 20 mm is ink.
    assert grey.getpixel((int(100 * k), int(300 * k))) > 250
    assert min(grey.getpixel((int(20 * k) + dx, int(300 * k))) for dx in (-1, 0, 1)) < 128


def test_svg_path_source_is_accepted(tmp_path, sheet_svg):
    svg_file = tmp_path / "sheet.svg"
    svg_file.write_text(sheet_svg, encoding="utf-8")
    assert svg_to_pdf(svg_file, tmp_path / "a.pdf").read_bytes().startswith(b"%PDF")


def test_first_installed_family_moves_to_front(monkeypatch):
    svg = '<g font-family="osifont, \'DejaVu Sans Condensed\', \'DejaVu Sans\'"/>'
    monkeypatch.setattr(export, "installed_families", lambda: frozenset({"dejavu sans condensed"}))
    assert export.prefer_installed_font(svg) == (
        '<g font-family="\'DejaVu Sans Condensed\', osifont, \'DejaVu Sans\'"/>'
    )
    monkeypatch.setattr(export, "installed_families", lambda: frozenset({"osifont"}))
    assert export.prefer_installed_font(svg) == svg
    monkeypatch.setattr(export, "installed_families", lambda: None)
    assert export.prefer_installed_font(svg) == svg
