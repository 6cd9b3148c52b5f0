"""A seeded mutator over the sample files, and the property every mutant keeps.

Each mutant is one of the files samples/*.toml and samples/tasks/**/*.toml,
changed by one to three mutations: a key deleted, two values swapped, a value
of another type, an extreme number (0, -0.0, ±1e308, 5e-324, nan, ±inf,
2**63-1, 10**30), a number scaled by a power of ten, a long or exotic string
(control characters, right-to-left marks, astral characters), a point, link
or force named twice, a link that refers to itself, a key added; or the
file's bytes damaged (truncated, bytes flipped or inserted, a line dropped or
doubled, another encoding, deep nesting, binary junk). About a third of the
mutants are plausible instead (points moved a little, other masses, speeds,
positions, plans, forces, gears): valid in form, they reach the solver, the
diagrams and the force analysis.

The property: `mmt_plans.load(file)`, mmt_plans.solve(`).to_json()` and
`json.dumps(..., allow_nan=False)` either succeed with every number finite,
or raise an `MmtError`, and a `SpecError` names the file, and a fix (or at
least the entry), in a message whose every line is printable. Anything else
(another exception, a non-finite number, more than SLOW_S seconds of processor time) is a
finding.

    .venv/bin/python tests/fuzz.py --cases 20000          # what `make fuzz` runs
    .venv/bin/python tests/fuzz.py --case 1234 --show     # one mutant: its text and outcome

Case k of seed s is always the same mutant (random.Random(f"{s}:{k}")).
"""

from __future__ import annotations

import argparse
import gc
import json
import math
import os
import random
import re
import signal
import sys
import tempfile
import time
import tomllib
import traceback
import warnings
from collections import Counter
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parents[1]
SAMPLES = ROOT / "samples"
SOURCES = sorted(SAMPLES.glob("*.toml")) + sorted((SAMPLES / "tasks").rglob("*.toml"))

# Every limit is in processor seconds of this process (user + system), not on
# the wall clock: on a machine shared with other work the wall clock also
# counts the waiting for a processor (a case of 8 s of processor took 120 s of
# wall time beside 15 other busy processes, and was called hung).
SLOW_S = 5.0  # a case slower than this is a finding
DRAW_SLOW_S = 60.0  # drawing both sheets of a mutant slower than this is a finding
HANG_S = 120.0  # a case is stopped (SIGPROF) after this much processor time
HANG_WALL_S = 3600.0  # ... or (SIGALRM) after this much wall time: one that waits

EXTREMES: tuple[Any, ...] = (0, -0.0, 1e308, -1e308, 5e-324, math.nan, math.inf, -math.inf,
                             2**63 - 1, -(2**63), 10**30, 1, -1, 0.5, 1e-300)
STRINGS: tuple[str, ...] = ("", " ", "A B", "Ж", "Щ2", "𝔸", "a\u0301", "\u202eB", "B\nC",
                            "\x00", "\t", "\x7f", "é" * 40, "x" * 10_000, "S2", "O", "A", "B",
                            "\ufeff", "R12", "F_PR", "π", "-", "..", "/", "[", '"', "\\")


# --- TOML out -----------------------------------------------------------------------

_BARE = re.compile(r"[A-Za-z0-9_-]+")


def _string(s: str) -> str:
    out = ['"']
    for ch in s:
        if ch == '"':
            out.append('\\"')
        elif ch == "\\":
            out.append("\\\\")
        elif ord(ch) < 0x20 or ord(ch) == 0x7F:
            out.append(f"\\u{ord(ch):04x}")
        else:
            out.append(ch)
    out.append('"')
    return "".join(out)


def _key(k: str) -> str:
    return k if _BARE.fullmatch(k) else _string(k)


def _value(v: Any) -> str:
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, int):
        return str(v)
    if isinstance(v, float):
        if math.isnan(v):
            return "nan"
        if math.isinf(v):
            return "inf" if v > 0 else "-inf"
        return repr(v)
    if isinstance(v, str):
        return _string(v)
    if isinstance(v, dict):
        return "{ " + ", ".join(f"{_key(str(k))} = {_value(x)}" for k, x in v.items()) + " }" \
            if v else "{}"
    if isinstance(v, (list, tuple)):
        return "[" + ", ".join(_value(x) for x in v) + "]"
    raise TypeError(type(v))


def _without_none(v: Any) -> Any:
    # a mutation that copied a missing value (None) leaves the key out
    if isinstance(v, dict):
        return {k: _without_none(x) for k, x in v.items() if x is not None}
    if isinstance(v, list):
        return [_without_none(x) for x in v if x is not None]
    return v


def dumps(data: dict) -> str:
    """TOML of `data`, every value inline (`link = [{ id = 1, ... }, ...]`)."""
    return "".join(f"{_key(str(k))} = {_value(v)}\n"
                   for k, v in _without_none(data).items())


# --- paths into the data ------------------------------------------------------------

Path_ = tuple  # keys and indices from the top


def paths(data: Any, prefix: Path_ = ()) -> list[Path_]:
    out = []
    if isinstance(data, dict):
        for k, v in data.items():
            out.append(prefix + (k,))
            out += paths(v, prefix + (k,))
    elif isinstance(data, list):
        for i, v in enumerate(data):
            out.append(prefix + (i,))
            out += paths(v, prefix + (i,))
    return out


def get(data: Any, path: Path_) -> Any:
    for k in path:
        data = data[k]
    return data


def put(data: Any, path: Path_, value: Any) -> None:
    get(data, path[:-1])[path[-1]] = value


def is_number(v: Any) -> bool:
    return isinstance(v, (int, float)) and not isinstance(v, bool)


# --- mutations ----------------------------------------------------------------------

def m_delete(rng: random.Random, data: dict) -> str:
    p = rng.choice(paths(data))
    parent = get(data, p[:-1])
    del parent[p[-1]]
    return f"delete {p}"


def m_swap(rng: random.Random, data: dict) -> str:
    ps = paths(data)
    a, b = rng.choice(ps), rng.choice(ps)
    if a[:len(b)] == b or b[:len(a)] == a:
        return "swap (skipped: nested)"
    va, vb = get(data, a), get(data, b)
    put(data, a, vb)
    put(data, b, va)
    return f"swap {a} <-> {b}"


