"""The note's front and back matter (DSTU 3008:2015, seed 003 §III; seed 002
§1): the title page, the task sheet with the scheme and the initial data, the
abstract with its counts, the contents, and the references at the end.

The words come from the catalogue's [note_front], the references from
literature.py (one list for both languages); the names
from the file's [sheet] table (or `--field KEY=VALUE`), blanks to be filled
in by hand where neither gives them; the numbers from the Mechanism and the
Solution, as written in the file (lengths in mm as the task gives them).
"""

from __future__ import annotations

import datetime as _dt
import math
import os
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np

from ..errors import MmtError
from ..i18n import Language, catalogue
from ..titles import title_in
from .content import Block
from .writer import plural

if TYPE_CHECKING:  # pragma: no cover
    from ..solution import Solution

__all__ = [
    "Counts",
    "TitleInfo",
    "title_info",
    "default_year",
    "title_page",
    "task_sheet",
    "data_rows",
    "abstract",
    "contents",
    "references",
    "reference_items",
    "TOC_KINDS",
]

# Blocks that the contents lists (those with a `step`).
TOC_KINDS = ("section", "subsection", "heading")


def default_year() -> str:
    """The year of SOURCE_DATE_EPOCH (reproducible builds), else this year."""
    epoch = os.environ.get("SOURCE_DATE_EPOCH", "").strip()
    if epoch.isdigit():
        return str(_dt.datetime.fromtimestamp(int(epoch), _dt.UTC).year)
    return str(_dt.datetime.now(_dt.UTC).year)


@dataclass(frozen=True)
class TitleInfo:
    """The names on the title page, the task sheet and forms 2/2a."""

    university: str
    department: str
    discipline: str
    title: str
    topic: str
    variant: str
    author: str
    group: str
    supervisor: str
    city: str
    year: str
    designation: str
    organisation: str


@dataclass(frozen=True)
class Counts:
    """The abstract's counts (a pass of the layout gives them)."""

    pages: int = 0
    figures: int = 0
    tables: int = 0
    references: int = 0


def _task_of(path: str) -> tuple[int, int] | None:
    import re

    m = re.search(r"task(\d+)_v(\d+)", os.path.basename(str(path)))
    return (int(m.group(1)), int(m.group(2))) if m else None


def _counted(lang: Language, n: int, forms: Any) -> str:
    return f"{n}\u00a0{plural(lang, n, list(forms))}"


def title_info(analysis: Solution, lang: Language) -> TitleInfo:
    mech = analysis.mechanism
    w = catalogue(lang).words("note_front")
    sheet = {k: str(v) for k, v in dict(getattr(mech, "sheet", None) or {}).items() if str(v)}
    blank = str(w["blank"])
    short = str(w["short_blank"])
    title = title_in(mech, lang)
    variant = sheet.get("variant", "")
    if variant:
        variant = w["variant"].format(variant=variant)
    else:
        tv = _task_of(mech.path)
        variant = w["task_variant"].format(task=tv[0], variant=tv[1]) if tv else ""
    designation = sheet.get("drawing_number", "")
    if designation:
        designation += " ПЗ" if lang == "uk" else " EN"
    return TitleInfo(
        university=sheet.get("university", str(w["university"])),
        department=sheet.get("department", str(w["department"])),
        discipline=sheet.get("discipline", str(w["discipline"])),
        title=title,
        topic=w["topic"].format(title=title),
        variant=variant,
        author=sheet.get("author", blank),
        group=sheet.get("group", short),
        supervisor=sheet.get("supervisor", sheet.get("checked_by", blank)),
        city=sheet.get("city", str(w["city"])),
        year=sheet.get("year", default_year()),
        designation=designation,
        organisation="\n".join(sheet[k] for k in ("school", "group") if k in sheet),
    )


def _center(text: str) -> Block:
    return Block("center", text)


def title_page(info: TitleInfo, lang: Language) -> list[Block]:
    """Page 1: ministry, university, department; the document; the topic and
    variant; who did it and who checks it; city and year."""
    w = catalogue(lang).words("note_front")
    return [
        Block("pagebreak", "none"),
        _center(w["ministry"]),
        _center(info.university),
        _center(info.department),
        Block("space", height=30.0),
        _center(w["document"]),
        _center(w["kind"]),
        _center(f"«{info.discipline}»"),
        Block("space", height=6.0),
        _center(f"«{info.topic}»"),
        Block("space", height=6.0),
        _center(info.variant),
        Block("space", height=40.0),
        Block("text", w["performed"].format(group=info.group), indent=85.0),
        Block("text", info.author, indent=85.0),
        Block("space", height=6.0),
        Block("text", w["supervisor"].format(name=info.supervisor), indent=85.0),
        Block("space", height=-1.0),
        _center(w["city_year"].format(city=info.city, year=info.year)),
    ]


