"""Every route of the class's web page through Flask's test client: the
student pages, the check and its withheld exact values, the JSON door, the
instructor's pages behind the token, and bad input at every door."""

import csv
import io
import json
import re
import subprocess
import sys

import pytest

from tests.web.conftest import (
    SEED003,
    TOKEN,
    VARIANT,
    answers_toml,
    as_student,
    csrf,
    student_values,
)

CAUSE_INERTIA = "inertia forces and moments of links 2–5 left out"


def variant(app, stem=VARIANT):
    return app.extensions["mmt"]["tasks"].variant(stem)


def cli_report(tmp_path, text, stem=VARIANT, lang="en"):
    """`mmt-plans check --json` on the same values, in its own process."""
    answers = tmp_path / "answers.toml"
    answers.write_text(text, encoding="utf-8")
    out = tmp_path / "report.json"
    subprocess.run(
        [sys.executable, "-m", "mmt_plans", "check", str(SEED003 / f"{stem}.toml"), str(answers),
         "--json", str(out), "--lang", lang],
        capture_output=True,
        check=False,
    )
    return json.loads(out.read_text(encoding="utf-8"))


def rows(html):
    """(what, result, cause) of each row of the page's report table."""
    body = html.split('id="report"', 1)[1].split("</table>", 1)[0]
    out = []
    for m in re.finditer(r'<tr class="(pass|fail)" data-what="([^"]*)".*?<td class="cause">(.*?)</td>', body, re.S):
        out.append((m.group(2), m.group(1) == "pass", m.group(3).strip() or None))
    return out


# --- the student's pages ------------------------------------------------------------


def test_index_lists_every_variant_of_tasks_dir(client):
    html = client.get("/").get_data(as_text=True)
    assert 'href="/variant/task01_v1"' in html and 'href="/variant/task02_v1"' in html


def test_index_serves_every_seed003_variant(make_app, tmp_path):
    from mmt_plans.web.app import Settings, create_app

    app = create_app(Settings(SEED003, tmp_path / "c.sqlite", TOKEN))
    html = app.test_client().get("/").get_data(as_text=True)
    stems = sorted(p.stem for p in SEED003.glob("*.toml"))
    assert len(stems) == 55
    assert all(f'href="/variant/{s}"' in html for s in stems)


def test_variant_page_shows_scheme_given_data_and_the_form(client):
    r = client.get(f"/variant/{VARIANT}")
    html = r.get_data(as_text=True)
    assert r.status_code == 200
    assert html.count("<svg") == 1 and "osifont" in html  # the task sheet's scheme, its lettering
    assert "Task 1, variant 1" in html
    # given: n1 = 100 rpm, l_AB = 800 mm, m4 = 80 kg (the task file's table)
    assert re.search(r"n<sub>1</sub></span></td><td class=\"num\">100</td><td>rpm", html)
    assert re.search(r"l<sub>AB</sub></span></td><td class=\"num\">800</td><td>mm", html)
    assert re.search(r"m<sub>4</sub></span></td><td class=\"num\">80</td><td>kg", html)
    # the form: sheet 1 at both investigated positions, sheet 2 at the force position
    for name in ("position|3|velocity|B", "position|9|eps|4", "position|3|mu_V|",
                 "diagrams|3|dV_percent|3", "diagrams||check_passed|",
                 "forces|3|reactions|R12", "forces|3|weights|5", "forces|3|balancing_moment|"):
        assert f'name="{name}"' in html, name
    assert 'name="position|3|velocity|O1"' not in html  # a frame point moves not


def test_the_form_asks_what_the_check_accepts(app):
    """Every field of the form, filled with 1, is a value the check's own
    loader takes (no unknown key, point, link or reaction)."""
    from mmt_plans.check import loads_answers
    from mmt_plans.web.answers import answers_from_fields, dump_toml

    v = variant(app)
    fields = v.fields()
    form = {fid: ("yes" if f.choice else "1") for fid, f in fields.items()}
    data, errors = answers_from_fields(fields, form)
    assert errors == []
    answers = loads_answers(dump_toml(data), v.solution)
    assert len(answers.values) == len(fields)


