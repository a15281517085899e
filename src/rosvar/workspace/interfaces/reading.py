"""Reading source files for extraction: the one place that opens them.

Sources, CMake files and headers come from repositories nobody vetted, as launch files do,
so they pass the same gate (:func:`rosvar.files.read_file`): regular files only (a FIFO
named ``node.cpp`` would block, ``/dev/zero`` would fill memory), at most
:data:`MAX_SOURCE_BYTES`, and within the workspace (a source symlinked to ``/etc/passwd``
must not end up in the output). Each refusal is reported once, at the refused file, with
the gate's code; a file that does not exist is no finding (a generated source, a header of
another package). Text is decoded leniently: a stray byte in a comment must not hide a
node's interface.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from rosvar.diagnostics import DiagnosticSink, Location
from rosvar.files import Confinement, FileRefused, read_file

MAX_SOURCE_BYTES = 4 * 1024 * 1024
"""No hand-written node is larger; a generated or vendored blob is not worth parsing."""


@dataclass
class SourceReader:
    """Reads the files of one extraction run, confined to ``confinement`` (None: anywhere
    but the system trees), reporting refusals to ``sink``."""

    confinement: Confinement | None = None
    sink: DiagnosticSink | None = None
    _refused: set[str] = field(default_factory=set)

    def data(self, path: str) -> bytes | None:
        """The bytes of ``path``; None when it cannot or may not be read."""
        try:
            return read_file(path, self.confinement, MAX_SOURCE_BYTES)
        except FileRefused as refusal:
            if self.sink is not None and path not in self._refused:
                self._refused.add(path)
                self.sink.warning(str(refusal.code), f"not read: {refusal}", Location(path))
            return None
        except (OSError, ValueError):
            return None

    def text(self, path: str) -> str | None:
        data = self.data(path)
        return None if data is None else data.decode("utf-8", errors="replace")
