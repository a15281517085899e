"""The interfaces of everything a workspace's packages can launch, from their sources.

Per package: each ``add_executable`` target is a node (entry ``main``), each exported nodelet
class is a nodelet (entry ``Class::onInit`` in its library's sources), each installed or
``scripts/``-style Python file is a node. A ROS 2 package adds its components (a library's
class registered with ``RCLCPP_COMPONENTS_REGISTER_NODE``, entry its constructor; the
executable ``rclcpp_components_register_node`` makes of one runs the same) and its
``console_scripts`` (the module the entry point names), and each node the name its code
gives it. Hints and the catalogue are applied afterwards
(:mod:`rosvar.workspace.interfaces.overrides`).
"""

from __future__ import annotations

import os
import re
from collections.abc import Iterable, Mapping, Sequence

from rosvar.diagnostics import DiagnosticSink, Location
from rosvar.files import Confinement
from rosvar.ros.version import RosVersion
from rosvar.workspace.executables import SCRIPT_FOLDERS, console_scripts
from rosvar.workspace.interfaces import python
from rosvar.workspace.interfaces.cmake import (
    CMAKE_FILE,
    Build,
    TargetKind,
    cmake_extras,
    read_build,
)
from rosvar.workspace.interfaces.cpp.extract import extract_node
from rosvar.workspace.interfaces.cpp.unit import Unit
from rosvar.workspace.interfaces.model import Extracted, Interfaces, NodeInterface, NodeKind
from rosvar.workspace.interfaces.nodelets import nodelet_classes
from rosvar.workspace.interfaces.python_modules import module_file
from rosvar.workspace.interfaces.reading import SourceReader
from rosvar.workspace.packages import Package

_COMPONENT = re.compile(r"RCLCPP_COMPONENTS_REGISTER_NODE\s*\(\s*([\w:]+)\s*\)")


def extract_package(
    package: Package,
    sink: DiagnosticSink,
    reader: SourceReader | None = None,
    extras: Mapping[str, list[str]] | None = None,
    headers: Sequence[str] = (),
) -> list[NodeInterface]:
    """The nodes and nodelets of one package, in a stable order; its files read through
    ``reader``, the CMake ``extras`` of the workspace's packages known by name, the include
    folders of the workspace's packages (``headers``) searched after the package's own: a
    wrapper class a dependency defines in a header (``nav2_util::SimpleActionServer``) is
    read where it is used."""
    reader = reader or SourceReader(Confinement.of([package.path]), sink)
    build = read_build(package.path, package.name, reader, extras, sink)
    include_dirs = [*build.include_dirs, os.path.join(package.path, "include"), *headers]
    ros2 = package.ros_version is RosVersion.ROS2
    nodes: list[NodeInterface] = []
    where = Location(os.path.join(package.path, CMAKE_FILE))

    def node(executable: str, kind: NodeKind, found: Extracted) -> None:
        name = found.node_name if ros2 else None
        nodes.append(NodeInterface(package.name, executable, kind, found.entries, name))

    for target in build.targets.values():
        if target.kind is TargetKind.EXECUTABLE:
            unit = Unit.load(_cpp_sources(build.sources(target.name)), include_dirs, reader)
            entry, owner = ("main", None) if target.plugin is None else _constructor(target.plugin)
            node(
                target.installed_name,
                NodeKind.NODE,
                extract_node(unit, entry, owner, sink, where, ros2),
            )
        elif ros2:
            plugins = _components(target.sources, reader)
            sources = _cpp_sources(build.sources(target.name)) if plugins else []
            unit = Unit.load(sources, include_dirs, reader)
            for plugin in plugins:
                found = extract_node(unit, *_constructor(plugin), sink, where, ros2)
                node(plugin, NodeKind.COMPONENT, found)
    for nodelet in nodelet_classes(package.path, sink, reader):
        if nodelet.library not in build.targets:
            sink.warning(
                "interface-no-library",
                f"nodelet {nodelet.name}: no library target '{nodelet.library}' in the CMake files",
                nodelet.location,
            )
            nodes.append(NodeInterface(package.name, nodelet.name, NodeKind.NODELET))
            continue
        unit = Unit.load(_cpp_sources(build.sources(nodelet.library)), include_dirs, reader)
        owner = nodelet.type.rsplit("::", 1)[-1]
        entries = extract_node(unit, "onInit", owner, sink, nodelet.location).entries
        nodes.append(NodeInterface(package.name, nodelet.name, NodeKind.NODELET, entries))
    python_roots = [package.path, os.path.join(package.path, "src")]
    for script in _python_scripts(package.path, build, reader):
        found = python.extract_node(script, sink, reader, python_roots)
        node(os.path.basename(script), NodeKind.NODE, found)
    for executable, module in console_scripts(package.path).items():
        path = module_file(python_roots, module)
        if path is None:
            sink.warning(
                "interface-no-module",
                f"console script {executable}: no module {module} in the package",
                Location(os.path.join(package.path, "setup.py")),
            )
            continue
        node(executable, NodeKind.NODE, python.extract_node(path, sink, reader, python_roots))
    return sorted(nodes, key=lambda node: node.executable)


def _constructor(plugin: str) -> tuple[str, str]:
    """The entry point of a component class ``ns::Class``: its constructor."""
    name = plugin.rsplit("::", 1)[-1]
    return name, name


def _components(sources: list[str], reader: SourceReader) -> list[str]:
    """The classes a library's sources register as components, as launch files name them."""
    found: list[str] = []
    for source in sources:
        text = reader.text(source) or ""
        for match in _COMPONENT.finditer(text):
            plugin = match.group(1).lstrip(":")
            if plugin not in found:
                found.append(plugin)
    return found


def extract_interfaces(
    packages: Iterable[Package],
    confinement: Confinement | None = None,
    workspace: Iterable[Package] = (),
) -> Interfaces:
    """The interfaces of every package in ``packages`` (by package name), their files read
    within ``confinement`` (by default, the packages' folders); the CMake functions and
    macros of ``workspace``'s packages (and ``packages``') are known to their builds."""
    chosen = sorted(packages, key=lambda p: p.name)
    sink = DiagnosticSink()
    reader = SourceReader(confinement or Confinement.of(p.path for p in chosen), sink)
    everything = {p.path: p for p in (*workspace, *chosen)}.values()
    extras = {p.name: cmake_extras(p.path) for p in everything}
    headers = [
        folder for p in everything if os.path.isdir(folder := os.path.join(p.path, "include"))
    ]
    nodes: list[NodeInterface] = []
    for package in chosen:
        nodes.extend(extract_package(package, sink, reader, extras, headers))
    return Interfaces(nodes, sink.items)


def _cpp_sources(sources: list[str]) -> list[str]:
    return [s for s in sources if not s.endswith((".c", ".cu", ".proto"))]


def _python_scripts(package_dir: str, build: Build, reader: SourceReader) -> list[str]:
    """Installed Python programs, and Python files in the usual script folders."""
    found = {p for p in build.programs if os.path.isfile(p) and _is_python(p, reader)}
    for folder in SCRIPT_FOLDERS:
        directory = os.path.join(package_dir, folder)
        if os.path.isdir(directory):
            for entry in os.scandir(directory):
                if entry.is_file() and _is_python(entry.path, reader):
                    found.add(entry.path)
    return sorted(found)


def _is_python(path: str, reader: SourceReader) -> bool:
    if path.endswith(".py"):
        return True
    data = reader.data(path)
    return data is not None and data.startswith(b"#!") and b"python" in data.split(b"\n", 1)[0]
