"""Gear trains: seed 002 task 1 worked example, signs, compound trains, Willis."""

from __future__ import annotations

import copy
import dataclasses
import math
import tomllib
from fractions import Fraction

import pytest
from hypothesis import given
from hypothesis import strategies as st

from mmt_plans.errors import SpecError
from mmt_plans.gears import GearPair, GearTrain, PlanetaryStage, Step

# Seed 002, §3 "Приклад розв'язування задач", task 1 (fig. 1 is lost in the text):
# n_дв = 1450; z1 = 25, z2 = 50 form the ordinary pair z1–z2, and
# z3 – z4 – z4' – z5 – H is the planetary stage (z5 fixed, carrier H the output).
SEED_002 = """
[gears]
motor_rpm = 1450
[[gears.stage]]
z = [25, 50]
mesh = "external"
[[gears.stage]]
kind = "planetary"
meshes = [ { z = [20, 30], mesh = "external" },
           { z = [15, 40], mesh = "external" } ]
"""


def seed_train() -> GearTrain:
    return GearTrain.from_toml(tomllib.loads(SEED_002)["gears"], "seed002.toml")


def pair_train(motor_rpm: float, *pairs: tuple[int, int, str]) -> GearTrain:
    stages = tuple(GearPair((z1, z2), mesh) for z1, z2, mesh in pairs)  # type: ignore[arg-type]
    return GearTrain(motor_rpm, stages)


def sun_planet_ring(sun: int, planet: int, ring: int) -> PlanetaryStage:
    # 2K-H: sun drives, one planet, the ring gear fixed, the carrier out.
    return PlanetaryStage((GearPair((sun, planet), "external"),
                           GearPair((planet, ring), "internal")))


# --- seed 002 worked example -------------------------------------------------


def test_seed_002_train_ratio_is_6():
    train = seed_train()
    # §1.4: u12 = −z2/z1 = −50/25 = −2.
    assert train.stages[0].exact_ratio == -2
    # §1.3: u35^H = (−z4/z3)·(−z5/z4') = (30·40)/(20·15) = 1200/300 = 4; u3H^5 = 1 − 4 = −3.
    assert train.stages[1].exact_carrier_held_ratio == 4
    assert train.stages[1].exact_ratio == -3
    # §1.5: u_дв1 = (−2)·(−3) = 6, "+": the crank turns with the motor shaft.
    assert train.exact_ratio == 6
    assert train.ratio == 6.0


def test_seed_002_crank_speed_is_25_31_rad_s():
    train = seed_train()
    # §1.6: ω_дв = π·1450/30 = 151.84 rad/s; ω1 = 151.84/6 = 25.31 rad/s.
    assert train.motor_omega == pytest.approx(151.84, abs=0.005)
    assert round(train.omega, 2) == 25.31
    # n1 = 1450/6 = 241.67 rpm, same sense as the motor.
    assert train.crank_rpm == pytest.approx(1450 / 6)
    assert train.crank_rpm > 0


def test_seed_002_calculation_note_reads_like_the_seed():
    lines = [str(step) for step in seed_train().steps()]
    # The numbers of seed 002 §1.3–1.6, written formula = numbers = result.
    assert lines == [
        "u12 = −z2/z1 = −50/25 = −2.000",
        "u35^H = (−z4/z3)·(−z5/z4') = (−30/20)·(−40/15) = 4.000",
        "u3H^5 = 1 − u35^H = 1 − 4.000 = −3.000",
        "u_m1 = u12·u3H^5 = (−2.000)·(−3.000) = 6.000",
        "ω_m = π·n_m/30 = π·1450/30 = 151.84 rad/s",
        "ω1 = ω_m/|u_m1| = 151.84/6.000 = 25.31 rad/s",
        "ε1 = dω1/dt = d(ω_m/|u_m1|)/dt = 0 rad/s²",
    ]
    assert all(isinstance(step, Step) and step.title for step in seed_train().steps())