def test_unknown_variant_and_paths_outside_tasks_dir_are_404(client, tasks_dir):
    (tasks_dir.parent / "secret.toml").write_text((SEED003 / f"{VARIANT}.toml").read_text())
    for path in ("/variant/nope", "/variant/..%2Fsecret", "/variant/../secret",
                 "/variant/%2E%2E", "/variant/.hidden", "/variant/" + "a" * 300):
        assert client.get(path).status_code == 404, path
    r = client.post("/api/check/..%2Fsecret", data="x = 1")
    assert r.status_code == 404 and r.is_json


def test_a_student_gives_name_and_group_once(client):
    as_student(client)
    html = client.get(f"/variant/{VARIANT}").get_data(as_text=True)
    assert '<b id="who-name">Olena Koval</b>, MM-21' in html


@pytest.mark.parametrize("name", ["", "   ", "x" * 101, "a\nb", "a\x1b[31m"])
def test_a_bad_name_is_refused(client, name):
    token = csrf(client)
    r = client.post("/student", data={"name": name, "group": "G", "csrf": token})
    assert r.status_code == 400


def test_a_student_named_script_is_text(client, app):
    as_student(client, name="<script>alert(1)</script>", group="<b>G</b>")
    html = client.get("/").get_data(as_text=True)
    assert "<script>" not in html and "&lt;script&gt;alert(1)&lt;/script&gt;" in html
    token = csrf(client, f"/variant/{VARIANT}")
    values = student_values(variant(app))
    client.post(f"/variant/{VARIANT}/check", data={**values, "csrf": token})
    ins = app.test_client()
    html = ins.get("/instructor", headers={"Authorization": f"Bearer {TOKEN}"}).get_data(as_text=True)
    assert "<script>" not in html and "&lt;script&gt;" in html and "&lt;b&gt;G&lt;/b&gt;" in html


def test_pages_carry_a_content_security_policy(client):
    r = client.get("/")
    assert "script-src" not in r.headers["Content-Security-Policy"]  # default-src 'none': no script
    assert r.headers["X-Content-Type-Options"] == "nosniff"


def test_the_check_gives_verdicts_and_causes_as_check_does_without_the_exact_values(
    client, app, tmp_path
):
    as_student(client)
    v = variant(app)
    values = student_values(v)
    token = csrf(client, f"/variant/{VARIANT}")
    r = client.post(f"/variant/{VARIANT}/check", data={**values, "csrf": token})
    assert r.status_code == 302 and "result=" in r.headers["Location"]
    html = client.get(r.headers["Location"]).get_data(as_text=True)
    cli = cli_report(tmp_path, answers_toml(values))
    page = rows(html)
    assert [(x["what"], x["passed"], x["cause"]) for x in cli["values"]] == page
    assert ("F_bal (plans)", False, CAUSE_INERTIA) in page
    # no exact value on the page (F_bal, V_B … as check's table prints them)
    for x in cli["values"]:
        assert f"{x['exact']:.6g}" not in html
    assert "withheld" in html


def test_released_exact_values_show(client, app):
    app.extensions["mmt"]["store"].release_exact(True)
    as_student(client)
    values = student_values(variant(app))
    token = csrf(client, f"/variant/{VARIANT}")
    r = client.post(f"/variant/{VARIANT}/check", data={**values, "csrf": token})
    html = client.get(r.headers["Location"]).get_data(as_text=True)
    exact = variant(app).solution.forces.balancing_force_plans
    given = float(values["forces|3|balancing_force_plans|"])
    assert f"{exact:.6g}" in html and f"{(given - exact) / exact * 100:+.2f}" in html


def test_a_result_is_shown_only_to_its_student(client, app):
    as_student(client)
    token = csrf(client, f"/variant/{VARIANT}")
    r = client.post(f"/variant/{VARIANT}/check", data={**student_values(variant(app)), "csrf": token})
    other = app.test_client()
    html = other.get(r.headers["Location"]).get_data(as_text=True)
    assert 'id="report"' not in html


