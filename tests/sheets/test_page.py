import itertools
import re
import xml.etree.ElementTree as ET

import pytest

from mmt_plans.render import RecordingBackend, SvgBackend
from mmt_plans.sheets import FIELDS, Page, Rect, draw_page, title_block_texts
from mmt_plans.drawing.page import (
    FORM1_CELLS,
    FORM1_COLUMNS,
    FORM1_MAIN_LINES,
    FORM1_THIN_LINES,
    load_title_block_look,
)

FIELDS_UK = {
    "title": "Структурний і кінематичний аналіз важільного механізму",
    "drawing_number": "ТМ 133.КП.01.00.000",
    "author": "Коваленко",
    "checked_by": "Довбуш",
    "date": "05.25",
    "school": "ТНТУ ім. І. Пулюя",
    "group": "гр. ІМ-31",
    "sheet": 1,
    "sheets": 2,
}
FIELDS_EN = {
    "title": "Force analysis of the mechanism",
    "drawing_number": "TM 133.CP.02.00.000",
    "author": "Kovalenko",
    "checked_by": "Dovbush",
    "school": "TNTU",
    "group": "gr. IM-31",
    "sheet": 2,
    "sheets": 2,
}


@pytest.fixture
def a1() -> Page:
    return Page.of("A1")


def test_a_sizes():
    assert (Page.of("A1").width, Page.of("A1").height) == (841, 594)
    assert (Page.of("A4").width, Page.of("A4").height) == (210, 297)
    assert Page.of("a4").landscape().width == 297
    with pytest.raises(ValueError):
        Page.of("B5")


def test_frame_at_20_5_5_5(a1):
    assert a1.frame == Rect.from_bounds(20, 5, 836, 589)


def test_title_block_185_by_55_in_the_bottom_right_corner(a1):
    tb = a1.title_block.rect
    assert (tb.width, tb.height) == (185, 55)
    assert (tb.right, tb.bottom) == (a1.frame.right, a1.frame.bottom)
    assert (tb.left, tb.top) == (651, 60)


def test_standard_column_widths():
    assert FORM1_COLUMNS == (7, 10, 23, 15, 10, 70, 50)
    assert sum(FORM1_COLUMNS) == 185
    header = [FORM1_CELLS[f"header_{c}"] for c in ("change", "change_sheet", "document", "signature", "date")]
    assert [c.width for c in header] == [7, 10, 23, 15, 10]
    assert all(c.height == 5 for c in header)
    assert FORM1_CELLS["title"].width == 70 and FORM1_CELLS["organisation"].width == 50
    assert [FORM1_CELLS[f"letter{i}"].width for i in (1, 2, 3)] == [5, 5, 5]
    assert FORM1_CELLS["mass"].width == 17 and FORM1_CELLS["scale"].width == 18
    assert FORM1_CELLS["sheet"].width == 20 and FORM1_CELLS["sheets"].width == 30
    assert FORM1_CELLS["designation"] == Rect(65, 40, 120, 15)
    # Eleven rows of 5 mm on the left.
    left = sorted({(c.bottom, c.top) for n, c in FORM1_CELLS.items() if c.right <= 65})
    assert left == [(5.0 * i, 5.0 * i + 5) for i in range(11)]


def test_cells_tile_the_block_inside_it(a1):
    block = a1.title_block
    cells = list(block.cells())
    assert all(block.rect.contains(c.rect) for c in cells)
    for a, b in itertools.combinations(cells, 2):
        assert not a.rect.overlaps(b.rect), (a.name, b.name)
    assert sum(c.rect.width * c.rect.height for c in cells) == pytest.approx(185 * 55)


def test_lines_run_inside_the_block_and_along_cell_edges():
    block = Rect(0, 0, 185, 55)
    edges_x = {c.left for c in FORM1_CELLS.values()} | {c.right for c in FORM1_CELLS.values()}
    edges_y = {c.bottom for c in FORM1_CELLS.values()} | {c.top for c in FORM1_CELLS.values()}
    for (x0, y0), (x1, y1) in FORM1_MAIN_LINES + FORM1_THIN_LINES:
        assert block.contains(Rect.from_bounds(min(x0, x1), min(y0, y1), max(x0, x1), max(y0, y1)))
        assert x0 == x1 or y0 == y1
        if x0 == x1:
            assert x0 in edges_x
        else:
            assert y0 in edges_y


