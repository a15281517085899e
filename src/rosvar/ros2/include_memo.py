"""An included file interpreted once per distinct binding of what it reads.

A large ROS 2 system includes the same files from many includers and entry files, and most
of those walks repeat an earlier one (docs/performance.md). What a walk of an included file
does follows from the file, the path condition, the context's fixed parts (namespace, global
remaps and parameters, environment, trigger, time, whether the command line is open) and
what it reads of the rest as it goes: launch configurations (:meth:`Context.get`) and the
entry model's inputs and listed args (:func:`is_input`, :func:`is_listed`).

The first walk is recorded: what it read of the state before it, in order, is a path in a
trie (the next read of a walk follows from what it read before), and its effect — the
model's records, the configurations, namespace, remaps and parameters it set, diagnostics,
unset reads and started processes — is replayed where a later walk of the file reads the
same. A read is of the state before the walk where it saw the value that state held: a value
the walk wrote, or a group emptied, follows from earlier reads.

A walk that made inputs of the entry model (an included file's arg the entry file does not
declare) or listed args in it keeps those declarations, replayed as the walk made them (the
same names, declaring files and domains); their values name the entry file's inputs, so such
a walk is replayed in that entry file only (another pass of it, another include). Its later
reads of a name it declared follow from the walk itself and are not keys.

A walk whose effect a replay would not reproduce is not kept: one that set timers, event
handlers, shutdowns, environment variables or anonymous names, forgot configurations or
replaced a global list, or met a limit (an include cycle, the include count and depth, the
nesting, the file's value budget). A replay is refused where one of those limits would be
met from where it stands.
"""

from __future__ import annotations

import copy
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from typing import Generic, TypeVar

from rosvar.diagnostics import Diagnostic, DiagnosticSink
from rosvar.frontends.entity import Entity
from rosvar.frontends.xml import Snapshot
from rosvar.interpreter.interpretation import (
    MAX_INCLUDE_DEPTH,
    MAX_INCLUDES,
    MAX_NESTING,
    Interpretation,
)
from rosvar.interpreter.model import (
    ArgDecl,
    Decision,
    ErrorEvent,
    IncludeDecl,
    LaunchModel,
    NodeDecl,
    Raw,
)
from rosvar.logic.bdd import BDD
from rosvar.logic.choice import Choice, leaf_key
from rosvar.logic.conditions import ConditionSpace
from rosvar.memo import EntryMemo
from rosvar.ros2.context import Configuration, Context, GlobalParam, GlobalRemap, Probe
from rosvar.ros2.substitutions import Ros2Substituter

CAPACITY = 4096
"""Included files in a fixed context whose walks are kept (:class:`~rosvar.memo.Memo`)."""
MAX_BINDINGS = 64
"""Walks kept per file and fixed context: the distinct bindings of what it reads."""
LIMITS = frozenset({"include-cycle", "include-too-many", "nesting-too-deep"})
"""Codes of the limits a walk can meet: such a walk depends on where it stands."""

Read = tuple[Probe, str, object]
T = TypeVar("T")


def _model_has_input(it: Interpretation[Context], _context: Context, name: str) -> object:
    return name in it.model.inputs


def _model_lists(it: Interpretation[Context], _context: Context, name: str) -> object:
    model = it.model
    return name in model.settable and not any(arg.name == name for arg in model.args)


def _names(_it: Interpretation[Context], context: Context, _name: str) -> object:
    return frozenset(context.configurations)


def _configuration(_it: Interpretation[Context], context: Context, name: str) -> object:
    return context.configurations.get(name)


PROBES: dict[Probe, Callable[[Interpretation[Context], Context, str], object]] = {
    Probe.CONFIGURATION: _configuration,
    Probe.INPUT: _model_has_input,
    Probe.LISTED: _model_lists,
    Probe.NAMES: _names,
}
"""How each probe reads the state (the walk, through :func:`observe`; a lookup, before)."""


def observe(it: Interpretation[Context], context: Context, probe: Probe, name: str) -> object:
    """What ``probe`` reads of ``name`` now, noted for the walks being recorded."""
    answer = PROBES[probe](it, context, name)
    recording = context.recording
    if recording.walks:
        recording.reads.append((probe, name, answer))
    return answer


def is_input(it: Interpretation[Context], context: Context, name: str) -> bool:
    """Whether the entry file's model has ``name`` as an input (its own arg, or one an
    included file's declaration made)."""
    return bool(observe(it, context, Probe.INPUT, name))


