"""Lettering of the textbook's symbols as rich-text markup (`Backend.rich_text`:
`_x` or `_{xy}` a subscript, `^x` a superscript)."""

from __future__ import annotations

import re
from collections.abc import Iterable

__all__ = [
    "image_markup",
    "point_markup",
    "component_markup",
    "plain_label",
    "force_markup",
    "equation_markup",
]


def _sup(tag: str) -> str:
    """The textbook's superscripts: τ for the tangential component (the
    solver's labels write t), n normal, k Coriolis, r relative."""
    return "τ" if tag == "t" else tag


# the poles of the velocity plan (and the lever) and of the acceleration plan
_POLES = ("p", "π")


def image_markup(name: str, names: Iterable[str] = ()) -> str:
    """ "S2" → "s_{2}", "B" → "b": images on a plan are lower-case letters.
    Two images never read alike: the image of a point named like a pole (P,
    π) takes a prime, "p'", so that it is never read as the pole; of the
    mechanism's `names` that differ only in case (O and o) the upper-case one
    is written first and plain, each next one with one prime more ("o", "o'")."""
    m = re.fullmatch(r"([A-Za-z]+)(\d+)", name)
    base = name.lower()
    if m:
        base = f"{m.group(1).lower()}_{{{m.group(2)}}}"
    alike = sorted({n for n in (*names, name) if n.lower() == name.lower()}, key=_upper_first)
    primes = alike.index(name) + (name.lower() in _POLES)
    return base + "'" * primes


def _upper_first(name: str) -> tuple[int, str]:
    return (sum(ch.islower() for ch in name), name)


def point_markup(name: str) -> str:
    m = re.fullmatch(r"([A-Za-z]+)(\d+)", name)
    return f"{m.group(1)}_{{{m.group(2)}}}" if m else name


def component_markup(label: str) -> str:
    """ "a^n_BA" → "a^{n}_{BA}", "V_E/0" → "V_{E/0}"."""
    m = re.fullmatch(r"([A-Za-z])(?:\^(\w))?_(.+)", label)
    if not m:
        return label
    sup = f"^{{{_sup(m.group(2))}}}" if m.group(2) else ""
    return f"{m.group(1)}{sup}_{{{_pair_index(m.group(3))}}}"


def _pair_index(index: str) -> str:
    """Two point names with numbers kept apart: "A3O2" → "A3,O2" (never read
    as "A302"); "BA" and "E/0" as they are."""
    names = re.findall(r"[A-Za-z]\d*", index)
    if "/" in index or "".join(names) != index or len(names) != 2:
        return index
    return ",".join(names) if any(ch.isdigit() for ch in index) else index


def plain_label(label: str) -> str:
    """A label for plain lettering (tables): "a^n_BA" → "anBA"."""
    return label.replace("^", "").replace("_", "")


def force_markup(label: str) -> str:
    """A solver's force label as lettering: "R34^n" → "R^{n}_{34}", "F_in4" → "F_{in4}",
    "R0_11" → "R_{0,11}", "G2" → "G_{2}", "F_bal" → "F_{bal}"."""
    m = re.fullmatch(r"R(\d+)_(\d+)(?:\^(\w))?", label)
    if m:
        sup = f"^{{{_sup(m.group(3))}}}" if m.group(3) else ""
        return f"R{sup}_{{{m.group(1)},{m.group(2)}}}"
    m = re.fullmatch(r"([A-Z])(\d+)(?:\^(\w))?", label)
    if m:
        sup = f"^{{{_sup(m.group(3))}}}" if m.group(3) else ""
        return f"{m.group(1)}{sup}_{{{m.group(2)}}}"
    m = re.fullmatch(r"([A-Z])'?_(\w+)", label.replace("'", ""))
    if m:
        return f"{m.group(1)}_{{{m.group(2)}}}"
    return label


def equation_markup(equation: str) -> str:
    return re.sub(r"[A-Za-z]+'?[\w^]*", lambda m: force_markup(m.group(0)), equation)
