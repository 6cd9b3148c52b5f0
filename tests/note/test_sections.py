"""The note's sections: every section present, and EVERY number printed in the
note equal, at its printed precision, to the value its recorded source gives
when this test evaluates that source on the solved mechanism by itself (the
results JSON `J`, the Solution `S`, the Mechanism `M` for inputs; `sheet1`,
`sheet2` the scales the sheets draw at, from composing the sheets here).

The writer records where each number came from (mmt_plans/note/writer.py);
the helpers below (moment, arm, the lever's moments) are written here again,
not imported from the solver, and no value is copied from the note."""

from __future__ import annotations

import functools
import math
import re
from fractions import Fraction
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest

import mmt_plans
from mmt_plans.drawing.page import Page
from mmt_plans.gears import GearPair
from mmt_plans.note import note_content, plain
from mmt_plans.render.recording import RecordingBackend
from mmt_plans.results_json import results
from mmt_plans.scales import ACCELERATION_PLAN, FORCE_PLAN, VELOCITY_PLAN, scale_for
from mmt_plans.sheets.sheet1 import compose_sheet1
from mmt_plans.sheets.sheet2 import compose_sheet2

ROOT = Path(__file__).resolve().parents[2]
SAMPLES = sorted((ROOT / "samples").glob("*.toml"))
SEED002_GEARS = ROOT / "samples/tasks/seed002/task5_v00.toml"  # pair + planetary, F_KO
SEED002_PAIR = ROOT / "samples/tasks/seed002/task1_v03.toml"
SEED003 = [
    ROOT / "samples/tasks/seed003/task01_v1.toml",
    ROOT / "samples/tasks/seed003/task02_v3.toml",
    ROOT / "samples/tasks/seed003/task11_v1.toml",  # RPP
]
SEED002_PRP = ROOT / "samples/tasks/seed002/task6_v00.toml"  # PRP and RPR
FILES = SAMPLES + [SEED002_GEARS, SEED002_PAIR, SEED002_PRP] + SEED003
CASES = [(p, lang) for p in FILES for lang in ("en", "uk")]


def _id(case) -> str:
    path, lang = case
    return f"{path.parent.name}/{path.stem}-{lang}"


@functools.cache
def solved(path: Path):
    return mmt_plans.solve(mmt_plans.load(path))


@functools.cache
def note(path: Path, lang: str):
    return note_content(solved(path), lang)  # type: ignore[arg-type]


# --- an evaluator of the sources, independent of the writer ----------------------------------
def _hyp(v) -> float:
    return math.hypot(float(v[0]), float(v[1]))


def _dist(p, q) -> float:
    return math.hypot(float(p[0]) - float(q[0]), float(p[1]) - float(q[1]))


def _moment(t, P) -> float:
    """(point, force, couple) about P, counter-clockwise positive."""
    (x, y), (fx, fy), c = t
    return (float(x) - float(P[0])) * float(fy) - (float(y) - float(P[1])) * float(fx) + float(c)


def _arm(t, P) -> float:
    return (_moment(t, P) - float(t[2])) / _hyp(t[1])


def _lever_moment(f) -> float:
    return float(f.image[0]) * float(f.force[1]) - float(f.image[1]) * float(f.force[0])


def _lever_arm(f) -> float:
    return _lever_moment(f) / _hyp(f.force)


