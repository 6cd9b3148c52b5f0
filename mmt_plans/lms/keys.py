"""A Moodle quiz from a batch of answer keys (`mmt-plans batch --moodle`).

A question per variant that can be solved from its own content: the
variant's full given data (every frame point, every link's points and
lengths, masses, centres of mass, J, the guides, the loads with where and
how they act, gravity, the crank's speed and sense, the output and its
working direction), what position 0 is and how positions are numbered, the
sign conventions of the asked values and how they are rounded; the scheme
with its names and the frame's dimensions. Answers: V and a of the output at
the investigated positions, |ω| and |ε| of the two fastest-turning links, the
balancing force (signed) and the frame's reaction on the crank, each rounded
to FIGURES significant figures with the batch's tolerance of the rounded
value; a zero answer gets that percentage of its quantity's scale in the
task (ω1·r for V, ω1²·r for a, ω1 for ω, ω1² for ε, the largest load for a
force).

One category per source task, whatever the files are called: a variant made
by `mmt-plans variants` names its source in its header (variants.variant_source),
and variants of one source share its category; other files share a category
when they have the same mechanism (links, points, guides, output) and the same
title once a variant's number ("v3", "variant 3", "варіант 3") is taken out of
it. Category paths are $course$/top/<the catalogue's quiz name>/<source title>:
no folder name is in them.
"""

from __future__ import annotations

import json
import math
import re
from collections.abc import Sequence
from pathlib import Path
from typing import Any

import numpy as np

from ..i18n import Language, catalogue
from ..model import FRAME, Mechanism
from ..spec import load
from ..variants import variant_source
from .quiz import NumericalAnswer, Quiz, QuizCategory, QuizQuestion, plain_name

__all__ = ["quiz_from_keys", "SCHEME_NAME", "FIGURES", "source_key", "given_data"]

SCHEME_NAME = "scheme.png"
FIGURES = 4  # significant figures of every answer

_VARIANT_WORDS = re.compile(
    r"[\s,;:—–-]*\b(?:v|variant|варіант)\s*\d+\b", flags=re.IGNORECASE | re.UNICODE
)


def source_title(title: str) -> str:
    """The title with a variant's number taken out ("... v3: x" -> "...: x")."""
    out = _VARIANT_WORDS.sub("", title).strip(" ,;—–-")
    return plain_name(out) or plain_name(title)


def _topology(mech: Mechanism) -> tuple[Any, ...]:
    return (
        tuple(sorted((lid, tuple(link.points)) for lid, link in mech.links.items())),
        tuple(sorted(mech.frame)),
        tuple((s.slider, s.guide) for s in mech.sliders),
        mech.drive.link,
        mech.study.output,
    )


def source_key(path: Path, mech: Mechanism) -> tuple[Any, ...]:
    """What identifies the task a file is a variant of (module docstring)."""
    try:
        head = path.read_text(encoding="utf-8-sig")[:4096]
    except (OSError, UnicodeDecodeError):
        head = ""
    marked = variant_source(head)
    if marked is not None:
        return ("variants", marked[0])
    return ("same task", source_title(mech.title), _topology(mech))


def _mm(x: float) -> float:
    return round(float(x) * 1e3, 6) + 0.0


