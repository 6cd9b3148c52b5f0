"""The sweep gives each group's links their motion without the plan's records
(`DyadSolver.motion`; RRR and RRP in closed form, fewer passes): the same
numbers, to 1e-12 of their size, as the plans of seed 003 §1.3 solved leg by
leg (`DyadSolver.plan`, Cramer's rule), on every sample, the hard cases and
generated chains of every dyad kind; the same assembly failures and singular
plans, angle for angle."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import mmt_plans
from mmt_plans.generate import generate_one
from mmt_plans.kinematics.chain import SINGULAR_SIN
from mmt_plans.kinematics.geometry import quiet
from mmt_plans.model import FRAME
from mmt_plans.spec import loads

ROOT = Path(__file__).resolve().parents[2]
FILES = sorted((ROOT / "samples").glob("*.toml")) + sorted((ROOT / "tests/data/hard").glob("*.toml"))
# generated chains: together they hold every dyad kind (checked below)
SEEDS = range(24)
TOL = 1e-12


def _mechanisms():
    for path in FILES:
        yield path.stem, lambda path=path: mmt_plans.load(path)
    for seed in SEEDS:
        yield f"seed{seed}", lambda seed=seed: loads(generate_one(seed).toml, f"gen{seed}.toml")


CASES = list(_mechanisms())


def _by_plans(chain, phi_deg: np.ndarray):
    """The links' motion the long way: positions, then each group's plan with
    its legs and their records, placed (`plan(m)`), as the sweep was solved
    before `motion`."""
    with quiet():
        m = chain.place_all(np.radians(phi_deg), chain.branches)
        regular = {}
        for solver in chain.solvers:
            plan = solver.plan(m)
            regular[solver.name] = np.broadcast_to(plan.regular(SINGULAR_SIN), phi_deg.shape)
    return m, regular


def _close(ours, theirs, scale: float, what: str) -> None:
    ours, theirs = np.broadcast_arrays(np.asarray(ours), np.asarray(theirs))
    assert np.array_equal(np.isnan(ours), np.isnan(theirs)), what
    ok = ~np.isnan(theirs)
    assert np.all(np.abs(ours[ok] - theirs[ok]) <= TOL * scale), what


def _scale(arrays) -> float:
    """The size of a kind of quantity over the whole chain (ω of every link,
    the velocities of every point …): a link at rest has ω of rounding noise,
    compared with the others'."""
    sizes = [np.nanmax(np.abs(a)) for a in arrays if np.isfinite(a).any()]
    return max([1e-300, *sizes])


@pytest.mark.parametrize("name, make", CASES, ids=[c[0] for c in CASES])
def test_motion_is_the_plans_motion(name, make):
    mech = make()
    chain = mmt_plans.kinematics(mech).chain
    phi = np.linspace(-7.0, 353.0, 721)
    sw = chain.sweep(phi)
    m, regular = _by_plans(chain, phi)
    moving = [lid for lid in sw.links if lid != FRAME]
    for attr, mine in (("w", "omega"), ("eps", "eps"), ("v", "v"), ("a", "a")):
        scale = _scale([np.asarray(getattr(m[lid], attr)) for lid in moving])
        for lid in moving:
            _close(getattr(sw.links[lid], mine), getattr(m[lid], attr), scale, f"{attr} {lid}")
    names = [n for n, (lid, _) in chain.locate.items() if lid != FRAME]
    for field, how in ((sw.points, "at"), (sw.v, "vel_at"), (sw.a, "acc_at")):
        theirs = {}
        for n in names:
            lid, p = chain.locate[n]
            z = np.broadcast_to(getattr(m[lid], how)(p), phi.shape)
            theirs[n] = np.stack((z.real, z.imag), axis=-1)
        scale = _scale(theirs.values())
        for n in names:
            _close(field[n], theirs[n], scale, f"{how} {n}")
    for solver in chain.solvers:
        g = solver.name
        failed = sw.failed[g]
        assert np.array_equal(sw.singular[g], ~failed & ~regular[g]), g


def test_the_generated_chains_hold_every_kind():
    kinds = set()
    for name, make in CASES:
        kinds |= {s.kind for s in mmt_plans.kinematics(make()).chain.solvers}
    assert kinds == {"RRR", "RRP", "RPR", "PRP", "RPP"}
