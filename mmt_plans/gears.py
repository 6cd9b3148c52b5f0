"""Gear trains between the motor and the crank: ordinary pairs and planetary stages.

Task 1 of seed 002 ("Визначення передаточного відношення зубчастого
механізму") and section 3 of seed 000. Ratios are signed as there: an external
mesh reverses the sense of rotation (u < 0), an internal one keeps it (u > 0);
a planetary stage is reduced to an ordinary train by holding the carrier
(Willis' method).

Entries in error messages count stages and meshes from 1, as a reader counts
the ``[[gears.stage]]`` blocks of the file: ``gears.stage[2].meshes[1].z``.
"""

from __future__ import annotations

import difflib
import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from fractions import Fraction
from typing import Any, Literal, TypeAlias, get_args

from mmt_plans.errors import SpecError
from mmt_plans.i18n import Language, catalogue, check_language

MeshKind: TypeAlias = Literal["external", "internal"]
StageKind: TypeAlias = Literal["pair", "planetary"]
Lang: TypeAlias = Language

MESH_KINDS: tuple[str, ...] = get_args(MeshKind)
STAGE_KINDS: tuple[str, ...] = get_args(StageKind)

_MINUS = "\u2212"


@dataclass(frozen=True)
class GearPair:
    """Two meshing gears, driving gear first: ``z = (z1, z2)``."""

    z: tuple[int, int]
    mesh: MeshKind

    def __post_init__(self) -> None:
        z = tuple(self.z)
        if len(z) != 2 or not all(_is_teeth(n) for n in z):
            raise ValueError(f"z must be two positive whole numbers, got {self.z!r}")
        if self.mesh not in MESH_KINDS:
            raise ValueError(f"mesh must be one of {MESH_KINDS}, got {self.mesh!r}")
        object.__setattr__(self, "z", z)

    @property
    def exact_ratio(self) -> Fraction:
        """u12 = −z2/z1 external (seed 000 eq. 1.18), +z2/z1 internal (eq. 1.19)."""
        sign = -1 if self.mesh == "external" else 1
        return sign * Fraction(self.z[1], self.z[0])

    @property
    def ratio(self) -> float:
        return float(self.exact_ratio)


@dataclass(frozen=True)
class PlanetaryStage:
    """Meshes from the input central gear to the fixed central gear; carrier H is the output.

    Consecutive meshes share a shaft on the carrier: the driven gear of one
    mesh turns with the driving gear of the next (a satellite block z4–z4',
    or one satellite meshing with both central gears).
    """

    meshes: tuple[GearPair, ...]

    def __post_init__(self) -> None:
        meshes = tuple(self.meshes)
        if len(meshes) < 2:
            raise ValueError(
                "a planetary stage needs two meshes or more (central, satellite, central)"
            )
        object.__setattr__(self, "meshes", meshes)
        if self.exact_carrier_held_ratio == 1:
            raise ValueError("u^H = 1: the carrier cannot turn (u_1H = 0)")

    @property
    def exact_carrier_held_ratio(self) -> Fraction:
        """u_1n^H, carrier held: the product of the signed mesh ratios (seed 000 eq. 1.21)."""
        u = Fraction(1)
        for mesh in self.meshes:
            u *= mesh.exact_ratio
        return u

    @property
    def carrier_held_ratio(self) -> float:
        return float(self.exact_carrier_held_ratio)

    @property
    def exact_ratio(self) -> Fraction:
        """Willis, gear n fixed: u_1H^(n) = 1 − u_1n^H (seed 000 eq. 1.25–1.26; seed 002 §1.3)."""
        return 1 - self.exact_carrier_held_ratio

    @property
    def ratio(self) -> float:
        return float(self.exact_ratio)


Stage: TypeAlias = GearPair | PlanetaryStage


@dataclass(frozen=True)
class Step:
    """One line of the calculation note: formula, numbers substituted, result (seed 002, §1)."""

    title: str
    formula: str
    substituted: str
    result: str

    def __str__(self) -> str:
        return f"{self.formula} = {self.substituted} = {self.result}"


