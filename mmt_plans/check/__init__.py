"""A student's answers against the exact values (`mmt-plans check`).

The student writes what they measured on their hand drawing in an answers
file (README.md, "Checking a student's work"): speeds and accelerations of
points, ω and ε of links, plan segments in mm with the plan's μ, the
reactions, the balancing force and moment. Each value is compared with the
exact one; a value outside the tolerance gets the likely cause where the
evidence shows one (a wrong scale, a swapped sign, an image read from the
wrong plan, position or point), and only when the cause reproduces the
student's value within the same tolerance.
"""

from __future__ import annotations

import difflib
import math
import re
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any, Literal

import numpy as np

from ..errors import MmtError, SpecError, shown
from ..scales import format_number, series
from ..spec import NAME_MAX, parse_toml, read_text, show_value

if TYPE_CHECKING:  # pragma: no cover
    from ..forces import ForceAnalysis
    from ..kinematics.plans import PlanView
    from ..solution import Solution

DEFAULT_TOLERANCE_PERCENT = 5.0

# Input limits of an answers file (README, "Input limits"): a plan's scale μ,
# the tolerance, any value, and how many values one file may give.
MU_MIN, MU_MAX = 1e-9, 1e9
TOLERANCE_MAX = 100.0
VALUE_MAX = 1e15
VALUES_MAX = 2000

LIMITS: dict[str, str] = {  # the answers file's rows of README's "Input limits"
    "answers: mu_V, mu_a": f"{MU_MIN:g} to {MU_MAX:g}",
    "answers: tolerance_percent, --tolerance": f"above 0, at most {TOLERANCE_MAX:g}",
    "answers: any value": f"finite, at most {VALUE_MAX:g} in size",
    "answers: values in one file": f"at most {VALUES_MAX:,}",
    "answers: names (points, links, segments, reactions)": "1 to 32 printable characters",
}

# An exact value this small against the largest of its kind is zero: the
# position's ε1 of a uniformly turning crank, a point on the frame.
_ZERO = 1e-9

Kind = Literal[
    "velocity",
    "acceleration",
    "omega",
    "eps",
    "velocity_plan_mm",
    "acceleration_plan_mm",
    "balancing_force_plans",
    "balancing_force_lever",
    "balancing_moment",
    "reaction",
]

KEYS: dict[str, tuple[str, ...]] = {
    "": ("check", "position", "forces"),
    "check": ("tolerance_percent",),
    "position": (
        "index",
        "mu_V",
        "mu_a",
        "velocity",
        "acceleration",
        "omega",
        "eps",
        "omega_magnitude",
        "eps_magnitude",
        "velocity_plan_mm",
        "acceleration_plan_mm",
    ),
    "forces": (
        "index",
        "balancing_force_plans",
        "balancing_force_lever",
        "balancing_moment",
        "reactions",
    ),
}

# What each key of a position or of [forces] holds.
_POSITION_TABLES: dict[str, tuple[Kind, bool]] = {  # key: (kind, signed)
    "velocity": ("velocity", False),
    "acceleration": ("acceleration", False),
    "omega": ("omega", True),
    "eps": ("eps", True),
    "omega_magnitude": ("omega", False),
    "eps_magnitude": ("eps", False),
    "velocity_plan_mm": ("velocity_plan_mm", False),
    "acceleration_plan_mm": ("acceleration_plan_mm", False),
}
_FORCE_VALUES: dict[str, Kind] = {
    "balancing_force_plans": "balancing_force_plans",
    "balancing_force_lever": "balancing_force_lever",
    "balancing_moment": "balancing_moment",
}

UNITS: dict[Kind, str] = {
    "velocity": "m/s",
    "acceleration": "m/s2",
    "omega": "rad/s",
    "eps": "rad/s2",
    "velocity_plan_mm": "mm",
    "acceleration_plan_mm": "mm",
    "balancing_force_plans": "N",
    "balancing_force_lever": "N",
    "balancing_moment": "N*m",
    "reaction": "N",
}

# The other plan of the same position: where a point's image is read by mistake.
_OTHER_PLAN: dict[Kind, Kind] = {
    "velocity": "acceleration",
    "acceleration": "velocity",
    "omega": "eps",
    "eps": "omega",
    "velocity_plan_mm": "acceleration_plan_mm",
    "acceleration_plan_mm": "velocity_plan_mm",
}
_PLAN_NAME: dict[Kind, str] = {
    "velocity": "velocity plan",
    "acceleration": "acceleration plan",
    "omega": "velocity plan",
    "eps": "acceleration plan",
    "velocity_plan_mm": "velocity plan",
    "acceleration_plan_mm": "acceleration plan",
}

