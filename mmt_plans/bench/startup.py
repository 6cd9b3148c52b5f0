"""The cost of `mmt-plans analyze` beyond the interpreter, numpy and click:
the median of 7 runs of each, in the same bench run (target: under 150 ms)."""

from __future__ import annotations

import sys
from collections.abc import Callable, Sequence
from pathlib import Path

from ..report import table
from .timing import median_run

RUNS = 7


def bench_startup(files: Sequence[Path], repeat: int, echo: Callable[[str], None]) -> None:
    sample = next((p for p in files if p.stem == "six_link_press"), files[0])
    base = median_run([sys.executable, "-c", "import numpy, click"], RUNS)
    analyze = median_run(
        [sys.executable, "-m", "mmt_plans", "analyze", str(sample), "--quiet"], RUNS
    )
    echo(
        f"Start-up: mmt-plans analyze against `python -c 'import numpy, click'` "
        f"(median of {RUNS} runs each):"
    )
    echo(
        table(
            ["command", "median s"],
            [
                ["import numpy, click", f"{base:.3f}"],
                [f"analyze {sample.name}", f"{analyze:.3f}"],
                ["difference", f"{analyze - base:.3f}"],
            ],
        )
    )
    echo("target: the difference under 0.150 s")
    echo("")
