"""``<node>`` and ``<test>``: a process of the computation graph (``_node_tag``)."""

from __future__ import annotations

from rosvar.frontends.entity import Entity
from rosvar.interpreter.interpretation import Interpretation, processed
from rosvar.interpreter.model import EnvSetting, NodeDecl, ParamDecl, Raw, Remap
from rosvar.logic.choice import Choice, combine
from rosvar.ros.names import is_legal_name
from rosvar.ros1.dialect import ROS1, tag
from rosvar.ros1.scope import Scope
from rosvar.ros1.tags.common import namespace_scope
from rosvar.ros1.tags.env import handle_env
from rosvar.ros1.tags.param import handle_param
from rosvar.ros1.tags.remap import add_remaps
from rosvar.ros1.tags.rosparam import handle_rosparam
from rosvar.ros1.validation import node_problem

NODE_ATTRIBUTES = (
    "pkg",
    "type",
    "machine",
    "name",
    "args",
    "output",
    "respawn",
    "respawn_delay",
    "cwd",
    "ns",
    "clear_params",
    "launch-prefix",
    "required",
)
TEST_ATTRIBUTES = (*NODE_ATTRIBUTES, "test-name", "time-limit", "retry")


OPTIONAL = (
    "machine",
    "args",
    "output",
    "respawn",
    "respawn_delay",
    "cwd",
    "launch-prefix",
    "required",
)


@tag("node")
def handle_node(it: Interpretation[Scope], entity: Entity, scope: Scope) -> None:
    _node(it, entity, scope, is_test=False)


@tag("test")
def handle_test(it: Interpretation[Scope], entity: Entity, scope: Scope) -> None:
    _node(it, entity, scope, is_test=True)


@processed
def _node(it: Interpretation[Scope], entity: Entity, scope: Scope, is_test: bool) -> None:
    fields: dict[str, Choice[Raw | None]] = {}
    if is_test:
        it.check_attributes(entity, TEST_ATTRIBUTES)
        for forbidden in ("respawn", "respawn_delay", "output"):
            if entity.has(forbidden):
                it.fail(
                    it.space.true,
                    "test-invalid",
                    f"<test> tags cannot have '{forbidden}' attribute",
                )
                return
        name = it.attr(entity, "name", scope)
        test_name = it.required(entity, "test-name", scope)
        if test_name is None:
            return
        fields["test-name"] = test_name
        fields["time-limit"] = it.attr(entity, "time-limit", scope) or Choice.const(it.space, None)
        fields["retry"] = it.attr(entity, "retry", scope) or Choice.const(it.space, None)
        name = test_name if name is None else combine([name, test_name], lambda v: v[0] or v[1])
    else:
        it.check_attributes(entity, NODE_ATTRIBUTES)
        name = it.required(entity, "name", scope)
        if name is None:
            return
    for _condition, leaf in name:
        if isinstance(leaf, str) and leaf and not is_legal_name(leaf):
            it.warn("node-name-illegal", f"illegal <node> name '{leaf}'")
    child = namespace_scope(it, "node", entity, scope, node_name=name)
    param_ns = it.lift("child_namespace", child.ns, name)
    param_scope = child.child(param_ns)
    param_scope.params = []
    package = it.required(entity, "pkg", scope)
    node_type = it.required(entity, "type", scope)
    if package is None or node_type is None:
        return
    absent: Choice[Raw | None] = Choice.const(it.space, None)
    attributes = entity.attributes
    for key in OPTIONAL:  # mostly absent: no call for them
        fields[key] = absent if key not in attributes else it.attr(entity, key, scope) or absent
    machine = fields["machine"]
    fields["machine"] = combine(
        [machine, it.default_machine],
        lambda v: v[0] or v[1],
    )
    fields["name"] = name
    fields["namespace"] = it.lift("node_namespace", child.ns)
    fields["pkg"] = package
    fields["type"] = node_type
    own_remaps: list[Remap] = []
    env = list(scope.env)
    for sub in entity.children:
        with it.at(sub):
            if sub.tag == "remap":
                add_remaps(it, sub, scope, own_remaps, own=True)
            elif sub.tag == "param":
                handle_param(it, sub, param_scope, force_local=True)
            elif sub.tag == "rosparam":
                handle_rosparam(it, sub, param_scope)
            elif sub.tag == "env":
                env_scope = scope.child(scope.ns)
                env_scope.env = []
                handle_env(it, sub, env_scope)
                env.extend(env_scope.env)
            else:
                it.warn("tag-unknown", f"unrecognized '{sub.tag}' child tag in <{entity.tag}>")
    for private in [*scope.params, *param_scope.params]:
        full = it.lift("private_key", param_ns, Choice.const(it.space, private.key))
        with it.under(private.condition):
            it.model.params.append(ParamDecl(it.pc, private.location, full, private.value))
    remaps = scope.remaps_with(own_remaps)
    problem = combine(
        [
            fields[k]
            for k in (
                "name",
                "pkg",
                "type",
                "output",
                "cwd",
                "respawn",
                "required",
                "respawn_delay",
            )
        ],
        lambda v: node_problem(*v),
    )
    for condition, message in problem:
        if message is not None:
            it.fail(condition, "node-invalid", f"Invalid <{entity.tag}> tag: {message}")
    it.model.nodes.append(
        NodeDecl(
            condition=it.pc,
            location=entity.location,
            filename=scope.filename,
            is_test=is_test,
            fields=fields,
            remaps=remaps,
            env=[EnvSetting(e.condition, e.name, e.value) for e in env],
            schema=ROS1.nodes,
            args=child.args,
        )
    )
