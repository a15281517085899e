"""CMake's language as the target reader runs it: loops, the workspace's functions and
macros, ``cmake_parse_arguments``, ``include``, other packages' extras; bounded on hostile
input; and, where CMake is installed, the targets real CMake configures from the same files."""

from __future__ import annotations

import json
import shutil
import subprocess
from pathlib import Path

import pytest

from rosvar.diagnostics import DiagnosticSink
from rosvar.workspace.interfaces.cmake import TargetKind, cmake_extras, read_build

LANGUAGE = """\
cmake_minimum_required(VERSION 3.10)
project(demo CXX)
include(cmake/helpers.cmake)
set(NODES talker listener)
foreach(node ${NODES})
  add_executable(${node} src/${node}.cpp)
endforeach()
foreach(source IN ITEMS src/tool_a.cpp src/tool_b.cpp)
  get_filename_component(name ${source} NAME_WE)
  add_executable(${name}_exe ${source})
endforeach()
function(demo_add_node)
  cmake_parse_arguments(ARG "" "NAME" "SOURCES" ${ARGN})
  add_executable(${ARG_NAME} ${ARG_SOURCES})
endfunction()
demo_add_node(NAME wrapped SOURCES src/wrapped.cpp src/util.cpp)
macro(demo_node name)
  add_executable(${name} src/${name}.cpp ${ARGN})
endmacro()
demo_node(macro_node src/util.cpp)
helper_node(from_include)
"""
HELPERS = """\
function(helper_node name)
  add_executable(${name} src/${name}.cpp)
endfunction()
"""
SOURCES = (
    "talker listener tool_a tool_b wrapped util macro_node from_include".split()  # noqa: SIM905
)


def _write(root: Path) -> None:
    (root / "cmake").mkdir(parents=True)
    (root / "src").mkdir()
    (root / "CMakeLists.txt").write_text(LANGUAGE)
    (root / "cmake" / "helpers.cmake").write_text(HELPERS)
    for name in SOURCES:
        (root / "src" / f"{name}.cpp").write_text("int main() { return 0; }\n")


EXPECTED = {
    "talker": ["talker"],
    "listener": ["listener"],
    "tool_a_exe": ["tool_a"],
    "tool_b_exe": ["tool_b"],
    "wrapped": ["wrapped", "util"],
    "macro_node": ["macro_node", "util"],
    "from_include": ["from_include"],
}


def _targets(root: Path) -> dict[str, list[str]]:
    build = read_build(str(root), "demo")
    return {
        name: [Path(source).stem for source in target.sources]
        for name, target in build.targets.items()
        if target.kind is TargetKind.EXECUTABLE
    }


def test_loops_functions_macros_and_includes(tmp_path: Path) -> None:
    _write(tmp_path)
    assert _targets(tmp_path) == EXPECTED


@pytest.mark.skipif(shutil.which("cmake") is None, reason="CMake is not installed")
def test_targets_agree_with_cmake(tmp_path: Path) -> None:
    """Real CMake configures the same project; its file API lists the targets it made."""
    source, build = tmp_path / "src_root", tmp_path / "build"
    _write(source)
    query = build / ".cmake" / "api" / "v1" / "query"
    query.mkdir(parents=True)
    (query / "codemodel-v2").write_text("")
    done = subprocess.run(
        ["cmake", "-S", str(source), "-B", str(build)], capture_output=True, check=False
    )
    if done.returncode != 0:
        pytest.skip("CMake cannot configure here: " + done.stderr.decode()[-300:])
    reply = build / ".cmake" / "api" / "v1" / "reply"
    index = json.loads(next(reply.glob("index-*.json")).read_text())
    model = index["reply"]["codemodel-v2"]["jsonFile"]
    configuration = json.loads((reply / model).read_text())["configurations"][0]
    real: dict[str, list[str]] = {}
    for target in configuration["targets"]:
        detail = json.loads((reply / target["jsonFile"]).read_text())
        if detail["type"] == "EXECUTABLE":
            real[detail["name"]] = [Path(s["path"]).stem for s in detail["sources"]]
    assert real == _targets(source)


