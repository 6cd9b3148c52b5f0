"""Write every task of seeds 003 and 002 as a mechanism file.

    .venv/bin/python samples/tasks/make_tasks.py          # writes seed003/, seed002/
    .venv/bin/python samples/tasks/make_tasks.py --check  # also analyses every file

The seeds lost their scheme figures; each builder below states the scheme
inferred from the task's parameters (samples/README.md explains each one).
A builder turns one column of a task's table into a `Task`: links in their own
coordinates (mm), sliders, the production resistance, the drive, and a rough
sketch. `Task.finish()` then

- solves the file at the sketch's crank angle and writes the exact positions of
  every moving point as `[sketch]`, so each file names its assembly branch
  (where a builder offers several rough sketches, the branch with the largest
  smallest transmission angle over the turn is kept, the first on a tie);
- picks the working direction: the slower stroke (the larger crank angle) is
  the working one, unless the task text fixes it (seed 003 task 1, section V:
  position 0 is the extreme left position);
- records the smallest transmission angle γ_min over the turn (the angle
  between the two direction lines of each group's plan; 90° is best).

Seed 002 describes one position of each mechanism (φ1); several of its tables
do not let the crank make a full turn. Such a variant gets the nearest value of
one frame dimension (1 mm steps) that turns with γ_min >= 15°; the file says so
in a "Correction:" comment. Seed 003's misprints are corrected by hand below.

Every file has its title in English (`title`) and in Ukrainian (`title_uk`, for
the Ukrainian sheets; one pattern for all, `uk_title`, in the terms of seeds 000
and 002).

Rerunnable: the output depends only on the tables here and on mmt_plans.
"""

from __future__ import annotations

import math
import sys
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable

import numpy as np

import mmt_plans
from mmt_plans.results_json import results
from mmt_plans.structure import analyse_structure

HERE = Path(__file__).resolve().parent
SWEEP = np.linspace(0.0, 360.0, 720, endpoint=False)
GAMMA_ACCEPT = 10.0  # seed 002: a table value is kept when the turn has γ_min above this
GAMMA_TARGET = 15.0  # ... and a corrected value reaches at least this


# ======================================================================================
# A mechanism described in Python and written as a mechanism file
# ======================================================================================

def num(x: float) -> str:
    """A length in mm as the files write it: whole mm, or one decimal."""
    r = round(float(x), 1)
    if r == 0:
        r = 0.0
    return str(int(r)) if r == int(r) else f"{r:.1f}"


def vec(p) -> str:
    return f"[{num(p[0])}, {num(p[1])}]"


def uk_title(seed: str, task: int, v: int, what: str, phi1: float | None = None) -> str:
    """The Ukrainian title, one pattern for every file (the English one is
    "Seed 003 task 1 v1: ..."): "Завдання 1 (посібник 003), варіант 1: ...";
    seed 002 adds its crank angle as "(φ1 = 210°)". Terms as in seeds 000 and 002."""
    angle = "" if phi1 is None else f" (φ1 = {phi1:g}°)"
    return f"Завдання {task} (посібник {seed}), варіант {v}: {what}{angle}"


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
    title_uk: str  # the same title in Ukrainian (uk_title), for the Ukrainian sheets
    header: list[str]
    frame: dict[str, tuple[float, float]]  # the crank pivot first
    links: list[Link]
    sliders: list[Slider]
    output: str
    out_link: int
    force_N: float
    axis: tuple[float, float]  # the output's line of motion; its sign is chosen
    hints: list[dict[str, tuple[float, float]]]  # rough sketches, preferred first
    rpm: float | None = None
    gears: list | None = None  # [motor_rpm, stage, ...]
    acts: str = "working"
    phi1: float | None = None  # seed 002: the given crank angle
    fixed_direction: bool = False
    corrections: list[str] = field(default_factory=list)
    # filled by finish()
    working_direction: tuple[float, float] = (1.0, 0.0)
    sketch: dict[str, tuple[float, float]] = field(default_factory=dict)
    gamma_min: float = float("nan")
    ok: bool = False
    formula: str = ""
    working_span: float = float("nan")

    # --- writing -----------------------------------------------------------------
    def toml(self, sketch: dict | None = None) -> str:
        sketch = self.sketch if sketch is None else sketch
        lines = [f"# {line}".rstrip() for line in self.header]
        for c in self.corrections:
            lines.append(f"# Correction: {c}")
        if self.ok:
            lines.append(f"# Smallest transmission angle over the turn: {self.gamma_min:.0f} deg; "
                         f"working stroke {self.working_span:.0f} deg of crank turn.")
        out = lines + ["", f'title = "{self.title}"', f'title_uk = "{self.title_uk}"', "",
                       "[drive]", "link = 1"]
        if self.rpm is not None:
            out.append(f"rpm = {num(self.rpm)}")
        out += ["", "[study]", "positions = 12", f'output = "{self.output}"',
                f"working_direction = [{self.working_direction[0]:g}, {self.working_direction[1]:g}]"]
        if self.phi1 is not None:
            out += [f"zero = {self.phi1:g}                  # position 0 is the task's phi1 ...",
                    "plans = [0, 6]              # ... so its plans",
                    "force_position = 0          # and its force analysis are at phi1",
                    f"angles = [{self.phi1:g}]"]
        out += ["", "[frame]"] + [f"{k} = {vec(p)}" for k, p in self.frame.items()]
        for link in self.links:
            out += ["", "[[link]]" + (f"    # {link.note}" if link.note else ""),
                    f"id = {link.id}",
                    "points = { " + ", ".join(f"{k} = {vec(p)}" for k, p in link.points.items()) + " }"]
            if link.mass:
                out.append(f"mass = {link.mass:g}")
            if link.J is not None:
                out.append(f"J = {link.J:g}")
        for s in self.sliders:
            out += ["", "[[slider]]" + (f"  # {s.note}" if s.note else ""),
                    f"link = {s.link}", f"on = {s.on}", f"through = {vec(s.through)}",
                    f"angle = {s.angle:g}"]
        if sketch:
            out += ["", "[sketch]"] + [f"{k} = {vec(p)}" for k, p in sketch.items()]
        out += ["", "[[force]]", 'name = "F_PR"', f"link = {self.out_link}", f'at = "{self.output}"',
                f"magnitude = {self.force_N:g}", f'acts = "{self.acts}"']
        if self.gears is not None:
            motor, *stages = self.gears
            out += ["", "[gears]", f"motor_rpm = {motor:g}"]
            for stage in stages:
                out += ["", "[[gears.stage]]"]
                if stage[0] == "pair":
                    out += [f"z = [{stage[1][0]}, {stage[1][1]}]", f'mesh = "{stage[2]}"']
                else:
                    meshes = ", ".join(f'{{ z = [{z[0]}, {z[1]}], mesh = "{k}" }}' for z, k in stage[1])
                    out += ['kind = "planetary"', f"meshes = [{meshes}]"]
        return "\n".join(out) + "\n"

    # --- solving -----------------------------------------------------------------
    def load(self, sketch=None) -> mmt_plans.Mechanism:
        return mmt_plans.loads(self.toml(sketch), self.path)

    def _pin(self) -> str:
        return next(p for p in self.links[0].points if p not in self.frame)

    def _exact_sketch(self, hints: dict) -> dict | None:
        mech = self.load(hints)
        pivot = np.array(next(iter(self.frame.values())), dtype=float)
        A = np.array(hints[self._pin()], dtype=float) - pivot
        phi = math.degrees(math.atan2(A[1], A[0]))
        sw = mmt_plans.sweep(mech, np.array([phi]))
        out = {}
        for link in self.links:
            for p in link.points:
                if p in self.frame or p in out:
                    continue
                xy = sw.points[p][0] * 1000.0
                if not np.all(np.isfinite(xy)):
                    return None
                out[p] = (float(xy[0]), float(xy[1]))
        return out

    def _quality(self, sketch: dict) -> tuple[bool, float]:
        sw = mmt_plans.sweep(self.load(sketch), SWEEP)
        if not sw.ok.all():
            return False, float(np.mean(sw.ok))
        return True, min(float(np.degrees(np.arcsin(np.clip(p.sin_angle.min(), 0.0, 1.0))))
                         for p in sw.plans)

    def finish(self) -> "Task":
        best = None
        for hints in self.hints:
            sketch = self._exact_sketch(hints)
            if sketch is None:
                continue
            ok, q = self._quality(sketch)
            key = (ok, round(q))
            if best is None or key > best[0]:
                best = (key, sketch, q)
        if best is None:  # no rough sketch assembles at its own crank angle
            self.ok, self.sketch = False, dict(self.hints[0])
            self.formula = analyse_structure(self.load()).formula
            return self
        (self.ok, _), self.sketch, q = best
        mech = self.load()
        self.formula = analyse_structure(mech).formula
        if self.ok:
            self.gamma_min = q
            sw = mmt_plans.sweep(mech, SWEEP)
            self.working_direction = self.axis if self.fixed_direction else self._slow(sw)
            self.working_span = self._span(sw, self.working_direction)
        return self

    def _span(self, sw, wd) -> float:
        """Crank angle (deg, ccw) from the extreme where the output is least along
        wd to the one where it is greatest: the working stroke for wd."""
        s = sw.points[self.output] @ np.array(wd, dtype=float)
        return float((SWEEP[int(np.argmax(s))] - SWEEP[int(np.argmin(s))]) % 360.0)

    def _slow(self, sw) -> tuple[float, float]:
        if self._span(sw, self.axis) >= 179.5:  # ties (central slider-cranks) work along +axis
            return self.axis
        return (0.0 - self.axis[0], 0.0 - self.axis[1])

    def write(self) -> Path:
        path = HERE / self.path
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(self.toml(), encoding="utf-8")
        return path


