"""Substitution args (``$(arg)``, ``$(find)``, ``$(eval)``, ...) over all configurations.

roslaunch's ``substitution_args``, which xacro reuses for its ``$()``: so the module is the
core's, read by ROS 1's launch files and by robot descriptions of either ROS version. The
scanning and replacement rules are roslaunch's: a
first pass for ``env optenv dirname anon arg`` in order of appearance (each
replacing every occurrence of its text), then a ``find`` pass over the result,
and ``$(eval ...)`` only when it spans the whole attribute. Values are
:class:`Choice` objects; what is unknown stays a :class:`Term`.
"""

from __future__ import annotations

import ast
import functools
import itertools
import os
from collections.abc import Callable, Hashable, Iterable, Sequence
from typing import Final, Protocol

from rosvar.frontends.xml import Snapshot
from rosvar.interpreter.model import Raw
from rosvar.logic.bdd import BDD
from rosvar.logic.cells import Cells, register_cells
from rosvar.logic.choice import Choice, Fail, combine
from rosvar.logic.conditions import ConditionSpace
from rosvar.logic.given_up import Combination, GivenUp
from rosvar.logic.inputs import Input
from rosvar.logic.terms import (
    Apply,
    Hole,
    PackageTable,
    TermError,
    concat,
    is_term,
    measure_parts,
    register,
    term_inputs,
)
from rosvar.memo import Memo

Value = Raw | Fail

MAX_COMBINATIONS = 4096
"""Combinations of operand values one attribute may compute (each varying ``$(arg)`` of a
text multiplies them: a few lines could otherwise ask for 2^N strings)."""
MAX_FILE_COMBINATIONS = 1_000_000
"""Combinations all the attributes of one interpretation may compute together."""
MAX_VALUE_SIZE = 1_000_000
"""Characters (a term's operands counted each time they occur) of one value; args that
concatenate the previous one twice would otherwise double it at every line."""
MAX_TERM_DEPTH = 100
"""Nesting of a symbolic value; deeper ones would exhaust recursion when evaluated."""
MAX_CONDITION_NODES = 4096
"""BDD nodes of one condition computed for a value instead of crossing (a chain of
``$(eval)``s, each reading the one before twice, would double them at every line)."""
MAX_TESTED_TERMS = 64
"""Values not known yet (terms) one ``if``/``unless`` or one ``$(eval)`` of comparisons may
test: each is predicates of its own in the conditions, and a value crossed from many args'
``<other>`` values would make thousands."""


class Missing:
    def __repr__(self) -> str:
        return "<undefined>"


MISSING: Final = Missing()
"""Leaf of an arg or anon value in the configurations where it is not defined."""

ArgValue = Choice[Raw | Missing]


class Scope(Protocol):
    """What substitution reads of the place a text is in: ROS 1's launch scope, xacro's."""

    filename: str
    args: dict[str, ArgValue]
    anon: dict[str, ArgValue]


class SubstitutionError(Exception):
    """The attribute text itself is malformed (roslaunch's ``SubstitutionException``)."""


class Host(Protocol):
    """What substitution needs from the running interpretation."""

    space: ConditionSpace

    def find_package(self, name: str) -> str | None: ...

    def env_value(self, name: str) -> Choice[Raw | None]: ...

    def new_anon(self, anon_id: str) -> Choice[Raw]: ...

    def note_unknown_package(self, name: str) -> None: ...

    def note_too_complex(self, message: str) -> None: ...


