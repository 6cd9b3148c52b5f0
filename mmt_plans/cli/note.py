"""`mmt-plans note`: the A4 calculation and explanatory note of a mechanism
file as one PDF (title page, task sheet, abstract, contents, the calculation,
references)."""

from __future__ import annotations

from pathlib import Path

import click

from .errors import reports_errors
from .fields import field_option, with_fields


@click.command()
@click.argument("file", type=click.Path(dir_okay=False, path_type=Path))
@click.option(
    "-o",
    "--out",
    "target",
    default="note.pdf",
    show_default=True,
    type=click.Path(dir_okay=False, path_type=Path),
    help="The PDF to write.",
)
@click.option("--lang", type=click.Choice(["en", "uk"]), default="en", show_default=True)
@click.option(
    "--partial-turn",
    is_flag=True,
    help="A crank that cannot make a whole turn: analyse the range where it assembles.",
)
@click.option(
    "--form",
    type=click.Choice(["2", "5"]),
    default=None,
    help="The pages' forms: 2 (GOST 2.104 forms 2 and 2a, seed 003) or 5 (GOST 2.106 "
    "forms 5 and 5a, seed 002); default the file's [sheet] note_form, else 2.",
)
@field_option
@reports_errors
def note(
    file: Path,
    target: Path,
    lang: str,
    partial_turn: bool,
    form: str | None,
    fields: dict[str, str],
) -> None:
    """Write the calculation and explanatory note of FILE as a PDF.

    The title page and the task sheet take the names from the file's [sheet]
    table and from --field (author, group, supervisor, university,
    department, discipline, variant, city, year, drawing_number ...); blanks
    to fill in by hand where neither gives them."""
    from ..files import check_output
    from ..note import write_note
    from ..solution import solve
    from ..spec import load
    from ..titles import title_warning

    check_output(target)
    solution = solve(with_fields(load(file), fields), partial_turn=partial_turn)
    path = write_note(solution, target, lang=lang, form=form)  # type: ignore[arg-type]
    warning = title_warning(solution.mechanism, lang)  # type: ignore[arg-type]
    if warning:
        click.echo(warning, err=True)
    click.echo(f"written {path}")
