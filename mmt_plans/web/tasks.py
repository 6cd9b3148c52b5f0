"""The variants a class works on: the mechanism files of TASKS_DIR, each
solved once, its kinematic scheme, its given data and the quantities the
page asks for.

A variant is named by its file's stem; the stems come from a listing of
TASKS_DIR (`*.toml`, not recursive), so a name from a request is looked up
in that listing and never joined onto a path: nothing outside TASKS_DIR can
be read.
"""

from __future__ import annotations

import math
import re
import threading
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Literal

from ..i18n import Language, catalogue
from ..model import FRAME

if TYPE_CHECKING:  # pragma: no cover
    from ..forces import ForceAnalysis
    from ..solution import Solution

__all__ = ["STEM", "Field", "FieldGroup", "TaskDir", "Variant"]

STEM = re.compile(r"[A-Za-z0-9][A-Za-z0-9_.-]{0,63}")  # a variant's name, as a file stem

Section = Literal["position", "forces", "diagrams"]


@dataclass(frozen=True)
class Field:
    """One value the form asks for, and where it goes in an answers file:
    [[position]] index = where; key = { name = value } (name "" for a scalar
    such as mu_V)."""

    section: Section
    where: int | None  # the position (index), None for [diagrams]' check_passed
    key: str
    name: str
    symbol: str  # the textbook's letter
    sub: str  # its index, written as a subscript
    unit: str  # the catalogue's [units] key ("" for none)
    choice: bool = False  # true/false (check_passed), not a number

    @property
    def id(self) -> str:
        """The form field's name: what comes back in a request."""
        return "|".join(
            (self.section, "" if self.where is None else str(self.where), self.key, self.name)
        )


@dataclass(frozen=True)
class FieldGroup:
    sheet: int
    title: str  # a key of the web words: "plans", "check_5", "loads", "reactions", "balancing"
    where: int | None
    phi1_deg: float | None
    fields: tuple[Field, ...]