@functools.lru_cache(maxsize=65536)
def collect(text: str) -> tuple[str, ...]:
    """The ``$(...)`` bodies of ``text``, by roslaunch's scanning state machine."""
    out, dollar, lparen, inside = 0, 1, 2, 3
    state = out
    bodies: list[str] = []
    buffer: list[str] = []
    for ch in text:
        if ch == "$":
            if state == out:
                state = dollar
            elif state != dollar:
                raise SubstitutionError(
                    f"Dollar signs '$' cannot be inside of substitution args [{text}]"
                )
        elif ch == "(":
            if state == dollar:
                state = lparen
            elif state != out:
                raise SubstitutionError(
                    f"Invalid left parenthesis '(' in substitution args [{text}]"
                )
        elif ch == ")":
            if state == inside:
                bodies.append("".join(buffer))
                buffer.clear()
            state = out
        elif state == dollar:
            state = out
        elif state == lparen:
            state = inside
        if state == inside:
            buffer.append(ch)
    return tuple(bodies)


@functools.lru_cache(maxsize=65536)
def _split(body: str) -> tuple[str, ...]:
    words = tuple(w for w in body.split(" ") if w)
    if not words:
        raise SubstitutionError(
            f"Unknown substitution command [{body}]. Valid commands are {list(COMMANDS)}"
        )
    if words[0] not in COMMANDS:
        raise SubstitutionError(
            f"Unknown substitution command [{body}]. Valid commands are {list(COMMANDS)}"
        )
    return words


@functools.lru_cache(maxsize=65536)
def _segments(text: str, bodies: tuple[str, ...]) -> tuple[tuple[str, ...], tuple[str | int, ...]]:
    """The distinct first-pass bodies of ``text``, and ``text`` cut at each of them.

    An int segment stands for the value of that body; cutting at every occurrence is
    roslaunch's ``replace()`` of all of them. Cached: the same texts recur in every
    file that includes them.
    """
    segments: list[str | int] = [text]
    distinct = tuple(dict.fromkeys(b for b in bodies if _split(b)[0] in FIRST_PASS))
    for index, body in enumerate(distinct):
        marker = f"$({body})"
        next_segments: list[str | int] = []
        for segment in segments:
            if isinstance(segment, int):
                next_segments.append(segment)
                continue
            pieces = segment.split(marker)
            for k, piece in enumerate(pieces):
                if k:
                    next_segments.append(index)
                next_segments.append(piece)
        segments = next_segments
    return distinct, tuple(segments)


@functools.lru_cache(maxsize=65536)
def _plan(
    text: str,
) -> tuple[tuple[str, ...], tuple[str | int, ...], bool, tuple[str, ...] | None]:
    """How to resolve ``text``: its first-pass bodies and segments (as :func:`_segments`),
    whether a find pass follows, and the args it reads when it reads nothing else (no
    ``env``, ``anon`` nor ``dirname``): its value is then a function of theirs (and of the
    workspace's packages). Raises :class:`SubstitutionError` for malformed text.
    """
    bodies = collect(text)
    for body in bodies:
        _split(body)
    distinct, segments = _segments(text, bodies)
    find = any(_split(b)[0] == "find" for b in bodies)
    words = [_split(body) for body in distinct]
    only_args = all(w[0] == "arg" and len(w) == 2 for w in words)
    return distinct, segments, find, tuple(w[1] for w in words) if only_args else None


# -- the find pass, on a concrete string (also used to evaluate terms later) ----------------
def find_pass(text: str, lookup: Callable[[str], str | None]) -> str:
    """roslaunch's second pass: every ``$(find pkg)`` plus the path that follows it."""
    resolved = text
    for body in collect(text):
        words = _split(body)
        if words[0] != "find":
            continue
        if len(words) != 2:
            raise SubstitutionError(f"$(find pkg) command only accepts one argument [{body}]")
        command = f"$({body})"
        index = resolved.find(command)
        if index < 0:
            continue
        before, after = resolved[:index], resolved[index + len(command) :]
        space = after.find(" ")
        path, after = (after, "") if space < 0 else (after[:space], after[space:])
        if path.startswith("/"):
            path = path[1:]
        package_path = lookup(words[1])
        if package_path is None:
            raise LookupError(f"package '{words[1]}' not found")
        if path:
            package_path = os.path.join(package_path, path)
        resolved = before + package_path + after
    return resolved


