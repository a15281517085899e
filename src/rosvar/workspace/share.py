"""A ROS 2 source package's share folder as its install rules fill it.

``$(find-pkg-share p)`` (``FindPackageShare``) is ``<prefix>/share/p``, which holds what the
build installs there, not the source tree: ros2_control_demos' ``install(DIRECTORY
bringup/config DESTINATION share/${PROJECT_NAME})`` makes ``bringup/config/x.yaml`` the
share's ``config/x.yaml``. rosvar lets a source package's own folder stand for its share
folder (the paths it shows are those), and reads a path below it that is not found from the
source file the install copies there (a path that exists is read where it is: the common
``install(DIRECTORY launch config ...)`` keeps the source's layout): CMake's
``install(DIRECTORY|FILES|PROGRAMS ... DESTINATION share/<package>[/sub])`` and
``ament_auto_package(INSTALL_TO_SHARE ...)``, read by
:mod:`rosvar.workspace.interfaces.cmake`, and an ament_python ``setup.py``'s ``data_files``
(:mod:`rosvar.workspace.python_setup`). A path no rule covers stays as it is, as does a path
below a rule rosvar cannot read (told once per rule, ``install-unread``).
"""

from __future__ import annotations

import fnmatch
import glob
import itertools
import os
from dataclasses import dataclass

from rosvar.diagnostics import Diagnostic, Location, Severity
from rosvar.files import Confinement
from rosvar.workspace.interfaces.cmake import (
    CMAKE_FILE,
    INSTALL_UNREAD,
    SHARE_FOLDER,
    Shared,
    read_build,
)
from rosvar.workspace.interfaces.reading import SourceReader
from rosvar.workspace.python_setup import data_files

SETUP_FILE = "setup.py"
MAX_GLOBBED = 10_000
"""Files one ``data_files`` glob may give; the rest are not mapped."""


@dataclass(frozen=True)
class ShareMap:
    """What a source package's install rules put in its share folder, in order (a later rule
    overwrites an earlier one's file), and the rules rosvar could not read."""

    shared: tuple[Shared, ...]
    diagnostics: tuple[Diagnostic, ...]

    def source(self, relative: str) -> str | None:
        """The existing source file or folder the install puts at ``relative`` (a path below
        ``share/<package>``); None when no rule puts one there."""
        for rule in reversed(self.shared):
            tail = _below(relative, rule.destination)
            if tail is None or (tail and not _kept(rule, tail)):
                continue
            candidate = os.path.join(rule.source, tail) if tail else rule.source
            if os.path.exists(candidate):
                return candidate
        return None


def _below(path: str, folder: str) -> str | None:
    """``path`` relative to ``folder`` ("" for itself; ``folder`` "" is the share folder)."""
    if path == folder:
        return ""
    if not folder:
        return path
    return path[len(folder) + 1 :] if path.startswith(folder + "/") else None


def _kept(rule: Shared, tail: str) -> bool:
    """Whether a folder rule copies its file ``tail``: its ``PATTERN``s (``FILES_MATCHING``)
    match the file's name and none of the excluded ones matches a part of its path."""
    parts = tail.split("/")
    if any(fnmatch.fnmatchcase(part, glob) for part in parts for glob in rule.excluded):
        return False
    return not rule.patterns or any(fnmatch.fnmatchcase(parts[-1], p) for p in rule.patterns)


def share_map(package_dir: str, package_name: str) -> ShareMap:
    """The share folder of the source package at ``package_dir``: its CMake install rules,
    then its ``setup.py``'s ``data_files`` (each read within the package)."""
    reader = SourceReader(Confinement.of([package_dir]))
    shared: list[Shared] = []
    diagnostics: list[Diagnostic] = []
    if os.path.isfile(os.path.join(package_dir, CMAKE_FILE)):
        build = read_build(package_dir, package_name, reader)
        shared.extend(build.shared)
        diagnostics.extend(build.unread_installs)
    setup = os.path.join(package_dir, SETUP_FILE)
    text = reader.text(setup) if os.path.isfile(setup) else None
    share = f"{SHARE_FOLDER}/{package_name}"
    for entry in data_files(text or ""):
        destination = None if entry.destination is None else os.path.normpath(entry.destination)
        sub = None if destination is None else _below(destination.lstrip("/"), share)
        if entry.files is None or destination is None:
            if destination is None or sub is not None:
                diagnostics.append(_unread(setup, entry.line))
            continue
        if sub is None:
            continue
        for file in entry.files:
            pattern = os.path.join(package_dir, file.path)
            found = itertools.islice(glob.iglob(pattern), MAX_GLOBBED) if file.glob else [pattern]
            for path in sorted(found):
                landing = os.path.join(sub, os.path.basename(path))
                shared.append(Shared(os.path.normpath(path), landing))
    return ShareMap(tuple(shared), tuple(diagnostics))


def _unread(setup: str, line: int) -> Diagnostic:
    return Diagnostic(
        INSTALL_UNREAD,
        Severity.WARNING,
        "a data_files entry rosvar cannot read statically: the files it puts in the share "
        "folder are looked for at the same path in the source package",
        Location(setup, line),
    )
