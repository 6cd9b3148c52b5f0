"""The note's millimetres are the sheets' millimetres (issue 14 / 13).

For the samples and two seed tasks, every number the note prints in mm of a
drawing (a plan's segment, a force polygon's side, an arm ...) is checked
against the sheets drawn here on a RecordingBackend, not against the note's
code:

- each equals value/μ with μ read from the scale label the sheet prints on
  that drawing ("μF = 40 N/mm" in the group's force polygon), the value being
  the source's own (the numerator of its recorded source, evaluated as
  tests/note/test_sections.py does);
- each leg of a plan's vector equations (relative velocities, a^n, a^k, a^τ,
  a^r) and each force-polygon side of 1 mm or more equals the length of a
  line or arrow drawn in that drawing's group, to 0.1 mm (plus the printed
  number's rounding); similarity segments and p-to-image lengths, which the
  plans do not draw as one primitive, by the label's μ only; the group arms the sheet draws (h'_i, pivot to
  foot) each equal an arm the note prints for that group.
"""

from __future__ import annotations

import functools
import math
import re
from pathlib import Path

import pytest

from mmt_plans.drawing.page import Page
from mmt_plans.note import note_content
from mmt_plans.render.recording import RecordingBackend
from mmt_plans.sheets.sheet1 import compose_sheet1
from mmt_plans.sheets.sheet2 import compose_sheet2
from tests.note.test_sections import _value, _where, namespace, solved

ROOT = Path(__file__).resolve().parents[1]
FILES = sorted((ROOT / "samples").glob("*.toml")) + [
    ROOT / "samples/tasks/seed002/task5_v00.toml",
    ROOT / "samples/tasks/seed003/task01_v1.toml",
]
CASES = [(p, lang) for p in FILES for lang in ("en", "uk")]

# a printed mm: (numerator)/(the sheet's scale of the drawing)
SCALED = re.compile(
    r"^(?P<num>.+)/(?P<mu>sheet1\.mu_[Va]\[\d+\]|sheet1\.mu_l|sheet2\.mu_F\['[^']+'\]"
    r"|sheet2\.mu_l_group\['[^']+'\]|sheet2\.mu_l_driving|sheet2\.mu_l|sheet2\.mu_V)$"
)


def _drawing(mu: str) -> tuple[int, str, str]:
    """(sheet, group id of the drawing, index of its μ label) of a scale's source."""
    if m := re.fullmatch(r"sheet1\.mu_([Va])\[(\d+)\]", mu):
        kind = "velocity" if m.group(1) == "V" else "acceleration"
        return 1, f"{kind}-plan-{m.group(2)}", m.group(1)
    if mu == "sheet1.mu_l":
        return 1, "mechanism", "l"
    if m := re.fullmatch(r"sheet2\.mu_F\['(?:group |link )([^']+)'\]", mu):
        return 2, f"force-polygon-{m.group(1)}", "F"
    if m := re.fullmatch(r"sheet2\.mu_l_group\['([^']+)'\]", mu):
        return 2, f"group-{m.group(1)}", "l"
    return {
        "sheet2.mu_l_driving": (2, "driving-link", "l"),
        "sheet2.mu_l": (2, "force-mechanism", "l"),
        "sheet2.mu_V": (2, "zhukovsky-lever", "V"),
    }[mu]


@functools.cache
def sheets(path: Path, lang: str) -> dict[int, RecordingBackend]:
    a = solved(path)
    page = Page.of("A1")
    out = {1: RecordingBackend(page.width, page.height)}
    compose_sheet1(a, out[1], lang)  # type: ignore[arg-type]
    if a.forces is not None:
        out[2] = RecordingBackend(page.width, page.height)
        compose_sheet2(a, out[2], lang)  # type: ignore[arg-type]
    return out


def label_scale(rec: RecordingBackend, group: str, index: str) -> float:
    """μ as the sheet prints it in the drawing `group`: "μ", its index, "= 0,004 м/мм"."""
    texts = [c["content"] for c in rec.in_group(group) if c.name == "text"]
    for k in range(len(texts) - 2):
        if texts[k] == "μ" and texts[k + 1] == index:
            m = re.match(r"\s*=\s*(-?\d+(?:[.,]\d+)?)", texts[k + 2])
            if m:
                return float(m.group(1).replace(",", "."))
    raise AssertionError(f"no μ{index} label in {group}")


def drawn_lengths(rec: RecordingBackend, group: str, kinds=("line", "arrow")) -> list[float]:
    return [
        math.dist(c["start"], c["end"])
        for c in rec.in_group(group)
        if c.name in kinds and (c.name != "line" or kinds != ("thin",))
    ]


