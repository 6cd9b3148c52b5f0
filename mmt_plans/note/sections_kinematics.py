"""Sheet 1 of the note (seed 003 §IV 1.1–1.8): structure, positions, the
plans with their vector equations, ω and ε, the diagrams and the 5 % check.

Every number goes in through `Writer.v` with its source (writer.py); the
values are the solver's, a segment of a plan is the value divided by the
plan's scale (seed 003 (5), (9))."""

from __future__ import annotations

import math
import re
from typing import TYPE_CHECKING, Any

import numpy as np

from ..drawing.markup import image_markup
from ..errors import MmtError
from . import sources as src
from .literature import cite
from .writer import Writer, sub, vec

if TYPE_CHECKING:  # pragma: no cover
    from ..diagrams import KinematicDiagrams
    from ..kinematics.plans import GroupPlanView, PlanView
    from ..sheets.scales_record import DiagramScales

__all__ = ["sheet1", "plan_scales"]


def sheet1(wr: Writer) -> None:
    a = wr.solution
    wr.text(
        wr.w["method_refs"].format(
            guide=cite("dovbush2018"),
            self=cite("strilets2025"),
            books=cite("artobolevskiy1954", "kinytskyi2002", "koreniako1993"),
            dstu=cite("dstu3008"),
        )
    )
    views: dict[int, PlanView | MmtError] = {}
    for i in a.plan_positions:
        try:
            views[i] = a.plan(i)
        except MmtError as err:
            views[i] = err
    structure(wr)
    positions(wr)
    velocity_plans(wr, views)
    angular_velocities(wr, views)
    acceleration_plans(wr, views)
    angular_accelerations(wr, views)
    diagrams(wr)


# --- 1.1 -------------------------------------------------------------------------------------
def structure(wr: Writer) -> None:
    st = wr.solution.structure
    S = "J['structure']"
    wr.heading("1.1")
    wr.text(wr.w["chebyshev"])
    n, p5, p4 = (wr.i(st.n, f"{S}['n']"), wr.i(st.p5, f"{S}['p5']"), wr.i(st.p4, f"{S}['p4']"))
    wr.text(wr.w["structure_counts"])
    wr.eq(f"n = {n}, p_5 = {p5}, p_4 = {p4}")
    n, p5, p4 = (wr.i(st.n, f"{S}['n']"), wr.i(st.p5, f"{S}['p5']"), wr.i(st.p4, f"{S}['p4']"))
    W = wr.i(st.W, f"{S}['W']")
    wr.eq(f"W = 3n - 2p_5 - p_4 = 3·{n} - 2·{p5} - {p4} = {W}")
    wr.text(wr.w["groups"].format(d=wr.i(st.driver, "M.drive.link")))
    for j, g in enumerate(st.groups):
        G = f"{S}['groups'][{j}]"
        links = sorted(g.links)
        wr.eq(
            wr.w["group_line"].format(
                label=g.label,
                links=", ".join(wr.i(x, f"{G}['links'][{m}]") for m, x in enumerate(links)),
                cls=wr.i(g.group_class, f"{G}['class']"),
                order=wr.i(g.order, f"{G}['order']"),
                kind=_kind(wr, g.kind),
                pairs=", ".join(p.name for p in g.pairs),
            )
        )
    wr.text(
        wr.w["class"].format(
            cls=wr.i(st.mechanism_class, f"{S}['mechanism_class']"), formula=st.formula
        )
    )
    structural_scheme(wr)


def structural_scheme(wr: Writer) -> None:
    """Seed 003 Fig. 1b: the driving link and the groups apart, as a figure."""
    from .figures import sketches_height, structure_sketches
    from .writer import FIGURE_WIDTH

    parts = structure_sketches(wr.solution)
    if not parts:
        return
    height = sketches_height([sk for _, sk in parts], FIGURE_WIDTH, labelled=True)
    wr.text(wr.w["structure_scheme"] + wr.cite(wr.next_figure) + ".")
    wr.drawing("structure", height, wr.w["fig_structure"], parts)


# the kinds of the class II groups in the textbook's order: "2-го виду" is RRP
DYAD_KINDS = ("RRR", "RRP", "RPR", "PRP", "RPP")


def _kind(wr: Writer, kind: str | None) -> str:
    """A group's kind as the textbook numbers it: "kind 2 (RRP)", "2-го виду (ВВП)"."""
    if not kind:
        return "-"
    letters = dict(wr.w["kind_letters"])
    local = "".join(letters.get(ch, ch) for ch in kind)
    if kind not in DYAD_KINDS:
        return local
    return str(wr.w["kind_n"]).format(n=DYAD_KINDS.index(kind) + 1, kind=local)


