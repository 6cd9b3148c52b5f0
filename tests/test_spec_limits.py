"""The input limits (README, "Input limits"): every number finite and within
its bounds, names printable and short, lists where lists are meant, the
sizes of the file bounded. Each refusal names the file, the entry and a fix;
a value at the limit is accepted."""

from __future__ import annotations

import re
import time
from pathlib import Path

import pytest

import mmt_plans
from mmt_plans.structure import analyse_structure
from mmt_plans import spec
from mmt_plans.check import LIMITS as ANSWER_LIMITS

ROOT = Path(__file__).resolve().parents[1]
PRESS = (ROOT / "samples" / "six_link_press.toml").read_text(encoding="utf-8")
GEARS = '\n[gears]\nmotor_rpm = 1450\n[[gears.stage]]\nz = [20, 40]\nmesh = "external"\n'


def edited(old: str, new: str, text: str = PRESS) -> str:
    assert old in text, old
    return text.replace(old, new, 1)


def without_rpm(text: str = PRESS) -> str:
    return edited("rpm = 100", "", text)


MANY_LINKS = "".join(f"\n[[link]]\nid = {i}\npoints = {{ Z{i} = [0, 0], Y{i} = [10, 0] }}\n"
                     for i in range(6, 27))
MANY_POINTS = ", ".join(f"Q{i} = [{i + 1}, 5]" for i in range(20))
FRAME_POINTS = "".join(f"P{i} = [{i}, {-i}]\n" for i in range(50))

