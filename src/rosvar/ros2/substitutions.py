"""ROS 2 substitutions (``$(var x)``, ``$(find-pkg-share p)``, ``$(eval ...)``, ...).

The text is parsed as launch's frontend grammar does (substitutions nest; arguments are
split at whitespace, quoted with ``'``/``"``; a backslash escapes the next character),
then every substitution is computed over all configurations with :func:`combine`.
Handlers live in :data:`HANDLERS`, keyed by name: one for each substitution of the launch
API's registry (:mod:`rosvar.ros2.api.substitutions`) rosvar computes, and rosvar's own.
"""

from __future__ import annotations

import builtins
import functools
import math
import os
import posixpath
import re
import shlex
import weakref
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import cast

import yaml

from rosvar.bounded_yaml import check_limits
from rosvar.files import FileCode, FileRefused, python_text, read_file
from rosvar.frontends.xml import Snapshot
from rosvar.interpreter.interpretation import Interpretation
from rosvar.interpreter.model import Raw
from rosvar.interpreter.safe_eval import (
    EvalEnvironment,
    EvalFailed,
    EvalRefused,
    evaluate,
    referenced_names,
)
from rosvar.interpreter.substitution_args import (
    MAX_COMBINATIONS,
    MAX_TERM_DEPTH,
    MAX_VALUE_SIZE,
    ValueBudget,
    too_complex,
)
from rosvar.logic.bdd import BDD
from rosvar.logic.choice import Choice, Fail, combine_bind, crossed, ite
from rosvar.logic.conditions import ConditionSpace
from rosvar.logic.given_up import terms_merged
from rosvar.logic.terms import (
    Apply,
    Hole,
    PackageTable,
    TermError,
    TermFunction,
    concat,
    register,
)
from rosvar.memo import EntryMemo, Memo
from rosvar.ros2.api.substitutions import SUBSTITUTIONS
from rosvar.ros2.api.unmodelled import UNMODELLED
from rosvar.ros2.boolean_eval import BooleanExpression, boolean_expression
from rosvar.ros2.context import Context, optional, unset_as_given
from rosvar.ros2.frontends.python.text import (
    CONFIGURATION_EQUALS,
    EMPTY,
    NODE_NAME,
    PATH_JOIN,
    PATH_PART,
    PATH_PARTS,
    PYTHON_STRING,
    PYTHON_YAML,
    UNKNOWN,
    WRITTEN_FILE,
)
from rosvar.ros2.nodes import ROS2_NODES
from rosvar.workspace import Workspace

Value = Raw | Fail
UNSUPPORTED = "substitution-unsupported"
"""The code of a launch substitution rosvar does not compute (reported with the reason)."""


class SubstitutionSyntaxError(Exception):
    """The text is not in launch's substitution grammar."""


@dataclass(frozen=True)
class Call:
    """``$(name arg ...)``: each argument a sequence of text and nested calls."""

    name: str
    arguments: tuple[Template, ...]


Template = tuple[str | Call, ...]


class SubstitutionTooDeep(SubstitutionSyntaxError):
    """Substitutions nested deeper than any value may be (the parser recurses)."""


class _Parser:
    def __init__(self, text: str) -> None:
        self.text = text
        self.at = 0
        self.depth = 0

    def template(self, stop: str = "") -> Template:
        parts: list[str | Call] = []
        buffer: list[str] = []
        text = self.text
        while self.at < len(text):
            ch = text[self.at]
            if stop and ch in stop:
                break
            if ch == "\\" and self.at + 1 < len(text):
                buffer.append(text[self.at + 1])
                self.at += 2
            elif text.startswith("$(", self.at):
                if buffer:
                    parts.append("".join(buffer))
                    buffer.clear()
                parts.append(self.call())
            else:
                buffer.append(ch)
                self.at += 1
        if buffer:
            parts.append("".join(buffer))
        return tuple(parts)

    def call(self) -> Call:
        if self.depth >= MAX_TERM_DEPTH:
            raise SubstitutionTooDeep(
                f"substitutions nested more than {MAX_TERM_DEPTH} levels deep are not read"
            )
        self.depth += 1
        try:
            return self._call()
        finally:
            self.depth -= 1

    def _call(self) -> Call:
        self.at += 2
        start = self.at
        text = self.text
        while self.at < len(text) and (text[self.at].isalnum() or text[self.at] in "-_"):
            self.at += 1
        name = text[start : self.at]
        if not name:
            raise SubstitutionSyntaxError(f"a substitution has no name in [{text}]")
        arguments: list[Template] = []
        while True:
            while self.at < len(text) and text[self.at].isspace():
                self.at += 1
            if self.at >= len(text):
                raise SubstitutionSyntaxError(f"unclosed substitution in [{text}]")
            if text[self.at] == ")":
                self.at += 1
                return Call(name, tuple(arguments))
            arguments.append(self.argument())

    def argument(self) -> Template:
        parts: list[str | Call] = []
        text = self.text
        while self.at < len(text) and not text[self.at].isspace() and text[self.at] != ")":
            ch = text[self.at]
            if ch in "'\"":
                self.at += 1
                parts.extend(self.template(ch))
                if self.at >= len(text):
                    raise SubstitutionSyntaxError(f"unclosed quote in [{text}]")
                self.at += 1
            else:
                parts.extend(self.template(" \t\n)'\""))
        return tuple(parts)


