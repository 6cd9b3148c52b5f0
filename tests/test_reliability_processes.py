"""#26: children die with their parent. `batch` killed with SIGKILL (which
lets it clean nothing up) leaves no pool worker waiting for ever."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
SAMPLES = [ROOT / "samples" / f"{n}.toml" for n in
           ("six_link_press", "shaper", "five_dyads", "four_bar_coupler")]

pytestmark = pytest.mark.skipif(not Path("/proc/self/stat").exists(), reason="needs /proc")


def _state_and_parent(pid: int) -> tuple[str, int] | None:
    try:
        text = Path(f"/proc/{pid}/stat").read_text()
    except OSError:
        return None
    fields = text[text.rindex(")") + 2:].split()
    return fields[0], int(fields[1])


def children_of(pid: int) -> list[int]:
    out = []
    for entry in os.listdir("/proc"):
        if entry.isdigit():
            info = _state_and_parent(int(entry))
            if info is not None and info[1] == pid and info[0] != "Z":
                out.append(int(entry))
    return out


def alive(pid: int) -> bool:
    info = _state_and_parent(pid)
    return info is not None and info[0] != "Z"  # a zombie has ended


def batch_process(out: Path) -> subprocess.Popen:
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    return subprocess.Popen(
        [sys.executable, "-m", "mmt_plans", "batch", *map(str, SAMPLES), "-o", str(out),
         "--jobs", "2", "--format", "svg"],
        env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
    )


def wait_for(condition, seconds: float) -> bool:
    end = time.monotonic() + seconds
    while time.monotonic() < end:
        if condition():
            return True
        time.sleep(0.05)
    return condition()


def test_batch_workers_die_when_the_main_process_is_killed(tmp_path):
    proc = batch_process(tmp_path / "out")
    try:
        assert wait_for(lambda: len(children_of(proc.pid)) >= 2, 60), "no workers started"
        workers = children_of(proc.pid)
        os.kill(proc.pid, signal.SIGKILL)
        proc.wait(timeout=10)
        # PR_SET_PDEATHSIG: at once; the parent-watching thread: within a second
        assert wait_for(lambda: not any(alive(w) for w in workers), 10), (
            f"orphan workers left: {[w for w in workers if alive(w)]}")
    finally:
        if proc.poll() is None:
            proc.kill()
        for w in children_of(proc.pid):
            os.kill(w, signal.SIGKILL)


def test_the_parent_watch_alone_ends_a_worker(tmp_path):
    # without prctl (another system): the watching thread ends the worker
    # whose parent died. A child forks a grandchild that starts the watch
    # with no PR_SET_PDEATHSIG, then the child is killed.
    code = f"""
import os, sys, time
sys.path.insert(0, {str(ROOT)!r})
import mmt_plans.batch as b
r, w = os.pipe()
pid = os.fork()
if pid == 0:
    os.close(r)
    b._die_with_parent(os.getppid(), pdeathsig=False)
    os.write(w, str(os.getpid()).encode() + b"\\n")
    time.sleep(60)
    os._exit(0)
os.close(w)
print(os.read(r, 100).decode().strip(), flush=True)
time.sleep(60)
"""
    proc = subprocess.Popen([sys.executable, "-c", code], stdout=subprocess.PIPE, text=True)
    try:
        grandchild = int(proc.stdout.readline())
        assert alive(grandchild)
        os.kill(proc.pid, signal.SIGKILL)
        proc.wait(timeout=10)
        assert wait_for(lambda: not alive(grandchild), 10), "the watch did not end the worker"
    finally:
        if proc.poll() is None:
            proc.kill()
