"""The variational computation graph: every node, param and topic any product can have.

Built once from the models of the entry files. An element of ``model(f)`` is in a product
when ``f`` is *launched* (selected, and not included by another selected file that includes
it there) and its own condition holds. An element whose fields differ between
configurations is split into *variants* (HAROS-style: each value paired with its
condition); each variant keeps its presence condition in the analysis' manager (for
people) and lowered into the solver's (for the solver). Values that are terms stay
symbolic until the user's choices make their inputs concrete.
"""

from __future__ import annotations

import os
from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass, field
from enum import StrEnum
from typing import Protocol, cast

from rosvar.analyses.communication import (
    CHANNEL,
    Channel,
    LaunchedNode,
    entry_names,
    entry_when,
    find_interface,
)
from rosvar.analyses.feature_model.features import launched_conditions
from rosvar.analyses.feature_model.model import FeatureModel
from rosvar.analyses.param_values import ParamValues
from rosvar.configuration.lowering import Bounds, Lowering
from rosvar.diagnostics import Location
from rosvar.files import Confinement
from rosvar.interpreter.dialect import dialect_of
from rosvar.interpreter.model import (
    DeferredValue,
    LaunchModel,
    NodeDecl,
    ParamDecl,
    Raw,
    YamlDecl,
)
from rosvar.interpreter.resolution import (
    ResolutionError,
    deferred_value,
    evaluated,
    rosparam_pairs,
)
from rosvar.interpreter.workspace_models import Analysis
from rosvar.logic.bdd import BDD
from rosvar.logic.choice import Choice
from rosvar.logic.inputs import Input
from rosvar.logic.terms import TermError, evaluate, is_term, term_inputs
from rosvar.ros import names
from rosvar.workspace.interfaces.model import Interfaces, Role

Fields = dict[str, object]
"""An entry of the graph as the state document shows it."""
Shown = tuple[str, str | None]
"""A condition's presence at one step, and its readable form while undetermined."""


class Values:
    """Concrete strings of inputs where the choices fix them; evaluates terms with them."""

    def __init__(self, concrete: Mapping[Input, str], host: object) -> None:
        self.concrete = concrete
        self.host = host

    def knows(self, raws: Iterable[Raw | None]) -> bool:
        """Every input the terms among ``raws`` need has a concrete string."""
        return all(term_inputs(raw) <= self.concrete.keys() for raw in raws if is_term(raw))  # type: ignore[arg-type]

    def text(self, raw: Raw | None) -> str | None:
        """The string of ``raw``, or its symbolic form while an input is unknown."""
        if raw is None or isinstance(raw, str):
            return raw
        try:
            return evaluate(raw, self.concrete, self.host)
        except (TermError, LookupError, ValueError):
            return str(raw)

    def strict(self, raw: Raw | None, location: Location, what: str) -> str | None:
        """The string of ``raw``, or :class:`ResolutionError` where roslaunch has none."""
        if raw is None or isinstance(raw, str):
            return raw
        return evaluated(raw, self.concrete, self.host, location, what)


class PartKind(StrEnum):
    """What a node's part sets: a remap, an environment variable or (ROS 2) a parameter."""

    REMAP = "remap"
    ENV = "env"
    PARAMETER = "parameter"


@dataclass(frozen=True)
class Part:
    """A remap or environment setting that only some configurations of its node have.

    Judged at each step like an element (its condition includes its node's), not
    multiplied into the node's variants: conditional remaps on independent args make a
    variant per combination, exponentially many in the remaps, while a part costs one more
    condition to judge."""

    condition: BDD  # analysis manager, fixed atoms substituted
    bounds: Bounds  # solver manager


class ElementKind(StrEnum):
    """What an element of the graph is; each kind is a list of the shown graph."""

    NODE = "node"
    TEST = "test"
    PARAM = "param"
    TOPIC = "topic"
    SERVICE = "service"
    ACTION = "action"
    ERROR = "error"


NAMED: dict[Channel, ElementKind] = {
    Channel.TOPICS: ElementKind.TOPIC,
    Channel.SERVICES: ElementKind.SERVICE,
    Channel.ACTIONS: ElementKind.ACTION,
}
"""The element kind of each channel's names: those with ``nodes`` using them."""


