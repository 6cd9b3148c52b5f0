"""Independent routes for the force tests: each link's loads rebuilt from the
mechanism file and the kinematics alone (not from mmt_plans.forces), the
equilibrium sums, and the balancing force by virtual power.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path


import mmt_plans

ROOT = Path(__file__).resolve().parents[2]
SAMPLES = sorted((ROOT / "samples").glob("*.toml"))


@dataclass
class Load:
    force: complex
    point: complex
    couple: float = 0.0
    link: int = 0


def c(v) -> complex:
    return complex(float(v[0]), float(v[1]))


def cross(a: complex, b: complex) -> float:
    return a.real * b.imag - a.imag * b.real


def own_loads(mech, sweep, k: int, stroke: str) -> dict[int, list[Load]]:
    """G = m·g (−y), F_in = −m·a_S at S, M_in = −J·ε, and the [[force]] entries
    by SPEC_FORMAT's rules, from the sweep's kinematics."""
    out: dict[int, list[Load]] = {lid: [] for lid in mech.links}
    for lid, link in mech.links.items():
        S = c(sweep.points[link.cm_name][k])
        a_S = c(sweep.a[link.cm_name][k])
        out[lid].append(Load(complex(0.0, -link.mass * mech.g), S, 0.0, lid))
        out[lid].append(Load(-link.mass * a_S, S, 0.0, lid))
        out[lid].append(Load(0j, S, -link.J * float(sweep.eps[lid][k]), lid))
    wd = c(mech.study.working_direction)
    for f in mech.forces:
        state = sweep.links[f.link]
        local = complex(*mech.links[f.link].points[f.at])
        P = complex(state.at(local)[k])
        V = complex(state.vel(state.at(local))[k])
        if f.direction is not None:
            d, acting = c(f.direction), f.acts == "always" or stroke == "working"
        elif f.acts == "working":
            d, acting = -wd, stroke == "working"
        elif abs(V) > 1e-12 * abs(c(sweep.v[mech.crank_pin][k])):
            d, acting = -V / abs(V), True
        else:  # at rest: a resistance opposing the motion is zero (SPEC_FORMAT)
            d, acting = 0j, False
        out[f.link].append(Load(f.magnitude * d if acting else 0j, P, 0.0, f.link))
    return out


def velocity_of_load(sweep, k: int, load: Load) -> complex:
    """The velocity of the load's point as a point of its link: V_o + ω × (P − o)."""
    state = sweep.links[load.link]
    return complex(state.v[k]) + 1j * float(state.omega[k]) * (load.point - complex(state.o[k]))


def virtual_power_balancing_force(mech, sweep, k: int, stroke: str) -> float:
    """F_bal = −(Σ F·V + Σ M·ω) / V_A: the principle of virtual power (seed 000 §4.5)."""
    power = 0.0
    for lid, loads in own_loads(mech, sweep, k, stroke).items():
        for ld in loads:
            V = velocity_of_load(sweep, k, ld)
            power += ld.force.real * V.real + ld.force.imag * V.imag
            power += ld.couple * float(sweep.omega[lid][k])
    V_A = abs(c(sweep.v[mech.crank_pin][k]))
    return -power / V_A


def balancing_direction(mech, sweep, k: int) -> complex:
    """The unit vector at A perpendicular to OA in the sense of the crank's rotation."""
    O = c(sweep.points[mech.crank_pivot][k])
    A = c(sweep.points[mech.crank_pin][k])
    s = 1.0 if mech.drive.sense == "ccw" else -1.0
    return s * 1j * (A - O) / abs(A - O)


def pairs_of(mech) -> list[tuple[int, int, str]]:
    return [(p.links[0], p.links[1], p.name) for p in mech.pairs]


def equilibrium_residuals(mech, sweep, k: int, stroke: str, fa) -> dict[int, tuple[float, float, float]]:
    """Per moving link: |ΣF|, the largest |ΣM_P| over a few points P, and the
    scale (largest load) — every force on the link: its own loads, the
    reactions R_ij of all its pairs from the results, F_bal on the crank."""
    own = own_loads(mech, sweep, k, stroke)
    size = max(abs(c(p[k])) for p in sweep.points.values()) + 1.0
    out = {}
    for j in mech.links:
        forces = list(own[j])
        for a, b, _ in pairs_of(mech):
            if j in (a, b):
                i = b if a == j else a
                r = fa.reaction(i, j)
                forces.append(Load(c(r.force), c(r.point), r.couple, j))
        if j == mech.drive.link:
            A = c(sweep.points[mech.crank_pin][k])
            t = balancing_direction(mech, sweep, k)
            forces.append(Load(fa.balancing_force_plans * t, A, 0.0, j))
        scale = max(abs(f.force) for f in forces) + max(abs(f.couple) for f in forces) / size
        F = sum((f.force for f in forces), 0j)
        worst = 0.0
        for P in (0j, complex(size, -2 * size), complex(-3 * size, size)):
            M = sum(cross(f.point - P, f.force) + f.couple for f in forces)
            worst = max(worst, abs(M) / size)
        out[j] = (abs(F), worst, scale)
    return out


def analyses():
    for path in SAMPLES:
        yield path.stem, mmt_plans.solve(mmt_plans.load(path))


def close(a: float, b: float, rel: float = 1e-9, abs_: float = 0.0) -> bool:
    return math.isclose(a, b, rel_tol=rel, abs_tol=abs_)
