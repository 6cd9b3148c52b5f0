"""A Moodle quiz from a batch of answer keys (`mmt-plans batch --moodle`): a
category per task, a question per variant with its scheme, the given data and
numerical answers for V and a of the output at the investigated positions, ω
and ε of two links, the balancing force and the frame's reaction on the crank,
each with the batch's tolerance."""

from __future__ import annotations

import json
import math
import re
from collections.abc import Sequence
from pathlib import Path
from typing import Any

import numpy as np

from ..i18n import Language, catalogue
from ..spec import load
from .quiz import NumericalAnswer, Quiz, QuizCategory, QuizQuestion

__all__ = ["quiz_from_keys", "SCHEME_NAME"]

SCHEME_NAME = "scheme.png"


def _task(path: Path) -> tuple[str, str]:
    m = re.search(r"task(\d+)_v(\d+)", path.stem)
    return (m.group(1).lstrip("0") or "0", m.group(2)) if m else (path.stem, "")


def _question(path: Path, folder: Path, lang: Language, tolerance: float) -> QuizQuestion:
    words = catalogue(lang).words("lms")
    units = catalogue(lang).words("units")
    cat = catalogue(lang)
    data = json.loads((folder / "results.json").read_text(encoding="utf-8"))
    mech = load(path)
    given: list[tuple[str, str]] = []
    rpm = mech.drive.n1_rpm
    given.append((str(words["n1"]), f"{cat.number(rpm, 4)} {units['rpm']}"))
    for lid, link in mech.links.items():
        names = list(link.points)
        if len(names) >= 2:
            given.append(
                (
                    f"l{lid} ({names[0]}{names[1]})",
                    f"{cat.number(link.length * 1e3, 4)} {units['mm']}",
                )
            )
        if link.mass:
            given.append((f"m{lid}", f"{cat.number(link.mass, 4)} {units['kg']}"))
    for f in mech.forces:
        given.append((f.name, f"{cat.number(f.magnitude, 4)} {units['N']}"))
    out = mech.study.output
    answers: list[NumericalAnswer] = []
    plans = data.get("plans", [])
    kin = {k["index"]: k for k in data["kinematics"] if k.get("index") is not None}
    for i in plans:
        k = kin.get(i)
        if k is None or "v" not in k:
            continue
        pos = str(words["position"]).format(i=i)
        answers.append(
            NumericalAnswer(
                f"V_{out}, {pos}", float(np.hypot(*k["v"][out])), str(units["m/s"]), tolerance
            )
        )
        answers.append(
            NumericalAnswer(
                f"a_{out}, {pos}", float(np.hypot(*k["a"][out])), str(units["m/s2"]), tolerance
            )
        )
    if plans and plans[0] in kin and "omega" in kin[plans[0]]:
        k = kin[plans[0]]
        pos = str(words["position"]).format(i=plans[0])
        links = sorted(
            (lid for lid in k["omega"] if int(lid) != mech.drive.link),
            key=lambda lid: -abs(k["omega"][lid]),
        )[:2]
        for lid in links:
            answers.append(
                NumericalAnswer(
                    f"|ω{lid}|, {pos}", abs(k["omega"][lid]), str(units["rad/s"]), tolerance
                )
            )
            answers.append(
                NumericalAnswer(
                    f"|ε{lid}|, {pos}", abs(k["eps"][lid]), str(units["rad/s2"]), tolerance
                )
            )
    forces: dict[str, Any] = data.get("forces", {})
    if "balancing_force_plans" in forces and forces["balancing_force_plans"] is not None:
        pos = str(words["position"]).format(i=forces["index"])
        answers.append(
            NumericalAnswer(
                f"F_bal, {pos}", float(forces["balancing_force_plans"]), str(units["N"]), tolerance
            )
        )
        r0 = f"R0{mech.drive.link}" if mech.drive.link < 10 else f"R0_{mech.drive.link}"
        if r0 in forces.get("reactions", {}):
            answers.append(
                NumericalAnswer(
                    f"|{r0}|, {pos}",
                    float(math.hypot(*forces["reactions"][r0])),
                    str(units["N"]),
                    tolerance,
                )
            )
    task, variant = _task(path)
    title = mech.title_in(lang)
    scheme = folder / SCHEME_NAME
    return QuizQuestion(
        name=folder.name,
        title=title,
        given=tuple(given),
        answers=tuple(answers),
        image_png=scheme.read_bytes() if scheme.is_file() else None,
        image_alt=str(words["scheme"]),
    )


def quiz_from_keys(
    items: Sequence[tuple[Path, Path]], lang: Language, tolerance: float, name: str
) -> Quiz:
    """The quiz of the batch's finished items: (input file, output folder) pairs."""
    words = catalogue(lang).words("lms")
    by_task: dict[str, list[QuizQuestion]] = {}
    for path, folder in items:
        task, _ = _task(path)
        label = str(words["task"]).format(task=task) if task.isdigit() else task
        by_task.setdefault(label, []).append(_question(path, folder, lang, tolerance))
    return Quiz(
        name=name,
        categories=tuple(QuizCategory(k, tuple(v)) for k, v in by_task.items()),
        given_heading=str(words["given"]),
        find_heading=str(words["find"]),
    )
