"""The class's store: one SQLite file (the standard library's sqlite3).

The schema is versioned (`PRAGMA user_version`) and created on first start;
the journal is WAL so that readers (the instructor's table) never block a
student's submission, and every write is one short transaction begun
IMMEDIATE, so two submissions at once queue for the lock (busy_timeout)
instead of failing. A connection is opened per request and closed after it:
sqlite3 connections are not shared between threads.

The SQL is portable (no SQLite-only types or functions in the queries; ids
are INTEGER PRIMARY KEY, times ISO-8601 text in UTC), so the same tables
can be created on PostgreSQL by a department that outgrows one file.
"""

from __future__ import annotations

import json
import os
import secrets
import sqlite3
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass
from datetime import UTC, datetime
from pathlib import Path
from typing import Any

__all__ = ["SCHEMA_VERSION", "Store", "Submission"]

SCHEMA_VERSION = 1

# Each version's statements, applied in order from the file's user_version.
_MIGRATIONS: dict[int, tuple[str, ...]] = {
    1: (
        """CREATE TABLE submission (
            id INTEGER PRIMARY KEY,
            created TEXT NOT NULL,
            student TEXT NOT NULL,
            grp TEXT NOT NULL,
            variant TEXT NOT NULL,
            source TEXT NOT NULL,
            lang TEXT NOT NULL,
            passed INTEGER NOT NULL,
            n_values INTEGER NOT NULL,
            n_failed INTEGER NOT NULL,
            answers TEXT NOT NULL,
            report TEXT NOT NULL
        )""",
        "CREATE INDEX submission_variant ON submission (variant, grp, student)",
        """CREATE TABLE setting (
            name TEXT PRIMARY KEY,
            value TEXT NOT NULL
        )""",
        """CREATE TABLE draft (
            client TEXT NOT NULL,
            variant TEXT NOT NULL,
            fields TEXT NOT NULL,
            updated TEXT NOT NULL,
            PRIMARY KEY (client, variant)
        )""",
    ),
}


@dataclass(frozen=True)
class Submission:
    id: int
    created: str
    student: str
    group: str
    variant: str
    source: str  # "form", "toml" (pasted on the page) or "api"
    lang: str
    passed: bool
    n_values: int
    n_failed: int
    answers: str  # the answers TOML checked
    report: dict[str, Any]  # check --json's report, with the exact values


def _now() -> str:
    return datetime.now(UTC).strftime("%Y-%m-%dT%H:%M:%SZ")