def _names_unknown_package(value: object) -> bool:
    """Whether ``value`` is a find pass left symbolic because a package is not known."""
    return (
        isinstance(value, Apply)
        and value.function == "find_pass"
        and isinstance(value.operands[0], str)
    )


def _find_term(host: object, text: str) -> str:
    if not isinstance(host, PackageTable):
        raise LookupError("no package table to resolve $(find)")
    return find_pass(text, host.paths.get)


register("find_pass", _find_term)


Command = Callable[["Substituter", str, tuple[str, ...], Scope], Choice[Value]]
"""A first-pass command: the substituter, the whole body (for messages), its parameters."""
FIRST_PASS: dict[str, Command] = {}
"""The commands of roslaunch's first pass by name, in roslaunch's order; ``find`` is the
second pass (:func:`find_pass`)."""


def command(name: str) -> Callable[[Command], Command]:
    """Register the first-pass command ``$(name ...)`` (extension by registry, like tags)."""

    def register(handler: Command) -> Command:
        if name in FIRST_PASS:
            raise ValueError(f"substitution command {name!r} is registered twice")
        FIRST_PASS[name] = handler
        return handler

    return register


def _invalid(substituter: Substituter, message: str) -> Choice[Value]:
    return Choice.const(substituter.space, Fail(message, "substitution-invalid"))


@command("env")
def _env(
    substituter: Substituter, body: str, params: tuple[str, ...], scope: Scope
) -> Choice[Value]:
    if len(params) != 1:
        return _invalid(substituter, f"$(env var) command only accepts one argument [{body}]")
    name = params[0]
    return substituter.host.env_value(name).map(
        lambda v: Fail(f"environment variable '{name}' is not set", "env-unset") if v is None else v
    )


@command("optenv")
def _optenv(
    substituter: Substituter, body: str, params: tuple[str, ...], scope: Scope
) -> Choice[Value]:
    if not params:
        return _invalid(substituter, f"$(optenv var) must specify an environment variable [{body}]")
    default = " ".join(params[1:])
    return substituter.host.env_value(params[0]).map(lambda v: default if v is None else v)


@command("dirname")
def _dirname(
    substituter: Substituter, body: str, params: tuple[str, ...], scope: Scope
) -> Choice[Value]:
    return Choice.const(substituter.space, os.path.abspath(os.path.dirname(scope.filename)))


@command("anon")
def _anon(
    substituter: Substituter, body: str, params: tuple[str, ...], scope: Scope
) -> Choice[Value]:
    if len(params) != 1:
        if not params:
            return _invalid(substituter, f"$(anon var) must specify a name [{body}]")
        return _invalid(substituter, f"$(anon var) may only specify one name [{body}]")
    return substituter.anon(params[0], scope)


@command("arg")
def _arg(
    substituter: Substituter, body: str, params: tuple[str, ...], scope: Scope
) -> Choice[Value]:
    if len(params) != 1:
        if not params:
            return _invalid(substituter, f"$(arg var) must specify a variable name [{body}]")
        return _invalid(substituter, f"$(arg var) may only specify one arg [{body}]")
    return substituter.arg(params[0], scope)


COMMANDS = ("find", *FIRST_PASS)


Resolved = Memo[tuple[object, ...], tuple[Choice[Value], int]]
"""Values of texts that read args only, by text and the choices of the args read, each with
the combinations it spent of the file's budget."""


def shared_texts(files: Snapshot) -> Resolved:
    """The resolved texts one analysis's walks share, kept with the files they read (as
    :func:`rosvar.ros2.include_memo._table`: not on the condition space, where a cycle's
    collection freed BDD nodes after their manager)."""
    return files.kept(__name__)


