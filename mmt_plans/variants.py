"""New variants of a task from one mechanism file (`mmt-plans variants`).

Every length (the links' point coordinates, the frame's points, the guides'
offsets), every mass, the crank speed and the loads are varied within
±spread % by a seeded random draw and rounded as a task table rounds them:
lengths to whole millimetres, masses to whole kilograms (tenths below 10 kg),
speeds to whole rpm, forces to whole newtons (tens above 1000 N) — and where
that rounding would leave the ±spread band, to the next step back inside it
(a mass of 18 kg at ±15 % is at most 20 kg, never 21). A centre of mass given
in the source (`cm`) moves with its link: it keeps its place along the line
of the link's first two points and across it, as a fraction of that line's
length (cm = [350, 0] on a 700 mm rocker stays at the middle of a 737 mm one);
a link without a second point keeps its cm. A variant is kept only when

- its structure is the source's (the same formula and kinds of groups);
- it assembles over the whole turn on the source's combination of branches
  (written into the variant as a `[sketch]`, so it is analysed on it);
- its smallest transmission angle over the turn (the angle between the two
  direction lines of every group's velocity plan, γ for a four-bar) is at
  least TRANSMISSION_FLOOR_DEG, or the source's own less 10 % where the source
  itself is below that floor;
- it differs from every variant kept before by at least 2 % in some length.

The same source, seed and spread give the same files, byte for byte. Each
file's header records its source (`# variant-of: <sha256 of the source> <n>`,
read back by `variant_source`), so that a quiz groups the variants of one
source in one category whatever their file names.
"""

from __future__ import annotations

import copy
import hashlib
import math
import random
import re
from collections import Counter
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from .errors import MmtError, shown
from .files import read_input
from .kinematics.branches import turns_fully
from .kinematics.handle import kinematics
from .spec import TITLE_MAX, loads, parse_toml
from .structure import analyse_structure

__all__ = [
    "Variant",
    "VariantError",
    "make_variants",
    "write_variants",
    "earlier_variants",
    "variant_source",
    "to_toml",
    "TRANSMISSION_FLOOR_DEG",
    "DISTINCT",
    "CSV_NAME",
]

CSV_NAME = "variants.csv"
_SOURCE_MARK = "# variant-of: "  # + the source's sha256 and the variant's number
_SOURCE_LINE = re.compile(r"^# variant-of: ([0-9a-f]{64}) (\d+)$", re.MULTILINE)

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
    # every varied quantity by its CSV column name, signed, in the file's order
    quantities: tuple[tuple[str, float], ...] = ()


class VariantError(MmtError, ValueError):
    """Not enough variants could be made from the source."""


# --- drawing the numbers -------------------------------------------------------------------


def _within(x: float, f: float, spread: float, step: float) -> float:
    """x·f rounded to a multiple of `step`, kept inside x·(1 ± spread): a
    rounding that would leave the band goes one step back towards x (x itself
    where no multiple lies inside)."""
    lo, hi = sorted((x * (1.0 - spread), x * (1.0 + spread)))
    v = round(x * f / step) * step
    if v > hi + 1e-9:
        v -= step
    elif v < lo - 1e-9:
        v += step
    if not lo - 1e-9 <= v <= hi + 1e-9:
        return float(x)
    return round(v, 6) + 0.0  # no -0.0, no 20.700000000000003


def _length(x: float, f: float, spread: float) -> float:
    return _within(x, f, spread, 1.0)


def _mass(m: float, f: float, spread: float) -> float:
    return _within(m, f, spread, 1.0 if m * f >= 10 else 0.1)


def _force(F: float, f: float, spread: float) -> float:
    return _within(F, f, spread, 10.0 if F * f >= 1000 else 1.0)


def _moved_cm(cm: list[float], before: list[list[float]], after: list[list[float]]) -> list[float]:
    """The centre of mass at the same place relative to the link's first two
    points (along and across their line, as fractions of its length)."""
    (x0, y0), (x1, y1) = before[0], before[1]
    (u0, v0), (u1, v1) = after[0], after[1]
    dx, dy = x1 - x0, y1 - y0
    n2 = dx * dx + dy * dy
    if n2 == 0.0:
        return list(cm)
    along = ((cm[0] - x0) * dx + (cm[1] - y0) * dy) / n2
    across = (-(cm[0] - x0) * dy + (cm[1] - y0) * dx) / n2
    ex, ey = u1 - u0, v1 - v0
    return [
        round(u0 + along * ex - across * ey, 1) + 0.0,
        round(v0 + along * ey + across * ex, 1) + 0.0,
    ]


