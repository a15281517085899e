"""Entries that are not read from the workspace's sources: hints and the catalogue.

Precedence, per node and per (role, name): hints over sources over the catalogue. The
catalogue only fills nodes the sources do not define (third-party packages not in the
workspace); a hint replaces the entries of the same role and name and adds the others,
and names a node that no source defines, it creates that node.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

from rosvar.workspace.interfaces.model import Entry, Interfaces, NodeInterface, NodeKind


def _split(key: str, nodes: Sequence[NodeInterface]) -> tuple[str, str]:
    """``pkg/executable`` → (pkg, executable); a nodelet's ``pkg/Class`` is kept whole."""
    package, _, executable = key.partition("/")
    if any(node.executable == key and node.package == package for node in nodes):
        return package, key
    return package, executable


def apply_hints(interfaces: Interfaces, hints: Mapping[str, list[Entry]]) -> None:
    """Give or override entries of the nodes the hints name (``pkg/executable`` keys)."""
    for key, entries in hints.items():
        package, executable = _split(key, interfaces.nodes)
        node = interfaces.find(package, executable)
        if node is None:
            kind = NodeKind.NODELET if executable == key else NodeKind.NODE
            node = NodeInterface(package, executable, kind)
            interfaces.nodes.append(node)
        hinted = {(entry.role, entry.name) for entry in entries}
        node.entries = [e for e in node.entries if (e.role, e.name) not in hinted] + entries
    interfaces.nodes.sort(key=lambda node: (node.package, node.executable))


def add_catalogue(interfaces: Interfaces, catalogue: Sequence[NodeInterface]) -> None:
    """The catalogue's nodes that the sources do not define."""
    for node in catalogue:
        if interfaces.find(node.package, node.executable) is None:
            interfaces.nodes.append(node)
    interfaces.nodes.sort(key=lambda node: (node.package, node.executable))
