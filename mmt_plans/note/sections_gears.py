"""The gear train (seed 002 task 1: each stage's ratio, Willis' formula for a
planetary stage, the total ratio, the crank's speed), the reduction to the
crank (tasks 5 and 6: the reduced moment and moment of inertia) and the
conclusions, with their numbers."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np

from ..gears import GearPair, PlanetaryStage
from . import sources as src
from .literature import cite
from .sections_forces import force_markup
from .writer import Writer

if TYPE_CHECKING:  # pragma: no cover
    from ..gears import GearTrain

__all__ = ["gear_train", "reduction", "conclusions"]

GT = "M.drive.gear_train"


def _u(a: str, b: str) -> str:
    return a + b if max(len(a.rstrip("'")), len(b.rstrip("'"))) == 1 else f"{a},{b}"


def _scheme(wr: Writer) -> None:
    """Seed 002 Fig. 1: the train's kinematic scheme, the gears named z_n."""
    from .figures import gear_sketch, sketches_height
    from .writer import FIGURE_WIDTH

    sketch = gear_sketch(wr.solution)
    if sketch is None:
        return
    wr.text(wr.w["gears_scheme"] + wr.cite(wr.next_figure) + ".")
    wr.drawing("gears", sketches_height([sketch], FIGURE_WIDTH, False), wr.w["fig_gears"])


def gear_train(wr: Writer) -> None:
    train: GearTrain | None = wr.mech.drive.gear_train
    if train is None:
        return
    w, u = wr.w, wr.u
    wr.add("section", w["gears_title"], "gears")
    labels = train.gear_labels
    teeth: list[str] = []
    for si, (stage, gears) in enumerate(zip(train.stages, labels)):
        meshes = stage.meshes if isinstance(stage, PlanetaryStage) else (stage,)
        base = f"{GT}.stages[{si}]" + (".meshes" if isinstance(stage, PlanetaryStage) else "")
        for mi, mesh in enumerate(meshes):
            m_src = f"{base}[{mi}]" if isinstance(stage, PlanetaryStage) else base
            for side in (0, 1):
                name = gears[2 * mi + side]
                entry = f"z_{{{name}}} = {wr.i(mesh.z[side], f'{m_src}.z[{side}]')}"
                if entry.split(" = ")[0] not in {t.split(" = ")[0] for t in teeth}:
                    teeth.append(entry)
    wr.text(w["gears_data"].format(n=wr.v(train.motor_rpm, f"{GT}.motor_rpm")))
    wr.eq("; ".join(teeth))
    _scheme(wr)
    wr.text(w["gears_split"])
    names: list[str] = []
    values: list[tuple[float, str]] = []
    for si, (stage, gears) in enumerate(zip(train.stages, labels)):
        S = f"{GT}.stages[{si}]"
        if isinstance(stage, GearPair):
            a, b = gears
            sign = "-" if stage.mesh == "external" else ""
            name = f"u_{{{_u(a, b)}}}"
            wr.text(w["gears_pair"].format(a=a, b=b, mesh=w[stage.mesh]))
            wr.eq(
                f"{name} = {sign}z_{{{b}}}/z_{{{a}}} = {sign}{wr.i(stage.z[1], f'{S}.z[1]')}/"
                f"{wr.i(stage.z[0], f'{S}.z[0]')} = {wr.v(stage.ratio, f'{S}.ratio')}"
            )
        else:
            first, last = gears[0], gears[-1]
            held = f"u^{{H}}_{{{_u(first, last)}}}"
            name = f"u^{{{last}}}_{{{_u(first, 'H')}}}"
            wr.text(w["gears_planetary"].format(chain="-".join(gears), fixed=last))
            symbols, numbers = [], []
            for mi, mesh in enumerate(stage.meshes):
                a, b = gears[2 * mi], gears[2 * mi + 1]
                sign = "-" if mesh.mesh == "external" else "+"
                M = f"{S}.meshes[{mi}]"
                symbols.append(f"({sign}z_{{{b}}}/z_{{{a}}})")
                numbers.append(
                    f"({sign}{wr.i(mesh.z[1], f'{M}.z[1]')}/{wr.i(mesh.z[0], f'{M}.z[0]')})"
                )
            wr.text(w["gears_held"])
            wr.eq(
                f"{held} = {'·'.join(symbols)} = {'·'.join(numbers)} = "
                f"{wr.v(stage.carrier_held_ratio, f'{S}.carrier_held_ratio')}"
            )
            wr.text(w["gears_willis"].format(fixed=last, ref=cite("strilets2025", "kinytskyi2002")))
            wr.eq(
                f"{name} = 1 - {held} = 1 - {wr.vp(stage.carrier_held_ratio, f'{S}.carrier_held_ratio')}"
                f" = {wr.v(stage.ratio, f'{S}.ratio')}"
            )
        names.append(name)
        values.append((stage.ratio, f"{S}.ratio"))
    total = "u_{m1}"
    U = "J['drive']['gear_ratio']"
    if len(train.stages) > 1:
        wr.text(w["gears_total"])
        wr.eq(
            f"{total} = {'·'.join(names)} = {'·'.join(wr.vp(x, s) for x, s in values)} = "
            f"{wr.v(train.ratio, U)}"
        )
    else:
        wr.eq(f"{total} = {names[0]} = {wr.v(train.ratio, U)}")
    wr.text(w["gears_sign_same" if train.ratio > 0 else "gears_sign_opposite"])
    wm = train.motor_omega
    WM = f"pi*{GT}.motor_rpm/30"
    W1 = "abs(J['drive']['omega'])"
    N1 = "J['drive']['n1_rpm']"
    wr.text(w["gears_speed"])
    wr.eq(
        f"ω_{{m}} = π·n_{{m}}/30 = π·{wr.v(train.motor_rpm, f'{GT}.motor_rpm')}/30 = {wr.v(wm, WM)} "
        f"{u['rad/s']};"
    )
    wr.eq(
        f"ω_1 = ω_{{m}}/|{total}| = {wr.v(wm, WM)}/{wr.v(abs(train.ratio), f'abs({U})')} = "
        f"{wr.v(train.omega, W1)} {u['rad/s']}; n_1 = n_{{m}}/|{total}| = "
        f"{wr.v(train.motor_rpm, f'{GT}.motor_rpm')}/{wr.v(abs(train.ratio), f'abs({U})')} = "
        f"{wr.v(abs(train.crank_rpm), N1)} {u['rpm']}"
    )
    wr.text(w["gears_eps"])


