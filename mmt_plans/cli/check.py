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
from .options import tolerance_percent


@click.command()
@click.argument("file", type=click.Path(dir_okay=False, path_type=Path))
@click.argument("answers", type=click.Path(dir_okay=False, path_type=Path))
@click.option(
    "--tolerance",
    type=float,
    default=None,
    callback=tolerance_percent,
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
    help="Also write the verdict as JSON: passed, and every value with its cause "
    "(- for standard output, without the table).",
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
    from ..files import STDOUT, check_output, write_output

    if json_path is not None:
        check_output(json_path, stdout=True)
    result = check_file(file, answers, tolerance)
    if json_path is not None:
        write_output(json_path, result.json(lang, hide_exact=hide_exact))  # type: ignore[arg-type]
    if json_path is None or str(json_path) != STDOUT:  # standard output carries the JSON alone
        click.echo(result.text(lang, hide_exact=hide_exact))  # type: ignore[arg-type]
    if not result.passed:
        sys.exit(1)