def is_listed(it: Interpretation[Context], context: Context, name: str) -> bool:
    """Whether an included file's declaration of ``name`` is listed among the model's args:
    the command line can set it (:attr:`LaunchModel.settable`) and none is listed yet."""
    return bool(observe(it, context, Probe.LISTED, name))


def declare(it: Interpretation[Context], context: Context, name: str) -> Configuration:
    """Make ``name``, an included file's arg the entry file does not declare, an input of the
    entry model (settable on the command line): its value per input slot, unset where not
    given."""
    _entered(context, name, context.filename)
    return _declared(it, name, context.filename)


def _declared(it: Interpretation[Context], name: str, file: str) -> Configuration:
    it.model.settable[name] = file
    value: Configuration = it.entry_args(it.model.file, [name], None, {name: file})[name]
    return value


def list_arg(it: Interpretation[Context], context: Context, declaration: ArgDecl) -> None:
    """List an included file's declaration among the entry model's args."""
    _entered(context, declaration.name, None)
    it.model.args.append(declaration)


def _entered(context: Context, name: str, file: str | None) -> None:
    recording = context.recording
    if recording.walks:
        recording.entered.append((len(recording.reads), name, file))


def configuration_names(it: Interpretation[Context], context: Context) -> frozenset[str]:
    """The names of every launch configuration set."""
    names = observe(it, context, Probe.NAMES, "")
    assert isinstance(names, frozenset)
    return names


def _answer_key(probe: Probe, answer: object) -> object:
    """A read's answer as a key: a configuration's value by its branches."""
    if probe is Probe.CONFIGURATION:
        return None if answer is None else answer.key()  # type: ignore[attr-defined]
    return answer


@dataclass(frozen=True, slots=True)
class _Appended(Generic[T]):
    """What a walk did to a global list (remaps, parameters): made it, or appended to it."""

    made: bool
    items: tuple[T, ...]


@dataclass(frozen=True, slots=True)
class Effect:
    """What one walk of an included file did, as a replay repeats it."""

    configurations: tuple[tuple[str, Configuration], ...]
    namespace_set: bool
    namespace: Choice[Raw | None] | None
    remaps: _Appended[GlobalRemap]
    params: _Appended[GlobalParam]
    declared: tuple[tuple[str, str], ...]  # inputs made, with the file declaring each
    args: tuple[ArgDecl, ...]  # included declarations listed in the model
    entry: str | None  # the entry file whose inputs it made or listed; None: none
    nodes: tuple[NodeDecl, ...]
    includes: tuple[IncludeDecl, ...]
    errors: tuple[ErrorEvent, ...]
    decisions: tuple[Decision, ...]
    diagnostics: tuple[Diagnostic, ...]
    unset_reads: frozenset[str]
    started: tuple[tuple[str, BDD], ...]
    included: frozenset[str]  # real paths the nested includes named (cycles)
    loaded: tuple[str, ...]  # launch files loaded, as the model lists them
    followed: int  # nested includes followed (MAX_INCLUDES)
    combinations: int  # spent from the file's value budget
    depth: int  # nesting below the walk's start (MAX_NESTING)
    include_depth: int | None
    """The deepest include stack a nested include's depth was checked at, below the walk's
    file (MAX_INCLUDE_DEPTH); None: no nested include got so far."""


@dataclass(slots=True)
class _Node:
    """A trie node: the next read of every walk that got here, or the effect of the one that
    read nothing more."""

    probe: tuple[Probe, str] | None = None
    next: dict[object, _Node] = field(default_factory=dict)
    effect: Effect | None = None


@dataclass(slots=True)
class _Walks:
    """The recorded walks of one file (its parsed ``entity``) in one fixed context."""

    entity: Entity
    root: _Node = field(default_factory=_Node)
    kept: int = 0
    own: bool = False  # a walk kept read values some input steers, or made inputs


def _table(files: Snapshot) -> EntryMemo[object, _Walks]:
    """The analysis's table of recorded walks, kept with the files it read: keyed by the
    parsed files, it must not outlive them, and a table on the condition space made a
    cycle with it, whose collection freed BDD nodes after their manager."""
    table = files.tables.get(__name__)
    if not isinstance(table, EntryMemo):
        table = files.tables[__name__] = EntryMemo(CAPACITY)
    return table


def forget_walks(_space: ConditionSpace, files: Snapshot) -> None:
    """Drop the walks recorded for the entry file done (a ``Release`` of
    :mod:`~rosvar.interpreter.semantics`): those whose fixed context some input steers (a
    path condition, a namespace over its inputs), and the files' whose kept walks read
    such values or made inputs (replayed in their entry file only). Walks of constant
    contexts and reads stay for every entry file."""
    table = files.tables.get(__name__)
    if isinstance(table, EntryMemo):
        table.release()
        for key in [key for key, walks in table.items() if walks.own]:
            del table[key]