def test_seed_002_calculation_note_in_ukrainian():
    steps = seed_train().steps("uk")
    # Seed 002 writes u_дв1 and decimal commas: ω1 = 151,84/6 = 25,31 рад/с.
    assert str(steps[3]) == "u_дв1 = u12·u3H^5 = (−2,000)·(−3,000) = 6,000"
    assert steps[5].result == "25,31 рад/с"
    with pytest.raises(ValueError):
        seed_train().steps("de")  # type: ignore[arg-type]


# --- ordinary pairs and compound trains -----------------------------------------


def test_external_mesh_reverses_internal_keeps_the_sense():
    # Seed 000 eq. (1.18): external u12 = −z2/z1 = −60/20 = −3; eq. (1.19): internal +3.
    assert GearPair((20, 60), "external").ratio == -3.0
    assert GearPair((20, 60), "internal").ratio == 3.0
    # 1500 rpm through −3: the crank turns at 500 rpm against the motor,
    # ω = π·500/30 = 52.36 rad/s (a magnitude).
    train = pair_train(1500, (20, 60, "external"))
    assert train.crank_rpm == pytest.approx(-500.0)
    assert train.omega == pytest.approx(52.35988, abs=1e-5)
    assert str(train.steps()[0]) == "u12 = −z2/z1 = −60/20 = −3.000"
    assert str(pair_train(1500, (20, 60, "internal")).steps()[0]) == "u12 = +z2/z1 = +60/20 = 3.000"


def test_compound_train_of_three_external_pairs():
    # Seed 000 fig. 1.17: three external pairs, an odd count, so u < 0:
    # u16 = (−40/20)·(−45/15)·(−36/18) = (−2)·(−3)·(−2) = −12;
    # 1440 rpm / −12 = −120 rpm, ω1 = π·120/30 = 4π = 12.566 rad/s.
    train = pair_train(1440, (20, 40, "external"), (15, 45, "external"), (18, 36, "external"))
    assert train.exact_ratio == -12
    assert train.crank_rpm == pytest.approx(-120.0)
    assert train.omega == pytest.approx(4 * math.pi)
    # Gears 2–3 and 4–5 share shafts, so the pairs are u12, u34, u56 as in the seed.
    assert [s.formula.split(" =")[0] for s in train.steps()[:4]] == ["u12", "u34", "u56", "u_m1"]


def test_compound_train_with_an_internal_pair():
    # (−40/20)·(+80/20) = (−2)·(+4) = −8.
    assert pair_train(1000, (20, 40, "external"), (20, 80, "internal")).exact_ratio == -8


# --- planetary stages by Willis ------------------------------------------------------


def test_2kh_with_fixed_ring():
    # Sun 20, planet 30, ring 80 (coaxial: 20 + 2·30 = 80), ring fixed, carrier out.
    # Carrier held: u13^H = (−30/20)·(+80/30) = −80/20 = −4; Willis: u1H = 1 − (−4) = 5,
    # which is seed 000 eq. (1.26): 1 + z3/z1 = 1 + 80/20 = 5.
    stage = sun_planet_ring(20, 30, 80)
    assert stage.exact_carrier_held_ratio == -4
    assert stage.exact_ratio == 5
    lines = [str(s) for s in GearTrain(1000, (stage,)).steps()[:2]]
    # One satellite meshes with both central gears, so it stays z2 (no z2').
    assert lines == [
        "u13^H = (−z2/z1)·(+z3/z2) = (−30/20)·(+80/30) = −4.000",
        "u1H^3 = 1 − u13^H = 1 − (−4.000) = 5.000",
    ]


def test_double_satellite_high_reduction():
    # The classic 2K-H with a satellite block, all external: z1 = 100, z2 = 101, z2' = 100,
    # z3 = 99 fixed. u13^H = (101/100)·(99/100) = 9999/10000; u1H = 1 − 9999/10000 = 1/10000:
    # the carrier turns 10000 times for one turn of gear 1.
    stage = PlanetaryStage((GearPair((100, 101), "external"), GearPair((100, 99), "external")))
    assert stage.exact_carrier_held_ratio == Fraction(9999, 10000)
    assert stage.exact_ratio == Fraction(1, 10000)
    assert GearTrain(1, (stage,)).crank_rpm == pytest.approx(10000.0)


