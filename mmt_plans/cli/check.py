"""`mmt-plans check`: a student's answers file against the exact values.

Exit code 0 when every value is within the tolerance, 1 when some is not, 2
for a bad mechanism or answers file (reports_errors). `--json REPORT` writes
the verdict as JSON too; `--lang uk` prints the table in Ukrainian; `--hide-exact` leaves the exact
values out of both."""

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
@click.option(
    "--json",
    "json_path",
    type=click.Path(dir_okay=False, path_type=Path),
    default=None,
    metavar="REPORT",
    help="Also write the verdict as JSON: passed, and every value with its cause.",
)
@click.option("--lang", type=click.Choice(["en", "uk"]), default="en", show_default=True)
@click.option(
    "--hide-exact",
    is_flag=True,
    default=False,
    help="Verdicts and causes without the exact values (JSON exact: null), "
    "for students checking their own work.",
)
@reports_errors
def check(
    file: Path,
    answers: Path,
    tolerance: float | None,
    json_path: Path | None,
    lang: str,
    hide_exact: bool,
) -> None:
    """Check the values of ANSWERS (a student's hand drawing) against FILE's exact ones."""
    from ..check import check_file
    from ..files import write_text_atomic

    result = check_file(file, answers, tolerance)
    if json_path is not None:
        write_text_atomic(json_path, result.json(lang, hide_exact=hide_exact))  # type: ignore[arg-type]
    click.echo(result.text(lang, hide_exact=hide_exact))  # type: ignore[arg-type]
    if not result.passed:
        sys.exit(1)
