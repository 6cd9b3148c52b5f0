"""Sheet 2 of the note (seed 003 §IV 2.1–2.11): loads, the groups' moment
equations with every arm, the force polygons, the driving link, the
reactions, Zhukovsky's lever and the comparison (21).

One sign convention, stated once at the head of the sheet: a moment is
positive counter-clockwise, and an arm h carries the sign of its force's
moment (M = F·h); the balancing force is positive in the sense of the
crank's rotation (it drives)."""

from __future__ import annotations

import math
import re
from typing import TYPE_CHECKING

import numpy as np

from ..drawing.markup import image_markup
from . import sources as src
from .literature import cite
from .writer import Writer, and_list, sub, vec

if TYPE_CHECKING:  # pragma: no cover
    from ..forces import ForceAnalysis, ForcePolygon, GroupForces
    from ..forces.loads import AppliedForce

__all__ = ["sheet2", "force_markup", "equation_markup"]

L = "J['forces']['loads']"


def force_markup(label: str) -> str:
    """Labels of the force solver as markup: "F_in2" → "F_{in2}", "R34^t" → "R^{τ}_{34}"."""
    m = re.fullmatch(r"R(\d+)(?:_(\d+))?(?:\^(\w))?", label)
    if m:
        idx = m.group(1) + (f",{m.group(2)}" if m.group(2) else "")
        sup = {"t": "τ", "n": "n"}.get(m.group(3) or "", m.group(3) or "")
        return f"R^{{{sup}}}_{{{idx}}}" if sup else f"R_{{{idx}}}"
    if label == "F_bal":
        return "F_{bal.pl}"
    m = re.fullmatch(r"(F'?|G|M)_?([A-Za-z]*)(\d*)", label)
    if m and (m.group(2) or m.group(3)):
        return f"{m.group(1)}_{{{m.group(2)}{m.group(3)}}}"
    if "_" in label:
        head, tail = label.split("_", 1)
        return f"{head}_{{{tail}}}"
    return label


def equation_markup(eq: str) -> str:
    """A polygon's vector equation with its vectors marked: "F⃗_{in2} + R⃗_{12} + … = 0"."""
    terms = eq.replace("= 0", "").split("+")
    return " + ".join(vec(force_markup(t.strip())) for t in terms) + " = 0"


def sheet2(wr: Writer) -> None:
    a = wr.solution
    if a.forces is None:
        wr.heading("2.1")
        wr.problem(a.forces_problem or "no force analysis")
        return
    fa = a.forces
    wr.text(wr.w["sign_convention"])
    loads(wr, fa)
    n = len(fa.groups)
    for j, g in enumerate(fa.groups):
        group(wr, fa, j, g, f"2.{6 + j}")
    driving_link(wr, fa, f"2.{6 + n}")
    reactions(wr, fa, f"2.{7 + n}")
    lever(wr, fa, f"2.{8 + n}")
    match(wr, fa, f"2.{9 + n}")


def _step(wr: Writer, step: str, text: str) -> None:
    wr.add("subsection", f"{step}. {text}", step)


