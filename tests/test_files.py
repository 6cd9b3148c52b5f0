"""files.py: inputs refused before they are read, atomic outputs, clean
errors for outputs that cannot be written, finite JSON, fixed PDF dates."""

from __future__ import annotations

import errno
import json
import math
import os
import time
from pathlib import Path

import pytest

import mmt_plans
from mmt_plans.files import (MAX_INPUT_BYTES, NonFiniteResultError, OutputError, atomic_path,
                             check_output, document_date, ensure_dir, finite_json,
                             first_non_finite, read_input, write_text_atomic)

ROOT = Path(__file__).resolve().parents[1]
SMALL = ROOT / "samples" / "offset_slider_crank.toml"


def refused(path, *words) -> str:
    with pytest.raises(mmt_plans.SpecError) as err:
        read_input(path)
    message = str(err.value)
    assert message.startswith(f"{path}: file: "), message
    assert "\n  fix: " in message
    for w in words:
        assert w in message, message
    return message


# --- reading ------------------------------------------------------------------------

def test_a_folder_is_refused(tmp_path):
    refused(tmp_path, "is a folder")


@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="no FIFOs here")
def test_a_fifo_is_refused_without_blocking(tmp_path):
    fifo = tmp_path / "pipe.toml"
    os.mkfifo(fifo)
    t0 = time.perf_counter()
    refused(fifo, "FIFO")
    assert time.perf_counter() - t0 < 1.0


@pytest.mark.skipif(not Path("/dev/zero").exists(), reason="no /dev/zero")
def test_a_device_is_refused_at_once():
    t0 = time.perf_counter()
    refused("/dev/zero", "is a device")
    assert time.perf_counter() - t0 < 1.0


def test_a_file_over_the_limit_is_refused_before_reading(tmp_path):
    big = tmp_path / "big.toml"
    with big.open("wb") as fh:
        fh.truncate(MAX_INPUT_BYTES + 1)  # sparse: nothing to read
    refused(big, "bytes, more than the 1,000,000")


def test_a_missing_file(tmp_path):
    refused(tmp_path / "none.toml", "cannot be read (No such file or directory)")


@pytest.mark.parametrize("encoding,words", [
    ("latin-1", ["not UTF-8 text: byte 0xE9 at line 1, column 13"]),
    ("cp1251", ["not UTF-8 text", "line 1"]),
    ("utf-16", ["UTF-16 or UTF-32"]),
    ("utf-32", ["UTF-16 or UTF-32"]),
    ("utf-16-le", ["NUL byte (line 1)"]),
])
def test_text_that_is_not_utf8_is_named(tmp_path, encoding, words):
    path = tmp_path / "enc.toml"
    path.write_bytes('title = "Café Ж"\n'.replace("Ж", "Ж" if encoding == "cp1251" else "e")
                     .encode(encoding, errors="replace"))
    refused(path, *words)


def test_binary_data_is_refused(tmp_path):
    path = tmp_path / "bin.toml"
    path.write_bytes(bytes(range(256)) * 4)
    refused(path, "NUL byte")


def test_utf8_with_a_byte_order_mark_is_read(tmp_path):
    path = tmp_path / "bom.toml"
    path.write_bytes(b"\xef\xbb\xbf" + SMALL.read_bytes())
    assert read_input(path) == SMALL.read_text(encoding="utf-8")
    assert mmt_plans.solve(mmt_plans.load(path)).structure.W == 1


def test_answers_files_are_read_the_same_way(tmp_path):
    from mmt_plans.check import load_answers

    path = tmp_path / "answers.toml"
    path.write_bytes("[[position]]\nindex = 0\nvelocity = { B = 1.5 } # é\n".encode("latin-1"))
    analysis = mmt_plans.solve(mmt_plans.load(SMALL))
    with pytest.raises(mmt_plans.SpecError, match="answers.toml: file: is not UTF-8"):
        load_answers(path, analysis)


# --- writing ------------------------------------------------------------------------