def test_entered_values_survive_a_failed_submission_and_a_reload(client):
    as_student(client)
    token = csrf(client, f"/variant/{VARIANT}")
    data = {"position|3|velocity|B": "2,724", "position|3|velocity|C": "two", "csrf": token}
    r = client.post(f"/variant/{VARIANT}/check", data=data)
    html = r.get_data(as_text=True)
    assert r.status_code == 400
    assert 'name="position|3|velocity|C" value="two"' in html and "not a number" in html
    html = client.get(f"/variant/{VARIANT}").get_data(as_text=True)  # a reload
    assert 'name="position|3|velocity|B" value="2,724"' in html
    assert 'name="position|3|velocity|C" value="two"' in html


def test_a_value_out_of_the_clis_limits_is_refused_by_its_message(client):
    as_student(client)
    token = csrf(client, f"/variant/{VARIANT}")
    r = client.post(f"/variant/{VARIANT}/check", data={"position|3|velocity|B": "-2", "csrf": token})
    assert r.status_code == 400
    assert "is a magnitude and must not be negative" in r.get_data(as_text=True)
    r = client.post(f"/variant/{VARIANT}/check", data={"position|3|omega|2": "1e16", "csrf": token})
    assert "out of the range this tool accepts" in r.get_data(as_text=True)
    r = client.post(f"/variant/{VARIANT}/check", data={"position|3|omega|2": "nan", "csrf": token})
    assert r.status_code == 400 and "not a number" in r.get_data(as_text=True)


def test_an_empty_form_and_a_form_without_a_student(client):
    token = csrf(client, f"/variant/{VARIANT}")
    r = client.post(f"/variant/{VARIANT}/check", data={"position|3|velocity|B": "1", "csrf": token})
    assert r.status_code == 400 and "name and group first" in r.get_data(as_text=True)
    as_student(client)
    r = client.post(f"/variant/{VARIANT}/check", data={"csrf": token})
    assert r.status_code == 400 and "at least one value" in r.get_data(as_text=True)


def test_a_form_without_its_token_is_refused(client):
    as_student(client)
    r = client.post(f"/variant/{VARIANT}/check", data={"position|3|velocity|B": "1"})
    assert r.status_code == 400
    r = client.post("/student", data={"name": "a", "group": "b", "csrf": "0" * 32})
    assert r.status_code == 400


def test_a_pasted_answers_file_is_checked_as_check_does(client, app, tmp_path):
    as_student(client)
    text = answers_toml(student_values(variant(app))) + "\n[student]\nname = \"x\"\n"
    token = csrf(client, f"/variant/{VARIANT}")
    r = client.post(f"/variant/{VARIANT}/check", data={"answers_toml": text, "csrf": token})
    assert r.status_code == 302
    html = client.get(r.headers["Location"]).get_data(as_text=True)
    cli = cli_report(tmp_path, answers_toml(student_values(variant(app))))
    assert [(x["what"], x["passed"], x["cause"]) for x in cli["values"]] == rows(html)


@pytest.mark.parametrize(
    "text, message",
    [
        ("[[position]]\nindex = 3\nvelocty = { B = 1 }\n", "unknown key"),
        ("[[position]]\nindex = 3\nvelocity = { Q = 1 }\n", "point Q does not exist"),
        ("[[position]]\nindex = 30\nvelocity = { B = 1 }\n", "position 30 does not exist"),
        ("[[position]\n", "TOML"),
        ("[[position]]\nindex = 3\nvelocity = { B = \"fast\" }\n", "must be a number"),
    ],
)
def test_a_bad_pasted_file_names_the_entry(client, text, message):
    as_student(client)
    token = csrf(client, f"/variant/{VARIANT}")
    r = client.post(f"/variant/{VARIANT}/check", data={"answers_toml": text, "csrf": token})
    html = r.get_data(as_text=True)
    assert r.status_code == 400 and message in html
    assert "velocty" not in text or "velocty" in html


