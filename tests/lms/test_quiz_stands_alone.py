"""Issue 24: a quiz a student can solve from its own content, one category per
source task whatever the files are called, answers rounded as stated; and the
issue 26 defects of the quiz (GIFT escaping, names from file names, a quiz
name that an input's folder could take)."""

from __future__ import annotations

import html
import json
import math
import re
import shutil
import tomllib
import xml.etree.ElementTree as ET
from decimal import Decimal
from pathlib import Path

import pytest
from click.testing import CliRunner

from mmt_plans.cli import main
from mmt_plans.lms import NumericalAnswer, Quiz, QuizCategory, QuizQuestion, gift, moodle_xml

from .moodle_regex import subquestions

ROOT = Path(__file__).resolve().parents[2]
TASK = ROOT / "samples" / "tasks" / "seed003" / "task01_v1.toml"
TASK2 = ROOT / "samples" / "tasks" / "seed003" / "task02_v1.toml"


def mm(v: float) -> str:
    """A length as the quiz writes it: the shortest decimal, no trailing zeros."""
    text = format(Decimal(repr(round(float(v), 6) + 0.0)).normalize(), "f")
    return text.rstrip("0").rstrip(".") if "." in text else text


def batch(inputs, out: Path, *extra: str):
    result = CliRunner().invoke(main, ["batch", *map(str, inputs), "-o", str(out), "--moodle",
                                       "--format", "svg", "--jobs", "1", *extra])
    assert result.exit_code == 0, result.output
    return result


def cloze_questions(quiz_xml: Path) -> dict[str, list[str]]:
    """Category path -> the texts of its cloze questions."""
    root = ET.parse(quiz_xml).getroot()
    out: dict[str, list[str]] = {}
    current = None
    for q in root.findall("question"):
        if q.get("type") == "category":
            current = q.find("category/text").text
            out[current] = []
        else:
            out[current].append(q.find("questiontext/text").text)
    return out


def expected_given(data: dict) -> list[str]:
    """Every given value of a mechanism file, as text the question must hold,
    read from the TOML itself (not from the model the quiz was made from)."""
    want = []
    drive = data["drive"]
    want.append(f"n1 = {mm(drive['rpm'])} rpm")
    want.append("clockwise" if drive.get("sense") == "cw" else "counter-clockwise")
    for name, (x, y) in data["frame"].items():
        want.append(f"frame point {name}")
        want.append(f"({mm(x)}; {mm(y)}) mm")
    for link in data["link"]:
        lid, pts = link["id"], link["points"]
        names = list(pts)
        for i, a in enumerate(names):
            for b in names[i + 1:]:
                length = math.hypot(pts[b][0] - pts[a][0], pts[b][1] - pts[a][1])
                want.append(f"l{lid} ({a}{b}) = {mm(length)} mm")
        if len(names) >= 2:
            want += [f"{n} ({mm(x)}; {mm(y)}) mm" for n, (x, y) in pts.items()]
        if link.get("mass"):
            want.append(f"m{lid}: {mm(link['mass'])} kg")
        if "cm" in link:
            want.append(f"S{lid}: centre of mass of link {lid}: ({mm(link['cm'][0])}; {mm(link['cm'][1])}) mm")
        if "J" in link:
            want.append(f"J_S{lid}: {mm(link['J'])} kg·m²")
    for s in data.get("slider", []):
        want.append(f"slider {s['link']}")
        where = "of the frame" if s["on"] == 0 else f"of link {s['on']}"
        want.append(f"on a guide {where}")
        want.append(f"through ({mm(s['through'][0])}; {mm(s['through'][1])}) mm at {mm(s['angle'])}°")
    for f in data.get("force", []):
        want.append(f"{f['name']}: on link {f['link']} at {f['at']}: {mm(f['magnitude'])} N")
    study = data["study"]
    wx, wy = study.get("working_direction", [1, 0])
    want.append(f"output: point {study['output']}, working direction ({mm(wx)}; {mm(wy)})")
    positions = study.get("positions", 12)
    want.append("Position 0: the extreme position of " + study["output"])
    want.append(f"Positions 0 … {positions - 1} follow each other every {mm(360 / positions)}°")
    want.append("F_bal: the balancing force at the crank pin")
    want.append("positive when it acts in the sense of the crank")
    want.append("rounded to 4 significant figures")
    return want


def plain(text: str) -> str:
    """The question as a student reads it: the table's cells as "label: value"."""
    text = text.replace("</td><td>", ": ")
    return html.unescape(re.sub(r"<[^>]+>", " ", text))