@functools.cache
def drawn_scales(path: Path, lang: str) -> tuple[SimpleNamespace, SimpleNamespace]:
    """`sheet1`, `sheet2` of the sources: the scales the sheets of `path` are
    drawn at, read from what compose_sheet1/2 return after drawing them here."""
    S = solved(path)
    page = Page.of("A1")
    s1 = compose_sheet1(S, RecordingBackend(page.width, page.height), lang).scales  # type: ignore[arg-type]
    plans = S.plan_positions
    sheet1 = SimpleNamespace(
        mu_l=s1["mu_l"],
        # each position's plans at their own μ where one cannot hold both (#21)
        mu_V={i: s1.get(f"mu_V {i}", s1["mu_V"]) for i in plans},
        mu_a={i: s1.get(f"mu_a {i}", s1["mu_a"]) for i in plans},
        # the S, V, a diagrams as sheet 1 draws them (larger where it has room)
        diagrams=SimpleNamespace(
            L=s1["L"],
            mu_t=s1["mu_t"],
            mu_S=s1["mu_S"],
            mu_V=s1["mu_V_diagram"],
            mu_a=s1["mu_a_diagram"],
            H1=s1["H1"],
            H2=s1["H2"],
        ),
    )
    sheet2 = SimpleNamespace()
    if S.forces is not None:
        s2 = compose_sheet2(S, RecordingBackend(page.width, page.height), lang).scales  # type: ignore[arg-type]
        groups = [g.name for g in S.forces.groups]
        d = S.forces.driving_link.link
        sheet2 = SimpleNamespace(
            mu_l=s2["mu_l"],
            mu_l_group={n: s2[f"mu_l {n}"] for n in groups},
            mu_l_driving=s2[f"mu_l {d}"],
            mu_F={**{f"group {n}": s2[f"mu_F {n}"] for n in groups}, f"link {d}": s2[f"mu_F {d}"]},
            mu_V=s2["mu_V"],
        )
    return sheet1, sheet2


@functools.cache
def namespace(path: Path, lang: str = "en") -> dict:
    S = solved(path)
    sheet1, sheet2 = drawn_scales(path, lang)
    return {
        "sheet1": sheet1,
        "sheet2": sheet2,
        "J": results(S),
        "S": S,
        "M": S.mechanism,
        "F": S.forces,
        "plan": functools.cache(S.plan),
        "hyp": _hyp,
        "dist": _dist,
        "xy": lambda z: [complex(z).real, complex(z).imag],
        "moment": _moment,
        "arm": _arm,
        "as_load": lambda f: (f.point, f.force, f.couple),
        "lever_moment": _lever_moment,
        "lever_arm": _lever_arm,
        "mu_F": lambda polys: scale_for(max(p.largest for p in polys), FORCE_PLAN),
        "scale_for": scale_for,
        "VELOCITY_PLAN": VELOCITY_PLAN,
        "ACCELERATION_PLAN": ACCELERATION_PLAN,
        "FORCE_PLAN": FORCE_PLAN,
        "pi": math.pi,
    }


def _value(text: str) -> tuple[float, float]:
    """A printed number and half a unit of its last digit."""
    t = text.replace(",", ".")
    decimals = len(t.split(".", 1)[1]) if "." in t else 0
    return float(t), 0.5 * 10.0**-decimals


def _where(content, p) -> str:
    b = content.blocks[p.block]
    return b.text if p.row < 0 else b.rows[p.row][p.col]


# --- sections -----------------------------------------------------------------------------------
@pytest.mark.parametrize("case", CASES, ids=_id)
def test_every_section_present(case):
    path, lang = case
    a, content = solved(path), note(path, lang)
    steps = content.steps
    sheet1 = ["sheet1", "1.1", "1.2", "1.3", "1.4", "1.5", "1.6", "1.7", "1.8"]
    assert [s for s in steps if s in sheet1] == sheet1
    if a.forces is not None:
        n = len(a.forces.groups)
        sheet2 = ["sheet2", "2.1", "2.2", "2.3", "2.4", "2.5"] + [
            f"2.{6 + j}" for j in range(n + 4)
        ]
        assert [s for s in steps if s in sheet2] == sheet2
        assert steps.index("sheet2") > steps.index("1.8")
    assert steps[-1] == "conclusions"
    gears = a.mechanism.drive.gear_train is not None
    assert ("gears" in steps) == gears
    # the reduction to the crank (M_red, J_red) in every note, gears or not (issue 22),
    # where the force position solved
    k = a.entry(a.force_position)
    solved_there = bool(np.isfinite(a.reduction.reduced_inertia[k]))
    assert ("reduction" in steps) == solved_there
    if gears:
        assert steps.index("gears") < steps.index("sheet1")


