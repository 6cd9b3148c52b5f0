"""Building blocks of make_tasks.py: a mechanism described in Python, written
as a mechanism file (the TOML of ../../shared/SPEC_FORMAT.md) and checked.

A task builder returns a `Task`: links in their own coordinates, sliders, the
force, the drive, and a rough `hints` sketch (the crank pin and a few points
roughly where the task's figure has them). `finish()` loads the file with the
hints, reads the exact positions of every moving point at the hint's crank
angle and writes them back as the `[sketch]`, so the file states its assembly
branch explicitly; it also picks the working direction (the slower stroke
works, unless the task fixes it) and records the smallest transmission angle.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

import mmt_plans

SWEEP = np.linspace(0.0, 360.0, 720, endpoint=False)


def num(x: float) -> str:
    """A length in mm as the files write it: whole mm, or one decimal."""
    r = round(float(x), 1)
    return str(int(r)) if r == int(r) else f"{r:.1f}"


def vec(p) -> str:
    return f"[{num(p[0])}, {num(p[1])}]"


@dataclass
class Link:
    id: int
    points: dict[str, tuple[float, float]]
    mass: float = 0.0
    J: float | None = None
    note: str = ""


@dataclass
class Slider:
    link: int
    through: tuple[float, float]
    angle: float
    on: int = 0
    note: str = ""


@dataclass
class Task:
    path: str  # relative to samples/tasks
    title: str
    header: list[str]
    frame: dict[str, tuple[float, float]]
    links: list[Link]
    sliders: list[Slider]
    output: str
    out_link: int
    force_N: float
    axis: tuple[float, float]  # the output's line of motion; the sign is chosen
    hints: dict[str, tuple[float, float]]
    rpm: float | None = None
    gears: dict | None = None
    acts: str = "working"
    angles: list[float] = field(default_factory=list)
    fixed_direction: bool = False  # keep `axis` as the working direction
    corrected: bool = False
    # filled by finish()
    working_direction: tuple[float, float] = (1.0, 0.0)
    sketch: dict[str, tuple[float, float]] = field(default_factory=dict)
    gamma_min: float = float("nan")
    formula: str = ""
    working_span: float = float("nan")

    # --- writing -----------------------------------------------------------------
    def toml(self, sketch: dict[str, tuple[float, float]] | None = None) -> str:
        sketch = self.sketch if sketch is None else sketch
        out = [f"# {line}".rstrip() for line in self.header]
        out += ["", f'title = "{self.title}"', "", "[drive]", "link = 1"]
        if self.rpm is not None:
            out.append(f"rpm = {num(self.rpm)}")
        out += ["", "[study]", "positions = 12", f'output = "{self.output}"',
                f"working_direction = [{self.working_direction[0]:g}, {self.working_direction[1]:g}]"]
        if self.angles:
            out.append("angles = [" + ", ".join(f"{a:g}" for a in self.angles) + "]")
        out += ["", "[frame]"]
        out += [f"{k} = {vec(p)}" for k, p in self.frame.items()]
        for link in self.links:
            out += ["", "[[link]]" + (f"                                 # {link.note}" if link.note else ""),
                    f"id = {link.id}",
                    "points = { " + ", ".join(f"{k} = {vec(p)}" for k, p in link.points.items()) + " }"]
            if link.mass:
                out.append(f"mass = {link.mass:g}")
            if link.J is not None:
                out.append(f"J = {link.J:g}")
        for s in self.sliders:
            out += ["", "[[slider]]" + (f"                               # {s.note}" if s.note else ""),
                    f"link = {s.link}", f"on = {s.on}", f"through = {vec(s.through)}",
                    f"angle = {s.angle:g}"]
        if sketch:
            out += ["", "[sketch]"] + [f"{k} = {vec(p)}" for k, p in sketch.items()]
        out += ["", "[[force]]", 'name = "F_PR"', f"link = {self.out_link}", f'at = "{self.output}"',
                f"magnitude = {self.force_N:g}", f'acts = "{self.acts}"']
        if self.gears is not None:
            out += ["", "[gears]", f"motor_rpm = {self.gears['motor_rpm']:g}"]
            for stage in self.gears["stages"]:
                out += ["", "[[gears.stage]]"]
                if stage[0] == "pair":
                    out += [f"z = [{stage[1][0]}, {stage[1][1]}]", f'mesh = "{stage[2]}"']
                else:
                    meshes = ", ".join(f'{{ z = [{z[0]}, {z[1]}], mesh = "{k}" }}' for z, k in stage[1])
                    out += ['kind = "planetary"', f"meshes = [{meshes}]"]
        return "\n".join(out) + "\n"

    # --- checking ----------------------------------------------------------------
    def load(self, sketch=None) -> mmt_plans.Mechanism:
        return mmt_plans.loads(self.toml(sketch), self.path)

    def finish(self) -> "Task":
        mech = self.load(self.hints)
        pin = next(p for p in self.links[0].points if p not in self.frame)
        A = np.array(self.hints[pin], dtype=float) - np.array(self.frame[next(iter(self.frame))])
        phi = math.degrees(math.atan2(A[1], A[0]))
        sw = mech.sweep(np.array([phi]))
        moving = [p for link in self.links for p in link.points if p not in self.frame]
        self.sketch = {}
        for p in dict.fromkeys(moving):
            xy = sw.points[p][0] * 1000.0
            if not np.all(np.isfinite(xy)):
                raise RuntimeError(f"{self.path}: {p} does not assemble at the sketch angle {phi:.1f}")
            self.sketch[p] = (float(xy[0]), float(xy[1]))
        mech = self.load()
        sw = mech.sweep(SWEEP)
        self.formula = mech.structure.formula
        if sw.ok.all():
            self.gamma_min = min(float(np.degrees(np.arcsin(np.clip(p.sin_angle.min(), 0, 1))))
                                 for p in sw.plans)
            if not self.fixed_direction:
                self.working_direction = self.slow_stroke(sw)
            else:
                self.working_direction = self.axis
            self.working_span = self.span(sw, self.working_direction)
        else:
            self.working_direction = self.axis
        return self

    def span(self, sw, wd) -> float:
        """Crank angle (deg, in the drive's ccw sense) from the extreme where the
        output is least along wd to the extreme where it is greatest."""
        s = sw.points[self.output] @ np.array(wd, dtype=float)
        lo, hi = SWEEP[int(np.argmin(s))], SWEEP[int(np.argmax(s))]
        return (hi - lo) % 360.0

    def slow_stroke(self, sw) -> tuple[float, float]:
        """The working stroke is the slower one (it takes the larger crank angle);
        on a tie (a central slider-crank) the output works along +axis."""
        span = self.span(sw, self.axis)
        if span >= 180.0 - 0.5:
            return self.axis
        return (-self.axis[0] + 0.0, -self.axis[1] + 0.0)

    def check(self) -> None:
        """What the tests check: loads, assembles at all 720 angles, analyses."""
        mech = self.load()
        assert mech.sweep(SWEEP).ok.all(), self.path
        mech.analyze().to_json()

    def write(self, root: Path) -> Path:
        path = root / self.path
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(self.toml(), encoding="utf-8")
        return path


# --- geometry helpers used by the builders --------------------------------------

def fourbar_coupler(d: float, r: float, rho: float) -> float:
    """The coupler length that makes the transmission angle of a crank-rocker
    swing symmetrically about 90° (γ_min + γ_max = 180°): l² + ρ² = d² + r²."""
    return math.sqrt(d * d + r * r - rho * rho)


def fourbar_distance(r: float, l: float, rho: float) -> float:
    """The frame length with the same property, given the three moving links."""
    return math.sqrt(l * l + rho * rho - r * r)


def rocker_swing(r: float, l: float, rho: float, O2: tuple[float, float], up: bool = True,
                 n: int = 720) -> tuple[np.ndarray, np.ndarray]:
    """Rocker angles (rad) over a turn and the points B, for the branch with B on
    the left of A→O2 when `up` (the upper branch for O2 right of O1)."""
    phi = np.linspace(0, 2 * np.pi, n, endpoint=False)
    A = r * np.exp(1j * phi)
    O = complex(*O2)
    dv = O - A
    dd = np.abs(dv)
    cosg = (dd ** 2 + l ** 2 - rho ** 2) / (2 * dd * l)
    ang = np.angle(dv) + (1 if up else -1) * np.arccos(np.clip(cosg, -1, 1))
    B = A + l * np.exp(1j * ang)
    return np.angle(B - O), B


def r5(x: float) -> float:
    """Round an accepted dimension to 5 mm, as a drawing would give it."""
    return 5.0 * round(x / 5.0)