def test_model_is_frozen():
    train = seed_train()
    with pytest.raises(dataclasses.FrozenInstanceError):
        train.motor_rpm = 1000  # type: ignore[misc]
    assert isinstance(train.stages, tuple)
    assert isinstance(train.stages[1].meshes, tuple)


# --- properties ----------------------------------------------------------------------

teeth = st.integers(min_value=8, max_value=200)
meshes = st.sampled_from(["external", "internal"])
pairs = st.builds(lambda a, b, m: GearPair((a, b), m), teeth, teeth, meshes)
planetaries = st.lists(pairs, min_size=2, max_size=4).map(tuple).filter(
    lambda ms: math.prod(m.exact_ratio for m in ms) != 1).map(PlanetaryStage)
stages = st.one_of(pairs, planetaries)


@given(st.lists(stages, min_size=1, max_size=5), st.floats(min_value=100, max_value=3000))
def test_train_ratio_is_the_product_of_stage_ratios(stage_list, rpm):
    train = GearTrain(rpm, tuple(stage_list))
    # Seed 000 eq. (1.21): the train's ratio is the product of its stages' ratios.
    assert train.exact_ratio == math.prod(s.exact_ratio for s in stage_list)
    assert train.crank_rpm * train.ratio == pytest.approx(rpm)
    assert train.omega == pytest.approx(math.pi * abs(train.crank_rpm) / 30)
    assert train.omega == pytest.approx(train.motor_omega / abs(train.ratio))


@given(st.lists(st.tuples(teeth, teeth, meshes), min_size=1, max_size=6))
def test_sign_follows_the_count_of_external_meshes(spec):
    train = pair_train(1000, *spec)
    # Seed 000 §3.2: even count of external meshes gives u > 0, odd gives u < 0;
    # the magnitude is the product of z_driven/z_driving.
    externals = sum(m == "external" for _, _, m in spec)
    magnitude = math.prod(Fraction(b, a) for a, b, _ in spec)
    assert train.exact_ratio == (-1) ** externals * magnitude


@given(sun=teeth, planet=teeth, ring=teeth)
def test_fixed_ring_gives_one_plus_ring_over_sun(sun, planet, ring):
    # Willis with the ring fixed: u1H = 1 − (−zp/zs)·(zr/zp) = 1 + zr/zs whatever the planet.
    assert sun_planet_ring(sun, planet, ring).exact_ratio == 1 + Fraction(ring, sun)


@given(sun=teeth, planet=teeth)
def test_fixed_ring_by_instant_centres(sun, planet):
    # Independent of Willis: radii ∝ teeth, ring r = rs + 2·rp. Carrier at ωH = 1 moves the
    # planet centre at v = rs + rp; the planet rolls on the fixed ring, whose contact is its
    # instant centre, so its point on the sun moves at 2v and ωs = 2v/rs.
    ring = sun + 2 * planet
    omega_sun = 2 * (sun + planet) / sun
    assert sun_planet_ring(sun, planet, ring).ratio == pytest.approx(omega_sun)


# --- bad input -----------------------------------------------------------------------


def seed_table() -> dict:
    return copy.deepcopy(tomllib.loads(SEED_002)["gears"])


def broken(edit) -> dict:
    table = seed_table()
    edit(table)
    return table


def _set(keys, value):
    def edit(t):
        for k in keys[:-1]:
            t = t[k]
        t[keys[-1]] = value
    return edit


def _del(keys):
    def edit(t):
        for k in keys[:-1]:
            t = t[k]
        del t[keys[-1]]
    return edit


def _rename(keys, new):
    def edit(t):
        for k in keys[:-1]:
            t = t[k]
        t[new] = t.pop(keys[-1])
    return edit


