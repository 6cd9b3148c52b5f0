"""Mechanism file (TOML, mm) → `Mechanism` (SI), with errors a student can act on.

Every error is a `SpecError` naming the file, the entry (`link[2].points`) and
the fix. The format is the contract of ../shared/SPEC_FORMAT.md.

Every number is checked to be finite and within the physical bounds of
`LIMITS` (README, "Input limits"), every name to be printable and short, and
the sizes of the file's lists to be bounded, so that nothing downstream can
overflow, hang or run out of memory on a file that passes.
"""

from __future__ import annotations

import difflib
import math
import reprlib
import tomllib
from pathlib import Path
from typing import Any, cast

import numpy as np

from .errors import SpecError, shown
from .files import read_input
from .model import (
    FRAME,
    SHEET_FIELDS,
    Acts,
    Drive,
    Force,
    Link,
    Mechanism,
    Prismatic,
    Sense,
    Study,
    frozen_array,
)

MM = 1e-3

# --- input limits (README, "Input limits") ----------------------------------------------
COORDINATE_MAX_MM = 100_000.0  # |x|, |y| of every point (frame, links, cm, guides, sketch)
LENGTH_MIN_MM = 0.01  # the distance of any two points of one link
MASS_MAX_KG = 1e6
J_MAX = 1e6  # kg·m², when given
K_MAX = 10.0  # J = k·m·l²
SPEED_MIN, SPEED_MAX = 1e-3, 1e5  # drive.rpm (1/min), drive.omega (rad/s), gears.motor_rpm
# and the crank speed a gear train gives
FORCE_MAX_N = 1e9
G_MAX = 1000.0  # m/s²
POSITIONS_MIN, POSITIONS_MAX = 4, 360  # the diagrams need 4; `draw` takes ~40 s at 360
ANGLES_MAX = 100  # extra crank angles of study.angles
LINKS_MAX = 25  # the Assur-group search takes ~2 s at 25 links in its worst case
LINK_ID_MAX = 999
POINTS_PER_LINK_MAX = 20
POINTS_MAX = 200  # distinct point names (frame and links together)
FRAME_POINTS_MAX = 50
SLIDERS_MAX = LINKS_MAX
HIGHER_PAIRS_MAX = LINKS_MAX
FORCES_MAX = 50
NAME_MAX = 32  # point and force names
TITLE_MAX = 200  # title, title_uk and each [sheet] field
TEETH_MAX = 10_000  # a gear's tooth count
GEAR_STAGES_MAX = 20  # stages of [gears], and meshes of one planetary stage

LIMITS: dict[str, str] = {  # README's table "Input limits" is this, row by row
    "coordinates (frame, points, cm, through, sketch)": f"x and y within ±{COORDINATE_MAX_MM:,.0f} mm",
    "distance of two points of one link": f"at least {LENGTH_MIN_MM} mm",
    "link mass": f"0 to {MASS_MAX_KG:,.0f} kg",
    "link J (when given)": f"0 to {J_MAX:,.0f} kg·m²",
    "link k": f"0 to {K_MAX:g}",
    "drive.rpm, gears.motor_rpm, the crank speed of a gear train": f"{SPEED_MIN:g} to {SPEED_MAX:,.0f} 1/min",
    "drive.omega": f"{SPEED_MIN:g} to {SPEED_MAX:,.0f} rad/s",
    "force magnitude": f"0 to {FORCE_MAX_N:.0e} N",
    "env.g": f"0 to {G_MAX:,.0f} m/s²",
    "study.positions": f"{POSITIONS_MIN} to {POSITIONS_MAX}",
    "study.angles": f"at most {ANGLES_MAX} angles, finite (taken mod 360)",
    "study.zero, slider angle": "finite (taken mod 360)",
    "study.plans": "a non-empty list of positions",
    "links": f"at most {LINKS_MAX}, ids 1 to {LINK_ID_MAX}",
    "points": f"at most {POINTS_PER_LINK_MAX} per link, {FRAME_POINTS_MAX} on the frame, "
    f"{POINTS_MAX} names in all",
    "sliders; higher pairs": f"at most {SLIDERS_MAX} each",
    "forces": f"at most {FORCES_MAX}",
    "point and force names": f"1 to {NAME_MAX} printable characters",
    "title, title_uk, [sheet] fields": f"at most {TITLE_MAX} printable characters",
    "gear tooth counts": f"1 to {TEETH_MAX:,}",
    "gear stages; meshes of a planetary stage": f"at most {GEAR_STAGES_MAX}",
}

_VALUE = reprlib.Repr()
_VALUE.maxstring, _VALUE.maxother, _VALUE.maxlong, _VALUE.maxlevel = 60, 60, 40, 3


