"""The workspace's Python modules a launch file imports, and the files its Python reads:
read by the same interpreter, never imported, within the confinement and the bounds."""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

from rosvar.diagnostics import Diagnostic, DiagnosticSink
from rosvar.files import Confinement
from rosvar.frontends.entity import Entity
from rosvar.ros2.frontends.python import interpreter
from rosvar.ros2.frontends.python.interpreter import Interpreter
from rosvar.ros2.frontends.python.modules import ModulePath
from rosvar.ros2.frontends.python.values import Instance, Module, Unknown, Value

SHARE = "import os\nfrom ament_index_python.packages import get_package_share_directory as share\n"
"""The imports of the launch files below that name a package's share directory."""


def run(workspace: Path, text: str) -> tuple[dict[str, Value], list[Diagnostic]]:
    """Module-level names of ``text`` read as ``workspace/pkg/launch/t.launch.py``."""
    packages = {path.parent.name: str(path.parent) for path in workspace.glob("*/package.xml")}
    modules = ModulePath(packages, Confinement.of([str(workspace)]))
    sink = DiagnosticSink()
    launch = workspace / "pkg" / "launch" / "t.launch.py"
    reader = Interpreter(str(launch), text, sink, modules)
    return reader.run_module(ast.parse(text)).names, sink.items


def package(workspace: Path, name: str, files: dict[str, str]) -> None:
    (workspace / name).mkdir(parents=True, exist_ok=True)
    (workspace / name / "package.xml").write_text("<package/>")
    for relative, text in files.items():
        path = workspace / name / relative
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)


def test_a_module_of_another_package_is_read_with_its_classes(tmp_path: Path) -> None:
    package(tmp_path, "pkg", {})
    package(
        tmp_path,
        "helpers",
        {
            "src/helpers_py/__init__.py": "from .tools import Scaled as Scaled\nBASE = 2\n",
            "src/helpers_py/tools.py": (
                "from . import limits\n"
                "class Scaled:\n"
                "    factor = limits.FACTOR\n"
                "    def __init__(self, v):\n"
                "        self.v = v\n"
                "    def value(self):\n"
                "        return self.v * self.factor\n"
            ),
            "src/helpers_py/limits.py": "FACTOR = 3\n",
        },
    )
    names, diagnostics = run(
        tmp_path,
        "import helpers_py\nfrom helpers_py.tools import Scaled\n"
        "v = Scaled(helpers_py.BASE).value() + helpers_py.Scaled(1).value()\n"
        "import yaml\nimport launch_ros.actions\n",
    )
    assert names["v"] == 2 * 3 + 3
    assert names["yaml"] == Module("yaml") and names["launch_ros"] == Module("launch_ros")
    assert diagnostics == []


def test_a_launch_folder_never_shadows_the_launch_api(tmp_path: Path) -> None:
    package(tmp_path, "pkg", {"launch/__init__.py": "X = 1\n"})
    names, _ = run(tmp_path, "import launch\nfrom launch.actions import GroupAction\n")
    assert names["launch"] == Module("launch")
    assert names["GroupAction"] == Module("launch.actions.GroupAction")


def test_an_import_cycle_sees_the_partial_module_and_ends(tmp_path: Path) -> None:
    package(tmp_path, "pkg", {"loop/__init__.py": "import loop\nfrom loop import A\nA = 1\n"})
    names, diagnostics = run(tmp_path, "import loop\nv = loop.A\n")
    assert names["v"] == 1
    assert diagnostics == []


