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
}
