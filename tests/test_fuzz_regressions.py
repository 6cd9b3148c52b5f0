"""One regression test per bug the fuzzer found (tests/fuzz.py), named after
it: each reproducer now ends in a clean error naming the file (exit 2)."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

import mmt_plans
from mmt_plans.errors import MmtError

TASKS = Path(__file__).resolve().parents[1] / "samples" / "tasks"
SAMPLES = Path(__file__).resolve().parents[1] / "samples"


def with_points(text: str, link: int, points: str) -> str:
    i = text.index(f"id = {link}\n")
    j = text.index("points", i)
    k = text.index("\n", j)
    return text[:j] + f"points = {points}" + text[k:]


def refused(text: str, name: str) -> str:
    with pytest.raises(MmtError) as err:
        mmt_plans.solve(mmt_plans.loads(text, name))
    assert str(err.value).startswith(name)
    return str(err.value)


def test_crank_blocked_in_a_window_narrower_than_the_grid_is_refused():
    # seed 002 task 1 v07 with C at 116 mm on link 3: no assembly for phi1 ~ 4.7–9.7°
    text = (TASKS / "seed002" / "task1_v07.toml").read_text()
    text = with_points(text, 3, "{ O2 = [0, 0], B = [78, 0], C = [116, 0] }")
    message = refused(text, "narrow.toml")
    assert "cannot make a whole turn" in message and "°…" in message


def test_group_fixed_to_the_frame_only_by_revolutes_is_a_clean_error():
    # seed 003 task 4 v1 with link 4 pinned at the frame pivot O2 instead of B
    text = with_points((TASKS / "seed003" / "task04_v1.toml").read_text(), 4,
                       "{ O2 = [0, 0], D = [600, 0] }")
    refused(text, "frame-group.toml")


def test_group_of_two_sliders_on_the_frame_with_parallel_guides_is_refused():
    text = (TASKS / "seed002" / "task6_v07.toml").read_text()
    parts = text.split("[[slider]]")
    parts[2] = parts[2].replace("on = 3\n", "", 1)
    message = refused("[[slider]]".join(parts), "parallel.toml")
    # #26: both outer pairs of group 4-5 are then on the frame: refused by the
    # structure (it holds to no moving link) before the guides are compared
    assert "group II(4,5)" in message and "no pair to a moving link" in message


def test_a_sketched_frame_point_is_accepted():
    text = (SAMPLES / "six_link_press.toml").read_text().replace("[sketch]\n",
                                                                  "[sketch]\nC = [750, -80]\n")
    solution = mmt_plans.solve(mmt_plans.loads(text, "sketch.toml"))
    assert solution.branches.rule == "sketch" and solution.branches.whole_turn
    assert re.fullmatch(r"I\(0,1\) <- II\(2,3\) <- II\(4,5\)", solution.structure.formula)


def test_partial_turn_opted_in_but_assembling_nowhere_is_refused():
    # fuzz case 13658 (seed 1): seed-003 task 10 v3 with partial_turn and O2 renamed A
    text = (TASKS / "seed003" / "task10_v3.toml").read_text()
    text = text.replace("[study]\n", "[study]\npartial_turn = true\n", 1)
    text = with_points(text, 3, "{ A = [0, 0], B = [550, 0] }")
    message = refused(text, "nowhere.toml")
    assert "assembles at no crank angle" in message


def test_a_bidi_override_in_the_file_name_is_escaped_in_the_solvers_messages():
    # fuzz seed 3 case 1284: seed-002 task 6 v02 saved as 'bidi\u202egpj.toml'
    # with a working direction its output does not move along; the solver's
    # message carried the raw U+202E (it reverses the rest of the line)
    from fuzz import mutant

    m = mutant(3, 1284)
    name = "bidi\u202egpj.toml"
    with pytest.raises(MmtError) as err:
        mmt_plans.solve(mmt_plans.loads(m.data.decode("utf-8"), name))
    message = str(err.value)
    assert message.startswith("bidi\\u202egpj.toml: output")
    assert all(ch.isprintable() or ch == "\n" for ch in message), message
