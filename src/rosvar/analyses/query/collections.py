"""What queries range over: named collections of elements, each with a presence condition.

An element is anything with the :class:`Queryable` shape: a kind, a name, the entry file whose
model holds it, a presence condition and conditional attribute values
(:class:`~rosvar.logic.choice.Choice`). A collection is registered under the name queries use
(``nodes``, ``topics``...) with a provider that lists its elements in one entry file's model;
another analysis (the communication graph) registers a better provider under the same name and
queries pick it up unchanged. A set-valued attribute (a topic's publishers) is a
:class:`ElementSet`: elements with the conditions under which they belong; a query sees, per
condition, the tuple of members present, so ``len()`` of it is a conditional count.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Iterator, Sequence
from dataclasses import dataclass, field
from enum import StrEnum
from typing import Protocol

from rosvar.diagnostics import Location
from rosvar.interpreter.model import Binary, DeferredValue, LaunchModel, NodeDecl, ParamDecl
from rosvar.interpreter.workspace_models import Analysis
from rosvar.logic.bdd import BDD
from rosvar.logic.choice import Choice, combine
from rosvar.logic.conditions import ConditionSpace
from rosvar.ros import names


class Kind(StrEnum):
    NODE = "node"
    PARAM = "param"
    TOPIC = "topic"
    SERVICE = "service"
    ACTION = "action"
    LAUNCH_FILE = "launch_file"
    ARG = "arg"


class Queryable(Protocol):
    """An element a query can select; ``attribute`` answers for every name its collection
    declares, with values of plain Python types (None where analysis does not know the text)."""

    @property
    def kind(self) -> str: ...

    @property
    def name(self) -> str: ...

    @property
    def file(self) -> str: ...

    @property
    def presence(self) -> BDD: ...

    @property
    def location(self) -> Location | None: ...

    def attribute(self, name: str) -> Choice[object]: ...


@dataclass(eq=False, slots=True)
class Element:
    """The plain :class:`Queryable`: attribute values computed when the element is listed."""

    kind: Kind
    name: str
    file: str
    presence: BDD
    location: Location | None
    values: dict[str, Choice[object]] = field(default_factory=dict)

    def attribute(self, name: str) -> Choice[object]:
        return self.values[name]


@dataclass(eq=False, frozen=True, slots=True)
class ElementSet:
    """Elements with the condition under which each belongs to the set."""

    members: tuple[tuple[BDD, Queryable], ...]

    def __iter__(self) -> Iterator[tuple[BDD, Queryable]]:
        return iter(self.members)

    def subsets(self, space: ConditionSpace, limit: int) -> Choice[tuple[Queryable, ...]] | None:
        """The members present, per condition (``len()`` of them is the conditional count);
        None when more than ``limit`` distinct subsets are possible."""
        partial: list[tuple[BDD, tuple[Queryable, ...]]] = [(space.true, ())]
        for condition, member in self.members:
            grown = []
            for holds, present in partial:
                for both, chosen in (
                    (holds & condition, (*present, member)),
                    (holds & ~condition, present),
                ):
                    if both != space.false:
                        grown.append((both, chosen))
            if len(grown) > limit:
                return None
            partial = grown
        return Choice.of(partial, space.false)


Provider = Callable[[Analysis, LaunchModel], Iterable[Queryable]]


@dataclass(frozen=True)
class Collection:
    """A name queries use, the attributes its elements have and where they come from."""

    name: str
    attributes: tuple[str, ...]
    provider: Provider
    doc: str


COLLECTIONS: dict[str, Collection] = {}


def register_collection(collection: Collection) -> None:
    """Add or replace a collection (the last registration of a name wins)."""
    COLLECTIONS[collection.name] = collection


def known(value: object) -> object:
    """An attribute value as queries see it: terms (text analysis cannot know, an ``<other>``
    arg value) and deferred or binary params are None."""
    if isinstance(value, (str, int, float, bool, type(None), list, dict, tuple)):
        return value
    return None


def _known(choice: Choice[object]) -> Choice[object]:
    """``choice`` itself when all its values are known (the Choice shared by the elements of
    one scope stays shared: queries remember results per Choice)."""
    if all(type(value) is str or value is None for value in choice.values()):
        return choice
    return choice.map(known)


def _const(space: ConditionSpace, value: object) -> Choice[object]:
    return Choice.const(space, value)


def _in_namespace(parts: Sequence[object]) -> str | None:
    """A relative name (a remap's target) resolved in a namespace, where both are known."""
    namespace, name = parts
    if not isinstance(name, str) or not (namespace is None or isinstance(namespace, str)):
        return None
    return names.ns_join("/" if namespace is None else namespace, name)


def _shown(value: object) -> str:
    """A name for people: a term shows the inputs it awaits (``⟨robot⟩/map``)."""
    return value if isinstance(value, str) else f"{value}"


def _namespace(node: NodeDecl) -> Choice[object]:
    """The namespace a node is launched in, ``/`` where none is given (ROS 2)."""
    namespace = node.value(node.schema.namespace)
    if None in namespace.values():
        return _known(namespace.map(lambda value: names.SEP if value is None else value))
    return _known(namespace)


def _shown_names(node: NodeDecl) -> Iterator[tuple[BDD, str | None, str]]:
    """Each variant of a node's full name (None where not known) with its text for people (a
    term shows the inputs it awaits); a ROS 2 node without a name is shown by its label,
    ``⟨EXEC⟩`` in its namespace, per executable, as ``rosvar resolve`` prints it."""
    schema = node.schema
    for condition, name in node.value(schema.full_name):
        if name is not None:
            yield condition, name if isinstance(name, str) else None, _shown(name)
            continue
        for when, label in node.value(schema.label):
            both = condition & when
            if both != both.bdd.false:
                yield both, None, _shown(label)


def _nodes(analysis: Analysis, model: LaunchModel) -> Iterator[Element]:
    return (element for _node, element in node_elements(analysis, model))


def node_elements(analysis: Analysis, model: LaunchModel) -> Iterator[tuple[NodeDecl, Element]]:
    """One element per node declaration and resolved name (a name that varies splits it)."""
    space = analysis.space
    entry = analysis.label(model.file)
    for node in model.nodes:
        schema = node.schema
        namespace = _namespace(node)
        for condition, name, shown in _shown_names(node):
            values: dict[str, Choice[object]] = {
                "name": _const(space, name),
                "namespace": namespace,
                "package": _known(node.value(schema.package)),
                "type": _known(node.value(schema.executable)),
                "test": _const(space, node.is_test),
                "launch_file": _const(space, entry),
                "file": _const(space, node.location.file),
            }
            presence = node.condition & condition
            yield node, Element(Kind.NODE, shown, entry, presence, node.location, values)


def _params(analysis: Analysis, model: LaunchModel) -> Iterator[Element]:
    space = analysis.space
    entry = analysis.label(model.file)
    for param in model.params:
        if not isinstance(param, ParamDecl):
            continue  # a <rosparam> whose text is only known per configuration
        value = param.value.map(_param_value)
        for condition, name in param.name:
            values = {
                "name": _const(space, known(name)),
                "value": value,
                "launch_file": _const(space, entry),
                "file": _const(space, param.location.file),
            }
            presence = param.condition & condition
            yield Element(Kind.PARAM, _shown(name), entry, presence, param.location, values)


def _param_value(value: object) -> object:
    return None if isinstance(value, (DeferredValue, Binary)) else known(value)


def remapped_topics(analysis: Analysis, model: LaunchModel) -> list[Element]:
    """Topics named by ``<remap>``s of nodes (resolved in the node's namespace); without a
    communication graph their publishers and subscribers are empty sets."""
    space = analysis.space
    entry = analysis.label(model.file)
    remapped: dict[str, list[tuple[BDD, Queryable]]] = {}
    located: dict[str, Location] = {}
    for declaration, node in node_elements(analysis, model):
        for remap in declaration.remaps:
            target = Choice.of([(remap.condition, remap.target)], space.false)
            for condition, name in combine([node.attribute("namespace"), target], _in_namespace):
                presence = node.presence & condition
                if name is not None and presence != space.false:
                    remapped.setdefault(name, []).append((presence, node))
                    located.setdefault(name, declaration.location)
    empty = _const(space, ElementSet(()))
    topics = []
    for name, members in remapped.items():
        presence = space.false
        for condition, _member in members:
            presence |= condition
        values = {
            "name": _const(space, name),
            "publishers": empty,
            "subscribers": empty,
            "remapped_by": _const(space, ElementSet(tuple(members))),
            "launch_file": _const(space, entry),
        }
        topics.append(Element(Kind.TOPIC, name, entry, presence, located[name], values))
    return topics


def _launch_files(analysis: Analysis, model: LaunchModel) -> list[Element]:
    """The entry file itself: always present in its own model."""
    space = analysis.space
    entry = analysis.label(model.file)
    loads = model.loads
    values: dict[str, Choice[object]] = {
        "name": _const(space, entry),
        "path": _const(space, model.file),
        "nodes": _set(space, _nodes(analysis, model)),
        "params": _set(space, _params(analysis, model)),
        "args": _set(space, _args(analysis, model)),
        "loads": Choice.of([(loads, True), (~loads, False)], space.false),
    }
    return [Element(Kind.LAUNCH_FILE, entry, entry, space.true, Location(model.file), values)]


def _set(space: ConditionSpace, elements: Iterable[Queryable]) -> Choice[object]:
    members = tuple((element.presence, element) for element in elements)
    return Choice.of([(space.true, ElementSet(members))], space.false)


def _args(analysis: Analysis, model: LaunchModel) -> Iterator[Element]:
    """The args a user can set on the entry file's command line."""
    space = analysis.space
    entry = analysis.label(model.file)
    for arg in model.args:
        if arg.input is None:
            continue
        values: dict[str, Choice[object]] = {
            "name": _const(space, arg.name),
            "default": _const(space, arg.default),
            "doc": _const(space, arg.doc),
            "launch_file": _const(space, entry),
        }
        yield Element(Kind.ARG, arg.name, entry, arg.condition, arg.location, values)


for _collection in (
    Collection("nodes", ("name", "namespace", "package", "type", "test", "launch_file", "file"),
               _nodes, "node declarations, one per resolved name"),
    Collection("params", ("name", "value", "launch_file", "file"), _params,
               "parameters set by <param> and concrete <rosparam>"),
    Collection("topics", ("name", "publishers", "subscribers", "remapped_by", "launch_file"),
               remapped_topics, "topics named by remaps (users: query/channels.py)"),
    Collection("launch_files", ("name", "path", "nodes", "params", "args", "loads"),
               _launch_files, "entry launch files"),
    Collection("args", ("name", "default", "doc", "launch_file"), _args,
               "args of the entry file a user can set"),
):  # fmt: skip
    register_collection(_collection)
