"""The kinematic scheme of a gear train (seed 002 task 1, Fig. 1; GOST 2.770):
the shafts as axial lines, each gear as its symbol in side view (a line across
its shaft as long as its pitch diameter, capped by its rim), an internal gear
open towards its pinion, the carrier H of a planetary stage as a cranked arm
carrying the satellites' axle, a fixed gear hatched to the frame; each gear
named z_n by the numbers the calculation uses (GearTrain.gear_labels).

Not to scale: a gear's pitch radius is drawn proportional to its teeth, and a
planetary stage's last central gear closes on the satellites' axis (the drawn
train is coaxial whatever the teeth). Drawn through the drawing interface into
a Sketch, in local mm, for the note to replay (note/figures.py).
"""

from __future__ import annotations

from typing import Any

from ..gears import GearPair, GearTrain, PlanetaryStage
from .sketch import Sketch

__all__ = ["sketch_gear_train", "RADIUS_PER_TOOTH"]

RADIUS_PER_TOOTH = 0.5  # mm of pitch radius per tooth
RIM = 1.6  # half the width of a gear's rim, mm
INSIDE = 3 * RIM  # an internal gear stands this far beside its pinion, its rims over it
STEP = 12.0  # between gears along a shaft, mm
TEXT = 3.5  # the capital height of the gears' names, mm
LEAD = 10.0  # the motor's and the output's shaft ends, mm


def _gear(
    sk: Sketch,
    x: float,
    axis: float,
    r: float,
    name: str,
    open_to: float = 0.0,
    below: bool = False,
) -> None:
    """A gear on the shaft at height `axis`: the line across the shaft at x,
    its rims; an internal gear (`open_to` ±1: the side its pinion is on) has
    its rims reaching over the pinion on that side only; named z_name over its
    top (`below`: under its foot, for a gear whose top meets another's)."""
    sk.line((x, axis - r), (x, axis + r), "main")
    for y in (axis - r, axis + r):
        if open_to:
            sk.line((x, y), (x + open_to * INSIDE, y), "main")
        else:
            sk.line((x - RIM, y), (x + RIM, y), "main")
    if below:
        sk.rich_text((x + 0.8, axis - r - 4.0 - TEXT), f"z_{{{name}}}", TEXT)  # under the frame
    else:
        sk.rich_text((x + 0.8, axis + r + 1.2), f"z_{{{name}}}", TEXT)


def _ground(sk: Sketch, x: float, y: float) -> None:
    """A fixed gear's hub held by the frame: a short line hatched below."""
    sk.line((x - 4.0, y), (x + 4.0, y), "main")
    for k in range(5):
        hx = x - 4.0 + 2.0 * k + 0.5
        sk.line((hx, y), (hx - 1.6, y - 1.6), "thin")


def _radius(z: int) -> float:
    return RADIUS_PER_TOOTH * z


def sketch_gear_train(train: GearTrain, look: Any) -> Sketch:
    """The train from the motor's shaft (left) to the crank's (right)."""
    sk = Sketch(look)
    labels = train.gear_labels
    x, axis = 0.0, 0.0
    shaft_from = x - LEAD  # where the current shaft's drawn line starts
    with sk.group("gear-train", "gear-train"):
        for stage, names in zip(train.stages, labels):
            x += STEP / 2
            if isinstance(stage, GearPair):
                ra, rb = (_radius(z) for z in stage.z)
                internal = stage.mesh == "internal"
                # the output axis above the input: centre distance ra + rb, or the
                # ring's radius less the pinion's; a ring stands beside its pinion
                out = axis + (abs(rb - ra) if internal else ra + rb)
                xa, xb = (x, x + INSIDE) if internal and rb > ra else (x, x)
                if internal and ra > rb:
                    xa, xb = x, x + INSIDE
                sk.line((shaft_from, axis), (xa + RIM, axis), "dashdot")
                _gear(sk, xa, axis, ra, names[0], open_to=1.0 if internal and ra > rb else 0.0)
                _gear(sk, xb, out, rb, names[1], open_to=-1.0 if internal and rb > ra else 0.0)
                axis, shaft_from = out, xb - RIM
                x = xb + STEP / 2
                continue
            assert isinstance(stage, PlanetaryStage)
            meshes = stage.meshes
            first = meshes[0]
            r_in, r_sat = (_radius(z) for z in first.z)
            d = abs(r_sat - r_in) if first.mesh == "internal" else r_in + r_sat
            sat = axis + d
            sk.line((shaft_from, axis), (x + RIM, axis), "dashdot")
            _gear(sk, x, axis, r_in, names[0])
            _gear(sk, x, sat, r_sat, names[1])
            xs = [x]
            for k, mesh in enumerate(meshes[1:], start=1):
                if names[2 * k] != names[2 * k - 1]:  # a block of satellites: the next one
                    x += STEP
                    _gear(sk, x, sat, _radius(mesh.z[0]), names[2 * k])
                xs.append(x)
            last = meshes[-1]
            r_sat2 = _radius(last.z[0])
            internal = last.mesh == "internal"
            r_fixed = max(d + r_sat2 if internal else d - r_sat2, 2.0)
            if internal:  # a ring beside the satellite, its rims over it
                x_fixed = x + INSIDE
            else:  # a sun gear: beside gear 3 when one satellite meshes with both
                x_fixed = x + (STEP / 2 if names[-2] == names[1] and len(meshes) == 2 else 0.0)
            if x_fixed != x:
                xs.append(x_fixed)
            _gear(
                sk, x_fixed, axis, r_fixed, names[-1], open_to=-1.0 if internal else 0.0, below=True
            )
            _ground(sk, x_fixed, axis - r_fixed - 1.5)
            sk.line((x_fixed, axis - r_fixed), (x_fixed, axis - r_fixed - 1.5), "main")
            # the carrier: its arm up to the satellites' axle, the axle through them
            xh = max(xs) + STEP
            sk.line((xh, axis), (xh, sat), "main")
            sk.line((xs[0] - 2 * RIM, sat), (xh, sat), "main")
            sk.text((xh + 1.2, (axis + sat) / 2), "H", TEXT, valign="middle")
            x, shaft_from = xh, xh
            x += STEP / 2
        # the output shaft, to the crank
        sk.line((shaft_from, axis), (x + LEAD, axis), "dashdot")
        sk.line((x + LEAD - 4.0, axis), (x + LEAD, axis), "main")
    return sk
