"""Tests of the ROS 2 Python launch frontend: each inline file gives the tree of its XML
equivalent, typed values keep their types, and what cannot be followed is reported."""

from __future__ import annotations

import random
from pathlib import Path

import pytest

from ros2.frontends.trees import Shape, demo_launch, shape, xml_shape
from rosvar.diagnostics import Diagnostic, Location
from rosvar.ros2.frontends.python.parser import parse_python_launch_bytes, parse_python_launch_file


def read(body: str, header: str = "") -> tuple[Shape | None, list[Diagnostic]]:
    """The shape (typed marks left out, as in XML) and the diagnostics of a file."""
    result = parse_python_launch_bytes((header + body).encode(), "t.launch.py")
    return (shape(result.root, typed=False) if result.root else None), result.diagnostics


def codes(diagnostics: list[Diagnostic]) -> list[str]:
    return [diagnostic.code for diagnostic in diagnostics]


IMPORTS = """\
import os
from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import (DeclareLaunchArgument, GroupAction, IncludeLaunchDescription,
    SetEnvironmentVariable, ExecuteProcess, TimerAction)
from launch.conditions import IfCondition, UnlessCondition, LaunchConfigurationEquals
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import (EnvironmentVariable, LaunchConfiguration,
    PathJoinSubstitution, PythonExpression, TextSubstitution)
from launch_ros.actions import Node, PushRosNamespace, SetParameter, SetRemap
from launch_ros.substitutions import FindPackageShare
"""


def test_actions_and_substitutions_give_the_xml_tree() -> None:
    tree, diagnostics = read(
        """
def generate_launch_description():
    ns = LaunchConfiguration('ns', default='robot')
    config = PathJoinSubstitution([FindPackageShare('demo'), 'config', 'p.yaml'])
    return LaunchDescription([
        DeclareLaunchArgument('ns', default_value='r1', description='the namespace',
                              choices=['r1', 'r2']),
        DeclareLaunchArgument('mode', default_value=EnvironmentVariable('MODE', default_value='a')),
        SetParameter(name='global', value='7'),
        SetEnvironmentVariable('E', [TextSubstitution(text='x-'), ns]),
        GroupAction([
            PushRosNamespace(['/', ns]),
            SetRemap(src='a', dst='b'),
            Node(package='demo', executable='talker', name='talker', output='screen',
                 parameters=[config, {'rate': 10, 'use_sim': True, 'name': 'x',
                                      'gains': [1.0, 2.5], 'nested': {'a': 'b'}}],
                 remappings=[('chatter', [ns, '/chatter'])],
                 arguments=['--verbose', 'two words'], ros_arguments=['--log-level', 'debug'],
                 condition=UnlessCondition(LaunchConfiguration('quiet'))),
        ], scoped=False, forwarding=True),
        IncludeLaunchDescription(
            PythonLaunchDescriptionSource(os.path.join(
                get_package_share_directory('demo'), 'launch', 'sub.launch.py')),
            launch_arguments=[('robot', ns)],
            condition=LaunchConfigurationEquals('mode', 'a')),
        ExecuteProcess(cmd=['ls', '-l'], condition=IfCondition(
            PythonExpression([LaunchConfiguration('mode'), " == 'b'"]))),
        TimerAction(period=2.0, actions=[Node(package='demo', executable='late')]),
    ])
""",
        IMPORTS,
    )
    assert diagnostics == []
    assert tree == xml_shape(
        """<launch>
  <arg name="ns" default="r1" description="the namespace">
    <choice value="r1"/><choice value="r2"/>
  </arg>
  <arg name="mode" default="$(env MODE a)"/>
  <set_parameter name="global" value="7"/>
  <set_env name="E" value="x-$(var ns robot)"/>
  <group scoped="false" forwarding="true">
    <push-ros-namespace namespace="/$(var ns robot)"/>
    <set_remap from="a" to="b"/>
    <node pkg="demo" exec="talker" name="talker" output="screen" unless="$(var quiet)"
          args="--verbose 'two words'" ros_args="--log-level debug">
      <param from="$(find-pkg-share demo)/config/p.yaml"/>
      <param name="rate" value="10"/>
      <param name="use_sim" value="true"/>
      <param name="name" value="x"/>
      <param name="gains" value="[1.0, 2.5]"/>
      <param name="nested"><param name="a" value="b"/></param>
      <remap from="chatter" to="$(var ns robot)/chatter"/>
    </node>
  </group>
  <include file="$(find-pkg-share demo)/launch/sub.launch.py"
           if="$(rosvar-configuration-equals mode a)">
    <arg name="robot" value="$(var ns robot)"/>
  </include>
  <executable cmd="ls -l" if="$(eval '$(var mode) == \\'b\\'')"/>
  <timer period="2.0"><node pkg="demo" exec="late"/></timer>
</launch>"""
    )


