"""``executables(package)``: the names a node's ``type`` can take in a package."""

from __future__ import annotations

from pathlib import Path

import pytest

from rosvar.workspace import Package, discover
from rosvar.workspace.executables import executables

MANIFEST = '<?xml version="1.0"?>\n<package format="2"><name>{}</name></package>\n'


def package_dir(tmp_path: Path, name: str = "drv") -> Path:
    directory = tmp_path / name
    directory.mkdir(parents=True)
    (directory / "package.xml").write_text(MANIFEST.format(name))
    return directory


def write(path: Path, text: str = "", mode: int | None = None) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text)
    if mode is not None:
        path.chmod(mode)


def test_executables_file_is_read_by_discovery(tmp_path: Path) -> None:
    directory = package_dir(tmp_path)
    write(directory / ".executables", "driver_node\n\n  spaced_tool  \n")
    [package] = discover([tmp_path], ros_package_path="").packages.values()
    assert package.executables == frozenset({"driver_node", "spaced_tool"})
    assert executables(package) == {"driver_node", "spaced_tool"}


def test_no_executables_file_means_unknown_not_empty(tmp_path: Path) -> None:
    package_dir(tmp_path)
    [package] = discover([tmp_path], ros_package_path="").packages.values()
    assert package.executables is None
    assert executables(package) == frozenset()


def test_scripts_nodes_and_bin(tmp_path: Path) -> None:
    directory = package_dir(tmp_path)
    write(directory / "scripts" / "teleop.py")  # .py counts even without the x bit
    write(directory / "scripts" / "run_me", "#!/bin/sh\n", 0o755)
    write(directory / "scripts" / "README", "docs\n")  # neither .py nor executable
    write(directory / "nodes" / "mover", "#!/usr/bin/env python\n", 0o755)
    write(directory / "bin" / "helper.py")
    write(directory / "src" / "lib.py")  # not a script folder, not executable
    write(directory / "launch" / "wrapper.py", "", 0o755)  # executable anywhere: found
    write(directory / "meshes" / "body.dae", "", 0o755)  # meshes are not executables
    package = Package("drv", str(directory), None)
    assert executables(package) == {"teleop.py", "run_me", "mover", "helper.py", "wrapper.py"}


BUILD_FILES = {
    "cmake": (
        "CMakeLists.txt",
        "cmake_minimum_required(VERSION 3.0.2)\nproject(drv)\n"
        "add_executable(${PROJECT_NAME}_node src/node.cpp)\n"
        "ADD_EXECUTABLE( upper_case src/u.cpp )\n"
        "add_executable(${UNKNOWN_VAR}_x src/x.cpp)\n"
        "catkin_install_python(PROGRAMS scripts/a.py nodes/b\n"
        "  DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})\n"
        "install(PROGRAMS tools/c.sh DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})\n",
        {"drv_node", "upper_case", "a.py", "b", "c.sh"},
    ),
    "ament_cmake": (
        "CMakeLists.txt",
        "cmake_minimum_required(VERSION 3.8)\nproject(drv)\nfind_package(ament_cmake REQUIRED)\n"
        "add_library(drv_component SHARED src/component.cpp)\n"
        "rclcpp_components_register_node(drv_component\n"
        '  PLUGIN "drv::Driver"\n  EXECUTABLE driver_node)\n'
        'rclcpp_components_register_nodes(drv_component "drv::Other")\n'
        "install(TARGETS drv_component DESTINATION lib/${PROJECT_NAME})\nament_package()\n",
        {"driver_node"},
    ),
    "ament_cmake_auto": (
        "CMakeLists.txt",
        "project(drv)\nfind_package(ament_cmake_auto REQUIRED)\n"
        "ament_auto_find_build_dependencies()\n"
        "ament_auto_add_library(${PROJECT_NAME}_lib SHARED src/lib.cpp)\n"
        "ament_auto_add_executable(${PROJECT_NAME}_node src/main.cpp)\n"
        "ament_auto_add_executable(globbed DIRECTORY src/globbed)\nament_auto_package()\n",
        {"drv_node", "globbed"},
    ),
    "setup.py over lines": (
        "setup.py",
        "from setuptools import setup\n"
        "setup(\n"
        "    name='drv',\n"
        "    entry_points={\n"
        "        'console_scripts': [\n"
        "            'talker = drv.talker:main',\n"
        '            "listener=drv.listener:main",\n'
        "        ],\n"
        "    },\n"
        ")\n",
        {"talker", "listener"},
    ),
    "setup.py on one line": (
        "setup.py",
        "from setuptools import setup\n"
        "setup(name='drv', entry_points={'console_scripts': "
        "['talker = drv.talker:main', 'listener = drv.listener:main']})\n",
        {"talker", "listener"},
    ),
    "setup.cfg": (
        "setup.cfg",
        "[metadata]\nname = drv\n\n[options.entry_points]\nconsole_scripts =\n"
        "    cfg_tool = drv.tool:main\n",
        {"cfg_tool"},
    ),
}


@pytest.mark.parametrize(
    ("name", "text", "expected"), list(BUILD_FILES.values()), ids=list(BUILD_FILES)
)
def test_build_file_targets(tmp_path: Path, name: str, text: str, expected: set[str]) -> None:
    directory = package_dir(tmp_path)
    write(directory / name, text)
    assert executables(Package("drv", str(directory), None)) == expected


def test_all_sources_together(tmp_path: Path) -> None:
    directory = package_dir(tmp_path)
    write(directory / ".executables", "listed\n")
    write(directory / "scripts" / "script.py")
    write(directory / "CMakeLists.txt", "project(drv)\nadd_executable(built src/a.cpp)\n")
    write(
        directory / "setup.py",
        "setup(\n    entry_points={\n        'console_scripts': [\n"
        "            'entry = drv.e:main',\n        ]\n    }\n)\n",
    )
    [package] = discover([tmp_path], ros_package_path="").packages.values()
    assert executables(package) == {"listed", "script.py", "built", "entry"}
