"""How the sheets' work runs: independent pieces on two cores, half of them
in a forked child, and the cyclic collector at a slower pace meanwhile.

`on_two_cores(work, items)` gives `[work(item) for item in items]`, with the
items at even places (sheet 1, sheet 3 …) worked in a child process forked
from this one while this one works the rest. The child inherits everything
already computed (the solution, the fonts' metrics, the modules), so nothing
is sent to it; it sends back its results pickled through a pipe (a sheet's
recording: some 10 ms).

The result is the same as working them in turn, and nothing depends on the
child: where it fails in any way (an exception, a result that does not
pickle or unpickle, a killed process) the parent works its items itself, so
the same error is raised the same way. It forks only where that is safe and
pays: on Linux, with two cores or more, from a process running one thread
(batch's workers write from a thread; the web app serves from threads), and
not where MMT_PLANS_JOBS=1.

`fewer_collections()` collects the youngest generation every 5,000 new
containers instead of 700 while it holds (composing makes many short-lived
ones: recorded calls, label boxes, points; nearly none is a cycle): some
15 % of a sheet's time. Batch's workers run at that pace throughout.

Imports only the standard library.
"""

from __future__ import annotations

import copyreg
import gc
import io
import os
import pickle
import sys
import threading
from collections.abc import Callable, Iterator, Sequence
from contextlib import contextmanager
from types import MappingProxyType
from typing import Any, TypeVar

__all__ = ["FEWER_COLLECTIONS", "can_fork", "die_with", "fewer_collections", "on_two_cores"]

T = TypeVar("T")
R = TypeVar("R")

# the collector's thresholds while sheets are composed (gc.set_threshold):
# the youngest generation every 5,000 new containers, the older ones as usual
FEWER_COLLECTIONS = (5_000, 10, 10)


@contextmanager
def fewer_collections() -> Iterator[None]:
    """The collector at FEWER_COLLECTIONS' pace while this holds, its own
    pace again after; left as it is where it is that slow already (a batch
    worker, an enclosing `fewer_collections`)."""
    before = gc.get_threshold()
    if before[0] >= FEWER_COLLECTIONS[0]:
        yield
        return
    gc.set_threshold(*FEWER_COLLECTIONS)
    try:
        yield
    finally:
        gc.set_threshold(*before)


def can_fork() -> bool:
    """Whether `on_two_cores` forks here: Linux, two usable cores or more, one
    thread running, MMT_PLANS_JOBS not 1."""
    if os.environ.get("MMT_PLANS_JOBS", "").strip() == "1":
        return False
    if not sys.platform.startswith("linux") or not hasattr(os, "fork"):
        return False
    if threading.active_count() != 1:
        return False
    return len(os.sched_getaffinity(0)) >= 2


def on_two_cores(work: Callable[[T], R], items: Sequence[T]) -> list[R]:
    """`[work(item) for item in items]`: the items at even places worked in a
    forked child where `can_fork`, the rest here; anything the child did not
    give back worked here too."""
    items = list(items)
    if len(items) < 2 or not can_fork():
        return [work(item) for item in items]
    theirs = list(range(0, len(items), 2))
    parent = os.getpid()
    read, write = os.pipe()
    pid = os.fork()
    if pid == 0:  # the child: never returns, never runs the parent's exit handlers
        status = 1
        try:
            os.close(read)
            die_with(parent)
            blob = _dumps([work(items[i]) for i in theirs])
            with os.fdopen(write, "wb") as pipe:
                pipe.write(blob)
            status = 0
        except BaseException:  # the parent works these items itself
            pass
        finally:
            os._exit(status)
    os.close(write)
    got: dict[int, R] = {}
    try:
        mine = {i: work(items[i]) for i in range(1, len(items), 2)}
    finally:
        # (read the pipe to its end before waiting: the child blocks on a full pipe)
        with os.fdopen(read, "rb") as pipe:
            blob = pipe.read()
        _, status = os.waitpid(pid, 0)
    if os.waitstatus_to_exitcode(status) == 0:
        try:
            got = dict(zip(theirs, pickle.loads(blob), strict=True))
        except Exception:  # a result that does not unpickle: worked here
            got = {}
    got.update(mine)
    return [got[i] if i in got else work(items[i]) for i in range(len(items))]


_PR_SET_PDEATHSIG = 1  # linux/prctl.h


def die_with(parent: int) -> None:
    """This process ends when the process `parent` does, even killed by
    SIGKILL (on Linux the kernel sends it SIGKILL then: prctl
    PR_SET_PDEATHSIG): no fork left composing a sheet nobody will read, no
    batch worker left waiting (batch._die_with_parent)."""
    import ctypes
    import signal

    try:
        libc = ctypes.CDLL(None, use_errno=True)
        libc.prctl(_PR_SET_PDEATHSIG, signal.SIGKILL, 0, 0, 0)
    except (OSError, AttributeError):
        pass  # (without prctl: a fork ends at its first write to a pipe nobody
        # reads, a batch worker by its thread watching the parent)
    if os.getppid() != parent:  # the parent died before prctl took effect
        os._exit(1)


def _dumps(value: Any) -> bytes:
    """`value` pickled, read-only mappings (MappingProxyType) among it too."""
    out = io.BytesIO()
    pickler = pickle.Pickler(out, protocol=pickle.HIGHEST_PROTOCOL)
    pickler.dispatch_table = {**copyreg.dispatch_table, MappingProxyType: _proxy}  # type: ignore[dict-item]
    pickler.dump(value)
    return out.getvalue()


def _proxy(m: MappingProxyType[Any, Any]) -> tuple[Any, tuple[dict[Any, Any]]]:
    return _read_only, (dict(m),)


def _read_only(d: dict[Any, Any]) -> MappingProxyType[Any, Any]:
    """A read-only mapping unpickled (MappingProxyType has no name pickle finds)."""
    return MappingProxyType(d)
