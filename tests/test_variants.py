"""`mmt-plans variants`: reproducible, distinct, analysable over the whole
turn on the source's branches, with the source's structure."""

from __future__ import annotations

import csv
from pathlib import Path

import pytest
from click.testing import CliRunner

import mmt_plans
from mmt_plans.cli import main
from mmt_plans.structure import analyse_structure
from mmt_plans.variants import DISTINCT, make_variants, to_toml

ROOT = Path(__file__).resolve().parents[1]
PRESS = ROOT / "samples" / "six_link_press.toml"


def run(out: Path, *extra: str):
    return CliRunner().invoke(main, ["variants", str(PRESS), "--count", "20", "--seed", "7",
                                     "-o", str(out), *extra])


def test_twenty_variants_of_the_press_reproducible_and_analysable(tmp_path):
    first, second = tmp_path / "a", tmp_path / "b"
    r1, r2 = run(first), run(second)
    assert r1.exit_code == 0 and r2.exit_code == 0, r1.output
    files = sorted(first.glob("six_link_press_v*.toml"))
    assert len(files) == 20
    for f in files:  # the same bytes on a second run
        assert f.read_bytes() == (second / f.name).read_bytes()
    source = mmt_plans.solve(mmt_plans.load(PRESS))
    lengths = []
    for f in files:
        text = f.read_text(encoding="utf-8")
        assert text.startswith("# Variant") and "seed 7" in text
        solution = mmt_plans.solve(mmt_plans.load(f))
        assert solution.branches.whole_turn
        assert dict(solution.branches.signs) == dict(source.branches.signs)
        assert solution.structure.formula == source.structure.formula
        mech = solution.mechanism
        lengths.append([float(x) for lk in mech.links.values() for p in lk.points.values()
                        for x in p] + [float(x) for p in mech.frame.values() for x in p])
    # distinct: no two variants within 2 % in every length
    for i in range(len(lengths)):
        for j in range(i):
            assert any(abs(a - b) > DISTINCT * max(abs(a), abs(b), 1e-3) * 0.999
                       for a, b in zip(lengths[i], lengths[j]))
    rows = list(csv.DictReader((first / "variants.csv").open()))
    assert len(rows) == 20 and all(float(r["transmission_min_deg"]) >= 29.99 for r in rows)


def test_an_impossible_request_is_reported_not_faked(tmp_path):
    # a spread so small that the draws round back onto the source: no distinct variant
    result = CliRunner().invoke(main, ["variants", str(PRESS), "--count", "5", "--seed", "1",
                                       "--spread", "0.01", "-o", str(tmp_path)])
    assert result.exit_code == 2
    assert "only 0 of 5 variants" in result.output + result.stderr
    assert not list(tmp_path.glob("*.toml"))


def test_toml_writer_round_trips_a_sample():
    import tomllib

    for f in sorted((ROOT / "samples").glob("*.toml")):
        data = tomllib.loads(f.read_text(encoding="utf-8"))
        assert tomllib.loads(to_toml(data)) == data


def test_variants_keep_the_kinds_of_groups():
    for v in make_variants(ROOT / "samples" / "shaper.toml", 3, 11):
        mech = mmt_plans.loads(v.text)
        assert [g.kind for g in analyse_structure(mech).groups] == [
            g.kind for g in analyse_structure(mmt_plans.load(ROOT / "samples" / "shaper.toml")).groups]


@pytest.mark.parametrize("count", [0, 501])
def test_count_out_of_range_is_a_usage_error(tmp_path, count):
    result = CliRunner().invoke(main, ["variants", str(PRESS), "--count", str(count),
                                       "-o", str(tmp_path)])
    assert result.exit_code == 2