# --- geometry -------------------------------------------------------------------------

def coupler_for(d: float, r: float, rho: float) -> float:
    """The coupler length that makes a crank-rocker's transmission angle swing
    symmetrically about 90° (γ_min + γ_max = 180°): l² + ρ² = d² + r²."""
    return math.sqrt(d * d + r * r - rho * rho)


def frame_for(r: float, l: float, rho: float) -> float:
    """The frame length O1O2 with the same property, the links given."""
    return math.sqrt(l * l + rho * rho - r * r)


def polar(p, length: float, deg: float) -> tuple[float, float]:
    return (p[0] + length * math.cos(math.radians(deg)), p[1] + length * math.sin(math.radians(deg)))


def rocker_angles(r: float, l: float, rho: float, O2, upper: bool = True) -> np.ndarray:
    """Rocker angles (deg) over a turn; `upper`: B on the left of A→O2."""
    phi = np.radians(SWEEP)
    A = r * np.exp(1j * phi)
    O = complex(*O2)
    dv = O - A
    dd = np.abs(dv)
    cosg = (dd ** 2 + l ** 2 - rho ** 2) / (2 * dd * l)
    ang = np.angle(dv) + (1 if upper else -1) * np.arccos(np.clip(cosg, -1.0, 1.0))
    B = A + l * np.exp(1j * ang)
    return np.degrees(np.angle(B - O))


def r5(x: float) -> float:
    """An accepted dimension, rounded to 5 mm as a drawing gives it."""
    return 5.0 * round(x / 5.0)


def crank(r: float, m: float = 0.0) -> Link:
    return Link(1, {"O1": (0, 0), "A": (r, 0)}, m, note="crank")


def bar(id_: int, names: str, lengths: list[float], m: float = 0.0, J: float | None = None,
        note: str = "") -> Link:
    """A straight link: the first point at 0, the others along +x at the given
    distances (the first two points give l of J = k·m·l² and the default centre of mass)."""
    pts = {names[0]: (0.0, 0.0)}
    for n, d in zip(names[1:], lengths):
        pts[n] = (float(d), 0.0)
    return Link(id_, pts, m, J, note)


def block(id_: int, name: str, m: float = 0.0, note: str = "") -> Link:
    return Link(id_, {name: (0.0, 0.0)}, m, note=note)


# ======================================================================================
# Seed 003: tasks 1-11, five variants (masses kg, lengths mm, F_PR kN, n1 rpm)
# ======================================================================================

S3 = {
    1: dict(a=[700, 750, 800, 850, 900], b=[70, 80, 90, 100, 110], O1A=[200, 210, 250, 270, 300],
            O2B=[350, 400, 450, 500, 550], AB=[800, 850, 850, 900, 1000], BC=[850, 1000, 1100, 1200, 1300],
            n=[100, 95, 90, 80, 70], m1=[15, 20, 24, 28, 32], m2=[50, 60, 65, 70, 80], m3=[30, 40, 50, 60, 70],
            m4=[80, 100, 110, 120, 130], m5=[80, 90, 100, 110, 120], F=[9.0, 9.5, 9.7, 9.8, 9.4]),
    2: dict(a=[500, 550, 570, 600, 520], O1A=[200, 25, 220, 280, 230], AC=[750, 780, 800, 950, 920],
            BD=[650, 680, 700, 820, 750], n=[95, 85, 75, 65, 70], m1=[18, 19, 21, 24, 20],
            m2=[70, 72, 60, 55, 65], m3=[18, 20, 30, 35, 28], m4=[35, 45, 40, 60, 45], m5=[32, 40, 34, 20, 24],
            F=[5.2, 6.2, 5.5, 6.0, 5.4]),
    3: dict(O1A=[200, 180, 160, 150, 140], AB=[500, 480, 450, 440, 400], n=[120, 130, 140, 150, 160],
            m1=[9, 10, 11, 12, 13], m2=[40, 42, 38, 44, 45], m3=[10, 9, 8, 11, 12], F=[6.0, 5.5, 4.8, 6.2, 5.2]),
    4: dict(a=[300, 400, 450, 550, 600], b=[400, 500, 600, 700, 750], O1A=[200, 220, 250, 270, 300],
            AB=[500, 600, 700, 800, 900], O2C=[450, 550, 650, 700, 850], CD=[600, 700, 800, 900, 1000],
            n=[95, 85, 110, 75, 80], m1=[25, 27, 30, 35, 40], m2=[60, 63, 70, 68, 75], m3=[55, 60, 70, 67, 75],
            m4=[40, 45, 50, 55, 60], m5=[100, 90, 105, 110, 120], F=[9.0, 9.5, 9.1, 9.8, 9.9]),
    5: dict(a=[600, 650, 700, 750, 800], b=[400, 450, 500, 550, 600], O1A=[150, 170, 190, 220, 250],
            O2B=[300, 320, 350, 370, 400], BC=[450, 500, 550, 600, 650], n=[100, 110, 90, 95, 80],
            m1=[11.0, 10.5, 10.0, 8.0, 12.0], m2=[40, 45, 50, 50, 60], m3=[20, 22, 24, 20, 30],
            m4=[35, 40, 45, 50, 55], m5=[60, 70, 80, 90, 100], F=[8.6, 9.2, 9.6, 9.2, 9.6]),
    6: dict(c=[200, 220, 240, 260, 280], O1A=[140, 160, 180, 230, 250], AB=[380, 400, 420, 450, 480],
            CD=[400, 420, 460, 500, 520], O2B=[600, 620, 680, 700, 680], n=[70, 80, 90, 100, 110],
            m1=[12, 14, 16, 18, 20], m2=[30, 35, 40, 45, 50], m3=[65, 70, 70, 75, 75], m4=[35, 40, 45, 45, 50],
            m5=[20, 24, 28, 30, 35], F=[6.0, 6.2, 6.4, 6.6, 6.8]),
    7: dict(b=[200, 220, 240, 260, 300], c=[150, 160, 180, 200, 220], O1A=[180, 200, 160, 190, 210],
            AB=[600, 650, 700, 680, 720], O2B=[500, 520, 540, 580, 620], BD=[450, 480, 500, 500, 480],
            n=[60, 50, 55, 60, 55], m1=[8, 10, 12, 14, 16], m2=[42, 44, 44, 42, 40], m3=[30, 32, 32, 36, 36],
            m4=[37, 30, 35, 38, 38], m5=[20, 25, 30, 35, 40], F=[6.5, 6.7, 6.9, 7.1, 7.3]),
    8: dict(b=[300, 280, 320, 340, 260], O1A=[180, 190, 200, 210, 220], AC=[550, 580, 600, 520, 550],
            O2C=[600, 620, 640, 680, 700], BD=[600, 580, 620, 610, 600], c=[450, 480, 500, 500, 550],
            n=[60, 65, 70, 75, 80], m1=[20, 22, 25, 27, 30], m2=[45, 47, 50, 48, 52], m3=[60, 62, 55, 58, 60],
            m4=[50, 52, 54, 56, 58], m5=[15, 18, 21, 25, 30], F=[6.4, 6.6, 6.8, 7.0, 7.2]),
    9: dict(a=[900, 950, 1000, 1050, 1100], O1A=[140, 150, 180, 200, 220], AB=[550, 600, 750, 800, 900],
            BC=[500, 600, 750, 750, 800], n=[100, 90, 80, 70, 60], m1=[10, 12, 14, 16, 18],
            m2=[30, 35, 40, 45, 50], m3=[15, 18, 21, 24, 27], m4=[40, 50, 60, 60, 60], m5=[12, 16, 20, 24, 28],
            F=[6.0, 6.5, 7.0, 7.5, 8.0]),
    10: dict(a=[440, 500, 600, 700, 800], b=[700, 750, 800, 900, 1000], O1A=[150, 180, 210, 240, 270],
             AB=[780, 870, 960, 1080, 1140], O2C=[400, 450, 550, 650, 750], CD=[300, 400, 45, 500, 500],
             n=[100, 110, 110, 90, 80], m1=[20, 25, 28, 32, 35], m2=[80, 100, 120, 140, 160],
             m3=[40, 50, 55, 60, 65], m4=[35, 38, 42, 45, 50], m5=[10, 15, 20, 25, 28], F=[4.0, 4.5, 5.0, 5.5, 6.0]),
    11: dict(a=[160, 180, 200, 230, 250], b=[200, 220, 240, 280, 320], c=[500, 550, 600, 650, 700],
             O1A=[100, 120, 140, 160, 180], AB=[300, 350, 400, 450, 500], O2A=[200, 220, 240, 260, 280],
             O2C=[400, 44, 480, 520, 560], n=[110, 100, 90, 80, 70], m1=[10, 12, 14, 16, 18],
             m2=[24, 28, 32, 36, 40], m3=[28, 31, 34, 37, 40], m4=[20, 20, 20, 20, 20], m5=[0, 0, 0, 0, 0],
             F=[6.0, 6.6, 7.2, 7.8, 8.4]),
}