@dataclass(frozen=True)
class GearTrain:
    """Motor → stages → crank. ``ratio`` is the signed u_m1 = ω_motor/ω_crank."""

    motor_rpm: float
    stages: tuple[Stage, ...]

    def __post_init__(self) -> None:
        stages = tuple(self.stages)
        if not stages:
            raise ValueError("a gear train needs at least one stage")
        if not (math.isfinite(self.motor_rpm) and self.motor_rpm > 0):
            raise ValueError(f"motor_rpm must be a positive number, got {self.motor_rpm!r}")
        object.__setattr__(self, "stages", stages)

    @property
    def exact_ratio(self) -> Fraction:
        """u_m1 = u12·u34·…, the product of the stage ratios (seed 000 eq. 1.21; seed 002 §1.5)."""
        u = Fraction(1)
        for stage in self.stages:
            u *= stage.exact_ratio
        return u

    @property
    def ratio(self) -> float:
        return float(self.exact_ratio)

    @property
    def gear_labels(self) -> list[list[str]]:
        """The gears of each stage as seed 002 numbers them: [["1", "2"], ["3", "4", "4'", "5"]]."""
        return _gear_labels(self.stages)

    @property
    def crank_rpm(self) -> float:
        """n1 = n_m/u_m1, signed: negative when the crank turns against the motor."""
        return self.motor_rpm / self.ratio

    @property
    def motor_omega(self) -> float:
        """ω_m = π·n_m/30, rad/s (seed 002 §1.6)."""
        return math.pi * self.motor_rpm / 30

    @property
    def omega(self) -> float:
        """ω1 = π·|n1|/30 = ω_m/|u_m1|, rad/s, a magnitude (seed 002 §1.6)."""
        return math.pi * abs(self.crank_rpm) / 30

    @classmethod
    def from_toml(cls, table: Mapping[str, Any], path: str) -> GearTrain:
        """Read the ``[gears]`` table of a mechanism file (SPEC_FORMAT.md, "Gears")."""
        if not isinstance(table, Mapping):
            raise SpecError(
                path,
                "gears",
                "must be a table",
                "write [gears] with motor_rpm and [[gears.stage]] blocks",
            )
        _check_keys(table, ("motor_rpm", "stage"), "gears", path)
        motor_rpm = _read_motor_rpm(table, path)
        raw_stages = table.get("stage")
        if raw_stages is None or (isinstance(raw_stages, list) and not raw_stages):
            raise SpecError(
                path,
                "gears.stage",
                "no stages given",
                'add a [[gears.stage]] with z = [z1, z2] and mesh = "external"',
            )
        if not isinstance(raw_stages, list):
            raise SpecError(
                path,
                "gears.stage",
                "must be an array of tables",
                "write each stage as its own [[gears.stage]] block",
            )
        stages = tuple(
            _read_stage(raw, f"gears.stage[{i}]", path) for i, raw in enumerate(raw_stages, 1)
        )
        return cls(motor_rpm=motor_rpm, stages=stages)

    def steps(self, lang: Lang = "en") -> list[Step]:
        """The calculation note of task 1, in the order of seed 002 §1.3–1.6."""
        words = catalogue(check_language(lang)).words("gears")
        labels = _gear_labels(self.stages)
        out: list[Step] = []
        stage_names: list[str] = []
        stage_values: list[Fraction] = []
        for stage, gears in zip(self.stages, labels):
            if isinstance(stage, GearPair):
                name = "u" + _join(gears[0], gears[1])
                sym, num = _mesh_terms(stage, gears[0], gears[1])
                out.append(
                    Step(words["pair"], f"{name} = {sym}", num, _ratio(stage.exact_ratio, lang))
                )
            else:
                first, last = gears[0], gears[-1]
                held = f"u{_join(first, last)}^H"
                name = f"u{_join(first, 'H')}^{last}"
                terms = [
                    _mesh_terms(m, gears[2 * k], gears[2 * k + 1])
                    for k, m in enumerate(stage.meshes)
                ]
                out.append(
                    Step(
                        words["held"],
                        f"{held} = " + "·".join(f"({s})" for s, _ in terms),
                        "·".join(f"({n})" for _, n in terms),
                        _ratio(stage.exact_carrier_held_ratio, lang),
                    )
                )
                out.append(
                    Step(
                        words["willis"],
                        f"{name} = 1 {_MINUS} {held}",
                        f"1 {_MINUS} {_paren(stage.exact_carrier_held_ratio, lang)}",
                        _ratio(stage.exact_ratio, lang),
                    )
                )
            stage_names.append(name)
            stage_values.append(stage.exact_ratio)
        # A single stage is the whole train: its own name stands for u_m1.
        total = words["u_total"] if len(self.stages) > 1 else stage_names[0]
        if len(self.stages) > 1:
            out.append(
                Step(
                    words["train"],
                    f"{total} = " + "·".join(stage_names),
                    "·".join(_paren(v, lang) for v in stage_values),
                    _ratio(self.exact_ratio, lang),
                )
            )
        w_m, rad = words["omega_m"], words["rad/s"]
        out.append(
            Step(
                words["motor"],
                f"{w_m} = π·{words['n_m']}/30",
                f"π·{_num(self.motor_rpm, None, lang)}/30",
                f"{_num(self.motor_omega, 2, lang)} {rad}",
            )
        )
        out.append(
            Step(
                words["crank"],
                f"ω1 = {w_m}/|{total}|",
                f"{_num(self.motor_omega, 2, lang)}/{_ratio(abs(self.exact_ratio), lang)}",
                f"{_num(self.omega, 2, lang)} {rad}",
            )
        )
        # Seed 002 §1.6 closes task 1 with ε1: constant motor speed through a constant ratio.
        out.append(
            Step(words["eps"], "ε1 = dω1/dt", f"d({w_m}/|{total}|)/dt", f"0 {words['rad/s2']}")
        )
        return out