# The pole of each plan as a student may write it: p (velocities), π or pi (accelerations).
VELOCITY_POLES = ("p",)
ACCELERATION_POLES = ("pi", "π", "p")
POLE = ""  # a segment's end at the pole

# Two causes whose values differ from the student's by less than this (relative)
# are equally likely: a value read to 3 significant figures is good to 0.5 %.
_TIE = 0.01

# Two neighbouring values of the standard series (1, 1.25, 2, 2.5, 4, 5, 8) differ
# by 1.25 or 1.6 times.
_NEIGHBOUR_RATIOS = (1.25, 1.6)


# --- what the student gave ----------------------------------------------------------


@dataclass(frozen=True)
class Answer:
    """One value of the answers file."""

    entry: str  # where it is written: "position[1].velocity.B"
    position: int
    kind: Kind
    name: str  # "B", "2", "pb", "R12"; "" for a balancing force or moment
    value: float
    signed: bool
    segment: tuple[str, str] | None = None  # the two images of a plan segment (POLE = pole)
    mu: float | None = None  # the plan's μ of a segment or a value read off a plan
    other_mu: float | None = None  # the other plan's μ at the same position, if given

    @property
    def label(self) -> str:
        if self.kind == "velocity":
            return f"V_{self.name}"
        if self.kind == "acceleration":
            return f"a_{self.name}"
        if self.kind in ("omega", "eps"):
            return f"{self.kind}{self.name}" if self.signed else f"|{self.kind}{self.name}|"
        if self.kind == "velocity_plan_mm":
            return f"{self.name} (V plan)"
        if self.kind == "acceleration_plan_mm":
            return f"{self.name} (a plan)"
        if self.kind == "reaction":
            return self.name
        return {
            "balancing_force_plans": "F_bal (plans)",
            "balancing_force_lever": "F_bal (lever)",
            "balancing_moment": "M_bal",
        }[self.kind]


@dataclass(frozen=True)
class Answers:
    path: str
    tolerance_percent: float | None  # None: not given in the file
    values: tuple[Answer, ...]

    @property
    def positions(self) -> tuple[int, ...]:
        return tuple(sorted({a.position for a in self.values}))


# --- the verdict --------------------------------------------------------------------


@dataclass(frozen=True)
class CheckedValue:
    """A student's value against the exact one."""

    answer: Answer
    exact: float  # in the answer's terms: a magnitude unless the answer is signed
    deviation_percent: float | None  # (value − exact) / |exact|·100; None for an exact zero
    passed: bool
    causes: tuple[str, ...]  # likely causes of a failure, the closest first

    @property
    def cause(self) -> str | None:
        return self.causes[0] if self.causes else None


@dataclass(frozen=True)
class CheckResult:
    mechanism: str  # the mechanism file
    answers: str  # the answers file
    tolerance_percent: float
    values: tuple[CheckedValue, ...]

    @property
    def passed(self) -> bool:
        return all(v.passed for v in self.values)

    @property
    def failures(self) -> tuple[CheckedValue, ...]:
        return tuple(v for v in self.values if not v.passed)

    def text(self) -> str:
        from ..report import table

        rows = []
        for v in self.values:
            a = v.answer
            dev = "-" if v.deviation_percent is None else f"{v.deviation_percent:+.2f}"
            rows.append(
                [
                    str(a.position),
                    a.label,
                    UNITS[a.kind],
                    _num(v.exact),
                    _num(a.value),
                    dev,
                    "pass" if v.passed else "FAIL",
                    v.cause or "",
                ]
            )
        head = f"Check of {self.answers} against {self.mechanism}"
        out = [head, "=" * len(head), ""]
        headers = ["pos", "value", "unit", "exact", "student", "dev %", "result", "likely cause"]
        body = table(headers, rows)
        # The cause is free text: left-aligned reads better than right-aligned.
        out += [line.rstrip() for line in _left_last(body, rows)]
        also = [
            f"  position {v.answer.position}, {v.answer.label}: also fits: {why}"
            for v in self.failures
            for why in v.causes[1:]
        ]
        if also:
            out += ["", "Other causes that fit as well:", *also]
        n, bad = len(self.values), len(self.failures)
        out += [
            "",
            f"{n - bad} of {n} values within {format_number(self.tolerance_percent)} %"
            + ("" if bad else ": passed"),
        ]
        return "\n".join(out)


