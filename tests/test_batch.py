"""`mmt-plans batch`: many files, one failing, summary, exit codes."""

from __future__ import annotations

import csv
import json
import shutil
from pathlib import Path

import pytest
from click.testing import CliRunner

from mmt_plans.batch import BatchError, find_files, plan_outputs, run_batch
from mmt_plans.cli import main

ROOT = Path(__file__).resolve().parents[1]
SMALL = ROOT / "samples" / "offset_slider_crank.toml"
COUPLER = ROOT / "samples" / "four_bar_coupler.toml"


@pytest.fixture
def inputs(tmp_path):
    src = tmp_path / "in"
    (src / "deeper").mkdir(parents=True)
    shutil.copy(SMALL, src / "a_slider.toml")
    shutil.copy(COUPLER, src / "deeper" / "b_coupler.toml")
    (src / "c_broken.toml").write_text('title = "broken"\n[drive\nlink = 1\n', encoding="utf-8")
    return src


@pytest.mark.parametrize("jobs", ["1", "2"])
def test_two_done_one_reported(inputs, tmp_path, jobs):
    out = tmp_path / "out"
    result = CliRunner().invoke(main, ["batch", str(inputs), "-o", str(out), "--jobs", jobs])
    assert result.exit_code == 1, result.output
    assert "Traceback" not in result.output
    assert "c_broken.toml" in result.output  # the failing file is named with its message
    for stem in ("a_slider", "b_coupler"):
        d = out / stem
        assert (d / "sheet1.svg").is_file() and (d / "sheet1.pdf").is_file()
        assert (d / "note.pdf").read_bytes().startswith(b"%PDF")
        data = json.loads((d / "results.json").read_text(encoding="utf-8"))
        assert data["schema"] == "mmt_plans/results@1"
    assert not (out / "c_broken").exists()
    with (out / "summary.csv").open(encoding="utf-8") as fh:
        rows = list(csv.DictReader(fh))
    assert [Path(r["path"]).stem for r in rows] == ["a_slider", "c_broken", "b_coupler"]
    assert [r["status"] for r in rows] == ["done", "FAILED", "done"]
    assert rows[1]["message"]
    assert rows[0]["W"] == "1" and rows[0]["F_bal plans N"] != "-"
    for stem in ("a_slider", "b_coupler", "c_broken"):
        assert stem in result.output  # the summary table has every row


def test_all_good_exits_zero(tmp_path):
    out = tmp_path / "out"
    result = CliRunner().invoke(main, ["batch", str(SMALL), "-o", str(out), "--lang", "uk"])
    assert result.exit_code == 0, result.output
    assert (out / "offset_slider_crank" / "note.pdf").is_file()


def test_results_json_is_what_analyze_writes(tmp_path):
    out = tmp_path / "out"
    [r] = run_batch([SMALL], out, jobs=1)
    assert r.ok and r.W == 1
    runner = CliRunner()
    ref = tmp_path / "ref.json"
    assert runner.invoke(main, ["analyze", str(SMALL), "--json", str(ref), "--quiet"]).exit_code == 0
    assert (out / "offset_slider_crank" / "results.json").read_text(encoding="utf-8") == \
        ref.read_text(encoding="utf-8")


def test_missing_input_is_a_clean_error(tmp_path):
    result = CliRunner().invoke(main, ["batch", str(tmp_path / "nope"), "-o", str(tmp_path)])
    assert result.exit_code == 2
    assert "no such file" in result.output
    with pytest.raises(BatchError):
        find_files([tmp_path])  # an empty directory


def test_repeated_stems_get_distinct_folders(tmp_path):
    a = tmp_path / "seed002" / "task01_v1.toml"
    b = tmp_path / "seed003" / "task01_v1.toml"
    outs = plan_outputs([a, b], tmp_path / "out")
    assert outs[0] != outs[1]
    # clashing stems keep their path relative to the folder the files share
    assert [o.relative_to(tmp_path / "out").as_posix() for o in outs] == \
        ["seed002/task01_v1", "seed003/task01_v1"]
