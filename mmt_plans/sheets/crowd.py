"""Where a drawing's names crowd: the names the sheet linter finds far from
what they name, or on a line or another name, and what they name (the points
a detail view, `drawing.detail`, is drawn round)."""

from __future__ import annotations

from collections.abc import Callable, Iterable, Iterator, Mapping, Sequence
from typing import Any

import numpy as np

from ..drawing.labels import Labels
from ..drawing.page import Rect
from ..drawing.sketch import Sketch
from ..i18n import Language
from ..render.recording import Naming
from .lint import Finding, SheetView, label_clear, label_near

__all__ = [
    "crowded",
    "crowded_ends",
    "crowded_names",
    "far_names_again",
    "placer_among",
    "stand_for",
    "written_again",
]


def crowded(sketch: Sketch, lang: Language, strict: bool = True) -> Iterator[Naming]:
    """What the names of a drawing that the sheet linter finds far from what
    they name, or on a line or another name, name (`strict`: a leader across
    a main line counted far however walled in its name, as `label_near`)."""
    view = _view(sketch, lang)
    for naming, _ in _named_at(view, (*label_near(view, strict=strict), *label_clear(view))):
        yield naming


def crowded_names(
    sketch: Sketch, lang: Language, anchors: bool = False, strict: bool = True
) -> np.ndarray:
    """Where the names of a drawing that the sheet linter finds far from what
    they name, or on a line or another name, stand for (mm, one row each: the
    point, or the middle of the segment, they name; with `anchors`, the
    segment's start: where a force is applied; `strict` as `crowded`'s)."""
    return stand_for(crowded(sketch, lang, strict), anchors)


def stand_for(namings: Iterable[Naming], anchors: bool = False) -> np.ndarray:
    """Where `namings` stand for, as `crowded_names`."""
    out = []
    for n in namings:
        end = n.anchor if n.end is None or anchors else n.end
        out.append(((n.anchor[0] + end[0]) / 2.0, (n.anchor[1] + end[1]) / 2.0))
    return np.array(out, dtype=float).reshape(-1, 2)


def crowded_ends(sketch: Sketch, lang: Language) -> np.ndarray:
    """What the crowded names of a drawing (as `crowded_names`) stand for,
    both ends (mm, one row each, x0, y0, x1, y1): the point, or the arrow's
    start, twice; the segment's ends."""
    out = []
    for n in crowded(sketch, lang):
        end = n.end if n.kind == "segment" and n.end is not None else n.anchor
        out.append((n.anchor[0], n.anchor[1], end[0], end[1]))
    return np.array(out, dtype=float).reshape(-1, 4)


def far_names_again(
    sketch: Sketch,
    lang: Language,
    labelling: Mapping[str, Any],
    words: Callable[[str], str],
    fits: Callable[[Rect], bool],
) -> int:
    """On a laid-out drawing, each name the sheet linter finds far from what
    it names written again, alone, among everything else drawn and written
    there (`Labels` with `labelling` and `words`, at the height it has): kept
    where the placer finds it a place near or a leader, the drawing's box
    still `fits`, and the linter then finds fewer names far or on something
    in the drawing; else put back as it was. While the drawing was lettered,
    the place near it was taken by a name that went elsewhere later (gen
    104's view of the loaded mechanism: h2 14.3 mm off its arm, a place by
    it free on the laid-out sheet). Those left far are tried again while
    a pass moves one: a name moved may leave room for one tried before it
    (held-out gen 222 uk's lever view: 'h18' led off the place by p that
    'h13,17' needs). How many it moved (each move leaves fewer names far or
    on something, so the passes end)."""
    view = _view(sketch, lang)
    far = _far(view)
    crowd = _crowd(view) if far else 0
    moved = 0
    while far:
        view, crowd, now_moved = _one_pass(sketch, far, lang, labelling, words, fits, view, crowd)
        moved += now_moved
        if not now_moved:  # a pass that moved none: another would move none
            break
        far = _far(view)
    if not far:
        return moved
    # the last resort of those still far: led across main lines (`across_main`),
    # kept where the linter then finds no place near them free (a name walled
    # in: held-out gen 376's G2 amid its group's forces) and fewer names far
    # or on something
    across = dict(labelling, across_main=True, fine=True)
    crowd = _crowd(view, strict=False)
    return (
        moved
        + _one_pass(sketch, far, lang, across, words, fits, view, crowd, strict=False, led=True)[2]
    )


