"""The note's pages as one PDF: the Cairo replay of render/cairo_pdf.py, the
same path the sheets' PDF takes."""

from __future__ import annotations

from ..render.cairo_pdf import CairoPage, PdfDocument, pages_to_pdf, pages_to_pdf_bytes

__all__ = ["CairoPage", "PdfDocument", "pages_to_pdf", "pages_to_pdf_bytes"]
