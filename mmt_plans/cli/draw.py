"""`mmt-plans draw`: the A1 sheets of a mechanism file as SVG, PDF, PNG."""

from __future__ import annotations

from pathlib import Path

import click

from .errors import reports_errors
from .fields import field_option, with_fields


def sheet_choice(ctx: click.Context, param: click.Parameter, value: str) -> str:
    """ "all" or a sheet's number (1, 2, 3 …: whether the mechanism has it is
    known once solved)."""
    if value == "all" or (value.isdigit() and int(value) >= 1):
        return value
    raise click.BadParameter(f"{value!r} is not a sheet: expected 1, 2, 3 … or all")


def sheet_formats(ctx: click.Context, param: click.Parameter, value: str) -> tuple[str, ...]:
    from ..render.output import FORMATS

    items = tuple(v.strip().lower() for v in value.split(",") if v.strip())
    bad = [v for v in items if v not in FORMATS]
    if bad or not items:
        raise click.BadParameter(f"expected a comma-separated subset of {','.join(FORMATS)}")
    return items


@click.command()
@click.argument("file", type=click.Path(dir_okay=False, path_type=Path))
@click.option(
    "-o",
    "--out",
    "out_dir",
    default="out",
    show_default=True,
    type=click.Path(path_type=Path),  # the kind of node: files.check_output
    help="Directory for the sheets.",
)
@click.option(
    "--format",
    "formats",
    default="svg,pdf,png",
    show_default=True,
    callback=sheet_formats,
    help="Comma-separated: svg, pdf, png, dxf.",
)
@click.option("--lang", type=click.Choice(["en", "uk"]), default="en", show_default=True)
@click.option(
    "--sheet",
    callback=sheet_choice,
    default="all",
    show_default=True,
    help="1, 2, a further sheet of a force analysis too large for sheet 2 (3 …), or all.",
)
@click.option(
    "--partial-turn",
    is_flag=True,
    help="A crank that cannot make a whole turn: draw the range where it assembles.",
)
@field_option
@reports_errors
def draw(
    file: Path,
    out_dir: Path,
    formats: tuple[str, ...],
    lang: str,
    sheet: str,
    partial_turn: bool,
    fields: dict[str, str],
) -> None:
    """Draw the A1 sheets of FILE."""
    from ..files import check_output
    from ..sheets.compose import available_sheets, compose, write_composed
    from ..solution import solve
    from ..spec import load

    check_output(out_dir, folder=True)
    numbers = sorted(available_sheets()) if sheet == "all" else [int(sheet)]
    for n in numbers:  # a link, FIFO or device where a sheet goes: refused before the work
        for fmt in formats:
            check_output(out_dir / f"sheet{n}.{fmt}")
    solution = solve(
        with_fields(load(file), fields), partial_turn=partial_turn, forces=max(numbers) >= 2
    )
    if sheet == "all":  # and the further sheets of a force analysis too large for sheet 2
        numbers = sorted(available_sheets(solution))
        for n in numbers[2:]:
            for fmt in formats:
                check_output(out_dir / f"sheet{n}.{fmt}")
    from ..titles import has_title, sheet_title

    if not has_title(solution.mechanism, lang):  # type: ignore[arg-type]
        from ..i18n import catalogue

        built = sheet_title(solution.mechanism, lang)  # type: ignore[arg-type]
        words = catalogue(lang).words("titles")  # type: ignore[arg-type]
        click.echo(str(words["no_title"]).format(file=file, lang=lang, title=built), err=True)
    composed = compose(solution, lang, numbers)  # type: ignore[arg-type]
    for path in write_composed(composed, solution, out_dir, formats, numbers):
        click.echo(f"written {path}")
