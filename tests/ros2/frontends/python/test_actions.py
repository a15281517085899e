"""Launch actions of Python launch files as their XML elements (``actions.py``), where the
Python computes them from launch-time values: composable node descriptions chosen by an
``if`` on such a value, and a container object given as a ``LoadComposableNodes`` target.
Each is checked against the real ros2/launch (the oracle) for several command lines."""

from __future__ import annotations

from pathlib import Path

import pytest

from oracle.ros2_client import canonical_nodes, resolution_nodes, run_oracle
from ros2.tags.launches import launch

HEADER = """from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, OpaqueFunction
from launch.conditions import IfCondition, UnlessCondition
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import ComposableNodeContainer, LoadComposableNodes, PushRosNamespace
from launch_ros.descriptions import ComposableNode
"""

BRANCHES = (
    HEADER
    + """

def setup(context):
    split = LaunchConfiguration('split').perform(context).lower() == 'true'
    shared = ComposableNode(package='pkg', plugin='p::Crop', name='crop')
    if not split:
        one = ComposableNode(package='pkg', plugin='p::Both', name='both')
        parts = [one]
    else:
        parts = [
            ComposableNode(package='pkg', plugin='p::Sync', name='sync'),
            ComposableNode(package='pkg', plugin='p::Concat', name='concat'),
        ]
        if LaunchConfiguration('extra').perform(context) == 'yes':
            parts.append(ComposableNode(package='pkg', plugin='p::Extra', name='extra'))
    return [ComposableNodeContainer(
        name='box', namespace='ns', package='pkg',
        executable='component_container', composable_node_descriptions=parts + [shared])]


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('split', default_value='true'),
        DeclareLaunchArgument('extra', default_value='no'),
        OpaqueFunction(function=setup),
    ])
"""
)


@pytest.mark.oracle
@pytest.mark.parametrize(
    "arguments",
    [{}, {"split": "False"}, {"split": "TRUE", "extra": "yes"}, {"split": "no", "extra": "yes"}],
)
def test_descriptions_chosen_by_a_launch_time_if_agree_with_ros2_launch(
    tmp_path: Path, arguments: dict[str, str]
) -> None:
    it = launch(tmp_path, BRANCHES, ".launch.py", values={"split": ["False", "TRUE", "no"]})
    assert not [d for d in it.model.diagnostics if d.code == "python-not-followed"]
    it.matches_oracle(arguments)


def test_each_description_chosen_by_a_branch_is_present_under_its_test(tmp_path: Path) -> None:
    """(Where an argument has a value no file names, the tests are terms that ``resolve``
    evaluates.)"""
    values = {"split": ["False", "TRUE"], "extra": ["yes"]}
    it = launch(tmp_path, BRANCHES, ".launch.py", values=values)
    present = {}
    for node in it.model.nodes:
        for condition, plugin in node.field("plugin"):
            if isinstance(plugin, str):
                present[plugin] = node.condition & condition
    true, false = it.given("split", "true") | it.given("split", "TRUE"), it.given("split", "False")
    assert it.implies(false, present["p::Both"]) and it.never(true & present["p::Both"])
    for plugin in ("p::Sync", "p::Concat"):
        assert it.implies(true, present[plugin]) and it.never(false & present[plugin])
    extra = it.given("extra", "yes")
    assert it.implies(true & extra, present["p::Extra"])
    known = extra | it.given("extra", "no")
    assert it.never(present["p::Extra"] & known & (false | true & it.given("extra", "no")))
    assert it.same(present["p::Crop"], it.analysis.space.true)


