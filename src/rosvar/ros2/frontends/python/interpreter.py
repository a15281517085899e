"""An abstract interpreter of the part of Python that launch files use, over ``ast``.

The file is never executed: its syntax tree is read statement by statement with abstract
values (:mod:`~rosvar.ros2.frontends.python.values`). Constants, strings, lists, dicts,
local variables, helper functions, loops over known sequences and ``if`` on known values
are followed exactly; calls go to the launch API's registry
(:mod:`~rosvar.ros2.frontends.python.calls`). Anything else (``OpaqueFunction``, files read,
other modules called, unknown names, ``while``) becomes an :class:`Unknown` with a
diagnostic at its ``file:line:col``, and the reading goes on. A step budget and a call
depth bound the work whatever the file does.
"""

from __future__ import annotations

import ast
import builtins
import string
from collections.abc import Callable, Iterator
from typing import Any

from rosvar.arithmetic import ARITHMETIC, COMPARISONS
from rosvar.diagnostics import DiagnosticSink, Location
from rosvar.frontends.entity import Entity
from rosvar.ros2.api.registry import python_name
from rosvar.ros2.frontends.python.actions import add_actions
from rosvar.ros2.frontends.python.calls import (
    CALLS,
    NOT_FOLLOWED,
    REASONS,
    Call,
    join_path,
)
from rosvar.ros2.frontends.python.text import Sub, Text
from rosvar.ros2.frontends.python.values import (
    Description,
    Function,
    Key,
    LaunchContext,
    Method,
    Module,
    Scope,
    Unknown,
    Value,
)

MAX_STEPS = 500_000
"""Statements and expressions read per file before giving up (``python-budget``)."""
MAX_CALL_DEPTH = 40
"""Nested calls of the file's own functions (recursion) before a call stays unknown."""
MAX_LENGTH = 100_000
"""Longest string, text or list the reading builds (``*``, ``+``, ``join``, ``range``...)."""
MAX_INT_BITS = 4096
"""Largest integer the reading computes: repeated squaring must not exhaust memory."""
CHARS_PER_STEP = 64
"""Characters of a string built that cost one step (a string is copied a word at a time)."""

MODULE_NAME = "__launch__"
"""``__name__`` while the file is read: launch imports it as a module, not as ``__main__``."""


class _Return(Exception):
    def __init__(self, value: Value) -> None:
        super().__init__()
        self.value = value


class _Break(Exception):
    pass


class _Continue(Exception):
    pass


class OutOfBudget(Exception):
    """The file needs more than :data:`MAX_STEPS` steps."""


_SCALARS = (str, int, float, bool, type(None))
_STR_METHODS = frozenset(
    {
        "join",
        "replace",
        "strip",
        "lstrip",
        "rstrip",
        "lower",
        "upper",
        "startswith",
        "endswith",
        "split",
        "format",
    }
)


def _constant(value: Value) -> bool:
    if isinstance(value, list | tuple):
        return all(_constant(item) for item in value)
    return isinstance(value, _SCALARS)


def size(value: Value) -> int:
    """The length of a string, text or sequence, the bytes of an integer; 1 otherwise."""
    if isinstance(value, str | list | tuple):
        return len(value)
    if isinstance(value, Text):
        return sum(len(part) if isinstance(part, str) else 1 for part in value.parts)
    if isinstance(value, int) and not isinstance(value, bool):
        return value.bit_length() // 8
    return 1


class Expansion:
    """The size of values with every shared part counted each time it occurs, as walking
    them (their launch elements, a parameter dict) would meet it: ``[[s] * n] * n`` is
    n * n, ``GroupAction([g, g])`` nested k deep 2^k. Each object's size is computed once
    per question; a launch element's is remembered (by its identity and number of children:
    elements are built once, descriptions only grow), so that a chain of k nested groups
    costs k, not k^2."""

    def __init__(self) -> None:
        self._elements: dict[tuple[int, int], int] = {}
        self._kept: list[Entity] = []  # ids stay unique while their objects live

    def cost(self, value: object, limit: int) -> int:
        """The expanded size of ``value`` less that of the launch elements built before that
        it holds, each credited once (they were charged when built: a chain of k groups
        costs k, two copies of one group are one group more); counting stops past
        ``limit``, so the work done is at most the size found."""
        sizes: dict[int, int] = {}
        keep: list[object] = []
        credited: set[int] = set()
        credit = 0

        def measure(item: object) -> int:
            nonlocal credit
            if isinstance(item, str):
                return 1 + len(item) // CHARS_PER_STEP
            if not isinstance(item, list | tuple | dict | Entity | Text | Description):
                return 1
            element = (id(item), len(item.children)) if isinstance(item, Entity) else None
            known = sizes.get(id(item)) if element is None else self._elements.get(element)
            if known is not None:
                if element is not None and id(item) not in credited:
                    credited.add(id(item))
                    credit += known
                return known
            keep.append(item)
            sizes[id(item)] = limit + credit + 1  # a container holding itself is too large
            total = 1
            for part in _parts(item):
                total += measure(part)
                if total > limit + credit:
                    return total  # not remembered: a later question may allow more
            sizes[id(item)] = total
            if element is not None and isinstance(item, Entity):
                self._elements[element] = total
                self._kept.append(item)
            return total

        return measure(value) - credit