@dataclass(frozen=True, slots=True)
class NodeContent:
    """A node variant: its fields' raw values, and its remaps, environment settings and
    (ROS 2) parameters, each with the part it depends on."""

    raw: Mapping[str, Raw | None]
    remaps: list[Setting]
    env: list[Setting]
    parameters: list[Setting]
    node: NodeDecl
    confinement: Confinement  # where its parameter files may be read
    typed: list[Setting]  # (value, type) of the parameters coerced once their text is known

    def failures(self, values: Values) -> list[Failure]:
        """Where a node variant's strings make its launch tool stop, as ``rosvar resolve``
        loads it (its dialect's checks): its fields, and each remap and environment setting
        (in its part, if any)."""
        checks = dialect_of(self.node.schema.version).checks
        if checks is None:
            return []
        where = self.node.location
        found: list[Failure] = []
        if values.knows(self.raw.values()):
            try:
                text = {k: values.strict(v, where, f"<node> {k}") for k, v in self.raw.items()}
                checks.node(text, where)
                if self.node.is_test:
                    checks.test(text, where)
            except ResolutionError as error:
                found.append(Failure.of(None, error))
        settings = [*((r, "remap") for r in self.remaps), *((e, "env") for e in self.env)]
        for (first, second, part), label in settings:
            if not values.knows((first, second)):
                continue
            try:
                pair = (values.strict(first, where, label), values.strict(second, where, label))
                if label == "remap":
                    checks.remap(*pair, where)
            except ResolutionError as error:
                found.append(Failure.of(part, error))
        for value, kind, part in self.typed:
            if not values.knows((value,)):
                continue
            try:
                given = values.strict(value, where, "parameter value")
                checks.parameter(str(given), str(kind), where)
            except ResolutionError as error:
                found.append(Failure.of(part, error))
        return found


@dataclass(frozen=True, slots=True)
class ParamContent:
    """A ``<param>`` variant: its name and value (a deferred one converted once known)."""

    name: object
    value: object
    location: Location
    confinement: Confinement  # the files its conversion may read

    @property
    def raw(self) -> object:
        """Its value's string, or the term of it."""
        return self.value.raw if isinstance(self.value, DeferredValue) else self.value

    def loaded(self, values: Values) -> object:
        """The value roslaunch loads with ``values`` (the same conversion as ``rosvar
        resolve``'s), or :class:`ResolutionError` where it stops (or a string is unknown)."""
        value, where = self.value, self.location
        what = f"param {values.text(cast(Raw, self.name))}"
        if isinstance(value, DeferredValue):
            text = values.strict(value.raw, where, what) or ""
            return deferred_value(value, text, where, self.confinement)
        if is_term(value):
            return values.strict(cast(Raw, value), where, what)
        return value

    def failures(self, values: Values) -> list[Failure]:
        if not values.knows([cast(Raw, self.name), cast(Raw, self.raw)]):
            return []
        try:
            values.strict(cast(Raw, self.name), self.location, "param name")
            self.loaded(values)
        except ResolutionError as error:
            return [Failure.of(None, error)]
        return []


@dataclass(frozen=True, slots=True)
class YamlContent:
    """A ``<rosparam>`` with terms: loaded (by its dialect's ``load``) once they are known."""

    param: YamlDecl
    confinement: Confinement

    @property
    def raws(self) -> tuple[Raw | None, ...]:
        param = self.param
        return (param.scope_ns, param.command, param.ns, param.file, param.param, param.text)

    def pairs(self, values: Values) -> list[tuple[str, object]]:
        """The params roslaunch sets with ``values`` (``rosvar resolve``'s load), or
        :class:`ResolutionError` where it stops (or a string is unknown)."""
        where = self.param.location
        scope_ns, command, ns, file, name, body = (
            values.strict(raw, where, "<rosparam>") for raw in self.raws
        )
        texts = (str(scope_ns), str(command), ns, file, name, body or "")
        return rosparam_pairs(self.param, texts, self.confinement)

    def failures(self, values: Values) -> list[Failure]:
        if not values.knows(self.raws):
            return []
        try:
            self.pairs(values)
        except ResolutionError as error:
            return [Failure.of(None, error)]
        return []


@dataclass(frozen=True, slots=True)
class TopicContent:
    """A topic named from a file's args: the namespace, name and remap target of its first
    use."""

    raws: tuple[Raw | None, Raw | None, Raw]