def _left_last(body: str, rows: list[list[str]]) -> list[str]:
    """The table with its last column aligned to the left."""
    width = max([len("likely cause"), *(len(r[-1]) for r in rows)])
    lines = body.splitlines()
    return [
        line[: len(line) - width] + line[len(line) - width :].strip().ljust(width) for line in lines
    ]


def _num(x: float) -> str:
    return f"{x:.6g}"


# --- reading the answers file -------------------------------------------------------


def load_answers(path: str | Path, analysis: Solution) -> Answers:
    """Read an answers file and check every name in it against the mechanism."""
    return loads_answers(read_text(path, "answers file"), analysis, str(path))


def loads_answers(text: str, analysis: Solution, path: str = "<string>") -> Answers:
    return _Reader(path, analysis).answers(parse_toml(text, path))


class _Reader:
    def __init__(self, path: str, analysis: Solution) -> None:
        self.path = path
        self.analysis = analysis
        self.exact = Exact(analysis)

    def fail(self, entry: str, problem: str, fix: str = "") -> SpecError:
        return SpecError(self.path, entry, problem, fix)

    def check_keys(self, table: Any, section: str, entry: str) -> dict:
        if not isinstance(table, dict):
            raise self.fail(
                entry or "file",
                "must be a table",
                f"write it as [{entry}] with keys" if entry else "",
            )
        allowed = KEYS[section]
        for key in table:
            if key not in allowed:
                raise self.fail(
                    f"{entry}.{key}" if entry else key,
                    "unknown key",
                    _suggest(key, allowed, "allowed keys"),
                )
        return table

    def number(
        self,
        value: Any,
        entry: str,
        *,
        positive: bool = False,
        non_negative: bool = False,
        signed_key: str = "",
        minimum: float | None = None,
        maximum: float = VALUE_MAX,
    ) -> float:
        x = None
        if not isinstance(value, bool) and isinstance(value, (int, float)):
            try:
                x = float(value)
            except OverflowError:  # an integer beyond any float
                x = math.inf
        if x is None or not math.isfinite(x):
            raise self.fail(
                entry,
                f"must be a number, not {show_value(value)}",
                f"write {entry.rsplit('.', 1)[-1]} = <number>, e.g. 1.23",
            )
        if positive and x <= 0:
            raise self.fail(entry, f"must be positive, not {x:g}", "give a value above zero")
        if non_negative and x < 0:
            fix = "give the magnitude"
            if signed_key:
                fix += f", or write the signed value under {signed_key}"
            raise self.fail(entry, f"is a magnitude and must not be negative, not {x:g}", fix)
        if abs(x) > maximum or (minimum is not None and abs(x) < minimum):
            span = (
                f"between {minimum:g} and {maximum:g}"
                if minimum is not None
                else f"at most {maximum:g} in size"
            )
            raise self.fail(
                entry,
                f"is {x:g}, out of the range this tool accepts: {span}",
                "check the value and its unit; README lists the input limits",
            )
        return x

    def key(self, name: str, entry: str) -> str:
        """A name from the file (a point, a link, a segment, a reaction): short and printable."""
        if len(name) > NAME_MAX or not name.isprintable() or not name:
            raise self.fail(
                f"{entry}.{shown(name, NAME_MAX)}",
                f"'{shown(name, NAME_MAX)}' is not a name this mechanism uses",
                f"write a point, link, segment or reaction name (at most {NAME_MAX} "
                "printable characters)",
            )
        return name

    def index(self, table: dict, entry: str, default: int | None = None) -> int:
        n = self.analysis.mechanism.study.positions
        if "index" not in table:
            if default is None:
                raise self.fail(
                    f"{entry}.index", "is required", f"add index = <position number 0..{n - 1}>"
                )
            return default
        value = table["index"]
        if isinstance(value, bool) or not isinstance(value, int):
            raise self.fail(
                f"{entry}.index",
                f"must be a whole position number, not {value!r}",
                f"use a position 0..{n - 1} (0 = the extreme position)",
            )
        if not 0 <= value < n:
            raise self.fail(
                f"{entry}.index",
                f"position {value} does not exist",
                f"use a position 0..{n - 1} (0 = the extreme position)",
            )
        return value

    def answers(self, data: dict) -> Answers:
        self.check_keys(data, "", "")
        tolerance = None
        if "check" in data:
            check = self.check_keys(data["check"], "check", "check")
            if "tolerance_percent" in check:
                tolerance = self.number(
                    check["tolerance_percent"],
                    "check.tolerance_percent",
                    positive=True,
                    maximum=TOLERANCE_MAX,
                )
        values: list[Answer] = []
        seen: dict[int, str] = {}
        for k, table in enumerate(_as_list(data.get("position", [])), start=1):
            entry = f"position[{k}]"
            values += self.position(table, entry, seen)
        for k, table in enumerate(_as_list(data.get("forces", [])), start=1):
            entry = "forces" if not isinstance(data["forces"], list) else f"forces[{k}]"
            values += self.forces(table, entry)
        if len(values) > VALUES_MAX:
            raise self.fail(
                "file",
                f"gives {len(values)} values, more than the {VALUES_MAX} "
                "this tool checks in one file",
                "split the answers into several files",
            )
        if not values:
            raise self.fail(
                "file",
                "gives no value to check",
                "add a [[position]] with e.g. velocity = { B = 1.23 }, or [forces]",
            )
        return Answers(self.path, tolerance, tuple(values))

    def position(self, table: Any, entry: str, seen: dict[int, str]) -> list[Answer]:
        self.check_keys(table, "position", entry)
        index = self.index(table, entry)
        if index in seen:
            raise self.fail(
                f"{entry}.index",
                f"position {index} is already given in {seen[index]}",
                "write each position once",
            )
        seen[index] = entry
        entry = f"{entry} (index {index})"
        try:
            plan = self.exact.plan(index)
        except MmtError as err:
            raise self.fail(
                f"{entry}.index",
                f"position {index} has no plans: {err}",
                "check a position where the mechanism assembles",
            ) from None
        mu_v = (
            self.number(
                table["mu_V"], f"{entry}.mu_V", positive=True, minimum=MU_MIN, maximum=MU_MAX
            )
            if "mu_V" in table
            else None
        )
        mu_a = (
            self.number(
                table["mu_a"], f"{entry}.mu_a", positive=True, minimum=MU_MIN, maximum=MU_MAX
            )
            if "mu_a" in table
            else None
        )
        out = []
        for key, (kind, signed) in _POSITION_TABLES.items():
            if key not in table:
                continue
            where = f"{entry}.{key}"
            values = table[key]
            if not isinstance(values, dict):
                raise self.fail(
                    where, "must be a table of values", f"write {key} = {{ {_example(kind)} }}"
                )
            if len(values) > VALUES_MAX:
                raise self.fail(
                    where,
                    f"gives {len(values)} values, more than the {VALUES_MAX} "
                    "this tool checks in one file",
                    "give the values you measured",
                )
            for name, raw in values.items():
                name = self.key(str(name), where)
                value = self.number(
                    raw,
                    f"{where}.{name}",
                    non_negative=not signed,
                    signed_key=kind if kind in ("omega", "eps") else "",
                )
                mu, other_mu = _scales(kind, mu_v, mu_a)
                segment = None
                if kind in ("velocity", "acceleration"):
                    self.point(name, plan, f"{where}.{name}")
                elif kind in ("omega", "eps"):
                    name = self.link(name, plan, f"{where}.{name}")
                else:
                    if mu is None:
                        scale = "mu_V" if kind == "velocity_plan_mm" else "mu_a"
                        unit = "(m/s)/mm" if scale == "mu_V" else "(m/s2)/mm"
                        raise self.fail(
                            where,
                            f"plan segments in mm need the plan's scale {scale}",
                            f"add {scale} = <{unit}>, e.g. {scale} = 0.02, to {entry}",
                        )
                    segment = self.segment(name, kind, plan, f"{where}.{name}")
                out.append(
                    Answer(
                        f"{where}.{name}", index, kind, name, value, signed, segment, mu, other_mu
                    )
                )
        return out

    def point(self, name: str, plan: PlanView, entry: str) -> None:
        if name not in plan.velocity_images:
            names = list(plan.velocity_images)
            raise self.fail(
                entry,
                f"point {name} does not exist",
                _suggest(name, names, "points of this mechanism"),
            )

    def link(self, name: str, plan: PlanView, entry: str) -> str:
        links = [str(lid) for lid in plan.omega]
        if name not in links:
            raise self.fail(
                entry,
                f"link {name} does not exist",
                f"links of this mechanism: {', '.join(links)} "
                '(write the link number as the key, e.g. "2" = -1.36)',
            )
        return name

    def segment(self, name: str, kind: Kind, plan: PlanView, entry: str) -> tuple[str, str]:
        """The two images a segment like "pb", "ab", "πb", "pis2", "a-s2" joins."""
        poles = VELOCITY_POLES if kind == "velocity_plan_mm" else ACCELERATION_POLES
        images = {p.lower(): p for p in plan.velocity_images}

        def ends(token: str) -> set[str]:
            return ({POLE} if token in poles else set()) | (
                {images[token]} if token in images else set()
            )

        key = name.lower()
        if "-" in key:
            parts = key.split("-")
            splits = [(parts[0], parts[1])] if len(parts) == 2 else []
        else:
            splits = [(key[:i], key[i:]) for i in range(1, len(key))]
        found = {(x, y) for left, right in splits for x in ends(left) for y in ends(right)}
        pole = poles[0] if kind == "velocity_plan_mm" else "pi"
        fix = (
            f"name the two ends by their images: the pole {pole} and lower-case point "
            f"names ({', '.join(images)}), e.g. {pole}b or ab; a dash may separate them: a-s2"
        )
        if not found:
            raise self.fail(entry, f"{name!r} is not a segment of the {_PLAN_NAME[kind]}", fix)
        if len(found) > 1:
            readings = " or ".join(_segment_name(kind, seg, dash=True) for seg in sorted(found))
            raise self.fail(
                entry,
                f"{name!r} can be read as {readings}",
                "separate the two images with a dash, e.g. a-s2",
            )
        x, y = found.pop()
        if x == y:
            raise self.fail(entry, f"{name!r} joins an image to itself", fix)
        return x, y

    def forces(self, table: Any, entry: str) -> list[Answer]:
        self.check_keys(table, "forces", entry)
        index = self.index(table, entry, default=self.analysis.force_position)
        try:
            fa = self.exact.forces(index)
        except MmtError as err:
            raise self.fail(
                f"{entry}.index",
                f"no force analysis at position {index}: {err}",
                "check the position of your force analysis",
            ) from None
        out = []
        for key, kind in _FORCE_VALUES.items():
            if key in table:
                value = self.number(table[key], f"{entry}.{key}")
                out.append(Answer(f"{entry}.{key}", index, kind, "", value, True))
        if "reactions" in table:
            where = f"{entry}.reactions"
            reactions = table["reactions"]
            if not isinstance(reactions, dict):
                raise self.fail(
                    where,
                    "must be a table of values",
                    "write reactions = { R12 = 15100, R03 = 15300 }",
                )
            if len(reactions) > VALUES_MAX:
                raise self.fail(
                    where,
                    f"gives {len(reactions)} values, more than the "
                    f"{VALUES_MAX} this tool checks in one file",
                    "give the reactions you found",
                )
            for name, raw in reactions.items():
                name = self.key(str(name), where)
                value = self.number(raw, f"{where}.{name}", non_negative=True)
                self.reaction(name, fa, f"{where}.{name}")
                out.append(Answer(f"{where}.{name}", index, "reaction", name, value, False))
        return out

    def reaction(self, name: str, fa: ForceAnalysis, entry: str) -> None:
        pairs = ", ".join(fa.reactions)
        m = _REACTION.fullmatch(name)
        if m is None:
            raise self.fail(
                entry,
                f"{name!r} is not a reaction name",
                f"write R and the two links, e.g. R12 (R1_12 for link 12); "
                f"this mechanism's pairs: {pairs}",
            )
        try:
            fa.reaction(*_reaction_links(m))
        except KeyError:
            raise self.fail(
                entry,
                f"no pair joins links {m[1] or m[3]} and {m[2] or m[4]}",
                f"this mechanism's pairs: {pairs}",
            ) from None


