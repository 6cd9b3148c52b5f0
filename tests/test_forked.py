"""Work on two cores (mmt_plans.forked): the results are those of working the
items in turn, whatever the forked child does, and the sheets composed so
are the sheets composed one after the other, byte for byte."""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from mmt_plans import forked
from mmt_plans.errors import MmtError
from mmt_plans.forked import can_fork, on_two_cores

ROOT = Path(__file__).resolve().parents[1]

needs_fork = pytest.mark.skipif(
    not can_fork(), reason="forks only on Linux with two cores or more and one thread running"
)


def _square(x: int) -> int:
    return x * x


@needs_fork
def test_the_results_come_in_the_items_order_from_both_processes() -> None:
    pids: dict[int, int] = {}

    def work(x: int) -> tuple[int, int]:
        return x * x, os.getpid()

    got = on_two_cores(work, range(7))
    assert [v for v, _ in got] == [x * x for x in range(7)]
    for k, (_, pid) in enumerate(got):
        pids[k] = pid
    # the even places worked in the child, the odd ones here
    assert {pids[k] for k in range(1, 7, 2)} == {os.getpid()}
    assert {pids[k] for k in range(0, 7, 2)} != {os.getpid()}


@needs_fork
def test_an_item_that_fails_in_the_child_fails_here_as_it_would_in_turn() -> None:
    def work(x: int) -> int:
        if x == 2:
            raise MmtError("no assembly at 2")
        return x

    with pytest.raises(MmtError, match="no assembly at 2"):
        on_two_cores(work, [0, 1, 2, 3])


@needs_fork
def test_a_child_that_dies_leaves_its_items_to_this_process() -> None:
    parent = os.getpid()

    def work(x: int) -> int:
        if os.getpid() != parent:
            os._exit(9)  # killed mid-work, nothing sent
        return x + 100

    assert on_two_cores(work, [1, 2, 3]) == [101, 102, 103]


@needs_fork
def test_a_result_that_does_not_pickle_is_worked_here() -> None:
    parent = os.getpid()

    def work(x: int) -> object:
        # a lambda made in the child cannot be pickled; here it is a plain value
        return (lambda: x) if os.getpid() != parent else x

    assert on_two_cores(work, [5, 6]) == [5, 6]


def test_one_item_or_jobs_one_works_in_turn_here(monkeypatch: pytest.MonkeyPatch) -> None:
    def work(x: int) -> int:
        return os.getpid()

    assert on_two_cores(work, [1]) == [os.getpid()]
    monkeypatch.setenv("MMT_PLANS_JOBS", "1")
    assert not can_fork()
    assert on_two_cores(work, [1, 2, 3]) == [os.getpid()] * 3


def test_no_fork_while_another_thread_runs() -> None:
    import threading

    stop = threading.Event()
    t = threading.Thread(target=stop.wait)
    t.start()
    try:
        assert not can_fork()
        assert on_two_cores(_square, [1, 2, 3]) == [1, 4, 9]
    finally:
        stop.set()
        t.join()


@needs_fork
def test_read_only_mappings_cross_the_pipe() -> None:
    from types import MappingProxyType

    def work(x: int) -> MappingProxyType[str, int]:
        return MappingProxyType({"x": x})

    got = on_two_cores(work, [1, 2])
    assert [dict(m) for m in got] == [{"x": 1}, {"x": 2}]
    assert all(isinstance(m, MappingProxyType) for m in got)


@needs_fork
@pytest.mark.parametrize("lang", ["en", "uk"])
def test_sheets_composed_on_two_cores_are_those_composed_in_turn(
    lang: str, monkeypatch: pytest.MonkeyPatch
) -> None:
    from mmt_plans.generate import generate_one
    from mmt_plans.sheets.compose import available_sheets, compose, rendered_composed
    from mmt_plans.solution import solve
    from mmt_plans.spec import loads

    forks = []
    real_fork = os.fork

    def counted() -> int:
        forks.append(1)
        return real_fork()

    monkeypatch.setattr(forked.os, "fork", counted)
    g = generate_one(3)  # four groups, both sheets
    for text, name in [
        ((ROOT / "samples" / "six_link_press.toml").read_text(), "six_link_press.toml"),
        (g.toml, f"{g.name}.toml"),
    ]:
        files = {}
        forks.clear()
        for jobs in ("1", ""):
            monkeypatch.setenv("MMT_PLANS_JOBS", jobs)
            solution = solve(loads(text, name))
            sheets = sorted(available_sheets(solution))
            composed = compose(solution, lang, sheets)  # type: ignore[arg-type]
            files[jobs] = rendered_composed(composed, solution, ("svg", "pdf"), sheets)
        assert len(forks) == 2  # composed and rendered on two cores the second time only
        rendered_composed(composed, solution, ("svg",), sheets)
        assert len(forks) == 2  # SVG alone is written in turn (a fork costs more)
        assert [n for n, _ in files[""]] == [n for n, _ in files["1"]]
        assert files[""] == files["1"]


