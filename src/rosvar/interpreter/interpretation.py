"""Symbolic interpretation of one entry launch file, for all configurations at once.

The walk follows the launch code tag by tag (roslaunch's ``XmlLoader``, ros2/launch's
actions), but where it holds one value the walk holds a :class:`Choice`, and where it tests
a condition the walk narrows its *path condition* (``pc``). What the tags mean is a dialect's
(:class:`~rosvar.interpreter.semantics.Semantics`): its tag handlers, its substitution
language and the scope type ``S`` both carry along the walk.
"""

from __future__ import annotations

import functools
from collections.abc import Callable, Mapping, Sequence
from typing import Any, Concatenate, Generic, ParamSpec, Protocol, TypeVar

from rosvar.diagnostics import DiagnosticSink, Location
from rosvar.files import FileRefused
from rosvar.frontends.entity import Entity
from rosvar.frontends.xml import Snapshot
from rosvar.interpreter.lifted import apply, lift
from rosvar.interpreter.model import (
    INCLUDE_UNREAD,
    Decision,
    ErrorEvent,
    Guard,
    LaunchModel,
    Raw,
    Tested,
)
from rosvar.interpreter.substitution_args import MAX_TESTED_TERMS, too_complex
from rosvar.logic.atoms import register_predicate
from rosvar.logic.bdd import BDD
from rosvar.logic.cells import register_predicate_texts, spellings
from rosvar.logic.choice import Choice, Fail
from rosvar.logic.conditions import ConditionSpace
from rosvar.logic.given_up import first
from rosvar.logic.inputs import OTHER, UNSET, ArgInput, EnvInput, Slot
from rosvar.logic.terms import Hole
from rosvar.workspace import Workspace
from rosvar.workspace.launch_files import INVALID_FILE

V = TypeVar("V")
P = ParamSpec("P")
S = TypeVar("S")
"""The scope a dialect's handlers carry along the walk (roslaunch's scope, ros2's context)."""
S_contra = TypeVar("S_contra", contravariant=True)
MAX_INCLUDE_DEPTH = 64
MAX_INCLUDES = 4096
"""Includes followed in one interpretation: a diamond (each file including the next twice)
would otherwise walk 2^depth files."""
MAX_NESTING = 128
"""Elements walked inside one another, across includes: deeper ones are not interpreted
(``nesting-too-deep``), so that the walk, which recurses, stays far from Python's limit."""

TRUE_WORDS = ("true", "1")
FALSE_WORDS = ("false", "0")


class Substituter(Protocol[S_contra]):
    """A dialect's substitution language: attribute text to its values in a scope."""

    escapes: bool
    """Whether a backslash escapes the next character (ROS 2's grammar): then a text holding
    one is not literal, even without a substitution."""

    def resolve(self, text: str | None, scope: S_contra) -> Choice[Raw | Fail] | None: ...


Handler = Callable[["Interpretation[S]", Entity, S], None]
"""A tag handler: the walk, the element, and the dialect's scope."""


def processed(
    body: Callable[Concatenate[Interpretation[S], Entity, S, P], None],
) -> Callable[Concatenate[Interpretation[S], Entity, S, P], None]:
    """roslaunch's ``ifunless_test``, which every tag handler starts with: ``body`` runs
    where the tag's ``if``/``unless`` lets it, on the path narrowed to there.

    One wrapper for all tags, and no condition to compute nor path to narrow for the
    many tags with neither attribute (this runs for every element walked).
    """

    def guarded(
        it: Interpretation[S], entity: Entity, scope: S, /, *args: P.args, **kwargs: P.kwargs
    ) -> None:
        attributes = entity.attributes
        if "if" not in attributes and "unless" not in attributes:
            body(it, entity, scope, *args, **kwargs)
            return
        with it.under(it.condition_of(entity, scope)) as live:
            if live:
                body(it, entity, scope, *args, **kwargs)

    functools.update_wrapper(guarded, body)  # the handler's name in profiles and errors
    return guarded


def _truthy(text: str) -> bool:
    return text.lower().strip() in TRUE_WORDS


def _falsy(text: str) -> bool:
    return text.lower().strip() in FALSE_WORDS