def _retyped(rng: random.Random, v: Any) -> Any:
    choices: list[Any] = [[], {}, "", True, [v], {"x": v}, "text", 1, 1.5, [1, 2], [[1], 2]]
    if is_number(v):
        choices += [str(v), [v, v], [v, v, v]]
    elif isinstance(v, str):
        choices += [len(v), [v], {v: v}]
    elif isinstance(v, list):
        choices += [v[0] if v else 0, {str(i): x for i, x in enumerate(v)}, v * 3, v[:1]]
    elif isinstance(v, dict):
        choices += [list(v.values()), list(v.keys()), [v, v]]
    return rng.choice(choices)


def m_retype(rng: random.Random, data: dict) -> str:
    p = rng.choice(paths(data))
    # a tree of its own (no object shared with the data or within itself), so
    # that a later swap cannot put a table inside itself
    new = json.loads(json.dumps(_retyped(rng, get(data, p))))
    put(data, p, new)
    return f"retype {p} = {_short(new)}"


def _numbers(data: dict) -> list[Path_]:
    return [p for p in paths(data) if is_number(get(data, p))]


def m_extreme(rng: random.Random, data: dict) -> str:
    nums = _numbers(data)
    p = rng.choice(nums if nums and rng.random() < 0.85 else paths(data))
    v = rng.choice(EXTREMES)
    put(data, p, v)
    return f"extreme {p} = {v!r}"


def m_scale(rng: random.Random, data: dict) -> str:
    nums = _numbers(data)
    if not nums:
        return "scale (no number)"
    p = rng.choice(nums)
    v = get(data, p)
    how = rng.random()
    if how < 0.5:
        new = v * 10.0 ** rng.randint(-9, 9)
    elif how < 0.8:
        new = v + rng.uniform(-1, 1) * (abs(v) + 1) * rng.choice((0.01, 0.3, 3))
    else:
        new = -v
    if isinstance(v, int) and rng.random() < 0.5 and math.isfinite(new) and abs(new) < 2**62:
        new = int(new)
    put(data, p, new)
    return f"scale {p} = {new!r}"


def _string_paths(data: dict) -> list[Path_]:
    return [p for p in paths(data) if isinstance(get(data, p), str)]


def _key_paths(data: dict) -> list[Path_]:
    """Paths of table keys that are names: points of links, frame, sketch."""
    return [p for p in paths(data) if isinstance(get(data, p[:-1]), dict) and isinstance(p[-1], str)
            and (len(p) >= 2 and p[-2] in ("points", "frame", "sketch") or p[0] in ("frame", "sketch"))]


def _rename_key(table: dict, old: str, new: str) -> None:
    items = list(table.items())
    table.clear()
    for k, v in items:
        table[new if k == old else k] = v


def m_string(rng: random.Random, data: dict) -> str:
    value = rng.choice(STRINGS)
    keys = _key_paths(data)
    if keys and rng.random() < 0.4:
        p = rng.choice(keys)
        _rename_key(get(data, p[:-1]), p[-1], value)
        return f"rename key {p} -> {_short(value)}"
    strs = _string_paths(data)
    p = rng.choice(strs if strs and rng.random() < 0.8 else paths(data))
    put(data, p, value)
    return f"string {p} = {_short(value)}"


def _point_names(data: dict) -> list[str]:
    names: set[str] = set()
    for table in [data.get("frame")] + [l.get("points") for l in _list(data.get("link"))
                                        if isinstance(l, dict)]:
        if isinstance(table, dict):
            names |= set(table)
    return sorted(names)


def _list(v: Any) -> list:
    return v if isinstance(v, list) else []


def m_duplicate(rng: random.Random, data: dict) -> str:
    """A name used twice: a point renamed to another point's name, a link or a
    force entry copied, a force's name taken by another."""
    how = rng.random()
    links = [l for l in _list(data.get("link")) if isinstance(l, dict)]
    if how < 0.4:
        keys = _key_paths(data)
        names = _point_names(data)
        if keys and names:
            p = rng.choice(keys)
            new = rng.choice(names + ["S1", "S2", "S3", "S4", "S5"])
            table = get(data, p[:-1])
            if new in table:
                return "duplicate (skipped: same table)"
            _rename_key(table, p[-1], new)
            return f"rename {p} -> {new} (a name used twice)"
    if how < 0.7 and links:
        copy = json.loads(json.dumps(rng.choice(links)))
        data["link"].insert(rng.randrange(len(data["link"]) + 1), copy)
        return f"link id {copy.get('id')} given twice"
    forces = [f for f in _list(data.get("force")) if isinstance(f, dict)]
    if forces:
        copy = json.loads(json.dumps(rng.choice(forces)))
        data["force"].append(copy)
        return f"force {copy.get('name')} given twice"
    return "duplicate (nothing to duplicate)"


def m_self_reference(rng: random.Random, data: dict) -> str:
    links = [l for l in _list(data.get("link")) if isinstance(l, dict)]
    ids = [l.get("id") for l in links]
    how = rng.randrange(7)
    if how == 0 and _list(data.get("slider")):
        s = rng.choice(data["slider"])
        if isinstance(s, dict):
            s["on"] = s.get("link")
            return "slider on its own link"
    if how == 1 and ids:
        i = rng.choice(ids)
        data.setdefault("higher_pair", [])
        if isinstance(data["higher_pair"], list):
            data["higher_pair"].append({"links": [i, i]})
            return f"higher pair [{i}, {i}]"
    if how == 2 and ids and isinstance(data.get("drive"), dict):
        data["drive"]["link"] = rng.choice(ids + [0, -1, 99])
        return f"drive.link = {data['drive']['link']}"
    if how == 3 and isinstance(data.get("study"), dict):
        names = _point_names(data)
        if names:
            data["study"]["output"] = rng.choice(names)
            return f"study.output = {data['study']['output']}"
    if how == 4 and links:
        link = rng.choice(links)
        link["id"] = rng.choice(ids + [0, -3, 2**63 - 1])
        return f"a link's id = {link['id']}"
    if how == 5 and ids:
        forces = [f for f in _list(data.get("force")) if isinstance(f, dict)]
        if forces:
            f = rng.choice(forces)
            f["link"] = rng.choice(ids)
            return f"force on link {f['link']}"
    if how == 6 and links:
        a, b = rng.sample(links, 2) if len(links) >= 2 else (links[0], links[0])
        if isinstance(a.get("points"), dict) and isinstance(b.get("points"), dict):
            a["points"] = dict(b["points"])
            return f"link {a.get('id')} takes the points of link {b.get('id')}"
    return "self-reference (none applicable)"