@functools.lru_cache(maxsize=16384)
def parse(text: str) -> Template:
    """``text`` as a template; raises :class:`SubstitutionSyntaxError`."""
    return _Parser(text).template()


def _invalid(error: SubstitutionSyntaxError) -> Fail:
    """A text outside the grammar fails as launch's parser does; one over the nesting limit
    is rosvar's limit on hostile input."""
    code = "nesting-too-deep" if isinstance(error, SubstitutionTooDeep) else "substitution-invalid"
    return Fail(str(error), code)


def command_line(text: str) -> list[Template]:
    """``text`` as a command line's arguments, split as launch's ``_parse_cmdline`` does:
    literal text at whitespace (``shlex``), substitution values never (``$(var x)`` is one
    argument whatever its value). Raises :class:`SubstitutionSyntaxError`, also for an
    unclosed quote in the literal text."""
    arguments: list[Template] = []
    current: list[str | Call] = []

    def close() -> None:
        nonlocal current
        arguments.append(tuple(current))
        current = []

    for part in parse(text):
        if not isinstance(part, str):
            current.append(part)
            continue
        try:
            tokens = shlex.split(part)
        except ValueError as error:
            raise SubstitutionSyntaxError(f"{error} in [{text}]") from None
        if not tokens:  # only whitespace: it separates two substitutions
            close()
            continue
        if part[0].isspace() and current:
            close()
        current.append(tokens[0])
        if len(tokens) > 1:
            close()
            arguments.extend((token,) for token in tokens[1:-1])
            current.append(tokens[-1])
        if part[-1].isspace():
            close()
    if current:
        close()
    return arguments


Handler = Callable[[Interpretation[Context], Context, list[Raw]], Choice[Value]]
HANDLERS: dict[str, Handler] = {}
OWN = frozenset(
    {
        PATH_JOIN,
        PATH_PART,
        PYTHON_STRING,
        PYTHON_YAML,
        UNKNOWN,
        CONFIGURATION_EQUALS,
        EMPTY,
        NODE_NAME,
        WRITTEN_FILE,
    }
)
"""rosvar's own substitutions, which the Python frontend writes (no launch API name)."""


EMPTY_ARGUMENT: dict[str, str] = {}
"""The text an empty quoted argument (``''``) is to a substitution, where not empty: launch's
grammar gives it as an empty list, which some substitutions turn into text (``[]``)."""


MERGED_TERMS: dict[str, str] = {}
"""Substitutions whose values not known yet are one value (the display given), which a
configuration computes (:func:`~rosvar.logic.given_up.terms_merged`): values nothing reads
before they are concrete, such as a whole file."""


def substitution(name: str, merged_terms: str | None = None) -> Callable[[Handler], Handler]:
    """Register the handler of ``$(name ...)``; it gets the arguments' texts. A name the
    launch API's registry does not know, or a second handler, is refused. ``merged_terms``:
    the display of the one value its terms make (:data:`MERGED_TERMS`)."""
    if name not in SUBSTITUTIONS.by_name and name not in OWN:
        raise ValueError(f"$({name}) is no substitution of the launch API's registry")
    if name in HANDLERS:
        raise ValueError(f"$({name}) has two handlers")

    def register(handler: Handler) -> Handler:
        HANDLERS[name] = handler
        if merged_terms is not None:
            MERGED_TERMS[name] = merged_terms
        return handler

    return register


Computation = Callable[[list[Raw]], Value]
COMPUTED: dict[str, Computation] = {}
"""The substitutions whose value follows from their arguments' values alone (no launch
configuration, no file, no workspace): a value given up over the work limits is computed
again from one leaf of each argument in a configuration (:mod:`rosvar.logic.given_up`)."""


def computed(name: str) -> Callable[[Computation], Computation]:
    """Register ``$(name ...)`` as a :data:`COMPUTED` substitution: its handler too."""

    def register(computation: Computation) -> Computation:
        COMPUTED[name] = computation
        substitution(name)(lambda host, _context, args: Choice.const(host.space, computation(args)))
        return computation

    return register


PURE = frozenset(
    {
        "var",
        "eval",
        "find-pkg-share",
        "find-pkg-prefix",
        "exec-in-pkg",
        "dirname",
        "filename",
        PATH_JOIN,
        PATH_PART,
        UNKNOWN,
    }
)
"""Substitutions whose value follows from their arguments, the launch configurations they
name and the file's name (the workspace is the space's): a text made only of them is
resolved once per distinct value of what it reads (:meth:`Ros2Substituter.resolve`)."""
RESOLVED_CAPACITY = 20_000
"""Resolved texts kept per condition space (:class:`~rosvar.memo.Memo`)."""
RESOLVED_BRANCHES = 16
"""Only values of at most this many branches are kept: larger ones are cross products of
values that vary a lot, which no other read met again (docs/performance.md)."""
_resolved: weakref.WeakKeyDictionary[
    ConditionSpace, EntryMemo[object, tuple[Choice[Value], frozenset[str], int]]
] = weakref.WeakKeyDictionary()
"""Each value with the unset names it read and the combinations it spent of the file's
budget (a reuse spends them too, so that the budget is the same whatever was resolved
before; a value that met a limit is not kept)."""