@dataclass(frozen=True, slots=True)
class ChannelContent:
    """A topic, service or action known by name, with its nodes' uses (its parts, in
    order)."""

    channel: Channel
    name: str
    edges: Sequence[Edge]


@dataclass(frozen=True, slots=True)
class NamedContent:
    """A topic known by name alone (no interfaces to tell its nodes' uses)."""

    name: str


@dataclass(frozen=True, slots=True)
class ErrorContent:
    """Where roslaunch would stop, and why."""

    code: str
    message: str
    location: Location


@dataclass(frozen=True, slots=True)
class Failure:
    """Where the strings typed for ``<other>`` values make roslaunch stop loading an element:
    in one of its parts (its index), or in the element itself (``part`` None). A record,
    not the exception: one kept would hold the frames it was raised in, and the diagrams
    they reach."""

    part: int | None
    error: ErrorContent

    @classmethod
    def of(cls, part: int | None, error: ResolutionError) -> Failure:
        return cls(part, ErrorContent(error.code, error.message, error.location))


Content = (
    NodeContent
    | ParamContent
    | YamlContent
    | TopicContent
    | ChannelContent
    | NamedContent
    | ErrorContent
)
"""What an element shows, in raw values and conditions; presentation renders it."""


def failures(content: Content, values: Values) -> list[Failure]:
    """Where ``content`` fails to load with ``values`` (every string it reads known, else
    not yet): the contents roslaunch converts or checks say so; the others cannot fail."""
    if isinstance(content, NodeContent | ParamContent | YamlContent):
        return content.failures(values)
    return []


class Render(Protocol):
    """An element's entries for concrete ``values`` and the presence of each of its parts
    (several for a YAML load): the presentation's, given to the engine."""

    def __call__(
        self, content: Content, values: Values, parts: Sequence[Shown]
    ) -> list[Fields]: ...


@dataclass(slots=True)
class Element:
    """One variant of a node, param, topic or error, with its presence condition."""

    kind: ElementKind
    id: str
    entry: str  # the entry launch file (path) whose model holds it
    condition: BDD  # analysis manager, fixed atoms substituted
    bounds: Bounds  # solver manager
    content: Content  # what it shows, in raw values: rendered for each set of concrete ones
    inputs: frozenset[Input] = frozenset()  # inputs its fields still need
    nodes: list[str] = field(default_factory=list)  # names: the node variants using it
    parts: tuple[Part, ...] = ()  # nodes: their conditional remaps and environment settings


