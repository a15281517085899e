"""ROS 2 fixtures, one per corner of the semantics: rosvar's resolution against the real
ros2/launch (the oracle), for sampled launch arguments. A fixture's entry is ``main.launch.xml``
and, where the construct exists there, the same launch as ``main.launch.yaml`` and
``main.launch.py``; each is compared."""

from __future__ import annotations

import itertools
from pathlib import Path

import pytest

from oracle.ros2_client import canonical_nodes, requires_ros2_oracle, resolution_nodes, run_oracle
from rosvar.interpreter.workspace_models import Analysis
from rosvar.workspace import discover

from .helpers_cases import CASES as HELPERS_CASES
from .names_cases import CASES as NAMES_CASES

pytestmark = requires_ros2_oracle

PACKAGE_XML = """<?xml version="1.0"?>
<package format="3">
  <name>pkg</name><version>0.0.0</version><description>d</description>
  <maintainer email="a@b.c">m</maintainer><license>BSD</license>
  <export><build_type>ament_cmake</build_type></export>
</package>
"""

Case = tuple[dict[str, str], list[dict[str, str]]]

CASES: dict[str, Case] = {
    "arg-default-and-given": (
        {
            "main.launch.xml": """<launch>
            <arg name="n" default="talker"/>
            <node pkg="pkg" exec="talker" name="$(var n)"/>
          </launch>"""
        },
        [{}, {"n": "other"}],
    ),
    "if-unless-truthiness": (
        {
            "main.launch.xml": """<launch>
            <arg name="on" default="true"/>
            <node pkg="pkg" exec="a" name="a" if="$(var on)"/>
            <node pkg="pkg" exec="b" name="b" unless="$(var on)"/>
          </launch>"""
        },
        [{}, {"on": "False"}, {"on": "1"}, {"on": "0"}],
    ),
    "include-args-leak-to-includer": (
        {
            "main.launch.xml": """<launch>
                <include file="$(dirname)/sub.launch.xml"><arg name="x" value="given"/></include>
                <node pkg="pkg" exec="a" name="$(var x)_$(var y)"/>
              </launch>""",
            "sub.launch.xml": """<launch>
                <arg name="x" default="dflt"/>
                <let name="y" value="leaked"/>
                <node pkg="pkg" exec="b" name="in_$(var x)"/>
              </launch>""",
        },
        [{}, {"x": "cli"}],
    ),
    "scoped-group-confines-let": (
        {
            "main.launch.xml": """<launch>
            <let name="v" value="outer"/>
            <group><let name="v" value="inner"/><node pkg="pkg" exec="a" name="$(var v)"/></group>
            <group scoped="false"><push-ros-namespace namespace="ns"/></group>
            <node pkg="pkg" exec="b" name="$(var v)"/>
          </launch>"""
        },
        [{}],
    ),
    "namespaces-pushed-and-absolute": (
        {
            "main.launch.xml": """<launch>
            <group>
              <push-ros-namespace namespace="robot"/>
              <push-ros-namespace namespace="arm"/>
              <node pkg="pkg" exec="a" name="a"/>
              <node pkg="pkg" exec="b" name="b" namespace="sub"/>
              <node pkg="pkg" exec="c" name="c" namespace="/abs"/>
            </group>
            <node pkg="pkg" exec="d" name="d"/>
          </launch>"""
        },
        [{}],
    ),
    "remaps-global-then-own": (
        {
            "main.launch.xml": """<launch>
            <group><set_remap from="z" to="w"/></group>
            <set_remap from="a" to="b"/>
            <group><set_remap from="c" to="d"/>
              <node pkg="pkg" exec="x" name="x"><remap from="e" to="f"/></node></group>
            <node pkg="pkg" exec="y" name="y"/>
          </launch>"""
        },
        [{}],
    ),
    "global-params-shared-list-through-groups": (
        {
            "main.launch.xml": """<launch>
            <group><set_parameter name="first" value="1"/></group>
            <node pkg="pkg" exec="x" name="x"/>
            <set_parameter name="a" value="1"/>
            <group><set_parameter name="b" value="2"/></group>
            <group forwarding="false"><node pkg="pkg" exec="z" name="z"/></group>
            <node pkg="pkg" exec="y" name="y"/>
          </launch>"""
        },
        [{}],
    ),
    "parameters-typed-files-nested-global": (
        {
            "main.launch.xml": """<launch>
                <arg name="rate" default="10"/>
                <set_parameter name="g" value="1.5"/>
                <node pkg="pkg" exec="x" name="x" namespace="r1">
                  <param from="$(find-pkg-share pkg)/params.yaml"/>
                  <param name="rate" value="$(var rate)"/>
                  <param name="flag" value="true"/>
                  <param name="text" value="hello"/>
                  <param name="group"><param name="inner" value="3"/></param>
                </node>
                <node pkg="pkg" exec="y" name="y"><param name="g" value="2"/></node>
              </launch>""",
            "params.yaml": """/**:
  ros__parameters: {common: 1, rate: 5}
/r1/x:
  ros__parameters: {only_x: [1, 2], nested: {a: b}}
/*/y:
  ros__parameters: {never: 0}
""",
        },
        [{}, {"rate": "20"}],
    ),
    "eval-and-substitution-quoting": (
        {
            "main.launch.xml": """<launch>
            <arg name="k" default="2"/>
            <node pkg="pkg" exec="x" name="n$(eval '$(var k) * 3')"
                  if="$(eval '\\'$(var k)\\' == \\'2\\'')"/>
            <node pkg="pkg" exec="y" name="y" args="--a 'b c' $(var k)"/>
          </launch>"""
        },
        [{}, {"k": "5"}],
    ),
    "errors-required-choices-truthiness": (
        {
            "main.launch.xml": """<launch>
            <arg name="need"/>
            <arg name="mode" default="a"><choice value="a"/><choice value="b"/></arg>
            <arg name="flag" default="true"/>
            <node pkg="pkg" exec="x" name="x_$(var need)_$(var mode)" if="$(var flag)"/>
          </launch>"""
        },
        [
            {},
            {"need": "1"},
            {"need": "1", "mode": "c"},
            {"need": "1", "flag": "yes"},
            {"need": "1", "mode": "b", "flag": "TRUE"},
        ],
    ),
    "unexpected-attribute-fails-even-where-never-entered": (
        {
            "main.launch.xml": """<launch>
            <arg name="on" default="false"/>
            <node pkg="pkg" exec="x" name="x"/>
            <group if="$(var on)"><node pkg="pkg" exec="y" name="y" bogus="1"/></group>
          </launch>"""
        },
        [{}, {"on": "true"}],
    ),
    "unknown-tag-fails": (
        {
            "main.launch.xml": """<launch>
            <node pkg="pkg" exec="x" name="x"/><frobnicate/>
          </launch>"""
        },
        [{}],
    ),
    "timers-run-in-the-final-context": (
        {
            "main.launch.xml": """<launch>
            <let name="x" value="before"/>
            <group>
              <push-ros-namespace namespace="g"/>
              <timer period="1.5"><node pkg="pkg" exec="a" name="a_$(var x)"/>
                <timer period="1"><node pkg="pkg" exec="c" name="c"/></timer></timer>
              <node pkg="pkg" exec="d" name="d"/>
            </group>
            <let name="x" value="after"/>
            <timer period="2"><node pkg="pkg" exec="b" name="b_$(var x)"/></timer>
          </launch>"""
        },
        [{}],
    ),
    "composable-nodes-in-and-loaded-into-containers": (
        {
            "main.launch.xml": """<launch>
            <set_remap from="g" to="h"/>
            <set_parameter name="gp" value="1"/>
            <push-ros-namespace namespace="ns"/>
            <node_container pkg="pkg" exec="component_container" name="box" namespace="">
              <composable_node pkg="pkg" plugin="pkg::A" name="a" namespace="sub">
                <param name="p" value="2"/><remap from="x" to="y"/>
              </composable_node>
            </node_container>
            <load_composable_node target="/ns/box">
              <composable_node pkg="pkg" plugin="pkg::B" name="b"/>
            </load_composable_node>
          </launch>"""
        },
        [{}],
    ),
    "parameter-value-typing": (
        {
            "main.launch.xml": """<launch>
            <node pkg="pkg" exec="x" name="x">
              <param name="a" value="[1, 2]"/><param name="b" value="1,2"/>
              <param name="c" value="yes"/><param name="d" value="1e3"/>
              <param name="e" value="0x10"/><param name="f" value="'7'"/>
              <param name="g" value="$(var g)"/><param name="h" value=""/>
              <param name="j" value="True"/>
            </node>
          </launch>"""
        },
        [{"g": "[a, b]"}, {"g": "[a, 1]"}, {"g": "[1, 2.5]"}, {"g": "~"}, {"g": "a: b"}],
    ),
    "parameter-file-named-by-an-unset-environment-variable": (
        {
            "main.launch.xml": """<launch>
            <node pkg="pkg" exec="a" name="a">
              <param from="$(dirname)/p_$(env JOY logitech).yaml"/>
            </node>
          </launch>""",
            "p_logitech.yaml": "/**:\n  ros__parameters:\n    x: 1\n",
        },
        [{}],
    ),
    "env-set-unset": (
        {
            "main.launch.xml": """<launch>
            <set_env name="R" value="set"/>
            <node pkg="pkg" exec="x" name="$(env R)_$(env NOPE fallback)"/>
            <unset_env name="R"/>
            <node pkg="pkg" exec="y" name="y_$(env R dflt)"/>
          </launch>"""
        },
        [{}],
    ),
    "find-exec-not-searched": (
        {
            "main.launch.xml": """<launch>
            <arg name="tool" default="rosvar_no_such_tool"/>
            <node pkg="pkg" exec="x" name="x" args="$(find-exec $(var tool)) --flag">
              <param name="description" value="$(command '$(find-exec xacro) robot.xacro')"/>
            </node>
          </launch>""",
            "main.launch.yaml": """launch:
- arg: {name: tool, default: rosvar_no_such_tool}
- node:
    pkg: pkg
    exec: x
    name: x
    args: $(find-exec $(var tool)) --flag
    param:
    - {name: description, value: "$(command '$(find-exec xacro) robot.xacro')"}
""",
            "main.launch.py": """from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import Command, FindExecutable, LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    tool = FindExecutable(name=LaunchConfiguration('tool'))
    description = Command([FindExecutable(name='xacro'), ' robot.xacro'])
    return LaunchDescription([
        DeclareLaunchArgument('tool', default_value='rosvar_no_such_tool'),
        Node(package='pkg', executable='x', name='x', arguments=[tool, '--flag'],
             parameters=[{'description': description}]),
    ])
""",
        },
        [{}, {"tool": "other_missing_tool"}],
    ),
    "command-lines-split-before-substitution": (
        {
            "main.launch.xml": """<launch>
            <arg name="v" default="a b"/>
            <executable cmd="ls -l $(var v) x$(var v)y 'c d'" name="lister"/>
            <node pkg="pkg" exec="n" name="n" args="--ros-args -r a:=b -- $(var v) plain"
                  ros_args="-p q:=1 -r __ns:=/other -r c:=d --log-level debug"/>
            <node pkg="pkg" exec="m" name="m"
                  ros_args="-r __node:=renamed --params-file $(dirname)/p.yaml"/>
          </launch>""",
            "main.launch.yaml": """launch:
- arg: {name: v, default: a b}
- executable: {cmd: "ls -l $(var v) x$(var v)y 'c d'", name: lister}
- node:
    {pkg: pkg, exec: n, name: n, args: "--ros-args -r a:=b -- $(var v) plain",
     ros_args: "-p q:=1 -r __ns:=/other -r c:=d --log-level debug"}
- node: {pkg: pkg, exec: m, name: m, ros_args: "-r __node:=renamed --params-file $(dirname)/p.yaml"}
""",
            "main.launch.py": """from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, ExecuteProcess
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution, ThisLaunchFileDir
from launch_ros.actions import Node


def generate_launch_description():
    v = LaunchConfiguration('v')
    return LaunchDescription([
        DeclareLaunchArgument('v', default_value='a b'),
        ExecuteProcess(cmd=['ls', '-l', v, ['x', v, 'y'], 'c d'], name='lister'),
        Node(package='pkg', executable='n', name='n',
             arguments=['--ros-args', '-r', 'a:=b', '--', v, 'plain'],
             ros_arguments=['-p', 'q:=1', '-r', '__ns:=/other', '-r', 'c:=d',
                            '--log-level', 'debug']),
        Node(package='pkg', executable='m', name='m',
             ros_arguments=['-r', '__node:=renamed', '--params-file',
                            PathJoinSubstitution([ThisLaunchFileDir(), 'p.yaml'])]),
    ])
""",
            "p.yaml": "/**:\n  ros__parameters: {k: 3}\n/renamed:\n  ros__parameters: {r: 1}\n",
        },
        [{}, {"v": "one"}],
    ),
    "lifecycle-node-python-only": (
        {
            "main.launch.py": """from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.conditions import IfCondition
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import LifecycleNode


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('on', default_value='true'),
        LifecycleNode(package='pkg', executable='lc', name='lc', namespace='ns',
                      parameters=[{'rate': 5}], remappings=[('a', 'b')],
                      condition=IfCondition(LaunchConfiguration('on'))),
    ])
""",
            "main.launch.xml": """<launch>
            <lifecycle_node pkg="pkg" exec="lc" name="lc" namespace="ns"/>
          </launch>""",
        },
        [{}, {"on": "false"}],
    ),
    "undeclared-arguments-reach-included-files": (
        {
            "main.launch.xml": """<launch>
                <node pkg="pkg" exec="p" name="pre_$(var mode early)"/>
                <include file="$(dirname)/sub.launch.xml"/>
                <node pkg="pkg" exec="a" name="a_$(var mode)"/>
              </launch>""",
            "sub.launch.xml": """<launch>
                <arg name="mode" default="sim"/>
                <arg name="on" default="true"/>
                <group if="$(var on)"><arg name="robot" default="r1"/></group>
                <node pkg="pkg" exec="b" name="b_$(var robot r0)" if="$(var on)"/>
              </launch>""",
            "main.launch.yaml": """launch:
- node: {pkg: pkg, exec: p, name: pre_$(var mode early)}
- include: {file: $(dirname)/sub.launch.yaml}
- node: {pkg: pkg, exec: a, name: a_$(var mode)}
""",
            "sub.launch.yaml": """launch:
- arg: {name: mode, default: sim}
- arg: {name: "on", default: "true"}
- group:
    if: $(var on)
    children:
    - arg: {name: robot, default: r1}
- node: {pkg: pkg, exec: b, name: b_$(var robot r0), if: $(var on)}
""",
        },
        [{}, {"mode": "real"}, {"robot": "r2", "on": "false"}, {"robot": "r2"}],
    ),
    "reset-env-ros-timer-and-shutdown": (
        {
            "main.launch.xml": """<launch>
            <arg name="stop" default="false"/>
            <set_env name="R" value="set"/>
            <node pkg="pkg" exec="x" name="x_$(env R dflt)"/>
            <group>
              <set_env name="S" value="in"/>
              <reset_env/>
              <node pkg="pkg" exec="g" name="g_$(env R dflt)_$(env S none)"/>
            </group>
            <node pkg="pkg" exec="a" name="a_$(env R dflt)_$(env S none)"/>
            <set_env name="S" value="late" if="$(var stop)"/>
            <reset_env if="$(var stop)"/>
            <node pkg="pkg" exec="y" name="y_$(env R dflt)_$(env S none)"/>
            <ros_timer period="1.0"><node pkg="pkg" exec="t" name="t_$(env R dflt)"/></ros_timer>
            <timer period="0.5" cancel_on_shutdown="false">
              <node pkg="pkg" exec="u" name="u"/></timer>
            <shutdown reason="stopped by $(var stop)" if="$(var stop)"/>
            <node pkg="pkg" exec="z" name="z"/>
          </launch>""",
            "main.launch.py": """from launch import LaunchDescription
from launch.actions import (DeclareLaunchArgument, GroupAction, ResetEnvironment,
                            SetEnvironmentVariable, Shutdown, TimerAction)
from launch.conditions import IfCondition
from launch.substitutions import EnvironmentVariable as Env, LaunchConfiguration
from launch_ros.actions import Node, RosTimer


def generate_launch_description():
    stop = IfCondition(LaunchConfiguration('stop'))
    return LaunchDescription([
        DeclareLaunchArgument('stop', default_value='false'),
        SetEnvironmentVariable('R', 'set'),
        Node(package='pkg', executable='x', name=['x_', Env('R', default_value='dflt')]),
        GroupAction([
            SetEnvironmentVariable('S', 'in'),
            ResetEnvironment(),
            Node(package='pkg', executable='g', name=[
                'g_', Env('R', default_value='dflt'), '_', Env('S', default_value='none')]),
        ]),
        Node(package='pkg', executable='a', name=[
            'a_', Env('R', default_value='dflt'), '_', Env('S', default_value='none')]),
        SetEnvironmentVariable('S', 'late', condition=stop),
        ResetEnvironment(condition=stop),
        Node(package='pkg', executable='y', name=[
            'y_', Env('R', default_value='dflt'), '_', Env('S', default_value='none')]),
        RosTimer(period=1.0, actions=[
            Node(package='pkg', executable='t', name=['t_', Env('R', default_value='dflt')])]),
        TimerAction(period=0.5, actions=[Node(package='pkg', executable='u', name='u')],
                    cancel_on_shutdown=False),
        Shutdown(reason=['stopped by ', LaunchConfiguration('stop')], condition=stop),
        Node(package='pkg', executable='z', name='z'),
    ])
""",
        },
        [{}, {"stop": "true"}],
    ),
    "opaque-function-read-where-it-stands": (
        {
            "main.launch.py": """from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, OpaqueFunction, SetLaunchConfiguration
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def setup(context, prefix, suffix=''):
    robot = LaunchConfiguration('robot').perform(context)
    mode = context.launch_configurations.get('mode', 'sim')
    return [
        SetLaunchConfiguration('inner', 'set_by_opaque'),
        Node(package='pkg', executable='a', name=prefix + robot + suffix,
             parameters=[{'mode': mode, 'ns': context.launch_configurations['robot'] + '_ns'}]),
        Node(package='pkg', executable='b',
             name=context.perform_substitution(LaunchConfiguration('robot')) + '_b'),
    ]


def nothing(context):
    return None


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('robot', default_value='r1'),
        DeclareLaunchArgument('mode', default_value='real'),
        OpaqueFunction(function=setup, args=['p_'], kwargs={'suffix': '_s'}),
        OpaqueFunction(function=nothing),
        Node(package='pkg', executable='c',
             name=[LaunchConfiguration('inner', default='unset'), '_c']),
    ])
""",
        },
        [{}, {"robot": "r2"}, {"mode": "sim", "robot": "r3"}],
    ),
    "python-launch-time-values": (
        {
            "main.launch.py": """from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, OpaqueFunction
from launch.conditions import IfCondition
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def setup(context):
    imu = LaunchConfiguration('imu_topic').perform(context) != ''
    voxel = LaunchConfiguration('voxel')
    size = float(voxel.perform(context)) * 10.0
    sim = context.launch_configurations['sim']
    flag = sim.lower() in ('true', '1')
    nodes = []
    if imu:
        nodes.append(Node(package='pkg', executable='imu', name='imu',
                          parameters=[{'size': size, 'count': int(size) + 1}]))
    if not flag and imu:
        nodes.append(Node(package='pkg', executable='real', name='real'))
    else:
        nodes.append(Node(package='pkg', executable='other', name='other_' + sim.upper()))
    speed = 'fast' if size > 1.0 else 'slow'
    extra = Node(package='pkg', executable='x', name='extra')
    if sim:  # a non-empty string is true, 'false' too
        nodes.append(extra)
    label = 'on' if flag else 'off'
    if len(sim) > 3 and sim[0] != 'f':
        label = label + '_long'
    if IfCondition(LaunchConfiguration('flag')).evaluate(context):
        nodes.append(Node(package='pkg', executable='f', name='flagged'))
    extra = {} if sim == 'true' else {'mode': 'm_' + sim, 'scale': size}
    nodes.append(Node(package='pkg', executable='s', name=speed + '_' + label,
                      parameters=[{'fixed': 1}, extra]))
    return nodes


def pick(context):
    if LaunchConfiguration('sim').perform(context) == 'true':
        return [Node(package='pkg', executable='a', name='sim_node')]
    name = f"real_{context.perform_substitution(LaunchConfiguration('voxel')).split('.')[0]}"
    return [Node(package='pkg', executable='b', name=name)]


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('imu_topic', default_value='imu'),
        DeclareLaunchArgument('voxel', default_value='0.05'),
        DeclareLaunchArgument('sim', default_value='false'),
        DeclareLaunchArgument('flag', default_value='true'),
        OpaqueFunction(function=setup),
        OpaqueFunction(function=pick),
    ])
""",
        },
        [
            {},
            {"imu_topic": ""},
            {"voxel": "1e3", "sim": "true"},
            {"sim": "1", "imu_topic": ""},
            {"sim": "", "voxel": "7", "flag": " False"},
            {"imu_topic": "it's \\ ''"},
        ],
    ),
    "python-values-changed-under-launch-time-ifs": (
        {
            "main.launch.py": """from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, OpaqueFunction
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


class Options:
    def __init__(self):
        self.mode = 'plain'


def spawner(controllers, active=True):
    flags = ['--inactive'] if not active else []
    return Node(package='pkg', executable='spawner', name='spawn_' + ('a' if active else 'i'),
                arguments=['--cm', '/cm'] + flags + controllers)


def setup(context):
    chosen = LaunchConfiguration('chosen').perform(context)
    active = ['state', 'io']
    inactive = ['scaled', 'plain', 'fwd']
    if LaunchConfiguration('activate').perform(context) == 'true':
        active.append(chosen)
        inactive.remove(chosen)
    if LaunchConfiguration('mock').perform(context) == 'true':
        active.remove('io')
    params = {'rate': 10}
    remaps = [('in', 'raw')]
    options = Options()
    if LaunchConfiguration('fast').perform(context) == 'true':
        params['rate'] = 100
        params.update({'burst': True})
        remaps += [('out', 'fast_out')]
        options.mode = 'fast'
    else:
        params.setdefault('slow', 1)
        del params['rate']
    names = ['n1']
    names.append('n2') if chosen == 'plain' else names.extend(['n3', 'n4'])
    nodes = [
        spawner(active),
        spawner(inactive, active=False),
        Node(package='pkg', executable='tuned', name='tuned_' + options.mode,
             parameters=[params, {'active': active}], remappings=remaps,
             arguments=[' '.join(active), str(len(inactive))]),
    ]
    for name in names:
        nodes.append(Node(package='pkg', executable='n', name=name))
    return nodes


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('chosen', default_value='scaled'),
        DeclareLaunchArgument('activate', default_value='true'),
        DeclareLaunchArgument('mock', default_value='false'),
        DeclareLaunchArgument('fast', default_value='false'),
        OpaqueFunction(function=setup),
    ])
""",
        },
        [
            {},
            {"activate": "false"},
            {"chosen": "plain"},
            {"chosen": "fwd", "mock": "true"},
            {"fast": "true"},
            {"chosen": "plain", "fast": "true", "activate": "false", "mock": "true"},
            {"chosen": "other"},
            {"chosen": "other", "activate": "false"},
        ],
    ),
    "python-loops-over-launch-time-lists": (
        {
            "main.launch.py": """import yaml
from itertools import chain

from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, GroupAction, OpaqueFunction
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node, PushRosNamespace


def per_camera(namespace):
    return [GroupAction([PushRosNamespace(namespace),
                         Node(package='pkg', executable='detect', name='detector')]),
            Node(package='pkg', executable='relay', name='relay_' + namespace)]


def setup(context):
    cameras = yaml.load(LaunchConfiguration('cameras').perform(context),
                        Loader=yaml.FullLoader)
    nodes = list(chain(*[per_camera(camera) for camera in cameras]))
    for index, topic in enumerate(['a', 'b']):
        nodes.append(Node(package='pkg', executable='t', name=f'fixed_{index}_{topic}'))
    for word in LaunchConfiguration('words').perform(context).split(','):
        nodes.append(Node(package='pkg', executable='w', name='word_' + word.strip()))
    return nodes


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('cameras', default_value='[camera6, camera7]'),
        DeclareLaunchArgument('words', default_value='x'),
        OpaqueFunction(function=setup),
    ])
""",
        },
        [
            {},
            {"cameras": "[]"},
            {"cameras": "['c1']", "words": "p, q,r"},
            {"cameras": "[a, b, c, d, e, f, g, h]", "words": "only"},
        ],
    ),
    "python-workspace-modules": (
        {
            "pkg_helpers/__init__.py": "",
            "pkg_helpers/launch.py": """from launch.action import Action
from launch.substitution import Substitution
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node

PREFIX = 'helper_'


class LaunchConfigAsBool(Substitution):
    def __init__(self, name):
        super().__init__()
        self.name = name

    def perform(self, context):
        value = LaunchConfiguration(self.name).perform(context)
        return str(value.lower() in ('true', '1', 'yes'))


class NodeBuilder:
    def __init__(self, package):
        self.package = package
        self.nodes = []
        self.count = 0

    def add(self, executable):
        self.count += 1
        name = PREFIX + executable + str(self.count)
        self.nodes.append(Node(package=self.package, executable=executable, name=name))
        return self

    def build(self):
        return self.nodes


class Base:
    label = 'base'

    def __init__(self, name):
        self.name = name

    def full(self):
        return self.label + '_' + self.name


class Derived(Base):
    label = 'derived'

    def __init__(self, name):
        super().__init__(name + '_x')

    def full(self):
        return super().full() + '_d'


class Extra(Action):
    def __init__(self, name, **kwargs):
        super().__init__(**kwargs)
        self.name = name

    def execute(self, context):
        return [Node(package='pkg', executable='e', name=self.name)]


def setup(context, suffix):
    robot = LaunchConfiguration('robot').perform(context)
    return [Node(package='pkg', executable='o', name=robot + suffix)]
""",
            "main.launch.py": """from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, OpaqueFunction
from launch.conditions import IfCondition
from launch_ros.actions import Node
from pkg_helpers.launch import Derived, Extra, LaunchConfigAsBool, NodeBuilder
import pkg_helpers.launch as helpers


def generate_launch_description():
    ld = LaunchDescription([
        DeclareLaunchArgument('use_x', default_value='yes'),
        DeclareLaunchArgument('robot', default_value='r1'),
        Node(package='pkg', executable='x', name='x',
             condition=IfCondition(LaunchConfigAsBool('use_x'))),
        Node(package='pkg', executable='d', name=Derived('n').full()),
        OpaqueFunction(function=helpers.setup, args=['_s']),
        Extra('extra'),
    ])
    for node in NodeBuilder('pkg').add('a').add('b').build():
        ld.add_action(node)
    return ld
""",
        },
        [{}, {"use_x": "no", "robot": "r2"}, {"use_x": "TRUE"}],
    ),
    "python-reads-yaml-of-the-workspace": (
        {
            "config/params.yaml": """name: from_yaml
node:
  ros__parameters:
    rate: 10
    label: abc
    gain: 2.5
list: [1, 2, 3]
""",
            "config/star.yaml": """/**:
  ros__parameters:
    speed: 3.5
    mode: fast
""",
            "main.launch.py": """import os

import yaml
from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, OpaqueFunction
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare


def setup(context):
    with open(LaunchConfiguration('param_file').perform(context), 'r') as f:
        named = yaml.safe_load(f)['/**']['ros__parameters']
    return [Node(package='pkg', executable='b', name='b', parameters=[named])]


def generate_launch_description():
    path = os.path.join(get_package_share_directory('pkg'), 'config', 'params.yaml')
    with open(path, 'r') as f:
        params = yaml.load(f, Loader=yaml.SafeLoader)
    beside = os.path.join(os.path.dirname(__file__), 'config', 'params.yaml')
    other = yaml.safe_load(open(beside).read())
    node_params = params['node']['ros__parameters']
    node_params['extra'] = LaunchConfiguration('extra')
    return LaunchDescription([
        DeclareLaunchArgument('extra', default_value='e'),
        DeclareLaunchArgument('param_file', default_value=PathJoinSubstitution(
            [FindPackageShare('pkg'), 'config', 'star.yaml'])),
        Node(package='pkg', executable='a', name=params['name'],
             parameters=[node_params, {'k': other['list'][1] * 2}]),
        OpaqueFunction(function=setup),
    ])
""",
        },
        [{}, {"extra": "f"}],
    ),
    "append-env-after-before-or-alone": (
        {
            "main.launch.xml": """<launch>
            <arg name="sep" default="+"/>
            <set_env name="P" value="base"/>
            <append_env name="P" value="end"/>
            <append_env name="P" value="start" prepend="true"/>
            <append_env name="Q" value="only" separator=";"/>
            <append_env name="P" value="x" separator="$(var sep)"/>
            <node pkg="pkg" exec="a" name="a" args="$(env P) $(env Q)"/>
          </launch>""",
            "main.launch.yaml": """launch:
- arg: {name: sep, default: +}
- set_env: {name: P, value: base}
- append_env: {name: P, value: end}
- append_env: {name: P, value: start, prepend: true}
- append_env: {name: Q, value: only, separator: ;}
- append_env: {name: P, value: x, separator: $(var sep)}
- node: {pkg: pkg, exec: a, name: a, args: $(env P) $(env Q)}
""",
            "main.launch.py": """from launch import LaunchDescription
from launch.actions import (AppendEnvironmentVariable, DeclareLaunchArgument,
                            SetEnvironmentVariable)
from launch.substitutions import EnvironmentVariable, LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('sep', default_value='+'),
        SetEnvironmentVariable('P', 'base'),
        AppendEnvironmentVariable('P', 'end'),
        AppendEnvironmentVariable('P', 'start', prepend=True),
        AppendEnvironmentVariable('Q', 'only', separator=';'),
        AppendEnvironmentVariable('P', 'x', separator=LaunchConfiguration('sep')),
        Node(package='pkg', executable='a', name='a',
             arguments=[EnvironmentVariable('P'), EnvironmentVariable('Q')]),
    ])
""",
        },
        [{}, {"sep": "-"}],
    ),
    "reset-forgets-configurations-namespace-remaps-parameters": (
        {
            "main.launch.xml": """<launch>
            <arg name="a" default="1"/>
            <arg name="r" default="false"/>
            <let name="b" value="2"/>
            <push-ros-namespace namespace="ns"/>
            <set_remap from="x" to="y"/>
            <set_parameter name="g" value="1"/>
            <node pkg="pkg" exec="n1" name="before_$(var a)_$(var b)"/>
            <group>
              <reset><keep name="c" value="$(var a)"/></reset>
              <node pkg="pkg" exec="n2" name="in_$(var c)_$(var b nob)"/>
            </group>
            <node pkg="pkg" exec="n3" name="after_$(var a)"/>
            <reset if="$(var r)"/>
            <node pkg="pkg" exec="n4" name="last_$(var a none)"/>
          </launch>""",
            "main.launch.yaml": """launch:
- arg: {name: a, default: "1"}
- arg: {name: r, default: "false"}
- let: {name: b, value: "2"}
- push-ros-namespace: {namespace: ns}
- set_remap: {from: x, to: y}
- set_parameter: {name: g, value: "1"}
- node: {pkg: pkg, exec: n1, name: before_$(var a)_$(var b)}
- group:
  - reset: {keep: [{name: c, value: $(var a)}]}
  - node: {pkg: pkg, exec: n2, name: in_$(var c)_$(var b nob)}
- node: {pkg: pkg, exec: n3, name: after_$(var a)}
- reset: {if: $(var r)}
- node: {pkg: pkg, exec: n4, name: last_$(var a none)}
""",
            "main.launch.py": """from launch import LaunchDescription
from launch.actions import (DeclareLaunchArgument, GroupAction, ResetLaunchConfigurations,
                            SetLaunchConfiguration)
from launch.conditions import IfCondition
from launch.substitutions import LaunchConfiguration as V
from launch_ros.actions import Node, PushRosNamespace, SetParameter, SetRemap


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('a', default_value='1'),
        DeclareLaunchArgument('r', default_value='false'),
        SetLaunchConfiguration('b', '2'),
        PushRosNamespace('ns'),
        SetRemap(src='x', dst='y'),
        SetParameter(name='g', value='1'),
        Node(package='pkg', executable='n1', name=['before_', V('a'), '_', V('b')]),
        GroupAction([
            ResetLaunchConfigurations(launch_configurations={'c': V('a')}),
            Node(package='pkg', executable='n2', name=['in_', V('c'), '_', V('b', default='nob')]),
        ]),
        Node(package='pkg', executable='n3', name=['after_', V('a')]),
        ResetLaunchConfigurations(condition=IfCondition(V('r'))),
        Node(package='pkg', executable='n4', name=['last_', V('a', default='none')]),
    ])
""",
        },
        [{}, {"r": "true"}, {"a": "5", "r": "true"}],
    ),
    "set-parameters-from-file-global-and-missing-files": (
        {
            "main.launch.xml": """<launch>
            <arg name="m" default="x"/>
            <arg name="f" default="g"/>
            <arg name="use" default="false"/>
            <group>
              <set_parameters_from_file filename="$(dirname)/g.yaml"/>
              <node pkg="pkg" exec="a" name="a">
                <param name="own" value="1"/><param from="$(dirname)/missing_$(var m).yaml"/>
              </node>
            </group>
            <node pkg="pkg" exec="b" name="b"/>
            <set_parameters_from_file filename="$(dirname)/$(var f).yaml" if="$(var use)"/>
            <node pkg="pkg" exec="c" name="c"/>
          </launch>""",
            "main.launch.yaml": """launch:
- arg: {name: m, default: x}
- arg: {name: f, default: g}
- arg: {name: use, default: "false"}
- group:
  - set_parameters_from_file: {filename: $(dirname)/g.yaml}
  - node:
      pkg: pkg
      exec: a
      name: a
      param: [{name: own, value: 1}, {from: $(dirname)/missing_$(var m).yaml}]
- node: {pkg: pkg, exec: b, name: b}
- set_parameters_from_file: {filename: $(dirname)/$(var f).yaml, if: $(var use)}
- node: {pkg: pkg, exec: c, name: c}
""",
            "main.launch.py": """from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, GroupAction
from launch.conditions import IfCondition
from launch.substitutions import LaunchConfiguration as V, ThisLaunchFileDir
from launch_ros.actions import Node, SetParametersFromFile


def generate_launch_description():
    here = ThisLaunchFileDir()
    return LaunchDescription([
        DeclareLaunchArgument('m', default_value='x'),
        DeclareLaunchArgument('f', default_value='g'),
        DeclareLaunchArgument('use', default_value='false'),
        GroupAction([
            SetParametersFromFile([here, '/g.yaml']),
            Node(package='pkg', executable='a', name='a',
                 parameters=[{'own': 1}, [here, '/missing_', V('m'), '.yaml']]),
        ]),
        Node(package='pkg', executable='b', name='b'),
        SetParametersFromFile([here, '/', V('f'), '.yaml'], condition=IfCondition(V('use'))),
        Node(package='pkg', executable='c', name='c'),
    ])
""",
            "g.yaml": "/**:\n  ros__parameters: {shared: 1, own: 0}\n"
            "/a:\n  ros__parameters: {only_a: true}\n",
        },
        [{}, {"use": "true"}, {"use": "true", "f": "nope"}],
    ),
    "python-path-join-of-values": (
        {
            "main.launch.py": """from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration as V, PathJoinSubstitution
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('dir', default_value='/etc/robot/'),
        DeclareLaunchArgument('ns', default_value=''),
        Node(package='pkg', executable='a', name='a',
             parameters=[{'p': PathJoinSubstitution([V('dir'), 'x.yaml'])}],
             remappings=[('a', PathJoinSubstitution(['/', V('ns'), 'b']))]),
    ])
""",
        },
        [{}, {"dir": "/opt", "ns": "r1"}, {"ns": "/abs"}],
    ),
    "package-executables-and-file-contents": (
        {
            "main.launch.xml": """<launch>
            <arg name="exe" default="talker"/>
            <arg name="file" default="robot.urdf"/>
            <executable cmd="$(exec-in-pkg $(var exe) pkg) --depth 1" name="monitor"/>
            <node pkg="pkg" exec="x" name="x">
              <param name="robot_description"
                     value="$(file-content $(find-pkg-share pkg)/$(var file))"/>
            </node>
          </launch>""",
            "main.launch.yaml": """launch:
- arg: {name: exe, default: talker}
- arg: {name: file, default: robot.urdf}
- executable: {cmd: "$(exec-in-pkg $(var exe) pkg) --depth 1", name: monitor}
- node:
    pkg: pkg
    exec: x
    name: x
    param:
    - {name: robot_description, value: "$(file-content $(find-pkg-share pkg)/$(var file))"}
""",
            "main.launch.py": """from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, ExecuteProcess
from launch.substitutions import FileContent, LaunchConfiguration as V, PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import ExecutableInPackage, FindPackageShare


def generate_launch_description():
    urdf = FileContent(PathJoinSubstitution([FindPackageShare('pkg'), V('file')]))
    return LaunchDescription([
        DeclareLaunchArgument('exe', default_value='talker'),
        DeclareLaunchArgument('file', default_value='robot.urdf'),
        ExecuteProcess(cmd=[ExecutableInPackage(V('exe'), 'pkg'), '--depth', '1'],
                       name='monitor'),
        Node(package='pkg', executable='x', name='x',
             parameters=[{'robot_description': urdf}]),
    ])
""",
            "robot.urdf": '<robot name="r">\n  <link name="base"/>\n</robot>\n',
            "other.urdf": "<robot name='o'/>",
        },
        [{}, {"exe": "listener", "file": "other.urdf"}],
    ),
    "list-parameters": (
        {
            "main.launch.xml": """<launch>
            <arg name="first" default="a"/>
            <node pkg="pkg" exec="x" name="x">
              <param name="rate" value="1"/>
              <param name="names" value="[$(var first), b]"/>
              <param name="numbers" value="[1, 2]"/>
              <param name="group.flags" value="[true, false]"/>
              <param name="rate" value="2"/>
            </node>
          </launch>""",
            "main.launch.py": """from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration as V
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('first', default_value='a'),
        Node(package='pkg', executable='x', name='x',
             parameters=[{'rate': 1}, {'names': [V('first'), 'b'], 'numbers': [1, 2]},
                         {'group': {'flags': [True, False]}}, {'rate': 2}]),
    ])
""",
        },
        [{}, {"first": "c"}],
    ),
    "undeclared-argument-declared-by-each-include": (
        {
            "main.launch.xml": """<launch>
            <arg name="roi" default="true"/>
            <let name="input" value="roi" if="$(var roi)"/>
            <let name="input" value="plain" unless="$(var roi)"/>
            <group><include file="$(dirname)/sub.launch.xml"/></group>
            <group>
              <push-ros-namespace namespace="fusion"/>
              <include file="$(dirname)/sub.launch.xml">
                <arg name="in" value="$(var input)"/>
              </include>
            </group>
          </launch>""",
            "sub.launch.xml": """<launch>
            <arg name="in" default="x"/>
            <arg name="model_path" default="$(dirname)/m.onnx"/>
            <node pkg="pkg" exec="x" name="n">
              <param name="model_path" value="$(var model_path)"/>
              <param name="in" value="$(var in)"/>
            </node>
          </launch>""",
        },
        [{}, {"model_path": "given"}, {"model_path": "given", "roi": "false"}],
    ),
    "actions-that-start-nothing": (
        {
            "main.launch.xml": """<launch>
            <arg name="a" default="1"/>
            <log message="a is $(var a)"/>
            <set_ros_log_dir new_log_dir="/tmp/rosvar-log"/>
            <node pkg="pkg" exec="x" name="x_$(var a)"/>
          </launch>""",
            "main.launch.py": """from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, LogInfo
from launch.substitutions import LaunchConfiguration as V
from launch_ros.actions import Node, SetROSLogDir


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('a', default_value='1'),
        LogInfo(msg=['a is ', V('a')]),
        SetROSLogDir(new_log_dir='/tmp/rosvar-log'),
        Node(package='pkg', executable='x', name=['x_', V('a')]),
    ])
""",
        },
        [{}, {"a": "2"}],
    ),
    "values-over-the-work-limits-once-bound": (
        {
            "params.yaml": "/**:\n  ros__parameters:\n    first: $(var a0)\n    joined: "
            + "".join(f"$(var a{i})" for i in range(14))
            + "\n",
            "main.launch.xml": "<launch>"
            + "".join(f'<arg name="a{i}" default="x"/>' for i in range(14))
            + '<node pkg="pkg" exec="x" name="n{}" args="{}">'.format(
                "".join(f"$(var a{i})" for i in range(14)),
                " ".join(f"$(var a{i})" for i in range(14)),
            )
            + '<param from="$(dirname)/params.yaml" allow_substs="true"/></node></launch>',
            "main.launch.py": """import os
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration as V
from launch_ros.actions import Node
from launch_ros.parameter_descriptions import ParameterFile


def generate_launch_description():
    path = os.path.join(os.path.dirname(__file__), 'params.yaml')
    names = [f'a{i}' for i in range(14)]
    return LaunchDescription([DeclareLaunchArgument(n, default_value='x') for n in names] + [
        Node(package='pkg', executable='x', name=['n'] + [V(n) for n in names],
             parameters=[ParameterFile(path, allow_substs=True)]),
    ])
""",
        },
        [{}, {"a1": "y", "a13": "z"}, {"a0": "7"}],
    ),
    "conditions-over-the-work-limits-once-bound": (  # 2^13 combinations in one $(eval)
        {
            "main.launch.xml": "<launch>"
            + "".join(
                f'<arg name="a{i}" default="a"><choice value="a"/><choice value="b"/></arg>'
                for i in range(13)
            )
            + "<group if=\"$(eval &quot;'{}' == '{}'&quot;)\">".format(
                "".join(f"$(var a{i})" for i in range(13)), "a" * 13
            )
            + '<node pkg="pkg" exec="x" name="all_a"/></group>'
            + '<node pkg="pkg" exec="x" name="some_b" unless="$(eval &quot;\'{}\' == \'{}\''
            '&quot;)"/>'.format("".join(f"$(var a{i})" for i in range(13)), "a" * 13)
            + "</launch>",
            "main.launch.py": """from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, GroupAction
from launch.conditions import IfCondition, UnlessCondition
from launch.substitutions import LaunchConfiguration as V, PythonExpression
from launch_ros.actions import Node


def generate_launch_description():
    names = [f'a{i}' for i in range(13)]
    test = PythonExpression(["'"] + [V(n) for n in names] + ["' == '" + 'a' * 13 + "'"])
    return LaunchDescription([
        DeclareLaunchArgument(n, default_value='a', choices=['a', 'b']) for n in names
    ] + [
        GroupAction([Node(package='pkg', executable='x', name='all_a')],
                    condition=IfCondition(test)),
        Node(package='pkg', executable='x', name='some_b', condition=UnlessCondition(test)),
    ])
""",
        },
        [{}, {"a3": "b"}, {"a0": "b", "a12": "b"}],
    ),
    "python-path-join-of-choices": (
        {
            "main.launch.py": """from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration as V, PathJoinSubstitution
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('a', default_value='x', choices=['x', '/y', 'z/']),
        DeclareLaunchArgument('b', default_value='p', choices=['p', '/q', 'r']),
        Node(package='pkg', executable='n', name='n',
             parameters=[{'path': PathJoinSubstitution([V('a'), V('b'), 'f.yaml'])}]),
    ])
""",
        },
        [{}, {"a": "/y", "b": "r"}, {"a": "z/", "b": "/q"}],
    ),
    "command-line-words-with-spaces": (  # each word one argument, even given up
        {
            "main.launch.xml": """<launch>
<arg name="a" default="x y"><choice value="x y"/><choice value="p"/><choice value="q"/></arg>
<arg name="b" default="1"><choice value="1"/><choice value="2 3"/><choice value="4"/></arg>
<node pkg="pkg" exec="n" name="n" args="--f $(var a)$(var b) tail"/>
<executable cmd="echo $(var a)$(var b) z" name="e"/>
</launch>""",
            "main.launch.py": """from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, ExecuteProcess
from launch.substitutions import LaunchConfiguration as V
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('a', default_value='x y', choices=['x y', 'p', 'q']),
        DeclareLaunchArgument('b', default_value='1', choices=['1', '2 3', '4']),
        Node(package='pkg', executable='n', name='n',
             arguments=['--f', [V('a'), V('b')], 'tail', [V('b'), ' end']]),
        ExecuteProcess(cmd=['echo', [V('a'), V('b')], 'z'], name='e'),
    ])
""",
        },
        [{}, {"a": "p", "b": "2 3"}, {"a": "q", "b": "4"}],
    ),
    "path-joins-of-joined-values": (  # a value given up may be absolute, end in '/'
        {
            "main.launch.py": """import os

from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, OpaqueFunction
from launch.substitutions import LaunchConfiguration as V, PathJoinSubstitution, PythonExpression
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare


def setup(context):
    ab = context.launch_configurations['a'] + context.launch_configurations['b']
    return [Node(package='pkg', executable='m', name='m',
                 parameters=[{'o': os.path.join(get_package_share_directory('pkg'), 'c', ab)}])]


def generate_launch_description():
    ab = PythonExpression(["'", V('a'), "' + '", V('b'), "'"])
    return LaunchDescription([
        DeclareLaunchArgument('a', default_value='/y', choices=['/y', 'x', 'z/']),
        DeclareLaunchArgument('b', default_value='p', choices=['p', 'q/', 'r']),
        Node(package='pkg', executable='n', name='n',
             parameters=[{'j': PathJoinSubstitution(['base', ab, 'f.yaml']),
                          'k': PathJoinSubstitution([FindPackageShare('pkg'), ab]),
                          'l': PathJoinSubstitution([ab, '/abs', 'g'])}]),
        OpaqueFunction(function=setup),
    ])
""",
        },
        [{}, {"a": "x", "b": "q/"}, {"a": "z/", "b": "r"}],
    ),
    "workspace-substitutions-of-joined-values": (  # packages and files named by a value
        {
            "main.launch.xml": """<launch>
<arg name="a" default="f"><choice value="f"/><choice value="g"/><choice value="h"/></arg>
<arg name="b" default="1"><choice value="1"/><choice value="2"/><choice value="3"/></arg>
<node pkg="pkg" exec="n" name="n" args="$(exec-in-pkg $(var a)$(var b) pkg)">
  <param name="c" value="$(file-content $(dirname)/$(var a)$(var b).txt)"/>
  <param name="s" value="$(find-pkg-share $(var a)$(var b))"/>
  <param name="p" value="$(find-pkg-prefix $(var a)$(var b))"/>
</node>
</launch>""",
            **{f"{name}.txt": f"content of {name}" for name in ("f1", "g3")},
            **{
                f"../{name}/package.xml": PACKAGE_XML.replace("<name>pkg", f"<name>{name}")
                for name in ("f1", "g3")
            },
        },
        [{}, {"a": "g", "b": "3"}, {"a": "h", "b": "2"}],
    ),
    "namespaces-pushed-from-values": (  # also values no file names (configure's typed ones)
        {
            "main.launch.xml": """<launch>
<arg name="ns" default="a"/>
<group><push-ros-namespace namespace="outer"/>
  <group><push-ros-namespace namespace="$(var ns)"/><node pkg="pkg" exec="n" name="n"/></group>
</group>
</launch>""",
            "main.launch.py": """from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, GroupAction, OpaqueFunction
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node, PushROSNamespace


def setup(context):
    actions = []
    for ns in LaunchConfiguration('names').perform(context).split(','):
        actions.append(GroupAction([
            PushROSNamespace(ns),
            Node(package='pkg', executable='n', name='n'),
        ]))
    return actions


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('ns', default_value='a'),
        DeclareLaunchArgument('names', default_value='a,b'),
        GroupAction([PushROSNamespace('outer'), OpaqueFunction(function=setup)]),
        GroupAction([PushROSNamespace(LaunchConfiguration('ns')),
                     Node(package='pkg', executable='m', name='m')]),
    ])
""",
        },
        [{}, {"ns": "x", "names": "x"}, {"ns": "/abs/", "names": "p,/q,r/s"}],
    ),
    "names-launch-ros-refuses": (  # rmw's rules, checked before a node starts or a push
        {
            "main.launch.xml": """<launch>
<arg name="n" default="talker"><choice value="talker"/><choice value="a/b"/></arg>
<arg name="ns" default="x"><choice value="x"/><choice value="9x"/><choice value="a/"/></arg>
<arg name="p" default="p"><choice value="p"/><choice value="p q"/></arg>
<arg name="free" default="ok"/>
<group><push-ros-namespace namespace="$(var p)"/>
  <node pkg="pkg" exec="n" name="$(var n)" namespace="$(var ns)"/>
  <node pkg="pkg" exec="n" name="$(var free)"/>
</group>
<executable cmd="echo" name="$(var n)"/>
</launch>""",
            "main.launch.py": """from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, GroupAction
from launch.substitutions import LaunchConfiguration as V
from launch_ros.actions import Node, PushROSNamespace


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('n', default_value='talker', choices=['talker', 'a/b']),
        DeclareLaunchArgument('ns', default_value='x', choices=['x', '9x', 'a/']),
        DeclareLaunchArgument('p', default_value='p', choices=['p', 'p q']),
        DeclareLaunchArgument('free', default_value='ok'),
        GroupAction([
            PushROSNamespace(V('p')),
            Node(package='pkg', executable='n', name=V('n'), namespace=V('ns')),
            Node(package='pkg', executable='n', name=V('free')),
        ]),
    ])
""",
        },
        [{}, {"n": "a/b"}, {"ns": "9x"}, {"ns": "a/"}, {"p": "p q"}, {"free": "o k"}],
    ),
}