def forget_resolved(space: ConditionSpace, _files: Snapshot) -> None:
    """Drop the texts resolved for the entry file done (a ``Release`` of
    :mod:`~rosvar.interpreter.semantics`) over values some input steers, which no other
    entry file reads; those over constants stay. A text resolved again over the same
    values makes the same value, give-ups included
    (:class:`~rosvar.logic.given_up.GivenUp`), hence the same predicates."""
    memo = _resolved.get(space)
    if memo is not None:
        memo.release()


@dataclass(frozen=True)
class Reads:
    """What a text made of :data:`PURE` substitutions reads besides its own text."""

    names: tuple[str, ...]  # launch configurations, by ``$(var NAME)`` with a literal name
    filename: bool  # ``$(dirname)`` or ``$(filename)``


@functools.lru_cache(maxsize=16384)
def _reads(text: str) -> Reads | None:
    """What ``text`` (already parsed) reads, or None where a substitution may do more than
    read: a name that is itself substituted, ``$(anon)`` (sets a configuration), ``$(env)``
    (declares an input), ``$(command)``, ``$(find-exec)`` (warn where they are)."""
    names: list[str] = []
    filename = False
    pending: list[Template] = [parse(text)]
    while pending:
        for part in pending.pop():
            if isinstance(part, str):
                continue
            if part.name not in PURE:
                return None
            if part.name == "var":
                name = part.arguments[0] if part.arguments else ()
                if len(name) != 1 or not isinstance(name[0], str):
                    return None
                if name[0] not in names:
                    names.append(name[0])
            filename = filename or part.name in ("dirname", "filename")
            pending.extend(part.arguments)
    return Reads(tuple(names), filename)


def _content(value: Choice[Raw | None] | None) -> object:
    """A configuration's value as a key: equal keys, the same branches in the same order."""
    return None if value is None else value.key()