def _parts(item: object) -> Iterator[object]:
    if isinstance(item, dict):
        for key, value in item.items():
            yield key
            yield value
    elif isinstance(item, Entity):
        yield from item.attributes.values()
        yield from item.children
    elif isinstance(item, Text):
        yield from item.parts
    elif isinstance(item, Description):
        yield item.root
    elif isinstance(item, list | tuple):
        yield from item


_REFERENCES = (ast.Name, ast.Attribute, ast.Constant)
"""Expressions that only refer to a value already built: nothing to charge."""


def truth(value: Value) -> bool | None:
    """Python's truth of ``value``; ``None`` when it is not known statically."""
    if isinstance(value, Unknown | Module):  # a Module may be any value of another module
        return None
    if isinstance(value, (*_SCALARS, list, tuple, dict)):
        return bool(value)
    return True  # launch objects and texts with substitutions are never empty


class Interpreter:
    """Reads one file; diagnostics go to ``sink``."""

    def __init__(self, filename: str, text: str, sink: DiagnosticSink) -> None:
        self.filename = filename
        self.lines = text.splitlines()
        self.sink = sink
        self.steps = 0
        self.statement: ast.stmt | None = None
        self.expansion = Expansion()
        self.depth = 0
        self.statements: dict[type[ast.stmt], Callable[[Any, Scope], None]] = {
            ast.Expr: self._expression_statement,
            ast.Assign: self._assign,
            ast.AnnAssign: self._ann_assign,
            ast.AugAssign: self._aug_assign,
            ast.Return: self._return,
            ast.If: self._if,
            ast.For: self._for,
            ast.FunctionDef: self._function_def,
            ast.Import: self._import,
            ast.ImportFrom: self._import_from,
            ast.Try: self._try,
            ast.With: self._with,
            ast.Break: self._break,
            ast.Continue: self._continue,
            ast.Pass: lambda node, scope: None,
            ast.Assert: lambda node, scope: None,
            ast.Global: lambda node, scope: None,
            ast.Nonlocal: lambda node, scope: None,
        }
        self.expressions: dict[type[ast.expr], Callable[[Any, Scope], Value]] = {
            ast.Constant: self._constant,
            ast.Name: self._name,
            ast.JoinedStr: self._joined_str,
            ast.BinOp: self._bin_op,
            ast.UnaryOp: self._unary_op,
            ast.BoolOp: self._bool_op,
            ast.Compare: self._compare,
            ast.IfExp: self._if_exp,
            ast.List: self._sequence,
            ast.Tuple: lambda node, scope: tuple(self._elements(node.elts, scope)),
            ast.Set: self._sequence,
            ast.Dict: self._dict,
            ast.Subscript: self._subscript,
            ast.Attribute: self._attribute,
            ast.Call: self._call,
            ast.ListComp: self._comprehension,
            ast.GeneratorExp: self._comprehension,
            ast.SetComp: self._comprehension,
            ast.DictComp: self._comprehension,
            ast.NamedExpr: self._named_expr,
        }

    # ------------------------------------------------------------------ helpers

    def location(self, node: ast.AST) -> Location:
        line = getattr(node, "lineno", 1)
        offset = getattr(node, "col_offset", 0)  # in UTF-8 bytes
        text = self.lines[line - 1] if 0 < line <= len(self.lines) else ""
        column = len(text.encode()[:offset].decode(errors="replace"))
        return Location(self.filename, line, column + 1)

    def not_followed(self, what: str, node: ast.AST) -> Unknown:
        self.sink.warning(NOT_FOLLOWED, f"{what} is not followed", self.location(node))
        return Unknown(what)

    def step(self) -> None:
        self.steps += 1
        if self.steps > MAX_STEPS:
            raise OutOfBudget

    def charge(self, value: object) -> None:
        """Count the expanded size of a value an operation built or walked, so that work
        multiplied by sharing or by long operands (``l == l``, ``l[:]``, ``s.split()``)
        is bounded by the same budget as the statements."""
        self.steps += self.expansion.cost(value, MAX_STEPS - self.steps) - 1
        if self.steps > MAX_STEPS:
            raise OutOfBudget

    # ------------------------------------------------------------------ statements

    def run_module(self, tree: ast.Module) -> Scope:
        scope = Scope({"__name__": MODULE_NAME, "__file__": Text.of(Sub("filename"))})
        try:
            self.block(tree.body, scope)
        except _Return:
            pass
        except (_Break, _Continue):
            pass
        return scope

    def block(self, body: list[ast.stmt], scope: Scope) -> None:
        for statement in body:
            self.step()
            self.statement = statement  # where a budget runs out
            handler = self.statements.get(type(statement))
            if handler is None:
                self.not_followed(f"a '{type(statement).__name__}' statement", statement)
                continue
            handler(statement, scope)

    def assign(self, target: ast.expr, value: Value, scope: Scope) -> None:
        if isinstance(target, ast.Name):
            scope.names[target.id] = value
        elif isinstance(target, ast.Tuple | ast.List):
            items: list[Value]
            if isinstance(value, list | tuple) and len(value) == len(target.elts):
                items = list(value)
            else:
                if not isinstance(value, Unknown):
                    value = self.not_followed("unpacking of a value of unknown length", target)
                items = [value] * len(target.elts)
            for element, item in zip(target.elts, items, strict=True):
                self.assign(element, item, scope)
        elif isinstance(target, ast.Subscript):
            container = self.expr(target.value, scope)
            index = self.expr(target.slice, scope)
            if isinstance(container, dict) and isinstance(index, Key):
                container[index] = value
                return
            if (
                isinstance(container, list)
                and isinstance(index, int)
                and (-len(container) <= index < len(container))
            ):
                container[index] = value
                return
            self.not_followed("assignment to an item of an unknown container", target)
        else:
            self.not_followed(f"assignment to a '{type(target).__name__}'", target)

    def _expression_statement(self, node: ast.Expr, scope: Scope) -> None:
        self.expr(node.value, scope)

    def _assign(self, node: ast.Assign, scope: Scope) -> None:
        value = self.expr(node.value, scope)
        for target in node.targets:
            self.assign(target, value, scope)

    def _ann_assign(self, node: ast.AnnAssign, scope: Scope) -> None:
        if node.value is not None:
            self.assign(node.target, self.expr(node.value, scope), scope)

    def _aug_assign(self, node: ast.AugAssign, scope: Scope) -> None:
        current = self.expr(node.target, scope)
        value = self.binary(node.op, current, self.expr(node.value, scope), node)
        if isinstance(current, list) and isinstance(value, list):
            current[:] = value  # += extends the list in place
            value = current
        self.assign(node.target, value, scope)

    def _return(self, node: ast.Return, scope: Scope) -> None:
        raise _Return(None if node.value is None else self.expr(node.value, scope))

    def _if(self, node: ast.If, scope: Scope) -> None:
        test = truth(self.expr(node.test, scope))
        if test is None:
            self.not_followed("an 'if' on a value not known statically (neither branch)", node)
        else:
            self.block(node.body if test else node.orelse, scope)

    def _for(self, node: ast.For, scope: Scope) -> None:
        items = self.iterate(self.expr(node.iter, scope), node.iter)
        if items is None:
            return
        for item in items:
            self.assign(node.target, item, scope)
            try:
                self.block(node.body, scope)
            except _Break:
                return
            except _Continue:
                continue
        self.block(node.orelse, scope)

    def _break(self, node: ast.Break, scope: Scope) -> None:
        raise _Break

    def _continue(self, node: ast.Continue, scope: Scope) -> None:
        raise _Continue

    def _function_def(self, node: ast.FunctionDef, scope: Scope) -> None:
        if node.decorator_list:
            scope.names[node.name] = self.not_followed(f"decorated function {node.name}()", node)
            return
        arguments = node.args
        positional = [*arguments.posonlyargs, *arguments.args]
        defaults: dict[str, Value] = {}
        for argument, default in zip(
            positional[len(positional) - len(arguments.defaults) :],
            arguments.defaults,
            strict=True,
        ):
            defaults[argument.arg] = self.expr(default, scope)
        for argument, kw_default in zip(arguments.kwonlyargs, arguments.kw_defaults, strict=True):
            if kw_default is not None:
                defaults[argument.arg] = self.expr(kw_default, scope)
        scope.names[node.name] = Function(node, scope, defaults)

    def _import(self, node: ast.Import, scope: Scope) -> None:
        for alias in node.names:
            if alias.asname is not None:
                scope.names[alias.asname] = Module(alias.name)
            else:
                top = alias.name.partition(".")[0]
                scope.names[top] = Module(top)

    def _import_from(self, node: ast.ImportFrom, scope: Scope) -> None:
        module = "." * node.level + (node.module or "")
        for alias in node.names:
            if alias.name == "*":
                self.not_followed(f"'from {module} import *'", node)
                continue
            scope.names[alias.asname or alias.name] = Module(f"{module}.{alias.name}")

    def _try(self, node: ast.Try, scope: Scope) -> None:
        """The body as if it raised nothing (nothing read here raises)."""
        self.block(node.body, scope)
        self.block(node.orelse, scope)
        self.block(node.finalbody, scope)

    def _with(self, node: ast.With, scope: Scope) -> None:
        for item in node.items:
            value = self.expr(item.context_expr, scope)
            if item.optional_vars is not None:
                if not isinstance(value, Unknown):
                    value = self.not_followed("a 'with' context manager", item.context_expr)
                self.assign(item.optional_vars, value, scope)
        self.block(node.body, scope)

    # ------------------------------------------------------------------ expressions

    def expr(self, node: ast.expr, scope: Scope) -> Value:
        self.step()
        handler = self.expressions.get(type(node))
        if handler is None:
            return self.not_followed(f"a '{type(node).__name__}' expression", node)
        value = handler(node, scope)
        if not isinstance(node, _REFERENCES):
            self.charge(value)
        return value

    def _constant(self, node: ast.Constant, scope: Scope) -> Value:
        if isinstance(node.value, _SCALARS):
            return node.value
        return self.not_followed(f"a {type(node.value).__name__} constant", node)

    def _name(self, node: ast.Name, scope: Scope) -> Value:
        found, value = scope.lookup(node.id)
        if found:
            return value
        if node.id in BUILTINS or hasattr(builtins, node.id):
            return Module(node.id)  # a call of a builtin not in BUILTINS is reported as such
        return self.not_followed(f"name '{node.id}'", node)

    def _joined_str(self, node: ast.JoinedStr, scope: Scope) -> Value:
        parts: list[Value] = []
        for value in node.values:
            if isinstance(value, ast.FormattedValue):
                if value.format_spec is not None or value.conversion not in (-1, ord("s")):
                    return self.not_followed("a formatted value with a format", value)
                parts.append(self.stringify(self.expr(value.value, scope), value))
            else:
                parts.append(self.expr(value, scope))
        return self.concatenate(parts, node)

    def stringify(self, value: Value, node: ast.AST) -> Value:
        """``str(value)`` where it is known."""
        if isinstance(value, _SCALARS):
            return str(value)
        if isinstance(value, Text | Unknown):
            return value
        return self.not_followed(f"str() of a {type(value).__name__}", node)

    def concatenate(self, parts: list[Value], node: ast.AST) -> Value:
        if sum(size(part) for part in parts) > MAX_LENGTH:
            return self.not_followed(f"a string longer than {MAX_LENGTH}", node)
        if all(isinstance(part, str) for part in parts):
            return "".join(str(part) for part in parts)
        texts: list[str | Text] = []
        for part in parts:
            if isinstance(part, Unknown):
                return part
            if not isinstance(part, str | Text):
                return self.not_followed(f"a {type(part).__name__} in a string", node)
            texts.append(part)
        return Text.of(*texts)

    def binary(self, op: ast.operator, left: Value, right: Value, node: ast.AST) -> Value:
        if isinstance(left, Unknown):
            return left
        if isinstance(right, Unknown):
            return right
        if isinstance(op, ast.Add) and (isinstance(left, Text) or isinstance(right, Text)):
            return self.concatenate([left, right], node)
        if isinstance(op, ast.Div) and isinstance(left, Text) and isinstance(right, str | Text):
            return join_path(left, Text.of(right))  # PathSubstitution(...) / 'config'

        function = ARITHMETIC.get(type(op))
        if function is not None and _constant(left) and _constant(right):
            if self._too_large(op, left, right):
                return self.not_followed("a value too large to compute", node)
            if isinstance(op, ast.Mod) and isinstance(left, str):
                return self.not_followed("'%' formatting", node)
            try:
                result: Value = function(left, right)
            except (TypeError, ValueError, ArithmeticError) as error:
                return self.not_followed(f"an operation that fails ({error})", node)
            return result
        if isinstance(op, ast.Add) and size(left) + size(right) > MAX_LENGTH:
            return self.not_followed(f"a list longer than {MAX_LENGTH}", node)
        if isinstance(op, ast.Add) and isinstance(left, list) and isinstance(right, list):
            return left + right
        if isinstance(op, ast.Add) and isinstance(left, tuple) and isinstance(right, tuple):
            return left + right
        return self.not_followed(f"operator {type(op).__name__}", node)

    @staticmethod
    def _too_large(op: ast.operator, left: Value, right: Value) -> bool:
        """Whether an operation on constants would build a result over the limits."""
        if isinstance(op, ast.Mult):
            if isinstance(left, int) and isinstance(right, int):
                return left.bit_length() + right.bit_length() > MAX_INT_BITS
            count = right if isinstance(right, int) else left
            sequence = left if count is right else right
            return not isinstance(count, int) or size(sequence) * max(count, 0) > MAX_LENGTH
        if isinstance(op, ast.Add):
            return size(left) + size(right) > max(MAX_LENGTH, MAX_INT_BITS)
        return False

    def _bin_op(self, node: ast.BinOp, scope: Scope) -> Value:
        return self.binary(node.op, self.expr(node.left, scope), self.expr(node.right, scope), node)

    def _unary_op(self, node: ast.UnaryOp, scope: Scope) -> Value:
        operand = self.expr(node.operand, scope)
        if isinstance(node.op, ast.Not):
            test = truth(operand)
            return Unknown("not of an unknown value") if test is None else not test
        if isinstance(operand, int | float) and isinstance(node.op, ast.USub | ast.UAdd):
            return -operand if isinstance(node.op, ast.USub) else operand
        return self.not_followed(f"operator {type(node.op).__name__}", node)

    def _bool_op(self, node: ast.BoolOp, scope: Scope) -> Value:
        value: Value = None
        for operand in node.values:
            value = self.expr(operand, scope)
            test = truth(value)
            if test is None:
                return Unknown("a condition not known statically")
            if test is isinstance(node.op, ast.Or):
                return value
        return value

    def _compare(self, node: ast.Compare, scope: Scope) -> Value:
        left = self.expr(node.left, scope)
        for op, comparator in zip(node.ops, node.comparators, strict=True):
            right = self.expr(comparator, scope)
            self.charge((left, right))  # a comparison walks both
            if not (_constant(left) or isinstance(left, dict)) or not (
                _constant(right) or isinstance(right, dict)
            ):
                return Unknown("a comparison of values not known statically")
            try:
                if not COMPARISONS[type(op)](left, right):
                    return False
            except TypeError as error:
                return self.not_followed(f"a comparison that fails ({error})", node)
            left = right
        return True

    def _if_exp(self, node: ast.IfExp, scope: Scope) -> Value:
        test = truth(self.expr(node.test, scope))
        if test is None:
            return self.not_followed("a conditional expression on an unknown value", node)
        return self.expr(node.body if test else node.orelse, scope)

    def _elements(self, nodes: list[ast.expr], scope: Scope) -> list[Value]:
        items: list[Value] = []
        for element in nodes:
            if isinstance(element, ast.Starred):
                expanded = self.iterate(self.expr(element.value, scope), element)
                items.extend(expanded if expanded is not None else [Unknown("*unknown")])
            else:
                items.append(self.expr(element, scope))
        return items

    def _sequence(self, node: ast.List | ast.Set, scope: Scope) -> Value:
        return self._elements(node.elts, scope)

    def _dict(self, node: ast.Dict, scope: Scope) -> Value:
        result: dict[Key, Value] = {}
        for key_node, value_node in zip(node.keys, node.values, strict=True):
            value = self.expr(value_node, scope)
            if key_node is None:
                if isinstance(value, dict):
                    result.update(value)
                else:
                    self.not_followed("'**' of a value that is not a known dict", value_node)
                continue
            name = self.expr(key_node, scope)
            if isinstance(name, Key):
                result[name] = value
            else:
                self.not_followed(f"a dict key that is a {type(name).__name__}", key_node)
        return result

    def _subscript(self, node: ast.Subscript, scope: Scope) -> Value:
        container = self.expr(node.value, scope)
        if isinstance(node.slice, ast.Slice):
            bounds = [
                None if part is None else self.expr(part, scope)
                for part in (node.slice.lower, node.slice.upper, node.slice.step)
            ]
            numbers = [bound for bound in bounds if bound is None or isinstance(bound, int)]
            if isinstance(container, str | list | tuple) and len(numbers) == len(bounds):
                return container[slice(*numbers)]
            return self.not_followed("a slice of a value not known statically", node)
        index = self.expr(node.slice, scope)
        if container == Module("os.environ") and isinstance(index, str | Text):
            return Text.of(Sub("env", (Text.of(index),)))
        if container == Method(LaunchContext(), "launch_configurations"):
            return _configuration(self, node, index)
        try:
            if isinstance(container, dict) and isinstance(index, Key):
                return container[index]
            if isinstance(container, str | list | tuple) and isinstance(index, int):
                return container[index]
        except (KeyError, IndexError):
            return self.not_followed(f"a missing item {index!r}", node)
        if isinstance(container, Unknown):
            return container
        return self.not_followed("an item of a value not known statically", node)

    def _attribute(self, node: ast.Attribute, scope: Scope) -> Value:
        owner = self.expr(node.value, scope)
        if isinstance(owner, Module):
            return Module(f"{owner.qualified}.{node.attr}")
        if isinstance(owner, Unknown):
            return owner
        return Method(owner, node.attr)

    def _named_expr(self, node: ast.NamedExpr, scope: Scope) -> Value:
        value = self.expr(node.value, scope)
        self.assign(node.target, value, scope)
        return value

    def _comprehension(
        self, node: ast.ListComp | ast.GeneratorExp | ast.SetComp | ast.DictComp, scope: Scope
    ) -> Value:
        inner = Scope(parent=scope)
        results: list[Value] = []
        pairs: dict[Key, Value] = {}
        for _ in self._generate(node.generators, inner):
            if isinstance(node, ast.DictComp):
                name = self.expr(node.key, inner)
                if isinstance(name, Key):
                    pairs[name] = self.expr(node.value, inner)
                else:
                    return self.not_followed("a dict key not known statically", node.key)
            else:
                results.append(self.expr(node.elt, inner))
        return pairs if isinstance(node, ast.DictComp) else results

    def _generate(self, generators: list[ast.comprehension], scope: Scope) -> Iterator[None]:
        if not generators:
            yield None
            return
        first, rest = generators[0], generators[1:]
        items = self.iterate(self.expr(first.iter, scope), first.iter)
        for item in items or []:
            self.assign(first.target, item, scope)
            tests = [truth(self.expr(test, scope)) for test in first.ifs]
            if None in tests:
                self.not_followed("a comprehension filter not known statically", first)
                return
            if all(tests):
                yield from self._generate(rest, scope)

    def iterate(self, value: Value, node: ast.AST) -> list[Value] | None:
        if isinstance(value, list | tuple | str):
            return list(value)
        if isinstance(value, dict):
            return list(value)
        if not isinstance(value, Unknown):
            self.not_followed(f"iteration over a {type(value).__name__}", node)
        return None

    # ------------------------------------------------------------------ calls

    def _call(self, node: ast.Call, scope: Scope) -> Value:
        callee = self.expr(node.func, scope)
        args = self._elements(node.args, scope)
        kwargs: dict[str, Value] = {}
        for keyword in node.keywords:
            value = self.expr(keyword.value, scope)
            if keyword.arg is not None:
                kwargs[keyword.arg] = value
            elif isinstance(value, dict) and all(isinstance(name, str) for name in value):
                kwargs.update({str(name): item for name, item in value.items()})
            else:
                self.not_followed("'**' of a value that is not a known dict", keyword)
        return self.invoke(callee, args, kwargs, node)

    def invoke(
        self, callee: Value, args: list[Value], kwargs: dict[str, Value], node: ast.AST
    ) -> Value:
        if isinstance(callee, Unknown):
            return callee
        if isinstance(callee, Function):
            return self.call_function(callee, args, kwargs, node)
        if isinstance(callee, Method):
            return self.call_method(callee, args, kwargs, node)
        if isinstance(callee, Module):
            builtin = BUILTINS.get(callee.qualified) or CALLING.get(python_name(callee.qualified))
            if builtin is not None:
                return builtin(self, args, kwargs, node)
            call = Call(callee.qualified, args, kwargs, self.location(node), self.sink)
            builder = CALLS.get(python_name(callee.qualified))
            if builder is not None:
                return builder(call)
            reason = REASONS.get(python_name(callee.qualified))
            return self.not_followed(reason or f"call to {callee.qualified}()", node)
        return self.not_followed(f"call of a {type(callee).__name__}", node)

    def call_function(
        self, function: Function, args: list[Value], kwargs: dict[str, Value], node: ast.AST
    ) -> Value:
        if self.depth >= MAX_CALL_DEPTH:
            return self.not_followed(f"recursion of {function.node.name}()", node)
        arguments = function.node.args
        positional = [argument.arg for argument in (*arguments.posonlyargs, *arguments.args)]
        scope = Scope(dict(function.defaults), function.scope)
        for name, value in zip(positional, args, strict=False):
            scope.names[name] = value
        if arguments.vararg is not None:
            scope.names[arguments.vararg.arg] = tuple(args[len(positional) :])
        elif len(args) > len(positional):
            return self.not_followed(f"too many arguments to {function.node.name}()", node)
        extra: dict[Key, Value] = {}
        names = {*positional, *(argument.arg for argument in arguments.kwonlyargs)}
        for name, value in kwargs.items():
            if name in names:
                scope.names[name] = value
            else:
                extra[name] = value
        if arguments.kwarg is not None:
            scope.names[arguments.kwarg.arg] = extra
        elif extra:
            return self.not_followed(f"unexpected arguments to {function.node.name}()", node)
        missing = names - scope.names.keys()
        if missing:
            return self.not_followed(
                f"{function.node.name}() without {', '.join(sorted(missing))}", node
            )
        self.depth += 1
        try:
            self.block(function.node.body, scope)
        except _Return as returned:
            return returned.value
        finally:
            self.depth -= 1
        return None

    def call_method(
        self, method: Method, args: list[Value], kwargs: dict[str, Value], node: ast.AST
    ) -> Value:
        receiver, name = method.receiver, method.name
        if isinstance(receiver, Description) and name in ("add_action", "add_entity") and args:
            call = Call(f"LaunchDescription.{name}", args, kwargs, self.location(node), self.sink)
            add_actions(call, receiver.root, [args[0]])
            return None
        if isinstance(receiver, list) and name in ("append", "extend", "insert") and args:
            if name == "append":
                receiver.append(args[0])
            elif name == "insert" and len(args) == 2 and isinstance(args[0], int):
                receiver.insert(args[0], args[1])
            else:
                items = self.iterate(args[0], node)
                if items is not None and len(receiver) + len(items) > MAX_LENGTH:
                    return self.not_followed(f"a list longer than {MAX_LENGTH}", node)
                receiver.extend(items if items is not None else [Unknown("*unknown")])
            return None
        if isinstance(receiver, dict):
            return self._dict_method(receiver, name, args, node)
        if isinstance(receiver, list | tuple) and name == "copy":
            return list(receiver)
        if isinstance(receiver, Text) and name == "perform":
            return receiver  # the value at launch time, which the text stands for
        if isinstance(receiver, LaunchContext) and name == "perform_substitution" and args:
            return Call(name, args, kwargs, self.location(node), self.sink).text(args[0])
        if receiver == Method(LaunchContext(), "launch_configurations") and name == "get" and args:
            return _configuration(self, node, *args[:2])
        if isinstance(receiver, str) and name in _STR_METHODS:
            return self._str_method(receiver, name, args, kwargs, node)
        return self.not_followed(f"method {name}() of a {type(receiver).__name__}", node)

    def _dict_method(
        self, receiver: dict[Key, Value], name: str, args: list[Value], node: ast.AST
    ) -> Value:
        if name == "items":
            return [(name_, value) for name_, value in receiver.items()]
        if name == "keys":
            return list(receiver)
        if name == "values":
            return list(receiver.values())
        if name == "copy":
            return dict(receiver)
        if name == "get" and args and isinstance(args[0], Key):
            return receiver.get(args[0], args[1] if len(args) > 1 else None)
        if name == "update" and len(args) == 1 and isinstance(args[0], dict):
            receiver.update(args[0])
            return None
        return self.not_followed(f"method {name}() of a dict", node)

    def _format(
        self, template: str, args: list[Value], kwargs: dict[str, Value], node: ast.AST
    ) -> Value:
        """``str.format`` with plain fields (``{}``, ``{0}``, ``{name}``), no format specs."""
        parts: list[Value] = []
        automatic = 0
        try:
            fields = list(string.Formatter().parse(template))
        except ValueError as error:
            return self.not_followed(f"str.format() that fails ({error})", node)
        for literal, field, spec, conversion in fields:
            parts.append(literal)
            if field is None:
                continue
            if spec or conversion:
                return self.not_followed("str.format() with a format", node)
            if field == "":
                field, automatic = str(automatic), automatic + 1
            if field.isdigit() and int(field) < len(args):
                parts.append(self.stringify(args[int(field)], node))
            elif field in kwargs:
                parts.append(self.stringify(kwargs[field], node))
            else:
                return self.not_followed(f"str.format() field {{{field}}}", node)
        return self.concatenate(parts, node)

    def _str_method(
        self, receiver: str, name: str, args: list[Value], kwargs: dict[str, Value], node: ast.AST
    ) -> Value:
        if name == "join" and len(args) == 1:
            items = self.iterate(args[0], node)
            if items is None:
                return Unknown("join of unknown items")
            parts: list[Value] = []
            for index, item in enumerate(items):
                parts.extend([receiver, item] if index else [item])
            return self.concatenate(parts, node)
        if name == "format":
            return self._format(receiver, args, kwargs, node)
        if size(receiver) * max([1, *(size(arg) for arg in args)]) > MAX_LENGTH:
            return self.not_followed(f"str.{name}() of long strings", node)
        if all(_constant(arg) for arg in args) and not kwargs:
            try:
                result: Value = getattr(receiver, name)(*args)
            except (TypeError, ValueError) as error:
                return self.not_followed(f"str.{name}() that fails ({error})", node)
            return result
        return self.not_followed(f"str.{name}() of values not known statically", node)


