"""#26, keep the fuzzer ahead: the geometry grammar of tests/fuzz.py edits
mechanisms the way they go wrong (and stays valid TOML), the near-toggle edit
really lands at the edge of assembly, hostile file names keep messages
clean, and a case far slower than its family fails `make fuzz`."""

from __future__ import annotations

import json
import random
import tomllib
from pathlib import Path

import pytest

import fuzz
import mmt_plans
from mmt_plans.errors import shown

ROOT = Path(__file__).resolve().parents[1]
SMALL = ROOT / "samples" / "offset_slider_crank.toml"
PRESS = ROOT / "samples" / "six_link_press.toml"


def parsed(path: Path) -> dict:
    return tomllib.loads(path.read_text(encoding="utf-8"))


@pytest.mark.parametrize("op", fuzz.GEOMETRY, ids=lambda op: op.__name__)
def test_each_geometry_edit_changes_the_file_and_stays_valid_toml(op):
    for seed in range(5):
        data = parsed(PRESS)
        before = json.dumps(data, sort_keys=True)
        step = op(random.Random(seed), data, PRESS)
        assert "(no" not in step and "none" not in step, step
        assert json.dumps(data, sort_keys=True) != before, step
        tomllib.loads(fuzz.dumps(data))  # a valid file in form


def test_the_near_toggle_edit_lands_at_the_edge_of_assembly():
    data = parsed(SMALL)
    edge = fuzz._crank_edge(SMALL, data)
    # offset slider-crank r = 100, l = 400, e = 30: the crank turns fully while
    # r + e <= l, i.e. up to r = 370 mm: the factor 3.7 (by hand, not by the code)
    assert edge == pytest.approx(3.7, rel=1e-3)

    def assembles(f: float) -> bool:
        trial = parsed(SMALL)
        fuzz._scale_link(trial["link"][0], f)
        try:
            mmt_plans.solve(mmt_plans.loads(fuzz.dumps(trial), "t.toml"), forces=False)
        except mmt_plans.MmtError:
            return False
        return True

    assert assembles(3.69) and not assembles(3.71)


def test_unloaded_edit_leaves_massless_links_without_forces():
    data = parsed(PRESS)
    for seed in range(10):
        d = json.loads(json.dumps(data))
        fuzz.g_unloaded(random.Random(seed), d, PRESS)
        zero = {l["id"] for l in d["link"] if l.get("mass") == 0}
        assert zero and not any(f.get("link") in zero for f in d.get("force", []))


def test_angles_near_the_wrap_are_offered():
    flat = [a for angles in fuzz.NEAR_WRAP_ANGLES for a in angles]
    assert 359.9999999999 in flat and 1e-12 in flat


@pytest.mark.parametrize("name", fuzz.HOSTILE_PATHS)
def test_a_hostile_file_name_keeps_the_message_clean(tmp_path, name):
    # a damaged file under that name: the message starts with the name escaped
    path = tmp_path / name
    outcome = fuzz.check(b"[drive]\nrpm = \n", str(path))
    assert outcome.kind == "clean error", outcome
    with pytest.raises(mmt_plans.SpecError) as err:
        mmt_plans.load(path)
    text = str(err.value)
    assert text.startswith(shown(path)) and all(line.isprintable() for line in text.split("\n"))


def _timed(seconds: list[float], drawn: float | None = None):
    src = SMALL
    out = []
    for i, s in enumerate(seconds):
        m = fuzz.Mutant(i, src, b"", kind="geometry")
        out.append((m, fuzz.Outcome("analysed", s)))
    return out


def test_a_case_ten_times_its_family_median_is_slow():
    timed = _timed([0.2] * 10 + [2.5, 1.5])
    slow = fuzz.slow_cases(timed)
    assert [m.case for m, _, _ in slow] == [10]  # 12.5x; 7.5x is not
    assert "the median 0.200 s of offset_slider_crank:geometry:analysed" in slow[0][2]


