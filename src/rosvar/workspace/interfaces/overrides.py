"""Entries that are not read from the workspace's sources: hints and the catalogue.

Precedence, per node and per (role, name): hints over sources over the catalogue. The
catalogue only fills nodes the sources do not define (third-party packages not in the
workspace); a hint replaces the entries of the same role and name and adds the others,
and names a node that no source defines, it creates that node.
"""

from __future__ import annotations

from collections.abc import Mapping

from rosvar.workspace.interfaces.model import Entry, Fallback, Interfaces, NodeInterface, NodeKind


def _split(key: str, interfaces: Interfaces) -> tuple[str, str]:
    """``pkg/executable`` → (pkg, executable); a nodelet's ``pkg/Class`` is kept whole."""
    package, _, executable = key.partition("/")
    found = interfaces.find(package, key)
    if found is not None and found.package == package:
        return package, key
    return package, executable


def apply_hints(interfaces: Interfaces, hints: Mapping[str, list[Entry]]) -> None:
    """Give or override entries of the nodes the hints name (``pkg/executable`` keys)."""
    for key, entries in hints.items():
        package, executable = _split(key, interfaces)
        node = next(
            (n for n in interfaces.nodes if (n.package, n.executable) == (package, executable)),
            None,
        )
        if node is None:  # a copy of the fallback's node, or a new one
            known = interfaces.find(package, executable)
            kind = NodeKind.NODELET if executable == key else NodeKind.NODE
            if "::" in executable:  # a ROS 2 component's class
                kind = NodeKind.COMPONENT
            node = NodeInterface(package, executable, kind)
            if known is not None:
                node = NodeInterface(package, executable, known.kind, list(known.entries))
            interfaces.nodes.append(node)
        hinted = {(entry.role, entry.name) for entry in entries}
        node.entries = [e for e in node.entries if (e.role, e.name) not in hinted] + entries
    interfaces.nodes.sort(key=lambda node: (node.package, node.executable))


def add_catalogue(interfaces: Interfaces, catalogue: Fallback) -> None:
    """The catalogue answers for the nodes that the sources do not define."""
    interfaces.fallback = catalogue