ADDITIONS: tuple[tuple[str, str, Any], ...] = (
    ("study", "positions", lambda r: r.choice([0, 1, 2, 3, 4, 5, 7, 360, 361, 720, 2000,
                                               10**6, 2**63 - 1, 10**30, -12])),
    ("study", "plans", lambda r: r.choice([[], [0], [0, 0], [0, 1, 2, 3, 4, 5], [-1], [99],
                                           [0, 6, 3], [[1]], "0"])),
    ("study", "angles", lambda r: r.choice([[math.inf], [math.nan], [1e308], [-720, 720, 1e9],
                                            list(range(0, 360, 3)), [0] * 100, [[0]]])),
    ("study", "zero", lambda r: r.choice([math.nan, math.inf, -1e308, 1e300, 720, -30, "x",
                                          "extreme", [0]])),
    ("study", "force_position", lambda r: r.choice([0, -1, 11, 12, 10**30, 3.5, "2"])),
    ("study", "partial_turn", lambda r: r.choice([True, False, 1, "yes"])),
    ("study", "working_direction", lambda r: r.choice([[0, 0], [1e-300, 0], [1e308, 1e308],
                                                       [5e-324, 5e-324], [0, -1], [1]])),
    ("drive", "rpm", lambda r: r.choice([1e308, 5e-324, 1e-3, 1e5, 1e6, 0, -5, 1e-4])),
    ("drive", "omega", lambda r: r.choice([1e308, 5e-324, 1e5, 1e-3, 0])),
    ("drive", "sense", lambda r: r.choice(["cw", "CW", [], "ccw"])),
    ("env", "g", lambda r: r.choice([0, 9.81, 1e308, 1e3, 1e4, -9.81])),
    ("env", "gravity", lambda r: r.choice([False, True, 0])),
    ("sheet", "author", lambda r: r.choice(STRINGS)),
    ("", "title", lambda r: r.choice(STRINGS + ("x" * 300,))),
    ("", "title_uk", lambda r: r.choice(STRINGS)),
    ("", "gears", lambda r: r.choice([
        {"motor_rpm": 1e308, "stage": [{"z": [20, 40], "mesh": "external"}]},
        {"motor_rpm": 1450, "stage": [{"z": [1, 10**6], "mesh": "external"}]},
        {"motor_rpm": 1450, "stage": [{"z": [20, 40], "mesh": "external"}] * 30},
        {"motor_rpm": 5e-324, "stage": [{"z": [20, 40], "mesh": "internal"}]},
        {"motor_rpm": 1450, "stage": [{"kind": "planetary", "meshes": [
            {"z": [20, 20], "mesh": "external"}, {"z": [20, 20], "mesh": "external"}]}]},
    ])),
    ("", "higher_pair", lambda r: r.choice([[{"links": [[1], 2]}], [{"links": [1, 2, 3]}],
                                            [{"links": [True, 2]}], {"links": [1, 2]}, "x"])),
    ("", "slider", lambda r: r.choice([[], {}, [{"link": 1, "on": 0}], "x"])),
    ("", "force", lambda r: r.choice([[{"link": 1, "at": [], "magnitude": 1}],
                                      [{"link": 1, "at": ["E"], "magnitude": 1}],
                                      [{"link": 1, "at": "A", "magnitude": 1e308}],
                                      [{"link": 1, "at": "A", "magnitude": 10,
                                        "direction": [0, 0]}]])),
)


def m_add(rng: random.Random, data: dict) -> str:
    section, key, make = rng.choice(ADDITIONS)
    value = make(rng)
    if section:
        table = data.setdefault(section, {})
        if not isinstance(table, dict):
            return f"add {section}.{key} (skipped: not a table)"
        table[key] = value
    else:
        data[key] = value
    return f"add {section + '.' if section else ''}{key} = {_short(value)}"


def m_many(rng: random.Random, data: dict) -> str:
    """A list made very long: links, points of a link, frame points, forces."""
    how = rng.randrange(4)
    n = rng.choice([30, 61, 300, 5000])
    if how == 0 and _list(data.get("link")):
        base = data["link"][-1]
        data["link"] += [json.loads(json.dumps(base)) | {"id": 100 + i} if isinstance(base, dict)
                         else base for i in range(n)]
        return f"{n} more links"
    if how == 1 and isinstance(data.get("frame"), dict):
        data["frame"] |= {f"P{i}": [i, -i] for i in range(n)}
        return f"{n} more frame points"
    if how == 2 and _list(data.get("link")) and isinstance(data["link"][0], dict):
        pts = data["link"][0].get("points")
        if isinstance(pts, dict):
            pts |= {f"Q{i}": [i + 1000, 7] for i in range(n)}
            return f"{n} more points on the first link"
    forces = _list(data.get("force"))
    if forces and isinstance(forces[0], dict):
        data["force"] += [dict(forces[0], name=f"F{i}") for i in range(n)]
        return f"{n} more forces"
    return "many (nothing)"