def test_a_path_join_is_text_where_its_boundaries_are_known() -> None:
    tree, diagnostics = read(
        """
def generate_launch_description():
    d = LaunchConfiguration('d')
    return LaunchDescription([
        SetEnvironmentVariable('A', PathJoinSubstitution([FindPackageShare('p'), 'c', 'x.yaml'])),
        SetEnvironmentVariable('B', PathJoinSubstitution(['/etc/', d, 'x.yaml'])),
        SetEnvironmentVariable('C', PathJoinSubstitution([d, FindPackageShare('p')])),
        SetEnvironmentVariable('D', os.path.join(d, 'x')),
    ])
""",
        IMPORTS,
    )
    assert diagnostics == []
    assert tree == xml_shape(
        """<launch>
  <set_env name="A" value="$(find-pkg-share p)/c/x.yaml"/>
  <set_env name="B" value="$(rosvar-path-join $(rosvar-path-join /etc/ $(var d)) x.yaml)"/>
  <set_env name="C" value="$(find-pkg-share p)"/>
  <set_env name="D" value="$(rosvar-path-join $(var d) x)"/>
</launch>"""
    )


def test_typed_values_keep_their_types() -> None:
    result = parse_python_launch_bytes(
        (
            IMPORTS
            + """
def generate_launch_description():
    return LaunchDescription([
        GroupAction([Node(package='p', executable='e', respawn=True,
                          parameters=[{'rate': 10, 'ratio': 0.5, 'on': False, 'name': '10',
                                       'list': [1, 2], 'words': ['a', '1']}])],
                    scoped=False),
    ])
"""
        ).encode(),
        "t.py",
    )
    assert result.root is not None
    group = result.root.children[0]
    node = group.children[0]
    assert (group.attributes, group.typed) == ({"scoped": "false"}, frozenset({"scoped"}))
    assert node.typed == {"respawn"} and node.attributes["respawn"] == "true"
    values = [(p.attributes["value"], p.typed, p.get("type")) for p in node.children]
    assert values == [
        ("10", {"value"}, None),
        ("0.5", {"value"}, None),
        ("false", {"value"}, None),
        ("10", frozenset(), "str"),  # a string, as XML says with type="str"
        ("[1, 2]", {"value"}, None),
        ("[a, '1']", {"value"}, None),
    ]


def test_import_aliases_and_module_paths() -> None:
    tree, diagnostics = read(
        """
import launch
import launch_ros.actions
import launch.substitutions as subst
from launch_ros.actions import Node as N
from launch_ros.actions.node import Node as DeepNode

def generate_launch_description():
    return launch.LaunchDescription([
        launch.actions.DeclareLaunchArgument('x'),
        launch_ros.actions.Node(package='a', executable=subst.LaunchConfiguration('x')),
        N(package='b', executable='e'),
        DeepNode(package='c', executable='e'),
    ])
"""
    )
    assert diagnostics == []
    assert tree == xml_shape(
        '<launch><arg name="x"/><node pkg="a" exec="$(var x)"/><node pkg="b" exec="e"/>'
        '<node pkg="c" exec="e"/></launch>'
    )


def test_variables_helpers_loops_and_constant_ifs_are_followed() -> None:
    tree, diagnostics = read(
        """
ROBOTS = ['r1', 'r2']
USE_RVIZ = False

def robot_node(name, *, rate=10, **extra):
    params = {'rate': rate}
    params.update(extra)
    return Node(package='demo', executable='driver', name=f'{name}_driver',
                namespace='/' + name, parameters=[params])

def generate_launch_description():
    ld = LaunchDescription()
    nodes = []
    for index, robot in enumerate(ROBOTS):
        nodes.append(robot_node(robot, rate=10 * (index + 1), id=index))
    ld.add_action(GroupAction(nodes))
    if USE_RVIZ:
        ld.add_action(Node(package='rviz2', executable='rviz2'))
    else:
        ld.add_action(Node(package='demo', executable='headless'))
    extra = [Node(package='demo', executable=name) for name in ('a', 'b') if name != 'b']
    ld.add_action(GroupAction([*extra]))
    return ld
""",
        IMPORTS,
    )
    assert diagnostics == []
    assert tree == xml_shape(
        """<launch>
  <group>
    <node pkg="demo" exec="driver" name="r1_driver" namespace="/r1">
      <param name="rate" value="10"/><param name="id" value="0"/>
    </node>
    <node pkg="demo" exec="driver" name="r2_driver" namespace="/r2">
      <param name="rate" value="20"/><param name="id" value="1"/>
    </node>
  </group>
  <node pkg="demo" exec="headless"/>
  <group><node pkg="demo" exec="a"/></group>
</launch>"""
    )


