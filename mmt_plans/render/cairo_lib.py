"""cairocffi, imported once and cheaply: the PDF writer (cairo_pdf) and the
PNG/PDF export (export) both load it through here."""

from __future__ import annotations

from typing import Any

__all__ = ["import_cairo"]


def import_cairo() -> Any:
    """cairocffi, imported without ctypes' library search on Linux.

    cairocffi looks for libcairo with `ctypes.util.find_library`, which on
    Linux runs ldconfig, gcc and ld (about a quarter of a second of a cold
    `mmt-plans note`) before it opens "libcairo.so.2" by name anyway; the
    dynamic loader finds the same library by that name. Where it does not,
    the import is made again with the search."""
    import sys

    if "cairocffi" in sys.modules or not sys.platform.startswith("linux"):
        import cairocffi

        return cairocffi
    import ctypes.util

    search = ctypes.util.find_library
    ctypes.util.find_library = lambda name: None
    try:
        import cairocffi
    except OSError:
        ctypes.util.find_library = search
        import cairocffi
    finally:
        ctypes.util.find_library = search
    return cairocffi