CASES = [
    # (name, text, entry, words of the problem)
    ("positions 2", edited("positions = 12", "positions = 2"), "study.positions", "4 or more"),
    ("positions 3", edited("positions = 12", "positions = 3"), "study.positions", "4 or more"),
    ("positions 361", edited("positions = 12", "positions = 361"), "study.positions",
     "more than the 360"),
    ("positions 2**63-1", edited("positions = 12", f"positions = {2**63 - 1}"),
     "study.positions", "more than the 360"),
    ("positions 10**30", edited("positions = 12", f"positions = {10**30}"), "study.positions",
     "more than the 360"),
    ("plans empty", edited("plans = [2, 8]", "plans = []"), "study.plans", "non-empty list"),
    ("plans nested", edited("plans = [2, 8]", "plans = [[2], 8]"), "study.plans",
     "non-empty list"),
    ("zero nan", edited('zero = "extreme"', "zero = nan"), "study.zero", "not nan"),
    ("zero inf", edited('zero = "extreme"', "zero = -inf"), "study.zero", "not -inf"),
    ("angles inf", edited("angles = []", "angles = [inf]"), "study.angles", "not [inf]"),
    ("angles nan", edited("angles = []", "angles = [10, nan]"), "study.angles", "crank angles"),
    ("101 angles", edited("angles = []", f"angles = {list(range(101))}"), "study.angles",
     "more than the 100"),
    ("working direction tiny", edited("working_direction = [1, 0]",
                                      "working_direction = [1e-300, 0]"),
     "study.working_direction", "too short"),
    ("rpm 1e308", edited("rpm = 100", "rpm = 1e308"), "drive.rpm", "between 0.001 and 100000"),
    ("rpm 5e-324", edited("rpm = 100", "rpm = 5e-324"), "drive.rpm", "between 0.001"),
    ("rpm 10**400", edited("rpm = 100", f"rpm = {10**400}"), "drive.rpm", "must be a number"),
    ("omega 1e6", edited("rpm = 100", "omega = 1e6"), "drive.omega",
     "between 0.001 and 100000 rad/s"),
    ("sense a list", edited('sense = "ccw"', "sense = []"), "drive.sense", "not []"),
    ("motor_rpm 1e308", without_rpm(PRESS + GEARS.replace("1450", "1e308")), "gears.motor_rpm",
     "between 0.001 and 100000"),
    ("tooth count 10**6", without_rpm(PRESS + GEARS.replace("[20, 40]", "[20, 1000000]")),
     "gears.stage[1].z", "above 10000"),
    ("crank too fast", without_rpm(PRESS + GEARS.replace("1450", "100000")
                                   .replace("[20, 40]", "[40, 1]")),
     "gears", "turns the crank at 4e+06 rpm"),
    ("21 stages", without_rpm(PRESS + GEARS + '[[gears.stage]]\nz = [20, 20]\nmesh = "internal"\n'
                              * 20), "gears.stage", "21 stages"),
    ("mass 1e308", edited("mass = 50", "mass = 1e308"), "link[2] (id 2).mass", "at most 1e+06 kg"),
    ("J 1e7", edited("mass = 50", "mass = 50\nJ = 1e7"), "link[2] (id 2).J", "at most 1e+06"),
    ("k 100", edited("mass = 50", "mass = 50\nk = 100"), "link[2] (id 2).k", "at most 10"),
    ("coordinate 1e300", edited("B = [850, 0]", "B = [1e300, 0]"), "link[2] (id 2).points.B",
     "coordinate of 1e+300 mm"),
    ("frame 1e6 mm", edited("O = [0, 0]\nC", "O = [0, 1e6]\nC"), "frame.O", "100,000 mm"),
    ("sketch far", edited("E = [1396, 700]", "E = [1396, -1e9]"), "sketch.E", "100,000 mm"),
    ("guide far", edited("through = [0, 700]", "through = [0, 7e5]"), "slider[1].through",
     "100,000 mm"),
    ("cm far", edited("mass = 50", "mass = 50\ncm = [1e7, 0]"), "link[2] (id 2).cm", "100,000 mm"),
    ("points 0.001 mm apart", edited("B = [850, 0]", "B = [0.001, 0]"), "link[2] (id 2).points",
     "0.001 mm apart, less than 0.01 mm"),
    ("force 1e10 N", edited("magnitude = 9000", "magnitude = 1e10"), "force[1].magnitude",
     "at most 1e+09 N"),
    ("force at []", edited('at = "E"', "at = []"), "force[1].at", "point [] is not on link 5"),
    ("force at ['E']", edited('at = "E"', 'at = ["E"]'), "force[1].at", "point ['E'] is not on"),
    ("force direction tiny", edited('at = "E"', 'at = "E"\ndirection = [5e-324, 0]'),
     "force[1].direction", "too short"),
    ("force name a list", edited('name = "F_PR"', "name = [1]"), "force[1].name",
     "must be a force name"),
    ("force name with a tab", edited('name = "F_PR"', 'name = "F\\tPR"'), "force[1].name",
     "F\\tPR"),
    ("g 1e4", PRESS + "\n[env]\ng = 1e4\n", "env.g", "at most 1000 m/s2"),
    ("higher pair unhashable", PRESS + "\n[[higher_pair]]\nlinks = [[1], 2]\n",
     "higher_pair[1].links", "two existing links"),
    ("higher pair to itself", PRESS + "\n[[higher_pair]]\nlinks = [2, 2]\n",
     "higher_pair[1].links", "joins link 2 to itself"),
    ("higher pair of a bool", PRESS + "\n[[higher_pair]]\nlinks = [true, 2]\n",
     "higher_pair[1].links", "two existing links"),
    ("higher pair not a list", PRESS + "\n[higher_pair]\nlinks = [1, 2]\n", "higher_pair",
     "array of tables"),
    ("title with NUL", edited('title = "Six-link press (crank, rocker, slider)"',
                              'title = "a\\u0000b"'), "title", "'a\\x00b' has a control"),
    ("title too long", edited('title = "Six-link press (crank, rocker, slider)"',
                              f'title = "{"x" * 201}"'), "title", "201 characters"),
    ("sheet field a table", PRESS + '\n[sheet]\nauthor = { a = 1 }\n', "sheet.author",
     "must be a string"),
    ("point name with a newline", edited("D = [620, 506]", 'D = [620, 506]\n"B\\nC" = [1, 1]'),
     "sketch.B\\nC", "does not exist"),
    ("point name too long", edited("O = [0, 0]\nC", f'O = [0, 0]\n{"Q" * 33} = [5, 5]\nC'),
     "frame." + "Q" * 32 + "...", "33 characters is too long"),
    ("empty point name", edited("O = [0, 0]\nC", 'O = [0, 0]\n"" = [5, 5]\nC'), "frame.",
     "must not be empty"),
    ("26 links", PRESS + MANY_LINKS, "link", "26 links, more than the 25"),
    ("21 points on a link", edited("points = { A = [0, 0], B = [850, 0] }",
                                   "points = { A = [0, 0], B = [850, 0], " + MANY_POINTS + " }"),
     "link[2] (id 2).points", "22 points, more than the 20"),
    ("51 frame points", edited("O = [0, 0]\n", "O = [0, 0]\n" + FRAME_POINTS), "frame",
     "52 points, more than the 50"),
    ("link id 1000", edited("id = 5", "id = 1000"), "link[5] (id 1000).id", "more than 999"),
    ("nested 1000 deep", PRESS + "\nx = " + "[" * 1000 + "]" * 1000 + "\n", "TOML",
     "nested too deeply"),
    ("an integer of 5000 digits", PRESS + "\nx = 1" + "0" * 5000 + "\n", "TOML",
     "cannot be read"),
]