register_predicate("true", _truthy, "{} is true")
register_predicate("false", _falsy, "{} is false")
for _test in ("true", "false"):
    register_predicate_texts(_test, spellings((*TRUE_WORDS, *FALSE_WORDS)))


class Interpretation(Generic[S]):
    """State of one symbolic launch run over one or more entry files."""

    def __init__(
        self,
        workspace: Workspace,
        space: ConditionSpace,
        domains: Callable[[str, str], tuple[Slot, ...]],
        env_domains: Callable[[str], tuple[Slot, ...]],
        file: str,
        files: Snapshot,
        tags: Mapping[str, Handler[S]],
        substituter: Callable[[Interpretation[S]], Substituter[S]],
    ) -> None:
        self.tags = tags
        self.workspace = workspace
        self.files = files
        self.space = space
        self._domains = domains
        self._env_domains = env_domains
        self.sink = DiagnosticSink()
        self.pc: BDD = space.true
        # A cycle (broken by ``close``): left to the garbage collector, it could free BDD
        # nodes after their manager, which CUDD reports as an error.
        self.substituter = substituter(self)
        self._escapes = self.substituter.escapes
        inputs: dict[str, ArgInput] = {}
        self.model = LaunchModel(
            file=file, space=space, inputs=inputs, domains={}, loads=space.true
        )
        self.default_machine: Choice[Raw | None] = Choice.const(space, None)
        self.anon_count: Choice[int] = Choice.const(space, 0)
        self.stack: list[str] = []
        self.depth = 0
        self.deepest = 0  # the deepest nesting walked (a replayed walk must fit in MAX_NESTING)
        self.included = 0  # includes followed, up to MAX_INCLUDES
        self._location = Location(file)

    def finish(self) -> LaunchModel:
        """The model, loading wherever no error is raised, with what the walk gathered."""
        failing = self.space.false
        for error in self.model.errors:
            failing |= error.condition
        self.model.loads = ~failing
        self.model.anon_count = self.anon_count
        self.model.diagnostics = self.sink.items
        return self.model

    def close(self) -> None:
        """Drop the substituter: reference counting then frees this run's BDDs."""
        del self.substituter

    # -- Host protocol for substitution ------------------------------------------------
    def find_package(self, name: str) -> str | None:
        return self.workspace.find(name)

    def note_unknown_package(self, name: str) -> None:
        self.sink.warning(
            "package-unknown",
            f"package '{name}' is not in the workspace; $(find {name}) stays symbolic",
            self.location,
        )

    def note_too_complex(self, message: str) -> None:
        self.sink.warning("value-too-complex", message, self.location)

    def env_value(self, name: str) -> Choice[Raw | None]:
        input_ = EnvInput(name)
        self.space.declare_input(input_, self._env_domains(name))
        return self._input_value(input_, None)

    def _input_value(self, input_: ArgInput | EnvInput, unset: object) -> Choice[Any]:
        """An input's value per slot: the literal, ``unset`` when not given, a hole for others."""
        branches: list[tuple[BDD, object]] = []
        for slot, atom in self.space.slot_atoms(input_):
            if slot is UNSET:
                branches.append((atom, unset))
            elif slot is OTHER:
                branches.append((atom, Hole(input_)))
            else:
                branches.append((atom, slot))
        return Choice.of(branches)

    def new_anon(self, anon_id: str) -> Choice[Raw]:
        pc = self.pc
        current = self.anon_count
        # roslaunch's anonymous_name() screens '.', '-' and ':' out of names; the
        # counter stands for its random part (the oracle uses the same convention).
        base = anon_id.replace(".", "_").replace("-", "_").replace(":", "_")
        self.model.anon_ids.add(base)
        names = current.map(lambda n: f"{base}_anon{n + 1}")
        self.anon_count = Choice.of(
            [(c & pc, n + 1) for c, n in current] + [(c & ~pc, n) for c, n in current]
        )
        return names

    # -- inputs --------------------------------------------------------------------------
    def entry_args(
        self,
        file: str,
        names: Sequence[str],
        unset: object,
        declared_in: Mapping[str, str] | None = None,
    ) -> dict[str, Choice[Any]]:
        """Command-line args of the entry file as choices over their input slots, ``unset``
        where one is not given (the dialect's way of saying so). An arg ``declared_in``
        another file (ROS 2: an included file's) takes that file's values, and can be left
        out whatever its default there."""
        args: dict[str, Choice[Any]] = {}
        for name in names:
            input_ = ArgInput(file, name)
            elsewhere = (declared_in or {}).get(name)
            domain = self._domains(elsewhere or file, name)
            if elsewhere is not None and UNSET not in domain:
                domain = (*[s for s in domain if s is not OTHER], UNSET, OTHER)
            self.space.declare_input(input_, domain)
            self.model.inputs[name] = input_
            self.model.domains[name] = domain
            args[name] = self._input_value(input_, unset)
        return args

    # -- conditions and errors -------------------------------------------------------------
    @property
    def location(self) -> Location:
        return self._location

    def at(self, entity: Entity) -> _At[S]:
        """Attribute what happens inside to ``entity``'s location."""
        return _At(self, entity.location)

    def under(self, condition: BDD) -> _Under[S]:
        """Narrow the path condition; entering says whether anything is left."""
        return _Under(self, condition)

    def fail(
        self,
        condition: BDD,
        code: str,
        message: str,
        location: Location | None = None,
        tested: Tested | None = None,
    ) -> None:
        """roslaunch raises here under ``condition`` (within the current path)."""
        if condition == self.space.false:  # most checks find nothing: no conjunction
            return
        where = self.pc & condition
        if where == self.space.false:
            return
        place = location or self.location
        self.model.errors.append(ErrorEvent(where, place, code, message, tested))

    def warn(self, code: str, message: str) -> None:
        self.sink.warning(code, message, self.location)

    def strip(self, choice: Choice[V | Fail], context: str = "") -> Choice[V]:
        """Record the failing branches of ``choice`` as errors; keep the rest."""
        for _condition, leaf in choice.branches:
            if isinstance(leaf, Fail):
                break
        else:
            return choice  # type: ignore[return-value]  # nothing failed: no copy
        good: list[tuple[BDD, V]] = []
        for condition, leaf in choice:
            if isinstance(leaf, Fail):
                message = f"{context}: {leaf.message}" if context else leaf.message
                self.fail(condition, leaf.code, message)
            else:
                good.append((condition, leaf))
        return Choice.of(good, self.space.false)

    def lift(self, name: str, *operands: Choice[Raw], context: str = "") -> Choice[Raw]:
        """A lifted name function (see :mod:`rosvar.interpreter.lifted`), failures recorded.

        Most operands are constants (one branch, true): their result is the function's
        value, a constant too, with no cross product to build nor branches to strip.
        """
        true = self.space.true
        leaves = []
        for operand in operands:
            branches = operand.branches
            if len(branches) != 1 or branches[0][0] is not true:
                return self.strip(lift(name, *operands), context)
            leaves.append(branches[0][1])
        value = apply(name, tuple(leaves))
        if isinstance(value, Fail):
            self.fail(true, value.code, f"{context}: {value.message}" if context else value.message)
            return Choice.empty(self.space)
        return Choice.const(self.space, value)

    def resolve(self, text: str | None, scope: S, context: str = "") -> Choice[Raw] | None:
        if text is not None and "$" not in text and not (self._escapes and "\\" in text):
            return Choice.const(self.space, text)  # most texts are literal: nothing can fail
        value = self.substituter.resolve(text, scope)
        return None if value is None else self.strip(value, context)

    def attr(self, entity: Entity, name: str, scope: S) -> Choice[Raw] | None:
        text = entity.attributes.get(name)
        if text is None:  # most optional attributes are absent: no message to format
            return None
        if "$" not in text and not (self._escapes and "\\" in text):  # nor does a literal
            return Choice.const(self.space, text)
        return self.resolve(text, scope, f"<{entity.tag}> attribute '{name}'")

    def required(self, entity: Entity, name: str, scope: S) -> Choice[Raw] | None:
        value = self.attr(entity, name, scope)  # None exactly when the attribute is absent
        if value is None:
            self.fail(
                self.space.true,
                "attribute-missing",
                f"<{entity.tag}> tag is missing required attribute: '{name}'",
            )
        return value

    def check_attributes(self, entity: Entity, allowed: Sequence[str]) -> None:
        for name in entity.attributes:
            if name not in allowed and name not in ("if", "unless"):
                self.warn("attribute-unknown", f"unknown <{entity.tag}> attribute '{name}'")

    def truth(self, value: Choice[Raw], label: str) -> BDD:
        """Where ``value`` is roslaunch-true (``convert_value(.., 'bool')``); errors elsewhere."""
        true = self.space.false
        invalid = self.space.false
        for condition, leaf in value:
            if isinstance(leaf, str):
                if _truthy(leaf):
                    true |= condition
                elif not _falsy(leaf):
                    self.fail(condition, "bool-invalid", f"{label}: {leaf} is not a 'bool' type")
            else:
                is_true = self.space.predicate("true", leaf)
                is_false = self.space.predicate("false", leaf)
                self.space.constrain(~(is_true & is_false))
                true |= condition & is_true
                invalid |= condition & ~(is_true | is_false)  # the condition conjoined once
        if invalid != self.space.false:
            message = f"{label}: value is not a 'bool' type"
            self.fail(invalid, "bool-invalid", message, tested=Tested(label, value))
        return true

    def condition_of(self, entity: Entity, scope: S) -> BDD:
        """``ifunless_test``: where the tag is processed."""
        attributes = entity.attributes
        if "if" not in attributes and "unless" not in attributes:  # most tags
            return self.space.true
        if_text, unless_text = attributes.get("if"), attributes.get("unless")
        if if_text is not None and unless_text is not None:
            self.fail(
                self.space.true,
                "ifunless-both",
                "cannot set both 'if' and 'unless' on the same tag",
            )
            return self.space.false
        text = if_text if if_text is not None else unless_text
        label = Guard.IF if if_text is not None else Guard.UNLESS
        what = f"<{entity.tag}> attribute '{label}'"
        value = self.resolve(text, scope, what)
        assert value is not None
        value = self._bounded(value, what)
        true = self.truth(value, what)
        if if_text is None:  # unless: processed where the value is false (valid and not true)
            true = value.covered() & ~true & ~self._invalid(value)
        self.model.decisions.append(Decision(self.pc, entity.location, label, true))
        return true

    def _bounded(self, value: Choice[Raw], what: str) -> Choice[Raw]:
        """``value``, or where it holds more terms than a test may make predicates of
        (:data:`MAX_TESTED_TERMS`), one unknown value that a configuration computes."""
        terms = sum(not isinstance(leaf, str) for _condition, leaf in value.branches)
        if terms <= MAX_TESTED_TERMS:
            return value
        self.note_too_complex(
            f"{what} is not computed: it tests {terms} values not known yet, "
            f"over {MAX_TESTED_TERMS}"
        )
        return Choice.const(self.space, too_complex(what, [value], first))

    def _invalid(self, value: Choice[Raw]) -> BDD:
        invalid = self.space.false
        for condition, leaf in value:
            if isinstance(leaf, str):
                if not (_truthy(leaf) or _falsy(leaf)):
                    invalid |= condition
            else:
                neither = self.space.predicate("true", leaf) | self.space.predicate("false", leaf)
                invalid |= condition & ~neither
        return invalid

    # -- walking ------------------------------------------------------------------------
    def walk(self, children: Sequence[Entity], scope: S) -> None:
        if not children:
            return
        if self.depth >= MAX_NESTING:
            self.sink.error(
                "nesting-too-deep",
                f"elements nested more than {MAX_NESTING} levels deep (includes counted): "
                "the inner ones are not interpreted",
                children[0].location,
            )
            return
        saved = self._location
        tags = self.tags
        self.depth += 1
        if self.depth > self.deepest:
            self.deepest = self.depth
        try:
            for child in children:
                handler = tags.get(child.tag)
                self._location = child.location
                if handler is None:
                    self.warn("tag-unknown", f"unrecognized tag <{child.tag}>")
                else:
                    handler(self, child, scope)
        finally:
            self.depth -= 1
            self._location = saved

    def load(self, path: str) -> Entity | None:
        """Parse a launch file (cached) if the workspace's read gate lets it through (after
        symlinks: a link to a file outside is not read), from the source an install puts
        at ``path`` (:meth:`~rosvar.workspace.packages.Workspace.installed`). A refusal is an
        error naming the path, a parse problem one in the words of the file's format; both
        at the including tag, or for the entry file where its own diagnostic places the
        problem. A dependency's file that cannot be read is a warning at the including tag,
        the include not followed (``include-unread``), as roslaunch's include of a file
        rosvar may not read."""
        confinement = self.workspace.confinement()
        try:
            confinement.check(path)
        except FileRefused as refused:
            self.fail(
                self.space.true,
                refused.code,
                f"launch file {path}: {refused.message}",
                self._placed(path, []),
            )
            return None
        result = self.files.load(confinement.source(path))
        messages = "; ".join(d.message for d in result.diagnostics) or "unreadable"
        if result.root is None and self.location.line > 0 and self.workspace.of_dependency(path):
            # the installed dependency has the file (a build may make it): for the user the
            # include is not followed, as one rosvar may not read, and the launch goes on
            self.warn(
                INCLUDE_UNREAD,
                f"included file {path} of a dependency is not read ({messages}): what it "
                "launches is not known",
            )
            return None
        for diagnostic in result.diagnostics:
            self.sink.add(diagnostic)
        if result.root is None:
            self.unread_installs(path)
            invalid = INVALID_FILE[self.workspace.ros_version, self.workspace.launch_format(path)]
            self.fail(
                self.space.true,
                "launch-invalid",
                f"{invalid} in {path}: {messages}",
                self._placed(path, [d.location for d in result.diagnostics]),
            )
            return None
        if path not in self.model.files:
            self.model.files.append(path)
        return result.root

    def unread_installs(self, path: str) -> None:
        """Tell the install rules rosvar could not read of the package whose share folder
        ``path``, a file not found, may be in (one of them may put it there)."""
        share = self.workspace.share_of(path)
        if share is not None:
            self.sink.extend(list(share[1].diagnostics))

    def _placed(self, path: str, found: list[Location]) -> Location:
        if self.location.line > 0:  # an include
            return self.location
        return next((where for where in found if where.line > 0), Location(path, 1, 1))


