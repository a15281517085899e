"""The modules of its own package that a Python node imports, and what of them runs.

A node's script is often a few lines that import a class from the package's Python package
(``from turtlebot3_example.turtlebot3_obstacle import Obstacle``, rclpy's ``console_scripts``
module importing its node class); the interfaces are made there. The package's own modules
are those found below its folder or its ``src/`` (as ``catkin_python_setup`` and
``ament_python`` install them); anything else is a library, not followed. Of a module
imported as ``from m import A``, what runs is ``A`` (only ``A.f`` when the script only calls
``A.f``; and the definitions of ``m`` it names, its base classes among them) and ``m``'s
module-level statements (run on import, its
``if __name__ == "__main__"`` block left out); ``import m`` takes all of ``m``. Modules are
parsed, never imported, at most :data:`MAX_MODULES` per node.
"""

from __future__ import annotations

import ast
import os
from collections.abc import Callable, Iterator, Sequence
from dataclasses import dataclass, field

MAX_MODULES = 32

Parse = Callable[[str], ast.Module | None]
"""Reads and parses a module's file (None when it cannot)."""


@dataclass
class Module:
    """A module of the package and the parts of it that run for the node."""

    path: str
    tree: ast.Module
    parts: list[ast.AST] = field(default_factory=list)


def module_file(roots: Sequence[str], dotted: str) -> str | None:
    """The file of module ``dotted`` below one of ``roots`` (``pkg/mod.py`` or
    ``pkg/mod/__init__.py``)."""
    relative = dotted.replace(".", os.sep)
    for root in roots:
        for candidate in (relative + ".py", os.path.join(relative, "__init__.py")):
            path = os.path.join(root, candidate)
            if os.path.isfile(path):
                return path
    return None


def followed(tree: ast.Module, path: str, roots: Sequence[str], parse: Parse) -> list[Module]:
    """The modules the script ``tree`` (at ``path``) reaches through its imports of the
    package's own modules, each with the parts that run (the script itself not included)."""
    found: dict[str, Module] = {}
    pending = list(_used_imports(tree, [tree], path, roots, set()))
    while pending and len(found) < MAX_MODULES:
        file, wanted = pending.pop(0)
        if os.path.realpath(file) == os.path.realpath(path):
            continue
        module = found.get(file)
        if module is None:
            parsed = parse(file)
            if parsed is None:
                continue
            module = found[file] = Module(file, parsed)
        added = _select(module, wanted)
        pending.extend(_used_imports(module.tree, added, file, roots, wanted or set()))
    return list(found.values())


def _used_imports(
    tree: ast.Module, parts: Sequence[ast.AST], path: str, roots: Sequence[str], wanted: set[str]
) -> Iterator[tuple[str, set[str] | None]]:
    """The package's own modules that ``parts`` of module ``tree`` use through an import
    (of the module's top level or inside them), or that re-export a ``wanted`` name:
    (file, the names taken from it, None for all)."""
    used = set(wanted)
    plain = set(wanted)  # used other than as ``name.attribute``
    attributes: dict[str, set[str]] = {}
    imports: list[ast.Import | ast.ImportFrom] = [
        node for node in tree.body if isinstance(node, ast.Import | ast.ImportFrom)
    ]
    for part in parts:
        bases = {id(n.value) for n in ast.walk(part) if isinstance(n, ast.Attribute)}
        for node in ast.walk(part):
            if isinstance(node, ast.Name):
                used.add(node.id)
                if id(node) not in bases:
                    plain.add(node.id)
            elif isinstance(node, ast.Attribute) and (base := _dotted(node.value)):
                attributes.setdefault(base, set()).add(node.attr)  # pkg.mod.main: main
            elif isinstance(node, ast.Import | ast.ImportFrom) and node not in imports:
                imports.append(node)
    for node in imports:
        if isinstance(node, ast.Import):
            for alias in node.names:
                bound = alias.asname or alias.name
                file = module_file(roots, alias.name)
                if file is not None and bound.split(".")[0] in used:
                    yield file, attributes.get(bound) or None
            continue
        search = [_base(node, path)] if node.level else roots
        for alias in node.names:
            bound = alias.asname or alias.name
            if bound not in used and alias.name != "*":
                continue
            dotted = f"{node.module}.{alias.name}" if node.module else alias.name
            submodule = module_file(search, dotted)
            if submodule is not None:  # from pkg import mod: the module itself
                yield submodule, attributes.get(bound) or None
            elif node.module and (file := module_file(search, node.module)) is not None:
                if alias.name == "*":
                    yield file, None
                elif bound in plain:  # constructed or called: all of it
                    yield file, {alias.name}
                else:  # only Class.method: that method
                    yield file, {f"{alias.name}.{a}" for a in attributes.get(bound, ())}


def _dotted(node: ast.expr) -> str | None:
    if isinstance(node, ast.Name):
        return node.id
    if isinstance(node, ast.Attribute):
        base = _dotted(node.value)
        return None if base is None else f"{base}.{node.attr}"
    return None


def _base(node: ast.ImportFrom, path: str) -> str:
    """The folder a relative import (``from .mod import x``) starts from."""
    folder = os.path.dirname(path)
    for _ in range(max(node.level - 1, 0)):
        folder = os.path.dirname(folder)
    return folder


def _select(module: Module, wanted: set[str] | None) -> list[ast.AST]:
    """Add to ``module.parts`` what runs for ``wanted`` (None: everything); the parts added."""
    definitions = {
        node.name: node
        for node in module.tree.body
        if isinstance(node, ast.FunctionDef | ast.AsyncFunctionDef | ast.ClassDef)
    }
    added: list[ast.AST] = []
    if not module.parts:  # the first time: what runs on import
        added = [
            node
            for node in module.tree.body
            if node not in definitions.values()
            and not isinstance(node, ast.Import | ast.ImportFrom)
            and not _main(node)
        ]
    chosen = {id(part) for part in module.parts + added}
    pending = list(definitions) if wanted is None else [n for n in wanted if n in definitions]
    for name in wanted or ():  # Class.method: only that method of the class
        owner, _, method = name.partition(".")
        if method and isinstance(definitions.get(owner), ast.ClassDef):
            member = next(
                (n for n in definitions[owner].body if getattr(n, "name", None) == method), None
            )
            if member is not None and id(member) not in chosen:
                chosen.add(id(member))
                added.append(member)
                named = {n.id for n in ast.walk(member) if isinstance(n, ast.Name)}
                pending.extend(n for n in named if n in definitions)
    while pending:
        definition = definitions[pending.pop()]
        if id(definition) in chosen:
            continue
        chosen.add(id(definition))
        added.append(definition)
        named = {n.id for n in ast.walk(definition) if isinstance(n, ast.Name)}
        pending.extend(n for n in named if n in definitions)
    module.parts.extend(added)
    return added


def _main(node: ast.stmt) -> bool:
    """``if __name__ == "__main__":`` (runs only when the module is the script)."""
    return (
        isinstance(node, ast.If)
        and isinstance(node.test, ast.Compare)
        and isinstance(node.test.left, ast.Name)
        and node.test.left.id == "__name__"
    )