# --- 2.1–2.5 ---------------------------------------------------------------------------------
def loads(wr: Writer, fa: ForceAnalysis) -> None:
    w, u, a = wr.w, wr.u, wr.solution
    k = a.entry(fa.index) if fa.index is not None else 0
    wr.heading("2.1")
    wr.text(
        w["force_at"].format(
            i=wr.i(fa.index or 0, "J['forces']['index']"),
            phi=wr.v(fa.phi1_deg, "J['forces']['phi1_deg']", 5),
            stroke=w[fa.stroke],
            g=wr.v(fa.loads.g, "M.g"),
        )
    )
    del k
    g = fa.loads.g
    for lid, ll in fa.loads.links.items():
        if ll.mass:
            G = f"-{L}['{lid}']['G'][1]"
            wr.eq(
                f"G_{{{lid}}} = m_{{{lid}}}·g = {wr.v(ll.mass, f'M.links[{lid}].mass')}·"
                f"{wr.v(g, 'M.g')} = {wr.v(ll.mass * g, G)} {u['N']}"
            )
    massless = [str(lid) for lid, ll in fa.loads.links.items() if not ll.mass]
    if massless:
        key = "massless" if len(massless) > 1 else "massless_one"
        wr.text(w[key].format(links=and_list(massless, w["and"])))
    wr.heading("2.2")
    wr.text(w["inertia_rule"])
    for lid, ll in fa.loads.links.items():
        if not ll.mass:
            continue
        aS = float(np.hypot(*ll.acceleration_cm))
        AS, FI = f"hyp({L}['{lid}']['a_S'])", f"hyp({L}['{lid}']['F_in'])"
        wr.eq(
            f"F_{{in{lid}}} = m_{{{lid}}}·a_{{S{lid}}} = {wr.v(ll.mass, f'M.links[{lid}].mass')}·"
            f"{wr.v(aS, AS)} = {wr.v(ll.mass * aS, FI)} {u['N']}"
        )
    for j, f in enumerate(fa.loads.production_resistance):
        name = force_markup(f.name)
        if f.acting:
            FF = f"hyp(J['forces']['external_forces'][{f.name!r}]['force'])"
            wr.text(
                w["F_PR"].format(
                    name=name, link=f.link, at=f.at, F=wr.v(float(np.hypot(*f.force)), FF)
                )
            )
        else:
            wr.text(w["F_PR_idle"].format(name=name))
    wr.heading("2.3")
    for lid, ll in fa.loads.links.items():
        link = wr.mech.links[lid]
        if not ll.J:
            continue
        l = link.length
        JS = f"M.links[{lid}].J"
        if l > 0 and math.isclose(link.J, link.k * link.mass * l * l, rel_tol=1e-9):
            wr.eq(
                f"J_{{S{lid}}} = k·m_{{{lid}}}·l_{{{lid}}}^2 = {wr.v(link.k, f'M.links[{lid}].k')}·"
                f"{wr.v(link.mass, f'M.links[{lid}].mass')}·{wr.v(l, f'M.links[{lid}].length')}^2"
                f" = {wr.v(link.J, JS)} {u['kgm2']}"
            )
        else:
            wr.eq(f"J_{{S{lid}}} = {wr.v(link.J, JS)} {u['kgm2']} " + w["given"])
    wr.heading("2.4")
    wr.text(w["moment_rule"])
    for lid, ll in fa.loads.links.items():
        if ll.J and ll.eps:
            E, MI = f"abs({L}['{lid}']['eps'])", f"abs({L}['{lid}']['M_in'])"
            wr.eq(
                f"M_{{in{lid}}} = J_{{S{lid}}}·ε_{{{lid}}} = {wr.v(ll.J, f'M.links[{lid}].J')}·"
                f"{wr.v(abs(ll.eps), E)} = {wr.v(abs(ll.inertia_moment), MI)} {u['Nm']}"
                + _sense(wr, ll.inertia_moment)
            )
    wr.heading("2.5")
    for lid, ll in fa.loads.links.items():
        if not ll.inertia_moment:
            continue
        sh = ll.shifted_inertia_force
        if sh is None:
            wr.text(w["no_shift"].format(lid=lid))
            continue
        F = float(np.hypot(*ll.inertia_force))
        MI, FI = f"abs({L}['{lid}']['M_in'])", f"hyp({L}['{lid}']['F_in'])"
        H = f"{L}['{lid}']['h']"
        mu_l, ML = wr.drawn.loaded()
        wr.eq(
            f"h_{{F{lid}}} = M_{{in{lid}}}/F_{{in{lid}}} = {wr.v(abs(ll.inertia_moment), MI)}/"
            f"{wr.v(F, FI)} = {wr.v(sh.arm, H)} {u['m']}; |h_{{F{lid}}}| = h_{{F{lid}}}/μ_l = "
            f"{wr.v(sh.arm, H)}/{wr.v(mu_l, ML)} = {wr.v(sh.arm / mu_l, f'{H}/{ML}')} "
            f"{u['mm']}"
        )
        wr.text(w["shift_side"].format(lid=lid))
    drawings = [(2, ("force-mechanism",))]
    # the mechanism's detail view (sheet 2 draws one where its names crowd)
    details = [(2, (g,)) for g in wr.drawings_named(2, "force-mechanism-detail")]
    if wr.has_figure(drawings):
        mu_l, ML = wr.drawn.loaded()
        n_fig = wr.next_figure
        drawn = w["loads_drawn"].format(mu=wr.v(mu_l, ML)) + wr.cite(n_fig) + "."
        wr.text(drawn + (" " + w["loads_details_drawn"] if details else ""))
        caption = w["fig_loads"].format(
            i=wr.i(fa.index or 0, "J['forces']['index']"), mu=wr.v(mu_l, ML)
        )
        if details:
            parts = ", ".join(str(w["part_letters"])[1 : 1 + len(details)])
            caption += w["fig_loads_parts"].format(parts=parts)
        wr.figure(drawings + details, caption)


def _sense(wr: Writer, x: float) -> str:
    if abs(x) < 1e-12:
        return ""
    return f" ({wr.w['ccw'] if x > 0 else wr.w['cw']})"


