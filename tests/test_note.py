"""The A4 calculation note: seed 003 §IV order, the solver's numbers, pages, PDF."""

from __future__ import annotations

import math
import re
from pathlib import Path

import numpy as np
import pytest

import mmt_plans
from mmt_plans.note import (
    draw_note,
    layout_note,
    note_content,
    note_document,
    number,
    write_note,
)
from mmt_plans.note.pages import note_page
from mmt_plans.render.recording import RecordingBackend

ROOT = Path(__file__).resolve().parents[1]
PRESS = ROOT / "samples" / "six_link_press.toml"
SMALL = ROOT / "samples" / "offset_slider_crank.toml"
SAMPLES = sorted((ROOT / "samples").glob("*.toml"))

SEED003_ORDER = [
    "sheet1",
    "1.1",
    "1.2",
    "1.3",
    "1.4",
    "1.5",
    "1.6",
    "1.7",
    "1.8",
    "sheet2",
    "2.1",
    "2.2",
    "2.3",
    "2.4",
    "2.5",
]


@pytest.fixture(scope="module")
def press():
    analysis = mmt_plans.solve(mmt_plans.load(PRESS))
    return analysis, note_content(analysis, "en")


def test_steps_in_seed003_order(press):
    analysis, note = press
    groups = len(analysis.structure.groups)
    # 2.6 ... one item per group (the last attached first), the driving link,
    # the reactions, the lever and the comparison (21)
    tail = [f"2.{6 + j}" for j in range(groups + 4)]
    # the reduction to the crank (M_red, J_red) in every note (issue 22), then the conclusions
    reduction = ["reduction", "reduction.M", "reduction.J"]
    assert note.steps == SEED003_ORDER + tail + reduction + ["conclusions"]
    text = note.text()
    headings = [text.index(f"\n{s}. ") for s in SEED003_ORDER if s[0].isdigit() and "." in s]
    assert headings == sorted(headings)


def test_mobility_with_numbers(press):
    analysis, note = press
    st = analysis.structure
    assert f"W = 3n - 2p_5 - p_4 = 3·{st.n} - 2·{st.p5} - {st.p4} = {st.W}" in note.text()
    assert st.formula in note.text()


def test_crank_velocity_is_omega_times_length(press):
    # ω1 = π·n1/30 = π·100/30 = 10.47 rad/s (3); V_A = ω1·l_OA = 10.47·0.2 = 2.094 m/s (4)
    analysis, note = press
    text = note.text()
    w1 = math.pi * 100 / 30
    l_oa = 0.2
    assert analysis.mechanism.crank_length == pytest.approx(l_oa)
    assert f"ω_1 = π·n_1/30 = π·100/30 = {number(w1)} rad/s" in text
    assert f"V_A = ω_1·l_OA = {number(w1)}·{number(l_oa)} = {number(w1 * l_oa)} m/s" in text
    assert "2.094 m/s" in text


def test_plan_numbers_are_the_solvers(press):
    analysis, note = press
    text = note.text()
    for i in analysis.plan_positions:
        view = analysis.plan(i)
        vB = float(np.hypot(*view.velocity_images["B"]))
        aE = float(np.hypot(*view.acceleration_images["E"]))
        assert re.search(rf"V_B = pb·μ_V = [\d.]+·[\d.]+ = {re.escape(number(vB))} m/s", text)
        assert re.search(rf"a_E = πe·μ_a = [\d.]+·[\d.]+ = {re.escape(number(aE))} m/s²", text)
        for lid in (2, 3, 4):
            assert f"= {number(abs(view.omega[lid]))} rad/s" in text
            assert f"= {number(abs(view.eps[lid]))} rad/s²" in text


def test_balancing_force_by_both_methods(press):
    analysis, note = press
    fa = analysis.forces_at()
    text = note.text()
    assert f"= {number(fa.balancing_force_plans)} N" in text
    assert re.search(rf"F_bal\.pl = .* = {re.escape(number(fa.balancing_force_plans))} N", text)
    assert re.search(rf"F_bal\.z = .* = {re.escape(number(fa.balancing_force_lever))} N", text)
    assert f"= {number(fa.discrepancy_percent, sig=3)} %" in text
    for lid, ll in fa.loads.links.items():
        assert f"G_{lid} = m_{lid}·g = {number(ll.mass)}·9.81 = {number(ll.mass * 9.81)} N" in text


def test_ukrainian_note(press):
    analysis, _ = press
    uk = note_content(analysis, "uk")
    text = uk.text()
    assert "Структурний аналіз механізму" in text
    assert "рад/с" in text and "Н" in text
    w1 = math.pi * 100 / 30
    assert f"V_A = ω_1·l_OA = {number(w1, 'uk')}·0,2 = {number(w1 * 0.2, 'uk')} м/с" in text
    assert uk.steps == note_content(analysis, "en").steps
    with pytest.raises(ValueError):
        note_content(analysis, "de")  # type: ignore[arg-type]


def test_pages_stay_inside_the_text_area(press):
    analysis, note = press
    pages = layout_note(note)
    assert len(pages) > 1
    frame = note_page().frame
    for p in pages:
        for line in p.lines:
            assert frame.left + 5 - 1e-9 <= line.x
            assert line.y >= frame.bottom + 15 + 10 - 1e-9
            assert line.y <= frame.top - 10


def test_every_page_drawn_with_frame_and_stamp(press):
    analysis, _ = press
    backends = draw_note(analysis, lambda w, h, title: RecordingBackend(w, h))
    # the title page and the task sheet have no frame (DSTU 3008: tests/note/)
    backends = [b for b in backends if any(c.args.get("id") == "frame" for c in b.calls)]
    assert len(backends) > 1
    for b in backends:
        groups = {c.args["id"] for c in b.calls if c.name == "begin_group"}
        assert "frame" in groups
        assert ("title-block" in groups) != ("form-2a" in groups)
    assert backends[0].width == 210.0 and backends[0].height == 297.0


def _pdf_pages(path: Path) -> int:
    return len(re.findall(rb"/Type\s*/Page[^s]", path.read_bytes()))


def test_one_multi_page_pdf(tmp_path):
    analysis = mmt_plans.solve(mmt_plans.load(SMALL))
    pages = len(note_document(analysis, "uk").pages)
    target = write_note(analysis, tmp_path / "sub" / "note.pdf", lang="uk")
    assert target.read_bytes().startswith(b"%PDF")
    assert _pdf_pages(target) == pages > 1


@pytest.mark.parametrize("path", SAMPLES, ids=lambda p: p.stem)
def test_every_sample_has_a_note(path):
    analysis = mmt_plans.solve(mmt_plans.load(path))
    for lang in ("en", "uk"):
        note = note_content(analysis, lang)  # type: ignore[arg-type]
        assert note.steps[:9] == SEED003_ORDER[:9]
        assert layout_note(note)