def test_timer_noise_below_the_floor_is_not_slow():
    assert fuzz.slow_cases(_timed([0.01] * 10 + [0.5])) == []


def test_a_slow_case_fails_make_fuzz(monkeypatch, capsys):
    from collections import Counter

    m = fuzz.Mutant(7, SMALL, b"", kind="geometry")
    monkeypatch.setattr(fuzz, "run", lambda *a, **k: (
        Counter({"analysed": 10, "slow": 1}), [(m, fuzz.Outcome("slow", 3.0, "30x"))]))
    assert fuzz.main(["--cases", "10"]) == 1
    assert "slow              1" in capsys.readouterr().out


def test_a_small_family_is_compared_with_its_kind_among_the_same_outcome():
    # two analysed mutants of one source (too few for a family) among many
    # quick refusals: compared with the analysed of their kind, not the refused
    timed = [(fuzz.Mutant(i, PRESS, b"", kind="structural"), fuzz.Outcome("clean error", 0.001))
             for i in range(50)]
    timed += [(fuzz.Mutant(100 + i, SMALL, b"", kind="structural"), fuzz.Outcome("analysed", s))
              for i, s in enumerate([1.2, 1.1, 0.9])]
    assert fuzz.slow_cases(timed) == []


def test_slow_and_hung_are_judged_in_processor_time_not_on_the_wall_clock():
    # fuzz seed 12 case 3888 (five_dyads, link 1 scaled) drew in 56 s of wall
    # time but 6 s of processor beside 15 busy processes: not slow
    waited = fuzz.Outcome("analysed", 9.0, "", "drawn", 75.0, cpu=0.2, draw_cpu=6.4)
    assert not waited.slow
    assert fuzz.Outcome("analysed", 0.3, "", "drawn", 7.0, cpu=0.2, draw_cpu=61.0).slow
    assert fuzz.Outcome("analysed", 6.0).slow  # no processor time taken: the wall clock


def test_a_busy_loop_is_stopped_by_the_processor_clock(monkeypatch):
    import mmt_plans

    def spin(path):
        while True:
            pass

    monkeypatch.setattr(mmt_plans, "load", spin)
    outcome = fuzz.check(b"", timeout=0.3)
    assert outcome.kind == "hung" and "s of processor" in outcome.detail
    assert outcome.work >= 0.25  # the kernel's accounting is in ticks


def test_a_case_waiting_without_working_is_stopped_by_the_wall_clock(monkeypatch):
    import time

    import mmt_plans

    monkeypatch.setattr(mmt_plans, "load", lambda path: time.sleep(30))
    outcome = fuzz.check(b"", timeout=60, wall_timeout=0.3)
    assert outcome.kind == "hung" and outcome.seconds < 10


def test_a_stopped_run_reports_the_cases_it_ran():
    # a long run on a shared machine may be stopped (SIGTERM): what it ran is
    # still counted and reported, and the run does not pass
    asked = iter([False, False, True])
    counts, _ = fuzz.run(1, 10, start=0, stop=lambda: next(asked))
    assert counts["cases"] == 2
    assert counts["cases"] == sum(counts[k] for k in (
        "analysed", "clean error", "unexpected", "non-finite", "bad message", "hung", "known bug"))


def test_sigterm_ends_make_fuzz_after_the_case_with_its_counts(capsys, monkeypatch):
    import os
    import signal

    real = fuzz.check
    calls = []

    def check_then_terminate(*a, **k):
        calls.append(1)
        if len(calls) == 2:
            os.kill(os.getpid(), signal.SIGTERM)
        return real(*a, **k)

    monkeypatch.setattr(fuzz, "check", check_then_terminate)
    assert fuzz.main(["--cases", "50", "--seed", "1"]) == 1
    out = capsys.readouterr().out
    assert "2 mutants (cases 0..1)" in out and "stopped by signal 15 before the 50" in out
