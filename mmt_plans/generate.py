"""Seeded random mechanisms for the sheet linter and the tests: a crank and a
chain of two to five dyads of every kind (RRR, RRP, RPR, PRP, RPP, seed 004),
each written out as a mechanism file (SPEC_FORMAT.md).

Each dyad is sized from the path of the point it hangs on (the partial
mechanism is solved over the turn first), so that it assembles over the whole
turn; a mechanism that still does not (checked by the chain's own branch
search), or that the tool does not solve, is drawn again. The output is the
last point, its working direction the way it moves furthest. The draws lean on the cases that break sheets: long
frames (pivots up to 1.3 m apart), 10:1 link ratios, frame pivots a few
millimetres apart, guides along the line of gravity (collinear forces), and
points named p, P, π, O, o (the letters of the poles and of position 0).
"""

from __future__ import annotations

import math
import random
from dataclasses import dataclass
from typing import Any

import numpy as np

from .errors import MmtError
from .kinematics.branches import build_chain
from .solution import solve
from .spec import loads
from .structure import DYAD_KINDS, analyse_structure
from .variants import to_toml

__all__ = ["GeneratedMechanism", "generate", "generate_one"]

_TURN = np.linspace(0.0, 360.0, 73)
_PLAIN = list("ABCDEFGHJKLMNQRSTUVWXYZ")
# the names that collide with the sheets' own letters: the poles p and π, the
# pole P of a force plan, position 0 against the pivot O
_HARD_NAMES = ["p", "P", "π", "O", "o", "O1", "A3", "O2"]
_ATTEMPTS = 200  # draws per mechanism before the seed is given up


@dataclass(frozen=True)
class GeneratedMechanism:
    """One drawn mechanism: its file's text, the kinds of its dyads and what
    makes it hard."""

    seed: int
    kinds: tuple[str, ...]
    features: tuple[str, ...]
    toml: str

    @property
    def name(self) -> str:
        return f"gen{self.seed:04d}_{'-'.join(self.kinds)}"


class _Builder:
    def __init__(self, rng: random.Random) -> None:
        self.rng = rng
        self.names = list(_PLAIN)
        rng.shuffle(self.names)
        hard = [n for n in _HARD_NAMES if rng.random() < 0.25]
        self.names = hard + self.names
        self.frame: dict[str, list[float]] = {}
        self.links: list[dict[str, Any]] = []
        self.sliders: list[dict[str, Any]] = []
        self.features: set[str] = set()
        self.kinds: list[str] = []
        self.rpm = rng.choice([30, 60, 90, 120, 200, 400])
        self.sense = rng.choice(["ccw", "cw"])

    def name(self) -> str:
        return self.names.pop(0)

    def link(self, points: dict[str, list[float]]) -> int:
        lid = len(self.links) + 1
        mass = 0.0 if self.rng.random() < 0.1 else round(self.rng.uniform(1.0, 80.0), 1)
        self.links.append({"id": lid, "points": points, "mass": mass})
        return lid

    def data(self, output: str) -> dict[str, Any]:
        return {
            "title": "Generated mechanism",
            "drive": {"link": 1, "rpm": self.rpm, "sense": self.sense},
            "study": {"positions": 12, "output": output},
            "frame": dict(self.frame),
            "link": [dict(lk) for lk in self.links],
            "slider": [dict(s) for s in self.sliders],
        }

    def path(self, output: str) -> tuple[np.ndarray, dict[str, np.ndarray]]:
        """Where every point goes over the turn (mm, complex), of the chain so far."""
        if len(self.links) == 1:  # the crank alone: its pin's circle
            (pivot, _), (pin, (r, _)) = self.links[0]["points"].items()
            circle = r * np.exp(1j * np.radians(_TURN))
            return _TURN, {pin: circle, pivot: 0 * circle}
        d = self.data(output)
        if not d["slider"]:
            del d["slider"]
        chain = build_chain(loads(to_toml(d), "generated"))
        if not chain.choice.whole_turn:
            raise _Redraw
        sw = chain.sweep(_TURN)
        names = {n for lk in self.links for n in lk["points"]} | set(self.frame)
        return _TURN, {n: np.asarray(sw.position_of(n)) * 1000.0 for n in names}

    def frame_point(self, near: complex, reach: float) -> tuple[str, complex]:
        """A frame pivot `reach` mm from `near`, in a random direction; sometimes a
        few millimetres from a pivot already there."""
        if self.frame and self.rng.random() < 0.15:
            x, y = self.rng.choice(list(self.frame.values()))
            q = complex(x, y) + self.rng.uniform(3.0, 8.0) * complex(1, 1)
            self.features.add("near-coincident pivots")
        else:
            q = near + reach * np.exp(1j * self.rng.uniform(0, 2 * math.pi))
        name = self.name()
        self.frame[name] = [_length(q.real), _length(q.imag)]
        return name, complex(*self.frame[name])