def reduction(wr: Writer) -> None:
    """Seed 002 tasks 5 and 6 at the force position (the task's φ_1)."""
    a = wr.solution
    w, u = wr.w, wr.u
    red = a.reduction
    i = a.force_position
    k = a.entry(i)
    if not np.isfinite(red.reduced_inertia[k]):
        return
    wr.add("section", w["reduction_title"], "reduction")
    w1 = red.omega1
    W1 = "M.drive.omega"
    pos = a.positions[k]
    wr.text(
        w["reduction_at"].format(
            i=wr.i(i, "S.force_position"),
            phi=wr.v(pos.phi1_deg, f"J['positions'][{k}]['phi1_deg']", 5),
        )
    )
    wr.add("subsection", w["reduced_moment"], "reduction.M")
    wr.text(w["reduced_moment_rule"])
    total_src = f"S.reduction.reduced_moment[{k}]"
    for fj, f in enumerate(wr.mech.forces):
        name = force_markup(f.name)
        Mf = float(red.reduced_moment_of[f.name][k])
        MS = f"S.reduction.reduced_moment_of[{f.name!r}][{k}]"
        V_src = f"hyp({src.point(a, i, f.at, 'v')})"
        V = float(np.hypot(*a.sweep.v[f.at][k])) if f.at in a.sweep.v else 0.0
        if Mf == 0.0 or V == 0.0:
            wr.eq(f"M_{{red}}({name}) = {wr.v(Mf, MS)} {u['Nm']} " + w["reduced_idle"])
            continue
        cos = Mf * w1 / (f.magnitude * V)
        wr.eq(
            f"M_{{red}}({name}) = {name}·V_{{{f.at}}}·cos({name}, V_{{{f.at}}})/ω_1 = "
            f"{wr.v(f.magnitude, f'M.forces[{fj}].magnitude')}·{wr.v(V, V_src)}·"
            f"{wr.vp(cos, f'{MS}*{W1}/(M.forces[{fj}].magnitude*{V_src})')}/"
            f"{wr.v(w1, W1)} = {wr.v(Mf, MS)} {u['Nm']}"
        )
    if len(wr.mech.forces) > 1:
        wr.eq(f"M_{{red}} = {wr.v(float(red.reduced_moment[k]), total_src)} {u['Nm']}")
    if wr.mech.forces:
        wr.text(w["reduced_sign"])
    wr.add("subsection", w["reduced_inertia"], "reduction.J")
    wr.text(w["reduced_inertia_rule"])
    sym, num = [], []
    for lid, link in wr.mech.links.items():
        VS = f"hyp(J['kinematics'][{k}]['v_cm']['{lid}'])"
        OM = f"abs({src.rate(a, i, lid, 'omega')})"
        v_s = float(np.hypot(*a.sweep.v[link.cm_name][k])) if link.cm_name in a.sweep.v else 0.0
        om = abs(float(a.sweep.omega[lid][k]))
        if link.mass:
            sym.append(f"m_{{{lid}}}·V_{{S{lid}}}^2")
            num.append(f"{wr.v(link.mass, f'M.links[{lid}].mass')}·{wr.v(v_s, VS)}^2")
        if link.J:
            sym.append(f"J_{{S{lid}}}·ω_{{{lid}}}^2")
            num.append(f"{wr.v(link.J, f'M.links[{lid}].J')}·{wr.v(om, OM)}^2")
    JR = f"S.reduction.reduced_inertia[{k}]"
    wr.eq(
        f"J_{{red}} = ({' + '.join(sym) or '0'})/ω_1^2 = "
        f"({' + '.join(num) or '0'})/{wr.v(w1, W1)}^2 = "
        f"{wr.v(float(red.reduced_inertia[k]), JR)} {u['kgm2']}"
    )


