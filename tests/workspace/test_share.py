"""A ROS 2 source package's share folder as its install rules fill it: ``$(find-pkg-share)``
paths read from the source files ``install`` / ``data_files`` copy there."""

from __future__ import annotations

from pathlib import Path

from rosvar.files import read_file
from rosvar.workspace import discover
from workspace.interfaces.ros2_packages import MANIFEST

CMAKE = """cmake_minimum_required(VERSION 3.8)
project(demo)
set(CONFIG_DIRS bringup/config)
install(DIRECTORY bringup/launch ${CONFIG_DIRS} DESTINATION share/${PROJECT_NAME})
install(DIRECTORY description/ DESTINATION share/demo/robot
  FILES_MATCHING PATTERN "*.xacro" PATTERN "private" EXCLUDE)
install(FILES extra/a.yaml extra/old.yaml extra/b.yaml DESTINATION share/${PROJECT_NAME}/params)
install(FILES extra/new.yaml DESTINATION share/${PROJECT_NAME}/params RENAME old.yaml)
install(DIRECTORY hardware/include/ DESTINATION include/${PROJECT_NAME})
install(DIRECTORY ${UNSET_FOLDER}/maps DESTINATION share/${PROJECT_NAME})
"""
FILES = [
    "bringup/launch/main.launch.xml",
    "bringup/config/controllers.yaml",
    "description/arm.urdf.xacro",
    "description/notes.txt",
    "description/private/secret.xacro",
    "extra/a.yaml",
    "extra/old.yaml",
    "extra/new.yaml",
    "extra/b.yaml",
    "params/b.yaml",
    "config/as_is.yaml",
    "hardware/include/x.hpp",
]


def _package(root: Path, name: str, build: str, files: dict[str, str]) -> Path:
    package = root / name
    package.mkdir(parents=True)
    (package / "package.xml").write_text(MANIFEST.format(name=name, build=build))
    for relative, text in files.items():
        (package / relative).parent.mkdir(parents=True, exist_ok=True)
        (package / relative).write_text(text)
    return package


def test_cmake_install_rules_map_share_paths_to_their_sources(tmp_path: Path) -> None:
    package = _package(
        tmp_path, "demo", "ament_cmake", {"CMakeLists.txt": CMAKE} | {f: f for f in FILES}
    )
    workspace = discover([str(tmp_path)], ament_prefix_path="")
    share = str(package)

    def installed(relative: str) -> str:
        return workspace.installed(f"{share}/{relative}")

    # a folder named without "/" lands under its name; one with "/" gives its contents
    assert installed("config/controllers.yaml") == f"{share}/bringup/config/controllers.yaml"
    assert installed("launch/main.launch.xml") == f"{share}/bringup/launch/main.launch.xml"
    assert installed("launch") == f"{share}/bringup/launch"
    assert installed("robot/arm.urdf.xacro") == f"{share}/description/arm.urdf.xacro"
    # FILES_MATCHING: a file no pattern matches is not copied; EXCLUDE leaves a folder out
    assert installed("robot/notes.txt") == f"{share}/robot/notes.txt"
    assert installed("robot/private/secret.xacro") == f"{share}/robot/private/secret.xacro"
    # FILES, and a later RENAME overwrites the earlier file of that name
    assert installed("params/a.yaml") == f"{share}/extra/a.yaml"
    assert installed("params/old.yaml") == f"{share}/extra/new.yaml"
    # no rule puts it there, or not into the share folder: the path as it is; a file that
    # exists where the path names it is read there (the rules are not read for it)
    assert installed("config/as_is.yaml") == f"{share}/config/as_is.yaml"
    assert installed("params/b.yaml") == f"{share}/params/b.yaml"
    assert installed("x.hpp") == f"{share}/x.hpp"
    # the workspace's read gate reads the source
    assert read_file(f"{share}/params/old.yaml", workspace.confinement()) == b"extra/new.yaml"


