"""Moodle XML and GIFT quiz files (Moodle's "Moodle XML format" and "GIFT
format" import), built with ElementTree and escaped by the writer.

One category per task, one question per variant: with kind "cloze" (the
default) a multi-answer question whose text holds the given data, the
variant's scheme (a PNG embedded as base64, `@@PLUGINFILE@@`) and one
NUMERICAL sub-question per quantity; with kind "numerical", one numerical
question per quantity. Tolerances are given in percent and written as Moodle's
absolute tolerances, |value|·percent/100; an exact value of zero gets the
tolerance `zero_tolerance` of its answer (Moodle cannot take a relative
tolerance of zero).
"""

from __future__ import annotations

import base64
import html
import math
import re
import xml.etree.ElementTree as ET
from dataclasses import dataclass

__all__ = ["NumericalAnswer", "QuizQuestion", "QuizCategory", "Quiz", "moodle_xml", "gift"]

# characters XML 1.0 does not allow (C0 controls but tab, newline, return; U+FFFE, U+FFFF)
_NOT_XML = re.compile("[\x00-\x08\x0b\x0c\x0e-\x1f\ufffe\uffff]")


def clean(text: str) -> str:
    """Text with the characters XML cannot carry removed."""
    return _NOT_XML.sub("", str(text))


@dataclass(frozen=True)
class NumericalAnswer:
    label: str  # plain text before the box: "V_E, position 2"
    value: float
    unit: str
    tolerance_percent: float
    zero_tolerance: float = 1e-9  # the absolute tolerance of an exact zero

    def tolerance(self) -> float:
        if not (math.isfinite(self.value) and math.isfinite(self.tolerance_percent)):
            raise ValueError(f"{self.label}: value and tolerance must be finite")
        if not self.tolerance_percent > 0:
            raise ValueError(f"{self.label}: the tolerance must be positive")
        tol = abs(self.value) * self.tolerance_percent / 100.0
        return tol if tol > 0 else self.zero_tolerance


@dataclass(frozen=True)
class QuizQuestion:
    name: str
    title: str
    given: tuple[tuple[str, str], ...]  # (label, value text) of the initial data
    answers: tuple[NumericalAnswer, ...]
    image_png: bytes | None = None
    image_alt: str = ""


@dataclass(frozen=True)
class QuizCategory:
    name: str
    questions: tuple[QuizQuestion, ...]


@dataclass(frozen=True)
class Quiz:
    name: str
    categories: tuple[QuizCategory, ...]
    given_heading: str
    find_heading: str


def _number(x: float) -> str:
    return repr(float(x)) if math.isfinite(x) else "nan"


def _cloze_text(text: str) -> str:
    """Plain text inside a cloze question: its braces cannot open a sub-question."""
    return text.replace("{", "&#123;").replace("}", "&#125;")


def _html(q: QuizQuestion, quiz: Quiz, file_name: str | None, cloze: bool) -> str:
    def esc(text: str) -> str:
        escaped = html.escape(clean(text))
        return _cloze_text(escaped) if cloze else escaped

    parts = [f"<p><b>{esc(q.title)}</b></p>"]
    if file_name:
        parts.append(f'<p><img src="@@PLUGINFILE@@/{file_name}" alt="{esc(q.image_alt)}"></p>')
    parts.append(f"<p>{esc(quiz.given_heading)}</p><table>")
    parts += [f"<tr><td>{esc(k)}</td><td>{esc(v)}</td></tr>" for k, v in q.given]
    parts.append(f"</table><p>{esc(quiz.find_heading)}</p>")
    if cloze:
        for a in q.answers:
            sub = f"{{1:NUMERICAL:={_number(a.value)}:{_number(a.tolerance())}}}"
            parts.append(f"<p>{esc(a.label)} = {sub} {esc(a.unit)}</p>")
    return "".join(parts)


def _text(parent: ET.Element, tag: str, text: str, **attrs: str) -> ET.Element:
    el = ET.SubElement(parent, tag, attrs)
    ET.SubElement(el, "text").text = clean(text)
    return el


