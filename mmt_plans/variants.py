"""New variants of a task from one mechanism file (`mmt-plans variants`).

Every length (the links' point coordinates, the frame's points, the guides'
offsets), every mass, the crank speed and the loads are varied within
±spread % by a seeded random draw and rounded as a task table rounds them:
lengths to whole millimetres, masses to whole kilograms (tenths below 10 kg),
speeds to whole rpm, forces to whole newtons (tens above 1000 N). A variant is
kept only when

- its structure is the source's (the same formula and kinds of groups);
- it assembles over the whole turn on the source's combination of branches
  (written into the variant as a `[sketch]`, so it is analysed on it);
- its smallest transmission angle over the turn (the angle between the two
  direction lines of every group's velocity plan, γ for a four-bar) is at
  least TRANSMISSION_FLOOR_DEG, or the source's own less 10 % where the source
  itself is below that floor;
- it differs from every variant kept before by at least 2 % in some length.

The same source, seed and spread give the same files, byte for byte.
"""

from __future__ import annotations

import copy
import math
import random
import re
import tomllib
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from .errors import MmtError
from .files import read_input
from .kinematics.branches import turns_fully
from .kinematics.handle import kinematics
from .spec import loads
from .structure import analyse_structure

__all__ = ["Variant", "make_variants", "to_toml", "TRANSMISSION_FLOOR_DEG", "DISTINCT"]

TRANSMISSION_FLOOR_DEG = 30.0
DISTINCT = 0.02  # a variant differs from every other by this much in some length
ATTEMPTS_PER_VARIANT = 60
GRID = np.linspace(0.0, 360.0, 360, endpoint=False)


@dataclass(frozen=True)
class Variant:
    number: int
    text: str  # the mechanism file
    lengths: tuple[float, ...]  # every varied length, mm (the distinctness test)
    masses: tuple[float, ...]
    rpm: float | None
    transmission_min_deg: float


class VariantError(MmtError, ValueError):
    """Not enough variants could be made from the source."""


# --- drawing the numbers -------------------------------------------------------------------


def _length(x: float, f: float) -> float:
    return float(round(x * f))


def _mass(m: float, f: float) -> float:
    v = m * f
    return float(round(v)) if v >= 10 else round(v, 1)


def _force(F: float, f: float) -> float:
    v = F * f
    return float(round(v, -1)) if v >= 1000 else float(round(v))


def _vary(data: dict, rng: random.Random, spread: float) -> dict:
    """A copy of the file's tables with every length, mass, speed and load varied."""
    d = copy.deepcopy(data)

    def f() -> float:
        return 1.0 + rng.uniform(-spread, spread)

    frame = d.get("frame", {})
    for name in sorted(frame):
        x, y = frame[name]
        frame[name] = [_length(x, f()), _length(y, f())]
    for link in d.get("link", []):
        points = link.get("points", {})
        for name in list(points):
            x, y = points[name]
            if x == 0 and y == 0:
                continue  # the link's own origin
            k = f()  # the point moves along its radius: the link keeps its shape's angles
            points[name] = [_length(x, k), _length(y, k)]
        if "mass" in link and link["mass"]:
            link["mass"] = _mass(float(link["mass"]), f())
        if "J" in link and link["J"]:
            link["J"] = round(float(link["J"]) * f(), 4)
    for slider in d.get("slider", []):
        if "through" in slider:
            x, y = slider["through"]
            slider["through"] = [_length(x, f()), _length(y, f())]
    drive = d.get("drive", {})
    if "rpm" in drive:
        drive["rpm"] = float(round(float(drive["rpm"]) * f()))
    elif "omega" in drive:
        drive["omega"] = round(float(drive["omega"]) * f(), 1)
    for force in d.get("force", []):
        if "magnitude" in force:
            force["magnitude"] = _force(float(force["magnitude"]), f())
    d.pop("sketch", None)  # written again for the source's branches
    return d


def _lengths(data: dict) -> tuple[float, ...]:
    out: list[float] = []
    for name in sorted(data.get("frame", {})):
        out += [abs(v) for v in data["frame"][name]]
    for link in data.get("link", []):
        for name in sorted(link.get("points", {})):
            out.append(math.hypot(*link["points"][name]))
    for slider in data.get("slider", []):
        out += [abs(v) for v in slider.get("through", [])]
    return tuple(out)


