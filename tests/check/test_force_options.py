"""The force analysis' keyword options (a mistake made on purpose, for the
student check): the defaults are bit-identical to the plain call, and each
option gives what the same calculation gives by an independent route."""

import math
from pathlib import Path

import numpy as np
import pytest

import mmt_plans
from mmt_plans.forces import force_analysis_at

ROOT = Path(__file__).resolve().parents[2]
SAMPLES = sorted(ROOT.glob("samples/*.toml")) + [ROOT / "samples/answers/seed002_example.toml"]
EXAMPLE = ROOT / "samples/answers/seed002_example.toml"


def fingerprint(fa) -> list:
    out = [
        fa.balancing_force_plans,
        fa.balancing_force_lever,
        fa.balancing_moment,
        fa.lever.balancing_force_couples,
    ]
    for name, r in fa.reactions.items():
        out += [
            name,
            r.force.tobytes(),
            r.point.tobytes(),
            r.couple,
            [(c.label, c.value) for c in r.components],
        ]
    out += [(f.label, f.moment, f.arm) for f in fa.lever.forces]
    for lid, ll in fa.loads.links.items():
        out += [lid, ll.weight.tobytes(), ll.inertia_force.tobytes(), ll.inertia_moment]
    return out


@pytest.mark.parametrize("path", SAMPLES, ids=[p.stem for p in SAMPLES])
def test_defaults_are_bit_identical(path):
    sol = mmt_plans.solve(mmt_plans.load(path))
    i = sol.force_position
    state = sol.state(i)
    links = list(sol.mechanism.links)
    plain = force_analysis_at(state, mu_l=sol.mu_l)
    assert fingerprint(plain) == fingerprint(sol.forces)
    spelled = force_analysis_at(
        state,
        mu_l=sol.mu_l,
        inertia_forces=None,
        inertia_moments=None,
        gravity=True,
        balancing_in_r0d=True,
        lever_turn_deg=None,
    )
    every = force_analysis_at(state, mu_l=sol.mu_l, inertia_forces=links, inertia_moments=links)
    assert fingerprint(spelled) == fingerprint(plain) == fingerprint(every)


def text_of(**changes) -> str:
    text = EXAMPLE.read_text(encoding="utf-8")
    for old, new in changes.items():
        text = text.replace(old, new)
    return text


def analysis(tmp_path, text):
    path = tmp_path / "m.toml"
    path.write_text(text, encoding="utf-8")
    return mmt_plans.solve(mmt_plans.load(path))


PHI = 210.862


def test_inertia_left_out_is_a_crank_turning_very_slowly(tmp_path):
    # Inertia forces and moments grow as omega1^2: at 0.001 rad/s they are 1.6e-9 of these.
    slow = analysis(tmp_path, text_of(**{"omega = 25.31": "omega = 0.001"}))
    sol = mmt_plans.solve(mmt_plans.load(EXAMPLE))
    ref = slow.forces_at(phi1_deg=PHI)
    fa = force_analysis_at(sol.state(phi1_deg=PHI), inertia_forces=(), inertia_moments=())
    assert fa.balancing_force_plans == pytest.approx(ref.balancing_force_plans, rel=1e-6)
    assert fa.balancing_force_lever == pytest.approx(ref.balancing_force_lever, rel=1e-6)
    for name, r in ref.reactions.items():
        assert fa.reactions[name].magnitude == pytest.approx(r.magnitude, rel=1e-6)


def test_inertia_moments_left_out_are_zero_moments_of_inertia(tmp_path):
    no_j = analysis(
        tmp_path, text_of(**{"J = 0.2812": "J = 0", "J = 0.25": "J = 0", "J = 0.001": "J = 0"})
    )
    sol = mmt_plans.solve(mmt_plans.load(EXAMPLE))
    ref = no_j.forces_at(phi1_deg=PHI)
    fa = force_analysis_at(sol.state(phi1_deg=PHI), inertia_moments=())
    assert fa.balancing_force_plans == pytest.approx(ref.balancing_force_plans, rel=1e-12)
    assert fa.reaction(1, 2).magnitude == pytest.approx(ref.reaction(1, 2).magnitude, rel=1e-12)


def test_gravity_off_is_the_file_without_gravity(tmp_path):
    off = analysis(tmp_path, text_of(**{"[frame]": "[env]\ngravity = false\n\n[frame]"}))
    sol = mmt_plans.solve(mmt_plans.load(EXAMPLE))
    ref = off.forces_at(phi1_deg=PHI)
    fa = force_analysis_at(sol.state(phi1_deg=PHI), gravity=False)
    assert fa.balancing_force_plans == pytest.approx(ref.balancing_force_plans, rel=1e-12)
    assert fa.reaction(0, 5).magnitude == pytest.approx(ref.reaction(0, 5).magnitude, rel=1e-12)


