"""`Labels.write_later` with retries and `Labels.write_each` write a label
again as an order before wrote it where what its writing asked about stands
as it stood then (drawing/labels.py `_memo_write`), and cut an order short
where it can no longer letter better than the best (`_beaten`): the drawing
made so is the one made writing every label anew in every order, record for
record."""

from __future__ import annotations

import dataclasses
from pathlib import Path
from typing import Any

import numpy as np
import pytest

import mmt_plans
from mmt_plans.drawing.labels import Labels
from mmt_plans.drawing.sketch import Sketch
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
    again = _count_memo_writes(monkeypatch)
    with_memo = _records(_sheet2("shaper"))
    assert again[0] > 0

    _anew(monkeypatch)
    assert with_memo == _records(_sheet2("shaper"))


def _count_memo_writes(monkeypatch: pytest.MonkeyPatch) -> list[int]:
    """How many labels are written again from the memo (its one entry, counted as they are)."""
    again = [0]
    write_again = Labels._write_again

    def counted(self: Labels, memo: Any) -> None:
        again[0] += 1
        write_again(self, memo)

    monkeypatch.setattr(Labels, "_write_again", counted)
    return again


def _anew(monkeypatch: pytest.MonkeyPatch) -> None:
    """Every label written anew, every order to its end."""

    def anew(self: Labels, key: Any, markup: Any, write: Any) -> None:
        write()

    monkeypatch.setattr(Labels, "_memo_write", anew)
    monkeypatch.setattr(Labels, "_beaten", lambda self, bound, far: False)


def _walled_and_free() -> tuple[Sketch, Labels, list[Any]]:
    """A point walled in by a square of main lines hatched inside (its name
    finds no free place near nor a leader: it stands far), and 100 mm off
    three points with room round them; `write_each`'s writes, the walled one last."""
    sk = Sketch(RecordingBackend().look)
    square = [(-8.0, -8.0), (8.0, -8.0), (8.0, 8.0), (-8.0, 8.0), (-8.0, -8.0)]
    for a, b in zip(square, square[1:]):
        sk.line(a, b, "main")
    for y in np.arange(-7.0, 7.5, 1.5):
        sk.line((-7.5, float(y)), (7.5, float(y)), "thin")
    points = [(100.0, 0.0), (110.0, 5.0), (120.0, 0.0)]
    for p in points:
        sk.circle(p, 0.5, fill="black")
    labels = Labels(sk, 3.5)
    writes: list[Any] = [
        (lambda p=p, name=name: labels.place(p, name)) for p, name in zip(points, "ABD")
    ]
    writes.append(lambda: labels.place((0.0, 0.0), "C", towards=(0.0, 1.0)))
    return sk, labels, writes


def test_write_each_writes_again_from_the_memo_what_the_walled_name_leaves_as_it_was(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """The walled name stands far, so all are written once more in the
    order asked (the same), each finding what stands within reach of what
    it asks about as in the first (none is near another): all four written
    again from the memo; then with the walled one first, again from the
    memo, and cut short there (one far already, as many as the best). The
    drawing is the one written anew in every order."""
    again = _count_memo_writes(monkeypatch)
    sk, labels, writes = _walled_and_free()
    labels.write_each(writes, [[0, 1, 2, 3]])
    assert labels.far == 1 and again[0] == 5
    with_memo = _records(sk)
    _anew(monkeypatch)
    sk, labels, writes = _walled_and_free()
    labels.write_each(writes, [[0, 1, 2, 3]])
    assert labels.far == 1
    assert with_memo == _records(sk)