class VariationalGraph:
    """Every element variant of the feature model's files, built once."""

    def __init__(
        self,
        analysis: Analysis,
        model: FeatureModel,
        lowering: Lowering,
        file_ids: Mapping[str, str],
        progress: Callable[[int, int], None] | None = None,
        interfaces: Interfaces | None = None,
    ) -> None:
        """``progress``: told how many of the files are done, and of how many;
        ``interfaces``: the nodes' own topics (else topics come from remaps only)."""
        self.lowering = lowering
        self.space = analysis.space
        self.confinement = analysis.workspace.confinement()
        self.elements: list[Element] = []
        self.launched: dict[str, BDD] = launched_conditions(model.files, model.requires)
        self.interfaces = interfaces
        self._topics: dict[tuple[str, str], _Topic] = {}
        self._shadows: dict[BDD, BDD] = {}
        self._edges: dict[tuple[Channel, str], list[Edge]] = {}  # a static name → its uses
        self._served: dict[tuple[Channel, str], tuple[list[str], BDD]] = {}  # services, actions
        self.params = ParamValues(  # the nodes' parameters, for hints' when:
            self.space, ((self.launched[f.file], analysis.model(f.file)) for f in model.files)
        )
        for done, file in enumerate(model.files):
            if progress is not None:
                progress(done, len(model.files))
            self._add_model(
                analysis.model(file.file),
                file_ids[file.file],
                lowering.fix(self.launched[file.file]),
            )
        for (entry, name), (nodes, condition, raws) in sorted(self._topics.items()):
            if not entry:
                edges = self._edges.get((Channel.TOPICS, name), [])
                content: Content = (
                    NamedContent(name)
                    if interfaces is None
                    else ChannelContent(Channel.TOPICS, name, edges)
                )
                parts = tuple(Part(when, bounds) for _n, _r, _t, when, bounds in edges)
                self._add(
                    ElementKind.TOPIC,
                    f"topic:{name}",
                    "",
                    condition,
                    content,
                    nodes=nodes,
                    parts=parts,
                )
                continue
            self._add(
                ElementKind.TOPIC,
                f"topic:{file_ids[entry]}|{name}",
                entry,
                condition,
                TopicContent(raws),
                _needs(*raws),
                nodes=nodes,
            )
        for (channel, name), (nodes, condition) in sorted(self._served.items()):
            edges = self._edges[channel, name]
            self._add(
                NAMED[channel],
                f"{NAMED[channel]}:{name}",
                "",
                condition,
                ChannelContent(channel, name, edges),
                nodes=nodes,
                parts=tuple(Part(when, bounds) for _n, _r, _t, when, bounds in edges),
            )
        self._topics.clear()
        self._served.clear()
        self._shadows.clear()  # only the build's products need them

    def _add(
        self,
        kind: ElementKind,
        id_: str | Callable[[], str],
        entry: str,
        condition: BDD,
        content: Content,
        inputs: Iterable[Input] = (),
        nodes: list[str] | None = None,
        parts: tuple[Part, ...] = (),
    ) -> Element | None:
        """The element, unless no configuration has it; ``id_`` (or made by it) is only
        taken by an element added, so the variants of one place are numbered 1, 2, ..."""
        fixed = self.lowering.fix(condition)
        if not self.lowering.satisfiable(fixed):
            return None  # e.g. two values of one arg: combinations no configuration has
        element = Element(
            kind,
            id_ if isinstance(id_, str) else id_(),
            entry,
            fixed,
            self.lowering.bounds(condition),
            content,
            frozenset(inputs),
            nodes or [],
            parts,
        )
        self.elements.append(element)
        return element

    def _add_model(self, model: LaunchModel, file_id: str, launched: BDD) -> None:
        """The elements of an entry file's model; ``launched``: fixed (``Lowering.fix``).

        Conditions are fixed factor by factor and then conjoined (fixing is a cofactor, which
        distributes over ∧): the factors are few and shared (``launched`` is a large diagram
        for a file included from many places), their conjunctions many and small."""
        fix, conjunction = self.lowering.fix, self.lowering.conjunction
        counters: dict[str, int] = {}

        def new_id(location: Location) -> str:
            key = f"{file_id}|{os.path.basename(location.file)}:{location.line}:{location.col}"
            counters[key] = counters.get(key, 0) + 1
            return f"{key}#{counters[key]}"

        def numbered(location: Location) -> Callable[[], str]:
            return lambda: new_id(location)

        for node in model.nodes:
            self._add_node(model, node, launched, numbered(node.location))
        for param in model.params:
            factors = (launched, fix(param.condition))
            if isinstance(param, ParamDecl):
                for variant, (name, value) in self._variants(factors, [param.name, param.value]):
                    self._add(
                        ElementKind.PARAM,
                        numbered(param.location),
                        model.file,
                        variant,
                        ParamContent(name, value, param.location, self.confinement),
                        _needs(name, value.raw if isinstance(value, DeferredValue) else value),
                    )
            else:
                self._add(
                    ElementKind.PARAM,
                    numbered(param.location),
                    model.file,
                    conjunction(factors),
                    YamlContent(param, self.confinement),
                    _needs(
                        param.scope_ns, param.command, param.ns, param.file, param.param, param.text
                    ),
                )
        for include in model.includes:
            if not include.resolved:  # roslaunch stops where it cannot read the file
                target = Values({}, None).text(include.file.values()[0]) if include.file else ""
                message = f"cannot load included file {target}"
                self._add(
                    ElementKind.ERROR,
                    numbered(include.location),
                    model.file,
                    conjunction((launched, fix(include.condition))),
                    ErrorContent("include-unknown", message, include.location),
                )
        for error in model.errors:
            self._add(
                ElementKind.ERROR,
                numbered(error.location),
                model.file,
                conjunction((launched, fix(error.condition))),
                ErrorContent(error.code, error.message, error.location),
            )

    def _add_node(
        self, model: LaunchModel, node: NodeDecl, launched: BDD, new_id: Callable[[], str]
    ) -> None:
        keys = sorted(node.fields)
        fields: list[Choice[object]] = [node.fields[k] for k in keys]
        within = (launched, self.lowering.fix(node.condition))
        for condition, values in self._variants(within, fields):
            if not self.lowering.satisfiable(self.lowering.fix(condition)):
                continue  # before its parts are lowered
            raw = cast(dict[str, Raw | None], dict(zip(keys, values, strict=True)))
            parts: list[Part] = []
            remaps = self._parted(
                condition, [(r.condition, r.source, r.target) for r in node.remaps], parts
            )
            env = self._parted(condition, [(e.condition, e.name, e.value) for e in node.env], parts)
            parameters = self._parted(condition, _parameter_settings(node), parts)
            typed = self._parted(condition, _typed_parameters(node), parts)
            element = self._add(
                ElementKind.TEST if node.is_test else ElementKind.NODE,
                new_id,
                model.file,
                condition,
                NodeContent(raw, remaps, env, parameters, node, self.confinement, typed),
                _needs(
                    *raw.values(),
                    *(p for pair in remaps + env + parameters for p in pair[:2]),
                ),
                parts=tuple(parts),
            )
            if element is not None and not node.is_test:
                self._topic_uses(element, raw, remaps, node)
                if self.interfaces is not None:
                    self._interface_uses(element, raw, node, condition)

    def _variants(
        self, within: Sequence[BDD], fields: Sequence[Choice[object]]
    ) -> list[tuple[BDD, tuple[object, ...]]]:
        """The conjunction of the fixed factors ``within`` ∧ each combination of the fields'
        values, in ``combine``'s order, but without the combinations the facts rule out (two
        values of one arg), dropped as the product is formed: a node whose fields read
        several args makes a combination per value of each, mostly impossible ones, which
        ``_add`` would lower one by one only to refuse them (one gazebo node of
        empty_world.launch made 8,424). Each condition is conjoined from its factors
        (``Lowering.conjunction``).

        Each partial combination carries a *shadow*: its condition conjoined with the facts
        over the variables of its parts, FALSE as soon as the facts rule it out."""
        lowering = self.lowering
        false = lowering.space.false
        varying = [index for index, field_ in enumerate(fields) if len(field_) != 1]
        leaves: list[object] = [None] * len(fields)
        factors = list(within)
        for index, field_ in enumerate(fields):
            if len(field_) == 1:
                condition, leaves[index] = field_.branches[0]
                factors.append(lowering.fix(condition))
        start = lowering.conjunction(factors)
        partial = [(tuple(factors), self._shadow(start), leaves)]
        for index in varying:
            grown = []
            for conjoined, shadow, values in partial:
                for branch, leaf in fields[index]:
                    own = lowering.fix(branch)
                    both = shadow & self._shadow(own)
                    if both != false:
                        chosen = list(values)
                        chosen[index] = leaf
                        grown.append(((*conjoined, own), both, chosen))
            partial = grown
        return [
            (lowering.conjunction(conjoined), tuple(values))
            for conjoined, shadow, values in partial
            if shadow != false
        ]

    def _shadow(self, condition: BDD) -> BDD:
        """``condition`` (fixed) ∧ the facts over its variables."""
        found = self._shadows.get(condition)
        if found is None:
            found = self._shadows[condition] = condition & self.lowering.space.care(condition)
        return found

    def _parted(
        self, condition: BDD, settings: list[tuple[BDD, Raw, Raw]], parts: list[Part]
    ) -> list[Setting]:
        """The settings a node variant of ``condition`` (fixed) may have, each with the index of
        its part in ``parts`` (added) or None when the variant always has it."""
        kept: list[Setting] = []
        for own, first, second in settings:
            both = self.lowering.conjunction((condition, self.lowering.fix(own)))
            if both == condition:
                kept.append((first, second, None))
                continue
            fixed, bounds = self.lowering.lower(both)
            if self.lowering.satisfiable(fixed):
                kept.append((first, second, len(parts)))
                parts.append(Part(fixed, bounds))
        return kept

    def _topic_uses(
        self,
        element: Element,
        raw: Mapping[str, Raw | None],
        remaps: list[Setting],
        node: NodeDecl,
    ) -> None:
        symbolic = Values({}, None)
        namespace = node.schema.namespace.of(raw)
        for _source, target, part in remaps:
            used = element.condition if part is None else element.parts[part].condition
            raws = (namespace, raw.get("name"), target)
            topic = topic_name(symbolic, *raws)
            # a name that reads args is the entry file's own: another file's ⟨scan⟩ is
            # another arg, and its string is known only with that file's choices
            key = (element.entry if _needs(*raws) else "", topic)
            nodes, condition, _raws = self._topics.get(key, ([], used.bdd.false, raws))
            nodes.append(element.id)
            self._topics[key] = (nodes, condition | used, raws)

    def _interface_uses(
        self, element: Element, raw: Mapping[str, Raw | None], node: NodeDecl, condition: BDD
    ) -> None:
        """The names the node variant publishes, subscribes to, serves or calls by its
        interface, each use an edge of its topic, service or action (judged as a part of
        it); names known statically only."""
        assert self.interfaces is not None
        fields = {key: raw.get(key) for key in node.schema.launched}
        if not all(text is None or isinstance(text, str) for text in fields.values()):
            return
        launched = LaunchedNode.of(node.schema, fields)
        unit = launched.unit()
        found = None if unit is None else find_interface(self.interfaces, unit)
        interface = launched.interface(found, node.location)
        if interface is None:
            return
        launched = launched.named(interface)
        remaps = [(remap.condition, remap.source, remap.target) for remap in node.remaps]
        for entry in interface.entries:
            channel = CHANNEL.get(entry.role)
            if channel is None or not entry.static:
                continue
            used = condition
            if entry.when is not None:
                hinted = entry_when(self.params, node, launched, interface, entry.when)
                used &= self.lowering.fix(hinted.condition)
            for when, resolved in entry_names(launched, remaps, entry, used):
                fixed, bounds = self.lowering.lower(when)
                if "{" in resolved or not self.lowering.satisfiable(fixed):
                    continue
                self._edges.setdefault((channel, resolved), []).append(
                    (element.id, entry.role, entry.type, fixed, bounds)
                )
                if channel == Channel.TOPICS:
                    nodes, used, raws = self._topics.get(
                        ("", resolved), ([], fixed.bdd.false, None)
                    )
                    self._topics[("", resolved)] = (
                        nodes,
                        used | fixed,
                        raws or (None, None, resolved),
                    )
                else:
                    nodes, used = self._served.get((channel, resolved), ([], fixed.bdd.false))
                    self._served[channel, resolved] = (nodes, used | fixed)
                if element.id not in nodes:
                    nodes.append(element.id)


