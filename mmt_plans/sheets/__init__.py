"""Composing the A1 sheets from a Solution (sheet1, sheet2, the task schematics);
the page, frame, title block, tables and layout come from mmt_plans.drawing."""

from __future__ import annotations

from ..drawing.layout import Element, LayoutError, SheetLayout, as_footprint, find_overlaps
from ..drawing.page import (
    FIELDS,
    GOST_MARGINS,
    PAGE_SIZES,
    Cell,
    Margins,
    Page,
    Rect,
    TitleBlock,
    draw_frame,
    draw_page,
    draw_title_block,
    title_block_texts,
)
from ..drawing.table import Table

__all__ = [
    "FIELDS",
    "GOST_MARGINS",
    "PAGE_SIZES",
    "Cell",
    "Element",
    "LayoutError",
    "Margins",
    "Page",
    "Rect",
    "SheetLayout",
    "Table",
    "TitleBlock",
    "as_footprint",
    "draw_frame",
    "draw_page",
    "draw_title_block",
    "find_overlaps",
    "title_block_texts",
]