def test_pages_in_ukrainian(client, app):
    html = client.get(f"/variant/{VARIANT}?lang=uk").get_data(as_text=True)
    assert "Кінематична схема" in html and "м/с" in html and "Завдання 1, варіант 1" in html
    assert "F<sub>зр</sub>" in html  # the sheets' index of the balancing force
    as_student(client)
    token = csrf(client, f"/variant/{VARIANT}")
    values = student_values(variant(app))
    r = client.post(f"/variant/{VARIANT}/check", data={**values, "csrf": token})
    html = client.get(r.headers["Location"]).get_data(as_text=True)
    assert "НІ" in html and "інерції" in html  # the cause from the uk catalogue


# --- the JSON door ----------------------------------------------------------------------


def test_api_answers_checks_json_report_with_exact_null(client, app, tmp_path):
    text = answers_toml(student_values(variant(app)))
    r = client.post(f"/api/check/{VARIANT}", data='[student]\nname = "Ivan"\ngroup = "MM-22"\n' + text)
    assert r.status_code == 200
    got = r.get_json()
    cli = cli_report(tmp_path, text)
    assert set(got) == set(cli) and got["passed"] == cli["passed"] is False
    for g, c in zip(got["values"], cli["values"], strict=True):
        assert set(g) == set(c)
        assert g["exact"] is None and g["error_percent"] is None
        assert (g["what"], g["position"], g["unit"], g["given"], g["passed"], g["cause"]) == (
            c["what"], c["position"], c["unit"], c["given"], c["passed"], c["cause"])
    sub = app.extensions["mmt"]["store"].submissions()
    assert [(s.student, s.group, s.variant, s.source, s.passed) for s in sub] == [
        ("Ivan", "MM-22", VARIANT, "api", False)]


def test_api_takes_the_student_from_the_query(client, app):
    text = answers_toml(student_values(variant(app)))
    r = client.post(f"/api/check/{VARIANT}?name=Petro&group=MM-23", data=text)
    assert r.status_code == 200
    assert app.extensions["mmt"]["store"].submissions()[0].student == "Petro"


def test_api_released_gives_the_exact_values(client, app):
    app.extensions["mmt"]["store"].release_exact(True)
    text = answers_toml(student_values(variant(app)))
    got = client.post(f"/api/check/{VARIANT}?name=a&group=b", data=text).get_json()
    assert all(v["exact"] is not None for v in got["values"])


def test_api_withholds_the_number_of_a_sign_cause(client, app):
    """"sign or direction swapped: the exact value is X" says the exact value:
    its number is withheld too."""
    w2 = variant(app).solution.plan(3).omega[2]
    text = f"[[position]]\nindex = 3\nomega = {{ 2 = {-w2:.4g} }}\n"
    got = client.post(f"/api/check/{VARIANT}?name=a&group=b", data=text).get_json()
    cause = got["values"][0]["cause"]
    assert cause == "sign or direction swapped: the exact value is …"


@pytest.mark.parametrize(
    "body, query, message",
    [
        (b"[[position]]\nindex = 3\nvelocity = { B = 1 }\n", "", "name and group"),
        (b"[[position]\n", "?name=a&group=b", "TOML"),
        (b"[student]\nname = 5\ngroup = \"g\"\n", "", "student.name"),
        (b"[student]\nname = \"a\"\ngroup = \"g\"\nage = 3\n", "", "student.age"),
        (b"\xff\xfe[", "?name=a&group=b", "UTF-8"),
        (b"[[position]]\nindex = 3\nvelocity = { B = 1e16 }\n", "?name=a&group=b", "out of the range"),
        (b"", "?name=a&group=b", "no value"),
    ],
)
def test_api_bad_input_is_400_with_the_message(client, body, query, message):
    r = client.post(f"/api/check/{VARIANT}{query}", data=body)
    assert r.status_code == 400 and r.is_json
    assert message in r.get_json()["error"]


def test_api_unknown_variant_is_404(client):
    r = client.post("/api/check/task99_v9?name=a&group=b", data=b"x")
    assert r.status_code == 404 and r.is_json


