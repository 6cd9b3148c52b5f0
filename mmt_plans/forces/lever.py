"""Zhukovsky's rigid lever (seed 003 §2.9; seed 000 §4.5, (1.41), (1.42)).

The velocity plan is turned by 90° against the crank's rotation; every force
is carried parallel to itself to the image of its point of application; the
plan, taken as a rigid lever pivoted at the pole p, is in equilibrium:

    Σ M_p(F_i) = Σ F_i·h_i = 0,                                  (1.41)

which gives the balancing force at the image a, perpendicular to pa. An
inertia moment enters either through the inertia force shifted to K_i (seed
003 §2.5, as the textbook's lever is loaded) or as a couple of forces
F'_M = M_IN / l applied at two points of the link perpendicular to it (seed
000 fig. 1.29, seed 002 task 4.3); both are kept and agree.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np

from .loads import Loads
from .state import PositionState, cross, xy_rows


@dataclass(frozen=True)
class LeverForce:
    """One force on the lever, at the image of its point of application."""

    label: str  # "G2", "F_in2", "F_PR", "F_M2", "F'_M2", "F_bal"
    link: int
    point: str  # the mechanism's point: "S2", "K2", "E", "A"
    image: np.ndarray  # its image on the turned plan (pole p at the origin), m/s
    force: np.ndarray  # N
    moment: float  # about the pole, N·m/s
    arm: float  # signed arm h about the pole, m/s: moment = |F|·h


@dataclass(frozen=True)
class ZhukovskyLever:
    turn_deg: float  # the plan's turn: −90 for a counter-clockwise crank, +90 for clockwise
    images: Mapping[str, np.ndarray]  # turned images of the points (m/s), pole at 0
    forces: tuple[LeverForce, ...]  # loads, with the inertia forces shifted to K_i
    balancing: LeverForce  # F_bal at a, perpendicular to pa
    balancing_force: float  # F_bal,z, N: positive in the sense of the crank's rotation
    pa: float  # |pa| = V_A, m/s
    couple_forces: tuple[LeverForce, ...]  # the other loading: F_IN at S_i, M_IN as couples
    balancing_force_couples: float

    @property
    def equation(self) -> str:
        terms = " + ".join(f"M_p({f.label})" for f in self.forces)
        return f"Sum M_p = {terms} + F_bal * pa = 0"


def _complex(v: np.ndarray) -> complex:
    """An [x, y] array as a complex number (through Python floats: no numpy scalars)."""
    return complex(*v.tolist())


@dataclass(frozen=True)
class _Pending:
    """A force on the lever before its vectors are made arrays (`_Builder.made`)."""

    label: str
    link: int
    point: str
    image: complex
    force: complex
    moment: float
    arm: float


class _Builder:
    def __init__(self, state: PositionState, turn: complex | None = None) -> None:
        self.state = state
        mech = state.mech
        self.s = 1.0 if mech.drive.sense == "ccw" else -1.0
        # 90° against the crank's rotation (another turn: a mistake recomputed)
        self.turn = -1j * self.s if turn is None else turn
        self.images: dict[str, complex] = {}
        self.pending: list[_Pending] = []  # the forces, made into LeverForce at once (`made`)

    def image(self, link: int, name: str, P: complex) -> complex:
        img = self.turn * self.state.links[link].vel(P)
        self.images.setdefault(name, img)
        return img

    def force(self, label: str, link: int, name: str, P: complex, F: complex) -> _Pending:
        img = self.image(link, name, P)
        M = cross(img, F)
        size = abs(F)
        found = _Pending(label, link, name, img, F, M, M / size if size else 0.0)
        self.pending.append(found)
        return found

    def made(self) -> dict[int, LeverForce]:
        """Every force as a LeverForce (by the id of its pending record), the
        images and the forces as [x, y] rows of one array."""
        rows = xy_rows([p.image for p in self.pending] + [p.force for p in self.pending])
        n = len(self.pending)
        return {
            id(p): LeverForce(p.label, p.link, p.point, rows[i], rows[n + i], p.moment, p.arm)
            for i, p in enumerate(self.pending)
        }

    def couple(self, link: int, M: float) -> list[_Pending]:
        """M as two forces ±M/l at two points of the link, perpendicular to the
        line joining them (seed 000 fig. 1.29: F'_2 = M_2 / l_AB)."""
        state = self.state
        lk = state.mech.links[link]
        names = list(lk.points)
        P = state.point(link, names[0])
        if len(names) > 1 and lk.length > 0:
            qn = names[1]
            Q = state.point(link, qn)
        else:  # a block: a point one metre along its own axis
            qn = f"{names[0]}'"
            Q = P + state.links[link].e
        d = Q - P
        l = abs(d)
        F = (M / l) * 1j * d / l  # at Q; −F at P: (Q − P) × F = M
        return [
            self.force(f"F_M{link}", link, names[0], P, -F),
            self.force(f"F'_M{link}", link, qn, Q, F),
        ]


def zhukovsky_lever(loads: Loads, *, turn_deg: float | None = None) -> ZhukovskyLever:
    """The lever; `turn_deg` another turn of the plan than 90° against the
    crank's rotation (0: not turned, the wrong way: a mistake recomputed), with
    F_bal still at a, perpendicular to pa."""
    state = loads.state
    mech = state.mech
    turn = None if turn_deg is None else complex(np.exp(1j * np.radians(turn_deg)))
    b = _Builder(state, turn)
    for lid in mech.links:  # every point's image, for the drawing
        for name in mech.links[lid].points:
            b.image(lid, name, state.point(lid, name))
    shifted: list[_Pending] = []
    couples: list[_Pending] = []
    for lid, ll in loads.links.items():
        S = _complex(ll.centre_of_mass)
        sname = ll.cm_name
        b.image(lid, sname, S)
        G = _complex(ll.weight)
        F_in = _complex(ll.inertia_force)
        if G:
            if ll.weight_point is None:
                g = b.force(f"G{lid}", lid, sname, S, G)
            else:  # a mistake recomputed: G at another point of the link
                assert ll.weight_at is not None
                g = b.force(f"G{lid}", lid, ll.weight_at, _complex(ll.weight_point), G)
            shifted.append(g)
            couples.append(g)
        if F_in:
            couples.append(b.force(f"F_in{lid}", lid, sname, S, F_in))
        sh = ll.shifted_inertia_force
        if sh is not None:
            shifted.append(b.force(f"F_in{lid}", lid, f"K{lid}", _complex(sh.point), F_in))
        else:  # nothing to shift: F_IN (if any) at S and the couple
            if F_in:
                shifted.append(couples[-1])
            if ll.inertia_moment:
                shifted += b.couple(lid, ll.inertia_moment)
        if ll.inertia_moment:
            couples += b.couple(lid, ll.inertia_moment)
    for f in loads.production_resistance:
        if f.acting:
            lf = b.force(f.name, f.link, f.at, _complex(f.point), _complex(f.force))
            shifted.append(lf)
            couples.append(lf)
    d = mech.drive.link
    O = state.point(d, mech.crank_pivot)
    A = state.point(d, mech.crank_pin)
    t = b.s * 1j * (A - O) / abs(A - O)  # the sense of rotation at A
    pa_img = b.image(d, mech.crank_pin, A)
    if turn is not None:  # F_bal perpendicular to pa on the plan turned by turn_deg
        t = b.s * 1j * pa_img / abs(pa_img)
    lever_arm = cross(pa_img, t)  # = s·|pa|

    def balance(forces: list[_Pending]) -> float:
        return -sum(f.moment for f in forces) / lever_arm

    F_bal = balance(shifted)
    bal = b.force("F_bal", d, mech.crank_pin, A, F_bal * t)
    made = b.made()
    return ZhukovskyLever(
        -90.0 * b.s if turn_deg is None else turn_deg,
        dict(zip(b.images, xy_rows(list(b.images.values())))),
        tuple(made[id(f)] for f in shifted),
        made[id(bal)],
        F_bal,
        abs(pa_img),
        tuple(made[id(f)] for f in couples),
        balance(couples),
    )