# --- forces of a free body as sources ----------------------------------------------------------
def _terms(
    wr: Writer, fa: ForceAnalysis, body: tuple[AppliedForce, ...], skip: set[str], base: str
) -> list[tuple[str, np.ndarray, np.ndarray, float, str]]:
    """(label, force, point, couple, source of the (point, force, couple)) of each load
    of a free body, the inertia force moved to K (seed 003 §2.5) and its couple
    dropped; `base` is the source of the body's tuple."""
    out = []
    shifted = set()
    for m, f in enumerate(body):
        if f.label in skip:
            continue
        mi = re.fullmatch(r"F_in(\d+)", f.label)
        if mi:
            ll = fa.loads.links[int(mi.group(1))]
            if ll.shifted_inertia_force is not None and ll.inertia_moment:
                K = ll.shifted_inertia_force.point
                lid = mi.group(1)
                out.append(
                    (f.label, f.force, K, 0.0, f"({L}['{lid}']['K'], {L}['{lid}']['F_in'], 0)")
                )
                shifted.add(f"M_in{lid}")
                continue
        out.append((f.label, f.force, f.point, f.couple, f"as_load({base}[{m}])"))
    return [t for t in out if t[0] not in shifted]


def _moment_terms(
    wr: Writer,
    fa: ForceAnalysis,
    terms,
    P: np.ndarray,
    P_src: str,
    about: str,
    scale: tuple[float, str],
) -> tuple[float, list[str]]:
    """Write M_P of each term as F·h (h in m and in mm of the drawing at
    `scale`, the sheet's μ_l of it, with its source); the sum and the terms
    (markup, with numbers) for the equation."""
    u = wr.u
    mu_l, ML = scale
    total, parts = 0.0, list[str]()
    for label, force, point, couple, s in terms:
        r = np.asarray(point) - P
        F = float(np.hypot(*force))
        M = float(r[0] * force[1] - r[1] * force[0]) + couple
        total += M
        MS = f"moment({s}, {P_src})"
        name = force_markup(label)
        if F > 0:
            h = (M - couple) / F
            HS = f"arm({s}, {P_src})"
            FS = f"hyp({s}[1])"
            hn = f"h_{{{len(parts) + 1}}}"
            wr.eq(
                f"{hn} = {wr.v(h / mu_l, f'{HS}/{ML}')} {u['mm']}·μ_l = "
                f"{wr.vp(h / mu_l, f'{HS}/{ML}')}·{wr.v(mu_l, ML)} = {wr.v(h, HS)} {u['m']}; "
                f"M_{sub(about)}({name}) = {name}·{hn} = {wr.v(F, FS)}·{wr.vp(h, HS)} = "
                f"{wr.v(M, MS)} {u['Nm']}"
            )
            parts.append(f"{name}·{hn}")
        elif couple:
            wr.eq(f"M_{sub(about)}({name}) = {wr.v(M, MS)} {u['Nm']}")
            parts.append(name)
    return total, parts


# --- 2.6 … groups ----------------------------------------------------------------------------
def group(wr: Writer, fa: ForceAnalysis, j: int, g: GroupForces, step: str) -> None:
    w, u, a = wr.w, wr.u, wr.solution
    _step(wr, step, w["group"].format(name=g.name, kind=g.kind))
    fp = fa.index if fa.index is not None else a.force_position
    own = {r.name for r in g.reactions} | {r.reversed().name for r in g.reactions}
    loads_on = []
    for lid in g.links:
        loads_on += [
            force_markup(f.label)
            for f in g.free_bodies[lid]
            if f.label not in own and not f.label.startswith("M_in")
        ]
    wr.text(w["group_loads"].format(name=g.name, loads=", ".join(dict.fromkeys(loads_on))))
    inner = g.reactions[2]
    for r_ix, r in enumerate(g.reactions[:2]):
        comp = next((c for c in r.components if c.label.endswith("^t")), None)
        if comp is None:
            continue
        lid = r.on
        B = inner.pair
        P = np.asarray(inner.point)
        P_src = src.point(a, fp, B, "points")
        A_name = r.pair
        l_AB = float(np.hypot(*(np.asarray(r.point) - P)))
        l_src = src.diff(src.point(a, fp, A_name, "points"), P_src)
        wr.text(
            w["tangential_eq"].format(
                R=force_markup(comp.label), B=B, lid=lid, A=A_name, n=force_markup(r.name)
            )
        )
        terms = _terms(wr, fa, g.free_bodies[lid], own, f"F.groups[{j}].free_bodies[{lid}]")
        total, parts = _moment_terms(wr, fa, terms, P, P_src, B, wr.drawn.group(g.name))
        RT = f"J['forces']['reaction_details'][{r.name!r}]['components'][{comp.label!r}]"
        sum_src = "+".join(f"moment({t[4]}, {P_src})" for t in terms) or "0"
        Rt = force_markup(comp.label)
        lhs = " + ".join(parts) if parts else "0"
        wr.eq(f"ΣM_{sub(B)}({lid}) = {lhs} - {Rt}·l_{{{A_name}{B}}} = 0;")
        wr.eq(
            f"{Rt} = ΣM_{sub(B)}/l_{{{A_name}{B}}} = {wr.vp(total, sum_src)}/"
            f"{wr.v(l_AB, l_src)} = {wr.v(comp.value, RT)} {u['N']}"
            + (" " + w["reverse"] if comp.value < 0 else "")
        )
    if g.kind == "RPR":
        _slot_reaction(wr, fa, j, g, own)
    if g.kind in ("PRP", "RPP"):
        _guide_reactions(wr, j, g)
    mu_f = wr.drawn.force(f"group {g.name}", g.polygons, f"F.groups[{j}].polygons")
    for p_ix, poly in enumerate(g.polygons):
        _polygon(wr, poly, f"F.groups[{j}].polygons[{p_ix}]", p_ix == 0, mu_f)
    wr.text(w["found_R"])
    for r in g.reactions:
        _reaction_line(wr, r, *mu_f)
    _guide_points(wr, fa, j, g, own)
    _guide_couples(wr, fa, j, g)
    # on sheet 2, or on the further sheet that holds the group (sheet2_further)
    n = wr.composed.holding(f"group-{g.name}")
    drawings = [(n, (f"group-{g.name}",)), (n, (f"force-polygon-{g.name}",))]
    if wr.has_figure(drawings):
        mu_l, ML = wr.drawn.group(g.name)
        n_fig = wr.next_figure
        wr.text(
            w["group_drawn"].format(name=g.name, mu=wr.v(mu_l, ML), mf=wr.v(*mu_f))
            + wr.cite(n_fig)
            + "."
        )
        wr.figure(
            drawings,
            w["fig_group"].format(name=g.name, mu=wr.v(mu_l, ML), mf=wr.v(*mu_f)),
        )