class Ros2Substituter:
    """Resolves attribute text in a :class:`Context`, for all configurations at once."""

    escapes = True

    def __init__(self, host: Interpretation[Context]) -> None:
        self.host = host
        self.space = host.space
        # the host's method, not one of this object: a cycle through the budget would hold
        # the analysis's conditions until a collection freed them after their manager
        self.budget = ValueBudget(host.space, host.note_too_complex)

    def resolve(self, text: str | None, context: Context) -> Choice[Value] | None:
        if text is None:
            return None
        try:
            template = parse(text)
        except SubstitutionSyntaxError as error:
            return Choice.const(self.space, _invalid(error))
        reads = _reads(text)
        if reads is None:
            return self.template(template, context, text)
        key = (
            text,
            context.filename if reads.filename else None,
            tuple(_content(context.get(name)) for name in reads.names),
        )
        memo = _resolved.get(self.space)
        if memo is None:
            memo = _resolved[self.space] = EntryMemo(RESOLVED_CAPACITY)
        known = memo.get(key)
        if known is not None and self.budget.spares(known[2]):
            self.budget.combinations += known[2]
            context.unset_reads |= known[1]
            return known[0]
        unset_reads, context.unset_reads = context.unset_reads, set()
        notes, spent = self.budget.notes, self.budget.combinations
        try:
            value = self.template(template, context, text)
            if len(value.branches) <= RESOLVED_BRANCHES and self.budget.notes == notes:
                spent = self.budget.combinations - spent
                entry = (value, frozenset(context.unset_reads), spent)
                memo.keep(key, entry, self.space.varies(key))
        finally:
            unset_reads |= context.unset_reads
            context.unset_reads = unset_reads
        return value

    def template(self, template: Template, context: Context, text: str) -> Choice[Value]:
        """The value of ``template``, a part of ``text`` (which messages name)."""
        return self._joined(self._parts(template, context, text), text)

    def _parts(self, template: Template, context: Context, text: str) -> list[Choice[Value]]:
        return [self._part(part, context, text) for part in template]

    def _joined(self, parts: list[Choice[Value]], text: str) -> Choice[Value]:
        if not parts:
            return Choice.const(self.space, "")
        return self.budget.join(text, parts)

    def command_line(self, text: str, context: Context) -> Choice[Value]:
        """A command line's arguments (:func:`command_line`), each resolved, as one
        ``shlex``-quoted text that :func:`shlex.split` gives back."""
        try:
            arguments = command_line(text)
        except SubstitutionSyntaxError as error:
            return Choice.const(self.space, _invalid(error))
        if not arguments:
            return Choice.const(self.space, "")
        words = [self.template(a, context, text) for a in arguments]
        return self.budget.join(text, words, _quoted)

    def _part(self, part: str | Call, context: Context, text: str) -> Choice[Value]:
        if isinstance(part, str):
            return Choice.const(self.space, part)
        handler = HANDLERS.get(part.name)
        if handler is None:
            reported = UNMODELLED.by_name.get(part.name)
            if reported is not None:
                return Choice.const(
                    self.space, Fail(f"{reported.why()} is not modelled", UNSUPPORTED)
                )
            return Choice.const(
                self.space, Fail(f"unknown substitution '{part.name}'", "substitution-unknown")
            )
        empty = EMPTY_ARGUMENT.get(part.name, "")
        arguments: list[Choice[Value]] = []
        for argument in part.arguments:
            if not argument:
                arguments.append(Choice.const(self.space, empty))
                continue
            parts = self._parts(argument, context, text)
            if part.name == "eval" and len(part.arguments) == 1:
                condition = self._condition(argument, parts, text)
                if condition is not None:
                    return condition
            arguments.append(self._joined(parts, text))
        if not arguments:
            return handler(self.host, context, [])
        computation = COMPUTED.get(part.name)
        again = None if computation is None else functools.partial(_computed, computation)
        if not self.budget.affordable(text, arguments):
            return self.budget.given_up(text, arguments, again)
        value = combine_bind(arguments, lambda leaves: _call(handler, self.host, context, leaves))
        merged = MERGED_TERMS.get(part.name)
        return value if merged is None else terms_merged(value, text, f"⟨{merged}⟩")

    def _condition(
        self, template: Template, parts: list[Choice[Value]], text: str
    ) -> Choice[Value] | None:
        """``$(eval template)`` (``parts``: its parts' values) computed as the condition
        where it is true (:mod:`rosvar.ros2.boolean_eval`); None where it is to be crossed.
        Of strings alone, with the budget and notes that crossing them would have spent and
        made, in crossing's order; with terms, as :meth:`_over_terms`."""
        expression = boolean_expression(template, EVAL_NAMESPACES)
        if expression is None:
            return None
        values = [v for v, part in zip(parts, template, strict=True) if isinstance(part, Call)]
        if not expression.accepts(values):
            return None
        if any(isinstance(leaf, Hole | Apply) for value in values for leaf in value.values()):
            return self._over_terms(expression, template, values, text)
        if any(isinstance(leaf, Fail) for value in values for leaf in value.values()):
            return None  # crossed: the failures in crossing's order
        product = math.prod(len(value.branches) for value in values)
        if product <= 1 or not self.budget.fits(product):
            return None  # nothing to cross, or crossing warns or fails somewhere
        if product > MAX_COMBINATIONS or expression.longest(values) > MAX_VALUE_SIZE:
            return None
        count, first = _combinations(self.space, values, product)
        if count == 0:
            self.budget.affordable_count(text, product)
            return Choice.empty(self.space)
        leading = _evaluation(_text(template, cast("list[str]", first)))
        if leading not in (TRUE, FALSE):
            return None
        self.budget.affordable_count(text, product)  # the text's combinations
        if not self.budget.affordable_count(text, count):  # the evaluation of each text
            again = functools.partial(_evaluated_with, template)
            return self.budget.given_up(text, values, again)
        holds = expression.condition(self.space, cast("list[Choice[Raw]]", values))
        covered = self.space.true
        for value in values:
            covered &= value.covered()
        where = {TRUE: covered & holds, FALSE: covered & ~holds}
        other = FALSE if leading == TRUE else TRUE
        branches: list[tuple[BDD, Value]] = [(where[leading], leading)]
        if where[other] != self.space.false:
            branches.append((where[other], other))
        return Choice(tuple(branches), self.space.false)

    def _over_terms(
        self,
        expression: BooleanExpression,
        template: Template,
        values: list[Choice[Value]],
        text: str,
    ) -> Choice[Value]:
        """The expression over values some of which are terms: ``True`` and ``False`` where
        every term keeps its literal, the first failing substitution's failure where one
        fails (as crossing gives it), and one unknown value where a term may leave its
        literal, computed in a configuration. Nothing is crossed: the work grows with the
        terms tested and the size of the conditions, which :meth:`ValueBudget.affords_tests`
        and :meth:`ValueBudget.affords_conditions` bound."""
        computed = functools.partial(_evaluated_with, template)
        if not self.budget.affords_tests(text, expression.tested(values)):
            return Choice.const(self.space, too_complex(text, values, computed))
        false = self.space.false
        covered = self.space.true
        for value in values:
            covered &= value.covered()
        branches: list[tuple[BDD, Value]] = []
        failed = false
        for value in values:  # crossing fails with the first failing substitution
            failing = false
            for condition, leaf in value.branches:
                if isinstance(leaf, Fail):
                    branches.append((covered & ~failed & condition, leaf))
                    failing |= condition
            failed |= failing
        escapes = expression.escapes(self.space, values)
        holds = expression.condition(self.space, values)
        kept = covered & ~failed & ~escapes
        branches += [(kept & holds, TRUE), (kept & ~holds, FALSE)]
        if escapes != false:  # one unknown value, which a configuration computes
            unknown = too_complex(text, values, computed)
            branches.append((covered & ~failed & escapes, unknown))
        if not self.budget.affords_conditions(text, (branch[0] for branch in branches)):
            return Choice.const(self.space, too_complex(text, values, computed))
        return Choice.of(branches, false)


TRUE, FALSE = str(True), str(False)


