"""#26, every door holds: one regression test per defect, named after it.

Outputs only where a file belongs (a regular file or a new path; `-` to
standard output where a command offers it), synced before the rename, stale
temporaries of killed runs swept; one door for every command (options,
SOURCE_DATE_EPOCH, integer sizes, name lengths, names from file names, a
group held by the frame alone); messages in words that name the file."""

from __future__ import annotations

import errno
import json
import os
import socket
import stat
import subprocess
import sys
import time
from pathlib import Path

import pytest
from click.testing import CliRunner

import mmt_plans
import mmt_plans.files as files
from mmt_plans.cli import main
from mmt_plans.errors import ForceError, MmtError, StructureError

ROOT = Path(__file__).resolve().parents[1]
SMALL = ROOT / "samples" / "offset_slider_crank.toml"
PRESS = ROOT / "samples" / "six_link_press.toml"
ANSWERS = ROOT / "samples" / "answers" / "six_link_press.answers.toml"
LONG = "x" * 300  # a name of 300 bytes: more than the 255 a name may have


def invoke(*args, env=None):
    return CliRunner().invoke(main, [str(a) for a in args], env=env)


def clean_exit_2(result, *words):
    assert result.exit_code == 2, (result.exit_code, result.output)
    assert "Traceback" not in result.output and "internal error" not in result.output
    for w in words:
        assert w in result.stderr, result.stderr
    return result.stderr


@pytest.fixture
def nodes(tmp_path):
    """A FIFO, a symbolic link to a file, a dangling link and a socket."""
    (tmp_path / "real.json").write_text("keep")
    os.mkfifo(tmp_path / "fifo")
    os.symlink(tmp_path / "real.json", tmp_path / "link")
    os.symlink(tmp_path / "nowhere", tmp_path / "dangling")
    sock = socket.socket(socket.AF_UNIX)
    sock.bind(str(tmp_path / "sock"))
    yield tmp_path
    sock.close()


# --- outputs only where a file belongs ----------------------------------------------

@pytest.mark.parametrize("name,words", [
    ("fifo", "is a FIFO (named pipe)"),
    ("link", "is a symbolic link (to "),
    ("dangling", "is a symbolic link (to "),
    ("sock", "is a socket"),
])
def test_analyze_json_onto_a_symlink_fifo_or_socket_is_refused_and_left_alone(nodes, name, words):
    path = nodes / name
    before = os.lstat(path)
    err = clean_exit_2(invoke("analyze", SMALL, "--json", path, "--quiet"), words,
                       "writes only to a regular file or a new path")
    assert err.startswith(f"error: {path}: ")
    after = os.lstat(path)
    assert stat.S_IFMT(after.st_mode) == stat.S_IFMT(before.st_mode)
    assert (nodes / "real.json").read_text() == "keep"  # the link's target untouched
    assert not [n for n in os.listdir(nodes) if ".tmp-" in n]


@pytest.mark.skipif(not Path("/dev/null").exists(), reason="no /dev/null")
def test_analyze_json_onto_dev_null_is_refused_not_replaced():
    before = os.lstat("/dev/null")
    clean_exit_2(invoke("analyze", SMALL, "--json", "/dev/null"), "/dev/null: is a device")
    after = os.lstat("/dev/null")
    assert stat.S_ISCHR(after.st_mode) and after.st_rdev == before.st_rdev


@pytest.mark.skipif(not os.path.islink("/dev/stdout"), reason="/dev/stdout is no link here")
def test_note_onto_dev_stdout_is_refused_before_the_work():
    clean_exit_2(invoke("note", SMALL, "-o", "/dev/stdout"), "/dev/stdout: is a symbolic link")


def test_check_json_onto_a_fifo_is_refused(nodes):
    clean_exit_2(invoke("check", PRESS, ANSWERS, "--json", nodes / "fifo"), "is a FIFO")
    assert stat.S_ISFIFO(os.lstat(nodes / "fifo").st_mode)


def test_json_dash_is_standard_output_by_design(tmp_path):
    result = invoke("analyze", SMALL, "--json", "-")
    assert result.exit_code == 0
    data = json.loads(result.stdout)  # the JSON alone: no text report around it
    assert data["title"] == "Offset slider-crank"
    assert not (Path.cwd() / "-").exists()
    checked = invoke("check", PRESS, ANSWERS, "--json", "-")
    assert checked.exit_code in (0, 1)
    assert "passed" in json.loads(checked.stdout)


