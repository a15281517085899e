"""The ``when:`` of a hinted interface entry: where a launched node has that entry.

A hint may say that a node publishes ``scan`` only when its launch file's ``use_laser`` arg
is true, or only when its own parameter ``~use_imu`` is (docs/hints.md). The text is an
``$(eval)`` expression over the args the ``<node>``'s scope sees (``use_laser``,
``arg('robot') == 'husky'``) and the node's parameters (``param('~use_imu')``: private, relative
and global names resolved as the node resolves them), or a whole ``$(arg NAME)`` or
``$(eval EXPR)`` as in an ``if=`` attribute. Each ``param('NAME')`` is replaced by the
parameter's value as a literal, then the restricted ``$(eval)`` interpreter evaluates the rest
(nothing is executed), once per jointly possible combination of the values of the args and
parameters it reads; it holds under the disjunction of the conditions of the combinations
whose value is roslaunch-true. Where the value needs an arg's text that only a configuration
knows (a typed ``<other>`` value), a ``when:`` that is that arg (or that parameter, set from
it) alone holds where the text is ``true`` (decided once it is typed, as an ``if=``), any
other keeps the entry: analysis cannot rule it out. A parameter whose value analysis cannot
know (:class:`Unknown`: unset without a default, a term, an unknown ``<rosparam>``) keeps the
entry too, and the condition says where (:attr:`When.unknown`, reported by ``rosvar check``).
Where an arg is undefined, or the expression fails, it does not hold. An expression the
interpreter refuses keeps the entry everywhere; it is reported when the hints are read
(:func:`refusals`).
"""

from __future__ import annotations

import ast
import copy
import functools
import re
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass

from rosvar.analyses.param_values import Unknown
from rosvar.diagnostics import Diagnostic, Severity
from rosvar.interpreter.model import NodeDecl
from rosvar.interpreter.safe_eval import (
    EvalEnvironment,
    EvalFailed,
    EvalRefused,
    evaluate,
    referenced_args,
)
from rosvar.logic.bdd import BDD
from rosvar.logic.choice import Choice, combine
from rosvar.logic.conditions import ConditionSpace
from rosvar.logic.terms import Apply, Hole
from rosvar.ros import names
from rosvar.workspace.interfaces.model import Entry

_ARG = re.compile(r"\$\(arg\s+([^\s()]+)\s*\)")
_EVAL = re.compile(r"\$\(eval\s+(.*)\)", re.DOTALL)
_TRUE = ("true", "1")
_ALONE = re.compile(r"\s*(?:\w+|arg\((['\"])\w+\1\))\s*")
_ALONE_PARAM = re.compile(r"\s*param\((['\"])[^'\"]+\1\)\s*")
_PARAM = "param"
ParamLookup = Callable[[str], Choice[object]]
"""The values of a node's parameter, by its name as the ``when:`` writes it."""


@dataclass(frozen=True)
class When:
    """Where a hinted entry exists: ``condition``; ``unknown`` is the part of it where it
    is kept only because a parameter's value is not known, for the ``reasons`` given."""

    condition: BDD
    unknown: BDD
    reasons: tuple[str, ...] = ()


def expression(text: str) -> str:
    """The ``$(eval)`` expression a ``when:`` text stands for."""
    text = text.strip()
    if arg := _ARG.fullmatch(text):
        return f"arg({arg.group(1)!r})"
    if whole := _EVAL.fullmatch(text):
        return whole.group(1)
    return text


@dataclass(frozen=True)
class _Template:
    """An expression whose ``param('NAME')`` calls are holes for literals."""

    tree: ast.Expression | None  # None: no parameter is read (the text is evaluated as is)
    source: str
    params: tuple[str, ...]

    def filled(self, values: Sequence[object]) -> str:
        """The expression with each parameter's value (JSON-like) as a literal."""
        if self.tree is None:
            return self.source
        literals = dict(zip(self.params, values, strict=True))
        return ast.unparse(_Filler(literals).visit(copy.deepcopy(self.tree)))


class _Filler(ast.NodeTransformer):
    def __init__(self, literals: Mapping[str, object]) -> None:
        self.literals = literals

    def visit_Call(self, node: ast.Call) -> ast.AST:
        name = _param_name(node)
        if name is None:
            return self.generic_visit(node)
        return ast.parse(repr(self.literals[name]), mode="eval").body


@functools.lru_cache(maxsize=1024)
def _template(source: str) -> _Template:
    """The parameters ``source`` reads; :class:`EvalRefused` where it is refused (a
    ``param`` call that is not one literal name included)."""
    try:
        tree = ast.parse(source.lstrip(" \t"), mode="eval")
    except (SyntaxError, ValueError, RecursionError, MemoryError):
        referenced_args(source)  # raises the evaluator's own refusal
        raise EvalRefused("cannot parse expression") from None
    read: list[str] = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Call) and _is_param_call(node):
            name = _param_name(node)
            if name is None or not names.is_legal_name(name) or not name:
                raise EvalRefused(
                    "param() takes one parameter name written as a string ('~x', 'x' or '/x')"
                )
            if name not in read:
                read.append(name)
    template = _Template(tree if read else None, source, tuple(read))
    referenced_args(template.filled([None] * len(read)))  # the rest as $(eval) checks it
    return template


