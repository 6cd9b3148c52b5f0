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
@click.option(
    "--force",
    is_flag=True,
    help="Delete the variants an earlier run left in OUT (and its variants.csv) first.",
)
@reports_errors
def variants(file: Path, count: int, seed: int, spread: float, out_dir: Path, force: bool) -> None:
    """COUNT new variants of FILE: the same structure and branches, a good
    transmission angle, distinct from each other; the same files for the same
    seed. Writes OUT/<stem>_vNN.toml and OUT/variants.csv into a folder that
    holds no earlier variants (--force deletes them)."""
    from ..errors import shown
    from ..files import OutputError, check_output
    from ..variants import earlier_variants, make_variants, write_variants

    check_output(out_dir, folder=True)
    earlier = earlier_variants(out_dir)
    if earlier and not force:
        raise OutputError(
            out_dir,
            f"holds {len(earlier)} files of an earlier variants run "
            f"({', '.join(shown(p.name) for p in earlier[:3])}{', ...' if len(earlier) > 3 else ''})",
            "give a new folder, or add --force to delete them first",
        )
    with click.progressbar(
        length=count, label=f"{count} variants", file=sys.stderr, show_pos=True
    ) as bar:
        made = make_variants(file, count, seed, spread, progress=bar.update)
    for path in earlier:  # only now: a failed run leaves the earlier variants as they were
        path.unlink(missing_ok=True)
    for path in write_variants(made, file, out_dir):
        click.echo(f"written {path}")