@pytest.mark.parametrize("command", ["draw", "batch", "variants"])
@pytest.mark.parametrize("name,words", [
    ("fifo", "is a FIFO (named pipe), not a folder"),
    ("link", "is a symbolic link to "),
    ("dangling", "which leads nowhere"),
])
def test_out_folder_on_a_fifo_device_or_symlink_says_what_it_is(nodes, command, name, words):
    err = clean_exit_2(invoke(command, SMALL, "-o", nodes / name), words)
    assert "is a file, not a folder" not in err


@pytest.mark.skipif(not Path("/dev/null").exists(), reason="no /dev/null")
def test_out_folder_on_a_device_says_it_is_a_device():
    clean_exit_2(invoke("draw", SMALL, "-o", "/dev/null"), "/dev/null is a device, not a folder")


def test_an_out_folder_through_a_link_to_a_folder_is_written(tmp_path):
    (tmp_path / "real").mkdir()
    os.symlink(tmp_path / "real", tmp_path / "to_real")
    result = invoke("analyze", SMALL, "--json", tmp_path / "to_real" / "r.json", "--quiet")
    assert result.exit_code == 0 and (tmp_path / "real" / "r.json").is_file()


def test_the_temporary_file_and_its_folder_are_synced_before_and_after_the_rename(
        tmp_path, monkeypatch):
    events = []
    real_fsync, real_replace = os.fsync, os.replace
    monkeypatch.setattr(os, "fsync", lambda fd: (events.append(
        ("fsync", stat.S_ISDIR(os.fstat(fd).st_mode))), real_fsync(fd)))
    monkeypatch.setattr(os, "replace", lambda a, b: (events.append(("replace", None)),
                                                      real_replace(a, b)))
    files.write_text_atomic(tmp_path / "r.json", "{}\n")
    assert events == [("fsync", False), ("replace", None), ("fsync", True)]


def _old_temp(folder: Path, name: str) -> Path:
    path = folder / name
    path.write_bytes(b"half a PDF")
    old = files.RUN_STARTED - 60
    os.utime(path, (old, old))
    return path


def _dead_pid() -> int:
    proc = subprocess.Popen([sys.executable, "-c", "pass"])
    proc.wait()
    return proc.pid


def test_stale_temporaries_of_killed_runs_are_swept_and_nothing_else(tmp_path, monkeypatch):
    monkeypatch.setattr(files, "_SWEPT", set())
    dead = _dead_pid()
    stale = _old_temp(tmp_path, f".note.pdf.tmp-{dead}-0123abcd")
    live = _old_temp(tmp_path, f".note.pdf.tmp-{os.getppid()}-0123abcd")  # a live run's
    other = _old_temp(tmp_path, f".note.pdf.tmp-{dead}-notours")  # not our pattern
    plain = _old_temp(tmp_path, "note.pdf.tmp-1-0123abcd")  # not hidden: not ours
    fresh = tmp_path / f".sheet1.svg.tmp-{dead}-89abcdef"  # newer than this run
    fresh.write_text("x")
    files.write_text_atomic(tmp_path / "note.pdf", "new")
    left = sorted(os.listdir(tmp_path))
    assert stale.name not in left
    assert {live.name, other.name, plain.name, fresh.name, "note.pdf"} == set(left)


def test_a_killed_note_leaves_no_temporary_after_the_next_run(tmp_path):
    # the next run (note, draw or batch writing in that folder) sweeps it
    out = tmp_path / "note.pdf"
    stale = _old_temp(tmp_path, f".note.pdf.tmp-{_dead_pid()}-deadbeef")
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    subprocess.run([sys.executable, "-m", "mmt_plans", "analyze", str(SMALL), "--quiet",
                    "--json", str(tmp_path / "r.json")], env=env, check=True)
    assert not stale.exists() and (tmp_path / "r.json").is_file()


def test_a_name_too_long_for_the_temporary_still_writes(tmp_path):
    name = "n" * 250 + ".json"  # 255 bytes: the temporary name is cut to fit
    files.write_text_atomic(tmp_path / name, "{}")
    assert os.listdir(tmp_path) == [name]


