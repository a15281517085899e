"""Query text to a checked syntax tree: the path form and the FLWOR form, never executed.

Two spellings select elements of one collection (HAROS's and PyFLWOR's):

* ``COLLECTION[PREDICATE][PREDICATE]...``, the element being ``self`` in each predicate;
* ``for VAR in COLLECTION [where PREDICATE] return VAR``.

A predicate is a Python expression parsed with :func:`ast.parse` (which runs nothing) and
checked against a whitelist: names, literals, attribute reads of the element, comparisons,
boolean/arithmetic operators, conditional expressions, tuples and lists, calls of a few pure
functions and of read-only ``str`` methods. Comprehensions, lambdas, dunder names, keyword
arguments and everything else are refused with :class:`QueryError` before any evaluation.
"""

from __future__ import annotations

import ast
import re
from dataclasses import dataclass
from typing import Final

from rosvar.arithmetic import COMPARISONS
from rosvar.interpreter.safe_eval.checking import _parse
from rosvar.interpreter.safe_eval.errors import EvalRefused
from rosvar.interpreter.safe_eval.names import REFUSED_NODES

FUNCTIONS: Final = frozenset({"len", "str", "int", "float", "bool", "abs", "min", "max"})
STR_METHODS: Final = frozenset(
    {
        "lower", "upper", "strip", "lstrip", "rstrip", "startswith", "endswith", "split",
        "count", "find", "rfind", "isdigit", "isalpha", "isalnum",
    }
)  # fmt: skip
"""Methods whose result is never larger than the string and its arguments."""
CONSTANTS: Final = {"True": True, "False": False, "None": None, "true": True, "false": False}
BINARY_OPERATORS: Final = (ast.Add, ast.Sub, ast.Mult, ast.Div, ast.FloorDiv, ast.Mod)
UNARY_OPERATORS: Final = (ast.Not, ast.USub, ast.UAdd)
MAX_LENGTH: Final = 2000
"""Queries are typed by people: a longer text is refused rather than parsed."""
MAX_DEPTH: Final = 100
"""Nesting of a predicate's syntax tree: its compiled closures call each other that deep."""

_FLWOR: Final = re.compile(
    r"\s*for\s+(?P<var>[A-Za-z_]\w*)\s+in\s+(?P<collection>[A-Za-z_]\w*)"
    r"(?:\s+where\s+(?P<where>.+?))?\s+return\s+(?P<ret>[A-Za-z_]\w*)\s*",
    re.DOTALL,
)
_COMPREHENSIONS: Final = (ast.ListComp, ast.SetComp, ast.DictComp, ast.GeneratorExp)


class QueryError(Exception):
    """The query is not valid or not allowed; ``col`` is the offset in the query text."""

    def __init__(self, message: str, col: int = 0) -> None:
        super().__init__(message)
        self.message = message
        self.col = col

    def __str__(self) -> str:
        return f"{self.message} (at character {self.col + 1})"


@dataclass(frozen=True)
class Predicate:
    """One filter: ``body`` evaluated with the element bound to ``variable``."""

    body: ast.expr
    variable: str
    offset: int  # where the predicate's text starts in the query


@dataclass(frozen=True)
class Query:
    text: str
    collection: str
    predicates: tuple[Predicate, ...]


def parse(text: str) -> Query:
    """The checked query; :class:`QueryError` for anything else."""
    if len(text) > MAX_LENGTH:
        raise QueryError(f"query longer than {MAX_LENGTH} characters")
    flwor = _FLWOR.fullmatch(text)
    if flwor is not None:
        return _flwor(text, flwor)
    tree = _expression(text, 0)
    predicates: list[Predicate] = []
    while isinstance(tree, ast.Subscript):
        predicates.append(Predicate(_checked(tree.slice, "self"), "self", 0))
        tree = tree.value
    if not isinstance(tree, ast.Name):
        raise QueryError("a query is COLLECTION[PREDICATE] or for X in COLLECTION ... return X")
    return Query(text, tree.id, tuple(reversed(predicates)))


def _flwor(text: str, match: re.Match[str]) -> Query:
    variable = match["var"]
    if match["ret"] != variable:
        raise QueryError(f"return must name the variable '{variable}'", match.start("ret"))
    if variable in CONSTANTS or variable in FUNCTIONS:
        raise QueryError(f"'{variable}' cannot be a variable", match.start("var"))
    predicates: tuple[Predicate, ...] = ()
    if match["where"] is not None:
        offset = match.start("where")
        body = _checked(_expression(match["where"], offset), variable, offset)
        predicates = (Predicate(body, variable, offset),)
    return Query(text, match["collection"], predicates)


