"""The DXF through a real client: LibreCAD (Debian's package) prints it to PDF
(`librecad dxf2pdf`), and the PDF is read back as pixels (pdftoppm).

Issue 24: white masks printed black in monochrome (pins as black dots, slider
blocks as black rectangles), and every Cyrillic and Greek letter printed as a
diamond (LibreCAD has no osifont). `make cad-check` installs LibreCAD and runs
this file; with MMT_CAD_DOCS=folder it also writes LibreCAD's print of both
sheets there as PNG (docs/librecad/)."""

from __future__ import annotations

import os
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest
from click.testing import CliRunner

import ezdxf

from mmt_plans.cli import main
from mmt_plans.render.dxf import TEXT_STYLE, DxfBackend

ROOT = Path(__file__).resolve().parents[2]
LIBRECAD = shutil.which("librecad")
PDFTOPPM = shutil.which("pdftoppm")
pytestmark = pytest.mark.skipif(
    LIBRECAD is None or PDFTOPPM is None,
    reason="LibreCAD or pdftoppm not installed (make cad-check installs librecad and poppler-utils)",
)
MISSING = "\ue000"  # a private-use character: no font has it, LibreCAD draws its diamond


def librecad_print(dxf: Path, dpi: int = 100) -> np.ndarray:
    """LibreCAD's monochrome print of `dxf`, fitted to its page: grey pixels, 0 black."""
    env = dict(os.environ, QT_QPA_PLATFORM="offscreen", XDG_RUNTIME_DIR=str(dxf.parent))
    pdf = dxf.with_suffix(".pdf")
    subprocess.run([LIBRECAD, "dxf2pdf", "-a", "-m", dxf.name], cwd=dxf.parent, env=env,
                   check=True, capture_output=True, timeout=300)
    assert pdf.stat().st_size > 1000, "LibreCAD wrote no page"
    stem = dxf.with_suffix("")
    subprocess.run([PDFTOPPM, "-r", str(dpi), "-gray", "-singlefile", str(pdf), str(stem)],
                   check=True, timeout=120)
    from PIL import Image

    return np.asarray(Image.open(f"{stem}.pgm"))


def ink_box(img: np.ndarray) -> tuple[int, int, int, int]:
    rows, cols = np.nonzero(img < 128)
    return rows.min(), rows.max(), cols.min(), cols.max()


def test_white_masks_do_not_print_black_and_black_fills_do(tmp_path):
    # a page whose frame shows where the drawing went on LibreCAD's fitted page
    b = DxfBackend(100.0, 100.0)
    b.rectangle((0, 0), 100, 100, "thin")
    b.line((0, 50), (100, 50), "main")  # a link ...
    b.circle((50, 50), 4.0, "main", fill="white")  # ... under a pin
    b.line((10, 25), (60, 25), "main")  # a guide ...
    b.rectangle((20, 20), 20, 10, "main", fill="white")  # ... under a slider block
    b.polygon([(70, 70), (90, 75), (70, 80)], line="thin", fill="black")  # an arrowhead
    b.save(tmp_path / "masks.dxf")
    img = librecad_print(tmp_path / "masks.dxf")
    top, bottom, left, right = ink_box(img)

    def pixel(x: float, y: float) -> int:  # page mm -> the print's pixel
        col = left + (right - left) * x / 100.0
        row = bottom - (bottom - top) * y / 100.0
        return int(img[int(round(row)) - 1 : int(round(row)) + 2,
                       int(round(col)) - 1 : int(round(col)) + 2].min())

    assert pixel(80, 75) < 128  # the black fill is black
    for x, y in [(50, 52.5), (50, 47.5), (48, 51), (25, 27.5), (35, 22.5), (30, 28)]:
        assert pixel(x, y) > 200, f"({x}, {y}) mm inside a white mask printed dark"
    assert (img < 128).mean() < 0.05


