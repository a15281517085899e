"""String functions of roslaunch lifted to conditional, possibly unknown values.

``lift("ns_join", a, b)`` applies :func:`rosvar.ros.names.ns_join` to every
combination of branches; where an operand is a term the result is a term that
applies the same function later. A ``ValueError`` is roslaunch raising, so it
becomes a :class:`Fail` branch.
"""

from __future__ import annotations

import functools
from collections.abc import Callable

from rosvar.interpreter.model import Raw
from rosvar.logic.choice import Choice, Fail, combine
from rosvar.logic.terms import Apply, is_term, register
from rosvar.ros import names

StringFunction = Callable[..., str]
LIFTED: dict[str, StringFunction] = {
    "ns_join": names.ns_join,
    "child_namespace": lambda ns, child: names.child_namespace(ns, child or None),
    "make_global_ns": names.make_global_ns,
    "canonicalize": names.canonicalize_name,
    "node_namespace": lambda ns: _collapse(names.make_global_ns(ns or "/")),
    "strip": str.strip,
    "append": lambda a, b: a + b,
    "private_key": lambda ns, key: names.canonicalize_name(
        ns + (key[1:] if key[:1] == "~" else key)
    ),
}


def _collapse(text: str) -> str:
    while "//" in text:
        text = text.replace("//", "/")
    return text


for _name, _function in LIFTED.items():
    register(_name, lambda _host, *operands, _f=_function: _f(*operands))


def lift(name: str, *operands: Choice[Raw]) -> Choice[Raw | Fail]:
    """``LIFTED[name]`` over all branch combinations of ``operands``."""
    return combine(list(operands), lambda leaves: apply(name, tuple(leaves)))


@functools.lru_cache(maxsize=65536)
def apply(name: str, leaves: tuple[Raw, ...]) -> Raw | Fail:
    """One combination (cached: the same namespaces and names recur in every includer)."""
    if any(is_term(leaf) for leaf in leaves):
        return Apply(name, leaves)
    try:
        return LIFTED[name](*leaves)
    except ValueError as error:
        return Fail(str(error), "name-invalid")