def _slot_reaction(wr: Writer, fa: ForceAnalysis, j: int, g: GroupForces, own: set[str]) -> None:
    """RPR: the reaction normal to the slot from ΣM of link L2 about its pivot
    (the shaper's ΣM_C(3) = 0): the outer reaction there has no arm."""
    a, w, u = wr.solution, wr.w, wr.u
    r, outer = g.reactions[2], g.reactions[1]
    if r.couple or not r.components or r.magnitude == 0:
        return
    comp = r.components[0]
    lid, C = outer.on, outer.pair
    fp = fa.index if fa.index is not None else a.force_position
    P = np.asarray(outer.point)
    P_src = src.point(a, fp, C, "points")
    name = force_markup(r.name)
    wr.text(w["slot_eq"].format(R=name, C=C, lid=lid, n=force_markup(outer.name)))
    terms = _terms(wr, fa, g.free_bodies[lid], own, f"F.groups[{j}].free_bodies[{lid}]")
    total, parts = _moment_terms(wr, fa, terms, P, P_src, C, wr.drawn.group(g.name))
    D = f"J['forces']['reaction_details'][{r.name!r}]"
    N_src = f"{D}['components'][{comp.label!r}]"
    rp = np.asarray(r.point) - P
    h = float(rp[0] * comp.direction[1] - rp[1] * comp.direction[0])
    H = f"moment(({D}['point'], J['forces']['reactions'][{r.name!r}], 0), {P_src})/{N_src}"
    mu_l, ML = wr.drawn.group(g.name)
    hn = f"h_{{{len(parts) + 1}}}"
    wr.eq(
        f"{hn} = {wr.v(h / mu_l, f'({H})/{ML}')} {u['mm']}·μ_l = {wr.v(h, H)} {u['m']} "
        + w["slot_arm"].format(R=name)
    )
    sum_src = "+".join(f"moment({t[4]}, {P_src})" for t in terms) or "0"
    lhs = " + ".join(parts + [f"{name}·{hn}"])
    wr.eq(f"ΣM_{sub(C)}({lid}) = {lhs} = 0;")
    wr.eq(
        f"{name} = -ΣM_{sub(C)}/{hn} = {wr.neg(total, sum_src)}/{wr.vp(h, H)} = "
        f"{wr.v(comp.value, N_src)} {u['N']}" + (" " + w["reverse"] if comp.value < 0 else "")
    )