class _Redraw(Exception):
    pass


def _length(r: float) -> float:
    return float(round(float(r), 1))


def _add_dyad(b: _Builder, kind: str, p: str, carrier: tuple[str, str] | None) -> str:
    """Append a dyad of `kind` hung on the point `p` (and, for PRP, the slot of
    the link through `carrier`); returns the point the next dyad hangs on."""
    rng = b.rng
    _, where = b.path(p)
    P = where[p]
    centre = complex(P.mean())
    spread = float(np.abs(P - centre).max())
    long_frame = rng.random() < 0.2
    reach = rng.uniform(900.0, 1300.0) if long_frame else rng.uniform(1.5, 4.0) * max(spread, 40)
    if long_frame:
        b.features.add("long frame")
    if kind == "RRR":
        qn, q = b.frame_point(centre, reach)
        d = np.abs(P - q)
        lo, hi = float(d.min()), float(d.max())
        if lo < 1.0:
            raise _Redraw
        s = hi * rng.uniform(1.15, 1.6)
        diff = lo * rng.uniform(-0.8, 0.8)
        a, c = (s + diff) / 2, (s - diff) / 2
        x = b.name()
        b.link({p: [0, 0], x: [_length(a), 0]})
        ext = b.name()
        b.link({qn: [0, 0], x: [_length(c), 0], ext: [_length(c * rng.uniform(1.2, 1.6)), 0]})
        return ext
    if kind == "RRP":
        angle = rng.choice([0.0, 0.0, 90.0, rng.uniform(-60, 60)])
        if angle == 90.0:
            b.features.add("vertical guide (collinear forces)")
        u = np.exp(1j * math.radians(angle))
        through = centre + rng.uniform(-1.0, 1.0) * spread * 1j * u
        h = np.abs(((P - through) * np.conj(u)).imag)
        a = float(h.max()) / rng.uniform(0.3, 0.85) + rng.uniform(0, 200)
        if rng.random() < 0.2:
            a = max(a, 10.0 * spread)
            b.features.add("10:1 links")
        x = b.name()
        b.link({p: [0, 0], x: [_length(a), 0]})
        ext = b.name()
        lid = b.link({x: [0, 0], ext: [0, _length(rng.uniform(30.0, 120.0))]})
        b.sliders.append(
            {
                "link": lid,
                "on": 0,
                "through": [_length(through.real), _length(through.imag)],
                "angle": _length(angle),
            }
        )
        return ext
    if kind == "RPR":
        qn, q = b.frame_point(centre, max(reach, 1.3 * spread + 20))
        if float(np.abs(P - q).min()) < 10.0:
            raise _Redraw
        block = b.link({p: [0, 0]})
        t = b.name()
        length = float(np.abs(P - q).max()) * rng.uniform(1.1, 1.5)
        rocker = b.link({qn: [0, 0], t: [_length(length), 0]})
        b.sliders.append({"link": block, "on": rocker, "through": [0, 0], "angle": 0})
        return t
    if kind == "PRP":
        if carrier is None:
            raise _Redraw
        c0, c1 = where[carrier[0]], where[carrier[1]]
        slot = np.angle(c1 - c0)
        lid = next(
            lk["id"] for lk in b.links if carrier[0] in lk["points"] and carrier[1] in lk["points"]
        )
        # a frame guide never within 35° of the slot over the turn
        for _ in range(20):
            angle = rng.uniform(0.0, 180.0)
            rel = np.degrees(np.angle(np.exp(1j * (slot - math.radians(angle)))))
            if (np.abs(np.abs(rel) - 90.0) < 55.0).all():
                break
        else:
            raise _Redraw
        u = np.exp(1j * math.radians(angle))
        through = centre + rng.uniform(-0.5, 0.5) * spread * u
        j, k = b.name(), b.name()
        slider = b.link({j: [0, 0], k: [0, _length(-rng.uniform(60.0, 200.0))]})
        b.sliders.append(
            {
                "link": slider,
                "on": 0,
                "through": [_length(through.real), _length(through.imag)],
                "angle": _length(angle),
            }
        )
        block = b.link({j: [0, 0]})
        # the slot of the carrier: through its first point along its first two points
        start = next(lk for lk in b.links if lk["id"] == lid)["points"]
        (n0, v0), (n1, v1) = list(start.items())[:2]
        local = math.degrees(math.atan2(v1[1] - v0[1], v1[0] - v0[0]))
        b.sliders.append(
            {"link": block, "on": lid, "through": list(v0), "angle": float(round(local, 3))}
        )
        return k
    # RPP: a block at p in the slot of a yoke, the yoke on a frame guide
    angle = rng.choice([0.0, 90.0, rng.uniform(0, 180)])
    rel = rng.choice([90.0, rng.uniform(45.0, 135.0)])
    block = b.link({p: [0, 0]})
    y, z = b.name(), b.name()
    yoke = b.link({y: [0, 0], z: [0, _length(rng.uniform(150.0, 400.0))]})
    b.sliders.append({"link": block, "on": yoke, "through": [0, 0], "angle": _length(rel)})
    through = centre + rng.uniform(-1.0, 1.0) * spread * 1j
    b.sliders.append(
        {
            "link": yoke,
            "on": 0,
            "through": [_length(through.real), _length(through.imag)],
            "angle": _length(angle),
        }
    )
    return z