def _combinations(
    space: ConditionSpace, values: Sequence[Choice[Value]], product: int
) -> tuple[int, list[Value]]:
    """How many combinations of one branch of each of ``values`` are possible, and the first
    (that of a nested loop over them, first outermost), as :func:`crossed` gives them: all
    of them and the first branches where no two values' conditions share a variable."""
    seen: set[str] = set()
    for value in values:
        for condition, _leaf in value.branches:
            if condition.var is None:
                continue
            support = space.support(condition)
            if not seen.isdisjoint(support):
                combinations = crossed(values)
                return len(combinations), combinations[0][1] if combinations else []
        for condition, _leaf in value.branches:
            seen |= space.support(condition) if condition.var is not None else set()
    return product, [value.branches[0][1] for value in values]


def _computed(computation: Computation, leaves: Sequence[Value]) -> Value:
    """A :data:`COMPUTED` substitution of one leaf of each argument (the first failing one
    fails it, as :func:`_call`)."""
    for leaf in leaves:
        if isinstance(leaf, Fail):
            return leaf
    return computation(list(leaves))  # type: ignore[arg-type]  # Fails returned


def _text(template: Template, leaves: Sequence[str]) -> str:
    """The text ``template`` makes with ``leaves`` for its substitutions, in order."""
    substituted = iter(leaves)
    return "".join(part if isinstance(part, str) else next(substituted) for part in template)


def _call(
    handler: Handler, host: Interpretation[Context], context: Context, leaves: Sequence[Value]
) -> Choice[Value]:
    for leaf in leaves:
        if isinstance(leaf, Fail):
            return Choice.const(host.space, leaf)
    return handler(host, context, list(leaves))  # type: ignore[arg-type]  # Fails returned


def _quoted(leaves: Sequence[Raw]) -> list[Raw]:
    """Command-line words joined by spaces, each quoted: a word known only in a
    configuration (a term) is quoted there, when its text is (:data:`SHELL_WORD`), and
    shown as it is."""
    words: list[Raw] = []
    for leaf in leaves:
        word = shlex.quote(leaf) if isinstance(leaf, str) else Apply(SHELL_WORD, (leaf,), str(leaf))
        words += [" ", word]
    return words[1:]


SHELL_WORD = "rosvar-shell-word"
"""The term of a command-line word known only in a configuration: its text quoted as
:func:`shlex.quote` quotes a known word, so that a value with spaces, even one given up
(:mod:`rosvar.logic.given_up`), stays one word when the command line is split."""

register(SHELL_WORD, lambda _host, word: shlex.quote(word))


def _fail(host: Interpretation[Context], message: str, code: str) -> Choice[Value]:
    return Choice.const(host.space, Fail(message, code))


@substitution("var")
def _var(host: Interpretation[Context], context: Context, args: list[Raw]) -> Choice[Value]:
    if not 1 <= len(args) <= 2 or not isinstance(args[0], str):
        return _fail(host, "$(var) takes a name and an optional default", "substitution-invalid")
    name = args[0]
    missing: Value = (
        args[1]
        if len(args) == 2
        else Fail(f"launch configuration '{name}' does not exist", "var-undefined")
    )
    return configuration(host, context, name).map(lambda leaf: missing if leaf is None else leaf)


def configuration(host: Interpretation[Context], context: Context, name: str) -> Choice[Raw | None]:
    """The launch configuration ``name`` (None where it is undefined, which is recorded:
    :attr:`Context.unset_reads`, unless only the command line leaves it so)."""
    value = context.get(name)
    if value is None:
        context.unset_reads.add(name)
        return Choice.const(host.space, None)
    if any(leaf is None for _condition, leaf in value.branches) and not unset_as_given(
        host.space, host.model.file, name, value.where(_unset)
    ):
        context.unset_reads.add(name)
    return value


def _unset(leaf: Raw | None) -> bool:
    return leaf is None


@substitution("env")
def _env(host: Interpretation[Context], context: Context, args: list[Raw]) -> Choice[Value]:
    if not 1 <= len(args) <= 2 or not isinstance(args[0], str):
        return _fail(host, "$(env) takes one or two arguments", "substitution-invalid")
    name, default = args[0], args[1] if len(args) == 2 else None
    value = context.env.get(name)
    if value is None:
        value = host.env_value(name)

    def pick(leaf: Raw | None) -> Value:
        if leaf is not None:
            return leaf
        if default is not None:
            return default
        return Fail(f"environment variable '{name}' does not exist", "env-undefined")

    return value.map(pick)


WorkspaceComputation = Callable[["Workspace", list[str]], str | Fail]
"""A substitution's value from its arguments' texts and the workspace (a package's folder,
a file's text)."""


def _of_workspace(name: str, arity: int, usage: str) -> Callable[[WorkspaceComputation], None]:
    """Register ``$(name ...)``, of ``arity`` arguments, computed from the workspace: with
    an argument known only in a configuration (an argument's value, one given up: a term)
    it is a term that the configuration's resolution computes the same way."""
    term = f"rosvar-{name}"

    def register_computation(compute: WorkspaceComputation) -> None:
        def handler(
            host: Interpretation[Context], context: Context, args: list[Raw]
        ) -> Choice[Value]:
            if len(args) != arity:
                return _fail(host, f"$({name}) takes {usage}", "substitution-invalid")
            known = [arg for arg in args if isinstance(arg, str)]
            if len(known) < arity:
                shown = " ".join(str(arg) for arg in args)
                return Choice.const(host.space, Apply(term, tuple(args), f"$({name} {shown})"))
            return Choice.const(host.space, compute(host.workspace, known))

        def evaluated(host: object, *args: str) -> str:
            workspace = host.workspace if isinstance(host, PackageTable) else None
            if workspace is None:
                raise TermError(f"$({name}) is not known without the workspace")
            value = compute(workspace, list(args))
            if isinstance(value, Fail):
                raise TermError(value.message, value.code)
            return value

        substitution(name)(handler)
        register(term, evaluated)

    return register_computation


