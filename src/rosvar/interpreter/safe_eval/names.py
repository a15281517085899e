"""What an expression can see: the caller's environment, and the names and operators the
whitelist allows."""

from __future__ import annotations

import ast
import builtins
import math
import operator
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from typing import Any, Final


@dataclass(frozen=True)
class EvalEnvironment:
    """What an expression can see outside itself; the caller decides how args and hosts resolve.

    ``lookup_arg`` returns the raw string value of a launch arg and raises ``KeyError`` if it is
    undefined.  ``functions`` supplies the host functions ``env optenv find anon dirname`` (other
    keys are ignored; ``arg`` is always built from ``lookup_arg``).  A host function that is not
    supplied makes its calls :class:`EvalRefused`.  Exceptions raised by either callable become
    :class:`EvalFailed`, except :class:`EvalRefused`/:class:`EvalFailed`, which pass through.
    """

    lookup_arg: Callable[[str], str]
    functions: Mapping[str, Callable[..., object]] = field(default_factory=dict)
    symbols: Callable[[str], object] | None = None
    """Set for xacro's ``${}``: a bare name is first the typed value this returns (a
    property; ``KeyError`` when none is defined), then a namespace of ``namespaces``, then
    one of :data:`_SYMBOL_GLOBALS`; roslaunch's names (args, ``true``, host functions) are
    not names there, as in xacro's symbol table."""
    namespaces: Mapping[str, Mapping[str, str]] = field(default_factory=dict)
    """Namespaces whose members an expression reads as ``ns.member`` (xacro's ``math.pi``,
    ``python.len``): each member stands for the global name it maps to."""
    dunder_text: bool = True
    """Whether a ``__`` anywhere in the text is refused, as roslaunch's ``$(eval)`` refuses it
    (a path holding ``__`` too); ROS 2's ``PythonExpression`` and xacro refuse only names
    (identifiers, attributes) that hold one, which the whitelist refuses in every case."""


_HOST_FUNCTION_NAMES: Final = frozenset({"arg", "env", "optenv", "find", "anon", "dirname"})
_BOOL_NAMES: Final[Mapping[str, bool]] = {
    "true": True,
    "false": False,
    "True": True,
    "False": False,
}
_MATH_NAMES: Final[Mapping[str, object]] = {
    name: value for name, value in vars(math).items() if "__" not in name
}
_BUILTIN_FUNCTIONS: Final[Mapping[str, Callable[..., object]]] = {
    name: getattr(builtins, name)
    for name in (
        "list", "dict", "map", "str", "float", "int",  # roslaunch's own __builtins__ list
        "bool", "len", "abs", "min", "max", "round", "sorted",
        "set", "frozenset", "tuple", "any", "all",  # ros2/launch's PythonExpression's too
    )
}  # fmt: skip
_PYTHON_BUILTIN_NAMES: Final = frozenset(name for name in dir(builtins) if "__" not in name)
#: The global names of a symbols environment (xacro's): no args, host functions or
#: lower-case booleans.
_SYMBOL_GLOBALS: Final = frozenset({"True", "False"}).union(_MATH_NAMES, _BUILTIN_FUNCTIONS)
_STR_METHODS: Final = frozenset(
    {
        "lower", "upper", "strip", "lstrip", "rstrip", "startswith", "endswith", "replace",
        "split", "join", "format", "capitalize", "title", "isdigit", "isalpha", "isalnum",
        "zfill", "count", "find", "rfind", "index",
    }
)  # fmt: skip
#: Bare names that never read a launch arg.  Whitelisted builtins are included: they would
#: only read an arg that shadows the builtin, which real launch files do not declare.
_NOT_ARG_NAMES: Final = _HOST_FUNCTION_NAMES.union(_BOOL_NAMES, _MATH_NAMES, _BUILTIN_FUNCTIONS)
_CALLABLE_NAMES: Final = _HOST_FUNCTION_NAMES.union(
    (name for name, value in _MATH_NAMES.items() if callable(value)), _BUILTIN_FUNCTIONS
)
ROSLAUNCH_CALLS: Final = "whitelisted builtins, math functions and arg/env/optenv/find/anon/dirname"
"""What roslaunch's ``$(eval)`` may call, as a refusal names it."""


def allowed_calls(env: EvalEnvironment) -> str:
    """What an expression evaluated in ``env`` may call, as a refusal names it: roslaunch's
    names where it has them; in a symbols environment (ROS 2's ``$(eval)`` and
    ``PythonExpression``, xacro's ``${}``), which has none of them, the builtins rosvar
    evaluates and math's functions."""
    if env.symbols is None:
        return ROSLAUNCH_CALLS
    builtins_ = ", ".join(sorted(_BUILTIN_FUNCTIONS))
    math_ = "as NAME or math.NAME" if "math" in env.namespaces else "as NAME"
    return f"the builtins {builtins_} and math's functions, {math_}"


_LITERAL_TYPES: Final = (str, int, float, bool, type(None))
_CONVERSION_FUNCTIONS: Final = frozenset({"str", "int", "float"})
_CASE_METHODS: Final = frozenset({"lower", "upper", "strip", "lstrip", "rstrip"})

_UNARY_OPS: Final[Mapping[type[ast.unaryop], Callable[[Any], Any]]] = {
    ast.Not: operator.not_,
    ast.USub: operator.neg,
    ast.UAdd: operator.pos,
    ast.Invert: operator.invert,
}


REFUSED_NODES: Final[Mapping[type[ast.AST], str]] = {
    ast.Lambda: "lambda expressions are not allowed",
    ast.NamedExpr: "assignment expressions (:=) are not allowed",
    ast.Starred: "starred unpacking (*) is not allowed",
    ast.JoinedStr: "f-strings are not allowed",
    ast.FormattedValue: "f-strings are not allowed",
    ast.Await: "await is not allowed",
    ast.Yield: "yield is not allowed",
    ast.YieldFrom: "yield is not allowed",
}
_GETITEM: Final[Callable[[Any, Any], Any]] = operator.getitem
_MULT: Final = ast.Mult()
_EQ: Final = ast.Eq()
_CONTAINERS: Final = (list, tuple, dict, set, frozenset)
_SIZED: Final = (str, list, tuple, dict, set, frozenset)
#: Calls whose cost does not depend on the size of their arguments.
_CHEAP_FUNCTIONS: Final = frozenset({"len", "bool"})
#: Calls that compare or hash every element of an iterable argument: an iterator is
#: materialised first so that its elements can be weighed (they consume it entirely anyway).
_CONSUMING_FUNCTIONS: Final = frozenset(
    {"sorted", "min", "max", "dict", "set", "frozenset", "tuple"}
)
_END: Final = object()
