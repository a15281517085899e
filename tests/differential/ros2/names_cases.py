"""Fixtures of the launch API's names (``rosvar.ros2.api``): each name in each frontend that
has it, for :mod:`.test_fixtures` (rosvar's resolution) and :mod:`.test_variational` (the
model restricted) to compare with the oracle."""

from __future__ import annotations

Case = tuple[dict[str, str], list[dict[str, str]]]

_BOOLEAN_XML = """<launch>
  <arg name="mode" default="a"/>
  <arg name="on" default="true"/>
  <arg name="gripper" default=""/>
  <node pkg="pkg" exec="x" name="eq" if="$(equals $(var mode) a)"/>
  <node pkg="pkg" exec="x" name="ne" if="$(not-equals $(var mode) a)"/>
  <node pkg="pkg" exec="x" name="empty" if="$(equals $(var gripper) '')"/>
  <node pkg="pkg" exec="x" name="num" if="$(equals $(var mode) 1.0)"/>
  <node pkg="pkg" exec="x" name="t_$(not $(var on))_$(and $(var on) $(var on))_$(or $(var on) 0)"/>
  <node pkg="pkg" exec="x" name="$(if $(var on) yes no)_$(if $(var on) only)"/>
</launch>"""

_BOOLEAN_YAML = """launch:
- arg: {name: mode, default: a}
- arg: {name: 'on', default: 'true'}
- arg: {name: gripper, default: ''}
- node: {pkg: pkg, exec: x, name: eq, if: $(equals $(var mode) a)}
- node: {pkg: pkg, exec: x, name: ne, if: $(not-equals $(var mode) a)}
- node: {pkg: pkg, exec: x, name: empty, if: "$(equals $(var gripper) '')"}
- node: {pkg: pkg, exec: x, name: num, if: $(equals $(var mode) 1.0)}
- node: {pkg: pkg, exec: x, name: t_$(not $(var on))_$(and $(var on) $(var on))_$(or $(var on) 0)}
- node: {pkg: pkg, exec: x, name: $(if $(var on) yes no)_$(if $(var on) only)}
"""

_BOOLEAN_PY = """from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.conditions import IfCondition, LaunchConfigurationEquals
from launch.conditions import LaunchConfigurationNotEquals
from launch.substitutions import AllSubstitution, AndSubstitution, AnySubstitution
from launch.substitutions import EqualsSubstitution, IfElseSubstitution
from launch.substitutions import LaunchConfiguration as V
from launch.substitutions import NotSubstitution, OrSubstitution
from launch_ros.actions import Node


def generate_launch_description():
    on = V('on')
    return LaunchDescription([
        DeclareLaunchArgument('mode', default_value='a'),
        DeclareLaunchArgument('on', default_value='true'),
        DeclareLaunchArgument('gripper', default_value=''),
        Node(package='pkg', executable='x', name='eq',
             condition=LaunchConfigurationEquals('mode', 'a')),
        Node(package='pkg', executable='x', name='ne',
             condition=LaunchConfigurationNotEquals('mode', 'a')),
        Node(package='pkg', executable='x', name='empty',
             condition=IfCondition(EqualsSubstitution(V('gripper'), ''))),
        Node(package='pkg', executable='x', name='num',
             condition=IfCondition(EqualsSubstitution(V('mode'), '1.0'))),
        Node(package='pkg', executable='x', name=[
            't_', NotSubstitution(on), '_', AndSubstitution(on, on), '_', OrSubstitution(on, '0')
        ]),
        Node(package='pkg', executable='x', name=[
            IfElseSubstitution(on, 'yes', 'no'), '_', IfElseSubstitution(on, 'only')
        ]),
        Node(package='pkg', executable='x', name=[
            'u_', AllSubstitution(on, '1', 'yes'), '_', AnySubstitution('false', on), '_',
            AllSubstitution(), AnySubstitution()
        ]),
    ])
"""

_EMIT_SHUTDOWN_PY = """from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, EmitEvent, TimerAction
from launch.conditions import IfCondition
from launch.events import Shutdown
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('stop', default_value='false'),
        TimerAction(period=1.0, actions=[Node(package='pkg', executable='x', name='late')]),
        EmitEvent(event=Shutdown(reason='asked'),
                  condition=IfCondition(LaunchConfiguration('stop'))),
        Node(package='pkg', executable='x', name='now'),
    ])
"""

_TYPES_XML = """<launch>
  <arg name="n" default="8"/>
  <node pkg="pkg" exec="x" name="typed">
    <param name="m" type="str" value="{a: 1, b: 2}"/>
    <param name="i" type="int" value="7"/>
    <param name="i2" type="float" value="$(var n)"/>
    <param name="b" type="bool" value="1"/>
    <param name="l" type="list_of_str" value="[a, '1']"/>
    <param name="l2" type="list_of_int" value="[1, 2]"/>
    <param name="y" type="yaml" value="[1, 2]"/>
    <param name="Reg/Strategy" type="str" value="1"/>
  </node>
</launch>"""

