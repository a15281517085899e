"""xacro's values: how it reads a literal text, what it takes for true, and the values known
only per configuration.

xacro keeps properties typed: ``<xacro:property name="w" value="0.5"/>`` holds the float
0.5, a macro parameter ``n="2"`` the int 2, and ``${w * n}`` computes with them; a text that
holds a launch file's arg in its ``<other>`` slot cannot be read now. Such a value is
:class:`Deferred`: a term whose string is the value's ``str()``, read back as xacro reads a
literal. Expressions over deferred values are deferred in turn (term function
``xacro_eval``) and evaluated by the same restricted evaluator once a configuration gives the
strings, so the model stays exact for values nobody foresaw.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Final

from rosvar.interpreter.safe_eval import EvalEnvironment, EvalFailed, EvalRefused, evaluate_value
from rosvar.logic.atoms import register_predicate
from rosvar.logic.cells import register_predicate_texts, spellings
from rosvar.logic.terms import Apply, Hole, Operand, Term, TermError, register

TRUE_WORDS: Final = ("true", "True")
FALSE_WORDS: Final = ("false", "False")


@dataclass(frozen=True)
class Deferred:
    """A typed value known per configuration: ``term``'s string read as a literal
    (:func:`read_literal`); an expression's result of another type (a string that reads as a
    number) is read back the same way."""

    term: Term

    def __str__(self) -> str:
        return str(self.term)


def read_literal(text: str) -> object:
    """xacro's reading of a property or parameter text: a quoted string unquoted, a text
    with ``_`` kept (Python would read ``1_0`` as 10), else an int, a float, a boolean word,
    or the text itself."""
    if len(text) >= 2 and text[0] == "'" and text[-1] == "'":
        return text[1:-1]
    if "_" in text:
        return text
    for read in (int, float):
        try:
            return read(text)
        except ValueError:
            pass
    if text in TRUE_WORDS:
        return True
    if text in FALSE_WORDS:
        return False
    return text


def truth(value: object) -> bool:
    """xacro's ``get_boolean_value``: ``ValueError`` when the value is no boolean."""
    if isinstance(value, str):
        if value in TRUE_WORDS:
            return True
        if value in FALSE_WORDS:
            return False
        return bool(int(value))
    return bool(value)


def is_true(text: str) -> bool:
    try:
        return truth(text)
    except ValueError:
        return False


def is_false(text: str) -> bool:
    try:
        return not truth(text)
    except ValueError:
        return False


register_predicate("xacro-true", is_true, "{} is true for xacro")
register_predicate("xacro-false", is_false, "{} is false for xacro")
for _test in ("xacro-true", "xacro-false"):  # and any integer: 0 is false, others true
    register_predicate_texts(_test, (*spellings((*TRUE_WORDS, *FALSE_WORDS)), "0", "1", "2"))


def text_of(value: object) -> str | Term:
    """The text xacro writes for a value (``str()``): a deferred value's term as is."""
    if isinstance(value, Deferred):
        return value.term
    if isinstance(value, str | Apply | Hole):
        return value
    return str(value)


def stored(text: str | Term) -> object:
    """A text as a table stores it: read as a literal now, or deferred."""
    if isinstance(text, str):
        return read_literal(text)
    return Deferred(Apply("xacro_literal_text", (text,), display=str(text)))


def _literal_text(_host: object, text: str) -> str:
    return str(read_literal(text))


register("xacro_literal_text", _literal_text)


# -- deferred expressions --------------------------------------------------------------------

_ENCODED: Final[Mapping[type, str]] = {bool: "bool", int: "int", float: "float", str: "str"}


def encode(value: object) -> Operand | None:
    """A value as an operand of a deferred expression: a deferred value's term, a plain
    scalar as ``(type, text)``; None for what a term cannot carry (lists, blocks)."""
    if isinstance(value, Deferred):
        return value.term
    kind = _ENCODED.get(type(value))
    if kind is None:
        return None
    return (kind, repr(value) if isinstance(value, float) else str(value))


def _decode(operand: object) -> object:
    if isinstance(operand, str):  # a term's string
        return read_literal(operand)
    assert isinstance(operand, tuple)
    kind, text = operand
    if kind == "bool":
        return text == "True"
    if kind == "int":
        return int(text)
    if kind == "float":
        return float(text)
    return text


def deferred(expression: str | Term, names: tuple[str, ...], operands: list[Operand]) -> Term:
    """The term of ``expression`` over the values of ``names`` (``operands``, encoded): its
    string is the value's ``str()``."""
    return Apply("xacro_eval", (expression, names, *operands), display=f"${{{expression}}}")


def _evaluate_deferred(_host: object, expression: str, *operands: object) -> str:
    names = operands[0]
    assert isinstance(names, tuple)
    values = dict(zip(names, map(_decode, operands[1:]), strict=True))
    try:
        return str(evaluate(expression.strip(), values))
    except (EvalRefused, EvalFailed) as error:
        raise TermError(f"${{{expression}}}: {error.message}") from None


register("xacro_eval", _evaluate_deferred)


# -- the environment of ${} ------------------------------------------------------------------

XACRO_GLOBALS: Final = frozenset(
    {
        "list", "dict", "map", "len", "str", "float", "int", "bool", "True", "False", "min",
        "max", "round", "sorted", "range", "python", "math", "xacro", "load_yaml",
        "abs_filename", "dotify",
        *(name for name in vars(math) if not name.startswith("_")),
    }
)  # fmt: skip
"""The global symbols of xacro's ``${}``: a few builtins, the math module's names, the
``python``, ``math`` and ``xacro`` namespaces and three deprecated functions."""
_PYTHON_NAMESPACE: Final = (
    "list", "dict", "map", "len", "str", "float", "int", "bool", "True", "False", "min",
    "max", "round", "abs", "sorted",
)  # fmt: skip
NAMESPACES: Final[Mapping[str, Mapping[str, str]]] = {
    "math": {name: name for name in vars(math) if not name.startswith("_")},
    "python": {name: name for name in _PYTHON_NAMESPACE},
}
"""The namespaces rosvar evaluates (``xacro.*`` reads files and prints: it is not)."""


class Unread(EvalRefused):
    """The expression reads a value known only per configuration: it is deferred."""


def evaluate(expression: str, values: Mapping[str, object]) -> object:
    """The value of ``${expression}`` where the names of ``values`` are properties (the
    others xacro's globals): ``EvalFailed`` where xacro fails, ``EvalRefused`` for what
    rosvar does not evaluate, :class:`Unread` when it reads a :class:`Deferred` value (one
    that ``and``/``or``/``if`` skip is not read)."""
    return evaluate_value(expression, environment(values))


def environment(values: Mapping[str, object]) -> EvalEnvironment:
    def symbols(name: str) -> object:
        if name in values:
            value = values[name]
            if isinstance(value, Deferred):
                raise Unread(f"{name} is known per configuration")
            return value
        if name not in XACRO_GLOBALS:
            raise EvalFailed(f"NameError: name '{name}' is not defined")
        if name in NAMESPACES or name in _EVALUATED_GLOBALS:
            raise KeyError(name)
        raise EvalRefused(f"xacro's '{name}' is not evaluated by rosvar")

    return EvalEnvironment(
        lookup_arg=_no_arg, symbols=symbols, namespaces=NAMESPACES, dunder_text=False
    )


_EVALUATED_GLOBALS: Final = XACRO_GLOBALS - {
    "range", "xacro", "load_yaml", "abs_filename", "dotify",
}  # fmt: skip


def _no_arg(name: str) -> str:
    raise KeyError(name)
