"""The Moodle XML quiz: the structure Moodle's importer expects, proper
escaping, absolute tolerances from percent, embedded PNGs, determinism; and
`mmt-plans batch --moodle` over seed-003 task 1."""

from __future__ import annotations

import base64
import re
import struct
import xml.etree.ElementTree as ET
import zlib
from pathlib import Path

import pytest
from click.testing import CliRunner

from mmt_plans.cli import main
from mmt_plans.lms import NumericalAnswer, Quiz, QuizCategory, QuizQuestion, gift, moodle_xml
from mmt_plans.lms.quiz import significant

ROOT = Path(__file__).resolve().parents[2]
CLOZE = re.compile(r"\{1:NUMERICAL:=([^:}]+):([^}]+)\}")


def tiny_png() -> bytes:
    def chunk(kind: bytes, data: bytes) -> bytes:
        return struct.pack(">I", len(data)) + kind + data + struct.pack(
            ">I", zlib.crc32(kind + data) & 0xFFFFFFFF)
    raw = b"\x00\xff\x00\x00"
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", 1, 1, 8, 2, 0, 0, 0))
            + chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))


HOSTILE = "<script>&\"'`]]>{1:NUMERICAL:=0}}#~ שלום 😀\x00\x07"


def quiz(text: str = "task", value: float = 2.5) -> Quiz:
    answers = (NumericalAnswer(f"V_E {text}", value, "m/s", 5.0),
               NumericalAnswer("R01", -1234.5, "N", 5.0),
               NumericalAnswer("eps1", 0.0, "rad/s²", 5.0, zero_tolerance=0.01))
    q = QuizQuestion(name=f"v1 {text}", title=f"Title {text}", given=((f"l1 {text}", "200 mm"),),
                     answers=answers, image_png=tiny_png(), image_alt=text)
    return Quiz(name=f"keys {text}", categories=(QuizCategory(f"Task 1 {text}", (q,)),),
                given_heading="Given", find_heading="Find")


def test_cloze_structure_tolerances_and_image():
    data = moodle_xml(quiz())
    root = ET.fromstring(data)
    assert root.tag == "quiz"
    kinds = [q.get("type") for q in root.findall("question")]
    assert kinds == ["category", "cloze"]
    assert root.find("question/category/text").text.startswith("$course$/top/")
    q = root.findall("question")[1]
    text = q.find("questiontext/text").text
    subs = CLOZE.findall(text)
    assert len(subs) == 3
    # issue 24: answers rounded to 4 significant figures (halves away from zero),
    # the tolerance from the rounded value
    for (v, t), (value, pct) in zip(subs, [(2.5, 5), (-1235.0, 5), (0.0, None)]):
        assert float(v) == value
        assert float(t) == (abs(value) * pct / 100 if pct else 0.01)
    f = q.find("questiontext/file")
    assert f.get("encoding") == "base64" and f.get("path") == "/"
    assert base64.b64decode(f.text) == tiny_png()
    assert f"@@PLUGINFILE@@/{f.get('name')}" in text
    assert q.find("penalty") is not None and q.find("hidden").text == "0"


def test_numerical_kind():
    root = ET.fromstring(moodle_xml(quiz(), kind="numerical"))
    qs = [q for q in root.findall("question") if q.get("type") == "numerical"]
    assert len(qs) == 3
    first = qs[0]
    assert first.find("answer").get("fraction") == "100"
    assert float(first.find("answer/text").text) == 2.5
    assert float(first.find("answer/tolerance").text) == pytest.approx(0.125)
    assert first.find("units/unit/unit_name").text == "m/s"


def test_hostile_text_cannot_break_the_xml_or_add_subquestions():
    data = moodle_xml(quiz(HOSTILE))
    root = ET.fromstring(data)  # well formed
    q = root.findall("question")[1]
    text = q.find("questiontext/text").text
    assert len(CLOZE.findall(text)) == 3  # the injected "{1:NUMERICAL:=0}" is neutralised
    assert "<script>" not in text and "&lt;script&gt;" in text
    assert "שלום" in text and "😀" in text and "\x00" not in text and "\x07" not in text
    assert q.find("name/text").text == "v1 " + HOSTILE.replace("\x00", "").replace("\x07", "")


def test_bad_values_are_refused():
    for bad in (float("nan"), float("inf")):
        with pytest.raises(ValueError):
            moodle_xml(quiz(value=bad))
    with pytest.raises(ValueError):
        NumericalAnswer("x", 1.0, "m", 0.0).tolerance()


def test_deterministic_and_gift_escaped():
    assert moodle_xml(quiz()) == moodle_xml(quiz())
    text = gift(quiz("a:b{c}=d#e~f"))
    assert text.startswith("$CATEGORY: $course$/top/")
    assert "a\\:b\\{c\\}\\=d\\#e\\~f" in text
    assert len(re.findall(r"\{#[^}]+:[^}]+\}", text)) == 3


def test_batch_moodle_over_task_1(tmp_path):
    files = sorted(str(p) for p in (ROOT / "samples" / "tasks" / "seed003").glob("task01_v*.toml"))
    result = CliRunner().invoke(main, ["batch", *files, "-o", str(tmp_path), "--moodle",
                                       "--format", "svg", "--jobs", "1"])
    assert result.exit_code == 0, result.output
    root = ET.parse(tmp_path / "quiz.xml").getroot()
    cats = [q for q in root.findall("question") if q.get("type") == "category"]
    cloze = [q for q in root.findall("question") if q.get("type") == "cloze"]
    assert len(cats) == 1 and len(cloze) == len(files)
    for q in cloze:
        text = q.find("questiontext/text").text
        subs = CLOZE.findall(text)
        assert len(subs) >= 6  # V and a at two positions, ω and ε of two links, F_bal, R01
        for v, t in subs:
            # the tolerance is 5 % of the rounded answer, written to 6 significant figures
            assert float(t) == significant(abs(float(v)) * 0.05, 6)
            assert len(v.lstrip("-").replace(".", "").lstrip("0").rstrip("0")) <= 4
        assert base64.b64decode(q.find("questiontext/file").text).startswith(b"\x89PNG")
