"""Helpers shared by several tags (roslaunch's ``_ns_clear_params_attr`` and friends)."""

from __future__ import annotations

from rosvar.frontends.entity import Entity
from rosvar.interpreter.booleans import bool_value
from rosvar.interpreter.interpretation import Interpretation
from rosvar.interpreter.model import ClearParamDecl, Raw
from rosvar.logic.atoms import PREDICATES, register_predicate
from rosvar.logic.bdd import BDD
from rosvar.logic.cells import register_predicate_texts, spellings
from rosvar.logic.choice import Choice
from rosvar.logic.terms import Apply, Hole
from rosvar.ros1.scope import Scope

# Tests on attribute text; on a term they become predicate atoms decided per configuration.
register_predicate("empty", lambda text: text == "", "{} is empty")
register_predicate("bool-true", lambda text: text.lower() == "true", "{} is 'true'")
register_predicate("bool-false", lambda text: text.lower() == "false", "{} is 'false'")
register_predicate_texts("empty", ("",))
for _test in ("bool-true", "bool-false"):
    register_predicate_texts(_test, spellings(("true", "false")))


def where_text(it: Interpretation[Scope], value: Choice[object], test: str) -> BDD:
    """Where ``value`` is text passing the predicate ``test``: decided now for strings, later
    (as a predicate atom) for terms."""
    check = PREDICATES[test][0]
    result = it.space.false
    for condition, leaf in value:
        if isinstance(leaf, str):
            if check(leaf):
                result |= condition
        elif isinstance(leaf, Hole | Apply):
            result |= condition & it.space.predicate(test, leaf)
    return result


def namespace_scope(
    it: Interpretation[Scope],
    tag_name: str,
    entity: Entity,
    scope: Scope,
    node_name: Choice[Raw] | None = None,
    include_filename: str | None = None,
) -> Scope:
    """The child scope of a tag with ``ns``/``clear_params`` (roslaunch rules and errors)."""
    ns: Choice[Raw] | None = None
    if entity.has("ns"):
        ns = it.attr(entity, "ns", scope)
        assert ns is not None
        empty = where_text(it, ns, "empty")
        if empty != it.space.false:
            it.fail(empty, "ns-empty", f"<{tag_name}> tag has an empty 'ns' attribute")
            ns = ns.restrict(~empty)
    if ns is None and all(isinstance(leaf, str) for _c, leaf in scope.ns):
        child_ns = scope.ns  # what child_namespace gives without a child (a term it would wrap)
    else:
        child_ns = it.lift(
            "child_namespace",
            scope.ns,
            ns if ns is not None else Choice.const(it.space, ""),
            context=f"<{tag_name}> namespace",
        )
    if include_filename is not None:
        child = scope.include_child(child_ns, include_filename)
    else:
        child = scope.child(child_ns)
    clear = it.attr(entity, "clear_params", scope)
    if clear is not None:
        empty = where_text(it, clear, "empty")
        wanted = bool_value(it, clear.restrict(~empty), False, "clear_params")  # `if clear_p:`
        true, false = where_text(it, wanted, "bool-true"), where_text(it, wanted, "bool-false")
        it.space.constrain(~(true & false) & ~(where_text(it, clear, "bool-true") & empty))
        condition = wanted.where(lambda v: v is True) | true
        unknown = wanted.where(lambda v: not isinstance(v, bool)) & ~true & ~false
        it.fail(unknown, "bool-invalid", "invalid bool value for clear_params")
        if condition != it.space.false:
            with it.under(condition) as live:
                if live:
                    _clear(it, tag_name, child, ns, node_name)
    return child


def _clear(
    it: Interpretation[Scope],
    tag_name: str,
    child: Scope,
    ns: Choice[Raw] | None,
    node_name: Choice[Raw] | None,
) -> None:
    if tag_name == "node":
        if node_name is None:
            it.fail(
                it.space.true,
                "clear-params-invalid",
                f"<{tag_name}> tag must have a 'name' attribute to use 'clear_params'",
            )
            return
        name = it.lift("make_global_ns", it.lift("ns_join", child.ns, node_name))
    else:
        if ns is None:
            it.fail(
                it.space.true,
                "clear-params-invalid",
                "'ns' attribute must be set in order to use 'clear_params'",
            )
            return
        name = child.ns
    it.model.clear_params.append(ClearParamDecl(it.pc, it.location, name))