# --- messages in words ---------------------------------------------------------------

@pytest.mark.parametrize("code,words", [
    (errno.ENOSPC, "the disk is full"),
    (errno.EROFS, "the file system is read-only"),
    (errno.EDQUOT, "the disk quota is exceeded"),
    (errno.EIO, "an input/output error"),
])
def test_errno_is_said_in_words(tmp_path, monkeypatch, code, words):
    def failing(*args, **kwargs):
        raise OSError(code, os.strerror(code))

    monkeypatch.setattr("builtins.open", failing)
    with pytest.raises(files.OutputError) as err:
        files.write_text_atomic(tmp_path / "note.pdf", "x")
    assert str(err.value).startswith(f"{tmp_path / 'note.pdf'}: cannot be written: {words}")
    monkeypatch.undo()
    assert os.listdir(tmp_path) == []


def test_cairo_status_11_is_said_in_words(tmp_path, monkeypatch):
    # cairocffi raises IOError(message, status): errno is the message, strerror 11
    cairo = OSError("cairo returned CAIRO_STATUS_WRITE_ERROR: error while writing", 11)

    class Full:
        f_flag, f_bavail = 0, 0

    class ReadOnly:
        f_flag, f_bavail = os.ST_RDONLY, 100

    for vfs, words in ((Full, "the disk is full"), (ReadOnly, "the file system is read-only")):
        monkeypatch.setattr(os, "statvfs", lambda p, vfs=vfs: vfs)
        message = str(files._os_problem(cairo, tmp_path / "note.pdf"))
        assert f"cannot be written: {words}" in message and ": 11" not in message


def test_a_full_disk_while_writing_the_note_is_said_in_words(tmp_path, monkeypatch):
    real_open = open

    def full(path, mode="r", *args, **kwargs):
        if ".tmp-" in str(path) and "x" in mode:
            raise OSError(errno.ENOSPC, "No space left on device")
        return real_open(path, mode, *args, **kwargs)

    monkeypatch.setattr("builtins.open", full)
    err = clean_exit_2(invoke("note", SMALL, "-o", tmp_path / "note.pdf"),
                       "note.pdf: cannot be written: the disk is full")
    assert ": 11" not in err
    assert os.listdir(tmp_path) == []


def test_sheet_2_does_not_fit_names_the_file_and_what_did_not_fit(tmp_path, monkeypatch):
    from mmt_plans.sheets import sheet2

    monkeypatch.setattr(sheet2._Composer, "first_fit", lambda self: None)
    err = clean_exit_2(invoke("draw", SMALL, "-o", tmp_path, "--sheet", "2", "--format", "svg"),
                       f"error: {SMALL}: sheet 2 does not fit on A1: its ",
                       "force-mechanism", "fix: ")
    assert "None" not in err


def test_an_error_made_far_from_the_file_is_given_the_file_name(monkeypatch):
    import mmt_plans.solution

    def fails(*args, **kwargs):
        raise ForceError("no force acts")

    monkeypatch.setattr(mmt_plans.solution, "solve", fails)
    clean_exit_2(invoke("analyze", SMALL), f"error: {SMALL}: no force acts")


# --- one door for every command -------------------------------------------------------

@pytest.mark.parametrize("args", [
    ["analyze", SMALL, "--json", f"{{tmp}}/{LONG}.json"],
    ["draw", SMALL, "-o", f"{{tmp}}/{LONG}"],
    ["note", SMALL, "-o", f"{{tmp}}/{LONG}.pdf"],
    ["batch", SMALL, "-o", f"{{tmp}}/{LONG}"],
    ["variants", SMALL, "-o", f"{{tmp}}/{LONG}"],
    ["check", PRESS, ANSWERS, "--json", f"{{tmp}}/{LONG}.json"],
])
def test_an_output_name_over_255_bytes_is_a_clean_error(tmp_path, args):
    args = [str(a).replace("{tmp}", str(tmp_path)) for a in args]
    clean_exit_2(invoke(*args), "bytes, more than the 255 a file or folder name may have")
    assert os.listdir(tmp_path) == []


