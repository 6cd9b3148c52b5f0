"""The Flask application of `mmt-plans serve`: student pages, instructor
pages behind a token, and a JSON door (`POST /api/check/<variant>`).

Flask is imported here only, and this module only by the serve command, so
that `analyze` and the other commands start without it.
"""

from __future__ import annotations

import csv
import hmac
import io
import secrets
import threading
import tomllib
import zipfile
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from flask import (
    Flask,
    Response,
    abort,
    g,
    jsonify,
    redirect,
    render_template,
    request,
    send_file,
    session,
    url_for,
)
from markupsafe import Markup
from werkzeug.exceptions import HTTPException

from ..check.report import label
from ..errors import MmtError, SpecError, shown
from ..files import MAX_INPUT_BYTES, decode_input
from ..i18n import LANGUAGES, Language, catalogue
from .answers import (
    STUDENT_MAX,
    FieldError,
    answers_from_fields,
    dump_toml,
    split_student,
    student_report,
    valid_student,
)
from .db import Store
from .ratelimit import TokenBuckets
from .tasks import STEM, TaskDir, Variant

__all__ = ["Settings", "create_app"]

_WORDS: dict[str, dict[str, str]] = {}
_WORDS_LOCK = threading.Lock()


def words(lang: str) -> dict[str, str]:
    """The web pages' words (web/words.toml), by language."""
    with _WORDS_LOCK:
        if not _WORDS:
            text = Path(__file__).with_name("words.toml").read_text(encoding="utf-8")
            _WORDS.update(tomllib.loads(text))
    return _WORDS[lang]


@dataclass(frozen=True)
class Settings:
    tasks_dir: Path
    db: Path
    token: str  # the instructor's token (or --password)
    lang: Language = "en"
    burst: float = 60.0  # a client's requests at once …
    rate: float = 2.0  # … and per second after that
    check_cost: float = 6.0  # a check (a submission, an upload, keys) costs this many
    behind_proxy: bool = False


def _osifont() -> Path | None:
    """The sheets' lettering, served to the pages where a drawing shows."""
    for p in (
        Path("/usr/share/fonts/truetype/osifont/osifont.ttf"),
        Path("/usr/share/fonts/opentype/osifont/osifont.otf"),
    ):
        if p.is_file():
            return p
    return None