def test_an_opaque_function_of_the_file_is_read_where_it_stands() -> None:
    """Its actions are an unscoped group; what it reads of ``context`` is the substitution,
    and ``dict()`` of pairs is followed (realsense's ``rs_launch.py`` builds its parameters
    so)."""
    tree, diagnostics = read(
        """
from launch.actions import OpaqueFunction

def setup(context, names, rate=1):
    name = LaunchConfiguration('robot').perform(context)
    params = dict([(key, LaunchConfiguration(key)) for key in names])
    params['mode'] = context.launch_configurations.get('mode', 'sim')
    return [Node(package='demo', executable='driver', name=name + '_driver',
                 namespace=context.launch_configurations['ns'], parameters=[params])]

def generate_launch_description():
    return LaunchDescription([
        OpaqueFunction(function=setup, args=[('gain',)]),
        OpaqueFunction(function=print),
    ])
""",
        IMPORTS,
    )
    assert codes(diagnostics) == ["python-not-followed"]  # print is no function of the file
    assert diagnostics[0].location.line == 25 and "Module" in diagnostics[0].message
    assert tree == xml_shape(
        """<launch>
  <group scoped="false">
    <node pkg="demo" exec="driver" name="$(var robot)_driver" namespace="$(var ns)">
      <param name="gain" value="$(var gain)"/>
          <param name="mode" value="$(var mode sim)" type="str"/>
    </node>
  </group>
</launch>"""
    )


def test_what_an_opaque_function_reads_of_context_by_a_computed_name_is_reported() -> None:
    _tree, diagnostics = read(
        """
from launch.actions import OpaqueFunction
def f(context):
    x = context.launch_configurations[LaunchConfiguration('a')]
    y = context.launch_configurations.get(5)
    w = context.launch_configurations.get('a', ['list'])
    return [Node(package='a', executable=x, name=y), Node(package='a', executable=w)]
def generate_launch_description():
    return LaunchDescription([OpaqueFunction(function=f)])
""",
        IMPORTS,
    )
    assert [(d.location.line, d.message) for d in diagnostics] == [
        (15, "a launch configuration named by a non-string is not followed"),
        (16, "a launch configuration named by a non-string is not followed"),
        (17, "a launch configuration's non-string default is not followed"),
    ]


def test_composable_nodes_and_containers() -> None:
    tree, diagnostics = read(
        """
from launch import LaunchDescription
from launch_ros.actions import ComposableNodeContainer, LoadComposableNodes
from launch_ros.descriptions import ComposableNode

def generate_launch_description():
    talker = ComposableNode(package='demo', plugin='demo::Talker', name='talker',
                            remappings=[('a', 'b')],
                            extra_arguments=[{'use_intra_process_comms': True}])
    return LaunchDescription([
        ComposableNodeContainer(name='box', namespace='', package='rclcpp_components',
                                executable='component_container',
                                composable_node_descriptions=[talker]),
        LoadComposableNodes(target_container='/box', composable_node_descriptions=[
            ComposableNode(package='demo', plugin='demo::Listener', name='listener')]),
    ])
"""
    )
    assert diagnostics == []
    assert tree == xml_shape(
        """<launch>
  <node_container name="box" namespace="" pkg="rclcpp_components" exec="component_container">
    <composable_node pkg="demo" plugin="demo::Talker" name="talker">
      <remap from="a" to="b"/>
      <extra_arg name="use_intra_process_comms" value="true"/>
    </composable_node>
  </node_container>
  <load_composable_node target="/box">
    <composable_node pkg="demo" plugin="demo::Listener" name="listener"/>
  </load_composable_node>
</launch>"""
    )


