"""The ``when:`` of a hinted interface entry: where a launched node has that entry.

A hint may say that a node publishes ``scan`` only when its launch file's ``use_laser`` arg
is true (docs/hints.md). The text is an ``$(eval)`` expression over the args the ``<node>``'s
scope sees (``use_laser``, ``arg('robot') == 'husky'``), or a whole ``$(arg NAME)`` or
``$(eval EXPR)`` as in an ``if=`` attribute. It is evaluated by the restricted ``$(eval)``
interpreter (nothing is executed), once per jointly possible combination of the values of the
args it reads; it holds under the disjunction of the conditions of the combinations whose
value is roslaunch-true. Where the value needs an arg's text that only a configuration knows
(a typed ``<other>`` value), a ``when:`` that is that arg alone holds where the text is
``true`` (decided once it is typed, as an ``if=``), any other keeps the entry: analysis cannot
rule it out. Where an arg is undefined, or the expression fails, it does not hold. An
expression the interpreter refuses keeps the entry everywhere; it is reported when the hints
are read (:func:`refusals`).
"""

from __future__ import annotations

import re
from collections.abc import Mapping, Sequence

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
from rosvar.workspace.interfaces.model import Entry

_ARG = re.compile(r"\$\(arg\s+([^\s()]+)\s*\)")
_EVAL = re.compile(r"\$\(eval\s+(.*)\)", re.DOTALL)
_TRUE = ("true", "1")
_ALONE = re.compile(r"\s*(?:\w+|arg\((['\"])\w+\1\))\s*")


def expression(text: str) -> str:
    """The ``$(eval)`` expression a ``when:`` text stands for."""
    text = text.strip()
    if arg := _ARG.fullmatch(text):
        return f"arg({arg.group(1)!r})"
    if whole := _EVAL.fullmatch(text):
        return whole.group(1)
    return text


def refusal(text: str) -> str | None:
    """Why the restricted ``$(eval)`` refuses a ``when:`` text, or None when it takes it."""
    try:
        referenced_args(expression(text))
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


def when_condition(space: ConditionSpace, node: NodeDecl, text: str) -> BDD:
    """Where ``text`` holds for ``node``, over the args of its scope."""
    source = expression(text)
    try:
        names = sorted(referenced_args(source))
    except EvalRefused:
        return space.true
    undefined: Choice[object] = Choice.const(space, None)
    values = [node.args.get(name, undefined) for name in names]
    holds = space.false
    alone = _ALONE.fullmatch(source) is not None  # the expression is one arg's truth
    for condition, leaves in combine(values, tuple):
        shown, read = _evaluated(source, dict(zip(names, leaves, strict=True)))
        if shown is not None:
            if shown.lower() in _TRUE:
                holds |= condition
        elif alone and read:  # decided once the text is typed, as an ``if=``
            holds |= condition & space.predicate("true", read[0])
        elif read:  # a text only a configuration knows: may hold
            holds |= condition
    return holds


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
