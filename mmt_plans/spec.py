"""Mechanism file (TOML, mm) → `Mechanism` (SI), with errors a student can act on.

Every error is a `SpecError` naming the file, the entry (`link[2].points`) and
the fix. The format is the contract of ../shared/SPEC_FORMAT.md.
"""

from __future__ import annotations

import difflib
import math
import tomllib
from pathlib import Path
from typing import Any

import numpy as np

from .errors import SpecError
from .model import FRAME, Drive, Force, Link, Mechanism, Prismatic, Study, frozen_array

MM = 1e-3

KEYS: dict[str, tuple[str, ...]] = {
    "": ("title", "title_uk", "drive", "study", "frame", "link", "slider", "sketch", "force", "gears",
         "env", "higher_pair", "sheet"),
    "drive": ("link", "rpm", "omega", "sense"),
    "study": ("positions", "output", "working_direction", "zero", "plans", "force_position",
              "angles", "partial_turn"),
    "link": ("id", "points", "mass", "cm", "J", "k"),
    "slider": ("link", "on", "through", "angle"),
    "force": ("name", "link", "at", "magnitude", "acts", "direction"),
    "env": ("g", "gravity"),
    "higher_pair": ("links",),
    "sheet": ("author", "group", "checked_by", "school", "drawing_number", "approved",
              "lang"),
}


def load(path: str | Path) -> Mechanism:
    """Read and check a mechanism file."""
    return loads(read_text(path), str(path))


def loads(text: str, path: str = "<string>") -> Mechanism:
    return _Reader(path).mechanism(parse_toml(text, path))


def read_text(path: str | Path) -> str:
    """The text of an input file (a mechanism, answers), or a SpecError naming it."""
    try:
        return Path(path).read_text(encoding="utf-8")
    except OSError as err:
        raise SpecError(str(path), "file", f"cannot be read ({err.strerror})",
                        "check the path") from None


def parse_toml(text: str, path: str) -> dict[str, Any]:
    """The tables of an input file's TOML, or a SpecError at the line that is wrong."""
    try:
        return tomllib.loads(text)
    except tomllib.TOMLDecodeError as err:
        raise SpecError(path, "TOML", str(err), "fix the TOML syntax at that line") from None