def _fixed(root: Entity, file: str, it: Interpretation[Context], context: Context) -> object:
    """The key of what a walk reads without probing: the file, the path condition and the
    context's parts other than launch configurations."""
    namespace = context.namespace
    remaps = context.remaps
    params = context.params
    return (
        id(root),
        file,
        it.pc,
        None if namespace is None else namespace.key(),
        None
        if remaps is None
        else tuple((r.condition, leaf_key(r.source), leaf_key(r.target)) for r in remaps),
        None
        if params is None
        else tuple(
            (p.condition, leaf_key(p.name), leaf_key(p.value), leaf_key(p.file)) for p in params
        ),
        tuple((name, value.key()) for name, value in context.env.items()),
        context.trigger,
        context.now,
        context.open_command_line,
    )


def _find(
    walks: _Walks, it: Interpretation[Context], context: Context
) -> tuple[Effect, list[Read]] | None:
    """The effect of the recorded walk that read what a walk would read now, with the reads."""
    node = walks.root
    seen: list[Read] = []
    while node.effect is None:
        if node.probe is None:
            return None
        probe, name = node.probe
        answer = PROBES[probe](it, context, name)
        seen.append((probe, name, answer))
        found = node.next.get(_answer_key(probe, answer))
        if found is None:
            return None
        node = found
    return node.effect, seen


def _keep(walks: _Walks, reads: list[tuple[Probe, str, object]], effect: Effect) -> None:
    """File ``effect`` under ``reads`` (answers as keys); a walk that read otherwise than
    the trie's walks (a value it wrote that was the earlier one itself) is not kept."""
    if walks.kept >= MAX_BINDINGS:
        return
    node = walks.root
    for probe, name, key in reads:
        if node.effect is not None:
            return
        if node.probe is None:
            node.probe = (probe, name)
        elif node.probe != (probe, name):
            return
        child = node.next.get(key)
        if child is None:
            child = node.next[key] = _Node()
        node = child
    if node.probe is None and node.effect is None:
        node.effect = effect
        walks.kept += 1


def _budget(it: Interpretation[Context]) -> Ros2Substituter | None:
    substituter = it.substituter
    return substituter if isinstance(substituter, Ros2Substituter) else None


def _fits(effect: Effect, it: Interpretation[Context], substituter: Ros2Substituter) -> bool:
    """Whether a walk from here would meet no limit the recorded one did not, in the entry
    file whose inputs it made, if any."""
    return (
        it.included + effect.followed <= MAX_INCLUDES
        and (
            effect.include_depth is None
            or len(it.stack) + 1 + effect.include_depth < MAX_INCLUDE_DEPTH
        )
        and it.depth + effect.depth <= MAX_NESTING
        and substituter.budget.spares(effect.combinations)
        and not any(path in effect.included for path in it.stack)
        and effect.entry in (None, it.model.file)
    )


def walk_included(
    it: Interpretation[Context], root: Entity, context: Context, file: str, path: str
) -> None:
    """Walk ``root``, the included ``file`` (real path ``path``), in ``context``: replayed
    where a recorded walk read what this one would."""
    substituter = _budget(it)
    if substituter is None:
        _walk(it, root, context, file, path)
        return
    table = _table(it.files)
    key = _fixed(root, file, it, context)
    walks = table.get(key)
    if walks is None or walks.entity is not root:
        walks = _Walks(root)
        table.keep(key, walks, it.space.varies(key))
    found = _find(walks, it, context)
    if found is not None and _fits(found[0], it, substituter):
        _replay(it, context, substituter, *found)
        return
    _record(it, root, context, file, path, substituter, None if found is not None else walks)


def _walk(
    it: Interpretation[Context], root: Entity, context: Context, file: str, path: str
) -> None:
    it.stack.append(path)
    filename, context.filename = context.filename, file
    try:
        it.walk(root.children, context)
    finally:
        context.filename = filename
        it.stack.pop()


