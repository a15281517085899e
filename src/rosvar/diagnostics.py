"""Diagnostics: every problem found in the analysed files, with where it is.

Analysis never stops on bad input; it records a :class:`Diagnostic` and carries on,
so one broken file never hides what the rest of a workspace says.
"""

from __future__ import annotations

import enum
from dataclasses import dataclass, field


class Severity(enum.Enum):
    """How bad a diagnostic is; ``ERROR`` means roslaunch would refuse the file."""

    ERROR = "error"
    WARNING = "warning"
    NOTE = "note"


@dataclass(frozen=True, order=True, init=False)
class Location:
    """A position in a file (1-based line and column, as editors count)."""

    file: str
    line: int = 0
    col: int = 0

    def __init__(self, file: str, line: int = 0, col: int = 0) -> None:
        # Written out: a frozen dataclass's own sets each field through
        # ``object.__setattr__``, twice as slow, and a parse makes one per element.
        fields = self.__dict__
        fields["file"] = file
        fields["line"] = line
        fields["col"] = col

    def __str__(self) -> str:
        if self.line <= 0:
            return self.file
        return f"{self.file}:{self.line}:{self.col}"

    def to_json(self) -> dict[str, object]:
        return {"file": self.file, "line": self.line, "col": self.col}


@dataclass(frozen=True)
class Diagnostic:
    """One finding: a stable ``code`` for tools, a message for people."""

    code: str
    severity: Severity
    message: str
    location: Location

    def __str__(self) -> str:
        return f"{self.location}: {self.severity.value}: {self.message} [{self.code}]"


READ_AS_ROSLAUNCH = frozenset(
    {"tag-unknown", "attribute-unknown", "node-name-illegal", "launch-nested-root"}
)
"""Codes of warnings about something roslaunch itself only warns of and reads past, as
rosvar does: what the file loads is known all the same."""


def leaves_unknown(diagnostic: Diagnostic) -> bool:
    """Whether the file it is about loads something rosvar does not know: a warning or an
    error (a part not followed, not read, or only known per configuration), not a note."""
    return diagnostic.severity is not Severity.NOTE and diagnostic.code not in READ_AS_ROSLAUNCH


@dataclass
class DiagnosticSink:
    """Collects diagnostics in the order they are found, without duplicates."""

    items: list[Diagnostic] = field(default_factory=list)
    _seen: set[Diagnostic] = field(default_factory=set, repr=False)

    def add(self, diagnostic: Diagnostic) -> None:
        if diagnostic not in self._seen:
            self._seen.add(diagnostic)
            self.items.append(diagnostic)

    def error(self, code: str, message: str, location: Location) -> None:
        self.add(Diagnostic(code, Severity.ERROR, message, location))

    def warning(self, code: str, message: str, location: Location) -> None:
        self.add(Diagnostic(code, Severity.WARNING, message, location))

    def note(self, code: str, message: str, location: Location) -> None:
        self.add(Diagnostic(code, Severity.NOTE, message, location))

    def extend(self, diagnostics: list[Diagnostic]) -> None:
        for diagnostic in diagnostics:
            self.add(diagnostic)