def _str(
    interpreter: Interpreter, args: list[Value], kwargs: dict[str, Value], node: ast.AST
) -> Value:
    return interpreter.stringify(args[0], node) if len(args) == 1 else ""


def _convert(kind: type[int] | type[float] | type[bool]) -> Builtin:
    def convert(
        interpreter: Interpreter, args: list[Value], kwargs: dict[str, Value], node: ast.AST
    ) -> Value:
        if len(args) == 1 and isinstance(args[0], str | int | float | bool):
            try:
                return kind(args[0])
            except ValueError as error:
                return interpreter.not_followed(f"{kind.__name__}() that fails ({error})", node)
        if not args:
            return kind()
        return interpreter.not_followed(f"{kind.__name__}() of a value not known statically", node)

    return convert


def _len(
    interpreter: Interpreter, args: list[Value], kwargs: dict[str, Value], node: ast.AST
) -> Value:
    if len(args) == 1 and isinstance(args[0], str | list | tuple | dict):
        return len(args[0])
    return interpreter.not_followed("len() of a value not known statically", node)


def _range(
    interpreter: Interpreter, args: list[Value], kwargs: dict[str, Value], node: ast.AST
) -> Value:
    if 1 <= len(args) <= 3 and all(isinstance(arg, int) for arg in args):
        numbers = range(*(int(arg) for arg in args if isinstance(arg, int)))
        if len(numbers) <= MAX_LENGTH:
            return list(numbers)
    return interpreter.not_followed("range() of values not known statically", node)


