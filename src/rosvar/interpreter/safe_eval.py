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
   sorted`` are allowed here; roslaunch would accept any builtin);
4. otherwise the name is undefined (:class:`EvalFailed`).

So an arg named like a math name (``e``, ``pi``, ``log``) is only reachable as ``arg('e')``, and
an arg named like a builtin (``len``) hides it.  Inside a comprehension body Python compiles free
names as globals, so roslaunch sees only the comprehension's own variables and the builtins
there; that quirk is reproduced too.

Allowed beyond names and literals: boolean/unary/binary operators (not ``@``), comparisons,
conditional expressions, subscripts and slices, tuple/list/set/dict displays, single-``for``
comprehensions and generator expressions, calls of the names above and of a fixed set of
``str`` methods (checked at run time to be called on a ``str``).  The ``MAX_*`` guards make the
evaluator refuse, never silently alter, results or total work beyond fixed bounds.
"""

from __future__ import annotations

import ast
import builtins
import functools
import itertools
import math
import operator
import re
import string
import warnings
from collections import ChainMap
from collections.abc import Callable, Iterable, Iterator, Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any, Final, NoReturn, TypeVar, cast

from rosvar.interpreter.typed_values import convert_scalar

__all__ = [
    "MAX_COMBINATORIC_ARGUMENT",
    "MAX_INT_BITS",
    "MAX_ITERATIONS",
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
    "referenced_args",
]

#: ``a ** b`` on ints is refused above this exponent (huge results, slow to compute).
MAX_POW_EXPONENT: Final = 10_000
#: Integer results of ``**``, ``*``, ``<<`` and ``prod`` are refused above this many bits.
MAX_INT_BITS: Final = 1_000_000
#: Strings/lists/tuples built by ``*``, ``+``, ``join``, ``replace``, ``zfill`` stay below this.
MAX_SEQUENCE: Final = 1_000_000
#: Text produced by ``str()``, ``%`` and ``str.format`` (estimated beforehand) stays below this.
MAX_RENDERED: Final = 2_000_000
#: Work budget of one evaluation, in characters/elements: sizes of the strings and containers
#: produced, compared, searched, ordered or rendered.  Each single result is bounded by the
#: limits above, but a comprehension could otherwise repeat expensive work many times.
MAX_WORK: Final = 20_000_000
#: Comprehension iterations plus function calls (``map``, ``key=``...) per evaluation.
MAX_ITERATIONS: Final = 100_000
#: ``factorial``/``comb``/``perm`` arguments above this are refused (their cost explodes).
MAX_COMBINATORIC_ARGUMENT: Final = 10_000
#: ``round(int, ndigits)`` computes ``10 ** -ndigits``; refused above this magnitude.
MAX_ROUND_DIGITS: Final = 10_000

_UNPLACED: Final = -1  # column of an error raised where no AST node is at hand
_DUNDER_MESSAGE: Final = "$(eval ...) may not contain double underscore expressions"

_T = TypeVar("_T")


class EvalRefused(Exception):
    """The expression uses something the restricted evaluator does not allow, or is not Python.

    ``col`` is the 0-based character offset in the expression text of the offending construct.
    Host callables may raise it without a column; the evaluator then fills in the call's.
    """

    def __init__(self, message: str, col: int = _UNPLACED) -> None:
        super().__init__(message)
        self.message = message
        self.col = col


class EvalFailed(Exception):
    """The expression is allowed but fails at run time where Python/roslaunch would raise.

    ``col`` is the 0-based character offset of the failing construct, for diagnostics.
    """

    def __init__(self, message: str, col: int = _UNPLACED) -> None:
        super().__init__(message)
        self.message = message
        self.col = col


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


# --------------------------------------------------------------------------- name tables

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
    )
}  # fmt: skip
_PYTHON_BUILTIN_NAMES: Final = frozenset(name for name in dir(builtins) if "__" not in name)
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
_LITERAL_TYPES: Final = (str, int, float, bool, type(None))
_CONVERSION_FUNCTIONS: Final = frozenset({"str", "int", "float"})
_CASE_METHODS: Final = frozenset({"lower", "upper", "strip", "lstrip", "rstrip"})

_BIN_OPS: Final[Mapping[type[ast.operator], Callable[[Any, Any], Any]]] = {
    ast.Add: operator.add,
    ast.Sub: operator.sub,
    ast.Mult: operator.mul,
    ast.Div: operator.truediv,
    ast.FloorDiv: operator.floordiv,
    ast.Mod: operator.mod,
    ast.Pow: operator.pow,
    ast.LShift: operator.lshift,
    ast.RShift: operator.rshift,
    ast.BitOr: operator.or_,
    ast.BitXor: operator.xor,
    ast.BitAnd: operator.and_,
}
_UNARY_OPS: Final[Mapping[type[ast.unaryop], Callable[[Any], Any]]] = {
    ast.Not: operator.not_,
    ast.USub: operator.neg,
    ast.UAdd: operator.pos,
    ast.Invert: operator.invert,
}


def _contains(item: Any, container: Any) -> bool:
    return item in container


def _not_contains(item: Any, container: Any) -> bool:
    return item not in container


_COMPARE_OPS: Final[Mapping[type[ast.cmpop], Callable[[Any, Any], Any]]] = {
    ast.Eq: operator.eq,
    ast.NotEq: operator.ne,
    ast.Lt: operator.lt,
    ast.LtE: operator.le,
    ast.Gt: operator.gt,
    ast.GtE: operator.ge,
    ast.Is: operator.is_,
    ast.IsNot: operator.is_not,
    ast.In: _contains,
    ast.NotIn: _not_contains,
}
_REFUSED_NODES: Final[Mapping[type[ast.AST], str]] = {
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
_CONSUMING_FUNCTIONS: Final = frozenset({"sorted", "min", "max", "dict"})
_END: Final = object()


# --------------------------------------------------------------------------- public API


def convert_auto(value: str) -> bool | int | float | str:
    """roslaunch's ``convert_value(value, 'auto')``: how eval sees an arg's raw string.

    Replicated statement by statement because the quirks matter: ``'1_0'`` stays a string,
    ``'1_0.5'`` becomes ``10.5``, ``' 7 '`` becomes ``7``, ``'TRUE'`` becomes ``True``.
    """
    return cast(bool | int | float | str, convert_scalar(value, "auto"))


def referenced_args(expr: str) -> frozenset[str]:
    """Launch args the expression may read, so dependencies are known before evaluating.

    These are the bare names that are not eval functions, constants, math names or whitelisted
    builtins (and not comprehension-local), plus the literal names in ``arg('...')`` calls.  A
    computed ``arg(x)`` contributes only ``x``.  Raises :class:`EvalRefused` when the expression
    is not allowed at all, so callers can report it early.
    """
    _tree, _source, analysis = _checked(expr)
    return frozenset(analysis.args)


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
    tree, source, _analysis = _checked(expr)
    interpreter = _Interpreter(env, source)
    try:
        return interpreter.run(tree)
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


# --------------------------------------------------------------------------- parsing

_NEWLINE: Final = re.compile(r"\r\n|\r|\n")


class _Source:
    """Maps AST positions (1-based lines, UTF-8 byte columns) to character offsets in the text."""

    def __init__(self, text: str, prefix: int) -> None:
        self.text = text
        self.prefix = prefix  # leading blanks eval() strips and ast.parse() would reject
        self._starts = [0, *(match.end() for match in _NEWLINE.finditer(text))]

    def offset(self, lineno: int | None, char_col: int) -> int:
        """Absolute offset of a (line, character column) position, clamped to the text."""
        line = min(max((lineno or 1) - 1, 0), len(self._starts) - 1)
        return self.prefix + min(self._starts[line] + max(char_col, 0), len(self.text))

    def _chars(self, lineno: int | None, byte_col: int | None) -> int:
        line = min(max((lineno or 1) - 1, 0), len(self._starts) - 1)
        end = self._starts[line + 1] if line + 1 < len(self._starts) else len(self.text)
        encoded = self.text[self._starts[line] : end].encode("utf-8", "surrogatepass")
        return self.offset(lineno, len(encoded[: max(byte_col or 0, 0)].decode("utf-8", "ignore")))

    def col(self, node: ast.AST) -> int:
        """Offset where ``node`` starts."""
        return self._chars(getattr(node, "lineno", None), getattr(node, "col_offset", 0))

    def attr_col(self, node: ast.Attribute) -> int:
        """Offset of the attribute name (more useful than the start of the receiver)."""
        end = node.end_col_offset if node.end_col_offset is not None else node.col_offset
        return self._chars(node.end_lineno, end - len(node.attr.encode("utf-8")))


@functools.lru_cache(maxsize=4096)
def _checked(expr: str) -> tuple[ast.Expression, _Source, _Analyser]:
    """Parsed and checked once per text (read-only afterwards): an expression is evaluated
    for every combination of the values of the args it reads, in every includer."""
    tree, source = _parse(expr)
    return tree, source, _analyse(tree, source)


def _parse(expr: str) -> tuple[ast.Expression, _Source]:
    """Parse like ``eval`` would (leading blanks stripped); never compiles to code."""
    dunder = expr.find("__")
    if dunder >= 0:
        raise EvalRefused(_DUNDER_MESSAGE, dunder)
    text = expr.lstrip(" \t")
    source = _Source(text, len(expr) - len(text))
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")  # invalid escapes etc. are not our diagnostics
            tree = ast.parse(text, mode="eval")
    except SyntaxError as exc:
        col = source.offset(exc.lineno, (exc.offset or 1) - 1)
        raise EvalRefused(f"invalid Python expression: {exc.msg}", col) from None
    except (ValueError, RecursionError, MemoryError) as unparsable:
        raise EvalRefused(f"cannot parse expression: {unparsable}", source.prefix) from None
    return tree, source


# --------------------------------------------------------------------------- static analysis


class _Analyser:
    """Whitelist check; also records the args an expression reads and the literals it compares."""

    def __init__(self, source: _Source) -> None:
        self._source = source
        self.args: set[str] = set()
        self.compared: dict[str, set[str]] = {}

    def _refuse(self, message: str, node: ast.AST) -> NoReturn:
        raise EvalRefused(message, self._source.col(node))

    def _check_identifier(self, name: str | None, node: ast.AST) -> None:
        # NFKC-normalised identifiers can contain '__' that the raw-text check missed.
        if name is not None and "__" in name:
            self._refuse(_DUNDER_MESSAGE, node)

    def visit(self, node: ast.expr, bound: frozenset[str] | None) -> None:
        """Check ``node``; ``bound`` is None at top level, else the comprehension's names."""
        if isinstance(node, ast.Constant):
            if type(node.value) not in _LITERAL_TYPES:
                self._refuse(f"{type(node.value).__name__} literals are not allowed", node)
        elif isinstance(node, ast.Name):
            self._check_identifier(node.id, node)
            if bound is None and node.id not in _NOT_ARG_NAMES:
                self.args.add(node.id)
        elif isinstance(node, ast.BoolOp):
            for value in node.values:
                self.visit(value, bound)
        elif isinstance(node, ast.UnaryOp):
            self.visit(node.operand, bound)
        elif isinstance(node, ast.BinOp):
            if type(node.op) not in _BIN_OPS:
                self._refuse(f"the {type(node.op).__name__} operator is not allowed", node)
            self.visit(node.left, bound)
            self.visit(node.right, bound)
        elif isinstance(node, ast.Compare):
            self.visit(node.left, bound)
            for comparator in node.comparators:
                self.visit(comparator, bound)
            if bound is None:
                self._record_comparisons(node)
        elif isinstance(node, ast.IfExp):
            self.visit(node.test, bound)
            self.visit(node.body, bound)
            self.visit(node.orelse, bound)
        elif isinstance(node, ast.Subscript):
            self.visit(node.value, bound)
            self.visit(node.slice, bound)
        elif isinstance(node, ast.Slice):
            for part in (node.lower, node.upper, node.step):
                if part is not None:
                    self.visit(part, bound)
        elif isinstance(node, (ast.Tuple, ast.List, ast.Set)):
            for element in node.elts:
                self.visit(element, bound)
        elif isinstance(node, ast.Dict):
            for key, value in zip(node.keys, node.values, strict=True):
                if key is None:
                    self._refuse("dict unpacking (**) is not allowed", value)
                self.visit(key, bound)
                self.visit(value, bound)
        elif isinstance(node, ast.Call):
            self._visit_call(node, bound)
        elif isinstance(node, (ast.ListComp, ast.SetComp, ast.DictComp, ast.GeneratorExp)):
            self._visit_comprehension(node, bound)
        elif isinstance(node, ast.Attribute):
            raise EvalRefused(
                f"attribute access '.{node.attr}' is not allowed"
                " (only calls of whitelisted str methods)",
                self._source.attr_col(node),
            )
        else:
            message = _REFUSED_NODES.get(type(node), f"{type(node).__name__} is not allowed")
            self._refuse(message, node)

    def _visit_call(self, node: ast.Call, bound: frozenset[str] | None) -> None:
        func = node.func
        if isinstance(func, ast.Name):
            self._check_identifier(func.id, func)
            if func.id not in _CALLABLE_NAMES:
                self._refuse(
                    f"calling '{func.id}' is not allowed (only whitelisted builtins, math"
                    " functions and arg/env/optenv/find/anon/dirname)",
                    func,
                )
            if bound is None and func.id == "arg":
                name = _literal_arg_name(node)
                if name is not None:
                    self.args.add(name)
        elif isinstance(func, ast.Attribute):
            self._check_identifier(func.attr, func)
            if func.attr not in _STR_METHODS:
                raise EvalRefused(
                    f"method '{func.attr}' is not allowed (only whitelisted str methods)",
                    self._source.attr_col(func),
                )
            self.visit(func.value, bound)
        else:
            self._refuse("only named functions and str methods may be called", func)
        for argument in node.args:
            self.visit(argument, bound)
        for keyword in node.keywords:
            if keyword.arg is None:
                self._refuse("keyword unpacking (**) is not allowed", keyword)
            self._check_identifier(keyword.arg, keyword)
            self.visit(keyword.value, bound)

    def _visit_comprehension(
        self,
        node: ast.ListComp | ast.SetComp | ast.DictComp | ast.GeneratorExp,
        bound: frozenset[str] | None,
    ) -> None:
        if len(node.generators) != 1:
            self._refuse("only comprehensions with a single 'for' are allowed", node)
        generator = node.generators[0]
        if generator.is_async:
            self._refuse("async comprehensions are not allowed", node)
        names = self._target_names(generator.target)
        self.visit(generator.iter, bound)  # evaluated in the enclosing scope
        inner = (bound or frozenset()) | names
        for condition in generator.ifs:
            self.visit(condition, inner)
        if isinstance(node, ast.DictComp):
            self.visit(node.key, inner)
            self.visit(node.value, inner)
        else:
            self.visit(node.elt, inner)

    def _target_names(self, target: ast.expr) -> frozenset[str]:
        if isinstance(target, ast.Name):
            self._check_identifier(target.id, target)
            return frozenset({target.id})
        if isinstance(target, (ast.Tuple, ast.List)):
            names: set[str] = set()
            for element in target.elts:
                names |= self._target_names(element)
            return frozenset(names)
        self._refuse("a comprehension may only assign to names", target)

    def _record_comparisons(self, node: ast.Compare) -> None:
        operands = [node.left, *node.comparators]
        for index, op in enumerate(node.ops):
            left, right = operands[index], operands[index + 1]
            if isinstance(op, (ast.Eq, ast.NotEq)):
                for arg_side, literal_side in ((left, right), (right, left)):
                    name, text = _compared_arg(arg_side), _literal_text(literal_side)
                    if name is not None and text is not None:
                        self.compared.setdefault(name, set()).add(text)
            elif isinstance(op, (ast.In, ast.NotIn)) and isinstance(
                right, (ast.Tuple, ast.List, ast.Set)
            ):
                name = _compared_arg(left)
                texts = [_literal_text(element) for element in right.elts]
                if name is not None and any(text is not None for text in texts):
                    self.compared.setdefault(name, set()).update(t for t in texts if t is not None)