@pytest.mark.parametrize("name,text,entry,words", CASES, ids=[c[0] for c in CASES])
def test_out_of_limits_is_refused(tmp_path, name, text, entry, words):
    path = tmp_path / "limits.toml"
    path.write_text(text, encoding="utf-8")
    t0 = time.perf_counter()
    with pytest.raises(mmt_plans.SpecError) as err:
        mmt_plans.load(path)
    assert time.perf_counter() - t0 < 2.0
    message = str(err.value)
    assert message.startswith(f"{path}: {entry}: "), message
    assert words in message, message
    assert "\n  fix: " in message
    # one line of problem and one of fix, each printable: nothing raw from the file
    assert len(message.split("\n")) == 2 and all(line.isprintable()
                                                 for line in message.split("\n"))


AT_THE_LIMIT = [
    ("positions 4", edited("positions = 12", "positions = 4").replace("plans = [2, 8]",
                                                                      "plans = [1, 3]")),
    ("positions 360", edited("positions = 12", "positions = 360")),
    ("100 angles", edited("angles = []", f"angles = {list(range(0, 1000, 10))}")),
    ("angles beyond a turn", edited("angles = []", "angles = [-30, 750, 1e300]")),
    ("zero beyond a turn", edited('zero = "extreme"', "zero = -690")),
    ("slider angle beyond a turn", edited("angle = 0", "angle = 1e200")),
    ("mass 1e6", edited("mass = 50", "mass = 1e6")),
    ("rpm 1e5", edited("rpm = 100", "rpm = 1e5")),
    ("rpm 0.001", edited("rpm = 100", "rpm = 0.001")),
    ("force 1e9 N", edited("magnitude = 9000", "magnitude = 1e9")),
    ("coordinates at 100 m", edited("C = [750, -80]", "C = [750, -80]\nF = [100000, -100000]")),
    ("a UTF-8 name", edited('title = "Six-link press (crank, rocker, slider)"',
                            'title = "Шестиланковий прес 𝔸"')),
    ("a group number", PRESS + "\n[sheet]\ngroup = 21\n"),
]


@pytest.mark.parametrize("name,text", AT_THE_LIMIT, ids=[c[0] for c in AT_THE_LIMIT])
def test_values_at_the_limit_are_accepted(tmp_path, name, text):
    path = tmp_path / "ok.toml"
    path.write_text(text, encoding="utf-8")
    mech = mmt_plans.load(path)
    assert analyse_structure(mech).W == 1


def test_angles_and_zero_are_taken_mod_360():
    mech = mmt_plans.loads(edited('zero = "extreme"', "zero = -690")
                           .replace("angles = []", "angles = [750, -30]"))
    assert mech.study.zero == pytest.approx(30.0)
    assert mech.study.angles == pytest.approx((30.0, 330.0))


def test_a_file_name_with_a_control_character_makes_a_printable_title(tmp_path):
    path = tmp_path / "bad\x1bname.toml"
    path.write_text(edited('title = "Six-link press (crank, rocker, slider)"\n', ""),
                    encoding="utf-8")
    assert mmt_plans.load(path).title == "bad\\x1bname"


def test_the_limit_on_links_keeps_the_structure_search_fast():
    """The worst case measured for README: 25 links that do not split into
    Assur groups (the search tries every 2, 4 and 6 of the 24 moving links)."""
    text = _undecomposable_chain(12)
    assert text.count("[[link]]") == spec.LINKS_MAX
    t0 = time.perf_counter()
    with pytest.raises(mmt_plans.StructureError, match="do not split into Assur groups"):
        analyse_structure(mmt_plans.loads(text, "chain.toml"))
    assert time.perf_counter() - t0 < 15.0  # ~2 s on one core of the reference machine