def test_atomic_write_leaves_no_temporary_file(tmp_path):
    target = write_text_atomic(tmp_path / "a" / "b.json", "{}\n")
    assert target.read_text() == "{}\n"
    assert os.listdir(tmp_path / "a") == ["b.json"]


def test_a_failed_writer_keeps_the_old_file_and_leaves_nothing(tmp_path):
    target = tmp_path / "sheet1.pdf"
    target.write_text("old")
    with pytest.raises(ZeroDivisionError):
        with atomic_path(target) as tmp:
            tmp.write_text("half")
            1 / 0
    assert target.read_text() == "old"
    assert os.listdir(tmp_path) == ["sheet1.pdf"]


def test_the_temporary_name_is_hidden_and_beside_the_target(tmp_path):
    with atomic_path(tmp_path / "note.pdf") as tmp:
        assert tmp.parent == tmp_path
        assert tmp.name.startswith(".note.pdf.tmp-")
        tmp.write_text("x")
    assert (tmp_path / "note.pdf").read_text() == "x"


def test_a_path_under_a_file_is_an_output_error(tmp_path):
    (tmp_path / "f").write_text("")
    for call in (lambda: write_text_atomic(tmp_path / "f" / "x.json", "{}"),
                 lambda: ensure_dir(tmp_path / "f" / "g"),
                 lambda: check_output(tmp_path / "f" / "x.json"),
                 lambda: check_output(tmp_path / "f" / "g", folder=True)):
        with pytest.raises(OutputError) as err:
            call()
        assert f"{tmp_path / 'f'} is a file" in str(err.value)
        assert "\n  fix: " in str(err.value)
        assert isinstance(err.value, (mmt_plans.MmtError, OSError))


def test_a_folder_where_a_file_should_go(tmp_path):
    with pytest.raises(OutputError, match="is a folder, not a file"):
        write_text_atomic(tmp_path, "{}")


def test_a_read_only_folder_is_an_output_error(tmp_path, monkeypatch):
    # root may write anywhere: the refusal of the system is simulated
    def denied(*args, **kwargs):
        raise PermissionError(errno.EACCES, "Permission denied")

    monkeypatch.setattr("builtins.open", denied)
    with pytest.raises(OutputError) as err:
        write_text_atomic(tmp_path / "results.json", "{}")
    assert "cannot be written: Permission denied" in str(err.value)
    assert "choose a folder you may write to" in str(err.value)
    monkeypatch.undo()
    assert os.listdir(tmp_path) == []


# --- results ------------------------------------------------------------------------

def test_finite_json_names_the_first_non_finite_number():
    data = {"positions": [{"points": {"A": [0.0, 1.0]}}, {"points": {"B": [2.0, math.inf]}}]}
    assert first_non_finite(data) == ("positions[1].points.B[1]", math.inf)
    with pytest.raises(NonFiniteResultError) as err:
        finite_json(data, "press.toml")
    assert str(err.value).startswith("press.toml: the result positions[1].points.B[1] is inf")
    assert isinstance(err.value, mmt_plans.MmtError)


def test_finite_json_is_what_json_writes():
    data = {"a": [1, 2.5, None, "x"], "b": {"c": True}}
    assert finite_json(data) == json.dumps(data, indent=1, allow_nan=False) + "\n"


def test_document_date(monkeypatch):
    monkeypatch.delenv("SOURCE_DATE_EPOCH", raising=False)
    assert document_date() == "2000-01-01T00:00:00Z"
    monkeypatch.setenv("SOURCE_DATE_EPOCH", "1700000000")
    assert document_date() == "2023-11-14T22:13:20Z"
    # #26: a value that is not whole seconds is refused, not silently 2000-01-01
    for bad in ("not a number", "1.5", "-5", "99999999999999999"):
        monkeypatch.setenv("SOURCE_DATE_EPOCH", bad)
        with pytest.raises(mmt_plans.MmtError, match="SOURCE_DATE_EPOCH: '"):
            document_date()