@pytest.mark.parametrize("value", ["1.5", "-1", "1e9", "soon", "99999999999999"])
@pytest.mark.parametrize("args", [
    ["draw", SMALL, "--format", "dxf", "--sheet", "1", "-o"],
    ["draw", SMALL, "--format", "pdf", "--sheet", "1", "-o"],
    ["note", SMALL, "-o"],
    ["analyze", SMALL, "--json"],
])
def test_source_date_epoch_not_whole_seconds_is_refused_by_every_command(tmp_path, value, args):
    target = tmp_path / ("r.json" if args[0] == "analyze" else "out")
    result = invoke(*args, target, env={"SOURCE_DATE_EPOCH": value})
    clean_exit_2(result, f"SOURCE_DATE_EPOCH: '{value}' is ", "fix: ")
    assert os.listdir(tmp_path) == []  # no silent 2000-01-01 either


def test_source_date_epoch_whole_seconds_dates_the_dxf_and_the_pdf_alike(tmp_path):
    env = {"SOURCE_DATE_EPOCH": "1700000000"}
    result = invoke("draw", SMALL, "--format", "dxf,pdf", "--sheet", "1", "-o", tmp_path, env=env)
    assert result.exit_code == 0, result.output
    assert b"20231114221320" in (tmp_path / "sheet1.pdf").read_bytes()  # D:20231114221320


def test_batch_tolerance_nan_is_refused_before_the_work(tmp_path):
    for bad in ("nan", "inf", "0", "-5", "101"):
        result = invoke("batch", SMALL, "-o", tmp_path / "out", "--moodle", "--tolerance", bad)
        assert result.exit_code == 2 and "is not a percentage in (0, 100]" in result.output
        assert not (tmp_path / "out").exists()
    checked = invoke("check", PRESS, ANSWERS, "--tolerance", "nan")
    assert "is not a percentage in (0, 100]" in checked.output  # the same message


def test_batch_jobs_out_of_range_is_refused(tmp_path):
    for bad in ("0", "100000"):
        result = invoke("batch", SMALL, "-o", tmp_path / "out", "--jobs", bad)
        assert result.exit_code == 2 and "--jobs" in result.output
        assert not (tmp_path / "out").exists()


def _gears_file(tmp_path: Path, rpm: str) -> Path:
    text = PRESS.read_text().replace("rpm = 100\n", "")
    text += f'\n[gears]\nmotor_rpm = {rpm}\n[[gears.stage]]\nz = [20, 40]\nmesh = "external"\n'
    path = tmp_path / "gears.toml"
    path.write_text(text)
    return path


def test_motor_rpm_of_310_digits_is_refused_with_the_limit(tmp_path):
    path = _gears_file(tmp_path, "9" * 310)
    clean_exit_2(invoke("analyze", path), f"{path}: gears.motor_rpm: ",
                 "between 0.001 and 100000 1/min")
    clean_exit_2(invoke("analyze", _gears_file(tmp_path, "-" + "9" * 310)), "gears.motor_rpm")


def test_an_integer_beyond_64_bits_anywhere_is_named(tmp_path):
    # an entry with a limit says its limit; one without (an angle, taken mod
    # 360) is held by TOML's own 64 bits, named, never an OverflowError
    text = SMALL.read_text().replace("mass = 5\n", f"mass = {10**40}\n")
    with pytest.raises(MmtError, match=r"big.toml: link\[2\].*mass: .*at most 1e\+06 kg"):
        mmt_plans.loads(text, "big.toml")
    text = SMALL.read_text().replace("angle = 0\n", f"angle = {10**40}\n")
    with pytest.raises(MmtError, match=r"big.toml: slider\[1\]\.angle: an integer of 41 digits"):
        mmt_plans.loads(text, "big.toml")


TRUSS = """
[drive]
rpm = 60
[study]
output = "B"
[frame]
O = [0, 0]
C = [400, 0]
P = [0, 300]
Q = [300, 300]
[[link]]
id = 1
points = { O = [0, 0], A = [100, 0] }
[[link]]
id = 2
points = { A = [0, 0], B = [350, 0] }
[[link]]
id = 3
points = { B = [0, 0], C = [250, 0] }
[[link]]
id = 4
points = { P = [0, 0], E = [150, 0] }
[[link]]
id = 5
points = { E = [0, 0], Q = [160, 0] }
[sketch]
A = [100, 0]
B = [250, 250]
E = [150, 150]
"""