_REACTION = re.compile(r"R(?:(\d)(\d)|(\d+)_(\d+))")


def _reaction_links(m: re.Match) -> tuple[int, int]:
    return (int(m[1]), int(m[2])) if m[1] else (int(m[3]), int(m[4]))


def _scales(
    kind: Kind, mu_v: float | None, mu_a: float | None
) -> tuple[float | None, float | None]:
    """(this plan's μ, the other plan's μ) for a value read off a plan."""
    if kind in ("velocity", "velocity_plan_mm"):
        return mu_v, mu_a
    if kind in ("acceleration", "acceleration_plan_mm"):
        return mu_a, mu_v
    return None, None


def _as_list(value: Any) -> list:
    return value if isinstance(value, list) else [value]


def _example(kind: Kind) -> str:
    return {
        "velocity": "B = 1.23",
        "acceleration": "B = 31.7",
        "omega": '"2" = -1.36',
        "eps": '"2" = -56.1',
        "velocity_plan_mm": "pb = 61.5",
        "acceleration_plan_mm": "pib = 254",
    }[kind]


def _suggest(name: str, allowed: list[str] | tuple[str, ...], what: str) -> str:
    same_case = [a for a in allowed if a.lower() == name.lower()]
    close = same_case or difflib.get_close_matches(name, allowed, n=1)
    if close:
        return f"did you mean '{close[0]}'?"
    return f"{what}: {', '.join(allowed)}"


