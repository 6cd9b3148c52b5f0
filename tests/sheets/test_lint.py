"""The sheet linter (mmt_plans/sheets/lint.py): each rule finds a drawing that
breaks it and passes one that keeps it, on hand-made recordings; then the
rules of the text class on real sheets (a fixed small subset; `make
sheets-lint` runs them all over every sample, seed task and generated
mechanism)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from mmt_plans.drawing.table import Table, _one_format_per_column
from mmt_plans.render.recording import RecordingBackend
from mmt_plans.sheets.lint import SheetView, label_near, lint, lint_pair
from mmt_plans.sheets.lint_run import Case, lint_case

ROOT = Path(__file__).resolve().parents[2]


def view(b: RecordingBackend, lang="en") -> SheetView:
    return SheetView.of(b, lang, "test")


def rules(b: RecordingBackend, rule: str, lang="en") -> list:
    return lint(view(b, lang), [rule])


def label(b, markup, kind, anchor, end=None, at=None, size=3.5):
    at = anchor if at is None else at
    with b.naming(markup, kind, anchor, end):
        b.rich_text(at, markup, size, anchor="center", valign="middle")


def test_label_near_what_it_names_or_tied_by_a_leader():
    b = RecordingBackend()
    with b.group("m", "mechanism"):
        b.circle((100, 100), 1.0)
        label(b, "B", "point", (100, 100), at=(103, 103))  # 1.5 mm off: near
        label(b, "C", "point", (100, 100), at=(120, 100))  # 18 mm off, no leader
    found = rules(b, "label-near")
    assert [f.message.split()[0] for f in found] == ["'C'"]
    # the same far label with its leader from the anchor to its box is fine
    b = RecordingBackend()
    with b.group("m", "mechanism"):
        with b.naming("C", "point", (100, 100)):
            b.line((100, 100), (118.5, 100), "thin")
            b.text((120, 100), "C", 3.5, valign="middle")
    assert rules(b, "label-near") == []
    # ... unless the leader crosses a main line on its way
    b = RecordingBackend()
    with b.group("m", "mechanism"):
        b.line((110, 90), (110, 110), "main")
        with b.naming("C", "point", (100, 100)):
            b.line((100, 100), (118.5, 100), "thin")
            b.text((120, 100), "C", 3.5, valign="middle")
    assert "crosses" in rules(b, "label-near")[0].message


def _fan(gap_from: float | None = None) -> RecordingBackend:
    """A pivot at (100, 100) in the fan of main lines through it every 10°
    (none from `gap_from`° for 60°: a free side), a main line x = 110 across
    them, and its name "C" led 20 mm out across that line."""
    b = RecordingBackend()
    with b.group("m", "mechanism"):
        for a in range(0, 180, 10):
            if gap_from is not None and gap_from <= a < gap_from + 60:
                continue
            d = 40.0 * np.array([np.cos(np.radians(a)), np.sin(np.radians(a))])
            b.line(tuple(100.0 + d), tuple(100.0 - d), "main")
        b.line((110, 60), (110, 140), "main")
        b.circle((100, 100), 0.8)
        with b.naming("C", "point", (100, 100)):
            b.line((100, 100), (118.5, 101.6), "thin")
            b.text((119, 101.6), "C", 3.5, valign="middle")
    return b


def test_a_walled_in_name_may_be_led_across_main_lines():
    """GOST 2.316 keeps a leader off the drawing's lines where it can be: a
    pivot in the fan of its positions' links has no free place near it (gen
    332's U), and its name led across a main line passes; where a side is
    free, it does not. The composers ask strictly (a drawing that needs no
    such leader is better)."""
    assert rules(_fan(), "label-near") == []
    strict = list(label_near(view(_fan()), strict=True))
    assert len(strict) == 1 and "crosses a main line" in strict[0].message
    found = rules(_fan(gap_from=60), "label-near")  # 60°-120° free: room above the pivot
    assert len(found) == 1 and "a place near it is free" in found[0].message


def test_a_leader_that_crosses_another_name_does_not_join():
    # a far name led to its point past another label: the reader follows the
    # leader into the other name's letters
    def drawn(other_at):
        b = RecordingBackend()
        with b.group("m", "mechanism"):
            b.circle((100, 100), 1.0)
            label(b, "D", "point", (110, 106), at=other_at)
            with b.naming("C", "point", (100, 100)):
                b.line((100, 100), (118.5, 100), "thin")
                b.text((120, 100), "C", 3.5, valign="middle")
        return b

    found = rules(drawn((110, 100)), "leader-clear")  # "D" written across the leader
    assert len(found) == 1 and "crosses the name 'D'" in found[0].message
    assert rules(drawn((110, 100)), "label-near") == []  # joined: near is another question
    assert rules(drawn((110, 104)), "leader-clear") == []  # "D" 2 mm clear above it


def test_a_point_inside_a_slider_block_is_named_beside_the_block():
    """A slider's pin (or mass centre) drawn inside its 12 x 7 mm block: a
    draughtsman writes its name beside the block, so the distance is measured
    to the block's outline; NEAR_MM itself is unchanged."""

    def drawn(at: tuple[float, float], block: float = 6.0) -> RecordingBackend:
        b = RecordingBackend()
        with b.group("m", "mechanism"):
            c = (100.0, 100.0)
            x0, x1 = c[0] - block, c[0] + block
            b.polygon([(x0, 97.0), (x1, 97.0), (x1, 103.0), (x0, 103.0)], "main", "white")
            label(b, "S5", "point", c, at=at)
        return b

    # "S5" is 7 mm wide: its box 5.5 mm right of the block's edge, 11.5 mm from the point: near
    assert rules(drawn((115.0, 100.0)), "label-near") == []
    # 7 mm off the block's edge: far, as from any other point
    found = rules(drawn((116.5, 100.0)), "label-near")
    assert len(found) == 1 and "stands 7.0 mm" in found[0].message
    # 5.5 mm off a filled outline wider than BLOCK_MM (a link, not a block):
    # measured from the point itself, 31.5 mm
    found = rules(drawn((135.0, 100.0), block=26.0), "label-near")
    assert len(found) == 1 and "stands 31.5 mm" in found[0].message
    # a block 14 mm long still holds its point's name beside it
    assert rules(drawn((116.0, 100.0), block=7.0), "label-near") == []


