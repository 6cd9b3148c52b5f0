"""`mmt-plans serve TASKS_DIR`: a small web application for a class.

Students open a variant of TASKS_DIR, see its kinematic scheme, its given
data and what is to be found, type the values read off their drawings and
get `check`'s verdict and cause for each, the exact values withheld until
the instructor releases them. The instructor (behind a token) sees every
submission as a table and CSV and downloads the answer keys. `POST
/api/check/<variant>` is the same check for other tools.

Flask is imported only by `create_app` (app.py), so the other commands
start without it.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:  # pragma: no cover
    from .app import Settings

__all__ = ["create_app"]


def create_app(settings: Settings) -> Any:
    """The Flask application (imported here, not at the package's import)."""
    from .app import create_app as _create

    return _create(settings)
