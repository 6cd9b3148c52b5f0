"""`mmt-plans`: click commands. An `MmtError` becomes one clean message and
exit code 2; anything else is a bug: exit code 3 and one line, the traceback
only with --debug (cli/errors.reports_errors)."""

from __future__ import annotations

from pathlib import Path

import click

from .batch import batch
from .check import check
from .draw import draw
from .errors import reports_errors
from .note import note
from .serve import serve
from .variants import variants


@click.group()
@click.version_option(package_name="mmt_plans")
@click.option(
    "--debug",
    is_flag=True,
    help="Show the traceback of an internal error (also: MMT_PLANS_DEBUG=1).",
)
def main(debug: bool) -> None:
    """Graph-analytic analysis of planar linkages: plans, forces, A1 sheets.

    Exit codes: 0 done, 1 some check or batch file failed, 2 bad input or
    unwritable output, 3 internal error (a bug), 130 interrupted."""


@main.command()
@click.argument("file", type=click.Path(dir_okay=False, path_type=Path))
@click.option(
    "--json",
    "json_out",
    type=click.Path(dir_okay=False, path_type=Path),
    help="Write the results JSON here (a regular file or a new path; - for "
    "standard output, without the text report).",
)
@click.option("--quiet", is_flag=True, help="Print nothing but errors.")
@click.option(
    "--partial-turn",
    is_flag=True,
    help="A crank that cannot make a whole turn: analyse the range where the "
    "mechanism assembles (as [study] partial_turn = true).",
)
@reports_errors
def analyze(file: Path, json_out: Path | None, quiet: bool, partial_turn: bool) -> None:
    """Structural, kinematic (and force) analysis of FILE."""
    from ..files import STDOUT, check_output, finite_json, write_output
    from ..report import text_report
    from ..results_json import results as results_json
    from ..solution import solve
    from ..spec import load

    if json_out is not None:
        check_output(json_out, stdout=True)
        quiet = quiet or str(json_out) == STDOUT  # standard output carries the JSON alone
    analysis = solve(load(file), partial_turn=partial_turn)
    results = results_json(analysis)
    text = finite_json(results, str(file)) if json_out is not None else ""
    if not quiet:
        click.echo(text_report(analysis))
    if json_out is not None:
        where = write_output(json_out, text)
        if not quiet:
            click.echo(f"results written to {where}")


@main.command()
@click.option(
    "--samples",
    "sample_dir",
    default="samples",
    show_default=True,
    type=click.Path(file_okay=False, path_type=Path),
)
@click.option("--quick", is_flag=True, help="Fewer repeats (for a smoke run).")
@click.option("--keys", is_flag=True, help="Also the 55 seed-task keys on two workers.")
@click.option("--summary", is_flag=True, help="Only the overview table of the figures.")
@reports_errors
def bench(sample_dir: Path, quick: bool, keys: bool, summary: bool) -> None:
    """Time the analysis of every sample and the vectorised sweep."""
    from ..bench import run_benchmarks

    run_benchmarks(sample_dir, quick=quick, echo=click.echo, keys=keys, summary=summary)


main.add_command(draw)
main.add_command(check)
main.add_command(batch)
main.add_command(variants)
main.add_command(note)
main.add_command(serve)
