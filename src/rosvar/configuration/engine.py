"""The configuration engine: from a list of user choices to everything a user sees.

A :class:`Configurator` is built once per workspace (feature model, lowered presence
conditions, the variational graph) and answers any list of choices, statelessly. Choices
are replayed in order; the solver's answer after each prefix is cached, so a session that
adds one choice at a time pays for one step.
"""

from __future__ import annotations

from collections import OrderedDict
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from functools import cached_property

from rosvar.analyses.features import FeatureModel, explain
from rosvar.configuration.catalog import Catalog, Feature, FileEntry
from rosvar.configuration.choices import ChoiceError, Refusal, UserChoice
from rosvar.configuration.command import Launch, command_line, group
from rosvar.configuration.conflicts import Conflicts, ConflictState
from rosvar.configuration.derivation import ABSENT, PRESENT, Decisions, Derivation
from rosvar.configuration.graph import Element, Fields, Values, VariationalGraph
from rosvar.configuration.lowering import Lowering
from rosvar.interpreter.analysis import Analysis
from rosvar.interpreter.model import LaunchModel
from rosvar.logic.conditions import BDD
from rosvar.logic.inputs import OTHER, UNSET, Input

CACHED_STEPS = 4096
"""Solver answers kept per list of effective choices (a session's history and then some)."""
EXACT_INTEGER = 2**53  # larger counts go to JSON as strings


@dataclass(frozen=True)
class FeatureState:
    kind: str
    file: str
    arg: str | None
    value: str | None
    parent: str | None
    state: str  # selected | deselected | unselected
    derived: bool

    def to_json(self) -> dict[str, object]:
        return {
            "kind": self.kind,
            "file": self.file,
            "arg": self.arg,
            "value": self.value,
            "parent": self.parent,
            "state": self.state,
            "derived": self.derived,
        }


@dataclass
class Graph:
    """Element variants with their presence; ``errors`` are where roslaunch would stop."""

    nodes: list[Fields] = field(default_factory=list)
    tests: list[Fields] = field(default_factory=list)
    params: list[Fields] = field(default_factory=list)
    topics: list[Fields] = field(default_factory=list)
    errors: list[Fields] = field(default_factory=list)

    def to_json(self) -> dict[str, object]:
        return {
            "nodes": self.nodes,
            "tests": self.tests,
            "params": self.params,
            "topics": self.topics,
            "errors": self.errors,
        }


@dataclass
class ConfigurationState:
    choices: list[UserChoice]
    refused: list[Refusal]
    features: dict[str, FeatureState]
    conflicts: list[ConflictState]
    graph: Graph
    complete: bool
    command: str | None
    counter: Callable[[], int] = field(repr=False)  # counting can cost more than the step
    unselected: int
    commands: list[list[Launch]] = field(default_factory=list)  # files sharing a command line
    untyped: list[str] = field(default_factory=list)  # args at <other> still without a text

    @cached_property
    def configurations(self) -> int:
        """Valid configurations remaining (counted on first use)."""
        return self.counter()

    def to_json(self) -> dict[str, object]:
        count = self.configurations
        return {
            "features": {k: v.to_json() for k, v in self.features.items()},
            "conflicts": [c.to_json() for c in self.conflicts],
            "graph": self.graph.to_json(),
            "complete": self.complete,
            "command": self.command,
            "refused": [r.to_json() for r in self.refused],
            "choices": [c.to_json() for c in self.choices],
            "configurations": count if count <= EXACT_INTEGER else str(count),
            "unselected": self.unselected,
            "launched": [launch.spelled for group in self.commands for launch in group],
            "untyped": self.untyped,
        }


@dataclass(frozen=True)
class _Effective:
    """An accepted choice as a literal: ``variable = value``, with the <other> text if any."""

    choice: UserChoice
    targets: frozenset[str]  # feature ids it decides (unselect removes it by any of them)
    variable: str
    value: bool
    arg: str | None = None
    text: str | None = None