def _guide_reactions(wr: Writer, j: int, g: GroupForces) -> None:
    """PRP, RPP: the two reactions normal to their guides from the polygon
    they close (the group's for PRP, the outer slider's for RPP), each from
    ΣF projected on the other's guide, where the other drops out."""
    w, u = wr.w, wr.u
    by_name = {r.name: k for k, r in enumerate(g.reactions)}
    for p_ix, poly in enumerate(g.polygons):
        unknown = [v.label for v in poly.vectors if not v.known]
        if len(unknown) == 2 and all(
            lb in by_name and g.reactions[by_name[lb]].kind == "P" for lb in unknown
        ):
            break
    else:
        return
    base = f"F.groups[{j}].polygons[{p_ix}]"
    known = [(m, v) for m, v in enumerate(poly.vectors) if v.known and v.magnitude > 0]
    names = [force_markup(lb) for lb in unknown]
    wr.text(w["guide_eq"].format(Ra=names[0], Rb=names[1], title=_title(wr, poly)))
    for a_ix, b_ix in ((0, 1), (1, 0)):
        ra, rb = g.reactions[by_name[unknown[a_ix]]], g.reactions[by_name[unknown[b_ix]]]
        Ra = names[a_ix]
        NB = f"F.groups[{j}].reactions[{by_name[rb.name]}].components[0].direction"
        NA = f"F.groups[{j}].reactions[{by_name[ra.name]}].components[0].direction"
        nb = np.asarray(rb.components[0].direction, dtype=float)
        t = np.array([nb[1], -nb[0]])  # the guide of rb: its normal turned by -90°

        def along(V: str) -> str:
            return f"({V}[0]*{NB}[1] - {V}[1]*{NB}[0])"

        wr.text(w["guide_axis"].format(Rb=names[b_ix], Ra=Ra))
        total, parts, src_sum = 0.0, list[str](), list[str]()
        for m, v in known:
            V = f"{base}.vectors[{m}].vector"
            F = float(np.hypot(*v.vector))
            proj = float(np.dot(v.vector, t))
            total += proj
            src_sum.append(along(V))
            name = force_markup(v.label)
            wr.eq(
                f"{name}·cos({name}, t) = {wr.v(F, f'hyp({V})')}·"
                f"{wr.vp(proj / F, f'{along(V)}/hyp({V})')} = {wr.v(proj, along(V))} {u['N']}"
            )
            parts.append(f"{name}·cos({name}, t)")
        c = float(np.dot(ra.components[0].direction, t))
        C = along(NA)
        N = ra.components[0]
        NS = f"J['forces']['reaction_details'][{ra.name!r}]['components'][{N.label!r}]"
        lhs = " + ".join([f"{Ra}·cos({Ra}, t)", *parts])
        wr.eq(f"ΣF_t = {lhs} = 0, cos({Ra}, t) = {wr.v(c, C)};")
        wr.eq(
            f"{Ra} = -ΣF_t/cos({Ra}, t) = {wr.neg(total, '+'.join(src_sum) or '0')}/"
            f"{wr.vp(c, C)} = {wr.v(N.value, NS)} {u['N']}"
            + (" " + w["reverse"] if N.value < 0 else "")
        )


def _guide_points(wr: Writer, fa: ForceAnalysis, j: int, g: GroupForces, own: set[str]) -> None:
    """Where each reaction normal to a guide acts (a prismatic pair's), from
    ΣM of its link about a revolute pair of the group that the link's other
    unknown reactions pass through: ΣM_P = ΣM_P(loads) + R·h = 0. An inner
    prismatic pair's from its first link about the outer pin A; an outer
    one's about the inner pin B (RRP, PRP), or A (RPP: its inner reaction
    known by then)."""
    w, u, a = wr.w, wr.u, wr.solution
    fp = fa.index if fa.index is not None else a.force_position
    scale = wr.drawn.group(g.name)
    mu_l, ML = scale
    # RPP: the inner reaction is placed from the first link, then known on the second
    order = sorted(
        (r for r in g.reactions if r.kind == "P" and not r.couple and r.magnitude > 0),
        key=lambda r: r.by not in g.links,
    )
    known: set[str] = set()
    for r in order:
        inner = r.by in g.links
        pin = g.reactions[0] if inner or g.reactions[2].kind != "R" else g.reactions[2]
        P = np.asarray(pin.point, dtype=float)
        P_name = pin.pair
        P_src = src.point(a, fp, P_name, "points")
        comp = r.components[0]
        lid, name, value = r.on, force_markup(r.name), comp.value
        D = f"J['forces']['reaction_details'][{r.name!r}]"
        N_src = f"{D}['components'][{comp.label!r}]"
        # the arm of the reaction about P: the same for it and for its opposite
        H = f"moment(({D}['point'], J['forces']['reactions'][{r.name!r}], 0), {P_src})/{N_src}"
        if inner:
            # the inner reaction from the link it acts back on (the outer one there passes P)
            lid, name, value, N_src = r.by, force_markup(r.reversed().name), -value, f"-{N_src}"
        wr.text(w["guide_point"].format(R=name, P=P_name, lid=lid))
        skip = (own - known) | {r.name, r.reversed().name}
        base = f"F.groups[{j}].free_bodies[{lid}]"
        terms = _terms(wr, fa, g.free_bodies[lid], skip, base)
        terms = [t for t in terms if np.hypot(*(np.asarray(t[2]) - P)) > 1e-12 or t[3]]
        total, parts = _moment_terms(wr, fa, terms, P, P_src, P_name, scale)
        n = np.asarray(comp.direction, dtype=float)
        rp = np.asarray(r.point, dtype=float) - P
        h = float(rp[0] * n[1] - rp[1] * n[0])
        hn = f"h_{{{len(parts) + 1}}}"
        sum_src = "+".join(f"moment({t[4]}, {P_src})" for t in terms) or "0"
        known |= {r.name, r.reversed().name}
        if not parts:  # every other force on the link passes through P, and so does R
            wr.eq(f"ΣM_{sub(P_name)}({lid}) = {name}·{hn} = 0; {hn} = {wr.v(h, H)} {u['m']}")
            continue
        lhs = " + ".join(parts + [f"{name}·{hn}"])
        wr.eq(f"ΣM_{sub(P_name)}({lid}) = {lhs} = 0;")
        wr.eq(
            f"{hn} = -ΣM_{sub(P_name)}/{name} = {wr.neg(total, sum_src)}/{wr.vp(value, N_src)} = "
            f"{wr.v(h, H)} {u['m']}; {hn}/μ_l = {wr.vp(h, H)}/{wr.v(mu_l, ML)} = "
            f"{wr.v(h / mu_l, f'({H})/{ML}')} {u['mm']}"
        )