TARGET = (
    HEADER
    + """

def setup(context):
    container = ComposableNodeContainer(
        name='own_box', namespace='inner', package='pkg',
        executable='component_container', composable_node_descriptions=[],
        condition=UnlessCondition(LaunchConfiguration('shared')))
    target = (
        LaunchConfiguration('shared_name')
        if IfCondition(LaunchConfiguration('shared')).evaluate(context)
        else container
    )
    load = LoadComposableNodes(
        composable_node_descriptions=[ComposableNode(package='pkg', plugin='p::A', name='a')],
        target_container=target)
    direct = LoadComposableNodes(
        composable_node_descriptions=[ComposableNode(package='pkg', plugin='p::B', name='b')],
        target_container=container)
    return [PushRosNamespace('pushed'), container, load, direct]


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('shared', default_value='false'),
        DeclareLaunchArgument('shared_name', default_value='/other_box'),
        OpaqueFunction(function=setup),
    ])
"""
)


@pytest.mark.oracle
@pytest.mark.parametrize("arguments", [{}, {"shared": "true"}, {"shared_name": "/third"}])
def test_a_container_object_as_target_is_named_as_launch_ros_names_it(
    tmp_path: Path, arguments: dict[str, str]
) -> None:
    it = launch(tmp_path, TARGET, ".launch.py")
    assert not [d for d in it.model.diagnostics if d.code == "python-not-followed"]
    expected = it.matches_oracle(arguments)
    if arguments.get("shared") == "true":  # the container is not launched: its name fails
        assert not expected["ok"]
    else:  # the oracle says what launch_ros does
        containers = {node["name"]: node.get("container") for node in expected["nodes"]}
        assert containers["b"] == "/pushed/inner/own_box"


@pytest.mark.oracle
@pytest.mark.parametrize("arguments", [{}, {"shared": "true"}])
def test_an_action_given_a_value_chosen_at_launch_time_is_made_in_each_branch(
    tmp_path: Path, arguments: dict[str, str]
) -> None:
    """``target = name if c else container``: where the name is chosen the container (not
    launched) is never asked for its name, as in launch_ros."""
    chosen_only = TARGET.replace(
        "[PushRosNamespace('pushed'), container, load, direct]", "[container, load]"
    )
    it = launch(tmp_path, chosen_only, ".launch.py")
    expected = it.matches_oracle(arguments)
    containers = {node["name"]: node.get("container") for node in expected["nodes"]}
    assert containers["a"] == ("/other_box" if arguments else "/inner/own_box")


PARAMETERS = (
    HEADER
    + """from launch_ros.actions import Node


def setup(context):
    voxel = LaunchConfiguration('voxel').perform(context)
    scaled = float(voxel) * 10.0
    return [Node(package='pkg', executable='n', name='n', parameters=[{
        'performed': voxel, 'converted': str(scaled), 'scaled': scaled, 'joined': 'v' + voxel,
        'lowered': voxel.lower(), 'substituted': LaunchConfiguration('voxel')}])]


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('voxel', default_value='0.5'),
        OpaqueFunction(function=setup),
    ])
"""
)


@pytest.mark.oracle
@pytest.mark.parametrize("arguments", [{}, {"voxel": "2"}, {"voxel": "1e3"}])
def test_a_launch_time_string_in_a_parameter_stays_a_string(
    tmp_path: Path, arguments: dict[str, str]
) -> None:
    """launch_ros reads by YAML rules only what it performs itself (the substitution); a
    Python string the file computed (``.perform(context)``, ``str(x)``) stays a string."""
    it = launch(tmp_path, PARAMETERS, ".launch.py")
    expected = it.matches_oracle(arguments)
    [node] = expected["nodes"]
    assert isinstance(node["parameters"]["performed"], str)


def test_a_launch_time_string_in_a_parameter_is_typed_str(tmp_path: Path) -> None:
    it = launch(tmp_path, PARAMETERS, ".launch.py")
    [node] = it.analysis.resolve([str(it.main)], {"voxel": "2"}).nodes
    assert node.parameters == {
        "performed": "2",
        "converted": "20.0",
        "scaled": 20.0,
        "joined": "v2",
        "lowered": "2",
        "substituted": 2,
    }


