"""The configuration engine: from a list of user choices to everything a user sees.

A :class:`Configurator` is built once per workspace (feature model, lowered presence
conditions, the variational graph) and answers any list of choices, statelessly. Choices
are replayed in order and every prefix's replay is cached, so a session that adds one
choice at a time pays for one step; what the literals show comes from ``view``, derived
from the longest earlier list of them.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass, field, replace
from enum import StrEnum
from functools import cached_property

from rosvar.analyses.feature_model.features import FeatureKind
from rosvar.analyses.feature_model.model import FeatureModel
from rosvar.configuration.catalog import Catalog, Feature
from rosvar.configuration.choices import Action, ChoiceError, Refusal, UserChoice
from rosvar.configuration.command import Launch, command_line, group, launch_tool
from rosvar.configuration.conflicts import Certainty, Conflicts, ConflictState
from rosvar.configuration.derivation import Decisions, Derivation
from rosvar.configuration.graph import Fields, Render, VariationalGraph
from rosvar.configuration.lowering import Lowering
from rosvar.configuration.prefix_cache import PrefixCache
from rosvar.configuration.presence import Presence
from rosvar.configuration.sat import Sat
from rosvar.configuration.view import Graph, Summary, Views
from rosvar.diagnostics import Diagnostic, leaves_unknown
from rosvar.interpreter.workspace_models import Analysis, collector_paused
from rosvar.logic.inputs import OTHER, UNSET
from rosvar.workspace.interfaces.model import Interfaces

Progress = Callable[[str, int, int], None]
"""Told what the engine builds while it is built: a phase, and how far it is (done, total)."""

CACHED_FEATURES = 1_000_000
"""Views, replays and solver answers are kept per list of choices (a session's history and
then some), each holding a state of every feature and an entry of every graph element: as
many as make this many feature states and entries in all, at least ``MIN_CACHED_STEPS``. A
fixed count of steps would hold memory in proportion to the workspace's size, without bound
on large ones."""
MIN_CACHED_STEPS = 64


class Selection(StrEnum):
    """A feature's state: in every valid configuration left, in none, or still open."""

    SELECTED = "selected"
    DESELECTED = "deselected"
    UNSELECTED = "unselected"


@dataclass(frozen=True, eq=False, slots=True, weakref_slot=True)  # documents kept by it
class FeatureState:
    """One feature's state; the engine hands out one object per feature and state, so
    states share them and an unchanged feature is the same object (compared, and its
    document kept, by identity)."""

    kind: FeatureKind
    file: str
    package: str | None  # the ROS package of the file, as ``roslaunch``/``ros2 launch`` name it
    doc: str | None  # an arg's description in its file
    arg: str | None
    value: str | None
    parent: str | None
    state: Selection
    derived: bool


_Row = tuple[str, str, Feature, dict[tuple[bool | None, bool], FeatureState]]
"""A feature's id, its variable, the feature, and its states handed out so far by (decided
value, chosen by the user): each made on first use (``Configurator._state``), as a feature
shows few of its six."""


@dataclass
class ConfigurationState:
    choices: list[UserChoice]
    refused: list[Refusal]
    features: dict[str, FeatureState]
    conflicts: list[ConflictState]
    grapher: Callable[[], Graph] = field(repr=False)  # judged and rendered on first use
    outliner: Callable[[], Graph] = field(repr=False)  # the same without conditions
    describer: Callable[[Iterable[str]], dict[str, Fields]] = field(repr=False)
    summarizer: Callable[[], Summary] = field(repr=False)  # judged on first use
    complete: bool
    command: str | None
    counter: Callable[[], int] = field(repr=False)  # counting can cost more than the step
    unselected: int
    commands: list[list[Launch]] = field(default_factory=list)  # files sharing a command line
    untyped: list[str] = field(default_factory=list)  # args at <other> still without a text
    unknown: list[Diagnostic] = field(default_factory=list)
    """What rosvar could not read of the selected files (``diagnostics.leaves_unknown``):
    the product's graph may lack what they load there."""

    @cached_property
    def graph(self) -> Graph:
        """The graph's elements with their presence (judged on first use)."""
        return self.grapher()

    @cached_property
    def outline(self) -> Graph:
        """The graph's elements with their presence, their conditions not described (None):
        what is summarised needs no condition, and describing is most of rendering."""
        return self.outliner()

    def described(self, ids: Iterable[str]) -> dict[str, Fields]:
        """The graph entries ``ids`` as ``graph`` has them, conditions described."""
        return self.describer(ids)

    @cached_property
    def summary(self) -> Summary:
        """The graph in numbers, judged on first use without describing conditions."""
        return self.summarizer()

    @cached_property
    def launches(self) -> bool | None:
        """Whether the product's command loads: False when roslaunch would stop (an error
        present) or refuse two nodes of one name (a certain conflict); None while there is
        no command (incomplete, or an ``<other>`` value without its text) or while rosvar
        could not read all of the product (``unknown``)."""
        if not self.complete or self.command is None:
            return None
        if self.summary.errors or any(c.status == Certainty.CERTAIN for c in self.conflicts):
            return False
        return None if self.unknown else True

    @cached_property
    def configurations(self) -> int:
        """Valid configurations remaining (counted on first use)."""
        return self.counter()