def _analyse(tree: ast.Expression, source: _Source) -> _Analyser:
    analyser = _Analyser(source)
    try:
        analyser.visit(tree.body, None)
    except RecursionError:
        raise EvalRefused("expression is nested too deeply", source.prefix) from None
    return analyser


def _literal_arg_name(call: ast.Call) -> str | None:
    """The name in ``arg('name')`` / ``arg(name='name')`` when it is a string literal."""
    argument: ast.expr | None = None
    if len(call.args) == 1 and not call.keywords:
        argument = call.args[0]
    elif not call.args and len(call.keywords) == 1 and call.keywords[0].arg == "name":
        argument = call.keywords[0].value
    if isinstance(argument, ast.Constant) and isinstance(argument.value, str):
        return argument.value
    return None


def _compared_arg(node: ast.expr) -> str | None:
    """The arg an operand of a comparison stands for, looking through conversions."""
    while isinstance(node, ast.Call):
        func = node.func
        if isinstance(func, ast.Name) and func.id == "arg":
            return _literal_arg_name(node)
        if node.keywords:
            return None
        if isinstance(func, ast.Name) and func.id in _CONVERSION_FUNCTIONS and len(node.args) == 1:
            node = node.args[0]
        elif isinstance(func, ast.Attribute) and func.attr in _CASE_METHODS and not node.args:
            node = func.value
        else:
            return None
    if isinstance(node, ast.Name) and node.id not in _NOT_ARG_NAMES:
        return node.id
    return None


