"""One catalogue of words, units and number formats for every output.

Each language is a TOML file beside this module (en.toml, uk.toml) with one
table per output (sheet1, sheet2, note, units, title_block, ...); the keys are
the same in every language. Ukrainian writes the decimal comma and Ukrainian
units (м, мм, м/с, рад/с, Н, Н·м, кг). Nothing else in mmt_plans holds words.

    >>> from mmt_plans.i18n import catalogue
    >>> catalogue("uk").number(2.0943951, 4)
    '2,094'
"""

from __future__ import annotations

import functools
import math
import tomllib
from collections.abc import Mapping
from dataclasses import dataclass
from decimal import Decimal
from pathlib import Path
from types import MappingProxyType
from typing import Any, Literal, get_args

__all__ = ["Language", "LANGUAGES", "Catalogue", "catalogue", "check_language"]

Language = Literal["en", "uk"]
LANGUAGES: tuple[Language, ...] = get_args(Language)


def check_language(lang: str) -> Language:
    if lang not in LANGUAGES:
        raise ValueError(f"unknown language {lang!r}; expected one of {', '.join(LANGUAGES)}")
    return lang  # type: ignore[return-value]


@dataclass(frozen=True)
class Catalogue:
    """The words of one language: `words(table)[key]`, `unit(key)`, numbers."""

    lang: Language
    tables: Mapping[str, Mapping[str, Any]]

    @property
    def decimal(self) -> str:
        return str(self.tables["language"]["decimal"])

    def words(self, table: str) -> Mapping[str, Any]:
        """One table of the catalogue (e.g. "sheet1"), as a read-only mapping."""
        try:
            return self.tables[table]
        except KeyError:
            raise KeyError(f"the {self.lang} catalogue has no table [{table}]") from None

    def word(self, table: str, key: str, **fields: object) -> str:
        """One entry, formatted with `fields`."""
        text = str(self.words(table)[key])
        return text.format(**fields) if fields else text

    def unit(self, key: str) -> str:
        return str(self.words("units")[key])

    def localise(self, text: str) -> str:
        """A number written with '.' in this language's decimal separator."""
        return text.replace(".", self.decimal) if self.decimal != "." else text

    def number(self, x: float, sig: int = 4) -> str:
        """At least `sig` significant digits, no exponent, no trailing zeros, no
        negative zero; the decimal separator of the language: 10.47, 0.2, 12403."""
        x = float(x)
        if not math.isfinite(x):
            return "-"
        if abs(x) < 1e-12:
            text = "0"
        else:
            digits = min(8, max(0, sig - 1 - int(math.floor(math.log10(abs(x))))))
            text = f"{x:.{digits}f}"
            if "." in text:
                text = text.rstrip("0").rstrip(".")
            if text in ("-0", ""):
                text = "0"
        return self.localise(text)

    def plain_number(self, value: float) -> str:
        """Shortest positional decimal that round-trips (scales: 0.0125, 50)."""
        if not math.isfinite(value):
            raise ValueError(f"cannot format {value!r}")
        text = format(Decimal(repr(float(value))).normalize(), "f")
        if "." in text:
            text = text.rstrip("0").rstrip(".")
        if text in ("-0", ""):
            text = "0"
        return self.localise(text)


def _freeze(data: dict) -> Mapping[str, Mapping[str, Any]]:
    return MappingProxyType({k: MappingProxyType(dict(v)) for k, v in data.items()})


@functools.cache
def catalogue(lang: str) -> Catalogue:
    """The catalogue of `lang` ("en" or "uk"), read once."""
    lang = check_language(lang)
    text = Path(__file__).with_name(f"{lang}.toml").read_text(encoding="utf-8")
    return Catalogue(lang, _freeze(tomllib.loads(text)))
