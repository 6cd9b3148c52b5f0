"""The one model of a mechanism: frozen dataclasses, SI units inside.

A mechanism file gives lengths in mm; `spec.py` converts them to metres once,
so everything below this module computes in SI.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field, replace
from functools import cached_property
from typing import Any, Literal

import numpy as np

Sense = Literal["ccw", "cw"]
Acts = Literal["working", "always"]
Stroke = Literal["working", "idle"]

FRAME = 0

# The [sheet] table's fields (and `--field KEY=VALUE`): what the title block of
# the sheets (GOST 2.104 form 1) and the note's title page and small title
# blocks (forms 2/2a) letter. Every one is optional; the outputs give defaults.
SHEET_FIELDS: tuple[str, ...] = (
    # the main inscription
    "drawing_number",  # the designation, e.g. "ТММ.КП.05.00.00"
    "sheet_name",  # overrides the catalogue's name of each sheet
    "organisation",  # the organisation cell (also "school" and "group")
    "school",
    "group",
    "author",  # the student: "developed"
    "date",
    "checked_by",  # the supervisor: "checked"
    "checked_date",
    "tech_control",
    "norm_control",
    "approved_by",
    "approved",  # legacy spelling of approved_by
    "material",
    "letter",
    "mass",
    "scale",
    # the note's title page
    "university",
    "department",
    "discipline",
    "variant",
    "supervisor",  # overrides checked_by on the title page
    "city",
    "year",
    "note_form",  # the note's forms: "2" (GOST 2.104 2, 2a) or "5" (GOST 2.106 5, 5a)
    "lang",
)


def frozen_array(values: Any) -> np.ndarray:
    """A float array that cannot be written to (results are values, not buffers)."""
    arr = np.array(values, dtype=float)
    arr.setflags(write=False)
    return arr


@dataclass(frozen=True)
class Link:
    """A rigid link: its named points in its own coordinates (m)."""

    id: int
    points: Mapping[str, np.ndarray]
    mass: float = 0.0
    cm: np.ndarray = field(default_factory=lambda: frozen_array([0.0, 0.0]))
    J: float = 0.0
    k: float = 1.0 / 12.0

    @property
    def point_names(self) -> tuple[str, ...]:
        return tuple(self.points)

    @cached_property
    def length(self) -> float:
        """Distance of the first two points: the textbook's l of J = k·m·l²."""
        names = self.point_names
        if len(names) < 2:
            return 0.0
        return float(np.linalg.norm(self.points[names[1]] - self.points[names[0]]))

    @property
    def cm_name(self) -> str:
        return f"S{self.id}"


@dataclass(frozen=True)
class Revolute:
    """A revolute (class V) pair at a point shared by two links; `links[0]` carries the pin."""

    point: str
    links: tuple[int, int]

    @property
    def name(self) -> str:
        return self.point

    @property
    def kind(self) -> Literal["R"]:
        return "R"


@dataclass(frozen=True)
class Prismatic:
    """A prismatic pair: `slider` moves along a guide line fixed in link `guide`.

    The slider's first point lies on the line; the slider keeps the guide's
    angle (its own axes stay parallel to those of the guide link).
    """

    slider: int
    guide: int
    through: np.ndarray  # a point of the guide line, guide-link coordinates (m)
    direction: np.ndarray  # unit vector of the line, guide-link coordinates
    slider_point: str  # the slider link's first point

    @property
    def links(self) -> tuple[int, int]:
        return (self.slider, self.guide)

    @property
    def name(self) -> str:
        return f"P{self.slider}/{self.guide}"

    @property
    def kind(self) -> Literal["P"]:
        return "P"


Pair = Revolute | Prismatic


@dataclass(frozen=True)
class Force:
    """An external force from `[[force]]` (the production resistance, usually)."""

    name: str
    link: int
    at: str
    magnitude: float
    acts: Acts = "working"
    direction: np.ndarray | None = None  # unit vector, global