class Substituter:
    """Resolves attribute text in a scope, for all configurations at once."""

    escapes = False  # roslaunch keeps a backslash as it is

    def __init__(self, host: Host, shared: Resolved | None = None) -> None:
        """``shared``: the values of texts other walks of the same analysis (condition
        space and packages) resolved, to reuse and add to."""
        self.host = host
        self.space = host.space
        # Values of texts that read args only (and packages), by text and the immutable
        # choices of the args read: a file's texts recur in its elements and its includes'.
        self._known: dict[tuple[object, ...], Choice[Value]] = {}
        self._shared = shared
        self.budget = ValueBudget(host.space, host.note_too_complex)

    def resolve(self, text: str | None, scope: Scope) -> Choice[Value] | None:
        if text is None:
            return None
        if "$" not in text:
            return Choice.const(self.space, text)
        try:
            if text.startswith("$(eval ") and text.endswith(")"):
                return self._eval(text[7:-1], scope)
            distinct, segments, find, reads = _plan(text)
        except SubstitutionError as error:
            return Choice.const(self.space, Fail(str(error), "substitution-invalid"))
        if reads is not None:
            args = scope.args
            key = (text, *map(args.get, reads))
            known = self._known.get(key)
            if known is None:
                known = self._shared_resolved(key, (text, distinct, segments, find), scope)
            return known
        return self._resolved(text, distinct, segments, find, scope)

    def _shared_resolved(
        self,
        key: tuple[object, ...],
        planned: tuple[str, tuple[str, ...], tuple[str | int, ...], bool],
        scope: Scope,
    ) -> Choice[Value]:
        """A text's value this walk has not met (``planned``: the text and its
        :func:`_plan`): another walk's where it read the same choices (the entry files'
        walks share the constants and their includes' args), and where spending what it
        spent keeps this file within its budget, as computing it again would; otherwise
        computed. (Husky's walks meet 2,222 texts anew, 1,260 of them another walk's.)"""
        shared = self._shared
        found = None if shared is None else shared.get(key)
        if found is not None and self.budget.fits(found[1]):
            self.budget.combinations += found[1]
            self._known[key] = found[0]
            return found[0]
        notes, spent = self.budget.notes, self.budget.combinations
        value = self._resolved(*planned, scope)
        if not any(map(_names_unknown_package, value.values())):
            self._known[key] = value  # (else its warning belongs to each place)
            if shared is not None and self.budget.notes == notes:  # (no limit met)
                shared[key] = (value, self.budget.combinations - spent)
        return value

    def _resolved(
        self,
        text: str,
        distinct: tuple[str, ...],
        segments: tuple[str | int, ...],
        find: bool,
        scope: Scope,
    ) -> Choice[Value]:
        first = self._first_pass(text, distinct, segments, scope)
        return first.map(self._apply_find) if find else first

    def _apply_find(self, value: Value) -> Value:
        if isinstance(value, Fail):
            return value
        if is_term(value):
            return Apply("find_pass", (value,), display=str(value))
        assert isinstance(value, str)
        unknown: list[str] = []

        def lookup(name: str) -> str | None:
            path = self.host.find_package(name)
            if path is None:
                unknown.append(name)
            return path

        try:
            return find_pass(value, lookup)
        except SubstitutionError as error:
            return Fail(str(error), "substitution-invalid")
        except LookupError:
            for name in unknown:
                self.host.note_unknown_package(name)
            return Apply("find_pass", (value,), display=value)

    def _first_pass(
        self,
        text: str,
        distinct: tuple[str, ...],
        segments: tuple[str | int, ...],
        scope: Scope,
    ) -> Choice[Value]:
        values = [self._command(body, scope) for body in distinct]
        if not values:
            return Choice.const(self.space, text)
        if segments == ("", 0, ""):  # the whole text is one substitution: its value as is
            return values[0]

        places = [(place, s) for place, s in enumerate(segments) if not isinstance(s, str)]

        def parts(leaves: Sequence[Raw]) -> list[Raw]:
            joined: list[Raw] = list(segments)  # type: ignore[arg-type]  # ints replaced below
            for place, leaf in places:
                joined[place] = leaves[leaf]
            return joined

        return self.budget.join(text, values, parts)

    def _command(self, body: str, scope: Scope) -> Choice[Value]:
        words = _split(body)
        return FIRST_PASS[words[0]](self, body, words[1:], scope)

    def arg(self, name: str, scope: Scope) -> Choice[Value]:
        value = scope.args.get(name)
        if value is not None and all(v is not MISSING for _c, v in value.branches):
            return value  # type: ignore[return-value]  # defined everywhere: no copy
        missing = Fail(f"requires the '{name}' arg to be set", "arg-undefined")
        if value is None:
            return Choice.const(self.space, missing)
        return value.map(lambda v: missing if v is MISSING else v)  # type: ignore[arg-type,return-value]

    def anon(self, anon_id: str, scope: Scope) -> Choice[Value]:
        known = scope.anon.get(anon_id)
        if known is not None and all(v is not MISSING for v in known.values()):
            return known  # type: ignore[return-value]
        generated = self.host.new_anon(anon_id)
        if known is None:
            scope.anon[anon_id] = generated
            return generated
        merged: Choice[Raw] = known.bind(
            lambda v: generated if isinstance(v, Missing) else Choice.const(self.space, v)
        )
        scope.anon[anon_id] = merged
        return merged

    # -- $(eval) ------------------------------------------------------------------------
    def _eval(self, expression: str, scope: Scope) -> Choice[Value]:
        # the evaluator is imported by the first file that needs it: most workspaces never do
        from rosvar.interpreter.safe_eval import EvalRefused, referenced_args

        space = self.space
        if "__" in expression:
            return Choice.const(
                space,
                Fail("$(eval ...) may not contain double underscore expressions", "eval-refused"),
            )
        try:
            arg_names = sorted(referenced_args(expression))
            env_names = sorted(_env_names(expression))
        except EvalRefused as error:
            return Choice.const(
                space, Fail(f"$(eval {expression}): {error.message}", "eval-refused")
            )
        except _Undecidable as undecidable:
            return Choice.const(
                space, Fail(f"$(eval {expression}): {undecidable}", "eval-undecidable")
            )
        arg_choices = [scope.args.get(n, Choice.const(space, MISSING)) for n in arg_names]
        env_choices = [self.host.env_value(n) for n in env_names]
        filename = scope.filename
        anon_values: dict[str, str] = {}

        deferred = functools.partial(_deferred_eval, expression, arg_names, env_names, filename)

        def run(leaves: list[object]) -> Value:
            if any(is_term(v) for v in leaves):
                return deferred(leaves)
            args = dict(zip(arg_names, leaves[: len(arg_names)], strict=True))
            envs = dict(zip(env_names, leaves[len(arg_names) :], strict=True))
            return _run_eval(
                expression,
                {k: v for k, v in args.items() if isinstance(v, str)},
                {k: v for k, v in envs.items() if isinstance(v, str)},
                filename,
                self.host.find_package,
                lambda anon_id: anon_values.setdefault(anon_id, f"{anon_id}_anon"),
            )

        if not arg_choices and not env_choices:
            return Choice.const(space, run([]))
        choices: list[Choice[object]] = [*arg_choices, *env_choices]
        if not self.budget.affordable(f"$(eval {expression})", choices):
            return Choice.const(space, too_complex(f"$(eval {expression})", choices, deferred))
        return combine(choices, run)


