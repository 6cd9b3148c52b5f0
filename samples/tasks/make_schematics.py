"""Draw the kinematic scheme of every task file, to check the tasks at a glance.

    .venv/bin/python samples/tasks/make_schematics.py          # writes <seed>/schematics/
    .venv/bin/python samples/tasks/make_schematics.py --check  # fails if they are out of date

For each seed folder: schematics/contact_sheet.svg (one scheme per file, a row
per task, a column per variant) and its PNG for GitHub, and task_NN.svg (the
first variant of each task, drawn large). The SVG is repeatable; the PNG
depends on the fonts of the machine and is not checked.
"""

from __future__ import annotations

import re
import sys
import tempfile
from pathlib import Path

from mmt_plans.sheets.schematic import write_task_files, write_task_schematics

HERE = Path(__file__).resolve().parent
SEEDS = ("seed003", "seed002")
CONTACT_SHEET = "contact_sheet.svg"


def write(seed_dir: Path, out_dir: Path, png: bool = True) -> list[Path]:
    """Every schematic file of one seed folder into out_dir; returns the SVG paths."""
    sheet = write_task_schematics(seed_dir, out_dir / CONTACT_SHEET, "en")
    written = [sheet, *write_task_files(seed_dir, out_dir, "en")]
    if png:
        from mmt_plans.render.export import svg_to_png

        svg_to_png(sheet, sheet.with_suffix(".png"), dpi=150.0)  # 2.5 mm letters readable on screen
    return written


def stale(seed_dir: Path, shipped: Path) -> list[str]:
    """Names of the shipped SVG files that differ from a fresh drawing (or are missing or extra)."""
    with tempfile.TemporaryDirectory() as tmp:
        fresh = {p.name: p.read_text(encoding="utf-8") for p in write(seed_dir, Path(tmp), png=False)}
    have = {p.name: p.read_text(encoding="utf-8") for p in shipped.glob("*.svg")}
    return sorted(n for n in set(fresh) | set(have) if not same_drawing(fresh.get(n), have.get(n)))


_NUMBER = re.compile(r"-?\d+(?:\.\d+)?")


def same_drawing(a: str | None, b: str | None, tolerance: float = 0.011) -> bool:
    """The same SVG but for coordinates within `tolerance` mm: the files keep
    three decimals, so the last bits of another platform's arithmetic may round
    a coordinate the other way."""
    if a is None or b is None:
        return a is b
    if _NUMBER.sub("#", a) != _NUMBER.sub("#", b):
        return False
    xs, ys = _NUMBER.findall(a), _NUMBER.findall(b)
    return all(abs(float(x) - float(y)) <= tolerance for x, y in zip(xs, ys))


def main(argv: list[str]) -> int:
    check = "--check" in argv
    bad = []
    for seed in SEEDS:
        seed_dir, out = HERE / seed, HERE / seed / "schematics"
        if check:
            bad += [f"{seed}/schematics/{n}" for n in stale(seed_dir, out)]
        else:
            for p in write(seed_dir, out):
                print(p.relative_to(HERE))
    if bad:
        print("out of date (rerun samples/tasks/make_schematics.py):", *bad, sep="\n  ")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