def _replay(
    it: Interpretation[Context],
    context: Context,
    substituter: Ros2Substituter,
    effect: Effect,
    seen: list[Read],
) -> None:
    recording = context.recording
    if recording.walks:
        recording.reads.extend(seen)
        recording.included.extend(effect.included)
        recording.loaded.extend(effect.loaded)
    for name, declared_in in effect.declared:
        _entered(context, name, declared_in)
        _declared(it, name, declared_in)
    for declaration in effect.args:
        _entered(context, declaration.name, None)
    model = it.model
    model.args.extend(copy.copy(declaration) for declaration in effect.args)
    if effect.include_depth is not None:
        deepest = len(it.stack) + 1 + effect.include_depth
        recording.deepest_check = max(recording.deepest_check, deepest)
    it.deepest = max(it.deepest, it.depth + effect.depth)
    it.included += effect.followed
    substituter.budget.combinations += effect.combinations
    configurations = context.configurations
    for name, value in effect.configurations:
        configurations[name] = value
    if effect.namespace_set:
        context.namespace = effect.namespace
    context.remaps = _appended(context.remaps, effect.remaps)
    context.params = _appended(context.params, effect.params)
    model.nodes.extend(copy.copy(node) for node in effect.nodes)
    model.includes.extend(copy.copy(include) for include in effect.includes)
    model.errors.extend(copy.copy(error) for error in effect.errors)
    model.decisions.extend(copy.copy(decision) for decision in effect.decisions)
    for loaded in effect.loaded:
        if loaded not in model.files:
            model.files.append(loaded)
    it.sink.extend(list(effect.diagnostics))
    context.unset_reads |= effect.unset_reads
    started = context.events.started
    for where, condition in effect.started:
        started[where] = started.get(where, it.space.false) | condition


def _appended(current: list[T] | None, change: _Appended[T]) -> list[T] | None:
    if change.made:
        return list(change.items)
    if change.items:
        assert current is not None  # the fixed key holds its content
        current.extend(change.items)
    return current


@dataclass(slots=True)
class _Before:
    """The state a walk starts from, as far as its effect is told from it."""

    configurations: dict[str, Configuration]
    namespace: Choice[Raw | None] | None
    remaps: list[GlobalRemap] | None
    remap_count: int
    params: list[GlobalParam] | None
    param_count: int
    env: dict[str, Choice[Raw | None]]
    counts: tuple[int, ...]
    anon: object
    combinations: int
    included: int
    marks: tuple[int, int, int, int]


def _counts(model: LaunchModel, context: Context) -> tuple[int, ...]:
    """Sizes of what a walk may only append to, or must not change at all."""
    return (
        len(model.nodes),
        len(model.includes),
        len(model.errors),
        len(model.decisions),
        len(model.args),
        len(context.timers),
        len(context.shutdowns),
        len(context.events.handlers),
    )


def _record(
    it: Interpretation[Context],
    root: Entity,
    context: Context,
    file: str,
    path: str,
    substituter: Ros2Substituter,
    walks: _Walks | None,
) -> None:
    """Walk, and keep the walk's effect in ``walks`` if a replay can reproduce it."""
    recording = context.recording
    before = _Before(
        dict(context.configurations),
        context.namespace,
        context.remaps,
        len(context.remaps or ()),
        context.params,
        len(context.params or ()),
        dict(context.env),
        _counts(it.model, context),
        it.anon_count,
        substituter.budget.combinations,
        it.included,
        (
            len(recording.reads),
            len(recording.included),
            len(recording.loaded),
            len(recording.entered),
        ),
    )
    deepest, it.deepest = it.deepest, it.depth
    deepest_check, recording.deepest_check = recording.deepest_check, -1
    sink, it.sink = it.sink, DiagnosticSink()
    unset_reads, context.unset_reads = context.unset_reads, set()
    events = context.events
    started, events.started = events.started, {}
    recording.walks += 1
    walked = False
    try:
        _walk(it, root, context, file, path)
        walked = True
    finally:
        recording.walks -= 1
        inner_sink, it.sink = it.sink, sink
        sink.extend(inner_sink.items)
        inner_unset, context.unset_reads = context.unset_reads, unset_reads
        unset_reads |= inner_unset
        inner_started, events.started = events.started, started
        for where, condition in inner_started.items():
            started[where] = started.get(where, it.space.false) | condition
        depth = it.deepest - it.depth
        it.deepest = max(deepest, it.deepest)
        checked = recording.deepest_check
        include_depth = None if checked < 0 else checked - len(it.stack) - 1
        recording.deepest_check = max(deepest_check, checked)
        reads, _included, _loaded, entered = before.marks
        read = _read_before(
            recording.reads[reads:],
            before.configurations,
            [(at - reads, name, file) for at, name, file in recording.entered[entered:]],
        )
        if recording.walks:  # the enclosing walks need no more of this one's reads
            del recording.reads[reads:]
            recording.reads.extend(read)
            end = len(recording.reads)  # after the reads this walk's declarations follow
            recording.entered[entered:] = [
                (end, name, file) for _at, name, file in recording.entered[entered:]
            ]
        if walked and walks is not None:
            effect = _effect(
                it,
                context,
                substituter,
                before,
                inner_sink.items,
                inner_unset,
                inner_started,
                max(depth, 0),
                include_depth,
            )
            if effect is not None:
                keys = [(p, n, _answer_key(p, answer)) for p, n, answer in read]
                walks.own = walks.own or effect.entry is not None or it.space.varies(tuple(keys))
                _keep(walks, keys, effect)
        if not recording.walks:
            recording.reads.clear()
            recording.included.clear()
            recording.loaded.clear()
            recording.entered.clear()


