"""Fixtures of the workspace helpers launch files call and the files they read (issue 28,
items 3 and 4): the methods of substitution objects, builders over ``pathlib`` paths, launch
actions subclassed in a workspace module, for :mod:`.test_fixtures` to compare with the
oracle (which has the fixture's package on its ``PYTHONPATH``)."""

from __future__ import annotations

Case = tuple[dict[str, str], list[dict[str, str]]]

CASES: dict[str, Case] = {
    "python-find-package-method": (
        {
            "main.launch.py": """import os
from launch import LaunchDescription
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackagePrefix, FindPackageShare


def generate_launch_description():
    share = FindPackageShare('pkg').find('pkg')
    prefix = FindPackagePrefix(package='pkg').find(package_name='pkg')
    return LaunchDescription([
        Node(package='pkg', executable='talker', name='t',
             parameters=[{'share': os.path.join(share, 'config'), 'prefix': prefix}]),
    ])
"""
        },
        [{}],
    ),
    "python-subclassed-launch-actions": (
        {
            "pkg_helpers/__init__.py": "",
            "pkg_helpers/launch_utils.py": """from launch.actions import DeclareLaunchArgument
from launch.conditions import IfCondition, UnlessCondition
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


class DeclareBooleanLaunchArg(DeclareLaunchArgument):
    def __init__(self, name, *, default_value=False, description=None, **kwargs):
        super().__init__(
            name,
            default_value=str(default_value),
            description=description,
            choices=['true', 'false', 'True', 'False'],
            **kwargs,
        )


class PlainNode(Node):
    pass


class DebugNode(Node):
    def __init__(self, flag, **kwargs):
        super().__init__(condition=IfCondition(LaunchConfiguration(flag)), **kwargs)
        self.flag = flag


def add_debuggable(ld, executable):
    ld.add_action(Node(package='pkg', executable=executable,
                       condition=UnlessCondition(LaunchConfiguration('debug'))))
    ld.add_action(DebugNode('debug', package='pkg', executable=executable,
                            name='debug_' + executable))
""",
            "main.launch.py": """from launch import LaunchDescription
from pkg_helpers.launch_utils import DeclareBooleanLaunchArg, PlainNode, add_debuggable


def generate_launch_description():
    ld = LaunchDescription()
    ld.add_action(DeclareBooleanLaunchArg('debug', default_value=False))
    ld.add_action(DeclareBooleanLaunchArg('extra', default_value=True))
    add_debuggable(ld, 'talker')
    ld.add_action(PlainNode(package='pkg', executable='listener', name='plain'))
    return ld
""",
        },
        [{}, {"debug": "true"}, {"debug": "False", "extra": "false"}],
    ),
}