def _not_found(package: str) -> Fail:
    return Fail(f"package '{package}' not found", "package-not-found")


@_of_workspace("find-pkg-share", 1, "one argument")
def _find_share(workspace: Workspace, args: list[str]) -> str | Fail:
    """The package's share folder: a source package's own folder stands for it."""
    return workspace.find(args[0]) or _not_found(args[0])


@_of_workspace("find-pkg-prefix", 1, "one argument")
def _find_prefix(workspace: Workspace, args: list[str]) -> str | Fail:
    return _prefix(workspace, args[0]) or _not_found(args[0])


def _prefix(workspace: Workspace, package: str) -> str | None:
    """An installed package's install prefix; a source package's folder stands for it, as for
    its share folder (its ``lib/`` is what ``colcon build`` would install)."""
    return workspace.find_prefix(package) or workspace.find(package)


@_of_workspace("exec-in-pkg", 2, "an executable and a package")
def _exec_in_pkg(workspace: Workspace, args: list[str]) -> str | Fail:
    """``lib/PACKAGE/EXECUTABLE`` below the package's prefix: launch also checks that the
    built executable is there, which a source workspace cannot show, so that is left to
    the install."""
    executable, package = args
    prefix = _prefix(workspace, package)
    if prefix is None:
        return _not_found(package)
    return posixpath.join(prefix, "lib", package, executable)


@substitution("dirname")
def _dirname(host: Interpretation[Context], context: Context, args: list[Raw]) -> Choice[Value]:
    return Choice.const(host.space, os.path.dirname(os.path.abspath(context.filename)))


@substitution("filename")
def _filename(host: Interpretation[Context], context: Context, args: list[Raw]) -> Choice[Value]:
    return Choice.const(host.space, os.path.abspath(context.filename))


@_of_workspace("file-content", 1, "a path")
def _file_content(workspace: Workspace, args: list[str]) -> str | Fail:
    """The text of the file, read through the workspace's gate (launch reads it when the
    substitution is performed; a file outside the workspace is refused, never opened)."""
    path = args[0]
    if not os.path.isabs(path):
        return Fail(
            f"$(file-content {path}): a relative path reads the launching directory, not known",
            UNSUPPORTED,
        )
    try:
        return python_text(read_file(path, workspace.confinement()))
    except FileRefused as error:
        return Fail(f"$(file-content {path}): {error}", error.code)
    except (OSError, UnicodeDecodeError) as error:
        return Fail(f"$(file-content {path}): file not readable: {error}", FileCode.UNREADABLE)


@substitution("command")
def _command(host: Interpretation[Context], context: Context, args: list[Raw]) -> Choice[Value]:
    """Never run: the value is the text a dry run shows, ``$(command TEXT)`` (as the oracle
    records it), so the launch around it is analysed; a warning says it is not known."""
    if not 1 <= len(args) <= 2:
        return _fail(
            host, "$(command) takes a command and an optional on_stderr", "command-invalid"
        )
    host.warn("command-not-run", "$(command) is never run by rosvar: its output is not known")
    return Choice.const(host.space, concat(["$(command ", args[0], ")"]))


@substitution("find-exec")
def _find_exec(host: Interpretation[Context], context: Context, args: list[Raw]) -> Choice[Value]:
    """The executable's path on the host's ``PATH``, which rosvar does not search (the
    PATH of the machine that launches is not the analysing one's): the value stays the
    text ``$(find-exec NAME)``, and a warning says so."""
    if len(args) != 1:
        return _fail(host, "$(find-exec) takes one argument", "substitution-invalid")
    host.warn(
        "find-exec-host",
        "$(find-exec) is the path of an executable on the launching host's PATH: not searched",
    )
    return Choice.const(host.space, concat(["$(find-exec ", args[0], ")"]))


@computed(PATH_JOIN)
def _path_join(args: list[Raw]) -> Value:
    """``PathJoinSubstitution`` (the Python frontend's): ``os.path.join`` of the values.
    With a value known only in a configuration (an argument's, one given up: a term), the
    join is a term that a configuration computes: the term may be absolute (replacing
    what is before it), end in ``/`` or be empty. The values before the last absolute
    known one never count, and adjacent known ones are joined now."""
    last = max(
        (i for i, arg in enumerate(args) if isinstance(arg, str) and arg[:1] == "/"), default=0
    )
    operands: list[Raw] = []
    for arg in args[last:]:
        if isinstance(arg, str) and operands and isinstance(operands[-1], str):
            operands[-1] = posixpath.join(operands[-1], arg)
        else:
            operands.append(arg)
    if len(operands) == 1:
        return operands[0]
    return Apply(PATH_JOIN, tuple(operands)) if operands else ""


register(PATH_JOIN, lambda _host, *paths: posixpath.join(*paths))


