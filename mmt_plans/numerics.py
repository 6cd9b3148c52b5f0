"""numpy's floating-point warnings kept off the user's terminal: the tool's own
checks (finite results, singular plans) say what went wrong instead."""

from __future__ import annotations

import warnings
from typing import Any

__all__ = ["quiet_numerics"]


class quiet_numerics:
    """numpy's floating-point errors and RuntimeWarnings silenced within."""

    def __enter__(self) -> quiet_numerics:
        import numpy as np

        self._errstate = np.errstate(all="ignore")
        self._errstate.__enter__()
        self._warnings = warnings.catch_warnings()
        self._warnings.__enter__()
        warnings.simplefilter("ignore", RuntimeWarning)
        return self

    def __exit__(self, *exc: Any) -> None:
        self._warnings.__exit__(*exc)
        self._errstate.__exit__(*exc)