# --- 1.2 -------------------------------------------------------------------------------------
def positions(wr: Writer) -> None:
    a, w, u = wr.solution, wr.w, wr.u
    wr.heading("1.2")
    l_oa = wr.mech.crank_length
    mu_l, ML = wr.drawn.mechanism()
    oa = l_oa / mu_l
    wr.text(w["mu_l"].format(oa=wr.v(oa, f"M.crank_length/{ML}")))
    wr.eq(
        f"μ_l = l_{{OA}}/OA = {wr.v(l_oa, 'M.crank_length')}/{wr.v(oa, f'M.crank_length/{ML}')}"
        f" = {wr.v(mu_l, ML)} {u['m/mm']}"
    )
    caption = w["fig_mechanism"].format(mu=wr.v(mu_l, ML))
    n_fig = wr.next_figure
    if wr.has_figure([(1, ("mechanism",))]):
        wr.text(w["mechanism_drawn"].format(mu=wr.v(mu_l, ML)) + wr.cite(n_fig) + ".")
        wr.figure([(1, ("mechanism",))], caption)
    if a.extremes is None:
        wr.problem(w["no_extremes"].format(out=wr.mech.study.output))
    else:
        lo, hi = a.extremes
        wr.text(
            w["extremes"].format(
                out=wr.mech.study.output,
                lo=wr.v(lo, "J['extremes_deg']['working_start']", 5),
                hi=wr.v(hi, "J['extremes_deg']['working_end']", 5),
                span=wr.v(a.working_span_deg or 0.0, "S.working_span_deg", 5),
            )
        )
    n = wr.mech.study.positions
    wr.text(
        w["positions"].format(
            n=wr.i(n, "M.study.positions"),
            step=wr.v(360.0 / n, "360/M.study.positions"),
            plans=", ".join(wr.i(p, f"J['plans'][{j}]") for j, p in enumerate(a.plan_positions)),
            force=wr.i(a.force_position, "S.force_position"),
        )
    )
    s, _, _ = a.output_along(a.sweep)
    k0 = a.entry(0)
    s0 = s[k0] if np.isfinite(s[k0]) else 0.0
    rows: list[tuple[str, ...]] = [tuple(w["pos_head"])]
    for k, pos in enumerate(a.positions):
        label = wr.i(pos.index, f"J['positions'][{k}]['index']") if pos.index is not None else "*"
        S = f"(S.output_along(S.sweep)[0][{k}] - S.output_along(S.sweep)[0][{k0}])*1e3"
        rows.append(
            (
                label,
                wr.v(pos.phi1_deg, f"J['positions'][{k}]['phi1_deg']", 5),
                w[pos.stroke],
                wr.v((s[k] - s0) * 1e3, S) if np.isfinite(s[k]) else "-",
            )
        )
    wr.add("table", w["tab_positions"], rows=rows, widths=(16, 26, 28, 26))
    if any(pos.index is None for pos in a.positions):
        wr.text(
            w["tab_positions_star"].format(out=wr.mech.study.output, n=wr.i(n, "M.study.positions"))
        )
    wr.text(w["positions_table"])


# --- scales of the plans ---------------------------------------------------------------------
def plan_scales(wr: Writer, i: int) -> tuple[float, float, str, str]:
    """μ_V and μ_a of the plans at position i as sheet 1 draws them (seed 003 (5),
    (9); drawn.py), with their sources."""
    mu_v, mv = wr.drawn.velocity(i)
    mu_a, ma = wr.drawn.acceleration(i)
    return mu_v, mu_a, mv, ma


def _first_plan(wr: Writer) -> int | None:
    """The first plan position that solved: its scales are the ones introduced."""
    a = wr.solution
    return next((i for i in a.plan_positions if a.problem(a.entry(i)) is None), None)


def plan_sections(wr: Writer, views: dict[int, Any]) -> Any:
    """Each plan position under its heading: a solved one yielded, a failed one's problem written."""
    a = wr.solution
    for i, view in views.items():
        k = a.entry(i)
        pos = a.positions[k]
        wr.sub_heading(
            wr.w["vplan"].format(
                i=wr.i(i, f"J['plans'][{a.plan_positions.index(i)}]"),
                phi=wr.v(pos.phi1_deg, f"J['positions'][{k}]['phi1_deg']", 5),
                stroke=wr.w[pos.stroke],
            )
        )
        if isinstance(view, Exception):
            wr.problem(view)
            continue
        yield i, view


def moving_points(wr: Writer, view: PlanView) -> list[str]:
    owners = wr.mech.point_owners
    names = [p for p, o in owners.items() if 0 not in o]
    names += [p for p in view.velocity_images if p not in owners]
    return [p for p in names if p in view.velocity_images]


