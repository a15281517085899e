"""A Python package's ``setup.py`` and ``setup.cfg``, read without running them: the scripts
and the ``console_scripts`` entry points they install, and the ``data_files`` they copy
(an ament_python package's launch and parameter files, into ``share/<package>``).

``setup.py`` is read with ``ast``: the lists given as ``scripts=`` and as
``entry_points={"console_scripts": [...]}``, each string as Python spells it (adjacent
literals joined, a backslash-continued literal, ``+``, f-strings and the module's string
constants such as ``package_name``, ``os.path.join``). ``setup.cfg`` is an INI file: its
``console_scripts =`` lines. Anything not known statically is left out (a ``data_files``
entry so left out is told by its line).
"""

from __future__ import annotations

import ast
import re
from dataclasses import dataclass

_ENTRY_POINT = re.compile(r"^\s*([\w.-]+)\s*=\s*([\w.]+)\s*:\s*[\w.]+")
_CFG_ENTRY_POINT = re.compile(r"([\w.-]+)\s*=\s*([\w.]+):\w+")
_MAX_DEPTH = 64
"""Nested ``+``/f-string parts evaluated before a string is given up."""


def _parse(text: str) -> ast.Module | None:
    try:
        return ast.parse(text)
    except (SyntaxError, ValueError, RecursionError, MemoryError):
        return None


class _Strings:
    """Strings of a ``setup.py`` known statically, through its module-level constants."""

    def __init__(self, tree: ast.Module) -> None:
        self.constants: dict[str, ast.expr] = {}
        for node in tree.body:
            if isinstance(node, ast.Assign) and len(node.targets) == 1:
                target = node.targets[0]
                if isinstance(target, ast.Name):
                    self.constants[target.id] = node.value

    def value(self, node: ast.expr, depth: int = 0) -> str | None:
        if depth > _MAX_DEPTH:
            return None
        if isinstance(node, ast.Constant):
            return node.value if isinstance(node.value, str) else None
        if isinstance(node, ast.BinOp) and isinstance(node.op, ast.Add):
            left, right = self.value(node.left, depth + 1), self.value(node.right, depth + 1)
            return None if left is None or right is None else left + right
        if isinstance(node, ast.JoinedStr):
            parts = [self.value(part, depth + 1) for part in node.values]
            return None if None in parts else "".join(p for p in parts if p is not None)
        if isinstance(node, ast.FormattedValue) and node.format_spec is None:
            return self.value(node.value, depth + 1)
        if isinstance(node, ast.Name) and node.id in self.constants:
            return self.value(self.constants[node.id], depth + 1)
        joined = _called(node, "join")  # os.path.join
        if joined is not None and not joined.keywords:
            parts = [self.value(part, depth + 1) for part in joined.args]
            return None if None in parts or not parts else "/".join(p for p in parts if p)
        return None

    def files(self, node: ast.expr, depth: int = 0) -> list[DataFile] | None:
        """The files of a ``data_files`` entry: strings, ``glob(pattern)`` calls, lists of
        them and their sums; None when a part is not known."""
        if depth > _MAX_DEPTH:
            return None
        if isinstance(node, ast.Name) and node.id in self.constants:
            return self.files(self.constants[node.id], depth + 1)
        if isinstance(node, ast.BinOp) and isinstance(node.op, ast.Add):
            left, right = self.files(node.left, depth + 1), self.files(node.right, depth + 1)
            return None if left is None or right is None else left + right
        globbed = _called(node, "glob")
        if globbed is not None and len(globbed.args) == 1:
            pattern = self.value(globbed.args[0], depth + 1)
            return None if pattern is None else [DataFile(pattern, glob=True)]
        if isinstance(node, ast.List | ast.Tuple):
            found: list[DataFile] = []
            for item in node.elts:
                text = self.value(item, depth + 1)
                listed = [DataFile(text)] if text is not None else self.files(item, depth + 1)
                if listed is None:
                    return None
                found.extend(listed)
            return found
        return None

    def listed(self, node: ast.expr) -> list[str]:
        """The strings of a list or tuple (or of a constant naming one)."""
        if isinstance(node, ast.Name) and node.id in self.constants:
            node = self.constants[node.id]
        if not isinstance(node, ast.List | ast.Tuple):
            return []
        return [text for item in node.elts if (text := self.value(item)) is not None]


def _called(node: ast.expr, name: str) -> ast.Call | None:
    """``node`` if it calls a function or method called ``name`` (``glob``, ``glob.glob``)."""
    if not isinstance(node, ast.Call):
        return None
    function = node.func
    if isinstance(function, ast.Name) and function.id == name:
        return node
    return node if isinstance(function, ast.Attribute) and function.attr == name else None


@dataclass(frozen=True)
class DataFile:
    """A file ``data_files`` names, relative to ``setup.py``'s folder (a ``glob`` pattern
    when ``glob``)."""

    path: str
    glob: bool = False


@dataclass(frozen=True)
class DataFiles:
    """One ``(destination, [files])`` entry of ``data_files``; ``files`` None when rosvar
    cannot tell them (or the destination), with the entry's line."""

    destination: str | None
    files: list[DataFile] | None
    line: int


def data_files(text: str) -> list[DataFiles]:
    """The entries of ``setup(data_files=[...])``, in order."""
    tree = _parse(text) if "data_files" in text else None
    if tree is None:
        return []
    strings = _Strings(tree)
    found: list[DataFiles] = []
    for node in ast.walk(tree):
        if not (isinstance(node, ast.keyword) and node.arg == "data_files"):
            continue
        value = node.value
        if isinstance(value, ast.Name) and value.id in strings.constants:
            value = strings.constants[value.id]
        if not isinstance(value, ast.List | ast.Tuple):
            found.append(DataFiles(None, None, node.value.lineno))
            continue
        for entry in value.elts:
            if isinstance(entry, ast.Tuple) and len(entry.elts) == 2:
                destination, files = strings.value(entry.elts[0]), strings.files(entry.elts[1])
                found.append(DataFiles(destination, files, entry.lineno))
            else:
                found.append(DataFiles(None, None, entry.lineno))
    return found


def setup_scripts(text: str) -> list[str]:
    """The ``scripts=`` of ``setup()`` (or catkin's ``generate_distutils_setup``)."""
    tree = _parse(text)
    if tree is None:
        return []
    strings = _Strings(tree)
    found: list[str] = []
    for node in ast.walk(tree):
        if isinstance(node, ast.keyword) and node.arg == "scripts":
            found.extend(s for s in strings.listed(node.value) if s not in found)
    return found


def console_scripts(setup_py: str, setup_cfg: str) -> dict[str, str]:
    """The ``console_scripts`` entry points: executable name → module (dotted)."""
    found: dict[str, str] = {}
    tree = _parse(setup_py) if "console_scripts" in setup_py else None
    if tree is None:  # not Python 3: its entry points as they are written
        setup_cfg = setup_py + "\n" + setup_cfg
    else:
        strings = _Strings(tree)
        for node in ast.walk(tree):
            if not isinstance(node, ast.Dict):
                continue
            for key, value in zip(node.keys, node.values, strict=True):
                if key is not None and strings.value(key) == "console_scripts":
                    for text in strings.listed(value):
                        if (match := _ENTRY_POINT.match(text)) is not None:
                            found.setdefault(match.group(1), match.group(2))
    for part in setup_cfg.split("console_scripts")[1:]:
        for match in _CFG_ENTRY_POINT.finditer(part):
            found.setdefault(match.group(1), match.group(2))
    return found
