import re
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from mmt_plans.render import SvgBackend

NS = {"svg": "http://www.w3.org/2000/svg"}
PACKAGE = Path(__file__).resolve().parents[2] / "mmt_plans"


def parse(backend: SvgBackend) -> ET.Element:
    return ET.fromstring(backend.to_string().encode("utf-8"))


def numbers(d: str) -> list[float]:
    return [float(n) for n in re.findall(r"-?\d+(?:\.\d+)?", d)]


def test_page_is_a1_in_millimetres():
    root = parse(SvgBackend())
    assert root.get("width") == "841mm"
    assert root.get("height") == "594mm"
    assert root.get("viewBox") == "0 0 841 594"
    paper = root.find("svg:rect[@id='paper']", NS)
    assert paper is not None and (paper.get("width"), paper.get("height")) == ("841", "594")


def test_y_up_becomes_y_down():
    b = SvgBackend()
    b.line((20, 5), (836, 589))
    line = parse(b).find(".//svg:line", NS)
    assert [float(line.get(k)) for k in ("x1", "y1", "x2", "y2")] == [20, 589, 836, 5]


def test_line_types_give_weights_and_dashes():
    b = SvgBackend()
    for kind in ("main", "thin", "dashed", "dashdot"):
        b.line((0, 0), (10, 0), kind)
    lines = {el.get("class"): el for el in parse(b).iter("{http://www.w3.org/2000/svg}line")}
    assert float(lines["main"].get("stroke-width")) == pytest.approx(0.7)
    assert float(lines["thin"].get("stroke-width")) == pytest.approx(0.35)
    assert lines["main"].get("stroke-dasharray") is None
    assert numbers(lines["dashed"].get("stroke-dasharray")) == [5, 1.5]
    assert len(numbers(lines["dashdot"].get("stroke-dasharray"))) == 4


def test_fixed_precision_and_repeatable_output():
    def draw() -> str:
        b = SvgBackend(title="sheet 1")
        b.polyline([(1 / 3, 2 / 3), (100.123456, 200.987654), (5, 5)], "thin")
        b.arc((100, 100), 25.55555, 10, 200, "dashdot")
        b.text((50.00001, 60.4444444), "pa = 120 mm", 3.5, anchor="center", rotation=30)
        with b.group("plan"):
            b.circle((1, 1), 0.5)
        return b.to_string()

    first, second = draw(), draw()
    assert first == second
    body = first.split("?>", 1)[1]
    assert not re.search(r"\d\.\d{4,}", body)


def test_group_ids_are_counted_per_document():
    def ids() -> list[str]:
        b = SvgBackend()
        for _ in range(3):
            with b.group("velocity plan", "plan"):
                b.line((0, 0), (1, 1))
        with b.group("1st"):
            pass
        with b.group("sheet"):
            pass
        return [g.get("id") for g in parse(b).iter("{http://www.w3.org/2000/svg}g")]

    assert ids() == ["sheet", "velocity-plan", "velocity-plan-2", "velocity-plan-3", "g-1st", "sheet-2"]
    assert ids() == ids()


def test_arc_counter_clockwise_with_y_up():
    b = SvgBackend(100, 100)
    b.arc((50, 50), 10, 0, 90)
    d = parse(b).find(".//svg:path", NS).get("d")
    # From (60, 50) up to (50, 60) on paper: in SVG from (60, 50) to (50, 40),
    # small arc, sweep flag 0.
    assert numbers(d) == [60, 50, 10, 10, 0, 0, 0, 50, 40]


def test_text_carries_size_anchor_and_slant():
    b = SvgBackend()
    b.text((100, 100), "Масштаб", 5.0, anchor="right", valign="top", rotation=90)
    text = parse(b).find(".//svg:text", NS)
    assert text.text == "Масштаб"
    assert text.get("text-anchor") == "end"
    assert float(text.get("font-size")) == pytest.approx(5.0 / b.look.lettering.cap_height, abs=1e-3)
    transform = text.get("transform")
    assert "rotate(-90)" in transform and "skewX(-15)" in transform


def test_text_squeezed_to_max_width():
    b = SvgBackend()
    natural = b.look.lettering.natural_width("Розроблено", 3.5)
    b.text((0, 0), "Розроблено", 3.5, max_width=natural * 0.8)
    transform = parse(b).find(".//svg:text", NS).get("transform")
    assert "scale(0.8 1)" in transform


def test_font_family_lists_osifont_then_a_cyrillic_fallback():
    sheet = parse(SvgBackend()).find("svg:g[@id='sheet']", NS)
    families = [f.strip(" '") for f in sheet.get("font-family").split(",")]
    assert families[0] == "osifont"
    assert "DejaVu Sans Condensed" in families


def test_only_svg_module_imports_svgwrite():
    users = sorted(
        p.relative_to(PACKAGE).as_posix()
        for p in PACKAGE.rglob("*.py")
        if re.search(r"^\s*(import svgwrite|from svgwrite)", p.read_text(encoding="utf-8"), re.M)
    )
    assert users == ["render/svg.py"]


def test_the_text_is_svgwrites_own_serialisation():
    """to_string() is svgwrite's tostring() of the same drawing (written as
    unicode rather than through a UTF-8 codec): escapes, non-ASCII letters
    and the attributes' order alike."""
    b = SvgBackend(100.0, 80.0, title="a < b & 'c' — ω")
    with b.group("plan & ω", "plan"):
        b.line((1.0, 2.0), (30.5, 40.25), "thin")
        b.polygon([(1.0, 1.0), (5.0, 1.0), (3.0, 4.0)], "main", "black")
        b.circle((10.0, 10.0), 2.5, None, "white")
        b.arc((20.0, 20.0), 5.0, 10.0, 250.0, "dashed")
        b.text((5.0, 5.0), 'V<sub> & "μ" ↑ Ї', 3.5, anchor="center", rotation=30.0)
    text = b.to_string()
    assert text == '<?xml version="1.0" encoding="utf-8" ?>\n' + b._dwg.tostring() + "\n"
    assert "&lt;" in text and "&amp;" in text and "μ" in text and "Ї" in text
