"""``<machine>``: a host nodes may run on; ``default="true"`` changes later nodes' machine."""

from __future__ import annotations

from rosvar.frontends.entity import Entity
from rosvar.interpreter.interpretation import Interpretation, processed, split
from rosvar.interpreter.model import MachineDecl
from rosvar.logic.choice import Choice, ite
from rosvar.ros1.dialect import tag
from rosvar.ros1.scope import Scope

ATTRIBUTES = ("name", "address", "env-loader", "ssh-port", "user", "password", "default", "timeout")


@tag("machine")
@processed
def handle_machine(it: Interpretation[Scope], entity: Entity, scope: Scope) -> None:
    it.check_attributes(entity, ATTRIBUTES)
    name = it.required(entity, "name", scope)
    address = it.required(entity, "address", scope)
    if name is None or address is None:
        return
    attributes = {a: it.attr(entity, a, scope) for a in ATTRIBUTES[1:]}
    for child in entity.children:
        if child.tag == "env":
            it.fail(
                it.space.true,
                "machine-env",
                "<machine>: <env> tag is not supported since ROS Fuerte.",
                child.location,
            )
        else:
            it.warn("tag-unknown", f"unrecognized '{child.tag}' tag in <machine> tag")
    default = attributes["default"] or Choice.const(it.space, "false")
    is_default = it.space.false
    for condition, word in split(it, default):
        if not isinstance(word, str):
            continue
        lowered = word.lower()
        if lowered not in ("true", "false", "never"):
            it.fail(condition, "machine-invalid", f"Invalid value for 'attribute': {lowered}")
        elif lowered == "true":
            is_default |= condition
    it.model.machines.append(
        MachineDecl(it.pc, entity.location, name, dict(attributes))  # type: ignore[arg-type]
    )
    if is_default != it.space.false:
        it.default_machine = ite(it.space, it.pc & is_default, name, it.default_machine)