@pytest.mark.parametrize("case", CASES, ids=_id)
def test_every_printed_number_is_its_sources(case):
    """Each recorded number sits where it says and equals its source's value."""
    path, lang = case
    content = note(path, lang)
    ns = namespace(path, lang)
    assert content.numbers
    for p in content.numbers:
        text = _where(content, p)
        assert text[p.start : p.end] == p.text, p
        expected = eval(p.source, ns)  # noqa: S307 - the writer's own source strings
        if p.sig == 0:
            assert int(p.text) == expected, (p.text, p.source)
            continue
        assert math.isfinite(float(expected)), p.source
        printed, half = _value(p.text)
        assert abs(printed - float(expected)) <= half * (1 + 1e-9) + 1e-12 * abs(expected), (
            p.text,
            expected,
            p.source,
        )
        assert p.text != "-0" and "e" not in p.text.lower()
        if lang == "uk":
            assert "." not in p.text, p  # the decimal comma


@pytest.mark.parametrize("case", CASES, ids=_id)
def test_no_number_is_printed_without_a_source(case):
    """Blank the recorded numbers out; what digits remain are identifiers (S2,
    R_{34}, link numbers, gear numbers), item and equation numbers, and the
    formulas' own constants (π·n/30, 100 %, ^2, 90°)."""
    path, lang = case
    a, content = solved(path), note(path, lang)
    spans: dict[tuple[int, int, int], list[tuple[int, int]]] = {}
    for p in content.numbers:
        spans.setdefault((p.block, p.row, p.col), []).append((p.start, p.end))
    ids = {str(lid) for lid in a.mechanism.links} | {"0"}
    train = a.mechanism.drive.gear_train
    if train is not None:
        ids |= {g.rstrip("'") for stage in train.gear_labels for g in stage}
    constants = {"1", "2", "3", "5", "30", "60", "90", "100"} | ids
    for bi, b in enumerate(content.blocks):
        if b.kind == "title":  # the file's own title
            continue
        cells = [(-1, -1, b.text)] + [
            (r, c, cell) for r, row in enumerate(b.rows) for c, cell in enumerate(row)
        ]
        for r, c, text in cells:
            chars = list(text)
            for start, end in spans.get((bi, r, c), []):
                chars[start:end] = " " * (end - start)
            rest = "".join(chars)
            if r == 0:  # a table's header: column titles
                continue
            rest = re.sub(r"^\d+(\.\d+)*\.\s", " ", rest)  # "1.3. "
            rest = re.sub(r"\b[IV]+\(\d+(,\d+)*\)", " ", rest)  # I(0,1), II(2,3)
            rest = re.sub(r"\(\d+\)", " ", rest)  # equation numbers (7)
            rest = re.sub(r"\(\d+\.\d+\)", " ", rest)  # the note's formula numbers (1.13)
            # the guide's formulas cited: [2, formula (7)], [2, формули (12)–(13)]
            rest = re.sub(r"\[\d+, [^\]]*\]", " ", rest)
            rest = re.sub(r"[A-Za-zА-Яа-яЄєІіЇїҐґα-ωΑ-Ω_^{(,'/]\d+", " ", rest)  # S2, R_{34}
            rest = re.sub(r"\d+'?(-\d+'?)+(-H)?", " ", rest)  # groups 2-3, gears 3-4-4'-5-H
            rest = re.sub(r"\[\d+(, \d+)*\]", " ", rest)  # citations [2, 6]
            rest = re.sub(r"\((figure|рисунок)\s\d+\)", " ", rest)  # (figure 3)
            rest = re.sub(r"(DSTU|ДСТУ) \d+:\d+", " ", rest)  # the standard's name
            rest = re.sub(r"(GOST|ГОСТ) \d+\.\d+", " ", rest)  # GOST 2.305, a detail view
            rest = re.sub(r"kind \d \(|\d-го виду \(", " ", rest)  # a dyad's kind, 1..5
            left = re.findall(r"\d+(?:[.,]\d+)?", rest)
            assert set(left) <= constants, (text, left)


