"""The interfaces of everything a workspace's packages can launch, from their sources.

Per package: each ``add_executable`` target is a node (entry ``main``), each exported nodelet
class is a nodelet (entry ``Class::onInit`` in its library's sources), each installed or
``scripts/``-style Python file is a node. Hints and the catalogue are applied afterwards
(:mod:`rosvar.workspace.interfaces.overrides`).
"""

from __future__ import annotations

import os
from collections.abc import Iterable

from rosvar.diagnostics import DiagnosticSink, Location
from rosvar.workspace.executables import SCRIPT_FOLDERS
from rosvar.workspace.interfaces import cpp, python
from rosvar.workspace.interfaces.cmake import CMAKE_FILE, Build, TargetKind, read_build
from rosvar.workspace.interfaces.model import Interfaces, NodeInterface, NodeKind
from rosvar.workspace.interfaces.nodelets import nodelet_classes
from rosvar.workspace.interfaces.reading import read_source
from rosvar.workspace.packages import Package


def extract_package(package: Package, sink: DiagnosticSink) -> list[NodeInterface]:
    """The nodes and nodelets of one package, in a stable order."""
    build = read_build(package.path, package.name)
    include_dirs = [*build.include_dirs, os.path.join(package.path, "include")]
    nodes: list[NodeInterface] = []
    where = Location(os.path.join(package.path, CMAKE_FILE))
    for target in build.targets.values():
        if target.kind is not TargetKind.EXECUTABLE:
            continue
        unit = cpp.Unit.load(_cpp_sources(build.sources(target.name)), include_dirs)
        entries = cpp.extract(unit, "main", None, sink, where)
        nodes.append(NodeInterface(package.name, target.installed_name, NodeKind.NODE, entries))
    for nodelet in nodelet_classes(package.path, sink):
        if nodelet.library not in build.targets:
            sink.warning(
                "interface-no-library",
                f"nodelet {nodelet.name}: no library target '{nodelet.library}' in the CMake files",
                nodelet.location,
            )
            nodes.append(NodeInterface(package.name, nodelet.name, NodeKind.NODELET))
            continue
        unit = cpp.Unit.load(_cpp_sources(build.sources(nodelet.library)), include_dirs)
        owner = nodelet.type.rsplit("::", 1)[-1]
        entries = cpp.extract(unit, "onInit", owner, sink, nodelet.location)
        nodes.append(NodeInterface(package.name, nodelet.name, NodeKind.NODELET, entries))
    for script in _python_scripts(package.path, build):
        entries = python.extract(script, sink)
        nodes.append(NodeInterface(package.name, os.path.basename(script), NodeKind.NODE, entries))
    return sorted(nodes, key=lambda node: node.executable)


def extract_interfaces(packages: Iterable[Package]) -> Interfaces:
    """The interfaces of every package in ``packages`` (by package name)."""
    sink = DiagnosticSink()
    nodes: list[NodeInterface] = []
    for package in sorted(packages, key=lambda p: p.name):
        nodes.extend(extract_package(package, sink))
    return Interfaces(nodes, sink.items)


def _cpp_sources(sources: list[str]) -> list[str]:
    return [s for s in sources if not s.endswith((".c", ".cu", ".proto"))]


def _python_scripts(package_dir: str, build: Build) -> list[str]:
    """Installed Python programs, and Python files in the usual script folders."""
    found = {path for path in build.programs if os.path.isfile(path) and _is_python(path)}
    for folder in SCRIPT_FOLDERS:
        directory = os.path.join(package_dir, folder)
        if os.path.isdir(directory):
            for entry in os.scandir(directory):
                if entry.is_file() and _is_python(entry.path):
                    found.add(entry.path)
    return sorted(found)


def _is_python(path: str) -> bool:
    if path.endswith(".py"):
        return True
    data = read_source(path)
    return data is not None and data.startswith(b"#!") and b"python" in data.split(b"\n", 1)[0]
