"""Executables a package provides: the values a node's ``type`` can take.

roslaunch finds a node's executable among the files its package installs; with
no build here, the candidates are read from what the sources declare: a
``.executables`` list (as in the corpus), executable files and scripts in
``scripts/``, ``nodes/``, ``bin/``, the executable targets and installed programs of
CMakeLists.txt (catkin's and ament's, read by :mod:`rosvar.workspace.interfaces.cmake`), and
``console_scripts`` in setup.py/setup.cfg (ament_python's entry points).
"""

from __future__ import annotations

import io
import os
from functools import lru_cache

from rosvar.files import read_file
from rosvar.workspace import python_setup
from rosvar.workspace.interfaces.cmake import TargetKind, read_build
from rosvar.workspace.packages import Package

SCRIPT_FOLDERS = ("scripts", "nodes", "bin")
_SKIP_SUFFIXES = (".png", ".jpg", ".dae", ".stl", ".STL", ".pgm", ".em", ".in")


def executables(package: Package) -> frozenset[str]:
    """Every executable name ``package`` is known to provide."""
    found = set(package.executables or ())
    found |= _scan(package.path, package.name)
    return frozenset(found)


@lru_cache(maxsize=4096)
def _scan(path: str, name: str) -> frozenset[str]:
    found: set[str] = set()
    for folder in SCRIPT_FOLDERS:
        directory = os.path.join(path, folder)
        if os.path.isdir(directory):
            for entry in os.scandir(directory):
                if entry.is_file() and (
                    entry.name.endswith(".py") or os.access(entry.path, os.X_OK)
                ):
                    found.add(entry.name)
    for root, dirs, files in os.walk(path):
        dirs[:] = [d for d in dirs if not d.startswith(".")]
        for file in files:
            full = os.path.join(root, file)
            if file.startswith(".") or file.endswith(_SKIP_SUFFIXES):
                continue
            if os.access(full, os.X_OK) and os.path.isfile(full):
                found.add(file)
    found |= _cmake(path, name)
    found |= console_scripts(path).keys()
    return frozenset(found)


def _read(path: str) -> str:
    """A build file's text as ``open(path, errors="replace")`` reads it; "" if unreadable."""
    try:
        data = read_file(path)
    except OSError:
        return ""
    with io.TextIOWrapper(io.BytesIO(data), encoding="utf-8", errors="replace") as text:
        return text.read()


def _cmake(path: str, project: str) -> set[str]:
    build = read_build(path, project)
    names = {
        t.name
        for t in build.targets.values()
        if t.kind == TargetKind.EXECUTABLE and t.name not in build.vague_names
    }
    return names | {os.path.basename(program) for program in build.programs}


def console_scripts(package_dir: str) -> dict[str, str]:
    """The ``console_scripts`` entry points of setup.py and setup.cfg: name → module."""
    return python_setup.console_scripts(
        _read(os.path.join(package_dir, "setup.py")), _read(os.path.join(package_dir, "setup.cfg"))
    )