# --- the exact values ---------------------------------------------------------------


class Exact:
    """The exact value of anything a student may give, from the analysis."""

    def __init__(self, analysis: Solution) -> None:
        self.analysis = analysis
        self._plans: dict[int, PlanView] = {}
        self._forces: dict[int, ForceAnalysis] = {}

    def plan(self, index: int) -> PlanView:
        if index not in self._plans:
            self._plans[index] = self.analysis.plan(index)
        return self._plans[index]

    def forces(self, index: int) -> ForceAnalysis:
        if index not in self._forces:
            self._forces[index] = self.analysis.forces_at(index)
        return self._forces[index]

    def value(
        self,
        kind: Kind,
        index: int,
        name: str,
        *,
        signed: bool = False,
        segment: tuple[str, str] | None = None,
        mu: float | None = None,
    ) -> float:
        """In SI units, or mm of the plan drawn at `mu` for a segment."""
        if kind in ("velocity", "acceleration"):
            plan = self.plan(index)
            images = plan.velocity_images if kind == "velocity" else plan.acceleration_images
            return float(np.hypot(*images[name]))
        if kind in ("omega", "eps"):
            plan = self.plan(index)
            x = (plan.omega if kind == "omega" else plan.eps)[int(name)]
            return x if signed else abs(x)
        if kind in ("velocity_plan_mm", "acceleration_plan_mm"):
            assert segment is not None and mu is not None
            plan = self.plan(index)
            images = (
                plan.velocity_images if kind == "velocity_plan_mm" else plan.acceleration_images
            )
            p, q = (np.zeros(2) if e == POLE else images[e] for e in segment)
            return float(np.hypot(*(q - p))) / mu
        fa = self.forces(index)
        if kind == "reaction":
            m = _REACTION.fullmatch(name)
            assert m is not None
            return fa.reaction(*_reaction_links(m)).magnitude
        return float(getattr(fa, kind))

    def of(self, a: Answer) -> float:
        return self.value(a.kind, a.position, a.name, signed=a.signed, segment=a.segment, mu=a.mu)

    def largest(self, a: Answer) -> float:
        """The largest value of the answer's kind at its position: what "zero"
        is measured against."""
        if a.kind in ("velocity", "acceleration", "velocity_plan_mm", "acceleration_plan_mm"):
            plan = self.plan(a.position)
            images = (
                plan.velocity_images if a.kind.startswith("velocity") else plan.acceleration_images
            )
            big = max(float(np.hypot(*v)) for v in images.values())
            return big / a.mu if a.mu is not None and a.kind.endswith("_mm") else big
        if a.kind in ("omega", "eps"):
            plan = self.plan(a.position)
            return max(abs(x) for x in (plan.omega if a.kind == "omega" else plan.eps).values())
        fa = self.forces(a.position)
        return max(
            [
                abs(fa.balancing_force_plans),
                abs(fa.balancing_force_lever),
                *(r.magnitude for r in fa.reactions.values()),
            ]
        )