def _vary(data: dict, rng: random.Random, spread: float) -> tuple[dict, list[tuple[str, float]]]:
    """A copy of the file's tables with every length, mass, speed and load
    varied, and every varied quantity by its CSV column name."""
    d = copy.deepcopy(data)
    named: list[tuple[str, float]] = []

    def f() -> float:
        return 1.0 + rng.uniform(-spread, spread)

    def point(prefix: str, xy: list[float], k: float | None = None) -> list[float]:
        # one factor k moves a link's point along its radius (the link keeps
        # its shape's angles); a frame point or a guide gets one per coordinate
        kx = f() if k is None else k
        ky = f() if k is None else k
        out = [_length(xy[0], kx, spread), _length(xy[1], ky, spread)]
        for axis, v, old in zip("xy", out, xy):
            if old != 0:
                named.append((f"{prefix}_{axis}_mm", v))
        return out

    frame = d.get("frame", {})
    for name in sorted(frame):
        frame[name] = point(f"frame.{name}", frame[name])
    for link in d.get("link", []):
        lid = link.get("id", "?")
        points = link.get("points", {})
        before = [list(map(float, xy)) for xy in points.values()]
        for name in list(points):
            x, y = points[name]
            if x == 0 and y == 0:
                continue  # the link's own origin
            points[name] = point(f"link{lid}.{name}", points[name], f())
        after = [list(map(float, xy)) for xy in points.values()]
        if "cm" in link and len(before) >= 2:
            link["cm"] = _moved_cm([float(v) for v in link["cm"]], before, after)
            for axis, v, old in zip("xy", link["cm"], _source_cm(link, data)):
                if old != 0:
                    named.append((f"link{lid}.cm_{axis}_mm", v))
        if "mass" in link and link["mass"]:
            link["mass"] = _mass(float(link["mass"]), f(), spread)
            named.append((f"link{lid}.mass_kg", link["mass"]))
        if "J" in link and link["J"]:
            J = float(link["J"])
            link["J"] = _within(J, f(), spread, 10.0 ** (math.floor(math.log10(abs(J))) - 3))
            named.append((f"link{lid}.J_kgm2", link["J"]))
    for i, slider in enumerate(d.get("slider", []), start=1):
        if "through" in slider:
            slider["through"] = point(f"slider{i}.through", slider["through"])
    drive = d.get("drive", {})
    if "rpm" in drive:
        drive["rpm"] = _within(float(drive["rpm"]), f(), spread, 1.0)
        named.append(("rpm", drive["rpm"]))
    elif "omega" in drive:
        drive["omega"] = _within(float(drive["omega"]), f(), spread, 0.1)
        named.append(("omega_rad_s", drive["omega"]))
    for i, force in enumerate(d.get("force", []), start=1):
        if "magnitude" in force:
            force["magnitude"] = _force(float(force["magnitude"]), f(), spread)
            named.append((f"{force.get('name', f'force{i}')}_N", force["magnitude"]))
    d.pop("sketch", None)  # written again for the source's branches
    return d, named


def _source_cm(link: dict, data: dict) -> list[float]:
    """The source's cm of `link` (matched by id)."""
    for source in data.get("link", []):
        if source.get("id") == link.get("id") and "cm" in source:
            return [float(v) for v in source["cm"]]
    return [0.0, 0.0]


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
    source = loads(text, str(path))  # every error as analyze reports it
    data = parse_toml(text.lstrip("\ufeff"), str(path))
    stem = file_stem(path)
    base_title = data.get("title", stem)
    _check_titles(path, base_title, data.get("title_uk"), count)
    digest = hashlib.sha256(text.encode("utf-8")).hexdigest()
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
    rejected: Counter[str] = Counter()
    while len(kept) < count and attempts < count * ATTEMPTS_PER_VARIANT:
        attempts += 1
        d, named = _vary(data, rng, spread_percent / 100.0)
        lengths = _lengths(d)
        if not all(_distinct(lengths, other) for other in seen):
            rejected["alike"] += 1
            continue
        number = len(kept) + 1
        d["title"] = f"{base_title}{_SUFFIX_EN.format(n=number)}"
        if "title_uk" in data:
            d["title_uk"] = f"{data['title_uk']}{_SUFFIX_UK.format(n=number)}"
        try:
            mech = loads(to_toml(d), f"{path} (variant)")
            st = analyse_structure(mech)
            if st.formula != structure.formula or [g.kind for g in st.groups] != kinds:
                rejected["structure"] += 1
                continue
            chain, turns = _on_branches(mech, signs)
            if not turns:
                rejected["turn"] += 1
                continue
            gamma = _transmission_min_deg(chain)
            if gamma < floor:
                rejected["angle"] += 1
                continue
            d["sketch"] = _sketch(chain, mech)
            body = to_toml(d)
            check = kinematics(loads(body, "variant")).branches
            if dict(check.signs) != signs or not check.whole_turn:
                rejected["turn"] += 1
                continue
        except (MmtError, ValueError, ArithmeticError):
            rejected["turn"] += 1
            continue
        header = (
            f"# Variant {number} of {shown(Path(path).name, 200)} (seed {seed}, "
            f"spread ±{spread_percent:g} %),\n"
            f"# made by mmt-plans variants: lengths, masses, speed and loads varied and\n"
            f"# rounded; the same structure and branches as the source; smallest\n"
            f"# transmission angle {gamma:.1f}° (floor {floor:.1f}°).\n"
            f"{_SOURCE_MARK}{digest} {number}\n\n"
        )
        masses = tuple(float(lk.get("mass", 0.0)) for lk in d.get("link", []))
        rpm = d.get("drive", {}).get("rpm")
        named.append(("transmission_min_deg", round(gamma, 2)))
        kept.append(Variant(number, header + body, lengths, masses, rpm, gamma, tuple(named)))
        seen.append(lengths)
        if progress:
            progress(1)
    if len(kept) < count:
        raise VariantError(
            _advice(path, len(kept), count, attempts, seed, spread_percent, rejected)
        )
    return kept


