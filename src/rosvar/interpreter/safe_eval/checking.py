"""Parsing and static checking of an expression: the whitelist, before anything runs, and
the args it reads and the literals they are compared with."""

from __future__ import annotations

import ast
import functools
import re
import warnings
from typing import Final, NoReturn, cast

from rosvar.arithmetic import BINARY
from rosvar.interpreter.safe_eval.errors import CallRefused, EvalRefused
from rosvar.interpreter.safe_eval.limits import MAX_NESTING, nesting
from rosvar.interpreter.safe_eval.names import (
    _BOOL_NAMES,
    _CALLABLE_NAMES,
    _CASE_METHODS,
    _CONVERSION_FUNCTIONS,
    _LITERAL_TYPES,
    _NOT_ARG_NAMES,
    _STR_METHODS,
    REFUSED_NODES,
    ROSLAUNCH_CALLS,
)

_DUNDER_MESSAGE: Final = "$(eval ...) may not contain double underscore expressions"


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
def _checked(
    expr: str, namespaces: frozenset[str] = frozenset(), dunder_text: bool = True
) -> tuple[ast.Expression, _Source, _Analyser]:
    """Parsed and checked once per text (read-only afterwards): an expression is evaluated
    for every combination of the values of the args it reads, in every includer.
    ``namespaces``: names whose members may be read (``math.pi``, xacro's);
    ``dunder_text``: whether a ``__`` anywhere in the text is refused (see
    :attr:`EvalEnvironment.dunder_text`); identifiers with one always are."""
    tree, source = _parse(expr, dunder_text)
    return tree, source, _analyse(tree, source, namespaces)


def _parse(expr: str, dunder_text: bool = True) -> tuple[ast.Expression, _Source]:
    """Parse like ``eval`` would (leading blanks stripped); never compiles to code."""
    dunder = expr.find("__") if dunder_text else -1
    if dunder >= 0:
        raise EvalRefused(_DUNDER_MESSAGE, dunder)
    text = expr.lstrip(" \t")
    source = _Source(text, len(expr) - len(text))
    if nesting(text) > MAX_NESTING:
        raise EvalRefused(
            f"expression is nested more than {MAX_NESTING} levels deep", source.prefix
        )
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

    def __init__(self, source: _Source, namespaces: frozenset[str]) -> None:
        self._source = source
        self._namespaces = namespaces
        self.args: set[str] = set()
        self.names: set[str] = set()  # every free name read or called
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
            if bound is None:
                self.names.add(node.id)
                if node.id not in _NOT_ARG_NAMES:
                    self.args.add(node.id)
        elif isinstance(node, ast.BoolOp):
            for value in node.values:
                self.visit(value, bound)
        elif isinstance(node, ast.UnaryOp):
            self.visit(node.operand, bound)
        elif isinstance(node, ast.BinOp):
            if type(node.op) not in BINARY:
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
        elif isinstance(node, ast.Attribute) and self._member(node, bound):
            self.visit(node.value, bound)
        elif isinstance(node, ast.Attribute):
            raise EvalRefused(
                f"attribute access '.{node.attr}' is not allowed"
                " (only calls of whitelisted str methods)",
                self._source.attr_col(node),
            )
        else:
            message = REFUSED_NODES.get(type(node), f"{type(node).__name__} is not allowed")
            self._refuse(message, node)

    def _member(self, node: ast.Attribute, bound: frozenset[str] | None) -> bool:
        """Whether ``node`` reads a member of a namespace (not of a comprehension's name)."""
        self._check_identifier(node.attr, node)
        value = node.value
        return (
            isinstance(value, ast.Name)
            and value.id in self._namespaces
            and (bound is None or value.id not in bound)
        )

    def _visit_call(self, node: ast.Call, bound: frozenset[str] | None) -> None:
        func = node.func
        if isinstance(func, ast.Attribute) and self._member(func, bound):
            self.visit(func, bound)
        elif isinstance(func, ast.Name):
            self._check_identifier(func.id, func)
            if bound is None:
                self.names.add(func.id)
            if func.id not in _CALLABLE_NAMES:
                raise CallRefused(
                    func.id,
                    f"calling '{func.id}' is not allowed (only {ROSLAUNCH_CALLS})",
                    self._source.col(func),
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


def _analyse(tree: ast.Expression, source: _Source, namespaces: frozenset[str]) -> _Analyser:
    analyser = _Analyser(source, namespaces)
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