def test_fewer_collections_slows_the_collector_and_restores_its_pace() -> None:
    import gc

    own = gc.get_threshold()
    gc.set_threshold(700, 10, 10)  # the interpreter's own pace (another test may have set one)
    try:
        _fewer_collections_then_before()
    finally:
        gc.set_threshold(*own)


def _fewer_collections_then_before() -> None:
    import gc

    from mmt_plans.forked import FEWER_COLLECTIONS, fewer_collections

    before = gc.get_threshold()
    with fewer_collections():
        assert gc.get_threshold() == FEWER_COLLECTIONS
        with fewer_collections():  # nested: left as it is, and not undone at its end
            assert gc.get_threshold() == FEWER_COLLECTIONS
        assert gc.get_threshold() == FEWER_COLLECTIONS
    assert gc.get_threshold() == before
    with pytest.raises(RuntimeError), fewer_collections():
        raise RuntimeError("a sheet that fails")
    assert gc.get_threshold() == before


def test_sheets_are_composed_at_the_slower_pace(monkeypatch: pytest.MonkeyPatch) -> None:
    import gc

    from mmt_plans.forked import FEWER_COLLECTIONS
    from mmt_plans.sheets import compose as compose_module
    from mmt_plans.solution import solve
    from mmt_plans.spec import load

    seen: list[tuple[int, ...]] = []
    real = compose_module.on_two_cores

    def spy(work, items):  # type: ignore[no-untyped-def]
        seen.append(gc.get_threshold())
        return real(work, items)

    monkeypatch.setattr(compose_module, "on_two_cores", spy)
    own = gc.get_threshold()
    gc.set_threshold(700, 10, 10)
    try:
        mech = load(ROOT / "samples" / "offset_slider_crank.toml")
        compose_module.compose(solve(mech), "en", [1])
        assert seen == [FEWER_COLLECTIONS]
        assert gc.get_threshold() == (700, 10, 10)
    finally:
        gc.set_threshold(*own)


@needs_fork
def test_the_child_dies_with_a_killed_parent(tmp_path: Path) -> None:
    """A process killed (SIGKILL) while its fork composes leaves no child
    working: the kernel ends the child too (PR_SET_PDEATHSIG)."""
    import signal
    import subprocess
    import sys
    import time

    pids = tmp_path / "pids"
    script = f"""
import os, time
from mmt_plans.forked import on_two_cores
def work(x):
    with open({str(pids)!r}, "a") as f:
        f.write(f"{{os.getpid()}}\\n")
    time.sleep(60)
on_two_cores(work, [0, 1])
"""
    proc = subprocess.Popen([sys.executable, "-c", script], cwd=ROOT)
    try:
        deadline = time.monotonic() + 30
        while time.monotonic() < deadline and len(_lines(pids)) < 2:
            time.sleep(0.05)
        assert len(_lines(pids)) == 2, "both processes started working"
        os.kill(proc.pid, signal.SIGKILL)
        proc.wait(10)
        child = next(int(p) for p in _lines(pids) if int(p) != proc.pid)
        deadline = time.monotonic() + 10
        while time.monotonic() < deadline and _alive(child):
            time.sleep(0.05)
        assert not _alive(child)
    finally:
        if proc.poll() is None:
            proc.kill()


def _lines(path: Path) -> list[str]:
    return path.read_text().split() if path.exists() else []


def _alive(pid: int) -> bool:
    try:
        with open(f"/proc/{pid}/stat") as f:
            return f.read().split(")")[-1].split()[0] != "Z"  # a zombie has ended
    except FileNotFoundError:
        return False