# --- comparing and diagnosing -------------------------------------------------------


def check(
    analysis: Solution,
    answers: Answers,
    tolerance_percent: float | None = None,
    *,
    mechanism: str | None = None,
) -> CheckResult:
    """Every answer against the exact value. The tolerance is `tolerance_percent`,
    else the answers file's, else 5 %."""
    tol = (
        tolerance_percent
        if tolerance_percent is not None
        else answers.tolerance_percent
        if answers.tolerance_percent is not None
        else DEFAULT_TOLERANCE_PERCENT
    )
    exact = Exact(analysis)
    drawn = sorted(set(analysis.plan_positions) | set(answers.positions))
    out = []
    for a in answers.values:
        x = exact.of(a)
        largest = exact.largest(a)
        if abs(x) <= _ZERO * largest:  # an exact zero: within tol of the largest value
            passed = abs(a.value) <= tol / 100.0 * largest
            out.append(CheckedValue(a, 0.0, None, passed, ()))
            continue
        deviation = (a.value - x) / abs(x) * 100.0
        passed = abs(deviation) <= tol
        causes = () if passed else _diagnose(a, x, tol / 100.0, exact, drawn)
        out.append(CheckedValue(a, x, deviation, passed, causes))
    return CheckResult(mechanism or str(analysis.mechanism.path), answers.path, tol, tuple(out))