def test_modules_read_are_bounded(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(interpreter, "MAX_MODULES", 3)
    chain = {f"m{i}/__init__.py": f"import m{i + 1}\nV = {i}\n" for i in range(10)}
    package(tmp_path, "pkg", chain)
    names, diagnostics = run(tmp_path, "import m0\nv = m0.V\n")
    assert names["v"] == 0
    assert any("beyond the bound on modules read" in d.message for d in diagnostics)


def test_a_module_that_cannot_be_read_is_reported_and_symbolic(tmp_path: Path) -> None:
    package(tmp_path, "pkg", {"broken/__init__.py": "def (:\n"})
    names, diagnostics = run(tmp_path, "import broken\n")
    assert names["broken"] == Module("broken")
    assert [d.code for d in diagnostics] == ["python-module"]
    assert "broken" in diagnostics[0].message


def test_sys_path_appends_find_modules_of_a_share_directory(tmp_path: Path) -> None:
    package(tmp_path, "pkg", {})
    package(tmp_path, "other", {"launch/common.py": "NAME = 'found'\n"})
    names, _ = run(
        tmp_path,
        f"{SHARE}import sys\nsys.path.append(os.path.join(share('other'), 'launch'))\n"
        "import common\nv = common.NAME\n",
    )
    assert names["v"] == "found"


def test_yaml_of_the_workspace_is_read_into_values(tmp_path: Path) -> None:
    package(tmp_path, "pkg", {"config/p.yaml": "a: {b: [1, x]}\n"})
    names, diagnostics = run(
        tmp_path,
        f"{SHARE}import yaml\npath = os.path.join(share('pkg'), 'config', 'p.yaml')\n"
        "with open(path) as f:\n    v = yaml.safe_load(f)\n",
    )
    assert names["v"] == {"a": {"b": [1, "x"]}}
    assert diagnostics == []


@pytest.mark.parametrize(
    "path",
    ["'/etc/passwd'", "os.path.join(os.path.dirname(__file__), '..', '..', '..', 'secret')"],
)
def test_a_read_outside_the_workspace_is_refused_naming_the_path(tmp_path: Path, path: str) -> None:
    workspace = tmp_path / "ws"
    package(workspace, "pkg", {})
    (tmp_path / "secret").write_text("password: hunter2\n")
    names, diagnostics = run(workspace, f"import os, yaml\nv = yaml.safe_load(open({path}))\n")
    assert isinstance(names["v"], Unknown)
    assert "hunter2" not in repr(names["v"])
    assert [d.code for d in diagnostics] == ["file-outside-workspace"]
    assert ("passwd" if "passwd" in path else "secret") in diagnostics[0].message


def test_yaml_bombs_and_large_files_are_refused(tmp_path: Path) -> None:
    bomb = "a: &a [x, x, x, x, x, x, x, x, x, x]\n" + "".join(
        f"{chr(98 + i)}: &{chr(98 + i)} [*{chr(97 + i)}, *{chr(97 + i)}, *{chr(97 + i)}, "
        f"*{chr(97 + i)}, *{chr(97 + i)}, *{chr(97 + i)}, *{chr(97 + i)}, *{chr(97 + i)}, "
        f"*{chr(97 + i)}, *{chr(97 + i)}]\n"
        for i in range(8)
    )
    files = {"bomb.yaml": bomb, "large.yaml": "x" * (2 * 1024 * 1024), "launch/t.launch.py": ""}
    package(tmp_path, "pkg", files)
    names, diagnostics = run(
        tmp_path,
        "import yaml, os\nd = os.path.dirname(__file__)\n"
        "b = yaml.safe_load(open(d + '/../bomb.yaml'))\n"
        "l = yaml.safe_load(open(d + '/../large.yaml'))\n",
    )
    assert isinstance(names["b"], Unknown) and isinstance(names["l"], Unknown)
    assert [d.code for d in diagnostics] == ["python-not-followed", "file-too-large"]


def test_a_dataclass_is_made_of_its_fields(tmp_path: Path) -> None:
    package(tmp_path, "pkg", {})
    names, diagnostics = run(
        tmp_path,
        "from dataclasses import dataclass, field\n"
        "@dataclass(slots=True)\n"
        "class Configs:\n"
        "    path: str = 'p'\n"
        "    robot: dict = field(default_factory=dict)\n"
        "    count: int = field(default=2)\n"
        "    def total(self):\n"
        "        return self.count + len(self.robot)\n"
        "a = Configs()\n"
        "b = Configs('q', {'x': 1}, count=5)\n"
        "a.robot['k'] = 1\n"
        "v = (a.path, a.total(), b.path, b.total(), Configs().robot)\n",
    )
    assert names["v"] == ("p", 3, "q", 6, {})
    assert diagnostics == []


def test_a_subclass_of_a_launch_action_is_that_action_with_its_super_arguments(
    tmp_path: Path,
) -> None:
    package(
        tmp_path,
        "helpers",
        {
            "helpers_py/__init__.py": (
                "from launch.actions import DeclareLaunchArgument\n"
                "from launch_ros.actions import Node\n"
                "class Flag(DeclareLaunchArgument):\n"
                "    def __init__(self, name, *, default_value=False, **kwargs):\n"
                "        super().__init__(name, default_value=str(default_value), **kwargs)\n"
                "class Plain(Node):\n"
                "    pass\n"
                "class Helper:\n"
                "    def __init__(self):\n"
                "        super().__init__()\n"
            )
        },
    )
    package(tmp_path, "pkg", {})
    names, diagnostics = run(
        tmp_path,
        "from helpers_py import Flag, Plain, Helper\n"
        "a = Flag('debug', default_value=True, description='d')\n"
        "n = Plain(package='p', executable='e')\n"
        "h = Helper()\n",
    )
    arg, node = names["a"], names["n"]
    assert isinstance(arg, Entity) and isinstance(node, Entity)
    assert (arg.tag, arg.attributes) == (
        "arg",
        {"name": "debug", "default": "True", "description": "d"},
    )
    assert (node.tag, node.attributes) == ("node", {"pkg": "p", "exec": "e"})
    assert isinstance(names["h"], Instance)
    assert diagnostics == []