def _gear_labels(stages: Sequence[Stage]) -> list[list[str]]:
    """Number the gears as seed 002 does: 1, 2 | 3, 4, 4', 5.

    A new stage starts a new number (its input gear sits on the previous
    output shaft, as gear 3 with gear 2); a satellite block on the carrier gets
    a prime (z4'). Equal tooth counts on one shaft are taken as one gear, so a
    single satellite meshing with both central gears stays z2 (seed 000 eq. 1.26).
    """
    labels: list[list[str]] = []
    number = 0
    last_teeth: int | None = None
    for stage in stages:
        meshes = stage.meshes if isinstance(stage, PlanetaryStage) else (stage,)
        gears: list[str] = []
        for k, mesh in enumerate(meshes):
            z_in, z_out = mesh.z
            if k == 0 and z_in == last_teeth and labels:
                gears.append(labels[-1][-1])
            elif k == 0:
                number += 1
                gears.append(str(number))
            elif z_in == last_teeth:
                gears.append(gears[-1])
            else:
                gears.append(gears[-1] + "'")
            number += 1
            gears.append(str(number))
            last_teeth = z_out
        labels.append(gears)
    return labels


def _join(a: str, b: str) -> str:
    # u12 as the textbooks write it; a separator only once numbers reach two digits.
    return a + b if max(len(a.rstrip("'")), len(b.rstrip("'"))) == 1 else f"{a},{b}"


def _mesh_terms(mesh: GearPair, a: str, b: str) -> tuple[str, str]:
    sign = _MINUS if mesh.mesh == "external" else "+"
    return f"{sign}z{b}/z{a}", f"{sign}{mesh.z[1]}/{mesh.z[0]}"


def _num(x: float, digits: int | None, lang: Lang) -> str:
    # digits=None: a given value (motor rpm) is written as given, 1450 not 1450.00.
    text = f"{x:g}" if digits is None else f"{x:.{digits}f}"
    text = text.replace("-", _MINUS)
    return catalogue(lang).localise(text)


def _ratio(u: Fraction | float, lang: Lang) -> str:
    # Three decimals as in the examples; a reduction like 1/10000 keeps its significant digits.
    x = float(u)
    text = f"{x:.3f}" if x == 0 or abs(x) >= 0.1 else f"{x:.4g}"
    text = text.replace("-", _MINUS)
    return catalogue(lang).localise(text)


def _paren(u: Fraction, lang: Lang) -> str:
    text = _ratio(u, lang)
    return f"({text})" if u < 0 else text


def _is_number(x: object) -> bool:
    return isinstance(x, (int, float)) and not isinstance(x, bool)


def _is_teeth(x: object) -> bool:
    # TOML's true is a Python int; a tooth count is not.
    return isinstance(x, int) and not isinstance(x, bool) and x > 0


def _check_keys(
    table: Mapping[str, Any],
    allowed: Sequence[str],
    entry: str,
    path: str,
    elsewhere: Mapping[str, str] | None = None,
) -> None:
    for key in table:
        if key in allowed:
            continue
        if elsewhere and key in elsewhere:
            raise SpecError(path, f"{entry}.{key}", f"{key!r} does not belong here", elsewhere[key])
        close = difflib.get_close_matches(str(key), allowed, n=1)
        fix = f"did you mean {close[0]!r}?" if close else "allowed keys: " + ", ".join(allowed)
        raise SpecError(path, f"{entry}.{key}", "unknown key", fix)


