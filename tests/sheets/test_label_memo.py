"""`Labels.write_later` with retries writes a label again as an order before
wrote it where what its writing asked about stands as it stood then
(drawing/labels.py `_memo_write`): the sheet drawn so is the sheet drawn
writing every label anew, record for record."""

from __future__ import annotations

import dataclasses
from pathlib import Path
from typing import Any

import pytest

import mmt_plans
from mmt_plans.drawing.labels import Labels
from mmt_plans.render.recording import RecordingBackend
from mmt_plans.sheets.sheet2 import compose_sheet2

ROOT = Path(__file__).resolve().parents[2]


def _records(backend: RecordingBackend) -> list[tuple[Any, ...]]:
    """Every call as drawn: its fields, a label's serial and naming's id left
    out (counted across the process, never drawn)."""
    out = []
    for c in backend.calls:
        values = dict(c.__dict__)
        if values.get("naming") is not None:
            values["naming"] = dataclasses.replace(values["naming"], label=0)
        if values.get("label") is not None:
            values["label"] = dataclasses.replace(values["label"], serial=0)
        out.append((c.name, sorted(values.items(), key=lambda kv: kv[0])))
    return out


def _sheet2(name: str) -> RecordingBackend:
    backend = RecordingBackend(841.0, 594.0)
    spec = mmt_plans.load(ROOT / "samples" / f"{name}.toml")
    compose_sheet2(mmt_plans.solve(spec), backend, "en")  # type: ignore[arg-type]
    return backend


def test_labels_written_again_from_the_memo_give_the_same_sheet(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """shaper's sheet 2 (its drawings lettered in several orders): some
    labels are written again from an order before, and the sheet is the one
    drawn writing each label anew in every order."""
    again = 0
    write_again = Labels._write_again

    def counted(self: Labels, memo: Any) -> None:
        nonlocal again
        again += 1
        write_again(self, memo)

    monkeypatch.setattr(Labels, "_write_again", counted)
    with_memo = _records(_sheet2("shaper"))
    assert again > 0

    def anew(self: Labels, key: Any, item: Any) -> None:
        self._write_one(*item)

    monkeypatch.setattr(Labels, "_memo_write", anew)
    assert with_memo == _records(_sheet2("shaper"))
