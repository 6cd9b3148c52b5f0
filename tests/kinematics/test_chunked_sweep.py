"""A long sweep is solved in chunks written into one block of memory
(`chain._Arena`): the result must be bit-identical to solving every angle at
once, whatever the chunk size, and an arena's memory reused by the next
sweep must not leak into it."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import mmt_plans
from mmt_plans.kinematics import chain as chain_module
from mmt_plans.kinematics.branches import build_chain

ROOT = Path(__file__).resolve().parents[2]
SAMPLES = sorted((ROOT / "samples").glob("*.toml"))


def everything(sw) -> dict[str, np.ndarray]:
    out = {}
    for name in sw.points:
        out[f"p {name}"], out[f"v {name}"], out[f"a {name}"] = sw.points[name], sw.v[name], sw.a[name]
    for lid in sw.omega:
        out[f"w {lid}"], out[f"e {lid}"] = sw.omega[lid], sw.eps[lid]
    for g in sw.failed:
        out[f"failed {g}"], out[f"singular {g}"] = sw.failed[g], sw.singular[g]
    for k, plan in enumerate(sw.plans):
        for j, leg in enumerate(plan.legs):
            out[f"plan {k} leg {j} x"], out[f"plan {k} leg {j} y"] = leg.x, leg.y
    return {k: np.asarray(v) for k, v in out.items()}


def same_bits(a: np.ndarray, b: np.ndarray) -> bool:
    a, b = np.broadcast_arrays(a, b)
    return a.shape == b.shape and a.tobytes() == b.tobytes()


@pytest.mark.parametrize("path", SAMPLES, ids=lambda p: p.stem)
@pytest.mark.parametrize("chunk", [7, 64, 1000])
def test_chunked_sweep_is_bit_identical_to_one_pass(path, chunk, monkeypatch):
    chain = build_chain(mmt_plans.load(path))
    # 1001 angles, not a multiple of any chunk: uneven chunks, a short last one
    phi = np.linspace(-17.0, 343.0, 1001)
    whole = everything(chain.sweep(phi))  # 1001 <= CHUNK: one pass
    monkeypatch.setattr(chain_module, "CHUNK", chunk)
    chunked_sweep = chain.sweep(phi)
    assert chunked_sweep.worked_out is not None  # the arena's path was taken
    chunked = everything(chunked_sweep)
    assert whole.keys() == chunked.keys()
    for key in whole:
        assert same_bits(whole[key], chunked[key]), key


def test_arena_memory_is_not_shared_between_sweeps(monkeypatch):
    chain = build_chain(mmt_plans.load(ROOT / "samples" / "six_link_press.toml"))
    monkeypatch.setattr(chain_module, "CHUNK", 50)
    first = chain.sweep(np.linspace(0.0, 180.0, 333))
    kept = {k: v.copy() for k, v in everything(first).items()}
    second = chain.sweep(np.linspace(180.0, 360.0, 333))
    again = everything(first)
    for key in kept:  # the second sweep wrote nothing into the first one's arrays
        assert same_bits(kept[key], again[key]), key
    assert not np.array_equal(first.points["E"], second.points["E"])


def test_arena_arrays_are_read_only(monkeypatch):
    chain = build_chain(mmt_plans.load(ROOT / "samples" / "shaper.toml"))
    monkeypatch.setattr(chain_module, "CHUNK", 40)
    sw = chain.sweep(np.linspace(0.0, 360.0, 101))
    for arr in (sw.points["A"], sw.v["A"], sw.omega[3], sw.links[3].e):
        with pytest.raises(ValueError):
            arr[0] = 0