def _guide_couples(wr: Writer, fa: ForceAnalysis, j: int, g: GroupForces) -> None:
    """A prismatic pair whose normal force is zero (a crosshead on its guide
    loaded along it) still holds its link against turning: its reaction is a
    couple M, from ΣM of the link about the slider's point Q, where the
    reaction is placed: ΣM_Q(loads) + M = 0."""
    w, u = wr.w, wr.u
    scale = wr.drawn.group(g.name)
    for r in g.reactions:
        if r.kind != "P" or not r.couple:
            continue
        D = f"J['forces']['reaction_details'][{r.name!r}]"
        C = D + "['couple']"
        P = np.asarray(r.point, dtype=float)
        P_src = f"{D}['point']"
        Q = next((p.slider_point for p in wr.mech.sliders if p.name == r.pair), r.pair)
        lid = r.on
        name = force_markup(r.name)
        M = f"M_{{{r.name[1:]}}}"
        base = f"F.groups[{j}].free_bodies[{lid}]"
        terms = _terms(wr, fa, g.free_bodies[lid], {r.name, r.reversed().name}, base)
        wr.text(w["guide_couple"].format(R=name, M=M, lid=lid, Q=Q))
        total, parts = _moment_terms(wr, fa, terms, P, P_src, Q, scale)
        sum_src = "+".join(f"moment({t[4]}, {P_src})" for t in terms) or "0"
        lhs = " + ".join(parts + [M])
        wr.eq(f"ΣM_{sub(Q)}({lid}) = {lhs} = 0;")
        wr.eq(
            f"{M} = -ΣM_{sub(Q)} = {wr.neg(total, sum_src)} = "
            f"{wr.v(r.couple, C)} {u['Nm']}" + _sense(wr, r.couple)
        )


def _polygon(
    wr: Writer,
    poly: ForcePolygon,
    base: str,
    first: bool,
    scale: tuple[float, str],
    head: str | None = None,
) -> None:
    """The vector equation (the polygon's order) and every side as F/μ_F = mm,
    μ_F (`scale`, with its source) the one sheet 2 draws the polygon at."""
    w, u = wr.w, wr.u
    wr.text(head or w["link_eq"].format(title=_title(wr, poly)))
    number = wr.eq(equation_markup(poly.equation))
    unknown = [force_markup(v.label) for v in poly.vectors if not v.known]
    if unknown:
        wr.text(w["unknown"].format(names=", ".join(unknown), eq=number))
    if not first:
        return
    mu, MU = scale
    wr.text(w["mu_F"])
    # seed 003 (20): μ_F from the largest force known before the plan is drawn (F_PR)
    known = [(v.magnitude, m, v) for m, v in enumerate(poly.vectors) if v.known and v.magnitude]
    if known:
        big, m, v = max(known, key=lambda t: t[0])
        VS = f"hyp({base}.vectors[{m}].vector)"
        name = force_markup(v.label)
        wr.eq(
            f"μ_F = {name}/|{name}| = {wr.v(big, VS)}/"
            f"{wr.v(big / mu, f'{VS}/{MU}')} = {wr.v(mu, MU)} {u['N/mm']}"
        )
    else:
        wr.eq(f"μ_F = {wr.v(mu, MU)} {u['N/mm']}")
    wr.text(w["sides"])
    for m, v in enumerate(poly.vectors):
        if not v.known or v.magnitude == 0:
            continue
        VS = f"hyp({base}.vectors[{m}].vector)"
        name = force_markup(v.label)
        wr.eq(
            f"|{name}| = {name}/μ_F = {wr.v(v.magnitude, VS)}/{wr.v(mu, MU)} = "
            f"{wr.v(v.magnitude / mu, f'{VS}/{MU}')} {u['mm']}"
        )


