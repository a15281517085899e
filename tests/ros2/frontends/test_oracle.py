"""The YAML and Python frontends against the ROS 2 oracle (the real launch code).

A fixture launch is loaded by the oracle as written (Python, YAML) and as the XML file
written from the frontend's tree; both must start the same nodes with the same names,
namespaces, parameters, remappings and arguments, in several configurations. The oracle
executes the Python file: these are this test's own fixtures. Skipped without the oracle's
virtual environment (``ROSVAR_ROS2_ORACLE_PYTHON``, or ``.oracle-ros2-venv`` in the
repository, made by the oracle's ``setup.sh``).
"""

from __future__ import annotations

import json
import os
import subprocess
from pathlib import Path
from typing import Any

import pytest

from ros2.frontends.trees import ORACLE, to_xml
from rosvar.frontends.entity import ParseResult
from rosvar.ros2.frontends.python.parser import parse_python_launch_file
from rosvar.ros2.frontends.yaml.parser import parse_yaml_launch_file

REPO = Path(__file__).resolve().parents[3]
ORACLE_PYTHON = Path(
    os.environ.get("ROSVAR_ROS2_ORACLE_PYTHON", REPO / ".oracle-ros2-venv" / "bin" / "python")
)

PACKAGE_XML = """<?xml version="1.0"?>
<package format="3"><name>wpkg</name><version>0.0.0</version><description>d</description>
<maintainer email="a@b.c">a</maintainer><license>BSD</license></package>
"""

MAIN_PY = """\
import os
from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import (DeclareLaunchArgument, GroupAction, IncludeLaunchDescription,
    SetEnvironmentVariable, SetLaunchConfiguration)
from launch.conditions import IfCondition, UnlessCondition
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import (EnvironmentVariable, LaunchConfiguration,
    PathJoinSubstitution, PythonExpression, EqualsSubstitution)
from launch_ros.actions import Node, PushRosNamespace, SetParameter, SetRemap
from launch_ros.substitutions import FindPackageShare
from launch_ros.parameter_descriptions import ParameterValue

ROBOTS = ['r1', 'r2']


def worker(name, rate=10):
    return Node(package='wpkg', executable='worker', name=f'{name}_worker',
                parameters=[{'rate': rate, 'label': name, 'flag': True, 'ratio': 0.5,
                             'nested': {'a': 'x', 'b': 3}, 'txt': '10', 'yes': 'true',
                             'sv': ParameterValue('42', value_type=str)}],
                arguments=['--a', 'two words'])


def generate_launch_description():
    ns = LaunchConfiguration('ns', default='base')
    mode = LaunchConfiguration('mode')
    ld = LaunchDescription([
        DeclareLaunchArgument('mode', default_value='sim', choices=['sim', 'real']),
        DeclareLaunchArgument('ns', default_value='robot'),
        DeclareLaunchArgument('use_extra', default_value='false'),
        SetLaunchConfiguration('derived', [ns, '_d']),
        SetEnvironmentVariable('W_ENV', 'hello'),
        SetParameter(name='global_p', value='7'),
    ])
    group = [PushRosNamespace(ns), SetRemap(src='chatter', dst='/global/chatter')]
    for robot in ROBOTS:
        group.append(worker(robot, rate=20 if robot == 'r2' else 10))
    ld.add_action(GroupAction(group, scoped=True))
    ld.add_action(Node(
        package='wpkg', executable='sim_only', name='sim_only',
        namespace=LaunchConfiguration('derived'),
        parameters=[PathJoinSubstitution([FindPackageShare('wpkg'), 'config', 'p.yaml'])],
        remappings=[('in', [ns, '/in'])],
        condition=IfCondition(EqualsSubstitution(LaunchConfiguration('mode'), 'sim'))))
    ld.add_action(Node(package='wpkg', executable='real_only', name='real_only',
                       condition=IfCondition(EqualsSubstitution(mode, 'real'))))
    ld.add_action(Node(package='wpkg', executable='extra', name='extra',
                       condition=IfCondition(PythonExpression(
                           ["'", LaunchConfiguration('use_extra'), "' == 'true' or '", mode,
                            "' == 'real'"]))))
    ld.add_action(Node(package='wpkg', executable='env_named',
                       name=EnvironmentVariable('W_ENV', default_value='nope'),
                       condition=UnlessCondition(LaunchConfiguration('use_extra'))))
    ld.add_action(IncludeLaunchDescription(
        PythonLaunchDescriptionSource(os.path.join(
            get_package_share_directory('wpkg'), 'launch', 'sub.launch.py')),
        launch_arguments={'who': 'sub1', 'ns': ns}.items()))
    return ld
"""

