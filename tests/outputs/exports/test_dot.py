"""DOT export: parsed by a small parser for the DOT subset it uses (no Graphviz binary needed):
quotes closed, braces balanced, every edge endpoint declared, the tree and the constraints
drawn as documented."""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import pytest

from rosvar.analyses.feature_model.model import FeatureModel
from rosvar.outputs.exports import dot
from rosvar.outputs.exports._common import Tree

from .test_uvl import tricky

if TYPE_CHECKING:
    from conftest import LaunchWorkspace  # tests/conftest.py

TOKEN = re.compile(
    r'\s+|(?P<string>"(?:[^"\\]|\\.)*")|(?P<arrow>->)|(?P<punct>[{}\[\]=;,])'
    r"|(?P<id>[A-Za-z_][A-Za-z_0-9]*|-?\d+(?:\.\d+)?)"
)


@dataclass
class Graph:
    name: str
    nodes: dict[str, dict[str, str]] = field(default_factory=dict)
    edges: list[tuple[str, str, dict[str, str]]] = field(default_factory=list)
    defaults: dict[str, dict[str, str]] = field(default_factory=dict)


def tokens(text: str) -> list[str]:
    found: list[str] = []
    position = 0
    while position < len(text):
        match = TOKEN.match(text, position)
        assert match is not None, f"bad DOT at {position}: {text[position : position + 40]!r}"
        if match.lastgroup is not None:
            found.append(match.group())
        position = match.end()
    return found


def value(token: str) -> str:
    if token.startswith('"'):
        return re.sub(r'\\(["\\])', r"\1", token[1:-1])  # DOT's \n etc. stay as written
    return token


def parse(text: str) -> Graph:
    """``digraph ID { stmt* }`` with node, edge, ``node``/``edge`` defaults and ``a=b`` stmts."""
    items = tokens(text)
    assert items[:1] == ["digraph"] and items[2] == "{" and items[-1] == "}"
    depth = 0
    for item in items:
        depth += {"{": 1, "}": -1}.get(item, 0)
        assert depth >= 0
    assert depth == 0
    graph = Graph(value(items[1]))
    position = 3

    def attributes() -> dict[str, str]:
        nonlocal position
        found: dict[str, str] = {}
        if items[position] != "[":
            return found
        position += 1
        while items[position] != "]":
            key, equals, raw = items[position : position + 3]
            assert equals == "=", items[position : position + 3]
            found[value(key)] = value(raw)
            position += 3
            if items[position] in (",", ";"):
                position += 1
        position += 1
        return found

    while items[position] != "}":
        first = items[position]
        position += 1
        if first in ("node", "edge"):
            graph.defaults[first] = attributes()
        elif items[position] == "=":
            position += 2
        elif items[position] == "->":
            target = items[position + 1]
            position += 2
            graph.edges.append((value(first), value(target), attributes()))
        else:
            assert value(first) not in graph.nodes, f"node {first} declared twice"
            graph.nodes[value(first)] = attributes()
        assert items[position] == ";", items[position - 3 : position + 1]
        position += 1
    assert position == len(items) - 1
    return graph


def check(model: FeatureModel) -> Graph:
    graph = parse(dot.write(model))
    tree = Tree(model)
    assert graph.name == tree.root
    assert set(graph.nodes) == {tree.root, *(e.id for e in tree.entries)}
    for source, target, _ in graph.edges:
        assert source in graph.nodes and target in graph.nodes
    tree_edges = [e for e in graph.edges if e[2].get("style") != "dashed"]
    assert sorted((s, t) for s, t, _ in tree_edges) == sorted(
        (e.parent or tree.root, e.id) for e in tree.entries
    )
    constraint_edges = [e for e in graph.edges if e[2].get("style") == "dashed"]
    assert len(constraint_edges) == len(model.constraints)
    for (source, target, look), constraint in zip(constraint_edges, model.constraints, strict=True):
        assert (source, target) == tuple(tree.files[f] for f in constraint.files)
        if constraint.kind == "excludes":
            assert (look["color"], look["dir"]) == ("red", "both")
        else:
            assert "dir" not in look
        expected = "" if constraint.unconditional else model.space.describe(constraint.condition)
        assert look.get("label", "") == expected
    for entry in tree.entries:
        feature = entry.feature
        if entry.kind == "value":
            label = graph.nodes[entry.id]["label"]
            assert label.startswith("✓ ") == bool(getattr(feature, "default", False))
    return graph


def test_corpus(model: FeatureModel) -> None:
    check(model)


def test_examples(examples_model: FeatureModel) -> None:
    graph = check(examples_model)
    assert graph.nodes["example/launch/control.xml:use_teleop=true"]["label"] == "✓ true"
    assert (
        graph.nodes["example/launch/control.xml:use_teleop"]["label"] == "use_teleop\\n(one of 3)"
    )
    kinds = {(s, t): look for s, t, look in graph.edges}
    assert kinds[("examples", "example/launch/control.xml")]["arrowhead"] == "odot"
    assert kinds[("example/launch/mapping.launch", "example/launch/control.xml")]["label"] == "¬sim"


def test_tricky_names(ws: LaunchWorkspace) -> None:
    graph = check(tricky(ws))
    assert graph.nodes['pkg/launch/main.launch:label=say "hi"']["label"] == '✓ say "hi"'


def test_quote_escapes() -> None:
    assert dot.quote('a "b" \\ c\nd') == '"a \\"b\\" \\\\ c\\nd"'
    with pytest.raises(AssertionError):
        parse('digraph "g" { "a" -> "b ; }')