CASES.update(NAMES_CASES)
CASES.update(HELPERS_CASES)

LENIENT = frozenset({"find-exec-not-searched"})
"""Fixtures the oracle loads leniently: ``$(find-exec)`` of a program not on its ``PATH``."""


def entries(package: Path) -> list[Path]:
    """The fixture's launch written in each format it has."""
    return sorted(package.glob("main.launch.*"))


def _workspace(tmp_path: Path, files: dict[str, str]) -> Path:
    package = tmp_path / "ws" / "pkg"
    package.mkdir(parents=True)
    (package / "package.xml").write_text(PACKAGE_XML)
    for name, text in files.items():
        (package / name).parent.mkdir(parents=True, exist_ok=True)
        (package / name).write_text(text)
    return package


@pytest.mark.parametrize("case", sorted(CASES))
def test_fixture_matches_the_oracle(case: str, tmp_path: Path) -> None:
    files, samples = CASES[case]
    package = _workspace(tmp_path, files)
    workspace = discover([str(package.parent)])
    for main, arguments in itertools.product(entries(package), samples):
        strict = case not in LENIENT
        expected = run_oracle(main, arguments, [package.parent], strict=strict)
        # the given values as known slots of the model, as `rosvar resolve` makes them
        analysis = Analysis(workspace, extra_values={k: [v] for k, v in arguments.items()})
        result = analysis.resolve([str(main)], arguments)
        assert result.ok == expected["ok"], (main.name, arguments, expected.get("error"))
        if result.ok:
            nodes = canonical_nodes(resolution_nodes(result))
            assert nodes == canonical_nodes(expected), (main.name, arguments)


@pytest.mark.parametrize("case", sorted(CASES))
def test_the_json_names_nodes_as_the_resolution(case: str, tmp_path: Path) -> None:
    """The comparison reads rosvar's nodes from the ``resolve --json`` document, which names
    a node by its fully qualified name only: the last part of it is the resolution's own
    name of the node (None where its code names it) on every fixture."""
    files, samples = CASES[case]
    package = _workspace(tmp_path, files)
    workspace = discover([str(package.parent)])
    for main, arguments in itertools.product(entries(package), samples):
        analysis = Analysis(workspace, extra_values={k: [v] for k, v in arguments.items()})
        result = analysis.resolve([str(main)], arguments)
        nodes = [node for node in result.sorted_nodes() if node.attributes["kind"] != "process"]
        named = [n for n in resolution_nodes(result)["nodes"] if n["kind"] != "process"]
        assert [n["name"] for n in named] == [n.own_name for n in nodes], (main.name, arguments)
