"""The ``xacro:`` tags, each a handler of the walk (:data:`~.xacro.HANDLERS`): blocks,
includes, properties, macros, args, dynamic elements and attributes, conditions, calls.

Each follows xacro's function of the same name (``grab_property``, ``process_include``, ...)
for every configuration at once; a macro's parameters are read as xacro's grammar writes
them (:func:`parse_params`).
"""

from __future__ import annotations

import ast
import glob
import keyword
import os
import re
from dataclasses import replace

from rosvar.analyses.robot_description.document import XElement
from rosvar.analyses.robot_description.evaluation import stored_value
from rosvar.analyses.robot_description.literals import read_literal, truth
from rosvar.analyses.robot_description.symbols import Lazy, Table
from rosvar.analyses.robot_description.xacro import (
    MAX_INCLUDE_DEPTH,
    XACRO_PREFIX,
    Block,
    Expansion,
    Handler,
    Macro,
    RawBlock,
    handler,
)
from rosvar.frontends.entity import Entity
from rosvar.interpreter.model import Raw
from rosvar.interpreter.substitution_args import MISSING, Missing
from rosvar.logic.bdd import BDD
from rosvar.logic.choice import Choice, ite


@handler("insert_block")
def _insert_block(
    it: Expansion, entity: Entity, parent: XElement, macros: Table, symbols: Table
) -> None:
    found = it.required(entity, "name")
    if found is None:
        return
    (name,) = found
    multi = symbols.defined("**" + name)
    single = symbols.defined("*" + name) & ~multi
    it.fail(~multi & ~single, f'Undefined block "{name}"')
    for key, content_only, where in (("**" + name, True, multi), ("*" + name, False, single)):
        with it.under(where) as live:
            if not live:
                continue
            for condition, block in symbols.lookup(key, it.pc, it.evaluator.lazy):
                with it.under(condition) as present:
                    if present:
                        _insert(it, block, content_only, parent, macros, symbols)


def _insert(
    it: Expansion,
    block: object,
    content_only: bool,
    parent: XElement,
    macros: Table,
    symbols: Table,
) -> None:
    if isinstance(block, RawBlock):
        for value in block.entity.attributes.values():
            it.eval(value, symbols)
        it.contents(block.entity, parent, macros, symbols)
    elif isinstance(block, Block):
        copied = _copy(block.element, it.pc)
        if content_only:
            parent.texts.extend(copied.texts)
            parent.children.extend(copied.children)
        else:
            parent.children.append(copied)


def _copy(element: XElement, condition: BDD) -> XElement:
    """``element`` present only where ``condition`` holds too."""
    return replace(
        element,
        condition=element.condition & condition,
        texts=[(c & condition, v) for c, v in element.texts],
        children=[_copy(child, condition) for child in element.children],
        attributes=dict(element.attributes),
    )


@handler("include")
def _include(
    it: Expansion, entity: Entity, parent: XElement, macros: Table, symbols: Table
) -> None:
    spec = entity.get("filename")
    if spec is None:
        it.fail(it.space.true, "xacro:include: missing attribute 'filename'")
        return
    namespace = entity.get("ns")
    optional = entity.get("optional")
    if entity.children:
        it.sink.warning(
            "xacro-include-children",
            "Child elements of a <xacro:include> tag are ignored",
            it.location,
        )
    for condition, name in it.words(spec, symbols):
        with it.under(condition) as live:
            if live:
                _include_files(it, name, namespace, optional, parent, macros, symbols)


def _include_files(
    it: Expansion,
    spec: str,
    namespace: str | None,
    optional: str | None,
    parent: XElement,
    macros: Table,
    symbols: Table,
) -> None:
    if not os.path.isabs(spec):
        spec = os.path.join(os.path.dirname(it.filename), spec)
    if re.search(r"[*[?]+", spec):
        files = sorted(glob.glob(spec))
        if not files:
            it.sink.warning(
                "xacro-include-none",
                f'Include tag\'s filename spec "{spec}" matched no files.',
                it.location,
            )
    else:
        files = [spec]
    for file in files:
        if len(it.stack) >= MAX_INCLUDE_DEPTH:
            it.limit(f"includes nested more than {MAX_INCLUDE_DEPTH} deep")
            return
        real = os.path.realpath(file)
        if any(real == walked for _given, walked in it.stack):
            it.fail(
                it.space.true,
                f"{file} includes itself (xacro recurses until it fails)",
                "xacro-include-cycle",
            )
            return
        parsed = it.reader.parse(file)
        if isinstance(parsed, str) and _optional(optional):
            continue
        root = it.load(file)
        if root is None:
            continue
        tables = (
            (macros, symbols) if namespace is None else _namespace(it, namespace, macros, symbols)
        )
        if tables is None:
            continue
        ns_macros, ns_symbols = tables
        it.stack.append((file, real))
        try:
            for value in root.attributes.values():
                if value and "$" in value:
                    it.eval(value, ns_symbols)
            it.contents(root, parent, ns_macros, ns_symbols)
        finally:
            it.stack.pop()


