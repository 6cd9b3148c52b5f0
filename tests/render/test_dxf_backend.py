"""DxfBackend: every check reads the written bytes back with ezdxf."""

import io
import math
import os
import subprocess
import sys
from collections import Counter
from pathlib import Path

import pytest

import ezdxf
from ezdxf.enums import TextEntityAlignment

from mmt_plans.render import RecordingBackend, arrow_geometry, load_look
from mmt_plans.render.dxf import DxfBackend, nearest_lineweight

ROOT = Path(__file__).resolve().parents[2]
LAYER = {"main": "MAIN", "thin": "THIN", "dashed": "DASHED", "dashdot": "DASHDOT"}
BYLAYER_COLOUR, BYLAYER_WEIGHT = 256, -1


def read(data: bytes):
    return ezdxf.read(io.TextIOWrapper(io.BytesIO(data), encoding="utf-8"))


def raw_header(data: bytes, var: str) -> str:
    """The first value written after header variable `var`, straight from the
    bytes (ezdxf.read itself sets $TDCREATE to the time of reading)."""
    lines = data.decode("utf-8").split("\n")
    for code, value, next_code, next_value in zip(lines[::2], lines[1::2], lines[2::2], lines[3::2]):
        if code.strip() == "9" and value == var:
            return next_value
    raise KeyError(var)


def readback(b: DxfBackend):
    return read(b.to_bytes())


def clean_audit(doc) -> None:
    auditor = doc.audit()
    assert [e.message for e in auditor.errors] == []
    assert [e.message for e in auditor.fixes] == []


def test_each_primitive_makes_its_entity_on_its_layer():
    b = DxfBackend()
    b.line((20, 5), (836, 589), "main")
    b.polyline([(1, 2), (3, 4), (5, 2)], "thin")
    b.polygon([(10, 10), (40, 10), (25, 30)], "dashed")
    b.circle((100, 200), 7.5, "dashdot")
    b.arc((300, 300), 20, 350, 30, "thin")  # counter-clockwise through 0 deg
    doc = readback(b)
    clean_audit(doc)
    msp = doc.modelspace()
    assert [e.dxftype() for e in msp] == ["LINE", "LWPOLYLINE", "LWPOLYLINE", "CIRCLE", "ARC"]
    line, poly, gon, circle, arc = msp
    assert [e.dxf.layer for e in msp] == ["MAIN", "THIN", "DASHED", "DASHDOT", "THIN"]
    for e in msp:  # every property from the layer
        assert e.dxf.color == BYLAYER_COLOUR
        assert e.dxf.linetype.upper() == "BYLAYER"
        assert e.dxf.lineweight == BYLAYER_WEIGHT
    assert tuple(line.dxf.start)[:2] == (20, 5) and tuple(line.dxf.end)[:2] == (836, 589)
    assert list(poly.vertices()) == [(1, 2), (3, 4), (5, 2)] and not poly.closed
    assert list(gon.vertices()) == [(10, 10), (40, 10), (25, 30)] and gon.closed
    assert tuple(circle.dxf.center)[:2] == (100, 200) and circle.dxf.radius == 7.5
    assert tuple(arc.dxf.center)[:2] == (300, 300) and arc.dxf.radius == 20
    assert (arc.dxf.start_angle, arc.dxf.end_angle) == (350, 30)
    # ezdxf's own construction tool agrees the arc runs ccw from 350 to 30 deg.
    assert arc.construction_tool().angle_span == pytest.approx(40)


def test_arc_special_spans():
    b = DxfBackend()
    b.arc((0, 0), 5, 30, 30)  # nothing
    b.arc((0, 0), 5, 30, 390)  # a full turn: a circle
    b.arc((0, 0), 5, -90, 90)
    msp = readback(b).modelspace()
    assert [e.dxftype() for e in msp] == ["CIRCLE", "ARC"]
    assert (msp[1].dxf.start_angle, msp[1].dxf.end_angle) == (270, 90)