def _undecomposable_chain(m: int) -> str:
    """A crank and m four-bar stages (2m + 1 links), W = 1, that cannot be
    decomposed: the first rocker is fixed by a second frame pivot (W -1 there),
    the last rocker lost its pivot (W +1 there)."""
    lines = ['title = "chain"', "[drive]", "link = 1", "rpm = 60", "[study]",
             f'output = "D{m}"', "[frame]", "O = [0, 0]", "E1 = [5000, 5000]"]
    links = ["[[link]]\nid = 1\npoints = { O = [0, 0], A = [200, 0] }\nmass = 1"]
    prev, p = "A", (200.0, 0.0)
    for k in range(1, m + 1):
        c = (p[0] + 750.0, p[1] - 80.0)
        b = (c[0] + 40.0, c[1] + 840.0)
        d = (c[0] + 0.6 * (b[0] - c[0]), c[1] + 0.6 * (b[1] - c[1]))
        pivot = "" if k == m else f"C{k} = [{c[0]}, {c[1]}], "
        extra = ", E1 = [5000, 5000]" if k == 1 else ""
        if k != m:
            lines.append(f"C{k} = [{c[0]}, {c[1]}]")
        links.append(f"[[link]]\nid = {2 * k}\npoints = {{ {prev} = [{p[0]}, {p[1]}], "
                     f"B{k} = [{b[0]}, {b[1]}] }}\nmass = 1")
        links.append(f"[[link]]\nid = {2 * k + 1}\npoints = {{ {pivot}B{k} = [{b[0]}, {b[1]}], "
                     f"D{k} = [{d[0]}, {d[1]}]{extra} }}\nmass = 1")
        prev, p = f"D{k}", d
    return "\n".join(lines + links) + "\n"


def test_readme_lists_every_limit():
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    for what, value in {**spec.LIMITS, **ANSWER_LIMITS}.items():
        assert re.search(rf"\| {re.escape(what)} \| {re.escape(value)} \|", readme), (what, value)


@pytest.mark.parametrize("key,value,words", [
    ("mu_V", "1e308", "between 1e-09 and 1e+09"),
    ("mu_V", "5e-324", "between 1e-09 and 1e+09"),
    ("mu_a", "nan", "must be a number, not nan"),
])
def test_answers_scales_within_limits(tmp_path, key, value, words):
    from mmt_plans.check import loads_answers

    analysis = mmt_plans.solve(mmt_plans.load(ROOT / "samples" / "six_link_press.toml"))
    text = f"[[position]]\nindex = 2\n{key} = {value}\nvelocity = {{ B = 2.9 }}\n"
    with pytest.raises(mmt_plans.SpecError) as err:
        loads_answers(text, analysis, "a.toml")
    assert f"a.toml: position[1] (index 2).{key}: " in str(err.value)
    assert words in str(err.value)


@pytest.mark.parametrize("value", ["nan", "inf", "0", "150", "-5"])
def test_answers_tolerance_within_limits(value):
    from mmt_plans.check import loads_answers

    analysis = mmt_plans.solve(mmt_plans.load(ROOT / "samples" / "six_link_press.toml"))
    text = f"[check]\ntolerance_percent = {value}\n[[position]]\nindex = 2\nvelocity = {{ B = 2.9 }}\n"
    with pytest.raises(mmt_plans.SpecError, match="check.tolerance_percent"):
        loads_answers(text, analysis, "a.toml")


def test_answers_names_are_short_and_printable():
    from mmt_plans.check import loads_answers

    analysis = mmt_plans.solve(mmt_plans.load(ROOT / "samples" / "six_link_press.toml"))
    long = "p" + "b" * 10_000
    text = f'[[position]]\nindex = 2\nmu_V = 0.02\nvelocity_plan_mm = {{ {long} = 5 }}\n'
    t0 = time.perf_counter()
    with pytest.raises(mmt_plans.SpecError, match="is not a name this mechanism uses"):
        loads_answers(text, analysis, "a.toml")
    assert time.perf_counter() - t0 < 1.0
    text = '[[position]]\nindex = 2\nvelocity = { "B\\nC" = 5 }\n'
    with pytest.raises(mmt_plans.SpecError) as err:
        loads_answers(text, analysis, "a.toml")
    assert "B\\nC" in str(err.value) and len(str(err.value).split("\n")) == 2
