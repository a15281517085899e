"""``<arg>``: declare an arg, give it a value or a default (``LoaderContext.add_arg``)."""

from __future__ import annotations

from rosvar.frontends.entity import Entity
from rosvar.interpreter.interpretation import Interpretation, processed, split
from rosvar.interpreter.model import ArgDecl, Raw
from rosvar.interpreter.substitution_args import MISSING, ArgValue
from rosvar.logic.choice import Choice, ite
from rosvar.ros1.dialect import tag
from rosvar.ros1.scope import Scope

ATTRIBUTES = ("name", "value", "default", "doc")


@tag("arg")
@processed
def handle_arg(it: Interpretation[Scope], entity: Entity, scope: Scope) -> None:
    it.check_attributes(entity, ATTRIBUTES)
    names = it.required(entity, "name", scope)
    if names is None:
        return
    value = it.attr(entity, "value", scope)
    default = it.attr(entity, "default", scope)
    it.attr(entity, "doc", scope)
    if value is not None and default is not None:
        it.fail(
            it.space.true,
            "arg-value-and-default",
            "<arg> tag must have one and only one of value/default.",
        )
        return
    for condition, name in split(it, names):
        if not isinstance(name, str):
            it.warn("arg-name-unknown", f"arg name {name} is only known per configuration")
            continue
        with it.under(condition):
            declare(it, scope, name, value, default)
            if len(it.stack) == 1 and scope.include_args is None:
                it.model.args.append(
                    ArgDecl(
                        name=name,
                        location=entity.location,
                        condition=it.pc,
                        default=entity.get("default"),
                        value=entity.get("value"),
                        doc=entity.get("doc"),
                        input=it.model.inputs.get(name),
                    )
                )


def declare(
    it: Interpretation[Scope],
    scope: Scope,
    name: str,
    value: Choice[Raw] | None,
    default: Choice[Raw] | None,
) -> None:
    """``add_arg`` on the current path."""
    false = it.space.false
    declared = scope.declared.get(name, false)
    if declared == false:  # most args: declared once (no message to format)
        scope.declared[name] = it.pc
    else:
        if not scope.pass_all_args:
            it.fail(declared, "arg-duplicate", f"arg '{name}' has already been declared")
        scope.declared[name] = declared | it.pc
    target = scope.include_args if scope.include_args is not None else scope.args
    existing = target.get(name)
    old: ArgValue = existing if existing is not None else Choice.const(it.space, MISSING)
    if value is not None:
        if existing is not None and not scope.pass_all_args:
            it.fail(
                existing.where(lambda v: v is not MISSING),
                "arg-override",
                f"cannot override arg '{name}', which has already been set",
            )
        target[name] = ite(it.space, it.pc, value, old)
    elif default is not None:
        if existing is None:
            new: ArgValue = default
        elif all(v is not MISSING for _c, v in existing.branches):
            new = existing  # given everywhere: the default never applies
        else:
            new = existing.bind(lambda v: default if v is MISSING else Choice.const(it.space, v))
        target[name] = ite(it.space, it.pc, new, old)
    elif existing is None:
        target[name] = old  # declared, no value: MISSING