def test_black_fills_are_hatches_white_fills_are_wipeouts_under_their_outlines():
    # issue 24: a white mask is a WIPEOUT (DXF's mask, the background colour in
    # monochrome output too), not a true-colour white HATCH that LibreCAD prints black
    b = DxfBackend()
    b.line((0, 50), (100, 50), "main")  # a link ...
    b.circle((50, 50), 2.0, "main", fill="white")  # ... and a pin over it
    b.polygon([(10, 10), (20, 10), (15, 18)], line=None, fill="black")
    b.arrow((0, 0), (30, 40))
    doc = readback(b)
    clean_audit(doc)
    msp = doc.modelspace()
    assert [e.dxftype() for e in msp] == [
        "LINE", "WIPEOUT", "CIRCLE", "HATCH", "LINE", "HATCH", "LWPOLYLINE"
    ]
    link, white, pin, black, shaft, head, head_outline = msp
    for hatch in (black, head):
        assert hatch.dxf.layer == "FILL"
        assert hatch.dxf.solid_fill == 1 and hatch.dxf.pattern_name == "SOLID"
        assert len(hatch.paths) == 1
    assert not any(h.rgb == (255, 255, 255) for h in msp.query("HATCH"))
    # The mask: after the link, before its rim; a 64-gon inscribed in the pin's circle.
    assert white.dxf.layer == "FILL"
    corners = white.boundary_path_wcs()
    assert len(corners) >= 64
    assert all(math.hypot(v.x - 50, v.y - 50) == pytest.approx(2.0) for v in corners)
    assert doc.objects.query("WIPEOUTVARIABLES")[0].dxf.frame == 0  # no frame drawn
    # Black is the layer's ink.
    assert black.dxf.color == BYLAYER_COLOUR and black.rgb is None
    assert [tuple(v)[:2] for v in black.paths[0].vertices] == [(10, 10), (20, 10), (15, 18)]
    # The arrow: a shaft to the head's base, the head a filled triangle with a thin rim.
    shaft_end, tri = arrow_geometry((0, 0), (30, 40), 5.0, 1.6)
    assert tuple(shaft.dxf.end)[:2] == pytest.approx(shaft_end)
    got = [c for v in head.paths[0].vertices for c in tuple(v)[:2]]
    assert got == pytest.approx([c for p in tri for c in p])
    assert head_outline.dxf.layer == "THIN" and head_outline.closed


def test_units_limits_and_extents():
    b = DxfBackend(841, 594)
    b.line((20, 5), (836, 589))
    b.circle((400, 300), 10)
    doc = readback(b)
    h = doc.header
    assert doc.dxfversion == "AC1024"  # R2010
    assert h["$INSUNITS"] == 4 and h["$MEASUREMENT"] == 1
    assert tuple(h["$LIMMIN"])[:2] == (0, 0) and tuple(h["$LIMMAX"])[:2] == (841, 594)
    assert tuple(h["$EXTMIN"])[:2] == (20, 5) and tuple(h["$EXTMAX"])[:2] == (836, 589)
    empty = readback(DxfBackend(841, 594)).header  # nothing drawn: the page
    assert tuple(empty["$EXTMIN"])[:2] == (0, 0) and tuple(empty["$EXTMAX"])[:2] == (841, 594)


def test_linetypes_and_lineweights_from_the_look():
    look = load_look()
    doc = readback(DxfBackend(look=look))
    weights = {kind: doc.layers.get(LAYER[kind]).dxf.lineweight for kind in LAYER}
    assert weights == {"main": 70, "thin": 35, "dashed": 35, "dashdot": 35}
    assert doc.layers.get("MAIN").dxf.linetype.upper() == "CONTINUOUS"
    dashed = doc.linetypes.get(doc.layers.get("DASHED").dxf.linetype)
    assert tuple(dashed.simplified_line_pattern()) == pytest.approx(look.line("dashed").dash)
    dashdot = doc.linetypes.get(doc.layers.get("DASHDOT").dxf.linetype)
    dash, gap, dot, gap2 = dashdot.simplified_line_pattern()
    # A DXF dot has no length: the look's 0.5 mm dot goes to the gaps, the period stays.
    assert (dash, dot, gap) == pytest.approx((15.0, 0.0, gap2))
    assert dash + gap + dot + gap2 == pytest.approx(sum(look.line("dashdot").dash))
    # Another look, other weights (the nearest valid DXF lineweights).
    heavy = look.with_changes(lines={**look.lines, "main": look.line("main").__class__(1.0)})
    assert readback(DxfBackend(look=heavy)).layers.get("MAIN").dxf.lineweight == 100
    assert [nearest_lineweight(w) for w in (0.18, 0.36, 0.68, 5.0)] == [18, 35, 70, 211]