class Store:
    """The submissions, the settings (the release switch, the session key) and
    the students' drafts, in one SQLite file."""

    def __init__(self, path: str | os.PathLike[str]) -> None:
        self.path = Path(path)
        self.path.parent.mkdir(parents=True, exist_ok=True)
        with self._connect() as conn:
            conn.execute("PRAGMA journal_mode=WAL")
            self._migrate(conn)

    def _connect(self) -> sqlite3.Connection:
        conn = sqlite3.connect(self.path, timeout=30.0, isolation_level=None)
        conn.execute("PRAGMA busy_timeout = 30000")
        conn.execute("PRAGMA foreign_keys = ON")
        return conn

    @contextmanager
    def _write(self) -> Iterator[sqlite3.Connection]:
        conn = self._connect()
        try:
            conn.execute("BEGIN IMMEDIATE")
            try:
                yield conn
            except BaseException:
                conn.execute("ROLLBACK")
                raise
            conn.execute("COMMIT")
        finally:
            conn.close()

    @contextmanager
    def _read(self) -> Iterator[sqlite3.Connection]:
        conn = self._connect()
        try:
            yield conn
        finally:
            conn.close()

    def _migrate(self, conn: sqlite3.Connection) -> None:
        conn.execute("BEGIN IMMEDIATE")
        try:
            version = conn.execute("PRAGMA user_version").fetchone()[0]
            if version > SCHEMA_VERSION:
                raise RuntimeError(
                    f"{self.path}: schema version {version} is newer than this "
                    f"program's {SCHEMA_VERSION}; use a newer mmt_plans"
                )
            for v in range(version + 1, SCHEMA_VERSION + 1):
                for statement in _MIGRATIONS[v]:
                    conn.execute(statement)
                conn.execute(f"PRAGMA user_version = {v}")
        except BaseException:
            conn.execute("ROLLBACK")
            raise
        conn.execute("COMMIT")

    @property
    def schema_version(self) -> int:
        with self._read() as conn:
            return int(conn.execute("PRAGMA user_version").fetchone()[0])

    # --- settings ---------------------------------------------------------------
    def setting(self, name: str, default: str | None = None) -> str | None:
        with self._read() as conn:
            row = conn.execute("SELECT value FROM setting WHERE name = ?", (name,)).fetchone()
        return default if row is None else str(row[0])

    def set_setting(self, name: str, value: str) -> None:
        with self._write() as conn:
            conn.execute("DELETE FROM setting WHERE name = ?", (name,))
            conn.execute("INSERT INTO setting (name, value) VALUES (?, ?)", (name, value))

    def secret_key(self) -> str:
        """The key that signs the session cookies: made once, kept in the file,
        so that students' sessions survive a restart."""
        with self._write() as conn:
            row = conn.execute("SELECT value FROM setting WHERE name = 'secret_key'").fetchone()
            if row is not None:
                return str(row[0])
            key = secrets.token_hex(32)
            conn.execute("INSERT INTO setting (name, value) VALUES ('secret_key', ?)", (key,))
            return key

    @property
    def exact_released(self) -> bool:
        return self.setting("release_exact", "0") == "1"

    def release_exact(self, released: bool) -> None:
        self.set_setting("release_exact", "1" if released else "0")

    # --- submissions --------------------------------------------------------------
    def add_submission(
        self,
        *,
        student: str,
        group: str,
        variant: str,
        source: str,
        lang: str,
        answers: str,
        report: dict[str, Any],
    ) -> int:
        values = report.get("values", [])
        failed = sum(1 for v in values if not v.get("passed"))
        with self._write() as conn:
            cur = conn.execute(
                "INSERT INTO submission (created, student, grp, variant, source, lang, passed, "
                "n_values, n_failed, answers, report) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)",
                (
                    _now(),
                    student,
                    group,
                    variant,
                    source,
                    lang,
                    1 if report.get("passed") else 0,
                    len(values),
                    failed,
                    answers,
                    json.dumps(report, ensure_ascii=False),
                ),
            )
            return int(cur.lastrowid or 0)

    def submissions(self, variant: str | None = None) -> list[Submission]:
        """Every submission, by group, student, variant and time."""
        query = "SELECT * FROM submission"
        args: tuple = ()
        if variant is not None:
            query += " WHERE variant = ?"
            args = (variant,)
        query += " ORDER BY grp, student, variant, id"
        with self._read() as conn:
            rows = conn.execute(query, args).fetchall()
        return [_submission(r) for r in rows]

    def submission(self, sid: int) -> Submission | None:
        with self._read() as conn:
            row = conn.execute("SELECT * FROM submission WHERE id = ?", (sid,)).fetchone()
        return None if row is None else _submission(row)

    # --- a student's values not yet submitted, or refused -------------------------------
    def save_draft(self, client: str, variant: str, fields: dict[str, str]) -> None:
        text = json.dumps(fields, ensure_ascii=False)
        with self._write() as conn:
            conn.execute("DELETE FROM draft WHERE client = ? AND variant = ?", (client, variant))
            conn.execute(
                "INSERT INTO draft (client, variant, fields, updated) VALUES (?, ?, ?, ?)",
                (client, variant, text, _now()),
            )

    def draft(self, client: str, variant: str) -> dict[str, str]:
        with self._read() as conn:
            row = conn.execute(
                "SELECT fields FROM draft WHERE client = ? AND variant = ?", (client, variant)
            ).fetchone()
        if row is None:
            return {}
        data = json.loads(row[0])
        return {str(k): str(v) for k, v in data.items()} if isinstance(data, dict) else {}


def _submission(row: tuple) -> Submission:
    (sid, created, student, grp, variant, source, lang, passed, n, bad, answers, report) = row
    return Submission(
        int(sid),
        str(created),
        str(student),
        str(grp),
        str(variant),
        str(source),
        str(lang),
        bool(passed),
        int(n),
        int(bad),
        str(answers),
        json.loads(report),
    )
