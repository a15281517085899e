"""The interpreter of checked expressions over plain Python values, under the limits."""

from __future__ import annotations

import ast
import functools
import itertools
import operator
from collections import ChainMap
from collections.abc import Callable, Iterable, Iterator, Mapping
from typing import Any, NoReturn, TypeVar, cast

from rosvar.arithmetic import BINARY, COMPARISONS
from rosvar.interpreter.safe_eval.checking import _Source
from rosvar.interpreter.safe_eval.errors import _UNPLACED, EvalFailed, EvalRefused
from rosvar.interpreter.safe_eval.limits import (
    MAX_COMBINATORIC_ARGUMENT,
    MAX_ITERATIONS,
    MAX_RENDERED,
    MAX_ROUND_DIGITS,
    MAX_SEQUENCE,
    MAX_WORK,
    FunctionValue,
    _binop_refusal,
    _format_refusal,
    _Sizer,
)
from rosvar.interpreter.safe_eval.names import (
    _BOOL_NAMES,
    _BUILTIN_FUNCTIONS,
    _CHEAP_FUNCTIONS,
    _CONSUMING_FUNCTIONS,
    _CONTAINERS,
    _END,
    _EQ,
    _GETITEM,
    _HOST_FUNCTION_NAMES,
    _MATH_NAMES,
    _MULT,
    _PYTHON_BUILTIN_NAMES,
    _SIZED,
    _SYMBOL_GLOBALS,
    _UNARY_OPS,
    EvalEnvironment,
)

_T = TypeVar("_T")


def _iterate(value: object) -> Iterator[object]:
    return iter(cast("Iterable[object]", value))


def _lookup_or_none(lookup: Callable[[str], str], name: str) -> str | None:
    try:
        return lookup(name)
    except KeyError:
        return None


@functools.lru_cache(maxsize=65536)
def convert_auto(value: str) -> bool | int | float | str:
    """roslaunch's ``convert_value(value, 'auto')``: how eval sees an arg's raw string.

    Replicated statement by statement because the quirks matter: ``'1_0'`` stays a string,
    ``'1_0.5'`` becomes ``10.5``, ``' 7 '`` becomes ``7``, ``'TRUE'`` becomes ``True``.
    (Cached: the same texts recur in every includer, and the results are immutable.)
    """
    try:
        if "." in value:
            return float(value)
        if "_" not in value:
            return int(value)
    except ValueError:
        pass
    if value.lower() in ("true", "false"):
        return value.lower() == "true"
    return value


class _Function(FunctionValue):
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


class _Namespace:
    """A namespace of the environment (``math``), whose members only are values."""

    __slots__ = ("name",)

    def __init__(self, name: str) -> None:
        self.name = name

    def __repr__(self) -> str:
        return f"<namespace {self.name}>"


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

    def value(self, tree: ast.Expression) -> object:
        """The expression's value itself (xacro keeps a lone ``${}``'s type); a function or
        namespace as the text ``str()`` would give."""
        value = self._eval(tree.body, None)
        if isinstance(value, FunctionValue | _Namespace):
            return repr(value)
        return value

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
        if self._env.symbols is not None and (scope is None or name not in scope):
            return self._symbol(node)
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

    def _symbol(self, node: ast.Name) -> object:
        """A name of a symbols environment: a property, a namespace, a global."""
        assert self._env.symbols is not None
        try:
            return self._env.symbols(node.id)
        except KeyError:
            pass
        if node.id in self._env.namespaces:
            return _Namespace(node.id)
        if node.id in _SYMBOL_GLOBALS:
            return self._global(node.id)
        raise EvalFailed(f"NameError: name '{node.id}' is not defined", self._col(node))

    def _global(self, name: str) -> object:
        """A global name's value (a bool, a math constant, a function)."""
        if name in _BOOL_NAMES:
            return _BOOL_NAMES[name]
        value = _MATH_NAMES.get(name)
        if value is not None and not callable(value):
            return value
        return self._function(name)

    def _member(self, node: ast.Attribute, scope: ChainMap[str, object] | None) -> object:
        """``ns.member`` of a namespace (the checker allows no other attribute)."""
        receiver = self._eval(node.value, scope)
        if not isinstance(receiver, _Namespace):
            raise EvalFailed(
                f"AttributeError: '{type(receiver).__name__}' object has no attribute "
                f"'{node.attr}'",
                self._source.attr_col(node),
            )
        name = self._env.namespaces[receiver.name].get(node.attr)
        if name is None or not (name in self._env.functions or name in _SYMBOL_GLOBALS):
            raise EvalRefused(
                f"'{receiver.name}.{node.attr}' is not available to the evaluator",
                self._source.attr_col(node),
            )
        return self._global(name)

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
        if name in self._env.functions:
            return f"<function {name}>", self._env.functions[name]
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
            return self._guarded(node, BINARY[type(node.op)], left, right)
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
        if isinstance(node, ast.Attribute):
            return self._member(node, scope)
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
            result = self._guarded(node, COMPARISONS[type(op)], left, operand)
            if not result:
                return result
            left = right
        return result

    def _call(self, node: ast.Call, scope: ChainMap[str, object] | None) -> object:
        func = node.func
        if isinstance(func, ast.Attribute) and not self._names_member(func, scope):
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

    def _names_member(self, func: ast.Attribute, scope: ChainMap[str, object] | None) -> bool:
        """Whether ``func`` is ``ns.member`` of a namespace rather than a str method."""
        value = func.value
        return (
            isinstance(value, ast.Name)
            and value.id in self._env.namespaces
            and isinstance(self._eval(value, scope), _Namespace)
        )

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
