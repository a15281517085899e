"""Every public name of launch and launch_ros is modelled or reported with its reason: the
``__all__`` lists of jazzy's packages (read with ``ast`` from ``../shared/ros2-oracle``, never
imported), rolling's names beyond them, and the frontends' ``@expose_action`` and
``@expose_substitution`` names. A name launch adds cannot slip by: this test then fails."""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

from ros2.api.upstream import UPSTREAM, exposed_by_upstream
from ros2.tags.launches import launch
from rosvar.ros2 import boolean_substitutions  # noqa: F401 - registers their handlers
from rosvar.ros2.api.actions import ACTIONS
from rosvar.ros2.api.conditions import CONDITIONS
from rosvar.ros2.api.registry import PythonName, python_name
from rosvar.ros2.api.sources import SOURCES
from rosvar.ros2.api.unmodelled import UNMODELLED
from rosvar.ros2.frontends.python.calls import CALLS
from rosvar.ros2.frontends.python.interpreter import CALLING
from rosvar.ros2.frontends.python.parser import parse_python_launch_bytes
from rosvar.ros2.substitutions import HANDLERS

SUBPACKAGES = {
    "launch": (
        "actions",
        "conditions",
        "descriptions",
        "event_handlers",
        "events",
        "events/process",
        "launch_description_sources",
        "substitutions",
    ),
    "launch_ros": (
        "actions",
        "descriptions",
        "event_handlers",
        "events",
        "events/lifecycle",
        "substitutions",
    ),
    "launch_xml": ("launch_description_sources",),
    "launch_yaml": ("launch_description_sources",),
}
"""The packages whose ``__all__`` lists the names a launch file uses."""

ROLLING = {
    ("launch", "ForEach"),
    ("launch", "ForLoop"),
    ("launch", "ScopedIncludeLaunchDescription"),
}
"""Names rolling's launch exports beyond jazzy's (its ``launch/actions/__init__.py``;
launch_ros' lists are jazzy's)."""


def _all(init: Path) -> list[str]:
    for node in ast.parse(init.read_text(encoding="utf-8")).body:
        if isinstance(node, ast.Assign) and any(
            isinstance(target, ast.Name) and target.id == "__all__" for target in node.targets
        ):
            value = ast.literal_eval(node.value)
            assert isinstance(value, list | tuple)
            return [str(name) for name in value]
    return []


def public_names() -> set[PythonName]:
    """Each name of the packages' and their subpackages' ``__all__``, modules left out."""
    found: set[PythonName] = set()
    for package, subpackages in SUBPACKAGES.items():
        root = UPSTREAM / package / package
        for module in ("", *subpackages):
            for name in _all(root / module / "__init__.py"):
                if f"{module}/{name}".lstrip("/") in subpackages:
                    continue  # a subpackage, walked itself
                found.add((package, name))
    return found


def modelled(key: PythonName) -> bool:
    return key in CALLS or key in CALLING or key in CONDITIONS.by_python or key in SOURCES.by_python


@pytest.mark.skipif(not UPSTREAM.is_dir(), reason="no ROS 2 oracle")
def test_every_public_name_is_modelled_or_reported() -> None:
    names = public_names() | ROLLING
    assert len(names) > 120  # the lists were read
    reported = set(UNMODELLED.by_python)
    neither = sorted(key for key in names if not modelled(key) and key not in reported)
    assert neither == [], "neither modelled nor reported"
    both = sorted(key for key in names if modelled(key) and key in reported)
    assert both == [], "modelled and reported"


@pytest.mark.skipif(not UPSTREAM.is_dir(), reason="no ROS 2 oracle")
def test_every_frontend_name_is_modelled_or_reported() -> None:
    actions = exposed_by_upstream("action")
    assert actions <= {name for action in ACTIONS if action.walked for name in action.names}
    substitutions = exposed_by_upstream("substitution") | {"test"}  # launch_testing's
    reported = set(UNMODELLED.by_name)
    neither = sorted(name for name in substitutions if name not in set(HANDLERS) | reported)
    assert neither == [], "neither modelled nor reported"
    assert not reported & set(HANDLERS), "modelled and reported"


def test_a_reason_names_the_name_and_its_kind() -> None:
    coroutine = UNMODELLED.by_python[python_name("launch.actions.OpaqueCoroutine")]
    assert coroutine.why().startswith("OpaqueCoroutine (action: runs a coroutine")
    assert UNMODELLED.by_name["log_dir"].why().startswith("$(launch_log_dir) (substitution: ")


def test_python_names_not_modelled_are_reported_with_their_reason() -> None:
    source = b"""from launch import LaunchDescription
from launch.actions import OpaqueCoroutine, UnsetLaunchConfiguration


def generate_launch_description():
    return LaunchDescription([OpaqueCoroutine(coroutine=None), UnsetLaunchConfiguration('x')])
"""
    result = parse_python_launch_bytes(source, "/w/p/launch/a.launch.py")
    messages = [(d.code, d.message, d.location.line) for d in result.diagnostics]
    assert messages == [
        (
            "python-not-followed",
            "OpaqueCoroutine (action: runs a coroutine on the launch's event loop, which is "
            "never run) is not followed",
            6,
        ),
        (
            "python-not-followed",
            "UnsetLaunchConfiguration (action: removes a launch configuration by name, which "
            "only the Python API can) is not followed",
            6,
        ),
    ]


def test_frontend_substitutions_not_modelled_fail_with_their_reason(tmp_path: Path) -> None:
    it = launch(
        tmp_path,
        """<launch>
  <node pkg="pkg" exec="x" name="b" args="$(log_dir)"/>
</launch>""",
    )
    errors = [(e.code, e.message) for e in it.model.errors]
    assert errors == [
        (
            "substitution-unsupported",
            "<node> attribute 'args': $(launch_log_dir) (substitution: the launch's log folder "
            "(~/.ros/log/<date>-<host>-<pid>), known only when the launch runs) is not modelled",
        ),
    ]