_SUFFIX_EN = " — variant {n}"
_SUFFIX_UK = " — варіант {n}"


def _check_titles(path: str | Path, title: Any, title_uk: Any, count: int) -> None:
    """Refuse before any draw a title that cannot take " — variant N"."""
    for entry, text, suffix in (("title", title, _SUFFIX_EN), ("title_uk", title_uk, _SUFFIX_UK)):
        if not isinstance(text, str):
            continue
        room = TITLE_MAX - len(suffix.format(n=count))
        if len(text) > room:
            raise VariantError(
                f"{shown(path)}: {entry}: {len(text)} characters; a variant's {entry} is it "
                f"with {suffix.format(n=count)!r} added, and a title may have at most "
                f"{TITLE_MAX}\n  fix: shorten the {entry} to at most {room} characters"
            )


def _advice(
    path: str | Path,
    made: int,
    count: int,
    attempts: int,
    seed: int,
    spread: float,
    rejected: Counter[str],
) -> str:
    """Why the draws fell short, and the cure for the main cause."""
    why = {
        "alike": "too close to the source or to another variant",
        "structure": "a different structure",
        "turn": "no full turn on the source's branches",
        "angle": "too small a transmission angle",
    }
    reasons = ", ".join(f"{n} {why[k]}" for k, n in rejected.most_common())
    if rejected["alike"] >= sum(rejected.values()) - rejected["alike"]:
        cure = "try a larger --spread (the draws round back onto each other) or another --seed"
    else:
        cure = "try a smaller --spread (the draws break the mechanism) or another --seed"
    return (
        f"{shown(path)}: only {made} of {count} variants after {attempts} draws with seed "
        f"{seed} and spread ±{spread:g} % (rejected: {reasons or 'none'})\n  fix: {cure}"
    )


def file_stem(path: str | Path) -> str:
    """The source's stem as it may start a file name: no control, format
    (bidirectional) or line-separating character."""
    return "".join(ch if ch.isprintable() else "_" for ch in Path(path).stem) or "variant"


def variant_source(text: str) -> tuple[str, int] | None:
    """(sha256 of the source, number) from a variant file's header, or None."""
    m = _SOURCE_LINE.search(text[:4096])
    return (m.group(1), int(m.group(2))) if m else None


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


def earlier_variants(out_dir: str | Path) -> list[Path]:
    """The files of an earlier `variants` run in `out_dir`: variants.csv and
    every *.toml whose header records a source."""
    out = Path(out_dir)
    if not out.is_dir():
        return []
    found = [out / CSV_NAME] if (out / CSV_NAME).is_file() else []
    for p in sorted(out.glob("*.toml")):
        try:
            with p.open("rb") as fh:
                head = fh.read(4096).decode("utf-8", "replace")
        except OSError:
            continue
        if p.is_file() and variant_source(head) is not None:
            found.append(p)
    return found


def write_variants(variants: list[Variant], source: str | Path, out_dir: str | Path) -> list[Path]:
    """Each variant as OUT/<stem>_vNN.toml and a table of all as OUT/variants.csv:
    a header row, then per variant its file and every varied quantity by name
    (signed point coordinates in mm, masses, J, speed, loads by their names,
    the smallest transmission angle)."""
    import csv
    import io

    from .files import ensure_dir, write_text_atomic

    out = ensure_dir(out_dir)
    stem = file_stem(source)
    written = []
    for v in variants:
        written.append(write_text_atomic(out / f"{stem}_v{v.number:02d}.toml", v.text))
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    columns = [name for name, _ in variants[0].quantities] if variants else []
    w.writerow(["file", *columns])
    for v in variants:
        values = dict(v.quantities)
        w.writerow(
            [f"{stem}_v{v.number:02d}.toml"]
            + [f"{values[c]:g}" if c in values else "" for c in columns]
        )
    written.append(write_text_atomic(out / CSV_NAME, buf.getvalue()))
    return written