def check_file(
    mechanism_path: str | Path, answers_path: str | Path, tolerance_percent: float | None = None
) -> CheckResult:
    """`mmt-plans check FILE ANSWERS` as a function."""
    from ..solution import solve
    from ..spec import load

    analysis = solve(load(mechanism_path))
    answers = load_answers(answers_path, analysis)
    return check(analysis, answers, tolerance_percent, mechanism=str(mechanism_path))


def _diagnose(a: Answer, exact: float, tol: float, ex: Exact, drawn: list[int]) -> tuple[str, ...]:
    """Causes whose value reproduces the student's within `tol`, the likeliest
    first: the closest, except that causes within a reading's precision of the
    closest (_TIE) count as equally close and keep the order of _candidates (a
    sign, a scale, the other plan, another position, another point). A
    candidate indistinguishable from the exact value explains nothing."""
    found: list[tuple[float, int, str]] = []
    for order, (candidate, why) in enumerate(_candidates(a, exact, ex, drawn)):
        if candidate == 0 or abs(candidate - exact) <= tol * abs(exact):
            continue
        miss = abs(a.value - candidate) / abs(candidate)
        if miss <= tol:
            found.append((miss, order, why))
    if not found:
        return ()
    best = min(miss for miss, _, _ in found)
    found.sort(key=lambda f: (f[0] > best + _TIE, f[0] if f[0] > best + _TIE else 0.0, f[1]))
    return tuple(why for _, _, why in found)


def _candidates(a: Answer, exact: float, ex: Exact, drawn: list[int]):
    """(value, cause) pairs: what the student's value would be after each mistake."""
    if a.signed:
        yield (
            -exact,
            (
                f"sign or direction swapped: the exact value is {_num(exact)}"
                + (" (counter-clockwise +)" if a.kind in ("omega", "eps") else "")
            ),
        )
    for factor, why in _scale_slips(a):
        yield exact * factor, f"wrong scale: {why}"
    yield from _wrong_images(a, ex, drawn)


def _scale_slips(a: Answer) -> list[tuple[float, str]]:
    """(student / exact, cause) for a wrong scale. A plan's own μ gives the
    precise story; the generic ratios come after and never repeat a factor."""
    slips: list[tuple[float, str]] = []
    plan_v = a.kind in ("velocity", "velocity_plan_mm")
    mine, other = ("mu_V", "mu_a") if plan_v else ("mu_a", "mu_V")
    if a.mu is not None and a.kind in ("velocity", "acceleration"):
        if a.other_mu is not None:
            slips.append(
                (
                    a.other_mu / a.mu,
                    f"the segment multiplied by {other} = "
                    f"{format_number(a.other_mu)} instead of {mine} = {format_number(a.mu)}",
                )
            )
        for mu in _neighbours(a.mu):
            slips.append(
                (
                    mu / a.mu,
                    f"the segment multiplied by {format_number(mu)}, the "
                    "neighbouring standard scale, instead of "
                    f"{mine} = {format_number(a.mu)}",
                )
            )
    if a.mu is not None and a.kind in ("velocity_plan_mm", "acceleration_plan_mm"):
        what = "speed" if plan_v else "acceleration"
        if a.other_mu is not None:
            slips.append(
                (
                    a.mu / a.other_mu,
                    f"the {what} divided by {other} = "
                    f"{format_number(a.other_mu)} instead of {mine} = {format_number(a.mu)}",
                )
            )
        for mu in _neighbours(a.mu):
            slips.append(
                (
                    a.mu / mu,
                    f"the plan drawn at {format_number(mu)}, the neighbouring "
                    f"standard scale, not at the stated {mine} = {format_number(a.mu)}",
                )
            )
    for k in (1, 2, 3):
        slips.append((10.0**k, f"{10**k} times the exact value (a decimal point or unit slip)"))
        slips.append((10.0**-k, f"1/{10**k} of the exact value (a decimal point or unit slip)"))
    for r in _NEIGHBOUR_RATIOS:
        slips.append(
            (
                r,
                f"{format_number(r)} times the exact value, the ratio of two "
                "neighbouring standard scales",
            )
        )
        slips.append(
            (
                1 / r,
                f"1/{format_number(r)} of the exact value, the ratio of two "
                "neighbouring standard scales",
            )
        )
    out: list[tuple[float, str]] = []
    for factor, why in slips:
        if all(not math.isclose(factor, f, rel_tol=1e-9) for f, _ in out):
            out.append((factor, why))
    return out