def _literal_text(node: ast.expr) -> str | None:
    """The string form of a literal operand, as an arg's raw value would be written."""
    if isinstance(node, ast.Constant) and type(node.value) in (str, int, float, bool):
        return str(node.value)
    if (
        isinstance(node, ast.UnaryOp)
        and isinstance(node.op, (ast.USub, ast.UAdd))
        and isinstance(node.operand, ast.Constant)
        and type(node.operand.value) in (int, float)
    ):
        number = cast("int | float", node.operand.value)
        return str(-number if isinstance(node.op, ast.USub) else number)
    if isinstance(node, ast.Name) and node.id in _BOOL_NAMES:
        return str(_BOOL_NAMES[node.id])
    return None


# --------------------------------------------------------------------------- resource guards


class _Sizer:
    """Upper-bound estimates of ``len(str(value))``, stopping once past :data:`MAX_WORK`.

    Values are never mutated once built, so container sizes are remembered by identity (the
    container is kept alive, so its id cannot be reused): ``[big] * n``, or ``big`` rendered
    again and again by ``map(str, ...)``, is walked once per evaluation.
    """

    def __init__(self) -> None:
        self._known: dict[int, tuple[object, int]] = {}

    def size(self, item: object) -> int:
        if isinstance(item, str):
            return len(item) + 2
        if isinstance(item, bool) or item is None:
            return 5
        if isinstance(item, int):
            return item.bit_length() * 31 // 100 + 2
        if isinstance(item, float):
            return 24
        if isinstance(item, (list, tuple, set, frozenset, dict)):
            known = self._known.get(id(item))
            if known is not None:
                return known[1]
            elements: Iterable[object] = (
                itertools.chain(item.keys(), item.values()) if isinstance(item, dict) else item
            )
            total = 2 + 2 * len(item)
            for element in elements:  # common scalars inline: this loop is the hot spot
                kind = type(element)
                if kind is str:
                    total += len(cast(str, element)) + 2
                elif kind is int:
                    total += cast(int, element).bit_length() * 31 // 100 + 2
                else:
                    total += self.size(element)
                if total > MAX_WORK:
                    break
            self._known[id(item)] = (item, total)
            return total
        return len(repr(item)) if isinstance(item, _Function) else 100