def m_plausible(rng: random.Random, data: dict) -> str:
    """A change a student might make that keeps the file valid in form: a
    point moved a little, another mass, speed, study setting or force; these
    reach the solver, the diagrams and the force analysis."""
    study = data.get("study") if isinstance(data.get("study"), dict) else None
    forces = [f for f in _list(data.get("force")) if isinstance(f, dict)]
    how = rng.randrange(10)
    if how <= 2:
        coords = [p for p in _numbers(data)
                  if any(k in ("points", "frame", "sketch", "through", "cm") for k in p
                         if isinstance(k, str))]
        if coords:
            changed = []
            for p in rng.sample(coords, min(len(coords), rng.randint(1, 3))):
                v = get(data, p)
                new = round(v + rng.gauss(0, 0.15 * (abs(v) + 50)), rng.choice((0, 1, 3)))
                put(data, p, new)
                changed.append(f"{p} = {new}")
            return "moved " + ", ".join(changed)
    if how == 3 and study is not None:
        n = rng.choice([4, 5, 6, 8, 9, 12, 16, 24, 36, 72, 360])
        study["positions"] = n
        for key in ("plans", "force_position"):
            study.pop(key, None)
        if rng.random() < 0.5:
            study["plans"] = sorted(rng.sample(range(n), rng.randint(1, min(3, n))))
        if rng.random() < 0.5:
            study["force_position"] = rng.randrange(n)
        return f"positions = {n}, plans {study.get('plans')}, force at {study.get('force_position')}"
    if how == 4 and study is not None:
        key = rng.choice(["zero", "angles", "working_direction", "partial_turn"])
        value = {"zero": rng.choice([rng.uniform(-720, 720), 0, 90, 180, "extreme"]),
                 "angles": [round(rng.uniform(-400, 400), 2) for _ in range(rng.randint(0, 5))],
                 "working_direction": [rng.choice([1, -1, 0, 0.3]), rng.choice([0, 1, -1, 0.7])],
                 "partial_turn": True}[key]
        study[key] = value
        return f"study.{key} = {value!r}"
    if how == 5 and isinstance(data.get("drive"), dict):
        drive = data["drive"]
        drive["sense"] = rng.choice(["cw", "ccw"])
        for key in ("rpm", "omega"):
            if key in drive:
                drive[key] = rng.choice([0.001, 0.5, 1, 60, 1450, 1e4, 1e5])
        return f"drive = {drive}"
    if how == 6:
        links = [l for l in _list(data.get("link")) if isinstance(l, dict)]
        if links:
            link = rng.choice(links)
            key = rng.choice(["mass", "J", "k", "cm"])
            value = {"mass": rng.choice([0, 0.001, 1, 1e3, 1e6]), "J": rng.choice([0, 1e-6, 1, 1e6]),
                     "k": rng.choice([0, 1 / 12, 1, 10]),
                     "cm": [rng.uniform(-500, 1500), rng.uniform(-300, 300)]}[key]
            link[key] = value
            return f"link {link.get('id')}.{key} = {value!r}"
    if how == 7 and forces:
        f = rng.choice(forces)
        key = rng.choice(["magnitude", "acts", "direction"])
        value = {"magnitude": rng.choice([0, 1, 1e9, 123.4]),
                 "acts": rng.choice(["working", "always"]),
                 "direction": [rng.uniform(-1, 1), rng.uniform(-1, 1)]}[key]
        f[key] = value
        if key == "direction":
            f.pop("acts", None)
        return f"force {f.get('name')}.{key} = {value!r}"
    if how == 8:
        data["env"] = {"g": rng.choice([0, 1.62, 9.81, 1000]), "gravity": rng.random() < 0.8}
        return f"env = {data['env']}"
    if isinstance(data.get("drive"), dict):
        data["drive"].pop("rpm", None)
        data["drive"].pop("omega", None)
        data["gears"] = {"motor_rpm": rng.choice([960, 1450, 2900]), "stage": [
            {"z": [rng.randint(12, 40), rng.randint(20, 120)],
             "mesh": rng.choice(["external", "internal"])} for _ in range(rng.randint(1, 3))]}
        return f"gears = {_short(data['gears'], 80)}"
    return "plausible (nothing)"


# --- the geometry grammar (#26) -----------------------------------------------------
# Edits that keep a file valid in form and change its geometry the way a
# mechanism can go wrong: a link scaled, a point moved, a guide rotated, the
# crank brought to the edge of assembly (near a toggle), groups without mass
# or load, named points crowded on one link, extra angles a hair from 0/360,
# names a file may hold (bidi, CR, markup, DXF and printf codes).

HOSTILE_NAMES: tuple[str, ...] = ("A\u202e", "B\u200f", "C\r", "O2'", "Ж1", "A B", "K" * 32,
                                  "<!--", "&amp;", "%%d", "^A", "{x}", "Σ̄", "𝔸1", "::")
HOSTILE_PATHS: tuple[str, ...] = ("a\nb.toml", "cr\r.toml", "bidi\u202egpj.toml",
                                  " lead.toml", "-dash.toml", "x" * 240 + ".toml", "Ж.toml",
                                  "quiz.xml.toml", "q\"'; $(x).toml", "tab\t.toml",
                                  "<!--.toml", "..toml")
NEAR_WRAP_ANGLES: tuple[list[float], ...] = (
    [0, 359.9999999999], [359.9999999999], [1e-12, 360 - 1e-12], [0, 0, 360],
    [180, 180.0000000001], [-1e-13, 720], [360 - 1e-9, -1e-9], [90, 90.0],
)


def _links(data: dict) -> list[dict]:
    return [l for l in _list(data.get("link"))
            if isinstance(l, dict) and isinstance(l.get("points"), dict)]


def _xy(v: Any) -> bool:
    return isinstance(v, list) and len(v) == 2 and all(is_number(x) for x in v)


def _scale_link(link: dict, f: float) -> None:
    pts = link["points"]
    for k, v in list(pts.items()):
        if _xy(v):
            pts[k] = [v[0] * f, v[1] * f]


def g_scale_link(rng: random.Random, data: dict, source: Path) -> str:
    links = _links(data)
    if not links:
        return "scale link (no link)"
    link = rng.choice(links)
    f = rng.choice((0.5, 0.8, 0.95, 0.999, 1.001, 1.05, 1.25, 2.0, 0.01, 100.0))
    _scale_link(link, f)
    return f"link {link.get('id')} scaled x{f}"


def g_move_point(rng: random.Random, data: dict, source: Path) -> str:
    tables = [l["points"] for l in _links(data)]
    if isinstance(data.get("frame"), dict):
        tables.append(data["frame"])
    choices = [(t, k) for t in tables for k, v in t.items() if _xy(v)]
    if not choices:
        return "move point (none)"
    table, key = rng.choice(choices)
    sigma = rng.choice((1e-6, 0.1, 5.0, 50.0, 300.0))
    x, y = table[key]
    table[key] = [x + rng.gauss(0, sigma), y + rng.gauss(0, sigma)]
    return f"point {key} moved by ~{sigma:g} mm"


def g_rotate_guide(rng: random.Random, data: dict, source: Path) -> str:
    sliders = [s for s in _list(data.get("slider")) if isinstance(s, dict)]
    if sliders:
        s = rng.choice(sliders)
        angle = s.get("angle", 0) if is_number(s.get("angle", 0)) else 0
        d = rng.choice((1e-9, 0.5, 15.0, 45.0, 90.0, 179.999999, -90.0, 89.999999))
        s["angle"] = angle + d
        if rng.random() < 0.3 and _xy(s.get("through")):
            s["through"] = [s["through"][0] + rng.gauss(0, 30), s["through"][1] + rng.gauss(0, 30)]
        return f"slider of link {s.get('link')} guide rotated by {d:g} deg"
    frame = data.get("frame")
    if isinstance(frame, dict):  # no guide: the frame's pivots turned about the origin
        a = math.radians(rng.choice((1.0, 30.0, 90.0, 180.0)))
        for k, v in list(frame.items()):
            if _xy(v):
                frame[k] = [v[0] * math.cos(a) - v[1] * math.sin(a),
                            v[0] * math.sin(a) + v[1] * math.cos(a)]
        return f"frame turned by {math.degrees(a):g} deg"
    return "rotate guide (none)"