def test_a_leader_may_leave_a_named_segment_anywhere_along_it():
    # a link's (a main line's) name led from the middle of the link: the leader
    # leaves the line it names; it crosses no other main line
    b = RecordingBackend()
    with b.group("m", "mechanism"):
        b.line((100, 100), (140, 100), "main")
        with b.naming("AB", "segment", (100, 100), (140, 100)):
            b.line((120, 100), (120, 116.5), "thin")
            b.text((120, 117), "AB", 3.5, anchor="center", valign="baseline")
    assert rules(b, "label-near") == []
    # a main line across the leader is still crossed
    with b.group("m2", "mechanism"):
        b.line((110, 108), (130, 108), "main")
    assert "crosses" in rules(b, "label-near")[0].message


def test_a_vector_named_far_off_through_its_own_leader_is_named():
    def drawn(leader: bool) -> RecordingBackend:
        b = RecordingBackend()
        with b.group("v", "plan"):
            b.arrow((100, 100), (160, 100))
            with b.naming("pb", "arrow", (100, 100), (160, 100)):
                if leader:
                    b.line((130, 100), (130, 114.5), "thin")
                b.text((130, 116), "pb", 3.5, anchor="center", valign="baseline")
        return b

    assert [f.message for f in rules(drawn(False), "arrows-named")] == [
        "a vector with no name near it"
    ]
    assert rules(drawn(True), "arrows-named") == []


def test_no_label_on_a_line_or_on_another_label():
    b = RecordingBackend()
    with b.group("p", "plan"):
        b.line((0, 100), (50, 100), "main")
        label(b, "a", "point", (10, 100), at=(10, 100))  # astride the line
        label(b, "b", "point", (30, 110), at=(30, 110))
        label(b, "c", "point", (30, 110), at=(31, 110))  # on "b"
        label(b, "d", "point", (40, 120), at=(40, 120))  # clear of all
    found = [f.message for f in rules(b, "label-clear")]
    assert any(m.startswith("'a' lies on a line") for m in found)
    assert any("'b' and 'c' overlap" in m for m in found)
    assert not any("'d'" in m for m in found)


