"""Speed against error of the ways of getting V and a of the output.

For each sample and position count: the plans (exact, the reference), the
textbook's graphical differentiation, and better numerical differentiations of
the same displacements (8th-order central differences, spectral). Error is the
largest deviation from the plans over the positions, divided by the largest
plan value; time is per call, best of several, including the sweep that gives
the displacements (which every method needs).
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from ..diagrams import DIFFERENTIATION_METHODS
from ..model import Mechanism
from ..report import table
from ..solution import solve
from ..spec import load
from .timing import best_time

COUNTS = (8, 12, 24, 36, 72, 360)
METHOD_NAMES = {
    "plans": "plans (exact)",
    "textbook": "graphical (textbook)",
    "central8": "8th-order differences",
    "spectral": "spectral (FFT)",
}


def measure(mech: Mechanism, counts=COUNTS, repeat=5):
    """Rows (method, n, seconds, V error, a error) for one mechanism."""
    solution = solve(mech)
    n1 = mech.drive.n1_rpm
    phi0 = solution.positions[0].phi1_deg
    rows = []
    for n in counts:
        phi = phi0 + solution.sense_sign * 360.0 * np.arange(n) / n

        def plans(phi=phi):
            return solution.output_along(solution.sweep_at(phi))

        s, v, a = plans()
        vmax, amax = np.abs(v).max(), np.abs(a).max()
        rows.append(("plans", n, best_time(plans, repeat), 0.0, 0.0))
        for name, method in DIFFERENTIATION_METHODS.items():

            def run(method=method):
                s_, _, _ = plans()
                return method(s_ - s_[0], n1=n1)

            try:
                vd, ad = run()
            except ValueError:  # too few positions for this method
                continue
            rows.append(
                (
                    name,
                    n,
                    best_time(run, repeat),
                    float(np.abs(vd - v).max() / vmax),
                    float(np.abs(ad - a).max() / amax),
                )
            )
    return rows


def bench_diagrams(files, repeat, echo, out_dir: Path = Path("out")) -> None:
    all_rows = []
    for path in files:
        mech = load(path)
        try:
            rows = measure(mech, repeat=max(3, repeat // 2))
        except Exception as err:  # noqa: BLE001 - a sample that cannot be differentiated
            echo(f"{path.stem}: skipped ({err})")
            continue
        all_rows += [(path.stem,) + r for r in rows]
    echo("Speed against error of V and a of the output (error = max |X - X_plan| / max |X_plan|)")
    echo(
        table(
            ["sample", "n", "method", "time us", "V error", "a error"],
            [
                [s, str(n), m, f"{t * 1e6:.0f}", f"{ev:.1e}", f"{ea:.1e}"]
                for s, m, n, t, ev, ea in all_rows
            ],
        )
    )
    default = [r for r in all_rows if r[0] == "six_link_press"] or all_rows
    path = plot_speed_error(default, out_dir / "speed_vs_error.svg")
    echo(f"plot: {path}")
    echo("")


def plot_speed_error(rows, path: Path) -> Path:
    """Error against time, both on log scales, one polyline per method."""
    from ..render.look import LineType
    from ..render.output import write_drawing
    from ..render.recording import RecordingBackend

    W, H = 200.0, 140.0
    x0, y0, x1, y1 = 25.0, 20.0, 150.0, 125.0
    tmin = 10 ** math.floor(math.log10(min(t for _, m, _, t, _, _ in rows)))
    tmax = 10 ** math.ceil(math.log10(max(t for _, m, _, t, _, _ in rows)))
    emin, emax = 1e-16, 1.0

    def xy(t, e):
        e = min(max(e, emin), emax)
        fx = (math.log10(t) - math.log10(tmin)) / (math.log10(tmax) - math.log10(tmin))
        fy = (math.log10(e) - math.log10(emin)) / (math.log10(emax) - math.log10(emin))
        return (x0 + fx * (x1 - x0), y0 + fy * (y1 - y0))

    b = RecordingBackend(W, H)
    with b.group("axes", "axes"):
        b.line((x0, y0), (x1, y0), "thin")
        b.line((x0, y0), (x0, y1), "thin")
        k = int(round(math.log10(tmin)))
        while 10.0**k <= tmax * 1.0001:
            x, _ = xy(10.0**k, emin)
            b.line((x, y0), (x, y0 - 1.5), "thin")
            b.text((x, y0 - 5), f"1e{k}", 2.5, anchor="center")
            k += 1
        for k in range(-16, 1, 2):
            _, y = xy(tmin, 10.0**k)
            b.line((x0, y), (x0 - 1.5, y), "thin")
            b.text((x0 - 2.5, y), f"1e{k}", 2.5, anchor="right", valign="middle")
        b.text(((x0 + x1) / 2, 8), "time per call, s (log)", 3.0, anchor="center")
        b.text(
            (8, (y0 + y1) / 2), "relative error of V, a (log)", 3.0, anchor="center", rotation=90
        )
        b.text((x0, y1 + 8), "Speed against error: six-link press, n = 8 to 360 positions", 3.5)
    lines: dict[str, LineType] = {"textbook": "main", "central8": "dashed", "spectral": "dashdot"}
    ly = y1 - 5
    for method, style in lines.items():
        series = [(t, max(ev, ea), n) for _, m, n, t, ev, ea in rows if m == method]
        if not series:
            continue
        with b.group(f"method-{method}", "series"):
            b.polyline([xy(t, e) for t, e, _ in series], style)
            for t, e, n in series:
                b.circle(xy(t, e), 0.8, "thin")
                px, py = xy(t, e)
                b.text((px + 1.5, py + 1.0), str(n), 2.0)
            b.line((x1 + 5, ly), (x1 + 15, ly), style)
            b.text((x1 + 17, ly), METHOD_NAMES[method], 2.2, valign="middle", max_width=28)
        ly -= 7
    plans = [(t, n) for _, m, n, t, _, _ in rows if m == "plans"]
    with b.group("method-plans", "series"):
        b.text((x1 + 5, ly), "plans: exact (error 0), time", 2.2, valign="middle", max_width=40)
        for t, n in plans:
            b.circle(xy(t, emin), 0.8, "main")
    path.parent.mkdir(parents=True, exist_ok=True)
    return write_drawing(b, path, "svg", "mmt_plans: speed against error")
