"""Format-neutral parsed launch description: the frontends' only product.

A frontend turns a file into a tree of :class:`Entity` objects and nothing else;
the interpreter gives them meaning. Attribute values stay raw strings here
(substitutions such as ``$(arg x)`` are not touched); the typed values of YAML and
Python launch files are text too, marked in ``Entity.typed``.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from rosvar.diagnostics import Diagnostic, Location


@dataclass(eq=False, slots=True)
class Entity:
    """One element: tag, raw attributes in document order, children, direct text.

    Slots: the parse cache holds every element of every launch file of a workspace.
    """

    tag: str
    attributes: dict[str, str]
    location: Location
    children: list[Entity] = field(default_factory=list)
    text: str = ""
    typed: frozenset[str] = frozenset()
    """Attributes written as typed values in YAML or Python, not as strings (their frontends
    write them as canonical text); XML has none."""

    def get(self, name: str) -> str | None:
        return self.attributes.get(name)

    def has(self, name: str) -> bool:
        return name in self.attributes


@dataclass
class ParseResult:
    """A parsed file: ``root`` is ``None`` exactly when the file cannot be used."""

    root: Entity | None
    diagnostics: list[Diagnostic] = field(default_factory=list)
