"""Restricted interpreter for roslaunch's ``$(eval EXPR)`` substitution.

roslaunch runs ``str(eval(EXPR))`` on launch-file text.  A static analyser has to predict that
string without ever executing launch-file content, so this module parses the expression with
:func:`ast.parse` (parsing runs no code) and *interprets* a whitelist of node types over plain
Python values.  It reproduces ``roslaunch.substitution_args._eval`` name resolution and
``roslaunch.loader.convert_value(value, 'auto')`` exactly, refuses everything outside the whitelist
(:class:`EvalRefused`), reports run-time errors where Python would raise them (:class:`EvalFailed`),
and guards against expressions built to exhaust memory or time.

Name resolution (as in roslaunch, where a ``_DictWrapper`` is eval's *locals* and ``{}`` its
globals):

1. ``arg anon dirname true false True False env optenv find`` and every name of :mod:`math`;
2. otherwise the launch arg of that name, converted with :func:`convert_auto`;
3. otherwise a Python builtin (only ``list dict map str float int bool len abs min max round
   sorted set frozenset tuple any all`` are allowed here; roslaunch would accept any builtin);
4. otherwise the name is undefined (:class:`EvalFailed`).

xacro's ``${}`` resolves names its own way (:attr:`EvalEnvironment.symbols`): the document's
typed properties first, then ``math``/``python`` namespaces (``math.pi``), then ``True``,
``False``, the builtins and math names; nothing else.

So an arg named like a math name (``e``, ``pi``, ``log``) is only reachable as ``arg('e')``, and
an arg named like a builtin (``len``) hides it.  Inside a comprehension body Python compiles free
names as globals, so roslaunch sees only the comprehension's own variables and the builtins
there; that quirk is reproduced too.

Allowed beyond names and literals: boolean/unary/binary operators (not ``@``), comparisons,
conditional expressions, subscripts and slices, tuple/list/set/dict displays, single-``for``
comprehensions and generator expressions, calls of the names above and of a fixed set of
``str`` methods (checked at run time to be called on a ``str``).  The ``MAX_*`` guards make the
evaluator refuse, never silently alter, results or total work beyond fixed bounds.

The package's modules, each used only by those after it: ``errors``, ``names`` (the
environment and the whitelist's tables), ``limits`` (the guards), ``checking`` (parsing and
the static whitelist check) and ``interpreter``; this module holds the public API.
"""

from __future__ import annotations

import ast
from collections.abc import Callable
from typing import TypeVar

from rosvar.interpreter.safe_eval.checking import _checked
from rosvar.interpreter.safe_eval.errors import CallRefused, EvalFailed, EvalRefused
from rosvar.interpreter.safe_eval.interpreter import _Interpreter, convert_auto
from rosvar.interpreter.safe_eval.limits import (
    MAX_COMBINATORIC_ARGUMENT,
    MAX_INT_BITS,
    MAX_ITERATIONS,
    MAX_NESTING,
    MAX_POW_EXPONENT,
    MAX_RENDERED,
    MAX_ROUND_DIGITS,
    MAX_SEQUENCE,
    MAX_WORK,
)
from rosvar.interpreter.safe_eval.names import EvalEnvironment, allowed_calls

_T = TypeVar("_T")

__all__ = [
    "MAX_COMBINATORIC_ARGUMENT",
    "MAX_INT_BITS",
    "MAX_ITERATIONS",
    "MAX_NESTING",
    "MAX_POW_EXPONENT",
    "MAX_RENDERED",
    "MAX_ROUND_DIGITS",
    "MAX_SEQUENCE",
    "MAX_WORK",
    "EvalEnvironment",
    "EvalFailed",
    "EvalRefused",
    "compared_literals",
    "convert_auto",
    "evaluate",
    "evaluate_value",
    "referenced_args",
    "referenced_names",
]


def referenced_args(expr: str) -> frozenset[str]:
    """Launch args the expression may read, so dependencies are known before evaluating.

    These are the bare names that are not eval functions, constants, math names or whitelisted
    builtins (and not comprehension-local), plus the literal names in ``arg('...')`` calls.  A
    computed ``arg(x)`` contributes only ``x``.  Raises :class:`EvalRefused` when the expression
    is not allowed at all, so callers can report it early.
    """
    _tree, _source, analysis = _checked(expr)
    return frozenset(analysis.args)


def referenced_names(
    expr: str, namespaces: frozenset[str] = frozenset(), dunder_text: bool = True
) -> frozenset[str]:
    """Every free name the expression reads or calls (xacro's properties may shadow any of
    them); raises :class:`EvalRefused` like :func:`referenced_args`; ``dunder_text`` as
    :attr:`EvalEnvironment.dunder_text`."""
    _tree, _source, analysis = _checked(expr, namespaces, dunder_text)
    return frozenset(analysis.names)


def compared_literals(expr: str) -> dict[str, set[str]]:
    """For each arg, the string forms of literals it is compared with (``==``, ``!=``, ``in``).

    Feeds value inference with candidate values: ``"arg('robot') == 'husky'"`` gives
    ``{'robot': {'husky'}}``, ``"x == 2"`` gives ``{'x': {'2'}}``.  The arg side may be wrapped
    in ``str()``/``int()``/``float()`` or ``.lower()``-like case/whitespace methods; the literal
    side may be a str/int/float/bool constant, a negated number, ``true``/``false``, or (for
    ``in``/``not in``) a tuple/list/set whose literal elements are taken.  Raises
    :class:`EvalRefused` like :func:`referenced_args`.
    """
    _tree, _source, analysis = _checked(expr)
    return {name: set(values) for name, values in analysis.compared.items()}


def evaluate(expr: str, env: EvalEnvironment) -> str:
    """roslaunch's ``str(eval(expr))`` under the whitelist, without executing any code.

    Raises :class:`EvalRefused` for disallowed expressions and exceeded resource guards, and
    :class:`EvalFailed` where roslaunch would raise at run time.
    """
    return _evaluated(expr, env, _Interpreter.run)


def evaluate_value(expr: str, env: EvalEnvironment) -> object:
    """The value of ``expr`` itself, not its text (xacro's ``${}``): under the same
    whitelist and guards as :func:`evaluate`."""
    return _evaluated(expr, env, _Interpreter.value)


def _evaluated(
    expr: str, env: EvalEnvironment, run: Callable[[_Interpreter, ast.Expression], _T]
) -> _T:
    try:
        tree, source, _analysis = _checked(expr, frozenset(env.namespaces), env.dunder_text)
    except CallRefused as refused:  # told in the words of what this environment allows
        message = f"calling '{refused.name}' is not allowed (only {allowed_calls(env)})"
        raise EvalRefused(message, refused.col) from None
    interpreter = _Interpreter(env, source)
    try:
        return run(interpreter, tree)
    except (EvalRefused, EvalFailed) as exc:
        if exc.col < 0:
            exc.col = source.prefix
        raise
    except RecursionError:
        raise EvalRefused("expression is nested too deeply to evaluate", source.prefix) from None
    except MemoryError:
        raise EvalRefused("evaluation ran out of memory", source.prefix) from None
    finally:
        interpreter.release()
