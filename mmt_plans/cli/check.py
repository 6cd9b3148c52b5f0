"""`mmt-plans check`: a student's answers file against the exact values.

Exit code 0 when every value is within the tolerance, 1 when some is not, 2
for a bad mechanism or answers file (reports_errors)."""

from __future__ import annotations

import sys
from pathlib import Path

import click

from .errors import reports_errors


def _tolerance(ctx: click.Context, param: click.Parameter, value: float | None) -> float | None:
    """A finite percentage in (0, 100] (click's FloatRange lets nan through)."""
    from ..check import TOLERANCE_MAX

    if value is not None and not (0 < value <= TOLERANCE_MAX):  # False for nan
        raise click.BadParameter(
            f"{value} is not a percentage in (0, {TOLERANCE_MAX:g}]; give e.g. --tolerance 5"
        )
    return value


@click.command()
@click.argument("file", type=click.Path(dir_okay=False, path_type=Path))
@click.argument("answers", type=click.Path(dir_okay=False, path_type=Path))
@click.option(
    "--tolerance",
    type=float,
    default=None,
    callback=_tolerance,
    metavar="PERCENT",
    help="Pass/fail limit in percent (default: the answers file's "
    "check.tolerance_percent, else 5).",
)
@reports_errors
def check(file: Path, answers: Path, tolerance: float | None) -> None:
    """Check the values of ANSWERS (a student's hand drawing) against FILE's exact ones."""
    from ..check import check_file

    result = check_file(file, answers, tolerance)
    click.echo(result.text())
    if not result.passed:
        sys.exit(1)
