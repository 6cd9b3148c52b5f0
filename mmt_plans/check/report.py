"""The check's verdict: the text table (in the catalogue's language) and the
JSON report of `--json REPORT`."""

from __future__ import annotations

import json
import math
from dataclasses import dataclass
from typing import Any

from ..i18n import Language, catalogue
from .causes import Cause
from .quantities import Answer

# The unit of each kind: the catalogue's [units] key (text) and the JSON's.
UNITS: dict[str, tuple[str, str]] = {
    "velocity": ("m/s", "m/s"),
    "acceleration": ("m/s2", "m/s2"),
    "omega": ("rad/s", "rad/s"),
    "eps": ("rad/s2", "rad/s2"),
    "velocity_plan_mm": ("mm", "mm"),
    "acceleration_plan_mm": ("mm", "mm"),
    "mu_V": ("v/mm", "(m/s)/mm"),
    "mu_a": ("a/mm", "(m/s2)/mm"),
    "diagram": ("mm", "mm"),
    "balancing_force_plans": ("N", "N"),
    "balancing_force_lever": ("N", "N"),
    "balancing_moment": ("Nm", "N*m"),
    "reaction": ("N", "N"),
    "reaction_component": ("N", "N"),
    "weight": ("N", "N"),
    "inertia_force": ("N", "N"),
    "inertia_moment": ("Nm", "N*m"),
    "inertia_arm_m": ("m", "m"),
    "inertia_arm_mm": ("mm", "mm"),
    "force_plan_mm": ("mm", "mm"),
    "lever_mm": ("mm", "mm"),
    "group_arm_m": ("m", "m"),
    "group_arm_mm": ("mm", "mm"),
    "check_V": ("m/s", "m/s"),
    "check_a": ("m/s2", "m/s2"),
    "check_delta": ("%", "%"),
    "check_verdict": ("", ""),
}


@dataclass(frozen=True)
class CheckedValue:
    """A student's value against the exact one."""

    answer: Answer
    exact: float  # in the answer's terms: a magnitude unless the answer is signed
    deviation_percent: float | None  # (value − exact) / |exact|·100; None for an exact zero
    passed: bool
    named: Cause | None  # the mistake recomputed that the value matches

    @property
    def cause(self) -> str | None:
        """The cause in English (None: none is named)."""
        return None if self.named is None else self.named.text(catalogue("en"))

    @property
    def cause_key(self) -> str | None:
        return None if self.named is None else self.named.key

    @property
    def group(self) -> str | None:
        return None if self.named is None else self.named.group


