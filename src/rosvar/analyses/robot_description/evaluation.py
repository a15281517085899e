"""xacro's ``eval_text``, for every configuration at once: ``${expression}``, ``$(extension)``,
``$${`` and plain text.

A text is cut into tokens as xacro's lexer cuts it; a lone token keeps its type (``${0.5}``
is the float 0.5), several are joined into a string. ``${}`` goes through rosvar's restricted
evaluator, with the properties the expression names as its symbols (each a :class:`Choice`:
the expression is evaluated per combination of their values, within a bound); ``$()`` is
roslaunch's substitution args, which xacro reuses, through the launch interpreter's
:class:`~rosvar.interpreter.substitution_args.Substituter` with xacro's args. Failures are
``Fail`` leaves; what rosvar does not evaluate is an unknown value, with a warning.
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Final, Protocol

from rosvar.analyses.robot_description.commands import parts
from rosvar.analyses.robot_description.document import Text
from rosvar.analyses.robot_description.literals import (
    NAMESPACES,
    Deferred,
    Unread,
    deferred,
    encode,
    evaluate,
    stored,
    text_of,
)
from rosvar.analyses.robot_description.symbols import ABSENT, Lazy, Table
from rosvar.diagnostics import Location
from rosvar.interpreter.model import Raw
from rosvar.interpreter.safe_eval import EvalFailed, EvalRefused, referenced_names
from rosvar.interpreter.substitution_args import (
    MAX_COMBINATIONS,
    ArgValue,
    Missing,
    Substituter,
    SubstitutionError,
    collect,
    too_complex,
)
from rosvar.logic.bdd import BDD
from rosvar.logic.choice import Choice, Fail, combine
from rosvar.logic.conditions import ConditionSpace
from rosvar.logic.terms import Operand, concat, is_term

XACRO_COMMANDS: Final = ("find", "env", "optenv", "dirname", "arg")
"""The ``$()`` commands xacro accepts (roslaunch's without ``anon``; ``eval`` when whole)."""
MAX_TEXT_COMBINATIONS: Final = 1_000_000
"""Combinations of values all the texts of one description may compute together."""


@dataclass(slots=True)
class _XacroScope:
    """Where a xacro text's ``$()`` is substituted: the document's args, no anon names."""

    filename: str
    args: dict[str, ArgValue]
    anon: dict[str, ArgValue] = field(default_factory=dict)


_TOKENS: Final = (
    ("dollars", re.compile(r"\$\$+[{(]")),
    ("expression", re.compile(r"\$\{[^}]*\}")),
    ("extension", re.compile(r"\$\([^)]*\)")),
    ("text", re.compile(r"[^$]+|\$[^{($]+|\$$")),
)


_SYNTAX_ERRORS: Final = ("invalid Python expression", "cannot parse", "$(eval ...) may not")
"""Refusals that are xacro's failures too (Python does not compile it, or ``__``)."""


class XacroSyntaxError(Exception):
    """A text xacro's lexer does not accept (``${`` never closed)."""


def tokens(text: str) -> list[tuple[str, str]]:
    """``text`` cut as xacro's lexer cuts it, each token with its kind."""
    found: list[tuple[str, str]] = []
    position = 0
    while position < len(text):
        for kind, pattern in _TOKENS:
            match = pattern.match(text, position)
            if match is not None:
                found.append((kind, match.group(0)))
                position = match.end()
                break
        else:
            raise XacroSyntaxError(f"invalid expression: {text[position:]}")
    return found


class Walk(Protocol):
    """What evaluation needs from the running expansion."""

    space: ConditionSpace
    pc: BDD
    args: dict[str, Choice[Raw | Missing]]

    @property
    def location(self) -> Location: ...

    @property
    def filename(self) -> str: ...

    def unsupported(self, message: str) -> None: ...


Value = object
"""A leaf of an evaluated text: a typed value, a text (str or term), Deferred, or Fail."""


class Evaluator:
    """eval_text of one expansion."""

    def __init__(self, walk: Walk, substituter: Substituter) -> None:
        self.walk = walk
        self.space = walk.space
        self.substituter = substituter
        self.combinations = 0  # spent of MAX_TEXT_COMBINATIONS
        self._resolving: set[tuple[int, str]] = set()  # lazy properties being evaluated

    def text(self, text: str, table: Table) -> Choice[Value]:
        """xacro's ``eval_text``: a lone token's value as is, several joined as a string."""
        if "$" not in text:
            return Choice.const(self.space, text)
        try:
            found = tokens(text)
        except XacroSyntaxError as error:
            return self._fail(str(error))
        values = [self._token(kind, body, table) for kind, body in found]
        if len(values) == 1:
            return values[0]
        if not self._affordable(text, values):
            return self._unknown(text)
        return combine(values, _joined)

    def _token(self, kind: str, body: str, table: Table) -> Choice[Value]:
        if kind == "text":
            return Choice.const(self.space, body)
        if kind == "dollars":
            return Choice.const(self.space, body[1:])
        inner = self.text(body[2:-1], table)
        if kind == "expression":
            return inner.bind(lambda leaf: self._expression(leaf, table))
        return inner.bind(self._extension)

    # -- $() -------------------------------------------------------------------------------
    def _extension(self, inner: Value) -> Choice[Value]:
        if isinstance(inner, Fail):
            return Choice.const(self.space, inner)
        if not isinstance(inner, str):
            return self._unknown(f"$({inner})")
        text = f"$({inner})"
        if text == "$(cwd)":
            self.walk.unsupported("$(cwd) is the directory xacro runs in: not known")
            return self._unknown(text)
        if not text.startswith("$(eval "):
            try:
                for body in collect(text):
                    words = body.split()
                    if not words or words[0] not in XACRO_COMMANDS:
                        return self._fail(
                            f"Unknown substitution command [{body}]. "
                            f"Valid commands are {list(XACRO_COMMANDS)}"
                        )
            except SubstitutionError as error:
                return self._fail(str(error))
        scope = _XacroScope(self.walk.filename, dict(self.walk.args))
        resolved = self.substituter.resolve(text, scope)
        assert resolved is not None
        return resolved.map(_undefined_arg)

    # -- ${} -------------------------------------------------------------------------------
    def _expression(self, inner: Value, table: Table) -> Choice[Value]:
        if isinstance(inner, Fail):
            return Choice.const(self.space, inner)
        if not isinstance(inner, str) and not is_term(inner):
            return self._unknown(f"${{{inner}}}")
        expression: Text = inner  # type: ignore[assignment]
        # a part known per configuration (``'$(arg x)' == 'a'``) stands inside one token:
        # the names are those of the text with a number in its place
        probe = "".join(p if isinstance(p, str) else "0" for p in parts(expression))
        try:
            names = sorted(
                referenced_names(probe.strip(), frozenset(NAMESPACES), dunder_text=False)
            )
        except EvalRefused as refused:
            if refused.message.startswith(_SYNTAX_ERRORS):
                return self._fail(f"{refused.message} when evaluating expression '{inner}'")
            self.walk.unsupported(f"${{{expression}}}: {refused.message}")
            return self._unknown(f"${{{expression}}}")
        values = [table.lookup(name, self.walk.pc, self.lazy) for name in names]
        if not self._affordable(str(expression), values):
            return self._unknown(f"${{{expression}}}")

        def run(leaves: list[object]) -> Value:
            return self._evaluated(expression, names, leaves)

        if not values:
            return Choice.const(self.space, run([]))
        return combine(values, run)

    def _evaluated(self, expression: Text, names: Sequence[str], leaves: list[object]) -> Value:
        present = [(n, v) for n, v in zip(names, leaves, strict=True) if v is not ABSENT]
        for _name, leaf in present:
            if isinstance(leaf, Fail):
                return leaf
        try:
            if not isinstance(expression, str):
                raise Unread("the expression's text is known per configuration")
            return evaluate(expression.strip(), dict(present))
        except Unread:
            operands: list[Operand] = []
            for _name, leaf in present:
                operand = encode(leaf)
                if operand is None:
                    return self._opaque(f"${{{expression}}}")
                operands.append(operand)
            written = expression.strip() if isinstance(expression, str) else expression
            return Deferred(deferred(written, tuple(n for n, _ in present), operands))
        except EvalFailed as failure:
            return Fail(f"{failure.message} when evaluating expression '{expression}'", "xacro")
        except EvalRefused as refused:
            self.walk.unsupported(f"${{{expression}}}: {refused.message}")
            return self._opaque(f"${{{expression}}}")

    # -- lazy properties -------------------------------------------------------------------
    def lazy(self, lazy: Lazy, table: Table) -> Choice[object]:
        """A lazy property's value: its text evaluated in its table, read as a literal."""
        key = (id(table), lazy.text)
        if key in self._resolving:
            return self._fail(f"circular variable definition: {lazy.text}")
        self._resolving.add(key)
        try:
            return self.text(lazy.text, table).map(stored_value)
        finally:
            self._resolving.discard(key)

    # -- helpers ---------------------------------------------------------------------------
    def _affordable(self, text: str, choices: Sequence[Choice[object]]) -> bool:
        count = 1
        for choice in choices:
            count *= max(len(choice.branches), 1)
        if count <= 1:
            return True
        if count <= MAX_COMBINATIONS and self.combinations + count <= MAX_TEXT_COMBINATIONS:
            self.combinations += count
            return True
        self.walk.unsupported(f"{text[:120]} is not computed: {count} combinations of values")
        return False

    def _fail(self, message: str) -> Choice[Value]:
        return Choice.const(self.space, Fail(message, "xacro"))

    def _unknown(self, text: str) -> Choice[Value]:
        return Choice.const(self.space, self._opaque(text))

    @staticmethod
    def _opaque(text: str) -> Deferred:
        return Deferred(too_complex(text))


def stored_value(value: Value) -> Value:
    """A value as a table stores it (xacro's ``_eval_literal`` of a text)."""
    if isinstance(value, str) or is_term(value):
        return stored(value)  # type: ignore[arg-type]
    return value


def _joined(leaves: list[Value]) -> Value:
    for leaf in leaves:
        if isinstance(leaf, Fail):
            return leaf
    return concat([text_of(leaf) for leaf in leaves])


def _undefined_arg(value: Raw | Fail) -> Value:
    """xacro's message for an arg nobody set."""
    if isinstance(value, Fail) and value.code == "arg-undefined":
        return Fail(f"Undefined substitution argument {value.message}", "xacro")
    return value
