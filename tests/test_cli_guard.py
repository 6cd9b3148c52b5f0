"""The one guard at the CLI boundary (cli/errors.reports_errors): MmtError →
exit 2, a bug → exit 3 and one line (the traceback with --debug),
Ctrl-C → 130, no numpy warning on the terminal, no non-finite number
written, outputs that cannot be written → exit 2."""

from __future__ import annotations

import errno
import math
import os
import warnings
from pathlib import Path

import numpy as np
import pytest
from click.testing import CliRunner

import mmt_plans
import mmt_plans.spec
from mmt_plans.cli import main

ROOT = Path(__file__).resolve().parents[1]
SMALL = ROOT / "samples" / "offset_slider_crank.toml"


def invoke(*args, env=None):
    return CliRunner().invoke(main, list(args), env=env)


@pytest.fixture
def buggy_load(monkeypatch):
    def load(path):
        raise ZeroDivisionError("float division by zero")

    monkeypatch.setattr(mmt_plans.spec, "load", load)


def test_a_bug_is_exit_3_and_one_line(buggy_load):
    result = invoke("analyze", str(SMALL))
    assert result.exit_code == 3
    assert result.stderr == (f"error: {SMALL}: internal error (ZeroDivisionError), please report "
                             "it (run with --debug for the traceback)\n")
    assert "Traceback" not in result.output


def test_debug_shows_the_traceback(buggy_load):
    result = invoke("--debug", "analyze", str(SMALL))
    assert result.exit_code == 3
    assert "Traceback" in result.stderr and "ZeroDivisionError" in result.stderr
    assert result.stderr.rstrip().endswith("please report it (run with --debug for the "
                                           "traceback)")


def test_the_environment_variable_shows_the_traceback(buggy_load):
    result = invoke("analyze", str(SMALL), env={"MMT_PLANS_DEBUG": "1"})
    assert result.exit_code == 3 and "Traceback" in result.stderr


def test_ctrl_c_is_exit_130_without_a_traceback(monkeypatch):
    def load(path):
        raise KeyboardInterrupt

    monkeypatch.setattr(mmt_plans.spec, "load", load)
    result = invoke("draw", str(SMALL), "-o", "unused")
    assert result.exit_code == 130
    assert "Traceback" not in result.output


def test_numpy_warnings_never_reach_the_terminal(monkeypatch):
    def load(path):
        np.log(np.zeros(3))
        np.float64(1.0) / np.float64(0.0)
        warnings.warn("overflow encountered in multiply", RuntimeWarning)
        raise mmt_plans.SpecError(str(path), "drive.rpm", "is bad", "fix it")

    monkeypatch.setattr(mmt_plans.spec, "load", load)
    with warnings.catch_warnings():
        warnings.simplefilter("always")
        result = invoke("analyze", str(SMALL))
    assert result.exit_code == 2
    assert "Warning" not in result.output
    assert result.stderr == f"error: {SMALL}: drive.rpm: is bad\n  fix: fix it\n"


def test_a_non_finite_result_is_not_written(monkeypatch, tmp_path):
    import mmt_plans.results_json

    real = mmt_plans.results_json.results

    def results(solution, *args, **kwargs):
        data = real(solution, *args, **kwargs)
        data["kinematics"][3]["v"]["B"][0] = math.nan
        return data

    monkeypatch.setattr(mmt_plans.results_json, "results", results)
    target = tmp_path / "r.json"
    result = invoke("analyze", str(SMALL), "--json", str(target), "--quiet")
    assert result.exit_code == 2
    assert "the result kinematics[3].v.B[0] is nan, not a finite number" in result.stderr
    assert not target.exists() and os.listdir(tmp_path) == []


def test_a_read_only_output_folder(monkeypatch, tmp_path):
    def replace(src, dst):
        raise PermissionError(errno.EACCES, "Permission denied")

    monkeypatch.setattr(os, "replace", replace)
    result = invoke("draw", str(SMALL), "-o", str(tmp_path / "out"), "--format", "svg",
                    "--sheet", "1")
    assert result.exit_code == 2
    assert "sheet1.svg: cannot be written: Permission denied" in result.stderr
    assert "Traceback" not in result.output
    assert os.listdir(tmp_path / "out") == []  # the temporary file is gone too


def test_json_onto_a_folder_and_under_a_file(tmp_path):
    (tmp_path / "f").write_text("")
    onto = invoke("analyze", str(SMALL), "--json", str(tmp_path))
    under = invoke("analyze", str(SMALL), "--json", str(tmp_path / "f" / "r.json"))
    assert onto.exit_code == 2 and under.exit_code == 2
    assert "is a file, not a folder" in under.stderr


def test_the_help_lists_the_exit_codes():
    result = invoke("--help")
    assert result.exit_code == 0
    assert "--debug" in result.output and "130 interrupted" in result.output
