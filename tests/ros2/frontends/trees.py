"""Entity trees compared across formats: everything but locations (and XML's layout text)."""

from __future__ import annotations

import os
from pathlib import Path
from xml.sax.saxutils import quoteattr

import pytest

from rosvar.frontends.entity import Entity
from rosvar.frontends.xml import parse_xml_bytes

SHARED = Path(__file__).resolve().parents[4] / "shared"
ORACLE = Path(os.environ.get("ROSVAR_ROS2_ORACLE", SHARED / "ros2-oracle"))
"""The ROS 2 oracle's folder (its example package holds one launch in all three formats)."""


def demo_launch(name: str) -> Path:
    """A launch file of the oracle's ``demo_pkg``; the test is skipped without the oracle."""
    path = ORACLE / "examples" / "pkgs" / "demo_pkg" / "launch" / name
    if not path.is_file():
        pytest.skip(f"no ROS 2 oracle at {ORACLE}")
    return path


Shape = tuple[str, dict[str, str], frozenset[str], str, list["Shape"]]


def shape(entity: Entity, rewrite: tuple[tuple[str, str], ...] = (), typed: bool = True) -> Shape:
    """Tag, attributes, typed attributes (unless ``typed`` is false: as XML, which has
    none), non-blank text and children's shapes; ``rewrite`` replaces texts in attribute
    values (where two files say the same thing differently)."""
    attributes = dict(entity.attributes)
    for old, new in rewrite:
        attributes = {name: value.replace(old, new) for name, value in attributes.items()}
    return (
        entity.tag,
        attributes,
        entity.typed if typed else frozenset(),
        entity.text.strip(),
        [shape(child, rewrite, typed) for child in entity.children],
    )


def xml_shape(source: str) -> Shape:
    """The shape of an inline XML launch file, which must parse cleanly."""
    result = parse_xml_bytes(source.encode(), "expected.xml")
    assert result.root is not None, result.diagnostics
    return shape(result.root)


def to_xml(entity: Entity, depth: int = 0) -> str:
    """The XML launch file of a tree (for running the equivalent XML through the oracle)."""
    attributes = "".join(f" {name}={quoteattr(value)}" for name, value in entity.attributes.items())
    indent = " " * depth
    if not entity.children:
        return f"{indent}<{entity.tag}{attributes}/>\n"
    inner = "".join(to_xml(child, depth + 2) for child in entity.children)
    return f"{indent}<{entity.tag}{attributes}>\n{inner}{indent}</{entity.tag}>\n"