def test_literal_text_is_escaped_for_the_substitution_grammar() -> None:
    tree, diagnostics = read(
        r"""
def generate_launch_description():
    return LaunchDescription([
        SetParameter(name='price', value='$(not a substitution) C:\\dir'),
        SetParameter(name='quoted', value=LaunchConfiguration("it's")),
        SetParameter(name='empty', value=EnvironmentVariable('E', default_value='')),
    ])
""",
        IMPORTS,
    )
    assert diagnostics == []
    assert tree == xml_shape(
        r"""<launch>
  <set_parameter name="price" value="\$(not a substitution) C:\\dir"/>
  <set_parameter name="quoted" value="$(var 'it\'s')"/>
  <set_parameter name="empty" value="$(env E '')"/>
</launch>"""
    )


def test_what_is_not_followed_is_reported_and_the_rest_is_kept() -> None:
    tree, diagnostics = read(
        """
import yaml
from launch.actions import RegisterEventHandler
from launch.event_handlers import OnProcessExit

def generate_launch_description():
    config = yaml.safe_load(open('/etc/robot.yaml'))
    return LaunchDescription([
        RegisterEventHandler(OnProcessExit(on_exit=[Node(package='hidden', executable='x')])),
        Node(package='demo', executable=config['exe'], name=undefined_name),
        Node(package='demo', executable='kept'),
    ])
""",
        IMPORTS,
    )
    assert tree == xml_shape(
        """<launch>
  <on_process_exit><node pkg="hidden" exec="x"/></on_process_exit>
  <node pkg="demo" exec="$(rosvar-unknown 'a read of /etc/robot.yaml (no workspace)')"
        name="$(rosvar-unknown 'name \\'undefined_name\\'')"/>
  <node pkg="demo" exec="kept"/>
</launch>"""
    )
    assert [(str(d.location), d.message) for d in diagnostics] == [
        ("t.launch.py:18:14", "a read of /etc/robot.yaml (no workspace) is not followed"),
        ("t.launch.py:21:61", "name 'undefined_name' is not followed"),
    ]
    assert set(codes(diagnostics)) == {"python-not-followed"}


def test_unknown_conditions_loops_and_recursion_are_reported() -> None:
    tree, diagnostics = read(
        """
import sys

def forever(n):
    return forever(n + 1)

def generate_launch_description():
    ld = LaunchDescription()
    if sys.argv:
        ld.add_action(Node(package='a', executable='b'))
    while True:
        pass
    forever(0)
    return ld
""",
        IMPORTS,
    )
    assert tree == xml_shape("<launch/>")
    messages = [d.message for d in diagnostics]
    assert messages == [
        "an 'if' on a value not known statically (neither branch) is not followed",
        "a 'While' statement is not followed",
        "recursion of forever() is not followed",
    ]


def test_the_file_is_never_executed(tmp_path: Path) -> None:
    marker = tmp_path / "executed"
    tree, diagnostics = read(
        f"""
import os
os.system('touch {marker}')
open({str(marker)!r}, 'w').write('x')
exec("open({str(marker)!r}, 'w')")

def generate_launch_description():
    __import__('os').system('touch {marker}')
    return LaunchDescription([])
""",
        IMPORTS,
    )
    assert not marker.exists()
    assert tree == xml_shape("<launch/>")
    assert [d.message for d in diagnostics] == [
        "call to os.system() is not followed",
        "open() in mode 'w' is not followed",
        "call to exec() is not followed",
        "call to __import__() is not followed",
    ]


def test_broken_files_are_diagnostics() -> None:
    for source, code in [
        ("def generate_launch_description(:\n", "python-syntax"),
        ("x = 1\n", "python-launch-entry"),
        ("def generate_launch_description():\n    return 1\n", "python-launch-entry"),
        ("a = 1\x00\n", "python-syntax"),
        ("x = " + "(" * 500 + ")" * 500 + "\n", "python-syntax"),
        (
            "def generate_launch_description():\n"
            "    for i in range(90000):\n        for j in range(90000):\n            pass\n",
            "python-budget",
        ),
    ]:
        tree, diagnostics = read(source)
        assert (tree, codes(diagnostics)) == (None, [code]), source
    result = parse_python_launch_bytes(b"x = '\xff'", "t.py")
    assert codes(result.diagnostics) == ["python-syntax"]
    assert result.diagnostics[0].location == Location("t.py", 1, 1)