def point_at(wr: Writer, i: int, name: str) -> complex:
    name = src.located(wr.solution, name)
    return complex(wr.solution.sweep.position_of(name)[wr.solution.entry(i)])


def distance(wr: Writer, i: int, P: str, Q: str) -> tuple[float, str]:
    """l_PQ at position i, m, with its source."""
    d = abs(point_at(wr, i, P) - point_at(wr, i, Q))
    a = wr.solution
    return d, src.diff(src.point(a, i, P, "points"), src.point(a, i, Q, "points"))


def _legs(g: GroupPlanView, X: str) -> list[tuple[str, str, str | None]]:
    """(base point, relative name, guide link or None) of each leg of a group."""
    out: list[tuple[str, str, str | None]] = []
    for c in g.velocity:
        body = c.label.split("_", 1)[1]
        if "/" in body:
            out.append((X, body, body.split("/", 1)[1]))
        else:
            out.append((body[len(X) :], body, None))
    return out


def _owners(wr: Writer, name: str) -> list[int]:
    """The moving links a point belongs to: D on links 3 and 4, S2 on link 2."""
    owners = wr.mech.point_owners.get(name)
    if owners:
        return [o for o in owners if o != 0]
    m = re.fullmatch(r"S(\d+)", name)
    return [int(m.group(1))] if m and int(m.group(1)) in wr.mech.links else []


def _fixed(wr: Writer, name: str) -> bool:
    return 0 in wr.mech.point_owners.get(name, ())


class _Similarity:
    """Points found on their link's image by similarity (seed 003: pd = pb·CD/CB),
    each written as soon as two points of one of its links are known."""

    def __init__(self, wr: Writer, i: int, view: PlanView, q: str, mu: float, mu_src: str):
        self.wr, self.i, self.view, self.q, self.mu, self.mu_src = wr, i, view, q, mu, mu_src
        solved = {g.point for g in view.groups}
        self.todo = [p for p in moving_points(wr, view) if p not in solved]
        self.todo = [p for p in self.todo if p != wr.mech.crank_pin]
        self.known = {p for p in wr.mech.point_owners if _fixed(wr, p)} | {wr.mech.crank_pin}
        self.head = False

    def add(self, name: str) -> None:
        self.known.add(name)
        self.flush()

    def flush(self) -> None:
        progress = True
        while progress:
            progress = False
            for name in list(self.todo):
                for lid in _owners(self.wr, name):
                    refs = [
                        p for p in self.wr.mech.links[lid].points if p != name and p in self.known
                    ]
                    if len(refs) >= 2:
                        self.write(name, refs[0], refs[1])
                        self.todo.remove(name)
                        self.known.add(name)
                        progress = True
                        break

    def write(self, name: str, Q1: str, Q2: str) -> None:
        wr, i, view, q, mu, mu_src = self.wr, self.i, self.view, self.q, self.mu, self.mu_src
        a = wr.solution
        if not self.head:
            wr.text(wr.w["similarity_v" if q == "v" else "similarity_a"])
            self.head = True
        imgs = view.velocity_images if q == "v" else view.acceleration_images
        pole = "p" if q == "v" else "π"

        def img(P: str) -> str:
            return pole if _fixed(wr, P) else image_markup(P, wr.mech.point_owners)

        l1p, s1p = distance(wr, i, Q1, name)
        l12, s12 = distance(wr, i, Q1, Q2)
        if l12 == 0:
            return
        seg_np = float(np.hypot(*(imgs[name] - imgs[Q1]))) / mu
        seg_12 = float(np.hypot(*(imgs[Q2] - imgs[Q1]))) / mu
        sp = src.diff(src.point(a, i, name, q), src.point(a, i, Q1, q))
        s2 = src.diff(src.point(a, i, Q2, q), src.point(a, i, Q1, q))
        wr.eq(
            f"{img(Q1)}{img(name)} = {img(Q1)}{img(Q2)}·l_{{{Q1}{name}}}/l_{{{Q1}{Q2}}} = "
            f"{wr.v(seg_12, f'{s2}/{mu_src}')}·{wr.v(l1p, s1p)}/{wr.v(l12, s12)} = "
            f"{wr.v(seg_np, f'{sp}/{mu_src}')} {wr.u['mm']}"
        )