def show_value(value: Any) -> str:
    """A value from the file as a message shows it: repr, bounded in length and depth."""
    try:
        return _VALUE.repr(value)
    except (ValueError, RecursionError):  # an integer of thousands of digits
        return f"<a {type(value).__name__} too large to show>"


def _real(value: Any) -> float | None:
    """The value as a float if it is a TOML number (not a bool); inf for an
    integer too large for a float; None for anything else."""
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        return None
    try:
        return float(value)
    except OverflowError:
        return math.inf if value > 0 else -math.inf


def _mod360(angle: float) -> float:
    """An angle within [-360, 360] as given (so sane files keep their exact
    numbers); a larger one reduced mod 360."""
    return angle if -360.0 <= angle <= 360.0 else angle % 360.0


KEYS: dict[str, tuple[str, ...]] = {
    "": (
        "title",
        "title_uk",
        "drive",
        "study",
        "frame",
        "link",
        "slider",
        "sketch",
        "force",
        "gears",
        "env",
        "higher_pair",
        "sheet",
    ),
    "drive": ("link", "rpm", "omega", "sense"),
    "study": (
        "positions",
        "output",
        "working_direction",
        "zero",
        "plans",
        "force_position",
        "angles",
        "partial_turn",
    ),
    "link": ("id", "points", "mass", "cm", "J", "k"),
    "slider": ("link", "on", "through", "angle"),
    "force": ("name", "link", "at", "magnitude", "acts", "direction"),
    "env": ("g", "gravity"),
    "higher_pair": ("links",),
    "sheet": SHEET_FIELDS,
}


def load(path: str | Path) -> Mechanism:
    """Read and check a mechanism file."""
    return loads(read_text(path), str(path))


def loads(text: str, path: str = "<string>") -> Mechanism:
    data = parse_toml(text, path)
    try:
        mech = _Reader(path).mechanism(data)
    except (OverflowError, MemoryError):
        # an integer too large for a float met by some reader: named here
        check_integer_sizes(data, path)
        raise
    # the entries' own limits spoke first; what they let pass is still 64-bit
    check_integer_sizes(data, path)
    return mech


def read_text(path: str | Path, what: str = "mechanism file") -> str:
    """The text of an input file (a mechanism, answers), or a SpecError naming
    it: only a regular UTF-8 file of at most 1 MB is read (files.read_input)."""
    return read_input(path, what)


INTEGER_MIN, INTEGER_MAX = -(2**63), 2**63 - 1
"""TOML's integers: 64-bit, signed ("an integer that cannot be represented
losslessly must be an error", toml.io v1.0.0); tomllib reads any size."""


def _entry_name(keys: list[str | int]) -> str:
    out = ""
    for k in keys:
        out += f"[{k + 1}]" if isinstance(k, int) else (f".{k}" if out else str(k))
    return out


def check_integer_sizes(data: Any, path: str) -> None:
    """Refuse an integer outside TOML's 64 bits, naming its entry, before any
    code reads it (a 310-digit motor_rpm would overflow float())."""
    stack: list[tuple[list[str | int], Any]] = [([], data)]
    while stack:
        keys, value = stack.pop()
        if isinstance(value, dict):
            stack.extend((keys + [k], v) for k, v in value.items())
        elif isinstance(value, list):
            stack.extend((keys + [i], v) for i, v in enumerate(value))
        elif isinstance(value, int) and not isinstance(value, bool):
            if not INTEGER_MIN <= value <= INTEGER_MAX:
                digits = len(str(abs(value))) if abs(value) < 10**4000 else 4000
                raise SpecError(
                    path,
                    _entry_name(keys) or "TOML",
                    f"an integer of {digits} digits, beyond TOML's 64-bit integers "
                    f"({INTEGER_MIN} to {INTEGER_MAX})",
                    "write a number of a sane size (mm, kg, N, rpm); README lists the input limits",
                )