def _optional(text: str | None) -> bool:
    try:
        return text is not None and truth(text)
    except ValueError:
        return False


def _namespace(
    it: Expansion, spec: str, macros: Table, symbols: Table
) -> tuple[Table, Table] | None:
    """An include's ``ns``: new namespace tables, set in the current ones."""
    words = list(it.words(spec, symbols))
    if len(words) != 1:
        it.unsupported(f"include namespace {spec} varies between configurations")
        return None
    _condition, name = words[0]
    ns_macros = Table(it.space, None, it.pc, namespace=True)
    ns_symbols = symbols.child(it.pc, namespace=True)
    macros.set(name, Choice.const(it.space, ns_macros), it.pc)
    symbols.set(name, Choice.const(it.space, ns_symbols), it.pc)
    return ns_macros, ns_symbols


@handler("property")
def _property(
    it: Expansion, entity: Entity, parent: XElement, macros: Table, symbols: Table
) -> None:
    spec = entity.get("name")
    if spec is None:
        it.fail(it.space.true, "xacro:property: missing attribute 'name'")
        return
    for condition, name in it.words(spec, symbols):
        with it.under(condition) as live:
            if live:
                _define(it, entity, name, symbols)


def _define(it: Expansion, entity: Entity, name: str, symbols: Table) -> None:
    """``grab_property`` for one name."""
    if not _valid_name(name):
        it.fail(it.space.true, f"Property names must be valid python identifiers: {name}")
        return
    if name.startswith("__"):
        it.fail(it.space.true, f"Property names must not start with double underscore:{name}")
        return
    value, default = entity.get("value"), entity.get("default")
    removed, kept = it.truth(it.eval(entity.get("remove") or "false", symbols), "remove")
    given = (value is not None) + (default is not None)
    exclusive = f"Property attributes default, value, and remove are mutually exclusive: {name}"
    if given > 1:
        it.fail(it.space.true, exclusive)
        return
    if given:
        it.fail(removed, exclusive)
    defined = symbols.defined(name)
    with it.under(removed & defined) as live:
        if live:
            symbols.remove(name, it.pc)
    with it.under((kept if given else kept | removed) & ~(removed & defined)) as live:
        if not live:
            return
        if default is None:
            _store(it, entity, name, value, symbols)
            return
        with it.under(~defined) as unset:
            if unset:
                _store(it, entity, name, default, symbols)


def _store(it: Expansion, entity: Entity, name: str, value: str | None, symbols: Table) -> None:
    """The property set in the table its ``scope`` names, lazily unless told otherwise; a
    property without a value is a block."""
    lazy, _greedy = it.truth(it.eval(entity.get("lazy_eval") or "true", symbols), "lazy_eval")
    target = symbols
    scope = entity.get("scope")
    if scope == "global":
        target = symbols.top()
        lazy = it.space.false
    elif scope == "parent":
        if symbols.parent is None:
            it.sink.warning("xacro-scope", f"{name}: no parent scope at global scope", it.location)
            return
        target = symbols.parent
        lazy = it.space.false
        if not symbols.namespace:  # in a macro: the caller's scope, past namespaces
            while target.namespace and target.parent is not None:
                target = target.parent
    if value is None:
        target.set("**" + name, Choice.const(it.space, RawBlock(entity)), it.pc)
        return
    literal = read_literal(value)
    with it.under(~lazy) as greedy:
        if greedy:
            target.set(name, it.eval(value, symbols).map(stored_value), it.pc)
    with it.under(lazy) as deferred:
        if deferred:
            kept = Lazy(literal, entity.location) if isinstance(literal, str) else literal
            target.set(name, Choice.const(it.space, kept), it.pc)


@handler("macro")
def _macro(it: Expansion, entity: Entity, parent: XElement, macros: Table, symbols: Table) -> None:
    found = it.required(entity, "name")
    if found is None:
        return
    (name,) = found
    if name == "call":
        it.fail(it.space.true, "Invalid use of macro name 'call'")
        return
    if "." in name:
        it.fail(
            it.space.true, f"macro names must not contain '.' (reserved for namespaces): {name}"
        )
        return
    if name.startswith(XACRO_PREFIX):
        it.sink.warning(
            "xacro-macro-prefix",
            f"macro names must not contain prefix 'xacro:': {name}",
            it.location,
        )
        name = name[len(XACRO_PREFIX) :]
    params, defaults = parse_params(entity.get("params") or "")
    macros.set(name, Choice.const(it.space, Macro(name, entity, params, defaults)), it.pc)