def test_a_dyad_with_both_outer_pairs_on_the_frame_is_a_structural_error(tmp_path):
    # links 4 and 5 pinned to the frame at P and Q and to each other at E:
    # W = 3·5 − 2·7 = 1 still, but the dyad holds to no moving link
    with pytest.raises(StructureError) as err:
        mmt_plans.solve(mmt_plans.loads(TRUSS, "truss.toml"))
    message = str(err.value)
    assert message.startswith("truss.toml: group II(4,5)")
    assert "(P, Q) on the frame" in message and "no pair to a moving link" in message
    path = tmp_path / "truss.toml"
    path.write_text(TRUSS)
    # the issue: draw failed with a TypeError, variants with a ValueError
    for args in (["analyze", path], ["draw", path, "-o", tmp_path / "out", "--format", "svg"],
                 ["note", path, "-o", tmp_path / "note.pdf"],
                 ["variants", path, "--count", "2", "-o", tmp_path / "variants"]):
        clean_exit_2(invoke(*args), "group II(4,5)")
    assert not (tmp_path / "variants").exists() and not (tmp_path / "note.pdf").exists()
    batch = invoke("batch", path, "-o", tmp_path / "batch")
    assert batch.exit_code == 1 and "Traceback" not in batch.output
    (line,) = [ln for ln in batch.stderr.splitlines() if ln.startswith("error: ")]
    assert line.startswith(f"error: {path}: analysis: group II(4,5)")  # the file named once
    assert line.count(str(path)) == 1


def test_a_group_hung_on_a_frame_only_group_is_refused_too():
    # a second dyad 6-7 between the truss (E) and the frame: the truss is named
    text = TRUSS.replace("E = [150, 0] }", "E = [150, 0], G = [150, 50] }") + """
[[link]]
id = 6
points = { G = [0, 0], H = [100, 0] }
[[link]]
id = 7
points = { H = [0, 0], C = [100, 0] }
"""
    with pytest.raises(MmtError, match="no pair to a moving link"):
        mmt_plans.solve(mmt_plans.loads(text, "two.toml"))


@pytest.mark.parametrize("name", ["a\nb.toml", "cr\rname.toml", "bidi\u202egpj.toml"])
def test_names_from_file_names_with_newline_cr_bidi_are_escaped(tmp_path, name):
    path = tmp_path / name
    path.write_text(SMALL.read_text().replace('title = "Offset slider-crank"\n', ""))
    result = invoke("analyze", path, "--json", tmp_path / "r.json", "--quiet")
    assert result.exit_code == 0, result.output
    title = json.loads((tmp_path / "r.json").read_text())["title"]
    assert title.isprintable()
    out = invoke("draw", path, "-o", tmp_path / "d", "--sheet", "1", "--format", "svg")
    assert out.exit_code == 0
    svg = (tmp_path / "d" / "sheet1.svg").read_text()
    for ch in ("\r", "\u202e"):
        assert ch not in svg
    bad = invoke("analyze", tmp_path / ("missing" + name))  # the message escapes it too
    assert bad.exit_code == 2 and bad.stderr.count("\n") == 2 and "\u202e" not in bad.stderr


def test_a_fifo_where_a_sheet_goes_is_refused_before_the_work(tmp_path, monkeypatch):
    import mmt_plans.solution

    os.mkfifo(tmp_path / "sheet1.svg")
    monkeypatch.setattr(mmt_plans.solution, "solve", lambda *a, **k: pytest.fail("solved"))
    clean_exit_2(invoke("draw", SMALL, "-o", tmp_path, "--format", "svg"),
                 "sheet1.svg: is a FIFO (named pipe)")
    assert stat.S_ISFIFO(os.lstat(tmp_path / "sheet1.svg").st_mode)


@pytest.mark.parametrize("command", [["analyze"], ["draw", "-o", "{tmp}/o"],
                                     ["note", "-o", "{tmp}/n.pdf"], ["batch", "-o", "{tmp}/b"],
                                     ["variants", "-o", "{tmp}/v"]])
def test_an_input_name_over_255_bytes_is_a_clean_error(tmp_path, command):
    name, *rest = command
    args = [name, tmp_path / f"{LONG}.toml", *[a.replace("{tmp}", str(tmp_path)) for a in rest]]
    clean_exit_2(invoke(*args), "File name too long")
    assert os.listdir(tmp_path) == []
