"""`mmt-plans batch`: many files, one failing, summary, exit codes."""

from __future__ import annotations

import csv
import json
import shutil
from pathlib import Path

import pytest
from click.testing import CliRunner

from mmt_plans.batch import MANIFEST_NAME, BatchError, find_files, plan_outputs, run_batch
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


# --- hygiene: relative paths, never outside OUT, resume, atomic outputs -----------------

def test_clashing_stems_keep_their_relative_paths(tmp_path):
    for seed in ("seed002", "seed003"):
        (tmp_path / "in" / seed).mkdir(parents=True)
        shutil.copy(SMALL, tmp_path / "in" / seed / "task.toml")
    out = tmp_path / "out"
    results = run_batch(find_files([tmp_path / "in"]), out, jobs=1)
    assert [Path(r.out_dir).relative_to(out).as_posix() for r in results] == \
        ["seed002/task", "seed003/task"]
    assert all(r.ok for r in results)
    assert (out / "seed002" / "task" / "results.json").is_file()


def test_no_output_escapes_out(tmp_path):
    files = [tmp_path / "a" / "...toml", tmp_path / "a" / "..toml", tmp_path / "b" / "x.toml",
             tmp_path / "c" / "x.toml"]
    out = tmp_path / "deep" / "out"
    for target in plan_outputs(files, out):
        rel = target.relative_to(out)
        assert ".." not in rel.parts and "." not in rel.parts and not rel.is_absolute()
    assert len(set(plan_outputs(files, out))) == len(files)


def test_a_symbolic_link_out_of_out_is_refused(tmp_path):
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    out = tmp_path / "out"
    out.mkdir()
    (out / "offset_slider_crank").symlink_to(elsewhere)
    [r] = run_batch([SMALL], out, jobs=1)
    assert not r.ok and "leads outside" in r.message
    assert list(elsewhere.iterdir()) == []


def test_a_second_run_keeps_what_is_done_and_force_redoes_it(tmp_path):
    src = tmp_path / "in"
    src.mkdir()
    shutil.copy(SMALL, src / "a.toml")
    (src / "b.toml").write_text('title = "broken"\n[drive\n', encoding="utf-8")
    out = tmp_path / "out"
    runner = CliRunner()
    first = runner.invoke(main, ["batch", str(src), "-o", str(out), "--jobs", "1"])
    assert first.exit_code == 1
    manifest = json.loads((out / "a" / MANIFEST_NAME).read_text(encoding="utf-8"))
    assert manifest["outputs"].keys() >= {"results.json", "sheet1.svg", "note.pdf"}
    assert len(manifest["input_sha256"]) == 64
    assert not (out / "b").exists()
    stamp = (out / "a" / "note.pdf").stat().st_mtime_ns

    second = runner.invoke(main, ["batch", str(src), "-o", str(out), "--jobs", "1"])
    assert second.exit_code == 1  # b still fails, and is named
    assert "b.toml" in second.stderr and "1 kept from an earlier run" in second.stdout
    assert (out / "a" / "note.pdf").stat().st_mtime_ns == stamp
    with (out / "summary.csv").open(encoding="utf-8") as fh:
        rows = {Path(r["path"]).stem: r for r in csv.DictReader(fh)}
    assert rows["a"]["status"] == "kept" and rows["a"]["W"] == "1"
    assert rows["b"]["status"] == "FAILED" and "TOML" in rows["b"]["message"]

    forced = runner.invoke(main, ["batch", str(src), "-o", str(out), "--jobs", "1", "--force"])
    assert "kept" not in forced.stdout
    assert (out / "a" / "note.pdf").stat().st_mtime_ns != stamp


@pytest.mark.parametrize("change", ["input", "output gone"])
def test_a_changed_item_is_redone(tmp_path, change):
    src = tmp_path / "a.toml"
    shutil.copy(SMALL, src)
    out = tmp_path / "out"
    [first] = run_batch([src], out, jobs=1, force=False)
    assert first.ok and not first.kept
    [again] = run_batch([src], out, jobs=1, force=False)
    assert again.kept and again.W == 1
    if change == "input":
        src.write_text(src.read_text(encoding="utf-8").replace("mass = 5", "mass = 6"),
                       encoding="utf-8")
    else:
        (out / "a" / "sheet1.pdf").unlink()
    [redone] = run_batch([src], out, jobs=1, force=False)
    assert redone.ok and not redone.kept
    assert (out / "a" / "sheet1.pdf").is_file()


def test_batch_leaves_no_temporary_file(tmp_path):
    out = tmp_path / "out"
    run_batch([SMALL], out, jobs=1)
    names = [p.name for p in out.rglob("*")]
    assert not [n for n in names if ".tmp-" in n], names


def test_one_batch_item_runs_the_solver_once(tmp_path, monkeypatch):
    """Sheets, note, results.json and the quiz's scheme all read one Solution."""
    import mmt_plans.solution
    from mmt_plans.batch import process_file

    real = mmt_plans.solution.solve
    calls = []

    def counting(*args, **kwargs):
        calls.append(args)
        return real(*args, **kwargs)

    monkeypatch.setattr(mmt_plans.solution, "solve", counting)
    sample = Path(__file__).resolve().parents[1] / "samples" / "offset_slider_crank.toml"
    result = process_file(sample, tmp_path / "item", formats=("svg", "pdf"), extras=("scheme",))
    assert result.ok, result.message
    assert len(calls) == 1
    names = {Path(p).name for p in result.written}
    assert {"results.json", "sheet1.svg", "sheet2.pdf", "note.pdf", "scheme.png"} <= names


