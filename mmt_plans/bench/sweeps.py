"""The sweep against plain numpy: positions, velocities and accelerations of
two mechanisms over N crank angles, `mmt_plans` beside a closed form written
here (issue 25's cases A and B), as ratios of the time per call.

A: slider-crank, r = 200, l = 800 mm, the guide 70 mm below the crank's pivot.
B: six-bar, crank 200, coupler 850, rocker 1000 pivoted at (750, −80) with D at
   600 on it, rod 800 to a slider on y = −900 mm. ω1 = 10.472 rad/s (100 rpm).
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from pathlib import Path

import numpy as np

from ..model import Mechanism
from ..report import table
from .timing import best_cpu_times

OMEGA = 2.0 * np.pi * 100.0 / 60.0
COUNTS = (12, 360, 36_000)

CASE_A = """
title = "bench A: offset slider-crank"
[drive]
link = 1
rpm = 100
[study]
positions = 12
output = "B"
working_direction = [1, 0]
[frame]
O = [0, 0]
[[link]]
id = 1
points = { O = [0, 0], A = [200, 0] }
[[link]]
id = 2
points = { A = [0, 0], B = [800, 0] }
[[link]]
id = 3
points = { B = [0, 0] }
[[slider]]
link = 3
on = 0
through = [0, -70]
angle = 0
[sketch]
A = [0, 200]
B = [780, -70]
"""

CASE_B = """
title = "bench B: six-bar"
[drive]
link = 1
rpm = 100
[study]
positions = 12
output = "E"
working_direction = [1, 0]
[frame]
O = [0, 0]
C = [750, -80]
[[link]]
id = 1
points = { O = [0, 0], A = [200, 0] }
[[link]]
id = 2
points = { A = [0, 0], B = [850, 0] }
[[link]]
id = 3
points = { C = [0, 0], B = [1000, 0], D = [600, 0] }
[[link]]
id = 4
points = { D = [0, 0], E = [800, 0] }
[[link]]
id = 5
points = { E = [0, 0] }
[[slider]]
link = 5
on = 0
through = [0, -900]
angle = 0
[sketch]
A = [200, 0]
B = [1000, -250]
D = [1050, -650]
E = [1800, -900]
"""


def _crank(phi_deg: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    A = 0.2 * np.exp(1j * np.radians(phi_deg))
    return A, 1j * OMEGA * A, -(OMEGA**2) * A


def _slider(D, VD, aD, l: float, y: float):
    """E on the line y through a rod of length l from D (closed form, E ahead in x)."""
    E = D.real + np.sqrt(l * l - (y - D.imag) ** 2) + 1j * y
    u = E - D
    w = -VD.imag / u.real
    VE = VD.real - w * u.imag
    eps = (w * w * u.imag - aD.imag) / u.real
    aE = aD.real - eps * u.imag - w * w * u.real
    return E, VE + 0j, aE + 0j, w, eps


def _as_sweep(points: dict[str, tuple[np.ndarray, ...]], frame: dict[str, complex], n: int):
    """What `Sweep` gives, as a numpy user would write it: every point's
    position, velocity and acceleration as [x, y] rows, the frame's points
    still. (A centre of mass in the middle of a link moves as the mean of its
    ends: a link's velocity and acceleration fields are affine.)"""
    out = []
    for k in range(3):
        field = {name: np.stack((z[k].real, z[k].imag), axis=-1) for name, z in points.items()}
        for name, z in frame.items():
            c = z if k == 0 else 0j
            field[name] = np.broadcast_to(np.array([c.real, c.imag]), (n, 2))
        out.append(field)
    return out


def _mid(P: tuple[np.ndarray, ...], Q: tuple[np.ndarray, ...]) -> tuple[np.ndarray, ...]:
    return tuple(0.5 * (p + q) for p, q in zip(P, Q))


def reference_a(phi_deg: np.ndarray) -> tuple[object, ...]:
    """Case A in closed form: every point (A, B, the centres of mass S1–S3) with
    V and a as [x, y], ω and ε of links 1–3."""
    n = phi_deg.size
    A = _crank(phi_deg)
    B, VB, aB, w2, e2 = _slider(*A, 0.8, -0.07)
    Bm = (B, VB, aB)
    O = (np.zeros(n, complex),) * 3
    fields = _as_sweep(
        {"A": A, "B": Bm, "S1": _mid(O, A), "S2": _mid(A, Bm), "S3": Bm}, {"O": 0j}, n
    )
    zero = np.zeros(n)
    omega = {1: np.full(n, OMEGA), 2: w2, 3: zero}
    eps = {1: zero, 2: e2, 3: zero}
    return fields, omega, eps


def reference_b(phi_deg: np.ndarray) -> tuple[object, ...]:
    """Case B in closed form: every point (A, B, D, E, the centres of mass
    S1–S5) with V and a as [x, y], ω and ε of links 1–5."""
    n = phi_deg.size
    A, VA, aA = _crank(phi_deg)
    C = 0.75 - 0.08j
    l2, l3 = 0.85, 1.0
    d = C - A
    dist = np.abs(d)
    alpha = np.arccos((l2 * l2 + dist * dist - l3 * l3) / (2.0 * l2 * dist))
    B = A + l2 * (d / dist) * np.exp(-1j * alpha)
    u, w = B - A, B - C
    cu, cw = np.conj(u), np.conj(w)
    w2 = (cw * VA).real / (cw * u).imag
    w3 = -(cu * VA).real / (cu * w).imag
    R = -aA + w2 * w2 * u - w3 * w3 * w
    e2 = -(cw * R).real / (cw * u).imag
    e3 = (cu * R).real / (cu * w).imag
    Bm = (B, 1j * w3 * w, (1j * e3 - w3 * w3) * w)
    Dr = 0.6 * w
    Dm = (C + Dr, 1j * w3 * Dr, (1j * e3 - w3 * w3) * Dr)
    E, VE, aE, w4, e4 = _slider(*Dm, 0.8, -0.9)
    Am, Em = (A, VA, aA), (E, VE, aE)
    Cm = (np.full(n, C), np.zeros(n, complex), np.zeros(n, complex))
    O = (np.zeros(n, complex),) * 3
    fields = _as_sweep(
        {
            "A": Am,
            "B": Bm,
            "D": Dm,
            "E": Em,
            "S1": _mid(O, Am),
            "S2": _mid(Am, Bm),
            "S3": _mid(Cm, Bm),
            "S4": _mid(Dm, Em),
            "S5": Em,
        },
        {"O": 0j, "C": C},
        n,
    )
    zero = np.zeros(n)
    omega = {1: np.full(n, OMEGA), 2: w2, 3: w3, 4: w4, 5: zero}
    eps = {1: zero, 2: e2, 3: e3, 4: e4, 5: zero}
    return fields, omega, eps


def mechanisms() -> dict[str, tuple[Mechanism, Callable[[np.ndarray], tuple[object, ...]]]]:
    from ..spec import loads

    return {
        "A": (loads(CASE_A, "bench-A.toml"), reference_a),
        "B": (loads(CASE_B, "bench-B.toml"), reference_b),
    }


def _steady_allocator() -> None:
    """Both sides timed with the allocator in the state a working process
    reaches, not in a fresh one's: a block larger than any array of a sweep,
    written and freed, lifts glibc's threshold for fresh mappings (and for
    giving memory back), so that the temporaries of neither side are timed
    as page faults. In a fresh process the 36,000-angle arrays (576 KB) are
    each a new mapping, and the reference, with more of them, paid 4× its
    time in faults."""
    np.ones(3 * 2**20)  # 24 MB


def sweep_rows(repeat: int, counts: Sequence[int] = COUNTS) -> list[list[str]]:
    """One row per case and N: µs per angle of `mmt_plans.sweep` (the cached
    chain) and of the closed form, and their ratio (CPU time, runs in turn)."""
    import mmt_plans

    _steady_allocator()
    rows = []
    for name, (mech, reference) in mechanisms().items():
        mmt_plans.sweep(mech, [0.0])  # the chain built once, as a caller sweeping in a loop
        for n in counts:
            phi = np.linspace(0.0, 360.0, n, endpoint=False)
            number = max(1, 2_000 // n)

            def ours() -> object:
                sw = mmt_plans.sweep(mech, phi)
                return sw.points, sw.v, sw.a, sw.omega, sw.eps

            def ref() -> object:
                return reference(phi)

            t_ours, t_ref = best_cpu_times((ours, ref), 3 * repeat, number)
            rows.append(
                [
                    name,
                    f"{n:,}",
                    f"{t_ours / n * 1e6:.3f}",
                    f"{t_ref / n * 1e6:.3f}",
                    f"{t_ours / t_ref:.2f}",
                    "2.0" if n < 360 else "1.2",
                ]
            )
    return rows


def bench_sweeps(files: Sequence[Path], repeat: int, echo: Callable[[str], None]) -> None:
    echo("Sweep against closed-form numpy (positions, V, a of every point, omega, eps):")
    echo(
        table(
            ["case", "N", "mmt_plans us/angle", "numpy us/angle", "ratio", "goal"],
            sweep_rows(repeat),
        )
    )
    echo("")