def create_app(settings: Settings) -> Flask:
    app = Flask(__name__)
    tasks = TaskDir(settings.tasks_dir)
    store = Store(settings.db)
    keys_dir = settings.db.parent / (settings.db.stem + ".keys")
    app.config.update(
        SECRET_KEY=store.secret_key(),
        MAX_CONTENT_LENGTH=MAX_INPUT_BYTES + 64_000,  # one input file and a form around it
        MAX_FORM_MEMORY_SIZE=MAX_INPUT_BYTES + 64_000,
        MAX_FORM_PARTS=5000,
        SESSION_COOKIE_HTTPONLY=True,
        SESSION_COOKIE_SAMESITE="Lax",
        PERMANENT_SESSION_LIFETIME=180 * 24 * 3600,
        JSON_SORT_KEYS=False,
    )
    app.json.sort_keys = False  # type: ignore[attr-defined]
    app.extensions["mmt"] = {"store": store, "tasks": tasks, "settings": settings}
    if settings.behind_proxy:
        from werkzeug.middleware.proxy_fix import ProxyFix

        app.wsgi_app = ProxyFix(app.wsgi_app, x_for=1, x_proto=1, x_host=1, x_prefix=1)  # type: ignore[method-assign]
    buckets = TokenBuckets(settings.burst, settings.rate)
    check_lock = threading.Lock()  # the check is CPU-bound: one at a time
    keys_lock = threading.Lock()
    font_file = _osifont()

    # --- every request ---------------------------------------------------------
    @app.before_request
    def before() -> Any:
        if request.endpoint == "static" or request.endpoint == "font":
            return None
        cost = settings.check_cost if request.method == "POST" else 1.0
        wait = buckets.take(request.remote_addr or "-", cost)
        if wait > 0:
            resp = Response(words(_lang())["too_many"] + "\n", 429, mimetype="text/plain")
            resp.headers["Retry-After"] = str(int(wait) + 1)
            return resp
        session.permanent = True
        if "client" not in session:
            session["client"] = secrets.token_hex(16)
        if "csrf" not in session:
            session["csrf"] = secrets.token_hex(16)
        lang = request.args.get("lang")
        if lang in LANGUAGES:
            session["lang"] = lang
        g.lang = _lang()
        return None

    @app.after_request
    def headers(resp: Response) -> Response:
        resp.headers["X-Content-Type-Options"] = "nosniff"
        resp.headers["X-Frame-Options"] = "DENY"
        resp.headers["Referrer-Policy"] = "same-origin"
        resp.headers["Content-Security-Policy"] = (
            "default-src 'none'; style-src 'self'; img-src 'self' data:; font-src 'self'; "
            "form-action 'self'; frame-ancestors 'none'; base-uri 'none'"
        )
        return resp

    def _lang() -> Language:
        lang = session.get("lang", settings.lang)
        return lang if lang in LANGUAGES else settings.lang  # type: ignore[no-any-return]

    @app.context_processor
    def context() -> dict[str, Any]:
        lang = getattr(g, "lang", settings.lang)
        return {
            "w": words(lang),
            "lang": lang,
            "languages": LANGUAGES,
            "unit": catalogue(lang).unit,
            "csrf": session.get("csrf", ""),
            "student": session.get("student"),
            "group": session.get("group"),
            "font": font_file is not None,
            "check_word": lambda key: catalogue(lang).word("check", key),
        }

    @app.template_filter("num")
    def num(x: float | None) -> str:
        if x is None:
            return "-"
        return catalogue(g.lang).localise(f"{float(x) + 0.0:.6g}")

    @app.template_filter("dev")
    def dev(x: float | None) -> str:
        if x is None:
            return "-"
        text = f"{float(x) + 0.0:+.2f}"
        return catalogue(g.lang).localise("0.00" if text in ("+0.00", "-0.00") else text)

    @app.template_filter("unit_text")
    def unit_text(json_unit: str) -> str:
        key = _UNIT_KEYS.get(json_unit)
        return catalogue(g.lang).unit(key) if key else json_unit

    @app.template_filter("subscript")
    def subscript(sub: str) -> str:
        """An index the textbook writes differently by language (bal: зр; the
        5 % check's plan, diagram as sheet 1 writes them)."""
        cat = catalogue(g.lang)
        if sub in ("plan", "diagram"):
            return cat.word("sheet1", sub)
        return str(cat.words("symbol_indices").get(sub, sub))

    def _csrf_ok() -> bool:
        sent = request.form.get("csrf", "")
        return bool(sent) and hmac.compare_digest(sent, session.get("csrf", ""))

    @app.errorhandler(HTTPException)
    def http_error(err: HTTPException) -> Any:
        if request.path.startswith("/api/"):
            return jsonify({"error": err.description}), err.code
        return (
            render_template("error.html", code=err.code, message=err.description),
            err.code or 500,
        )

    def _variant_or_404(stem: str) -> Variant:
        if not STEM.fullmatch(stem):
            abort(404, description=words(g.lang)["no_variant"])
        try:
            v = tasks.variant(stem)
        except MmtError as err:
            abort(422, description=shown(str(err), 2000))
        if v is None:
            abort(404, description=words(g.lang)["no_variant"])
        return v

    # --- student pages --------------------------------------------------------------
    @app.get("/")
    def index() -> Any:
        return render_template(
            "index.html", tasks=list(tasks.tasks()), title=lambda stem: tasks.title(stem, g.lang)
        )

    @app.post("/student")
    def set_student() -> Any:
        if not _csrf_ok():
            abort(400, description=words(g.lang)["bad_form"])
        name, group = request.form.get("name", ""), request.form.get("group", "")
        nxt = request.form.get("next", "")
        if not (valid_student(name) and valid_student(group)):
            return (
                render_template(
                    "index.html",
                    tasks=list(tasks.tasks()),
                    title=lambda stem: tasks.title(stem, g.lang),
                    error=words(g.lang)["bad_student"].format(n=STUDENT_MAX),
                ),
                400,
            )
        session["student"], session["group"] = name.strip(), group.strip()
        if STEM.fullmatch(nxt) and tasks.path(nxt) is not None:
            return redirect(url_for("variant", stem=nxt))
        return redirect(url_for("index"))

    @app.get("/font/osifont.ttf")
    def font() -> Any:
        if font_file is None:
            abort(404)
        return send_file(font_file, mimetype="font/ttf", max_age=86400)

    @app.get("/variant/<stem>")
    def variant(stem: str) -> Any:
        v = _variant_or_404(stem)
        values = store.draft(session["client"], stem)
        result = None
        sid = request.args.get("result", "")
        if sid.isdigit() and int(sid) in session.get("mine", []):
            sub = store.submission(int(sid))
            if sub is not None and sub.variant == stem:
                result = _shown_report(sub.report, sub.lang, store.exact_released)
        return _variant_page(v, values, result=result)

    def _variant_page(
        v: Variant,
        values: dict[str, str],
        *,
        result: dict[str, Any] | None = None,
        errors: list[FieldError] | None = None,
        message: str | None = None,
        toml: str = "",
        status: int = 200,
    ) -> tuple[str, int]:
        svg = tasks.schematic(v.stem, g.lang) or ""
        svg = svg[svg.find("<svg") :] if "<svg" in svg else ""
        return (
            render_template(
                "variant.html",
                v=v,
                svg=Markup(svg),  # our own drawing: svgwrite escapes every text in it
                given=v.given(g.lang),
                groups=v.field_groups(),
                field_ids=set(v.fields()),
                check_columns=_CHECK_COLUMNS,
                values=values,
                result=result,
                errors={e.field: e.problem for e in errors or []},
                message=message,
                toml=toml,
                released=store.exact_released,
            ),
            status,
        )

    @app.post("/variant/<stem>/check")
    def check_form(stem: str) -> Any:
        v = _variant_or_404(stem)
        w = words(g.lang)
        if not _csrf_ok():
            abort(400, description=w["bad_form"])
        fields = v.fields()
        values = {fid: request.form.get(fid, "")[:200] for fid in fields}
        values = {k: x for k, x in values.items() if x.strip()}
        store.save_draft(session["client"], stem, values)
        student, group = session.get("student"), session.get("group")
        if not student or not group:
            return _variant_page(v, values, message=w["need_student"], status=400)
        pasted = request.form.get("answers_toml", "")
        if pasted.strip():
            source = "toml"
            try:
                data, _ = split_student(_parse(pasted, "answers"), "answers")
                text = dump_toml(data, "answers")
            except MmtError as err:
                return _variant_page(v, values, message=str(err), toml=pasted, status=400)
        else:
            source = "form"
            data, errors = answers_from_fields(fields, values)
            if errors:
                return _variant_page(v, values, errors=errors, message=w["fix_fields"], status=400)
            if not data:
                return _variant_page(v, values, message=w["no_values"], status=400)
            text = dump_toml(data)
        try:
            sid, _ = _check(
                v, text, student, group, source, "answers" if source == "toml" else "form"
            )
        except MmtError as err:
            return _variant_page(v, values, message=shown(str(err), 2000), toml=pasted, status=400)
        session["mine"] = ([*session.get("mine", []), sid])[-50:]
        return redirect(url_for("variant", stem=stem, result=sid) + "#result")

    def _parse(text: str, path: str) -> dict[str, Any]:
        from ..spec import parse_toml

        if len(text.encode("utf-8")) > MAX_INPUT_BYTES:
            raise SpecError(
                path, "file", f"is more than {MAX_INPUT_BYTES:,} bytes", "give the answers only"
            )
        return parse_toml(text, path)

    def _check(
        v: Variant, text: str, student: str, group: str, source: str, path: str
    ) -> tuple[int, dict[str, Any]]:
        from ..check import check, loads_answers
        from ..numerics import quiet_numerics

        with check_lock, quiet_numerics():
            answers = loads_answers(text, v.solution, path)
            result = check(v.solution, answers, mechanism=v.path.name)
            report = result.json_data(g.lang)
            cat = catalogue(g.lang)
            for x, checked in zip(report["values"], result.values):
                x["label"] = label(cat, checked.answer)  # the text table's, in the language
            shown_report = student_report(result, g.lang, store.exact_released)
            for x, y in zip(shown_report["values"], report["values"]):
                x["label"] = y["label"]
            # the causes with their numbers withheld, for when the switch is off
            withheld = student_report(result, g.lang, False)
            report["causes_shown"] = [x["cause"] for x in withheld["values"]]
        sid = store.add_submission(
            student=student,
            group=group,
            variant=v.stem,
            source=source,
            lang=g.lang,
            answers=text,
            report=report,
        )
        return sid, shown_report

    def _shown_report(report: dict, lang: str, released: bool) -> dict:
        """A stored report as the student sees it now (the switch may have moved)."""
        values = []
        for k, x in enumerate(report["values"]):
            x = dict(x)
            if not released:
                x["exact"] = None
                x["error_percent"] = None
                shown_causes = report.get("causes_shown")
                if shown_causes is not None:
                    x["cause"] = shown_causes[k]
            values.append(x)
        return {"passed": report["passed"], "values": values}

    # --- the JSON door --------------------------------------------------------------
    @app.post("/api/check/<stem>")
    def api_check(stem: str) -> Any:
        v = _variant_or_404(stem)
        try:
            text = decode_input(request.get_data(cache=False), "answers", "answers file")
            data, who = split_student(_parse(text, "answers"), "answers")
            student = who.get("name") or request.args.get("name", "")
            group = who.get("group") or request.args.get("group", "")
            if not (valid_student(student) and valid_student(group)):
                raise SpecError(
                    "answers",
                    "student",
                    "a submission needs the student's name and group",
                    'add [student] name = "…" group = "…", or ?name=…&group=…',
                )
            _, report = _check(
                v, dump_toml(data, "answers"), student.strip(), group.strip(), "api", "answers"
            )
        except MmtError as err:
            return jsonify({"error": shown(str(err), 2000)}), 400
        for x in report["values"]:  # check --json's keys, no more
            x.pop("label", None)
        return jsonify(report)

    # --- instructor pages -------------------------------------------------------------
    def _instructor() -> None:
        """401 without a token, 403 with a wrong one."""
        auth = request.headers.get("Authorization", "")
        sent = auth[7:] if auth.startswith("Bearer ") else None
        if sent is None and session.get("instructor"):
            if hmac.compare_digest(session["instructor"], _mark()):
                return
            session.pop("instructor", None)
        if sent is None:
            sent = request.args.get("token")
        if sent is None:
            abort(401, description=words(g.lang)["need_token"])
        if not hmac.compare_digest(sent.encode("utf-8"), settings.token.encode("utf-8")):
            abort(403, description=words(g.lang)["bad_token"])

    def _mark() -> str:
        """What the session keeps of a good token: a digest bound to this server's token."""
        key = str(app.secret_key).encode()
        return hmac.new(key, settings.token.encode(), "sha256").hexdigest()

    @app.get("/instructor")
    def instructor() -> Any:
        if "token" in request.args:
            _instructor()
            session["instructor"] = _mark()
            return redirect(url_for("instructor"))
        if not session.get("instructor") and "Authorization" not in request.headers:
            return render_template("login.html"), 401
        _instructor()
        subs = store.submissions()
        return render_template(
            "instructor.html",
            subs=subs,
            released=store.exact_released,
            stems=tasks.stems(),
            upload_message=request.args.get("uploaded"),
        )

    @app.post("/instructor/login")
    def instructor_login() -> Any:
        if not _csrf_ok():
            abort(400, description=words(g.lang)["bad_form"])
        sent = request.form.get("token", "")
        if not hmac.compare_digest(sent.encode("utf-8"), settings.token.encode("utf-8")):
            return render_template("login.html", error=words(g.lang)["bad_token"]), 403
        session["instructor"] = _mark()
        return redirect(url_for("instructor"))

    @app.post("/instructor/logout")
    def instructor_logout() -> Any:
        session.pop("instructor", None)
        return redirect(url_for("index"))

    @app.get("/instructor/submission/<int:sid>")
    def instructor_submission(sid: int) -> Any:
        _instructor()
        sub = store.submission(sid)
        if sub is None:
            abort(404)
        return render_template("submission.html", sub=sub)

    @app.get("/instructor/submissions.csv")
    def instructor_csv() -> Any:
        _instructor()
        out = io.StringIO()
        wr = csv.writer(out)
        wr.writerow(
            [
                "id",
                "time",
                "group",
                "student",
                "variant",
                "source",
                "passed",
                "values",
                "failed",
                "failures",
            ]
        )
        for s in store.submissions():
            failures = "; ".join(
                f"{x['what']}@{x['position']}: {x['cause'] or '?'}"
                for x in s.report["values"]
                if not x["passed"]
            )
            wr.writerow(
                [
                    s.id,
                    s.created,
                    _cell(s.group),
                    _cell(s.student),
                    s.variant,
                    s.source,
                    "yes" if s.passed else "no",
                    s.n_values,
                    s.n_failed,
                    _cell(failures),
                ]
            )
        return Response(
            out.getvalue(),
            mimetype="text/csv",
            headers={"Content-Disposition": "attachment; filename=submissions.csv"},
        )

    @app.get("/instructor/values.csv")
    def instructor_values_csv() -> Any:
        """Every value of every submission, one row each, with the exact value."""
        _instructor()
        out = io.StringIO()
        wr = csv.writer(out)
        head = ["id", "time", "group", "student", "variant", "what", "position", "phi1_deg"]
        wr.writerow([*head, "unit", "given", "exact", "error_percent", "passed", "cause"])
        for s in store.submissions():
            for x in s.report["values"]:
                wr.writerow(
                    [
                        s.id,
                        s.created,
                        _cell(s.group),
                        _cell(s.student),
                        s.variant,
                        x["what"],
                        "" if x["position"] is None else x["position"],
                        "" if x["phi1_deg"] is None else repr(x["phi1_deg"]),
                        x["unit"],
                        "" if x["given"] is None else repr(x["given"]),
                        "" if x["exact"] is None else repr(x["exact"]),
                        "" if x["error_percent"] is None else repr(x["error_percent"]),
                        "yes" if x["passed"] else "no",
                        _cell(x["cause"] or ""),
                    ]
                )
        return Response(
            out.getvalue(),
            mimetype="text/csv",
            headers={"Content-Disposition": "attachment; filename=values.csv"},
        )

    @app.post("/instructor/release")
    def instructor_release() -> Any:
        _instructor()
        if not _csrf_ok():
            abort(400, description=words(g.lang)["bad_form"])
        store.release_exact(request.form.get("release") == "1")
        return redirect(url_for("instructor"))

    @app.post("/instructor/upload")
    def instructor_upload() -> Any:
        _instructor()
        if not _csrf_ok():
            abort(400, description=words(g.lang)["bad_form"])
        from ..files import write_bytes_atomic
        from ..solution import solve
        from ..spec import loads

        up = request.files.get("mechanism")
        w = words(g.lang)
        if up is None or not up.filename:
            abort(400, description=w["no_file"])
        stem = Path(up.filename).stem
        if not STEM.fullmatch(stem) or Path(up.filename).suffix != ".toml":
            abort(400, description=w["bad_file_name"])
        if tasks.path(stem) is not None:
            abort(409, description=w["file_exists"].format(stem=stem))
        data = up.read(MAX_INPUT_BYTES + 1)
        try:
            if len(data) > MAX_INPUT_BYTES:
                raise SpecError(
                    up.filename,
                    "file",
                    f"is more than {MAX_INPUT_BYTES:,} bytes",
                    "upload the mechanism file itself",
                )
            text = decode_input(data, stem + ".toml")
            with check_lock:
                solve(loads(text, stem + ".toml"))
        except MmtError as err:
            abort(400, description=shown(str(err), 2000))
        write_bytes_atomic(settings.tasks_dir / f"{stem}.toml", data)
        return redirect(url_for("instructor", uploaded=stem))

    def _keys(stem: str) -> Path:
        """The answer keys of one variant (sheets, note, JSON), made once into the cache."""
        from ..batch import process_file

        path = tasks.path(stem)
        if path is None:
            abort(404, description=words(g.lang)["no_variant"])
        out = keys_dir / g.lang / stem
        with keys_lock:
            res = process_file(path, out, g.lang, force=False)
        if not res.ok:
            abort(422, description=shown(res.message or "", 2000))
        return out

    def _key_files(out: Path) -> list[Path]:
        return sorted(p for p in out.iterdir() if p.is_file() and not p.name.startswith("."))

    @app.get("/instructor/keys/<stem>")
    def instructor_keys(stem: str) -> Any:
        _instructor()
        out = _keys(stem)
        return render_template("keys.html", stem=stem, files=[p.name for p in _key_files(out)])

    @app.get("/instructor/keys/<stem>/<name>")
    def instructor_key_file(stem: str, name: str) -> Any:
        _instructor()
        out = _keys(stem)
        for p in _key_files(out):
            if p.name == name:
                return send_file(p, as_attachment=p.suffix != ".svg")
        abort(404)

    @app.get("/instructor/keys.zip")
    def instructor_keys_zip() -> Any:
        _instructor()
        buf = io.BytesIO()
        with zipfile.ZipFile(buf, "w", zipfile.ZIP_DEFLATED) as z:
            for stem in tasks.stems():
                out = _keys(stem)
                for p in _key_files(out):
                    z.write(p, f"{stem}/{p.name}")
        buf.seek(0)
        return send_file(
            buf, mimetype="application/zip", as_attachment=True, download_name="keys.zip"
        )

    return app


# the 5 % check's table on the form: (key, symbol, index, unit) by column
_CHECK_COLUMNS = (
    ("V_plan", "V", "plan", "m/s"),
    ("V_diagram", "V", "diagram", "m/s"),
    ("dV_percent", "δ", "V", "%"),
    ("a_plan", "a", "plan", "m/s2"),
    ("a_diagram", "a", "diagram", "m/s2"),
    ("da_percent", "δ", "a", "%"),
)


def _units() -> dict[str, str]:
    from ..check.report import UNITS

    return {json_unit: key for key, json_unit in UNITS.values() if key}


_UNIT_KEYS = _units()


def _cell(text: str) -> str:
    """A CSV cell a spreadsheet will not run as a formula."""
    return "'" + text if text[:1] in ("=", "+", "-", "@", "\t", "\r") else text
