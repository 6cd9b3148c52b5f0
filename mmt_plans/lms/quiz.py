"""Moodle XML and GIFT quiz files (Moodle's "Moodle XML format" and "GIFT
format" import), built with ElementTree and escaped by the writer.

One category per task, one question per variant: with kind "cloze" (the
default) a multi-answer question whose text holds the given data, the
variant's scheme (a PNG embedded as base64, `@@PLUGINFILE@@`) and one
NUMERICAL sub-question per quantity; with kind "numerical", one numerical
question per quantity. Every answer is rounded to its `significant` figures
(4 unless said otherwise) and that rounded value is the answer Moodle shows;
tolerances are given in percent and written as Moodle's absolute tolerances,
|rounded value|·percent/100 (to 6 significant figures); an answer of zero gets
percent/100 of its quantity's `scale` (Moodle cannot take a relative tolerance
of zero), or `zero_tolerance` where no scale is given; a value under
ZERO_OF_SCALE of its scale is such a zero (an exact zero's rounding error).

Category paths are $course$/top/<quiz>/<category>: names without control or
format characters (a CR, a bidirectional override), a "/" inside a name
written "//" as Moodle's paths escape it. GIFT question texts are HTML
("[html]"), escaped for HTML first (a title's "<!--" is text, not a comment)
and then by GIFT's rules (~ = # { } : and the backslash).
"""

from __future__ import annotations

import base64
import html
import math
import re
import xml.etree.ElementTree as ET
from dataclasses import dataclass
from decimal import ROUND_HALF_UP, Decimal

__all__ = ["NumericalAnswer", "QuizQuestion", "QuizCategory", "Quiz", "moodle_xml", "gift"]

# characters XML 1.0 does not allow (C0 controls but tab, newline, return; U+FFFE, U+FFFF)
_NOT_XML = re.compile("[\x00-\x08\x0b\x0c\x0e-\x1f\ufffe\uffff]")


# a value under this fraction of its quantity's scale is an exact zero computed
# with rounding errors
ZERO_OF_SCALE = 1e-9


def clean(text: str) -> str:
    """Text with the characters XML cannot carry removed."""
    return _NOT_XML.sub("", str(text))


def plain_name(text: str) -> str:
    """A name on one line with no control or format character (CR, U+202E...)."""
    return " ".join("".join(ch if ch.isprintable() else " " for ch in str(text)).split())


def category_path(*names: str) -> str:
    """$course$/top/a/b with each name plain and its "/" written "//"."""
    return "/".join(["$course$", "top", *(plain_name(n).replace("/", "//") for n in names)])


def significant(x: float, figures: int) -> float:
    """x rounded to `figures` significant figures as a person rounds its
    decimal digits, halves away from zero (-1234.5 -> -1235; 0 stays 0)."""
    if x == 0 or not math.isfinite(x):
        return float(x)
    d = Decimal(repr(float(x)))
    exponent = d.adjusted() - figures + 1
    return float(d.quantize(Decimal(1).scaleb(exponent), rounding=ROUND_HALF_UP)) + 0.0


@dataclass(frozen=True)
class NumericalAnswer:
    label: str  # plain text before the box: "V_E, position 2"
    value: float
    unit: str
    tolerance_percent: float
    zero_tolerance: float = 1e-9  # the absolute tolerance of a zero answer without a scale
    scale: float | None = None  # the quantity's size in this task: a zero's tolerance base
    figures: int = 4  # significant figures of the answer

    def rounded(self) -> float:
        """The answer Moodle gets: the value to `figures` significant figures."""
        if not math.isfinite(self.value):
            raise ValueError(f"{self.label}: the value must be finite")
        if self.scale is not None and abs(self.value) < abs(self.scale) * ZERO_OF_SCALE:
            return 0.0  # a rounding error of an exact zero (ε of a link at rest...)
        return significant(self.value, self.figures)

    def tolerance(self) -> float:
        if not (math.isfinite(self.value) and math.isfinite(self.tolerance_percent)):
            raise ValueError(f"{self.label}: value and tolerance must be finite")
        if not self.tolerance_percent > 0:
            raise ValueError(f"{self.label}: the tolerance must be positive")
        tol = abs(self.rounded()) * self.tolerance_percent / 100.0
        if tol == 0 and self.scale is not None and math.isfinite(self.scale) and self.scale > 0:
            tol = abs(self.scale) * self.tolerance_percent / 100.0
        return significant(tol, 6) if tol > 0 else self.zero_tolerance


@dataclass(frozen=True)
class QuizQuestion:
    name: str
    title: str
    given: tuple[tuple[str, str], ...]  # (label, value text) of the initial data
    answers: tuple[NumericalAnswer, ...]
    image_png: bytes | None = None
    image_alt: str = ""
    notes: tuple[str, ...] = ()  # paragraphs after the given data: positions, conventions


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
    gift_image_note: str = ""  # said in GIFT, which cannot carry the scheme's image


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
    parts.append("</table>")
    parts += [f"<p>{esc(note)}</p>" for note in q.notes]
    parts.append(f"<p>{esc(quiz.find_heading)}</p>")
    if cloze:
        for a in q.answers:
            sub = f"{{1:NUMERICAL:={_number(a.rounded())}:{_number(a.tolerance())}}}"
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
        _text(c, "category", category_path(quiz.name, cat.name))
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
                ET.SubElement(ans, "text").text = _number(a.rounded())
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
    """Plain text by GIFT's rules: its special characters after a backslash,
    on one line (a blank line would end the question)."""
    return _GIFT_SPECIAL.sub(r"\\\1", " ".join(clean(text).split()))


def _gift_html(text: str) -> str:
    """Text inside an [html] GIFT question: HTML-escaped, then GIFT-escaped."""
    return _gift_escape(html.escape(" ".join(clean(text).split()), quote=False))


def gift(quiz: Quiz) -> str:
    """The quiz in GIFT, one numerical question per quantity. GIFT cannot carry
    an image: each question says so (`gift_image_note`) where a scheme exists."""
    out: list[str] = []
    for cat in quiz.categories:
        out.append(f"$CATEGORY: {category_path(quiz.name, cat.name)}")
        out.append("")
        for q in cat.questions:
            given = "; ".join(f"{k}: {v}" for k, v in q.given)
            head = f"<p><b>{_gift_html(q.title)}</b></p>"
            if q.image_png is not None and quiz.gift_image_note:
                head += f"<p>{_gift_html(quiz.gift_image_note)}</p>"
            body = f"<p>{_gift_html(quiz.given_heading)}\\: {_gift_html(given)}</p>"
            body += "".join(f"<p>{_gift_html(n)}</p>" for n in q.notes)
            for a in q.answers:
                name = _gift_escape(f"{q.name} – {a.label}")
                find = f"<p>{_gift_html(quiz.find_heading)}\\: {_gift_html(f'{a.label}, {a.unit}')}</p>"
                answer = f"{{#{_number(a.rounded())}:{_number(a.tolerance())}}}"
                out.append(f"::{name}::[html]{head}{body}{find} {answer}")
                out.append("")
    return "\n".join(out)
