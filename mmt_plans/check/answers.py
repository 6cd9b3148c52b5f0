"""Reading an answers file (README, "Checking a student's work"): every name
checked against the mechanism, every number against its limits; a bad entry
is a SpecError naming the file, the entry and the fix (exit code 2)."""

from __future__ import annotations

import difflib
import math
import re
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

from ..errors import MmtError, SpecError, degrees_range, shown
from ..spec import NAME_MAX, parse_toml, read_text, show_value
from .quantities import POLE, Answer, Exact, Grid, Where, component, reaction_links

if TYPE_CHECKING:  # pragma: no cover
    from ..forces import ForceAnalysis
    from ..kinematics.plans import PlanView
    from ..solution import Solution

# Input limits of an answers file (README, "Input limits").
MU_MIN, MU_MAX = 1e-9, 1e9
TOLERANCE_MAX = 100.0
VALUE_MAX = 1e15
VALUES_MAX = 2000

LIMITS: dict[str, str] = {  # the answers file's rows of README's "Input limits"
    "answers: mu_V, mu_a": f"{MU_MIN:g} to {MU_MAX:g}",  # and mu_F, mu_S, mu_l
    "answers: tolerance_percent, --tolerance": f"above 0, at most {TOLERANCE_MAX:g}",
    "answers: any value": f"finite, at most {VALUE_MAX:g} in size",
    "answers: values in one file": f"at most {VALUES_MAX:,}",
    "answers: names (points, links, segments, reactions)": "1 to 32 printable characters",
}

_WHERE = ("index", "phi1_deg")
KEYS: dict[str, tuple[str, ...]] = {
    "": ("check", "position", "forces", "diagrams"),
    "check": ("tolerance_percent",),
    "position": (
        *_WHERE,
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
        *_WHERE,
        "mu_F",
        "mu_V",
        "mu_l",
        "mu_l_groups",
        "balancing_force_plans",
        "balancing_force_lever",
        "balancing_moment",
        "reactions",
        "reaction_components",
        "weights",
        "inertia_forces",
        "inertia_moments",
        "inertia_arms_m",
        "inertia_arms_mm",
        "force_plan_mm",
        "lever_mm",
        "group_arms_m",
        "group_arms_mm",
    ),
    "diagrams": (
        "divisions",
        "H_V_mm",
        "H_a_mm",
        "L_mm",
        "mu_S",
        "mu_V",
        "mu_a",
        "S_mm",
        "V_mm",
        "a_mm",
        "check_passed",
        "V_plan",
        "V_diagram",
        "dV_percent",
        "a_plan",
        "a_diagram",
        "da_percent",
    ),
}

# key: (kind, signed) of a position's tables of values
_POSITION_TABLES: dict[str, tuple[str, bool]] = {
    "velocity": ("velocity", False),
    "acceleration": ("acceleration", False),
    "omega": ("omega", True),
    "eps": ("eps", True),
    "omega_magnitude": ("omega", False),
    "eps_magnitude": ("eps", False),
    "velocity_plan_mm": ("velocity_plan_mm", False),
    "acceleration_plan_mm": ("acceleration_plan_mm", False),
}
_FORCE_VALUES = ("balancing_force_plans", "balancing_force_lever", "balancing_moment")
# key: (kind, what the names are, the scale the values need)
_FORCE_TABLES: dict[str, tuple[str, str, str]] = {
    "reactions": ("reaction", "reaction", ""),
    "reaction_components": ("reaction_component", "component", ""),
    "weights": ("weight", "link", ""),
    "inertia_forces": ("inertia_force", "link", ""),
    "inertia_moments": ("inertia_moment", "link", ""),
    "inertia_arms_m": ("inertia_arm_m", "link", ""),
    "inertia_arms_mm": ("inertia_arm_mm", "link", ""),
    "force_plan_mm": ("force_plan_mm", "force", "mu_F"),
    "lever_mm": ("lever_mm", "lever", "mu_V"),
    "group_arms_m": ("group_arm_m", "arm", ""),
    "group_arms_mm": ("group_arm_mm", "arm", ""),
}
_DIAGRAM_TABLES = {"S_mm": ("S", "mu_S"), "V_mm": ("V", "mu_V"), "a_mm": ("a", "mu_a")}
# the 5 % check of the diagrams against the plans (seed 003 (12), (13)), by
# investigated position: key: (kind, quantity, column)
_CHECK_TABLES = {
    "V_plan": ("check_V", "v", "plan"),
    "V_diagram": ("check_V", "v", "diagram"),
    "dV_percent": ("check_delta", "v", "error"),
    "a_plan": ("check_a", "a", "plan"),
    "a_diagram": ("check_a", "a", "diagram"),
    "da_percent": ("check_delta", "a", "error"),
}