def parse_toml(text: str, path: str) -> dict[str, Any]:
    """The tables of an input file's TOML, or a SpecError at the line that is wrong."""
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as err:
        raise SpecError(path, "TOML", str(err), "fix the TOML syntax at that line") from None
    except RecursionError:
        raise SpecError(
            path,
            "TOML",
            "arrays or tables are nested too deeply to read",
            "a mechanism file nests at most a few levels: [[link]] points = { A = [0, 0] }",
        ) from None
    except ValueError as err:  # an integer of more than 4300 digits
        raise SpecError(
            path,
            "TOML",
            f"a value cannot be read: {err}",
            "write numbers of a sane size (mm, kg, N, rpm)",
        ) from None
    return data


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
                fix = (
                    f"did you mean '{close[0]}'?"
                    if close
                    else f"allowed keys: {', '.join(allowed)}"
                )
                where = f"{entry}.{key}" if entry else key
                raise self.fail(where, "unknown key", fix)
        return table

    def number(
        self,
        table: dict,
        key: str,
        entry: str,
        default: Any = ...,
        *,
        positive: bool = False,
        non_negative: bool = False,
        minimum: float | None = None,
        maximum: float | None = None,
        unit: str = "",
    ) -> float:
        if key not in table:
            if default is ...:
                raise self.fail(f"{entry}.{key}", "is required", f"add {key} = <number>")
            return default
        value = table[key]
        x = _real(value)
        if x is None or not math.isfinite(x):
            raise self.fail(
                f"{entry}.{key}",
                f"must be a number, not {show_value(value)}",
                f"write {key} = <number>",
            )
        if positive and x <= 0:
            raise self.fail(
                f"{entry}.{key}", f"must be positive, not {x:g}", "give a value above zero"
            )
        if non_negative and x < 0:
            raise self.fail(
                f"{entry}.{key}",
                f"must not be negative, not {x:g}",
                "give zero or a positive value",
            )
        self.bounded(x, f"{entry}.{key}", minimum, maximum, unit)
        return x

    def bounded(
        self, x: float, entry: str, minimum: float | None, maximum: float | None, unit: str = ""
    ) -> None:
        """A number outside [minimum, maximum] (README, "Input limits") is refused."""
        u = f" {unit}" if unit else ""
        if (minimum is not None and x < minimum) or (maximum is not None and x > maximum):
            lo = "" if minimum is None else f"{minimum:g}"
            hi = "" if maximum is None else f"{maximum:g}"
            span = (
                f"between {lo} and {hi}{u}"
                if lo and hi
                else f"at most {hi}{u}"
                if hi
                else f"at least {lo}{u}"
            )
            value = f"{x:g}{u}" if math.isfinite(x) else "a number beyond 1e308"
            raise self.fail(
                entry,
                f"is {value}, out of the range this tool accepts: {span}",
                "check the value and its unit (mechanism files use mm, kg, N, "
                "rpm or rad/s); README lists the input limits",
            )

    def integer(self, table: dict, key: str, entry: str, default: Any = ...) -> int:
        if key not in table:
            if default is ...:
                raise self.fail(f"{entry}.{key}", "is required", f"add {key} = <integer>")
            return default
        value = table[key]
        if isinstance(value, bool) or not isinstance(value, int):
            raise self.fail(
                f"{entry}.{key}",
                f"must be an integer, not {show_value(value)}",
                f"write {key} = <integer>",
            )
        return value

    def vector(
        self,
        value: Any,
        entry: str,
        *,
        what: str = "a point [x, y] in mm",
        limit: float = COORDINATE_MAX_MM,
    ) -> np.ndarray:
        xs = [_real(v) for v in value] if isinstance(value, list) and len(value) == 2 else None
        if xs is None or any(x is None or not math.isfinite(x) for x in xs):
            raise self.fail(
                entry,
                f"must be {what}, not {show_value(value)}",
                "write two numbers, e.g. [120, 0]",
            )
        for x in xs:
            if x is None:
                continue  # _real refused it above
            if abs(x) > limit and limit == COORDINATE_MAX_MM:
                raise self.fail(
                    entry,
                    f"has a coordinate of {x:g} mm, beyond the {limit:,.0f} mm this tool accepts",
                    "check the unit: mechanism files give lengths in mm",
                )
            if abs(x) > limit:
                raise self.fail(
                    entry,
                    f"has a component of {x:g}, beyond {limit:g}",
                    "give a direction like [1, 0] or [-0.5, 0.87]",
                )
        return np.array(xs, dtype=float)

    def direction(self, value: Any, entry: str, fix: str) -> np.ndarray:
        """A unit vector from [x, y] (any length above 1e-9)."""
        d = self.vector(value, entry, what="a direction [x, y]", limit=1e9)
        norm = math.hypot(*d)
        if norm == 0:
            raise self.fail(entry, "must not be [0, 0]", fix)
        if norm < 1e-9:
            raise self.fail(entry, f"is too short to give a direction (length {norm:g})", fix)
        return d / norm

    def name(self, value: Any, entry: str, what: str = "a point name") -> str:
        """A point or force name: a string of 1..NAME_MAX printable characters."""
        if not isinstance(value, str):
            raise self.fail(
                entry,
                f"must be {what} (a string), not {show_value(value)}",
                'write a name in quotes, e.g. "B"',
            )
        if not value:
            raise self.fail(entry, f"{what} must not be empty", 'give it a name, e.g. "B"')
        if len(value) > NAME_MAX:
            raise self.fail(
                entry,
                f"{what} of {len(value)} characters is too long (at most {NAME_MAX})",
                "use a short name, e.g. B or S2",
            )
        if not value.isprintable():
            raise self.fail(
                entry,
                f"{what} '{shown(value)}' has a control or invisible character",
                "write the name with visible characters only, e.g. B2",
            )
        return value

    def text(self, value: Any, entry: str, *, numbers: bool = False) -> str:
        """A title or a [sheet] field: a string of at most TITLE_MAX printable
        characters (with `numbers`, a number is taken as it is written: group = 21)."""
        if numbers and isinstance(value, int) and not isinstance(value, bool):
            value = show_value(value)
        elif numbers and isinstance(value, float) and math.isfinite(value):
            value = str(value)
        if not isinstance(value, str):
            raise self.fail(
                entry,
                f"must be a string, not {show_value(value)}",
                f'write {entry.rsplit(".", 1)[-1]} = "..."',
            )
        if len(value) > TITLE_MAX:
            raise self.fail(
                entry,
                f"is {len(value)} characters long (at most {TITLE_MAX})",
                "shorten it: it is lettered in the title block",
            )
        if not value.isprintable():
            raise self.fail(
                entry,
                f"'{shown(value, 60)}' has a control or invisible character "
                "(a newline, a tab, NUL ...)",
                "write it on one line, plain text",
            )
        return value

    def points_table(self, raw: dict, entry: str, limit: int) -> dict[str, np.ndarray]:
        """A table of named points (mm) → metres, names checked."""
        if len(raw) > limit:
            raise self.fail(
                entry,
                f"has {len(raw)} points, more than the {limit} this tool accepts",
                "README lists the input limits",
            )
        return {
            self.name(name, f"{entry}.{shown(name, NAME_MAX)}"): self.vector(
                v, f"{entry}.{shown(name, NAME_MAX)}"
            )
            * MM
            for name, v in raw.items()
        }

    # --- sections ---------------------------------------------------------------------
    def mechanism(self, data: dict) -> Mechanism:
        self.check_keys(data, "", "")
        if "title" in data:
            title = self.text(data["title"], "title")
        else:  # the file's name, made printable (it is lettered on the sheets)
            title = shown(Path(self.path).stem, TITLE_MAX)
        titles = {"en": title}
        if "title_uk" in data:
            titles["uk"] = self.text(data["title_uk"], "title_uk")

        frame = self.frame(data.get("frame", {}))
        links = self.links(data.get("link"), frame)
        sliders = self.sliders(data.get("slider", []), links)
        drive = self.drive(data, links)
        points = set(frame) | {p for link in links.values() for p in link.points}
        if len(points) > POINTS_MAX:
            raise self.fail(
                "link",
                f"the mechanism has {len(points)} point names, more than the "
                f"{POINTS_MAX} this tool accepts",
                "README lists the input limits",
            )
        study = self.study(data.get("study"), points)
        forces = self.forces(data.get("force", []), links)
        sketch = self.sketch(data.get("sketch", {}), points)
        higher = self.higher_pairs(data.get("higher_pair", []), links)
        g = self.env(data.get("env", {}))
        sheet = self.sheet(data.get("sheet", {}))

        mech = Mechanism(
            title=title,
            titles=titles,
            path=self.path,
            frame=frame,
            links=links,
            sliders=sliders,
            forces=forces,
            drive=drive,
            study=study,
            sketch=sketch,
            higher_pairs=higher,
            g=g,
            sheet=sheet,
        )
        self.check_connections(mech)
        self.check_study_indices(mech)
        return mech

    def frame(self, table: Any) -> dict[str, np.ndarray]:
        if not isinstance(table, dict):
            raise self.fail("frame", "must be a table of points", "write [frame] O = [0, 0]")
        return {
            name: frozen_array(v)
            for name, v in self.points_table(table, "frame", FRAME_POINTS_MAX).items()
        }

    def links(self, entries: Any, frame: dict) -> dict[int, Link]:
        if not isinstance(entries, list) or not entries:
            raise self.fail("link", "no [[link]] entries", "describe each moving link as [[link]]")
        if len(entries) > LINKS_MAX:
            raise self.fail(
                "link",
                f"{len(entries)} links, more than the {LINKS_MAX} this tool "
                "accepts (the search for Assur groups grows fast with the links)",
                "README lists the input limits",
            )
        links: dict[int, Link] = {}
        for i, table in enumerate(entries):
            entry = f"link[{i + 1}]"
            self.check_keys(table, "link", entry)
            lid = self.integer(table, "id", entry)
            entry = f"link[{i + 1}] (id {lid})" if abs(lid) <= 10**9 else entry
            if lid <= 0:
                raise self.fail(
                    f"{entry}.id",
                    "must be 1 or more (0 is the frame)",
                    "number the moving links 1..n",
                )
            if lid > LINK_ID_MAX:
                raise self.fail(
                    f"{entry}.id",
                    f"is {lid}, more than {LINK_ID_MAX}",
                    "number the moving links 1..n",
                )
            if lid in links:
                raise self.fail(
                    f"{entry}.id", f"link {lid} is given twice", "give every link its own id"
                )
            raw = table.get("points", {})
            if not isinstance(raw, dict):
                raise self.fail(
                    f"{entry}.points",
                    "must be a table of points",
                    "write points = { A = [0, 0], B = [500, 0] }",
                )
            points = self.points_table(raw, f"{entry}.points", POINTS_PER_LINK_MAX)
            names = list(points)
            for a in range(len(names)):
                for b in range(a + 1, len(names)):
                    d = np.linalg.norm(points[names[a]] - points[names[b]])
                    if d < 1e-12:
                        raise self.fail(
                            f"{entry}.points",
                            f"points {names[a]} and {names[b]} coincide (zero length)",
                            "give the link's points distinct coordinates: the distance "
                            "between them is the link length",
                        )
                    if d < LENGTH_MIN_MM * MM:
                        raise self.fail(
                            f"{entry}.points",
                            f"points {names[a]} and {names[b]} are {d / MM:.3g} mm apart, "
                            f"less than {LENGTH_MIN_MM} mm",
                            "give the link's points distinct coordinates in mm: the distance "
                            "between them is the link length",
                        )
            mass = self.number(
                table, "mass", entry, 0.0, non_negative=True, maximum=MASS_MAX_KG, unit="kg"
            )
            k = self.number(table, "k", entry, 1.0 / 12.0, non_negative=True, maximum=K_MAX)
            if "cm" in table:
                cm = self.vector(table["cm"], f"{entry}.cm") * MM
            elif len(names) >= 2:
                cm = (points[names[0]] + points[names[1]]) / 2
            elif names:
                cm = points[names[0]].copy()
            else:
                cm = np.zeros(2)
            length = np.linalg.norm(points[names[1]] - points[names[0]]) if len(names) >= 2 else 0.0
            J = self.number(
                table,
                "J",
                entry,
                k * mass * length**2,
                non_negative=True,
                maximum=J_MAX,
                unit="kg*m2",
            )
            links[lid] = Link(
                id=lid,
                points={n: frozen_array(p) for n, p in points.items()},
                mass=mass,
                cm=frozen_array(cm),
                J=J,
                k=k,
            )
        return dict(sorted(links.items()))

    def sliders(self, entries: Any, links: dict[int, Link]) -> tuple[Prismatic, ...]:
        if not isinstance(entries, list):
            raise self.fail("slider", "must be an array of tables", "write [[slider]]")
        if len(entries) > SLIDERS_MAX:
            raise self.fail(
                "slider",
                f"{len(entries)} sliders, more than the {SLIDERS_MAX} this tool accepts",
                "README lists the input limits",
            )
        out = []
        for i, table in enumerate(entries):
            entry = f"slider[{i + 1}]"
            self.check_keys(table, "slider", entry)
            lid = self.integer(table, "link", entry)
            if lid not in links:
                raise self.fail(
                    f"{entry}.link",
                    f"link {lid} does not exist",
                    f"use one of the links {sorted(links)}",
                )
            on = self.integer(table, "on", entry, 0)
            if on != FRAME and on not in links:
                raise self.fail(
                    f"{entry}.on",
                    f"the guide is on link {on}, which does not exist",
                    f"use 0 (the frame) or one of the links {sorted(links)}",
                )
            if on == lid:
                raise self.fail(
                    f"{entry}.on",
                    "a link cannot slide on itself",
                    "name the link that carries the guide",
                )
            if not links[lid].points:
                raise self.fail(
                    f"{entry}.link",
                    f"link {lid} has no point to put on the guide line",
                    f"give link {lid} a point, e.g. points = {{ E = [0, 0] }}",
                )
            through = self.vector(table.get("through", [0, 0]), f"{entry}.through") * MM
            angle = math.radians(_mod360(self.number(table, "angle", entry, 0.0)))
            out.append(
                Prismatic(
                    slider=lid,
                    guide=on,
                    through=frozen_array(through),
                    direction=frozen_array([math.cos(angle), math.sin(angle)]),
                    slider_point=links[lid].point_names[0],
                )
            )
        return tuple(out)

    def drive(self, data: dict, links: dict[int, Link]) -> Drive:
        table = self.check_keys(data.get("drive", {}), "drive", "drive")
        lid = self.integer(table, "link", "drive", 1)
        if lid not in links:
            raise self.fail(
                "drive.link", f"link {lid} does not exist", f"use one of the links {sorted(links)}"
            )
        sense = table.get("sense", "ccw")
        if not isinstance(sense, str) or sense not in ("ccw", "cw"):
            raise self.fail(
                "drive.sense",
                f'must be "ccw" or "cw", not {show_value(sense)}',
                'write sense = "ccw"',
            )
        given = [k for k in ("rpm", "omega") if k in table] + (
            ["[gears]"] if "gears" in data else []
        )
        if len(given) > 1:
            raise self.fail(
                "drive",
                f"the crank speed is given twice ({' and '.join(given)})",
                "keep one of drive.rpm, drive.omega or [gears]",
            )
        if not given:
            raise self.fail(
                "drive",
                "the crank speed is missing",
                "add drive.rpm, drive.omega or a [gears] table",
            )
        rpm = None
        train = None
        if "rpm" in table:
            rpm = self.number(
                table,
                "rpm",
                "drive",
                positive=True,
                minimum=SPEED_MIN,
                maximum=SPEED_MAX,
                unit="1/min",
            )
            omega = math.pi * rpm / 30.0
        elif "omega" in table:
            omega = self.number(
                table,
                "omega",
                "drive",
                positive=True,
                minimum=SPEED_MIN,
                maximum=SPEED_MAX,
                unit="rad/s",
            )
        else:
            train = self.gears(data["gears"])
            omega = abs(train.omega)
            rpm = abs(train.crank_rpm)
        return Drive(link=lid, omega=omega, sense=cast(Sense, sense), rpm=rpm, gear_train=train)

    def gears(self, table: Any) -> Any:
        """[gears] read by gears.py, within the limits: motor_rpm, tooth counts, the
        number of stages and meshes, and the crank speed the train gives."""
        from .gears import GearTrain

        if isinstance(table, dict):
            if "motor_rpm" in table:
                rpm = _real(table["motor_rpm"])
                if rpm is not None and rpm > 0:  # inf: an integer of hundreds of digits
                    self.bounded(rpm, "gears.motor_rpm", SPEED_MIN, SPEED_MAX, "1/min")
            stages = table.get("stage")
            if isinstance(stages, list):
                if len(stages) > GEAR_STAGES_MAX:
                    raise self.fail(
                        "gears.stage",
                        f"{len(stages)} stages, more than the {GEAR_STAGES_MAX} this tool accepts",
                        "README lists the input limits",
                    )
                for i, stage in enumerate(stages, 1):
                    if not isinstance(stage, dict):
                        continue
                    meshes = stage.get("meshes")
                    if isinstance(meshes, list) and len(meshes) > GEAR_STAGES_MAX:
                        raise self.fail(
                            f"gears.stage[{i}].meshes",
                            f"{len(meshes)} meshes, more "
                            f"than the {GEAR_STAGES_MAX} this tool accepts",
                            "README lists the input limits",
                        )
                    where = [(f"gears.stage[{i}].z", stage.get("z"))] + [
                        (f"gears.stage[{i}].meshes[{k}].z", m.get("z"))
                        for k, m in enumerate(meshes if isinstance(meshes, list) else [], 1)
                        if isinstance(m, dict)
                    ]
                    for entry, z in where:
                        if isinstance(z, list) and any(
                            isinstance(n, int) and not isinstance(n, bool) and n > TEETH_MAX
                            for n in z
                        ):
                            raise self.fail(
                                entry,
                                f"a tooth count above {TEETH_MAX}: {show_value(z)}",
                                "README lists the input limits",
                            )
        train = GearTrain.from_toml(table, self.path)
        crank_rpm = abs(train.crank_rpm)
        if not SPEED_MIN <= crank_rpm <= SPEED_MAX:
            raise self.fail(
                "gears",
                f"the train turns the crank at {crank_rpm:g} rpm, out of the "
                f"range this tool accepts: between {SPEED_MIN:g} and {SPEED_MAX:g}",
                "check motor_rpm and the tooth counts",
            )
        return train

    def study(self, table: Any, points: set[str]) -> Study:
        if table is None:
            raise self.fail("study", "is missing", 'add [study] with output = "<point>"')
        self.check_keys(table, "study", "study")
        output = table.get("output")
        if not isinstance(output, str):
            raise self.fail("study.output", "is required", 'add output = "<point name>"')
        if output not in points:
            close = difflib.get_close_matches(output, sorted(points), n=1)
            raise self.fail(
                "study.output",
                f"point {output!r} does not exist",
                f"did you mean '{close[0]}'?"
                if close
                else f"use one of the points {sorted(points)}",
            )
        n = self.integer(table, "positions", "study", 12)
        if n < POSITIONS_MIN:
            raise self.fail(
                "study.positions",
                f"must be {POSITIONS_MIN} or more, not {n} (the "
                "diagrams are differentiated over the positions)",
                "the textbook uses 8 or 12",
            )
        if n > POSITIONS_MAX:
            raise self.fail(
                "study.positions",
                f"is {show_value(n)}, more than the "
                f"{POSITIONS_MAX} this tool accepts (one per degree)",
                "the textbook uses 8 or 12; give extra crank angles in study.angles",
            )
        wd = self.direction(
            table.get("working_direction", [1, 0]),
            "study.working_direction",
            "give the direction the output moves in the working stroke",
        )
        zero_raw = table.get("zero", "extreme")
        zero_x = _real(zero_raw)
        if isinstance(zero_raw, str) and zero_raw == "extreme":
            zero = None
        elif zero_x is not None and math.isfinite(zero_x):
            zero = zero_x % 360.0
        else:
            raise self.fail(
                "study.zero",
                f'must be "extreme" or a crank angle, not {show_value(zero_raw)}',
                'write zero = "extreme" or zero = 30',
            )
        plans = table.get("plans")
        if plans is not None:
            if (
                not isinstance(plans, list)
                or not plans
                or not all(isinstance(p, int) and not isinstance(p, bool) for p in plans)
            ):
                raise self.fail(
                    "study.plans",
                    f"must be a non-empty list of position indices, not {show_value(plans)}",
                    "write plans = [2, 8]",
                )
            plans = tuple(plans)
        fp = table.get("force_position")
        if fp is not None and (not isinstance(fp, int) or isinstance(fp, bool)):
            raise self.fail(
                "study.force_position", "must be a position index", "write force_position = 2"
            )
        angles = table.get("angles", [])
        if not isinstance(angles, list) or not all(
            (r := _real(a)) is not None and math.isfinite(r) for a in angles
        ):
            raise self.fail(
                "study.angles",
                f"must be a list of crank angles in degrees, not {show_value(angles)}",
                "write angles = [210]",
            )
        if len(angles) > ANGLES_MAX:
            raise self.fail(
                "study.angles",
                f"{len(angles)} extra angles, more than the {ANGLES_MAX} this tool accepts",
                "give a few angles of the task; for a finer turn raise study.positions",
            )
        partial = table.get("partial_turn", False)
        if not isinstance(partial, bool):
            raise self.fail(
                "study.partial_turn",
                f"must be true or false, not {partial!r}",
                "write partial_turn = true to analyse only the crank angles where "
                "the mechanism assembles",
            )
        return Study(
            output=output,
            positions=n,
            working_direction=frozen_array(wd),
            zero=zero,
            plans=plans,
            force_position=fp,
            angles=tuple(float(a) % 360.0 for a in angles),
            partial_turn=partial,
        )

    def forces(self, entries: Any, links: dict[int, Link]) -> tuple[Force, ...]:
        if not isinstance(entries, list):
            raise self.fail("force", "must be an array of tables", "write [[force]]")
        if len(entries) > FORCES_MAX:
            raise self.fail(
                "force",
                f"{len(entries)} forces, more than the {FORCES_MAX} this tool accepts",
                "README lists the input limits",
            )
        out = []
        for i, table in enumerate(entries):
            entry = f"force[{i + 1}]"
            self.check_keys(table, "force", entry)
            name = self.name(table.get("name", f"F{i + 1}"), f"{entry}.name", "a force name")
            lid = self.integer(table, "link", entry)
            if lid not in links:
                raise self.fail(
                    f"{entry}.link",
                    f"link {lid} does not exist",
                    f"use one of the links {sorted(links)}",
                )
            at = table.get("at")
            if not isinstance(at, str) or at not in links[lid].points:
                raise self.fail(
                    f"{entry}.at",
                    f"point {show_value(at)} is not on link {lid}",
                    f"use one of its points {list(links[lid].points)}",
                )
            magnitude = self.number(
                table, "magnitude", entry, non_negative=True, maximum=FORCE_MAX_N, unit="N"
            )
            direction = None
            if "direction" in table:
                direction = frozen_array(
                    self.direction(
                        table["direction"],
                        f"{entry}.direction",
                        "give the force's direction, e.g. [-1, 0]",
                    )
                )
            if direction is not None and table.get("acts") == "always":
                raise self.fail(
                    f"{entry}.acts",
                    'acts = "always" (against the motion) contradicts a fixed direction',
                    "drop acts to keep the direction in every position, write "
                    'acts = "working" for the working stroke only, or drop direction',
                )
            # a fixed direction acts in every position unless acts = "working" is written
            acts = table.get("acts", "always" if direction is not None else "working")
            if not isinstance(acts, str) or acts not in ("working", "always"):
                raise self.fail(
                    f"{entry}.acts",
                    f'must be "working" or "always", not {show_value(acts)}',
                    'write acts = "working"',
                )
            out.append(
                Force(
                    name=name,
                    link=lid,
                    at=at,
                    magnitude=magnitude,
                    acts=cast(Acts, acts),
                    direction=direction,
                )
            )
        return tuple(out)

    def sketch(self, table: Any, points: set[str]) -> dict[str, np.ndarray]:
        if not isinstance(table, dict):
            raise self.fail("sketch", "must be a table of points", "write [sketch] A = [141, 141]")
        out = {}
        for name, v in table.items():
            if name not in points:
                raise self.fail(
                    f"sketch.{shown(name, NAME_MAX)}",
                    f"point {shown(name, NAME_MAX)!r} does not exist",
                    f"use points of the links: {sorted(points)}",
                )
            out[name] = frozen_array(self.vector(v, f"sketch.{name}") * MM)
        return out

    def higher_pairs(self, entries: Any, links: dict[int, Link]) -> tuple[tuple[int, int], ...]:
        if not isinstance(entries, list):
            raise self.fail(
                "higher_pair",
                "must be an array of tables",
                "write [[higher_pair]] with links = [2, 3]",
            )
        if len(entries) > HIGHER_PAIRS_MAX:
            raise self.fail(
                "higher_pair",
                f"{len(entries)} higher pairs, more than the {HIGHER_PAIRS_MAX} this tool accepts",
                "README lists the input limits",
            )
        out = []
        for i, table in enumerate(entries):
            entry = f"higher_pair[{i + 1}]"
            self.check_keys(table, "higher_pair", entry)
            ids = table.get("links")
            if (
                not isinstance(ids, list)
                or len(ids) != 2
                or any(isinstance(x, bool) or not isinstance(x, int) for x in ids)
                or any(x != FRAME and x not in links for x in ids)
            ):
                raise self.fail(
                    f"{entry}.links",
                    f"must name two existing links, not {show_value(ids)}",
                    "write links = [2, 3]",
                )
            if ids[0] == ids[1]:
                raise self.fail(
                    f"{entry}.links",
                    f"joins link {ids[0]} to itself",
                    "name the two links the pair joins, e.g. links = [2, 3]",
                )
            out.append((int(ids[0]), int(ids[1])))
        return tuple(out)

    def env(self, table: Any) -> float:
        self.check_keys(table, "env", "env")
        g = self.number(table, "g", "env", 9.81, non_negative=True, maximum=G_MAX, unit="m/s2")
        gravity = table.get("gravity", True)
        if not isinstance(gravity, bool):
            raise self.fail("env.gravity", "must be true or false", "write gravity = false")
        return g if gravity else 0.0

    def sheet(self, table: Any) -> dict[str, str]:
        self.check_keys(table, "sheet", "sheet")
        return {k: self.text(v, f"sheet.{k}", numbers=True) for k, v in table.items()}

    # --- whole-mechanism checks ---------------------------------------------------
    def check_connections(self, mech: Mechanism) -> None:
        drive_link = mech.links[mech.drive.link]
        owners = mech.point_owners
        if not any(FRAME in owners[p] for p in drive_link.points):
            raise self.fail(
                f"link (id {drive_link.id}).points",
                "the driving link has no point on the frame",
                "add its pivot (e.g. O) to [frame] with the same name",
            )
        pins = [
            p for p in drive_link.points if any(o not in (FRAME, drive_link.id) for o in owners[p])
        ]
        if len(pins) != 1:
            raise self.fail(
                f"link (id {drive_link.id}).points",
                f"the driving link must share exactly one point with another moving "
                f"link (its crank pin), it shares {len(pins)}: {pins}",
                "give the crank pin (e.g. A) to the crank and to the link it drives",
            )
        if mech.crank_length < 1e-9:
            raise self.fail(
                f"link (id {drive_link.id}).points",
                "the crank has zero length: no balancing force can act on it",
                "give the crank pin a distance from the pivot",
            )
        n = len(mech.links)
        p5 = len(mech.revolutes) + len(mech.sliders)
        p4 = len(mech.higher_pairs)
        W = 3 * n - 2 * p5 - p4
        if W != 1:
            lonely = [p for p, o in owners.items() if len(o) == 1 and o[0] != FRAME]
            hint = ""
            if lonely and W > 1:
                p = lonely[0]
                hint = (
                    f"point {p} is used by link {owners[p][0]} only and is not on the frame: "
                    f"if it is a fixed pivot, add {p} to [frame]; if it joins two links, "
                    f"give it to both"
                )
            raise self.fail(
                "link",
                f"the mechanism has W = 3n - 2p5 - p4 = 3*{n} - 2*{p5} - {p4} = {W}, not 1",
                hint
                or "check that every pair is there once: shared point names make revolute "
                "pairs, [[slider]] entries prismatic ones",
            )

    def check_study_indices(self, mech: Mechanism) -> None:
        n = mech.study.positions
        for i, p in enumerate(mech.study.plans or ()):
            if not 0 <= p < n:
                raise self.fail(
                    f"study.plans[{i + 1}]",
                    f"position {p} does not exist",
                    f"use positions 0..{n - 1}",
                )
        fp = mech.study.force_position
        if fp is not None and not 0 <= fp < n:
            raise self.fail(
                "study.force_position", f"position {fp} does not exist", f"use positions 0..{n - 1}"
            )
