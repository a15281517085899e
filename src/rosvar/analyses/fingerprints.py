"""Stable fingerprints of findings, so that a later run can tell which findings are new.

A fingerprint must survive what does not change the finding: another checkout path or
machine, another run, an unrelated edit that moves lines. So it is made of the finding's
check, its resolved name, its message (built from resolved names) and its files, each
relative to its package (``husky_control/launch/control.launch``; outside every package,
to the workspace root given in that place of the command line), never of line numbers or
absolute paths. Two findings alike in all of these share a fingerprint: a baseline
counts them (:func:`new_findings`).
"""

from __future__ import annotations

import hashlib
import os
import re
from collections import Counter
from collections.abc import Iterable, Sequence

from rosvar.analyses.checks import Finding
from rosvar.workspace.packages import Package

_NUMBERS = re.compile(r"(:\d+)+$")
VERSION = "rosvar/v1"
"""The key of the fingerprint among SARIF's ``partialFingerprints``; a new recipe gets a new one."""


class Fingerprints:
    """The fingerprints of findings of one workspace (its packages place the files, else
    its roots: a file a launch names that no package holds)."""

    def __init__(self, packages: Iterable[Package], roots: Sequence[str] = ()) -> None:
        places = [(os.path.abspath(p.path), p.name) for p in packages]
        folders = [root if os.path.isdir(root) else os.path.dirname(root) for root in roots]
        places += [(os.path.abspath(f), f"<root{i}>") for i, f in enumerate(folders)]
        self._roots = sorted(places, key=lambda r: -len(r[0]))  # the innermost place first

    def relative(self, file: str) -> str:
        """``file`` as ``package/path`` inside its package; a URL as it is; else its name."""
        if "://" in file:
            return file
        if not os.path.isabs(file) and os.sep in file and " " in file:
            # a described place ("the text of the parameter at /ws/pkg/f.launch:15:3")
            return self._place(file)
        absolute = os.path.abspath(file)
        for root, name in self._roots:
            if absolute.startswith(root + os.sep):
                return f"{name}/{os.path.relpath(absolute, root)}".replace(os.sep, "/")
        return os.path.basename(absolute)

    def _place(self, text: str) -> str:
        """``text`` with its package folders as package names and no trailing ``:line:col``."""
        return _NUMBERS.sub("", self._within(text))

    def _within(self, text: str) -> str:
        """``text`` with each package folder written as its package's name."""
        for root, name in self._roots:
            text = text.replace(root + os.sep, name + "/")
        return text

    def of(self, finding: Finding) -> str:
        parts = [
            str(finding.check),
            self._place(finding.name),  # an `unread` finding names a file or a place in one
            self._within(finding.message),  # a message naming a file names it in its package
            self.relative(finding.file),
            *(self.relative(location.file) for location in finding.locations),
        ]
        return hashlib.sha256("\x1f".join(parts).encode()).hexdigest()[:32]


def new_findings(
    findings: Sequence[Finding], fingerprints: Sequence[str], known: Iterable[str]
) -> list[Finding]:
    """The findings a baseline with the fingerprints ``known`` does not hold: of findings
    sharing a fingerprint, those beyond the baseline's count."""
    left = Counter(known)
    new = []
    for finding, fingerprint in zip(findings, fingerprints, strict=True):
        if left[fingerprint] > 0:
            left[fingerprint] -= 1
        else:
            new.append(finding)
    return new