def test_files_are_read_through_the_confined_reader(tmp_path: Path) -> None:
    missing = parse_python_launch_file(tmp_path / "none.launch.py")
    assert missing.root is None and codes(missing.diagnostics) == ["file-unreadable"]


def test_demo_package_python_equals_its_xml() -> None:
    for name in ("top", "sub"):
        result = parse_python_launch_file(demo_launch(f"{name}.launch.py"))
        assert result.root is not None and result.diagnostics == []
        expected = xml_shape(demo_launch(f"{name}.launch.xml").read_text())
        # the Python files include the Python version of sub: only the suffix differs
        assert shape(result.root, ((".launch.py", ".launch.xml"),)) == expected


def test_paths_environment_and_parameter_descriptions() -> None:
    tree, diagnostics = read(
        """
from launch.substitutions import Command, FindExecutable
from launch_ros.descriptions import ParameterFile, ParameterValue

def generate_launch_description():
    here = os.path.dirname(__file__)
    home, robot = os.environ['HOME'], os.environ.get('ROBOT', 'r1')
    description = Command([FindExecutable(name='xacro'), ' ', here, '/robot.xacro'])
    names = []
    for name in ['a', 'skip', 'b', 'stop', 'never']:
        if name == 'skip':
            continue
        if name == 'stop':
            break
        names.append(name)
    try:
        extra = {'x': 1}
    except ImportError:
        extra = {}
    return LaunchDescription([
        Node(package='demo', executable='robot', name=robot, on_exit=None,
             parameters=[ParameterFile(os.path.join(here, 'p.yaml'), allow_substs=True),
                         {'robot_description': ParameterValue(description, value_type=str),
                          'home': home, 'names': names, **extra}]),
        Node(package='demo', output={'stdout': 'screen', 'stderr': 'log'}),
    ])
""",
        IMPORTS,
    )
    assert tree == xml_shape(
        """<launch>
  <node pkg="demo" exec="robot" name="$(env ROBOT r1)">
    <param from="$(dirname)/p.yaml" allow_substs="true"/>
    <param name="robot_description" value="$(command '$(find-exec xacro) $(dirname)/robot.xacro')"
           type="str"/>
    <param name="home" value="$(env HOME)" type="str"/>
    <param name="names" value="[a, b]"/>
    <param name="x" value="1"/>
  </node>
  <node pkg="demo"/>
</launch>"""
    )
    assert [(d.severity.value, d.message) for d in diagnostics] == [
        (
            "note",
            "launch_ros.actions.Node() argument 'on_exit' has no XML equivalent; not analysed",
        ),
        (  # launch takes one output per stream; the streams do not change the graph
            "note",
            "launch_ros.actions.Node() argument 'output' as a dict (one per stream) has no XML "
            "equivalent; not analysed",
        ),
    ]


def test_path_operators_format_and_perform() -> None:
    tree, diagnostics = read(
        """
from launch.substitutions import PathSubstitution

def generate_launch_description():
    config = PathSubstitution(FindPackageShare('demo')) / 'config' / 'p.yaml'
    name = '{}_{robot}'.format('driver', robot=LaunchConfiguration('robot'))
    mode = LaunchConfiguration('mode').perform(None)
    return LaunchDescription([
        Node(package='demo', executable='{0}{0}'.format('x'), name=name, namespace=mode,
             parameters=[config]),
    ])
""",
        IMPORTS,
    )
    assert diagnostics == []
    assert tree == xml_shape(
        """<launch>
  <node pkg="demo" exec="xx" name="driver_$(var robot)" namespace="$(var mode)">
    <param from="$(find-pkg-share demo)/config/p.yaml"/>
  </node>
</launch>"""
    )


def test_mutants_of_a_launch_file_never_raise() -> None:
    """Seeded mutations (lines dropped, duplicated, swapped, cut) read without an exception."""
    source = (demo_launch("top.launch.py").read_text() + IMPORTS).splitlines()
    rng = random.Random(19)
    for _ in range(300):
        lines = list(source)
        for _ in range(rng.randint(1, 4)):
            at = rng.randrange(len(lines))
            mutation = rng.choice(("drop", "duplicate", "swap", "cut"))
            if mutation == "drop":
                del lines[at]
            elif mutation == "duplicate":
                lines.insert(at, lines[rng.randrange(len(lines))])
            elif mutation == "swap":
                other = rng.randrange(len(lines))
                lines[at], lines[other] = lines[other], lines[at]
            else:
                lines[at] = lines[at][: rng.randrange(len(lines[at]) + 1)]
        result = parse_python_launch_bytes("\n".join(lines).encode(), "m.py")
        assert result.root is not None or result.diagnostics