def _title(wr: Writer, poly: ForcePolygon) -> str:
    """The solver's "link 4" / "group 4-5" in the note's language."""
    kind, _, name = poly.title.partition(" ")
    return wr.w["of_link" if kind == "link" else "of_group"].format(name=name)


def _reaction_line(wr: Writer, r, mu_f: float, mu_src: str) -> None:
    u = wr.u
    name = force_markup(r.name)
    RS = f"hyp(J['forces']['reactions'][{r.name!r}])"
    comps = list(r.components)
    if len(comps) == 2:
        c1, c2 = comps
        C = f"J['forces']['reaction_details'][{r.name!r}]['components']"
        # the drafting font has no √: the root is written as a power 1/2
        wr.eq(
            f"{name} = (({force_markup(c1.label)})^2 + ({force_markup(c2.label)})^2)^{{1/2}} = "
            f"({wr.vp(c1.value, f'{C}[{c1.label!r}]')}^2 + {wr.vp(c2.value, f'{C}[{c2.label!r}]')}^2)"
            f"^{{1/2}} = {wr.v(r.magnitude, RS)} {u['N']}"
        )
    wr.eq(
        f"{name} = |{name}|·μ_F = {wr.v(r.magnitude / mu_f, f'{RS}/{mu_src}')}·"
        f"{wr.v(mu_f, mu_src)} = {wr.v(r.magnitude, RS)} {u['N']}"
    )


# --- the driving link -------------------------------------------------------------------------
def driving_link(wr: Writer, fa: ForceAnalysis, step: str) -> None:
    w, u, a = wr.w, wr.u, wr.solution
    mech = wr.mech
    _step(wr, step, w["driver"])
    dl = fa.driving_link
    O = dl.pivot
    OA_ = f"{O}{dl.pin}"
    fp = fa.index if fa.index is not None else a.force_position
    P = np.asarray(next(f.point for f in dl.free_body if f.label == dl.reaction.name))
    P_src = src.point(a, fp, O, "points")
    passed = [
        force_markup(f.label)
        for f in dl.free_body
        if f.label.startswith("R") and f.label != dl.reaction.name
    ]
    wr.text(w["driver_loads"].format(d=dl.link, A=dl.pin, O=O, R=", ".join(passed)))
    skip = {"F_bal", dl.reaction.name}
    terms = _terms(wr, fa, dl.free_body, skip, "F.driving_link.free_body")
    total, parts = _moment_terms(wr, fa, terms, P, P_src, O, wr.drawn.driving())
    sum_src = "+".join(f"moment({t[4]}, {P_src})" for t in terms) or "0"
    s = 1.0 if mech.drive.sense == "ccw" else -1.0
    OA = mech.crank_length
    lhs = " + ".join(parts) if parts else "0"
    sign = "+" if s > 0 else "-"
    wr.text(w["F_bal_pl"])
    wr.eq(f"ΣM_{sub(O)}({dl.link}) = {lhs} {sign} F_{{bal.pl}}·l_{{{OA_}}} = 0;")
    minus = "-" if s > 0 else ""
    FB = "J['forces']['balancing_force_plans']"
    MB = "J['forces']['balancing_moment']"
    wr.eq(
        f"F_{{bal.pl}} = {minus}ΣM_{sub(O)}/l_{{{OA_}}} = {wr.neg(total, sum_src) if minus else wr.vp(total, sum_src)}/"
        f"{wr.v(OA, 'M.crank_length')} = {wr.v(dl.balancing_force, FB)} {u['N']} "
        f"({w['drives'] if dl.balancing_force >= 0 else w['brakes']});"
    )
    wr.eq(
        f"M_{{bal}} = F_{{bal.pl}}·l_{{{OA_}}} = {wr.vp(dl.balancing_force, FB)}·"
        f"{wr.v(OA, 'M.crank_length')} = "
        f"{wr.v(dl.balancing_moment, MB)} {u['Nm']}"
    )
    head = w["link_eq"].format(title=_title(wr, dl.polygon))
    mu_f = wr.drawn.force(f"link {dl.link}", (dl.polygon,), "(F.driving_link.polygon,)")
    _polygon(wr, dl.polygon, "F.driving_link.polygon", True, mu_f, head)
    wr.text(w["R01"].format(O=O, d=dl.link))
    _reaction_line(wr, dl.reaction, *mu_f)
    drawings = [(2, ("driving-link",)), (2, (f"force-polygon-{dl.link}",))]
    if wr.has_figure(drawings):
        mu_l, ML = wr.drawn.driving()
        n_fig = wr.next_figure
        wr.text(w["driving_drawn"].format(mu=wr.v(mu_l, ML), mf=wr.v(*mu_f)) + wr.cite(n_fig) + ".")
        wr.figure(drawings, w["fig_driving"].format(d=dl.link, mu=wr.v(mu_l, ML), mf=wr.v(*mu_f)))