def _distinct(a: tuple[float, ...], b: tuple[float, ...]) -> bool:
    return any(abs(x - y) > DISTINCT * max(abs(x), abs(y), 1.0) for x, y in zip(a, b))


# --- checking a candidate ------------------------------------------------------------------


def _transmission_min_deg(chain: Any) -> float:
    sw = chain.sweep(GRID)
    if not sw.plans:
        return 90.0
    sines = np.min([np.asarray(p.sin_angle) for p in sw.plans], axis=0)
    return float(np.degrees(np.arcsin(np.clip(np.nanmin(sines), 0.0, 1.0))))


def _on_branches(mech: Any, signs: dict[str, int]) -> tuple[Any, bool]:
    """The chain of `mech` on the branch signs, and whether it turns fully on them."""
    from .kinematics.chain import Chain

    chain = Chain.build(mech)
    chain.branches = dict(signs)
    return chain, turns_fully(chain, signs)


def _sketch(chain: Any, mech: Any) -> dict[str, list[float]]:
    """The points of every group at the crank angle 30° on the chain's
    branches, and the crank pin: the variant's [sketch], in mm."""
    phi = np.radians(np.array([30.0]))
    m = chain.place(phi, chain.branches)
    out: dict[str, list[float]] = {}
    names = [mech.crank_pin] + [
        p for s in chain.solvers for lid in (s.L1, s.L2) for p in mech.links[lid].points
    ]
    for name in names:
        lid, local = chain.locate[name]
        z = complex(np.ravel(m[lid].at(local))[0]) * 1e3
        out.setdefault(name, [round(z.real, 3), round(z.imag, 3)])
    return out


def make_variants(
    path: str | Path,
    count: int,
    seed: int,
    spread_percent: float = 15.0,
    progress: Callable[[int], None] | None = None,
) -> list[Variant]:
    """`count` variants of the mechanism file at `path` (module docstring)."""
    if not 1 <= count <= 500:
        raise VariantError(f"--count must be 1 .. 500, not {count}")
    if not 0.0 < spread_percent <= 50.0:
        raise VariantError(f"--spread must be in (0, 50] %, not {spread_percent}")
    text = read_input(path)
    data = tomllib.loads(text.lstrip("\ufeff"))
    source = loads(text, str(path))
    structure = analyse_structure(source)
    handle = kinematics(source, structure)
    if not handle.branches.whole_turn:
        raise VariantError(f"{path}: the source itself does not turn fully")
    signs = dict(handle.branches.signs)
    kinds = [g.kind for g in structure.groups]
    floor = min(TRANSMISSION_FLOOR_DEG, 0.9 * _transmission_min_deg(handle))
    rng = random.Random(f"{seed}")
    kept: list[Variant] = []
    seen = [_lengths(data)]
    attempts = 0
    while len(kept) < count and attempts < count * ATTEMPTS_PER_VARIANT:
        attempts += 1
        d = _vary(data, rng, spread_percent / 100.0)
        lengths = _lengths(d)
        if not all(_distinct(lengths, other) for other in seen):
            continue
        number = len(kept) + 1
        d["title"] = f"{data.get('title', Path(path).stem)} — variant {number}"
        if "title_uk" in data:
            d["title_uk"] = f"{data['title_uk']} — варіант {number}"
        try:
            mech = loads(to_toml(d), f"{path} (variant)")
            st = analyse_structure(mech)
            if st.formula != structure.formula or [g.kind for g in st.groups] != kinds:
                continue
            chain, turns = _on_branches(mech, signs)
            if not turns:
                continue
            gamma = _transmission_min_deg(chain)
            if gamma < floor:
                continue
            d["sketch"] = _sketch(chain, mech)
            body = to_toml(d)
            check = kinematics(loads(body, "variant")).branches
            if dict(check.signs) != signs or not check.whole_turn:
                continue
        except (MmtError, ValueError, ArithmeticError):
            continue
        header = (
            f"# Variant {number} of {Path(path).name} (seed {seed}, spread ±{spread_percent:g} %),\n"
            f"# made by mmt-plans variants: lengths, masses, speed and loads varied and\n"
            f"# rounded; the same structure and branches as the source; smallest\n"
            f"# transmission angle {gamma:.1f}° (floor {floor:.1f}°).\n\n"
        )
        masses = tuple(float(lk.get("mass", 0.0)) for lk in d.get("link", []))
        rpm = d.get("drive", {}).get("rpm")
        kept.append(Variant(number, header + body, lengths, masses, rpm, gamma))
        seen.append(lengths)
        if progress:
            progress(1)
    if len(kept) < count:
        raise VariantError(
            f"{path}: only {len(kept)} of {count} variants after {attempts} draws with seed "
            f"{seed} and spread ±{spread_percent:g} %: try a smaller --spread or another --seed"
        )
    return kept


