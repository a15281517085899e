"""``pathlib`` paths in launch helpers: computed as pathlib computes them, the file system
asked only inside the workspace, and the xacro documents helpers make."""

from __future__ import annotations

import ast
from pathlib import Path, PurePosixPath

import pytest

from rosvar.diagnostics import Diagnostic, DiagnosticSink
from rosvar.files import Confinement
from rosvar.ros2.frontends.python.interpreter import Interpreter
from rosvar.ros2.frontends.python.modules import ModulePath
from rosvar.ros2.frontends.python.text import Sub, Text, render
from rosvar.ros2.frontends.python.values import Dynamic, FilePath, Unknown, Value

SHARE = "from ament_index_python.packages import get_package_share_directory as share\n"


def run(workspace: Path, text: str) -> tuple[dict[str, Value], list[Diagnostic]]:
    """Module-level names of ``text`` read as ``workspace/pkg/launch/t.launch.py``."""
    packages = {path.parent.name: str(path.parent) for path in workspace.glob("*/package.xml")}
    modules = ModulePath(packages, Confinement.of([str(workspace)]))
    sink = DiagnosticSink()
    reader = Interpreter(str(workspace / "pkg" / "launch" / "t.launch.py"), text, sink, modules)
    return reader.run_module(ast.parse(text)).names, sink.items


def workspace(root: Path, files: dict[str, str]) -> Path:
    (root / "pkg").mkdir(parents=True)
    (root / "pkg" / "package.xml").write_text("<package/>")
    for relative, text in files.items():
        (root / "pkg" / relative).parent.mkdir(parents=True, exist_ok=True)
        (root / "pkg" / relative).write_text(text)
    return root


@pytest.mark.parametrize(
    "expression",
    [
        "str(Path('a') / 'b' / 'c.yaml')",
        "str(Path('a//b/./c/'))",
        "str(Path('a') / '/abs' / 'x')",
        "str(Path('/r/a/b.txt').parent)",
        "(Path('a/b.tar.gz').name, Path('a/b.tar.gz').stem, Path('a/b.tar.gz').suffix)",
        "str(Path('a', 'b').joinpath('c', 'd'))",
        "str(Path('x').parent)",
        "str('pre' / Path('post'))",
        "isinstance(Path('a'), Path) and not isinstance('a', Path)",
    ],
)
def test_literal_paths_compute_as_pathlib(tmp_path: Path, expression: str) -> None:
    names, diagnostics = run(
        workspace(tmp_path, {}), f"from pathlib import Path\nv = {expression}\n"
    )
    assert names["v"] == eval(expression, {"Path": PurePosixPath})  # the oracle: pathlib
    assert diagnostics == []


def test_a_package_path_keeps_its_directory_and_knows_its_tail(tmp_path: Path) -> None:
    names, diagnostics = run(
        workspace(tmp_path, {"config/kinematics.yaml": "a: 1\n"}),
        f"{SHARE}from pathlib import Path\n"
        "p = Path(share('pkg')) / 'config' / 'kinematics.yaml'\n"
        "parent, name, text = p.parent, p.name, str(p)\n"
        "there, missing = p.exists(), (p.parent / 'none.yaml').is_file()\n"
        "listed = [c.name for c in p.parent.iterdir()]\n"
        "import yaml\nloaded = yaml.safe_load(open(p))\n",
    )
    assert names["parent"] == FilePath(Text.of(Sub("find-pkg-share", (Text.of("pkg"),))), "config")
    assert names["name"] == "kinematics.yaml"
    text = names["text"]
    assert isinstance(text, Dynamic) and text.text is not None
    assert render(text.text) == "$(find-pkg-share pkg)/config/kinematics.yaml"
    assert (names["there"], names["missing"], names["listed"]) == (True, False, ["kinematics.yaml"])
    assert names["loaded"] == {"a": 1}
    assert diagnostics == []


@pytest.mark.parametrize("path", ["'/etc'", "Path(share('pkg')) / '..' / '..' / 'outside'"])
def test_the_file_system_is_asked_only_inside_the_workspace(tmp_path: Path, path: str) -> None:
    root = workspace(tmp_path / "ws", {})
    (tmp_path / "outside").mkdir()
    names, diagnostics = run(
        root,
        f"{SHARE}from pathlib import Path\nimport os\n"
        f"a = Path({path}).exists()\nb = list(Path({path}).iterdir())\nc = os.path.isdir({path})\n",
    )
    assert all(isinstance(names[n], Unknown) for n in "abc")
    assert {d.code for d in diagnostics} == {"file-outside-workspace"}


def test_unknown_heads_are_reported_not_guessed(tmp_path: Path) -> None:
    names, diagnostics = run(
        workspace(tmp_path, {}),
        "from pathlib import Path\nfrom launch.substitutions import LaunchConfiguration as L\n"
        "p = Path(L('dir').perform(None))\na = p.parent\nb = p.exists()\n"
        "home = str(Path.home() / '.ros')\n",
    )
    assert isinstance(names["a"], Unknown) and isinstance(names["b"], Unknown)
    home = names["home"]
    assert isinstance(home, Dynamic) and home.text is not None
    assert render(home.text) == "$(env HOME)/.ros"
    assert [d.code for d in diagnostics] == ["python-not-followed"] * 2


def test_xacro_process_file_is_rosvars_xacro_command_never_the_package(tmp_path: Path) -> None:
    root = workspace(tmp_path, {"urdf/r.xacro": "<robot/>", "xacro/__init__.py": "1/0\n"})
    (root / "pkg" / "xacro" / "package.xml").write_text("<package/>")
    names, diagnostics = run(
        root,
        f"{SHARE}import xacro\nfrom pathlib import Path\n"
        "from launch.substitutions import LaunchConfiguration as L\n"
        "p = Path(share('pkg')) / 'urdf' / 'r.xacro'\n"
        "a = xacro.process_file(p, mappings={'name': 'a b', 'ns': L('ns').perform(None)}).toxml()\n"
        "b = xacro.process_file(str(p)).toprettyxml(indent='  ')\n",
    )
    a, b = names["a"], names["b"]
    assert isinstance(a, Text) and isinstance(b, Text)
    assert render(a) == (
        "$(command 'xacro $(find-pkg-share pkg)/urdf/r.xacro \\'name:=a b\\' ns:=$(var ns)')"
    )
    assert render(b) == "$(command 'xacro $(find-pkg-share pkg)/urdf/r.xacro')"
    assert diagnostics == []