_EDGE: dict[Path, float | None] = {}


def _assembles(text: str) -> bool:
    import mmt_plans

    try:
        mmt_plans.solve(mmt_plans.loads(text, "edge.toml"), forces=False)
    except Exception:
        return False
    return True


def _crank_edge(source: Path, data: dict) -> float | None:
    """The factor of the crank's size at which the source stops assembling
    over a whole turn (bisection, once per source file); None without one."""
    if source in _EDGE:
        return _EDGE[source]
    _EDGE[source] = None
    drive = data.get("drive") if isinstance(data.get("drive"), dict) else {}
    crank = [l for l in _links(data) if l.get("id") == drive.get("link", 1)]
    if not crank or not _assembles(dumps(data)):
        return None

    def ok(f: float) -> bool:
        trial = json.loads(json.dumps(data))
        _scale_link([l for l in _links(trial) if l.get("id") == crank[0].get("id")][0], f)
        return _assembles(dumps(trial))

    lo, hi = 1.0, 2.0
    while ok(hi):
        lo, hi = hi, hi * 2
        if hi > 64:
            return None
    for _ in range(14):
        mid = (lo + hi) / 2
        lo, hi = (mid, hi) if ok(mid) else (lo, mid)
    _EDGE[source] = lo
    return lo


def g_near_toggle(rng: random.Random, data: dict, source: Path) -> str:
    edge = _crank_edge(source, data)
    if edge is None:
        return "near toggle (no edge)"
    drive = data["drive"] if isinstance(data.get("drive"), dict) else {}
    crank = [l for l in _links(data) if l.get("id") == drive.get("link", 1)][0]
    f = edge * (1 + rng.choice((-1, 1)) * 10.0 ** -rng.randint(4, 9))
    _scale_link(crank, f)
    return f"crank scaled x{f:.10g} (the edge of assembly at x{edge:.6g})"


def g_unloaded(rng: random.Random, data: dict, source: Path) -> str:
    links = _links(data)
    if not links:
        return "unloaded (no link)"
    if rng.random() < 0.5:
        chosen = links
        data.pop("force", None)
        data["env"] = {"gravity": False}
    else:
        chosen = rng.sample(links, min(2, len(links)))
        ids = {l.get("id") for l in chosen}
        forces = [f for f in _list(data.get("force"))
                  if not (isinstance(f, dict) and f.get("link") in ids)]
        data["force"] = forces
    for l in chosen:
        l["mass"] = 0
        l.pop("J", None)
    return f"links {[l.get('id') for l in chosen]} massless and unloaded"


def g_crowded(rng: random.Random, data: dict, source: Path) -> str:
    links = _links(data)
    if not links:
        return "crowded (no link)"
    link = rng.choice(links)
    base = next((v for v in link["points"].values() if _xy(v)), [0, 0])
    gap = rng.choice((10.0, 1.0, 0.02))
    count = rng.choice((3, 6, 10))
    for i in range(count):
        link["points"][f"K{i + 1}"] = [base[0] + gap * (i + 1), base[1] + gap * 0.5]
    return f"{count} points {gap:g} mm apart on link {link.get('id')}"


def g_angles(rng: random.Random, data: dict, source: Path) -> str:
    study = data.setdefault("study", {})
    if not isinstance(study, dict):
        return "angles (no study)"
    study["angles"] = list(rng.choice(NEAR_WRAP_ANGLES))
    return f"study.angles = {study['angles']}"


def _rename_everywhere(data: Any, old: str, new: str) -> Any:
    if isinstance(data, dict):
        return {(new if k == old else k): _rename_everywhere(v, old, new) for k, v in data.items()}
    if isinstance(data, list):
        return [_rename_everywhere(v, old, new) for v in data]
    return new if data == old else data


def g_hostile_name(rng: random.Random, data: dict, source: Path) -> str:
    names = _point_names(data)
    if not names:
        return "hostile name (no point)"
    old, new = rng.choice(names), rng.choice(HOSTILE_NAMES)
    renamed = _rename_everywhere(data, old, new)
    data.clear()
    data.update(renamed)
    return f"point {old} renamed {new!r} everywhere"


GEOMETRY = (g_scale_link, g_move_point, g_rotate_guide, g_near_toggle, g_unloaded, g_crowded,
            g_angles, g_hostile_name)


STRUCTURAL = (m_delete, m_swap, m_retype, m_extreme, m_extreme, m_scale, m_scale, m_string,
              m_duplicate, m_self_reference, m_add, m_add, m_many)


def damage(rng: random.Random, raw: bytes) -> tuple[bytes, str]:
    """The file's bytes damaged."""
    how = rng.randrange(11)
    if how == 0:
        k = rng.randrange(len(raw) + 1)
        return raw[:k], f"truncated at byte {k}"
    if how == 1:
        b = bytearray(raw)
        for _ in range(rng.randint(1, 5)):
            if b:
                b[rng.randrange(len(b))] = rng.randrange(256)
        return bytes(b), "bytes flipped"
    if how == 2:
        k = rng.randrange(len(raw) + 1)
        junk = bytes(rng.randrange(256) for _ in range(rng.randint(1, 8)))
        return raw[:k] + junk + raw[k:], f"bytes inserted at {k}"
    lines = raw.split(b"\n")
    if how == 3 and lines:
        del lines[rng.randrange(len(lines))]
        return b"\n".join(lines), "a line deleted"
    if how == 4 and lines:
        k = rng.randrange(len(lines))
        lines.insert(k, lines[k])
        return b"\n".join(lines), "a line doubled"
    if how == 5:
        enc = rng.choice(["latin-1", "utf-16", "utf-16-be", "utf-32", "cp1251"])
        return raw.decode("utf-8").encode(enc, errors="replace"), f"encoded {enc}"
    if how == 6:
        return b"\xef\xbb\xbf" + raw, "UTF-8 byte-order mark"
    if how == 7:
        depth = rng.choice([50, 500, 1000, 5000])
        return raw + b"\nx = " + b"[" * depth + b"]" * depth + b"\n", f"nested {depth} deep"
    if how == 8:
        return bytes(rng.randrange(256) for _ in range(rng.randint(0, 4000))), "binary junk"
    if how == 9:
        k = rng.randrange(len(raw) + 1)
        return raw[:k] + b"\x00" + raw[k:], "a NUL byte"
    return raw.replace(b"\n", b"\r\n"), "CRLF line ends"


