"""Regression tests of the text corrections of issue 22: each names the
reviewer's complaint it guards against."""

from __future__ import annotations

import functools
import re
from pathlib import Path

import numpy as np

import mmt_plans
from mmt_plans.i18n import catalogue
from mmt_plans.note import note_content, plain
from mmt_plans.note.front import title_info
from mmt_plans.results_json import results
from mmt_plans.titles import structure_title, title_warning

ROOT = Path(__file__).resolve().parents[2]
PRESS = ROOT / "samples" / "six_link_press.toml"
SHAPER = ROOT / "samples" / "shaper.toml"
CROSSHEAD = ROOT / "samples" / "tasks" / "seed003" / "task11_v1.toml"  # RPP: R04 a couple


@functools.cache
def solved(path: Path):
    return mmt_plans.solve(mmt_plans.load(path))


@functools.cache
def text(path: Path, lang: str) -> str:
    return plain(note_content(solved(path), lang).text())  # type: ignore[arg-type]


def test_coriolis_direction_is_the_relative_velocity_turned_by_omega_of_the_guide():
    """Not "(ω of link 0 turned by 90°)": a^k is V_rel turned by 90° in the
    sense of ω of the guide link; on a fixed guide it is zero."""
    en = text(SHAPER, "en")
    assert "ω of link" not in en
    turned = [ln for ln in en.splitlines() if ln.startswith("a^k_") and "guide" in ln]
    assert turned
    for ln in turned:
        m = re.match(r"a\^k_(\S+) (= 0: the guide \(link 0\)|= 2·ω_(\d+)·V_\1, perpendicular)", ln)
        assert m, ln
        if m.group(3):  # a turning guide: the sense of its ω
            assert f"the relative velocity V_{m.group(1)} turned by 90° in the sense of" in ln
            assert f"ω_{m.group(3)} of the guide link {m.group(3)}" in ln
            assert m.group(3) != "0"


def test_prismatic_pair_couple_with_its_moment_equation():
    """R04 = 0 N on a crosshead guide: the couple the JSON gives is written
    with ΣM of the link about the slider's point."""
    S = solved(CROSSHEAD)
    J = results(S)
    couple = J["forces"]["reaction_details"]["R04"]["couple"]
    assert abs(couple) > 1.0
    for lang in ("en", "uk"):
        cat = catalogue(lang)  # type: ignore[arg-type]
        t = text(CROSSHEAD, lang)
        assert re.search(r"ΣM_\w+\(4\) = .*\+ M_04 = 0;", t), lang
        assert f"M_04 = -ΣM_" in t.replace("\u2212", "-")
        assert f"= {cat.number(couple)} {cat.words('units')['Nm']}" in t
    # the couple balances the other moments on link 4 about the reaction's point
    fa = S.require_forces()
    group = next(g for g in fa.groups if 4 in g.links)
    r = next(x for x in group.reactions if x.name == "R04")
    P = np.asarray(r.point, dtype=float)
    total = 0.0
    for f in group.free_bodies[4]:
        if f.label in ("R04", "R40"):
            continue
        d = np.asarray(f.point, dtype=float) - P
        total += d[0] * f.force[1] - d[1] * f.force[0] + f.couple
    assert abs(total + couple) <= 1e-6 * max(1.0, abs(couple))


def test_uk_title_built_from_the_structure_without_title_uk(tmp_path):
    source = PRESS.read_text(encoding="utf-8")
    assert "title_uk" in source
    bare = tmp_path / "press.toml"
    bare.write_text(
        "\n".join(ln for ln in source.splitlines() if not ln.startswith("title_uk")),
        encoding="utf-8",
    )
    mech = mmt_plans.load(bare)
    # six links with the frame: the press has five moving links
    assert len(mech.links) == 5
    assert structure_title(mech, "uk") == "Шестиланковий важільний механізм"
    S = mmt_plans.solve(mech)
    info = title_info(S, "uk")
    assert info.title == "Шестиланковий важільний механізм"
    assert mech.title not in info.topic
    assert title_warning(mech, "uk") and "title_uk" in title_warning(mech, "uk")  # type: ignore[operator]
    assert title_warning(mech, "en") is None
    assert mech.title not in note_content(S, "uk").title


def test_a_reduction_section_in_every_note():
    """M_red and J_red are written for a mechanism without gears too."""
    S = solved(PRESS)
    assert S.mechanism.drive.gear_train is None
    steps = note_content(S, "en").steps
    assert "reduction.M" in steps and "reduction.J" in steps
    t = text(PRESS, "en")
    J_red = float(S.reduction.reduced_inertia[S.entry(S.force_position)])
    assert f"= {catalogue('en').number(J_red)} kg·m²" in t


def test_force_scale_from_the_largest_known_force():
    """μ_F = F/|F| with F the largest force of the polygon known before it is
    drawn (F_PR in seed 003), never an unknown reaction."""
    S = solved(PRESS)
    fa = S.require_forces()
    t = text(PRESS, "en")
    named = re.findall(r"μ_F = (\S+)/\|\1\|", t)
    expected = []
    for g in fa.groups:
        known = [v for v in g.polygons[0].vectors if v.known]
        expected.append(max(known, key=lambda v: v.magnitude).label)
    known = [v for v in fa.driving_link.polygon.vectors if v.known]
    expected.append(max(known, key=lambda v: v.magnitude).label)
    assert [n.replace("_", "") for n in named] == [e.replace("_", "") for e in expected]
    assert "F_PR" in named[0]


def test_plurals_and_references_cited():
    t = text(PRESS, "en")
    assert "Links 5 have" not in t and "1 figures" not in t
    cited = {int(n) for m in re.findall(r"\[([\d, ]+)\]", t) for n in m.split(",")}
    from mmt_plans.note.literature import entries

    assert len(cited) >= 5 and max(cited) <= len(entries("en"))


def test_uk_kinds_as_seed_002_writes_them():
    t = text(PRESS, "uk")
    assert "2-го виду (ВВП)" in t  # the slider group 4-5 (RRP)
    assert "1-го виду (ВВВ)" in t  # the group 2-3 (RRR)
