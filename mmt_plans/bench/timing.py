"""Timing helpers of the benchmarks: best of several repeats, and what one
`analyze` or one sweep computes."""

from __future__ import annotations

import os
import statistics
import subprocess
import time
from collections.abc import Callable, Sequence
from typing import Any

import numpy as np

from ..kinematics.chain import Chain
from ..model import Mechanism
from ..results_json import results
from ..solution import solve


def median_run(args: list[str], runs: int) -> float:
    """The median wall time of `runs` runs of the command `args` (s)."""
    times = []
    for _ in range(runs):
        t0 = time.perf_counter()
        subprocess.run(args, check=True, capture_output=True)
        times.append(time.perf_counter() - t0)
    return statistics.median(times)


def best_time(fn: Callable[[], object], repeat: int, number: int = 1) -> float:
    """The least time of `repeat` runs of `number` calls, per call (s)."""
    best = float("inf")
    for _ in range(repeat):
        t0 = time.perf_counter()
        for _ in range(number):
            fn()
        best = min(best, (time.perf_counter() - t0) / number)
    return best


def best_wall_and_cpu(fn: Callable[[], object], repeat: int) -> tuple[float, float]:
    """The least wall time of `repeat` runs of `fn` and the CPU time of that
    run, this process's and its waited-for children's (the sheets' fork,
    mmt_plans.forked): what a user waits for, and what the machine spends."""

    def cpu() -> float:
        t = os.times()
        return t.user + t.system + t.children_user + t.children_system

    best = (float("inf"), float("inf"))
    for _ in range(repeat):
        t0, c0 = time.perf_counter(), cpu()
        fn()
        best = min(best, (time.perf_counter() - t0, cpu() - c0))
    return best


def best_cpu_times(
    fns: Sequence[Callable[[], object]], repeat: int, number: int = 1
) -> list[float]:
    """The least CPU time of this process (s per call) of each of `fns`, their
    runs taken in turn, so that a machine shared with other work weighs on
    each alike: for comparing in-process figures side by side (a ratio)."""
    best = [float("inf")] * len(fns)
    for _ in range(repeat):
        for k, fn in enumerate(fns):
            t0 = time.process_time()
            for _ in range(number):
                fn()
            best[k] = min(best[k], (time.process_time() - t0) / number)
    return best


def full_analysis(mech: Mechanism, diagrams: bool = True) -> dict[str, Any]:
    """Everything `analyze` computes: the solution and its results JSON."""
    return results(solve(mech), diagrams=diagrams)


def sweep_everything(chain: Chain, phi: np.ndarray) -> tuple[Any, ...]:
    sw = chain.sweep(phi)
    return sw.points, sw.v, sw.a, sw.omega, sw.eps
