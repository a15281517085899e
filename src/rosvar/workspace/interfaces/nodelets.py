"""Nodelet classes a package exports: class name → C++ type → library target.

``package.xml`` names the plugin description (``<export><nodelet plugin="${prefix}/x.xml"/>``);
that file maps each class (``pkg/Class``, what ``load pkg/Class manager`` asks for) to its
C++ type and the library that holds it (``lib/libNAME`` is target ``NAME``). Like pluginlib,
a file may hold several ``<library>`` elements without a common root.
"""

from __future__ import annotations

import os
import re
from dataclasses import dataclass

from rosvar.diagnostics import DiagnosticSink, Location
from rosvar.frontends.entity import Entity, ParseResult
from rosvar.frontends.xml import parse_xml_bytes, parse_xml_file
from rosvar.workspace.interfaces.reading import SourceReader

PREFIX = "${prefix}"
_DECLARATION = re.compile(rb"\s*<\?xml[^>]*\?>")


@dataclass(frozen=True)
class NodeletClass:
    """One exported class: ``name`` as launch files load it, ``type`` its C++ class."""

    name: str
    type: str
    library: str
    location: Location


def _children(entity: Entity, tag: str) -> list[Entity]:
    return [child for child in entity.children if child.tag == tag]


def plugin_files(package_dir: str) -> list[str]:
    """The nodelet plugin descriptions ``package.xml`` exports."""
    result = parse_xml_file(os.path.join(package_dir, "package.xml"))
    if result.root is None:
        return []
    files = []
    for export in _children(result.root, "export"):
        for nodelet in _children(export, "nodelet"):
            plugin = nodelet.get("plugin")
            if plugin:
                files.append(os.path.normpath(plugin.replace(PREFIX, package_dir)))
    return files


def nodelet_classes(
    package_dir: str, sink: DiagnosticSink, reader: SourceReader | None = None
) -> list[NodeletClass]:
    """Every nodelet class exported by the package at ``package_dir``."""
    found = []
    for path in plugin_files(package_dir):
        result = _parse_plugins(path, reader or SourceReader(sink=sink))
        if result.root is None:
            sink.warning(
                "nodelet-plugins-unreadable", "cannot read the nodelet plugins", Location(path)
            )
            continue
        libraries = (
            [result.root] if result.root.tag == "library" else _children(result.root, "library")
        )
        for library in libraries:
            target = os.path.basename(library.get("path") or "")
            target = target[3:] if target.startswith("lib") else target
            for entity in _children(library, "class"):
                name, type_name = entity.get("name"), entity.get("type")
                if name and type_name:
                    found.append(NodeletClass(name, type_name, target, entity.location))
    return found


def _parse_plugins(path: str, reader: SourceReader) -> ParseResult:
    """The plugin file's tree; several top-level ``<library>`` elements are put under one
    root on their own lines, so that line numbers stay."""
    data = reader.data(path)
    if data is None:
        return ParseResult(None, [])
    result = parse_xml_bytes(data, path)
    if result.root is not None:
        return result
    declaration = _DECLARATION.match(data)
    head = declaration.end() if declaration else 0
    wrapped = data[:head] + b"<class_libraries>" + data[head:] + b"</class_libraries>"
    again = parse_xml_bytes(wrapped, path)
    return again if again.root is not None else result
