"""The one rule of every command: an `MmtError` becomes one clean message on
stderr and exit code 2; anything else is a bug and keeps its traceback.

Kept apart from cli.py so that a command module (draw, check, batch) can be
imported on its own, before or without the command group.
"""

from __future__ import annotations

import sys
from functools import wraps

import click

from .errors import MmtError

__all__ = ["reports_errors"]


def reports_errors(fn):
    @wraps(fn)
    def wrapper(*args, **kwargs):
        try:
            return fn(*args, **kwargs)
        except MmtError as err:
            click.echo(f"error: {err}", err=True)
            sys.exit(2)
    return wrapper