def _n(x: float, lang: Language, sig: int = 4) -> str:
    return catalogue(lang).number(x, sig)


def data_rows(analysis: Solution, lang: Language) -> list[tuple[str, str, str, str]]:
    """The initial data: (quantity, symbol, value, unit) as the file gives them."""
    mech = analysis.mechanism
    w = catalogue(lang).words("note_front")
    u = catalogue(lang).words("units")
    mm = str(w["mm"])
    rows: list[tuple[str, str, str, str]] = []
    for lid in sorted(mech.links):
        link = mech.links[lid]
        names = list(link.points)
        for b in names[1:]:
            d = float(np.linalg.norm(link.points[b] - link.points[names[0]])) * 1e3
            rows.append(
                (
                    w["length"].format(a=names[0], b=b, link=lid),
                    f"l_{{{names[0]}{b}}}",
                    _n(d, lang),
                    mm,
                )
            )
    for p, xy in mech.frame.items():
        x, y = (float(v) * 1e3 for v in xy)
        rows.append(
            (w["fixed"].format(p=p), f"x_{{{p}}}, y_{{{p}}}", f"{_n(x, lang)}; {_n(y, lang)}", mm)
        )
    for s in mech.sliders:
        if s.guide != 0:
            continue
        x, y = (float(v) * 1e3 for v in s.through)
        angle = math.degrees(math.atan2(float(s.direction[1]), float(s.direction[0])))
        rows.append(
            (
                w["guide"].format(link=s.slider),
                "x, y; α",
                f"{_n(x, lang)}; {_n(y, lang)}; {_n(angle, lang)}°",
                mm,
            )
        )
    for lid in sorted(mech.links):
        link = mech.links[lid]
        if link.mass > 0:
            rows.append((w["mass"].format(link=lid), f"m_{{{lid}}}", _n(link.mass, lang), u["kg"]))
    for lid in sorted(mech.links):
        link = mech.links[lid]
        if link.J > 0:
            rows.append(
                (w["inertia"].format(link=lid), f"J_{{S{lid}}}", _n(link.J, lang), u["kgm2"])
            )
    train = getattr(mech.drive, "gear_train", None)
    if train is not None:
        rows.append(
            (
                w["motor"],
                _markup(catalogue(lang).words("gears")["n_m"]),
                _n(train.motor_rpm, lang),
                u["rpm"],
            )
        )
        for k, stage in enumerate(train.stages, 1):
            meshes = getattr(stage, "meshes", None) or (stage,)
            teeth = "; ".join("–".join(str(z) for z in m.z) for m in meshes)
            rows.append((w["stage"].format(k=k), "z", teeth, ""))
    else:
        rows.append((w["rpm"], "n_{1}", _n(mech.drive.n1_rpm, lang), u["rpm"]))
    rows.append((w["sense"], "", w[mech.drive.sense], ""))
    for f in mech.forces:
        rows.append(
            (
                w["force"].format(
                    name=f.name, link=f.link, at=f.at, acts=w.get(f"acts_{f.acts}", f.acts)
                ),
                _force_symbol(f.name),
                _n(f.magnitude, lang),
                u["N"],
            )
        )
    st = mech.study
    rows.append((w["positions"], "n", str(st.positions), ""))
    zero = _n(float(st.zero), lang) + "°" if st.zero is not None else w["extreme"]
    rows.append((w["zero"], "φ_{1}", zero, ""))
    rows.append((w["plans"], "", ", ".join(str(i) for i in analysis.plan_positions), ""))
    if analysis.force_position is not None:
        rows.append((w["force_position"], "", str(analysis.force_position), ""))
    return rows


def _markup(name: str) -> str:
    """ "n_дв" → "n_{дв}"."""
    return _force_symbol(name)


def _force_symbol(name: str) -> str:
    if "_" in name:
        head, tail = name.split("_", 1)
        return f"{head}_{{{tail}}}"
    return name