# seed 003 misprints: (task, variant, column) -> (value used, reason)
S3_FIX = {
    (2, 2, "O1A"): (250, "the table gives L_O1A = 25 mm, one tenth of its neighbours (200, 220, 280, "
                         "230): a dropped zero. With 25 mm the slider D would move 40 mm for a 780 mm "
                         "coupler; 250 mm is used."),
    (10, 3, "CD"): (450, "the table gives L_CD = 45 mm (neighbours 300, 400, 500, 500): a dropped zero. "
                         "The rocker end moves 50..180 mm below the slider's axis, which a 45 mm rod "
                         "cannot reach: the mechanism cannot assemble; 450 mm is used."),
    (11, 2, "O2C"): (440, "the table gives L_O2C = 44 mm: a dropped zero. In every other variant "
                          "L_O2C = 2 L_O2A (400/200, 480/240, 520/260, 560/280) and c = 1.25 L_O2C; "
                          "here L_O2A = 220 and c = 550 give 440 mm, and with 44 mm the coupler's "
                          "hinge B (220 mm from O2) would lie beyond the rocker's end C."),
}


def s3(task: int, v: int) -> tuple[dict, list[str]]:
    """Column v (1-based) of a seed 003 table, with the misprints corrected."""
    col = {k: vals[v - 1] for k, vals in S3[task].items()}
    notes = []
    for (t, var, key), (value, why) in S3_FIX.items():
        if t == task and var == v:
            col[key] = value
            notes.append(why)
    return col, notes


def s3_header(task: int, v: int, scheme: str, given: str, accepted: str = "") -> list[str]:
    lines = [f"Seed 003 (Dovbush et al., course-project guide, 2018), task {task}, variant {v}.",
             f"Scheme (inferred; the figure is lost): {scheme}",
             f"Table: {given}"]
    if accepted:
        lines.append(f"To accept / not in the table: {accepted}")
    lines.append("Masses: m_i on link i; F_PR on the output slider during the working stroke.")
    return lines


def t1(v: int) -> Task:
    c, fix = s3(1, v)
    r, l, rho, bc = c["O1A"], c["AB"], c["O2B"], c["BC"]
    O2 = (c["a"], -c["b"])
    return Task(
        path=f"seed003/task01_v{v}.toml",
        title=f"Seed 003 task 1 v{v}: six-link press (crank, rocker, rod, slider)",
        title_uk=uk_title("003", 1, v, "шестиланковий механізм преса (кривошип, коромисло, шатун, повзун)"),
        header=s3_header(1, v, "crank O1A (1), coupler AB (2), rocker O2B (3), rod BC (4) hinged "
                         "at B, slider C (5) on the axis x-x through O1.",
                         f"a = {c['a']} (O2 right of O1), b = {c['b']} (O2 below x-x), "
                         f"L_O1A = {r}, L_AB = {l}, L_O2B = {rho}, L_BC = {bc}, n1 = {c['n']} rpm.",
                         "the slider's axis passes through O1. Position 0: the extreme left "
                         "position of C (section V)."),
        frame={"O1": (0, 0), "O2": O2},
        links=[crank(r, c["m1"]), bar(2, "AB", [l], c["m2"], note="coupler"),
               bar(3, ["O2", "B"], [rho], c["m3"], note="rocker"),
               bar(4, "BC", [bc], c["m4"], note="rod"), block(5, "C", c["m5"], "slider")],
        sliders=[Slider(5, (0, 0), 0, note="C on x-x through O1")],
        output="C", out_link=5, force_N=c["F"] * 1000, axis=(1.0, 0.0), fixed_direction=True,
        hints=[{"A": (0, r), "B": polar(O2, rho, 80), "C": (O2[0] + rho + bc, 0)}],
        rpm=c["n"], corrections=fix)


def t2(v: int) -> Task:
    c, fix = s3(2, v)
    r, ac, bd, a = c["O1A"], c["AC"], c["BD"], c["a"]
    return Task(
        path=f"seed003/task02_v{v}.toml",
        title=f"Seed 003 task 2 v{v}: crank, coupler with two sliders",
        title_uk=uk_title("003", 2, v, "кривошип, шатун із двома повзунами"),
        header=s3_header(2, v, "crank O1A (1), coupler AC (2) with B at its middle, slider C (3) on "
                         "the axis x-x through O1, rod BD (4), slider D (5) on a vertical guide "
                         "at distance a right of O1.",
                         f"a = {a}, L_O1A = {c['O1A'] if not fix else '25 (misprint)'}, "
                         f"L_AC = {ac}, L_BD = {bd}, n1 = {c['n']} rpm.",
                         f"B at the middle of AC (AB = {num(ac / 2)}); C's axis through O1."),
        frame={"O1": (0, 0)},
        links=[crank(r, c["m1"]), bar(2, "ACB", [ac, ac / 2], c["m2"], note="coupler, B at its middle"),
               block(3, "C", c["m3"], "slider"), bar(4, "BD", [bd], c["m4"], note="rod"),
               block(5, "D", c["m5"], "slider")],
        sliders=[Slider(3, (0, 0), 0, note="C on x-x through O1"),
                 Slider(5, (a, 0), 90, note="D on the vertical guide x = a")],
        output="D", out_link=5, force_N=c["F"] * 1000, axis=(0.0, 1.0),
        hints=[{"A": (0, r), "C": (ac, 0), "B": (ac / 2, r / 2), "D": (a, bd)},
               {"A": (0, r), "C": (ac, 0), "B": (ac / 2, r / 2), "D": (a, -bd)}],
        rpm=c["n"], corrections=fix)