# --- 1.3 -------------------------------------------------------------------------------------
def velocity_plans(wr: Writer, views: dict[int, Any]) -> None:
    w, u = wr.w, wr.u
    wr.heading("1.3")
    d = wr.mech.drive
    n1 = d.n1_rpm
    w1 = math.pi * n1 / 30.0
    wr.text(w["omega1"])
    OMEGA = "abs(J['drive']['omega'])"
    wr.eq(f"ω_1 = π·n_1/30 = π·{wr.v(n1, 'M.drive.n1_rpm')}/30 = {wr.v(w1, OMEGA)} {u['rad/s']}")
    l_oa = wr.mech.crank_length
    first = _first_plan(wr)
    mu_v, _, mv, _ = plan_scales(wr, first) if first is not None else (1.0, 1.0, "1.0", "1.0")
    wr.text(w["VA"])
    wr.eq(
        f"V_A = ω_1·l_{{OA}} = {wr.v(w1, 'M.drive.omega')}·{wr.v(l_oa, 'M.crank_length')} = "
        f"{wr.v(w1 * l_oa, 'M.drive.omega*M.crank_length')} {u['m/s']};"
    )
    wr.eq(
        f"μ_V = V_A/pa = {wr.v(w1 * l_oa, 'M.drive.omega*M.crank_length')}/"
        f"{wr.v(w1 * l_oa / mu_v, f'M.drive.omega*M.crank_length/{mv}')} = "
        f"{wr.v(mu_v, mv)} {u['v/mm']}"
    )
    for i, view in plan_sections(wr, views):
        mu_v, _, mv, _ = plan_scales(wr, i)
        _velocity_plan(wr, i, view, mu_v, mv)


def _velocity_plan(wr: Writer, i: int, view: PlanView, mu_v: float, mv: str) -> None:
    w, u, a = wr.w, wr.u, wr.solution
    mu_a, ma = wr.drawn.acceleration(i)
    I = f"J['plans'][{a.plan_positions.index(i)}]"
    drawings = [(1, (f"velocity-plan-{i}",)), (1, (f"acceleration-plan-{i}",))]
    n_fig = wr.next_figure if wr.has_figure(drawings) else None
    wr.text(
        w["plans_drawn"].format(i=wr.i(i, I), mv=wr.v(mu_v, mv), ma=wr.v(mu_a, ma))
        + wr.cite(n_fig)
        + "."
    )
    if n_fig is not None:
        wr.figure(
            drawings, w["fig_plans"].format(i=wr.i(i, I), mv=wr.v(mu_v, mv), ma=wr.v(mu_a, ma))
        )
    similar = _Similarity(wr, i, view, "v", mu_v, mv)
    similar.flush()
    for gi, g in enumerate(view.groups):
        X = g.point
        wr.text(w["vequations"].format(name=g.group, kind=g.kind, X=X))
        legs = _legs(g, X)
        lines, legend = [], []
        for base, rel, guide in legs:
            if guide is None:
                lines.append(
                    f"{vec('V')}_{sub(X)} = {vec('V')}_{sub(base)} + {vec('V')}_{sub(rel)}"
                )
                fixed = 0 in wr.mech.point_owners.get(base, ())
                known = w["is_zero"] if fixed else w["known"]
                legend.append(
                    w["leg_rotation"].format(
                        base=f"V_{sub(base)}",
                        known=known,
                        # in words a vector is named by its segment on the plan: V_BA (ab)
                        rel=f"V_{sub(rel)} ({_segment(wr, X, base, None)})",
                        line=f"{X}{base}",
                    )
                )
            else:
                coinc = f"{X}({guide})"
                lines.append(
                    f"{vec('V')}_{sub(X)} = {vec('V')}_{sub(coinc)} + {vec('V')}_{sub(rel)}"
                )
                known = w["is_zero"] if guide == "0" else w["known"]
                legend.append(
                    w["leg_slide"].format(
                        base=f"V_{sub(coinc)}",
                        known=known,
                        rel=f"V_{sub(rel)} ({_segment(wr, X, base, guide)})",
                        X=X,
                        k=guide,
                    )
                )
        number = wr.eq("; ".join(lines))
        for line in legend:
            wr.text(line)
        wr.text(w["intersection_v"].format(x=image_markup(X, wr.mech.point_owners), eq=number))
        for ci, c in enumerate(g.velocity):
            base, rel, guide = legs[ci]
            seg = _segment(wr, X, base, guide)
            S = f"hyp(plan({i}).groups[{gi}].velocity[{ci}].vector)"
            wr.eq(
                f"{seg} = V_{sub(rel)}/μ_V = {wr.v(c.magnitude, S)}/{wr.v(mu_v, mv)} = "
                f"{wr.v(c.magnitude / mu_v, f'{S}/{mv}')} {u['mm']}"
            )
        similar.add(X)
    wr.text(w["found_v"])
    for name in moving_points(wr, view):
        v = float(np.hypot(*view.velocity_images[name]))
        S = f"hyp({src.point(a, i, name, 'v')})"
        wr.eq(
            f"V_{sub(name)} = p{image_markup(name, wr.mech.point_owners)}·μ_V = {wr.v(v / mu_v, f'{S}/{mv}')}·"
            f"{wr.v(mu_v, mv)} = {wr.v(v, S)} {u['m/s']}"
        )