class ValueBudget:
    """The bounds on the values one interpretation computes, the same for every dialect and
    frontend: combinations of operand values per text (:data:`MAX_COMBINATIONS`) and per
    file (:data:`MAX_FILE_COMBINATIONS`), and the size of every concatenation built
    (:data:`MAX_VALUE_SIZE`, :data:`MAX_TERM_DEPTH`). Past them a value is
    :func:`too_complex`, with one ``value-too-complex`` note."""

    def __init__(self, space: ConditionSpace, note: Callable[[str], None]) -> None:
        self.space = space
        self._note = note
        self.combinations = 0  # spent from MAX_FILE_COMBINATIONS
        self.notes = 0  # notes made: a memo keeps no value that made one

    def note(self, message: str) -> None:
        self.notes += 1
        self._note(message)

    def affordable(self, text: str, choices: Sequence[Choice[object]]) -> bool:
        """Whether combining ``choices`` for ``text`` stays within the work limits (and,
        if so, charge it); otherwise the caller makes ``text`` an unknown value."""
        count = 1
        for choice in choices:
            count *= len(choice.branches)
        return self.affordable_count(text, count)

    def affordable_count(self, text: str, count: int) -> bool:
        """:meth:`affordable` for ``count`` combinations (work that computes a value without
        crossing its operands charges what crossing them would have, so the budget and its
        notes are the same whichever way a value is computed)."""
        if count <= 1:
            return True
        if count > MAX_COMBINATIONS:
            reason = f"it has {count} combinations of values, over {MAX_COMBINATIONS}"
        elif not self.fits(count):
            reason = f"the file's values need over {MAX_FILE_COMBINATIONS} combinations"
        else:
            self.combinations += count
            return True
        self.note(f"{_short(text)} is not computed: {reason}")
        return False

    def affords_tests(self, text: str, count: int) -> bool:
        """Whether testing ``count`` terms for ``text`` stays within :data:`MAX_TESTED_TERMS`;
        otherwise a note, and the caller keeps the value unknown."""
        if count <= MAX_TESTED_TERMS:
            return True
        self.note(
            f"{_short(text)} is not computed: it tests {count} values not known yet, "
            f"over {MAX_TESTED_TERMS}"
        )
        return False

    def affords_conditions(self, text: str, conditions: Iterable[BDD]) -> bool:
        """Whether ``conditions`` computed for ``text`` stay within
        :data:`MAX_CONDITION_NODES` each; otherwise a note, and the caller keeps the value
        unknown."""
        largest = max((condition.dag_size for condition in conditions), default=0)
        if largest <= MAX_CONDITION_NODES:
            return True
        self.note(
            f"{_short(text)} is not computed: its conditions need {largest} BDD nodes, "
            f"over {MAX_CONDITION_NODES}"
        )
        return False

    def fits(self, count: int) -> bool:
        """Whether ``count`` more combinations stay within the file's budget (charging
        nothing)."""
        return self.combinations + count <= MAX_FILE_COMBINATIONS

    def spares(self, combinations: int) -> bool:
        """Whether work that spent ``combinations`` from here on would meet no limit: each
        of its texts within :data:`MAX_COMBINATIONS`, the file within
        :data:`MAX_FILE_COMBINATIONS` (memos replay such work, and spend as much)."""
        return self.combinations + combinations + MAX_COMBINATIONS <= MAX_FILE_COMBINATIONS

    def given_up(
        self, text: str, choices: Sequence[Choice[object]], combination: Combination | None
    ) -> Choice[Value]:
        """:func:`too_complex` where every one of ``choices`` has a value (as combining them
        would have it)."""
        covered = self.space.true
        for choice in choices:
            covered &= choice.covered()
        return Choice.of([(covered, too_complex(text, choices, combination))], self.space.false)

    def join(
        self,
        text: str,
        choices: Sequence[Choice[Value]],
        parts: Callable[[Sequence[Raw]], Sequence[Raw]] = list,
    ) -> Choice[Value]:
        """The concatenation of ``parts`` of the leaves, in every combination of
        ``choices`` (a failing leaf fails it), or :func:`too_complex` beyond the bounds."""
        concatenate = functools.partial(_concatenated, text, parts)
        if not self.affordable(text, choices):
            return self.given_up(text, choices, concatenate)
        result = combine(choices, concatenate)
        if any(_oversized(leaf, text) for leaf in result.values()):
            self.note(
                f"{_short(text)} is not computed: its value would be over {MAX_VALUE_SIZE} "
                f"characters or {MAX_TERM_DEPTH} levels"
            )
        return result