def _collection(kind: type[list[Value]] | type[tuple[Value, ...]]) -> Builtin:
    def collect(
        interpreter: Interpreter, args: list[Value], kwargs: dict[str, Value], node: ast.AST
    ) -> Value:
        if not args:
            return kind()
        items = interpreter.iterate(args[0], node)
        return Unknown(f"{kind.__name__}() of unknown items") if items is None else kind(items)

    return collect


def _dict_builtin(
    interpreter: Interpreter, args: list[Value], kwargs: dict[str, Value], node: ast.AST
) -> Value:
    """``dict(mapping)``, ``dict(pairs)``, then keywords."""
    result: dict[Key, Value] = {}
    if args and isinstance(args[0], dict):
        result.update(args[0])
    elif args:
        pairs = interpreter.iterate(args[0], node)
        if pairs is None or not all(
            isinstance(pair, list | tuple) and len(pair) == 2 and isinstance(pair[0], Key)
            for pair in pairs
        ):
            return interpreter.not_followed("dict() of a value that is not pairs", node)
        result.update((pair[0], pair[1]) for pair in pairs)  # type: ignore[index,misc]
    result.update(kwargs)
    return result


def _enumerate(
    interpreter: Interpreter, args: list[Value], kwargs: dict[str, Value], node: ast.AST
) -> Value:
    items = interpreter.iterate(args[0], node) if args else None
    return Unknown("enumerate()") if items is None else [(i, v) for i, v in enumerate(items)]