class _At(Generic[S]):
    """The context of :meth:`Interpretation.at` (a class: this runs for every tag, and
    generator-based context managers cost several times more)."""

    __slots__ = ("_it", "_location", "_saved")

    def __init__(self, it: Interpretation[S], location: Location) -> None:
        self._it = it
        self._location = location

    def __enter__(self) -> None:
        self._saved = self._it._location
        self._it._location = self._location

    def __exit__(self, *_exc: object) -> None:
        self._it._location = self._saved


class _Under(Generic[S]):
    """The context of :meth:`Interpretation.under` (a class, as :class:`_At`)."""

    __slots__ = ("_condition", "_it", "_saved")

    def __init__(self, it: Interpretation[S], condition: BDD) -> None:
        self._it = it
        self._condition = condition

    def __enter__(self) -> bool:
        it = self._it
        self._saved = it.pc
        if self._condition is not it.space.true:  # most tags have no if/unless
            it.pc = self._saved & self._condition
        return bool(it.pc != it.space.false)

    def __exit__(self, *_exc: object) -> None:
        self._it.pc = self._saved


def split(interpretation: Interpretation[S], choice: Choice[V]) -> Sequence[tuple[BDD, V]]:
    """The branches of ``choice`` that are possible on the current path.

    Most paths are true, where every branch is possible (a choice keeps no false
    branch), and most choices are constants, possible wherever the path is: neither
    needs a conjunction. (A sequence, not a generator: callers restore the path before
    the next branch, so nothing is gained by testing branches late.)
    """
    space = interpretation.space
    pc = interpretation.pc
    if pc == space.true:
        return choice.branches
    false = space.false
    return [
        branch
        for branch in choice.branches
        if (pc if branch[0] is space.true else pc & branch[0]) != false
    ]
