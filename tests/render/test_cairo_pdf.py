"""The PDF made on one Cairo surface (render/cairo_pdf.py): a page drawn
straight is the page recorded and replayed, byte for byte; Cairo is imported
without ctypes' library search and leaves that search as it found it."""

import ctypes.util

import pytest

from mmt_plans.render.cairo_lib import import_cairo
from mmt_plans.render.cairo_pdf import PdfDocument, pages_to_pdf_bytes
from mmt_plans.render.recording import RecordingBackend


def _draw(b) -> None:
    with b.group("g"):
        b.line((10, 10), (100, 40), "main")
        b.polyline([(10, 50), (60, 80), (110, 50)], "dashed")
        b.polygon([(20, 100), (40, 100), (30, 120)], "thin", "black")
        b.polygon([(50, 100), (70, 100), (60, 120)], None, "white")
        b.circle((150, 60), 12.0, "dashdot")
        b.arc((150, 120), 15.0, 30.0, 200.0, "thin")
        b.arrow((20, 150), (120, 170))
        b.text((20, 190), "A-B", 5.0)
        b.text((100, 190), "centred", 3.5, anchor="center", valign="middle", rotation=30.0)
        b.text((180, 190), "narrowed text", 3.5, anchor="right", valign="top", max_width=10.0)
        b.rich_text((20, 220), "V_{BA} = 1.2 m/s^2", 5.0)


def test_a_page_drawn_straight_is_the_page_recorded_and_replayed():
    recorded = RecordingBackend(210.0, 297.0)
    _draw(recorded)
    document = PdfDocument()
    try:
        _draw(document.page(210.0, 297.0, recorded.look))
        straight = document.finish()
    finally:
        document.close()
    assert straight.startswith(b"%PDF-")
    assert straight == pages_to_pdf_bytes([recorded])


def test_a_document_needs_a_page_and_ends_once():
    document = PdfDocument()
    with pytest.raises(ValueError, match="at least one page"):
        document.finish()
    with pytest.raises(RuntimeError, match="finished"):
        document.page(210.0, 297.0, RecordingBackend().look)


def test_cairo_is_imported_and_the_library_search_left_as_it_was():
    search = ctypes.util.find_library
    cairo = import_cairo()
    assert ctypes.util.find_library is search
    assert cairo.cairo.cairo_version() >= 11000  # libcairo 1.10 or later, opened
