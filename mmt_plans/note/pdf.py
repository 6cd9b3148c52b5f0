"""The note's pages as one PDF: render/export.svgs_to_pdf (multi-page, atomic,
with a fixed document date)."""

from __future__ import annotations

from ..render.export import svgs_to_pdf

__all__ = ["svgs_to_pdf"]
