"""The answer keys of a variant (sheets, note, JSON), made on demand into a
cache beside the db by the library functions `batch` uses, and a zip of all."""

import io
import json
import shutil
import zipfile

import pytest

from mmt_plans.web.app import Settings, create_app
from tests.web.conftest import SEED003, TOKEN, VARIANT

AUTH = {"Authorization": f"Bearer {TOKEN}"}


@pytest.fixture(scope="module")
def one_variant(tmp_path_factory):
    root = tmp_path_factory.mktemp("keys")
    tasks = root / "tasks"
    tasks.mkdir()
    shutil.copy(SEED003 / f"{VARIANT}.toml", tasks / f"{VARIANT}.toml")
    app = create_app(Settings(tasks, root / "class.sqlite", TOKEN, burst=1e6, rate=1e6))
    return app, root


def test_keys_of_a_variant_are_made_once_into_the_cache(one_variant):
    app, root = one_variant
    c = app.test_client()
    html = c.get(f"/instructor/keys/{VARIANT}", headers=AUTH).get_data(as_text=True)
    names = ["note.pdf", "results.json", "sheet1.pdf", "sheet1.svg", "sheet2.pdf", "sheet2.svg"]
    for name in names:
        assert f'href="/instructor/keys/{VARIANT}/{name}"' in html
    cache = root / "class.keys" / "en" / VARIANT
    assert sorted(p.name for p in cache.iterdir() if not p.name.startswith(".")) == names
    r = c.get(f"/instructor/keys/{VARIANT}/results.json", headers=AUTH)
    data = json.loads(r.data)
    solution = app.extensions["mmt"]["tasks"].variant(VARIANT).solution
    assert data["forces"]["balancing_force_plans"] == solution.forces.balancing_force_plans
    assert c.get(f"/instructor/keys/{VARIANT}/note.pdf", headers=AUTH).data[:5] == b"%PDF-"
    for bad in ("../class.sqlite", ".mmt-batch.json", "nope.pdf"):
        assert c.get(f"/instructor/keys/{VARIANT}/{bad}", headers=AUTH).status_code == 404
    assert c.get("/instructor/keys/task99_v1", headers=AUTH).status_code == 404


def test_a_zip_of_every_variants_keys(one_variant):
    app, _ = one_variant
    r = app.test_client().get("/instructor/keys.zip", headers=AUTH)
    assert r.status_code == 200 and r.mimetype == "application/zip"
    names = zipfile.ZipFile(io.BytesIO(r.data)).namelist()
    assert f"{VARIANT}/sheet2.pdf" in names and f"{VARIANT}/note.pdf" in names
