"""``<include>``: load another launch file in a child scope (``_include_tag``)."""

from __future__ import annotations

from rosvar.files import FileRefused
from rosvar.frontends.entity import Entity
from rosvar.interpreter.booleans import bool_value
from rosvar.interpreter.interpretation import (
    MAX_INCLUDE_DEPTH,
    MAX_INCLUDES,
    Interpretation,
    processed,
    split,
)
from rosvar.interpreter.model import IncludeDecl, Raw
from rosvar.interpreter.substitution_args import MISSING
from rosvar.logic.choice import Choice
from rosvar.ros1.dialect import tag
from rosvar.ros1.scope import Scope
from rosvar.ros1.tags.arg import declare, handle_arg
from rosvar.ros1.tags.common import namespace_scope
from rosvar.ros1.tags.env import handle_env
from rosvar.workspace.paths import real_path

ATTRIBUTES = ("file", "ns", "clear_params", "pass_all_args")


@tag("include")
@processed
def handle_include(it: Interpretation[Scope], entity: Entity, scope: Scope) -> None:
    it.check_attributes(entity, ATTRIBUTES)
    files = it.required(entity, "file", scope)
    if files is None:
        return
    pass_all = bool_value(it, it.attr(entity, "pass_all_args", scope), False, "pass_all_args")
    for f_condition, file in split(it, files):
        for p_condition, flag in split(it, pass_all):
            with it.under(f_condition & p_condition):
                _include(it, entity, scope, file, flag is True)


def _include(
    it: Interpretation[Scope], entity: Entity, scope: Scope, file: Raw, pass_all: bool
) -> None:
    if not isinstance(file, str):
        it.warn("include-unknown", f"included file {file} is only known per configuration")
        _not_followed(it, entity, scope, file)
        return
    child = namespace_scope(it, "include", entity, scope, include_filename=file)
    if pass_all:
        for name, value in scope.args.items():
            defined = value.where(lambda v: v is not MISSING)
            with it.under(defined) as live:
                if live:
                    declare(it, child, name, value.restrict(defined), None)  # type: ignore[arg-type]
        child.pass_all_args = True
    child.filename = scope.filename
    for sub in entity.children:
        with it.at(sub):
            if sub.tag == "env":
                handle_env(it, sub, child)
            elif sub.tag == "arg":
                handle_arg(it, sub, child)
            else:
                it.warn("tag-unknown", f"unrecognized '{sub.tag}' tag in <include> tag")
    child.filename = file
    passed = child.include_args or {}
    for name, declared in child.declared.items():
        given = passed.get(name)
        undefined = declared if given is None else declared & given.where(lambda v: v is MISSING)
        it.fail(undefined, "include-arg-undefined", "include args must have declared values")
    passed_where = {n: v.where(lambda leaf: leaf is not MISSING) for n, v in passed.items()}
    child.declared = {}
    child.args = passed
    child.include_args = None
    child.anon = {}
    path = real_path(file)
    if path in it.stack:
        it.fail(it.space.true, "include-cycle", f"include cycle: {file} includes itself")
        return
    try:
        it.workspace.confinement().check(file)
    except FileRefused as refused:
        it.warn(refused.code, f"included file {file} is not read: {refused.message}")
        _not_followed(it, entity, scope, file)
        return
    if it.included >= MAX_INCLUDES:
        it.warn("include-too-many", f"more than {MAX_INCLUDES} includes: {file} is not followed")
        _not_followed(it, entity, scope, file)
        return
    it.included += 1
    if len(it.stack) >= MAX_INCLUDE_DEPTH:
        it.fail(
            it.space.true, "include-too-deep", f"includes nested deeper than {MAX_INCLUDE_DEPTH}"
        )
        return
    root = it.load(file)
    it.model.includes.append(
        IncludeDecl(
            it.pc, entity.location, Choice.const(it.space, file), scope.ns, root is not None
        )
    )
    if root is None:
        return
    it.stack.append(path)
    try:
        it.walk(root.children, child)
    finally:
        it.stack.pop()
    if not pass_all:
        for name, where in passed_where.items():
            declared_here = child.declared.get(name, it.space.false)
            unused = where & ~declared_here
            it.fail(unused, "include-arg-unused", f"unused args [{name}] for include of [{file}]")


def _not_followed(it: Interpretation[Scope], entity: Entity, scope: Scope, file: Raw) -> None:
    """Record an include that is not interpreted: ``resolve`` fails where it is active."""
    it.model.includes.append(
        IncludeDecl(it.pc, entity.location, Choice.const(it.space, file), scope.ns, False)
    )