def conclusions(wr: Writer) -> None:
    a, w, u = wr.solution, wr.w, wr.u
    st = a.structure
    wr.add("section", w["conclusions_title"], "conclusions")
    wr.text(
        w["concl_structure"].format(
            W=wr.i(st.W, "J['structure']['W']"),
            cls=wr.i(st.mechanism_class, "J['structure']['mechanism_class']"),
            formula=st.formula,
        )
    )
    train = wr.mech.drive.gear_train
    if train is not None:
        wr.text(
            w["concl_gears"].format(
                u=wr.v(train.ratio, "J['drive']['gear_ratio']"),
                w1=wr.v(train.omega, "abs(J['drive']['omega'])"),
            )
        )
    out = wr.mech.study.output
    dg = a.diagrams
    if dg is not None:
        D = "J['diagrams']"
        for i in a.plan_positions:
            wr.text(
                w["concl_plan"].format(
                    i=wr.i(i, f"J['plans'][{a.plan_positions.index(i)}]"),
                    out=out,
                    V=wr.v(abs(dg.v_plan[i]), f"abs({D}['v_plan'][{i}])"),
                    a=wr.v(abs(dg.a_plan[i]), f"abs({D}['a_plan'][{i}])"),
                )
            )
        sc = dg.sheet_check
        rel = [(j, x) for j, x in enumerate(sc.values) if not x.ill_conditioned]
        if rel:
            j, worst = max(rel, key=lambda t: abs(t[1].error_percent))
            E = f"abs({D}['investigated'][{j}]['error_percent'])"
            wr.text(
                w["concl_check_ok" if sc.passed else "concl_check_bad"].format(
                    err=wr.v(abs(worst.error_percent), E, 3),
                    q="V" if worst.quantity == "v" else "a",
                    i=wr.i(worst.index, f"{D}['investigated'][{j}]['index']"),
                    lim=wr.v(sc.limit_percent, f"{D}['limit_percent']"),
                )
            )
    fa = a.forces
    if fa is not None:
        # what dominates the loads: the production resistance, the inertia forces, the weights
        kinds = []
        prs = [
            (
                float(np.hypot(*f.force)),
                f"hyp(J['forces']['external_forces'][{f.name!r}]['force'])",
                f.name,
            )
            for f in fa.loads.production_resistance
        ]
        ins = [
            (
                float(np.hypot(*ll.inertia_force)),
                f"hyp(J['forces']['loads']['{lid}']['F_in'])",
                f"F_in{lid}",
            )
            for lid, ll in fa.loads.links.items()
        ]
        gs = [
            (abs(float(ll.weight[1])), f"abs(J['forces']['loads']['{lid}']['G'][1])", f"G{lid}")
            for lid, ll in fa.loads.links.items()
        ]
        for key, group in (("concl_pr", prs), ("concl_in", ins), ("concl_g", gs)):
            if group:
                x, s, name = max(group, key=lambda t: t[0])
                if x > 0:
                    kinds.append((x, w[key].format(name=force_markup(name), F=wr.v(x, s))))
        kinds.sort(key=lambda t: -t[0])
        if kinds:
            wr.text(
                w["concl_loads"].format(
                    first=kinds[0][1], rest="; ".join(t[1] for t in kinds[1:]) or "-"
                )
            )
        name, r = max(fa.reactions.items(), key=lambda t: t[1].magnitude)
        wr.text(
            w["concl_reaction"].format(
                R=force_markup(name),
                pair=r.pair,
                F=wr.v(r.magnitude, f"hyp(J['forces']['reactions'][{name!r}])"),
            )
        )
        d = fa.discrepancy_percent
        FZ, FP = "J['forces']['balancing_force_lever']", "J['forces']['balancing_force_plans']"
        if math.isfinite(d):
            wr.text(
                w["concl_balance"].format(
                    pl=wr.v(fa.balancing_force_plans, FP),
                    z=wr.v(fa.balancing_force_lever, FZ),
                    d=wr.v(d, "J['forces']['discrepancy_percent']", 3),
                    M=wr.v(fa.balancing_moment, "J['forces']['balancing_moment']"),
                    verdict=w["concl_agree" if d <= 5.0 else "concl_disagree"],
                )
            )
    if train is not None and a.forces is not None:
        k = a.entry(a.force_position)
        red = a.reduction
        if np.isfinite(red.reduced_inertia[k]):
            wr.text(
                w["concl_reduction"].format(
                    M=wr.v(float(red.reduced_moment[k]), f"S.reduction.reduced_moment[{k}]"),
                    J=wr.v(float(red.reduced_inertia[k]), f"S.reduction.reduced_inertia[{k}]"),
                )
            )
    del u
