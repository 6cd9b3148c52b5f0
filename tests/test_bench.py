"""The benchmark's sweep figure comes from a fresh process and is a real,
finite time (what it is depends on the machine: `make bench` reports it)."""

import math
from pathlib import Path

from mmt_plans.bench import sweep_time

ROOT = Path(__file__).resolve().parents[1]


def test_sweep_time_in_a_fresh_process():
    t = sweep_time(ROOT / "samples" / "offset_slider_crank.toml", 360, 1)
    assert isinstance(t, float) and math.isfinite(t) and t > 0.0


def test_the_bench_baselines_compute_what_the_sweep_does():
    """The closed forms of the sweep table (cases A and B) are an independent
    route to the same numbers: every point's position, V and a, ω and ε."""
    import numpy as np

    import mmt_plans
    from mmt_plans.bench.sweeps import mechanisms

    phi = np.linspace(0.0, 360.0, 37, endpoint=False)
    for name, (mech, reference) in mechanisms().items():
        sw = mmt_plans.sweep(mech, phi)
        fields, omega, eps = reference(phi)
        for ours, theirs in zip((sw.points, sw.v, sw.a), fields):
            assert set(ours) == set(theirs), name
            for p in ours:
                scale = max(1.0, float(np.abs(theirs[p]).max()))
                assert np.allclose(ours[p], theirs[p], rtol=0, atol=1e-12 * scale), (name, p)
        for ours, theirs in ((sw.omega, omega), (sw.eps, eps)):
            assert set(ours) == set(theirs)
            for lid in ours:
                scale = max(1.0, float(np.abs(theirs[lid]).max()))
                assert np.allclose(ours[lid], theirs[lid], rtol=0, atol=1e-12 * scale), (name, lid)


def test_the_sweep_table_gives_a_ratio_for_each_case():
    from mmt_plans.bench.sweeps import sweep_rows

    rows = sweep_rows(1, counts=(12,))
    assert [r[0] for r in rows] == ["A", "B"]
    for row in rows:
        assert math.isfinite(float(row[4])) and float(row[4]) > 0.0
        assert row[5] == "2.0"


def test_the_overview_rows_read_measured_over_goal():
    from mmt_plans.bench.overview import _row

    assert _row("solve", 1.5e-3, "ms", "goal", 3e-3) == ["solve", "1.5 ms", "goal", "3 ms", "0.50"]


def test_bench_without_the_samples_folder_says_where_to_run_it(tmp_path):
    """Run outside the repository, the bench names the missing file and the fix
    (exit 2), instead of a subprocess failure reported as an internal error."""
    from click.testing import CliRunner

    from mmt_plans.cli import main

    result = CliRunner().invoke(main, ["bench", "--summary", "--samples", str(tmp_path)])
    assert result.exit_code == 2
    assert "six_link_press.toml does not exist" in result.output
    assert "fix:" in result.output and "Traceback" not in result.output
    (tmp_path / "six_link_press.toml").write_text("")
    result = CliRunner().invoke(main, ["bench", "--summary", "--keys", "--samples", str(tmp_path)])
    assert result.exit_code == 2 and "seed003 does not exist" in result.output
