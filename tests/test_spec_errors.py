"""Every bad input gets a message naming the file, the entry and the fix,
exit code 2 and no traceback."""

import re
from pathlib import Path

import pytest
from click.testing import CliRunner

import mmt_plans
from mmt_plans.cli import main

PRESS = (Path(__file__).parents[1] / "samples" / "six_link_press.toml").read_text()


def edited(old: str, new: str) -> str:
    assert old in PRESS, old
    return PRESS.replace(old, new, 1)


CASES = [
    # (name, file text, entry expected in the message, words of the fix)
    ("misspelt key", edited("mass = 50", "mas = 50"), "link[2].mas", "did you mean 'mass'"),
    ("unknown section", PRESS + "\n[drives]\nlink = 1\n", "drives", "did you mean 'drive'"),
    ("point on one link only", edited('C = [750, -80]\n', ''), "link",
     "point C is used by link 3 only and is not on the frame"),
    ("slider link without a point", edited("points = { E = [0, 0] }", "points = {}"),
     "slider[1].link", "give link 5 a point"),
    ("guide on a missing link", edited("on = 0", "on = 9"), "slider[1].on", "does not exist"),
    ("zero length", edited("points = { A = [0, 0], B = [850, 0] }",
                           "points = { A = [0, 0], B = [0, 0] }"),
     "link[2] (id 2).points", "coincide"),
    ("negative mass", edited("mass = 50", "mass = -50"), "link[2] (id 2).mass", "must not be negative"),
    ("negative J", edited("mass = 50", "mass = 50\nJ = -1"), "link[2] (id 2).J", "must not be negative"),
    ("rpm and gears", PRESS + "\n[gears]\nmotor_rpm = 1450\n[[gears.stage]]\nz = [20, 40]\n"
     "mesh = \"external\"\n", "drive", "keep one of"),
    ("unknown output", edited('output = "E"', 'output = "Q"'), "study.output", "does not exist"),
    ("W is not 1", edited("[[slider]]\nlink = 5\non = 0\nthrough = [0, 700]\nangle = 0\n", ""),
     "link", "W = 3n - 2p5 - p4 = 3*5 - 2*6 - 0 = 3, not 1"),
    ("force point not on its link", edited('at = "E"', 'at = "B"'), "force[1].at", "not on link 5"),
    ("force on an unknown link", edited("link = 5\nat", "link = 7\nat"), "force[1].link",
     "link 7 does not exist"),
    ("zero-length crank", edited("points = { O = [0, 0], A = [200, 0] }",
                                 "points = { O = [0, 0], A = [0, 0] }"),
     "link[1] (id 1).points", "coincide"),
    ("bad TOML", PRESS.replace("[drive]", "[drive"), "TOML", "fix the TOML syntax"),
]


@pytest.mark.parametrize("name,text,entry,fix", CASES, ids=[c[0] for c in CASES])
def test_bad_input_is_reported_cleanly(tmp_path, name, text, entry, fix):
    path = tmp_path / "bad.toml"
    path.write_text(text)
    with pytest.raises(mmt_plans.SpecError) as err:
        mmt_plans.load(path)
    message = str(err.value)
    assert message.startswith(str(path)), message
    assert f": {entry}:" in message, message
    assert fix in message, message

    result = CliRunner().invoke(main, ["analyze", str(path)])
    assert result.exit_code == 2
    assert "Traceback" not in result.output
    assert str(path) in result.output and entry in result.output


def test_missing_file_is_reported(tmp_path):
    result = CliRunner().invoke(main, ["analyze", str(tmp_path / "none.toml")])
    assert result.exit_code == 2 and "cannot be read" in result.output


def test_position_that_cannot_assemble_is_named(tmp_path):
    # AB = 500 and CB = 300 mm: at phi1 = 180 deg |AC| = sqrt(950² + 80²) = 953.362 mm > 800 mm
    text = edited("points = { C = [0, 0], B = [1000, 0], D = [600, 0] }",
                  "points = { C = [0, 0], B = [300, 0], D = [200, 0] }")
    text = text.replace("points = { A = [0, 0], B = [850, 0] }", "points = { A = [0, 0], B = [500, 0] }")
    path = tmp_path / "short.toml"
    path.write_text(text)
    mech = mmt_plans.load(path)
    sw = mmt_plans.sweep(mech, [0.0, 90.0, 180.0, 270.0])
    bad = [k for k in range(4) if not sw.ok[k]]
    assert bad, "the shortened rocker should fail somewhere"
    err = sw.problem(bad[0])
    assert isinstance(err, mmt_plans.AssemblyError)
    assert err.group == "2-3"
    assert 2 in bad  # phi1 = 180
    assert "links 2 and 3 cannot reach: |AC| = 0.953362 m" in str(sw.problem(2))
    assert "> l2 + l3 = 0.8 m" in str(sw.problem(2))
    assert re.search(r"at phi1 = \d+ deg, group 2-3 cannot assemble", str(err))