def _segment(wr: Writer, X: str, base: str, guide: str | None) -> str:
    """The segment of a relative velocity on the plan: V_BA → ab; V_E/0 → e_(0)e;
    a velocity from the pole (a fixed base) starts at p."""
    if guide is not None:
        start = "p" if guide == "0" else f"{image_markup(X, wr.mech.point_owners)}_{{({guide})}}"
        return f"{start}{image_markup(X, wr.mech.point_owners)}"
    fixed = 0 in wr.mech.point_owners.get(base, ())
    return f"{'p' if fixed else image_markup(base, wr.mech.point_owners)}{image_markup(X, wr.mech.point_owners)}"


# --- 1.4 / 1.6 -------------------------------------------------------------------------------
def link_pair(wr: Writer, lid: int, view: PlanView) -> tuple[str, str] | None:
    names = [p for p in wr.mech.links[lid].points if p in view.velocity_images]
    if len(names) < 2:
        return None
    return names[1], names[0]


def guide_of(wr: Writer, lid: int) -> int | None:
    for sl in wr.mech.sliders:
        if sl.slider == lid:
            return sl.guide
    return None


def sense(wr: Writer, x: float) -> str:
    if abs(x) < 1e-12:
        return ""
    return f" ({wr.w['ccw'] if x > 0 else wr.w['cw']})"


def _rates(wr: Writer, views: dict[int, Any], q: str) -> None:
    a, w = wr.solution, wr.w
    omega = q == "omega"
    sym, unit = ("ω", wr.u["rad/s"]) if omega else ("ε", wr.u["rad/s2"])
    d = wr.mech.drive.link
    for i, view in views.items():
        if isinstance(view, Exception):
            continue
        rates = view.omega if omega else view.eps
        P_i = wr.i(i, f"J['plans'][{a.plan_positions.index(i)}]")
        wr.text(w["omega_pos" if omega else "eps_pos"].format(i=P_i))
        if omega:
            wr.eq(
                f"ω_{{{d}}} = {wr.v(abs(rates[d]), f'abs({src.rate(a, i, d, q)})')} {unit}"
                f"{sense(wr, rates[d])}"
            )
        else:
            wr.eq(w["eps1"].replace("ε_1", f"ε_{{{d}}}"))
        for lid in wr.mech.links:
            if lid == d:
                continue
            R = src.rate(a, i, lid, q)
            pair = link_pair(wr, lid, view)
            if pair is None:
                g = guide_of(wr, lid)
                note = f"  ({w['slides_with'].format(lid=lid, g=g)})" if omega else ""
                wr.eq(
                    f"{sym}_{{{lid}}} = {sym}_{{{g if g is not None else 0}}} = "
                    f"{wr.v(abs(rates[lid]), f'abs({R})')} {unit}{sense(wr, rates[lid])}{note}"
                )
                continue
            P, Q = pair
            l, ls = distance(wr, i, P, Q)
            imgs = view.velocity_images if omega else view.acceleration_images
            if omega:
                rel = float(np.hypot(*(imgs[P] - imgs[Q])))
                rs = src.diff(src.point(a, i, P, "v"), src.point(a, i, Q, "v"))
                head = f"V_{{{P}{Q}}}"
            else:
                # the tangential part of a_PQ: a_PQ minus its normal part −ω²·r
                rc = point_at(wr, i, P) - point_at(wr, i, Q)
                r = np.array([rc.real, rc.imag])
                om = view.omega[lid]
                rel = float(np.hypot(*(imgs[P] - imgs[Q] + om * om * r)))
                rs = f"abs({R})*{ls}"
                head = f"a^τ_{{{P}{Q}}}"
            wr.eq(
                f"{sym}_{{{lid}}} = {head}/l_{{{P}{Q}}} = {wr.v(rel, rs)}/{wr.v(l, ls)} = "
                f"{wr.v(abs(rates[lid]), f'abs({R})')} {unit}{sense(wr, rates[lid])}"
            )
    wr.text(w["senses_v" if omega else "senses_a"])


def angular_velocities(wr: Writer, views: dict[int, Any]) -> None:
    wr.heading("1.4")
    wr.text(wr.w["omega_formula"])
    _rates(wr, views, "omega")


def angular_accelerations(wr: Writer, views: dict[int, Any]) -> None:
    wr.heading("1.6")
    wr.text(wr.w["eps_formula"])
    _rates(wr, views, "eps")


