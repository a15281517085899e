"""The launch command lines of a complete product: ``roslaunch`` or ``ros2 launch``.

Only *launched* files are named: a selected file that another selected file includes is
loaded by that include, not by the command line. Each file gives the args whose value
differs from its default or that have no default. roslaunch gives one set of args to every
file of a command line, so files share a command only while every file would read the
same value for every arg the others give; the rest get commands of their own. ``ros2
launch`` takes one file, so each file has its own. A single file inside a package is named
``PKG FILE``, several files by their paths.
"""

from __future__ import annotations

import os
import shlex
from collections.abc import Mapping, Sequence
from dataclasses import dataclass

from rosvar.ros.version import RosVersion
from rosvar.workspace import Workspace


@dataclass(frozen=True)
class Command:
    """How one ROS's launch command is spelled."""

    program: tuple[str, ...]
    files: int | None  # how many files one command line takes (None: any number)


COMMANDS: dict[RosVersion, Command] = {
    RosVersion.ROS1: Command(("roslaunch",), None),
    RosVersion.ROS2: Command(("ros2", "launch"), 1),
}


def launch_tool(version: RosVersion) -> str:
    """The launch command of ``version`` by name, for what is said of it (it stops, refuses)."""
    return " ".join(COMMANDS[version].program)


@dataclass(frozen=True)
class Launch:
    """A launched file: the args it is given, and what it reads for each of its inputs."""

    path: str
    spelled: str
    given: Mapping[str, str]
    reads: Mapping[str, str | None]  # input name → given value, else its literal default

    def agrees(self, given: Mapping[str, str]) -> bool:
        """This file would read ``given``'s values for the args it has, and gives no other."""
        return all(
            name not in self.reads or self.reads[name] == value for name, value in given.items()
        )


def group(launches: Sequence[Launch], version: RosVersion) -> list[list[Launch]]:
    """Files in order, each joining the first command line whose args it agrees with (and
    that has room for it)."""
    room = COMMANDS[version].files
    groups: list[tuple[list[Launch], dict[str, str]]] = []
    for launch in launches:
        for members, given in groups:
            if room is not None and len(members) >= room:
                continue
            if launch.agrees(given) and all(m.agrees(launch.given) for m in members):
                members.append(launch)
                given.update(launch.given)
                break
        else:
            groups.append(([launch], dict(launch.given)))
    return [members for members, _given in groups]


def given(members: Sequence[Launch]) -> dict[str, str]:
    """The args of one command line: what its files give, together."""
    found: dict[str, str] = {}
    for member in members:
        found.update(member.given)
    return found


def command_line(members: Sequence[Launch], workspace: Workspace) -> str:
    """The workspace's launch command for files that share a command line (:func:`group`)."""
    if len(members) == 1:
        files = _package_form(members[0], workspace) or [members[0].spelled]
    else:
        files = [m.spelled for m in members]
    program = COMMANDS[workspace.ros_version].program
    words = [*program, *files, *(f"{k}:={v}" for k, v in given(members).items())]
    return " ".join(shlex.quote(w) for w in words)


def _package_form(launch: Launch, workspace: Workspace) -> list[str] | None:
    """``[PKG, FILE]`` when the launch command finds exactly this file by package and name."""
    package = workspace.package_of(launch.path)
    if package is None or workspace.packages.get(package.name) is not package:
        return None
    name = os.path.basename(launch.path)
    inside = [
        f
        for f in workspace.launch_files
        if os.path.basename(f) == name and workspace.package_of(f) is package
    ]
    if len(inside) != 1:
        return None
    return [package.name, name]