# --- writing TOML ----------------------------------------------------------------------------

_BARE = re.compile(r"^[A-Za-z0-9_-]+$")


def _key(k: str) -> str:
    return k if _BARE.match(k) else _string(k)


def _string(s: str) -> str:
    out = ['"']
    for ch in s:
        if ch in '"\\':
            out.append("\\" + ch)
        elif ord(ch) < 0x20 or ord(ch) == 0x7F:
            out.append(f"\\u{ord(ch):04x}")
        else:
            out.append(ch)
    return "".join(out) + '"'


def _value(v: Any) -> str:
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, int):
        return str(v)
    if isinstance(v, float):
        if not math.isfinite(v):
            raise ValueError(f"not a finite number: {v!r}")
        return str(int(v)) if v.is_integer() and abs(v) < 1e15 else repr(v)
    if isinstance(v, str):
        return _string(v)
    if isinstance(v, list):
        return "[" + ", ".join(_value(x) for x in v) + "]"
    if isinstance(v, dict):
        return "{ " + ", ".join(f"{_key(k)} = {_value(x)}" for k, x in v.items()) + " }"
    raise ValueError(f"cannot write {type(v).__name__} to TOML")


def _is_tables(v: Any) -> bool:
    return isinstance(v, list) and bool(v) and all(isinstance(x, dict) for x in v)


def to_toml(data: dict) -> str:
    """The tables of a mechanism file as TOML text (what tomllib reads back)."""
    lines: list[str] = []
    for k, v in data.items():
        if not isinstance(v, dict) and not _is_tables(v):
            lines.append(f"{_key(k)} = {_value(v)}")
    for k, v in data.items():
        if isinstance(v, dict):
            lines += ["", f"[{_key(k)}]"]
            nested = []
            for kk, vv in v.items():
                if _is_tables(vv):
                    nested.append((kk, vv))
                else:
                    lines.append(f"{_key(kk)} = {_value(vv)}")
            for kk, tables in nested:
                for t in tables:
                    lines += ["", f"[[{_key(k)}.{_key(kk)}]]"]
                    lines += [f"{_key(a)} = {_value(b)}" for a, b in t.items()]
        elif _is_tables(v):
            for t in v:
                lines += ["", f"[[{_key(k)}]]"]
                lines += [f"{_key(a)} = {_value(b)}" for a, b in t.items()]
    return "\n".join(lines).lstrip("\n") + "\n"


def write_variants(variants: list[Variant], source: str | Path, out_dir: str | Path) -> list[Path]:
    """Each variant as OUT/<stem>_vNN.toml and a table of all as OUT/variants.csv."""
    import csv
    import io

    from .files import ensure_dir, write_text_atomic

    out = ensure_dir(out_dir)
    stem = Path(source).stem
    written = []
    for v in variants:
        written.append(write_text_atomic(out / f"{stem}_v{v.number:02d}.toml", v.text))
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    n_len = max((len(v.lengths) for v in variants), default=0)
    n_mass = max((len(v.masses) for v in variants), default=0)
    w.writerow(
        ["file", "rpm", "transmission_min_deg"]
        + [f"length_{i + 1}_mm" for i in range(n_len)]
        + [f"mass_{i + 1}_kg" for i in range(n_mass)]
    )
    for v in variants:
        w.writerow(
            [
                f"{stem}_v{v.number:02d}.toml",
                "" if v.rpm is None else f"{v.rpm:g}",
                f"{v.transmission_min_deg:.2f}",
            ]
            + [f"{x:g}" for x in v.lengths]
            + [f"{m:g}" for m in v.masses]
        )
    written.append(write_text_atomic(out / "variants.csv", buf.getvalue()))
    return written