def _concatenated(
    text: str, parts: Callable[[Sequence[Raw]], Sequence[Raw]], leaves: list[Value]
) -> Value:
    """``parts`` of one leaf of each operand of ``text`` joined (a failing leaf fails it),
    or :func:`too_complex` when the value would be over :data:`MAX_VALUE_SIZE` characters
    or :data:`MAX_TERM_DEPTH` levels."""
    for leaf in leaves:
        if isinstance(leaf, Fail):
            return leaf
    # Runs of strings joined first (a text's literal parts and the strings around its
    # terms): measuring and concatenating then see a few parts, and strings only are done.
    merged: list[Raw] = []
    for kind, run in itertools.groupby(parts(leaves), type):  # type: ignore[arg-type]
        if kind is str:
            merged.append("".join(run))  # type: ignore[arg-type]  # strings
        else:
            merged.extend(run)
    if len(merged) == 1 and type(merged[0]) is str:
        return merged[0] if len(merged[0]) <= MAX_VALUE_SIZE else too_complex(text)
    size, depth = measure_parts(merged)
    if size > MAX_VALUE_SIZE or depth > MAX_TERM_DEPTH:
        return too_complex(text)
    return concat(merged)


def _oversized(leaf: Value, text: str) -> bool:
    """Whether ``leaf`` is the value :func:`_concatenated` gives ``text`` over the bounds."""
    return type(leaf) is Apply and leaf.function == "too_complex" and leaf.operands == (text,)