def _expression(text: str, offset: int) -> ast.expr:
    dunder = text.find("__")
    if dunder >= 0:
        raise QueryError("names with double underscores are not allowed", offset + dunder)
    try:
        tree, _source = _parse(text)
    except EvalRefused as refused:
        raise QueryError(refused.message, offset + max(refused.col, 0)) from None
    return tree.body


def _checked(node: ast.expr, variable: str, offset: int = 0) -> ast.expr:
    """``node`` when the whitelist allows all of it."""
    _Checker(variable, offset).visit(node)
    return node


class _Checker:
    def __init__(self, variable: str, offset: int) -> None:
        self.variable = variable
        self.offset = offset
        self.depth = 0

    def refuse(self, message: str, node: ast.AST) -> QueryError:
        return QueryError(message, self.offset + getattr(node, "col_offset", 0))

    def visit(self, node: ast.expr) -> None:
        self.depth += 1
        if self.depth > MAX_DEPTH:
            raise self.refuse(f"the predicate is nested more than {MAX_DEPTH} levels deep", node)
        self.check(node)
        self.depth -= 1

    def check(self, node: ast.expr) -> None:
        if isinstance(node, ast.Constant):
            if not isinstance(node.value, (str, int, float, bool, type(None))):
                raise self.refuse("only str, number, bool and None literals", node)
        elif isinstance(node, ast.Name):
            if node.id == self.variable:
                raise self.refuse(f"read attributes of the element: {node.id}.ATTRIBUTE", node)
            if node.id not in CONSTANTS:
                allowed = ", ".join([f"{self.variable}.ATTRIBUTE", *sorted(CONSTANTS)])
                raise self.refuse(f"unknown name '{node.id}' (names: {allowed})", node)
        elif isinstance(node, ast.Attribute):
            if not (isinstance(node.value, ast.Name) and node.value.id == self.variable):
                raise self.refuse(f"attributes are read from {self.variable} only", node)
        elif isinstance(node, ast.Call):
            self.visit_call(node)
        elif isinstance(node, ast.BoolOp):
            for value in node.values:
                self.visit(value)
        elif isinstance(node, ast.BinOp):
            if not isinstance(node.op, BINARY_OPERATORS):
                raise self.refuse(f"operator {type(node.op).__name__} is not allowed", node)
            self.visit(node.left)
            self.visit(node.right)
        elif isinstance(node, ast.UnaryOp):
            if not isinstance(node.op, UNARY_OPERATORS):
                raise self.refuse(f"operator {type(node.op).__name__} is not allowed", node)
            self.visit(node.operand)
        elif isinstance(node, ast.Compare):
            if not all(type(op) in COMPARISONS for op in node.ops):
                raise self.refuse("comparison not allowed", node)
            for operand in (node.left, *node.comparators):
                self.visit(operand)
        elif isinstance(node, ast.IfExp):
            for part in (node.test, node.body, node.orelse):
                self.visit(part)
        elif isinstance(node, (ast.Tuple, ast.List)):
            for item in node.elts:
                self.visit(item)
        elif isinstance(node, ast.Subscript):
            self.visit(node.value)
            self.visit_index(node.slice)
        else:
            raise self.refuse(self.why(node), node)

    def visit_index(self, node: ast.expr) -> None:
        if isinstance(node, ast.Slice):
            for part in (node.lower, node.upper, node.step):
                if part is not None:
                    self.visit(part)
        else:
            self.visit(node)

    def visit_call(self, node: ast.Call) -> None:
        if node.keywords or any(isinstance(a, ast.Starred) for a in node.args):
            raise self.refuse("calls take positional arguments only", node)
        function = node.func
        if isinstance(function, ast.Name) and function.id in FUNCTIONS:
            pass
        elif isinstance(function, ast.Attribute) and function.attr in STR_METHODS:
            self.visit(function.value)
        else:
            allowed = ", ".join([*sorted(FUNCTIONS), *(f"str.{m}" for m in sorted(STR_METHODS))])
            raise self.refuse(f"only these functions can be called: {allowed}", node)
        for argument in node.args:
            self.visit(argument)

    @staticmethod
    def why(node: ast.expr) -> str:
        if isinstance(node, _COMPREHENSIONS):
            return "comprehensions are not allowed (use: for X in COLLECTION where ... return X)"
        return REFUSED_NODES.get(type(node), f"{type(node).__name__} expressions are not allowed")
