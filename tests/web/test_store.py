"""The SQLite store: schema versioned and made on first start, WAL, nothing
lost when students submit at once or when the server restarts."""

import sqlite3
import threading

import pytest

from mmt_plans.web.db import SCHEMA_VERSION, Store
from tests.web.conftest import TOKEN, VARIANT, answers_toml, as_student, csrf, student_values


def test_the_schema_is_made_on_first_start_and_versioned(tmp_path):
    path = tmp_path / "sub" / "class.sqlite"
    store = Store(path)
    assert path.is_file() and store.schema_version == SCHEMA_VERSION == 1
    conn = sqlite3.connect(path)
    assert conn.execute("PRAGMA journal_mode").fetchone()[0] == "wal"
    tables = {r[0] for r in conn.execute("SELECT name FROM sqlite_master WHERE type = 'table'")}
    assert {"submission", "setting", "draft"} <= tables
    conn.close()
    Store(path)  # a second start changes nothing
    assert Store(path).schema_version == 1


def test_a_newer_schema_is_refused(tmp_path):
    path = tmp_path / "class.sqlite"
    Store(path)
    conn = sqlite3.connect(path)
    conn.execute("PRAGMA user_version = 99")
    conn.commit()
    conn.close()
    with pytest.raises(RuntimeError, match="newer"):
        Store(path)


def test_concurrent_submissions_are_all_kept(make_app, tmp_path):
    """Eight students submit five times each at once through the JSON door,
    into one app, and eight more through two apps (two processes' worth of
    connections) on the same file: every submission is there once."""
    db = tmp_path / "class.sqlite"
    apps = [make_app(db), make_app(db)]
    v = apps[0].extensions["mmt"]["tasks"].variant(VARIANT)
    text = answers_toml(student_values(v))
    errors = []
    start = threading.Barrier(16)

    def student(k):
        c = apps[k % 2].test_client()
        start.wait()
        for n in range(5):
            r = c.post(f"/api/check/{VARIANT}?name=s{k}&group=g{n}", data=text)
            if r.status_code != 200:
                errors.append((k, n, r.status_code, r.get_data(as_text=True)))

    threads = [threading.Thread(target=student, args=(k,)) for k in range(16)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert errors == []
    subs = Store(db).submissions()
    assert len(subs) == 80
    assert sorted((s.student, s.group) for s in subs) == sorted(
        (f"s{k}", f"g{n}") for k in range(16) for n in range(5)
    )
    assert len({s.id for s in subs}) == 80


def test_concurrent_writes_straight_to_the_store(tmp_path):
    db = tmp_path / "class.sqlite"
    Store(db)

    def write(k):
        store = Store(db)
        for n in range(25):
            store.add_submission(student=f"s{k}", group="g", variant="v", source="api", lang="en",
                                 answers="", report={"passed": True, "values": []})
            store.save_draft(f"c{k}", "v", {"f": str(n)})

    threads = [threading.Thread(target=write, args=(k,)) for k in range(8)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    store = Store(db)
    assert len(store.submissions()) == 200
    assert all(store.draft(f"c{k}", "v") == {"f": "24"} for k in range(8))


def test_a_restart_keeps_submissions_drafts_sessions_and_the_switch(make_app, tmp_path):
    db = tmp_path / "class.sqlite"
    first = make_app(db)
    c = first.test_client()
    as_student(c, "Taras", "MM-24")
    token = csrf(c, f"/variant/{VARIANT}")
    values = student_values(first.extensions["mmt"]["tasks"].variant(VARIANT))
    r = c.post(f"/variant/{VARIANT}/check", data={**values, "csrf": token})
    result = r.headers["Location"]
    first.extensions["mmt"]["store"].release_exact(True)
    del first  # the server stops

    second = make_app(db)  # and starts again on the same file
    c2 = second.test_client()
    c2._cookies = c._cookies  # the student's browser kept its cookie
    html = c2.get(result).get_data(as_text=True)
    assert '<b id="who-name">Taras</b>' in html and 'id="report"' in html
    assert f'value="{values["position|3|velocity|B"]}"' in html  # the values typed
    exact = second.extensions["mmt"]["tasks"].variant(VARIANT).solution.forces.balancing_force_plans
    assert f"{exact:.6g}" in html  # released before the restart, still released
    ins = second.test_client()
    listing = ins.get("/instructor", headers={"Authorization": f"Bearer {TOKEN}"}).get_data(as_text=True)
    assert "<td>Taras</td>" in listing and "<td>MM-24</td>" in listing
