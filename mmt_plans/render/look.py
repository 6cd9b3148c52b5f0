"""The look of a drawing, read from templates/look.toml.

Line weights, dash patterns, arrowheads and lettering; no geometry. Like
ezdxf's drawing `Configuration`, a `Look` is frozen and changed with
`with_changes(**kw)`.
"""

from __future__ import annotations

import dataclasses
import functools
import json
import math
import os
import tomllib
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from pathlib import Path
from types import MappingProxyType
from typing import Any, Literal, get_args

__all__ = [
    "note_look",
    "LineType",
    "LINE_TYPES",
    "LineStyle",
    "Lettering",
    "Look",
    "templates_dir",
    "load_template",
    "load_json_template",
    "load_look",
]

LineType = Literal["main", "thin", "dashed", "dashdot"]
LINE_TYPES: tuple[LineType, ...] = get_args(LineType)


def templates_dir() -> Path:
    """The templates folder: $MMT_PLANS_TEMPLATES, else the one beside the package."""
    env = os.environ.get("MMT_PLANS_TEMPLATES")
    if env:
        return Path(env)
    return Path(__file__).resolve().parents[2] / "templates"


def load_template(name: str) -> dict[str, Any]:
    """Parse templates/<name> (TOML)."""
    path = templates_dir() / name
    try:
        with path.open("rb") as fh:
            return tomllib.load(fh)
    except FileNotFoundError:
        raise FileNotFoundError(
            f"template {path} not found; set MMT_PLANS_TEMPLATES to the templates folder"
        ) from None


def load_json_template(name: str) -> dict[str, Any]:
    """Parse templates/<name> (JSON)."""
    path = templates_dir() / name
    try:
        return json.loads(path.read_text(encoding="utf-8"))
    except FileNotFoundError:
        raise FileNotFoundError(
            f"template {path} not found; set MMT_PLANS_TEMPLATES to the templates folder"
        ) from None


@dataclass(frozen=True)
class LineStyle:
    """Stroke width and dash pattern (dash, gap, ...) in mm; () is solid."""

    width: float
    dash: tuple[float, ...] = ()


# texts whose advances a Lettering keeps (then it starts afresh)
_EMS_KEPT = 50_000


@dataclass(frozen=True)
class Lettering:
    """ISO 3098 / GOST 2.304 type B lettering. A size is the capital height in mm."""

    families: tuple[str, ...]
    cap_height: float
    slant_deg: float
    advances: Mapping[str, float]  # em fractions per character
    default_advance: float
    min_squeeze: float
    line_pitch: float
    sizes: tuple[float, ...]

    def font_size(self, size: float) -> float:
        """The CSS font-size (em, mm) that gives capitals `size` mm tall."""
        return size / self.cap_height

    def advance_width(self, text: str, size: float) -> float:
        """Sum of the advances of `text` at `size`, in mm, from the metrics table.

        From the table, not the installed font, so that layouts come out the
        same on every machine.
        """
        # the sum of a text's advances, worked out once per text (kept beside
        # the fields, out of the frozen dataclass's comparisons)
        kept = self.__dict__.get("_ems")
        if kept is None or len(kept) > _EMS_KEPT:
            kept = self.__dict__["_ems"] = {}
        ems = kept.get(text)
        if ems is None:
            ems = kept[text] = sum(self.advances.get(ch, self.default_advance) for ch in text)
        return ems * (size / self.cap_height)  # ems * font_size(size)

    def natural_width(self, text: str, size: float) -> float:
        """Width of one line of `text` at `size`, in mm, slant included."""
        # The slant moves the top of the last letter to the right.
        lean = self.lean * size if text else 0.0
        return self.advance_width(text, size) + lean

    @property
    def lean(self) -> float:
        """tan of the slant: how far a letter's top leans right per mm of height."""
        found = self.__dict__.get("_lean")  # worked out once (beside the fields)
        if found is None:
            found = self.__dict__["_lean"] = math.tan(math.radians(self.slant_deg))
        return found  # type: ignore[no-any-return]

    def index_size(self, size: float) -> float:
        """Lettering size of indices: the next smaller standard size; indices of
        the smallest size keep it (GOST 2.304: no lettering under 2.5 mm)."""
        # one answer per size, kept beside the fields as the advances are
        kept = self.__dict__.get("_index_sizes")
        if kept is None or len(kept) > _EMS_KEPT:
            kept = self.__dict__["_index_sizes"] = {}
        found = kept.get(size)
        if found is None:
            smaller = [s for s in self.sizes if s < size - 1e-9]
            found = kept[size] = max(smaller) if smaller else size
        return found  # type: ignore[no-any-return]

    def squeeze(self, text: str, size: float, max_width: float | None) -> float:
        """Horizontal scale (<= 1) that narrows `text` into max_width; never below min_squeeze."""
        if max_width is None:
            return 1.0
        return self._narrowed(self.natural_width(text, size), max_width)

    def _narrowed(self, natural: float, max_width: float) -> float:
        """squeeze() of a line `natural` mm wide."""
        if natural <= max_width or natural == 0.0:
            return 1.0
        return max(self.min_squeeze, max_width / natural)

    def width(self, text: str, size: float, max_width: float | None = None) -> float:
        """Drawn width of one line: natural, or narrowed to fit max_width."""
        natural = self.natural_width(text, size)
        return natural if max_width is None else natural * self._narrowed(natural, max_width)

    def block_height(self, lines: int, size: float) -> float:
        """Height from the top of the first line's capitals to the last baseline."""
        return size + max(lines - 1, 0) * self.line_pitch * size

    def wrap(
        self,
        text: str,
        size: float,
        max_width: float,
        *,
        measure: Callable[[str, float], float] | None = None,
        first_indent: float = 0.0,
    ) -> list[str]:
        """Break `text` at spaces (and at given newlines) into lines no wider than max_width,
        as `measure(line, size)` gives widths (plain text's by default); the very
        first line `first_indent` narrower (a paragraph's indent).

        A single word wider than max_width stays on its own line. Spaces inside
        a line are kept as written (an equation's "  (" stays two).
        """
        measure = measure or self.width
        lines: list[str] = []
        for paragraph in text.split("\n"):
            current = ""
            for word in paragraph.split(" "):
                trial = f"{current} {word}" if current else word
                room = max_width - (first_indent if not lines else 0.0)
                if current and measure(trial, size) > room:
                    lines.append(current)
                    current = word
                else:
                    current = trial
            lines.append(current)
        return lines

    def fit_line(
        self, text: str, box_width: float, box_height: float, sizes: tuple[float, ...] | None = None
    ) -> float:
        """The largest size (of `sizes`) at which `text` fits the box on one
        line, narrowed down to min_squeeze if need be; the smallest size if
        none does. Draw it with max_width=box_width."""
        candidates = sorted(sizes or self.sizes, reverse=True)
        for size in candidates:
            if size <= box_height and self.width(text, size, box_width) <= box_width:
                return size
        return candidates[-1]

    def fit(
        self,
        text: str,
        box_width: float,
        box_height: float,
        sizes: tuple[float, ...] | None = None,
    ) -> tuple[float, list[str]]:
        """The largest size (of `sizes`, default all standard sizes) at which
        `text`, wrapped, fits the box; the smallest size if none does."""
        candidates = sorted(sizes or self.sizes, reverse=True)
        for size in candidates:
            lines = self.wrap(text, size, box_width)
            fits_width = all(self.width(line, size) <= box_width for line in lines)
            if fits_width and self.block_height(len(lines), size) <= box_height:
                return size, lines
        size = candidates[-1]
        return size, self.wrap(text, size, box_width)


