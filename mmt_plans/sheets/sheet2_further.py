"""The further sheets of a force analysis too large for one sheet 2 (README,
Sheet 2; common.further_groups): sheet 3 on ("Force analysis, continued")
holds the Assur groups that sheet 2 leaves out, each drawn apart to μ_l with
its loads, reactions and arms, beside its force polygons to μF.

The polygons are drawn at the guide's scale (longest side 150–300 mm, as
on sheet 2); the groups of one sheet share one μ_l, the finest of the series
at which all of its drawings pack; where none packs, the polygons go a series
step coarser at a time (each then noted "reduced to fit") and the search is
made again. The arms h'_i are numbered on through the groups of the sheets
before, as sheet 2 numbers them through its own."""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any

from ..drawing.layout import LayoutError, SheetLayout, pack
from ..drawing.page import Page, Rect, draw_page
from ..drawing.sketch import Sketch
from ..errors import shown
from ..forces import ForceAnalysis, ForcePolygon, GroupForces
from ..i18n import Language, check_language
from ..render.backend import Backend
from ..scales import FORCE_PLAN
from ..solution import Solution
from .common import (
    EMPTY_MAX,
    further_groups,
    laid_out_empty_share,
    length_scale_step,
    title_fields,
)
from .sheet2 import (
    _COARSEST,
    _FINEST,
    Sheet2,
    _force_scale,
    _polygon_note,
    _translated,
    _with_note,
    _words,
    guide_side,
    sketch_force_polygons,
    sketch_group,
)

__all__ = ["FurtherSheet", "compose_sheet2_further"]

_GAP = 8.0  # mm between the drawings of a further sheet (sheet 2's first trial gap)


@dataclass
class FurtherSheet:
    """One further sheet as laid out: its groups, the μ_l they share, the
    polygons' series steps coarser than the guide's scale, the sketches and
    where each went, and the arm names numbered through it."""

    groups: tuple[GroupForces, ...]
    mu_l: float
    poly_steps: int
    sketches: dict[str, Sketch]
    placed: dict[str, Rect]
    arm_names: tuple[str, ...]
    scales: dict[str, float] = field(default_factory=dict)


def _sketched(
    fa: ForceAnalysis,
    groups: Sequence[GroupForces],
    mus: Sequence[float],
    poly_steps: int,
    look: Any,
    lang: Language,
    before: tuple[str, ...],
    cache: dict[tuple[Any, ...], Any],
) -> tuple[dict[str, Sketch], tuple[str, ...], dict[str, float]]:
    """The drawings of `groups`, each at its μ_l of `mus`, and their polygons
    `poly_steps` steps coarser than the guide's scale (name → sketch, in
    drawing order), the arm names after them and the scales drawn ("mu_l":
    the sheet's, its groups' coarsest)."""
    out: dict[str, Sketch] = {}
    scales = {"mu_l": max(mus)}
    names = before
    for g, mu_l in zip(groups, mus):
        key = ("group", g.name, mu_l, names)
        if key not in cache:
            arms = list(names)
            cache[key] = (sketch_group(fa, g, mu_l, look, lang, arms), tuple(arms))
        out[f"group-{g.name}"], names = cache[key]
        mu_F = _guide_scale(g.polygons, poly_steps)
        gid = f"force-polygon-{g.name}"
        pkey = ("polygon", g.name, mu_F)
        if pkey not in cache:
            drawn = sketch_force_polygons(g.polygons, mu_F, look, lang, gid, f"group {g.name}")
            note = _polygon_note(g.polygons, mu_F, lang)
            cache[pkey] = _with_note(drawn, note) if note else drawn
        out[gid] = cache[pkey]
        scales[f"mu_l {g.name}"] = mu_l
        scales[f"mu_F {g.name}"] = mu_F
    return out, names, scales


def _guide_scale(polygons: Sequence[ForcePolygon], steps: int) -> float:
    """μF `steps` series values coarser than the guide's (_force_scale); finer
    (negative) only as far as the guide's side stays within its 300 mm."""
    for s in range(min(steps, 0), 0):
        mu = _force_scale(polygons, s)
        if guide_side(polygons) / mu <= FORCE_PLAN.high:
            return mu
    return _force_scale(polygons, max(steps, 0))


def _packed(page: Page, sketches: dict[str, Sketch]) -> dict[str, Rect] | None:
    """The drawings from the top left, each group beside its polygon: in
    drawing order, else the largest first; None where neither packs."""
    size = {n: s.extent() for n, s in sketches.items()}
    order = list(sketches)
    for names in (order, sorted(order, key=lambda n: -size[n].width * size[n].height)):
        items = [(n, size[n].width, size[n].height, "top-left") for n in names]
        placed = pack(page, items, _GAP)
        if placed is not None:
            return placed
    return None