@dataclass(frozen=True)
class Variant:
    stem: str
    path: Path
    solution: Solution

    def title(self, lang: Language) -> str:
        return self.solution.mechanism.title_in(lang)

    # --- the form: sheets 1 and 2 at the investigated positions ----------------------
    def field_groups(self) -> tuple[FieldGroup, ...]:
        s = self.solution
        mech = s.mechanism
        frame = set(mech.frame)
        groups: list[FieldGroup] = []
        for i in s.plan_positions:
            if s.problem(s.entry(i)) is not None:
                continue
            plan = s.plan(i)
            points = [p for p in plan.velocity_images if p not in frame]
            links = [str(lid) for lid in plan.omega]
            # μ is checked as V_A / pa (a_A / πa): the scale and its crank segment
            fields = [
                Field("position", i, "mu_V", "", "μ", "V", "v/mm"),
                Field("position", i, "velocity_plan_mm", "pa", "pa", "", "mm"),
                Field("position", i, "mu_a", "", "μ", "a", "a/mm"),
                Field("position", i, "acceleration_plan_mm", "pia", "πa", "", "mm"),
            ]
            fields += [Field("position", i, "velocity", p, "V", p, "m/s") for p in points]
            fields += [Field("position", i, "acceleration", p, "a", p, "m/s2") for p in points]
            fields += [Field("position", i, "omega", k, "ω", k, "rad/s") for k in links]
            fields += [Field("position", i, "eps", k, "ε", k, "rad/s2") for k in links]
            groups.append(
                FieldGroup(1, "plans", i, float(s.positions[s.entry(i)].phi1_deg), tuple(fields))
            )
        if s.diagrams is not None:
            sc = s.diagrams.sheet_check
            fields = []
            for v in sc.values:
                q = "V" if v.quantity == "v" else "a"
                unit = "m/s" if q == "V" else "m/s2"
                fields += [
                    Field("diagrams", v.index, f"{q}_plan", str(v.index), q, "plan", unit),
                    Field("diagrams", v.index, f"{q}_diagram", str(v.index), q, "diagram", unit),
                ]
                if not v.ill_conditioned:
                    fields.append(
                        Field("diagrams", v.index, f"d{q}_percent", str(v.index), "δ", q, "%")
                    )
            fields.append(Field("diagrams", None, "check_passed", "", "", "", "", choice=True))
            groups.append(FieldGroup(1, "check_5", None, None, tuple(fields)))
        fp = s.force_position
        fa = self.forces()
        if fa is not None:
            phi = float(s.positions[s.entry(fp)].phi1_deg)
            links = [str(lid) for lid in fa.loads.links]
            loads = [Field("forces", fp, "weights", k, "G", k, "N") for k in links]
            loads += [Field("forces", fp, "inertia_forces", k, "F", f"in{k}", "N") for k in links]
            loads += [
                Field("forces", fp, "inertia_moments", str(lid), "M", f"in{lid}", "Nm")
                for lid, ld in fa.loads.links.items()
                if abs(float(ld.inertia_moment)) > 0.0
            ]
            groups.append(FieldGroup(2, "loads", fp, phi, tuple(loads)))
            reactions = [Field("forces", fp, "reactions", r, "R", r[1:], "N") for r in fa.reactions]
            groups.append(FieldGroup(2, "reactions", fp, phi, tuple(reactions)))
            balancing = (
                Field("forces", fp, "balancing_force_plans", "", "F", "bal", "N"),
                Field("forces", fp, "balancing_force_lever", "", "F", "bal", "N"),
                Field("forces", fp, "balancing_moment", "", "M", "bal", "Nm"),
            )
            groups.append(FieldGroup(2, "balancing", fp, phi, balancing))
        return tuple(groups)

    def fields(self) -> dict[str, Field]:
        return {f.id: f for g in self.field_groups() for f in g.fields}

    def forces(self) -> ForceAnalysis | None:
        """The force analysis at the force position, None where there is none."""
        from ..errors import MmtError

        try:
            return self.solution.forces
        except MmtError:
            return None

    # --- the given data ------------------------------------------------------------
    def given(self, lang: Language) -> list[tuple[str, str, str, str]]:
        """(symbol, subscript, value, unit) of the task's data: the crank's speed,
        the frame's points, the links' lengths and masses, the loads."""
        cat = catalogue(lang)
        mech = self.solution.mechanism
        out: list[tuple[str, str, str, str]] = []
        if mech.drive.rpm is not None:
            out.append(("n", "1", cat.number(mech.drive.rpm), cat.unit("rpm")))
        else:
            out.append(("ω", "1", cat.number(mech.drive.omega), cat.unit("rad/s")))
        names = list(mech.frame)
        for a, b in zip(names, names[1:]):
            dx, dy = (mech.frame[b] - mech.frame[a]) * 1000.0
            out.append(("x", f"{a}{b}", cat.number(dx), cat.unit("mm")))
            out.append(("y", f"{a}{b}", cat.number(dy), cat.unit("mm")))
        for lid, link in sorted(mech.links.items()):
            pts = [p for p in link.points if not p.startswith("S")]
            for a, b in zip(pts, pts[1:]):
                d = math.dist(link.points[a], link.points[b]) * 1000.0
                out.append(("l", f"{a}{b}", cat.number(d), cat.unit("mm")))
            if len(pts) > 2:
                d = math.dist(link.points[pts[0]], link.points[pts[-1]]) * 1000.0
                out.append(("l", f"{pts[0]}{pts[-1]}", cat.number(d), cat.unit("mm")))
        for lid, link in sorted(mech.links.items()):
            if link.mass:
                out.append(("m", str(lid), cat.number(link.mass), cat.unit("kg")))
        for f in mech.forces:
            out.append(
                (
                    f.name.split("_")[0],
                    "_".join(f.name.split("_")[1:]),
                    cat.number(f.magnitude),
                    cat.unit("N"),
                )
            )
        return out

    def guides(self, lang: Language) -> list[tuple[str, str, str, str]]:
        """(slider point, x, y, angle) of each guide on the frame: the line
        through (x, y) mm at the angle (degrees) on which the slider moves."""
        cat = catalogue(lang)
        out = []
        for pair in self.solution.mechanism.sliders:
            if pair.guide != FRAME:
                continue
            x, y = (float(c) * 1000.0 for c in pair.through)
            angle = math.degrees(math.atan2(float(pair.direction[1]), float(pair.direction[0])))
            out.append((pair.slider_point, cat.number(x), cat.number(y), cat.number(angle % 180.0)))
        return out

    def schematic_svg(self, lang: Language) -> str:
        """The kinematic scheme of the task sheet (sheets/schematic.py), as SVG text."""
        from ..render.look import load_look
        from ..render.output import render
        from ..render.recording import RecordingBackend
        from ..sheets.schematic import sketch_caption, sketch_schematic

        look = load_look()
        width, height, margin = 150.0, 100.0, 4.0
        cap_h = 2.0 * 2.5 + 5.0
        backend = RecordingBackend(width + 2 * margin, height + cap_h + 2 * margin)
        sk = sketch_schematic(self.solution, look, lang, width_mm=width, height_mm=height)
        sk.replay(backend, margin, margin + cap_h)
        sketch_caption(self.solution, self.path, look, lang, width).replay(
            backend, margin + width / 2.0, margin + cap_h
        )
        return render(backend, "svg", self.title(lang)).decode("utf-8")