def task_sheet(analysis: Solution, info: TitleInfo, lang: Language) -> list[Block]:
    """The task: who, what, the scheme (figure), the initial data (table) and
    what is to be done; the signatures of issue and acceptance."""
    w = catalogue(lang).words("note_front")
    blocks = [
        Block("pagebreak", "none"),
        Block("heading", w["task"], "task"),
        _center(w["task_for"].format(discipline=info.discipline)),
        Block("space", height=4.0),
        Block("text", w["task_student"].format(author=info.author, group=info.group), indent=0.1),
        Block("text", w["task_topic"].format(topic=info.topic), indent=0.1),
        Block("text", info.variant, indent=0.1),
        Block("figure", w["scheme"], figure="scheme", height=75.0),
        Block(
            "table",
            w["data"],
            rows=(tuple(w["data_head"]), *data_rows(analysis, lang)),
            widths=(84.0, 26.0, 40.0, 20.0),
        ),
        Block("text", w["todo"], indent=0.1),
    ]
    items = [str(t) for t in w["todo_items"]]
    if getattr(analysis.mechanism.drive, "gear_train", None) is not None:
        items += [str(w["todo_gears"]), str(w["todo_reduction"])]
    for k, item in enumerate(items, 1):
        blocks.append(Block("text", f"{k}) {item}"))
    blocks += [
        Block("text", w["todo_sheets"]),
        Block("space", height=8.0),
        Block("text", w["issued"].format(year=info.year, name=info.supervisor), indent=0.1),
        Block("text", w["accepted"].format(year=info.year, name=info.author), indent=0.1),
    ]
    return blocks


def abstract(analysis: Solution, info: TitleInfo, counts: Counts, lang: Language) -> list[Block]:
    """The abstract (реферат): the counts, object, aim, methods, the results
    in numbers, the key words."""
    w = catalogue(lang).words("note_front")
    blocks = [
        Block("pagebreak", "2"),
        Block("heading", w["abstract"], "abstract"),
        Block(
            "text",
            w["abstract_counts"].format(
                pages=_counted(lang, counts.pages, w["n_pages"]),
                figures=_counted(lang, counts.figures, w["n_figures"]),
                tables=_counted(lang, counts.tables, w["n_tables"]),
                refs=_counted(lang, counts.references, w["n_refs"]),
            ),
        ),
        Block("text", w["abstract_object"].format(title=info.title)),
        Block("text", w["abstract_aim"]),
        Block("text", w["abstract_methods"]),
    ]
    train = getattr(analysis.mechanism.drive, "gear_train", None)
    if train is not None:
        blocks.append(
            Block(
                "text",
                w["abstract_gears"].format(
                    u=_n(train.ratio, lang), n=_n(abs(train.crank_rpm), lang)
                ),
            )
        )
    try:
        fa = analysis.forces_at()
        blocks.append(
            Block(
                "text",
                w["abstract_result"].format(
                    pos=analysis.force_position,
                    plans=_n(fa.balancing_force_plans, lang),
                    lever=_n(fa.balancing_force_lever, lang),
                    d=_n(fa.discrepancy_percent, lang, 3),
                ),
            )
        )
    except (MmtError, AttributeError, TypeError):
        pass
    keywords = str(w["keywords"])
    if train is not None:
        keywords += ", " + str(w["keywords_gears"])
    blocks.append(Block("text", keywords))
    return blocks


def contents(entries: Sequence[Block], lang: Language) -> list[Block]:
    """The contents: a line per numbered heading of `entries`, its page from
    the layout's previous pass."""
    w = catalogue(lang).words("note_front")
    out = [Block("pagebreak", "2a"), Block("heading", w["contents"], "contents")]
    for b in entries:
        if b.kind not in TOC_KINDS or not b.step:
            continue
        indent = 5.0 if b.kind == "subsection" else 0.0
        out.append(Block("toc", b.text, b.step, indent=indent))
    return out


def reference_items(lang: Language) -> list[str]:
    """The references in `lang`: one list for both languages (literature.py)."""
    from .literature import entries

    return entries(lang)


def references(lang: Language) -> list[Block]:
    """The references, numbered, on a page of their own at the end."""
    w = catalogue(lang).words("note_front")
    out = [Block("heading", w["references"], "references")]
    for k, item in enumerate(reference_items(lang), 1):
        out.append(Block("text", f"{k}. {item}"))
    return out


def stamp_fields(info: TitleInfo, lang: Language) -> Mapping[str, Any]:
    w = catalogue(lang).words("note_front")
    return {
        "designation": info.designation,
        "title": w["stamp_title"].format(title=info.title),
        "author": info.author if not set(info.author) <= {"_"} else "",
        "checked_by": info.supervisor if not set(info.supervisor) <= {"_"} else "",
        "organisation": info.organisation,
    }