_Topic = tuple[list[str], BDD, tuple[Raw | None, Raw | None, Raw]]
"""A topic's node variants, when one of them uses it, and the namespace, name and remap
target it was named from (the first use's)."""


def topic_name(values: Values, namespace: Raw | None, name: Raw | None, target: Raw) -> str:
    """The topic a node remaps to, resolved in its namespace (a private name in its own)."""
    space = values.text(namespace) or "/"
    topic = values.text(target) or ""
    if names.is_private(topic):
        return names.ns_join(names.ns_join(space, values.text(name) or "") + "/", topic[1:])
    return names.ns_join(space, topic)


Edge = tuple[str, Role, str | None, BDD, Bounds]
"""A node variant's use of a name: its id, its role (publishes, serves...), the type, and
the condition of the use (analysis manager, fixed) with its bounds."""


def _needs(*raws: object) -> set[Input]:
    found: set[Input] = set()
    for raw in raws:
        if is_term(raw):
            found |= term_inputs(raw)  # type: ignore[arg-type]
    return found


Setting = tuple[Raw, Raw, int | None]
"""A remap (from, to) or environment setting (name, value) of a node variant, with the
index of its part (None: the variant always has it)."""


def _typed_parameters(node: NodeDecl) -> list[tuple[BDD, Raw, Raw]]:
    """A ROS 2 node's ``<param type>`` values known per configuration only, with their type:
    launch coerces them as it loads (a literal one is checked as the file is read)."""
    return [
        (parameter.condition, parameter.value, parameter.kind)
        for parameter in node.parameters
        if parameter.kind and parameter.value is not None and not isinstance(parameter.value, str)
    ]


def _parameter_settings(node: NodeDecl) -> list[tuple[BDD, Raw, Raw]]:
    """A ROS 2 node's parameters as settings, in order: ``(name, value)``, or ``("", file)``
    for a parameter file (a parameter's name is never empty)."""
    settings: list[tuple[BDD, Raw, Raw]] = []
    for parameter in node.parameters:
        if parameter.file is not None:
            settings.append((parameter.condition, "", parameter.file))
        elif parameter.name is not None and parameter.value is not None:
            settings.append((parameter.condition, parameter.name, parameter.value))
    return settings