def test_known_wrappers_of_other_tools(tmp_path: Path) -> None:
    (tmp_path / "CMakeLists.txt").write_text(
        "cuda_add_executable(gpu_node src/gpu.cu src/host.cpp OPTIONS -arch sm_60)\n"
        "cs_add_executable(simple_node src/simple.cpp)\n"
        "ament_auto_add_executable(auto_node DIRECTORY src/auto)\n"
    )
    (tmp_path / "src" / "auto").mkdir(parents=True)
    (tmp_path / "src" / "auto" / "main.cpp").write_text("")
    (tmp_path / "src" / "auto" / "notes.txt").write_text("")
    build = read_build(str(tmp_path), "demo")
    src = tmp_path / "src"
    assert build.targets["gpu_node"].sources == [str(src / "gpu.cu"), str(src / "host.cpp")]
    assert build.targets["simple_node"].kind is TargetKind.EXECUTABLE
    assert build.targets["auto_node"].sources == [str(src / "auto" / "main.cpp")]


def test_functions_of_another_package_of_the_workspace(tmp_path: Path) -> None:
    """A package's CMake extras define a wrapper that dependents call after find_package."""
    tools, user = tmp_path / "my_cmake_tools", tmp_path / "user"
    (tools / "cmake").mkdir(parents=True)
    (tools / "cmake" / "my_cmake_tools-extras.cmake").write_text(
        "macro(my_add_node name)\n  add_executable(${name} src/${name}.cpp)\nendmacro()\n"
        "add_executable(never_here x.cpp)\n"
    )
    user.mkdir()
    (user / "CMakeLists.txt").write_text(
        "find_package(catkin REQUIRED COMPONENTS roscpp my_cmake_tools)\nmy_add_node(driver)\n"
    )
    extras = {"my_cmake_tools": cmake_extras(str(tools))}
    assert set(read_build(str(user), "user").targets) == set()  # unknown without the extras
    build = read_build(str(user), "user", extras=extras)
    assert set(build.targets) == {"driver"}
    assert build.targets["driver"].sources == [str(user / "src" / "driver.cpp")]


def test_catkin_python_setup_installs_the_scripts_of_setup_py(tmp_path: Path) -> None:
    (tmp_path / "CMakeLists.txt").write_text("catkin_python_setup()\n")
    (tmp_path / "setup.py").write_text(
        "from catkin_pkg.python_setup import generate_distutils_setup\n"
        "d = generate_distutils_setup(packages=['demo'], package_dir={'': 'src'},\n"
        "    scripts=['scripts/a_node', 'scripts/' 'b_node'])\n"
    )
    build = read_build(str(tmp_path), "demo")
    assert build.programs == [str(tmp_path / "scripts" / n) for n in ("a_node", "b_node")]


@pytest.mark.parametrize(
    ("text", "limit"),
    [
        ("function(f)\n  f()\nendfunction()\nf()\nadd_executable(after a.cpp)\n", "nested"),
        (
            "set(X x)\nforeach(i RANGE 100)\n  set(X ${X}${X})\nendforeach()\n"
            "add_executable(after a.cpp)\n",
            "characters",
        ),
        (
            "macro(m)\n  foreach(i RANGE 200)\n    add_library(l${i} a.cpp)\n  endforeach()\n"
            "endmacro()\nforeach(j RANGE 200)\n  m()\nendforeach()\nadd_executable(after a.cpp)\n",
            "commands",
        ),
        ("foreach(i RANGE 100000000)\nendforeach()\nadd_executable(after a.cpp)\n", "loop"),
    ],
)
def test_hostile_scripts_stay_bounded(tmp_path: Path, text: str, limit: str) -> None:
    (tmp_path / "CMakeLists.txt").write_text(text)
    sink = DiagnosticSink()
    build = read_build(str(tmp_path), "demo", sink=sink)
    (warning,) = [d for d in sink.items if d.code == "cmake-limit"]
    assert limit in warning.message
    assert warning.location.file.endswith("CMakeLists.txt") and warning.location.line > 0
    if limit != "commands":  # the budget stops the file; the other limits let it go on
        assert "after" in build.targets
