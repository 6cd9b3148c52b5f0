"""`mmt-plans check`: a student's answers file against the exact values.

Exit code 0 when every value is within the tolerance, 1 when some is not, 2
for a bad mechanism or answers file (reports_errors)."""

from __future__ import annotations

import sys
from pathlib import Path

import click

from .cli_errors import reports_errors


@click.command()
@click.argument("file", type=click.Path(dir_okay=False, path_type=Path))
@click.argument("answers", type=click.Path(dir_okay=False, path_type=Path))
@click.option("--tolerance", type=click.FloatRange(min=0, min_open=True), default=None,
              metavar="PERCENT",
              help="Pass/fail limit in percent (default: the answers file's "
                   "check.tolerance_percent, else 5).")
@reports_errors
def check(file: Path, answers: Path, tolerance: float | None) -> None:
    """Check the values of ANSWERS (a student's hand drawing) against FILE's exact ones."""
    from .check import check_file

    result = check_file(file, answers, tolerance)
    click.echo(result.text())
    if not result.passed:
        sys.exit(1)
