"""The analysed model as plain data (the ``analyze`` JSON), with readable conditions."""

from __future__ import annotations

from rosvar.analyses.json_values import json_value
from rosvar.interpreter.model import (
    DeferredValue,
    ErrorEvent,
    LaunchModel,
    ParamDecl,
    ParamSource,
)
from rosvar.logic.choice import Choice
from rosvar.logic.inputs import OTHER, UNSET, Slot
from rosvar.logic.terms import Apply, Hole
from rosvar.outputs.documents.diagnostics import diagnostic_document


def _slot(slot: Slot) -> str:
    if slot is UNSET:
        return "<unset>"
    if slot is OTHER:
        return "<other>"
    return str(slot)


def _values(choice: Choice[object], model: LaunchModel) -> object:
    """One value when it does not vary, else ``[{value, condition}]``."""
    branches = list(choice)
    if len(branches) == 1:
        return _leaf(branches[0][1])
    return [
        {"value": _leaf(leaf), "condition": model.space.describe(condition)}
        for condition, leaf in branches
    ]


def _leaf(leaf: object) -> object:
    if isinstance(leaf, DeferredValue):
        return f"__command__({leaf.raw})" if leaf.kind == ParamSource.COMMAND else str(leaf.raw)
    if isinstance(leaf, Hole | Apply):
        return str(leaf)
    return json_value(leaf)


def describe_model(model: LaunchModel) -> dict[str, object]:
    space = model.space
    describe = space.describe
    return {
        "file": model.file,
        "loads": describe(model.loads),
        "args": [
            {
                "name": a.name,
                "default": a.default,
                "value": a.value,
                "doc": a.doc,
                "command_line": a.input is not None and a.value is None,
                "domain": [_slot(s) for s in model.domains.get(a.name, ())],
                "condition": describe(a.condition),
                **a.location.to_json(),
            }
            for a in model.args
        ],
        "includes": [
            {
                "target": _values(i.file, model),
                "resolved": i.resolved,
                "condition": describe(i.condition),
                **i.location.to_json(),
            }
            for i in model.includes
        ],
        "nodes": [
            {
                "name": _values(n.value(n.schema.name), model),
                "namespace": _values(n.fields["namespace"], model),  # its own (ROS 2: not pushed)
                "package": _values(n.value(n.schema.package), model),
                "type": _values(n.value(n.schema.executable), model),
                "test": n.is_test,
                "condition": describe(n.condition),
                **n.location.to_json(),
            }
            for n in model.nodes
        ],
        "params": [
            {
                "name": _values(p.name, model)
                if isinstance(p, ParamDecl)
                else f"{p.scope_ns}{p.param or ''} (YAML)",
                "value": _values(p.value, model) if isinstance(p, ParamDecl) else "<yaml>",
                "condition": describe(p.condition),
                **p.location.to_json(),
            }
            for p in model.params
        ],
        "errors": [
            {
                "code": e.code,
                "message": e.message,
                "condition": describe(e.condition),
                **e.location.to_json(),
            }
            for e in possible_errors(model)
        ],
        "diagnostics": [diagnostic_document(d) for d in model.diagnostics],
    }


def possible_errors(model: LaunchModel) -> list[ErrorEvent]:
    """The model's errors that some configuration raises: one the space's facts rule out
    (its condition met only by predicates no value makes hold together, learnt after it was
    recorded) is no error to show."""
    return [e for e in model.errors if model.space.satisfiable(e.condition)]


EXACT_BELOW = 10**7
SUPERSCRIPTS = str.maketrans("0123456789", "⁰¹²³⁴⁵⁶⁷⁸⁹")


def count_text(count: int) -> str:
    """A count for people: exact while short, else ``≈ 8.8 × 10⁵⁹`` (the JSON stays exact)."""
    if count < EXACT_BELOW:
        return str(count)
    digits = str(count)
    exponent = len(digits) - 1
    mantissa = round(count / 10**exponent, 1)
    if mantissa >= 10:  # 9.96 rounds up
        mantissa, exponent = 1.0, exponent + 1
    return f"≈ {mantissa} × 10{str(exponent).translate(SUPERSCRIPTS)}"
