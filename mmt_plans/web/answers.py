"""The door between a request and `check`: a form's fields or a pasted or
posted answers file become an answers TOML that `check`'s own loader reads
(the CLI's limits, names and messages), and the report goes back to the
student with the exact values withheld unless the instructor released them.
"""

from __future__ import annotations

import json
import math
from collections.abc import Mapping
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from ..errors import SpecError

if TYPE_CHECKING:  # pragma: no cover
    from ..check import CheckResult
    from .tasks import Field

__all__ = [
    "FieldError",
    "STUDENT_MAX",
    "VALUE_TEXT_MAX",
    "answers_from_fields",
    "dump_toml",
    "parse_number",
    "split_student",
    "student_report",
    "valid_student",
]

STUDENT_MAX = 100  # characters of a student's name or group
VALUE_TEXT_MAX = 40  # characters of one number typed in the form
_DEPTH_MAX = 8  # an answers file nests [[position]] velocity = { B = ... }: 3 levels


@dataclass(frozen=True)
class FieldError:
    field: str  # Field.id
    problem: str  # a key of the web words


def parse_number(text: str) -> float | None:
    """A number as a student types it: 1.23, 1,23 (decimal comma), −4.5 (a
    typographic minus), 1e3; None if it is not a finite number."""
    t = text.strip().replace("\u2212", "-").replace(" ", "").replace("\u00a0", "")
    if not t or len(t) > VALUE_TEXT_MAX:
        return None
    if "," in t and "." not in t:
        t = t.replace(",", ".")
    try:
        x = float(t)
    except ValueError:
        return None
    return x if math.isfinite(x) else None


def answers_from_fields(
    fields: Mapping[str, Field], form: Mapping[str, str]
) -> tuple[dict[str, Any], list[FieldError]]:
    """The answers table of the values filled in (empty fields are left out)
    and the fields that are not numbers. Only the variant's own fields are
    read: any other name in the request is ignored."""
    data: dict[str, Any] = {}
    positions: dict[int, dict[str, Any]] = {}
    errors: list[FieldError] = []
    for fid, f in fields.items():
        raw = form.get(fid, "")
        if not raw or not raw.strip():
            continue
        if f.choice:
            if raw not in ("yes", "no"):
                errors.append(FieldError(fid, "not_choice"))
                continue
            data.setdefault("diagrams", {})[f.key] = raw == "yes"
            continue
        x = parse_number(raw)
        if x is None:
            errors.append(FieldError(fid, "not_number"))
            continue
        if f.section == "position":
            assert f.where is not None
            table = positions.setdefault(f.where, {"index": f.where})
        elif f.section == "forces":
            table = data.setdefault("forces", {"index": f.where})
        else:
            table = data.setdefault("diagrams", {})
        if f.name:
            table.setdefault(f.key, {})[f.name] = x
        else:
            table[f.key] = x
    if positions:
        data["position"] = [positions[i] for i in sorted(positions)]
    return data, errors


def split_student(data: dict[str, Any], path: str) -> tuple[dict[str, Any], dict[str, str]]:
    """The answers without their [student] table, and its name and group
    (a table the check does not know: the web's, for the record)."""
    data = dict(data)
    student = data.pop("student", {})
    if not isinstance(student, dict):
        raise SpecError(
            path, "student", "must be a table", 'write [student] name = "…" group = "…"'
        )
    out = {}
    for key in ("name", "group"):
        value = student.get(key)
        if value is None:
            continue
        if not isinstance(value, str) or not valid_student(value):
            raise SpecError(
                path,
                f"student.{key}",
                f"must be text of 1 to {STUDENT_MAX} printable characters",
                f'write {key} = "…"',
            )
        out[key] = value.strip()
    unknown = set(student) - {"name", "group"}
    if unknown:
        raise SpecError(
            path, f"student.{sorted(unknown)[0]}", "unknown key", "allowed keys: name, group"
        )
    return data, out


def valid_student(text: str) -> bool:
    t = text.strip()
    return 0 < len(t) <= STUDENT_MAX and t.isprintable()


def dump_toml(data: Mapping[str, Any], path: str = "<form>") -> str:
    """TOML of an answers table, every table inline (an array of inline tables
    reads back as `[[position]]` does). Keys are quoted; values the check's
    loader refuses (text where a number belongs) are written as they are so
    that its own message names them."""

    def key(k: object) -> str:
        return json.dumps(str(k), ensure_ascii=False)

    def value(v: Any, depth: int) -> str:
        if depth > _DEPTH_MAX:
            raise SpecError(
                path, "TOML", "tables are nested too deeply", "an answers file nests 3 levels"
            )
        if isinstance(v, bool):
            return "true" if v else "false"
        if isinstance(v, int):
            return str(v)
        if isinstance(v, float):
            return (
                "nan"
                if math.isnan(v)
                else ("inf" if v > 0 else "-inf")
                if math.isinf(v)
                else repr(v)
            )
        if isinstance(v, Mapping):
            return (
                "{ " + ", ".join(f"{key(k)} = {value(x, depth + 1)}" for k, x in v.items()) + " }"
            )
        if isinstance(v, list | tuple):
            return "[ " + ", ".join(value(x, depth + 1) for x in v) + " ]"
        return json.dumps(str(v), ensure_ascii=False)

    return "".join(f"{key(k)} = {value(v, 1)}\n" for k, v in data.items())


class _Withheld:
    """A catalogue whose numbers are withheld: a cause's fields (the exact
    value of a sign swapped, the value a mistake gives) print as "…"."""

    def __init__(self, cat: Any) -> None:
        self._cat = cat

    def number(self, x: float, sig: int = 4) -> str:
        return "…"

    def __getattr__(self, name: str) -> Any:
        return getattr(self._cat, name)


def student_report(result: CheckResult, lang: str, released: bool) -> dict[str, Any]:
    """`check --json`'s report; unless `released`, with `exact` and
    `error_percent` null (the deviation and the student's value give the exact
    one away) and the numbers in the causes withheld."""
    from ..i18n import catalogue

    data = result.json_data(lang)  # type: ignore[arg-type]
    if released:
        return data
    hidden = _Withheld(catalogue(lang))
    for v, checked in zip(data["values"], result.values):
        v["exact"] = None
        v["error_percent"] = None
        named = getattr(checked, "named", None)
        if v.get("cause") is not None and named is not None:
            v["cause"] = named.text(hidden)
    return data
