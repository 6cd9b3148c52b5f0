"""The one guard of every command, at the CLI boundary.

- an `MmtError` (bad input, an output that cannot be written) becomes one
  clean `error: ...` message on stderr and exit code 2;
- Ctrl-C (KeyboardInterrupt) exits with 130, without a traceback;
- anything else is a bug: exit code 3 and ONE line naming the file and the
  exception's type; the traceback is printed only with `mmt-plans --debug`
  (or the environment variable MMT_PLANS_DEBUG=1).

numpy's floating-point warnings never reach the terminal: every command runs
inside `np.errstate(all="ignore")` with RuntimeWarnings filtered out (a
non-finite number that matters is caught where it is written, by
files.finite_json).

Kept apart from cli.py so that a command module (draw, check, batch) can be
imported on its own, before or without the command group.
"""

from __future__ import annotations

import os
import sys
import traceback
from functools import wraps
from pathlib import Path

import click

from ..errors import MmtError, shown
from ..numerics import quiet_numerics

__all__ = [
    "reports_errors",
    "debug_enabled",
    "quiet_numerics",
    "EXIT_OK",
    "EXIT_FAILED",
    "EXIT_BAD_INPUT",
    "EXIT_INTERNAL",
    "EXIT_INTERRUPTED",
    "DEBUG_ENV",
]

EXIT_OK = 0  # done (check: every value within the tolerance)
EXIT_FAILED = 1  # check: some value out of the tolerance; batch: some file failed
EXIT_BAD_INPUT = 2  # an MmtError: a bad input file or option, an unwritable output
EXIT_INTERNAL = 3  # a bug: please report it
EXIT_INTERRUPTED = 130  # Ctrl-C

DEBUG_ENV = "MMT_PLANS_DEBUG"


def debug_enabled() -> bool:
    """`mmt-plans --debug ...`, or MMT_PLANS_DEBUG=1 in the environment."""
    if os.environ.get(DEBUG_ENV, "").strip() not in ("", "0"):
        return True
    ctx = click.get_current_context(silent=True)
    while ctx is not None:
        if ctx.params.get("debug"):
            return True
        ctx = ctx.parent
    return False


def _subject(kwargs: dict) -> str:
    """What the command was working on, for the one-line report of a bug."""
    for key in ("file", "answers"):
        if kwargs.get(key) is not None:
            return str(kwargs[key])
    inputs = kwargs.get("inputs")
    if inputs:
        return str(inputs[0]) if len(inputs) == 1 else f"{inputs[0]} (and {len(inputs) - 1} more)"
    return "mmt-plans"


def _named(err: MmtError, kwargs: dict) -> str:
    """The message of `err`, with the file the command worked on in front
    when the message names no file of its own (a layout, an assembly or a
    force error raised far from the file)."""
    text = str(err)
    if kwargs.get("file") is None or getattr(err, "path", None):
        return text
    subject = shown(kwargs["file"])
    first = text.split("\n", 1)[0]
    if subject in first or Path(subject).name in first or first.startswith("SOURCE_DATE"):
        return text
    return f"{subject}: {text}"


def reports_errors(fn):
    @wraps(fn)
    def wrapper(*args, **kwargs):
        try:
            with quiet_numerics():
                from ..files import check_environment

                check_environment()  # SOURCE_DATE_EPOCH: refused at the door, by every command
                return fn(*args, **kwargs)
        except MmtError as err:
            # each line printable: no terminal control sequence from an input
            text = "\n".join(shown(line, 10_000) for line in _named(err, kwargs).split("\n"))
            click.echo(f"error: {text}", err=True)
            sys.exit(EXIT_BAD_INPUT)
        except KeyboardInterrupt:
            click.echo("interrupted", err=True)
            sys.exit(EXIT_INTERRUPTED)
        except (click.exceptions.ClickException, click.exceptions.Exit, click.exceptions.Abort):
            raise  # click's own: usage errors (exit 2), --help, an abort
        except Exception as err:
            if debug_enabled():
                traceback.print_exc(file=sys.stderr)
            click.echo(
                f"error: {shown(_subject(kwargs))}: internal error ({type(err).__name__}), "
                "please report it (run with --debug for the traceback)",
                err=True,
            )
            sys.exit(EXIT_INTERNAL)

    return wrapper
