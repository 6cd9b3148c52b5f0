"""The force analysis's own error (kept at the root, mmt_plans.errors)."""

from __future__ import annotations

from ..errors import ForceError

__all__ = ["ForceError"]