SUB_PY = """\
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('who'),
        Node(package='wpkg', executable='sub', name=LaunchConfiguration('who'),
             parameters=[{'from_sub': LaunchConfiguration('ns')}]),
    ])
"""

MAIN_YAML = """\
launch:
- arg: {name: mode, default: sim}
- arg: {name: count, default: "3"}
- group:
    scoped: true
    children:
    - push-ros-namespace: {namespace: $(var mode)}
    - node:
        pkg: wpkg
        exec: worker
        name: typed
        args: --x "two words"
        param:
        - {name: s10, value: "10"}
        - {name: i10, value: 10}
        - {name: f, value: 0.5}
        - {name: b, value: yes}
        - {name: sb, value: "true"}
        - {name: sl, value: ["1", "2"]}
        - {name: il, value: [1, 2]}
        - {name: count, value: $(var count)}
        - name: nested
          param:
          - {name: a, value: x}
        remap:
        - {from: a, to: /b}
- node: {pkg: wpkg, exec: sim, name: sim, if: $(equals $(var mode) sim)}
"""

CONFIGURATIONS: tuple[list[str], ...] = (
    [],
    ["mode:=real", "use_extra:=true"],
    ["ns:=zz"],
    ["mode:=bad"],
)


def oracle(launch: Path, package_path: Path, arguments: list[str]) -> dict[str, Any]:
    completed = subprocess.run(
        [
            str(ORACLE_PYTHON),
            str(ORACLE / "oracle.py"),
            str(launch),
            *arguments,
            "--package-path",
            str(package_path),
            "--strict",
            "--env",
            "W_ENV=from_env",
        ],
        capture_output=True,
        text=True,
        timeout=120,
        check=False,
        env={"PATH": "/usr/bin:/bin"},
    )
    result: dict[str, Any] = json.loads(completed.stdout)
    return result


def summary(result: dict[str, Any]) -> tuple[tuple[bool, str | None], list[str]]:
    """What must agree: success, error, and each node but the file it came from."""
    ignored = {"launch_file", "cmd", "inline_parameters"}
    nodes = sorted(
        json.dumps({k: v for k, v in node.items() if k not in ignored}, sort_keys=True)
        for node in result.get("nodes", [])
    )
    return (result["ok"], result.get("error")), nodes


def write_xml(result: ParseResult, path: Path) -> None:
    assert result.root is not None, result.diagnostics
    path.write_text(to_xml(result.root).replace(".launch.py", ".launch.xml"))


@pytest.fixture
def package(tmp_path: Path) -> Path:
    if not (ORACLE_PYTHON.is_file() and (ORACLE / "oracle.py").is_file()):
        pytest.skip(f"no ROS 2 oracle environment at {ORACLE_PYTHON}")
    root = tmp_path / "pkgs" / "wpkg"
    (root / "launch").mkdir(parents=True)
    (root / "config").mkdir()
    (root / "package.xml").write_text(PACKAGE_XML)
    (root / "config" / "p.yaml").write_text("/**:\n  ros__parameters:\n    common: 1\n")
    return root


def test_python_and_its_tree_as_xml_start_the_same_nodes(package: Path) -> None:
    launch = package / "launch"
    for name, source in (("main", MAIN_PY), ("sub", SUB_PY)):
        (launch / f"{name}.launch.py").write_text(source)
        result = parse_python_launch_file(launch / f"{name}.launch.py")
        assert result.diagnostics == []
        write_xml(result, launch / f"{name}.launch.xml")
    for arguments in CONFIGURATIONS:
        python = summary(oracle(launch / "main.launch.py", package.parent, arguments))
        xml = summary(oracle(launch / "main.launch.xml", package.parent, arguments))
        assert python == xml, arguments
        assert python[0][0] == (arguments != ["mode:=bad"])


def test_yaml_and_its_tree_as_xml_start_the_same_nodes(package: Path) -> None:
    launch = package / "launch"
    (launch / "main.launch.yaml").write_text(MAIN_YAML)
    result = parse_yaml_launch_file(launch / "main.launch.yaml")
    assert result.diagnostics == []
    write_xml(result, launch / "main.launch.xml")
    for arguments in CONFIGURATIONS[:2]:
        yaml_run = summary(oracle(launch / "main.launch.yaml", package.parent, arguments))
        xml = summary(oracle(launch / "main.launch.xml", package.parent, arguments))
        assert yaml_run == xml, arguments
        assert yaml_run[0] == (True, None) and len(yaml_run[1]) == 2 - len(arguments) // 2