def t3(v: int) -> Task:
    c, fix = s3(3, v)
    r, l = c["O1A"], c["AB"]
    return Task(
        path=f"seed003/task03_v{v}.toml",
        title=f"Seed 003 task 3 v{v}: two slider-cranks on one crank (opposed)",
        title_uk=uk_title("003", 3, v, "два кривошипно-повзунні механізми на одному кривошипі (опозитні)"),
        header=s3_header(3, v, "crank O1A (1) drives two equal rods from its pin A: rod AB (2) with "
                         "slider B (3) and rod AC (4) with slider C (5), both sliders on the axis "
                         "x-x through O1, B to the right, C to the left (m2 = m4, m3 = m5).",
                         f"L_O1A = {r}, L_AB = L_AC = {l}, n1 = {c['n']} rpm, m2 = m4 = {c['m2']}, "
                         f"m3 = m5 = {c['m3']}.",
                         "the axes of both sliders pass through O1 (central); F_PR acts on B."),
        frame={"O1": (0, 0)},
        links=[crank(r, c["m1"]), bar(2, "AB", [l], c["m2"], note="rod"), block(3, "B", c["m3"], "slider"),
               bar(4, "AC", [l], c["m2"], note="second rod"), block(5, "C", c["m3"], "second slider")],
        sliders=[Slider(3, (0, 0), 0, note="B on x-x"), Slider(5, (0, 0), 0, note="C on x-x")],
        output="B", out_link=3, force_N=c["F"] * 1000, axis=(1.0, 0.0),
        hints=[{"A": (0, r), "B": (l, 0), "C": (-l, 0)}],
        rpm=c["n"], corrections=fix)


def rocker_on_axis(task: int, v: int) -> Task:
    """Tasks 4 and 10: the coupler and the rod share the rocker's end."""
    c, fix = s3(task, v)
    r, l, rho, cd = c["O1A"], c["AB"], c["O2C"], c["CD"]
    O2 = (c["b"], -c["a"])
    return Task(
        path=f"seed003/task{task:02d}_v{v}.toml",
        title=f"Seed 003 task {task} v{v}: crank-rocker with a slider on the axis through O1",
        title_uk=uk_title("003", task, v, "кривошипно-коромисловий механізм із повзуном на осі, "
                                          "що проходить через O1"),
        header=s3_header(task, v, "crank O1A (1), coupler AB (2), rocker O2C (3) whose end C is the "
                         "coupler's hinge B (C = B), rod CD (4, written BD), slider D (5) on the "
                         "axis x-x through O1.",
                         f"a = {c['a']} (O2 below x-x), b = {c['b']} (O2 right of O1), L_O1A = {r}, "
                         f"L_AB = {l}, L_O2C = {rho}, L_CD = "
                         f"{S3[task]['CD'][v - 1]}{' (misprint)' if fix else ''}, n1 = {c['n']} rpm.",
                         "no L_O2B: the coupler is hinged at the rocker's end (B at the middle would "
                         "leave variant 4 (task 4) and 5 (task 10) unable to turn)."),
        frame={"O1": (0, 0), "O2": O2},
        links=[crank(r, c["m1"]), bar(2, "AB", [l], c["m2"], note="coupler"),
               bar(3, ["O2", "B"], [rho], c["m3"], note="rocker O2C, its end C = B"),
               bar(4, "BD", [cd], c["m4"], note="rod CD"), block(5, "D", c["m5"], "slider")],
        sliders=[Slider(5, (0, 0), 0, note="D on x-x through O1")],
        output="D", out_link=5, force_N=c["F"] * 1000, axis=(1.0, 0.0),
        hints=[{"A": (0, r), "B": polar(O2, rho, 80), "D": (O2[0] + cd, 0)}],
        rpm=c["n"], corrections=fix)


def t5(v: int) -> Task:
    c, fix = s3(5, v)
    r, rho, bc = c["O1A"], c["O2B"], c["BC"]
    O2 = (c["a"], -c["b"])
    l = r5(coupler_for(math.hypot(*O2), r, rho))
    return Task(
        path=f"seed003/task05_v{v}.toml",
        title=f"Seed 003 task 5 v{v}: six-link press with an accepted coupler",
        title_uk=uk_title("003", 5, v, "шестиланковий механізм преса з прийнятою довжиною шатуна"),
        header=s3_header(5, v, "crank O1A (1), coupler AB (2), rocker O2B (3), rod BC (4) hinged at "
                         "B, slider C (5) on the axis x-x through O1 (the scheme of task 1).",
                         f"a = {c['a']} (O2 right of O1), b = {c['b']} (O2 below x-x), L_O1A = {r}, "
                         f"L_O2B = {rho}, L_BC = {bc}, n1 = {c['n']} rpm.",
                         f"L_AB = {num(l)} (from l^2 + L_O2B^2 = O1O2^2 + L_O1A^2: the transmission "
                         "angle swings symmetrically about 90 deg); the slider's axis through O1."),
        frame={"O1": (0, 0), "O2": O2},
        links=[crank(r, c["m1"]), bar(2, "AB", [l], c["m2"], note="coupler (accepted length)"),
               bar(3, ["O2", "B"], [rho], c["m3"], note="rocker"),
               bar(4, "BC", [bc], c["m4"], note="rod"), block(5, "C", c["m5"], "slider")],
        sliders=[Slider(5, (0, 0), 0, note="C on x-x through O1")],
        output="C", out_link=5, force_N=c["F"] * 1000, axis=(1.0, 0.0),
        hints=[{"A": (0, r), "B": polar(O2, rho, 80), "C": (O2[0] + bc, 0)}],
        rpm=c["n"], corrections=fix)


def t6(v: int) -> Task:
    c, fix = s3(6, v)
    r, l, rho, cd, cc = c["O1A"], c["AB"], c["O2B"], c["CD"], c["c"]
    d = frame_for(r, l, rho)
    th = rocker_angles(r, l, rho, (d, 0.0))
    turn = 90.0 - (th.min() + th.max()) / 2.0  # turn the frame so the rocker swings about the vertical
    O2 = (r5(d * math.cos(math.radians(turn))), r5(d * math.sin(math.radians(turn))))
    C0 = polar(O2, rho / 2, 90)
    return Task(
        path=f"seed003/task06_v{v}.toml",
        title=f"Seed 003 task 6 v{v}: crank-rocker, rod from the rocker's middle, slider",
        title_uk=uk_title("003", 6, v, "кривошипно-коромисловий механізм, шатун від середини коромисла, повзун"),
        header=s3_header(6, v, "crank O1A (1), coupler AB (2), rocker O2B (3) with C at its middle, "
                         "rod CD (4), slider D (5) on a horizontal guide c above O2.",
                         f"c = {cc}, L_O1A = {r}, L_AB = {l}, L_O2B = {rho}, L_CD = {cd}, "
                         f"n1 = {c['n']} rpm.",
                         f"a = {num(O2[0])}, b = {num(-O2[1])} (O2 right of and below O1): O1O2 from "
                         "l^2 + rho^2 = O1O2^2 + r^2 (transmission angle symmetric about 90 deg), "
                         "turned so that the rocker swings symmetrically about the vertical; "
                         f"C at the middle of O2B (O2C = {num(rho / 2)})."),
        frame={"O1": (0, 0), "O2": O2},
        links=[crank(r, c["m1"]), bar(2, "AB", [l], c["m2"], note="coupler"),
               bar(3, ["O2", "B", "C"], [rho, rho / 2], c["m3"], note="rocker, C at its middle"),
               bar(4, "CD", [cd], c["m4"], note="rod"), block(5, "D", c["m5"], "slider")],
        sliders=[Slider(5, (0, O2[1] + cc), 0, note="D on the horizontal c above O2")],
        output="D", out_link=5, force_N=c["F"] * 1000, axis=(1.0, 0.0),
        hints=[{"A": (0, r), "B": polar(O2, rho, 90), "C": C0, "D": (C0[0] + cd, O2[1] + cc)},
               {"A": (0, r), "B": polar(O2, rho, 90), "C": C0, "D": (C0[0] - cd, O2[1] + cc)}],
        rpm=c["n"], corrections=fix)