def _zip(
    interpreter: Interpreter, args: list[Value], kwargs: dict[str, Value], node: ast.AST
) -> Value:
    columns = [interpreter.iterate(arg, node) for arg in args]
    if any(column is None for column in columns):
        return Unknown("zip()")
    return [tuple(row) for row in zip(*(column or [] for column in columns), strict=False)]


def _print(
    interpreter: Interpreter, args: list[Value], kwargs: dict[str, Value], node: ast.AST
) -> Value:
    return None


def _configuration(
    interpreter: Interpreter, node: ast.AST, name: Value, default: Value = None
) -> Value:
    """``context.launch_configurations[name]`` (``.get(name, default)``): ``$(var name)``."""
    if not isinstance(name, str):
        return interpreter.not_followed("a launch configuration named by a non-string", node)
    if default is None:
        return Text.of(Sub("var", (Text.of(name),)))
    if not isinstance(default, str | Text):
        return interpreter.not_followed("a launch configuration's non-string default", node)
    return Text.of(Sub("var", (Text.of(name), Text.of(default))))


def _opaque_function(
    interpreter: Interpreter, args: list[Value], kwargs: dict[str, Value], node: ast.AST
) -> Value:
    """``OpaqueFunction(function=f, args=..., kwargs=...)``: launch calls ``f(context, ...)``
    where the action stands and visits the actions it returns there, in the same launch
    configurations: the file's own ``f`` is read now, its actions an unscoped group."""
    call = Call("OpaqueFunction", args, kwargs, interpreter.location(node), interpreter.sink)
    function = call.arg(0, "function")
    given, named = call.arg(1, "args", []), call.arg(2, "kwargs", {})
    if not isinstance(function, Function):
        return call.not_followed(f"OpaqueFunction of a {type(function).__name__}")
    if not isinstance(given, list | tuple) or not isinstance(named, dict):
        return call.not_followed("OpaqueFunction arguments not known statically")
    if not all(isinstance(name, str) for name in named):
        return call.not_followed("OpaqueFunction keyword names not known statically")
    actions = interpreter.call_function(
        function, [LaunchContext(), *given], {str(k): v for k, v in named.items()}, node
    )
    if isinstance(actions, Unknown):
        return actions
    group = Call(
        "GroupAction",
        [],
        {"actions": [] if actions is None else actions, "scoped": False},
        call.location,
        call.sink,
    )
    return CALLS[("launch", "GroupAction")](group)


