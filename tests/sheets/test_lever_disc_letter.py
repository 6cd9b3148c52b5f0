"""The letter of a detail view's disc on the lever (#21). Where the lever as
laid out has a name far, it is lettered again on the laid-out sheet
(`_Composer._lever_again`, kept only where fewer names stand far); lettered
so, each disc's letter is written last, at the first point of its rim
(`detail.rim_anchors`, the old up-right one first) where it stands near and
covers nothing. Gen 90 (RPR-PRP-RRR-RPP): the lever's disc A had its letter
10.0 mm from the disc in en and uk, its up-right rim walled in by the
images' names. The detail views and the layout are chosen on the lever
lettered as before, so the letter's place does not choose other views."""

from __future__ import annotations

import pytest
from lettering import composed_sheet2

WALLED = 90  # gen 90: the lever's disc A, its up-right rim crowded


@pytest.mark.parametrize("lang", ["en", "uk"])
def test_regression_gen90_lever_disc_letter_stands_by_its_disc(lang):
    result, _, found = composed_sheet2(WALLED, lang)
    letters = [d.letter for d in result.details]
    assert letters, "gen 90's lever is drawn with a detail view"
    far = [
        f
        for f in found
        if f.rule in ("label-near", "label-clear")
        and any(f.message.startswith(f"'{x}' ") for x in letters)
    ]
    assert far == []


def _walled(walled_in: bool):
    """A disc of 10 mm round the origin in a thin frame that sets the
    drawing's box, a grid of main lines 2 mm apart from 3 mm left of and
    below its centre up and right (`walled_in`: over the whole frame but a
    10 mm pocket 9 mm above the first point of the rim); its letter written up and right of it, as the
    lever writes it, stands 10 mm off (in the open left of or below the
    grid; in the pocket), joined by no leader across main lines."""
    import math

    import numpy as np

    from mmt_plans.drawing.labels import Labels
    from mmt_plans.drawing.sketch import Sketch
    from mmt_plans.render.recording import RecordingBackend

    sk = Sketch(RecordingBackend().look)
    # walled in: the grid over the whole frame, cut round a pocket (|x - 7|,
    # |y - 21| < 5) 9 mm above the first rim point, 6 mm or more from all
    pocket = np.array([7.0, 21.0]) if walled_in else None
    with sk.group("zhukovsky-lever", "lever"):
        for n in (0, 1):  # the lines along x, then along y
            o = 1 - n  # the coordinate across them
            low = -3.0 if pocket is None else float(pocket[o]) - 47.0
            for v in np.arange(low, 40.0, 2.0):
                a, b = [0.0, 0.0], [0.0, 0.0]
                a[o] = b[o] = v
                a[n], b[n] = (-3.0, 40.0) if pocket is None else (-45.0, 45.0)
                spans = [(a[n], b[n])]
                if pocket is not None and abs(v - pocket[o]) < 4.0:
                    spans = [(a[n], float(pocket[n]) - 5.0), (float(pocket[n]) + 5.0, b[n])]
                for lo, hi in spans:
                    a[n], b[n] = lo, hi
                    sk.line(tuple(a), tuple(b), "main")
        sk.polyline([(-50.0, -50.0), (50.0, -50.0), (50.0, 50.0), (-50.0, 50.0), (-50.0, -50.0)])
        sk.circle((0.0, 0.0), 10.0, "thin")
        rim = 10.0 * np.array([math.sqrt(0.5), math.sqrt(0.5)])
        labels = Labels(sk, 3.5)
        labels.place(rim, "A", towards=rim)
    return sk, labels


def _letter(sk):
    (text,) = [c for c in sk.calls if getattr(c, "naming", None) and c.naming.markup == "A"]
    return text


def test_a_far_disc_letter_goes_to_a_free_point_of_the_rim_in_the_drawings_box():
    import math

    import numpy as np
    from test_label_placer import _findings

    from mmt_plans.sheets.sheet2 import _letter_by_rim

    sk, labels = _walled(False)
    assert labels.far == 1 and labels.unsettled == 0  # off in the open
    box = sk.extent()
    _letter_by_rim(sk, np.zeros(2), 10.0, "A", "en")
    text = _letter(sk)
    assert math.isclose(math.dist(text.naming.anchor, (0.0, 0.0)), 10.0)
    assert math.dist(text.naming.anchor, (7.0, 7.0)) > 1.0  # another rim point
    assert text.groups == ("zhukovsky-lever",)
    assert sk.extent() == box
    sk.calls[:] = [c for c in sk.calls if c.name not in ("begin_group", "end_group")]
    assert _findings(sk, ["label-near", "label-clear"]) == []


def test_a_disc_letter_no_rim_point_serves_is_left_as_it_was():
    import numpy as np

    from mmt_plans.sheets.sheet2 import _letter_by_rim

    sk, labels = _walled(True)
    assert labels.far == 1 and labels.unsettled == 0  # in the pocket, far
    before = list(sk.calls)
    _letter_by_rim(sk, np.zeros(2), 10.0, "A", "en")
    assert sk.calls == before
