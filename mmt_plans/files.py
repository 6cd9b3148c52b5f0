"""Reading inputs and writing outputs safely: the two doors of the tool.

Inputs (a mechanism file, an answers file) are read by `read_input`, which
refuses, before reading a byte, anything that is not a regular file of at
most `MAX_INPUT_BYTES` (a folder, a FIFO that would block forever, /dev/zero
that would fill the memory), and then text that is not UTF-8. Every refusal
is a `SpecError(path, "file", problem, fix)`.

Outputs are written atomically: into a hidden temporary file next to the
target (`.NAME.tmp-<pid>-<random>`), synced to the disk, renamed onto the
target only once it is complete (then the folder is synced), removed on any
failure: an interrupted run or a power cut leaves each output either as it
was or complete, never half-written. A killed run cannot remove its
temporary file: the next run writing into that folder sweeps it
(`sweep_stale_temporaries`: our pattern, older than this run, of a process
no longer alive). An output goes only where a file belongs, a regular file
or a new path: a symbolic link, FIFO, device or socket there is refused, as
replacing it would destroy it. A target that cannot be written (a read-only
folder or full disk, said in words; a path under an existing file; a folder
where a file should go; a name over NAME_MAX bytes) is an `OutputError`
naming the path and the fix. `SOURCE_DATE_EPOCH` is read here, once, for
every dated output.

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
import re
import stat
import sys
import time
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import Any

from .errors import MmtError, SettingError, SpecError, shown

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
    "source_date_epoch",
    "check_environment",
    "sweep_stale_temporaries",
    "temporary_name",
    "write_output",
    "STDOUT",
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

STDOUT = "-"
"""The output name that means standard output, where a command offers it."""

NAME_MAX = 255
"""The most bytes one name of a path may have (ext4, XFS, tmpfs, APFS, NTFS)."""

_TEMP_NAME = re.compile(r"^\..+\.tmp-(\d+)-[0-9a-f]{8}$", re.DOTALL)
"""Our temporary files: `.NAME.tmp-<pid>-<8 hex digits>` (atomic_path)."""

RUN_STARTED = time.time()
"""When this run started: a temporary file older than this, of a process no
longer alive, was left by a run that was killed (sweep_stale_temporaries)."""

_SWEPT: set[str] = set()

# errno → what it means for an output, in words a user acts on
_ERRNO_WORDS = {
    errno.ENOSPC: ("the disk is full", "free some space, or write elsewhere"),
    errno.EDQUOT: ("the disk quota is exceeded", "free some space, or write elsewhere"),
    errno.EROFS: (
        "the file system is read-only",
        "write to a folder on a writable disk (-o / --json)",
    ),
    errno.EFBIG: ("the file is too large for this file system", "write elsewhere"),
    errno.EIO: (
        "an input/output error (a failing disk or a lost network share?)",
        "check the disk, or write elsewhere",
    ),
    errno.EBUSY: ("the file is busy", "close what uses it, or write elsewhere"),
    errno.ETXTBSY: ("the file is busy", "close what uses it, or write elsewhere"),
    errno.ELOOP: (
        "its path has a loop of symbolic links",
        "choose an output path without that link",
    ),
}


def _node_kind(mode: int) -> str:
    """What a node that is not where a file belongs is, in words."""
    if stat.S_ISLNK(mode):
        return "a symbolic link"
    if stat.S_ISREG(mode):
        return "a file"
    return _kind(mode)


def _lstat(path: Path) -> os.stat_result | None:
    """The lstat of `path`, None when nothing is there; an OutputError for a
    name that is too long (Path.is_dir() would raise it unhandled)."""
    try:
        return os.lstat(path)
    except FileNotFoundError:
        return None
    except NotADirectoryError:
        return None  # a parent is a file: _file_in_the_way names it
    except OSError as err:
        raise _os_problem(err, path) from None


def _check_name_lengths(target: Path) -> None:
    for part in target.parts:
        size = len(os.fsencode(part))
        if size > NAME_MAX:
            raise OutputError(
                target,
                f"cannot be written: the name {shown(part, 40)} is {size} bytes, more than "
                f"the {NAME_MAX} a file or folder name may have",
                "choose a shorter output name",
            )


def _refuse_node(target: Path) -> None:
    """Refuse an existing output that is not a regular file: replacing a
    symbolic link, a FIFO, a device (/dev/null) or a socket with a regular
    file would destroy it (as root, a system node)."""
    st = _lstat(target)
    if st is None or stat.S_ISREG(st.st_mode):
        return
    if stat.S_ISDIR(st.st_mode):
        raise OutputError(
            target, "is a folder, not a file", "give a file name, e.g. out/results.json"
        )
    what = _node_kind(st.st_mode)
    if stat.S_ISLNK(st.st_mode):
        what += f" (to {shown(os.readlink(target), 200)})"
    raise OutputError(
        target,
        f"is {what}: mmt-plans writes only to a regular file or a new path, and would replace it",
        "give the path of a regular file, or a new one",
    )


def _os_problem(err: OSError, target: Path) -> OutputError:
    """A clean OutputError for an OSError met while writing `target`."""
    if isinstance(err, OutputError):
        return err
    if not isinstance(err.errno, int):
        # cairocffi raises IOError(message, cairo status): no errno to read;
        # find out from the folder why it could not be written
        return _cairo_problem(target)
    if err.errno in (errno.EACCES, errno.EPERM):
        return OutputError(
            target,
            f"cannot be written: {err.strerror}",
            "choose a folder you may write to (-o / --json), or change its permissions",
        )
    if err.errno in _ERRNO_WORDS:
        words, fix = _ERRNO_WORDS[err.errno]
        return OutputError(target, f"cannot be written: {words}", fix)
    if err.errno in (errno.ENOTDIR, errno.EEXIST):
        blocker = _file_in_the_way(target.parent)
        where = (
            f"{shown(blocker)} is {_node_kind(os.lstat(blocker).st_mode)}, not a folder"
            if blocker
            else err.strerror
        )
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
            target,
            f"cannot be written: the name is too long (at most {NAME_MAX} bytes a name)",
            "choose a shorter output path",
        )
    return OutputError(
        target,
        f"cannot be written: {err.strerror or os.strerror(err.errno)}",
        "check the output path",
    )


def _cairo_problem(target: Path) -> OutputError:
    """Why Cairo could not write `target`, found from its folder."""
    folder = target.parent
    try:
        vfs = os.statvfs(folder)
        if vfs.f_flag & getattr(os, "ST_RDONLY", 1):
            words, fix = _ERRNO_WORDS[errno.EROFS]
            return OutputError(target, f"cannot be written: {words}", fix)
        if vfs.f_bavail == 0:
            words, fix = _ERRNO_WORDS[errno.ENOSPC]
            return OutputError(target, f"cannot be written: {words}", fix)
    except OSError:
        pass
    if not os.access(folder, os.W_OK):
        return OutputError(
            target,
            "cannot be written: Permission denied",
            "choose a folder you may write to (-o / --json), or change its permissions",
        )
    return OutputError(
        target,
        "cannot be written: the writer failed (the disk full or removed?)",
        "check the disk, or write elsewhere",
    )


def _file_in_the_way(folder: Path) -> Path | None:
    """The nearest existing ancestor of `folder` (itself included) that is not
    a folder (a symbolic link to a folder counts as one)."""
    for p in (folder, *folder.parents):
        st = _lstat(p)
        if st is None:
            continue
        if stat.S_ISDIR(st.st_mode):
            return None
        if stat.S_ISLNK(st.st_mode):
            return None if _is_dir(p) else p
        return p
    return None


def _is_dir(path: Path) -> bool:
    try:
        return stat.S_ISDIR(os.stat(path).st_mode)
    except OSError:
        return False


def _not_a_folder(path: Path, blocker: Path, verb: str) -> OutputError:
    st = _lstat(blocker)
    what = "missing" if st is None else _node_kind(st.st_mode)
    if st is not None and stat.S_ISLNK(st.st_mode):
        what += f" to {shown(os.readlink(blocker), 200)}"
        st2 = _stat_or_none(blocker)
        what += f" ({_node_kind(st2.st_mode)})" if st2 else " (which leads nowhere)"
    problem = f"{verb}: {shown(blocker)} is {what}, not a folder"
    return OutputError(path, problem, "choose another output path, or move that file away")


def _stat_or_none(path: Path) -> os.stat_result | None:
    try:
        return os.stat(path)
    except OSError:
        return None


def check_output(
    path: str | os.PathLike[str], *, folder: bool = False, stdout: bool = False
) -> Path:
    """Refuse early (before a long analysis) an output that cannot be written:
    a name too long, a path under an existing file, a folder where a file
    should go, a symbolic link, FIFO, device or socket where a file should go
    (or, for a folder, a node that is no folder). `stdout`: the command writes
    "-" to standard output. Nothing is created; permissions are met when writing."""
    target = Path(path)
    if stdout and str(path) == STDOUT:
        return target
    _check_name_lengths(target)
    where = target if folder else target.parent
    blocker = _file_in_the_way(where)
    if blocker is not None:
        raise _not_a_folder(target, blocker, "cannot be written")
    if not folder:
        _refuse_node(target)
    return target


def ensure_dir(folder: str | os.PathLike[str]) -> Path:
    """Create `folder` (and its parents) if need be; an OutputError if it cannot be."""
    folder = Path(folder)
    _check_name_lengths(folder)
    if _is_dir(folder):
        return folder
    blocker = _file_in_the_way(folder)
    if blocker is not None:
        raise _not_a_folder(folder, blocker, "cannot be a folder")
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


def temporary_name(target: Path) -> Path:
    """The hidden temporary file beside `target`: `.NAME.tmp-<pid>-<random>`,
    NAME cut so that the whole stays within NAME_MAX bytes."""
    tail = f".tmp-{os.getpid()}-{os.urandom(4).hex()}"
    name = target.name
    room = NAME_MAX - 1 - len(tail)
    if len(os.fsencode(name)) > room:
        name = os.fsencode(name)[:room].decode("utf-8", "ignore")
    return target.with_name(f".{name}{tail}")


def _pid_alive(pid: int) -> bool:
    """Whether process `pid` still runs: a zombie (killed, not yet reaped: a
    killed run's worker whose parent died first) does not."""
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except OSError:
        return True  # alive, another user's
    try:
        with open(f"/proc/{pid}/stat", "rb") as f:
            state = f.read().rsplit(b")", 1)[1].split()[0]
    except (OSError, IndexError):
        return True
    return state not in (b"Z", b"X")


def sweep_stale_temporaries(folder: str | os.PathLike[str]) -> list[Path]:
    """Remove from `folder` the temporary files that killed runs left: only
    our own names (`.NAME.tmp-<pid>-<hex>`), regular files, older than this
    run and of a process that is no longer alive (never another live run's).
    Once per folder and run; returns what was removed."""
    folder = Path(folder)
    key = os.path.abspath(folder)
    if key in _SWEPT:
        return []
    _SWEPT.add(key)
    removed: list[Path] = []
    try:
        names = os.listdir(folder)
    except OSError:
        return removed
    for name in names:
        match = _TEMP_NAME.match(name)
        if match is None:
            continue
        pid = int(match.group(1))
        path = folder / name
        try:
            st = os.lstat(path)
        except OSError:
            continue
        if not stat.S_ISREG(st.st_mode) or st.st_mtime >= RUN_STARTED:
            continue
        if pid == os.getpid() or _pid_alive(pid):
            continue
        try:
            os.unlink(path)
            removed.append(path)
        except OSError:
            pass
    return removed


def _fsync_folder(folder: Path) -> None:
    try:
        fd = os.open(folder, os.O_RDONLY | getattr(os, "O_DIRECTORY", 0))
    except OSError:
        return
    try:
        os.fsync(fd)
    except OSError:
        pass  # some file systems cannot sync a folder: the rename still is atomic
    finally:
        os.close(fd)


def _fsync_file(path: Path) -> None:
    fd = os.open(path, os.O_RDONLY)
    try:
        os.fsync(fd)
    finally:
        os.close(fd)


@contextmanager
def atomic_path(path: str | os.PathLike[str]) -> Iterator[Path]:
    """A temporary path next to `path` for a writer that needs a file name;
    synced to the disk and renamed onto `path` when the block completes,
    removed on any failure. `path` must be a regular file or a new path (a
    symbolic link, FIFO, device or socket there is refused, OutputError).

        with atomic_path("out/sheet1.pdf") as tmp:
            cairosvg.svg2pdf(bytestring=svg, write_to=str(tmp))
    """
    target = Path(path)
    _check_name_lengths(target)
    ensure_dir(target.parent)
    sweep_stale_temporaries(target.parent)
    _refuse_node(target)
    tmp = temporary_name(target)
    try:
        yield tmp
        _fsync_file(tmp)  # the data on the disk before the name points at it
        _refuse_node(target)  # nothing planted there meanwhile
        os.replace(tmp, target)
        _fsync_folder(target.parent)  # the rename itself on the disk
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


def write_output(path: str | os.PathLike[str], text: str) -> str:
    """`text` to `path` (atomically), or to standard output when `path` is
    "-"; returns where it went, for a message."""
    if str(path) == STDOUT:
        sys.stdout.write(text)
        sys.stdout.flush()
        return "standard output"
    return str(write_text_atomic(path, text))


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


def source_date_epoch() -> _dt.datetime | None:
    """$SOURCE_DATE_EPOCH (reproducible-builds.org) as a UTC date, None when
    it is not set; an MmtError naming the variable when it is not whole
    seconds since 1970 (1.5, a date, a number past the year 9999): the PDF,
    the DXF and the note's year all read it here, so all refuse it alike."""
    raw = os.environ.get("SOURCE_DATE_EPOCH", "")
    epoch = raw.strip()
    if not epoch:
        return None
    if not (epoch.isascii() and epoch.isdigit()) or len(epoch) > 12:
        raise SettingError(
            f"SOURCE_DATE_EPOCH: '{shown(raw, 40)}' is not whole seconds since "
            "1970-01-01 00:00 UTC (an integer from 0 to 253402300799)\n"
            "  fix: unset it, or set it to an integer, e.g. SOURCE_DATE_EPOCH=1700000000"
        )
    try:
        return _dt.datetime.fromtimestamp(int(epoch), _dt.UTC)
    except (ValueError, OverflowError, OSError):
        raise SettingError(
            f"SOURCE_DATE_EPOCH: '{shown(raw, 40)}' is past the year 9999\n"
            "  fix: unset it, or set it to an integer, e.g. SOURCE_DATE_EPOCH=1700000000"
        ) from None


def check_environment() -> None:
    """Refuse, before any work, an environment variable the outputs would read."""
    source_date_epoch()


def document_date() -> str:
    """The creation date written into PDFs, ISO 8601: SOURCE_DATE_EPOCH when
    it is set (reproducible-builds.org), else a fixed date, so that two runs
    give the same bytes; an MmtError when it is set to something else than
    whole seconds (source_date_epoch)."""
    when = source_date_epoch() or FIXED_DATE
    return when.strftime("%Y-%m-%dT%H:%M:%SZ")