# --- the gear train by Willis, checked from the teeth ------------------------------------------
@pytest.mark.parametrize("lang", ["en", "uk"])
def test_willis_steps_from_the_teeth(lang):
    a = solved(SEED002_GEARS)
    text = note(SEED002_GEARS, lang).text()
    train = a.mechanism.drive.gear_train
    cat = mmt_plans.i18n.catalogue(lang)
    u_total = Fraction(1)
    for stage in train.stages:
        if isinstance(stage, GearPair):
            sign = -1 if stage.mesh == "external" else 1
            u = sign * Fraction(stage.z[1], stage.z[0])
        else:
            held = Fraction(1)
            for m in stage.meshes:
                held *= (-1 if m.mesh == "external" else 1) * Fraction(m.z[1], m.z[0])
            assert f"= {cat.number(float(held))}\n" in text + "\n"
            u = 1 - held  # Willis, the last central gear fixed
            assert f"1 - {_paren(cat.number(float(held)))} = {cat.number(float(u))}" in text
        u_total *= u
    symbol = "u_m1" if lang == "en" else "u_дв1"
    assert re.search(rf"{symbol} = .* = {re.escape(cat.number(float(u_total)))}\n", text)
    omega1 = math.pi * train.motor_rpm / 30 / abs(float(u_total))
    assert f"= {cat.number(omega1)} {cat.unit('rad/s')}" in text


def _paren(t: str) -> str:
    return f"({t})" if t.startswith("-") else t


def test_reduced_moment_and_inertia_by_their_definitions():
    """J_red = Σ(m·V_S² + J_S·ω²)/ω1² and M_red = F·V·cos/ω1, from the JSON's velocities."""
    a = solved(SEED002_GEARS)
    text = note(SEED002_GEARS, "en").text()
    J = results(a)
    k = a.entry(a.force_position)
    kin = J["kinematics"][k]
    w1 = a.mechanism.drive.omega
    energy = sum(
        lk.mass * _hyp(kin["v_cm"][str(lid)]) ** 2 + lk.J * kin["omega"][str(lid)] ** 2
        for lid, lk in a.mechanism.links.items()
    )
    assert f"= {mmt_plans.note.number(energy / w1**2)} kg·m²" in text
    (f,) = a.mechanism.forces
    V = kin["v"][f.at]
    # acts = "always": against the velocity of its point
    M_red = -f.magnitude * _hyp(V) / w1
    assert f"= {mmt_plans.note.number(M_red)} N·m" in text


@pytest.mark.parametrize("case", [c for c in CASES if c[1] == "uk"], ids=_id)
def test_ukrainian_note_has_no_english_unit_or_decimal_point(case):
    path, _ = case
    text = note(path, "uk").text()
    for word in (
        " m/s",
        " rad/s",
        " N·m",
        " kg",
        " mm",
        " N ",
        " rpm",
        "clockwise",
        "link ",
        "group ",
    ):
        assert word not in text, word
    for p in note(path, "uk").numbers:
        assert "." not in p.text


@pytest.mark.parametrize("case", CASES, ids=_id)
def test_one_sign_convention_and_a_verdict_that_agrees(case):
    path, lang = case
    a, content = solved(path), note(path, lang)
    text = content.text()
    w = mmt_plans.i18n.catalogue(lang).words("note")
    if a.forces is not None:
        assert text.count(w["sign_convention"]) == 1
    if a.diagrams is not None:
        sc = a.diagrams.sheet_check
        lim = mmt_plans.i18n.catalogue(lang).number(sc.limit_percent)
        assert (w["passed"].format(lim=lim) in text) == sc.passed
        assert (w["failed"].split("{")[0] in text) == (not sc.passed)


def test_moment_equations_name_every_arm():
    """Seed 003 §2.7: ΣM_B = 0 of link 3 with the arms of G3, F_in3 and R43."""
    a = solved(ROOT / "samples/six_link_press.toml")
    text = note(ROOT / "samples/six_link_press.toml", "en").text()
    assert "ΣM_B(3) = G_3·h_1 + F_in3·h_2 + R_43·h_3 - R^τ_03·l_CB = 0;" in text
    assert "ΣM_E(4) = G_4·h_1 + F_in4·h_2 - R^τ_34·l_DE = 0;" in text
    # every arm in mm of the drawing and in m
    assert len(re.findall(r"h_\d = -?[\d.]+ mm·μ_l = .* m; M_", text)) >= 7
    # the driving link's polygon in the textbook's order, each force a vector (issue 22)
    v = "\u20d7"
    assert f"G{v}_1 + F{v}_in1 + R{v}_21 + F{v}_bal.pl + R{v}_01 = 0" in text
    assert a.forces is not None