RENAMED = """from launch import LaunchDescription
from launch_ros.actions import ComposableNodeContainer, Node
from launch_ros.descriptions import ComposableNode


def generate_launch_description():
    return LaunchDescription([
        Node(package='pkg', {node}='talker', {name}='t', {namespace}='robot'),
        ComposableNodeContainer(
            {name}='box', {namespace}='', package='pkg',
            executable='component_container',
            composable_node_descriptions=[
                ComposableNode(package='pkg', plugin='pkg::C', {name}='c', {namespace}='x'),
            ]),
    ])
"""


def test_launch_ros_names_before_galactic_are_read_as_their_successors(tmp_path: Path) -> None:
    """``node_executable``, ``node_name``, ``node_namespace`` (Dashing, Eloquent): the file
    starts what it did there, which is what the oracle starts with today's names; each old
    name is a warning, as jazzy refuses it."""
    new = {"node": "executable", "name": "name", "namespace": "namespace"}
    it = launch(tmp_path, RENAMED.format(**new), suffix=".launch.py")
    expected = it.matches_oracle({})
    old = launch(
        tmp_path / "old",
        RENAMED.format(node="node_executable", name="node_name", namespace="node_namespace"),
        suffix=".launch.py",
    )
    result = old.analysis.resolve([str(old.main)], {})
    assert result.ok, result.errors
    assert canonical_nodes(resolution_nodes(result)) == canonical_nodes(expected)
    warned = [d for d in old.model.diagnostics if d.code == "python-launch-renamed"]
    assert len(warned) == 7
    assert warned[0].message == (
        "launch_ros.actions.Node() argument 'node_executable' is launch_ros' name before "
        "Galactic, which later releases refuse: read as 'executable'"
    )
    assert not run_oracle(old.main, {}, [old.main.parent.parent])["ok"]  # jazzy refuses them


PYTHON_VALUES = """import os
from pathlib import Path

import yaml
from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node
from launch_ros.parameter_descriptions import ParameterValue


def generate_launch_description():
    share = get_package_share_directory('pkg')
    with open(os.path.join(share, 'robot.urdf'), 'r') as infp:
        robot_description = infp.read()
    loaded = yaml.safe_load(open(os.path.join(share, 'values.yaml')))
    digit = '1'
    return LaunchDescription([
        DeclareLaunchArgument('x', default_value='2'),
        Node(package='pkg', executable='n', name='n', parameters=[{
            'robot_description': robot_description,
            'one': open(os.path.join(share, 'one.txt')).read(),
            'digit': '1', 'word': 'true', 'blank': ' x', 'empty': '', 'null': 'null',
            'tilde': '~', 'flow': '[1, 2]', 'map': '{a: 1}', 'colon': 'a: b', 'hash': '#x',
            'backslash': 'a\\\\b',
            'quoted': "'q'", 'lines': 'a\\n  b\\n\\nc', 'dollar': '$(var x)', 'tab': '\\tx',
            'formatted': f'{digit}.5', 'joined': '\\n'.join(['1', '2']), 'converted': str(1.5),
            'nested': {'a': '1', 'b': {'c': 'x\\ny', 'd': 'false'}},
            'strings': ['1', 'true', 'a b', ''], 'numbers': [1, 2.5], 'loaded': loaded,
            'with_substitution': ['1', LaunchConfiguration('x')],
            'joined_path': os.path.join(share, 'a: b'), 'path': str(Path(share) / 'x #c'),
            'beside': os.path.dirname(__file__) + '/x #c', 'share': share + ' #c',
            'value': ParameterValue('1'), 'value_lines': ParameterValue('a\\n  b: $(c)\\n'),
            'value_list': ParameterValue(['1', '2']),
            'value_str': ParameterValue('1', value_type=str),
            'value_substitution': ParameterValue(LaunchConfiguration('x')),
        }]),
    ])
"""
PYTHON_VALUE_FILES = {
    "robot.urdf": '<robot name="r">\n  <!-- $(find x) -->\n  <link name="a"/>\n</robot>\n',
    "values.yaml": "a: '1'\nb: 'true'\nc:\n  d: 'x y'\n  e: ['1', '2']\nf: '#x'\n",
    "one.txt": "1\n",
}


