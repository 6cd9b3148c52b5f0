"""Readable text tables of an analysis (what `mmt-plans analyze` prints)."""

from __future__ import annotations

import math

import numpy as np

from .errors import degrees_range
from .forces import ForceAnalysis
from .results_json import diagrams_json
from .solution import Solution


def table(headers: list[str], rows: list[list[str]]) -> str:
    widths = [
        max(len(h), *(len(r[i]) for r in rows)) if rows else len(h) for i, h in enumerate(headers)
    ]
    line = "  ".join(h.rjust(w) for h, w in zip(headers, widths))
    out = [line, "  ".join("-" * w for w in widths)]
    out += ["  ".join(c.rjust(w) for c, w in zip(r, widths)) for r in rows]
    return "\n".join(out)


def num(x: float, digits: int = 6) -> str:
    return f"{x:.{digits}g}"


def text_report(analysis: Solution) -> str:
    mech = analysis.mechanism
    st = analysis.structure
    out = [
        f"{mech.title}",
        "=" * len(mech.title),
        "",
        "Structural analysis",
        f"  n = {st.n}, p5 = {st.p5}, p4 = {st.p4}, "
        f"W = 3n - 2p5 - p4 = 3*{st.n} - 2*{st.p5} - {st.p4} = {st.W}",
    ]
    for g in st.groups:
        pairs = ", ".join(p.name for p in g.pairs)
        out.append(
            f"  group {g.label}: links {g.name}, class {g.group_class}, order {g.order}, "
            f"kind {g.kind or '-'}, pairs {pairs}"
        )
    out += [f"  mechanism class {st.mechanism_class}", f"  structural formula: {st.formula}", ""]
    d = mech.drive
    out.append(
        f"Drive: link {d.link}, omega1 = {d.signed_omega:.6g} rad/s "
        f"({d.n1_rpm:.6g} rpm, {d.sense})"
        + (f", gear ratio u = {d.gear_train.ratio:.6g}" if d.gear_train else "")
    )
    out += gears_report(analysis)
    out.append(f"Assembly: {analysis.branches.note}")
    if analysis.limits is not None:
        spans = ", ".join(degrees_range(a, b) for a, b in analysis.assembly_ranges)
        first, last = analysis.limits
        out.append(
            f"The crank does not make a whole turn: the mechanism assembles for phi1 in "
            f"{spans} (counter-clockwise); analysed (partial_turn): "
            f"{degrees_range(first, last)} in the drive's sense, whose ends are limits "
            "of assembly, not extreme positions"
        )
    if analysis.extremes is not None:
        lo, hi = analysis.extremes
        out.append(
            f"Extreme positions of {mech.study.output}: phi1 = {lo:.9g} deg (start of the "
            f"working stroke) and {hi:.9g} deg; working stroke "
            f"{analysis.working_span_deg:.6g} deg of crank turn"
        )
    else:
        out.append(f"Output {mech.study.output} has no extreme position in the range analysed")
    out.append(
        f"Plans at positions {list(analysis.plan_positions)}, forces at {analysis.force_position}"
    )
    out.append("")
    sw = analysis.sweep
    names = [n for n in analysis.chain.locate]
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
            rows.append(
                [
                    n,
                    num(p[0] * 1e3, 7),
                    num(p[1] * 1e3, 7),
                    num(v[0]),
                    num(v[1]),
                    num(float(np.hypot(*v))),
                    num(a[0]),
                    num(a[1]),
                    num(float(np.hypot(*a))),
                ]
            )
        out.append(
            _indent(
                table(
                    [
                        "point",
                        "x mm",
                        "y mm",
                        "Vx m/s",
                        "Vy m/s",
                        "V m/s",
                        "ax m/s2",
                        "ay m/s2",
                        "a m/s2",
                    ],
                    rows,
                )
            )
        )
        rows = [
            [str(lid), num(float(sw.omega[lid][k])), num(float(sw.eps[lid][k]))]
            for lid in mech.links
        ]
        out.append(_indent(table(["link", "omega rad/s", "eps rad/s2"], rows)))
        out.append("")
    out += diagrams_report(analysis)
    out.append(_forces(analysis))
    out += reduction_report(analysis)
    return "\n".join(out)


