"""Reading inputs and writing outputs safely: the two doors of the tool.

Inputs (a mechanism file, an answers file) are read by `read_input`, which
refuses, before reading a byte, anything that is not a regular file of at
most `MAX_INPUT_BYTES` (a folder, a FIFO that would block forever, /dev/zero
that would fill the memory), and then text that is not UTF-8. Every refusal
is a `SpecError(path, "file", problem, fix)`.

Outputs are written atomically: into a hidden temporary file next to the
target (`.NAME.tmp-<pid>-<random>`), renamed onto the target only once it is
complete, removed on any failure. An interrupted run leaves each output
either as it was or complete, never half-written (a rename is atomic on one
file system; a power cut may still lose the data of the last files, as we
do not fsync). A target that cannot be written (a read-only folder, a path
under an existing file, a folder where a file should go) is an
`OutputError` naming the path and the fix.

`finite_json` turns results into JSON text, naming the first number that is
not finite instead of letting json raise a bare ValueError.

Imports only the standard library and `mmt_plans.errors`.
"""

from __future__ import annotations

import codecs
import datetime as _dt
import errno
import json
import math
import os
import stat
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import Any

from .errors import MmtError, SpecError, shown

__all__ = [
    "MAX_INPUT_BYTES",
    "OutputError",
    "NonFiniteResultError",
    "read_input",
    "write_bytes_atomic",
    "write_text_atomic",
    "atomic_path",
    "ensure_dir",
    "check_output",
    "finite_json",
    "first_non_finite",
    "document_date",
]

MAX_INPUT_BYTES = 1_000_000
"""The largest input file read (1 MB): the largest sample is about 5 kB."""

_UTF16_32_BOMS = (
    codecs.BOM_UTF32_LE,
    codecs.BOM_UTF32_BE,
    codecs.BOM_UTF16_LE,
    codecs.BOM_UTF16_BE,
)


class OutputError(MmtError, OSError):
    """An output that cannot be written where it was asked for."""

    def __init__(self, path: str | os.PathLike[str], problem: str, fix: str = "") -> None:
        self.path, self.problem, self.fix = str(path), problem, fix
        text = f"{shown(path)}: {problem}"
        if fix:
            text += f"\n  fix: {fix}"
        super().__init__(text)

    def __str__(self) -> str:  # OSError's own str() would show errno and filename
        return self.args[0]


class NonFiniteResultError(MmtError, ValueError):
    """A result that is not a finite number, about to be written."""


# --- reading ------------------------------------------------------------------------


def _kind(mode: int) -> str:
    if stat.S_ISDIR(mode):
        return "a folder"
    if stat.S_ISFIFO(mode):
        return "a FIFO (named pipe)"
    if stat.S_ISSOCK(mode):
        return "a socket"
    if stat.S_ISCHR(mode) or stat.S_ISBLK(mode):
        return "a device"
    return "not a regular file"


def read_input(path: str | os.PathLike[str], what: str = "mechanism file") -> str:
    """The text of an input file, or a SpecError naming the problem.

    Refused before reading: a path that does not exist or cannot be opened,
    anything but a regular file, a file over MAX_INPUT_BYTES. Decoded as
    UTF-8 with or without a byte-order mark; NUL bytes (binary data, UTF-16)
    and bytes that are not UTF-8 are refused with where they are."""
    name = str(path)

    def fail(problem: str, fix: str) -> SpecError:
        return SpecError(name, "file", problem, fix)

    try:
        st = os.stat(path)
    except OSError as err:
        raise fail(f"cannot be read ({err.strerror})", f"check the path of the {what}") from None
    if not stat.S_ISREG(st.st_mode):
        raise fail(f"is {_kind(st.st_mode)}, not a {what}", f"give the path of the {what} itself")
    if st.st_size > MAX_INPUT_BYTES:
        raise fail(
            f"is {st.st_size:,} bytes, more than the {MAX_INPUT_BYTES:,} a {what} may have",
            f"give the {what} itself (a mechanism file is a few kB of text)",
        )
    try:
        # O_NONBLOCK: if the path became a FIFO since stat(), open() must not wait for a writer
        fd = os.open(path, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0))
        with os.fdopen(fd, "rb") as fh:
            if not stat.S_ISREG(os.fstat(fh.fileno()).st_mode):
                raise fail(
                    f"is not a regular file, not a {what}", f"give the path of the {what} itself"
                )
            data = fh.read(MAX_INPUT_BYTES + 1)
    except OSError as err:
        raise fail(f"cannot be read ({err.strerror})", f"check the path of the {what}") from None
    if len(data) > MAX_INPUT_BYTES:
        raise fail(
            f"is more than the {MAX_INPUT_BYTES:,} bytes a {what} may have",
            f"give the {what} itself (a mechanism file is a few kB of text)",
        )
    return decode_input(data, name, what)