def test_a_rule_with_a_variable_not_known_is_told_and_its_paths_read_as_they_are(
    tmp_path: Path,
) -> None:
    package = _package(
        tmp_path, "demo", "ament_cmake", {"CMakeLists.txt": CMAKE, "maps/m.yaml": "m"}
    )
    workspace = discover([str(tmp_path)], ament_prefix_path="")
    assert workspace.installed(f"{package}/maps/m.yaml") == f"{package}/maps/m.yaml"
    share = workspace.share_of(str(package / "maps" / "m.yaml"))
    assert share is not None
    [unread] = share[1].diagnostics
    assert unread.code == "install-unread"
    assert "${UNSET_FOLDER}/maps" in unread.message
    assert (unread.location.file, unread.location.line) == (str(package / "CMakeLists.txt"), 10)


def test_ament_cmake_auto_install_to_share(tmp_path: Path) -> None:
    cmake = "project(auto)\nament_auto_package(INSTALL_TO_SHARE launch param USE_SCOPED_X)\n"
    files = {"CMakeLists.txt": cmake, "param/p.yaml": "", "USE_SCOPED_X/f": ""}
    package = _package(tmp_path, "auto", "ament_cmake", files)
    workspace = discover([str(tmp_path)], ament_prefix_path="")
    assert workspace.installed(f"{package}/param/p.yaml") == f"{package}/param/p.yaml"
    share = workspace.share_of(str(package))
    assert share is not None
    assert [(s.source, s.destination) for s in share[1].shared] == [
        (f"{package}/launch", "launch"),
        (f"{package}/param", "param"),
    ]


SETUP = """import os
from glob import glob
from setuptools import setup

package_name = 'pyd'
setup(
    name=package_name,
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
        (os.path.join('share', package_name, 'launch'), glob('bringup/*.launch.py')),
        (f'share/{package_name}/config', ['params/p.yaml'] + glob('params/more/*.yaml')),
        (os.path.join('share', package_name, 'maps'), compute_maps()),
    ],
)
"""


def test_ament_python_data_files_map_share_paths(tmp_path: Path) -> None:
    package = _package(
        tmp_path,
        "pyd",
        "ament_python",
        {
            "setup.py": SETUP,
            "bringup/a.launch.py": "",
            "params/p.yaml": "",
            "params/more/q.yaml": "",
        },
    )
    workspace = discover([str(tmp_path)], ament_prefix_path="")
    assert workspace.installed(f"{package}/launch/a.launch.py") == f"{package}/bringup/a.launch.py"
    assert workspace.installed(f"{package}/config/p.yaml") == f"{package}/params/p.yaml"
    assert workspace.installed(f"{package}/config/q.yaml") == f"{package}/params/more/q.yaml"
    share = workspace.share_of(str(package))
    assert share is not None
    [unread] = share[1].diagnostics  # the maps' list is computed: not known
    assert (unread.code, unread.location.line) == ("install-unread", 13)


def test_installed_and_ros1_packages_are_read_as_they_are(tmp_path: Path) -> None:
    rule = "project(p)\ninstall(DIRECTORY bringup/config DESTINATION share/p)\n"
    files = {"CMakeLists.txt": rule, "bringup/config/c.yaml": "", "config/c.yaml": ""}
    prefix = tmp_path / "install"
    installed = _package(prefix / "share", "p", "ament_cmake", files)
    workspace = discover([str(tmp_path / "none")], ament_prefix_path=str(prefix))
    assert workspace.installed(f"{installed}/config/c.yaml") == f"{installed}/config/c.yaml"
    ros1 = _package(tmp_path / "ros1", "p", "catkin", files)
    workspace = discover([str(tmp_path / "ros1")], ament_prefix_path="")
    assert workspace.installed(f"{ros1}/config/c.yaml") == f"{ros1}/config/c.yaml"


def test_a_launch_file_not_found_below_an_unread_rule_tells_the_rule(tmp_path: Path) -> None:
    from rosvar.interpreter.workspace_models import Analysis

    entry = "launch/entry.launch.xml"
    include = '<launch><include file="$(find-pkg-share demo)/maps/m.launch.xml"/></launch>'
    package = _package(tmp_path, "demo", "ament_cmake", {"CMakeLists.txt": CMAKE, entry: include})
    workspace = discover([str(tmp_path)], ament_prefix_path="")
    model = Analysis(workspace).model(str(package / entry))
    assert {d.code for d in model.diagnostics} >= {"install-unread", "file-unreadable"}