class TaskDir:
    """TASKS_DIR: its variants by stem, each loaded and solved once (again
    when its file changes)."""

    def __init__(self, folder: str | Path) -> None:
        self.folder = Path(folder)
        if not self.folder.is_dir():
            from ..errors import SpecError

            raise SpecError(
                str(folder), "TASKS_DIR", "is not a folder", "give the folder of the task files"
            )
        self._lock = threading.Lock()
        self._solved: dict[str, tuple[float, Variant]] = {}
        self._svg: dict[tuple[str, str, float], str] = {}

    def stems(self) -> list[str]:
        """The variants: the stems of the `*.toml` files directly in the folder."""
        return sorted(
            p.stem for p in self.folder.glob("*.toml") if p.is_file() and STEM.fullmatch(p.stem)
        )

    def path(self, stem: str) -> Path | None:
        """The file of a listed stem; None for any other name."""
        for p in self.folder.glob("*.toml"):
            if p.stem == stem and p.is_file() and STEM.fullmatch(p.stem):
                return p
        return None

    def variant(self, stem: str) -> Variant | None:
        """The solved variant, or None for a stem that is not listed; a file that
        does not load or solve raises its MmtError."""
        from ..numerics import quiet_numerics
        from ..solution import solve
        from ..spec import load

        path = self.path(stem)
        if path is None:
            return None
        mtime = path.stat().st_mtime
        with self._lock:
            hit = self._solved.get(stem)
            if hit is not None and hit[0] == mtime:
                return hit[1]
            with quiet_numerics():
                v = Variant(stem, path, solve(load(path)))
            self._solved[stem] = (mtime, v)
            return v

    def schematic(self, stem: str, lang: Language) -> str | None:
        v = self.variant(stem)
        if v is None:
            return None
        key = (stem, lang, v.path.stat().st_mtime)
        with self._lock:
            if key not in self._svg:
                self._svg[key] = v.schematic_svg(lang)
            return self._svg[key]

    def title(self, stem: str, lang: Language) -> str:
        """A variant's title as its file gives it (title_uk in Ukrainian), read
        without solving; the stem where the file gives none or cannot be read."""
        import tomllib

        from ..errors import MmtError
        from ..spec import read_text

        path = self.path(stem)
        if path is None:
            return stem
        try:
            data = tomllib.loads(read_text(path))
        except (MmtError, tomllib.TOMLDecodeError, RecursionError, ValueError):
            return stem
        text = data.get("title_uk") if lang == "uk" else None
        text = text if isinstance(text, str) else data.get("title")
        return text[:200] if isinstance(text, str) and text.isprintable() else stem

    def tasks(self) -> Iterator[tuple[str, list[str]]]:
        """The stems grouped by task ("task03" of "task03_v2"; else the stem itself)."""
        groups: dict[str, list[str]] = {}
        for stem in self.stems():
            m = re.fullmatch(r"(.*?)[_-]v\d+", stem)
            groups.setdefault(m.group(1) if m else stem, []).append(stem)
        yield from groups.items()