def _draw(rng: random.Random, seed: int) -> GeneratedMechanism:
    b = _Builder(rng)
    pivot = b.name()
    b.frame[pivot] = [0.0, 0.0]
    crank = rng.uniform(40.0, 200.0)
    pin = b.name()
    b.link({pivot: [0, 0], pin: [_length(crank), 0]})
    count = rng.randint(2, 5)
    kinds = [rng.choice(DYAD_KINDS) for _ in range(count)]
    if kinds[0] == "PRP":  # a PRP needs a moving slotted link before it
        kinds[0] = "RPR"
    point, carrier = pin, None
    for kind in kinds:
        if kind == "PRP" and carrier is None:
            kind = "RRR"
        point = _add_dyad(b, kind, point, carrier)
        b.kinds.append(kind)
        # the rocker of an RRR or RPR carries the next PRP's slot
        last = b.links[-1]["points"] if kind in ("RRR", "RPR") else None
        carrier = tuple(list(last)[:2]) if last and len(last) >= 2 else None  # type: ignore[assignment]
    _, where = b.path(point)  # the whole chain turns fully
    data = b.data(point)
    # the working direction: the way the output point moves furthest
    z = where[point] - where[point].mean()
    _, _, vt = np.linalg.svd(np.c_[z.real, z.imag], full_matrices=False)
    data["study"]["working_direction"] = [round(float(vt[0][0]), 4), round(float(vt[0][1]), 4)]
    lid = next(lk["id"] for lk in reversed(b.links) if point in lk["points"])
    data["force"] = [
        {
            "name": "F_PR",
            "link": lid,
            "at": point,
            "magnitude": float(rng.choice([500, 2000, 9000, 25000])),
            "acts": "always",
        }
    ]
    text = to_toml(data)
    mech = loads(text, "generated")
    st = analyse_structure(mech)
    got = tuple(str(g.kind) for g in st.groups)
    if sorted(got) != sorted(b.kinds):
        raise _Redraw
    if not build_chain(mech, st).choice.whole_turn:
        raise _Redraw
    solve(mech, forces=False)  # strokes and plans: a file the tool takes
    header = (
        f"# Generated by mmt_plans.generate (seed {seed}): dyads {' '.join(b.kinds)}"
        + (f"; {', '.join(sorted(b.features))}" if b.features else "")
        + "\n\n"
    )
    return GeneratedMechanism(seed, tuple(b.kinds), tuple(sorted(b.features)), header + text)


def generate_one(seed: int) -> GeneratedMechanism:
    """The mechanism of `seed`: the first draw of its random stream that turns fully."""
    rng = random.Random(f"mmt-generate-{seed}")
    for _ in range(_ATTEMPTS):
        try:
            return _draw(rng, seed)
        except (_Redraw, MmtError, ValueError, ArithmeticError, StopIteration):
            continue
    raise RuntimeError(f"seed {seed}: no mechanism turned fully in {_ATTEMPTS} draws")


def generate(count: int, first_seed: int = 0) -> list[GeneratedMechanism]:
    """`count` mechanisms of the seeds first_seed, first_seed + 1, …"""
    return [generate_one(s) for s in range(first_seed, first_seed + count)]
