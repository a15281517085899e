"""The package's imports follow the README's Layout: each layer (a row of its table) imports
only itself and the rows before it, no import cycle exists, and the core never imports a
dialect (only ``rosvar/dialects.py`` does, and a dialect never imports another).

Every import counts, read with ``ast``: at module level, under ``TYPE_CHECKING`` and inside
functions. The table is the one source of the layer order; a module no row covers fails.
"""

from __future__ import annotations

import ast
import re
from collections.abc import Iterator
from pathlib import Path

import pytest

import rosvar

PACKAGE = Path(rosvar.__file__).resolve().parent
README = PACKAGE.parents[1] / "README.md"
ROOT = "rosvar"
REGISTRATION = "rosvar.dialects"
"""The one module that imports the dialects: it registers them with the core."""


def module_name(path: Path, package: Path) -> str:
    parts = [package.name, *path.relative_to(package).with_suffix("").parts]
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


def modules(package: Path = PACKAGE) -> dict[str, Path]:
    return {module_name(path, package): path for path in sorted(package.rglob("*.py"))}


def imported(module: str, path: Path, known: set[str]) -> set[str]:
    """The package's modules ``module`` imports anywhere in its source (relative imports
    resolved; ``from package import name`` is the submodule ``name`` when there is one)."""
    found: set[str] = set()
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"), str(path))):
        if isinstance(node, ast.Import):
            found.update(alias.name for alias in node.names)
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                base = module.split(".")
                if path.name != "__init__.py":
                    base.pop()
                base = base[: len(base) - node.level + 1]
                target = ".".join([*base, *([node.module] if node.module else [])])
            else:
                target = node.module or ""
            for alias in node.names:
                submodule = f"{target}.{alias.name}"
                found.add(submodule if submodule in known else target)
    return {name for name in found if name in known and name != module}


def import_graph(package: Path = PACKAGE) -> dict[str, set[str]]:
    found = modules(package)
    known = set(found)
    return {name: imported(name, path, known) for name, path in found.items()}


def layers(readme: Path = README) -> list[list[str]]:
    """The module prefixes of each row of the README's Layout table, in order."""
    text = readme.read_text(encoding="utf-8")
    section = text[text.index("## Layout") :]
    section = section[: section.index("\n## ", 1)]
    rows = []
    for line in section.splitlines():
        cells = line.split("|")
        if len(cells) < 3 or not cells[1].strip().startswith("`"):
            continue
        names = re.findall(r"`([^`]+)`", cells[1])
        rows.append([_prefix(name) for name in names])
    return rows


def _prefix(name: str) -> str:
    """``ros/`` → ``rosvar.ros``, ``files.py`` → ``rosvar.files``, ``__init__.py`` → ``rosvar``."""
    stem = name.rstrip("/").removesuffix(".py")
    return ROOT if stem == "__init__" else f"{ROOT}.{stem.replace('/', '.')}"


def layer_of(module: str, rows: list[list[str]]) -> int | None:
    """The row of the longest prefix naming ``module`` (the package itself only names
    itself)."""
    best: tuple[int, int] | None = None  # (prefix length, row)
    for index, prefixes in enumerate(rows):
        for prefix in prefixes:
            names = module == prefix or (prefix != ROOT and module.startswith(prefix + "."))
            if names and (best is None or len(prefix) > best[0]):
                best = (len(prefix), index)
    return None if best is None else best[1]


def dialects(graph: dict[str, set[str]], rows: list[list[str]]) -> set[str]:
    """The dialect packages: of the top-level packages the registration module imports,
    those of the latest row (the registry it fills and the versions it names come before)."""
    packages = {".".join(target.split(".")[:2]) for target in graph[REGISTRATION]}
    latest = max(layer_of(package, rows) or 0 for package in packages)
    return {package for package in packages if layer_of(package, rows) == latest}