Builtin = Callable[[Interpreter, list[Value], dict[str, Value], ast.AST], Value]

CALLING: dict[tuple[str, str], Builtin] = {("launch", "OpaqueFunction"): _opaque_function}
"""Callables of the launch API that call back into the file (by (package, name))."""

BUILTINS: dict[str, Builtin] = {
    "str": _str,
    "int": _convert(int),
    "float": _convert(float),
    "bool": _convert(bool),
    "len": _len,
    "range": _range,
    "list": _collection(list),
    "tuple": _collection(tuple),
    "dict": _dict_builtin,
    "enumerate": _enumerate,
    "zip": _zip,
    "print": _print,
}
"""Python's builtins the reading follows (a call of any other is not followed)."""


def entry_point(interpreter: Interpreter, tree: ast.Module) -> Entity | None:
    """The ``launch`` element ``generate_launch_description()`` returns, or ``None``."""
    scope = interpreter.run_module(tree)
    found, function = scope.lookup("generate_launch_description")
    where = Location(interpreter.filename, 1, 1)
    if not (found and isinstance(function, Function)):
        interpreter.sink.error(
            "python-launch-entry", "no function generate_launch_description()", where
        )
        return None
    result = interpreter.call_function(function, [], {}, function.node)
    if isinstance(result, Description):
        return result.root
    if not isinstance(result, Unknown):
        interpreter.sink.error(
            "python-launch-entry",
            "generate_launch_description() does not return a LaunchDescription",
            interpreter.location(function.node),
        )
    return None
