"""`mmt-plans serve samples/tasks/seed003` serves every seed-003 variant: its
page with the scheme and the form, and every field of the form is a value
the check's own loader takes."""

from pathlib import Path

import pytest

from mmt_plans.web.app import Settings, create_app
from tests.web.conftest import SEED003, TOKEN

STEMS = sorted(p.stem for p in SEED003.glob("*.toml"))


@pytest.fixture(scope="module")
def app(tmp_path_factory):
    db = tmp_path_factory.mktemp("seed003") / "class.sqlite"
    return create_app(Settings(SEED003, Path(db), TOKEN, burst=1e6, rate=1e6))


def test_there_are_55_variants():
    assert len(STEMS) == 55


@pytest.mark.parametrize("stem", STEMS)
def test_every_variant_is_served_and_its_form_is_what_check_takes(app, stem):
    from mmt_plans.check import loads_answers
    from mmt_plans.web.answers import answers_from_fields, dump_toml

    html = app.test_client().get(f"/variant/{stem}").get_data(as_text=True)
    assert html.count("<svg") == 1
    v = app.extensions["mmt"]["tasks"].variant(stem)
    fields = v.fields()
    assert all(f'name="{fid}"' in html for fid in fields)
    form = {fid: ("no" if f.choice else "1") for fid, f in fields.items()}
    data, errors = answers_from_fields(fields, form)
    assert errors == []
    assert len(loads_answers(dump_toml(data), v.solution).values) == len(fields)