def _file(parent: ET.Element, q: QuizQuestion) -> str | None:
    if q.image_png is None:
        return None
    name = f"{re.sub(r'[^A-Za-z0-9_.-]', '_', q.name)}.png"
    f = ET.SubElement(parent, "file", {"name": name, "path": "/", "encoding": "base64"})
    f.text = base64.b64encode(q.image_png).decode("ascii")
    return name


def moodle_xml(quiz: Quiz, *, kind: str = "cloze") -> bytes:
    """The quiz as a Moodle XML file (UTF-8 bytes, the same for the same quiz)."""
    if kind not in ("cloze", "numerical"):
        raise ValueError(f"kind must be 'cloze' or 'numerical', not {kind!r}")
    root = ET.Element("quiz")
    for cat in quiz.categories:
        c = ET.SubElement(root, "question", {"type": "category"})
        _text(c, "category", f"$course$/top/{clean(quiz.name)}/{clean(cat.name)}")
        for q in cat.questions:
            if kind == "cloze":
                el = ET.SubElement(root, "question", {"type": "cloze"})
                _text(el, "name", q.name)
                qt = ET.SubElement(el, "questiontext", {"format": "html"})
                text = ET.SubElement(qt, "text")
                file_name = _file(qt, q)
                text.text = clean(_html(q, quiz, file_name, cloze=True))
                _text(el, "generalfeedback", "", format="html")
                ET.SubElement(el, "penalty").text = "0.3333333"
                ET.SubElement(el, "hidden").text = "0"
                continue
            for a in q.answers:
                el = ET.SubElement(root, "question", {"type": "numerical"})
                _text(el, "name", f"{q.name} – {a.label}")
                qt = ET.SubElement(el, "questiontext", {"format": "html"})
                text = ET.SubElement(qt, "text")
                file_name = _file(qt, q)
                body = _html(q, quiz, file_name, cloze=False)
                body += f"<p>{html.escape(clean(a.label))}, {html.escape(clean(a.unit))}</p>"
                text.text = clean(body)
                _text(el, "generalfeedback", "", format="html")
                ET.SubElement(el, "defaultgrade").text = "1.0000000"
                ET.SubElement(el, "penalty").text = "0.3333333"
                ET.SubElement(el, "hidden").text = "0"
                ans = ET.SubElement(
                    el, "answer", {"fraction": "100", "format": "moodle_auto_format"}
                )
                ET.SubElement(ans, "text").text = _number(a.value)
                ET.SubElement(ans, "tolerance").text = _number(a.tolerance())
                units = ET.SubElement(el, "units")
                unit = ET.SubElement(units, "unit")
                ET.SubElement(unit, "multiplier").text = "1"
                ET.SubElement(unit, "unit_name").text = clean(a.unit)
                ET.SubElement(el, "unitgradingtype").text = "0"
                ET.SubElement(el, "showunits").text = "3"
                ET.SubElement(el, "unitsleft").text = "0"
    ET.indent(root)
    return b'<?xml version="1.0" encoding="UTF-8"?>\n' + ET.tostring(root, encoding="utf-8") + b"\n"


_GIFT_SPECIAL = re.compile(r"([~=#{}:\\])")


def _gift_escape(text: str) -> str:
    return _GIFT_SPECIAL.sub(r"\\\1", clean(text).replace("\n", " "))


def gift(quiz: Quiz) -> str:
    """The quiz in GIFT, one numerical question per quantity (GIFT cannot embed
    images: the scheme is left out; use Moodle XML for it)."""
    out: list[str] = []
    for cat in quiz.categories:
        out.append(f"$CATEGORY: $course$/top/{_gift_escape(quiz.name)}/{_gift_escape(cat.name)}")
        out.append("")
        for q in cat.questions:
            given = "; ".join(f"{k} = {v}" for k, v in q.given)
            for a in q.answers:
                name = _gift_escape(f"{q.name} – {a.label}")
                text = _gift_escape(
                    f"{q.title}. {quiz.given_heading}: {given}. "
                    f"{quiz.find_heading}: {a.label}, {a.unit}"
                )
                out.append(f"::{name}::{text} {{#{_number(a.value)}:{_number(a.tolerance())}}}")
                out.append("")
    return "\n".join(out)