def test_vectors_along_one_line_are_found_side_by_side_pass():
    b = RecordingBackend()
    with b.group("force-polygon-2-3", "force-polygon"):
        b.arrow((0, 0), (100, 0))
        b.arrow((40, 0), (160, 0))  # 60 mm over the first
        b.arrow((0, 5), (100, 5))  # offset 5 mm: apart
    found = rules(b, "vectors-apart")
    assert len(found) == 1 and "60.0 mm" in found[0].message


def test_one_name_for_one_thing_and_no_look_alikes():
    b = RecordingBackend()
    with b.group("velocity-plan-2", "plan"):
        label(b, "p", "point", (0, 0), at=(-3, -3))  # the pole
        label(b, "p", "point", (60, 20), at=(63, 23))  # the image of a point named P
    with b.group("mechanism", "mechanism"):
        label(b, "O", "point", (200, 200), at=(203, 203))
        label(b, "0", "point", (210, 200), at=(212, 203))  # position 0 beside the pivot O
    found = [f.message for f in rules(b, "names-unique")]
    assert any("'p' names two different things" in m for m in found)
    assert any("'O' and '0' read alike" in m for m in found)


def test_a_detail_letter_names_one_view_of_the_sheet():
    def drawn(second):
        b = RecordingBackend()
        with b.group("zhukovsky-lever-detail", "lever"):
            b.text((100, 100), "H (2:1)", 5.0)
        with b.group("force-mechanism-detail", "mechanism"):
            b.text((300, 100), f"{second} (10:1)", 5.0)
        return b

    found = [f.message for f in rules(drawn("H"), "names-unique")]
    assert found == [
        "two detail views are lettered 'H' (zhukovsky-lever-detail and force-mechanism-detail)"
    ]
    assert rules(drawn("K"), "names-unique") == []


def test_letters_and_indices_at_least_2_5_mm():
    b = RecordingBackend()
    b.text((0, 0), "V", 3.5)
    b.text((2, -1), "BA", 1.75)
    found = rules(b, "letter-height")
    assert [f.message.split()[0] for f in found] == ["'BA'"]
    # an index of 2.5 mm lettering keeps 2.5 mm (GOST 2.304's smallest size)
    b = RecordingBackend()
    b.rich_text((0, 0), "a^{τ}_{BA}", 2.5)
    assert rules(b, "letter-height") == []


def test_one_number_format_per_column_and_units_in_the_header():
    b = RecordingBackend()
    Table(["Pos", "V"], [["1", "84.7376"], ["2", "2480.62"]], [20, 30]).draw(b, (10, 100), "t")
    found = [f.message for f in rules(b, "table-format")]
    assert any("mixes [2, 4] decimals" in m for m in found)
    assert any("no unit" in m for m in found)
    b = RecordingBackend()
    Table(["Pos", "V, m/s"], [["1", "84.74"], ["2", "2480.62"]], [20, 30]).draw(b, (10, 100), "t")
    assert rules(b, "table-format") == []


def test_a_continued_table_has_its_unit_in_its_table_title():
    # GOST 2.105: a table's further parts are titled "Continuation of Table
    # 1" alone; the unit in the first part's title ", m/s" is theirs too
    # (drawing/table.table_sketch names the parts t, t-2, t-3)
    def continued(first_title: str) -> RecordingBackend:
        b = RecordingBackend()
        body = [["1", "84.74"], ["2", "80.62"]]
        Table(["Pos", "V"], body, [20, 30], title=first_title).draw(b, (10, 100), "t")
        Table(["Pos", "V"], body, [20, 30], title="Continuation of Table 1").draw(
            b, (70, 100), "t-2"
        )
        return b

    assert rules(continued("Table 1 – Velocities, m/s"), "table-format") == []
    found = [f.message for f in rules(continued("Table 1 – Velocities"), "table-format")]
    assert any("of t-2 has no unit" in m for m in found)
    assert any("of t has no unit" in m for m in found)


