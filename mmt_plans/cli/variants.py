"""`mmt-plans variants`: new variants of a task from one mechanism file."""

from __future__ import annotations

import sys
from pathlib import Path

import click

from .errors import reports_errors


@click.command()
@click.argument("file", type=click.Path(dir_okay=False, path_type=Path))
@click.option("--count", type=click.IntRange(1, 500), default=10, show_default=True)
@click.option("--seed", type=int, default=1, show_default=True)
@click.option(
    "--spread",
    type=click.FloatRange(0.0, 50.0, min_open=True),
    default=15.0,
    show_default=True,
    metavar="PERCENT",
    help="Each length, mass, speed and load varied within ± this.",
)
@click.option("-o", "--out", "out_dir", required=True, type=click.Path(path_type=Path))
@reports_errors
def variants(file: Path, count: int, seed: int, spread: float, out_dir: Path) -> None:
    """COUNT new variants of FILE: the same structure and branches, a good
    transmission angle, distinct from each other; the same files for the same
    seed. Writes OUT/<stem>_vNN.toml and OUT/variants.csv."""
    from ..files import check_output
    from ..variants import make_variants, write_variants

    check_output(out_dir, folder=True)
    with click.progressbar(
        length=count, label=f"{count} variants", file=sys.stderr, show_pos=True
    ) as bar:
        made = make_variants(file, count, seed, spread, progress=bar.update)
    for path in write_variants(made, file, out_dir):
        click.echo(f"written {path}")