class _Reader:
    def __init__(self, path: str) -> None:
        self.path = path

    # --- small typed getters -------------------------------------------------------
    def fail(self, entry: str, problem: str, fix: str = "") -> SpecError:
        return SpecError(self.path, entry, problem, fix)

    def check_keys(self, table: Any, section: str, entry: str) -> dict:
        if not isinstance(table, dict):
            raise self.fail(entry, "must be a table", f"write it as [{entry}] with keys")
        allowed = KEYS[section]
        for key in table:
            if key not in allowed:
                close = difflib.get_close_matches(key, allowed, n=1)
                fix = (f"did you mean '{close[0]}'?" if close
                       else f"allowed keys: {', '.join(allowed)}")
                where = f"{entry}.{key}" if entry else key
                raise self.fail(where, "unknown key", fix)
        return table

    def number(self, table: dict, key: str, entry: str, default: Any = ..., *,
               positive: bool = False, non_negative: bool = False) -> float:
        if key not in table:
            if default is ...:
                raise self.fail(f"{entry}.{key}", "is required", f"add {key} = <number>")
            return default
        value = table[key]
        if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
            raise self.fail(f"{entry}.{key}", f"must be a number, not {value!r}",
                            f"write {key} = <number>")
        if positive and value <= 0:
            raise self.fail(f"{entry}.{key}", f"must be positive, not {value}",
                            "give a value above zero")
        if non_negative and value < 0:
            raise self.fail(f"{entry}.{key}", f"must not be negative, not {value}",
                            "give zero or a positive value")
        return float(value)

    def integer(self, table: dict, key: str, entry: str, default: Any = ...) -> int:
        if key not in table:
            if default is ...:
                raise self.fail(f"{entry}.{key}", "is required", f"add {key} = <integer>")
            return default
        value = table[key]
        if isinstance(value, bool) or not isinstance(value, int):
            raise self.fail(f"{entry}.{key}", f"must be an integer, not {value!r}",
                            f"write {key} = <integer>")
        return value

    def vector(self, value: Any, entry: str) -> np.ndarray:
        if (not isinstance(value, list) or len(value) != 2
                or not all(isinstance(v, (int, float)) and not isinstance(v, bool)
                           and math.isfinite(v) for v in value)):
            raise self.fail(entry, f"must be a point [x, y] in mm, not {value!r}",
                            "write two numbers, e.g. [120, 0]")
        return np.array(value, dtype=float)

    # --- sections ---------------------------------------------------------------------
    def mechanism(self, data: dict) -> Mechanism:
        self.check_keys(data, "", "")
        title = data.get("title", Path(self.path).stem)
        if not isinstance(title, str):
            raise self.fail("title", "must be a string", 'write title = "..."')
        titles = {"en": title}
        if "title_uk" in data:
            if not isinstance(data["title_uk"], str):
                raise self.fail("title_uk", "must be a string", 'write title_uk = "..."')
            titles["uk"] = data["title_uk"]

        frame = self.frame(data.get("frame", {}))
        links = self.links(data.get("link"), frame)
        sliders = self.sliders(data.get("slider", []), links)
        drive = self.drive(data, links)
        points = set(frame) | {p for link in links.values() for p in link.points}
        study = self.study(data.get("study"), points)
        forces = self.forces(data.get("force", []), links)
        sketch = self.sketch(data.get("sketch", {}), points)
        higher = self.higher_pairs(data.get("higher_pair", []), links)
        g = self.env(data.get("env", {}))
        sheet = self.sheet(data.get("sheet", {}))

        mech = Mechanism(title=title, titles=titles, path=self.path, frame=frame, links=links,
                         sliders=sliders, forces=forces, drive=drive, study=study,
                         sketch=sketch, higher_pairs=higher, g=g, sheet=sheet)
        self.check_connections(mech)
        self.check_study_indices(mech)
        return mech

    def frame(self, table: Any) -> dict[str, np.ndarray]:
        if not isinstance(table, dict):
            raise self.fail("frame", "must be a table of points", "write [frame] O = [0, 0]")
        return {name: frozen_array(self.vector(v, f"frame.{name}") * MM) for name, v in table.items()}

    def links(self, entries: Any, frame: dict) -> dict[int, Link]:
        if not isinstance(entries, list) or not entries:
            raise self.fail("link", "no [[link]] entries", "describe each moving link as [[link]]")
        links: dict[int, Link] = {}
        for i, table in enumerate(entries):
            entry = f"link[{i + 1}]"
            self.check_keys(table, "link", entry)
            lid = self.integer(table, "id", entry)
            entry = f"link[{i + 1}] (id {lid})"
            if lid <= 0:
                raise self.fail(f"{entry}.id", "must be 1 or more (0 is the frame)",
                                "number the moving links 1..n")
            if lid in links:
                raise self.fail(f"{entry}.id", f"link {lid} is given twice",
                                "give every link its own id")
            raw = table.get("points", {})
            if not isinstance(raw, dict):
                raise self.fail(f"{entry}.points", "must be a table of points",
                                "write points = { A = [0, 0], B = [500, 0] }")
            points = {name: self.vector(v, f"{entry}.points.{name}") * MM for name, v in raw.items()}
            names = list(points)
            for a in range(len(names)):
                for b in range(a + 1, len(names)):
                    d = np.linalg.norm(points[names[a]] - points[names[b]])
                    if d < 1e-12:
                        raise self.fail(
                            f"{entry}.points",
                            f"points {names[a]} and {names[b]} coincide (zero length)",
                            "give the link's points distinct coordinates: the distance "
                            "between them is the link length")
            mass = self.number(table, "mass", entry, 0.0, non_negative=True)
            k = self.number(table, "k", entry, 1.0 / 12.0, non_negative=True)
            if "cm" in table:
                cm = self.vector(table["cm"], f"{entry}.cm") * MM
            elif len(names) >= 2:
                cm = (points[names[0]] + points[names[1]]) / 2
            elif names:
                cm = points[names[0]].copy()
            else:
                cm = np.zeros(2)
            length = (np.linalg.norm(points[names[1]] - points[names[0]])
                      if len(names) >= 2 else 0.0)
            J = self.number(table, "J", entry, k * mass * length**2, non_negative=True)
            links[lid] = Link(id=lid, points={n: frozen_array(p) for n, p in points.items()},
                              mass=mass, cm=frozen_array(cm), J=J, k=k)
        return dict(sorted(links.items()))

    def sliders(self, entries: Any, links: dict[int, Link]) -> tuple[Prismatic, ...]:
        if not isinstance(entries, list):
            raise self.fail("slider", "must be an array of tables", "write [[slider]]")
        out = []
        for i, table in enumerate(entries):
            entry = f"slider[{i + 1}]"
            self.check_keys(table, "slider", entry)
            lid = self.integer(table, "link", entry)
            if lid not in links:
                raise self.fail(f"{entry}.link", f"link {lid} does not exist",
                                f"use one of the links {sorted(links)}")
            on = self.integer(table, "on", entry, 0)
            if on != FRAME and on not in links:
                raise self.fail(f"{entry}.on", f"the guide is on link {on}, which does not exist",
                                f"use 0 (the frame) or one of the links {sorted(links)}")
            if on == lid:
                raise self.fail(f"{entry}.on", "a link cannot slide on itself",
                                "name the link that carries the guide")
            if not links[lid].points:
                raise self.fail(f"{entry}.link",
                                f"link {lid} has no point to put on the guide line",
                                f"give link {lid} a point, e.g. points = {{ E = [0, 0] }}")
            through = self.vector(table.get("through", [0, 0]), f"{entry}.through") * MM
            angle = math.radians(self.number(table, "angle", entry, 0.0))
            out.append(Prismatic(slider=lid, guide=on, through=frozen_array(through),
                                 direction=frozen_array([math.cos(angle), math.sin(angle)]),
                                 slider_point=links[lid].point_names[0]))
        return tuple(out)

    def drive(self, data: dict, links: dict[int, Link]) -> Drive:
        table = self.check_keys(data.get("drive", {}), "drive", "drive")
        lid = self.integer(table, "link", "drive", 1)
        if lid not in links:
            raise self.fail("drive.link", f"link {lid} does not exist",
                            f"use one of the links {sorted(links)}")
        sense = table.get("sense", "ccw")
        if sense not in ("ccw", "cw"):
            raise self.fail("drive.sense", f"must be \"ccw\" or \"cw\", not {sense!r}",
                            'write sense = "ccw"')
        given = [k for k in ("rpm", "omega") if k in table] + (["[gears]"] if "gears" in data else [])
        if len(given) > 1:
            raise self.fail("drive", f"the crank speed is given twice ({' and '.join(given)})",
                            "keep one of drive.rpm, drive.omega or [gears]")
        if not given:
            raise self.fail("drive", "the crank speed is missing",
                            "add drive.rpm, drive.omega or a [gears] table")
        rpm = None
        train = None
        if "rpm" in table:
            rpm = self.number(table, "rpm", "drive", positive=True)
            omega = math.pi * rpm / 30.0
        elif "omega" in table:
            omega = self.number(table, "omega", "drive", positive=True)
        else:
            from .gears import GearTrain

            train = GearTrain.from_toml(data["gears"], self.path)
            omega = abs(train.omega)
            rpm = abs(train.crank_rpm)
        return Drive(link=lid, omega=omega, sense=sense, rpm=rpm, gear_train=train)

    def study(self, table: Any, points: set[str]) -> Study:
        if table is None:
            raise self.fail("study", "is missing", 'add [study] with output = "<point>"')
        self.check_keys(table, "study", "study")
        output = table.get("output")
        if not isinstance(output, str):
            raise self.fail("study.output", "is required", 'add output = "<point name>"')
        if output not in points:
            close = difflib.get_close_matches(output, sorted(points), n=1)
            raise self.fail("study.output", f"point {output!r} does not exist",
                            f"did you mean '{close[0]}'?" if close
                            else f"use one of the points {sorted(points)}")
        n = self.integer(table, "positions", "study", 12)
        if n < 2:
            raise self.fail("study.positions", f"must be 2 or more, not {n}",
                            "the textbook uses 8 or 12")
        wd = self.vector(table.get("working_direction", [1, 0]), "study.working_direction")
        if np.linalg.norm(wd) == 0:
            raise self.fail("study.working_direction", "must not be [0, 0]",
                            "give the direction the output moves in the working stroke")
        zero_raw = table.get("zero", "extreme")
        if zero_raw == "extreme":
            zero = None
        elif isinstance(zero_raw, (int, float)) and not isinstance(zero_raw, bool):
            zero = float(zero_raw)
        else:
            raise self.fail("study.zero", f"must be \"extreme\" or a crank angle, not {zero_raw!r}",
                            'write zero = "extreme" or zero = 30')
        plans = table.get("plans")
        if plans is not None:
            if not isinstance(plans, list) or not all(isinstance(p, int) and not isinstance(p, bool)
                                                      for p in plans):
                raise self.fail("study.plans", "must be a list of position indices",
                                "write plans = [2, 8]")
            plans = tuple(plans)
        fp = table.get("force_position")
        if fp is not None and (not isinstance(fp, int) or isinstance(fp, bool)):
            raise self.fail("study.force_position", "must be a position index",
                            "write force_position = 2")
        angles = table.get("angles", [])
        if not isinstance(angles, list) or not all(
                isinstance(a, (int, float)) and not isinstance(a, bool) for a in angles):
            raise self.fail("study.angles", "must be a list of crank angles in degrees",
                            "write angles = [210]")
        partial = table.get("partial_turn", False)
        if not isinstance(partial, bool):
            raise self.fail("study.partial_turn", f"must be true or false, not {partial!r}",
                            "write partial_turn = true to analyse only the crank angles where "
                            "the mechanism assembles")
        return Study(output=output, positions=n,
                     working_direction=frozen_array(wd / np.linalg.norm(wd)), zero=zero,
                     plans=plans, force_position=fp, angles=tuple(float(a) for a in angles),
                     partial_turn=partial)

    def forces(self, entries: Any, links: dict[int, Link]) -> tuple[Force, ...]:
        if not isinstance(entries, list):
            raise self.fail("force", "must be an array of tables", "write [[force]]")
        out = []
        for i, table in enumerate(entries):
            entry = f"force[{i + 1}]"
            self.check_keys(table, "force", entry)
            name = table.get("name", f"F{i + 1}")
            lid = self.integer(table, "link", entry)
            if lid not in links:
                raise self.fail(f"{entry}.link", f"link {lid} does not exist",
                                f"use one of the links {sorted(links)}")
            at = table.get("at")
            if at not in links[lid].points:
                raise self.fail(f"{entry}.at", f"point {at!r} is not on link {lid}",
                                f"use one of its points {list(links[lid].points)}")
            magnitude = self.number(table, "magnitude", entry, non_negative=True)
            direction = None
            if "direction" in table:
                d = self.vector(table["direction"], f"{entry}.direction")
                if np.linalg.norm(d) == 0:
                    raise self.fail(f"{entry}.direction", "must not be [0, 0]",
                                    "give the force's direction, e.g. [-1, 0]")
                direction = frozen_array(d / np.linalg.norm(d))
            if direction is not None and table.get("acts") == "always":
                raise self.fail(f"{entry}.acts",
                                'acts = "always" (against the motion) contradicts a fixed direction',
                                'drop acts to keep the direction in every position, write '
                                'acts = "working" for the working stroke only, or drop direction')
            # a fixed direction acts in every position unless acts = "working" is written
            acts = table.get("acts", "always" if direction is not None else "working")
            if acts not in ("working", "always"):
                raise self.fail(f"{entry}.acts", f"must be \"working\" or \"always\", not {acts!r}",
                                'write acts = "working"')
            out.append(Force(name=str(name), link=lid, at=at, magnitude=magnitude, acts=acts,
                             direction=direction))
        return tuple(out)

    def sketch(self, table: Any, points: set[str]) -> dict[str, np.ndarray]:
        if not isinstance(table, dict):
            raise self.fail("sketch", "must be a table of points", "write [sketch] A = [141, 141]")
        out = {}
        for name, v in table.items():
            if name not in points:
                raise self.fail(f"sketch.{name}", f"point {name!r} does not exist",
                                f"use points of the links: {sorted(points)}")
            out[name] = frozen_array(self.vector(v, f"sketch.{name}") * MM)
        return out

    def higher_pairs(self, entries: Any, links: dict[int, Link]) -> tuple[tuple[int, int], ...]:
        out = []
        for i, table in enumerate(entries if isinstance(entries, list) else []):
            entry = f"higher_pair[{i + 1}]"
            self.check_keys(table, "higher_pair", entry)
            ids = table.get("links")
            if (not isinstance(ids, list) or len(ids) != 2
                    or any(x != FRAME and x not in links for x in ids)):
                raise self.fail(f"{entry}.links", f"must name two existing links, not {ids!r}",
                                "write links = [2, 3]")
            out.append((int(ids[0]), int(ids[1])))
        return tuple(out)

    def env(self, table: Any) -> float:
        self.check_keys(table, "env", "env")
        g = self.number(table, "g", "env", 9.81, non_negative=True)
        gravity = table.get("gravity", True)
        if not isinstance(gravity, bool):
            raise self.fail("env.gravity", "must be true or false", "write gravity = false")
        return g if gravity else 0.0

    def sheet(self, table: Any) -> dict[str, str]:
        self.check_keys(table, "sheet", "sheet")
        return {k: str(v) for k, v in table.items()}

    # --- whole-mechanism checks ---------------------------------------------------
    def check_connections(self, mech: Mechanism) -> None:
        drive_link = mech.links[mech.drive.link]
        owners = mech.point_owners
        if not any(FRAME in owners[p] for p in drive_link.points):
            raise self.fail(f"link (id {drive_link.id}).points",
                            "the driving link has no point on the frame",
                            "add its pivot (e.g. O) to [frame] with the same name")
        pins = [p for p in drive_link.points
                if any(o not in (FRAME, drive_link.id) for o in owners[p])]
        if len(pins) != 1:
            raise self.fail(f"link (id {drive_link.id}).points",
                            f"the driving link must share exactly one point with another moving "
                            f"link (its crank pin), it shares {len(pins)}: {pins}",
                            "give the crank pin (e.g. A) to the crank and to the link it drives")
        if mech.crank_length < 1e-9:
            raise self.fail(f"link (id {drive_link.id}).points",
                            "the crank has zero length: no balancing force can act on it",
                            "give the crank pin a distance from the pivot")
        n = len(mech.links)
        p5 = len(mech.revolutes) + len(mech.sliders)
        p4 = len(mech.higher_pairs)
        W = 3 * n - 2 * p5 - p4
        if W != 1:
            lonely = [p for p, o in owners.items() if len(o) == 1 and o[0] != FRAME]
            hint = ""
            if lonely and W > 1:
                p = lonely[0]
                hint = (f"point {p} is used by link {owners[p][0]} only and is not on the frame: "
                        f"if it is a fixed pivot, add {p} to [frame]; if it joins two links, "
                        f"give it to both")
            raise self.fail(
                "link",
                f"the mechanism has W = 3n - 2p5 - p4 = 3*{n} - 2*{p5} - {p4} = {W}, not 1",
                hint or "check that every pair is there once: shared point names make revolute "
                        "pairs, [[slider]] entries prismatic ones")

    def check_study_indices(self, mech: Mechanism) -> None:
        n = mech.study.positions
        for i, p in enumerate(mech.study.plans or ()):
            if not 0 <= p < n:
                raise self.fail(f"study.plans[{i + 1}]", f"position {p} does not exist",
                                f"use positions 0..{n - 1}")
        fp = mech.study.force_position
        if fp is not None and not 0 <= fp < n:
            raise self.fail("study.force_position", f"position {fp} does not exist",
                            f"use positions 0..{n - 1}")