def _small_number(digits: str) -> int:
    """A width/precision from a format string; absurdly long digit runs count as too big."""
    return int(digits) if len(digits) <= 8 else MAX_WORK + 1


def _repeat_size(sequence: object, count: object) -> int:
    if isinstance(sequence, (str, list, tuple)) and isinstance(count, int):
        return len(sequence) * count
    return 0


def _binop_refusal(op: ast.operator, left: object, right: object, sizer: _Sizer) -> str | None:
    """Why ``left op right`` would produce a result too large to compute, if it would."""
    if isinstance(op, ast.Pow) and isinstance(left, int) and isinstance(right, int):
        if right > MAX_POW_EXPONENT:
            return f"exponent {right} of ** exceeds the limit of {MAX_POW_EXPONENT}"
        if right > 0 and left.bit_length() * right > MAX_INT_BITS:
            return f"result of ** would exceed {MAX_INT_BITS} bits"
    elif isinstance(op, ast.Mult):
        if isinstance(left, int) and isinstance(right, int):
            if left.bit_length() + right.bit_length() > MAX_INT_BITS:
                return f"result of * would exceed {MAX_INT_BITS} bits"
        elif max(_repeat_size(left, right), _repeat_size(right, left)) > MAX_SEQUENCE:
            return f"repetition would exceed {MAX_SEQUENCE} elements"
    elif isinstance(op, ast.Add):
        if (
            isinstance(left, (str, list, tuple))
            and isinstance(right, (str, list, tuple))
            and len(left) + len(right) > MAX_SEQUENCE
        ):
            return f"concatenation would exceed {MAX_SEQUENCE} elements"
    elif isinstance(op, ast.LShift):
        if (
            isinstance(left, int)
            and isinstance(right, int)
            and left
            and right > 0
            and left.bit_length() + right > MAX_INT_BITS
        ):
            return f"result of << would exceed {MAX_INT_BITS} bits"
    elif isinstance(op, ast.Mod) and isinstance(left, str):
        return _printf_refusal(left, right, sizer)
    return None


_PRINTF_SPEC: Final = re.compile(
    r"%(?:\([^)]*\))?[-#0 +]*(?P<width>\*|\d+)?(?:\.(?P<precision>\*|\d*))?[hlL]?.?", re.DOTALL
)


