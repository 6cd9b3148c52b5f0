"""The benchmark's sweep figure comes from a fresh process and is a real time."""

from pathlib import Path

from mmt_plans.bench import sweep_time

ROOT = Path(__file__).resolve().parents[1]


def test_sweep_time_in_a_fresh_process():
    t = sweep_time(ROOT / "samples" / "offset_slider_crank.toml", 360, 1)
    assert 0.0 < t < 1.0