def reactions(wr: Writer, fa: ForceAnalysis, step: str) -> None:
    w = wr.w
    _step(wr, step, w["reactions"])
    rows: list[tuple[str, ...]] = [tuple(w["react_head"])]
    for name, r in fa.reactions.items():
        R = f"J['forces']['reactions'][{name!r}]"
        rows.append(
            (
                force_markup(r.name),
                r.pair,
                wr.v(r.force[0], f"{R}[0]"),
                wr.v(r.force[1], f"{R}[1]"),
                wr.v(r.magnitude, f"hyp({R})"),
            )
        )
    wr.add("table", w["tab_reactions"], rows=rows, widths=(24, 22, 32, 32, 32))


# --- Zhukovsky's lever --------------------------------------------------------------------------
def lever(wr: Writer, fa: ForceAnalysis, step: str) -> None:
    w, u = wr.w, wr.u
    lv = fa.lever
    mu_v, MV = wr.drawn.lever(lv.pa)
    _step(wr, step, w["lever"])
    s = 1.0 if wr.mech.drive.sense == "ccw" else -1.0
    wr.text(w["lever_text"].format(turn=w["against"], ref=cite("dovbush2018", "kinytskyi2002")))
    pa = lv.pa / mu_v
    wr.eq(
        f"pa = V_A/μ_V = {wr.v(lv.pa, 'F.lever.pa')}/{wr.v(mu_v, MV)} = "
        f"{wr.v(pa, f'F.lever.pa/{MV}')} {u['mm']}"
    )
    rows: list[tuple[str, ...]] = [tuple(w["lever_head"])]
    total = 0.0
    for m, f in enumerate(lv.forces):
        F = float(np.hypot(*f.force))
        LF = f"F.lever.forces[{m}]"
        total += f.moment / mu_v
        rows.append(
            (
                force_markup(f.label),
                image_markup(f.point, wr.mech.point_owners),
                wr.v(F, f"hyp({LF}.force)"),
                wr.v(f.arm / mu_v, f"lever_arm({LF})/{MV}"),
                wr.v(f.moment / mu_v, f"lever_moment({LF})/{MV}"),
            )
        )
    wr.add("table", w["tab_lever"], rows=rows, widths=(24, 16, 30, 30, 36))
    drawings = [(2, ("zhukovsky-lever",))]
    # the lever's detail views (sheet 2 draws one where its names crowd round p)
    details = [(2, (g,)) for g in wr.drawings_named(2, "zhukovsky-lever-detail")]
    if wr.has_figure(drawings):
        n_fig = wr.next_figure
        drawn = w["lever_drawn"].format(mv=wr.v(mu_v, MV)) + wr.cite(n_fig) + "."
        wr.text(drawn + (" " + w["lever_details_drawn"] if details else ""))
        caption = w["fig_lever"].format(mv=wr.v(mu_v, MV))
        if details:
            parts = ", ".join(str(w["part_letters"])[1 : 1 + len(details)])
            caption += w["fig_lever_parts"].format(parts=parts)
        wr.figure(drawings + details, caption)
    TOT = f"sum(lever_moment(f) for f in F.lever.forces)/{MV}"
    wr.text(w["F_bal_z"])
    sign = "+" if s > 0 else "-"
    wr.eq(f"ΣM_p = ΣF_i·h_i {sign} F_{{bal.z}}·pa = 0;")
    minus = "-" if s > 0 else ""
    FZ = "J['forces']['balancing_force_lever']"
    wr.eq(
        f"F_{{bal.z}} = {minus}ΣF_i·h_i/pa = {wr.neg(total, TOT) if minus else wr.vp(total, TOT)}/"
        f"{wr.v(pa, f'F.lever.pa/{MV}')} = {wr.v(lv.balancing_force, FZ)} {u['N']} "
        f"({w['drives'] if lv.balancing_force >= 0 else w['brakes']})"
    )


def match(wr: Writer, fa: ForceAnalysis, step: str) -> None:
    w = wr.w
    _step(wr, step, w["match"])
    wr.text(w["discrepancy"])
    d = fa.discrepancy_percent
    z, pl = fa.balancing_force_lever, fa.balancing_force_plans
    FZ, FP = "J['forces']['balancing_force_lever']", "J['forces']['balancing_force_plans']"
    D = "J['forces']['discrepancy_percent']"
    if not math.isfinite(d):
        wr.text(w["no_discrepancy"])
        return
    wr.eq(
        f"Δ_F = |F_{{bal.z}} - F_{{bal.pl}}|/|F_{{bal.z}}|·100 % = |{wr.v(z, FZ, 6)} - "
        f"{wr.vp(pl, FP, 6)}|/{wr.v(abs(z), f'abs({FZ})', 6)}·100 % = {wr.v(d, D, 3)} % "
        + (w["within"] if d <= 5.0 else w["beyond"])
    )
