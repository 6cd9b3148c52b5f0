"""Every task of seeds 003 and 002 as a mechanism file (samples/tasks, written
by samples/tasks/make_tasks.py; the schemes are explained in samples/README.md).
"""

from __future__ import annotations

import re
import tomllib
from pathlib import Path

import numpy as np
import pytest

import mmt_plans
from mmt_plans.results_json import results as results_json
from mmt_plans.structure import analyse_structure

ROOT = Path(__file__).resolve().parents[1]
TASKS = ROOT / "samples" / "tasks"
README = ROOT / "samples" / "README.md"
FILES = sorted(TASKS.rglob("*.toml"))
TURN = np.linspace(0.0, 360.0, 720, endpoint=False)

# The table values the files correct, each with a "# Correction:" comment.
SEED003_FIXES = {
    "seed003/task02_v2.toml": ("crank", 250.0),  # L_O1A = 25 in the table
    "seed003/task10_v3.toml": ("rod", 450.0),  # L_CD = 45
    "seed003/task11_v2.toml": ("rocker", 440.0),  # L_O2C = 44
}
SEED002_FIXED = {
    "seed002/task1_v02.toml", "seed002/task1_v05.toml", "seed002/task1_v06.toml",
    "seed002/task2_v00.toml", "seed002/task2_v01.toml", "seed002/task2_v03.toml",
    "seed002/task2_v04.toml", "seed002/task2_v05.toml", "seed002/task2_v06.toml",
    "seed002/task2_v07.toml", "seed002/task2_v09.toml", "seed002/task4_v04.toml",
    "seed002/task5_v02.toml",
}


def rel(path: Path) -> str:
    return path.relative_to(TASKS).as_posix()


def test_every_task_and_variant_has_a_file():
    names = {rel(p) for p in FILES}
    seed003 = {f"seed003/task{t:02d}_v{v}.toml" for t in range(1, 12) for v in range(1, 6)}
    seed002 = {f"seed002/task{t}_v{v:02d}.toml" for t in range(1, 7) for v in range(10)}
    assert names == seed003 | seed002


@pytest.mark.parametrize("path", FILES, ids=rel)
def test_task_file_analyses_over_the_whole_turn(path):
    mech = mmt_plans.load(path)
    sweep = mmt_plans.sweep(mech, TURN)
    assert sweep.ok.all(), f"{rel(path)} does not assemble at {TURN[~sweep.ok][:3]} deg"
    results = results_json(mmt_plans.solve(mech))
    assert results["structure"]["W"] == 1
    # plans against the lever (2.10): both exact, they agree to rounding, not to 5 %
    assert results["forces"]["discrepancy_percent"] < 1e-7


def test_seed003_task1_variant1_has_the_structure_of_the_default_sample():
    press = mmt_plans.load(ROOT / "samples" / "six_link_press.toml")
    task = mmt_plans.load(TASKS / "seed003" / "task01_v1.toml")
    assert (analyse_structure(task).formula == analyse_structure(press).formula
            == "I(0,1) <- II(2,3) <- II(4,5)")


@pytest.mark.parametrize("name", sorted(SEED003_FIXES))
def test_seed003_misprints_are_corrected_with_the_reason(name):
    text = (TASKS / name).read_text(encoding="utf-8")
    assert re.search(r"^# Correction: .*dropped zero", text, re.M), name
    which, length = SEED003_FIXES[name]
    link = {"crank": 1, "rod": 4, "rocker": 3}[which]
    points = tomllib.loads(text)["link"][link - 1]["points"]
    assert max(np.hypot(*p) for p in points.values()) == pytest.approx(length)


def test_the_corrected_files_are_the_listed_ones_and_in_the_readme():
    corrected = {rel(p) for p in FILES
                 if re.search(r"^# Correction: ", p.read_text(encoding="utf-8"), re.M)}
    assert corrected == set(SEED003_FIXES) | SEED002_FIXED
    readme = README.read_text(encoding="utf-8")
    for name in corrected:
        stem = Path(name).stem  # "task2_v00"; the README lists v00, v01, ... after the first
        task, variant = stem.split("_")
        assert re.search(rf"{Path(name).parent}/{task}_v\d+[^|]*\b{variant}\b", readme) or \
            f"{Path(name).parent}/{stem}" in readme, name


def test_seed002_files_carry_their_gear_train_and_crank_angle():
    for path in FILES:
        if "seed002" not in path.parts:
            continue
        data = tomllib.loads(path.read_text(encoding="utf-8"))
        mech = mmt_plans.load(path)
        assert mech.drive.gear_train is not None, rel(path)
        phi1 = data["study"]["angles"][0]
        assert mech.study.angles == (phi1,)
        assert results_json(mmt_plans.solve(mech))["forces"]["phi1_deg"] == pytest.approx(phi1 % 360)


def test_seed002_task1_train_is_the_worked_example_shape():
    # pair 1-2, then planetary 3-4-4'-5: variant 0, z = 20/80 | 30-32-30-48
    mech = mmt_plans.load(TASKS / "seed002" / "task1_v00.toml")
    u = mech.drive.gear_train.ratio
    assert u == pytest.approx((-80 / 20) * (1 - (32 / 30) * (48 / 30)))


# --- Ukrainian titles (title_uk), printed on the Ukrainian sheets ---------------------

FOUNDATION = sorted((ROOT / "samples").glob("*.toml"))
ENGLISH = {"task", "seed", "crank", "rocker", "slider", "coupler", "rod", "link", "shaper", "ram",
           "press", "yoke", "slotted", "block", "point", "mechanism", "and", "with", "on", "of",
           "the", "an", "phi", "phi1", "deg"}  # not "a": A is a point's name


def sample_id(path: Path) -> str:
    return path.relative_to(ROOT / "samples").as_posix()


@pytest.mark.parametrize("path", FOUNDATION + FILES, ids=sample_id)
def test_every_sample_has_a_ukrainian_title(path):
    text = path.read_text(encoding="utf-8")
    title = tomllib.loads(text).get("title_uk", "")
    assert title.strip(), f"{sample_id(path)} has no title_uk"
    assert re.search(r"[А-ЩЬЮЯЄІЇҐа-щьюяєіїґ]", title), title
    latin = re.findall(r"[A-Za-z][A-Za-z0-9]*", title)
    assert not {w.lower() for w in latin} & ENGLISH, title
    # Latin only in symbols: point and link names (O1, BD), pair kinds (RPP)
    assert all(w.isupper() for w in latin), title
    assert re.search(r'^title = ".*"\ntitle_uk = ', text, re.M), "title_uk right after title"
    assert mmt_plans.load(path).title_in("uk") == title


@pytest.mark.parametrize("path", FILES, ids=rel)
def test_task_titles_follow_one_pattern(path):
    data = tomllib.loads(path.read_text(encoding="utf-8"))
    seed, stem = path.parent.name[-3:], path.stem  # "002", "task2_v05"
    task, variant = (int(x) for x in re.fullmatch(r"task(\d+)_v(\d+)", stem).groups())
    start = f"Завдання {task} (посібник {seed}), варіант {variant}: "
    assert data["title_uk"].startswith(start), data["title_uk"]
    if seed == "002":
        assert data["title_uk"].endswith(f" (φ1 = {data['study']['angles'][0]:g}°)")