def test_r0d_without_the_balancing_force():
    # R01 = -(G1 + F_in1 + R21 + F_bal) with F_bal along the crank's sense at A;
    # left out: R01 + F_bal * t.
    sol = mmt_plans.solve(mmt_plans.load(EXAMPLE))
    state = sol.state(phi1_deg=PHI)
    fa = force_analysis_at(state)
    wrong = force_analysis_at(state, balancing_in_r0d=False)
    A = state.point(1, "A")
    t = -1j * A / abs(A)  # the crank turns clockwise
    r01 = complex(*fa.reaction(0, 1).force) + fa.balancing_force_plans * t
    assert wrong.reaction(0, 1).magnitude == pytest.approx(abs(r01), rel=1e-12)
    assert wrong.balancing_force_plans == fa.balancing_force_plans


def test_lever_not_turned():
    # On the plan not turned, each force's moment about p is V x F; F_bal stays
    # perpendicular to pa: F_bal * |pa| * s = -sum(V_P x F).
    sol = mmt_plans.solve(mmt_plans.load(EXAMPLE))
    state = sol.state(phi1_deg=PHI)
    fa = force_analysis_at(state)
    wrong = force_analysis_at(state, lever_turn_deg=0.0)
    total = 0.0
    for lid, ll in fa.loads.links.items():
        pose = state.links[lid]
        S = complex(*ll.centre_of_mass)
        total += cross(_xy(pose.vel(S)), ll.weight)
        if ll.shifted_inertia_force is not None:
            K = complex(*ll.shifted_inertia_force.point)
            total += cross(_xy(pose.vel(K)), ll.inertia_force)
        # a couple's two forces have no moment about p on a plan not turned
    for f in fa.loads.production_resistance:
        total += cross(_xy(state.links[f.link].vel(complex(*f.point))), f.force)
    v_a = abs(state.links[1].vel(state.point(1, "A")))
    s = -1.0  # clockwise
    assert wrong.balancing_force_lever == pytest.approx(-total / (s * v_a), rel=1e-9)
    assert not math.isclose(wrong.balancing_force_lever, fa.balancing_force_lever, rel_tol=0.05)


def _xy(z: complex) -> np.ndarray:
    return np.array([z.real, z.imag])


def cross(a, b) -> float:
    return float(a[0] * b[1] - a[1] * b[0])


def test_weight_at_another_point_is_the_centre_of_mass_moved_there(tmp_path):
    # G2 applied at B: the same as a link 2 whose centre of mass is at B, with
    # the inertia gone (a crank turning very slowly), where only G acts.
    moved = analysis(
        tmp_path,
        text_of(**{"omega = 25.31": "omega = 0.001", "mass = 10.4": "mass = 10.4\ncm = [400, 0]"}),
    )
    ref = moved.forces_at(phi1_deg=PHI)
    sol = mmt_plans.solve(mmt_plans.load(EXAMPLE))
    fa = force_analysis_at(
        sol.state(phi1_deg=PHI), inertia_forces=(), inertia_moments=(), weight_at={2: "B"}
    )
    assert fa.balancing_force_plans == pytest.approx(ref.balancing_force_plans, rel=1e-6)
    assert fa.balancing_force_lever == pytest.approx(ref.balancing_force_lever, rel=1e-6)
    for name, r in ref.reactions.items():
        assert fa.reactions[name].magnitude == pytest.approx(r.magnitude, rel=1e-6, abs=1e-6)
    plain = force_analysis_at(sol.state(phi1_deg=PHI), inertia_forces=(), inertia_moments=())
    assert not math.isclose(plain.balancing_force_plans, fa.balancing_force_plans, rel_tol=0.01)
    with pytest.raises(mmt_plans.errors.MmtError, match="no point 'Q'"):
        force_analysis_at(sol.state(phi1_deg=PHI), weight_at={2: "Q"})


def test_inertia_moment_reversed_is_linear_in_the_moment():
    # Every result is linear in the loads: M_in taken the wrong way gives
    # X(-M) = 2 X(0) - X(M), X(0) the analysis without the moment.
    sol = mmt_plans.solve(mmt_plans.load(EXAMPLE))
    state = sol.state(phi1_deg=PHI)
    right = force_analysis_at(state, mu_l=sol.mu_l)
    kept = [lid for lid in sol.mechanism.links if lid != 2]
    none = force_analysis_at(state, mu_l=sol.mu_l, inertia_moments=kept)
    wrong = force_analysis_at(state, mu_l=sol.mu_l, inertia_moments_reversed=[2])
    for x in ("balancing_force_plans", "balancing_force_lever"):
        expect = 2 * getattr(none, x) - getattr(right, x)
        assert getattr(wrong, x) == pytest.approx(expect, rel=1e-9)
    for name, r in right.reactions.items():
        expect = 2 * none.reactions[name].force - r.force
        assert wrong.reactions[name].force == pytest.approx(expect, rel=1e-9, abs=1e-6)
    # K mirrored about S: the inertia force shifted to the wrong side
    S = right.loads.links[2].centre_of_mass
    K = right.loads.links[2].shifted_inertia_force.point
    assert wrong.loads.links[2].shifted_inertia_force.point == pytest.approx(2 * S - K)