def _is_param_call(node: ast.Call) -> bool:
    return isinstance(node.func, ast.Name) and node.func.id == _PARAM


def _param_name(node: ast.Call) -> str | None:
    """NAME of ``param('NAME')``, else None."""
    if not _is_param_call(node) or node.keywords or len(node.args) != 1:
        return None
    argument = node.args[0]
    if isinstance(argument, ast.Constant) and isinstance(argument.value, str):
        return argument.value
    return None


def params_read(text: str) -> tuple[str, ...]:
    """The parameter names a ``when:`` text reads (none where it is refused)."""
    try:
        return _template(expression(text)).params
    except EvalRefused:
        return ()


def refusal(text: str) -> str | None:
    """Why the restricted ``$(eval)`` refuses a ``when:`` text, or None when it takes it."""
    try:
        _template(expression(text))
    except EvalRefused as refused:
        return refused.message
    return None


def refusals(nodes: Mapping[str, Sequence[Entry]]) -> list[Diagnostic]:
    """A ``hints-invalid`` diagnostic for each hinted entry whose ``when:`` is refused."""
    found = []
    for key, entries in nodes.items():
        for entry in entries:
            reason = None if entry.when is None else refusal(entry.when)
            if reason is not None:
                message = f"the 'when' of {key} {entry.role} {entry.name} is refused: {reason}"
                found.append(Diagnostic("hints-invalid", Severity.ERROR, message, entry.location))
    return found


def when_condition(space: ConditionSpace, node: NodeDecl, text: str, params: ParamLookup) -> When:
    """Where ``text`` holds for ``node``, over the args of its scope and the values of its
    parameters (``params``)."""
    source = expression(text)
    try:
        template = _template(source)
        names_ = sorted(referenced_args(template.filled([None] * len(template.params))))
    except EvalRefused:
        return When(space.true, space.false)
    undefined: Choice[object] = Choice.const(space, None)
    values = [node.args.get(name, undefined) for name in names_]
    values += [params(name) for name in template.params]
    holds = unknown = space.false
    reasons: list[str] = []
    alone = _ALONE.fullmatch(source) is not None  # the expression is one arg's truth
    alone_param = _ALONE_PARAM.fullmatch(source) is not None  # one parameter's truth
    for condition, leaves in combine(values, tuple):
        texts = dict(zip(names_, leaves[: len(names_)], strict=True))
        read_params = leaves[len(names_) :]
        missing = [
            (name, value)
            for name, value in zip(template.params, read_params, strict=True)
            if isinstance(value, Unknown)
        ]
        if missing:
            [(_name, value), *others] = missing
            if alone_param and not others and value.term is not None:  # decided once typed
                holds |= condition & space.predicate("true", value.term)
                continue
            holds |= condition  # analysis cannot rule it out
            unknown |= condition
            for name, value in missing:
                if f"{name}: {value.reason}" not in reasons:
                    reasons.append(f"{name}: {value.reason}")
            continue
        shown, read = _evaluated(template.filled(read_params), texts)
        if shown is not None:
            if shown.lower() in _TRUE:
                holds |= condition
        elif alone and read:  # decided once the text is typed, as an ``if=``
            holds |= condition & space.predicate("true", read[0])
        elif read:  # a text only a configuration knows: may hold
            holds |= condition
    return When(holds, unknown, tuple(reasons))


def concrete_holds(text: str, args: Mapping[str, str], params: Callable[[str], object]) -> bool:
    """Whether ``text`` holds in one configuration: ``args`` are the texts of the node's
    args, ``params`` gives the value of a parameter by its name as written (an
    :class:`Unknown` where it is not known: the entry is kept, as the variational
    condition keeps it)."""
    source = expression(text)
    try:
        template = _template(source)
    except EvalRefused:
        return True
    values = [params(name) for name in template.params]
    if any(isinstance(value, Unknown) for value in values):
        return True
    shown, _read = _evaluated(template.filled(values), args)
    return shown is not None and shown.lower() in _TRUE


def _evaluated(source: str, texts: Mapping[str, object]) -> tuple[str | None, list[Hole | Apply]]:
    """The expression's value with the args' ``texts`` (None where it fails), and the terms it
    needed (their texts unknown, it failed on the first)."""
    read: list[Hole | Apply] = []

    def lookup(name: str) -> str:
        text = texts[name]
        if isinstance(text, Hole | Apply):
            read.append(text)
        if not isinstance(text, str):
            raise KeyError(name)
        return text

    try:
        return evaluate(source, EvalEnvironment(lookup_arg=lookup)), read
    except (EvalFailed, EvalRefused):
        return None, read
