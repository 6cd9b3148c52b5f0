"""The fuzzer in the suite: 300 seeded mutants of the samples keep the
property of tests/fuzz.py (load, analyze, to_json: finite results or an
MmtError with a well-formed message, each under 5 s), and CLI reproducers of
what fuzzing found, run as `python -m mmt_plans` in subprocesses: exit code 2
(or 0 with finite output), one `error:` line, no traceback.

`make fuzz` runs 20,000 mutants (tests/fuzz.py)."""

from __future__ import annotations

import json
import math
import os
import subprocess
import sys
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import pytest

import fuzz

ROOT = Path(__file__).resolve().parents[1]
PRESS = (ROOT / "samples" / "six_link_press.toml").read_text(encoding="utf-8")
# the press without its Ukrainian title: text that Latin-1 can encode
LATIN = "\n".join(line for line in PRESS.splitlines() if not line.startswith("title_uk"))
SMALL = (ROOT / "samples" / "offset_slider_crank.toml").read_text(encoding="utf-8")
ANSWERS = ROOT / "samples" / "answers" / "six_link_press.answers.toml"


def test_mutants_keep_the_property():
    t0 = time.perf_counter()
    counts, findings = fuzz.run(seed=2024, cases=300, draw_every=30)
    print(f"\nfuzz: 300 mutants in {time.perf_counter() - t0:.1f} s: {dict(counts)}")
    report = "\n".join(f"{m.describe()}\n  -> {o.kind} ({o.seconds:.1f} s): {o.detail}"
                       for m, o in findings)
    assert not findings, report
    assert counts["analysed"] > 20 and counts["clean error"] > 100  # the mutants reach both


def test_a_mutant_is_reproducible():
    a, b = fuzz.mutant(7, 123), fuzz.mutant(7, 123)
    assert a.data == b.data and a.steps == b.steps and a.source == b.source


def test_the_toml_writer_round_trips():
    import tomllib

    data = {"title": 'a "q" \\ \x00 \x7f Ж 𝔸', "x": [1, -0.0, 1e308, 5e-324, 2**63 - 1],
            "t": {"a b": {"c": [{"d": True}]}}, "e": []}
    back = tomllib.loads(fuzz.dumps(data))
    assert back == data | {"x": back["x"]} and back["x"][2] == 1e308
    assert math.isnan(tomllib.loads(fuzz.dumps({"n": math.nan}))["n"])


# --- CLI reproducers --------------------------------------------------------------------

def _edit(text: str, old: str, new: str) -> str:
    assert old in text, old
    return text.replace(old, new, 1)


def _chain(n_links: int) -> str:
    links = "".join(f"[[link]]\nid = {i}\npoints = {{ P{i} = [0, 0], P{i + 1} = [100, 0] }}\n"
                    for i in range(1, n_links + 1))
    return ('[drive]\nrpm = 60\n[study]\noutput = "P2"\n[frame]\nP1 = [0, 0]\n' + links)


def _frame_points(n: int) -> str:
    return _edit(SMALL, "O = [0, 0]\n", "O = [0, 0]\n" + "".join(f"F{i} = [{i % 1000}, 1]\n"
                                                                for i in range(n)))


GEARS = '\n[gears]\nmotor_rpm = 1e308\n[[gears.stage]]\nz = [20, 40]\nmesh = "external"\n'