def _one_sheet(
    fa: ForceAnalysis,
    groups: Sequence[GroupForces],
    mu0: float,
    page: Page,
    look: Any,
    lang: Language,
    before: tuple[str, ...],
) -> FurtherSheet | None:
    """One further sheet of `groups`: the polygons at the guide's scale (a
    step coarser at a time where nothing packs), the groups at the finest
    μ_l that packs with them (sought by halving the series steps between
    _FINEST and _COARSEST of the textbook's); then, while the field is left
    more than EMPTY_MAX empty (the linter's field-filled rule), the polygons
    a step larger within the guide's 300 mm, then each group alone a step
    larger (its own μ_l under it), where the sheet still packs."""
    cache: dict[tuple[Any, ...], Any] = {}
    steps_of: dict[int, tuple[int, ...]] = {}

    def laid(step: int | tuple[int, ...], poly_steps: int) -> FurtherSheet | None:
        steps = step if isinstance(step, tuple) else (step,) * len(groups)
        mus = [length_scale_step(mu0, k) for k in steps]
        sketches, names, scales = _sketched(fa, groups, mus, poly_steps, look, lang, before, cache)
        placed = _packed(page, sketches)
        if placed is None:
            return None
        sheet = FurtherSheet(tuple(groups), max(mus), poly_steps, sketches, placed, names, scales)
        steps_of[id(sheet)] = steps
        return sheet

    def finest(poly_steps: int) -> FurtherSheet | None:
        """The sheet with its groups at the finest μ_l that packs (None: none does)."""
        best = laid(_COARSEST, poly_steps)
        if best is None:
            return None
        fine, coarse = _FINEST - 1, _COARSEST  # `coarse` packs, `fine` is not known to
        while coarse - fine > 1:
            mid = (fine + coarse) // 2
            trial = laid(mid, poly_steps)
            if trial is None:
                fine = mid
            else:
                coarse, best = mid, trial
        return best

    def empty(sheet: FurtherSheet) -> float:
        return laid_out_empty_share(page, sheet.sketches, sheet.placed, lambda s: s.extent())

    for poly_steps in range(_COARSEST + 1):
        best = finest(poly_steps)
        if best is None:
            continue
        # the field-filled rule: where the field is left more than EMPTY_MAX
        # empty, the polygons a step larger at a time within the guide's 300 mm
        left = empty(best) if poly_steps == 0 else 0.0
        for larger in range(-1, _FINEST - 1, -1):
            if left <= EMPTY_MAX:
                break
            if all(
                _guide_scale(g.polygons, larger) == _guide_scale(g.polygons, larger + 1)
                for g in groups
            ):
                break  # every polygon at the guide's largest
            trial = finest(larger)
            if trial is not None and empty(trial) < left:
                best, left = trial, empty(trial)
        while left > EMPTY_MAX:
            now = steps_of[id(best)]
            for k in range(len(groups)):
                if now[k] <= _FINEST:
                    continue
                trial = laid(now[:k] + (now[k] - 1,) + now[k + 1 :], best.poly_steps)
                if trial is not None and empty(trial) < left:
                    best, left = trial, empty(trial)
                    break
            else:
                break
        return best
    return None


# the last force analysis's further sheets, by language and page (each
# further sheet composed on its own asks for all of them: the arms of one
# are numbered on from those of the sheets before)
_LAID_OUT: dict[tuple[int, str, str], tuple[ForceAnalysis, list[FurtherSheet]]] = {}


def further_sheets(
    fa: ForceAnalysis, solution: Solution, page: Page, look: Any, lang: Language
) -> list[FurtherSheet]:
    """Every further sheet of `fa` laid out, in turn (none where sheet 2
    holds every group)."""
    key = (id(fa), lang, page.name or f"{page.width}x{page.height}")
    kept = _LAID_OUT.get(key)
    if kept is not None and kept[0] is fa:
        return kept[1]
    sheets: list[FurtherSheet] = []
    before: tuple[str, ...] = ()
    for k, run in enumerate(further_groups(len(fa.groups))):
        groups = [fa.groups[i] for i in run]
        laid = _one_sheet(fa, groups, float(solution.mu_l), page, look, lang, before)
        if laid is None:
            names = ", ".join(g.name for g in groups)
            raise LayoutError(
                f"{shown(solution.mechanism.path)}: sheet {k + 3} does not fit on "
                f"{page.name or 'the page'}: the groups {names} with their force polygons "
                f"find no arrangement even {_COARSEST} scale steps smaller than the textbook's\n"
                "  fix: draw sheet 1 alone (--sheet 1)"
            )
        sheets.append(laid)
        before = laid.arm_names
    _LAID_OUT.clear()  # one force analysis kept
    _LAID_OUT[key] = (fa, sheets)
    return sheets


def compose_sheet2_further(
    solution: Solution,
    backend: Backend,
    lang: Language = "en",
    *,
    number: int = 3,
    page: Page | None = None,
    forces: ForceAnalysis | None = None,
) -> Sheet2:
    """Draw further sheet `number` (3, 4 …) of `solution`'s force analysis on
    `backend`: its Assur groups with their force polygons."""
    page = page if page is not None else Page.of("A1")
    check_language(lang)
    fa = forces if forces is not None else solution.require_forces()
    sheets = further_sheets(fa, solution, page, backend.look, lang)
    if not 3 <= number < 3 + len(sheets):
        raise LayoutError(
            f"{shown(solution.mechanism.path)}: sheet {number} does not exist: its force "
            f"analysis takes sheets 2–{2 + len(sheets)}"
            if sheets
            else f"{shown(solution.mechanism.path)}: sheet {number} does not exist: "
            "sheet 2 holds its whole force analysis"
        )
    laid = sheets[number - 3]
    layout = SheetLayout(page, gap=_GAP)
    for name, rect in laid.placed.items():
        layout.register(name, rect, "drawing")
    result = Sheet2(fa, layout, dict(laid.scales), groups=tuple(g.name for g in laid.groups))
    result.shrink = laid.poly_steps
    for name, sketch in laid.sketches.items():
        ext, rect = sketch.extent(), laid.placed[name]
        dx, dy = rect.x - ext.x, rect.y - ext.y
        _translated(sketch, lang).replay(backend, dx, dy)
        result.origins[name] = (dx, dy)
        result.placed[name] = rect
    fields = title_fields(solution, laid.mu_l, lang, sheet=number)
    fields.setdefault("sheet_name", str(_words(lang)["further_sheet"]))
    draw_page(backend, page, fields, lang)
    return result