def t7(v: int) -> Task:
    c, fix = s3(7, v)
    r, l, rho, bd, b, cc = c["O1A"], c["AB"], c["O2B"], c["BD"], c["b"], c["c"]
    a = r5(math.sqrt(frame_for(r, l, rho) ** 2 - b * b))
    O2 = (a, -b)
    B0 = polar(O2, rho, 110)
    return Task(
        path=f"seed003/task07_v{v}.toml",
        title=f"Seed 003 task 7 v{v}: crank-rocker and slider, accepted frame",
        title_uk=uk_title("003", 7, v, "кривошипно-коромисловий механізм і повзун, прийнятий розмір стояка"),
        header=s3_header(7, v, "crank O1A (1), coupler AB (2), rocker O2B (3), rod BD (4) hinged at "
                         "B, slider D (5) on a horizontal guide c above O1.",
                         f"b = {b} (O2 below O1), c = {cc}, L_O1A = {r}, L_AB = {l}, L_O2B = {rho}, "
                         f"L_BD = {bd}, n1 = {c['n']} rpm.",
                         f"a = {num(a)} (O2 right of O1): O1O2 from l^2 + rho^2 = O1O2^2 + r^2, "
                         "the transmission angle symmetric about 90 deg."),
        frame={"O1": (0, 0), "O2": O2},
        links=[crank(r, c["m1"]), bar(2, "AB", [l], c["m2"], note="coupler"),
               bar(3, ["O2", "B"], [rho], c["m3"], note="rocker"),
               bar(4, "BD", [bd], c["m4"], note="rod"), block(5, "D", c["m5"], "slider")],
        sliders=[Slider(5, (0, cc), 0, note="D on the horizontal c above O1")],
        output="D", out_link=5, force_N=c["F"] * 1000, axis=(1.0, 0.0),
        hints=[{"A": (0, r), "B": B0, "D": (B0[0] + bd, cc)}],
        rpm=c["n"], corrections=fix)


def t8(v: int) -> Task:
    c, fix = s3(8, v)
    r, l, rho, bd, b, cc = c["O1A"], c["AC"], c["O2C"], c["BD"], c["b"], c["c"]
    a = r5(math.sqrt(frame_for(r, l, rho) ** 2 - b * b))
    O2 = (a, -b)
    C0 = polar(O2, rho, 110)
    B0 = ((0 + C0[0]) / 2, (r + C0[1]) / 2)
    return Task(
        path=f"seed003/task08_v{v}.toml",
        title=f"Seed 003 task 8 v{v}: crank-rocker, rod from the coupler's middle, slider",
        title_uk=uk_title("003", 8, v, "кривошипно-коромисловий механізм, шатун BD від середини "
                                       "шатуна AC, повзун"),
        header=s3_header(8, v, "crank O1A (1), coupler AC (2) with B at its middle, rocker O2C (3), "
                         "rod BD (4), slider D (5) on a vertical guide c right of O1.",
                         f"b = {b} (O2 below O1), c = {cc}, L_O1A = {r}, L_AC = {l}, L_O2C = {rho}, "
                         f"L_BD = {bd}, n1 = {c['n']} rpm.",
                         f"a = {num(a)} (O2 right of O1): O1O2 from l^2 + rho^2 = O1O2^2 + r^2; "
                         f"B at the middle of AC (AB = {num(l / 2)}), as in task 2."),
        frame={"O1": (0, 0), "O2": O2},
        links=[crank(r, c["m1"]), bar(2, "ACB", [l, l / 2], c["m2"], note="coupler, B at its middle"),
               bar(3, ["O2", "C"], [rho], c["m3"], note="rocker"),
               bar(4, "BD", [bd], c["m4"], note="rod"), block(5, "D", c["m5"], "slider")],
        sliders=[Slider(5, (cc, 0), 90, note="D on the vertical x = c")],
        output="D", out_link=5, force_N=c["F"] * 1000, axis=(0.0, 1.0),
        hints=[{"A": (0, r), "C": C0, "B": B0, "D": (cc, B0[1] + bd)},
               {"A": (0, r), "C": C0, "B": B0, "D": (cc, B0[1] - bd)}],
        rpm=c["n"], corrections=fix)


def t9(v: int) -> Task:
    c, fix = s3(9, v)
    r, l, bc, a = c["O1A"], c["AB"], c["BC"], c["a"]
    return Task(
        path=f"seed003/task09_v{v}.toml",
        title=f"Seed 003 task 9 v{v}: slider-crank driving two symmetric toggle sliders",
        title_uk=uk_title("003", 9, v, "кривошипно-повзунний механізм, що приводить два симетричні "
                                       "повзуни колінно-важільного механізму"),
        header=s3_header(9, v, "crank O1A (1), rod AB (2), slider B (3) on the axis x-x through O1; "
                         "from B two equal rods BC (4) and BD (6) drive sliders C (5) and D (7) on "
                         "one vertical guide at distance a right of O1, C above x-x, D below "
                         "(m4 = m6, m5 = m7).",
                         f"a = {a}, L_O1A = {r}, L_AB = {l}, L_BC = L_BD = {bc}, n1 = {c['n']} rpm.",
                         "B's axis through O1; F_PR acts on C (one force is given)."),
        frame={"O1": (0, 0)},
        links=[crank(r, c["m1"]), bar(2, "AB", [l], c["m2"], note="rod"), block(3, "B", c["m3"], "slider"),
               bar(4, "BC", [bc], c["m4"], note="upper rod"), block(5, "C", c["m5"], "upper slider"),
               bar(6, "BD", [bc], c["m4"], note="lower rod"), block(7, "D", c["m5"], "lower slider")],
        sliders=[Slider(3, (0, 0), 0, note="B on x-x"), Slider(5, (a, 0), 90, note="C on x = a"),
                 Slider(7, (a, 0), 90, note="D on x = a")],
        output="C", out_link=5, force_N=c["F"] * 1000, axis=(0.0, 1.0),
        hints=[{"A": (0, r), "B": (l, 0), "C": (a, bc / 2), "D": (a, -bc / 2)}],
        rpm=c["n"], corrections=fix)


def t11(v: int) -> Task:
    c, fix = s3(11, v)
    r, l, rho, L, a, b, cc = c["O1A"], c["AB"], c["O2A"], c["O2C"], c["a"], c["b"], c["c"]
    O2 = (0.0, -(a + b))
    C0 = polar(O2, L, 30)
    return Task(
        path=f"seed003/task11_v{v}.toml",
        title=f"Seed 003 task 11 v{v}: crank-rocker driving a slotted crosshead",
        title_uk=uk_title("003", 11, v, "кривошипно-коромисловий механізм, що приводить поступальну кулісу"),
        header=s3_header(11, v, "crank O1A (1), coupler AB (2), rocker O2C (3) with the coupler's hinge "
                         "B at its middle, a block C (5, massless) on the rocker's end slides in the "
                         "horizontal slot of the crosshead (4), which slides on a vertical guide at "
                         "distance c right of the line O1O2 (an RPP group).",
                         f"a = {a}, b = {b}, c = {cc}, L_O1A = {r}, L_AB = {l}, "
                         f"L_O2A = {rho} (read as L_O2B, the rocker arm of the coupler), "
                         f"L_O2C = {S3[11]['O2C'][v - 1]}{' (misprint)' if fix else ''}, n1 = {c['n']} rpm.",
                         "O2 lies a + b below O1 on the vertical through O1 (a and b read as two "
                         "stacked vertical distances); the crosshead's point D is on its guide. "
                         "The reading O2 = (a, b) gives a four-bar with transmission angles down "
                         "to 8 deg."),
        frame={"O1": (0, 0), "O2": O2},
        links=[crank(r, c["m1"]), bar(2, "AB", [l], c["m2"], note="coupler"),
               bar(3, ["O2", "C", "B"], [L, rho], c["m3"], note="rocker, B at its middle"),
               block(4, "D", c["m4"], "crosshead on the vertical guide x = c"),
               block(5, "C", c["m5"], "block in the crosshead's slot")],
        sliders=[Slider(4, (cc, 0), 90, note="crosshead on x = c"),
                 Slider(5, (0, 0), 0, on=4, note="block C in the horizontal slot through D")],
        output="D", out_link=4, force_N=c["F"] * 1000, axis=(0.0, 1.0),
        hints=[{"A": (0, r), "B": polar(O2, rho, 30), "C": C0, "D": (cc, C0[1])}],
        rpm=c["n"], corrections=fix)


SEED003: dict[int, Callable[[int], Task]] = {
    1: t1, 2: t2, 3: t3, 4: lambda v: rocker_on_axis(4, v), 5: t5, 6: t6, 7: t7, 8: t8, 9: t9,
    10: lambda v: rocker_on_axis(10, v), 11: t11,
}


# ======================================================================================
# Seed 002: tasks 1-6, ten variants 0..9 (lengths mm, masses kg, I_S kg·m², F_KO N)
# ======================================================================================