def too_complex(
    text: str,
    choices: Sequence[Choice[object]] = (),
    combination: Combination | None = None,
) -> Apply:
    """The unknown value of ``text`` when computing it would go beyond the work limits: a
    term no configuration can evaluate, unless ``combination`` of one leaf of each of
    ``choices`` computes it: then a configuration's resolution does (:mod:`~rosvar.logic.given_up`),
    and reports ``value-unknown`` only where that too is over the bounds."""
    display = f"⟨{_short(text)}⟩"
    if combination is None:
        return Apply("too_complex", (text,), display=display)
    return GivenUp(text, display, choices, combination)


def _too_complex_term(_host: object, text: str) -> str:
    raise TermError(f"{_short(text)} was not computed: over rosvar's work limits")


def _short(text: str) -> str:
    """``text`` for a message (attribute texts can be megabytes long)."""
    return text if len(text) <= 120 else f"{text[:117]}..."


register("too_complex", _too_complex_term)


class _Undecidable(Exception):
    pass


@functools.lru_cache(maxsize=4096)
def _env_names(expression: str) -> frozenset[str]:
    """Environment variables read by ``env('X')``/``optenv('X', ...)`` calls (cached: the
    same expression is met in every includer)."""
    tree = ast.parse(expression, mode="eval")
    names: set[str] = set()
    for node in ast.walk(tree):
        if (
            isinstance(node, ast.Call)
            and isinstance(node.func, ast.Name)
            and node.func.id in ("env", "optenv")
        ):
            if (
                node.args
                and isinstance(node.args[0], ast.Constant)
                and isinstance(node.args[0].value, str)
            ):
                names.add(node.args[0].value)
            else:
                raise _Undecidable("the environment variable name is not a literal")
    return frozenset(names)


def _deferred_eval(
    expression: str,
    arg_names: Sequence[str],
    env_names: Sequence[str],
    filename: str,
    leaves: list[object],
) -> Apply:
    """``$(eval expression)`` of one value of each arg and environment variable it reads
    (``leaves``, in that order), as the term :func:`_eval_term` evaluates once they are
    concrete (an undefined one is missing)."""
    operands = [v if isinstance(v, str) or is_term(v) else "\x00missing" for v in leaves]
    count = len(arg_names)
    return Apply(
        "eval",
        (
            expression,
            tuple(arg_names),
            *operands[:count],  # type: ignore[arg-type]  # strings and terms
            tuple(env_names),
            *operands[count:],  # type: ignore[arg-type]
            filename,
        ),
        display=f"$(eval {expression})",
    )