def test_a_column_is_written_with_one_number_of_decimals():
    # four significant figures of the largest (15140 → 0 decimals), two of the
    # smallest non-zero (52.88 → 0): all in whole newtons
    rows = [["R34", "15140"], ["R12", "11977.5"], ["R32", "52.88"], ["R01", "0"], ["R05", "—"]]
    assert [r[1] for r in _one_format_per_column(rows)] == ["15140", "11978", "53", "0", "—"]
    # 261.5 at four figures needs one decimal: 52.88 → 52.9
    assert [r[1] for r in _one_format_per_column([["1", "52.88"], ["2", "261.5"]])] == [
        "52.9", "261.5"]
    # 0.05 needs three decimals for two figures; 4.267 has four figures at three
    assert [r[1] for r in _one_format_per_column([["1", "0.0500"], ["2", "4.267"], ["3", "2.5"]])] \
        == ["0.050", "4.267", "2.500"]
    # the balancing force to the tenth of a newton as given, the discrepancy with it
    assert [r[1] for r in _one_format_per_column(
        [["F", "12403.1"], ["F", "12403.1"], ["Δ", "0.00"], ["M", "2480.62"]])] == [
        "12403.1", "12403.1", "0.0", "2480.6"]
    # a marked value stays as it is
    assert _one_format_per_column([["1", "±0.049*"], ["2", "18.8"]])[0][1] == "±0.049*"


def test_the_language_of_the_sheet():
    b = RecordingBackend()
    with b.group("t", "table"):
        b.text((0, 0), "1.82", 3.5, valign="middle")  # a cell, as a table sets it
        b.text((0, 10), "ω, 1/s", 3.5, valign="middle")
    found = [f.message for f in rules(b, "language", "uk")]
    assert any("decimal point" in m for m in found) and any("Latin unit" in m for m in found)
    b = RecordingBackend()
    with b.group("t", "table"):
        b.text((0, 0), "1,82", 3.5, valign="middle")
        b.text((0, 10), "ω, 1/с", 3.5, valign="middle")
        b.text((20, 0), "0,11", 2.5)  # an index run (R_{0,11}), not a number
    assert rules(b, "language", "uk") == []
    assert [f.message for f in rules(b, "language", "en")][0].startswith("a decimal comma")


def test_designation_per_gost_2_201_the_same_in_both_languages():
    def sheet(designation):
        b = RecordingBackend()
        with b.group("title-block", "title-block"):
            b.text((700, 50), "Title", 5.0)
            b.text((776, 52), designation, 7.0)
        return view(b)

    assert [f.rule for f in lint(sheet("TMM.CP.SIX_LINK_PRESS.01"), ["designation"])] == [
        "designation"]
    assert lint(sheet("ТММ.КП.3314.01"), ["designation"]) == []
    assert lint_pair(sheet("ТММ.КП.3314.01"), sheet("ТММ.КП.3314.01")) == []
    assert len(lint_pair(sheet("TMM.CP.3314.01"), sheet("ТММ.КП.3314.01"))) == 1


def test_guide_sizes_prose_and_an_empty_field():
    b = RecordingBackend()
    with b.group("frame", "frame"):
        b.rectangle((20, 5), 816, 584)
    with b.group("velocity-plan-2", "plan"):
        b.arrow((100, 100), (150, 100))  # pa 50 mm
    with b.group("diagram-s", "diagram"):
        b.text((30, 30), "the mechanism is drawn at the μ that fills its field", 3.5)
    v = view(b)
    assert "50 mm" in lint(v, ["guide-sizes"])[0].message
    assert lint(v, ["no-dev-prose"])
    assert "empty" in lint(v, ["field-filled"])[0].message


