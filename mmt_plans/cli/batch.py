"""`mmt-plans batch`: sheets, results JSON and the note for many files at once."""

from __future__ import annotations

import sys
from pathlib import Path

import click

from .draw import sheet_formats
from .errors import reports_errors
from .fields import field_option
from .options import tolerance_percent

MAX_JOBS = 256  # more processes than this only exhaust the memory


@click.command()
@click.argument("inputs", nargs=-1, required=True, type=click.Path(path_type=Path))
@click.option(
    "-o",
    "--out",
    "out_dir",
    required=True,
    type=click.Path(path_type=Path),  # the kind of node: files.check_output
    help="Directory for OUT/<file stem>/ and OUT/summary.csv.",
)
@click.option(
    "--jobs",
    type=click.IntRange(min=1, max=MAX_JOBS),
    default=None,
    help=f"Processes to run at once, 1 to {MAX_JOBS}  [default: every core]",
)
@click.option("--lang", type=click.Choice(["en", "uk"]), default="en", show_default=True)
@click.option("--force", is_flag=True, help="Redo every file, also those an earlier run finished.")
@click.option(
    "--format",
    "formats",
    default="svg,pdf",
    show_default=True,
    callback=sheet_formats,
    help="The sheets' formats, comma-separated: svg, pdf, png, dxf.",
)
@click.option(
    "--moodle",
    is_flag=True,
    help="Also write OUT/quiz.xml (Moodle XML, a cloze question per variant) and OUT/quiz.gift.",
)
@click.option(
    "--tolerance",
    type=float,
    callback=tolerance_percent,  # check's own door: nan and inf refused alike
    default=5.0,
    show_default=True,
    metavar="PERCENT",
    help="The quiz answers' tolerance.",
)
@field_option
@reports_errors
def batch(
    inputs: tuple[Path, ...],
    out_dir: Path,
    jobs: int | None,
    lang: str,
    force: bool,
    formats: tuple[str, ...],
    moodle: bool,
    tolerance: float,
    fields: dict[str, str],
) -> None:
    """Answer keys for many mechanism files: each file's sheets (SVG, PDF),
    results.json and note.pdf into OUT/<file stem>/ (OUT/<relative path>/ when
    stems clash); directories are searched recursively for *.toml. A file an
    earlier run finished (same input, outputs there) is kept unless --force.
    Exit code 1 if some file failed."""
    from ..batch import find_files, run_batch, summary_table, write_summary_csv
    from ..errors import shown
    from ..files import check_output, ensure_dir

    check_output(out_dir, folder=True)
    files = find_files(inputs)
    ensure_dir(out_dir)
    with click.progressbar(
        length=len(files), label=f"{len(files)} files", file=sys.stderr, show_pos=True
    ) as bar:
        results = run_batch(
            files,
            out_dir,
            jobs=jobs,
            lang=lang,
            force=force,
            formats=formats,
            extras=("scheme",) if moodle else (),
            fields=fields,
            progress=lambda result: bar.update(1),
        )
    for r in results:
        if not r.ok:
            name = shown(r.path)
            # a stage's message names the file already ("analysis: FILE: ..."):
            # the line names it once
            message = (r.message or "").replace(f": {name}: ", ": ", 1)
            click.echo(f"error: {name}: {message}", err=True)
    click.echo(summary_table(results, out_dir))
    csv_path = write_summary_csv(results, out_dir / "summary.csv")
    failed = sum(not r.ok for r in results)
    kept = sum(r.kept for r in results)
    kept_note = f" ({kept} kept from an earlier run; --force redoes them)" if kept else ""
    click.echo(
        f"{len(results) - failed} done{kept_note}, {failed} failed; summary written to {csv_path}"
    )
    if moodle:
        from ..batch import QUIZ_GIFT, QUIZ_XML
        from ..files import write_bytes_atomic
        from ..lms import gift, moodle_xml
        from ..lms.keys import quiz_from_keys

        done = [(Path(r.path), Path(r.out_dir)) for r in results if r.ok]
        quiz = quiz_from_keys(done, lang, tolerance)  # type: ignore[arg-type]
        for name, body in ((QUIZ_XML, moodle_xml(quiz)), (QUIZ_GIFT, gift(quiz).encode())):
            click.echo(f"quiz written to {write_bytes_atomic(out_dir / name, body)}")
    if failed:
        sys.exit(1)