def _run_eval(
    expression: str,
    args: dict[str, str],
    envs: dict[str, str],
    filename: str,
    find: Callable[[str], str | None],
    anon: Callable[[str], str],
) -> Value:
    from rosvar.interpreter.safe_eval import EvalEnvironment, EvalFailed, EvalRefused, evaluate

    def env(name: str) -> str:
        if name not in envs:
            raise EvalFailed(f"environment variable '{name}' is not set")
        return envs[name]

    def optenv(name: str, default: str = "") -> str:
        return envs.get(name, default)

    def find_function(name: str) -> str:
        path = find(name)
        if path is None:
            raise EvalFailed(f"package '{name}' not found")
        return path

    def lookup(name: str) -> str:
        return args[name]

    environment = EvalEnvironment(
        lookup_arg=lookup,
        functions={
            "env": env,
            "optenv": optenv,
            "find": find_function,
            "anon": anon,
            "dirname": lambda: os.path.abspath(os.path.dirname(filename)),
        },
    )
    try:
        return evaluate(expression, environment)
    except EvalRefused as error:
        return Fail(f"$(eval {expression}): {error.message}", "eval-refused")
    except EvalFailed as failure:
        return Fail(f"$(eval {expression}): {failure.message}", "eval-failed")


def _eval_term(host: object, expression: str, *operands: object) -> str:
    """Evaluate a deferred ``$(eval)`` once its inputs are concrete."""
    arg_names = operands[0]
    assert isinstance(arg_names, tuple)
    n = len(arg_names)
    arg_values = operands[1 : 1 + n]
    env_names = operands[1 + n]
    assert isinstance(env_names, tuple)
    env_values = operands[2 + n : 2 + n + len(env_names)]
    filename = operands[-1]
    assert isinstance(filename, str)
    args = {k: v for k, v in zip(arg_names, arg_values, strict=True) if v != "\x00missing"}
    envs = {k: v for k, v in zip(env_names, env_values, strict=True) if v != "\x00missing"}
    paths = host.paths if isinstance(host, PackageTable) else {}
    result = _run_eval(
        expression,
        args,  # type: ignore[arg-type]
        envs,  # type: ignore[arg-type]
        filename,
        paths.get,
        lambda anon_id: f"{anon_id}_anon",
    )
    if isinstance(result, Fail):
        raise ValueError(result.message)
    assert isinstance(result, str)
    return result


register("eval", _eval_term)


def _eval_constants(term: Apply, input_: Input) -> frozenset[Hashable] | None:
    """What a deferred ``$(eval)`` compares ``input_``'s value with, when that is all it does
    with it (:mod:`rosvar.interpreter.safe_eval.cells`); None otherwise."""
    from rosvar.interpreter.safe_eval.cells import compared_constants

    expression, arg_names = term.operands[0], term.operands[1]
    assert isinstance(expression, str) and isinstance(arg_names, tuple)
    values = term.operands[2 : 2 + len(arg_names)]
    hole = Hole(input_)
    readers = [name for name, value in zip(arg_names, values, strict=True) if value == hole]
    if not readers or any(
        term_inputs(value) and value != hole
        for value in term.operands[2:]
        if not isinstance(value, str | tuple)
    ):
        return None  # the input is also read through a text built from it
    constants: set[Hashable] = set()
    for name in readers:
        found = compared_constants(expression, name)
        if found is None:
            return None
        constants |= found
    return frozenset(constants)


def _eval_witnesses(constants: Iterable[Hashable]) -> tuple[str, ...]:
    from rosvar.interpreter.safe_eval.cells import Literal, witnesses

    return witnesses(c for c in constants if isinstance(c, Literal))


register_cells("eval", Cells(_eval_constants, _eval_witnesses))
