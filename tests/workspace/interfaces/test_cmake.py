"""The CMake reader: targets with their sources, variables, globs, links, programs."""

from __future__ import annotations

from pathlib import Path

from rosvar.workspace.interfaces.cmake import TargetKind, read_build
from rosvar.workspace.interfaces.cmake_script import commands

CMAKE = """\
cmake_minimum_required(VERSION 2.8.3)
project(demo)
set(SOURCES src/a.cpp "src/b.cpp")  # a comment (with parentheses)
list(APPEND SOURCES src/c.cpp)
add_library(${PROJECT_NAME}_core ${SOURCES})
add_executable(demo_node src/main.cpp)
target_link_libraries(demo_node ${PROJECT_NAME}_core ${catkin_LIBRARIES})
add_subdirectory(nodelet)
catkin_install_python(PROGRAMS scripts/tool.py
  DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})
include_directories(include ${catkin_INCLUDE_DIRS})
"""
SUB = """\
file(GLOB NODELET_SOURCES RELATIVE ${CMAKE_CURRENT_SOURCE_DIR} *.cpp)
add_library(demo_nodelet SHARED ${NODELET_SOURCES})
"""


def test_targets(tmp_path: Path) -> None:
    (tmp_path / "CMakeLists.txt").write_text(CMAKE)
    (tmp_path / "nodelet").mkdir()
    (tmp_path / "nodelet" / "CMakeLists.txt").write_text(SUB)
    for name in ("x.cpp", "y.cpp"):
        (tmp_path / "nodelet" / name).write_text("")
    build = read_build(str(tmp_path), "demo")
    src = tmp_path / "src"
    assert build.targets["demo_core"].sources == [str(src / n) for n in ("a.cpp", "b.cpp", "c.cpp")]
    assert build.targets["demo_node"].kind is TargetKind.EXECUTABLE
    assert build.sources("demo_node") == [
        str(src / n) for n in ("main.cpp", "a.cpp", "b.cpp", "c.cpp")
    ]
    assert build.targets["demo_nodelet"].sources == [
        str(tmp_path / "nodelet" / n) for n in ("x.cpp", "y.cpp")
    ]
    assert build.programs == [str(tmp_path / "scripts" / "tool.py")]
    assert build.include_dirs == [str(tmp_path / "include")]


def test_commands_quotes_and_comments() -> None:
    text = 'set(A "x y" b) # set(B c)\n#[[ add_executable(no) ]]\nmessage(STATUS "(")\n'
    found = [(c.name, list(c.arguments), c.line) for c in commands(text)]
    assert found == [("set", ["A", '"x y"', "b"], 1), ("message", ["STATUS", '"("'], 3)]


def test_output_name_and_source_without_suffix(tmp_path: Path) -> None:
    """move_base's ``move_base_node`` is installed as ``move_base``; interactive_marker_twist_server
    names its source ``src/marker_server``."""
    (tmp_path / "CMakeLists.txt").write_text(
        "add_executable(demo_node src/main)\n"
        "add_executable(other src/main.cpp)\n"
        'set_target_properties(demo_node PROPERTIES OUTPUT_NAME demo PREFIX "")\n'
    )
    (tmp_path / "src").mkdir()
    (tmp_path / "src" / "main.cpp").write_text("")
    build = read_build(str(tmp_path), "demo")
    assert build.targets["demo_node"].sources == [str(tmp_path / "src" / "main.cpp")]
    assert build.targets["demo_node"].installed_name == "demo"
    assert build.targets["other"].installed_name == "other"


def test_ament_targets_and_components(tmp_path: Path) -> None:
    (tmp_path / "CMakeLists.txt").write_text(
        "project(cam)\n"
        "ament_auto_add_library(cam_component SHARED src/component.cpp src/util.cpp)\n"
        'rclcpp_components_register_node(cam_component PLUGIN "cam::Node" EXECUTABLE cam_node)\n'
        "ament_auto_add_executable(tool src/tool.cpp NO_TARGET_LINK_LIBRARIES)\n"
        'rclcpp_components_register_node(cam_component PLUGIN "cam::Other")\n'
    )
    build = read_build(str(tmp_path), "cam")
    kinds = {name: target.kind for name, target in build.targets.items()}
    assert kinds == {
        "cam_component": TargetKind.LIBRARY,
        "cam_node": TargetKind.EXECUTABLE,
        "tool": TargetKind.EXECUTABLE,
    }
    # The component's executable runs the library's code.
    src = tmp_path / "src"
    assert build.sources("cam_node") == [str(src / "component.cpp"), str(src / "util.cpp")]
    assert build.sources("tool") == [str(src / "tool.cpp")]


def test_target_named_with_an_unknown_variable_is_vague(tmp_path: Path) -> None:
    (tmp_path / "CMakeLists.txt").write_text(
        "project(p)\nset(KNOWN k)\n"
        "add_executable(${KNOWN}_a a.cpp)\nadd_executable(${OTHER}_b b.cpp)\n"
    )
    build = read_build(str(tmp_path), "p")
    assert set(build.targets) == {"k_a", "_b"}
    assert build.vague_names == {"_b"}