VELOCITY_POLES = ("p",)
ACCELERATION_POLES = ("pi", "π", "p")

_EXAMPLES = {
    "velocity": "B = 1.23",
    "acceleration": "B = 31.7",
    "omega": '"2" = -1.36',
    "eps": '"2" = -56.1',
    "velocity_plan_mm": "pb = 61.5",
    "acceleration_plan_mm": "pib = 254",
    "reactions": "R12 = 15100",
    "reaction_components": "R12t = 347.6",
    "weights": '"2" = 102',
    "inertia_forces": '"2" = 453',
    "inertia_moments": '"2" = 18.0',
    "inertia_arms_m": '"2" = 0.04',
    "inertia_arms_mm": '"2" = 20',
    "force_plan_mm": "R12 = 203",
    "lever_mm": "h_G2 = 12.5",
    "group_arms_m": "G2 = 0.081",
    "group_arms_mm": "G2 = 40.5",
    "S_mm": '"3" = 41.5',
    "V_mm": '"3" = 52.0',
    "a_mm": '"3" = -20.4',
    "V_plan": '"3" = 1.52',
    "V_diagram": '"3" = 1.49',
    "dV_percent": '"3" = 2.0',
    "a_plan": '"3" = -5.1',
    "a_diagram": '"3" = -5.3',
    "da_percent": '"3" = -3.9',
}


def kinematic_label(kind: str, name: str, signed: bool) -> str:
    if kind == "velocity":
        return f"V_{name}"
    if kind == "acceleration":
        return f"a_{name}"
    if kind in ("omega", "eps"):
        return f"{kind}{name}" if signed else f"|{kind}{name}|"
    if kind == "velocity_plan_mm":
        return f"{name} (V plan)"
    return f"{name} (a plan)"


@dataclass(frozen=True)
class Answers:
    path: str
    tolerance_percent: float | None  # None: not given in the file
    values: tuple[Answer, ...]
    grid: Grid | None = None  # the student's own differentiation of the diagrams

    @property
    def positions(self) -> tuple[int, ...]:
        return tuple(sorted({a.where.index for a in self.values if a.where.index is not None}))


def load_answers(path: str | Path, analysis: Solution) -> Answers:
    """Read an answers file and check every name in it against the mechanism."""
    return loads_answers(read_text(path, "answers file"), analysis, str(path))


def loads_answers(text: str, analysis: Solution, path: str = "<string>") -> Answers:
    return _Reader(path, analysis).answers(parse_toml(text, path))


