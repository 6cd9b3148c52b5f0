"""A corpus of student work for `mmt-plans check`, made by an independent
construction: three mechanisms nobody tuned the diagnoser for (a slotted-link
shaper, a crosshead in mid-chain, a ten-position vertical-output press), each
solved here by its own closed forms (circle and line intersections), its own
velocity and acceleration vector equations written out per group, and its
own kinetostatics (every link's three equilibrium equations at once, one
linear system: not the tool's group-by-group force plans). A student's
mistake is made by really making it in this construction (the Coriolis term
reversed in the group's equation, the force system solved without inertia,
the lever's moments taken on the plan not turned, ω1 = n in rad/s ...).

Right values carry a drawing's error of 2–4 %; wrong values the reading
error of 0–1 % on top of the mistake.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

G = 9.81


def cross(a: complex, b: complex) -> float:
    return (a.conjugate() * b).imag


def solve2(d1: complex, d2: complex, rhs: complex) -> tuple[float, float]:
    """α, β of α·d1 + β·d2 = rhs."""
    m = np.array([[d1.real, d2.real], [d1.imag, d2.imag]])
    a, b = np.linalg.solve(m, np.array([rhs.real, rhs.imag]))
    return float(a), float(b)


def circles(P1: complex, l1: float, P2: complex, l2: float, sign: int) -> complex:
    d = P2 - P1
    L = abs(d)
    a = (l1 * l1 - l2 * l2 + L * L) / (2 * L)
    h = math.sqrt(max(l1 * l1 - a * a, 0.0))
    return P1 + d / L * (a + sign * 1j * h)


def on_line(P: complex, l: float, Q0: complex, u: complex, sign: int) -> complex:
    """The point of the line Q0 + t·u at the distance l from P."""
    w = P - Q0
    t0 = (w * u.conjugate()).real
    dist = (w * u.conjugate()).imag
    return Q0 + (t0 + sign * math.sqrt(l * l - dist * dist)) * u


@dataclass(frozen=True)
class Method:
    """How the student constructs the plans (the textbook's by default)."""

    coriolis: float = 1.0  # -1: reversed, 0: left out
    normal: float = 1.0  # 0: a^n left out of the groups' equations
    normal_groups: tuple[str, ...] = ()  # a^n left out of these groups' equations only
    eps_reversed: tuple[int, ...] = ()  # links whose a^τ is turned the wrong way
    omega_factor: float = 1.0  # 30/π: the rpm taken as rad/s

    def n(self, group: str) -> float:
        """The factor of a^n in a group's equation."""
        return 0.0 if group in self.normal_groups else self.normal


@dataclass
class Kin:
    """One position's kinematics: points, V, a (complex, SI), ω, ε."""

    P: dict[str, complex] = field(default_factory=dict)
    V: dict[str, complex] = field(default_factory=dict)
    A: dict[str, complex] = field(default_factory=dict)
    w: dict[int, float] = field(default_factory=dict)
    e: dict[int, float] = field(default_factory=dict)

    def rotate(self, link: int, centre: str, names: list[str], method: Method) -> None:
        """Points of a link turning about `centre` by the formulas
        V = V_c + iω·r, a = a_c + a^n + a^τ (a^τ the wrong way when asked)."""
        C = self.P[centre]
        eps = -self.e[link] if link in method.eps_reversed else self.e[link]
        for n in names:
            r = self.P[n] - C
            self.V[n] = self.V[centre] + 1j * self.w[link] * r
            self.A[n] = self.A[centre] + (1j * eps - self.w[link] ** 2) * r
        if link in method.eps_reversed:
            self.e[link] = eps


# --- the three mechanisms ----------------------------------------------------------


@dataclass(frozen=True)
class Pair:
    kind: str  # "R" or "P"
    a: int  # for "P": the slider
    b: int  # for "P": the guide
    point: str
    u: complex = 0j  # for "P": the guide's direction, local to the guide (frame: global)


@dataclass(frozen=True)
class Link:
    id: int
    mass: float
    J: float
    cm: str  # the point name of its centre of mass


class Mechanism:
    toml: str
    links: tuple[Link, ...]
    pairs: tuple[Pair, ...]
    rpm: float
    crank: float  # l_OA, m
    loads_at: str  # the point the production resistance acts at (against its velocity)
    F_PR: float
    slide_link: int | None = None  # the link the slotted pair turns with

    @property
    def omega1(self) -> float:
        return self.rpm * math.pi / 30.0

    def kin(self, phi_deg: float, method: Method = Method()) -> Kin:
        raise NotImplementedError

    def guide_u(self, pair: Pair, k: Kin) -> complex:
        if pair.b == 0:
            return pair.u
        return self.link_e(pair.b, k) * pair.u

    def link_e(self, link: int, k: Kin) -> complex:
        raise NotImplementedError


class Shaper(Mechanism):
    """Crank 1, block 2 in the slot of the rocker 3 (about C), rod 4, ram 5."""

    r, l3, l4, yD = 0.10, 0.56, 0.20, 0.33
    C = -0.30j
    rpm = 75.0
    crank = 0.10
    loads_at = "D"
    F_PR = 2500.0
    links = (
        Link(1, 3.0, 0.0, "O"),
        Link(2, 1.5, 0.0, "A"),
        Link(3, 18.0, 0.5, "S3"),
        Link(4, 5.0, 0.02, "S4"),
        Link(5, 25.0, 0.0, "D"),
    )
    pairs = (
        Pair("R", 0, 1, "O"),
        Pair("R", 1, 2, "A"),
        Pair("P", 2, 3, "A", 1 + 0j),
        Pair("R", 0, 3, "C"),
        Pair("R", 3, 4, "B"),
        Pair("R", 4, 5, "D"),
        Pair("P", 5, 0, "D", 1 + 0j),
    )
    toml = """
title = "Corpus shaper"
[drive]
link = 1
rpm = 75
[study]
positions = 12
output = "D"
working_direction = [-1, 0]
[frame]
O = [0, 0]
C = [0, -300]
[[link]]
id = 1
points = { O = [0, 0], A = [100, 0] }
mass = 3
cm = [0, 0]
[[link]]
id = 2
points = { A = [0, 0] }
mass = 1.5
[[link]]
id = 3
points = { C = [0, 0], B = [560, 0] }
mass = 18
J = 0.5
cm = [280, 0]
[[link]]
id = 4
points = { B = [0, 0], D = [200, 0] }
mass = 5
J = 0.02
cm = [100, 0]
[[link]]
id = 5
points = { D = [0, 0] }
mass = 25
[[slider]]
link = 2
on = 3
through = [0, 0]
angle = 0
[[slider]]
link = 5
on = 0
through = [0, 330]
angle = 0
[sketch]
A = [0, 100]
B = [0, 260]
D = [190, 330]
[[force]]
name = "F_PR"
link = 5
at = "D"
magnitude = 2500
acts = "always"
"""

    def kin(self, phi_deg: float, method: Method = Method()) -> Kin:
        k = Kin()
        w1 = self.omega1 * method.omega_factor
        phi = math.radians(phi_deg)
        O, C = 0j, self.C
        A = self.r * complex(math.cos(phi), math.sin(phi))
        k.P.update(O=O, C=C, A=A)
        k.V.update(O=0j, C=0j, A=1j * w1 * A)
        k.A.update(O=0j, C=0j, A=-(w1**2) * A)
        k.w[1], k.e[1] = w1, 0.0
        k.w[2] = k.e[2] = 0.0
        u = (A - C) / abs(A - C)
        # group 2–3: V_A3 = V_A2 + V_A3A2 (along the slot) = iω3·CA
        w3, x = solve2(1j * (A - C), -u, k.V["A"])
        # a_A3 = a_A2 + a^k + a^r = a^n + a^τ about C
        cor = method.coriolis * 2j * w3 * x * u
        e3, _ = solve2(1j * (A - C), -u, k.A["A"] + cor + method.n("2-3") * w3 * w3 * (A - C))
        k.w[3], k.e[3] = w3, e3
        k.w[2], k.e[2] = w3, e3  # the block turns with the slotted link
        B = C + self.l3 * u
        k.P["B"] = B
        k.P["S3"] = C + self.l3 / 2 * u
        k.P["A3"] = A
        k.rotate(3, "C", ["B", "S3"], method)
        # group 4–5: D on the ram's guide
        D = on_line(B, self.l4, 1j * self.yD, 1 + 0j, 1)
        k.P["D"] = D
        w4, v5 = solve2(1j * (D - B), -1 + 0j, -k.V["B"])
        e4, a5 = solve2(1j * (D - B), -1 + 0j, -k.A["B"] + method.n("4-5") * w4 * w4 * (D - B))
        k.w[4], k.e[4], k.w[5], k.e[5] = w4, e4, 0.0, 0.0
        k.P["S4"] = (B + D) / 2
        k.rotate(4, "B", ["D", "S4"], method)
        k.V["D"], k.A["D"] = complex(v5), complex(a5) if 4 not in method.eps_reversed else k.A["D"]
        k.P["S1"], k.V["S1"], k.A["S1"] = O, 0j, 0j
        for n in ("S2", "S5"):
            src = "A" if n == "S2" else "D"
            k.P[n], k.V[n], k.A[n] = k.P[src], k.V[src], k.A[src]
        return k

    def link_e(self, link: int, k: Kin) -> complex:
        d = k.P["B"] - self.C
        return d / abs(d)


class Crosshead(Mechanism):
    """Crank 1, rod 2, crosshead 3 on a horizontal guide, rod 4 from its pin F,
    rocker 5 about C."""

    r, l2, l4, l5 = 0.08, 0.30, 0.25, 0.20
    C = 0.52 + 0.26j
    fF = 0.04  # F on the crosshead, 40 mm ahead of B
    rpm = 120.0
    crank = 0.08
    loads_at = "D"
    F_PR = 1500.0
    links = (
        Link(1, 2.0, 0.0, "O"),
        Link(2, 6.0, 0.05, "S2"),
        Link(3, 8.0, 0.0, "B"),
        Link(4, 5.0, 0.03, "S4"),
        Link(5, 4.0, 0.02, "S5"),
    )
    pairs = (
        Pair("R", 0, 1, "O"),
        Pair("R", 1, 2, "A"),
        Pair("R", 2, 3, "B"),
        Pair("P", 3, 0, "B", 1 + 0j),
        Pair("R", 3, 4, "F"),
        Pair("R", 4, 5, "D"),
        Pair("R", 0, 5, "C"),
    )
    toml = """
title = "Corpus crosshead in mid-chain"
[drive]
link = 1
rpm = 120
[study]
positions = 12
output = "B"
working_direction = [1, 0]
[frame]
O = [0, 0]
C = [520, 260]
[[link]]
id = 1
points = { O = [0, 0], A = [80, 0] }
mass = 2
cm = [0, 0]
[[link]]
id = 2
points = { A = [0, 0], B = [300, 0] }
mass = 6
J = 0.05
cm = [150, 0]
[[link]]
id = 3
points = { B = [0, 0], F = [40, 0] }
mass = 8
cm = [0, 0]
[[link]]
id = 4
points = { F = [0, 0], D = [250, 0] }
mass = 5
J = 0.03
cm = [125, 0]
[[link]]
id = 5
points = { C = [0, 0], D = [200, 0] }
mass = 4
J = 0.02
cm = [100, 0]
[[slider]]
link = 3
on = 0
through = [0, 0]
angle = 0
[sketch]
A = [80, 0]
B = [380, 0]
D = [400, 230]
[[force]]
name = "F_PR"
link = 5
at = "D"
magnitude = 1500
acts = "always"
"""

    def kin(self, phi_deg: float, method: Method = Method()) -> Kin:
        k = Kin()
        w1 = self.omega1 * method.omega_factor
        phi = math.radians(phi_deg)
        A = self.r * complex(math.cos(phi), math.sin(phi))
        k.P.update(O=0j, C=self.C, A=A)
        k.V.update(O=0j, C=0j, A=1j * w1 * A)
        k.A.update(O=0j, C=0j, A=-(w1**2) * A)
        k.w[1], k.e[1] = w1, 0.0
        B = on_line(A, self.l2, 0j, 1 + 0j, 1)
        k.P["B"] = B
        # group 2–3: V_B = V_A + iω2·AB, along the guide
        w2, vB = solve2(1j * (B - A), -1 + 0j, -k.V["A"])
        e2, aB = solve2(1j * (B - A), -1 + 0j, -k.A["A"] + method.n("2-3") * w2 * w2 * (B - A))
        k.w[2], k.e[2], k.w[3], k.e[3] = w2, e2, 0.0, 0.0
        k.P["S2"] = (A + B) / 2
        k.rotate(2, "A", ["B", "S2"], method)
        k.V["B"] = complex(vB)
        if 2 not in method.eps_reversed:
            k.A["B"] = complex(aB)
        F = B + self.fF
        k.P["F"], k.V["F"], k.A["F"] = F, k.V["B"], k.A["B"]
        # group 4–5: D = F + FD = C + CD
        D = circles(F, self.l4, self.C, self.l5, 1)
        k.P["D"] = D
        w4, w5 = solve2(1j * (D - F), -1j * (D - self.C), -k.V["F"])
        rhs = -k.A["F"] + method.n("4-5") * (w4 * w4 * (D - F) - w5 * w5 * (D - self.C))
        e4, e5 = solve2(1j * (D - F), -1j * (D - self.C), rhs)
        k.w[4], k.e[4], k.w[5], k.e[5] = w4, e4, w5, e5
        k.P["S4"] = (F + D) / 2
        k.P["S5"] = (self.C + D) / 2
        k.rotate(5, "C", ["D", "S5"], method)
        k.rotate(4, "F", ["S4"], method)
        k.A["D"] = k.A["F"] + (1j * e4 - method.n("4-5") * w4 * w4) * (D - F)  # the plan's d
        k.P["S1"], k.V["S1"], k.A["S1"] = 0j, 0j, 0j
        k.P["S3"], k.V["S3"], k.A["S3"] = B, k.V["B"], k.A["B"]
        return k


class Press(Mechanism):
    """Four-bar O-A-B-C with the rocker 3 carried on to D, rod 4, ram 5 on a
    vertical guide: the output moves vertically; ten positions."""

    r, l2, l3, l3D, l4 = 0.09, 0.32, 0.25, 0.40, 0.45
    C = 0.30 - 0.15j
    xE = 0.55
    rpm = 90.0
    crank = 0.09
    loads_at = "E"
    F_PR = 4000.0
    links = (
        Link(1, 3.0, 0.0, "O"),
        Link(2, 8.0, 0.07, "S2"),
        Link(3, 10.0, 0.15, "S3"),
        Link(4, 6.0, 0.05, "S4"),
        Link(5, 20.0, 0.0, "E"),
    )
    pairs = (
        Pair("R", 0, 1, "O"),
        Pair("R", 1, 2, "A"),
        Pair("R", 2, 3, "B"),
        Pair("R", 0, 3, "C"),
        Pair("R", 3, 4, "D"),
        Pair("R", 4, 5, "E"),
        Pair("P", 5, 0, "E", 1j),
    )
    toml = """
title = "Corpus vertical press"
[drive]
link = 1
rpm = 90
sense = "cw"
[study]
positions = 10
output = "E"
working_direction = [0, -1]
[frame]
O = [0, 0]
C = [300, -150]
[[link]]
id = 1
points = { O = [0, 0], A = [90, 0] }
mass = 3
cm = [0, 0]
[[link]]
id = 2
points = { A = [0, 0], B = [320, 0] }
mass = 8
J = 0.07
cm = [160, 0]
[[link]]
id = 3
points = { C = [0, 0], B = [250, 0], D = [400, 0] }
mass = 10
J = 0.15
cm = [200, 0]
[[link]]
id = 4
points = { D = [0, 0], E = [450, 0] }
mass = 6
J = 0.05
cm = [225, 0]
[[link]]
id = 5
points = { E = [0, 0] }
mass = 20
[[slider]]
link = 5
on = 0
through = [550, 0]
angle = 90
[sketch]
A = [0, 90]
B = [310, 100]
D = [320, 250]
E = [550, 60]
[[force]]
name = "F_PR"
link = 5
at = "E"
magnitude = 4000
acts = "always"
"""

    def kin(self, phi_deg: float, method: Method = Method()) -> Kin:
        k = Kin()
        w1 = -self.omega1 * method.omega_factor  # clockwise
        phi = math.radians(phi_deg)
        A = self.r * complex(math.cos(phi), math.sin(phi))
        C = self.C
        k.P.update(O=0j, C=C, A=A)
        k.V.update(O=0j, C=0j, A=1j * w1 * A)
        k.A.update(O=0j, C=0j, A=-(w1**2) * A)
        k.w[1], k.e[1] = w1, 0.0
        B = circles(A, self.l2, C, self.l3, 1)
        k.P["B"] = B
        w2, w3 = solve2(1j * (B - A), -1j * (B - C), -k.V["A"])
        rhs = -k.A["A"] + method.n("2-3") * (w2 * w2 * (B - A) - w3 * w3 * (B - C))
        e2, e3 = solve2(1j * (B - A), -1j * (B - C), rhs)
        k.w[2], k.e[2], k.w[3], k.e[3] = w2, e2, w3, e3
        u3 = (B - C) / abs(B - C)
        k.P["D"] = C + self.l3D * u3
        k.P["S3"] = C + 0.2 * u3
        k.P["S2"] = (A + B) / 2
        k.rotate(3, "C", ["B", "D", "S3"], method)
        k.rotate(2, "A", ["S2"], method)
        k.A["B"] = k.A["A"] + (1j * e2 - method.n("2-3") * w2 * w2) * (B - A)  # the plan's b
        D = k.P["D"]
        E = on_line(D, self.l4, self.xE + 0j, 1j, -1)
        k.P["E"] = E
        w4, vE = solve2(1j * (E - D), -1j, -k.V["D"])
        e4, aE = solve2(1j * (E - D), -1j, -k.A["D"] + method.n("4-5") * w4 * w4 * (E - D))
        k.w[4], k.e[4], k.w[5], k.e[5] = w4, e4, 0.0, 0.0
        k.P["S4"] = (D + E) / 2
        k.rotate(4, "D", ["S4"], method)
        k.V["E"] = 1j * vE
        if 4 not in method.eps_reversed:
            k.A["E"] = 1j * aE
        k.P["S1"], k.V["S1"], k.A["S1"] = 0j, 0j, 0j
        k.P["S5"], k.V["S5"], k.A["S5"] = E, k.V["E"], k.A["E"]
        return k


MECHANISMS = {"shaper": Shaper(), "crosshead": Crosshead(), "press": Press()}


# --- kinetostatics: every link's equilibrium at once -------------------------------------


@dataclass(frozen=True)
class Forces:
    reactions: dict[str, float]  # |R_ij| by "Rij" (i < j)
    F_bal: float  # N, + drives the crank
    F_bal_lever: float
    F_in: dict[int, float]
    M_in: dict[int, float]
    G: dict[int, float]


@dataclass(frozen=True)
class ForceMethod:
    inertia: tuple[int, ...] | None = None  # links whose F_in, M_in are kept (None: all)
    gravity: bool = True
    lever_turned: bool = True
    moments: bool = True  # False: M_in left out (F_in at S)
    weight_at: tuple[tuple[int, str], ...] = ()  # G of a link at this point, not at S


def forces(mech: Mechanism, k: Kin, fm: ForceMethod = ForceMethod()) -> Forces:
    """Reactions and F_bal from ΣF = 0, ΣM = 0 of every moving link (one
    linear system); F_bal also by Zhukovsky's lever (power of every load)."""
    ids = [lk.id for lk in mech.links]
    row = {lid: 3 * n for n, lid in enumerate(ids)}
    unknowns: list[tuple[str, list[tuple[int, complex, complex, float]]]] = []
    # each unknown: a list of (link, force per unit, point, couple per unit)
    for p in mech.pairs:
        P = k.P[p.point]
        if p.kind == "R":
            for d in (1 + 0j, 1j):
                unknowns.append((f"R{p.a}{p.b}", [(p.b, d, P, 0.0), (p.a, -d, P, 0.0)]))
        else:
            n = 1j * mech.guide_u(p, k)
            unknowns.append((f"R{min(p.a, p.b)}{max(p.a, p.b)}", [(p.a, n, P, 0.0), (p.b, -n, P, 0.0)]))
            unknowns.append(("couple", [(p.a, 0j, P, 1.0), (p.b, 0j, P, -1.0)]))
    A = k.P["A"]
    s = 1.0 if k.w[1] > 0 else -1.0
    t = s * 1j * A / abs(A)
    unknowns.append(("F_bal", [(1, t, A, 0.0)]))
    m = np.zeros((3 * len(ids), len(unknowns)))
    for j, (_, acts) in enumerate(unknowns):
        for link, f, P, c in acts:
            if link == 0:
                continue
            r = row[link]
            m[r, j] += f.real
            m[r + 1, j] += f.imag
            m[r + 2, j] += cross(P, f) + c
    rhs = np.zeros(3 * len(ids))
    loads = []  # (link, force, point, couple) of the known loads
    F_in, M_in, Gs = {}, {}, {}
    for lk in mech.links:
        S = k.P[lk.cm]
        g = -1j * lk.mass * G
        f_in = -lk.mass * k.A[lk.cm]
        m_in = -lk.J * k.e[lk.id]
        F_in[lk.id], M_in[lk.id], Gs[lk.id] = abs(f_in), abs(m_in), abs(g)
        if fm.gravity:
            at = dict(fm.weight_at).get(lk.id)
            loads.append((lk.id, g, S if at is None else k.P[at], 0.0))
        if fm.inertia is None or lk.id in fm.inertia:
            loads.append((lk.id, f_in, S, m_in if fm.moments else 0.0))
    V_at = k.V[mech.loads_at]
    F_pr = -mech.F_PR * V_at / abs(V_at) if abs(V_at) > 1e-12 else 0j
    link_pr = next(p.b for p in mech.pairs if p.point == mech.loads_at and p.kind == "R")
    loads.append((link_pr, F_pr, k.P[mech.loads_at], 0.0))
    for link, f, P, c in loads:
        r = row[link]
        rhs[r] -= f.real
        rhs[r + 1] -= f.imag
        rhs[r + 2] -= cross(P, f) + c
    x = np.linalg.solve(m, rhs)
    values: dict[str, list[float]] = {}
    for (name, _), val in zip(unknowns, x):
        if name not in ("couple", "F_bal"):
            values.setdefault("R" + "".join(sorted(name[1:])), []).append(float(val))
    mags = {n: float(np.hypot(*v)) if len(v) == 2 else abs(v[0]) for n, v in values.items()}
    F_bal = float(x[-1])
    # Zhukovsky: Σ moments on the plan turned by 90° (the power of every load),
    # or on the plan not turned (F_in at K, shifted by h = M_in / F_in)
    total = 0.0
    for link, f, P, c in loads:
        VP = _velocity_at(mech, k, link, P)
        if c and abs(f) > 1e-12:  # F_in shifted to K: moment about S equals M_in
            P = P - c * 1j * f / abs(f) ** 2
            VP = _velocity_at(mech, k, link, P)
        elif c:
            total += c * k.w[link] if fm.lever_turned else 0.0
        total += (VP.conjugate() * f).real if fm.lever_turned else cross(VP, f)
    VA = k.V["A"]
    lever = -total / (abs(VA) if fm.lever_turned else s * abs(VA))
    return Forces(mags, F_bal, lever, F_in, M_in, Gs)


def _velocity_at(mech: Mechanism, k: Kin, link: int, P: complex) -> complex:
    """Velocity of the point of `link` now at P (the link's ω about one of its points)."""
    ref = next(n for n in _points_of(mech, link) if n in k.V)
    return k.V[ref] + 1j * k.w[link] * (P - k.P[ref])


def _points_of(mech: Mechanism, link: int) -> list[str]:
    names = [p.point for p in mech.pairs if link in (p.a, p.b) and p.kind == "R"]
    return names + [lk.cm for lk in mech.links if lk.id == link]