def _read_before(
    reads: list[Read],
    initial: dict[str, Configuration],
    entered: list[tuple[int, str, str | None]],
) -> list[Read]:
    """What a walk read of the state before it (``initial``'s configurations), each once,
    in order: a configuration that held another value then was written by the walk (or a
    group it emptied), and whether a name is an input after the walk made it one, or is
    listed after the walk made it an input or listed it (``entered``, after that many reads),
    follow from earlier reads."""
    kept: list[Read] = []
    names: set[str] = set()
    met: set[Read] = set()
    since: dict[tuple[Probe, str], int] = {}
    for at, name, file in entered:
        since.setdefault((Probe.LISTED, name), at)
        if file is not None:
            since.setdefault((Probe.INPUT, name), at)
    for index, read in enumerate(reads):
        probe, name, answer = read
        if since.get((probe, name), index + 1) <= index:
            continue
        if probe is Probe.CONFIGURATION:
            if name in names or answer is not initial.get(name):
                continue
            names.add(name)
        elif read in met:
            continue
        else:
            met.add(read)
        kept.append(read)
    return kept


def _effect(
    it: Interpretation[Context],
    context: Context,
    substituter: Ros2Substituter,
    before: _Before,
    diagnostics: list[Diagnostic],
    unset_reads: set[str],
    started: dict[str, BDD],
    depth: int,
    include_depth: int | None,
) -> Effect | None:
    """The recorded walk's effect, or None where a replay would not reproduce it."""
    model = it.model
    nodes, includes, errors, decisions, args, *fixed = before.counts
    now = _counts(model, context)
    if now[5:] != tuple(fixed) or it.anon_count is not before.anon:
        return None  # timers, handlers, shutdowns, anonymous names
    if context.env.keys() != before.env.keys() or any(
        value is not before.env[name] for name, value in context.env.items()
    ):
        return None
    new_errors = tuple(model.errors[errors:])
    if any(error.code in LIMITS for error in new_errors) or any(
        diagnostic.code in LIMITS for diagnostic in diagnostics
    ):
        return None
    if not substituter.budget.spares(0):
        return None  # the file's budget may have been met
    combinations = substituter.budget.combinations - before.combinations
    remaps = _list_change(before.remaps, before.remap_count, context.remaps)
    params = _list_change(before.params, before.param_count, context.params)
    if remaps is None or params is None:
        return None
    initial = before.configurations
    final = context.configurations
    if any(name not in final for name in initial):
        return None  # a <reset> forgot them
    recording = context.recording
    _reads, included, loaded, entered = before.marks
    declared = tuple(
        (name, file) for _at, name, file in recording.entered[entered:] if file is not None
    )
    listed = tuple(model.args[args:])
    return Effect(
        tuple((name, value) for name, value in final.items() if initial.get(name) is not value),
        context.namespace is not before.namespace,
        context.namespace,
        remaps,
        params,
        declared,
        listed,
        model.file if declared or listed else None,
        tuple(model.nodes[nodes:]),
        tuple(model.includes[includes:]),
        new_errors,
        tuple(model.decisions[decisions:]),
        tuple(diagnostics),
        frozenset(unset_reads),
        tuple(started.items()),
        frozenset(recording.included[included:]),
        tuple(dict.fromkeys(recording.loaded[loaded:])),
        it.included - before.included,
        combinations,
        depth,
        include_depth,
    )


def _list_change(
    initial: Sequence[T] | None, count: int, final: Sequence[T] | None
) -> _Appended[T] | None:
    if final is initial:
        return _Appended(False, () if final is None else tuple(final[count:]))
    if initial is None and final is not None:
        return _Appended(True, tuple(final))
    return None  # replaced (a <reset> on a path)