def component_key(label: str) -> str:
    """A plan component's label as a key: a^n_BA -> an_BA, a^t_BA -> at_BA,
    a^k_B/3 -> ak_B/3, V_BA -> V_BA (τ is t)."""
    return label.replace("^", "").replace("τ", "t")


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

    def scale(self, table: dict, key: str, entry: str) -> float | None:
        if key not in table:
            return None
        return self.number(
            table[key], f"{entry}.{key}", positive=True, minimum=MU_MIN, maximum=MU_MAX
        )

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

    # --- where: a position or a crank angle -----------------------------------------
    def where(self, table: dict, entry: str, default: int | None = None) -> Where:
        n = self.analysis.mechanism.study.positions
        fix = f"use a position 0..{n - 1} (0 = the extreme position), or phi1_deg = <angle>"
        if "index" in table and "phi1_deg" in table:
            raise self.fail(entry, "gives both index and phi1_deg", "give one of them")
        if "phi1_deg" in table:
            phi = self.number(table["phi1_deg"], f"{entry}.phi1_deg", maximum=1e6)
            ranges = self.analysis.assembly_ranges
            if not _inside(phi % 360.0, ranges):
                where = ", ".join(degrees_range(lo, hi) for lo, hi in ranges)
                raise self.fail(
                    f"{entry}.phi1_deg",
                    f"the mechanism does not assemble at phi1 = {phi:g}° on the file's branches",
                    f"give a crank angle where it does: {where}",
                )
            return self.exact.where(phi1_deg=phi)
        if "index" not in table:
            if default is None:
                raise self.fail(
                    f"{entry}.index",
                    "is required",
                    f"add index = <position number 0..{n - 1}> or phi1_deg = <crank angle>",
                )
            return self.exact.where(index=default)
        value = table["index"]
        if isinstance(value, bool) or not isinstance(value, int):
            raise self.fail(
                f"{entry}.index", f"must be a whole position number, not {value!r}", fix
            )
        if not 0 <= value < n:
            raise self.fail(f"{entry}.index", f"position {value} does not exist", fix)
        return self.exact.where(index=value)

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
        seen: dict[tuple, str] = {}
        for k, table in enumerate(_as_list(data.get("position", [])), start=1):
            values += self.position(table, f"position[{k}]", seen)
        for k, table in enumerate(_as_list(data.get("forces", [])), start=1):
            entry = "forces" if not isinstance(data["forces"], list) else f"forces[{k}]"
            values += self.forces(table, entry)
        grid = None
        if "diagrams" in data:
            values += self.diagrams(data["diagrams"], "diagrams")
            grid = self.grid(data["diagrams"], "diagrams")
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
        return Answers(self.path, tolerance, tuple(values), grid)

    def values_of(self, table: dict, key: str, where: str) -> dict:
        values = table[key]
        if not isinstance(values, dict):
            raise self.fail(
                where, "must be a table of values", f"write {key} = {{ {_EXAMPLES[key]} }}"
            )
        if len(values) > VALUES_MAX:
            raise self.fail(
                where,
                f"gives {len(values)} values, more than the {VALUES_MAX} "
                "this tool checks in one file",
                "give the values you measured",
            )
        return values

    def position(self, table: Any, entry: str, seen: dict[tuple, str]) -> list[Answer]:
        self.check_keys(table, "position", entry)
        w = self.where(table, entry)
        if w.key in seen:
            raise self.fail(
                f"{entry}.{'index' if w.index is not None else 'phi1_deg'}",
                f"this position is already given in {seen[w.key]}",
                "write each position once",
            )
        seen[w.key] = entry
        entry = (
            f"{entry} (index {w.index})"
            if w.index is not None
            else f"{entry} (phi1 {w.phi1_deg:g}°)"
        )
        try:
            plan = self.exact.plan(w)
        except MmtError as err:
            raise self.fail(
                f"{entry}.index",
                f"this position has no plans: {err}",
                "check a position where the mechanism assembles",
            ) from None
        mu_v = self.scale(table, "mu_V", entry)
        mu_a = self.scale(table, "mu_a", entry)
        out = []
        pin = self.analysis.mechanism.crank_pin
        for key, (kind, signed) in _POSITION_TABLES.items():
            if key not in table:
                continue
            where = f"{entry}.{key}"
            for name, raw in self.values_of(table, key, where).items():
                name = self.key(str(name), where)
                value = self.number(
                    raw,
                    f"{where}.{name}",
                    non_negative=not signed,
                    signed_key=kind if kind in ("omega", "eps") else "",
                )
                mu, other_mu = _scales(kind, mu_v, mu_a)
                segment = None
                extra: tuple = ()
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
                    label = self.plan_component(name, kind, plan)
                    if label is not None:
                        extra = (label,)
                    else:
                        segment = self.segment(name, kind, plan, f"{where}.{name}")
                        if segment == (POLE, pin):  # pa / πa: the student's μ is checked
                            mu_kind = "mu_V" if kind == "velocity_plan_mm" else "mu_a"
                            assert mu is not None
                            out.append(
                                Answer(
                                    f"{entry}.{mu_kind}",
                                    w,
                                    mu_kind,
                                    pin,
                                    mu,
                                    label=mu_kind,
                                    extra=(value,),
                                )
                            )
                out.append(
                    Answer(
                        f"{where}.{name}",
                        w,
                        kind,
                        name,
                        value,
                        signed,
                        kinematic_label(kind, name, signed),
                        mu,
                        other_mu,
                        segment,
                        extra,
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

    def link(self, name: str, plan: PlanView, entry: str, links: list[str] | None = None) -> str:
        links = links or [str(lid) for lid in plan.omega]
        if name not in links:
            raise self.fail(
                entry,
                f"link {name} does not exist",
                f"links of this mechanism: {', '.join(links)} "
                '(write the link number as the key, e.g. "2" = -1.36)',
            )
        return name

    @staticmethod
    def plan_component(name: str, kind: str, plan: PlanView) -> str | None:
        """The label of a plan's component named `name` (an_BA, at_BA, ak_B/3, V_BA)."""
        key = component_key(name)
        for g in plan.groups:
            for c in g.velocity if kind == "velocity_plan_mm" else g.acceleration:
                if component_key(c.label) == key:
                    return c.label
        return None

    def segment(self, name: str, kind: str, plan: PlanView, entry: str) -> tuple[str, str]:
        """The two images a segment like "pb", "ab", "πb", "pis2", "a-s2" joins.

        A token written as a pole (p; pi, π or p) is the pole, never an image;
        a point's image is its name in lower case or as the mechanism writes
        it, and a point whose lower-case name is a pole's (P, Pi) is written
        in capitals: "p-P" (or "pP") is the pole to P's image, "P-a" P's
        image to a's, "p-a" the pole to a's."""
        poles = VELOCITY_POLES if kind == "velocity_plan_mm" else ACCELERATION_POLES
        images: dict[str, set[str]] = {}
        for p in plan.velocity_images:
            for spelling in {p, p.lower(), p.upper()}:
                if spelling not in poles:
                    images.setdefault(spelling, set()).add(p)

        def ends(token: str) -> set[str]:
            if token in poles:
                return {POLE}
            if token in images:
                return images[token]
            return {POLE} if token.lower() in poles else set()

        if "-" in name:
            parts = name.split("-")
            splits = [(parts[0], parts[1])] if len(parts) == 2 else []
        else:
            splits = [(name[:i], name[i:]) for i in range(1, len(name))]
        found = {(x, y) for left, right in splits for x in ends(left) for y in ends(right)}
        pole = poles[0] if kind == "velocity_plan_mm" else "pi"
        comps = [
            component_key(c.label)
            for g in plan.groups
            for c in (g.velocity if kind == "velocity_plan_mm" else g.acceleration)
        ]
        fix = (
            f"name the two ends by their images: the pole {pole} and lower-case point "
            f"names ({', '.join(sorted({p.lower() for p in plan.velocity_images}))}), e.g. "
            f"{pole}b or ab (a point named like a pole in capitals: {pole}-P); "
            "a dash may separate them: a-s2; "
            f"or a component: {', '.join(comps)}"
        )
        plan_name = "velocity plan" if kind == "velocity_plan_mm" else "acceleration plan"
        if not found:
            raise self.fail(entry, f"{name!r} is not a segment of the {plan_name}", fix)
        if len(found) > 1:
            readings = " or ".join(segment_name(kind, seg, dash=True) for seg in sorted(found))
            raise self.fail(
                entry,
                f"{name!r} can be read as {readings}",
                "separate the two images with a dash, e.g. a-s2",
            )
        x, y = found.pop()
        if x == y:
            raise self.fail(entry, f"{name!r} joins an image to itself", fix)
        return x, y

    # --- [forces] -----------------------------------------------------------------
    def forces(self, table: Any, entry: str) -> list[Answer]:
        self.check_keys(table, "forces", entry)
        w = self.where(table, entry, default=self.analysis.force_position)
        try:
            fa = self.exact.forces(w)
        except MmtError as err:
            raise self.fail(
                f"{entry}.index",
                f"no force analysis at this position: {err}",
                "check the position of your force analysis",
            ) from None
        scales = {k: self.scale(table, k, entry) for k in ("mu_F", "mu_V", "mu_l", "mu_l_groups")}
        out = []
        for key in _FORCE_VALUES:
            if key in table:
                value = self.number(table[key], f"{entry}.{key}")
                label = {
                    "balancing_force_plans": "F_bal (plans)",
                    "balancing_force_lever": "F_bal (lever)",
                    "balancing_moment": "M_bal",
                }[key]
                out.append(Answer(f"{entry}.{key}", w, key, "", value, True, label))
        links = [str(lid) for lid in fa.loads.links]
        for key, (kind, names, needs) in _FORCE_TABLES.items():
            if key not in table:
                continue
            where = f"{entry}.{key}"
            mu = scales[needs] if needs else None
            if needs and mu is None:
                unit = {"mu_F": "N/mm", "mu_V": "(m/s)/mm"}[needs]
                raise self.fail(
                    where,
                    f"segments in mm need the scale {needs}",
                    f"add {needs} = <{unit}> to [{entry}]",
                )
            if kind == "inertia_arm_mm":
                mu = scales["mu_l"] or self.analysis.mu_l
            if kind == "group_arm_mm":
                mu = scales["mu_l_groups"] or scales["mu_l"] or self.analysis.mu_l
            for name, raw in self.values_of(table, key, where).items():
                name = self.key(str(name), where)
                at = f"{where}.{name}"
                value = self.number(raw, at, non_negative=True)
                extra: tuple = ()
                if names == "reaction":
                    self.reaction(name, fa, at)
                    label = name
                elif names == "component":
                    extra = self.component(name, fa, at)
                    label = f"{extra[0]}{'τ' if extra[1] == 't' else 'n'}"
                elif names == "link":
                    self.link(name, None, at, links)  # type: ignore[arg-type]
                    label = {
                        "weight": "G",
                        "inertia_force": "F_in",
                        "inertia_moment": "M_in",
                        "inertia_arm_m": "h",
                        "inertia_arm_mm": "h",
                    }[kind] + name
                    if kind == "inertia_arm_mm":
                        label += " (mm)"
                elif names == "force":
                    self.plan_force(name, fa, at)
                    label = f"{name} (force plan)"
                elif names == "arm":
                    self.arm(name, fa, at)
                    label = f"h'_{name}" + (" (mm)" if kind == "group_arm_mm" else "")
                else:
                    extra = self.lever_name(name, fa, at)
                    label = f"{name} (lever)"
                out.append(Answer(at, w, kind, name, value, False, label, mu, None, None, extra))
        return out

    def reaction(self, name: str, fa: ForceAnalysis, entry: str) -> None:
        pairs = ", ".join(fa.reactions)
        try:
            fa.reaction(*reaction_links(name, fa))
        except KeyError:
            if re.fullmatch(r"R(?:\d\d|\d+_\d+)", name) is None:
                raise self.fail(
                    entry,
                    f"{name!r} is not a reaction name",
                    f"write R and the two links, e.g. R12 (R1_12 for link 12; R0d for the "
                    f"frame on the driving link); this mechanism's pairs: {pairs}",
                ) from None
            raise self.fail(
                entry, f"no pair joins the links of {name}", f"this mechanism's pairs: {pairs}"
            ) from None

    def component(self, name: str, fa: ForceAnalysis, entry: str) -> tuple[str, str]:
        comps = [f"{r.name}{c.label[-1]}" for r in fa.reactions.values() for c in r.components]
        fix = f"write the reaction and t (or τ) or n: {', '.join(comps) or 'none here'}"
        if name[-1:] not in ("t", "τ", "n"):
            raise self.fail(entry, f"{name!r} is not a tangential or normal component", fix)
        which = "n" if name.endswith("n") else "t"
        self.reaction(name[:-1], fa, entry)
        try:
            component(fa, name[:-1], which)
        except KeyError:
            raise self.fail(entry, f"{name[:-1]} is not split into components", fix) from None
        return name[:-1], which

    def plan_force(self, name: str, fa: ForceAnalysis, entry: str) -> None:
        from .quantities import _named_force

        try:
            _named_force(fa, name)
        except (KeyError, ValueError):
            forces = [f"G{lid}" for lid in fa.loads.links] + [
                f"F_in{lid}" for lid in fa.loads.links
            ]
            forces += [f.name for f in fa.loads.production_resistance]
            forces += list(fa.reactions) + ["F_bal", "R12t", "R12n"]
            raise self.fail(
                entry,
                f"{name!r} is not a force of this mechanism's force plans",
                f"forces: {', '.join(forces)}",
            ) from None

    def arm(self, name: str, fa: ForceAnalysis, entry: str) -> None:
        from .quantities import arm_forces

        forces = list(arm_forces(fa))
        if name not in forces:
            raise self.fail(
                entry,
                f"{name!r} is not a force of a group's moment equation about its inner pin",
                f"forces with an arm h': {', '.join(forces) or 'none in this mechanism'}",
            )

    def lever_name(self, name: str, fa: ForceAnalysis, entry: str) -> tuple:
        lever = fa.lever
        labels = [f.label for f in lever.forces] + ["F_bal"]
        if name.startswith("h_") and name[2:] in labels:
            return ()
        if name[:1] == "p" and name[1:] in {k.lower(): k for k in lever.images}:
            return ({k.lower(): k for k in lever.images}[name[1:]],)
        raise self.fail(
            entry,
            f"{name!r} is not a segment or an arm of Zhukovsky's lever",
            "write p and a point's image (pa, ps2, pk2) or h_ and a force "
            f"({', '.join('h_' + x for x in labels)})",
        )

    # --- [diagrams] -----------------------------------------------------------------
    def grid(self, table: dict, entry: str) -> Grid | None:
        """The student's grid: `divisions` of the turn, with the pole distances
        and the time axis when given (README, "The student's own method")."""
        if "divisions" not in table:
            for key in ("H_V_mm", "H_a_mm", "L_mm"):
                if key in table:
                    raise self.fail(
                        f"{entry}.{key}",
                        "a pole distance or time axis needs the grid it was drawn on",
                        f"add divisions = <the number of equal parts of the turn> to [{entry}]",
                    )
            return None
        value = table["divisions"]
        n = self.analysis.mechanism.study.positions
        if isinstance(value, bool) or not isinstance(value, int) or not 4 <= value <= 720:
            raise self.fail(
                f"{entry}.divisions",
                f"must be a whole number of divisions of the turn, 4 to 720, not {show_value(value)}",
                f"write divisions = {n} (one per position) or a multiple of it",
            )
        if self.analysis.diagrams is None:
            raise self.fail(
                f"{entry}.divisions",
                f"this mechanism has no kinematic diagrams: {self.analysis.diagrams_problem}",
                "leave out [diagrams]",
            )
        sizes = {}
        for key in ("H_V_mm", "H_a_mm", "L_mm"):
            if key in table:
                sizes[key] = self.number(
                    table[key], f"{entry}.{key}", positive=True, minimum=MU_MIN, maximum=1e6
                )
        return Grid(value, sizes.get("H_V_mm"), sizes.get("H_a_mm"), sizes.get("L_mm"))

    def diagrams(self, table: Any, entry: str) -> list[Answer]:
        """The output's diagrams: ordinates in mm and the 5 % check against the plans."""
        self.check_keys(table, "diagrams", entry)
        n = self.analysis.mechanism.study.positions
        out = []
        for key, (what, scale) in _DIAGRAM_TABLES.items():
            if key not in table:
                continue
            where = f"{entry}.{key}"
            mu = self.scale(table, scale, entry) or self.derived(table, scale, entry)
            if mu is None:
                raise self.fail(
                    where,
                    f"ordinates in mm need the diagram's scale {scale}",
                    f"add {scale} = <scale per mm> to [{entry}]",
                )
            for name, raw in self.values_of(table, key, where).items():
                name = self.key(str(name), where)
                at = f"{where}.{name}"
                if not name.isdigit() or not 0 <= int(name) < n:
                    raise self.fail(
                        at,
                        f"{name!r} is not a position number",
                        f'key each ordinate by its position 0..{n - 1}, e.g. "3" = 41.5',
                    )
                value = self.number(raw, at)
                w = self.exact.where(index=int(name))
                label = f"{what} ordinate"
                out.append(
                    Answer(at, w, "diagram", name, value, True, label, mu, None, None, (what,))
                )
        if any(k in table for k in ("check_passed", *_CHECK_TABLES)):
            out += self.sheet_check(table, entry)
        return out

    def derived(self, table: dict, scale: str, entry: str) -> float | None:
        """μV = μS/(μt·H_V), μa = μV/(μt·H_a) (seed 003 §1.7) from the student's
        pole distances, μt = 60/(n1·L), when the scale itself is not given."""
        from ..diagrams import DEFAULT_TIME_AXIS_MM, derived_scale, time_scale

        pole = {"mu_V": "H_V_mm", "mu_a": "H_a_mm"}.get(scale)
        source = {"mu_V": "mu_S", "mu_a": "mu_V"}.get(scale)
        if pole is None or source is None or pole not in table:
            return None
        mu_source = self.scale(table, source, entry) or self.derived(table, source, entry)
        if mu_source is None:
            return None
        L = table.get("L_mm", DEFAULT_TIME_AXIS_MM)
        H = self.number(table[pole], f"{entry}.{pole}", positive=True, minimum=MU_MIN, maximum=1e6)
        L = self.number(L, f"{entry}.L_mm", positive=True, minimum=MU_MIN, maximum=1e6)
        mu_t = time_scale(self.analysis.mechanism.drive.n1_rpm, L)
        return derived_scale(mu_source, mu_t, H)

    def sheet_check(self, table: dict, entry: str) -> list[Answer]:
        """The 5 % check's verdict and its values at the investigated positions."""
        dg = self.analysis.diagrams
        if dg is None:
            raise self.fail(
                entry,
                f"this mechanism has no kinematic diagrams: {self.analysis.diagrams_problem}",
                "leave out check_passed and the check's values",
            )
        sc = dg.sheet_check
        out = []
        if "check_passed" in table:
            value = table["check_passed"]
            if not isinstance(value, bool):
                raise self.fail(
                    f"{entry}.check_passed",
                    f"must be true or false, not {show_value(value)}",
                    "write check_passed = true (every δ within 5 %) or false",
                )
            w = self.exact.where(index=sc.values[0].index)
            out.append(
                Answer(
                    f"{entry}.check_passed",
                    w,
                    "check_verdict",
                    "",
                    1.0 if value else 0.0,
                    True,
                    "5 % check passed",
                )
            )
        investigated = sorted({v.index for v in sc.values})
        for key, (kind, quantity, column) in _CHECK_TABLES.items():
            if key not in table:
                continue
            where = f"{entry}.{key}"
            for name, raw in self.values_of(table, key, where).items():
                name = self.key(str(name), where)
                at = f"{where}.{name}"
                if not name.isdigit() or int(name) not in investigated:
                    raise self.fail(
                        at,
                        f"{name!r} is not an investigated position of the 5 % check",
                        "key each value by an investigated position: "
                        + ", ".join(f'"{i}"' for i in investigated),
                    )
                val = next(v for v in sc.values if v.index == int(name) and v.quantity == quantity)
                if column == "error" and val.ill_conditioned:
                    raise self.fail(
                        at,
                        f"at position {name} the plan's value is near zero: the check takes "
                        "its absolute error, not a percentage",
                        f"leave {key} out at position {name}",
                    )
                value = self.number(raw, at)
                label = {
                    "plan": f"{quantity.upper() if quantity == 'v' else 'a'} (plan)",
                    "diagram": f"{quantity.upper() if quantity == 'v' else 'a'} (diagram)",
                    "error": f"δ{'V' if quantity == 'v' else 'a'} %",
                }[column]
                w = self.exact.where(index=int(name))
                out.append(
                    Answer(
                        at, w, kind, name, value, True, label, None, None, None, (column, quantity)
                    )
                )
        return out


def segment_name(kind: str, segment: tuple[str, str], *, dash: bool = False) -> str:
    """The segment as an answers file writes it (a point named like a pole in capitals)."""
    pole = "p" if kind == "velocity_plan_mm" else "pi"
    poles = VELOCITY_POLES if kind == "velocity_plan_mm" else ACCELERATION_POLES
    return ("-" if dash else "").join(
        pole if e == POLE else e.lower() if e.lower() not in poles else e.upper() for e in segment
    )


def _inside(phi: float, ranges: tuple[tuple[float, float], ...]) -> bool:
    for lo, hi in ranges:
        if hi - lo >= 360.0:
            return True
        span = (hi - lo) % 360.0
        if (phi - lo) % 360.0 <= span:
            return True
    return False


def _scales(kind: str, mu_v: float | None, mu_a: float | None) -> tuple[float | None, float | None]:
    """(this plan's μ, the other plan's μ) for a value read off a plan."""
    if kind in ("velocity", "velocity_plan_mm"):
        return mu_v, mu_a
    if kind in ("acceleration", "acceleration_plan_mm"):
        return mu_a, mu_v
    return None, None


def _as_list(value: Any) -> list:
    return value if isinstance(value, list) else [value]


def _suggest(name: str, allowed: list[str] | tuple[str, ...], what: str) -> str:
    same_case = [a for a in allowed if a.lower() == name.lower()]
    close = same_case or difflib.get_close_matches(name, allowed, n=1)
    if close:
        return f"did you mean '{close[0]}'? {what}: {', '.join(allowed)}"
    return f"{what}: {', '.join(allowed)}"
