"""One root exception; each subclass also inherits the builtin it resembles.

The CLI catches `MmtError`, prints `str(err)` and exits with code 2. Anything
else reaching the CLI is a bug: exit code 3 and one line, the traceback only
with `mmt-plans --debug` (cli/errors.reports_errors).
"""

from __future__ import annotations

# A part of a message (a file name, an entry, a name from the file) longer
# than this is cut: a 1 MB key must not become a 1 MB message.
MESSAGE_PART_MAX = 1000


def shown(text: object, limit: int = MESSAGE_PART_MAX) -> str:
    """`text` as it may appear in a message: control and format characters
    (a newline, NUL, a bidirectional override) escaped as \\n, \\x00, \\u202e,
    and cut to `limit` characters with "..." after it."""
    text = str(text)
    if not text.isprintable():
        text = "".join(
            ch if ch.isprintable() else ch.encode("unicode_escape").decode("ascii") for ch in text
        )
    if len(text) > limit:
        text = text[:limit] + "..."
    return text


class MmtError(Exception):
    """Root of every error mmt_plans reports to a user."""


class SpecError(MmtError, ValueError):
    """A mechanism file (or answers file) that cannot be accepted as written.

    The message names the file, the entry and the fix.
    """

    def __init__(self, path: str, entry: str, problem: str, fix: str = "") -> None:
        # Names from the file reach the message only escaped: no raw newline,
        # NUL or terminal control sequence from an input is ever printed.
        self.path, self.entry, self.problem, self.fix = str(path), entry, problem, fix
        text = f"{shown(path)}: {shown(entry)}: {shown(problem)}"
        if fix:
            text += f"\n  fix: {shown(fix)}"
        super().__init__(text)


class SettingError(MmtError, ValueError):
    """An environment variable or option set to a value the tool cannot use
    (SOURCE_DATE_EPOCH=1.5); the message names it and the fix."""


class StructureError(MmtError, ValueError):
    """The links and pairs do not form a mechanism we can decompose or move."""


class AssemblyError(MmtError, ArithmeticError):
    """A group cannot assemble at a crank angle."""

    def __init__(self, phi1_deg: float, group: str, reason: str) -> None:
        self.phi1_deg, self.group, self.reason = phi1_deg, group, reason
        super().__init__(f"at phi1 = {phi1_deg:.10g} deg, group {group} cannot assemble: {reason}")


class SingularPlanError(MmtError, ArithmeticError):
    """A velocity or acceleration plan whose two direction lines are parallel."""

    def __init__(self, phi1_deg: float, group: str, reason: str) -> None:
        self.phi1_deg, self.group, self.reason = phi1_deg, group, reason
        super().__init__(
            f"at phi1 = {phi1_deg:.10g} deg, the plan of group {group} is singular: {reason}"
        )


class ForceError(MmtError, ValueError):
    """The force analysis cannot be done as asked; the message says why and what to change."""

    def __init__(
        self,
        problem: str,
        fix: str = "",
        *,
        phi1_deg: float | None = None,
        group: str | None = None,
    ) -> None:
        self.problem, self.fix, self.phi1_deg, self.group = problem, fix, phi1_deg, group
        where = []
        if phi1_deg is not None:
            where.append(f"at phi1 = {phi1_deg:.6g} deg")
        if group is not None:
            where.append(f"group {group}")
        text = (", ".join(where) + ": " if where else "") + problem
        if fix:
            text += f"\n  fix: {fix}"
        super().__init__(text)


class UnsupportedError(MmtError, NotImplementedError):
    """Something the file describes correctly that mmt_plans does not solve."""


class PartialTurnError(SpecError):
    """The driving link cannot make a whole turn: some group cannot assemble
    for part of it. The message names the group, the crank-angle ranges where
    the mechanism assembles and the fix."""

    def __init__(
        self, path: str, entry: str, problem: str, fix: str, ranges: tuple[tuple[float, float], ...]
    ) -> None:
        self.ranges = ranges
        super().__init__(path, entry, problem, fix)


def degrees_range(lo: float, hi: float) -> str:
    """ "12.5°…171.3°": a crank-angle interval, counter-clockwise from lo to hi."""
    return f"{lo:.6g}°…{hi:.6g}°"


def partial_turn_error(mech, choice) -> PartialTurnError:
    """The refusal of a mechanism whose chosen branches do not turn fully
    (`kinematics.branches.Branches`)."""
    spans = ", ".join(degrees_range(lo, hi) for lo, hi in choice.ranges)
    where = (
        f"assembles for phi1 in {spans} (counter-clockwise)"
        if spans
        else "assembles at no crank angle"
    )
    problem = f"the crank cannot make a whole turn: {choice.failing_reason}; the mechanism {where}"
    fixes = []
    if choice.rule == "sketch" and choice.full_turn:
        combos = "; ".join(
            ", ".join(f"group {g} {s:+d}" for g, s in c.items()) for c in choice.full_turn
        )
        problem += f"; the sketched branches do not turn fully, these do: {combos}"
        fixes.append("sketch one of the combinations that turn fully")
    if choice.cure:
        fixes.append(choice.cure)
    fixes.append(
        "or opt in with [study] partial_turn = true (or --partial-turn) to analyse "
        "only the range where it assembles"
    )
    entry = f"group {choice.failing_group}" if choice.failing_group else "link"
    return PartialTurnError(mech.path, entry, problem, "; ".join(fixes), choice.ranges)