def sheet_letters(folder: Path) -> set[str]:
    """Every non-ASCII character the sheets' texts and labels show."""
    letters: set[str] = set()
    for dxf in folder.glob("*.dxf"):
        doc = ezdxf.readfile(dxf)
        for e in doc.modelspace().query("TEXT MTEXT"):
            assert e.dxf.style == TEXT_STYLE
            letters |= {ch for ch in (e.dxf.text if e.dxftype() == "TEXT" else e.text)
                        if ord(ch) > 127}
    return letters


def test_every_cyrillic_and_greek_letter_of_the_sheets_prints_as_itself(tmp_path):
    for lang in ("en", "uk"):
        result = CliRunner().invoke(main, ["draw", str(ROOT / "samples" / "six_link_press.toml"),
                                           "--format", "dxf", "--lang", lang,
                                           "-o", str(tmp_path / lang)])
        assert result.exit_code == 0, result.output
    letters = sorted(sheet_letters(tmp_path / "en") | sheet_letters(tmp_path / "uk"))
    assert {"μ", "ω", "ε", "τ", "Ж", "і", "ї", "є"} & set(letters) >= {"μ", "ω", "ε", "і"}
    # each letter alone in a 20 mm cell, as TEXT in the sheets' style; the last
    # cell holds a character no font has: LibreCAD's diamond
    cells = [*letters, MISSING]
    n = int(np.ceil(np.sqrt(len(cells))))
    b = DxfBackend(20.0 * n, 20.0 * n)
    b.rectangle((0, 0), 20.0 * n, 20.0 * n, "thin")
    for i, ch in enumerate(cells):
        b.text((20 * (i % n) + 10, 20 * n - 20 * (i // n) - 10), ch, 7.0,
               anchor="center", valign="middle")
    b.save(tmp_path / "letters.dxf")
    img = librecad_print(tmp_path / "letters.dxf", dpi=150)
    top, bottom, left, right = ink_box(img)
    step_x, step_y = (right - left) / n, (bottom - top) / n

    def glyph(i: int) -> np.ndarray:
        r, c = divmod(i, n)
        cell = img[int(top + r * step_y) + 4 : int(top + (r + 1) * step_y) - 4,
                   int(left + c * step_x) + 4 : int(left + (c + 1) * step_x) - 4] < 128
        rows, cols = np.nonzero(cell)
        assert rows.size, f"{cells[i]!r} printed nothing"
        return cell[rows.min() : rows.max() + 1, cols.min() : cols.max() + 1]

    diamond = glyph(len(cells) - 1)
    shown_as_diamond = [
        ch for i, ch in enumerate(letters)
        if glyph(i).shape == diamond.shape and (glyph(i) != diamond).mean() < 0.1
    ]
    assert not shown_as_diamond, f"LibreCAD has no glyph for {''.join(shown_as_diamond)}"


def test_both_sheets_print_through_librecad(tmp_path):
    result = CliRunner().invoke(main, ["draw", str(ROOT / "samples" / "six_link_press.toml"),
                                       "--format", "dxf", "--lang", "uk", "-o", str(tmp_path)])
    assert result.exit_code == 0, result.output
    docs = os.environ.get("MMT_CAD_DOCS")
    for n in (1, 2):
        doc = ezdxf.readfile(tmp_path / f"sheet{n}.dxf")
        msp = doc.modelspace()
        # every mask a WIPEOUT (test_white_masks_do_not_print_black shows LibreCAD
        # leaves them white); every HATCH the layer's ink (arrowheads)
        assert len(msp.query("WIPEOUT")) > 0
        assert all(h.rgb is None and h.dxf.color == 256 for h in msp.query("HATCH"))
        img = librecad_print(tmp_path / f"sheet{n}.dxf", dpi=150 if docs else 100)
        assert 0.005 < (img < 128).mean() < 0.08  # a drawing, not a blank or black page
        if docs:
            from PIL import Image

            Path(docs).mkdir(parents=True, exist_ok=True)
            Image.fromarray(img).save(Path(docs) / f"librecad_sheet{n}.png", optimize=True)