@dataclass
class Mutant:
    case: int
    source: Path
    data: bytes
    steps: list[str] = field(default_factory=list)
    kind: str = "structural"  # "damaged", "plausible", "geometry", "structural"
    name: str = "mutant.toml"  # the file's name: now and then a hostile one

    @property
    def family(self) -> str:
        """Mutants whose times compare: one source, one kind of mutation, the
        same order of size (a file made 100 times longer takes longer to read)."""
        return f"{self.source.stem}:{self.kind}{self.size}"

    @property
    def size(self) -> str:
        # over MAX_INPUT_BYTES a file is refused unread: a class of its own
        n = len(self.data)
        return "" if n < 50_000 else ":large" if n <= 1_000_000 else ":over-limit"

    def describe(self) -> str:
        where = f" as {self.name!r}" if self.name != "mutant.toml" else ""
        return (f"case {self.case}: {self.source.relative_to(ROOT)}{where}: "
                + "; ".join(self.steps))


_PARSED: dict[Path, tuple[bytes, dict]] = {}


def _source(path: Path) -> tuple[bytes, dict]:
    if path not in _PARSED:
        raw = path.read_bytes()
        _PARSED[path] = (raw, tomllib.loads(raw.decode("utf-8")))
    return _PARSED[path]


def mutant(seed: int, case: int) -> Mutant:
    rng = random.Random(f"{seed}:{case}")
    source = rng.choice(SOURCES)
    raw, parsed = _source(source)
    m = Mutant(case, source, raw)
    if rng.random() < 0.1:  # a hostile file name: messages must show it escaped
        m.name = rng.choice(HOSTILE_PATHS)
    if rng.random() < 0.15:  # the original text, damaged
        m.data, why = damage(rng, raw)
        m.steps.append(why)
        m.kind = "damaged"
        return m
    data = json.loads(json.dumps(parsed))  # a deep copy (TOML data is JSON data here)
    draw = rng.random()
    # valid in form, these reach the solver: plausible edits and the geometry grammar
    m.kind = "plausible" if draw < 0.2 else "geometry" if draw < 0.4 else "structural"
    for _ in range(rng.choice((1, 1, 1, 2, 2, 3))):
        if m.kind == "geometry":
            op: Any = rng.choice(GEOMETRY)
            args: tuple = (rng, data, source)
        else:
            op = m_plausible if m.kind == "plausible" else rng.choice(STRUCTURAL)
            args = (rng, data)
        try:
            m.steps.append(op(*args))
        except (IndexError, KeyError, TypeError, ValueError) as err:
            m.steps.append(f"{op.__name__} (skipped: {type(err).__name__})")
        # a tree again: an operation may leave one object in two places (a
        # shallow copy), and a later swap must not put a table inside itself
        data = json.loads(json.dumps(data))
    m.data = dumps(data).encode("utf-8", errors="surrogatepass")
    if rng.random() < 0.05:
        m.data, why = damage(rng, m.data)
        m.steps.append(why)
    return m


def _short(v: Any, n: int = 40) -> str:
    text = repr(v)
    return text if len(text) <= n else text[:n] + "..."


# --- the property -------------------------------------------------------------------

@dataclass
class Outcome:
    kind: str  # "analysed", "clean error", "unexpected", "non-finite", "bad message", "hung"
    seconds: float  # load, analyze, to_json
    detail: str = ""
    drawn: str = ""  # with draw=True: "drawn", "clean error" (a sheet that cannot be laid out)
    draw_seconds: float = 0.0
    cpu: float | None = None  # processor seconds of the analysis (None: as `seconds`)
    draw_cpu: float | None = None

    @property
    def work(self) -> float:
        """The processor time of the analysis: what the slow-case counter
        compares (the wall clock also counts waiting for a shared processor)."""
        return self.seconds if self.cpu is None else self.cpu

    @property
    def draw_work(self) -> float:
        return self.draw_seconds if self.draw_cpu is None else self.draw_cpu

    @property
    def slow(self) -> bool:
        """Over an absolute limit, in processor time (the wall clock where
        the processor time was not taken)."""
        return self.work > SLOW_S or self.draw_work > DRAW_SLOW_S


def draw_sheets(analysis) -> None:
    """Both sheets as SVG, each parsed as XML (a control character in a name
    would make it ill-formed)."""
    import xml.etree.ElementTree as ET

    from mmt_plans.drawing.page import Page
    from mmt_plans.render.output import render
    from mmt_plans.render.recording import RecordingBackend
    from mmt_plans.sheets.compose import available_sheets

    page = Page.of("A1")
    for n, compose in sorted(available_sheets().items()):
        recording = RecordingBackend(page.width, page.height)
        compose(analysis, recording, "en")
        ET.fromstring(render(recording, "svg", f"{analysis.mechanism.title}, sheet {n}"))


def _where(err: BaseException) -> str:
    tb = traceback.extract_tb(err.__traceback__)
    return next((f"{Path(f.filename).relative_to(ROOT)}:{f.lineno} ({f.name})"
                 for f in reversed(tb) if str(ROOT / "mmt_plans") in f.filename), "?")


class _Hung(BaseException):
    pass


def _alarm(signum, frame):  # noqa: ARG001
    raise _Hung()


def _message_ok(err: Exception, path: str) -> str:
    """'' when the MmtError's message is well formed, else what is wrong with it."""
    import mmt_plans
    from mmt_plans.errors import shown

    text = str(err)
    if any(not line.isprintable() for line in text.split("\n")):
        return "a line of the message has a control character"
    if isinstance(err, mmt_plans.SpecError):
        if not text.startswith(shown(path)):
            return "the message does not start with the file"
        if "\n  fix: " not in text and not err.entry:
            return "the message names neither a fix nor an entry"
    return ""