def test_a_request_over_the_size_limit_is_413(client):
    r = client.post(f"/api/check/{VARIANT}?name=a&group=b", data=b"#" * 1_200_000)
    assert r.status_code == 413


def test_a_client_over_its_rate_gets_429(make_app):
    app = make_app(burst=12, rate=0.001, check_cost=6)
    c = app.test_client()
    codes = [c.post(f"/api/check/{VARIANT}?name=a&group=b", data=b"").status_code for _ in range(3)]
    assert codes == [400, 400, 429]
    r = c.get("/")
    assert r.status_code == 429 and int(r.headers["Retry-After"]) > 0
    # another computer is not held up
    other = app.test_client()
    assert other.get("/", environ_base={"REMOTE_ADDR": "10.0.0.2"}).status_code == 200


# --- the instructor's pages ------------------------------------------------------------------

INSTRUCTOR_GETS = ["/instructor", "/instructor/submissions.csv", "/instructor/values.csv", "/instructor/submission/1",
                   "/instructor/keys/task01_v1", "/instructor/keys/task01_v1/results.json",
                   "/instructor/keys.zip"]
INSTRUCTOR_POSTS = ["/instructor/release", "/instructor/upload"]


@pytest.mark.parametrize("path", INSTRUCTOR_GETS + INSTRUCTOR_POSTS)
def test_instructor_routes_are_401_without_the_token_and_403_with_a_wrong_one(client, path):
    send = client.post if path in INSTRUCTOR_POSTS else client.get
    assert send(path).status_code == 401
    assert send(path, headers={"Authorization": "Bearer wrong"}).status_code == 403
    assert send(path + "?token=wrong").status_code == 403


def test_the_token_signs_in_and_out(client):
    r = client.get("/instructor")
    assert r.status_code == 401 and 'name="token"' in r.get_data(as_text=True)
    token = csrf(client)
    assert client.post("/instructor/login", data={"token": "nope", "csrf": token}).status_code == 403
    r = client.post("/instructor/login", data={"token": TOKEN, "csrf": token})
    assert r.status_code == 302
    assert client.get("/instructor").status_code == 200
    client.post("/instructor/logout")
    assert client.get("/instructor").status_code == 401


def test_the_token_in_the_address_is_taken_off_it(client):
    r = client.get(f"/instructor?token={TOKEN}")
    assert r.status_code == 302 and "token" not in r.headers["Location"]
    assert client.get("/instructor").status_code == 200


def test_a_session_of_another_token_does_not_sign_in(make_app, tmp_path, tasks_dir):
    """A new token at a restart (the same db, the same cookie key): the old
    session is no longer the instructor's."""
    from mmt_plans.web.app import Settings, create_app

    db = tmp_path / "class.sqlite"
    first = make_app(db)
    c = first.test_client()
    c.get(f"/instructor?token={TOKEN}")
    second = create_app(Settings(tasks_dir, db, "another-token-xyz"))
    c2 = second.test_client()
    c2._cookies = c._cookies  # the same browser
    assert c2.get("/instructor").status_code == 401


