"""``$(rosvar-written-file)``: the readings of helpers' ``perform`` one analysis affords."""

from __future__ import annotations

from pathlib import Path

from oracle.ros2_client import canonical_nodes, resolution_nodes
from ros2.tags.launches import launch
from rosvar.ros2 import written_files
from rosvar.workspace import discover


def test_an_analysis_reads_a_bounded_number_of_argument_sets(tmp_path: Path) -> None:
    """Each distinct set of a helper's arguments is a reading of its whole source file; past
    :data:`MAX_READINGS` the file is left to each configuration. A set read already costs
    nothing more, and another analysis has its own count."""
    first, second = discover([tmp_path]), discover([tmp_path])
    sets = [("module.py", "pkg", "Rewritten", repr(((str(i),), {}))) for i in range(9)]
    limit = written_files.MAX_READINGS
    assert [written_files._affordable(first, s) for s in sets] == [
        i < limit for i in range(len(sets))
    ]
    assert all(written_files._affordable(first, s) for s in sets[:limit])
    assert written_files._affordable(second, sets[-1])


HELPER_ENTRY = """import tempfile
import launch
import yaml
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch.utilities import perform_substitutions
from launch_ros.actions import Node


class Listed(launch.Substitution):
    def __init__(self, *values):
        super().__init__()
        self.values = values

    def perform(self, context):
        listed = [perform_substitutions(context, [value]) for value in self.values]
        out = tempfile.NamedTemporaryFile(mode='w', delete=False)
        yaml.dump({'/**': {'ros__parameters': {'listed': listed}}}, out)
        return out.name


def generate_launch_description():
    a, b, c = (LaunchConfiguration(name) for name in 'abc')
    return LaunchDescription([
        DeclareLaunchArgument('a', default_value='1'),
        DeclareLaunchArgument('b', default_value='2'),
        DeclareLaunchArgument('c', default_value='3'),
        Node(package='pkg', executable='n', name='n', parameters=[Listed(a, b, c)]),
    ])
"""


def test_a_file_written_of_values_given_later_is_one_value_a_configuration_computes(
    tmp_path: Path,
) -> None:
    """Each argument may be given on the command line: the file written has 8
    combinations, 7 of them known per configuration only. They are one branch (crossing
    them on would multiply them with every text made of the file), which ``resolve``
    computes as launch does."""
    it = launch(tmp_path, HELPER_ENTRY, suffix=".launch.py")
    (node,) = it.model.nodes
    contents = [leaf for parameter in node.parameters for leaf in [parameter.content]]
    assert [isinstance(leaf, str) for leaf in contents] == [True, False]
    for arguments in [{}, {"a": "5"}, {"b": "x", "c": "7.5"}]:
        expected = it.matches_oracle(arguments)  # the values given known to the model
        result = it.analysis.resolve([str(it.main)], arguments)  # given later: the term
        assert canonical_nodes(resolution_nodes(result)) == canonical_nodes(expected)