BAD = [
    # (case, edit, entry, words the fix must contain)
    ("motor_rpm missing", _del(["motor_rpm"]), "gears.motor_rpm", "motor_rpm ="),
    ("motor_rpm zero", _set(["motor_rpm"], 0), "gears.motor_rpm", "1/min"),
    ("motor_rpm negative", _set(["motor_rpm"], -1450), "gears.motor_rpm", "1/min"),
    ("motor_rpm text", _set(["motor_rpm"], "1450"), "gears.motor_rpm", "1/min"),
    ("motor_rpm bool", _set(["motor_rpm"], True), "gears.motor_rpm", "1/min"),
    ("motor_rpm misspelt", _rename(["motor_rpm"], "motor_rmp"), "gears.motor_rmp", "'motor_rpm'"),
    ("stages plural", _rename(["stage"], "stages"), "gears.stages", "'stage'"),
    ("stage list empty", _set(["stage"], []), "gears.stage", "[[gears.stage]]"),
    ("stage not a list", _set(["stage"], 3), "gears.stage", "[[gears.stage]]"),
    ("z one number", _set(["stage", 0, "z"], [25]), "gears.stage[1].z", "z = [25, 50]"),
    ("z three numbers", _set(["stage", 0, "z"], [25, 50, 75]), "gears.stage[1].z", "z = [25, 50]"),
    ("z zero teeth", _set(["stage", 0, "z"], [25, 0]), "gears.stage[1].z", "z = [25, 50]"),
    ("z fractional", _set(["stage", 0, "z"], [25.5, 50]), "gears.stage[1].z", "z = [25, 50]"),
    ("z text", _set(["stage", 0, "z"], "25, 50"), "gears.stage[1].z", "z = [25, 50]"),
    ("z missing", _del(["stage", 0, "z"]), "gears.stage[1].z", "z = [z1, z2]"),
    ("mesh misspelt", _set(["stage", 0, "mesh"], "externel"), "gears.stage[1].mesh",
     'did you mean "external"'),
    ("mesh unknown", _set(["stage", 0, "mesh"], "bevel"), "gears.stage[1].mesh", '"internal"'),
    ("mesh missing", _del(["stage", 0, "mesh"]), "gears.stage[1].mesh", 'mesh = "external"'),
    ("stage key misspelt", _rename(["stage", 0, "mesh"], "mseh"), "gears.stage[1].mseh", "'mesh'"),
    ("meshes on a pair", _set(["stage", 0, "meshes"], []), "gears.stage[1].meshes",
     'kind = "planetary"'),
    ("kind misspelt", _set(["stage", 1, "kind"], "planetry"), "gears.stage[2].kind",
     'did you mean "planetary"'),
    ("kind unknown", _set(["stage", 1, "kind"], "worm"), "gears.stage[2].kind", '"planetary"'),
    ("z on a planetary", _set(["stage", 1, "z"], [20, 30]), "gears.stage[2].z", "meshes"),
    ("planetary key misspelt", _rename(["stage", 1, "meshes"], "mesh_list"),
     "gears.stage[2].mesh_list", "'meshes'"),
    ("one mesh", _set(["stage", 1, "meshes"], [{"z": [20, 30], "mesh": "external"}]),
     "gears.stage[2].meshes", "meshes = ["),
    ("bad planetary z", _set(["stage", 1, "meshes", 1, "z"], [15, -40]),
     "gears.stage[2].meshes[2].z", "z = [25, 50]"),
    ("bad planetary mesh", _set(["stage", 1, "meshes", 0, "mesh"], "inner"),
     "gears.stage[2].meshes[1].mesh", 'did you mean "internal"'),
    # (−30/20)·(−20/30) = 1: with the carrier held the train is 1:1, u1H = 0, the carrier stands.
    ("carrier cannot turn", _set(["stage", 1, "meshes", 1, "z"], [30, 20]),
     "gears.stage[2].meshes", "1:1"),
]


@pytest.mark.parametrize("edit, entry, fix_words", [b[1:] for b in BAD], ids=[b[0] for b in BAD])
def test_bad_input_names_the_entry(edit, entry, fix_words):
    with pytest.raises(SpecError) as info:
        GearTrain.from_toml(broken(edit), "press.toml")
    err = info.value
    assert err.entry == entry
    assert str(err).startswith(f"press.toml: {entry}: ")
    assert fix_words in err.fix
    assert isinstance(err, ValueError)


def test_gears_not_a_table():
    with pytest.raises(SpecError) as info:
        GearTrain.from_toml([1450], "press.toml")  # type: ignore[arg-type]
    assert info.value.entry == "gears"