def test_text_height_style_alignment_rotation():
    look = load_look()
    b = DxfBackend(look=look)
    b.text((100, 200), "pa = 120 mm", 5.0)
    b.text((50, 60), "μ_V", 3.5, anchor="center", valign="middle", rotation=30)
    long = "Кінематичний аналіз шестиланкового механізму"
    b.text((400, 20), long, 7.0, anchor="right", valign="top", max_width=100, rotation=-90)
    doc = readback(b)
    # issue 24: a style LibreCAD resolves by name to its GOST font with
    # Cyrillic and Greek; a TrueType file with both for the other programs
    style = doc.styles.get("OpenGostTypeA-Regular")
    assert style.dxf.font == "DejaVuSans.ttf" and style.dxf.oblique == 15
    texts = doc.modelspace().query("TEXT")
    assert [t.dxf.text for t in texts] == ["pa = 120 mm", "μ_V", long]
    for t in texts:
        assert t.dxf.layer == "TEXT" and t.dxf.style == "OpenGostTypeA-Regular"
        assert t.dxf.oblique == 15
    assert [t.dxf.height for t in texts] == [5.0, 3.5, 7.0]
    assert [t.dxf.rotation for t in texts] == [0, 30, 270]
    placements = [t.get_placement() for t in texts]
    assert [p[0] for p in placements] == [
        TextEntityAlignment.LEFT, TextEntityAlignment.MIDDLE_CENTER, TextEntityAlignment.TOP_RIGHT
    ]
    assert [tuple(p[1])[:2] for p in placements] == [(100, 200), (50, 60), (400, 20)]
    squeeze = look.lettering.squeeze(long, 7.0, 100)
    assert squeeze < 1.0
    assert [t.dxf.width for t in texts] == [1.0, 1.0, pytest.approx(squeeze)]


def test_a_label_with_indices_is_one_mtext_with_stacked_indices():
    # issue 24: separate TEXTs for "p", "5" placed by osifont's widths collide
    # in a program without osifont ("2p₅ – p₄"); one MTEXT keeps them together
    b = DxfBackend()
    width = b.rich_text((100, 50), "ω_2 = 1,5 с^{-1}", 5.0, anchor="center", valign="middle")
    b.rich_text((10, 10), "a^τ_{ED} {x}\\", 3.5, rotation=90)
    b.rich_text((10, 20), "V_{a;b}", 3.5)  # an index with a stack's separator stays inline
    doc = readback(b)
    clean_audit(doc)
    texts = doc.modelspace().query("MTEXT")
    assert len(texts) == 3 and not doc.modelspace().query("TEXT")
    first, second, third = texts
    assert first.text == "ω\\S^2; = 1,5 с\\S-1^;"
    assert first.dxf.attachment_point == 5 and first.dxf.char_height == 5.0
    assert tuple(first.dxf.insert)[:2] == (100, 50)
    assert width == pytest.approx(DxfBackend().rich_text((0, 0), "ω_2 = 1,5 с^{-1}", 5.0))
    # a baseline label hangs by its capitals' middle, half a height up the rotated text
    assert second.dxf.attachment_point == 4 and second.dxf.rotation == 90
    assert tuple(second.dxf.insert)[:2] == pytest.approx((10 - 1.75, 10))
    assert second.text == "a\\Sτ^;\\S^ED; \\{x\\}\\\\"
    assert third.text == "Va;b"


