"""`--field KEY=VALUE`: the [sheet] fields (title block, note's title page) given
on the command line, over the file's own."""

from __future__ import annotations

import difflib
from collections.abc import Callable, Mapping
from typing import Any, TypeVar

import click

from ..model import SHEET_FIELDS, Mechanism

F = TypeVar("F", bound=Callable[..., Any])

__all__ = ["field_option", "with_fields"]


def _parse(ctx: click.Context, param: click.Parameter, value: tuple[str, ...]) -> dict[str, str]:
    fields: dict[str, str] = {}
    for item in value:
        key, sep, text = item.partition("=")
        key = key.strip()
        if not sep or not key:
            raise click.BadParameter(
                f"{item!r}: write KEY=VALUE, e.g. --field author='I. Petrenko'"
            )
        if key not in SHEET_FIELDS:
            close = difflib.get_close_matches(key, SHEET_FIELDS, n=1)
            hint = f"did you mean {close[0]!r}? " if close else ""
            raise click.BadParameter(
                f"{key!r} is not a [sheet] field; {hint}the fields are {', '.join(SHEET_FIELDS)}"
            )
        if len(text) > 200 or not text.isprintable():
            raise click.BadParameter(f"{key}: at most 200 printable characters")
        fields[key] = text
    return fields


def field_option(fn: F) -> F:
    """The repeatable `--field KEY=VALUE` option, parsed into a dict."""
    return click.option(
        "--field",
        "fields",
        multiple=True,
        callback=_parse,
        metavar="KEY=VALUE",
        help="A [sheet] field over the file's (author, checked_by, drawing_number, "
        "organisation, university, department, variant, ...); repeatable.",
    )(fn)


def with_fields(mech: Mechanism, fields: Mapping[str, str]) -> Mechanism:
    """The mechanism with `fields` written over its [sheet] table."""
    if not fields:
        return mech
    return mech.with_changes(sheet={**dict(mech.sheet or {}), **fields})