def _discs(rec: RecordingBackend, group: str) -> list[tuple[tuple[float, float], float]]:
    """The thin open circles of `group`: a detail's disc (centre, radius)."""
    return [
        (c["center"], c["radius"])
        for c in rec.in_group(group)
        if c.name == "circle" and c["line"] == "thin" and c["fill"] == "none"
    ]


def detailed_lengths(rec: RecordingBackend, group: str) -> list[float]:
    """The vectors of plan `group` whose heads lie in a detail's disc, read back
    at the plan's scale: one wholly in the disc is drawn in the detail view
    alone (`group`-detail…, at its ratio); one from outside is drawn on the
    plan up to the disc's edge and on from there in the view, and is read as
    the plan's segment joined to the view's one that starts where it stops."""
    segments = [(c["start"], c["end"]) for c in rec.in_group(group) if c.name in ("line", "arrow")]
    views = sorted({g for c in rec.calls for g in c.groups if g.startswith(f"{group}-detail")})
    out = []
    for view in views:
        inner = [(c["start"], c["end"]) for c in rec.in_group(view) if c.name in ("line", "arrow")]
        (big_c, big_r) = max(_discs(rec, view), key=lambda d: d[1])
        for centre, radius in _discs(rec, group):
            ratio = big_r / radius

            def back(q, centre=centre, ratio=ratio):
                return (
                    centre[0] + (q[0] - big_c[0]) / ratio,
                    centre[1] + (q[1] - big_c[1]) / ratio,
                )

            # a vector wholly in the disc: drawn in the view alone
            out += [
                math.dist(s, e) / ratio
                for s, e in inner
                if max(math.dist(s, big_c), math.dist(e, big_c)) < big_r - 0.01
            ]
            for a, b in segments:
                if abs(math.dist(b, centre) - radius) > 0.01:
                    continue  # not cut at this disc
                for s, e in inner:
                    if math.dist(back(s), b) < 0.01:
                        out.append(math.dist(a, back(e)))
    return out


def thin_lines(rec: RecordingBackend, group: str) -> list[float]:
    return [
        math.dist(c["start"], c["end"])
        for c in rec.in_group(group)
        if c.name == "line" and c["line"] == "thin"
    ]


@pytest.mark.parametrize("case", CASES, ids=lambda c: f"{c[0].stem}-{c[1]}")
def test_note_mm_are_the_sheets_mm(case):
    path, lang = case
    content = note_content(solved(path), lang)  # type: ignore[arg-type]
    ns = namespace(path, lang)
    recs = sheets(path, lang)
    checked = {"plan": 0, "side": 0}
    arms: dict[str, list[float]] = {}
    for p in content.numbers:
        m = SCALED.match(p.source)
        if not m:
            continue
        sheet, group, index = _drawing(m.group("mu"))
        rec = recs[sheet]
        mu = label_scale(rec, group, index)
        value = float(eval(f"({m.group('num')})", ns))  # noqa: S307 - the note's source
        printed, half = _value(_where(content, p)[p.start : p.end])
        assert abs(printed - value / mu) <= half * (1 + 1e-9) + 1e-9 * abs(value / mu), (
            p.text,
            value,
            mu,
            p.source,
        )
        mm = abs(printed)
        num = m.group("num")
        # a leg of a plan's vector equation (a relative velocity, a^n, a^k, a^τ ...)
        plan = index in ("V", "a") and sheet == 1 and ".groups[" in num
        side = index == "F" and num.startswith("hyp(") and ".vectors[" in num
        if (plan or side) and mm >= 1.0:
            lengths = drawn_lengths(rec, group) + (detailed_lengths(rec, group) if plan else [])
            best = min((abs(x - mm) for x in lengths), default=math.inf)
            assert best <= 0.1 + half, (p.text, group, p.source, sorted(lengths))
            checked["plan" if plan else "side"] += 1
        if index == "l" and group.startswith("group-") and num.startswith("arm("):
            arms.setdefault(group, []).append(mm)
    assert checked["plan"] > 0
    if solved(path).forces is not None:
        assert checked["side"] > 0
        # every arm h'_i the sheet draws in a group (pivot to foot, thin) is an arm
        # the note prints for that group, at the group's scale
        for group, printed_arms in arms.items():
            names = [c["content"] for c in recs[2].in_group(group) if c.name == "text"]
            drawn = names.count("h'")
            thin = thin_lines(recs[2], group)
            matched = [
                h for h in printed_arms if h >= 1.0 and any(abs(x - h) <= 0.15 for x in thin)
            ]
            assert len(matched) >= min(drawn, 1), (group, printed_arms, sorted(thin))
