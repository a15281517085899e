"""The expanded robot description: an XML tree whose elements carry presence conditions and
whose texts are conditional values, as the launch model's elements do.

``<xacro:if>`` makes elements conditional, an arg makes a text vary, an
``<xacro:attribute>`` sets an attribute only where it is reached; restricting the tree to one
configuration (:func:`concrete`) gives what xacro prints for it, which the differential
tests compare with the real xacro (:func:`canonical`).
"""

from __future__ import annotations

from collections.abc import Callable, Iterator
from dataclasses import dataclass, field

from rosvar.diagnostics import Diagnostic, Location
from rosvar.logic.bdd import BDD
from rosvar.logic.choice import Choice, combine
from rosvar.logic.conditions import ConditionSpace
from rosvar.logic.terms import Term, concat

Text = str | Term
"""A text of the description: concrete, or known per configuration."""


@dataclass(slots=True, eq=False)
class XElement:
    """One element of the expanded description, present where ``condition`` holds."""

    tag: str
    condition: BDD
    location: Location  # where the element is written (in a macro's body, the body's)
    attributes: dict[str, Choice[Text | None]] = field(default_factory=dict)
    """None where an attribute is not set (``<xacro:attribute>`` under a condition)."""
    texts: list[tuple[BDD, Choice[Text]]] = field(default_factory=list)
    """The pieces of its text in document order, each present under its condition."""
    children: list[XElement] = field(default_factory=list)

    def text(self, space: ConditionSpace) -> Choice[Text]:
        """The element's whole text: its present pieces joined, stripped as xacro's
        readers (Gazebo's SDF, ``urdf``) take a value."""
        pieces: list[Choice[Text]] = [
            Choice.of([(condition & c, v) for c, v in value] + [(~condition, "")], space.false)
            for condition, value in self.texts
        ]
        if not pieces:
            return Choice.const(space, "")
        joined = combine(pieces, lambda parts: concat(list(parts)))
        return joined.map(lambda text: text.strip() if isinstance(text, str) else text)

    def attribute(self, name: str) -> Choice[Text | None] | None:
        return self.attributes.get(name)

    def elements(self, tag: str | None = None) -> Iterator[XElement]:
        """This element and those below it (``tag``: only those), in document order."""
        if tag is None or self.tag == tag:
            yield self
        for child in self.children:
            yield from child.elements(tag)


@dataclass(frozen=True)
class Failure:
    """Under ``condition`` xacro stops here with ``message`` (and prints nothing)."""

    condition: BDD
    location: Location
    message: str


@dataclass
class Description:
    """A robot description as the launch file's command expands it, in every configuration
    where ``condition`` holds (the command's own)."""

    file: str
    condition: BDD
    root: XElement | None
    failures: list[Failure] = field(default_factory=list)
    diagnostics: list[Diagnostic] = field(default_factory=list)
    files: list[str] = field(default_factory=list)
    unknown: BDD = field(kw_only=True)
    """Where a part was not followed (a file named by an unknown value, rosvar's limits):
    the description is then incomplete."""

    @property
    def fails(self) -> BDD:
        result = self.condition.bdd.false
        for failure in self.failures:
            result |= failure.condition
        return result

    @property
    def present(self) -> BDD:
        """Where xacro prints the description: the command runs and does not fail."""
        return self.condition & ~self.fails


# -- one configuration -------------------------------------------------------------------------

Node = tuple[str, tuple[tuple[str, str], ...], str, tuple["Node", ...]]
"""An element as xacro prints it, canonically: tag, attributes by name, text, children."""


def concrete(
    description: Description, holds: Callable[[BDD], bool], text: Callable[[Text], str]
) -> Node | None:
    """The description in one configuration (``holds`` decides a condition there, ``text``
    evaluates a term), or None where xacro fails or is not run."""
    if description.root is None or not holds(description.present):
        return None
    return _concrete(description.root, holds, text)


def _concrete(element: XElement, holds: Callable[[BDD], bool], text: Callable[[Text], str]) -> Node:
    attributes = []
    for name, value in element.attributes.items():
        leaf = _pick(value, holds)
        if leaf is not None and not _namespace(name):
            attributes.append((name, text(leaf)))
    pieces = []
    for condition, value in element.texts:
        piece = _pick(value, holds) if holds(condition) else None
        if piece is not None:
            pieces.append(text(piece))
    children = tuple(
        _concrete(child, holds, text) for child in element.children if holds(child.condition)
    )
    return element.tag, tuple(sorted(attributes)), "".join(pieces).strip(), children


def _pick(value: Choice[Text | None], holds: Callable[[BDD], bool]) -> Text | None:
    for condition, leaf in value:
        if holds(condition):
            return leaf
    return None


def _namespace(name: str) -> bool:
    return name == "xmlns" or name.startswith("xmlns:")


def canonical(tag: str, attributes: dict[str, str], text: str, children: list[Node]) -> Node:
    """An element read from xacro's output in :data:`Node` form (namespace declarations,
    which xacro moves between elements, left out)."""
    kept = tuple(sorted((k, v) for k, v in attributes.items() if not _namespace(k)))
    return tag, kept, text.strip(), tuple(children)