_TYPES_YAML = """launch:
- arg: {name: n, default: '8'}
- node:
    pkg: pkg
    exec: x
    name: typed
    param:
    - {name: m, type: str, value: '{a: 1, b: 2}'}
    - {name: i, type: int, value: 7}
    - {name: i2, type: int, value: $(var n)}
    - {name: b, type: bool, value: true}
    - {name: l, type: list_of_str, value: [a, '1']}
    - {name: y, type: yaml, value: '[1, 2]'}
    - {name: Reg/Strategy, value: '1'}
"""

_TYPES_PY = """from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node
from launch_ros.parameter_descriptions import ParameterValue


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('n', default_value='8'),
        Node(package='pkg', executable='x', name='typed', parameters=[{
            'm': '{a: 1, b: 2}',
            'i2': ParameterValue(LaunchConfiguration('n'), value_type=float),
            'y': ParameterValue('[1, 2]', value_type=str),
            'Reg/Strategy': '1',
            'e': '',
        }]),
    ])
"""

_EVENTS_PY = """from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, LogInfo, RegisterEventHandler, TimerAction
from launch.conditions import IfCondition
from launch.event_handlers import OnProcessStart, OnProcessExit, OnShutdown
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    first = Node(package='pkg', executable='x', name='first',
                 condition=IfCondition(LaunchConfiguration('go')))
    late = Node(package='pkg', executable='x', name='late')
    return LaunchDescription([
        DeclareLaunchArgument('go', default_value='true'),
        RegisterEventHandler(OnProcessStart(target_action=first, on_start=[
            Node(package='pkg', executable='x', name='after_first'),
            TimerAction(period=2.0, actions=[late]),
        ])),
        RegisterEventHandler(OnProcessStart(target_action=late, on_start=[
            Node(package='pkg', executable='x', name='after_late')])),
        RegisterEventHandler(OnProcessExit(target_action=first, on_exit=[
            Node(package='pkg', executable='x', name='on_exit')])),
        RegisterEventHandler(OnShutdown(on_shutdown=[LogInfo(msg='bye')])),
        first,
    ])
"""

CASES: dict[str, Case] = {
    "boolean-substitutions-and-equality-conditions": (
        {
            "main.launch.xml": _BOOLEAN_XML,
            "main.launch.yaml": _BOOLEAN_YAML,
            "main.launch.py": _BOOLEAN_PY,
        },
        [
            {},
            {"mode": "b", "on": "0", "gripper": "g"},
            {"mode": "1", "on": "yes"},
            {"mode": "A", "on": "Off", "gripper": "''"},
            {"on": "maybe"},
        ],
    ),
    "all-and-any-fail-in-xml-and-yaml": (
        {
            "main.launch.xml": """<launch>
            <node pkg="pkg" exec="x" name="a" if="$(all true 1)"/>
          </launch>""",
            "main.launch.yaml": """launch:
- node: {pkg: pkg, exec: x, name: a, if: $(any true 1)}
""",
        },
        [{}],
    ),
    "emit-event-shutdown": ({"main.launch.py": _EMIT_SHUTDOWN_PY}, [{}, {"stop": "true"}]),
    "parameter-types": (
        {
            "main.launch.xml": _TYPES_XML,
            "main.launch.yaml": _TYPES_YAML,
            "main.launch.py": _TYPES_PY,
        },
        [{}, {"n": "9"}, {"n": "x"}],
    ),
    "parameter-type-of-a-typed-frontends-literal": (
        {
            "main.launch.yaml": """launch:
- node:
    pkg: pkg
    exec: x
    param:
    - {name: i, type: int, value: '7'}
"""
        },
        [{}],
    ),
    "event-handlers": ({"main.launch.py": _EVENTS_PY}, [{}, {"go": "false"}]),
    "parameter-file-with-substitutions": (
        {
            "params.yaml": """/**:
  ros__parameters:
    rate: $(var rate)
    frame: $(var robot)_base
""",
            "main.launch.xml": """<launch>
  <arg name="rate" default="10"/>
  <arg name="robot" default="r1"/>
  <node pkg="pkg" exec="x" name="subst">
    <param from="$(dirname)/params.yaml" allow_substs="true"/>
  </node>
  <node pkg="pkg" exec="x" name="plain"><param from="$(dirname)/params.yaml"/></node>
</launch>""",
            "main.launch.py": """import os
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch_ros.actions import Node
from launch_ros.parameter_descriptions import ParameterFile


def generate_launch_description():
    path = os.path.join(os.path.dirname(__file__), 'params.yaml')
    return LaunchDescription([
        DeclareLaunchArgument('rate', default_value='10'),
        DeclareLaunchArgument('robot', default_value='r1'),
        Node(package='pkg', executable='x', name='subst',
             parameters=[ParameterFile(path, allow_substs=True)]),
    ])
""",
        },
        [{}, {"rate": "2.5", "robot": "r2"}],
    ),
}