# name: (file contents (str: UTF-8 text, bytes: as is), command after the file, exit code,
# words of the message)
MECHANISMS: dict[str, tuple[str | bytes, list[str], int, str]] = {
    "positions 2": (_edit(PRESS, "positions = 12", "positions = 2"), [], 2, "study.positions"),
    "positions 3": (_edit(PRESS, "positions = 12", "positions = 3"), [], 2, "study.positions"),
    "positions 2**63-1": (_edit(PRESS, "positions = 12", f"positions = {2**63 - 1}"), [], 2,
                          "study.positions"),
    "positions 10**30": (_edit(PRESS, "positions = 12", f"positions = {10**30}"), [], 2,
                         "study.positions"),
    "positions 1000000": (_edit(PRESS, "positions = 12", "positions = 1000000"), [], 2,
                          "study.positions"),
    "draw 2000 positions": (_edit(PRESS, "positions = 12", "positions = 2000"),
                            ["draw", "-o", "{tmp}/out2000"], 2, "study.positions"),
    "plans []": (_edit(PRESS, "plans = [2, 8]", "plans = []"), [], 2, "study.plans"),
    "force at []": (_edit(PRESS, 'at = "E"', "at = []"), [], 2, "force[1].at"),
    "force at ['E']": (_edit(PRESS, 'at = "E"', 'at = ["E"]'), [], 2, "force[1].at"),
    "higher pair [[1], 2]": (PRESS + "\n[[higher_pair]]\nlinks = [[1], 2]\n", [], 2,
                             "higher_pair[1].links"),
    "zero nan": (_edit(PRESS, 'zero = "extreme"', "zero = nan"), [], 2, "study.zero"),
    "angles [inf]": (_edit(PRESS, "angles = []", "angles = [inf]"), [], 2, "study.angles"),
    "rpm 1e308": (_edit(PRESS, "rpm = 100", "rpm = 1e308"), [], 2, "drive.rpm"),
    "rpm 5e-324": (_edit(PRESS, "rpm = 100", "rpm = 5e-324"), [], 2, "drive.rpm"),
    "motor_rpm 1e308": (_edit(PRESS, "rpm = 100", "") + GEARS, [], 2, "gears.motor_rpm"),
    "mass 1e308": (_edit(PRESS, "mass = 50", "mass = 1e308"), [], 2, "link[2] (id 2).mass"),
    "coordinates 1e300 mm": (_edit(PRESS, "B = [850, 0]", "B = [1e300, 0]"), [], 2,
                             "link[2] (id 2).points.B"),
    "title with U+0000": (_edit(PRESS, 'title = "Six-link press (crank, rocker, slider)"',
                                'title = "a\\u0000b"'),
                          ["draw", "-o", "{tmp}/nul", "--format", "svg"], 2, "title"),
    "name with a newline": (_edit(PRESS, 'output = "E"', 'output = "E\\nQ"'), [], 2,
                            "point 'E\\nQ' does not exist"),
    "501 links": (_chain(501), [], 2, "501 links, more than the 25"),
    "500000 frame points": (_frame_points(500_000), [], 2, "more than the 1,000,000 a mechanism file"),
    "nested 1000 deep": (PRESS + "\nx = " + "[" * 1000 + "]" * 1000 + "\n", [], 2,
                         "nested too deeply"),
    "Latin-1 file": (LATIN.replace("Six-link", "Café").encode("latin-1"), [], 2,
                     "not UTF-8 text: byte 0xE9"),
    "UTF-16 file": (PRESS.encode("utf-16"), [], 2, "UTF-16"),
    "binary file": (bytes(range(256)) * 64, [], 2, "NUL byte"),
    "UTF-8 with BOM": (b"\xef\xbb\xbf" + SMALL.encode("utf-8"),
                       ["analyze", "--json", "{tmp}/bom.json", "--quiet"], 0, ""),
    "-o under a file": (SMALL, ["draw", "-o", "{tmp}/a_file/sub"], 2, "is a file, not a folder"),
    "--json under a file": (SMALL, ["analyze", "--json", "{tmp}/a_file/r.json"], 2,
                            "is a file, not a folder"),
    "--json onto a folder": (SMALL, ["analyze", "--json", "{tmp}"], 2, "is a directory"),
    "check --tolerance nan": (PRESS, ["check", "{answers}", "--tolerance", "nan"], 2,
                              "not a percentage"),
    "check --tolerance inf": (PRESS, ["check", "{answers}", "--tolerance", "inf"], 2,
                              "not a percentage"),
    "answers mu_V 1e308": (PRESS, ["check", "{tmp}/mu_big.answers.toml"], 2, "mu_V"),
    "answers mu_V 5e-324": (PRESS, ["check", "{tmp}/mu_tiny.answers.toml"], 2, "mu_V"),
    "answers in Latin-1": (PRESS, ["check", "{tmp}/latin.answers.toml"], 2, "not UTF-8"),
}