# --- 1.5 -------------------------------------------------------------------------------------
def acceleration_plans(wr: Writer, views: dict[int, Any]) -> None:
    w, u = wr.w, wr.u
    wr.heading("1.5")
    d = wr.mech.drive
    w1 = abs(d.omega)
    l_oa = wr.mech.crank_length
    first = _first_plan(wr)
    _, mu_a, _, ma = plan_scales(wr, first) if first is not None else (1.0, 1.0, "1.0", "1.0")
    a_a = w1 * w1 * l_oa
    A = "M.drive.omega**2*M.crank_length"
    wr.text(w["aA"])
    wr.eq(
        f"a_A = a^n_A = ω_1^2·l_{{OA}} = {wr.v(w1, 'M.drive.omega')}^2·"
        f"{wr.v(l_oa, 'M.crank_length')} = {wr.v(a_a, A)} {u['m/s2']};"
    )
    wr.eq(
        f"μ_a = a_A/πa = {wr.v(a_a, A)}/{wr.v(a_a / mu_a, f'{A}/{ma}')} = "
        f"{wr.v(mu_a, ma)} {u['a/mm']}"
    )
    for i, view in plan_sections(wr, views):
        _, mu_a, _, ma = plan_scales(wr, i)
        _acceleration_plan(wr, i, view, mu_a, ma)