def test_the_instructor_sees_every_submission_as_table_and_csv(client, app):
    for name, group in (("Olena", "MM-21"), ("=HYPERLINK(1)", "MM-22")):
        c = app.test_client()
        as_student(c, name, group)
        token = csrf(c, f"/variant/{VARIANT}")
        c.post(f"/variant/{VARIANT}/check", data={**student_values(variant(app)), "csrf": token})
    auth = {"Authorization": f"Bearer {TOKEN}"}
    html = client.get("/instructor", headers=auth).get_data(as_text=True)
    assert html.count(f"<td>{VARIANT}</td>") == 2 and "<td>Olena</td>" in html
    csv_text = client.get("/instructor/submissions.csv", headers=auth).get_data(as_text=True)
    table = list(csv.reader(io.StringIO(csv_text)))
    assert table[0][:9] == ["id", "time", "group", "student", "variant", "source", "passed", "values", "failed"]
    by_group = {r[2]: r for r in table[1:]}
    assert by_group["MM-21"][3:9] == ["Olena", VARIANT, "form", "no", "5", "1"]
    assert CAUSE_INERTIA in by_group["MM-21"][9]
    assert by_group["MM-22"][3] == "'=HYPERLINK(1)"  # no formula in a spreadsheet
    values = list(csv.DictReader(io.StringIO(
        client.get("/instructor/values.csv", headers=auth).get_data(as_text=True))))
    assert len(values) == 10
    f_bal = next(r for r in values if r["what"] == "F_bal (plans)" and r["group"] == "MM-21")
    assert float(f_bal["exact"]) == variant(app).solution.forces.balancing_force_plans
    assert f_bal["passed"] == "no" and f_bal["cause"] == CAUSE_INERTIA
    html = client.get("/instructor/submission/1", headers=auth).get_data(as_text=True)
    assert f"{variant(app).solution.forces.balancing_force_plans:.6g}" in html  # the exact values
    assert client.get("/instructor/submission/99", headers=auth).status_code == 404


def test_the_release_switch_is_kept_in_the_db(client, app, make_app, tmp_path):
    client.get(f"/instructor?token={TOKEN}")
    token = csrf(client, "/instructor")
    assert client.post("/instructor/release", data={"release": "1"}).status_code == 400  # no csrf
    assert client.post("/instructor/release", data={"release": "1", "csrf": token}).status_code == 302
    assert app.extensions["mmt"]["store"].exact_released
    restarted = make_app(tmp_path / "class.sqlite")
    assert restarted.extensions["mmt"]["store"].exact_released
    client.post("/instructor/release", data={"release": "0", "csrf": token})
    assert not app.extensions["mmt"]["store"].exact_released


def test_an_instructor_adds_a_variant_through_the_clis_loader(client, tasks_dir):
    import io

    client.get(f"/instructor?token={TOKEN}")
    token = csrf(client, "/instructor")
    good = (SEED003 / "task03_v1.toml").read_bytes()

    def upload(name, data):
        return client.post("/instructor/upload", data={"csrf": token, "mechanism": (io.BytesIO(data), name)},
                           content_type="multipart/form-data")

    r = upload("../new_v1.toml", good)  # a folder in the name is dropped
    assert r.status_code == 302 and (tasks_dir / "new_v1.toml").read_bytes() == good
    assert 'href="/variant/new_v1"' in client.get("/").get_data(as_text=True)
    assert upload("new_v1.toml", good).status_code == 409
    bad = re.sub(rb"mass = \d+", b"mass = -15", good, count=1)
    assert bad != good
    r = upload("bad_v1.toml", bad)
    assert r.status_code == 400 and "mass" in r.get_data(as_text=True)
    assert upload("x.txt", good).status_code == 400
    assert upload("bad name.toml", good).status_code == 400
    assert upload("big.toml", b"#" * 1_050_000).status_code in (400, 413)
    assert not (tasks_dir / "bad_v1.toml").exists() and not (tasks_dir / "big.toml").exists()


def test_serve_command_checks_its_options(tmp_path):
    from click.testing import CliRunner

    from mmt_plans.cli import main

    r = CliRunner().invoke(main, ["serve", str(tmp_path / "missing"), "--db", str(tmp_path / "c.sqlite")])
    assert r.exit_code == 2 and "is not a folder" in r.output
    r = CliRunner().invoke(main, ["serve", str(SEED003), "--password", "short"])
    assert r.exit_code == 2 and "8 to 200" in r.output


def test_other_commands_start_without_flask():
    code = "import sys, mmt_plans.cli; assert 'flask' not in sys.modules, 'flask imported'"
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr


def test_a_variant_that_does_not_load_says_why(client, tasks_dir):
    (tasks_dir / "broken_v1.toml").write_text("[drive]\nlink = 1\nrpm = -5\n", encoding="utf-8")
    assert 'href="/variant/broken_v1"' in client.get("/").get_data(as_text=True)
    r = client.get("/variant/broken_v1")
    assert r.status_code == 422 and "broken_v1.toml" in r.get_data(as_text=True)