def _printf_refusal(template: str, values: object, sizer: _Sizer) -> str | None:
    """Refuse ``%``-formatting whose output would exceed :data:`MAX_RENDERED`."""
    padding = 0
    fields = 0
    for match in _PRINTF_SPEC.finditer(template):
        width, precision = match["width"] or "", match["precision"] or ""
        if "*" in width + precision:
            return "'*' widths in %-formatting are not supported"
        padding += _small_number(width or "0") + _small_number(precision or "0")
        fields += 1
        if padding > MAX_RENDERED:
            break
    # A tuple's items are consumed once each; a mapping's values may be reused by every field.
    if isinstance(values, tuple):
        inserted = sizer.size(values)
    elif isinstance(values, Mapping):
        inserted = fields * sizer.size(values)
    else:
        inserted = sizer.size(values)
    if len(template) + padding + inserted > MAX_RENDERED:
        return f"%-formatting would produce more than {MAX_RENDERED} characters"
    return None


_FORMATTER: Final = string.Formatter()


def _has_attribute_access(field_name: str) -> bool:
    in_brackets = False
    for char in field_name:
        if char == "[":
            in_brackets = True
        elif char == "]":
            in_brackets = False
        elif char == "." and not in_brackets:
            return True
    return False


def _format_refusal(
    template: str, args: Sequence[object], kwargs: Mapping[str, object], sizer: _Sizer
) -> str | None:
    """Refuse ``str.format`` that reaches attributes or would exceed :data:`MAX_RENDERED`."""
    try:
        fields = list(_FORMATTER.parse(template))
    except ValueError:
        return None  # str.format itself reports the malformed template
    total = len(template)
    sizes: dict[int | str, int] = {}
    auto = 0
    for _literal, name, spec, _conversion in fields:
        if name is None:
            continue
        if _has_attribute_access(name):
            return f"attribute access in format field '{{{name}}}' is not allowed"
        if spec and "{" in spec:
            return "nested replacement fields in a format spec are not supported"
        total += sum(_small_number(digits) for digits in re.findall(r"\d+", spec or ""))
        head = re.split(r"[.\[]", name, maxsplit=1)[0]
        key: int | str
        if not head:
            key, auto = auto, auto + 1
        elif head.isdecimal() and len(head) <= 8:
            key = int(head)
        else:
            key = head
        if key not in sizes:
            if isinstance(key, int):
                sizes[key] = sizer.size(args[key]) if key < len(args) else 0
            else:
                sizes[key] = sizer.size(kwargs[key]) if key in kwargs else 0
        total += sizes[key]
        if total > MAX_RENDERED:
            return f"str.format would produce more than {MAX_RENDERED} characters"
    return None


def _iterate(value: object) -> Iterator[object]:
    return iter(cast("Iterable[object]", value))


def _lookup_or_none(lookup: Callable[[str], str], name: str) -> str | None:
    try:
        return lookup(name)
    except KeyError:
        return None


# --------------------------------------------------------------------------- interpreter


class _Function:
    """A callable value the expression may use; every call is charged to the evaluation's budgets.

    Wrapping (rather than exposing the raw builtin) keeps guards in force when a function is
    passed on, e.g. ``map(str, ...)`` or ``sorted(..., key=len)``.
    """

    __slots__ = ("_display", "_impl", "_interpreter", "_name")

    def __init__(
        self, name: str, display: str, impl: Callable[..., object], interpreter: _Interpreter
    ) -> None:
        self._display = display
        self._impl = impl
        self._interpreter = interpreter
        self._name = name

    def __call__(self, *args: object, **kwargs: object) -> object:
        interpreter = self._interpreter
        interpreter.tick()
        args = interpreter.prepare_call(self._name, args, kwargs)
        result = self._impl(*args, **kwargs)
        interpreter.charge(result)
        return result

    def __repr__(self) -> str:
        return self._display


