"""The note's times for `make bench` (targets: a note written alone for the
default sample under 1 s, a batch item under 1.5 s).

"note alone" is what `mmt-plans note` does after loading the file: solve,
compose both sheets once (their scales and the figures' drawings), write the
note's PDF. "note from composed sheets" is the note's own cost, the sheets
composed beforehand as a batch item has them. "batch item" is one file of
`mmt-plans batch`: solve, compose once, both sheets as SVG and PDF,
results.json, note.pdf, manifest; its stages are listed under it.
"""

from __future__ import annotations

import tempfile
from collections.abc import Callable, Sequence
from pathlib import Path

from ..report import table
from ..solution import solve
from ..spec import load
from .timing import best_time

DEFAULT = "six_link_press"


def bench_note(files: Sequence[Path], repeat: int, echo: Callable[[str], None]) -> None:
    from ..batch import process_file
    from ..note import write_note
    from ..sheets.compose import compose

    chosen = [p for p in files if p.stem == DEFAULT] or list(files[:1])
    rows = []
    n = max(1, repeat // 2)
    with tempfile.TemporaryDirectory() as out:
        for path in chosen:
            mech = load(path)
            target = Path(out) / "note.pdf"
            solution = solve(mech)
            composed = compose(solution, "en")
            t_own = best_time(lambda: write_note(solution, target, "en", composed=composed), n)
            t_compose = best_time(lambda: compose(solve(mech), "en"), n)
            t_alone = best_time(lambda: write_note(solve(mech), target, "en"), n)
            stages: dict[str, float] = {}

            def item() -> None:
                result = process_file(path, Path(out) / "item", formats=("svg", "pdf"))
                stages.update(result.stages)

            t_item = best_time(item, n)
            rows += [
                [path.stem, "note alone (solve + compose + note.pdf)", f"{t_alone:.3f}"],
                [path.stem, "  of it: solve + compose both sheets", f"{t_compose:.3f}"],
                [path.stem, "  of it: the note from composed sheets", f"{t_own:.3f}"],
                [path.stem, "batch item (sheets SVG+PDF, JSON, note)", f"{t_item:.3f}"],
            ]
            rows += [
                [path.stem, f"  stage {name} (last run)", f"{seconds:.3f}"]
                for name, seconds in stages.items()
            ]
    echo("The calculation note and a batch item (best of repeats, in-process):")
    echo(table(["sample", "what", "seconds"], rows))
    echo("targets: a note alone < 1 s, a batch item < 1.5 s")
    echo("")