def given_data(mech: Mechanism, lang: Language) -> list[tuple[str, str]]:
    """Every given value of the variant as (label, value text), in the catalogue's words."""
    cat = catalogue(lang)
    w = cat.words("lms")
    u = cat.words("units")
    num = cat.plain_number
    mm, kg, N = str(u["mm"]), str(u["kg"]), str(u["N"])

    def xy(p: Any) -> str:
        return f"({num(_mm(p[0]))}; {num(_mm(p[1]))}) {mm}"

    def vec(p: Any) -> str:
        return f"({num(round(float(p[0]), 9) + 0.0)}; {num(round(float(p[1]), 9) + 0.0)})"

    out: list[tuple[str, str]] = []
    d = mech.drive
    sense = str(w["ccw"] if d.sense == "ccw" else w["cw"])
    if d.rpm is not None:
        speed = f"n1 = {num(d.rpm)} {u['rpm']}"
    else:
        speed = f"ω1 = {num(round(d.omega, 9))} {u['rad/s']}"
    out.append((str(w["crank"]).format(link=d.link), f"{speed}, {sense}"))
    for name, p in mech.frame.items():
        out.append((str(w["frame_point"]).format(name=name), xy(p)))
    for lid, link in mech.links.items():
        names = list(link.points)
        lengths = [
            f"l{lid} ({a}{b}) = {num(_mm(np.hypot(*(link.points[b] - link.points[a]))))} {mm}"
            for i, a in enumerate(names)
            for b in names[i + 1 :]
        ]
        if len(names) >= 2:
            out.append((str(w["link"]).format(link=lid), "; ".join(lengths)))
        if len(names) >= 2:
            own = ", ".join(f"{n} {xy(link.points[n])}" for n in names)
            out.append((str(w["own"]).format(link=lid), own))
        if link.mass:
            out.append((f"m{lid}", f"{num(link.mass)} {kg}"))
            out.append(
                (str(w["cm"]).format(link=lid), f"{xy(link.cm)} {w['in_own'].format(link=lid)}")
            )
            out.append((f"J_S{lid}", f"{cat.number(link.J, 6)} {u['kgm2']}"))
    for s in mech.sliders:
        angle = num(round(math.degrees(math.atan2(s.direction[1], s.direction[0])), 9) + 0.0)
        where = (
            str(w["guide_frame"]) if s.guide == FRAME else str(w["guide_link"]).format(link=s.guide)
        )
        out.append(
            (
                str(w["slider"]).format(link=s.slider, point=s.slider_point),
                str(w["guide"]).format(where=where, through=xy(s.through), angle=angle),
            )
        )
    for f in mech.forces:
        label = str(w["force"]).format(name=f.name, link=f.link, at=f.at)
        mag = f"{num(f.magnitude)} {N}"
        if f.direction is None and f.acts == "working":
            how = str(w["acts_working"])
        elif f.direction is None:
            how = str(w["acts_always"]).format(at=f.at)
        elif f.acts == "working":
            how = str(w["acts_along_working"]).format(d=vec(f.direction))
        else:
            how = str(w["acts_along"]).format(d=vec(f.direction))
        out.append((label, f"{mag}, {how}"))
    if mech.g:
        out.append(("g", f"{num(mech.g)} {u['m/s2']}, {w['down']}"))
    else:
        out.append(("g", str(w["no_gravity"])))
    wd = mech.study.working_direction
    out.append((str(w["output"]), str(w["output_is"]).format(point=mech.study.output, d=vec(wd))))
    return out


def _notes(mech: Mechanism, lang: Language, tolerance: float) -> tuple[str, ...]:
    cat = catalogue(lang)
    w = cat.words("lms")
    st = mech.study
    step = cat.plain_number(round(360.0 / st.positions, 9))
    sense = str(w["ccw"] if mech.drive.sense == "ccw" else w["cw"])
    if st.zero is None:
        zero = str(w["zero_extreme"]).format(out=st.output)
    else:
        zero = str(w["zero_angle"]).format(phi=cat.plain_number(st.zero))
    numbering = str(w["numbering"]).format(last=st.positions - 1, step=step, sense=sense)
    d = mech.drive.link
    r0 = f"R0{d}" if d < 10 else f"R0_{d}"
    return (
        str(w["axes"]),
        f"{zero} {numbering}",
        str(w["signs"]).format(out=st.output, pin=mech.crank_pin, r0=r0),
        str(w["rounding"]).format(n=FIGURES, tol=cat.plain_number(tolerance)),
    )