def cycles(graph: dict[str, set[str]]) -> list[list[str]]:
    """The strongly connected components of more than one module (Tarjan's algorithm,
    iterative)."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on_stack: set[str] = set()
    found: list[list[str]] = []
    for start in sorted(graph):
        if start in index:
            continue
        work: list[tuple[str, Iterator[str]]] = [(start, iter(sorted(graph[start])))]
        index[start] = low[start] = len(index)
        stack.append(start)
        on_stack.add(start)
        while work:
            node, successors = work[-1]
            for successor in successors:
                if successor not in index:
                    index[successor] = low[successor] = len(index)
                    stack.append(successor)
                    on_stack.add(successor)
                    work.append((successor, iter(sorted(graph[successor]))))
                    break
                if successor in on_stack:
                    low[node] = min(low[node], index[successor])
            else:
                work.pop()
                if work:
                    low[work[-1][0]] = min(low[work[-1][0]], low[node])
                if low[node] == index[node]:
                    component = []
                    while True:
                        member = stack.pop()
                        on_stack.discard(member)
                        component.append(member)
                        if member == node:
                            break
                    if len(component) > 1:
                        found.append(sorted(component))
    return found


GRAPH = import_graph()
ROWS = layers()
DIALECTS = dialects(GRAPH, ROWS)


def _in(module: str, package: str) -> bool:
    return module == package or module.startswith(package + ".")


def test_the_layout_names_the_dialects_and_every_module() -> None:
    assert {"rosvar.ros1", "rosvar.ros2"} == DIALECTS
    assert [m for m in GRAPH if layer_of(m, ROWS) is None] == []


def test_no_import_from_a_layer_to_a_later_one() -> None:
    wrong = {
        f"{source} -> {target}"
        for source, targets in GRAPH.items()
        for target in targets
        # every module imports the package itself first: importing it names nothing new
        if target != ROOT and (layer_of(target, ROWS) or 0) > (layer_of(source, ROWS) or 0)
    }
    assert wrong == set()


def test_no_import_cycle() -> None:
    assert cycles(GRAPH) == []


def test_the_core_imports_no_dialect() -> None:
    wrong = {
        f"{source} -> {target}"
        for source, targets in GRAPH.items()
        for target in targets
        for dialect in DIALECTS
        if _in(target, dialect) and not _in(source, dialect) and source != REGISTRATION
    }
    assert wrong == set()


# -- the checks themselves can fail --------------------------------------------------------

SAMPLE = {
    "__init__.py": "",
    "low.py": "",
    "mid/__init__.py": "",
    "mid/a.py": (
        "from typing import TYPE_CHECKING\n"
        "if TYPE_CHECKING:\n"
        "    from pkg.high import x\n"
        "def f():\n"
        "    from . import b\n"
    ),
    "mid/b.py": "import pkg.mid.a\nfrom ..low import y\n",
    "high.py": "from pkg.mid import a\n",
}


@pytest.fixture
def sample(tmp_path: Path) -> dict[str, set[str]]:
    package = tmp_path / "pkg"
    for name, text in SAMPLE.items():
        (package / name).parent.mkdir(parents=True, exist_ok=True)
        (package / name).write_text(text)
    return import_graph(package)


def test_every_import_is_read(sample: dict[str, set[str]]) -> None:
    assert sample["pkg.mid.a"] == {"pkg.high", "pkg.mid.b"}  # TYPE_CHECKING, in a function
    assert sample["pkg.mid.b"] == {"pkg.mid.a", "pkg.low"}  # absolute, relative


def test_a_cycle_is_found(sample: dict[str, set[str]]) -> None:
    assert cycles(sample) == [["pkg.high", "pkg.mid.a", "pkg.mid.b"]]


def test_rows_and_prefixes_are_read(tmp_path: Path) -> None:
    readme = tmp_path / "README.md"
    readme.write_text(
        "## Layout\n\n| layer | contents |\n|--|--|\n| `files.py`, `ros/` | base |\n"
        "| `interpreter/` | walk (`dialect.py`) |\n| `__init__.py` | top |\n\n## Next\n"
    )
    rows = layers(readme)
    assert rows == [["rosvar.files", "rosvar.ros"], ["rosvar.interpreter"], ["rosvar"]]
    assert layer_of("rosvar.ros.names", rows) == 0
    assert layer_of("rosvar.interpreter.dialect", rows) == 1
    assert layer_of("rosvar", rows) == 2
    assert layer_of("rosvar.outputs.cli", rows) is None  # the package's row names only it
