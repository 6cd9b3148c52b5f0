"""Readable text tables of an analysis (what `mmt-plans analyze` prints)."""

from __future__ import annotations

import numpy as np

from .analysis import Analysis


def table(headers: list[str], rows: list[list[str]]) -> str:
    widths = [max(len(h), *(len(r[i]) for r in rows)) if rows else len(h)
              for i, h in enumerate(headers)]
    line = "  ".join(h.rjust(w) for h, w in zip(headers, widths))
    out = [line, "  ".join("-" * w for w in widths)]
    out += ["  ".join(c.rjust(w) for c, w in zip(r, widths)) for r in rows]
    return "\n".join(out)


def num(x: float, digits: int = 6) -> str:
    return f"{x:.{digits}g}"


def text_report(analysis: Analysis) -> str:
    mech = analysis.mech
    st = analysis.structure
    out = [f"{mech.title}", "=" * len(mech.title), "",
           "Structural analysis",
           f"  n = {st.n}, p5 = {st.p5}, p4 = {st.p4}, "
           f"W = 3n - 2p5 - p4 = 3*{st.n} - 2*{st.p5} - {st.p4} = {st.W}"]
    for g in st.groups:
        pairs = ", ".join(p.name for p in g.pairs)
        out.append(f"  group {g.label}: links {g.name}, class {g.group_class}, order {g.order}, "
                   f"kind {g.kind or '-'}, pairs {pairs}")
    out += [f"  mechanism class {st.mechanism_class}", f"  structural formula: {st.formula}", ""]
    d = mech.drive
    out.append(f"Drive: link {d.link}, omega1 = {d.signed_omega:.6g} rad/s "
               f"({d.n1_rpm:.6g} rpm, {d.sense})"
               + (f", gear ratio u = {d.gear_train.ratio:.6g}" if d.gear_train else ""))
    out.append(f"Assembly: {mech.chain.branch_note or 'one configuration'}")
    lo, hi = analysis.extremes
    out.append(f"Working stroke: phi1 = {lo:.9g} deg -> {hi:.9g} deg "
               f"({analysis.working_span_deg:.6g} deg of crank turn); "
               f"plans at positions {list(analysis.plan_positions)}, "
               f"forces at {analysis.force_position}")
    out.append("")
    sw = analysis.sweep
    names = [n for n in mech.chain.locate]
    for k, pos in enumerate(analysis.positions):
        label = f"Position {pos.index}" if pos.index is not None else "Extra angle"
        out.append(f"{label}: phi1 = {pos.phi1_deg:.6f} deg, {pos.stroke} stroke")
        problem = analysis.problem(k)
        if problem is not None:
            out.append(f"  ! {problem}")
            if type(problem).__name__ == "AssemblyError":
                out.append("")
                continue
        rows = []
        for n in names:
            p, v, a = sw.points[n][k], sw.v[n][k], sw.a[n][k]
            rows.append([n, num(p[0] * 1e3, 7), num(p[1] * 1e3, 7), num(v[0]), num(v[1]),
                         num(float(np.hypot(*v))), num(a[0]), num(a[1]), num(float(np.hypot(*a)))])
        out.append(_indent(table(["point", "x mm", "y mm", "Vx m/s", "Vy m/s", "V m/s",
                                  "ax m/s2", "ay m/s2", "a m/s2"], rows)))
        rows = [[str(lid), num(float(sw.omega[lid][k])), num(float(sw.eps[lid][k]))]
                for lid in mech.links]
        out.append(_indent(table(["link", "omega rad/s", "eps rad/s2"], rows)))
        out.append("")
    return "\n".join(out)


def _indent(text: str) -> str:
    return "\n".join("  " + line for line in text.splitlines())