def test_a_quiz_of_five_variants_names_every_given_value_groups_by_source_and_rounds(tmp_path):
    made = tmp_path / "made"
    r = CliRunner().invoke(main, ["variants", str(TASK), "--count", "5", "--seed", "3",
                                  "-o", str(made)])
    assert r.exit_code == 0, r.output
    inputs = tmp_path / "in"
    (inputs / "deep" / "er").mkdir(parents=True)
    # names that say nothing, or the wrong thing, about the task they are a variant of
    names = ["a.toml", "task07_v2.toml", "deep/quiz_me.toml", "deep/er/zz.toml", "Б.toml"]
    for f, name in zip(sorted(made.glob("*.toml")), names):
        shutil.copy(f, inputs / name)
    shutil.copy(TASK, inputs / "x1.toml")  # seed-003 files of two tasks, renamed
    shutil.copy(TASK.with_name("task01_v2.toml"), inputs / "deep" / "x2.toml")
    shutil.copy(TASK2, inputs / "task01_v3.toml")  # task 2 under a task-1 name
    out = tmp_path / "my keys folder"
    batch([inputs], out)
    cats = cloze_questions(out / "quiz.xml")
    assert sorted(len(v) for v in cats.values()) == [1, 2, 5]
    for path in cats:  # no folder name, no file name in a category's path
        assert path.startswith("$course$/top/Kinematic and force analysis/")
        assert "my keys" not in path and "deep" not in path and "task07" not in path
    variants_cat = next(p for p, qs in cats.items() if len(qs) == 5)
    assert variants_cat.endswith("/Seed 003 task 1: six-link press (crank, rocker, rod, slider)")

    by_title = {}
    for f in inputs.rglob("*.toml"):
        data = tomllib.loads(f.read_text(encoding="utf-8"))
        by_title[data["title"]] = (f, data)
    for texts in cats.values():
        for text in texts:
            student = plain(text)
            title = re.search(r"<b>(.*?)</b>", text).group(1)
            f, data = by_title[html.unescape(title)]
            missing = [w for w in expected_given(data) if w not in student]
            assert not missing, (f.name, missing)
            # the answers: Moodle's own regexes find one NUMERICAL answer each,
            # 4 significant figures of analyze's value, 5 % of the rounded value
            subs = subquestions(text)
            assert len(subs) >= 6 and all(s["numerical"] and len(s["answers"]) == 1 for s in subs)
            results = tmp_path / "r.json"
            a = CliRunner().invoke(main, ["analyze", str(f), "--json", str(results)])
            assert a.exit_code == 0, a.output
            res = json.loads(results.read_text())
            kin = {k["index"]: k for k in res["kinematics"] if k["index"] is not None}
            out_pt = data["study"]["output"]
            exact = []
            for i in res["plans"]:
                exact += [math.hypot(*kin[i]["v"][out_pt]), math.hypot(*kin[i]["a"][out_pt])]
            for s, x in zip(subs, exact):
                v, t = float(s["answers"][0]), float(s["tolerances"][0])
                digits = s["answers"][0].lstrip("-").replace(".", "").lstrip("0").rstrip("0")
                assert len(digits) <= 4
                assert abs(v - x) <= 0.5 * 10 ** (math.floor(math.log10(abs(x))) - 3) * (1 + 1e-9)
                assert t == pytest.approx(abs(v) * 0.05, rel=1e-6)
            bal = res["forces"]["balancing_force_plans"]
            assert any(float(s["answers"][0]) == float(f"{bal:.4g}") or
                       abs(float(s["answers"][0]) - bal) <= 0.5 * 10 ** (math.floor(math.log10(abs(bal))) - 3)
                       for s in subs)  # F_bal, signed


def test_a_zero_answer_gets_the_tolerance_of_its_quantitys_scale():
    a = NumericalAnswer("ε2", 0.0, "rad/s²", 5.0, scale=109.66)  # ω1² of 100 rpm
    assert a.rounded() == 0.0 and a.tolerance() == pytest.approx(5.483)
    # a zero computed with rounding errors is a zero: 0 is the answer, within 5 % of 2 m/s
    tiny = NumericalAnswer("V", 1e-14, "m/s", 5.0, scale=2.0)
    assert tiny.rounded() == 0.0 and tiny.tolerance() == pytest.approx(0.1)
    assert NumericalAnswer("V", 1e-6, "m/s", 5.0, scale=2.0).rounded() == 1e-6