def test_every_filled_field_lands_in_its_cell(a1):
    texts = title_block_texts(a1.title_block, FIELDS_UK, "uk")
    contents = {t.content for t in texts}
    assert {"Коваленко", "Довбуш", "ТМ 133.КП.01.00.000", "1", "2", "05.25"} <= contents
    assert "ТНТУ ім. І. Пулюя" in contents and "гр. ІМ-31" in contents
    by_cell = {t.cell: t for t in texts}
    assert by_cell["developed_name"].content == "Коваленко"
    assert by_cell["checked_name"].content == "Довбуш"
    assert by_cell["designation"].size == 7.0
    assert by_cell["developed_name"].size == 3.5


@pytest.mark.parametrize("lang, fields", [("uk", FIELDS_UK), ("en", FIELDS_EN)])
def test_lettering_stays_inside_its_cells(a1, lang, fields):
    b = RecordingBackend()
    draw_page(b, a1, fields, lang)
    block = a1.title_block
    cells = {c.name: c.rect for c in block.cells()}
    for call in b.in_group("title-block"):
        if call.name != "text":
            continue
        x0, y0, x1, y1 = b.text_box(call)
        box = Rect.from_bounds(x0, y0, x1, y1)
        # Every text is wholly inside exactly one cell.
        homes = [name for name, r in cells.items() if r.contains(box, tol=0.05)]
        assert len(homes) == 1, (call["content"], box)
        assert call["size"] in (2.5, 3.5, 5.0, 7.0)


def test_captions_per_language(a1):
    uk = RecordingBackend()
    draw_page(uk, a1, {}, "uk")
    assert {"Розроб.", "Перев.", "Т.контр.", "Н.контр.", "Затв.", "Арк.", "Аркушів", "Літ.", "Маса",
            "Масштаб", "Змн.", "№ докум.", "Підпис", "Дата"} <= set(uk.texts())
    en = RecordingBackend()
    draw_page(en, a1, {}, "en")
    assert {"Drawn", "Checked", "Sheet", "Sheets", "Scale", "Mass", "Date"} <= set(en.texts())
    assert not set(en.texts()) & {"Розроб.", "Масштаб"}


def test_caption_texts_come_from_the_template():
    tb = load_title_block_look()
    assert tb.caption_text("uk", "sheets") == "Аркушів"
    assert (tb.caption, tb.field, tb.title, tb.designation) == (2.5, 3.5, 5.0, 7.0)


def test_unknown_fields_and_languages_are_refused(a1):
    with pytest.raises(ValueError, match="unknown title-block fields"):
        draw_page(RecordingBackend(), a1, {"titel": "x"})
    with pytest.raises(ValueError):
        draw_page(RecordingBackend(), a1, {}, "de")  # type: ignore[arg-type]
    assert "title" in FIELDS and "sheets" in FIELDS


def test_frame_and_block_lines_recorded(a1):
    b = RecordingBackend()
    draw_page(b, a1, FIELDS_UK)
    (frame,) = b.in_group("frame")
    assert frame.name == "polygon" and frame["line"] == "main"
    assert set(frame["points"]) == {(20, 5), (836, 5), (836, 589), (20, 589)}
    lines = [c for c in b.in_group("title-block") if c.name == "line"]
    assert sum(c["line"] == "main" for c in lines) == len(FORM1_MAIN_LINES)
    assert sum(c["line"] == "thin" for c in lines) == len(FORM1_THIN_LINES)
    tb = a1.title_block.rect
    for c in lines:
        for x, y in (c["start"], c["end"]):
            assert tb.left <= x <= tb.right and tb.bottom <= y <= tb.top


def test_frame_in_the_svg(a1):
    b = SvgBackend(a1.width, a1.height)
    draw_page(b, a1, FIELDS_EN, "en")
    root = ET.fromstring(b.to_string().encode("utf-8"))
    ns = {"svg": "http://www.w3.org/2000/svg"}
    assert (root.get("width"), root.get("height")) == ("841mm", "594mm")
    d = root.find(".//svg:g[@id='frame']/svg:path", ns).get("d")
    xy = [float(v) for v in re.findall(r"-?\d+(?:\.\d+)?", d)]
    xs, ys = xy[0::2], xy[1::2]
    # y down in SVG: the frame's top (589 up) is at 5, its bottom (5 up) at 589.
    assert (min(xs), max(xs), min(ys), max(ys)) == (20, 836, 5, 589)
    texts = [t.text for t in root.iter("{http://www.w3.org/2000/svg}text")]
    assert "Kovalenko" in texts and "TM 133.CP.02.00.000" in texts
