"""`--field KEY=VALUE` and the [sheet] table: one list of fields, checked at the door."""

from __future__ import annotations

from pathlib import Path

from click.testing import CliRunner

from mmt_plans.cli import main
from mmt_plans.model import SHEET_FIELDS
from mmt_plans.spec import loads

SAMPLE = Path(__file__).resolve().parent.parent / "samples" / "six_link_press.toml"


def test_every_sheet_field_is_accepted_in_the_file() -> None:
    text = SAMPLE.read_text(encoding="utf-8")
    extra = "\n[sheet]\n" + "".join(f'{key} = "v-{key}"\n' for key in SHEET_FIELDS)
    assert "[sheet]" not in text
    mech = loads(text + extra, "x.toml")
    assert dict(mech.sheet) == {key: f"v-{key}" for key in SHEET_FIELDS}


def test_field_option_reaches_the_title_block(tmp_path: Path) -> None:
    result = CliRunner().invoke(
        main,
        [
            "draw",
            str(SAMPLE),
            "-o",
            str(tmp_path),
            "--sheet",
            "1",
            "--format",
            "svg",
            "--field",
            "author=I. Petrenko",
        ],
    )
    assert result.exit_code == 0, result.output
    assert "I. Petrenko" in (tmp_path / "sheet1.svg").read_text(encoding="utf-8")


def test_unknown_field_is_refused_with_the_close_name(tmp_path: Path) -> None:
    result = CliRunner().invoke(
        main, ["draw", str(SAMPLE), "-o", str(tmp_path), "--field", "autor=X"]
    )
    assert result.exit_code == 2
    assert "did you mean 'author'" in result.output
    assert not any(tmp_path.iterdir())
