"""Interpret one ROS 2 entry launch file with given launch arguments."""

from __future__ import annotations

import os
import re
from collections.abc import Mapping

from rosvar.files import FileRefused, read_file
from rosvar.frontends import registry
from rosvar.frontends.ros1_xml.parser import Snapshot
from rosvar.interpreter.interpretation import Interpretation
from rosvar.interpreter.model import LaunchModel
from rosvar.interpreter.ros2 import schema
from rosvar.interpreter.ros2 import tags as _tags  # noqa: F401 - registers the handlers
from rosvar.interpreter.ros2.context import Context
from rosvar.interpreter.ros2.dialect import ROS2
from rosvar.interpreter.ros2.tags.timer import fire
from rosvar.logic.choice import Choice
from rosvar.logic.conditions import ConditionSpace
from rosvar.logic.inputs import UNSET
from rosvar.workspace import Workspace


def interpret(
    workspace: Workspace,
    space: ConditionSpace,
    file: str,
    arguments: Mapping[str, str],
    env: Mapping[str, str],
) -> LaunchModel:
    """The model of ``file`` launched as ``ros2 launch file name:=value ...``.

    Launch arguments are set before the file is loaded (as ``ros2 launch`` does), so a
    declaration's default applies only to those not given.
    """
    it = Interpretation(
        workspace,
        space,
        lambda _file, _name: (),
        lambda _name: (UNSET,),  # a variable not given is not set (a clean environment)
        file,
        Snapshot(registry.load),
        ROS2,
    )
    try:
        context = Context(file)
        context.configurations = {
            name: Choice.const(space, value) for name, value in arguments.items()
        }
        context.env = {name: Choice.const(space, value) for name, value in env.items()}
        it.stack.append(file)
        root = it.load(file)
        if root is not None:
            schema.check(it, root)
            with it.at(root):
                it.walk(root.children, context)
                fire(it, context)
        failing = space.false
        for error in it.model.errors:
            failing |= error.condition
        it.model.loads = ~failing
        it.model.diagnostics = it.sink.items
        return it.model
    finally:
        it.close()


ROS2_SUFFIXES = (".launch.py", ".launch.yaml")
ROS2_MARKERS = re.compile(rb"\$\((var|find-pkg-share|find-pkg-prefix) |<node\b[^>]*\bexec=|<let\b")
"""Texts no ROS 1 launch file has: ROS 2's substitutions, ``exec=`` on a node, ``<let>``."""


def is_ros2_launch(file: str) -> bool:
    """Whether ``file`` is a ROS 2 launch file: a Python or YAML launch file, a file built
    by ament (per the nearest ``package.xml`` above it) or one using ROS 2-only syntax.
    A minimal hook until the workspace knows its ROS version."""
    if file.endswith(ROS2_SUFFIXES):
        return True
    try:
        if ROS2_MARKERS.search(read_file(file)):
            return True
    except (FileRefused, OSError):
        return False
    folder = os.path.dirname(os.path.abspath(file))
    while True:
        manifest = os.path.join(folder, "package.xml")
        if os.path.isfile(manifest):
            try:
                text = read_file(manifest)
            except (FileRefused, OSError):
                return False
            return re.search(rb"<build_type>\s*ament_", text) is not None
        parent = os.path.dirname(folder)
        if parent == folder:
            return False
        folder = parent
