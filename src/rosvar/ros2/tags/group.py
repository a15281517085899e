"""``<group>`` (``GroupAction``) and ``<push-ros-namespace>``.

A group scopes launch configurations (and so the pushed namespace, global remaps and
global params) unless ``scoped="false"``; ``forwarding="false"`` starts its body from
the ``<keep>`` configurations only.
"""

from __future__ import annotations

from rosvar.frontends.entity import Entity
from rosvar.interpreter.booleans import bool_value
from rosvar.interpreter.interpretation import Interpretation, processed, split
from rosvar.interpreter.model import Raw
from rosvar.logic.choice import Choice, Fail, combine
from rosvar.logic.terms import Apply, TermError, register
from rosvar.ros2.context import Context, optional
from rosvar.ros2.conventions.names import namespace_problem
from rosvar.ros2.conventions.namespaces import make_absolute, prefix_namespace
from rosvar.ros2.dialect import tag
from rosvar.ros2.tags.common import assign, set_configuration


def _flag(
    it: Interpretation[Context], entity: Entity, name: str, context: Context
) -> Choice[bool | Raw]:
    return bool_value(it, it.attr(entity, name, context), True, f"<group> attribute '{name}'")


@tag("group")
@processed
def group(it: Interpretation[Context], entity: Entity, context: Context) -> None:
    body = [child for child in entity.children if child.tag != "keep"]
    keeps = [child for child in entity.children if child.tag == "keep"]
    scoped = _flag(it, entity, "scoped", context)
    forwarding = _flag(it, entity, "forwarding", context)
    for condition, (is_scoped, is_forwarding) in split(it, combine([scoped, forwarding], tuple)):
        with it.under(condition) as live:
            if not live:
                continue
            if is_scoped is not True:
                _keep(it, keeps, context, context)
                it.walk(body, context)
                continue
            saved = context.scoped()
            if is_forwarding is not True:
                context.forgetting.happened = True
                context.configurations = {}
                context.namespace = None
                context.remaps = None
                context.params = None
            _keep(it, keeps, saved, context)
            try:
                it.walk(body, context)
            finally:
                context.restore(saved)


def _keep(
    it: Interpretation[Context], keeps: list[Entity], source: Context, target: Context
) -> None:
    """``<keep name= value=>``: set before the body, values read in the enclosing context."""
    for keep in keeps:
        name, value = keep.get("name"), it.attr(keep, "value", source)
        if name and value is not None:
            set_configuration(it, target, name, optional(value))


@tag("push-ros-namespace")
@tag("push_ros_namespace")
@processed
def push_ros_namespace(it: Interpretation[Context], entity: Entity, context: Context) -> None:
    pushed = it.required(entity, "namespace", context)
    if pushed is None:
        return
    base = context.namespace or Choice.const(it.space, None)
    combined: Choice[Raw] = it.strip(
        combine([base, optional(pushed)], _push), "<push-ros-namespace>"
    )
    context.namespace = assign(it, context.namespace, optional(combined))


def _push(leaves: list[Raw | None]) -> Raw | Fail:
    """The namespace ``pushed`` under ``base``; with a value known only in a configuration
    (an argument's, a loop's item over one, one given up: a term) a term that the
    configuration computes (:data:`PUSHED`)."""
    base, pushed = leaves
    if pushed is None:
        return Fail("the namespace depends on an unknown value", "value-unknown")
    if isinstance(base, str | None) and isinstance(pushed, str):
        return _pushed(base, pushed)
    shown = make_absolute(prefix_namespace(str(base or ""), str(pushed)))
    return Apply(PUSHED, (base or "", pushed), shown or "/")


def _pushed(base: str | None, pushed: str) -> str | Fail:
    """The namespace, or launch_ros's failure where it is no valid namespace."""
    result = make_absolute(prefix_namespace(base, pushed))
    assert result is not None
    if namespace_problem(result) is None:
        return result
    return Fail(
        "The resulting namespace is invalid: "
        f"[previous_namespace='{base}', pushed_namespace='{pushed}']",
        "name-invalid",
    )


def _pushed_term(_host: object, base: str, pushed: str) -> str:
    value = _pushed(base or None, pushed)
    if isinstance(value, Fail):
        raise TermError(value.message, value.code)
    return value


PUSHED = "rosvar-pushed-namespace"
"""The term of a namespace pushed under another, either known only in a configuration."""

register(PUSHED, _pushed_term)