def gears_report(analysis: Solution) -> list[str]:
    """The gear train (seed 002 task 1): each stage's ratio, Willis' formula
    for a planetary stage (u^H first, then u), the total ratio, the crank's speed."""
    train = analysis.mechanism.drive.gear_train
    if train is None:
        return []
    out = [f"Gear train: motor {train.motor_rpm:.6g} rpm, {len(train.stages)} stage(s)"]
    out += [f"  {step.title}: {step}" for step in train.steps("en")]
    out.append(f"  crank: n1 = {abs(train.crank_rpm):.6g} rpm")
    return out


def reduction_report(analysis: Solution) -> list[str]:
    """Reduction to the crank (seed 002 tasks 5 and 6) at every position:
    M_red·ω1 = Σ F·V·cos(F, V), J_red·ω1² = Σ (m·V_S² + J_S·ω²)."""
    red = analysis.reduction
    rows = []
    for k, pos in enumerate(analysis.positions):
        if analysis.problem(k) is not None:
            continue
        label = str(pos.index) if pos.index is not None else "*"
        rows.append(
            [
                label,
                f"{pos.phi1_deg:.6f}",
                pos.stroke,
                _n(red.reduced_moment[k]),
                _n(red.reduced_inertia[k]),
            ]
        )
    out = [
        "",
        "Reduction to the crank (equal powers: M_red*omega1 = sum F*V*cos; "
        "equal kinetic energies: J_red*omega1^2 = sum m*V_S^2 + J_S*omega^2)",
        _indent(table(["pos", "phi1 deg", "stroke", "M_red N*m", "J_red kg*m2"], rows)),
    ]
    return out


def diagrams_report(analysis: Solution) -> list[str]:
    d = diagrams_json(analysis)
    out = [f"Kinematic diagrams of {d['output']} (graphical differentiation) against the plans"]
    if "problem" in d:
        return out + [f"  ! {d['problem']}", ""]
    sc = d["scales"]
    out.append(
        f"  mu_S = {sc['mu_S']:.6g} m/mm, mu_t = {sc['mu_t']:.6g} s/mm, H1 = {sc['H1_mm']:g} mm, "
        f"mu_V = {sc['mu_V']:.6g} (m/s)/mm, H2 = {sc['H2_mm']:g} mm, "
        f"mu_a = {sc['mu_a']:.6g} (m/s2)/mm"
    )
    plans = set(analysis.plan_positions)
    rows = []
    for i in range(len(d["s"])):
        ev, ea = d["error_percent"]["v"][i], d["error_percent"]["a"][i]
        rows.append(
            [
                f"{i}{'*' if i in plans else ''}",
                num(d["s"][i] * 1e3),
                num(d["v_plan"][i]),
                num(d["v_diagram"][i]),
                "-" if ev is None else f"{ev:.2f}",
                num(d["a_plan"][i]),
                num(d["a_diagram"][i]),
                "-" if ea is None else f"{ea:.2f}",
            ]
        )
    out.append(
        _indent(
            table(
                ["pos", "s mm", "V plan", "V diagram", "dV %", "a plan", "a diagram", "da %"], rows
            )
        )
    )
    out.append(
        f"  (* planned positions) diagrams drawn over {d['grid_intervals']} divisions "
        f"of the turn; 5 % check at the investigated positions: "
        f"{'passed' if d['passed'] else 'NOT passed'}"
    )
    tried = ", ".join(
        f"{g['intervals']} {'passed' if g['passed'] else 'not passed'}" for g in d["grids_tried"]
    )
    out.append(f"  grids tried by (12)/(13): {tried}")
    for v in d["investigated"]:
        q = "V" if v["quantity"] == "v" else "a"
        if v["ill_conditioned"]:
            out.append(
                f"  position {v['index']}, {q}: {v['plan_share_percent']:.2g} % of its largest "
                f"value, passed by (12)/(13) on no grid of the series (ill-conditioned): "
                f"absolute error {v['absolute_error']:.3g}"
            )
        elif not v["passed"]:
            out.append(f"  ! position {v['index']}, {q}: {v['error_percent']:.2f} %")
    out.append("")
    return out