def _acceleration_plan(wr: Writer, i: int, view: PlanView, mu_a: float, ma: str) -> None:
    w, u, a = wr.w, wr.u, wr.solution
    similar = _Similarity(wr, i, view, "a", mu_a, ma)
    similar.flush()
    for gi, g in enumerate(view.groups):
        X = g.point
        wr.text(w["aequations"].format(name=g.group, kind=g.kind, X=X))
        legs = _legs(g, X)
        lines = []
        A = vec("a")
        for base, rel, guide in legs:
            if guide is None:
                lines.append(
                    f"{A}_{sub(X)} = {A}_{sub(base)} + {A}^n_{sub(rel)} + {A}^τ_{sub(rel)}"
                )
            else:
                lines.append(
                    f"{A}_{sub(X)} = {A}_{sub(X + '(' + guide + ')')} + {A}^k_{sub(rel)} + {A}^r_{sub(rel)}"
                )
        number = wr.eq("; ".join(lines))
        for base, rel, guide in legs:
            if guide is None:
                wr.text(w["leg_rotation_a"].format(rel=rel, X=X, base=base))
            else:
                key = "leg_fixed_a" if guide == "0" else "leg_slide_a"
                wr.text(w[key].format(rel=rel, X=X, k=guide))
        comps = list(g.acceleration)
        for ci, c in enumerate(comps):
            base, rel, guide = legs[ci // 2]
            C = f"plan({i}).groups[{gi}].acceleration[{ci}].vector"
            val = c.magnitude
            if c.kind == "normal":
                vc = g.velocity[ci // 2].magnitude
                VS = f"hyp(plan({i}).groups[{gi}].velocity[{ci // 2}].vector)"
                l, ls = distance(wr, i, X, base)
                wr.eq(
                    f"a^n_{sub(rel)} = V_{sub(rel)}^2/l_{sub(rel)} = {wr.v(vc, VS)}^2/"
                    f"{wr.v(l, ls)} = {wr.v(val, f'hyp({C})')} {u['m/s2']}; "
                    f"|a^n_{sub(rel)}| = {wr.v(val, f'hyp({C})')}/{wr.v(mu_a, ma)} = "
                    f"{wr.v(val / mu_a, f'hyp({C})/{ma}')} {u['mm']}"
                )
            elif c.kind == "coriolis":
                k = int(rel.split("/", 1)[1])
                om = abs(view.omega.get(k, 0.0)) if k != 0 else 0.0
                vr = g.velocity[ci // 2].magnitude
                VS = f"hyp(plan({i}).groups[{gi}].velocity[{ci // 2}].vector)"
                OM = f"abs({src.rate(a, i, k, 'omega')})" if k != 0 else "0"
                wr.eq(
                    f"a^k_{sub(rel)} = 2·ω_{{{k}}}·V_{sub(rel)} = 2·{wr.v(om, OM)}·"
                    f"{wr.v(vr, VS)} = {wr.v(val, f'hyp({C})')} {u['m/s2']}; "
                    f"|a^k_{sub(rel)}| = {wr.v(val / mu_a, f'hyp({C})/{ma}')} {u['mm']}"
                )
        wr.text(w["intersection_a"].format(x=image_markup(X, wr.mech.point_owners), eq=number))
        for ci, c in enumerate(comps):
            if c.kind not in ("tangential", "slide"):
                continue
            _, rel, _ = legs[ci // 2]
            C = f"hyp(plan({i}).groups[{gi}].acceleration[{ci}].vector)"
            sym = "a^τ" if c.kind == "tangential" else "a^r"
            wr.eq(
                f"{sym}_{sub(rel)} = |{sym}_{sub(rel)}|·μ_a = "
                f"{wr.v(c.magnitude / mu_a, f'{C}/{ma}')}·{wr.v(mu_a, ma)} = "
                f"{wr.v(c.magnitude, C)} {u['m/s2']}"
            )
        similar.add(X)
    wr.text(w["found_a"])
    for name in moving_points(wr, view):
        acc = float(np.hypot(*view.acceleration_images[name]))
        S = f"hyp({src.point(a, i, name, 'a')})"
        wr.eq(
            f"a_{sub(name)} = π{image_markup(name, wr.mech.point_owners)}·μ_a = {wr.v(acc / mu_a, f'{S}/{ma}')}·"
            f"{wr.v(mu_a, ma)} = {wr.v(acc, S)} {u['m/s2']}"
        )


# --- 1.7, 1.8 --------------------------------------------------------------------------------
def _diagrams_as_drawn(wr: Writer, d: DiagramScales, c: KinematicDiagrams) -> str:
    """Where sheet 1 draws the diagrams at other scales than the construction
    above (larger, in the room the sheet leaves them), the sentence that says
    them; μ_S of the drawing, as a marker, for the figure's caption."""
    D = "sheet1.diagrams"
    mu_S = wr.v(d.mu_S, f"{D}.mu_S")
    same = all(
        wr.cat.number(x) == wr.cat.number(y)
        for x, y in ((d.L, c.L), (d.mu_S, c.mu_S), (d.H1, c.H1), (d.H2, c.H2))
    )
    if same:
        return mu_S
    u = wr.u
    wr.text(wr.w["diagrams_drawn"])
    wr.eq(
        f"L = {wr.v(d.L, f'{D}.L')} {u['mm']}; μ_t = {wr.v(d.mu_t, f'{D}.mu_t')} {u['s/mm']}; "
        f"μ_S = {mu_S} {u['m/mm']};"
    )
    wr.eq(
        f"OH_1 = {wr.v(d.H1, f'{D}.H1')} {u['mm']}, μ_V = {wr.v(d.mu_V, f'{D}.mu_V')} "
        f"{u['v/mm']}; OH_2 = {wr.v(d.H2, f'{D}.H2')} {u['mm']}, "
        f"μ_a = {wr.v(d.mu_a, f'{D}.mu_a')} {u['a/mm']}"
    )
    return mu_S


def diagrams(wr: Writer) -> None:
    a, w, u = wr.solution, wr.w, wr.u
    wr.heading("1.7")
    if a.diagrams is None:
        err = a.diagrams_problem or "no kinematic diagrams"
        wr.problem(err)
        wr.heading("1.8")
        wr.problem(err)
        return
    dg = a.diagrams
    c = dg.construction
    D = "J['diagrams']"
    sc = f"{D}['scales']"
    grid = dg.sheet_check.intervals
    wr.text(
        w["chord_method"].format(
            ref=cite("dovbush2018"),
            n=wr.i(grid, f"{D}['grid_intervals']"),
            step=wr.v(360.0 / grid, f"360/{D}['grid_intervals']"),
        )
    )
    wr.text(
        w["diagram_scales"].format(
            out=wr.mech.study.output,
            L=wr.v(c.L, f"{sc}['L_mm']"),
            H1=wr.v(c.H1, f"{sc}['H1_mm']"),
            H2=wr.v(c.H2, f"{sc}['H2_mm']"),
        )
    )
    MUS, MUT, MUV, MUA = (
        f"{sc}['mu_S']",
        f"{sc}['mu_t']",
        f"{sc}['mu_V']",
        f"{sc}['mu_a']",
    )
    LMM, H1, H2 = f"{sc}['L_mm']", f"{sc}['H1_mm']", f"{sc}['H2_mm']"
    wr.eq(
        f"μ_S = {wr.v(c.mu_S, MUS)} {u['m/mm']} "
        + w["mu_S_is"].format(mu_l=wr.v(*wr.drawn.mechanism()))
    )
    wr.eq(
        f"μ_t = 60/(n_1·L) = 60/({wr.v(c.n1, 'M.drive.n1_rpm')}·{wr.v(c.L, LMM)}) = "
        f"{wr.v(c.mu_t, MUT)} {u['s/mm']};"
    )
    wr.eq(
        f"μ_V = μ_S/(μ_t·OH_1) = {wr.v(c.mu_S, MUS)}/({wr.v(c.mu_t, MUT)}·"
        f"{wr.v(c.H1, H1)}) = "
        f"{wr.v(c.mu_V, MUV)} {u['v/mm']};"
    )
    wr.eq(
        f"μ_a = μ_V/(μ_t·OH_2) = {wr.v(c.mu_V, MUV)}/({wr.v(c.mu_t, MUT)}·"
        f"{wr.v(c.H2, H2)}) = "
        f"{wr.v(c.mu_a, MUA)} {u['a/mm']}"
    )
    drawings = [(1, ("diagram-s",)), (1, ("diagram-v",)), (1, ("diagram-a",))]
    n_fig = wr.next_figure if wr.has_figure(drawings) else None
    wr.text(w["diagram_read"][:-1] + wr.cite(n_fig) + ".")
    mu_S_drawn = wr.v(c.mu_S, MUS)
    on_sheet = wr.drawn.diagrams()
    if on_sheet is not None and n_fig is not None:
        mu_S_drawn = _diagrams_as_drawn(wr, on_sheet, c)
    if n_fig is not None:
        wr.figure(drawings, w["fig_diagrams"].format(out=wr.mech.study.output, mu=mu_S_drawn))
    wr.heading("1.8")
    plans = set(a.plan_positions)
    check = dg.check
    c_v, c_a = dg.at_position(c.v), dg.at_position(c.a)
    rows: list[tuple[str, ...]] = [tuple(w["check_head"])]
    for k in range(len(c_v)):
        ev, ea = check.v_error_percent[k], check.a_error_percent[k]
        rows.append(
            (
                wr.i(k, f"J['positions'][{k}]['index']") + ("*" if k in plans else ""),
                wr.v(dg.v_plan[k], f"{D}['v_plan'][{k}]"),
                wr.v(c_v[k], f"{D}['v_diagram'][{k}]"),
                "-" if ev is None else wr.v(ev, f"{D}['error_percent']['v'][{k}]", 3),
                wr.v(dg.a_plan[k], f"{D}['a_plan'][{k}]"),
                wr.v(c_a[k], f"{D}['a_diagram'][{k}]"),
                "-" if ea is None else wr.v(ea, f"{D}['error_percent']['a'][{k}]", 3),
            )
        )
    wr.add(
        "table",
        w["tab_check"].format(out=wr.mech.study.output),
        rows=rows,
        widths=(13, 25, 25, 18, 27, 27, 18),
    )
    marked = ", ".join(
        wr.i(i, f"J['plans'][{j}]") + "*" for j, i in enumerate(a.plan_positions) if i in plans
    )
    wr.text(w["tab_check_star"].format(marked=marked))
    sheet = dg.sheet_check
    wr.text(
        w["grid"].format(
            n=wr.i(sheet.intervals, f"{D}['grid_intervals']"),
            step=wr.v(360.0 / sheet.intervals, f"360/{D}['grid_intervals']"),
        )
    )
    lim = wr.v(sheet.limit_percent, f"{D}['limit_percent']")
    wr.text(w["check_rule"].format(lim=lim))
    for j, val in enumerate(sheet.values):
        I = f"{D}['investigated'][{j}]"
        if j == 0 or sheet.values[j - 1].index != val.index:
            wr.text(w["check_pos"].format(i=wr.i(val.index, f"{I}['index']")))
        sym = "V" if val.quantity == "v" else "a"
        unit = u["m/s"] if val.quantity == "v" else u["m/s2"]
        if val.ill_conditioned:
            P, Dg, AE = f"{I}['plan']", f"{I}['diagram']", f"{I}['absolute_error']"
            wr.eq(
                f"|{sym}_{{plan}} - {sym}_{{diagr}}| = |{wr.v(val.plan, P)} - "
                f"{wr.vp(val.diagram, Dg)}| = {wr.v(val.absolute_error, AE, 3)} {unit}"
            )
            wr.text(w["ill_conditioned"].format(q=sym))
            continue
        P = f"{I}['plan']"
        Dg = f"{I}['diagram']"
        E = f"{I}['error_percent']"
        wr.eq(
            f"Δ_{sym} = ({sym}_{{plan}} - {sym}_{{diagr}})/{sym}_{{plan}}·100 % = "
            f"({wr.v(val.plan, P)} - {wr.vp(val.diagram, Dg)})/{wr.vp(val.plan, P)}"
            f"·100 % = {wr.v(val.error_percent, E, 3)} % "
            + (w["le"] if val.passed else w["gt"]).format(lim=lim)
        )
    if sheet.passed:
        wr.text(w["passed"].format(lim=lim))
    else:
        parts = []
        for j, x in enumerate(sheet.values):
            if x.passed:
                continue
            I = f"{D}['investigated'][{j}]"
            E = f"{I}['error_percent']"
            q = "V" if x.quantity == "v" else "a"
            IX = f"{I}['index']"
            parts.append(f"{q}, {wr.i(x.index, IX)}: {wr.v(x.error_percent, E, 3)} %")
        bad = "; ".join(parts)
        wr.text(w["failed"].format(why=bad, lim=lim))