def _neighbours(mu: float) -> tuple[float, float]:
    """The standard-series values just below and just above μ."""
    below = [s for s in series(mu / 2, mu) if s < mu * (1 - 1e-9)]
    above = [s for s in series(mu, mu * 2) if s > mu * (1 + 1e-9)]
    return below[-1], above[0]


def _wrong_images(a: Answer, ex: Exact, drawn: list[int]):
    """The value read from the other plan, another drawn position, or another
    point's image (another link, another pair) of the same plan."""
    pos = a.position

    def value(kind: Kind, index: int, name: str, segment=None, mu=None) -> float:
        return ex.value(kind, index, name, signed=a.signed, segment=segment, mu=mu)

    if a.kind in ("velocity", "acceleration", "omega", "eps"):
        other = _OTHER_PLAN[a.kind]
        what = _describe(other, a.name, a.signed)
        yield (
            value(other, pos, a.name),
            (f"read off the {_PLAN_NAME[other]}: {what} = {_num(value(other, pos, a.name))}"),
        )
        if a.kind in ("velocity", "acceleration") and a.mu is not None and a.other_mu is not None:
            seg_name = f"{'pi' if other == 'acceleration' else 'p'}{a.name.lower()}"
            x = value(other, pos, a.name) / a.other_mu * a.mu
            yield (
                x,
                (
                    f"the segment {seg_name} of the {_PLAN_NAME[other]} ({_num(x / a.mu)} mm) "
                    f"multiplied by this plan's scale {format_number(a.mu)}"
                ),
            )
        for i in drawn:
            if i != pos:
                x = value(a.kind, i, a.name)
                what = _describe(a.kind, a.name, a.signed)
                yield x, f"taken from position {i}: {what} = {_num(x)}"
        plan = ex.plan(pos)
        names = (
            plan.velocity_images
            if a.kind in ("velocity", "acceleration")
            else {str(lid): 0 for lid in plan.omega}
        )
        for n in names:
            if n != a.name:
                x = value(a.kind, pos, n)
                noun = (
                    "another point's image on the same plan"
                    if a.kind in ("velocity", "acceleration")
                    else "another link"
                )
                yield x, f"{noun}: {_describe(a.kind, n, a.signed)} = {_num(x)}"
    elif a.segment is not None:
        other = _OTHER_PLAN[a.kind]
        if a.other_mu is not None:
            x = value(other, pos, a.name, a.segment, a.other_mu)
            yield x, (f"read off the {_PLAN_NAME[other]}: the same segment there is {_num(x)} mm")
        for i in drawn:
            if i != pos:
                x = value(a.kind, i, a.name, a.segment, a.mu)
                yield x, f"taken from position {i}: {a.name} = {_num(x)} mm there"
        plan = ex.plan(pos)
        ends = [POLE, *plan.velocity_images]
        start, end = a.segment
        for n in ends:
            for seg in ((start, n), (n, end)):
                if n in a.segment or seg[0] == seg[1]:
                    continue
                x = value(a.kind, pos, a.name, seg, a.mu)
                yield (
                    x,
                    (
                        f"another point's image on the same plan: {_segment_name(a.kind, seg)}"
                        f" = {_num(x)} mm"
                    ),
                )
    elif a.kind == "reaction":
        fa = ex.forces(pos)
        for r in fa.reactions.values():
            if {str(r.by), str(r.on)} != set(_reaction_pair(a.name)):
                yield r.magnitude, f"another pair's reaction: {r.name} = {_num(r.magnitude)} N"


def _reaction_pair(name: str) -> tuple[str, str]:
    m = _REACTION.fullmatch(name)
    assert m is not None
    by, on = _reaction_links(m)
    return str(by), str(on)


def _describe(kind: Kind, name: str, signed: bool) -> str:
    if kind in ("velocity", "acceleration"):
        return f"|{'V' if kind == 'velocity' else 'a'}_{name}|"
    return f"{kind}{name}" if signed else f"|{kind}{name}|"


def _segment_name(kind: Kind, segment: tuple[str, str], *, dash: bool = False) -> str:
    pole = "p" if kind == "velocity_plan_mm" else "pi"
    return ("-" if dash else "").join(pole if e == POLE else e.lower() for e in segment)
