"""Benchmark of the ROS 2 Python and YAML launch frontends on generated files, in process.

A Python launch file of about ``LINES`` lines (arguments, a helper function, a loop over a
literal list, nodes with typed parameters, remappings and conditions, includes) and the YAML
file of the same launch are each parsed ``RUNS`` times. Target: the Python file's median at
most ``TARGET_MS``. Exits 0 always; the target prints PASS/FAIL.
"""

from __future__ import annotations

import argparse
import statistics
import time
from collections.abc import Callable

from rosvar.ros2.frontends.python.parser import parse_python_launch_bytes
from rosvar.ros2.frontends.yaml.parser import parse_yaml_launch_bytes

LINES = 300
TARGET_MS = 100.0
RUNS = 30

_HEADER = """\
import os
from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, GroupAction, IncludeLaunchDescription
from launch.conditions import IfCondition, UnlessCondition
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution, PythonExpression
from launch_ros.actions import Node, PushRosNamespace
from launch_ros.substitutions import FindPackageShare

ROBOTS = [{robots}]


def sensor(name, rate):
    return Node(package='sensors', executable='driver', name=name,
                parameters=[{{'rate': rate, 'frame': name + '_link', 'enabled': True}}])


def generate_launch_description():
    ld = LaunchDescription()
"""

_ARG = """\
    ld.add_action(DeclareLaunchArgument('use_{i}', default_value='true',
                                        description='enable part {i}'))
"""

_NODE = """\
    ld.add_action(GroupAction([
        PushRosNamespace(LaunchConfiguration('ns_{i}', default='part_{i}')),
        Node(package='demo', executable='worker_{i}', name='worker_{i}',
             parameters=[PathJoinSubstitution([FindPackageShare('demo'), 'config', 'w{i}.yaml']),
                         {{'gain': {i}.5, 'limits': [1, {i}], 'label': f'worker {i}'}}],
             remappings=[('in', '/part_{i}/in'), ('out', 'out_{i}')],
             condition=IfCondition(LaunchConfiguration('use_{i}'))),
        IncludeLaunchDescription(
            PythonLaunchDescriptionSource(os.path.join(
                get_package_share_directory('demo'), 'launch', 'part_{i}.launch.py')),
            launch_arguments={{'index': '{i}'}}.items(),
            condition=UnlessCondition(PythonExpression(["'", LaunchConfiguration('use_{i}'),
                                                        "' == 'true'"]))),
    ]))
"""

_FOOTER = """\
    for robot in ROBOTS:
        ld.add_action(sensor(robot, 10))
    return ld
"""

_YAML_PART = """\
- arg: {{name: use_{i}, default: "true", description: enable part {i}}}
- group:
    children:
    - push-ros-namespace: {{namespace: $(var ns_{i} part_{i})}}
    - node:
        pkg: demo
        exec: worker_{i}
        name: worker_{i}
        if: $(var use_{i})
        param:
        - {{from: $(find-pkg-share demo)/config/w{i}.yaml}}
        - {{name: gain, value: {i}.5}}
        - {{name: limits, value: [1, {i}]}}
        remap:
        - {{from: in, to: /part_{i}/in}}
    - include:
        file: $(find-pkg-share demo)/launch/part_{i}.launch.yaml
        arg:
        - {{name: index, value: "{i}"}}
"""


def python_file(lines: int) -> str:
    """A Python launch file of about ``lines`` lines."""
    robots = ", ".join(f"'sensor_{i}'" for i in range(10))
    parts = [_HEADER.format(robots=robots)]
    i = 0
    while sum(part.count("\n") for part in parts) + _FOOTER.count("\n") < lines:
        parts.append(_ARG.format(i=i) + _NODE.format(i=i))
        i += 1
    return "".join(parts) + _FOOTER


def yaml_file(parts: int) -> str:
    return "launch:\n" + "".join(_YAML_PART.format(i=i) for i in range(parts))


def median_ms(parse: Callable[[bytes, str], object], data: bytes, runs: int) -> float:
    samples = []
    for _ in range(runs):
        start = time.perf_counter()
        parse(data, "bench.launch")
        samples.append((time.perf_counter() - start) * 1000)
    return statistics.median(samples)


def main() -> int:
    options = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    options.add_argument("--lines", type=int, default=LINES)
    options.add_argument("--runs", type=int, default=RUNS)
    arguments = options.parse_args()
    source = python_file(arguments.lines)
    result = parse_python_launch_bytes(source.encode(), "bench.launch.py")
    assert result.root is not None and not result.diagnostics, result.diagnostics
    entities = len(result.root.children)
    yaml_source = yaml_file(entities // 2)
    python_ms = median_ms(parse_python_launch_bytes, source.encode(), arguments.runs)
    yaml_ms = median_ms(parse_yaml_launch_bytes, yaml_source.encode(), arguments.runs)
    verdict = "PASS" if python_ms <= TARGET_MS else "FAIL"
    lines = source.count("\n")
    print(
        f"python  {lines:5d} lines  {entities:4d} actions  median {python_ms:7.2f} ms"
        f"  target <= {TARGET_MS:.0f} ms  {verdict}"
    )
    print(f"yaml    {yaml_source.count(chr(10)):5d} lines  median {yaml_ms:7.2f} ms")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