class Configurator:
    """Built once per workspace; answers any list of user choices (stateless)."""

    def __init__(
        self,
        analysis: Analysis,
        model: FeatureModel,
        env: Mapping[str, str] | None = None,
        spelling: Mapping[str, str] | None = None,
    ) -> None:
        solver = model.solver
        self.analysis = analysis
        self.model = model
        self.catalog = Catalog(model, spelling)
        self.derivation = Derivation(solver)
        self.lowering = Lowering(analysis, model, env or {})
        file_ids = {entry.path: entry.id for entry in self.catalog.files}
        self.graph = VariationalGraph(analysis, model, self.lowering, file_ids)
        self.conflicts = Conflicts(model, self.lowering, file_ids)
        self._launched = {
            entry.path: self.lowering.bounds(self.graph.launched[entry.path])
            for entry in self.catalog.files
        }
        self._steps: OrderedDict[tuple[tuple[str, bool], ...], Decisions] = OrderedDict()
        self._rendered: dict[
            tuple[str, frozenset[tuple[Input, str | None]] | None], list[Fields]
        ] = {}
        self._counts: dict[BDD, int] = {}  # by a component's cube of user literals
        self._entries: dict[str, tuple[tuple[str, str | None], list[Fields]]] = {}
        self._described: dict[tuple[BDD, frozenset[tuple[str, bool]]], str] = {}

    # -- choices -------------------------------------------------------------------------
    def state(self, choices: Sequence[UserChoice]) -> ConfigurationState:
        effective: list[_Effective] = []
        accepted: list[UserChoice] = []
        refused: list[Refusal] = []
        decisions = self.derivation.initial
        for choice in choices:
            feature = self.catalog.lookup(choice.feature)
            if choice.action == "unselect":
                effective = [e for e in effective if feature.id not in e.targets]
                found = self._decisions(effective)
                assert found is not None, "a part of an accepted list was refused"
                decisions = found
                accepted.append(choice)
                continue
            try:
                entry = self._literal(choice, feature)
            except _Refused as refusal:
                refused.append(Refusal(choice, str(refusal)))
                continue
            kept = effective
            if choice.action == "set":  # a new value replaces the arg's earlier one
                kept = [e for e in effective if feature.id not in e.targets]
            after = self._decisions([*kept, entry])
            if after is None:
                refused.append(Refusal(choice, self._reason(kept, entry)))
                continue
            effective = [*kept, entry]
            decisions = after
            accepted.append(choice)
        return self._answer(accepted, refused, effective, decisions)

    def completion(self, choices: Sequence[UserChoice]) -> list[UserChoice]:
        """Choices that finish ``choices`` with defaults: open files off, open args at default."""
        added: list[UserChoice] = []
        while True:
            state = self.state([*choices, *added])
            open_ = [f for f in self.catalog if state.features[f.id].state == "unselected"]
            if not open_:
                return added
            # values of the files in the product first, then files (deselecting one may
            # force values elsewhere), then values of files chosen since
            open_.sort(key=lambda f: 1 if f.kind == "file" else 0 if self._in(f, state) else 2)
            added.append(self._default_choice(open_[0], state))

    @staticmethod
    def _in(feature: Feature, state: ConfigurationState) -> bool:
        return state.features[feature.file].state == "selected"

    def _default_choice(self, feature: Feature, state: ConfigurationState) -> UserChoice:
        if feature.kind == "file":
            return UserChoice("deselect", feature.id)
        arg = feature.id if feature.kind == "arg" else str(feature.parent)
        values = self.catalog.values_of(arg)
        possible = [f for f, _v in values if state.features[f.id].state != "deselected"]
        defaults = [f for f, v in values if v.default and f in possible]
        known = [f for f in possible if f.value != "<other>"]
        return UserChoice("select", (defaults or known or possible)[0].id)

    def _literal(self, choice: UserChoice, feature: Feature) -> _Effective:
        if choice.action in ("select", "deselect"):
            return _Effective(
                choice, frozenset({feature.id}), feature.variable, choice.action == "select"
            )
        if feature.kind != "arg" or choice.value is None:
            raise ChoiceError(f"set expects FILE:ARG=VALUE, got {choice.feature!r}")
        values = self.catalog.values_of(feature.id)
        for entry, value in values:
            if value.slot == choice.value:
                return _Effective(choice, frozenset({feature.id, entry.id}), entry.variable, True)
        for entry, value in values:
            if value.slot is OTHER:
                return _Effective(
                    choice,
                    frozenset({feature.id, entry.id}),
                    entry.variable,
                    True,
                    feature.id,
                    choice.value,
                )
        raise _Refused(f"{feature.id} takes no value other than its known ones")

    def _decisions(self, effective: Sequence[_Effective]) -> Decisions | None:
        """The solver's answer for a list of literals (None: unsatisfiable), from the cache."""
        key = tuple((e.variable, e.value) for e in effective)
        length = len(key)
        while length and key[:length] not in self._steps:
            length -= 1
        decisions = self._steps[key[:length]] if length else self.derivation.initial
        for position in range(length, len(key)):
            variable, value = key[position]
            found = self.derivation.add(decisions, variable, value)
            if found is None:
                return None
            decisions = found
            self._steps[key[: position + 1]] = decisions
        if key:
            self._steps.move_to_end(key)
        while len(self._steps) > CACHED_STEPS:
            self._steps.popitem(last=False)
        return decisions

    def _reason(self, earlier: Sequence[_Effective], entry: _Effective) -> str:
        """The earlier choices and the constraints that together rule ``entry`` out."""
        manager = self.derivation.manager

        def literal(e: _Effective) -> BDD:
            atom = manager.var(e.variable)
            return atom if e.value else ~atom

        component = self.derivation.component_of[entry.variable]
        goal = literal(entry)
        kept = [e for e in earlier if self.derivation.component_of[e.variable] == component]
        position = 0
        while position < len(kept):
            trial = kept[:position] + kept[position + 1 :]
            cube = goal
            for e in trial:
                cube &= literal(e)
            if self.derivation.satisfiable(component, cube):
                position += 1
            else:
                kept = trial
        cube = goal
        for e in kept:
            cube &= literal(e)
        because = explain(self.model, cube)
        text = f"{_show(entry.choice)} is impossible"
        if kept:
            text += " after " + ", ".join(_show(e.choice) for e in kept)
        return f"{text}: {'; '.join(because)}"

    # -- the answer ---------------------------------------------------------------------
    def _answer(
        self,
        accepted: list[UserChoice],
        refused: list[Refusal],
        effective: Sequence[_Effective],
        decisions: Decisions,
    ) -> ConfigurationState:
        chosen = {t for e in effective for t in e.targets}
        features: dict[str, FeatureState] = {}
        for feature in self.catalog:
            decided = decisions.decided.get(feature.variable)
            state = "unselected" if decided is None else "selected" if decided else "deselected"
            features[feature.id] = FeatureState(
                feature.kind,
                feature.file,
                feature.arg,
                feature.value,
                feature.parent,
                state,
                state != "unselected" and feature.id not in chosen,
            )
        texts = {e.arg: e.text for e in effective if e.arg is not None and e.text is not None}
        values = {entry.path: self._values(entry, decisions, texts) for entry in self.catalog.files}
        unselected = sum(1 for f in features.values() if f.state == "unselected")
        complete = len(decisions.decided) == len(self.derivation.variables)
        launches = self._launches(decisions, texts) if complete else None
        commands = group(launches or [])
        workspace = self.analysis.workspace
        command = "\n".join(command_line(g, workspace) for g in commands) if launches else None
        return ConfigurationState(
            choices=accepted,
            refused=refused,
            features=features,
            conflicts=self.conflicts.judge(decisions, self._describe),
            graph=self._graph(decisions, values, texts),
            complete=complete,
            command=command,
            counter=lambda: self._count(decisions),
            unselected=unselected,
            commands=commands,
            untyped=[
                arg
                for arg, values in self.catalog.args.items()
                for feature, value in values[1]
                if value.slot is OTHER
                and decisions.decided.get(feature.variable)
                and arg not in texts
            ],
        )

    def _count(self, decisions: Decisions) -> int:
        """Valid configurations left: the product of the components' counts (each cached)."""
        derivation = self.derivation
        total = 1
        for component, cube in decisions.cubes.items():
            found = self._counts.get(cube)
            if found is None:
                members = derivation.members[component]
                fixed = {v: b for v, b in decisions.literals.items() if v in set(members)}
                formula = derivation.cofactor(derivation.formulas[component], fixed)
                free = len(members) - len(fixed)
                found = int(derivation.manager.count(formula, nvars=free))
                self._counts[cube] = found
            total *= found
        return total

    def _describe(self, condition: BDD, values: Mapping[str, bool]) -> str:
        """``condition`` simplified under ``values`` (decided variables), for people."""
        key = (condition, frozenset(values.items()))
        text = self._described.get(key)
        if text is None:
            space = self.analysis.space
            text = space.describe(space.cofactor(condition, values))
            self._described[key] = text
        return text

    def _values(self, entry: FileEntry, decisions: Decisions, texts: Mapping[str, str]) -> Values:
        """Concrete strings of a file's inputs as far as the choices fix them."""
        concrete: dict[Input, str] = dict(self.lowering.concrete)
        for arg in entry.feature.args:
            text = self._arg_text(entry, arg.name, decisions, texts)
            if text is not None:
                concrete[arg.input] = text
        return Values(concrete, self.lowering.host)

    def _arg_text(
        self, entry: FileEntry, name: str, decisions: Decisions, texts: Mapping[str, str]
    ) -> str | None:
        """The string an arg is given (or defaults to), once its value is decided."""
        arg_id = f"{entry.id}:{name}"
        for feature, value in self.catalog.values_of(arg_id):
            if decisions.decided.get(feature.variable):
                if value.slot is OTHER:
                    return texts.get(arg_id)
                if value.slot is UNSET:
                    return self.analysis.model(entry.path).unset_defaults.get(name)
                return str(value.slot)
        return None

    def _graph(
        self, decisions: Decisions, values: Mapping[str, Values], texts: Mapping[str, str]
    ) -> Graph:
        graph = Graph()
        lists = {
            "node": graph.nodes,
            "test": graph.tests,
            "param": graph.params,
            "topic": graph.topics,
            "error": graph.errors,
        }
        judged: dict[tuple[BDD, BDD], tuple[str, dict[str, bool]]] = {}
        typed: dict[str, dict[Input, str]] = {}  # entry file → its args' <other> texts
        for entry in self.catalog.files:
            for arg in entry.feature.args:
                text = texts.get(f"{entry.id}:{arg.name}")
                if text is not None:
                    typed.setdefault(entry.path, {})[arg.input] = text
        for element in self.graph.elements:
            bounds = element.bounds
            if not bounds.exact and element.entry in typed:
                bounds = self.lowering.decide(element.condition, typed[element.entry])
            key = (bounds.must, bounds.may)
            verdict = judged.get(key)
            if verdict is None:
                verdict = self.derivation.presence(bounds, decisions)
                judged[key] = verdict
            presence, restricted = verdict
            if presence == ABSENT and element.kind == "error":
                continue
            condition = (
                None
                if presence in (PRESENT, ABSENT)
                else self._describe(element.condition, restricted)
            )
            static = not element.inputs or presence == ABSENT
            entries = self._entries.get(element.id) if static else None
            if entries is None or entries[0] != (presence, condition):
                shown = self._fields(element, None if presence == ABSENT else values)
                extra: Fields = {"nodes": element.nodes} if element.kind == "topic" else {}
                made = [
                    {
                        **fields,
                        **extra,
                        "presence": presence,
                        "condition": condition,
                        "id": element.id if number == 0 else f"{element.id}/{number}",
                    }
                    for number, fields in enumerate(shown)
                ]
                entries = ((presence, condition), made)
                if static:  # the same entries serve every state with this verdict
                    self._entries[element.id] = entries
            lists[element.kind].extend(entries[1])
        return graph

    def _fields(self, element: Element, values: Mapping[str, Values] | None) -> list[Fields]:
        """The element's fields: with the state's values, or symbolic (``values`` None).

        Rendered once per combination of the strings its terms read.
        """
        given = values[element.entry] if values is not None and element.inputs else None
        strings = frozenset((i, given.concrete.get(i)) for i in element.inputs) if given else None
        key = (element.id, strings)
        found = self._rendered.get(key)
        if found is None:
            found = element.fields(given or Values(self.lowering.concrete, self.lowering.host))
            self._rendered[key] = found
        return found

    def _launches(self, decisions: Decisions, texts: Mapping[str, str]) -> list[Launch] | None:
        """The launched files and their args; None while an <other> value has no text."""
        launches = []
        for entry in self.catalog.files:
            presence, _ = self.derivation.presence(self._launched[entry.path], decisions)
            if presence != PRESENT:
                continue
            model = self.analysis.model(entry.path)
            reads: dict[str, str | None] = {}
            given: dict[str, str] = {}
            features = {arg.name: arg for arg in entry.feature.args}
            for name in model.inputs:
                default = model.unset_defaults.get(name)
                arg = features.get(name)
                if arg is None:
                    reads[name] = default
                    if default is None and _required(model, name):
                        literals = [s for s in model.domains.get(name, ()) if isinstance(s, str)]
                        if not literals:
                            return None
                        given[name] = reads[name] = literals[0]
                    continue
                text = self._arg_text(entry, name, decisions, texts)
                chosen = self._chosen_slot(entry, name, decisions)
                if chosen is OTHER and text is None:
                    return None
                reads[name] = text
                if chosen is not UNSET and (text != default or arg.default is None):
                    assert text is not None
                    given[name] = text
            launches.append(Launch(entry.path, entry.id, given, reads))
        return launches

    def _chosen_slot(self, entry: FileEntry, name: str, decisions: Decisions) -> object:
        for feature, value in self.catalog.values_of(f"{entry.id}:{name}"):
            if decisions.decided.get(feature.variable):
                return value.slot
        return None


class _Refused(Exception):
    """A choice the model cannot take, whatever was chosen before."""


def _required(model: LaunchModel, name: str) -> bool:
    """``name`` is an arg of the command line without a default: roslaunch insists on it."""
    return any(
        a.name == name and a.input is not None and a.default is None and a.value is None
        for a in model.args
    )


def _show(choice: UserChoice) -> str:
    if choice.action == "set":
        return f"set {choice.feature}={choice.value}"
    return f"{choice.action} {choice.feature}"