SPECIAL = {"/dev/zero": "/dev/zero", "FIFO": "fifo.toml"}
for _name in SPECIAL:
    MECHANISMS[_name] = ("", [], 2, "is a device" if _name == "/dev/zero" else "FIFO")


@pytest.fixture(scope="module")
def cli_runs(tmp_path_factory):
    """Every reproducer run at once (two at a time), as `python -m mmt_plans`."""
    tmp = tmp_path_factory.mktemp("cli")
    (tmp / "a_file").write_text("")
    (tmp / "mu_big.answers.toml").write_text("[[position]]\nindex = 2\nmu_V = 1e308\n"
                                             "velocity_plan_mm = { pb = 146 }\n")
    (tmp / "mu_tiny.answers.toml").write_text("[[position]]\nindex = 2\nmu_V = 5e-324\n"
                                              "velocity_plan_mm = { pb = 146 }\n")
    (tmp / "latin.answers.toml").write_bytes("# é\n[[position]]\nindex = 2\n".encode("latin-1"))
    if hasattr(os, "mkfifo"):
        os.mkfifo(tmp / "fifo.toml")
    jobs = []
    for k, (name, (content, command, _, _)) in enumerate(MECHANISMS.items()):
        if name in SPECIAL:
            path = SPECIAL[name] if name == "/dev/zero" else str(tmp / SPECIAL[name])
        else:
            path = str(tmp / f"case{k}.toml")
            data = content if isinstance(content, bytes) else content.encode("utf-8")
            Path(path).write_bytes(data)
        words = [w.format(tmp=tmp, answers=ANSWERS) for w in command]
        if not words:
            args = ["analyze", path]
        elif words[0] == "check":
            args = ["check", path, *words[1:]]
        else:
            args = [words[0], path, *words[1:]]
        jobs.append((name, args))

    def run(job):
        name, args = job
        t0 = time.perf_counter()
        proc = subprocess.run([sys.executable, "-m", "mmt_plans", *args], capture_output=True,
                              text=True, timeout=120, cwd=tmp,
                              env={**os.environ, "PYTHONWARNINGS": "default"})
        return name, (proc, time.perf_counter() - t0, tmp)

    with ThreadPoolExecutor(max_workers=2) as pool:
        return dict(pool.map(run, jobs))


@pytest.mark.parametrize("name", list(MECHANISMS))
def test_cli_reproducer(cli_runs, name):
    if name == "FIFO" and not hasattr(os, "mkfifo"):
        pytest.skip("no FIFOs here")
    if name == "/dev/zero" and not Path("/dev/zero").exists():
        pytest.skip("no /dev/zero")
    _, _, code, words = MECHANISMS[name]
    proc, seconds, tmp = cli_runs[name]
    everything = proc.stdout + proc.stderr
    assert proc.returncode == code, everything
    assert "Traceback" not in everything and "Warning" not in everything, everything
    assert seconds < 30, seconds
    if code == 2:
        errors = [line for line in proc.stderr.splitlines() if line.lower().startswith("error:")]
        assert len(errors) == 1, proc.stderr
        assert words in proc.stderr, proc.stderr
        assert all(line.isprintable() for line in proc.stderr.splitlines())
    else:
        from mmt_plans.files import first_non_finite

        data = json.loads((tmp / "bom.json").read_text(encoding="utf-8"))
        assert data["schema"] == "mmt_plans/results@1" and first_non_finite(data) is None