def test_serve_prints_its_token_and_the_token_opens_the_instructors_pages(tasks_dir, tmp_path):
    import socket
    import urllib.error
    import urllib.request

    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    proc = subprocess.Popen(
        [sys.executable, "-m", "mmt_plans", "serve", str(tasks_dir), "--port", str(port),
         "--db", str(tmp_path / "c.sqlite")],
        stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
    )
    try:
        lines = [proc.stdout.readline() for _ in range(4)]
        assert lines[0].startswith(f"serving 2 variants of {tasks_dir} at http://127.0.0.1:{port}/")
        token = lines[2].removeprefix("token: ").strip()
        assert lines[2].startswith("token: ") and len(token) >= 20
        url = f"http://127.0.0.1:{port}/instructor"
        for _ in range(100):
            try:
                urllib.request.urlopen(f"http://127.0.0.1:{port}/", timeout=5)
                break
            except OSError:
                import time

                time.sleep(0.1)
        req = urllib.request.Request(url, headers={"Authorization": f"Bearer {token}"})
        assert urllib.request.urlopen(req, timeout=30).status == 200
        with pytest.raises(urllib.error.HTTPError) as err:
            urllib.request.urlopen(url, timeout=30)
        assert err.value.code == 401
        # a second server on the same port: one clean message, exit 2
        r = subprocess.run(
            [sys.executable, "-m", "mmt_plans", "serve", str(tasks_dir), "--port", str(port),
             "--db", str(tmp_path / "c.sqlite")],
            capture_output=True, text=True, timeout=120,
        )
        assert r.returncode == 2 and "cannot listen there" in r.stderr
    finally:
        proc.terminate()
        proc.wait(timeout=10)


def test_the_index_names_each_task_by_its_title_and_a_student_can_change_name(client):
    html = client.get("/").get_data(as_text=True)
    assert "Seed 003 task 1 v1: six-link press (crank, rocker, rod, slider)" in html
    assert "Завдання 1 (посібник 003), варіант 1" in client.get("/?lang=uk").get_data(as_text=True)
    as_student(client)
    assert 'id="name"' not in client.get("/").get_data(as_text=True)
    assert 'value="Olena Koval"' in client.get("/?change=1").get_data(as_text=True)


def test_a_result_checked_while_released_is_withheld_again_with_the_switch(client, app):
    """Released, a sign swapped shows the exact value in its cause; withheld
    again, the same result shows it no more."""
    store = app.extensions["mmt"]["store"]
    store.release_exact(True)
    as_student(client)
    w2 = variant(app).solution.plan(3).omega[2]
    token = csrf(client, f"/variant/{VARIANT}")
    r = client.post(f"/variant/{VARIANT}/check", data={"position|3|omega|2": f"{-w2:.4g}", "csrf": token})
    html = client.get(r.headers["Location"]).get_data(as_text=True)
    assert f"sign or direction swapped: the exact value is {w2:.4g}" in html  # 4 digits
    assert f"{w2:.6g}" in html  # the exact column
    store.release_exact(False)
    html = client.get(r.headers["Location"]).get_data(as_text=True)
    assert "sign or direction swapped: the exact value is …" in html
    assert f"{w2:.6g}" not in html and f"is {w2:.4g}" not in html


def test_the_5_percent_check_table_writes_sheet_1s_words(client):
    html = client.get(f"/variant/{VARIANT}?lang=uk").get_data(as_text=True)
    assert "V<sub>план</sub></span>, м/с" in html and "a<sub>діагр.</sub></span>, м/с²" in html


def test_the_given_data_names_the_sliders_guide(client):
    # task01_v1: "slider C (5) on the axis x-x through O1" (the file's [[slider]] through [0, 0], angle 0)
    html = client.get(f"/variant/{VARIANT}").get_data(as_text=True)
    assert "the guide of C passes through (0, 0) mm at 0°" in html
