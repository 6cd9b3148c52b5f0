"""Options shared by several commands, validated by one callback each, so that
every command refuses a bad value with the same message."""

from __future__ import annotations

import click

__all__ = ["tolerance_percent"]


def tolerance_percent(
    ctx: click.Context, param: click.Parameter, value: float | None
) -> float | None:
    """A finite percentage in (0, 100] (click's FloatRange lets nan through):
    `check --tolerance` and `batch --tolerance` alike."""
    from ..check import TOLERANCE_MAX

    if value is not None and not (0 < value <= TOLERANCE_MAX):  # False for nan
        raise click.BadParameter(
            f"{value} is not a percentage in (0, {TOLERANCE_MAX:g}]; give e.g. --tolerance 5"
        )
    return value