@pytest.mark.oracle
@pytest.mark.parametrize("arguments", [{}, {"x": "'a'"}])
def test_python_values_in_parameters_are_kept_as_launch_ros_keeps_them(
    tmp_path: Path, arguments: dict[str, str]
) -> None:
    """launch_ros dumps a Python string given as a parameter (a literal, a file's text, a
    path ``os.path.join`` made, a value of a loaded YAML file) as YAML and reads it back:
    it stays that string, newlines and ``$(`` included; only substitutions' text is read
    by YAML rules. A list of ints and floats becomes floats."""
    it = launch(tmp_path, PYTHON_VALUES, ".launch.py", files=PYTHON_VALUE_FILES)
    expected = it.matches_oracle(arguments)
    [node] = expected["nodes"]
    assert node["parameters"]["robot_description"] == PYTHON_VALUE_FILES["robot.urdf"]


def test_a_file_read_as_a_parameter_keeps_its_lines(tmp_path: Path) -> None:
    it = launch(tmp_path, PYTHON_VALUES, ".launch.py", files=PYTHON_VALUE_FILES)
    result = it.analysis.resolve([str(it.main)], {})
    assert result.ok, result.errors
    [node] = result.nodes
    assert node.parameters is not None
    expected = {
        "robot_description": PYTHON_VALUE_FILES["robot.urdf"],
        "one": "1\n",
        "digit": "1",
        "lines": "a\n  b\n\nc",
        "dollar": "$(var x)",
        "backslash": "a\\b",
        "nested.b.c": "x\ny",
        "numbers": [1.0, 2.5],
        "loaded.c.e": ["1", "2"],
        "with_substitution": 12,
        "value": "1",
        "value_list": ["1", "2"],
        "value_lines": "a\n  b: $(c)\n",
        "value_substitution": 2,
    }
    assert {name: node.parameters[name] for name in expected} == expected
    assert str(node.parameters["joined_path"]).endswith("/pkg/a: b")


NAMED_BY_ENVIRONMENT = """import os

from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    model = os.environ['MODEL']
    path = os.path.join(get_package_share_directory('pkg'), 'robot_' + model + '.urdf')
    with open(path, 'r') as infp:
        description = infp.read()
    return LaunchDescription([
        Node(package='pkg', executable='n', name='n',
             parameters=[{'robot_description': description}]),
    ])
"""


@pytest.mark.oracle
@pytest.mark.parametrize("model", ["burger", "waffle"])
def test_a_file_named_by_the_environment_is_read_as_python_reads_it(
    tmp_path: Path, model: str
) -> None:
    """turtlebot3's ``robot_state_publisher.launch.py``: the file a launch-time value names
    is read once a configuration names it (launch's ``FileContent``), its line ends as
    Python's text mode gives them (``\\r\\n`` is ``\\n``), and stays a string."""
    files = {
        "robot_burger.urdf": '<robot name="b">\r\n  <!-- $(find x) -->\r\n</robot>\r\n',
        "robot_waffle.urdf": '<robot name="w">\n  <link name="a"/>\r</robot>\n',
    }
    it = launch(tmp_path, NAMED_BY_ENVIRONMENT, ".launch.py", files=files)
    expected = run_oracle(it.main, {}, [it.main.parent.parent], env={"MODEL": model})
    [node] = expected["nodes"]
    result = it.analysis.resolve([str(it.main)], {}, env={"MODEL": model})
    assert result.ok, result.errors
    assert canonical_nodes(resolution_nodes(result)) == canonical_nodes(expected)
    text = files[f"robot_{model}.urdf"].replace("\r\n", "\n").replace("\r", "\n")
    assert node["parameters"]["robot_description"] == text