@handler("arg")
def _arg(it: Expansion, entity: Entity, parent: XElement, macros: Table, symbols: Table) -> None:
    found = it.required(entity, "name", "default")
    if found is None:
        return
    name, default = found
    current = it.args.get(name, Choice.const(it.space, MISSING))
    missing = current.where(lambda leaf: leaf is MISSING)
    with it.under(missing) as live:
        if live:
            value: Choice[Raw | Missing] = it.texts(default, symbols)
            it.args[name] = ite(it.space, it.pc, value, current)


@handler("element")
def _element(
    it: Expansion, entity: Entity, parent: XElement, macros: Table, symbols: Table
) -> None:
    found = it.required(entity, "xacro:name")
    if found is None:
        return
    attributes = {k: v for k, v in entity.attributes.items() if k != "xacro:name"}
    for condition, name in it.words(found[0], symbols):
        with it.under(condition) as live:
            if not live:
                continue
            if not name:
                it.fail(it.space.true, "xacro:element: empty name")
                continue
            it.element(replace(entity, tag=name, attributes=attributes), parent, macros, symbols)


@handler("attribute")
def _attribute(
    it: Expansion, entity: Entity, parent: XElement, macros: Table, symbols: Table
) -> None:
    found = it.required(entity, "name", "value")
    if found is None:
        return
    value = it.texts(found[1], symbols)
    for condition, name in it.words(found[0], symbols):
        with it.under(condition) as live:
            if not live:
                continue
            if not name:
                it.fail(it.space.true, "xacro:attribute: empty name")
                continue
            old = parent.attributes.get(name) or Choice.const(it.space, None)
            parent.attributes[name] = ite(it.space, it.pc, value, old)


def _conditional(keep_true: bool) -> Handler:
    def walk(
        it: Expansion, entity: Entity, parent: XElement, macros: Table, symbols: Table
    ) -> None:
        found = it.required(entity, "value")
        if found is None:
            return
        true, false = it.truth(it.eval(found[0], symbols), found[0])
        with it.under(true if keep_true else false) as live:
            if live:
                it.contents(entity, parent, macros, symbols)

    return walk


handler("if")(_conditional(True))
handler("unless")(_conditional(False))


@handler("call")
def _dynamic_call(
    it: Expansion, entity: Entity, parent: XElement, macros: Table, symbols: Table
) -> None:
    spec = entity.get("macro")
    if not spec:
        it.fail(it.space.true, "xacro:call is missing the 'macro' attribute")
        return
    attributes = {k: v for k, v in entity.attributes.items() if k != "macro"}
    for condition, name in it.words(spec, symbols):
        with it.under(condition) as live:
            if live:
                it.call(replace(entity, attributes=attributes), name, parent, macros, symbols)


# -- macro parameters -------------------------------------------------------------------------

_PARAM = re.compile(
    r"""\s*(?P<name>[^\s:=]+?)\s*:?=\s*(?P<forward>\^\|?)?
        (?P<default>\$\{.*?\}|\$\(.*?\)|(?:'.*?'|".*?"|[^\s'"]+)+|)(?:\s+|$)""",
    re.VERBOSE,
)


def parse_params(spec: str) -> tuple[tuple[str, ...], dict[str, tuple[str | None, str | None]]]:
    """A macro's ``params``: names in order, and per name with a default the property it
    forwards (``^``) and the default's text (``name:=default``, ``name:=^``,
    ``name:=^|default``; quoted defaults and ``${}``/``$()`` defaults may hold blanks)."""
    params: list[str] = []
    defaults: dict[str, tuple[str | None, str | None]] = {}
    rest = spec
    while rest.strip():
        match = _PARAM.match(rest)
        if match is not None:
            name = match["name"]
            params.append(name)
            defaults[name] = (name if match["forward"] else None, match["default"] or None)
            rest = rest[match.end() :]
        else:
            name, _, rest = rest.strip().partition(" ")
            params.append(name)
    return tuple(params), defaults


def _valid_name(name: str) -> bool:
    """A Python identifier that is no keyword (xacro evaluates names as Python)."""
    try:
        tree = ast.parse(name, mode="eval")
    except SyntaxError:
        return False
    return isinstance(tree.body, ast.Name) and tree.body.id == name and not keyword.iskeyword(name)
