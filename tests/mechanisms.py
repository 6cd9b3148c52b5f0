"""Mechanism files the tests build with other numbers: the slider-crank and
the four-bar of the textbook, as TOML text (lengths in mm)."""

from __future__ import annotations


def slider_crank_toml(r: float, l: float, e: float = 0.0, *, drive: str = "rpm = 100",
                      extra: str = "") -> str:
    """Crank OA = r, rod AB = l, slider B on a horizontal guide e above O."""
    return f"""
[drive]
{drive}
[study]
output = "B"
[frame]
O = [0, 0]
[[link]]
id = 1
points = {{ O = [0, 0], A = [{r}, 0] }}
[[link]]
id = 2
points = {{ A = [0, 0], B = [{l}, 0] }}
[[link]]
id = 3
points = {{ B = [0, 0] }}
[[slider]]
link = 3
through = [0, {e}]
{extra}"""


def four_bar_toml(r: float, d: float, l: float, c: float, *, rpm: float = 100,
                  extra: str = "") -> str:
    """Crank OA = r, coupler AB = l, rocker CB = c, frame OC = d along x."""
    return f"""
[drive]
rpm = {rpm}
[study]
output = "B"
[frame]
O = [0, 0]
C = [{d}, 0]
[[link]]
id = 1
points = {{ O = [0, 0], A = [{r}, 0] }}
[[link]]
id = 2
points = {{ A = [0, 0], B = [{l}, 0] }}
[[link]]
id = 3
points = {{ C = [0, 0], B = [{c}, 0] }}
{extra}"""