@dataclass(frozen=True)
class Look:
    """Everything about how a sheet looks, nothing about where things are."""

    lines: Mapping[str, LineStyle]
    arrow_length: float
    arrow_width: float
    lettering: Lettering
    background: str
    ink: str

    def line(self, kind: LineType) -> LineStyle:
        try:
            return self.lines[kind]
        except KeyError:
            raise ValueError(
                f"unknown line type {kind!r}; expected one of {', '.join(LINE_TYPES)}"
            ) from None

    def with_changes(self, **changes: Any) -> Look:
        return dataclasses.replace(self, **changes)


def _look_from_dict(data: Mapping[str, Any]) -> Look:
    lines = {
        name: LineStyle(float(spec["width"]), tuple(float(d) for d in spec.get("dash", ())))
        for name, spec in data["lines"].items()
    }
    missing = set(LINE_TYPES) - set(lines)
    if missing:
        raise ValueError(f"look template lacks line types: {', '.join(sorted(missing))}")
    let = data["lettering"]
    metrics = load_json_template(str(let["metrics"]))
    per_em = float(metrics["units_per_em"])
    lettering = Lettering(
        families=tuple(let["families"]),
        cap_height=float(let["cap_height"]),
        slant_deg=float(let["slant_deg"]),
        advances=MappingProxyType({ch: float(v) / per_em for ch, v in metrics["advances"].items()}),
        default_advance=float(metrics["default_advance"]) / per_em,
        min_squeeze=float(let["min_squeeze"]),
        line_pitch=float(let["line_pitch"]),
        sizes=tuple(float(s) for s in let["sizes"]),
    )
    return Look(
        lines=MappingProxyType(lines),
        arrow_length=float(data["arrow"]["length"]),
        arrow_width=float(data["arrow"]["width"]),
        lettering=lettering,
        background=str(data["paper"]["background"]),
        ink=str(data["paper"]["ink"]),
    )


@functools.cache
def _default_look(folder: Path) -> Look:
    return _look_from_dict(load_template("look.toml"))


def load_look(path: str | os.PathLike[str] | None = None) -> Look:
    """The look from `path`, or templates/look.toml (read once)."""
    if path is None:
        return _default_look(templates_dir())
    with Path(path).open("rb") as fh:
        return _look_from_dict(tomllib.load(fh))


@functools.cache
def note_look() -> Look:
    """The calculation note's look: templates/note_look.toml (serif lettering)."""
    return load_look(templates_dir() / "note_look.toml")
