"""Which files are launch files, and in which format, for each ROS.

Every launch file found is an entry point, so discovery must tell launch files from the
other XML, YAML and Python files of a package without interpreting them: by name first
(the conventions of roslaunch and of ``ros2 launch``), then by a cheap look at the start
or the text of the file where the name alone says too little (a ``launch/`` folder
also holds helper modules and parameter files).
"""

from __future__ import annotations

import os
import re
from collections.abc import Callable
from dataclasses import dataclass
from enum import StrEnum

from rosvar.files import open_regular
from rosvar.frontends.xml import is_launch_root
from rosvar.ros.version import RosVersion

PACKAGE_FILE = "package.xml"
LAUNCH_FOLDER = "launch"
# ``ros2 launch`` loads a Python file by calling this function; files without it are
# helper modules or launch tests (``generate_test_description``).
PYTHON_ENTRY = b"generate_launch_description"
# How much of a file is read to find out whether it is a launch file: its beginning (a file
# too large to read is still found, and its reading says why it is not read).
MAX_PYTHON_PROBE_BYTES = 1024 * 1024
_YAML_ROOT = re.compile(rb"^launch\s*:", re.MULTILINE)


class LaunchFormat(StrEnum):
    """The frontend a launch file is read with."""

    XML = "xml"
    YAML = "yaml"
    PYTHON = "python"


INVALID_FILE = {
    (RosVersion.ROS1, LaunchFormat.XML): "Invalid roslaunch XML syntax",
    (RosVersion.ROS2, LaunchFormat.XML): "Invalid ROS 2 XML launch file",
    (RosVersion.ROS2, LaunchFormat.YAML): "Invalid ROS 2 YAML launch file",
    (RosVersion.ROS2, LaunchFormat.PYTHON): "Invalid ROS 2 Python launch file",
}
"""How an unreadable launch file is told, naming its format (roslaunch's own words)."""


@dataclass(frozen=True)
class _Rule:
    """Files named ``*SUFFIX`` (only in a ``launch/`` folder when ``in_launch_folder``) are
    launch files of ``format`` if ``confirm`` accepts them (None: the name suffices)."""

    format: LaunchFormat
    suffixes: tuple[str, ...]
    in_launch_folder: bool = False
    confirm: Callable[[str], bool] | None = None

    def names(self, in_folder: bool, name: str) -> bool:
        """Whether the rule is about file ``name`` (its confirmation aside), in a ``launch/``
        folder or not."""
        return name.endswith(self.suffixes) and (in_folder or not self.in_launch_folder)


def _beginning(path: str) -> bytes:
    """The first :data:`MAX_PYTHON_PROBE_BYTES` of a regular file; empty if unreadable."""
    try:
        with open_regular(path) as handle:
            return handle.read(MAX_PYTHON_PROBE_BYTES)
    except (OSError, ValueError):
        return b""


def _has_yaml_launch_root(path: str) -> bool:
    return _YAML_ROOT.search(_beginning(path)) is not None


def _defines_launch_description(path: str) -> bool:
    return PYTHON_ENTRY in _beginning(path)


# The first rule that names a file decides; its confirmation may still refuse.
RULES: dict[RosVersion, tuple[_Rule, ...]] = {
    RosVersion.ROS1: (
        _Rule(LaunchFormat.XML, (".launch", ".launch.xml")),
        _Rule(LaunchFormat.XML, (".xml",), confirm=is_launch_root),
    ),
    RosVersion.ROS2: (
        _Rule(LaunchFormat.XML, (".launch.xml",)),
        _Rule(LaunchFormat.YAML, (".launch.yaml", ".launch.yml")),
        _Rule(
            LaunchFormat.PYTHON, (".launch.py", "_launch.py"), confirm=_defines_launch_description
        ),
        _Rule(LaunchFormat.PYTHON, (".py",), True, _defines_launch_description),
        _Rule(LaunchFormat.XML, (".xml",), True, is_launch_root),
        _Rule(LaunchFormat.YAML, (".yaml", ".yml"), True, _has_yaml_launch_root),
    ),
}


_SUFFIXES = tuple(dict.fromkeys(s for rules in RULES.values() for r in rules for s in r.suffixes))
"""Every rule's suffixes: a file ending otherwise (meshes, configs...) is no launch file."""


def launch_format(directory: str, name: str, version: RosVersion) -> LaunchFormat | None:
    """The format of ``directory/name`` if it is a launch file of ``version``, else None."""
    if name.startswith(".") or name == PACKAGE_FILE or not name.endswith(_SUFFIXES):
        return None  # editor backups, lock files, manifests, files of no launch format
    in_folder = os.path.basename(directory) == LAUNCH_FOLDER
    for rule in RULES[version]:
        if rule.names(in_folder, name):
            if rule.confirm is None or rule.confirm(os.path.join(directory, name)):
                return rule.format
            return None
    return None


# ``ros2 launch`` picks the frontend by extension; anything else is tried as XML.
_EXTENSIONS = {".py": LaunchFormat.PYTHON, ".yaml": LaunchFormat.YAML, ".yml": LaunchFormat.YAML}


def format_of(path: str, version: RosVersion) -> LaunchFormat:
    """The frontend that reads launch file ``path`` (found or given) in a ``version``
    workspace: roslaunch reads only XML."""
    if version == RosVersion.ROS1:
        return LaunchFormat.XML
    return _EXTENSIONS.get(os.path.splitext(path)[1], LaunchFormat.XML)