def check(data: bytes, path: str | None = None, timeout: float = HANG_S,
          draw: bool = False, wall_timeout: float = HANG_WALL_S) -> Outcome:
    """Run the property on a file holding `data`; with `draw`, an analysed
    mutant's sheets are drawn too (an MmtError there is clean). The case is
    stopped as hung after `timeout` seconds of processor time or
    `wall_timeout` seconds of wall time (0: no limit)."""
    import numpy as np

    import mmt_plans
    from mmt_plans.results_json import results as results_json
    from mmt_plans.files import first_non_finite

    own = path is None
    if own:
        fd, path = tempfile.mkstemp(suffix=".toml", prefix="mutant-")
        os.close(fd)
    Path(path).write_bytes(data)
    timers = [(signal.ITIMER_PROF, signal.SIGPROF, timeout),
              (signal.ITIMER_REAL, signal.SIGALRM, wall_timeout)
              ] if hasattr(signal, "setitimer") else []
    timers = [(which, sig, limit) for which, sig, limit in timers if limit > 0]
    old_handlers = []
    for which, sig, limit in timers:
        old_handlers.append(signal.signal(sig, _alarm))
        signal.setitimer(which, limit)
    t0, c0 = time.perf_counter(), time.process_time()
    try:
        with np.errstate(all="ignore"), warnings.catch_warnings():
            warnings.simplefilter("ignore", RuntimeWarning)
            analysis = mmt_plans.solve(mmt_plans.load(path))
            results = results_json(analysis)
            json.dumps(results, allow_nan=False)
            bad = first_non_finite(results)
            dt, cdt = time.perf_counter() - t0, time.process_time() - c0
            if bad is not None:
                return Outcome("non-finite", dt, f"{bad[0]} = {bad[1]}", cpu=cdt)
            if not draw:
                return Outcome("analysed", dt, cpu=cdt)
            t1, c1 = time.perf_counter(), time.process_time()
            try:
                draw_sheets(analysis)
                drawn = "drawn"
            except mmt_plans.MmtError:
                drawn = "clean error"
            except Exception as err:
                return Outcome("unexpected", dt, f"draw: {type(err).__name__} at {_where(err)}: "
                               f"{str(err)[:200]}", "failed", time.perf_counter() - t1,
                               cpu=cdt, draw_cpu=time.process_time() - c1)
            return Outcome("analysed", dt, "", drawn, time.perf_counter() - t1, cpu=cdt,
                           draw_cpu=time.process_time() - c1)
    except _Hung as err:
        dt, cdt = time.perf_counter() - t0, time.process_time() - c0
        return Outcome("hung", dt, f"stopped after {cdt:.1f} s of processor ({dt:.0f} s of "
                       f"wall time) at {_where(err)}", cpu=cdt)
    except mmt_plans.MmtError as err:
        dt, cdt = time.perf_counter() - t0, time.process_time() - c0
        problem = _message_ok(err, path)
        if problem:
            return Outcome("bad message", dt, f"{problem}: {str(err)[:300]!r}", cpu=cdt)
        return Outcome("clean error", dt, f"{type(err).__name__}: {str(err)[:200]}", cpu=cdt)
    except Exception as err:  # the finding the fuzzer is for
        dt, cdt = time.perf_counter() - t0, time.process_time() - c0
        return Outcome("unexpected", dt, f"{type(err).__name__} at {_where(err)}: "
                       f"{str(err)[:200]}", cpu=cdt)
    finally:
        for (which, sig, _), old in zip(timers, old_handlers):
            signal.setitimer(which, 0)
            signal.signal(sig, old)
        if own:
            os.unlink(path)


# Mutants that expose a bug in a module this fuzzer's owner may not edit
# (analysis, kinematics/chain, forces, diagrams): matched by the finding's
# text, counted as "known bug" rather than failing the suite. Each names the
# bug; the reproducers are in the report of the `reliability` branch.
# The bugs the fuzzer found are fixed, each with its regression test in
# tests/test_fuzz_regressions.py; a new one would be listed here as
# (pattern of the outcome's detail, name of the bug) until it is fixed.
KNOWN_BUGS: tuple[tuple[str, str], ...] = (
    # (pattern of an outcome's detail, the issue that owns it): none open. The
    # two #26 entries (the crank's spokes a hair from 0/360; the unbounded
    # enlarging of a zero force polygon) were removed when their fixes merged.
)


def known_bug(outcome: Outcome) -> str | None:
    for pattern, bug in KNOWN_BUGS:
        if re.search(pattern, outcome.detail):
            return bug
    return None


SLOW_FACTOR = 10.0  # a case more than this many times its family's median is slow
SLOW_FLOOR_S = 1.0  # ... when it also takes longer than this (timer noise below)
DRAW_SLOW_FLOOR_S = 10.0
FAMILY_MIN = 5  # a family of fewer mutants is compared with its kind's median