def test_a_polygon_with_the_production_resistance_is_sized_by_it():
    # seed 003, formula (20): |F_PR| = 150 ... 300 mm; the polygon's other sides
    # follow from the forces (here the longest is 320 mm, as the series' step
    # between 5 and 8 N/mm leaves it)
    def polygon(f_pr_mm: float, longest_mm: float, named: str = "F_{PR}") -> RecordingBackend:
        b = RecordingBackend()
        with b.group("force-polygon-4-5", "force-polygon"):
            b.arrow((100, 100), (100 + f_pr_mm, 100))
            label(b, named, "point", (100 + f_pr_mm / 2, 100), at=(100 + f_pr_mm / 2, 104))
            b.arrow((100 + f_pr_mm, 100), (100 + f_pr_mm, 100 + longest_mm))
        return b

    assert rules(polygon(184, 320), "guide-sizes") == []
    assert rules(polygon(184, 320, "F_{КО}"), "guide-sizes", "uk") == []
    found = rules(polygon(115, 200), "guide-sizes")
    assert [f.message for f in found] == ["force-polygon-4-5: |F_PR| 115 mm (guide 150–300 mm)"]
    # |F_PR| small beside the polygon's other forces: at 150 mm it would put the
    # longest side past 300 mm, so the longest side is the measure (as sheet 2's
    # guide_side takes it)
    assert rules(polygon(90, 280), "guide-sizes") == []
    found = rules(polygon(60, 140), "guide-sizes")  # the whole polygon drawn too small
    assert [f.message for f in found] == [
        "force-polygon-4-5: longest side 140 mm (guide 150–300 mm)"
    ]
    found = rules(polygon(100, 140), "guide-sizes")  # F_PR at 150 mm would leave 210 mm
    assert [f.message for f in found] == ["force-polygon-4-5: |F_PR| 100 mm (guide 150–300 mm)"]
    # without the production resistance the longest side is the measure
    found = rules(polygon(184, 320, "R_{05}"), "guide-sizes")
    assert [f.message for f in found] == [
        "force-polygon-4-5: longest side 320 mm (guide 150–300 mm)"
    ]


# --- real sheets: the text rules hold (a fixed subset) ------------------------------------

TEXT_RULES = {"letter-height", "table-format", "language", "designation", "no-dev-prose",
              "names-unique"}


@pytest.mark.parametrize("path", ["samples/six_link_press.toml",
                                  "samples/tasks/seed002/task1_v00.toml"])
def test_the_text_rules_hold_on_samples(path):
    p = ROOT / path
    case, found, checked = lint_case(Case(p.stem, p.read_text(encoding="utf-8"), str(p)))
    assert TEXT_RULES <= checked
    bad = [str(f) for f in found if f.rule in TEXT_RULES | {"composes"}]
    assert bad == []


def test_a_file_without_title_uk_gets_a_ukrainian_title_from_its_structure():
    from mmt_plans.spec import loads
    from mmt_plans.titles import has_title, sheet_title, structure_title

    text = (ROOT / "samples" / "six_link_press.toml").read_text(encoding="utf-8")
    text = "\n".join(ln for ln in text.splitlines() if not ln.startswith("title_uk"))
    mech = loads(text, "press.toml")
    assert not has_title(mech, "uk") and has_title(mech, "en")
    # five moving links and the frame (seed 003: "шестиланковий важільний механізм")
    assert structure_title(mech, "uk") == "Шестиланковий важільний механізм"
    assert sheet_title(mech, "uk") == "Шестиланковий важільний механізм"
    assert sheet_title(mech, "en") == mech.title


def test_the_image_of_a_point_named_like_a_pole_is_not_the_pole():
    from mmt_plans.drawing.markup import image_markup

    assert image_markup("P") == "p'" and image_markup("π") == "π'"
    assert image_markup("B") == "b" and image_markup("S2") == "s_{2}"


def test_images_of_points_named_alike_but_for_case_read_apart():
    from mmt_plans.drawing.markup import image_markup

    names = ("p", "O", "o", "B")
    # O's image is o as the textbook writes it; o's takes a prime
    assert image_markup("O", names) == "o" and image_markup("o", names) == "o'"
    assert image_markup("B", names) == "b"
    # a point p beside P: both primed, neither the pole p
    assert image_markup("P", ("P", "p")) == "p'" and image_markup("p", ("P", "p")) == "p''"


def test_a_plan_component_keeps_the_case_of_its_centre():
    # gen 192: links 2 (O-O1) and 3 (o-O1) turn about O and about o; their
    # normal components were both written a^n_{O1O}
    from mmt_plans.generate import generate_one
    from mmt_plans.solution import solve
    from mmt_plans.spec import loads

    g = generate_one(192)
    view = solve(loads(g.toml, "g.toml")).plan(0)
    labels = {c.label for grp in view.groups for c in grp.acceleration}
    assert {"a^n_O1O", "a^n_O1o"} <= labels