N_MOTOR = [1450, 1460, 1455, 1475, 1450, 1455, 1460, 1465, 1470, 1450]
S2 = {
    1: dict(AO1=[65, 60, 63, 63, 50, 58, 60, 65, 40, 45], AB=[170, 165, 168, 160, 156, 148, 150, 150, 165, 150],
            CO2=[126, 114, 116, 125, 130, 122, 128, 130, 130, 135], BO2=[90, 80, 80, 90, 95, 80, 75, 78, 80, 80],
            CD=[90, 82, 80, 100, 120, 95, 90, 100, 120, 120], x=[168, 160, 146, 167, 160, 162, 165, 140, 145, 140],
            y=[144, 140, 126, 143, 140, 146, 148, 140, 136, 130],
            phi1=[210, 225, 210, 240, 225, 120, 150, 135, 120, 225],
            m2=[48, 50, 48, 52, 54, 50, 52, 48, 54, 52], m5=[100, 106, 102, 100, 110, 108, 100, 98, 106, 102],
            IS2=[0.03, 0.03, 0.028, 0.035, 0.03, 0.032, 0.03, 0.028, 0.036, 0.03],
            F=[860, 900, 840, 900, 1000, 920, 860, 800, 1200, 860], n=N_MOTOR,
            z1=[20, 22, 20, 21, 18, 20, 25, 24, 22, 26], z2=[80, 96, 100, 84, 96, 90, 125, 96, 100, 104],
            z3=[30, 20, 35, 32, 26, 28, 37, 35, 28, 36], z4=[32, 24, 37, 30, 30, 26, 35, 33, 30, 32],
            z4_=[30, 26, 33, 30, 28, 32, 33, 30, 32, 28], z5=[48, 52, 66, 56, 52, 64, 66, 62, 54, 58]),
    2: dict(AO1=[90, 80, 72, 90, 62, 80, 75, 78, 80, 90], AB=[170, 165, 168, 176, 166, 158, 160, 150, 175, 150],
            CO2=[122, 128, 130, 130, 135, 126, 114, 116, 125, 130],
            BO2=[180, 155, 186, 167, 146, 160, 162, 154, 165, 170],
            CD=[290, 282, 280, 300, 320, 295, 290, 300, 220, 220], x=[268, 260, 246, 267, 260, 262, 265, 240, 245, 240],
            phi1=[120, 300, 150, 240, 225, 120, 150, 135, 120, 180],
            m4=[78, 80, 78, 82, 84, 80, 82, 78, 84, 82], m5=[120, 116, 112, 108, 130, 118, 104, 108, 106, 102],
            IS4=[0.08, 0.08, 0.078, 0.085, 0.08, 0.082, 0.08, 0.078, 0.086, 0.08],
            F=[800, 600, 800, 900, 700, 900, 800, 800, 1000, 800],
            n=[1455, 1460, 1465, 1470, 1450, 1450, 1460, 1455, 1475, 1450],
            z1=[20, 22, 20, 21, 18, 20, 25, 24, 22, 26], z2=[80, 96, 100, 84, 96, 90, 125, 96, 100, 104],
            z2_=[30, 26, 33, 30, 28, 32, 33, 30, 32, 28], z3=[30, 20, 35, 32, 26, 28, 37, 35, 28, 36],
            z4=[32, 24, 37, 30, 30, 26, 35, 33, 30, 32], z5=[48, 52, 66, 56, 52, 64, 66, 62, 54, 58]),
    3: dict(AO1=[73, 75, 85, 70, 72, 60, 76, 72, 75, 80], CO2=[240, 242, 250, 210, 230, 180, 248, 220, 240, 250],
            CD=[132, 135, 140, 128, 130, 120, 138, 132, 130, 140], x=[134, 130, 176, 131, 132, 125, 135, 130, 134, 150],
            x1=[420, 380, 428, 400, 400, 380, 426, 410, 420, 440], y=[92, 96, 98, 100, 91, 96, 96, 91, 94, 100],
            phi1=[300, 330, 270, 315, 270, 300, 315, 0, 30, 35],
            m3=[30, 40, 35, 45, 36, 30, 46, 38, 41, 34], m5=[80, 120, 96, 98, 84, 79, 102, 85, 94, 97],
            IS3=[0.023, 0.023, 0.028, 0.032, 0.031, 0.033, 0.031, 0.026, 0.026, 0.023],
            F=[1700, 1500, 2500, 1200, 2000, 1800, 1700, 1600, 2600, 2400], n=N_MOTOR,
            z1=[120, 122, 120, 121, 118, 120, 125, 124, 122, 126], z2=[80, 96, 100, 84, 96, 90, 125, 96, 100, 104],
            z2_=[20, 22, 20, 21, 18, 20, 25, 24, 22, 26], z3=[130, 120, 135, 132, 126, 128, 137, 135, 128, 136],
            z4=[32, 24, 37, 30, 30, 26, 35, 33, 30, 32], z5=[90, 125, 96, 100, 104, 64, 66, 96, 100, 84]),
    4: dict(AO1=[150, 200, 230, 130, 220, 180, 200, 150, 140, 135],
            AB=[750, 655, 680, 650, 560, 648, 650, 750, 665, 550],
            BO2=[500, 600, 600, 550, 450, 550, 655, 700, 580, 680], CB=[200, 250, 260, 220, 180, 250, 265, 300, 230, 245],
            CD=[450, 560, 580, 520, 560, 500, 620, 580, 600, 560],
            x=[900, 960, 1000, 920, 940, 900, 1000, 980, 920, 1000], y=[400, 500, 460, 550, 480, 520, 460, 520, 650, 565],
            phi1=[30, 45, 40, 35, 60, 55, 30, 120, 135, 145],
            m2=[7, 6, 8, 7.5, 6.5, 6.2, 7.8, 8, 6.6, 7.5], m5=[13, 12, 14, 13, 12, 11, 13, 12.5, 18, 20],
            IS2=[0.023, 0.023, 0.022, 0.025, 0.023, 0.032, 0.023, 0.022, 0.026, 0.023],
            F=[1200, 1400, 1000, 1300, 1450, 1250, 1355, 1400, 1250, 1150], n=N_MOTOR,
            z1=[32, 24, 37, 30, 30, 26, 35, 33, 30, 32], z2=[80, 96, 100, 84, 96, 90, 125, 96, 100, 104],
            z3=[230, 220, 235, 232, 226, 228, 237, 235, 228, 236], z4=[32, 24, 37, 30, 30, 26, 35, 33, 30, 32],
            z4_=[30, 26, 33, 30, 28, 32, 33, 30, 32, 28], z5=[148, 152, 166, 156, 152, 164, 166, 162, 154, 158]),
    5: dict(AO1=[30, 50, 40, 35, 34, 45, 46, 38, 48, 33], AB=[200, 265, 168, 260, 156, 248, 250, 250, 265, 250],
            BO2=[326, 114, 316, 325, 280, 322, 128, 330, 330, 135], BC=[90, 80, 80, 90, 95, 80, 75, 78, 80, 80],
            CD=[125, 130, 132, 128, 126, 132, 130, 125, 128, 134], x=[68, 60, 46, 67, 60, 62, 65, 40, 45, 40],
            x1=[180, 190, 125, 210, 186, 178, 184, 135, 152, 146], y=[170, 175, 130, 200, 172, 146, 169, 152, 189, 195],
            phi1=[210, 225, 210, 240, 225, 120, 150, 135, 120, 225],
            m3=[4.8, 5, 4.8, 5.2, 5.4, 5, 5.2, 4.8, 5.4, 5.2], m5=[10, 16, 12, 10, 11, 18, 10, 9.8, 16, 12],
            IS3=[0.1, 0.13, 0.12, 0.15, 0.2, 0.132, 0.13, 0.128, 0.136, 0.13],
            F=[1100, 1550, 1200, 900, 1000, 920, 1500, 1450, 1200, 1150], n=N_MOTOR,
            z1=[20, 22, 20, 21, 18, 20, 25, 24, 22, 26], z2=[80, 96, 100, 84, 96, 90, 125, 96, 100, 104],
            z3=[230, 220, 235, 232, 226, 228, 237, 235, 228, 236], z4=[32, 24, 37, 30, 30, 26, 35, 33, 30, 32],
            z4_=[30, 26, 33, 30, 28, 32, 33, 30, 32, 28], z5=[48, 52, 66, 56, 52, 64, 66, 62, 54, 58]),
    6: dict(AO1=[85, 80, 83, 83, 80, 78, 90, 85, 80, 85], BO2=[490, 480, 480, 490, 495, 480, 475, 478, 480, 480],
            y1=[290, 282, 280, 200, 220, 295, 290, 300, 220, 220], y=[180, 175, 176, 170, 180, 120, 165, 125, 145, 155],
            phi1=[30, 45, 50, 40, 125, 120, 50, 35, 20, 25],
            m3=[48, 50, 48, 52, 54, 50, 52, 48, 54, 52], m5=[200, 106, 202, 200, 210, 208, 200, 198, 206, 202],
            IS3=[0.02, 0.02, 0.018, 0.025, 0.02, 0.022, 0.02, 0.018, 0.026, 0.02],
            F=[5500, 6000, 6500, 5000, 7000, 5500, 6000, 6500, 7000, 5700], n=N_MOTOR,
            z1=[120, 122, 120, 121, 118, 120, 125, 124, 122, 126], z2=[48, 52, 66, 56, 52, 64, 66, 62, 54, 58],
            z2_=[30, 26, 33, 30, 28, 32, 33, 30, 32, 28], z3=[80, 96, 100, 84, 96, 90, 125, 96, 100, 104],
            z4=[22, 24, 27, 20, 30, 26, 25, 23, 30, 22], z5=[48, 52, 66, 56, 52, 64, 66, 62, 54, 58]),
}

