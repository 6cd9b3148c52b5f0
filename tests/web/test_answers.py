"""The door between a form and `check`: numbers as students type them, the
answers TOML written for the check's loader, the report withheld."""

import math
import tomllib

import pytest

from mmt_plans.errors import SpecError
from mmt_plans.web.answers import dump_toml, parse_number, split_student
from mmt_plans.web.ratelimit import TokenBuckets


@pytest.mark.parametrize(
    "text, value",
    [("1.25", 1.25), ("1,25", 1.25), (" -3 ", -3.0), ("\u22124.5", -4.5), ("1e3", 1000.0),
     ("12 400", 12400.0), ("0", 0.0)],
)
def test_numbers_as_students_type_them(text, value):
    assert parse_number(text) == value


@pytest.mark.parametrize("text", ["", "abc", "1,2.3", "nan", "inf", "-inf", "1e400", "1" * 41, "0x10"])
def test_what_is_not_a_number(text):
    assert parse_number(text) is None


def test_dump_toml_reads_back_as_the_same_tables():
    data = {
        "check": {"tolerance_percent": 5},
        "position": [{"index": 3, "velocity": {"B": 1.5, 'we"ird\\': -0.0}, "omega": {"2": -1e-300}}],
        "forces": {"index": 3, "reactions": {"R12": 15100.0}},
        "diagrams": {"check_passed": True, "note": "text"},
    }
    back = tomllib.loads(dump_toml(data))
    assert back == data
    assert math.copysign(1.0, back["position"][0]["velocity"]['we"ird\\']) == -1.0


def test_dump_toml_refuses_a_deep_nest():
    deep = {"a": 1}
    for _ in range(20):
        deep = {"x": deep}
    with pytest.raises(SpecError, match="nested too deeply"):
        dump_toml(deep)


def test_the_student_table_is_taken_off_the_answers():
    data, who = split_student({"student": {"name": " Ivan ", "group": "MM-1"}, "forces": {}}, "a")
    assert data == {"forces": {}} and who == {"name": "Ivan", "group": "MM-1"}
    with pytest.raises(SpecError, match="student"):
        split_student({"student": "Ivan"}, "a")


def test_token_bucket_refills_at_its_rate():
    now = [0.0]
    b = TokenBuckets(burst=3, rate=1.0, clock=lambda: now[0])
    assert [b.take("a") for _ in range(3)] == [0.0, 0.0, 0.0]
    assert b.take("a") == pytest.approx(1.0)
    assert b.take("b") == 0.0  # another client has its own bucket
    now[0] = 2.0
    assert b.take("a") == 0.0 and b.take("a") == 0.0 and b.take("a") > 0
    assert b.take("a", cost=5) > 0


def test_token_buckets_stay_bounded():
    now = [0.0]
    b = TokenBuckets(burst=2, rate=1.0, clients_max=100, clock=lambda: now[0])
    for k in range(1000):
        b.take(f"c{k}")
    assert len(b._buckets) <= 101


def test_the_web_words_have_the_same_keys_in_every_language():
    from mmt_plans.i18n import LANGUAGES
    from mmt_plans.web.app import words

    keys = {lang: set(words(lang)) for lang in LANGUAGES}
    assert keys["en"] == keys["uk"] and len(keys["en"]) > 50
