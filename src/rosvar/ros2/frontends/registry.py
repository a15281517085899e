"""ROS 2's frontends by file suffix (the dialect's loader): every format is a thin adapter
producing :class:`Entity` trees.

XML is the shared reader ROS 1 uses as well; YAML and Python are ROS 2's own formats, read
into the same trees as the XML (the interpreter never knows which format it walks).
"""

from __future__ import annotations

import os
from collections.abc import Callable

from rosvar.frontends.entity import ParseResult
from rosvar.frontends.xml import load_launch_file
from rosvar.interpreter.dialect import Loader
from rosvar.ros2.frontends.python.modules import ModulePath
from rosvar.workspace import Workspace

FRONTENDS: dict[str, Loader] = {}


def frontend(*suffixes: str) -> Callable[[Loader], Loader]:
    """Register ``loader`` for files whose names end with one of ``suffixes``."""

    def register(loader: Loader) -> Loader:
        for suffix in suffixes:
            if suffix in FRONTENDS:
                raise ValueError(f"suffix {suffix} has two frontends")
            FRONTENDS[suffix] = loader
        return loader

    return register


frontend(".launch.xml", ".xml", ".launch")(load_launch_file)

# ROS 2's own formats are imported on first use: the Python frontend's abstract interpreter and
# the YAML loader are most of the frontends' import time, which a ROS 1 workspace never needs


@frontend(".launch.yaml", ".launch.yml", ".yaml", ".yml")
def _yaml_launch_file(path: str) -> ParseResult:
    from rosvar.ros2.frontends.yaml.parser import parse_yaml_launch_file

    return parse_yaml_launch_file(path)


def _python_launch_file(path: str, modules: ModulePath | None = None) -> ParseResult:
    from rosvar.ros2.frontends.python.parser import parse_python_launch_file

    return parse_python_launch_file(path, modules)


frontend(".launch.py", ".py")(_python_launch_file)


def _frontend(name: str) -> Loader:
    best = max((s for s in FRONTENDS if name.endswith(s)), key=len, default=None)
    return FRONTENDS[best] if best is not None else load_launch_file


def load(path: str | os.PathLike[str]) -> ParseResult:
    """Parse ``path`` with the frontend of its longest registered suffix (XML otherwise)."""
    name = os.fspath(path)
    return _frontend(name)(name)


def workspace_loader(workspace: Workspace) -> Loader:
    """:func:`load` for ``workspace``'s files: a Python launch file's imports find the
    modules of its packages (:mod:`rosvar.ros2.frontends.python.modules`)."""
    packages = {name: package.path for name, package in workspace.packages.items()}
    modules = ModulePath(packages, workspace.confinement())

    def load_in(path: str) -> ParseResult:
        frontend = _frontend(path)
        if frontend is _python_launch_file:
            return _python_launch_file(path, modules)
        return frontend(path)

    return load_in