def test_one_batch_item_composes_each_sheet_once(tmp_path, monkeypatch):
    """The note writes its millimetres at the sheets' scales: in a batch item it
    reads them from the sheets just drawn instead of composing them again."""
    import mmt_plans.sheets.compose as compose
    from mmt_plans.batch import process_file

    calls: list[int] = []

    def counting(n, real):
        def compose_n(*args, **kwargs):
            calls.append(n)
            return real(*args, **kwargs)

        return compose_n

    monkeypatch.setattr(compose, "compose_sheet1", counting(1, compose.compose_sheet1))
    monkeypatch.setattr(compose, "compose_sheet2", counting(2, compose.compose_sheet2))
    sample = Path(__file__).resolve().parents[1] / "samples" / "offset_slider_crank.toml"
    result = process_file(sample, tmp_path / "item", formats=("svg",))
    assert result.ok, result.message
    assert sorted(calls) == [1, 2]


def test_outputs_written_while_the_note_is_drawn_keep_their_order_and_errors(tmp_path):
    """The sheets are written by the item's writing thread while the note is
    drawn: the manifest still lists the outputs in the order made (results,
    sheets, note); a sheet that cannot be written is the item's failure,
    named by its stage, with no manifest; the other outputs are there."""
    from mmt_plans.batch import MANIFEST_NAME, process_file, read_manifest

    sample = Path(__file__).resolve().parents[1] / "samples" / "offset_slider_crank.toml"
    result = process_file(sample, tmp_path / "item", formats=("svg", "pdf"))
    assert result.ok, result.message
    order = ["results.json", "sheet1.svg", "sheet1.pdf", "sheet2.svg", "sheet2.pdf", "note.pdf"]
    assert [Path(p).name for p in result.written] == order
    manifest = read_manifest(tmp_path / "item")
    assert manifest is not None and list(manifest["outputs"]) == order
    assert all(manifest["outputs"][n] == (tmp_path / "item" / n).stat().st_size for n in order)

    (tmp_path / "bad").mkdir()
    (tmp_path / "bad" / "sheet2.pdf").mkdir()  # a folder where the sheet goes: refused
    failed = process_file(sample, tmp_path / "bad", formats=("svg", "pdf"))
    assert not failed.ok
    assert failed.message is not None and failed.message.startswith("sheets: ")
    assert "sheet2.pdf" in failed.message
    assert not (tmp_path / "bad" / MANIFEST_NAME).exists()
    assert (tmp_path / "bad" / "note.pdf").is_file() and (tmp_path / "bad" / "sheet2.svg").is_file()
    assert not [p.name for p in (tmp_path / "bad").iterdir() if ".tmp-" in p.name]


def test_a_worker_collects_garbage_less_often(monkeypatch):
    """A batch worker freezes what it imported and raises the young
    generation's threshold (its items' outputs are the same: the keys'
    comparison against main, and the batch tests here run through workers)."""
    import gc

    from mmt_plans import batch

    kept = gc.get_threshold()
    try:
        batch._worker_collector()
        assert gc.get_threshold() == batch._WORKER_GC_THRESHOLD
        assert gc.get_threshold()[0] > kept[0]
        assert gc.get_freeze_count() > 10_000  # the package and its libraries
    finally:
        gc.unfreeze()
        gc.set_threshold(*kept)


def test_items_done_in_process_leave_the_collector_as_it_was(tmp_path):
    import gc

    from mmt_plans import batch

    kept, frozen = gc.get_threshold(), gc.get_freeze_count()
    seen = []
    sample = Path(__file__).resolve().parents[1] / "samples" / "offset_slider_crank.toml"
    results = batch.run_batch(
        [sample], tmp_path / "out", jobs=1, formats=("svg",), progress=lambda r: seen.append(gc.get_threshold())
    )
    assert results[0].ok, results[0].message
    assert seen == [batch._WORKER_GC_THRESHOLD]
    assert gc.get_threshold() == kept and gc.get_freeze_count() == frozen


def test_in_process_runs_in_two_threads_share_the_collector():
    """The settings come back when the last run in the process ends, not the first."""
    import gc

    from mmt_plans import batch

    kept, frozen = gc.get_threshold(), gc.get_freeze_count()
    with batch._collector_of_items():
        with batch._collector_of_items():
            assert gc.get_threshold() == batch._WORKER_GC_THRESHOLD
        assert gc.get_threshold() == batch._WORKER_GC_THRESHOLD
    assert gc.get_threshold() == kept and gc.get_freeze_count() == frozen


def test_an_items_cpu_time_is_its_process_time(tmp_path):
    """FileResult.cpu_seconds (the keys bench sums it: what a loaded machine
    leaves) is the process time the item took, read by the caller around it
    too; a failed item has its own."""
    import time

    from mmt_plans.batch import process_file

    sample = Path(__file__).resolve().parents[1] / "samples" / "offset_slider_crank.toml"
    process_file(sample, tmp_path / "warm", formats=("svg",))  # the imports done first
    t = time.process_time()
    done = process_file(sample, tmp_path / "item", formats=("svg",))
    spent = time.process_time() - t
    assert done.ok and 0.5 * spent <= done.cpu_seconds <= spent
    bad = tmp_path / "bad.toml"
    bad.write_text("[mechanism\n", encoding="utf-8")
    t = time.process_time()
    failed = process_file(bad, tmp_path / "bad", formats=("svg",))
    spent = time.process_time() - t
    assert not failed.ok and 0.0 <= failed.cpu_seconds <= spent