@dataclass(frozen=True)
class _Effective:
    """An accepted choice as a literal: ``variable = value``, with the <other> text if any."""

    choice: UserChoice
    targets: frozenset[str]  # feature ids it decides (unselect removes it by any of them)
    variable: str
    value: bool
    arg: str | None = None
    text: str | None = None


@dataclass(frozen=True)
class _Replay:
    """A list of choices replayed: the accepted and refused ones, and the literals."""

    accepted: tuple[UserChoice, ...]
    refused: tuple[Refusal, ...]
    effective: tuple[_Effective, ...]
    decisions: Decisions


class Configurator:
    """Built once per workspace; answers any list of user choices (stateless)."""

    def __init__(
        self,
        analysis: Analysis,
        model: FeatureModel,
        env: Mapping[str, str] | None = None,
        spelling: Mapping[str, str] | None = None,
        progress: Progress | None = None,
        interfaces: Interfaces | None = None,
        *,
        render: Render,
    ) -> None:
        """``model`` from ``extract(analysis, products=True)``; ``progress``: told how far
        the build is (a large workspace takes a while); ``interfaces`` wire the nodes to
        their topics; ``render``: the graph's entries as the presentation shows them
        (``rosvar.outputs.web.entries.render``); ``env``, if given, must be the model's
        (``extract(..., env=)``: the solver fixes the environment as the graph does)."""
        if not model.products:
            raise ValueError("the configurator needs extract(..., products=True)")
        if env is not None and dict(env) != dict(model.environment):
            raise ValueError("the configurator's env must be the model's: extract(..., env=)")
        self._build(analysis, model, env, spelling, progress or _silent, interfaces, render)

    @collector_paused()  # a long-lived heap: left young, the collector rescanned it each step
    def _build(
        self,
        analysis: Analysis,
        model: FeatureModel,
        env: Mapping[str, str] | None,
        spelling: Mapping[str, str] | None,
        progress: Progress,
        interfaces: Interfaces | None,
        render: Render,
    ) -> None:
        self.analysis = analysis
        self.model = model
        self.catalog = Catalog(model, spelling)
        progress("solver", 0, 1)
        self.derivation = Derivation(model)
        self.lowering = Lowering(analysis, model, model.environment)
        file_ids = {entry.path: entry.id for entry in self.catalog.files}
        self.graph = VariationalGraph(
            analysis,
            model,
            self.lowering,
            file_ids,
            lambda done, total: progress("graph of files", done, total),
            interfaces,
        )
        progress("conflicts", 0, 1)
        self.conflicts = Conflicts(model, self.lowering, file_ids)
        self._launched = {
            entry.path: self.lowering.bounds(self.graph.launched[entry.path])
            for entry in self.catalog.files
        }
        self.lowering.built()
        held = len(self.catalog.features) + len(self.graph.elements)  # per step
        cached = max(MIN_CACHED_STEPS, CACHED_FEATURES // max(1, held))
        progress("presence of elements", 0, len(self.graph.elements))
        self.views = Views(
            analysis,
            self.catalog,
            self.graph,
            self.lowering,
            self.derivation,
            self.conflicts,
            cached,
            render,
        )
        self._others = [
            (arg_id, feature.variable)
            for arg_id, (_arg, values) in self.catalog.args.items()
            for feature, value in values
            if value.slot is OTHER
        ]
        self.packages: dict[str, str | None] = {  # launch file id → its ROS package
            entry.id: None
            if (package := analysis.workspace.package_of(entry.path)) is None
            else package.name
            for entry in self.catalog.files
        }
        self._rows: dict[str, _Row] = {f.id: (f.id, f.variable, f, {}) for f in self.catalog}
        self._explaining: dict[int, tuple[Sat, list[int]]] = {}  # by component, made on need
        self._unread = {  # launch file id → what of its model rosvar could not read
            entry.id: [d for d in analysis.model(entry.path).diagnostics if leaves_unknown(d)]
            for entry in self.catalog.files
        }
        self._rows_of: dict[str, list[_Row]] = {}
        for row in self._rows.values():
            self._rows_of.setdefault(row[1], []).append(row)
        self._last: (
            tuple[Mapping[str, bool], frozenset[str], dict[str, FeatureState], int] | None
        ) = None
        self._steps: PrefixCache[tuple[str, bool], Decisions] = PrefixCache(
            self.derivation.initial, cached
        )
        self._replays: PrefixCache[UserChoice, _Replay] = PrefixCache(
            _Replay((), (), (), self.derivation.initial), cached
        )
        progress("ready", 1, 1)

    # -- choices -------------------------------------------------------------------------
    def state(self, choices: Sequence[UserChoice]) -> ConfigurationState:
        """The answer for ``choices``. A step adds long-lived objects (views, verdicts,
        rendered entries) and no cycles: the collector is paused, and they go to the
        oldest generation unscanned, where its young scans found nothing to free in them
        and cost a noticeable share of each step."""
        with collector_paused():
            return self._answer(self._replay(tuple(choices)))

    def decisions(self, choices: Sequence[UserChoice]) -> Decisions:
        """The solver's view after ``choices``, to judge other conditions under them."""
        return self._replay(tuple(choices)).decisions

    def _replay(self, choices: tuple[UserChoice, ...]) -> _Replay:
        """The replay of ``choices``, from the longest prefix replayed before."""
        length, replay = self._replays.longest(choices)
        for position in range(length, len(choices)):
            replay = self._apply(replay, choices[position])
            self._replays.put(choices[: position + 1], replay)
        return replay

    def _apply(self, replay: _Replay, choice: UserChoice) -> _Replay:
        """``replay`` with one more choice: accepted, or refused with the reason."""
        feature = self.catalog.lookup(choice.feature)
        accepted = (*replay.accepted, choice)
        if choice.action == Action.UNSELECT:
            effective = tuple(e for e in replay.effective if feature.id not in e.targets)
            found = self._decisions(effective)
            assert found is not None, "a part of an accepted list was refused"
            return _Replay(accepted, replay.refused, effective, found)
        try:
            entry = self._literal(choice, feature)
        except _Refused as refusal:
            return replace(replay, refused=(*replay.refused, Refusal(choice, str(refusal))))
        kept = replay.effective
        if choice.action == Action.SET:  # a new value replaces the arg's earlier one
            kept = tuple(e for e in kept if feature.id not in e.targets)
        after = self._decisions([*kept, entry])
        if after is None:
            reason = self._reason(kept, entry)
            return replace(replay, refused=(*replay.refused, Refusal(choice, reason)))
        if entry.arg is not None:  # a typed text: refused where every product left fails by it
            stops = self.views.stops(after, _texts([*kept, entry]), entry.arg)
            if stops:
                because = "; ".join(
                    f"{f.error.location}: {f.error.message} [{f.error.code}]" for f in stops
                )
                tool = launch_tool(self.analysis.workspace.ros_version)
                reason = f"{_show(choice)} is impossible: {tool} would stop at {because}"
                return replace(replay, refused=(*replay.refused, Refusal(choice, reason)))
        return _Replay(accepted, replay.refused, (*kept, entry), after)

    def completion(self, choices: Sequence[UserChoice]) -> list[UserChoice]:
        """Choices that finish ``choices`` with defaults: open files off, open args at default."""
        added: list[UserChoice] = []
        while True:
            state = self.state([*choices, *added])
            open_ = [f for f in self.catalog if state.features[f.id].state == Selection.UNSELECTED]
            if not open_:
                return added
            # values of the files in the product first, then files (deselecting one may
            # force values elsewhere), then values of files chosen since
            open_.sort(
                key=lambda f: 1 if f.kind == FeatureKind.FILE else 0 if self._in(f, state) else 2
            )
            added.append(self._default_choice(open_[0], state))

    @staticmethod
    def _in(feature: Feature, state: ConfigurationState) -> bool:
        return state.features[feature.file].state == Selection.SELECTED

    def _default_choice(self, feature: Feature, state: ConfigurationState) -> UserChoice:
        if feature.kind == FeatureKind.FILE:
            return UserChoice(Action.DESELECT, feature.id)
        arg = feature.id if feature.kind == FeatureKind.ARG else str(feature.parent)
        values = self.catalog.values_of(arg)
        possible = [f for f, _v in values if state.features[f.id].state != Selection.DESELECTED]
        defaults = [f for f, v in values if v.default and f in possible]
        known = [f for f in possible if f.value != "<other>"]
        return UserChoice(Action.SELECT, (defaults or known or possible)[0].id)

    def _literal(self, choice: UserChoice, feature: Feature) -> _Effective:
        if choice.action in (Action.SELECT, Action.DESELECT):
            return _Effective(
                choice, frozenset({feature.id}), feature.variable, choice.action == Action.SELECT
            )
        if feature.kind != FeatureKind.ARG or choice.value is None:
            raise ChoiceError(f"set expects FILE:ARG=VALUE, got {choice.feature!r}")
        values = self.catalog.values_of(feature.id)
        for entry, value in values:
            # a known value, or the default's feature by its text (``<default: $(...)>``):
            # choosing the default leaves the arg unset, never typed as a value
            if value.slot == choice.value or (value.slot is UNSET and value.value == choice.value):
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
        length, decisions = self._steps.longest(key)
        for position in range(length, len(key)):
            variable, value = key[position]
            found = self.derivation.add(decisions, variable, value)
            if found is None:
                return None
            decisions = found
            self._steps.put(key[: position + 1], decisions)
        return decisions

    def _reason(self, earlier: Sequence[_Effective], entry: _Effective) -> str:
        """The earlier choices and the constraints that together rule ``entry`` out."""
        component = self.derivation.component_of[entry.variable]
        kept = [e for e in earlier if self.derivation.component_of[e.variable] == component]
        position = 0
        while position < len(kept):
            trial = kept[:position] + kept[position + 1 :]
            if self.derivation.satisfiable([(e.variable, e.value) for e in [*trial, entry]]):
                position += 1
            else:
                kept = trial
        because = self._because(component, [*kept, entry])
        text = f"{_show(entry.choice)} is impossible"
        if kept:
            text += " after " + ", ".join(_show(e.choice) for e in kept)
        return f"{text}: {'; '.join(because)}"

    def _because(self, component: int, literals: Sequence[_Effective]) -> list[str]:
        """The cross-tree constraints that rule ``literals`` (of ``component``) out: a
        minimal set, found by SAT within bounded work, or an honest "not explained"."""
        found = self._explaining.get(component)
        if found is None:
            found = self._explaining[component] = Sat.explaining(self.model, component)
        sat, numbers = found
        core = sat.core([sat.atom(e.variable, e.value) for e in literals])
        if core is None:
            return ["not explained (finding the constraints why took too long)"]
        return [self.model.constraints[numbers[i]].text for i in core] or [
            "the feature tree itself"
        ]

    # -- the answer ---------------------------------------------------------------------
    def _answer(self, replay: _Replay) -> ConfigurationState:
        decisions = replay.decisions
        texts = _texts(replay.effective)
        key = tuple((e.variable, e.value, e.text) for e in replay.effective)
        view = self.views.view(key, decisions, texts)
        chosen = frozenset(t for e in replay.effective for t in e.targets)
        decided = decisions.decided
        features, unselected = self._features(decided, chosen)
        complete = len(decided) == len(self.derivation.variables)
        launches = self._launches(decisions, texts) if complete else None
        workspace = self.analysis.workspace
        commands = group(launches or [], workspace.ros_version)
        command = "\n".join(command_line(g, workspace) for g in commands) if launches else None
        return ConfigurationState(
            choices=list(replay.accepted),
            refused=list(replay.refused),
            features=features,
            conflicts=self.conflicts.shown(view.conflicts, decisions),
            grapher=lambda: self.views.rendering(view).graph,
            outliner=lambda: self.views.outline(view).graph,
            describer=lambda ids: self.views.described(view, ids),
            summarizer=lambda: self.views.summary(view),
            complete=complete,
            command=command,
            counter=lambda: self.derivation.count(decisions),
            unselected=unselected,
            commands=commands,
            untyped=[
                arg for arg, variable in self._others if decided.get(variable) and arg not in texts
            ],
            unknown=list(
                dict.fromkeys(
                    diagnostic
                    for entry in self.catalog.files
                    if features[entry.id].state == Selection.SELECTED
                    for diagnostic in self._unread[entry.id]
                )
            ),
        )

    def _features(
        self, decided: Mapping[str, bool], chosen: frozenset[str]
    ) -> tuple[dict[str, FeatureState], int]:
        """Each feature's state, and how many are unselected: the last answer's with the
        features whose variable got decided (or undecided) or whose choice changed since,
        as a step changes a few of hundreds."""
        if self._last is None:
            rows: Iterable[_Row]
            rows, features, unselected = self._rows.values(), {}, 0
        else:
            before_decided, before_chosen, before, unselected = self._last
            features = dict(before)
            changed = decided.items() ^ before_decided.items()
            rows = {
                row[0]: row
                for row in [
                    *(row for variable, _ in changed for row in self._rows_of.get(variable, ())),
                    *(self._rows[i] for i in chosen ^ before_chosen if i in self._rows),
                ]
            }.values()
        for row in rows:
            id_ = row[0]
            earlier = features.get(id_)
            state = features[id_] = self._state(row, decided.get(row[1]), id_ in chosen)
            unselected += (state.state == Selection.UNSELECTED) - (
                earlier is not None and earlier.state == Selection.UNSELECTED
            )
        self._last = (decided, chosen, features, unselected)
        return features, unselected

    def _state(self, row: _Row, decided: bool | None, chosen: bool) -> FeatureState:
        """The one state object of a feature decided so (None: not), chosen or derived."""
        _id, _variable, feature, states = row
        found = states.get((decided, chosen))
        if found is None:
            found = states[decided, chosen] = FeatureState(
                feature.kind,
                feature.file,
                self.packages[feature.file],
                self.catalog.args[feature.id][0].doc if feature.kind == FeatureKind.ARG else None,
                feature.arg,
                feature.value,
                feature.parent,
                Selection.UNSELECTED
                if decided is None
                else Selection.SELECTED
                if decided
                else Selection.DESELECTED,
                decided is not None and not chosen,
            )
        return found

    def _launches(self, decisions: Decisions, texts: Mapping[str, str]) -> list[Launch] | None:
        """The launched files and their args; None while an <other> value has no text."""
        launches = []
        for entry in self.catalog.files:
            if (
                self.derivation.presence(self._launched[entry.path], decisions).presence
                != Presence.PRESENT
            ):
                continue
            model = self.analysis.model(entry.path)
            reads: dict[str, str | None] = {}
            given: dict[str, str] = {}
            features = {arg.name: arg for arg in entry.feature.args}
            for name in model.inputs:
                default = model.unset_defaults.get(name)
                arg = features.get(name)
                if arg is None:  # an arg the file never needs set: left off the command
                    reads[name] = default
                    continue
                text = self.views.arg_text(entry, name, decisions, texts)
                chosen = self.catalog.chosen(f"{entry.id}:{name}", decisions.decided)
                slot = None if chosen is None else chosen.slot
                if slot is OTHER and text is None:
                    return None
                reads[name] = text
                if slot is not UNSET and (text != default or arg.default is None):
                    assert text is not None
                    given[name] = text
            launches.append(Launch(entry.path, entry.id, given, reads))
        return launches


def _silent(_phase: str, _done: int, _total: int) -> None:
    """No progress shown."""


def _texts(effective: Iterable[_Effective]) -> dict[str, str]:
    """Arg id → the text typed for its ``<other>`` value."""
    return {e.arg: e.text for e in effective if e.arg is not None and e.text is not None}


class _Refused(Exception):
    """A choice the model cannot take, whatever was chosen before."""


def _show(choice: UserChoice) -> str:
    if choice.action == Action.SET:
        return f"set {choice.feature}={choice.value}"
    return f"{choice.action} {choice.feature}"
