"""`mmt-plans serve TASKS_DIR`: the class's web page (mmt_plans/web).

Flask (and waitress, when installed) are imported inside the command, so
that `analyze` and the other commands start without them."""

from __future__ import annotations

import secrets
import sys
from pathlib import Path

import click

from .errors import reports_errors


@click.command()
@click.argument("tasks_dir", type=click.Path(file_okay=False, path_type=Path))
@click.option(
    "--host",
    default="127.0.0.1",
    show_default=True,
    help="Address to listen on (0.0.0.0: the whole classroom network).",
)
@click.option("--port", type=click.IntRange(1, 65535), default=8000, show_default=True)
@click.option(
    "--lang",
    type=click.Choice(["en", "uk"]),
    default="en",
    show_default=True,
    help="The pages' language until a student picks another.",
)
@click.option(
    "--db",
    "db",
    type=click.Path(dir_okay=False, path_type=Path),
    default=Path("class.sqlite"),
    show_default=True,
    help="The SQLite file of the submissions (made on first start); the answer keys go to a folder beside it.",
)
@click.option(
    "--password",
    default=None,
    metavar="TEXT",
    help="The instructor's token (default: a new random one, printed at start).",
)
@click.option(
    "--behind-proxy",
    is_flag=True,
    help="Trust one reverse proxy's X-Forwarded-For/-Proto/-Host/-Prefix.",
)
@click.option("--threads", type=click.IntRange(1, 64), default=8, show_default=True)
@reports_errors
def serve(
    tasks_dir: Path,
    host: str,
    port: int,
    lang: str,
    db: Path,
    password: str | None,
    behind_proxy: bool,
    threads: int,
) -> None:
    """Serve TASKS_DIR's variants to a class: students check their values in
    a browser; the instructor sees the submissions under /instructor."""
    from ..errors import SpecError
    from ..web.app import Settings, create_app

    if password is not None and not (8 <= len(password) <= 200 and password.isprintable()):
        raise SpecError(
            "--password",
            "password",
            "must be 8 to 200 printable characters",
            "give a longer password",
        )
    token = password or secrets.token_urlsafe(18)
    app = create_app(
        Settings(tasks_dir, db, token, lang, behind_proxy=behind_proxy)  # type: ignore[arg-type]
    )
    n = len(app.extensions["mmt"]["tasks"].stems())
    shown_host = f"[{host}]" if ":" in host else host
    try:
        from waitress.server import create_server
    except ImportError:  # pragma: no cover - waitress is a dependency
        create_server = None
    server = None
    if create_server is not None:
        try:  # bind before printing: a port in use is a clean error
            server = create_server(app, host=host, port=port, threads=threads, ident="mmt-plans")
        except OSError as err:
            raise SpecError(
                "--port",
                f"{host}:{port}",
                f"cannot listen there ({err.strerror or err})",
                "give another --port, or stop the program that uses it",
            ) from None
    click.echo(f"serving {n} variants of {tasks_dir} at http://{shown_host}:{port}/")
    click.echo(f"submissions: {db.resolve()}")
    click.echo(f"token: {token if password is None else '(the --password given)'}")
    click.echo(f"instructor: http://{shown_host}:{port}/instructor", nl=True)
    sys.stdout.flush()
    if server is not None:
        server.run()
    else:  # pragma: no cover
        from werkzeug.serving import run_simple

        run_simple(host, port, app, threaded=True)