@dataclass(frozen=True)
class Drive:
    link: int
    omega: float  # rad/s, magnitude
    sense: Sense = "ccw"
    rpm: float | None = None
    gear_train: Any = None  # gears.GearTrain when [gears] is given

    @property
    def signed_omega(self) -> float:
        return self.omega if self.sense == "ccw" else -self.omega

    @property
    def n1_rpm(self) -> float:
        return self.omega * 30.0 / math.pi


@dataclass(frozen=True)
class Study:
    output: str
    positions: int = 12
    working_direction: np.ndarray = field(default_factory=lambda: frozen_array([1.0, 0.0]))
    zero: float | None = None  # None: the extreme position; else a crank angle (deg)
    plans: tuple[int, ...] | None = None
    force_position: int | None = None
    angles: tuple[float, ...] = ()
    partial_turn: bool = False  # analyse only where the mechanism assembles (opt-in)


@dataclass(frozen=True)
class Mechanism:
    """A planar linkage as read from a mechanism file (SI units)."""

    title: str
    path: str
    frame: Mapping[str, np.ndarray]
    links: Mapping[int, Link]
    sliders: tuple[Prismatic, ...]
    forces: tuple[Force, ...]
    drive: Drive
    study: Study
    sketch: Mapping[str, np.ndarray] = field(default_factory=dict)
    higher_pairs: tuple[tuple[int, int], ...] = ()
    g: float = 9.81
    sheet: Mapping[str, str] = field(default_factory=dict)
    titles: Mapping[str, str] = field(default_factory=dict)  # by language; "en" is `title`

    def title_in(self, lang: str) -> str:
        """The title in `lang` where the file gives one (title_uk), else `title`."""
        return self.titles.get(lang, self.title)

    def with_changes(self, **kw: Any) -> Mechanism:
        """A copy with some fields replaced (caches are not carried over)."""
        return replace(self, **kw)

    def with_partial_turn(self) -> Mechanism:
        """The same mechanism opted in to analysing a partial turn (--partial-turn)."""
        return replace(self, study=replace(self.study, partial_turn=True))

    # --- derived, computed once -------------------------------------------------
    @cached_property
    def revolutes(self) -> tuple[Revolute, ...]:
        """Every shared point name is a revolute pair; k links make k - 1 pairs.

        The frame, or else the lowest-numbered link, carries the pin (SPEC_FORMAT).
        """
        owners: dict[str, list[int]] = {}
        for name in self.frame:
            owners.setdefault(name, []).append(FRAME)
        for link in self.links.values():
            for name in link.points:
                owners.setdefault(name, []).append(link.id)
        pairs: list[Revolute] = []
        for name, ids in owners.items():
            ids = sorted(ids)
            pairs.extend(Revolute(name, (ids[0], other)) for other in ids[1:])
        return tuple(pairs)

    @property
    def pairs(self) -> tuple[Pair, ...]:
        return self.revolutes + self.sliders

    @cached_property
    def point_owners(self) -> dict[str, tuple[int, ...]]:
        owners: dict[str, list[int]] = {}
        for name in self.frame:
            owners.setdefault(name, []).append(FRAME)
        for link in self.links.values():
            for name in link.points:
                owners.setdefault(name, []).append(link.id)
        return {k: tuple(v) for k, v in owners.items()}

    @cached_property
    def crank_pivot(self) -> str:
        """The point the driving link shares with the frame."""
        link = self.links[self.drive.link]
        return next(p for p in link.points if FRAME in self.point_owners[p])

    @cached_property
    def crank_pin(self) -> str:
        """The one point the driving link shares with another moving link (A)."""
        link = self.links[self.drive.link]
        return next(
            p for p in link.points if any(o not in (FRAME, link.id) for o in self.point_owners[p])
        )

    @property
    def crank_length(self) -> float:
        link = self.links[self.drive.link]
        return float(np.linalg.norm(link.points[self.crank_pin] - link.points[self.crank_pivot]))