@computed(PATH_PART)
def _path_part(args: list[Raw]) -> Value:
    """``os.path.dirname`` or ``basename`` (the first argument) of a path (the Python
    frontend's); of a path known only in a configuration, a term it computes."""
    if len(args) != 2 or args[0] not in PATH_PARTS:
        return Fail(f"$({PATH_PART}) takes dirname or basename and a path", "substitution-invalid")
    part, path = args
    if isinstance(path, str):
        return PATH_PARTS[str(part)](path)
    return Apply(PATH_PART, (part, path), f"os.path.{part}({path})")


register(PATH_PART, lambda _host, part, path: PATH_PARTS[part](path))


@computed(PYTHON_STRING)
def _python_string(args: list[Raw]) -> Value:
    """The Python frontend's launch-time string inside an expression: its ``repr``; a value
    known only once the command line gives it (a term) is a term too."""
    if len(args) != 1:
        return Fail(f"$({PYTHON_STRING}) takes one argument", "substitution-invalid")
    if isinstance(args[0], str):
        return repr(args[0])
    return Apply(PYTHON_STRING, (args[0],), f"repr({args[0]})")


register(PYTHON_STRING, lambda _host, value: repr(value))


@computed(PYTHON_YAML)
def _python_yaml(args: list[Raw]) -> Value:
    """The Python frontend's ``yaml.load`` of a launch-time string inside an expression: the
    loaded value as a Python literal; a text that is no YAML of plain values fails, as the
    file's ``yaml.load`` raises (or gives what the expression cannot use)."""
    if len(args) != 1:
        return Fail(f"$({PYTHON_YAML}) takes one argument", "substitution-invalid")
    if isinstance(args[0], str):
        return _yaml_literal(args[0])
    return Apply(PYTHON_YAML, (args[0],), f"yaml({args[0]})")


def _yaml_literal(text: str) -> str | Fail:
    try:
        check_limits(text)
        loaded = yaml.load(text, Loader=getattr(yaml, "CSafeLoader", yaml.SafeLoader))
    except yaml.YAMLError as error:
        return Fail(f"yaml.load() of {text!r}: {error}", "eval-failed")
    if not _plain(loaded):
        return Fail(f"yaml.load() of {text!r} gives other than plain values", "eval-failed")
    return repr(loaded)


def _plain(value: object) -> bool:
    """Whether ``value`` is made of what a Python literal writes back (no dates, bytes)."""
    if value is None or isinstance(value, str | bool | int | float):
        return True
    if isinstance(value, list):
        return all(_plain(item) for item in value)
    if isinstance(value, dict):
        return all(_plain(key) and _plain(item) for key, item in value.items())
    return False


def _text_term(compute: Callable[..., str | Fail]) -> TermFunction:
    """The term function of a substitution computed from its text operands, once a
    configuration gives those texts: its failure is the term's error."""

    def term(_host: object, *texts: object) -> str:
        value = compute(*map(str, texts))
        if isinstance(value, Fail):
            raise TermError(value.message)
        return value

    return term


register(PYTHON_YAML, _text_term(_yaml_literal))


@substitution(NODE_NAME)
def _node_name(host: Interpretation[Context], context: Context, args: list[Raw]) -> Choice[Value]:
    """The Python frontend's container object given as a target: the fully qualified name of
    the node declared at the place named, as launch_ros reads it off the executed action
    (the pushed namespace there, then its own); where it was not launched, launch fails."""
    if len(args) != 1:
        return _fail(host, f"$({NODE_NAME}) takes a place", "substitution-invalid")
    name = _fail(host, "a container's name read where it was not launched", "value-unknown")
    for node in host.model.nodes:
        if str(node.location) == args[0]:
            name = ite(
                host.space, node.condition, node.value(ROS2_NODES.full_name).map(_named), name
            )
    return name


def _named(name: Raw | None) -> Value:
    return Fail("a container with no name", "value-unknown") if name is None else name


@substitution(UNKNOWN)
def _unknown(host: Interpretation[Context], context: Context, args: list[Raw]) -> Choice[Value]:
    """A value the Python frontend did not follow (it reported it): unknown, failing only
    where its text is needed, as an argument's value outside its domain."""
    what = args[0] if args and isinstance(args[0], str) else "value"
    return Choice.const(host.space, Apply(UNKNOWN, (what,), f"⟨{what}⟩"))


def _not_followed(_host: object, what: str) -> str:
    raise TermError(f"{what} is not followed by rosvar")


register(UNKNOWN, _not_followed)


DEFAULT_MODULES = "math"
"""``PythonExpression``'s ``python_modules`` when not given."""


@computed("eval")
def _eval(args: list[Raw]) -> Value:
    """``PythonExpression``: an expression, and optionally the modules it may use (launch's
    comma-separated names; ``math`` when not given)."""
    if not 1 <= len(args) <= 2:
        return Fail("eval substitution expects 1 or 2 arguments", "substitution-invalid")
    return _eval_value(args)


def _eval_value(args: Sequence[Raw]) -> Value:
    """``$(eval)`` of its arguments; a term where one is, evaluated once a configuration
    gives it."""
    if not all(isinstance(arg, str) for arg in args):
        shown = " ".join(map(str, args))
        return Apply("ros2-eval", tuple(args), f"$(eval {shown})")
    return _evaluation(*cast("list[str]", args))