RING = 100  # a central gear of this many teeth or more is read as a ring gear (internal mesh)


def mesh(z_drive: int, z_driven: int) -> str:
    return "internal" if max(z_drive, z_driven) >= RING else "external"


def train_pair_planetary(c: dict) -> list:
    """z1 z2 | z3 z4 z4' z5 (tasks 1, 4, 5): the worked example of seed 002 task 1 -
    a pair 1-2, then a planetary stage: central gear 3 (input, on gear 2's shaft),
    satellite block 4-4', fixed central gear 5, carrier H to the crank."""
    return [c["n"], ("pair", (c["z1"], c["z2"]), "external"),
            ("planetary", [((c["z3"], c["z4"]), mesh(c["z3"], c["z4"])),
                           ((c["z4_"], c["z5"]), mesh(c["z4_"], c["z5"]))])]


def train_planetary_pair(c: dict) -> list:
    """z1 z2 z2' z3 | z4 z5 (tasks 2, 3, 6): the prime marks a satellite block 2-2'
    as 4-4' does in the example - a planetary stage (central gear 1 from the motor,
    block 2-2', fixed central gear 3, carrier H), then a pair 4-5 to the crank."""
    return [c["n"], ("planetary", [((c["z1"], c["z2"]), mesh(c["z1"], c["z2"])),
                                   ((c["z2_"], c["z3"]), mesh(c["z2_"], c["z3"]))]),
            ("pair", (c["z4"], c["z5"]), "external")]


def s2_header(task: int, v: int, scheme: str, given: str, reading: str, train: str) -> list[str]:
    return [f"Seed 002 (Strilets, Pokhylchuk, self-study guide, 2025), task {task} (ЗАВДАННЯ №{task}), "
            f"variant {v}.",
            f"Scheme (inferred; the figure is lost): {scheme}",
            f"Table: {given}",
            f"Reading: {reading}",
            f"Gears: {train}",
            "Only the given masses and moments of inertia count (seed 002, Д1); the rest are 0.",
            "F_KO opposes the output's velocity in every position (acts = always): the task loads "
            "the position phi1, whichever stroke it falls in."]


TRAIN_A = ("pair z1-z2 external, then planetary 3-4-4'-5 with carrier H output (as the worked "
           "example); a central gear of 100+ teeth is a ring (internal mesh).")
TRAIN_B = ("planetary 1-2-2'-3 (satellite block 2-2', gear 3 fixed, carrier H output), then pair "
           "z4-z5 external; a central gear of 100+ teeth is a ring (internal mesh).")


def s2_rocker_task(task: int, v: int, c: dict, g: dict) -> Task:
    """Tasks 1, 2, 4, 5: crank, coupler AB, rocker O2B carrying C, rod CD, slider D."""
    r, l, cd = c["AO1"], c["AB"], c["CD"]
    if task == 1:
        rho, oc = c["BO2"], c["CO2"]
        O2, guide = (c["x"], 0.0), c["y"]
        scheme = ("crank O1A (1), coupler AB (2), rocker O2B (3) with C on it beyond B, rod CD (4), "
                  "slider D (5) on a horizontal guide.")
        given = (f"l_AO1 = {r}, l_AB = {l}, l_CO2 = {oc}, l_BO2 = {rho}, l_CD = {cd}, x = {g['x']}, "
                 f"y = {g['y']}, phi1 = {c['phi1']}.")
        reading = ("O2 on the horizontal through O1 at x; D's guide horizontal at height y; C on the "
                   "ray O2B at l_CO2 from O2.")
        masses = {2: (c["m2"], c["IS2"]), 5: (c["m5"], None)}
    elif task == 2:
        rho, oc = c["BO2"], c["CO2"]
        O2, guide = (c["x"], 0.0), 0.0
        scheme = ("crank O1A (1), coupler AB (2), rocker O2B (3) with C on it between O2 and B, "
                  "rod CD (4), slider D (5) on the line of centres O1O2.")
        given = (f"l_AO1 = {r}, l_AB = {l}, l_CO2 = {oc}, l_BO2 = {rho}, l_CD = {cd}, x = {g['x']}, "
                 f"phi1 = {c['phi1']}.")
        reading = "O2 on the horizontal through O1 at x; D slides along O1O2; C at l_CO2 from O2."
        masses = {4: (c["m4"], c["IS4"]), 5: (c["m5"], None)}
    elif task == 4:
        rho, oc = c["BO2"], c["BO2"] - c["CB"]
        O2, guide = (c["x"], 0.0), c["y"]
        scheme = ("crank O1A (1), coupler AB (2), rocker O2B (3) with C on it at l_CB from B, "
                  "rod CD (4), slider D (5) on a horizontal guide.")
        given = (f"l_AO1 = {r}, l_AB = {l}, l_BO2 = {rho}, l_CB = {c['CB']}, l_CD = {cd}, x = {g['x']}, "
                 f"y = {g['y']}, phi1 = {c['phi1']}.")
        reading = "O2 on the horizontal through O1 at x; D's guide horizontal at height y."
        masses = {2: (c["m2"], c["IS2"]), 5: (c["m5"], None)}
    else:
        rho, oc = c["BO2"], c["BO2"] - c["BC"]
        O2, guide = (c["x1"], c["y"]), c["y"]
        scheme = ("crank O1A (1), coupler AB (2), rocker O2B (3) with C on it at l_BC from B, "
                  "rod CD (4), slider D (5) on the horizontal through O2.")
        given = (f"l_AO1 = {r}, l_AB = {l}, l_BO2 = {rho}, l_BC = {c['BC']}, l_CD = {cd}, x = {g['x']}, "
                 f"x1 = {g['x1']}, y = {g['y']}, phi1 = {c['phi1']}.")
        reading = ("O2 at (x1, y) from O1; D slides on the horizontal through O2; x (a dimension of "
                   "the figure) is not needed.")
        masses = {3: (c["m3"], c["IS3"]), 5: (c["m5"], None)}
    m = {i: masses.get(i, (0.0, None)) for i in range(1, 6)}
    rocker = bar(3, ["O2", "B", "C"], [rho, oc], m[3][0], m[3][1], note="rocker")
    hints = []
    for up in (90, -90):
        for side in (1, -1):
            C0 = polar(O2, oc, up)
            hints.append({"A": (0, r), "B": polar(O2, rho, up), "C": C0,
                          "D": (C0[0] + side * cd, guide)})
    return Task(
        path=f"seed002/task{task}_v{v:02d}.toml",
        title=f"Seed 002 task {task} v{v}: crank-rocker with a slider (phi1 = {c['phi1']} deg)",
        title_uk=uk_title("002", task, v, "кривошипно-коромисловий механізм із повзуном", c["phi1"]),
        header=s2_header(task, v, scheme, given, reading,
                         TRAIN_A if task in (1, 4, 5) else TRAIN_B),
        frame={"O1": (0, 0), "O2": O2},
        links=[crank(r), bar(2, "AB", [l], m[2][0], m[2][1], note="coupler"), rocker,
               bar(4, "CD", [cd], m[4][0], m[4][1], note="rod"), block(5, "D", m[5][0], "slider")],
        sliders=[Slider(5, (0, guide), 0, note="D on a horizontal guide")],
        output="D", out_link=5, force_N=c["F"], axis=(1.0, 0.0), hints=hints, acts="always",
        phi1=c["phi1"], gears=train_pair_planetary(c) if task in (1, 4, 5) else train_planetary_pair(c))