def _forces(analysis: Solution) -> str:
    """The force analysis at the force position."""
    if analysis.forces is None:
        return f"Force analysis at position {analysis.force_position}: ! {analysis.forces_problem}"
    return force_text(analysis.forces)


def force_text(fa: ForceAnalysis) -> str:
    """Readable tables: loads, reactions per pair, the balancing force by both
    methods and the discrepancy (what `mmt-plans analyze` prints)."""
    head = f"Force analysis at position {fa.index}" if fa.index is not None else "Force analysis"
    out = [f"{head}: phi1 = {fa.phi1_deg:.6f} deg, {fa.stroke} stroke"]
    rows = []
    for lid, ll in fa.loads.links.items():
        F = ll.inertia_force
        sh = ll.shifted_inertia_force
        rows.append(
            [
                str(lid),
                _n(ll.mass),
                _n(ll.J),
                _n(-ll.weight[1]),
                _n(F[0]),
                _n(F[1]),
                _n(math.hypot(*F)),
                _n(ll.inertia_moment),
                "-" if sh is None else _n(sh.arm * 1e3),
                "-" if sh is None or sh.arm_mm is None else _n(sh.arm_mm),
            ]
        )
    out.append(
        _indent(
            table(
                [
                    "link",
                    "m kg",
                    "J kg*m2",
                    "G N",
                    "F_in x N",
                    "F_in y N",
                    "|F_in| N",
                    "M_in N*m",
                    "h mm",
                    "h drawn mm",
                ],
                rows,
            )
        )
    )
    if fa.loads.production_resistance:
        rows = [
            [
                f.name,
                str(f.link),
                f.at,
                _n(f.force[0]),
                _n(f.force[1]),
                _n(math.hypot(*f.force)),
                "yes" if f.acting else "no (idle stroke)",
            ]
            for f in fa.loads.production_resistance
        ]
        out.append(_indent(table(["force", "link", "at", "Fx N", "Fy N", "|F| N", "acts"], rows)))
    for g in fa.groups:
        out.append(f"  group {g.name} ({g.kind}):")
        out += [f"    {s}" for s in g.steps]
    out.append(f"  driving link {fa.driving_link.link}:")
    out += [f"    {s}" for s in fa.driving_link.steps]
    rows = []
    for name, r in fa.reactions.items():
        rows.append(
            [
                name,
                r.pair,
                _n(r.force[0]),
                _n(r.force[1]),
                _n(r.magnitude),
                _n(r.point[0] * 1e3),
                _n(r.point[1] * 1e3),
                _n(r.couple) if r.couple else "-",
            ]
        )
    out.append(
        _indent(
            table(
                ["reaction", "pair", "Rx N", "Ry N", "|R| N", "at x mm", "at y mm", "couple N*m"],
                rows,
            )
        )
    )
    d = fa.discrepancy_percent
    out.append(
        f"  balancing force: plans F_bal = {fa.balancing_force_plans:.6g} N, "
        f"Zhukovsky's lever F_bal = {fa.balancing_force_lever:.6g} N, "
        f"discrepancy = {'-' if math.isnan(d) else f'{d:.3g}'} % "
        f"({'driving' if fa.balancing_force_plans >= 0 else 'braking'})"
    )
    out.append(f"  balancing moment M_bal = {fa.balancing_moment:.6g} N*m")
    return "\n".join(out)


def _n(x: float, digits: int = 6) -> str:
    return f"{float(x) + 0.0:.{digits}g}"  # + 0.0: no "-0"


def _indent(text: str) -> str:
    return "\n".join("  " + line for line in text.splitlines())