def quiz(title: str, name: str = "v1", category: str = "Task 1") -> Quiz:
    q = QuizQuestion(name=name, title=title, given=(("l1 (OA)", "200 mm"),),
                     answers=(NumericalAnswer("V_C", 2.80651, "m/s", 5.0),), notes=("note",))
    return Quiz(name="keys", categories=(QuizCategory(category, (q,)),),
                given_heading="Given", find_heading="Find")


def gift_questions(text: str) -> list[str]:
    """The questions of a GIFT file as Moodle's reader splits them: by blank lines,
    // comment lines and $CATEGORY lines aside."""
    blocks = [b.strip() for b in re.split(r"\n\s*\n", text) if b.strip()]
    return [b for b in blocks if not b.startswith("$CATEGORY:") and not b.startswith("//")]


def test_gift_texts_are_escaped_by_gifts_rules():  # issue 26
    title = "Press <!-- hidden --> a~b=c#d{e}f:g \\ h"
    text = gift(quiz(title, name="n:a{me}"))
    (q,) = gift_questions(text)
    assert "<!--" not in q and "&lt;!--" in q  # a comment opener is text, not HTML
    assert q.startswith("::n\\:a\\{me\\} – V_C::[html]")
    # every GIFT special character of the title is escaped; the only unescaped
    # braces are the answer's
    assert "a\\~b\\=c\\#d\\{e\\}f\\:g \\\\ h" in q
    assert re.findall(r"(?<!\\)[{}]", q) == ["{", "}"]
    assert q.endswith("{#2.807:0.14035}")


def test_a_cr_or_a_bidi_override_in_names_stays_out_of_category_names(tmp_path):  # issue 26
    hostile = "Task\r1\u202e/x\n"
    data = moodle_xml(quiz("t", category=hostile))
    path = ET.fromstring(data).find("question/category/text").text
    assert path == "$course$/top/keys/Task 1 //x"  # "/" in a name is Moodle's "//"
    assert "$CATEGORY: $course$/top/keys/Task 1 //x" in gift(quiz("t", category=hostile))
    # through batch: a file named with a CR and U+202E and no title of its own
    src = TASK.read_text(encoding="utf-8")
    src = re.sub(r'^title.*\n', "", src, flags=re.M)
    odd = tmp_path / "in" / "t\r\u202eask.toml"
    odd.parent.mkdir()
    odd.write_text(src, encoding="utf-8")
    batch([odd], tmp_path / "out")
    for name in ("quiz.xml", "quiz.gift"):
        body = (tmp_path / "out" / name).read_text(encoding="utf-8")
        assert "\r" not in body and "\u202e" not in body


def test_an_input_named_quiz_xml_toml_does_not_block_the_quiz(tmp_path):  # issue 26
    src = tmp_path / "in" / "quiz.xml.toml"
    src.parent.mkdir()
    shutil.copy(TASK, src)
    gift_src = tmp_path / "in" / "quiz.gift.toml"
    shutil.copy(TASK, gift_src)
    out = tmp_path / "out"
    batch([src, gift_src], out)
    assert (out / "quiz.xml").is_file() and (out / "quiz.gift").is_file()
    assert (out / "quiz.xml-2" / "results.json").is_file()
    assert (out / "quiz.gift-2" / "results.json").is_file()


def test_the_scheme_carries_the_frames_dimensions():
    import mmt_plans
    from mmt_plans.render.recording import RecordingBackend
    from mmt_plans.sheets.schematic import frame_dimensions, sketch_schematic

    solution = mmt_plans.solve(mmt_plans.load(TASK))
    dims = frame_dimensions(solution.mechanism)
    # O2 = [700, -70] from O1 = [0, 0]: 700 along x, 70 along y
    assert [(d.horizontal, d.end, round(d.value * 1e3, 6)) for d in dims] == [
        (True, "O2", 700.0), (False, "O2", -70.0)]
    rec = RecordingBackend(140.0, 100.0)
    sketch_schematic(solution, rec.look, width_mm=140.0, height_mm=100.0,
                     dimensions=True).replay(rec)
    texts = [c["content"] for c in rec.in_group("dimensions") if c.name == "text"]
    assert texts == ["700", "70"]
    for c in rec.calls:
        for x, y in c.points():
            assert -1e-6 <= x <= 140.0 + 1e-6 and -1e-6 <= y <= 100.0 + 1e-6