def s2_slotted(v: int, c: dict, g: dict) -> Task:
    """Task 3: crank, block A in the slotted link O2C, rod CD, slider D."""
    r, oc, cd = c["AO1"], c["CO2"], c["CD"]
    O2 = (c["x1"], c["y"])
    toward = math.degrees(math.atan2(-O2[1], -O2[0]))
    C0 = polar(O2, oc, toward)
    return Task(
        path=f"seed002/task3_v{v:02d}.toml",
        title=f"Seed 002 task 3 v{v}: crank-slotted-link mechanism with a slider (phi1 = {c['phi1']} deg)",
        title_uk=uk_title("002", 3, v, "кривошипно-кулісний механізм із повзуном", c["phi1"]),
        header=s2_header(3, v, "crank O1A (1), block A (2) sliding in the slotted link O2C (3), "
                         "rod CD (4), slider D (5) on a vertical guide.",
                         f"l_AO1 = {r}, l_CO2 = {oc}, l_CD = {cd}, x = {g['x']}, x1 = {g['x1']}, "
                         f"y = {g['y']}, phi1 = {c['phi1']}.",
                         "no l_AB: the crank drives the slotted link through a block; O2 at (x1, y) "
                         "from O1, C on the slot on the crank's side, D's guide vertical at x from O1.",
                         TRAIN_B),
        frame={"O1": (0, 0), "O2": O2},
        links=[crank(r), block(2, "A", 0.0, "block in the slot"),
               bar(3, ["O2", "C"], [oc], c["m3"], c["IS3"], note="slotted link"),
               bar(4, "CD", [cd], 0.0, note="rod"), block(5, "D", c["m5"], "slider")],
        sliders=[Slider(2, (0, 0), 0, on=3, note="the slot runs along O2C"),
                 Slider(5, (c["x"], 0), 90, note="D on the vertical x")],
        output="D", out_link=5, force_N=c["F"], axis=(0.0, 1.0), acts="always", phi1=c["phi1"],
        hints=[{"A": (0, r), "C": C0, "D": (c["x"], C0[1] + side * cd)} for side in (1, -1)],
        gears=train_planetary_pair(c))


def s2_shaper(v: int, c: dict, g: dict) -> Task:
    """Task 6: crank, block A in the slotted link O2B, ram D pinned to a block in the slot."""
    r, L = c["AO1"], c["BO2"]
    O2 = (0.0, -c["y1"])
    return Task(
        path=f"seed002/task6_v{v:02d}.toml",
        title=f"Seed 002 task 6 v{v}: shaper, crank-slotted link and ram (phi1 = {c['phi1']} deg)",
        title_uk=uk_title("002", 6, v, "поперечно-стругальний верстат, кривошипно-кулісний механізм "
                                       "і повзун", c["phi1"]),
        header=s2_header(6, v, "crank O1A (1), block A (2) in the slotted link O2B (3), block D (4) "
                         "in the same slot, pinned to the ram D (5) on a horizontal guide (a PRP "
                         "group).",
                         f"l_AO1 = {r}, l_BO2 = {L}, y1 = {g['y1']}, y = {g['y']}, phi1 = {c['phi1']}.",
                         "no coupler and no rod: O2 lies y1 below O1, the ram's guide y above O1; "
                         "the slot (l_BO2) reaches the ram's line, y1 + y < l_BO2 in every variant.",
                         TRAIN_B),
        frame={"O1": (0, 0), "O2": O2},
        links=[crank(r), block(2, "A", 0.0, "block in the slot"),
               bar(3, ["O2", "B"], [L], c["m3"], c["IS3"], note="slotted link"),
               block(4, "D", 0.0, "block in the slot, pinned to the ram"), block(5, "D", c["m5"], "ram")],
        sliders=[Slider(2, (0, 0), 0, on=3, note="the slot runs along O2B"),
                 Slider(4, (0, 0), 0, on=3, note="the ram's block in the same slot"),
                 Slider(5, (0, c["y"]), 0, note="the ram on the horizontal y above O1")],
        output="D", out_link=5, force_N=c["F"], axis=(1.0, 0.0), acts="always", phi1=c["phi1"],
        hints=[{"A": (r, 0), "B": polar(O2, L, 90), "D": (0, c["y"])}],
        gears=train_planetary_pair(c))


# which frame dimension a seed 002 correction may change, in order of preference
S2_ADJUST = {1: ["x", "y"], 2: ["x"], 3: ["x", "x1", "y"], 4: ["x", "y"], 5: ["x1", "y"], 6: ["y1", "y"]}


def s2_build(task: int, v: int, c: dict, given: dict) -> Task:
    """The task's file from the values `c`; `given` (the table) is quoted in its header."""
    if task == 3:
        return s2_slotted(v, c, given)
    if task == 6:
        return s2_shaper(v, c, given)
    return s2_rocker_task(task, v, c, given)


def s2(task: int, v: int) -> Task:
    """Column v (0-based) of a seed 002 table; the nearest working frame dimension
    when the table's mechanism cannot turn (or turns with γ_min below 10°)."""
    c = {k: vals[v] for k, vals in S2[task].items()}
    t = s2_build(task, v, c, c).finish()
    if t.ok and t.gamma_min >= GAMMA_ACCEPT:
        return t
    best = None
    for key in S2_ADJUST[task]:
        for step in range(1, 301):
            found = None
            for sign in (-1, 1):
                trial = dict(c, **{key: c[key] + sign * step})
                tt = s2_build(task, v, trial, c).finish()
                if tt.ok and tt.gamma_min >= GAMMA_TARGET:
                    found = (step, key, trial[key], tt)
                    break
            if found:
                if best is None or found[0] < best[0]:
                    best = found
                break
    if best is None:
        t.corrections.append("no frame dimension within 300 mm lets the crank turn; "
                             "documented error (the file does not analyse over the turn)")
        return t
    step, key, value, tt = best
    why = (_why_not(t) if not t.ok else f"the transmission angle falls to {t.gamma_min:.0f} deg")
    tt.corrections.append(f"{key} = {c[key]} in the table: {why} (the task only draws phi1 = "
                          f"{c['phi1']} deg); {key} = {value} is the nearest value whose turn has "
                          f"a transmission angle of {GAMMA_TARGET:.0f} deg or more.")
    return tt


def _why_not(t: Task) -> str:
    sw = mmt_plans.sweep(t.load(), SWEEP)
    if any(m.any() for m in sw.failed.values()):
        four_bar = any(m.any() for name, m in sw.failed.items() if name.startswith("2"))
        return ("the crank cannot make a full turn (the four-bar is not a crank-rocker)" if four_bar
                else "the rod cannot reach the slider's guide in every position")
    return "the mechanism passes a dead point (a change-point four-bar)"


# ======================================================================================

def all_tasks() -> list[Task]:
    tasks = [SEED003[t](v).finish() for t in range(1, 12) for v in range(1, 6)]
    tasks += [s2(t, v) for t in range(1, 7) for v in range(10)]
    return tasks


def main(argv: list[str]) -> int:
    tasks = all_tasks()
    bad = 0
    for t in tasks:
        t.write()
        flag = "" if t.ok else "  CANNOT TURN"
        fix = "  corrected" if t.corrections else ""
        print(f"{t.path:28s} {t.formula:44s} gamma_min {t.gamma_min:5.1f}  "
              f"wd {t.working_direction}{fix}{flag}")
        if "--check" in argv:
            mech = mmt_plans.load(HERE / t.path)
            if mmt_plans.sweep(mech, SWEEP).ok.all():
                results(mmt_plans.solve(mech))
            else:
                bad += 1
    print(f"{len(tasks)} files, {sum(bool(t.corrections) for t in tasks)} corrected, "
          f"{sum(not t.ok for t in tasks)} cannot turn")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
