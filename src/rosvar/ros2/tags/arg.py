"""``<arg>`` (``DeclareLaunchArgument``) and ``<let>`` (``SetLaunchConfiguration``).

Both write the global launch configurations: an ``<arg>``'s ``default`` applies only where
no value is set yet (given on the command line or by an including file), and a value
outside its ``<choice value=...>`` children is an error.
"""

from __future__ import annotations

from rosvar.frontends.entity import Entity
from rosvar.interpreter.interpretation import Interpretation, processed
from rosvar.interpreter.model import ArgDecl, Raw
from rosvar.logic.bdd import BDD
from rosvar.logic.choice import Choice, ite
from rosvar.logic.terms import Apply, Hole, register
from rosvar.ros2.context import Configuration, Context, optional
from rosvar.ros2.dialect import tag
from rosvar.ros2.include_memo import declare, is_input, is_listed, list_arg
from rosvar.ros2.tags.common import assign, set_configuration


@tag("arg")
@processed
def arg(it: Interpretation[Context], entity: Entity, context: Context) -> None:
    name = entity.get("name")
    if not name:
        it.fail(it.space.true, "attribute-missing", "<arg> tag is missing required 'name'")
        return
    old = context.get(name)
    unset = _unset(it, old)
    included = len(it.stack) > 1
    if unset != it.space.false and context.open_command_line and included and "$" not in name:
        if not is_input(it, context, name):
            old = _given(it, context, name, old, unset)
            unset = _unset(it, old)
        else:  # declared before, where it was set: the next interpretation sets it first
            context.unset_reads.add(name)
        ordered = canonical(old)
        if ordered is not old and ordered is not None:  # as every pass orders it
            old = context.configurations[name] = ordered
    if entity.get("default") is None:
        it.fail(unset, "arg-required", f"Required launch argument '{name}' was not provided")
    else:
        with it.under(unset) as live:  # launch evaluates a default only where it applies
            default = it.attr(entity, "default", context) if live else None
            if default is not None:
                context.configurations[name] = assign(it, old, optional(default))
    value = context.get(name)
    allowed = [c.get("value") or "" for c in entity.children if c.tag == "choice"]
    if allowed and value is not None:
        it.fail(
            _outside(it, value, allowed),
            "arg-choice",
            f"argument '{name}' must be one of {allowed}",
        )
    if included and not is_listed(it, context, name):  # listed once, if an input (_given)
        return
    declaration = ArgDecl(
        name,
        entity.location,
        it.pc,
        entity.get("default"),
        None,
        entity.get("description"),
        it.model.inputs.get(name),
    )
    list_arg(it, context, declaration)


def _outside(it: Interpretation[Context], value: Configuration, allowed: list[str]) -> BDD:
    """Where ``value`` is none of ``allowed``: a string outside them, an input's ``<other>``
    value where its domain holds them all, another term where its string is not among them
    once configured (a predicate ``resolve`` decides)."""
    bad = it.space.false
    for condition, leaf in value:
        if isinstance(leaf, str):
            if leaf not in allowed:
                bad |= condition
        elif isinstance(leaf, Hole) and set(allowed) <= set(it.space.domain(leaf.input)):
            bad |= condition
        elif isinstance(leaf, Apply):
            one_of = Apply(ONE_OF, (leaf, tuple(allowed)), display=f"{leaf} in {allowed}")
            bad |= condition & ~it.space.predicate("true", one_of)
    return bad


ONE_OF = "ros2-one-of"
register(ONE_OF, lambda _host, text, allowed: "true" if text in allowed else "false")


def _unset(it: Interpretation[Context], value: Configuration | None) -> BDD:
    """Where ``value`` is not set."""
    return value.where(lambda leaf: leaf is None) if value is not None else it.space.true


def canonical(value: Configuration | None) -> Configuration | None:
    """``value``'s branches in one order, whatever order the writes that made it came in:
    an included file's arg set on a path before its declaration is built over the unset
    value in one interpretation and over the command line's from the start in the next
    (``Analysis._interpret``), whose writes order the same branches differently. Ordered by
    leaf (unset, strings, input holes, other terms; then by text), equal values are equal
    choices; only leaves of one text fall back to their ``repr``."""
    if value is None or len(value.branches) < 2:
        return value
    keys = [_leaf_order(leaf) for _condition, leaf in value.branches]
    if len(set(keys)) < len(keys):
        keys = [(_leaf_order(leaf)[0], repr(leaf)) for _condition, leaf in value.branches]
    order = sorted(range(len(keys)), key=keys.__getitem__)
    if order == list(range(len(keys))):
        return value
    return Choice(tuple(value.branches[index] for index in order), value.false)


_RANKS = {type(None): 0, str: 1, Hole: 2, Apply: 3}


def _leaf_order(leaf: Raw | None) -> tuple[int, str]:
    return _RANKS.get(type(leaf), 4), "" if leaf is None else str(leaf)


def _given(
    it: Interpretation[Context],
    context: Context,
    name: str,
    old: Configuration | None,
    unset: BDD,
) -> Configuration:
    """An included file's argument the entry file does not declare, where nothing set it
    (``unset``): ``ros2 launch`` set ``name:=value``, if given, before loading, so there the
    declaration sees the command line's value. It becomes an input here; a read of it before
    (or outside the scope it is set in) makes the next interpretation know it from the
    start."""
    given = declare(it, context, name)
    before = old if old is not None else Choice.const(it.space, None)
    context.configurations[name] = ite(it.space, unset, given, before)  # on every path
    return context.configurations[name]


@tag("let")
@processed
def let(it: Interpretation[Context], entity: Entity, context: Context) -> None:
    name = it.required(entity, "name", context)
    value = it.required(entity, "value", context)
    if name is None or value is None:
        return
    for condition, key in name:
        if not isinstance(key, str):
            it.fail(condition, "value-unknown", "<let> name depends on an unknown value")
            continue
        with it.under(condition) as live:
            if live:
                set_configuration(it, context, key, optional(value))
