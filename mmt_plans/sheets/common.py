"""What both sheets share: the title block's fields and the steps of the scale series."""

from __future__ import annotations

import re
import zlib
from collections.abc import Callable, Mapping, Sequence
from pathlib import Path

import shapely
from shapely.geometry.base import BaseGeometry

from ..drawing.page import FIELDS, Page, Rect
from ..drawing.sketch import Sketch
from ..i18n import Language, catalogue
from ..scales import LENGTH_MANTISSA_TEXT, series
from ..solution import Solution
from ..titles import sheet_title

__all__ = [
    "EMPTY_MAX",
    "empty_share",
    "laid_out_empty_share",
    "designation_base",
    "drawing_scale",
    "further_groups",
    "length_scale_step",
    "next_scale",
    "scale_step",
    "sheet_count",
    "title_fields",
]

# The largest share of a sheet's field left empty (the linter's field-filled
# rule, sheets/lint.py; the composers fill to it): here, where the composers
# read it without loading the linter.
EMPTY_MAX = 0.5

# The force analysis on more than one sheet (README, Sheet 2): sheet 2 holds
# the Assur groups, each drawn apart with its force polygon, of a mechanism of
# at most SHEET2_GROUPS groups (the generator's five-dyad chains fill it);
# one of more keeps on sheet 2 the loaded mechanism, the driving link and its
# polygon, the lever and the tables, and its groups with their polygons go on
# further sheets, at most FURTHER_GROUPS to a sheet (their polygons at the
# guide's 150–300 mm), as evenly as their number allows, in the order solved.
SHEET2_GROUPS = 5
FURTHER_GROUPS = 6


def further_groups(count: int) -> tuple[range, ...]:
    """The groups (indices in the order solved) of each further sheet of a
    force analysis of `count` groups: none where sheet 2 holds them all."""
    if count <= SHEET2_GROUPS:
        return ()
    sheets = -(-count // FURTHER_GROUPS)
    bounds = [round(k * count / sheets) for k in range(sheets + 1)]
    return tuple(range(a, b) for a, b in zip(bounds, bounds[1:]))


def sheet_count(solution: Solution) -> int:
    """How many sheets the mechanism's drawings take: sheets 1 and 2 and
    the further sheets of its groups (further_groups; counted on its
    structure where the force analysis was not made)."""
    count = len(solution.forces.groups if solution.forces else solution.structure.groups)
    return 2 + len(further_groups(count))


def empty_share(field_: BaseGeometry, boxes: Sequence[BaseGeometry]) -> float:
    """The share of `field_` outside every one of `boxes` (the field-filled
    rule: the linter on a recorded sheet, sheet 1 on its trial layouts)."""
    used = shapely.union_all(boxes).intersection(field_).area if boxes else 0.0
    return 1.0 - float(used) / float(field_.area)


def laid_out_empty_share(
    page: Page,
    sketches: Mapping[str, Sketch],
    placed: Mapping[str, Rect],
    extent: Callable[[Sketch], Rect],
) -> float:
    """The share of a laid-out sheet's field left empty, as the linter's
    field-filled rule measures it: the frame less the title block's band,
    less the box of every drawing's and table's groups where the layout puts
    them (`placed`; `extent` the sketch's own box): both composers' trials."""
    frame, block = page.frame, page.title_block.rect
    field_ = shapely.box(*frame.bounds).difference(
        shapely.box(block.left, frame.bottom, frame.right, block.top)
    )
    parts = []
    for name, rect in placed.items():
        ext = extent(sketches[name])
        dx, dy = rect.x - ext.x, rect.y - ext.y
        parts += [
            shapely.box(x0 + dx, y0 + dy, x1 + dx, y1 + dy)
            for x0, y0, x1, y1 in sketches[name].group_extents()
        ]
    return empty_share(field_, parts)


def next_scale(mu: float, steps: int) -> float:
    """The series value `steps` places above mu (mu itself for 0)."""
    if steps <= 0:
        return mu
    values = list(series(mu * (1 + 1e-6), mu * 1e4))
    return values[steps - 1]


def drawing_scale(mu_l: float) -> str:
    """μ_l (m/mm) as the scale of the title block: 0.004 → "1:4", 0.0005 → "2:1"."""
    k = float(mu_l) * 1000.0  # mm of the machine per mm of paper
    text = f"{k:.6g}" if k >= 1 else f"{1 / k:.6g}"
    return f"1:{text}" if k >= 1 else f"{text}:1"


def designation_base(solution: Solution, lang: Language = "en") -> str:
    """The designation without the sheet's number, from the file's stem, the
    same on the English and the Ukrainian sheet (one document, one
    designation; GOST 2.201 codes of capitals and digits joined by dots, no
    underscores): the stem's numbers ("task01_v1" → "ТММ.КП.01.1"), or, for a
    stem without digits, a four-digit number made from it. `lang` is kept for
    the callers; the designation does not depend on it."""
    del lang
    prefix = str(catalogue("uk").words("title_block")["designation_prefix"])
    stem = Path(solution.mechanism.path or "").stem.strip()
    if not stem:
        return prefix
    digits = re.findall(r"\d+", stem)
    code = ".".join(digits) if digits else f"{zlib.crc32(stem.encode()) % 10000:04d}"
    return f"{prefix}.{code}"


def title_fields(
    solution: Solution,
    mu_l: float | None = None,
    lang: Language = "en",
    *,
    sheet: int | None = None,
    sheets: int | None = None,
) -> dict[str, str]:
    """The title block's fields: the file's [sheet] entries (and --field), its
    title, the sheet's number, the scale of the mechanism's drawing (μ_l)
    unless the file gives one, and the defaults the title block completes by
    the sheet's number: the designation "<prefix>.<STEM>.0i" unless the file
    gives drawing_number, the catalogue's name of the sheet unless sheet_name,
    and the catalogue's organisation unless organisation, school or group."""
    mech = solution.mechanism
    fields = {
        k: str(v).strip()
        for k, v in dict(mech.sheet or {}).items()
        if k in FIELDS and str(v).strip()
    }
    if "approved" in (mech.sheet or {}) and "approved_by" not in fields:
        fields["approved_by"] = str(mech.sheet["approved"]).strip()
    if mu_l is not None:
        fields.setdefault("scale", catalogue(lang).localise(drawing_scale(mu_l)))  # 1:2,5
    fields.setdefault("title", sheet_title(mech, lang))
    fields["sheet"] = str(sheet) if sheet is not None else fields.get("sheet", "1")
    fields.setdefault("sheets", str(sheets if sheets is not None else sheet_count(solution)))
    fields.setdefault("designation_base", designation_base(solution, lang))
    return {k: v for k, v in fields.items() if v}


def scale_step(mu: float, steps: int) -> float:
    """The series value `steps` places above mu (below it for negative steps)."""
    if steps >= 0:
        return next_scale(mu, steps)
    return list(series(mu * 1e-4, mu * (1 - 1e-6)))[steps]


def length_scale_step(mu_l: float, steps: int) -> float:
    """μ_l `steps` places up (down for negative) the series of the mechanism's
    drawings, 1, 2, 2.5, 4, 5 × 10^k: the GOST 2.302 ratios of the title block."""
    if steps >= 0:
        up = list(series(mu_l * (1 - 1e-6), mu_l * 1e4, LENGTH_MANTISSA_TEXT))
        return up[steps]
    return list(series(mu_l * 1e-4, mu_l * (1 - 1e-6), LENGTH_MANTISSA_TEXT))[steps]
