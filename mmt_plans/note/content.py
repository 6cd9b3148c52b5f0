"""The calculation note as blocks of text, in the order of seed 003 §IV.

Every step is written as seed 002 writes it: formula = numbers substituted =
result unit, with the numbers taken from the solver (`Analysis`,
`PlanView`, `ForceAnalysis`), never re-derived here by another method. A
segment of a plan (pb, πb, |R|) is the solver's magnitude divided by the
plan's scale, so "segment·μ" gives back the solver's value.

Lines are `Backend.rich_text` markup: `_x` / `_{xy}` a subscript, `^x` a
superscript; `plain()` drops the braces for tests and text output.
"""

from __future__ import annotations

import math
import re
from collections.abc import Iterator, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, Literal

import numpy as np

from ..drawing.markup import image_markup as _image_markup
from ..errors import MmtError
from ..i18n import Language, catalogue, check_language
from ..scales import ACCELERATION_PLAN, FORCE_PLAN, VELOCITY_PLAN, scale_for

if TYPE_CHECKING:  # pragma: no cover
    from ..forces import ForceAnalysis
    from ..kinematics.plans import PlanView
    from ..solution import Solution

BlockKind = Literal[
    "title",
    "section",
    "subsection",
    "text",
    "equation",
    "table",
    "problem",
    # the document's frame (note/front.py, note/pages.py)
    "heading",  # a structural element's name, centred: CONTENTS, CONCLUSIONS, REFERENCES
    "figure",  # a drawing `figure` (note/figures.py) `height` mm tall, `text` its caption
    "pagebreak",  # the next block starts a page of form `text` ("none", "2", "2a")
    "center",  # a centred line of text
    "space",  # `height` mm of white space
    "toc",  # a line of the contents: `text` and the page of the heading `step`
]

__all__ = ["Block", "NoteContent", "note_content", "plain", "Language"]


@dataclass(frozen=True)
class Block:
    """One piece of the note. `step` is seed 003's item number ("1.3") of a
    (sub)section heading; a table has `rows` (the header first) and `widths`
    (mm), and `text` is its caption (numbered "Table N - text" by the layout).
    A figure draws `figure` (a key of note/figures.py) `height` mm tall, with
    `text` as its caption; `indent` (mm) moves a text line right."""

    kind: BlockKind
    text: str = ""
    step: str = ""
    rows: tuple[tuple[str, ...], ...] = ()
    widths: tuple[float, ...] = ()
    figure: str = ""
    height: float = 0.0
    indent: float = 0.0


@dataclass(frozen=True)
class NoteContent:
    title: str
    lang: Language
    blocks: tuple[Block, ...]

    @property
    def steps(self) -> list[str]:
        """Seed 003 item numbers of the headings, in the order written."""
        return [b.step for b in self.blocks if b.step]

    def text(self) -> str:
        """The whole note as plain text (markup braces dropped)."""
        out = []
        for b in self.blocks:
            if b.kind in ("pagebreak", "space"):
                continue
            if b.kind == "table":
                out += [plain(b.text)] if b.text else []
                out += ["  ".join(plain(c) for c in row) for row in b.rows]
            else:
                out.append(plain(b.text))
        return "\n".join(out)


def plain(markup: str) -> str:
    """ "V_{BA} = ω_{1}·l_{OA}" → "V_BA = ω_1·l_OA"."""
    return markup.replace("{", "").replace("}", "")


# Units, and the phrases of the force solver's step lines, per language.
# --- number formatting -----------------------------------------------------------------


def number(x: float, lang: Language = "en", sig: int = 4) -> str:
    """At least `sig` significant digits, no exponent, no trailing zeros; a
    decimal comma in Ukrainian: 10.47, 2.094, 0.2, 12403; "2,094"."""
    return catalogue(lang).number(x, sig)


def _paren(text: str) -> str:
    """A negative number substituted into a formula goes in parentheses."""
    return f"({text})" if text.startswith("-") else text


def _sub(name: str) -> str:
    """A point or link name as a subscript group: "S2" → "{S2}"."""
    return "{" + name + "}"


def _force_markup(label: str) -> str:
    """Labels of the force solver as markup: "F_in2" → "F_{in2}", "R34^t" → "R^{τ}_{34}"."""
    m = re.fullmatch(r"R(\d+)(?:_(\d+))?(?:\^(\w))?", label)
    if m:
        idx = m.group(1) + (f",{m.group(2)}" if m.group(2) else "")
        sup = {"t": "τ", "n": "n"}.get(m.group(3) or "", m.group(3) or "")
        return f"R^{{{sup}}}_{{{idx}}}" if sup else f"R_{{{idx}}}"
    m = re.fullmatch(r"(F'?|G|M)_?([A-Za-z]*)(\d*)", label)
    if m and (m.group(2) or m.group(3)):
        return f"{m.group(1)}_{{{m.group(2)}{m.group(3)}}}"
    if "_" in label:
        head, tail = label.split("_", 1)
        return f"{head}_{{{tail}}}"
    return label


