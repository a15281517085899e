"""``<include>`` (``IncludeLaunchDescription``): not a scope in ROS 2.

The ``<arg>`` children are set as launch configurations of the *current* context (their
values read before any is set) and stay set after the include; the included file's
declarations and ``<let>``s leak to the includer too. Only a scoped ``<group>`` confines them.
"""

from __future__ import annotations

from rosvar.files import FileRefused
from rosvar.frontends.entity import Entity
from rosvar.interpreter.interpretation import (
    MAX_INCLUDE_DEPTH,
    MAX_INCLUDES,
    Interpretation,
    processed,
    split,
)
from rosvar.interpreter.model import IncludeDecl, Raw
from rosvar.logic.choice import Choice
from rosvar.ros2 import schema
from rosvar.ros2.context import Context, optional
from rosvar.ros2.dialect import tag
from rosvar.ros2.include_memo import walk_included
from rosvar.ros2.tags.common import set_configuration
from rosvar.workspace.paths import real_path


@tag("include")
@processed
def include(it: Interpretation[Context], entity: Entity, context: Context) -> None:
    files = it.required(entity, "file", context)
    if files is None:
        return
    passed: list[tuple[str, Choice[Raw]]] = []
    for sub in entity.children:
        with it.at(sub):
            if sub.tag != "arg":
                it.warn("tag-unknown", f"unrecognized '{sub.tag}' tag in <include> tag")
                continue
            name, value = sub.get("name"), it.required(sub, "value", context)
            if name and value is not None:
                passed.append((name, value))
    for name, value in passed:
        set_configuration(it, context, name, optional(value))
    for condition, file in split(it, files):
        with it.under(condition):
            _include(it, entity, context, file)


def _include(it: Interpretation[Context], entity: Entity, context: Context, file: Raw) -> None:
    namespace = context.namespace or Choice.const(it.space, None)
    ns = namespace.map(lambda leaf: "/" if leaf is None else leaf)
    if not isinstance(file, str):
        it.fail(it.space.true, "include-unknown", f"included file {file} is not known")
        return
    path = real_path(file)
    if context.recording.walks:
        context.recording.included.append(path)
    if path in it.stack:
        it.fail(it.space.true, "include-cycle", f"include cycle: {file} includes itself")
        return
    try:
        it.workspace.confinement().check(file)
    except FileRefused as refused:
        it.fail(it.space.true, refused.code, f"included file {file}: {refused.message}")
        return
    recording = context.recording
    recording.deepest_check = max(recording.deepest_check, len(it.stack))
    if it.included >= MAX_INCLUDES or len(it.stack) >= MAX_INCLUDE_DEPTH:
        it.fail(it.space.true, "include-too-many", f"too many includes: {file} not followed")
        return
    it.included += 1
    root = it.load(file)
    it.model.includes.append(
        IncludeDecl(it.pc, entity.location, Choice.const(it.space, file), ns, root is not None)
    )
    if root is None:
        return
    if context.recording.walks:
        context.recording.loaded.append(file)
    schema.check(it, root)
    walk_included(it, root, context, file, path)