def decode_input(data: bytes, name: str, what: str = "mechanism file") -> str:
    """UTF-8 text (a byte-order mark allowed) of an input's bytes, or a SpecError."""
    save = "save it as UTF-8 text (in most editors: Save as, encoding UTF-8)"
    if data.startswith(_UTF16_32_BOMS) and not data.startswith(codecs.BOM_UTF8):
        raise SpecError(name, "file", "is UTF-16 or UTF-32 text, not UTF-8", save)
    nul = data.find(b"\0")
    if nul >= 0:
        line = data.count(b"\n", 0, nul) + 1
        raise SpecError(
            name,
            "file",
            f"contains a NUL byte (line {line}): it is binary data or "
            "UTF-16 text, not a UTF-8 text file",
            save,
        )
    try:
        return data.decode("utf-8-sig")
    except UnicodeDecodeError as err:
        start = err.start
        line = data.count(b"\n", 0, start) + 1
        column = start - (data.rfind(b"\n", 0, start) + 1) + 1
        raise SpecError(
            name,
            "file",
            f"is not UTF-8 text: byte 0x{data[start]:02X} at line {line}, column "
            f"{column} cannot be decoded (Latin-1 or Windows-1251 text?)",
            save,
        ) from None


# --- writing ------------------------------------------------------------------------


def _os_problem(err: OSError, target: Path) -> OutputError:
    """A clean OutputError for an OSError met while writing `target`."""
    if isinstance(err, OutputError):
        return err
    if err.errno in (errno.EACCES, errno.EPERM, errno.EROFS):
        return OutputError(
            target,
            f"cannot be written: {err.strerror}",
            "choose a folder you may write to (-o / --json), or change its permissions",
        )
    if err.errno == errno.ENOSPC:
        return OutputError(
            target, "cannot be written: the disk is full", "free some space, or write elsewhere"
        )
    if err.errno in (errno.ENOTDIR, errno.EEXIST):
        blocker = _file_in_the_way(target.parent)
        where = f"{shown(blocker)} is a file, not a folder" if blocker else err.strerror
        return OutputError(
            target,
            f"cannot be written: {where}",
            "choose another output path, or move that file away",
        )
    if err.errno == errno.EISDIR:
        return OutputError(
            target, "is a folder, not a file", "give a file name, e.g. out/results.json"
        )
    if err.errno == errno.ENAMETOOLONG:
        return OutputError(
            target, "cannot be written: the name is too long", "choose a shorter output path"
        )
    return OutputError(target, f"cannot be written: {err.strerror or err}", "check the output path")


def _file_in_the_way(folder: Path) -> Path | None:
    """The nearest existing ancestor of `folder` (itself included) that is not a folder."""
    for p in (folder, *folder.parents):
        if os.path.lexists(p):
            return None if p.is_dir() else p
    return None


def check_output(path: str | os.PathLike[str], *, folder: bool = False) -> Path:
    """Refuse early (before a long analysis) an output that cannot be written:
    a folder where a file should go, a path under an existing file. Nothing is
    created; permissions are met when writing."""
    target = Path(path)
    where = target if folder else target.parent
    blocker = _file_in_the_way(where)
    if blocker is not None:
        raise OutputError(
            target,
            f"cannot be written: {shown(blocker)} is a file, not a folder",
            "choose another output path, or move that file away",
        )
    if not folder and target.is_dir():
        raise OutputError(
            target, "is a folder, not a file", "give a file name, e.g. out/results.json"
        )
    return target