@dataclass(frozen=True)
class CheckResult:
    mechanism: str  # the mechanism file
    answers: str  # the answers file
    tolerance_percent: float
    values: tuple[CheckedValue, ...]
    # the grid the diagrams' values were judged on: (divisions, given by the answers)
    grid: tuple[int, bool] | None = None

    @property
    def passed(self) -> bool:
        return all(v.passed for v in self.values)

    @property
    def failures(self) -> tuple[CheckedValue, ...]:
        return tuple(v for v in self.values if not v.passed)

    def text(self, lang: Language = "en", *, hide_exact: bool = False) -> str:
        """The table; `hide_exact` leaves out the exact values (a student
        checking their work before the key is out)."""
        from ..report import table

        cat = catalogue(lang)
        w = cat.words("check")
        texts = [None if v.named is None else v.named.text(cat) for v in self.values]
        shared = [t for t in dict.fromkeys(texts) if t is not None and texts.count(t) > 1]
        marks = {t: f"[{k}]" for k, t in enumerate(shared, start=1)}
        rows = []
        for v, t in zip(self.values, texts):
            a = v.answer
            # the deviation and the student's value would give the exact one away
            hidden = hide_exact or v.deviation_percent is None
            dev = "-" if hidden else _signed(cat, v.deviation_percent)  # type: ignore[arg-type]
            cause = "" if v.passed else marks.get(t, t) if t else w["cause_unknown"]
            if hide_exact and t and not v.passed and t not in marks:
                cause = v.named.text(cat, hide_values=True) if v.named is not None else cause
            rows.append(
                [
                    _where(cat, a),
                    label(cat, a),
                    cat.unit(UNITS[a.kind][0]) if UNITS[a.kind][0] else "",
                    "-"
                    if hide_exact
                    else _yes_no(cat, v.exact)
                    if a.kind == "check_verdict"
                    else _num(cat, v.exact),
                    _yes_no(cat, a.value) if a.kind == "check_verdict" else _num(cat, a.value),
                    dev,
                    w["pass"] if v.passed else w["fail"],
                    cause,
                ]
            )
        head = cat.word("check", "title", answers=self.answers, mechanism=self.mechanism)
        out = [head, "=" * len(head), ""]
        headers = [
            w[k]
            for k in (
                "h_pos",
                "h_value",
                "h_unit",
                "h_exact",
                "h_student",
                "h_dev",
                "h_result",
                "h_cause",
            )
        ]
        body = table(headers, rows)
        out += [line.rstrip() for line in _left_last(body, rows, headers[-1])]
        if shared:
            out += ["", w["shared"]]
            for t in shared:
                labels = ", ".join(
                    label(cat, v.answer) for v, tt in zip(self.values, texts) if tt == t
                )
                said = t
                if hide_exact:
                    first = next(v for v, tt in zip(self.values, texts) if tt == t)
                    assert first.named is not None
                    said = first.named.text(cat, hide_values=True)
                out.append(f"  {marks[t]} {said}: {labels}")
        if self.grid is not None:
            key = "grid_given" if self.grid[1] else "grid_tool"
            out += ["", cat.word("check", key, divisions=self.grid[0])]
        n, bad = len(self.values), len(self.failures)
        out += [
            "",
            cat.word("check", "summary", ok=n - bad, n=n, tol=cat.number(self.tolerance_percent))
            + ("" if bad else w["passed"]),
        ]
        return "\n".join(out)

    def json_data(self, lang: Language = "en", *, hide_exact: bool = False) -> dict[str, Any]:
        """The report as JSON data; `hide_exact`: `exact` null and the causes
        without the values they would reveal."""
        cat = catalogue(lang)
        values = []
        for v in self.values:
            a = v.answer
            values.append(
                {
                    "what": a.label,
                    "position": None if a.kind == "check_verdict" else a.where.index,
                    "phi1_deg": None if a.kind == "check_verdict" else _finite(a.where.phi1_deg),
                    "unit": UNITS[a.kind][1],
                    "exact": None if hide_exact else _finite(v.exact),
                    "given": _finite(a.value),
                    "error_percent": None
                    if v.deviation_percent is None or hide_exact
                    else _finite(v.deviation_percent),
                    "passed": bool(v.passed),
                    "cause": None
                    if v.named is None or v.passed
                    else v.named.text(cat, hide_values=hide_exact),
                }
            )
        data: dict[str, Any] = {"passed": bool(self.passed), "values": values}
        if self.grid is not None:
            data["diagrams_grid"] = {"divisions": self.grid[0], "from_answers": self.grid[1]}
        return data

    def json(self, lang: Language = "en", *, hide_exact: bool = False) -> str:
        data = self.json_data(lang, hide_exact=hide_exact)
        return json.dumps(data, ensure_ascii=False, indent=2) + "\n"


# The words in a label (answers.py writes them in English for the JSON's
# "what"): the catalogue's [check] key of each.
_LABEL_WORDS = {
    "(plans)": "l_plans",
    "(lever)": "l_lever",
    "(V plan)": "l_v_plan",
    "(a plan)": "l_a_plan",
    "(force plan)": "l_force_plan",
    "ordinate": "l_ordinate",
    "(mm)": "l_mm",
    "(plan)": "l_plan",
    "(diagram)": "l_diagram",
    "5 % check passed": "l_check_passed",
}


def label(cat: Any, a: Answer) -> str:
    """The answer's label in the catalogue's language, its symbols as the
    sheets write them (ω2, ε2, F_зр)."""
    text = a.label
    if a.kind in ("omega", "eps"):
        text = text.replace(a.kind, cat.word("check", "l_" + a.kind), 1)
    bal = cat.words("symbol_indices")["bal"]
    text = text.replace("F_bal", f"F_{bal}").replace("M_bal", f"M_{bal}")
    for word, key in _LABEL_WORDS.items():
        if word in text:
            text = text.replace(word, cat.word("check", key))
    return text


def _where(cat: Any, a: Answer) -> str:
    if a.kind == "check_verdict":  # the verdict of every investigated position
        return "-"
    if a.where.index is not None:
        return str(a.where.index)
    return cat.word("check", "at_angle", phi=cat.number(a.where.phi1_deg, 6))


def _yes_no(cat: Any, x: float) -> str:
    return cat.word("check", "yes" if x else "no")


def _num(cat: Any, x: float) -> str:
    return cat.localise(f"{x + 0.0:.6g}") if math.isfinite(x) else "-"


def _signed(cat: Any, x: float) -> str:
    text = f"{x + 0.0:+.2f}"
    if text in ("+0.00", "-0.00"):
        text = "0.00"
    return cat.localise(text)


def _finite(x: float) -> float | None:
    return float(x) if math.isfinite(x) else None


def _left_last(body: str, rows: list[list[str]], header: str) -> list[str]:
    """The table with its last column aligned to the left."""
    width = max([len(header), *(len(r[-1]) for r in rows)])
    lines = body.splitlines()
    return [
        line[: len(line) - width] + line[len(line) - width :].strip().ljust(width) for line in lines
    ]
