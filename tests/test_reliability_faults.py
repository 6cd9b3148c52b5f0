"""#26, fault injection: draw, note and batch killed with SIGKILL at a random
moment leave no orphan process, their old outputs intact (each output either
as it was or complete: the outputs are byte-reproducible, so "complete" is
"the same bytes"), and no temporary file once the next run has been.

Bounded: FAULT_KILLS kills per command (default 1 in `make test`; raise it
for a longer probe), each at a moment drawn from a seeded generator within
the command's own duration, each wait bounded."""

from __future__ import annotations

import os
import random
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from test_reliability_processes import alive, children_of, wait_for

ROOT = Path(__file__).resolve().parents[1]
SMALL = ROOT / "samples" / "offset_slider_crank.toml"
FOUR_BAR = ROOT / "samples" / "four_bar_coupler.toml"
KILLS = int(os.environ.get("FAULT_KILLS", "1"))
SEED = int(os.environ.get("FAULT_SEED", "26"))

pytestmark = pytest.mark.skipif(not Path("/proc/self/stat").exists(), reason="needs /proc")

COMMANDS = {
    "draw": lambda out: ["draw", str(SMALL), "-o", str(out), "--format", "svg,pdf"],
    "note": lambda out: ["note", str(SMALL), "-o", str(out / "note.pdf")],
    "batch": lambda out: ["batch", str(SMALL), str(FOUR_BAR), "-o", str(out), "--jobs", "2",
                          "--format", "svg", "--force"],
}


def run(args: list[str], timeout: float = 600) -> float:
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    t0 = time.monotonic()
    subprocess.run([sys.executable, "-m", "mmt_plans", *args], env=env, check=True,
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, timeout=timeout)
    return time.monotonic() - t0


def outputs(folder: Path) -> dict[str, bytes]:
    """Every output under `folder` but the batch's bookkeeping (its manifest
    and summary record times)."""
    return {str(p.relative_to(folder)): p.read_bytes() for p in sorted(folder.rglob("*"))
            if p.is_file() and ".tmp-" not in p.name
            and p.name not in (".mmt-batch.json", "summary.csv")}


def temporaries(folder: Path) -> list[Path]:
    return [p for p in folder.rglob("*") if ".tmp-" in p.name]


def descendants(pid: int) -> list[int]:
    out, todo = [], [pid]
    while todo:
        kids = children_of(todo.pop())
        out += kids
        todo += kids
    return out


@pytest.mark.parametrize("command", sorted(COMMANDS))
def test_sigkill_at_a_random_moment_leaves_no_orphan_no_temporary_and_old_outputs_intact(
        tmp_path, command):
    out = tmp_path / "out"
    args = COMMANDS[command](out)
    took = run(args)
    old = outputs(out)
    assert old, "the first run wrote nothing"
    rng = random.Random(f"{SEED}:{command}")
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    for _ in range(KILLS):
        proc = subprocess.Popen([sys.executable, "-m", "mmt_plans", *args], env=env,
                                stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        family: set[int] = set()
        end = time.monotonic() + rng.uniform(0.3, max(0.5, took))
        while time.monotonic() < end and proc.poll() is None:
            family |= set(descendants(proc.pid))
            time.sleep(0.02)
        family |= set(descendants(proc.pid))
        proc.send_signal(signal.SIGKILL)
        proc.wait(timeout=10)
        assert wait_for(lambda: not any(alive(p) for p in family), 10), (
            f"{command}: orphans left after SIGKILL: {[p for p in family if alive(p)]}")
        now = outputs(out)
        for name, data in now.items():  # as it was, or complete: the same bytes
            assert data == old.get(name, data), f"{command}: {name} damaged by the kill"
        assert set(old) <= set(now), f"{command}: an old output vanished"
    run(args)  # the next run sweeps what the killed ones left
    assert temporaries(out) == [], f"{command}: temporaries left after the next run"
    assert outputs(out) == old