class _Interpreter:
    """Evaluates a checked AST; one instance per evaluation (it owns the iteration budget)."""

    def __init__(self, env: EvalEnvironment, source: _Source) -> None:
        self._env = env
        self._source = source
        self._steps = 0
        self._work = 0
        self._sizer = _Sizer()
        self._functions: dict[str, _Function] = {}

    def release(self) -> None:
        """Drop the functions made for this evaluation.

        They refer back to the interpreter: the cycle would keep everything the
        environment reaches (the whole interpretation) until a full collection.
        """
        self._functions.clear()

    def run(self, tree: ast.Expression) -> str:
        value = self._eval(tree.body, None)
        if isinstance(value, str):
            return value
        self._check_rendered(value)
        return self._guarded(tree.body, str, value)

    # ----------------------------------------------------------------- helpers

    def _col(self, node: ast.AST) -> int:
        return self._source.col(node)

    def _guarded(self, node: ast.AST, action: Callable[..., _T], *args: Any, **kwargs: Any) -> _T:
        """Run a Python operation, turning its exceptions into :class:`EvalFailed` at ``node``."""
        try:
            result = action(*args, **kwargs)
            if not isinstance(action, _Function):  # a _Function charges itself
                self.charge(result)
            return result
        except (EvalRefused, EvalFailed) as exc:
            if exc.col < 0:
                exc.col = self._col(node)
            raise
        except (RecursionError, MemoryError):
            raise
        except Exception as failure:
            raise EvalFailed(f"{type(failure).__name__}: {failure}", self._col(node)) from failure

    def tick(self) -> None:
        """Count one comprehension iteration or function call."""
        self._steps += 1
        if self._steps > MAX_ITERATIONS:
            raise EvalRefused(
                f"evaluation needs more than {MAX_ITERATIONS} iterations and calls", _UNPLACED
            )

    def charge(self, result: object) -> None:
        """Count the size of a produced string, container or big integer (in bytes),
        bounding the total work."""
        if isinstance(result, (str, list, tuple, dict, set, frozenset)):
            self._charge_size(len(result))
        elif type(result) is int:
            self._charge_size(result.bit_length() >> 3)

    def _charge_size(self, size: int) -> None:
        self._work += size
        if self._work > MAX_WORK:
            raise EvalRefused(f"evaluation needs more than {MAX_WORK} units of work")

    def _comparison_cost(self, op: ast.cmpop, left: object, right: object) -> int:
        """Elements/characters a comparison may visit (containers compare element-wise)."""
        if isinstance(op, (ast.Is, ast.IsNot)):
            return 0
        if isinstance(op, (ast.In, ast.NotIn)):
            if isinstance(left, str) and isinstance(right, str):
                return len(left) + len(right)
            if isinstance(right, (list, tuple)):
                return self._sizer.size(right)
            return self._sizer.size(left)  # hashing for dict/set membership
        if isinstance(left, str) and isinstance(right, str):
            return min(len(left), len(right))
        if isinstance(left, _CONTAINERS) and isinstance(right, _CONTAINERS):
            return min(self._sizer.size(left), self._sizer.size(right))
        return 0

    def prepare_call(
        self, name: str, args: tuple[object, ...], kwargs: Mapping[str, object]
    ) -> tuple[object, ...]:
        """Charge a call's arguments by size (parsing, copying, hashing, ordering them)."""
        if name in _CONSUMING_FUNCTIONS and len(args) == 1 and not isinstance(args[0], _SIZED):
            args = (list(_iterate(args[0])),)
        if name not in _CHEAP_FUNCTIONS:
            self._charge_size(sum(self._sizer.size(value) for value in (*args, *kwargs.values())))
        return args

    def _charge_key(self, node: ast.AST, key: object) -> None:
        """Charge hashing ``key`` (tuples and big ints are re-hashed on every use)."""
        self._guarded(node, self._charge_size, self._sizer.size(key))

    def _charged_iteration(self, left: object, iterator: Iterable[object]) -> Iterator[object]:
        """Feed ``left in iterator`` while charging each element comparison."""
        for element in iterator:
            self._charge_size(self._comparison_cost(_EQ, left, element))
            yield element

    def _check_rendered(self, value: object) -> None:
        """Refuse ``str(value)`` when too long; else charge its size before it is produced."""
        size = self._sizer.size(value)
        if size > MAX_RENDERED:
            raise EvalRefused(f"str() would produce more than {MAX_RENDERED} characters")
        self._charge_size(size)

    # ----------------------------------------------------------------- names

    def _lookup(self, node: ast.Name, scope: ChainMap[str, object] | None) -> object:
        name = node.id
        if scope is not None:
            if name in scope:
                return scope[name]
            return self._builtin(
                node,
                f"name '{name}' is not defined (roslaunch shows a comprehension body only its"
                " own variables and Python builtins, not args or eval functions)",
            )
        if name in _HOST_FUNCTION_NAMES:
            return self._function(name)
        if name in _BOOL_NAMES:
            return _BOOL_NAMES[name]
        if name in _MATH_NAMES:
            value = _MATH_NAMES[name]
            return self._function(name) if callable(value) else value
        raw = self._guarded(node, _lookup_or_none, self._env.lookup_arg, name)
        if raw is not None:
            return convert_auto(raw)
        return self._builtin(node, f"arg '{name}' is not defined")

    def _builtin(self, node: ast.Name, missing: str) -> object:
        if node.id in _BUILTIN_FUNCTIONS:
            return self._function(node.id)
        if node.id in _PYTHON_BUILTIN_NAMES:
            raise EvalRefused(f"the Python builtin '{node.id}' is not allowed", self._col(node))
        raise EvalFailed(missing, self._col(node))

    def _function(self, name: str) -> _Function:
        function = self._functions.get(name)
        if function is None:
            function = _Function(name, *self._implementation(name), self)
            self._functions[name] = function
        return function

    def _implementation(self, name: str) -> tuple[str, Callable[..., object]]:
        """Display text and guarded implementation of a callable name."""
        if name == "arg":
            return "<function arg>", self._arg
        if name in _HOST_FUNCTION_NAMES:
            host = self._env.functions.get(name)
            return f"<function {name}>", host if host is not None else self._unavailable(name)
        if name in _BUILTIN_FUNCTIONS:
            original = _BUILTIN_FUNCTIONS[name]
            guarded = {"str": self._str, "round": self._round}.get(name, original)
            return repr(original), guarded
        original = cast("Callable[..., object]", _MATH_NAMES[name])
        if name == "prod":
            return repr(original), self._prod
        if name in ("factorial", "comb", "perm"):
            return repr(original), self._combinatoric(original, self._charge_size)
        return repr(original), original

    @staticmethod
    def _unavailable(name: str) -> Callable[..., object]:
        def refuse(*_args: object, **_kwargs: object) -> NoReturn:
            raise EvalRefused(f"host function '{name}' is not available to the evaluator")

        return refuse

    def _arg(self, name: object) -> object:
        if not isinstance(name, str):
            raise EvalFailed(f"arg {name!r} is not defined")
        try:
            raw = self._env.lookup_arg(name)
        except KeyError:
            raise EvalFailed(f"arg '{name}' is not defined") from None
        return convert_auto(raw)

    # ----------------------------------------------------------------- guarded callables

    def _str(self, *args: object, **kwargs: object) -> object:
        value = args[0] if args else kwargs.get("object", "")
        if not isinstance(value, str):
            self._check_rendered(value)
        return _BUILTIN_FUNCTIONS["str"](*args, **kwargs)

    def _round(self, *args: object, **kwargs: object) -> object:
        number = args[0] if args else kwargs.get("number")
        digits = args[1] if len(args) > 1 else kwargs.get("ndigits")
        if isinstance(number, int) and isinstance(digits, int) and abs(digits) > MAX_ROUND_DIGITS:
            raise EvalRefused(f"round() with ndigits beyond ±{MAX_ROUND_DIGITS} is not allowed")
        return _BUILTIN_FUNCTIONS["round"](*args, **kwargs)

    def _prod(self, iterable: Iterable[object], /, *, start: object = 1) -> object:
        """``math.prod`` through the ``*`` guards (it multiplies sequences too)."""
        result = start
        for item in iterable:
            refusal = _binop_refusal(_MULT, result, item, self._sizer)
            if refusal is not None:
                raise EvalRefused(refusal)
            result = operator.mul(result, item)
            self.charge(result)
        return result

    @staticmethod
    def _combinatoric(
        original: Callable[..., object], charge: Callable[[int], None]
    ) -> Callable[..., object]:
        """Bounded arguments, and the cost charged before computing: the bits of the result
        (up to ``n log2 n``), so that a callback (``key=factorial``) cannot repeat it cheaply."""

        def guarded(*args: object, **kwargs: object) -> object:
            for value in (*args, *kwargs.values()):
                if isinstance(value, int) and abs(value) > MAX_COMBINATORIC_ARGUMENT:
                    raise EvalRefused(
                        f"{original.__name__}() arguments above {MAX_COMBINATORIC_ARGUMENT}"
                        " are not allowed"
                    )
            largest = max(
                (abs(v) for v in (*args, *kwargs.values()) if isinstance(v, int)), default=0
            )
            charge(largest * largest.bit_length())
            return original(*args, **kwargs)

        return guarded

    def _str_method(
        self, receiver: str, name: str, args: list[object], kwargs: dict[str, object]
    ) -> object:
        self._charge_size(
            len(receiver)
            + sum(len(value) for value in (*args, *kwargs.values()) if isinstance(value, str))
        )
        refusal: str | None = None
        if name == "replace" and len(args) in (2, 3) and not kwargs:
            old, new = args[0], args[1]
            count = args[2] if len(args) == 3 else -1
            if isinstance(old, str) and isinstance(new, str) and isinstance(count, int):
                hits = receiver.count(old) if old else len(receiver) + 1
                if count >= 0:
                    hits = min(hits, count)
                if len(receiver) + hits * (len(new) - len(old)) > MAX_SEQUENCE:
                    refusal = f"replace() would produce more than {MAX_SEQUENCE} characters"
        elif name == "zfill" and len(args) == 1 and isinstance(args[0], int):
            if args[0] > MAX_SEQUENCE:
                refusal = f"zfill() width above {MAX_SEQUENCE} is not allowed"
        elif name == "join" and len(args) == 1 and not kwargs:
            items = list(_iterate(args[0]))
            args = [items]
            if all(isinstance(item, str) for item in items):
                size = sum(len(cast(str, item)) for item in items)
                if size + len(receiver) * max(len(items) - 1, 0) > MAX_SEQUENCE:
                    refusal = f"join() would produce more than {MAX_SEQUENCE} characters"
        elif name == "format":
            refusal = _format_refusal(receiver, args, kwargs, self._sizer)
        if refusal is not None:
            raise EvalRefused(refusal)
        method: Callable[..., object] = getattr(receiver, name)
        return method(*args, **kwargs)

    # ----------------------------------------------------------------- evaluation

    def _eval(self, node: ast.expr, scope: ChainMap[str, object] | None) -> object:
        if isinstance(node, ast.Constant):
            return node.value
        if isinstance(node, ast.Name):
            return self._lookup(node, scope)
        if isinstance(node, ast.BoolOp):
            is_and = isinstance(node.op, ast.And)
            value: object = None
            for operand in node.values:
                value = self._eval(operand, scope)
                if bool(value) != is_and:
                    return value
            return value
        if isinstance(node, ast.UnaryOp):
            operand_value = self._eval(node.operand, scope)
            return self._guarded(node, _UNARY_OPS[type(node.op)], operand_value)
        if isinstance(node, ast.BinOp):
            left = self._eval(node.left, scope)
            right = self._eval(node.right, scope)
            refusal = _binop_refusal(node.op, left, right, self._sizer)
            if refusal is not None:
                raise EvalRefused(refusal, self._col(node))
            return self._guarded(node, _BIN_OPS[type(node.op)], left, right)
        if isinstance(node, ast.Compare):
            return self._compare(node, scope)
        if isinstance(node, ast.IfExp):
            branch = node.body if self._eval(node.test, scope) else node.orelse
            return self._eval(branch, scope)
        if isinstance(node, ast.Subscript):
            container = self._eval(node.value, scope)
            key = self._eval(node.slice, scope)
            if not isinstance(container, (str, list, tuple, dict)):
                raise EvalFailed(
                    f"TypeError: '{type(container).__name__}' object is not subscriptable",
                    self._col(node),
                )
            if isinstance(container, dict):
                self._charge_key(node, key)
            return self._guarded(node, _GETITEM, container, key)
        if isinstance(node, ast.Slice):
            parts = [
                None if part is None else self._eval(part, scope)
                for part in (node.lower, node.upper, node.step)
            ]
            return slice(*parts)
        if isinstance(node, ast.Tuple):
            return tuple(self._eval(element, scope) for element in node.elts)
        if isinstance(node, ast.List):
            return [self._eval(element, scope) for element in node.elts]
        if isinstance(node, ast.Set):
            elements = [self._eval(element, scope) for element in node.elts]
            for element in elements:
                self._charge_key(node, element)
            return self._guarded(node, set, elements)
        if isinstance(node, ast.Dict):
            result: dict[object, object] = {}
            for key_node, value_node in zip(node.keys, node.values, strict=True):
                assert key_node is not None  # refused by the analyser
                dict_key = self._eval(key_node, scope)
                self._charge_key(node, dict_key)
                self._guarded(node, result.__setitem__, dict_key, self._eval(value_node, scope))
            return result
        if isinstance(node, ast.Call):
            return self._call(node, scope)
        if isinstance(node, (ast.ListComp, ast.SetComp, ast.DictComp, ast.GeneratorExp)):
            return self._comprehension(node, scope)
        raise EvalRefused(f"{type(node).__name__} is not allowed", self._col(node))

    def _compare(self, node: ast.Compare, scope: ChainMap[str, object] | None) -> object:
        left = self._eval(node.left, scope)
        result: object = True
        for op, comparator in zip(node.ops, node.comparators, strict=True):
            right = self._eval(comparator, scope)
            operand = right
            if isinstance(op, (ast.In, ast.NotIn)) and not isinstance(right, _SIZED):
                if isinstance(right, Iterator):  # a map or generator: weigh as it is consumed
                    operand = self._charged_iteration(left, right)
            else:
                self._guarded(node, self._charge_size, self._comparison_cost(op, left, right))
            result = self._guarded(node, _COMPARE_OPS[type(op)], left, operand)
            if not result:
                return result
            left = right
        return result

    def _call(self, node: ast.Call, scope: ChainMap[str, object] | None) -> object:
        func = node.func
        if isinstance(func, ast.Attribute):
            receiver = self._eval(func.value, scope)
            if not isinstance(receiver, str):  # Python looks the method up before the arguments
                kind = type(receiver).__name__
                if hasattr(receiver, func.attr):
                    raise EvalRefused(
                        f"method '{func.attr}' is only allowed on str values, not on {kind}",
                        self._source.attr_col(func),
                    )
                raise EvalFailed(
                    f"AttributeError: '{kind}' object has no attribute '{func.attr}'",
                    self._source.attr_col(func),
                )
            args, kwargs = self._arguments(node, scope)
            return self._guarded(node, self._str_method, receiver, func.attr, args, kwargs)
        callee = self._eval(func, scope)
        args, kwargs = self._arguments(node, scope)
        if not isinstance(callee, _Function):
            raise EvalFailed(
                f"TypeError: '{type(callee).__name__}' object is not callable", self._col(node)
            )
        return self._guarded(node, callee, *args, **kwargs)

    def _arguments(
        self, node: ast.Call, scope: ChainMap[str, object] | None
    ) -> tuple[list[object], dict[str, object]]:
        args = [self._eval(argument, scope) for argument in node.args]
        kwargs = {
            cast(str, keyword.arg): self._eval(keyword.value, scope) for keyword in node.keywords
        }
        return args, kwargs

    def _comprehension(
        self,
        node: ast.ListComp | ast.SetComp | ast.DictComp | ast.GeneratorExp,
        scope: ChainMap[str, object] | None,
    ) -> object:
        generator = node.generators[0]
        iterator = self._guarded(node, _iterate, self._eval(generator.iter, scope))
        bindings: dict[str, object] = {}
        inner = ChainMap(bindings) if scope is None else scope.new_child(bindings)

        def rounds() -> Iterator[None]:
            """Binds the target for each item that passes the ``if`` clauses."""
            while True:
                item = self._guarded(node, next, iterator, _END)
                if item is _END:
                    return
                self._guarded(node, self.tick)
                self._assign(generator.target, item, bindings, node)
                if all(self._eval(condition, inner) for condition in generator.ifs):
                    yield None

        def elements(element: ast.expr) -> Iterator[object]:
            """A generator expression's items, lazily: ``1 in (1 / v for v in [1, 0])``
            must stop before it divides by zero."""
            for _ in rounds():
                yield self._eval(element, inner)

        if isinstance(node, ast.GeneratorExp):
            return elements(node.elt)
        if isinstance(node, ast.ListComp):
            return [self._eval(node.elt, inner) for _ in rounds()]
        if isinstance(node, ast.SetComp):
            members: set[object] = set()
            for _ in rounds():
                member = self._eval(node.elt, inner)
                self._charge_key(node, member)
                self._guarded(node, members.add, member)
            return members
        mapping: dict[object, object] = {}
        for _ in rounds():
            key = self._eval(node.key, inner)
            self._charge_key(node, key)
            self._guarded(node, mapping.__setitem__, key, self._eval(node.value, inner))
        return mapping

    def _assign(
        self, target: ast.expr, value: object, bindings: dict[str, object], node: ast.AST
    ) -> None:
        if isinstance(target, ast.Name):
            bindings[target.id] = value
            return
        elements = cast("ast.Tuple | ast.List", target).elts
        for element, item in zip(elements, self._unpack(value, len(elements), node), strict=True):
            self._assign(element, item, bindings, node)

    def _unpack(self, value: object, count: int, node: ast.AST) -> list[object]:
        try:
            iterator = _iterate(value)
        except TypeError:
            raise EvalFailed(
                f"TypeError: cannot unpack non-iterable {type(value).__name__} object",
                self._col(node),
            ) from None
        items: list[object] = self._guarded(node, list, itertools.islice(iterator, count + 1))
        if len(items) > count:
            raise EvalFailed(
                f"ValueError: too many values to unpack (expected {count})", self._col(node)
            )
        if len(items) < count:
            raise EvalFailed(
                f"ValueError: not enough values to unpack (expected {count}, got {len(items)})",
                self._col(node),
            )
        return items