def _question(
    path: Path, mech: Mechanism, folder: Path, lang: Language, tolerance: float
) -> QuizQuestion:
    words = catalogue(lang).words("lms")
    units = catalogue(lang).words("units")
    data = json.loads((folder / "results.json").read_text(encoding="utf-8"))
    omega1 = abs(mech.drive.omega)
    r = mech.crank_length
    loads = [abs(f.magnitude) for f in mech.forces] + [
        link.mass * mech.g for link in mech.links.values()
    ]
    force_scale = max(loads, default=0.0) or None

    def answer(label: str, value: float, unit: str, scale: float | None) -> NumericalAnswer:
        return NumericalAnswer(
            label, float(value), str(units[unit]), tolerance, scale=scale, figures=FIGURES
        )

    out = mech.study.output
    answers: list[NumericalAnswer] = []
    plans = data.get("plans", [])
    kin = {k["index"]: k for k in data["kinematics"] if k.get("index") is not None}
    for i in plans:
        k = kin.get(i)
        if k is None or "v" not in k:
            continue
        pos = str(words["position"]).format(i=i)
        answers.append(answer(f"V_{out}, {pos}", np.hypot(*k["v"][out]), "m/s", omega1 * r))
        answers.append(answer(f"a_{out}, {pos}", np.hypot(*k["a"][out]), "m/s2", omega1**2 * r))
    if plans and plans[0] in kin and "omega" in kin[plans[0]]:
        k = kin[plans[0]]
        pos = str(words["position"]).format(i=plans[0])
        links = sorted(
            (lid for lid in k["omega"] if int(lid) != mech.drive.link),
            key=lambda lid: -abs(k["omega"][lid]),
        )[:2]
        for lid in links:
            answers.append(answer(f"|ω{lid}|, {pos}", abs(k["omega"][lid]), "rad/s", omega1))
            answers.append(answer(f"|ε{lid}|, {pos}", abs(k["eps"][lid]), "rad/s2", omega1**2))
    forces: dict[str, Any] = data.get("forces", {})
    if forces.get("balancing_force_plans") is not None:
        pos = str(words["position"]).format(i=forces["index"])
        bal = str(catalogue(lang).words("symbol_indices").get("bal", "bal"))
        answers.append(answer(f"F_{bal}, {pos}", forces["balancing_force_plans"], "N", force_scale))
        d = mech.drive.link
        r0 = f"R0{d}" if d < 10 else f"R0_{d}"
        if r0 in forces.get("reactions", {}):
            answers.append(
                answer(f"|{r0}|, {pos}", math.hypot(*forces["reactions"][r0]), "N", force_scale)
            )
    scheme = folder / SCHEME_NAME
    title = plain_name(mech.title_in(lang))
    return QuizQuestion(
        name=title,
        title=title,
        given=tuple(given_data(mech, lang)),
        answers=tuple(answers),
        image_png=scheme.read_bytes() if scheme.is_file() else None,
        image_alt=str(words["scheme"]),
        notes=_notes(mech, lang, tolerance),
    )


def quiz_from_keys(
    items: Sequence[tuple[Path, Path]], lang: Language, tolerance: float, name: str | None = None
) -> Quiz:
    """The quiz of the batch's finished items: (input file, output folder)
    pairs. `name` is the quiz's top category (the catalogue's quiz name by
    default: never a folder's name)."""
    words = catalogue(lang).words("lms")
    groups: dict[tuple[Any, ...], list[tuple[int, str, QuizQuestion]]] = {}
    for order, (path, folder) in enumerate(items):
        mech = load(path)
        key = source_key(Path(path), mech)
        head = ""
        try:
            head = Path(path).read_text(encoding="utf-8-sig")[:4096]
        except (OSError, UnicodeDecodeError):
            pass
        marked = variant_source(head)
        number = marked[1] if marked else order
        q = _question(Path(path), mech, folder, lang, tolerance)
        groups.setdefault(key, []).append((number, source_title(mech.title_in(lang)), q))
    categories: list[QuizCategory] = []
    taken: set[str] = set()
    for members in groups.values():
        members.sort(key=lambda m: m[0])
        label = members[0][1] or str(words["task"]).format(task=len(categories) + 1)
        unique, n = label, 1
        while unique.lower() in taken:
            n += 1
            unique = f"{label} ({n})"
        taken.add(unique.lower())
        seen: set[str] = set()
        questions = []
        for _, _, q in members:
            qname, k = q.name, 1
            while qname.lower() in seen:
                k += 1
                qname = f"{q.name} ({k})"
            seen.add(qname.lower())
            questions.append(q if qname == q.name else _renamed(q, qname))
        categories.append(QuizCategory(unique, tuple(questions)))
    return Quiz(
        name=plain_name(name) if name else str(words["quiz"]),
        categories=tuple(categories),
        given_heading=str(words["given"]),
        find_heading=str(words["find"]),
        gift_image_note=str(words["gift_image"]),
    )


def _renamed(q: QuizQuestion, name: str) -> QuizQuestion:
    from dataclasses import replace

    return replace(q, name=name)