def _median(xs: list[float]) -> float:
    xs = sorted(xs)
    n = len(xs)
    return 0.0 if n == 0 else xs[n // 2] if n % 2 else (xs[n // 2 - 1] + xs[n // 2]) / 2


def slow_cases(timed: list[tuple[Mutant, Outcome]]) -> list[tuple[Mutant, Outcome, str]]:
    """The mutants slower (in processor time) than SLOW_FACTOR times the
    median of their family
    (one source, one kind of mutation, analysed or refused; for drawings, one
    source), above a
    floor that timer noise does not reach: a case the code handles in a way
    much slower than its kin (a loop without a bound, a quadratic search)."""
    def outcome(o: Outcome) -> str:
        return "analysed" if o.kind == "analysed" else "refused"

    def medians(key, value) -> tuple[dict[str, float], dict[str, float]]:
        fam: dict[str, list[float]] = {}
        kind: dict[str, list[float]] = {}  # the fallback of a small family
        for m, o in timed:
            v = value(o)
            if v is None:
                continue
            fam.setdefault(key(m, o), []).append(v)
            kind.setdefault(f"{m.kind}{m.size}:{outcome(o)}", []).append(v)
        return ({k: _median(v) for k, v in fam.items() if len(v) >= FAMILY_MIN},
                {k: _median(v) for k, v in kind.items()})

    def family(m: Mutant, o: Outcome) -> str:
        # like with like: a mutant refused while reading is not compared with
        # one analysed (its family's median would be the parser's milliseconds)
        return f"{m.family}:{outcome(o)}"

    out = []
    fam, kind = medians(family, lambda o: o.work)
    dfam, dkind = medians(lambda m, o: m.source.stem,
                          lambda o: o.draw_work if o.drawn else None)
    for m, o in timed:
        median = fam.get(family(m, o), kind.get(f"{m.kind}{m.size}:{outcome(o)}", 0.0))
        if o.work > SLOW_FLOOR_S and o.work > SLOW_FACTOR * median:
            out.append((m, o, f"{o.work:.2f} s of processor, {o.work / max(median, 1e-9):.0f}x "
                              f"the median {median:.3f} s of {family(m, o)}"))
        elif o.drawn:
            median = dfam.get(m.source.stem, dkind.get(f"{m.kind}{m.size}:{outcome(o)}", 0.0))
            if o.draw_work > DRAW_SLOW_FLOOR_S and o.draw_work > SLOW_FACTOR * median:
                out.append((m, o, f"sheets {o.draw_work:.1f} s of processor, "
                                  f"{o.draw_work / max(median, 1e-9):.0f}x the median "
                                  f"{median:.2f} s of {m.source.stem}'s drawings"))
    return out


def run(seed: int, cases: int, start: int = 0, echo=print, save: Path | None = None,
        every: int = 0, draw_every: int = 0, known: list | None = None,
        stop=None) -> tuple[Counter, list[tuple[Mutant, Outcome]]]:
    """Run `cases` mutants; (counts, findings). Counts: clean errors, analysed,
    unexpected, non-finite, bad messages, hung, known bugs, slow (> SLOW_S,
    drawing > DRAW_SLOW_S, or > SLOW_FACTOR times its family's median:
    slow_cases); with `draw_every` k, every k-th analysed mutant's sheets are
    drawn too ("drawn", "draw: clean error"). A mutant may be written under
    a hostile file name (HOSTILE_PATHS). The mutants of known bugs are
    appended to `known` as (mutant, outcome, bug) when it is given. With
    `stop`, a function, the run ends before the next case once it answers
    true (counts["cases"]: how many were run)."""
    counts: Counter = Counter()
    findings: list[tuple[Mutant, Outcome]] = []
    timed: list[tuple[Mutant, Outcome]] = []
    folder = Path(tempfile.mkdtemp(prefix="mutants-"))
    t0 = time.perf_counter()
    # The objects alive before the run (in a test session: every earlier test's
    # caches) are set aside from the collector, so a mutant's processor time is
    # its own work, not a full collection of a heap it did not make (CI: a
    # 0.1 s refusal measured 1.4 s late in the suite).
    gc.collect()
    gc.freeze()
    try:
        for case in range(start, start + cases):
            if stop is not None and stop():
                break
            m = mutant(seed, case)
            draw = bool(draw_every) and counts["analysed"] % draw_every == draw_every - 1
            path = folder / m.name
            outcome = check(m.data, str(path), draw=draw)
            path.unlink(missing_ok=True)
            if outcome.drawn:
                counts["drawn" if outcome.drawn == "drawn" else "draw: clean error"] += 1
            kind = outcome.kind
            if kind in ("unexpected", "non-finite", "bad message", "hung") and known_bug(outcome):
                kind = "known bug"
                if known is not None:
                    known.append((m, outcome, known_bug(outcome)))
            counts[kind] += 1
            counts["cases"] += 1
            if kind != "known bug":  # counted once, as the bug it is (a hang is not slow besides)
                timed.append((m, outcome))
                if outcome.slow:
                    counts["slow"] += 1
            if kind not in ("analysed", "clean error", "known bug") or (
                    kind != "known bug" and outcome.slow):
                findings.append((m, outcome))
                if save is not None:
                    save.mkdir(parents=True, exist_ok=True)
                    (save / f"case{case}.toml").write_bytes(m.data)
            if every and (case - start + 1) % every == 0:
                echo(f"  {case - start + 1} cases, {time.perf_counter() - t0:.0f} s: "
                     f"{dict(counts)}")
    finally:
        gc.unfreeze()
        for p in folder.iterdir():
            p.unlink()
        folder.rmdir()
    for m, o, why in slow_cases(timed):
        if o.slow:  # counted already (over the absolute limit)
            continue
        counts["slow"] += 1
        findings.append((m, Outcome("slow", o.seconds, why, o.drawn, o.draw_seconds, o.cpu,
                                    o.draw_cpu)))
        if save is not None:
            save.mkdir(parents=True, exist_ok=True)
            (save / f"case{m.case}.toml").write_bytes(m.data)
    return counts, findings


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--cases", type=int, default=20_000)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--start", type=int, default=0, help="the first case number")
    ap.add_argument("--case", type=int, help="run this one case only")
    ap.add_argument("--show", action="store_true", help="print the mutant's text")
    ap.add_argument("--save", type=Path, help="write the mutants of findings here")
    ap.add_argument("--draw-every", type=int, default=0, metavar="K",
                    help="draw the sheets of every K-th analysed mutant too")
    args = ap.parse_args(argv)
    if args.case is not None:
        m = mutant(args.seed, args.case)
        print(m.describe())
        if args.show:
            sys.stdout.write(m.data.decode("utf-8", errors="backslashreplace") + "\n")
        o = check(m.data, draw=bool(args.draw_every))
        print(f"{o.kind} in {o.seconds:.2f} s ({o.work:.2f} s of processor): {o.detail}"
              + (f"; sheets: {o.drawn} in {o.draw_seconds:.1f} s ({o.draw_work:.1f} s of "
                 f"processor)" if o.drawn else ""))
        return 0
    t0 = time.perf_counter()
    print(f"fuzzing {args.cases} mutants of {len(SOURCES)} sample files (seed {args.seed}) ...")
    known: list = []
    stopping: list[int] = []  # SIGTERM or SIGINT: finish the case, report what was run

    def stop_after_this_case(signum, frame):  # noqa: ARG001
        stopping.append(signum)

    old = {sig: signal.signal(sig, stop_after_this_case) for sig in (signal.SIGTERM, signal.SIGINT)}
    try:
        counts, findings = run(args.seed, args.cases, args.start, save=args.save, every=1000,
                               draw_every=args.draw_every, known=known,
                               stop=lambda: bool(stopping))
    finally:
        for sig, handler in old.items():
            signal.signal(sig, handler)
    total = time.perf_counter() - t0
    done = counts.get("cases", args.cases)
    print(f"\n{done} mutants (cases {args.start}..{args.start + done - 1}) in {total:.0f} s"
          + (f", stopped by signal {stopping[0]} before the {args.cases}" if stopping else "")
          + ":")
    for kind in ("clean error", "analysed", "unexpected", "non-finite", "bad message", "hung",
                 "known bug", "slow", "drawn", "draw: clean error"):
        print(f"  {kind:17s} {counts.get(kind, 0)}")
    if known:
        print("\nknown bugs (in modules this fuzzer's owner may not edit; KNOWN_BUGS):")
        for m, o, bug in known:
            print(f"  {m.describe()}\n      -> {bug}")
    if findings:
        print("\nfindings (reproduce with --case N --show):")
        for m, o in findings[:200]:
            print(f"  {m.describe()}\n      -> {o.kind} ({o.work:.1f} s of processor"
                  + (f", sheets {o.draw_work:.1f} s" if o.drawn else "") + f"): {o.detail}")
    bad = sum(counts.get(k, 0)
              for k in ("unexpected", "non-finite", "bad message", "hung", "slow"))
    return 1 if bad or stopping else 0


if __name__ == "__main__":
    sys.exit(main())
