"""The student's own differentiation (issue 23): the diagrams' ordinates and
the 5 % check judged on the grid the answers give. The student's
differentiation is made here independently: S from corpus.py's closed forms
at the guide's 12 positions, chords, and a smooth periodic curve through the
chords' mid points by trigonometric interpolation (not the tool's spline)."""

import json
import math

import numpy as np
from click.testing import CliRunner

import mmt_plans
from mmt_plans.check import check, loads_answers
from mmt_plans.cli import main

from .corpus import MECHANISMS


def trig_interpolate(x_mid: np.ndarray, y: np.ndarray, period: float, x: np.ndarray) -> np.ndarray:
    """The periodic trigonometric polynomial through (x_mid, y), n even, read at x."""
    n = len(y)
    c = np.fft.rfft(y) / n
    out = np.full(len(x), c[0].real)
    for k in range(1, n // 2 + 1):
        w = 2 * math.pi * k / period
        amp = c[k] if k < n // 2 else c[k] / 2
        out += 2 * (amp * np.exp(1j * w * (x[:, None] - x_mid[0]))).real[:, 0]
    return out


def student_diagrams(s: np.ndarray, T: float) -> tuple[np.ndarray, np.ndarray]:
    """V and a at the positions by chords and a smooth curve through their mid points."""
    n = len(s)
    dt = T / n
    t = np.arange(n) * dt
    mid = t + dt / 2
    v_mid = np.diff(np.append(s, s[0])) / dt
    v = trig_interpolate(mid, v_mid, T, t)
    a_mid = np.diff(np.append(v, v[0])) / dt
    a = trig_interpolate(mid, a_mid, T, t)
    return v, a


def test_a_correct_differentiation_over_twelve_positions_passes(tmp_path):
    mech = MECHANISMS["shaper"]
    path = tmp_path / "shaper.toml"
    path.write_text(mech.toml, encoding="utf-8")
    solution = mmt_plans.solve(mmt_plans.load(path))
    n = 12
    angles = [solution.positions[solution.entry(i)].phi1_deg for i in range(n)]
    kin = [mech.kin(phi) for phi in angles]
    # working direction −x: S from position 0, V and a of the plans along it
    s = np.array([-(k.P["D"] - kin[0].P["D"]).real for k in kin])
    v_plan = np.array([-k.V["D"].real for k in kin])
    a_plan = np.array([-k.A["D"].real for k in kin])
    T = 60.0 / mech.rpm
    v, a = student_diagrams(s, T)
    mu_S, mu_V, mu_a = 0.002, 0.01, 0.1
    inv = solution.plan_positions
    # δ by (12), (13); where the plan's value is under 5 % of its largest over
    # the turn the check takes the absolute error (and δ is not written)
    dv = {
        i: (v_plan[i] - v[i]) / v_plan[i] * 100
        for i in inv
        if abs(v_plan[i]) >= 0.05 * abs(v_plan).max()
    }
    da = {
        i: (a_plan[i] - a[i]) / a_plan[i] * 100
        for i in inv
        if abs(a_plan[i]) >= 0.05 * abs(a_plan).max()
    }
    verdict = all(abs(x) <= 5 for x in [*dv.values(), *da.values()])

    def table(d):
        return "{ " + ", ".join(f'"{i}" = {float(x)!r}' for i, x in d.items()) + " }"

    text = "\n".join(
        [
            "[diagrams]",
            f"divisions = {n}",
            f"mu_S = {mu_S}",
            f"mu_V = {mu_V}",
            f"mu_a = {mu_a}",
            f"S_mm = {table({i: s[i] / mu_S for i in range(n)})}",
            f"V_mm = {table({i: v[i] / mu_V for i in range(n)})}",
            f"a_mm = {table({i: a[i] / mu_a for i in range(n)})}",
            f"V_plan = {table({i: v_plan[i] for i in inv})}",
            f"V_diagram = {table({i: v[i] for i in inv})}",
            f"dV_percent = {table(dv)}",
            f"a_plan = {table({i: a_plan[i] for i in inv})}",
            f"a_diagram = {table({i: a[i] for i in inv})}",
            f"da_percent = {table(da)}",
            f"check_passed = {str(verdict).lower()}",
            "",
        ]
    )
    answers = tmp_path / "answers.toml"
    answers.write_text(text, encoding="utf-8")
    report = tmp_path / "r.json"
    res = CliRunner().invoke(main, ["check", str(path), str(answers), "--json", str(report)])
    assert res.exit_code == 0, res.output
    assert "your grid of 12 divisions" in res.output
    data = json.loads(report.read_text(encoding="utf-8"))
    assert data["diagrams_grid"] == {"divisions": 12, "from_answers": True}
    # without the grid, the same work is judged on the tool's own grid, and says so
    tool = check(solution, loads_answers(text.replace(f"divisions = {n}\n", ""), solution))
    assert tool.grid == (solution.diagrams.sheet_check.intervals, False)
    assert "the tool's grid" in tool.text()


def test_pole_distances_give_the_scales(tmp_path):
    """μV = μS/(μt·H_V), μa = μV/(μt·H_a), μt = 60/(n1·L) when the scales are not written."""
    mech = MECHANISMS["shaper"]
    path = tmp_path / "shaper.toml"
    path.write_text(mech.toml, encoding="utf-8")
    solution = mmt_plans.solve(mmt_plans.load(path))
    mu_S, H_V, H_a, L = 0.002, 40.0, 30.0, 240.0
    mu_t = 60.0 / (mech.rpm * L)
    mu_V = mu_S / (mu_t * H_V)
    mu_a = mu_V / (mu_t * H_a)
    v_plan = -mech.kin(solution.positions[solution.entry(3)].phi1_deg).V["D"].real
    text = (
        f"[diagrams]\ndivisions = 48\nH_V_mm = {H_V}\nH_a_mm = {H_a}\nL_mm = {L}\n"
        f"mu_S = {mu_S}\nV_mm = {{ \"3\" = {v_plan / mu_V} }}\n"
    )
    answers = loads_answers(text, solution)
    (v,) = answers.values
    assert v.mu == np.float64(mu_V) or math.isclose(v.mu, mu_V, rel_tol=1e-12)
    assert check(solution, answers).passed


def test_bad_grids_are_refused_with_the_entry_and_a_fix(tmp_path):
    path = tmp_path / "shaper.toml"
    path.write_text(MECHANISMS["shaper"].toml, encoding="utf-8")
    cases = {
        "divisions = 3\n": ("diagrams.divisions", "4 to 720"),
        "divisions = 12.5\n": ("diagrams.divisions", "whole number"),
        "divisions = true\n": ("diagrams.divisions", "whole number"),
        "H_V_mm = 40\n": ("diagrams.H_V_mm", "add divisions"),
        "divisions = 12\nH_a_mm = -3\n": ("diagrams.H_a_mm", "positive"),
        "divisions = 12\nL_mm = \"long\"\n": ("diagrams.L_mm", "number"),
    }
    for head, (entry, words) in cases.items():
        answers = tmp_path / "a.toml"
        answers.write_text(f'[diagrams]\n{head}mu_S = 0.002\nS_mm = {{ "3" = 10 }}\n', encoding="utf-8")
        res = CliRunner().invoke(main, ["check", str(path), str(answers)])
        assert res.exit_code == 2, (head, res.output)
        assert entry in res.output and words in res.output, (head, res.output)
        assert "Traceback" not in res.output