def test_hostile_text_and_title_round_trip_without_breaking_the_file(tmp_path):
    title = "<b>&\"' ]]> Лист 1"
    hostile = [
        "<b>&\"'",
        "]]>",
        "שלום עולם مرحبا",  # right to left
        "🛠️ 👩‍🔧 ok",  # emoji with a variation selector and a joiner
        "a\nb\r\x00c\x1bd\x7fe\u2028f",  # control characters and a line separator
        "^2 50%%d 10%",  # a caret and a %%d that must stay literal
    ]
    b = DxfBackend(title=title)
    for i, s in enumerate(hostile):
        b.text((10, 10 + 10 * i), s)
    data = b.save(tmp_path / "hostile.dxf").read_bytes()
    assert data == b.to_bytes()
    data.decode("utf-8")  # valid UTF-8
    doc = ezdxf.readfile(tmp_path / "hostile.dxf")
    clean_audit(doc)
    assert doc.header.custom_vars.get("Title") == title
    got = [t.dxf.text for t in doc.modelspace().query("TEXT")]
    assert got[:4] == hostile[:4]
    assert got[4] == "a b cde f"  # line ends became spaces, other controls went
    # DXF caret notation ("^ " is a caret) and AutoCAD's "%%%" for a percent sign
    # where "%%" would otherwise start a code (%%d is a degree sign).
    assert got[5] == "^ 2 50%%%%%%d 10%%%"
    # Nothing after the texts was swallowed: the file still ends properly.
    assert data.rstrip().endswith(b"EOF")


def test_groups_are_named_unique_and_nested():
    b = DxfBackend()
    with b.group("velocity plan", "plan"):
        b.line((0, 0), (10, 0))
        with b.group("pole"):
            b.circle((0, 0), 1.0, fill="black")
    with b.group("Velocity-Plan"):  # DXF group names ignore case
        b.line((5, 5), (6, 6))
    with b.group("empty"):
        pass
    b.text((1, 1), "outside")
    doc = readback(b)
    clean_audit(doc)
    groups = {name: sorted(e.dxftype() for e in g) for name, g in doc.groups}
    assert groups == {
        "velocity-plan": ["CIRCLE", "HATCH", "LINE"],  # the nested group's entities too
        "pole": ["CIRCLE", "HATCH"],
        "Velocity-Plan-2": ["LINE"],  # no group "empty": nothing was drawn in it
    }
    assert doc.groups.get("velocity-plan").dxf.description == "plan"
    with pytest.raises(RuntimeError):
        DxfBackend().end_group()
    unclosed = DxfBackend()
    unclosed.begin_group("open")
    with pytest.raises(RuntimeError):
        unclosed.to_bytes()


def draw_sample(b: DxfBackend) -> bytes:
    b.polyline([(1 / 3, 2 / 3), (100.123456, 200.987654), (5, 5)], "thin")
    b.arc((100, 100), 25.55555, 10, 200, "dashdot")
    b.text((50.00001, 60.4444444), "pa = 120 mm", 3.5, anchor="center", rotation=30)
    with b.group("plan"):
        b.circle((1, 1), 0.5, fill="white")
        b.arrow((0, 0), (10, 10))
    return b.to_bytes()


def test_output_is_byte_reproducible(monkeypatch):
    monkeypatch.delenv("SOURCE_DATE_EPOCH", raising=False)
    first = draw_sample(DxfBackend(title="sheet 1"))
    assert first == draw_sample(DxfBackend(title="sheet 1"))
    stamps = ("$TDCREATE", "$TDUCREATE", "$TDUPDATE", "$TDUUPDATE")
    assert {raw_header(first, v) for v in stamps} == {"2451545.0"}  # 2000-01-01 00:00
    assert raw_header(first, "$TDINDWG") == raw_header(first, "$TDUSRTIMER") == "0.0"
    guids = [raw_header(first, v) for v in ("$FINGERPRINTGUID", "$VERSIONGUID")]
    assert len(set(guids)) == 2 and "{00000000-0000-0000-0000-000000000000}" not in guids
    monkeypatch.setenv("SOURCE_DATE_EPOCH", "1700000000")  # 2023-11-14 22:13:20 UTC
    dated = draw_sample(DxfBackend(title="sheet 1"))
    assert dated == draw_sample(DxfBackend(title="sheet 1")) != first
    for v in stamps:
        assert float(raw_header(dated, v)) == pytest.approx(2460263 + (22 * 3600 + 13 * 60 + 20) / 86400)
    assert raw_header(dated, "$FINGERPRINTGUID") == guids[0]
    assert b"2023-11-14T22:13:20" in dated and b"2000-01-01" not in dated
    monkeypatch.setenv("SOURCE_DATE_EPOCH", "yesterday")
    with pytest.raises(ValueError):
        DxfBackend().to_bytes()