def test_values_stay_within_the_size_limits() -> None:
    """Doubling strings, lists, texts and integers is cut off, not computed."""
    for body in [
        "s = 'x'\n    for i in range(60):\n        s = s + s",
        "s = 'x'\n    for i in range(60):\n        s = f'{s}{s}'",
        "s = LaunchConfiguration('x')\n    for i in range(60):\n        s = s + s",
        "l = [1]\n    for i in range(60):\n        l.extend(l)",
        "n = 3\n    for i in range(60):\n        n = n * n",
        "s = 'a' * 100000\n    s = s.replace('a', s)",
    ]:
        source = f"def generate_launch_description():\n    {body}\n    return LaunchDescription()\n"
        tree, diagnostics = read(source, IMPORTS)
        assert tree == xml_shape("<launch/>"), body
        assert codes(diagnostics) == ["python-not-followed"], body


@pytest.mark.parametrize(
    "body",
    [
        "s = 'a' * 100000\n    s = ''.join([s] * 100000)",
        "s = 'x' * 1000\n    l = [[s] * 99999] * 99999",
        "s = 'x' * 99999\n    d = {str(i): s + str(i) for i in range(99999)}",
        "l = list(range(99999))\n    for i in range(99999):\n        l == l",
        "l = list(range(99999))\n    for i in range(99999):\n        m = l[:]",
        "s = 'a ' * 99999\n    for i in range(99999):\n        m = s.split()",
        "d = {'a': 1}\n    for i in range(40):\n        d = {'x': d, 'y': d}",
        "g = Node(package='p', executable='e')\n    for i in range(30):\n"
        "        g = GroupAction([g, g])",
    ],
)
def test_the_budget_counts_what_each_operation_builds(body: str) -> None:
    """Sequences built from shared parts, and loops of operations each walking a long
    value, are charged by the size they walk or expand to: the budget runs out, at the
    statement where it does, instead of minutes or gigabytes."""
    source = f"def generate_launch_description():\n    {body}\n    return LaunchDescription()\n"
    tree, diagnostics = read(source, IMPORTS)
    assert tree is None
    (budget,) = [d for d in diagnostics if d.code == "python-budget"]
    assert budget.location.line > 1


@pytest.mark.parametrize(("levels", "read_whole"), [(8, True), (60, False)])
def test_the_description_returned_is_charged_as_it_is_walked(levels: int, read_whole: bool) -> None:
    """Each level holds the last one twice, once inside a timer built before: the charge of
    each operation credits both, but the interpretation walks 2^levels elements. The
    description returned is counted as walked, each shared element once per place."""
    body = (
        "g = Node(package='p', executable='e')\n"
        f"    for i in range({levels}):\n"
        "        g = GroupAction([g, TimerAction(period=1.0, actions=[g])])\n"
        "    return LaunchDescription([g])\n"
    )
    source = IMPORTS + f"def generate_launch_description():\n    {body}"
    result = parse_python_launch_bytes(source.encode(), "t.launch.py")  # not walked here
    read_at_all = result.root is not None  # pytest would print the shared tree, whole
    assert read_at_all == read_whole
    if not read_whole:
        (budget,) = [d for d in result.diagnostics if d.code == "python-budget"]
        assert budget.location.line == len(IMPORTS.splitlines()) + 5  # the return


def test_environment_without_a_default_is_empty_where_unset() -> None:
    """Python's ``None`` for an unset variable compares and tests as ``''`` does (RealSense's
    ``os.getenv('ROS_DISTRO') == 'foxy'``); ``$(env X)`` would fail where launch does not."""
    tree, diagnostics = read(
        """
def generate_launch_description():
    return LaunchDescription([
        Node(package='demo', name=os.getenv('ROBOT'), namespace=os.environ.get('NS')),
        Node(package='demo', name=os.getenv('ROBOT', 'r1'), namespace=os.environ['NS']),
    ])
""",
        IMPORTS,
    )
    assert diagnostics == []
    assert tree == xml_shape(
        """<launch>
  <node pkg="demo" name="$(env ROBOT '')" namespace="$(env NS '')"/>
  <node pkg="demo" name="$(env ROBOT r1)" namespace="$(env NS)"/>
</launch>"""
    )