def ensure_dir(folder: str | os.PathLike[str]) -> Path:
    """Create `folder` (and its parents) if need be; an OutputError if it cannot be."""
    folder = Path(folder)
    if folder.is_dir():
        return folder
    blocker = _file_in_the_way(folder)
    if blocker is not None:
        raise OutputError(
            folder,
            f"cannot be a folder: {shown(blocker)} is a file",
            "choose another output folder, or move that file away",
        )
    try:
        folder.mkdir(parents=True, exist_ok=True)
    except OSError as err:
        if err.errno in (errno.EACCES, errno.EPERM, errno.EROFS):
            raise OutputError(
                folder,
                f"cannot be created: {err.strerror}",
                "choose a folder you may write to, or change the permissions of its parent",
            ) from None
        raise _os_problem(err, folder / "x") from None
    return folder


@contextmanager
def atomic_path(path: str | os.PathLike[str]) -> Iterator[Path]:
    """A temporary path next to `path` for a writer that needs a file name;
    renamed onto `path` when the block completes, removed on any failure.

        with atomic_path("out/sheet1.pdf") as tmp:
            cairosvg.svg2pdf(bytestring=svg, write_to=str(tmp))
    """
    target = Path(path)
    ensure_dir(target.parent)
    if target.is_dir():
        raise OutputError(
            target, "is a folder, not a file", "give a file name, e.g. out/results.json"
        )
    tmp = target.with_name(f".{target.name}.tmp-{os.getpid()}-{os.urandom(4).hex()}")
    try:
        yield tmp
        os.replace(tmp, target)
    except OSError as err:
        raise _os_problem(err, target) from None
    finally:
        try:
            os.unlink(tmp)
        except OSError:
            pass


def write_bytes_atomic(path: str | os.PathLike[str], data: bytes) -> Path:
    """Write `data` to `path` atomically; returns the path."""
    target = Path(path)
    with atomic_path(target) as tmp:
        with open(tmp, "xb") as fh:  # "x": never through a link planted at the temporary name
            fh.write(data)
    return target


def write_text_atomic(path: str | os.PathLike[str], text: str) -> Path:
    """Write `text` as UTF-8 to `path` atomically (newlines as given); returns the path."""
    return write_bytes_atomic(path, text.encode("utf-8"))


# --- results ------------------------------------------------------------------------


def first_non_finite(data: Any) -> tuple[str, float] | None:
    """(where, value) of the first float in `data` (dicts, lists, tuples) that
    is NaN or infinite, as `positions[3].points.B[0]`; None when all are finite."""
    stack: list[tuple[str, Any]] = [("", data)]
    while stack:
        where, value = stack.pop()
        if isinstance(value, float):
            if not math.isfinite(value):
                return where or "(the value)", value
        elif isinstance(value, dict):
            stack.extend(
                (f"{where}.{k}" if where else str(k), v) for k, v in reversed(list(value.items()))
            )
        elif isinstance(value, (list, tuple)):
            stack.extend((f"{where}[{i}]", v) for i, v in reversed(list(enumerate(value))))
    return None


def finite_json(data: Any, source: str = "results") -> str:
    """`data` as JSON text (indent 1, a final newline), or a NonFiniteResultError
    naming the first number that is not finite (`source` names the input)."""
    bad = first_non_finite(data)
    if bad is not None:
        where, value = bad
        raise NonFiniteResultError(
            f"{shown(source)}: the result {shown(where, 200)} is {value}, not a finite number; "
            "nothing was written\n  fix: check the file's numbers (units are mm, kg, N, rpm); "
            "if they are sane, please report this file"
        )
    return json.dumps(data, indent=1, allow_nan=False) + "\n"


# --- reproducible documents ---------------------------------------------------------

FIXED_DATE = _dt.datetime(2000, 1, 1, tzinfo=_dt.UTC)


def document_date() -> str:
    """The creation date written into PDFs, ISO 8601: SOURCE_DATE_EPOCH when
    it is set (reproducible-builds.org), else a fixed date, so that two runs
    give the same bytes."""
    epoch = os.environ.get("SOURCE_DATE_EPOCH", "").strip()
    when = FIXED_DATE
    if epoch:
        try:
            when = _dt.datetime.fromtimestamp(int(epoch), _dt.UTC)
        except (ValueError, OverflowError, OSError):
            when = FIXED_DATE
    return when.strftime("%Y-%m-%dT%H:%M:%SZ")