def test_output_does_not_depend_on_the_hash_seed():
    code = (
        "import sys, hashlib\n"
        "sys.path.insert(0, sys.argv[1])\n"
        "from test_dxf_backend import draw_sample\n"
        "from mmt_plans.render.dxf import DxfBackend\n"
        "print(hashlib.sha256(draw_sample(DxfBackend())).hexdigest())\n"
    )
    digests = set()
    for seed in ("1", "4"):  # ezdxf's CLASS order came from a set, seeds 1 and 4 differed
        env = {**os.environ, "PYTHONHASHSEED": seed}
        out = subprocess.run(
            [sys.executable, "-c", code, str(Path(__file__).parent)],
            env=env, cwd=ROOT, capture_output=True, text=True, check=True,
        )
        digests.add(out.stdout.strip())
    assert len(digests) == 1


def test_only_the_dxf_module_imports_ezdxf():
    users = [
        p.relative_to(ROOT).as_posix()
        for p in (ROOT / "mmt_plans").rglob("*.py")
        if any(
            line.lstrip().startswith(("import ezdxf", "from ezdxf"))
            for line in p.read_text(encoding="utf-8").splitlines()
        )
    ]
    assert users == ["mmt_plans/render/dxf.py"]


def groups_with_drawing(rec: RecordingBackend) -> int:
    """How many of the recorded groups have something drawn in them (at any depth)."""
    open_: list[bool] = []
    count = 0
    for c in rec.calls:
        if c.name == "begin_group":
            open_.append(False)
        elif c.name == "end_group":
            count += open_.pop()
        else:
            open_ = [True] * len(open_)
    return count


def test_sheet1_entities_match_the_recorded_calls():
    import mmt_plans
    from mmt_plans.sheets.sheet1 import compose_sheet1

    class Recorder(RecordingBackend):
        """Counts the labels with indices and the texts they are made of."""

        sets_labels_whole = True  # the sketches' labels come back as rich_text, as to DXF
        labels = inside = 0

        def rich_text(self, pos, content, size=3.5, **kw):
            before = len(self.named("text"))
            width = super().rich_text(pos, content, size, **kw)
            made = len(self.named("text")) - before
            type(self).labels += made > 0
            type(self).inside += made
            return width

    analysis = mmt_plans.solve(mmt_plans.load(ROOT / "samples" / "six_link_press.toml"))
    rec, dxf = Recorder(), DxfBackend()
    compose_sheet1(analysis, rec)
    compose_sheet1(analysis, dxf)
    doc = readback(dxf)
    clean_audit(doc)
    got = Counter(e.dxftype() for e in doc.modelspace())

    calls = Counter(c.name for c in rec.calls)
    arrows = rec.named("arrow")
    shafts = sum(arrow_geometry(a["start"], a["end"], a["head_length"], a["head_width"])[0]
                 != a["start"] for a in arrows)
    filled = [c for c in rec.named("polygon", "circle") if c["fill"] != "none"]
    # a label with indices is one MTEXT, its runs are not separate TEXTs (issue 24)
    assert got["MTEXT"] == Recorder.labels > 0
    assert got["TEXT"] == calls["text"] - Recorder.inside > 0
    assert got["LINE"] == calls["line"] + shafts
    assert got["ARC"] == calls["arc"]
    assert got["CIRCLE"] == sum(c["line"] is not None for c in rec.named("circle"))
    assert got["LWPOLYLINE"] == calls["polyline"] + calls["polygon"] + len(arrows)
    white = [c for c in filled if c["fill"] == "white"]
    assert got["WIPEOUT"] == len(white) > 0
    assert got["HATCH"] == len(filled) - len(white) + len(arrows)
    assert len(doc.groups) == groups_with_drawing(rec) > 0

    h = doc.header
    (x0, y0, _), (x1, y1, _) = h["$EXTMIN"], h["$EXTMAX"]
    assert 0 <= x0 < x1 <= 841 and 0 <= y0 < y1 <= 594
    assert tuple(h["$LIMMAX"])[:2] == (841, 594)
    for e in doc.modelspace().query("LINE"):
        for p in (e.dxf.start, e.dxf.end):
            assert 0 <= p.x <= 841 and 0 <= p.y <= 594
    assert all(0 <= t.dxf.insert.x <= 841 and 0 <= t.dxf.insert.y <= 594
               for t in doc.modelspace().query("TEXT"))