def _evaluated_with(template: Template, leaves: Sequence[Value]) -> Value:
    """``$(eval template)`` with ``leaves`` for its substitutions, in order."""
    for leaf in leaves:
        if isinstance(leaf, Fail):
            return leaf
    substituted = iter(cast("Sequence[Raw]", leaves))
    parts = [part if isinstance(part, str) else next(substituted) for part in template]
    return _eval_value([concat(parts)])


def _evaluation(text: str, modules: str = DEFAULT_MODULES) -> str | Fail:
    if modules != DEFAULT_MODULES:
        refused = _module_failure(text, modules)
        if refused is not None:
            return refused
    value = _evaluated.get(text)
    if value is None:
        try:
            value = evaluate(text, PYTHON_EXPRESSION)
        except EvalRefused as refused:  # what the restricted evaluator does not run
            value = Fail(f"$(eval {text}): {refused}", "eval-refused")
        except EvalFailed as error:  # what Python raises too
            value = Fail(f"$(eval {text}): {error}", "eval-failed")
        _evaluated[text] = value
    return value


register("ros2-eval", _text_term(_evaluation))


def _module_failure(text: str, modules: str) -> Fail | None:
    """Where ``PythonExpression`` with ``modules`` fails or rosvar cannot tell, before the
    expression is evaluated as with ``math`` (which then gives its value): launch imports
    each module, so a module rosvar does not model is refused (its import may fail, its
    members are not known); without ``math`` its names are not defined."""
    names = [name.strip() for name in modules.split(",")] if modules else []
    for name in names:
        if not name:
            return Fail(f"$(eval {text}): ValueError: Empty module name", "eval-failed")
        if name not in EVAL_NAMESPACES:
            modelled = ", ".join(sorted(EVAL_NAMESPACES))
            return Fail(
                f"$(eval {text}): module '{name}' is not modelled by rosvar (only {modelled})",
                "eval-refused",
            )
    if DEFAULT_MODULES in names:
        return None
    try:
        read = referenced_names(text, EVAL_NAMESPACES, dunder_text=False) & MATH_NAMES
    except EvalRefused:
        return None  # the evaluation says why
    for name in sorted(read):
        if name in BUILTIN_NAMES:  # Python's own pow, not math's: rosvar has math's only
            return Fail(
                f"$(eval {text}): '{name}' without the math module is Python's builtin, "
                "which rosvar does not model",
                "eval-refused",
            )
    first = next((m.group() for m in IDENTIFIER.finditer(text) if m.group() in read), None)
    if first is None:
        return None
    return Fail(f"$(eval {text}): NameError: name '{first}' is not defined", "eval-failed")


EVALUATED_CAPACITY = 65_536
"""Expression texts whose value :data:`_evaluated` keeps."""
_evaluated: Memo[str, str | Fail] = Memo(EVALUATED_CAPACITY)
"""``$(eval)``'s value (or failure) by text: it reads nothing else (no launch configuration
but through ``$(var)``, already substituted), and one text is met once per combination of
the values it was made of, in every includer (autoware.universe: 37,000 texts evaluated
148,000 times, more than the parser's cache holds)."""


def _no_arg(name: str) -> str:
    raise KeyError(name)  # ROS 2 expressions read launch configurations only through $(var)


PYTHON_EXPRESSION = EvalEnvironment(
    _no_arg,
    symbols=_no_arg,
    namespaces={"math": {name: name for name in dir(math) if "__" not in name}},
    dunder_text=False,
)
"""What ``PythonExpression`` evaluates in: ``eval(text, {}, locals)`` whose locals are the
``math`` module and its names (its default ``python_modules``), under Python's builtins; no
roslaunch names (``true``, ``arg``, ``env``: a ``NameError`` in ROS 2)."""
EVAL_NAMESPACES = frozenset(PYTHON_EXPRESSION.namespaces)
MATH_NAMES = frozenset({DEFAULT_MODULES, *PYTHON_EXPRESSION.namespaces[DEFAULT_MODULES]})
"""The names ``math`` as a module given puts in the expression's locals."""
BUILTIN_NAMES = frozenset(dir(builtins))
IDENTIFIER = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")


@substitution("anon")
def _anon(host: Interpretation[Context], context: Context, args: list[Raw]) -> Choice[Value]:
    """One name per id, kept as the launch configuration ``anon<id>`` (so groups scope it);
    a counter stands for launch's host, pid and random part, as for ROS 1."""
    if len(args) != 1 or not isinstance(args[0], str):
        return _fail(host, "$(anon) takes one argument", "substitution-invalid")
    key = "anon" + args[0]
    old = context.get(key)
    unset = host.space.true if old is None else old.where(lambda leaf: leaf is None)
    if unset != host.space.false:
        with host.under(unset) as live:
            if live:
                fresh = optional(host.new_anon(args[0]))
                before = old if old is not None else Choice.const(host.space, None)
                context.configurations[key] = ite(host.space, host.pc, fresh, before)
    return context.configurations[key].map(_present)


def _present(leaf: Raw | None) -> Value:
    return Fail("anonymous name not set", "value-unknown") if leaf is None else leaf