def _equation_markup(eq: str) -> str:
    return " + ".join(_force_markup(t.strip()) for t in eq.replace("= 0", "").split("+")) + " = 0"


# --- the builder -------------------------------------------------------------------------


class _Writer:
    def __init__(self, analysis: Solution, lang: Language) -> None:
        check_language(lang)
        self.a = analysis
        self.mech = analysis.mechanism
        self.lang = lang
        self.w = catalogue(lang).words("note")
        self.u = catalogue(lang).words("units")
        self.blocks: list[Block] = []

    # small helpers
    def n(self, x: float, sig: int = 4) -> str:
        return number(x, self.lang, sig)

    def np_(self, x: float, sig: int = 4) -> str:
        return _paren(self.n(x, sig))

    def add(self, kind: BlockKind, text: str = "", step: str = "", rows=(), widths=()) -> None:
        self.blocks.append(Block(kind, text, step, tuple(tuple(r) for r in rows), tuple(widths)))

    def text(self, t: str) -> None:
        self.add("text", t)

    def eq(self, t: str) -> None:
        self.add("equation", t)

    def section(self, key: str, step: str = "") -> None:
        self.add("subsection", f"{step}. {self.w[key]}" if step else self.w[key], step or key)

    def problem(self, err: Exception) -> None:
        self.add("problem", self.w["problem"].format(msg=str(err)))

    # ---------------------------------------------------------------------------------
    def build(self) -> NoteContent:
        a, w = self.a, self.w
        self.add("title", f"{w['title']}: {self.mech.title}")
        self.add("section", w["sheet1"], "sheet1")
        self.structure()
        self.positions()
        views: dict[int, PlanView | MmtError] = {}
        for i in a.plan_positions:
            try:
                views[i] = a.plan(i)
            except MmtError as err:
                views[i] = err
        self.velocity_plans(views)
        self.angular_velocities(views)
        self.acceleration_plans(views)
        self.angular_accelerations(views)
        self.diagrams()
        self.add("section", w["sheet2"], "sheet2")
        self.forces()
        return NoteContent(self.mech.title, self.lang, tuple(self.blocks))

    # --- 1.1 -----------------------------------------------------------------------------
    def structure(self) -> None:
        st = self.a.structure
        self.section("1.1", "1.1")
        self.text(self.w["chebyshev"])
        self.eq(f"n = {st.n}, p_5 = {st.p5}, p_4 = {st.p4}")
        self.eq(f"W = 3n - 2p_5 - p_4 = 3·{st.n} - 2·{st.p5} - {st.p4} = {st.W}")
        self.text(self.w["groups"].format(d=st.driver))
        for g in st.groups:
            self.eq(
                self.w["group_line"].format(
                    label=g.label,
                    links=", ".join(map(str, sorted(g.links))),
                    cls=g.group_class,
                    order=g.order,
                    kind=g.kind or "-",
                    pairs=", ".join(p.name for p in g.pairs),
                )
            )
        self.text(self.w["class"].format(cls=st.mechanism_class, formula=st.formula))

    # --- 1.2 -----------------------------------------------------------------------------
    def positions(self) -> None:
        a, w, u = self.a, self.w, self.u
        self.section("1.2", "1.2")
        l_oa = self.mech.crank_length
        mu_l = float(a.mu_l)
        oa = l_oa / mu_l
        self.text(w["mu_l"].format(oa=self.n(oa)))
        self.eq(f"μ_l = l_{{OA}}/OA = {self.n(l_oa)}/{self.n(oa)} = {self.n(mu_l)} {u['m/mm']}")
        try:
            if a.extremes is None:
                raise MmtError("the output has no extreme position in the range analysed")
            lo, hi = a.extremes
            self.text(
                w["extremes"].format(
                    out=self.mech.study.output,
                    lo=self.n(lo, 6),
                    hi=self.n(hi, 6),
                    span=self.n(a.working_span_deg or 0.0, 6),
                )
            )
        except MmtError as err:
            self.problem(err)
            return
        n = self.mech.study.positions
        self.text(
            w["positions"].format(
                n=n,
                step=self.n(360.0 / n),
                plans=", ".join(map(str, a.plan_positions)),
                force=a.force_position,
            )
        )
        s, _, _ = a.output_along(a.sweep)
        s0 = s[a.entry(0)] if np.isfinite(s[a.entry(0)]) else 0.0
        rows = [w["pos_head"]]
        for k, pos in enumerate(a.positions):
            label = str(pos.index) if pos.index is not None else "*"
            rows.append(
                (
                    label,
                    self.n(pos.phi1_deg, 5),
                    w[pos.stroke],
                    self.n((s[k] - s0) * 1e3) if np.isfinite(s[k]) else "-",
                )
            )
        self.add("table", rows=rows, widths=(16, 26, 28, 26))

    # --- scales of the plans ------------------------------------------------------------
    def plan_scales(self) -> tuple[float, float, float, float]:
        """V_A, a_A (solver) and μ_V, μ_a as sheet 1 chooses them (seed 003 (5), (9))."""
        pin = self.mech.crank_pin
        v_a = a_a = 0.0
        for i in self.a.plan_positions:
            try:
                view = self.a.plan(i)
            except MmtError:
                continue
            v_a = max(v_a, float(np.hypot(*view.velocity_images[pin])))
            a_a = max(a_a, float(np.hypot(*view.acceleration_images[pin])))
        mu_v = scale_for(v_a, VELOCITY_PLAN) if v_a > 0 else 1.0
        mu_a = scale_for(a_a, ACCELERATION_PLAN) if a_a > 0 else 1.0
        return v_a, a_a, mu_v, mu_a

    def moving_points(self, view: PlanView) -> list[str]:
        owners = self.mech.point_owners
        names = [p for p, o in owners.items() if 0 not in o]
        names += [p for p in view.velocity_images if p not in owners]
        return [p for p in names if p in view.velocity_images]

    def plan_positions(self, views) -> Iterator[tuple[int, Any]]:
        """Each plan position under its heading: a solved one yielded, a failed
        one's problem written."""
        for i, view in views.items():
            pos = self.a.positions[self.a.entry(i)]
            self.add(
                "subsection",
                self.w["vplan"].format(i=i, phi=self.n(pos.phi1_deg, 5), stroke=self.w[pos.stroke]),
            )
            if isinstance(view, Exception):
                self.problem(view)
                continue
            yield i, view

    def distance(self, i: int, P: str, Q: str) -> float:
        return abs(self.point(i, P) - self.point(i, Q))

    def point(self, i: int, name: str) -> complex:
        """Where point `name` is at position i (m, complex). "G7", the point
        of link 7 under G, is where G is."""
        locate = self.a.chain.locate
        if name not in locate:
            m = re.fullmatch(r"(.+?)(\d+)", name)
            if m and m.group(1) in locate:
                name = m.group(1)
        return complex(self.a.sweep.position_of(name)[self.a.entry(i)])

    # --- 1.3 -----------------------------------------------------------------------------
    def velocity_plans(self, views) -> None:
        w, u = self.w, self.u
        self.section("1.3", "1.3")
        d = self.mech.drive
        n1 = d.n1_rpm
        w1 = math.pi * n1 / 30.0
        self.text(w["omega1"])
        self.eq(f"ω_1 = π·n_1/30 = π·{self.n(n1)}/30 = {self.n(w1)} {u['rad/s']}")
        l_oa = self.mech.crank_length
        v_a, _, mu_v, _ = self.plan_scales()
        self.text(w["VA"])
        self.eq(
            f"V_A = ω_1·l_{{OA}} = {self.n(w1)}·{self.n(l_oa)} = {self.n(w1 * l_oa)} {u['m/s']};"
        )
        pa = v_a / mu_v
        self.eq(f"μ_V = V_A/pa = {self.n(v_a)}/{self.n(pa)} = {self.n(mu_v)} {u['v/mm']}")
        for i, view in self.plan_positions(views):
            for g in view.groups:
                X = g.point
                self.text(w["vequations"].format(name=g.group, kind=g.kind, X=X))
                lines, coincident = [], []
                for c in g.velocity:
                    base, rel = self.leg(c.label, X, "V_")
                    lines.append(f"V_{_sub(X)} = V_{_sub(base)} + V_{_sub(rel)}")
                    if "(" in base:
                        coincident.append(base)
                self.eq("; ".join(lines))
                for base in coincident:
                    m = re.fullmatch(r"(.+)\((\d+)\)", base)
                    if m is not None:
                        self.text(w["coincident"].format(X=m.group(1), k=m.group(2)))
            self.text(w["found_v"])
            for name in self.moving_points(view):
                v = float(np.hypot(*view.velocity_images[name]))
                self.eq(
                    f"V_{_sub(name)} = p{_image_markup(name)}·μ_V = {self.n(v / mu_v)}·"
                    f"{self.n(mu_v)} = {self.n(v)} {u['m/s']}"
                )
            for g in view.groups:
                for c in g.velocity:
                    base, rel = self.leg(c.label, g.point, "V_")
                    seg = self.segment(c.label, g.point)
                    self.eq(
                        f"V_{_sub(rel)} = {seg}·μ_V = {self.n(c.magnitude / mu_v)}·"
                        f"{self.n(mu_v)} = {self.n(c.magnitude)} {u['m/s']}"
                    )

    def leg(self, label: str, X: str, prefix: str) -> tuple[str, str]:
        """The known point of a leg and the relative part: "V_BA" → ("A", "BA");
        "V_E/0" → ("E(0)", "E/0")."""
        body = label.split("_", 1)[1]
        if "/" in body:
            k = body.split("/", 1)[1]
            return f"{X}({k})", body
        return body[len(X) :], body

    def segment(self, label: str, X: str) -> str:
        """The segment of a relative velocity on the plan: "V_BA" → "ab"."""
        base, rel = self.leg(label, X, "V_")
        if "/" in rel:
            k = rel.split("/", 1)[1]
            return f"{_image_markup(X)}_{{({k})}}{_image_markup(X)}"
        return f"{_image_markup(base)}{_image_markup(X)}"

    # --- 1.4 -----------------------------------------------------------------------------
    def link_pair(self, lid: int, view) -> tuple[str, str] | None:
        """Two points of link `lid` whose relative motion gives ω and ε: the
        textbook's (B, A) for link AB, i.e. the second point relative to the first."""
        names = [p for p in self.mech.links[lid].points if p in view.velocity_images]
        if len(names) < 2:
            return None
        return names[1], names[0]

    def guide_of(self, lid: int) -> int | None:
        for sl in self.mech.sliders:
            if sl.slider == lid:
                return sl.guide
        return None

    def sense(self, x: float) -> str:
        if abs(x) < 1e-12:
            return ""
        return f" ({self.w['ccw'] if x > 0 else self.w['cw']})"

    def link_rates(
        self, views, rate: Literal["omega", "eps"]
    ) -> Iterator[tuple[int, Any, int, tuple[str, str]]]:
        """Per plan position, the lines of ω (rate "omega") or ε ("eps") of every
        link: the drive's and those of links that slide along their guide (they
        turn with it) are written here; for each other link yields (i, view,
        link, its pair of points) for the caller to write."""
        omega = rate == "omega"
        symbol, unit = ("ω", self.u["rad/s"]) if omega else ("ε", self.u["rad/s2"])
        d = self.mech.drive.link
        for i, view in views.items():
            if isinstance(view, Exception):
                continue
            rates = view.omega if omega else view.eps
            self.text(self.w["omega_pos" if omega else "eps_pos"].format(i=i))
            if omega:
                self.eq(f"ω_{{{d}}} = {self.n(abs(rates[d]))} {unit}{self.sense(rates[d])}")
            else:
                self.eq(self.w["eps1"].replace("ε_1", f"ε_{{{d}}}"))
            for lid in self.mech.links:
                if lid == d:
                    continue
                pair = self.link_pair(lid, view)
                if pair is None:
                    g = self.guide_of(lid)
                    of_guide = 0.0 if g in (None, 0) else abs(rates[g])
                    note = f"  ({self.w['slides_with'].format(lid=lid, g=g)})" if omega else ""
                    self.eq(
                        f"{symbol}_{{{lid}}} = {symbol}_{{{g if g is not None else 0}}} = "
                        f"{self.n(of_guide)} {unit}{self.sense(rates[lid])}{note}"
                    )
                    continue
                yield i, view, lid, pair

    def angular_velocities(self, views) -> None:
        u = self.u
        self.section("1.4", "1.4")
        for i, view, lid, (P, Q) in self.link_rates(views, "omega"):
            om = view.omega[lid]
            v_pq = float(np.hypot(*(view.velocity_images[P] - view.velocity_images[Q])))
            l_pq = self.distance(i, P, Q)
            self.eq(
                f"ω_{{{lid}}} = V_{{{P}{Q}}}/l_{{{P}{Q}}} = {self.n(v_pq)}/{self.n(l_pq)} = "
                f"{self.n(v_pq / l_pq)} {u['rad/s']}{self.sense(om)}"
            )

    # --- 1.5 -----------------------------------------------------------------------------
    def acceleration_plans(self, views) -> None:
        w, u = self.w, self.u
        self.section("1.5", "1.5")
        d = self.mech.drive
        w1 = abs(d.omega)
        l_oa = self.mech.crank_length
        _, a_a, _, mu_a = self.plan_scales()
        self.text(w["aA"])
        self.eq(
            f"a_A = a^n_A = ω_1^2·l_{{OA}} = {self.n(w1)}^2·{self.n(l_oa)} = "
            f"{self.n(w1 * w1 * l_oa)} {u['m/s2']};"
        )
        pia = a_a / mu_a
        self.eq(f"μ_a = a_A/πa = {self.n(a_a)}/{self.n(pia)} = {self.n(mu_a)} {u['a/mm']}")
        for i, view in self.plan_positions(views):
            for g in view.groups:
                X = g.point
                self.text(w["aequations"].format(name=g.group, kind=g.kind, X=X))
                lines = []
                comps = list(g.acceleration)
                for c1, c2 in zip(comps[0::2], comps[1::2]):
                    base, rel = self.leg(c1.label, X, "a")
                    if c1.kind == "normal":
                        lines.append(
                            f"a_{_sub(X)} = a_{_sub(base)} + a^n_{_sub(rel)} + a^τ_{_sub(rel)}"
                        )
                    else:
                        lines.append(
                            f"a_{_sub(X)} = a_{_sub(base)} + a^k_{_sub(rel)} + a^r_{_sub(rel)}"
                        )
                self.eq("; ".join(lines))
                self.text(w["normal"])
                for c in comps:
                    base, rel = self.leg(c.label, X, "a")
                    if c.kind == "normal":
                        vc = self.velocity_leg(g, rel)
                        l = self.distance(i, X, base)
                        val = vc * vc / l if l > 0 else c.magnitude
                        self.eq(
                            f"a^n_{_sub(rel)} = V_{_sub(rel)}^2/l_{_sub(rel)} = "
                            f"{self.n(vc)}^2/{self.n(l)} = {self.n(val)} {u['m/s2']}; "
                            f"|a^n_{_sub(rel)}| = {self.n(val)}/{self.n(mu_a)} = "
                            f"{self.n(val / mu_a)} {u['mm']}"
                        )
                    elif c.kind == "coriolis":
                        k = int(rel.split("/", 1)[1])
                        om = abs(view.omega.get(k, 0.0)) if k != 0 else 0.0
                        vr = self.velocity_leg(g, rel)
                        val = 2.0 * om * vr
                        self.eq(
                            f"a^k_{_sub(rel)} = 2·ω_{{{k}}}·V_{_sub(rel)} = 2·{self.n(om)}·"
                            f"{self.n(vr)} = {self.n(val)} {u['m/s2']}; |a^k_{_sub(rel)}| = "
                            f"{self.n(val / mu_a)} {u['mm']}"
                        )
            self.text(w["found_a"])
            for name in self.moving_points(view):
                acc = float(np.hypot(*view.acceleration_images[name]))
                self.eq(
                    f"a_{_sub(name)} = π{_image_markup(name)}·μ_a = {self.n(acc / mu_a)}·"
                    f"{self.n(mu_a)} = {self.n(acc)} {u['m/s2']}"
                )
            for g in view.groups:
                for c in g.acceleration:
                    if c.kind not in ("tangential", "slide"):
                        continue
                    base, rel = self.leg(c.label, g.point, "a")
                    sym = "a^τ" if c.kind == "tangential" else "a^r"
                    self.eq(
                        f"{sym}_{_sub(rel)} = {self.n(c.magnitude / mu_a)}·{self.n(mu_a)} = "
                        f"{self.n(c.magnitude)} {u['m/s2']}"
                    )

    def velocity_leg(self, g, rel: str) -> float:
        for c in g.velocity:
            if c.label.split("_", 1)[1] == rel:
                return c.magnitude
        return 0.0

    # --- 1.6 -----------------------------------------------------------------------------
    def angular_accelerations(self, views) -> None:
        u = self.u
        self.section("1.6", "1.6")
        for i, view, lid, (P, Q) in self.link_rates(views, "eps"):
            e = view.eps[lid]
            rc = self.point(i, P) - self.point(i, Q)
            r = np.array([rc.real, rc.imag])
            om = view.omega[lid]
            a_rel = view.acceleration_images[P] - view.acceleration_images[Q]
            a_t = float(np.hypot(*(a_rel + om * om * r)))  # a_PQ minus its normal part −ω²·r
            l = float(np.hypot(*r))
            self.eq(
                f"ε_{{{lid}}} = a^τ_{{{P}{Q}}}/l_{{{P}{Q}}} = {self.n(a_t)}/{self.n(l)} = "
                f"{self.n(a_t / l)} {u['rad/s2']}{self.sense(e)}"
            )

    # --- 1.7, 1.8 ------------------------------------------------------------------------
    def diagrams(self) -> None:
        a, w, u = self.a, self.w, self.u
        self.section("1.7", "1.7")
        if a.diagrams is None:
            err = MmtError(a.diagrams_problem or "no kinematic diagrams")
            self.problem(err)
            self.section("1.8", "1.8")
            self.problem(err)
            return
        dg = a.diagrams
        construction, check = dg.construction, dg.check
        v_plan, a_plan = dg.v_plan, dg.a_plan
        c_v, c_a = dg.at_position(construction.v), dg.at_position(construction.a)
        c = construction
        self.text(
            w["diagram_scales"].format(
                out=a.mechanism.study.output, L=self.n(c.L), H1=self.n(c.H1), H2=self.n(c.H2)
            )
        )
        self.eq(f"μ_S = μ_l = {self.n(c.mu_S)} {u['m/mm']};")
        self.eq(
            f"μ_t = 60/(n_1·L) = 60/({self.n(c.n1)}·{self.n(c.L)}) = {self.n(c.mu_t)} {u['s/mm']};"
        )
        self.eq(
            f"μ_V = μ_S/(μ_t·OH_1) = {self.n(c.mu_S)}/({self.n(c.mu_t)}·{self.n(c.H1)}) = "
            f"{self.n(c.mu_V)} {u['v/mm']};"
        )
        self.eq(
            f"μ_a = μ_V/(μ_t·OH_2) = {self.n(c.mu_V)}/({self.n(c.mu_t)}·{self.n(c.H2)}) = "
            f"{self.n(c.mu_a)} {u['a/mm']}"
        )
        self.section("1.8", "1.8")
        plans = set(a.plan_positions)
        rows = [w["check_head"]]
        for k in range(len(c_v)):
            ev, ea = check.v_error_percent[k], check.a_error_percent[k]
            rows.append(
                (
                    f"{k}{'*' if k in plans else ''}",
                    self.n(v_plan[k]),
                    self.n(c_v[k]),
                    "-" if ev is None else self.n(ev, 3),
                    self.n(a_plan[k]),
                    self.n(c_a[k]),
                    "-" if ea is None else self.n(ea, 3),
                )
            )
        self.add("table", rows=rows, widths=(13, 25, 25, 18, 27, 27, 18))
        sc = dg.sheet_check
        self.text(w["grid"].format(n=sc.intervals, step=self.n(360.0 / sc.intervals)))
        for i in a.plan_positions:
            self.text(w["check_pos"].format(i=i))
            for val in (x for x in sc.values if x.index == i):
                sym = "V" if val.quantity == "v" else "a"
                if val.ill_conditioned:
                    unit = u["m/s"] if val.quantity == "v" else u["m/s2"]
                    self.eq(
                        f"|{sym}_{{plan}} - {sym}_{{diagr}}| = |{self.n(val.plan)} - "
                        f"{self.np_(val.diagram)}| = {self.n(val.absolute_error, 3)} {unit}"
                    )
                    self.text(w["ill_conditioned"].format(q=sym))
                    continue
                self.eq(
                    f"Δ_{sym} = ({sym}_{{plan}} - {sym}_{{diagr}})/{sym}_{{plan}}·100 % = "
                    f"({self.n(val.plan)} - {self.np_(val.diagram)})/{self.np_(val.plan)}"
                    f"·100 % = {self.n(val.error_percent, 3)} %"
                )
        if sc.passed:
            self.text(w["passed"])
        else:
            bad = "; ".join(
                f"{'V' if x.quantity == 'v' else 'a'}, {x.index}: {self.n(x.error_percent, 3)} %"
                for x in sc.values
                if not x.passed
            )
            self.text(w["failed"].format(why=bad))

    # --- sheet 2 -------------------------------------------------------------------------
    def forces(self) -> None:
        a = self.a
        if a.forces is None:
            self.section("2.1", "2.1")
            self.problem(MmtError(a.forces_problem or "no force analysis"))
            return
        fa = a.forces
        self.loads(fa)
        self.groups(fa)
        self.lever(fa)

    def loads(self, fa: ForceAnalysis) -> None:
        w, u = self.w, self.u
        self.section("2.1", "2.1")
        self.text(
            w["force_at"].format(
                i=fa.index, phi=self.n(fa.phi1_deg, 5), stroke=w[fa.stroke], g=self.n(fa.loads.g)
            )
        )
        g = fa.loads.g
        for lid, ll in fa.loads.links.items():
            if ll.mass:
                self.eq(
                    f"G_{{{lid}}} = m_{{{lid}}}·g = {self.n(ll.mass)}·{self.n(g)} = "
                    f"{self.n(ll.mass * g)} {u['N']}"
                )
        self.section("2.2", "2.2")
        for lid, ll in fa.loads.links.items():
            if ll.mass:
                aS = float(np.hypot(*ll.acceleration_cm))
                self.eq(
                    f"F_{{in{lid}}} = m_{{{lid}}}·a_{{S{lid}}} = {self.n(ll.mass)}·{self.n(aS)} = "
                    f"{self.n(ll.mass * aS)} {u['N']}"
                )
        for f in fa.loads.production_resistance:
            if f.acting:
                self.text(
                    w["F_PR"].format(
                        name=plain(_force_markup(f.name)),
                        link=f.link,
                        at=f.at,
                        F=self.n(float(np.hypot(*f.force))),
                    )
                )
            else:
                self.text(w["F_PR_idle"].format(name=plain(_force_markup(f.name))))
        self.section("2.3", "2.3")
        for lid, ll in fa.loads.links.items():
            link = self.mech.links[lid]
            if not ll.J:
                continue
            l = link.length
            if l > 0 and math.isclose(link.J, link.k * link.mass * l * l, rel_tol=1e-9):
                self.eq(
                    f"J_{{S{lid}}} = k·m_{{{lid}}}·l_{{{lid}}}^2 = {self.n(link.k)}·{self.n(link.mass)}·"
                    f"{self.n(l)}^2 = {self.n(link.J)} {u['kgm2']}"
                )
            else:
                self.eq(
                    w["J_given"]
                    .format(lid=lid, J=self.n(link.J))
                    .replace(f"J_S{lid}", f"J_{{S{lid}}}")
                )
        self.section("2.4", "2.4")
        for lid, ll in fa.loads.links.items():
            if ll.J and ll.eps:
                self.eq(
                    f"M_{{in{lid}}} = J_{{S{lid}}}·ε_{{{lid}}} = {self.n(ll.J)}·{self.n(abs(ll.eps))} = "
                    f"{self.n(abs(ll.inertia_moment))} {u['Nm']}"
                )
        self.section("2.5", "2.5")
        for lid, ll in fa.loads.links.items():
            if not ll.inertia_moment:
                continue
            sh = ll.shifted_inertia_force
            if sh is None:
                self.text(w["no_shift"].format(lid=lid))
                continue
            F = float(np.hypot(*ll.inertia_force))
            self.eq(
                f"h_{{{lid}}} = M_{{in{lid}}}/F_{{in{lid}}} = {self.n(abs(ll.inertia_moment))}/"
                f"{self.n(F)} = {self.n(sh.arm)} {u['m']}; |h_{{{lid}}}| = h_{{{lid}}}/μ_l = "
                f"{self.n(sh.arm)}/{self.n(float(self.a.mu_l))} = {self.n(sh.arm_mm or 0.0)} {u['mm']}"
            )

    def groups(self, fa: ForceAnalysis) -> None:
        w, u = self.w, self.u
        n_groups = len(fa.groups)
        for j, g in enumerate(fa.groups):
            step = f"2.{6 + j}"
            self.add("subsection", f"{step}. " + w["group"].format(name=g.name, kind=g.kind), step)
            poly = g.polygons[0]
            self.text(w["vector_eq"])
            self.eq(_equation_markup(poly.equation))
            mu_f = scale_for(poly.largest, FORCE_PLAN) if poly.largest > 0 else 1.0
            self.text(w["mu_F"])
            self.eq(
                f"μ_F = F_{{max}}/|F_{{max}}| = {self.n(poly.largest)}/{self.n(poly.largest / mu_f)} = "
                f"{self.n(mu_f)} {u['N/mm']}"
            )
            self.text(w["solve"])
            for s in g.steps:
                self.eq(self.step_line(s))
            self.text(w["found_R"])
            for r in g.reactions:
                comps = [c for c in r.components]
                name = _force_markup(r.name)
                if len(comps) == 2:
                    c1, c2 = comps
                    # osifont has no √: the root is written as a power 1/2
                    self.eq(
                        f"{name} = (({_force_markup(c1.label)})^2 + ({_force_markup(c2.label)})^2)^{{1/2}} = "
                        f"({self.np_(c1.value)}^2 + {self.np_(c2.value)}^2)^{{1/2}} = {self.n(r.magnitude)} {u['N']}"
                    )
                self.eq(
                    f"{name} = |{name}|·μ_F = {self.n(r.magnitude / mu_f)}·"
                    f"{self.n(mu_f)} = {self.n(r.magnitude)} {u['N']}"
                )
        step = f"2.{6 + n_groups}"
        self.add("subsection", f"{step}. {w['driver']}", step)
        dl = fa.driving_link
        mech = self.mech
        O = dl.pivot
        self.text(w["driver_eq"].format(O=O, d=dl.link))
        Opt = next(f.point for f in dl.free_body if f.label == dl.reaction.name)
        total = 0.0
        for f in dl.free_body:
            if f.label in ("F_bal", dl.reaction.name):
                continue
            M = f.moment_about(np.asarray(Opt))
            total += M
            F = float(np.hypot(*f.force))
            if F > 0:
                h = (M - f.couple) / F
                self.eq(
                    f"M_{_sub(O)}({_force_markup(f.label)}) = {self.n(F)}·{self.np_(h)} = {self.n(M)} {u['Nm']}"
                )
            elif f.couple:
                self.eq(f"M_{_sub(O)}({_force_markup(f.label)}) = {self.n(f.couple)} {u['Nm']}")
        sense = 1.0 if mech.drive.sense == "ccw" else -1.0
        OA = mech.crank_length
        self.text(w["F_bal_pl"].replace("{O}", _sub(O)))
        sign = "-" if sense > 0 else ""
        self.eq(
            f"F_{{bal.pl}} = {sign}ΣM_{_sub(O)}/l_{{OA}} = {sign}{self.np_(total)}/{self.n(OA)} = "
            f"{self.n(dl.balancing_force)} {u['N']}; M_{{bal}} = F_{{bal.pl}}·l_{{OA}} = "
            f"{self.n(dl.balancing_moment)} {u['Nm']}"
        )
        self.text(w["R01"].format(O=O, d=dl.link))
        self.eq(f"{_force_markup(dl.reaction.name)} = {self.n(dl.reaction.magnitude)} {u['N']}")
        step = f"2.{7 + n_groups}"
        self.add("subsection", f"{step}. {w['reactions']}", step)
        rows = [w["react_head"]]
        for name, r in fa.reactions.items():
            rows.append(
                (
                    _force_markup(r.name),
                    r.pair,
                    self.n(r.force[0]),
                    self.n(r.force[1]),
                    self.n(r.magnitude),
                )
            )
        self.add("table", rows=rows, widths=(24, 22, 32, 32, 32))
        self.fa_steps = 8 + n_groups

    def lever(self, fa: ForceAnalysis) -> None:
        w, u = self.w, self.u
        lv = fa.lever
        _, _, mu_v, _ = self.plan_scales()
        step = f"2.{self.fa_steps}"
        self.add("subsection", f"{step}. {w['lever']}", step)
        self.text(w["lever_text"].format(turn=w["against"]))
        rows = [w["lever_head"]]
        total = 0.0
        for f in lv.forces:
            F = float(np.hypot(*f.force))
            h_mm = f.arm / mu_v
            Fh = f.moment / mu_v
            total += Fh
            rows.append(
                (
                    _force_markup(f.label),
                    _image_markup(f.point),
                    self.n(F),
                    self.n(h_mm),
                    self.n(Fh),
                )
            )
        self.add("table", rows=rows, widths=(24, 16, 30, 30, 36))
        pa = lv.pa / mu_v
        s = 1.0 if self.mech.drive.sense == "ccw" else -1.0
        self.eq(
            f"ΣM_p = ΣF_i·h_i = {self.n(total)} {u['N']}·{u['mm']}; pa = V_A/μ_V = "
            f"{self.n(lv.pa)}/{self.n(mu_v)} = {self.n(pa)} {u['mm']}"
        )
        self.text(w["F_bal_z"])
        sign = "-" if s > 0 else ""
        self.eq(
            f"F_{{bal.z}} = {sign}ΣF_i·h_i/pa = {sign}{self.np_(total)}/{self.n(pa)} = "
            f"{self.n(lv.balancing_force)} {u['N']} "
            f"({w['drives'] if lv.balancing_force >= 0 else w['brakes']})"
        )
        step = f"2.{self.fa_steps + 1}"
        self.add("subsection", f"{step}. {w['match']}", step)
        self.text(w["discrepancy"])
        d = fa.discrepancy_percent
        z, pl = fa.balancing_force_lever, fa.balancing_force_plans
        self.eq(
            f"Δ_F = |F_{{bal.z}} - F_{{bal.pl}}|/|F_{{bal.z}}|·100 % = |{self.n(z, 6)} - "
            f"{self.np_(pl, 6)}|/{self.n(abs(z), 6)}·100 % = {self.n(d, 3)} % "
            + (w["within"] if math.isfinite(d) and d <= 5.0 else w["beyond"])
        )

    def step_line(self, s: str) -> str:
        """A step line of the force solver as markup, in the note's language."""
        # osifont has no ⇒ or →: the consequence is said in words
        s = s.replace(" -> ", f" {self.w['hence']} ").replace(" * ", "·").replace("Sum M_", "ΣM_")
        s = re.sub(r"\bR(\d)(\d)\^t\b", r"R^{τ}_{\1\2}", s)
        s = re.sub(r"\bR(\d)(\d)\^n\b", r"R^{n}_{\1\2}", s)
        s = re.sub(r"\bR(\d)(\d)\b", r"R_{\1\2}", s)
        s = s.replace("F_bal", "F_{bal.pl}").replace("M_bal", "M_{bal}")
        if self.lang == "uk":
            for en, uk in catalogue(self.lang).words("step_phrases").items():
                s = s.replace(en, str(uk))
            s = re.sub(r"(\d)\.(\d)", r"\1,\2", s)
        else:
            s = s.replace(" N*m", " N·m")
        return s


def note_content(analysis: Solution, lang: Language = "en") -> NoteContent:
    """The calculation note of `analysis` as blocks, in seed 003 §IV order."""
    return _Writer(analysis, lang).build()


def step_order() -> Sequence[str]:
    """Seed 003 §IV items of sheet 1, in order."""
    return ("1.1", "1.2", "1.3", "1.4", "1.5", "1.6", "1.7", "1.8")
