"""The class's web page (mmt_plans/web) through Flask's test client: a
TASKS_DIR of two seed-003 variants copied into a temporary folder, a fresh
SQLite file per test."""

import re
import shutil
from pathlib import Path

import numpy as np
import pytest

pytest.importorskip("flask")

from mmt_plans.web.app import Settings, create_app  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]
SEED003 = ROOT / "samples" / "tasks" / "seed003"
TOKEN = "test-token-0123456789"
VARIANT = "task01_v1"


@pytest.fixture
def tasks_dir(tmp_path):
    folder = tmp_path / "tasks"
    folder.mkdir()
    for stem in (VARIANT, "task02_v1"):
        shutil.copy(SEED003 / f"{stem}.toml", folder / f"{stem}.toml")
    return folder


@pytest.fixture
def make_app(tasks_dir, tmp_path):
    def make(db=None, **kw):
        settings = dict(burst=10_000, rate=10_000)
        settings.update(kw)
        return create_app(Settings(tasks_dir, Path(db or tmp_path / "class.sqlite"), TOKEN, **settings))

    return make


@pytest.fixture
def app(make_app):
    return make_app()


@pytest.fixture
def client(app):
    return app.test_client()


def csrf(client, path="/"):
    """The form token of the client's session (from a page's hidden field)."""
    html = client.get(path).get_data(as_text=True)
    return re.search(r'name="csrf" value="([0-9a-f]+)"', html).group(1)


def as_student(client, name="Olena Koval", group="MM-21"):
    token = csrf(client)
    r = client.post("/student", data={"name": name, "group": group, "csrf": token})
    assert r.status_code == 302
    return token


def student_values(variant):
    """A student's values for task01_v1 that `check` passes, but F_bal by the
    force plans computed with the inertia forces and moments left out (the
    known mistake); the form's field names with their typed text."""
    from mmt_plans.forces import force_analysis_at

    s = variant.solution
    p = s.plan(3)
    fp = s.force_position
    wrong = force_analysis_at(s.state(fp), mu_l=s.mu_l, inertia_forces=(), inertia_moments=())
    return {
        "position|3|velocity|B": f"{np.hypot(*p.velocity_images['B']):.4g}",
        "position|3|velocity|C": f"{np.hypot(*p.velocity_images['C']):.4g}",
        "position|3|omega|2": f"{p.omega[2]:.4g}",
        f"forces|{fp}|balancing_force_plans|": f"{wrong.balancing_force_plans:.5g}",
        f"forces|{fp}|balancing_force_lever|": f"{s.forces.balancing_force_lever:.5g}",
    }


def answers_toml(values, force_position=3):
    """The same values as an answers file, written by hand for `mmt-plans check`."""
    return (
        "[[position]]\nindex = 3\n"
        f"velocity = {{ B = {values['position|3|velocity|B']}, C = {values['position|3|velocity|C']} }}\n"
        f"omega = {{ 2 = {values['position|3|omega|2']} }}\n\n"
        f"[forces]\nindex = {force_position}\n"
        f"balancing_force_plans = {values[f'forces|{force_position}|balancing_force_plans|']}\n"
        f"balancing_force_lever = {values[f'forces|{force_position}|balancing_force_lever|']}\n"
    )
