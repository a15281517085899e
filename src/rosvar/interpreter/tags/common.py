"""Helpers shared by several tags (roslaunch's ``_ns_clear_params_attr`` and friends)."""

from __future__ import annotations

from rosvar.frontends.entity import Entity
from rosvar.interpreter.interpretation import Interpretation
from rosvar.interpreter.model import ClearParamDecl, Raw
from rosvar.interpreter.scope import Scope
from rosvar.interpreter.values import bool_attribute
from rosvar.logic.choice import Choice, Fail


def bool_value(
    it: Interpretation, value: Choice[Raw] | None, default: bool, label: str
) -> Choice[bool | Raw]:
    """``_bool_attr`` per branch; terms stay raw and are checked on resolution."""
    if value is None:
        return Choice.const(it.space, default)

    def convert(leaf: Raw) -> bool | Raw | Fail:
        if not isinstance(leaf, str):
            return leaf
        try:
            return bool_attribute(leaf, default, label)
        except ValueError as error:
            return Fail(str(error), "bool-invalid")

    return it.strip(value.map(convert), label)


def namespace_scope(
    it: Interpretation,
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
        empty = ns.where(lambda v: v == "")
        it.fail(empty, "ns-empty", f"<{tag_name}> tag has an empty 'ns' attribute")
        ns = ns.restrict(~empty)
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
        nonempty = clear.restrict(clear.where(lambda v: v != ""))
        wanted = bool_value(it, nonempty, False, "clear_params")
        condition = wanted.where(lambda v: v is True)
        if condition != it.space.false:
            with it.under(condition) as live:
                if live:
                    _clear(it, tag_name, child, ns, node_name)
    return child


def _clear(
    it: Interpretation,
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