def test_analyze_prints_the_gear_train_and_the_reduction():
    """`mmt-plans analyze` (report.py): Willis' steps and M_red, J_red at every position."""
    from mmt_plans.report import text_report

    a = solved(SEED002_GEARS)
    text = text_report(a)
    train = a.mechanism.drive.gear_train
    assert "Willis" in text and "u35^H" in text and "u3H^5 = 1 − u35^H" in text
    assert f"u_m1 = u12·u3H^5 = (−4.000)·{float(train.stages[1].exact_ratio):.3f}" in text
    assert "Reduction to the crank" in text
    k = a.entry(a.force_position)
    J = results(a)
    kin = J["kinematics"][k]
    w1 = a.mechanism.drive.omega
    energy = sum(
        lk.mass * _hyp(kin["v_cm"][str(lid)]) ** 2 + lk.J * kin["omega"][str(lid)] ** 2
        for lid, lk in a.mechanism.links.items()
    )
    assert f"{energy / w1**2:.6g}" in text
    assert "Gear train" not in text_report(solved(ROOT / "samples/six_link_press.toml"))


NUM = r"\(?(-?\d+(?:\.\d+)?)\)?"


@pytest.mark.parametrize(
    "path", [SEED002_PRP, ROOT / "samples/tasks/seed003/task11_v1.toml"], ids=lambda p: p.stem
)
def test_prismatic_reactions_by_projections_and_moments(path):
    """PRP and RPP (seed 000/003): each reaction normal to a guide from ΣF
    projected on the other guide, its point from ΣM about the revolute pair.
    The printed numbers (each checked against its source above) must also
    satisfy the printed equations: F·cos = projection, the projections' sum,
    R = -ΣF_t/cos, h = -ΣM/R, and every reaction normal to a guide solved so."""
    a, content = solved(path), note(path, "en")
    text = content.text()
    kinds = {g.kind for g in a.forces.groups}
    assert kinds & {"PRP", "RPP"}
    lines = text.splitlines()
    solved_names = []
    for k, line in enumerate(lines):
        m = re.fullmatch(rf"(\S+) = -ΣF_t/cos\(\1, t\) = -?{NUM}/{NUM} = {NUM} N.*", line)
        if not m:
            continue
        total, c, value = (float(x) for x in m.groups()[1:])
        assert value == pytest.approx(-total / c, rel=2e-3, abs=0.5)
        # the projections above it add up to the sum
        proj = []
        for prev in reversed(lines[:k]):
            if not prev.startswith(("Projections", "ΣF_t")) and "cos(" not in prev:
                break
            pm = re.fullmatch(rf"\S+·cos\(\S+, t\) = {NUM}·{NUM} = {NUM} N", prev)
            if pm:
                F, cosine, p = (float(x) for x in pm.groups())
                assert p == pytest.approx(F * cosine, rel=5e-3, abs=0.5)
                assert -1.0 - 1e-9 <= cosine <= 1.0 + 1e-9
                proj.append(p)
            if prev.startswith("Projections"):
                break
        assert total == pytest.approx(sum(proj), rel=2e-3, abs=1.0)
        solved_names.append(m.group(1))
    normal = {
        r.name
        for g in a.forces.groups
        if g.kind in ("PRP", "RPP")
        for r in g.reactions
        if r.kind == "P"
    }
    from mmt_plans.note.sections_forces import force_markup

    assert set(solved_names) == {plain(force_markup(n)) for n in normal}
    assert not re.search(r"-\(?0(?![.\d])", text)  # no negative zero, not even as -ΣM = -0
    arms = re.findall(rf"h_\d = -ΣM_\S+/\S+ = -?{NUM}/{NUM} = {NUM} m", text)
    # a reaction whose link's other forces all pass through the pin passes through it too
    through = re.findall(rf"ΣM_\S+ = \S+·h_\d = 0; h_\d = {NUM} m", text)
    assert arms or through
    assert all(float(h) == 0 for h in through)
    for moment, value, h in arms:
        assert float(h) == pytest.approx(-float(moment) / float(value), rel=2e-3, abs=1e-4)