def _read_motor_rpm(table: Mapping[str, Any], path: str) -> float:
    if "motor_rpm" not in table:
        raise SpecError(
            path, "gears.motor_rpm", "missing", "add motor_rpm = 1450 (the motor speed, 1/min)"
        )
    rpm = table["motor_rpm"]
    try:
        finite = _is_number(rpm) and math.isfinite(rpm)
    except OverflowError:  # an integer too large for a float (310 digits)
        finite = False
    if not finite or rpm <= 0:
        raise SpecError(
            path,
            "gears.motor_rpm",
            f"must be a positive number of rpm, got {_shown_number(rpm)}",
            "write the motor speed in 1/min, e.g. motor_rpm = 1450",
        )
    return float(rpm)


def _shown_number(x: object) -> str:
    text = (
        repr(x)
        if not isinstance(x, int) or abs(x) < 10**30
        else f"an integer of {len(str(abs(x)))} digits"
    )
    return text


def _choice(value: object, allowed: Sequence[str], entry: str, path: str) -> str:
    if isinstance(value, str) and value in allowed:
        return value
    close = difflib.get_close_matches(value, allowed, n=1) if isinstance(value, str) else []
    # Values are TOML strings, so the suggestion is quoted the way it is to be written.
    quoted = ", ".join(f'"{a}"' for a in allowed)
    fix = f'did you mean "{close[0]}"?' if close else f"write one of {quoted}"
    raise SpecError(path, entry, f"{value!r} is not one of {', '.join(allowed)}", fix)


def _read_pair(
    raw: object, entry: str, path: str, elsewhere: Mapping[str, str] | None = None
) -> GearPair:
    if not isinstance(raw, Mapping):
        raise SpecError(path, entry, "must be a table", 'write { z = [z1, z2], mesh = "external" }')
    allowed = ("z", "mesh") if elsewhere is None else ("kind", "z", "mesh")
    _check_keys(raw, allowed, entry, path, elsewhere)
    if "z" not in raw:
        raise SpecError(path, f"{entry}.z", "missing", "add z = [z1, z2], driving gear first")
    z = raw["z"]
    if not (isinstance(z, (list, tuple)) and len(z) == 2 and all(_is_teeth(n) for n in z)):
        raise SpecError(
            path,
            f"{entry}.z",
            f"must be a list of two positive whole numbers, got {z!r}",
            "write the tooth counts, driving gear first, e.g. z = [25, 50]",
        )
    if "mesh" not in raw:
        raise SpecError(
            path, f"{entry}.mesh", "missing", 'add mesh = "external" or mesh = "internal"'
        )
    mesh = _choice(raw["mesh"], MESH_KINDS, f"{entry}.mesh", path)
    return GearPair(z=(z[0], z[1]), mesh=mesh)  # type: ignore[arg-type]


def _read_stage(raw: object, entry: str, path: str) -> Stage:
    if not isinstance(raw, Mapping):
        raise SpecError(
            path, entry, "must be a table", "write the stage as a [[gears.stage]] block"
        )
    kind = _choice(raw.get("kind", "pair"), STAGE_KINDS, f"{entry}.kind", path)
    if kind == "pair":
        return _read_pair(
            raw,
            entry,
            path,
            elsewhere={"meshes": 'meshes belong to a planetary stage: add kind = "planetary"'},
        )
    in_meshes = 'a planetary stage lists its gears in meshes = [{ z = [..], mesh = ".." }, ...]'
    _check_keys(raw, ("kind", "meshes"), entry, path, elsewhere={"z": in_meshes, "mesh": in_meshes})
    meshes = raw.get("meshes")
    if not isinstance(meshes, list) or len(meshes) < 2:
        raise SpecError(
            path,
            f"{entry}.meshes",
            "a planetary stage needs a list of two meshes or more, from the input "
            "central gear through the satellites to the fixed central gear",
            'write meshes = [{ z = [20, 30], mesh = "external" }, '
            '{ z = [30, 80], mesh = "internal" }]',
        )
    pairs = tuple(_read_pair(m, f"{entry}.meshes[{k}]", path) for k, m in enumerate(meshes, 1))
    try:
        return PlanetaryStage(meshes=pairs)
    except ValueError as err:
        raise SpecError(
            path,
            f"{entry}.meshes",
            str(err),
            "check the tooth counts and meshes: with the carrier held the train must not be 1:1",
        ) from err
