"""The benchmark's sweep figure comes from a fresh process and is a real,
finite time (what it is depends on the machine: `make bench` reports it)."""

import math
from pathlib import Path

from mmt_plans.bench import sweep_time

ROOT = Path(__file__).resolve().parents[1]


def test_sweep_time_in_a_fresh_process():
    t = sweep_time(ROOT / "samples" / "offset_slider_crank.toml", 360, 1)
    assert isinstance(t, float) and math.isfinite(t) and t > 0.0