def _one_pass(
    sketch: Sketch,
    far: Sequence[tuple[Naming, float]],
    lang: Language,
    labelling: Mapping[str, Any],
    words: Callable[[str], str],
    fits: Callable[[Rect], bool],
    view: SheetView,
    crowd: int,
    strict: bool = True,
    led: bool = False,
) -> tuple[SheetView, int, int]:
    """One pass of `far_names_again`: each of `far` written again
    (`_written_again`, with `led`), kept where the drawing still `fits` and
    the linter (`strict` or not) then finds fewer than `crowd` names far or
    on something; else put back. The view and count after it, and how many
    it moved."""
    moved = 0
    for naming, size in far:
        before = list(sketch.calls)
        if _written_again(sketch, naming, size, lang, labelling, words, led) and fits(
            sketch.extent()
        ):
            now = _view(sketch, lang)
            left = _crowd(now, strict)
            if left < crowd:
                view, crowd, moved = now, left, moved + 1
                continue
        sketch.calls[:] = before
    return view, crowd, moved


def placer_among(
    sketch: Sketch,
    lang: Language,
    size: float,
    labelling: Mapping[str, Any],
    words: Callable[[str], str],
) -> Labels:
    """A placer (`Labels` at `size` with `labelling` and `words`) for one
    more name on a lettered drawing, each name written there kept off
    whole: the linter measures the runs of a name (a letter, its index) as
    one box, the placer each run (gen 262's 'H' by a detail's rim, clear of
    G6's letter and index, on the box of the two by 0.5 mm²)."""
    labels = Labels(sketch, size, **labelling, words=words)
    for lab in _view(sketch, lang).labels:
        labels.avoid(lab.box, labels.clearance)
    return labels


def _view(sketch: Sketch, lang: Language) -> SheetView:
    return SheetView(list(sketch.calls), 841.0, 594.0, lang)


def _far(view: SheetView) -> list[tuple[Naming, float]]:
    """What the labels of `view` that the linter finds far from what they
    name name, with each one's letter height."""
    return _named_at(view, label_near(view, strict=True))


def _named_at(view: SheetView, findings: Iterable[Finding]) -> list[tuple[Naming, float]]:
    """What the labels of `view` that `findings` are about (a label's
    finding stands at its box's centre) name, with each one's letter height."""
    found = {f.where for f in findings}
    return [
        (lab.naming, lab.runs[0].size)
        for lab in view.labels
        if lab.naming is not None
        and (round(float(lab.box.centroid.x), 1), round(float(lab.box.centroid.y), 1)) in found
    ]


def _crowd(view: SheetView, strict: bool = True) -> int:
    """How many names of `view` the linter finds far or on something (with
    `strict`, led across a main line too: `label_near`)."""
    return sum(1 for _ in label_near(view, strict)) + sum(1 for _ in label_clear(view))


def _written_again(
    sketch: Sketch,
    naming: Naming,
    size: float,
    lang: Language,
    labelling: Mapping[str, Any],
    words: Callable[[str], str],
    led: bool = False,
) -> bool:
    """`naming`'s label written again (`written_again`) by what it names:
    whether the placer found it a place near it or a leader to one (with
    `led`, any the placer counts far too: one across main lines), on
    nothing."""
    at = [i for i, c in enumerate(sketch.calls) if getattr(c, "naming", None) == naming]
    markup = naming.markup.replace(",\n", ", ")  # names one under another: in one line first

    def write(labels: Labels) -> None:
        if naming.kind == "point":
            labels.place(naming.anchor, markup)
        elif naming.kind == "arrow":
            assert naming.end is not None
            labels.place_arrow(naming.anchor, naming.end, markup)
        else:
            assert naming.end is not None
            labels.place_along(naming.anchor, naming.end, markup, around=True)

    labels = written_again(sketch, at, lang, size, labelling, words, write)
    return (led or labels.far == 0) and labels.unsettled == 0


def written_again(
    sketch: Sketch,
    at: Sequence[int],
    lang: Language,
    size: float,
    labelling: Mapping[str, Any],
    words: Callable[[str], str],
    write: Callable[[Labels], object],
) -> Labels:
    """The calls of one name (their places `at` in `sketch`) taken out, the
    name written again by `write` with a `placer_among` (`size`,
    `labelling`, `words`), and put where it stood among the calls, in its
    groups (the drawing's); the placer, for its counts."""
    groups = sketch.calls[at[0]].groups
    for i in sorted(at, reverse=True):
        del sketch.calls[i]
    start = len(sketch.calls)
    labels = placer_among(sketch, lang, size, labelling, words)
    write(labels)
    written = [c.with_changes(groups=groups) for c in sketch.calls[start:]]
    del sketch.calls[start:]
    sketch.calls[at[0] : at[0]] = written
    return labels
