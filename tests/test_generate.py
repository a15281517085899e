"""The ROS 2 benchmark workspaces of ``bench/generate.py --shape ros2`` and ``--shape
ros2-dense`` have their issues' size and shape, and are consistent ROS 2 workspaces (what
rosvar measures must be loadable)."""

from __future__ import annotations

import re
from functools import cache
from pathlib import Path

import pytest

import bench_scripts
from rosvar.frontends.entity import Entity
from rosvar.frontends.xml import parse_xml_file
from rosvar.ros.version import RosVersion
from rosvar.ros2.substitutions import Call, parse
from rosvar.workspace import discover
from rosvar.workspace.executables import executables
from rosvar.workspace.launch_files import LaunchFormat

generate = bench_scripts.load("generate")

_VAR = re.compile(r"\$\(var (\w+)\)")
_SHARE = re.compile(r"\$\(find-pkg-share (\w+)\)")


@pytest.fixture(scope="module", params=["ros2", "ros2-dense"])
def ros2_workspace(
    tmp_path_factory: pytest.TempPathFactory, request: pytest.FixtureRequest
) -> Path:
    root = tmp_path_factory.mktemp(request.param) / "src"
    generate.SHAPES[request.param](root, generate.ROS2_FILES)
    return root


def _count(root: Path, text: str) -> int:
    return sum(path.read_text().count(text) for path in root.glob("*/launch/*.launch.xml"))


@pytest.mark.parametrize(
    ("shape", "includes", "evals"), [("ros2", 150, 0), ("ros2-dense", 340, 180)]
)
def test_includes_and_evals(tmp_path: Path, shape: str, includes: int, evals: int) -> None:
    """Issue 28's system holds 340 includes and 180 ``$(eval)``s in its 120 files; the
    dense shape's flag (a computed ``<let>``) reaches the included files' args."""
    generate.SHAPES[shape](tmp_path, generate.ROS2_FILES)
    assert (_count(tmp_path, "<include "), _count(tmp_path, "$(eval ")) == (includes, evals)
    passed = _count(tmp_path, f'value="$(var {generate.FLAG})"/>')
    assert (passed > 0) == (shape == "ros2-dense")


def _walk(entity: Entity) -> list[Entity]:
    return [entity, *(e for child in entity.children for e in _walk(child))]


@cache
def _root(path: str) -> Entity:
    root = parse_xml_file(path).root
    assert root is not None and root.tag == "launch"
    return root


def test_size_and_kind(ros2_workspace: Path) -> None:
    workspace = discover([ros2_workspace], ros_package_path="", ament_prefix_path="")
    assert workspace.ros_version == RosVersion.ROS2
    assert workspace.diagnostics == []
    assert len(workspace.launch_files) == 120
    assert {workspace.launch_format(path) for path in workspace.launch_files} == {LaunchFormat.XML}
    args = [e for path in workspace.launch_files for e in _root(path).children if e.tag == "arg"]
    assert len(args) == 1500
    assert len(workspace.packages) == 12
    for package in workspace.packages.values():  # from CMakeLists.txt, as colcon builds them
        assert executables(package) == set(generate.EXECUTABLES)


def _included(root: Path, include: Entity) -> str:
    """The file an include names (it must exist), checking it is given its required args."""
    text = include.attributes["file"]
    package = _SHARE.search(text)
    assert package is not None
    target = root / package.group(1) / text.split(")/", 1)[1]
    assert target.is_file()
    passed = {arg.get("name") for arg in include.children}
    declared = [arg for arg in _root(str(target)).children if arg.tag == "arg"]
    assert {arg.get("name") for arg in declared if not arg.has("default")} <= passed
    return str(target)


def test_consistent_and_deep(ros2_workspace: Path) -> None:
    """Every ``$(var)`` is declared before use, every include names an existing file and
    passes the included file's required args, and include trees reach 8 files."""
    files = sorted(ros2_workspace.glob("*/launch/*.launch.xml"))
    includes: dict[str, list[str]] = {}
    for path in files:
        declared: set[str] = set()
        includes[str(path)] = []
        for child in _root(str(path)).children:  # args and lets are declared at the top
            for entity in _walk(child):
                used = _VAR.findall(" ".join(entity.attributes.values()))
                assert set(used) <= declared, (path, entity.tag)
                if entity.tag == "include":
                    includes[str(path)].append(_included(ros2_workspace, entity))
            if child.tag in ("arg", "let"):
                declared.add(child.attributes["name"])

    @cache
    def depth(path: str) -> int:
        return 1 + max((depth(target) for target in includes[path]), default=0)

    assert max(depth(path) for path in includes) == generate.ROS2_MAX_LEVEL + 1


def test_expressions_are_one_argument(ros2_workspace: Path) -> None:
    """Launch's ``$(eval)`` takes the expression and optional modules: an expression not
    quoted whole is split at its blanks into more arguments, and the file does not load."""
    evals = 0
    for path in ros2_workspace.glob("*/launch/*.launch.xml"):
        for entity in _walk(_root(str(path))):
            for text in entity.attributes.values():
                calls = [part for part in parse(text) if isinstance(part, Call)]
                evals += sum(call.name == "eval" for call in calls)
                assert all(len(c.arguments) == 1 for c in calls if c.name == "eval"), text
    assert (evals > 0) == (ros2_workspace.parent.name.startswith("ros2-dense"))


@pytest.mark.parametrize("shape", ["ros2", "ros2-dense"])
def test_deterministic(tmp_path: Path, shape: str) -> None:
    first = generate.SHAPES[shape](tmp_path / "a", 30, 3)
    second = generate.SHAPES[shape](tmp_path / "b", 30, 3)
    assert [p.read_text() for p in first] == [p.read_text() for p in second]
