"""Node interfaces as ``rosvar interfaces --json`` writes them, and the bundled catalogue
stores them (``tools/build_catalogue.py``)."""

from __future__ import annotations

from rosvar.outputs.documents.diagnostics import diagnostic_document
from rosvar.workspace.interfaces.model import Entry, Expression, Interfaces, NodeInterface, Role


def entry_document(entry: Entry) -> dict[str, object]:
    """One use of a name: a param's default (an expression as written), another role's
    type; the optional fields only where they say something."""
    document: dict[str, object] = {"name": entry.name}
    if entry.role is not Role.PARAMS:
        document["type"] = entry.type
    if entry.named_by is not None:
        named = {"parameter": entry.named_by.parameter}
        if entry.named_by.namespace:
            named["namespace"] = entry.named_by.namespace
        document["named_by"] = named
    if entry.role is Role.PARAMS or entry.named_by is not None:
        value = entry.default
        document["default"] = {"expression": value.text} if isinstance(value, Expression) else value
    document["file"] = entry.location.file
    document["line"] = entry.location.line
    document["origin"] = str(entry.origin)
    if not entry.static:
        document["static"] = False
    if entry.when is not None:
        document["when"] = entry.when
    if entry.boundary:
        document["boundary"] = True
    if entry.beside is not None:
        document["beside"] = entry.beside
    return document


def node_document(node: NodeInterface) -> dict[str, object]:
    """A node's interface, its entries listed by role."""
    document: dict[str, object] = {
        "package": node.package,
        "executable": node.executable,
        "kind": str(node.kind),
    }
    if node.node_name is not None:
        document["node_name"] = node.node_name
    for role in Role:
        document[str(role)] = [entry_document(entry) for entry in node.of(role)]
    return document


def interfaces_document(interfaces: Interfaces) -> dict[str, object]:
    return {
        "interfaces": [node_document(node) for node in interfaces.listed()],
        "diagnostics": [diagnostic_document(d) for d in interfaces.diagnostics],
    }
