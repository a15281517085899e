"""The variational model of ROS 2 files against the real ros2/launch (the oracle): each
file is interpreted once over every command line, then restricted to sampled arguments
(given samples and combinations of the values in the arguments' domains)."""

from __future__ import annotations

import itertools
import random
from collections.abc import Iterator, Mapping
from pathlib import Path

import pytest

from oracle.ros2_client import (
    ORACLE,
    canonical_nodes,
    requires_ros2_oracle,
    resolution_nodes,
    run_oracle,
)
from rosvar.interpreter import substitution_args
from rosvar.interpreter.workspace_models import Analysis
from rosvar.logic.inputs import OTHER
from rosvar.workspace import discover

from .test_fixtures import CASES, LENIENT, _workspace, entries

pytestmark = requires_ros2_oracle

DATA = Path(__file__).resolve().parents[2] / "data" / "ros2"
EXAMPLE = ORACLE / "examples" / "pkgs"
PER_FILE = 6  # sampled configurations per file, beyond the given ones


def configurations(
    analysis: Analysis, file: str, given: list[dict[str, str]]
) -> Iterator[dict[str, str]]:
    """The given samples (those setting only declared arguments: the model's inputs), then
    samples of the domains' literal values seeded by the file's name, each argument also left
    out."""
    model = analysis.model(file)
    yield from (sample for sample in given if set(sample) <= set(model.inputs))
    choices = [
        [(name, slot) for slot in domain if slot is not OTHER]
        for name, domain in model.domains.items()
    ]
    combinations = list(itertools.islice(itertools.product(*choices), 10_000))
    rng = random.Random(Path(file).name)  # the same samples in every checkout (issue 30)
    for combination in rng.sample(combinations, min(PER_FILE, len(combinations))):
        yield {name: slot for name, slot in combination if isinstance(slot, str)}  # not UNSET


def check(
    analysis: Analysis, file: Path, arguments: Mapping[str, str], packages: Path, strict: bool
) -> None:
    expected = run_oracle(file, arguments, [packages], strict=strict)
    result = analysis.resolve([str(file)], arguments)
    assert result.ok == expected["ok"], (arguments, expected.get("error"), result.errors)
    if result.ok:
        assert canonical_nodes(resolution_nodes(result)) == canonical_nodes(expected), arguments


@pytest.mark.parametrize("case", sorted(CASES))
def test_fixture_restricted_matches_the_oracle(case: str, tmp_path: Path) -> None:
    files, given = CASES[case]
    package = _workspace(tmp_path, files)
    values: dict[str, list[str]] = {}
    for sample in given:  # given values are known slots, as `rosvar resolve` makes them
        for name, value in sample.items():
            values.setdefault(name, []).append(value)
    analysis = Analysis(discover([str(package.parent)]), extra_values=values)
    for main in entries(package):
        for arguments in configurations(analysis, str(main), given):
            check(analysis, main, arguments, package.parent, strict=case not in LENIENT)


@pytest.mark.parametrize(
    "case",
    [
        "conditions-over-the-work-limits-once-bound",
        "python-path-join-of-choices",
        "command-line-words-with-spaces",
        "path-joins-of-joined-values",
        "workspace-substitutions-of-joined-values",
    ],
)
def test_values_given_up_are_computed_in_each_configuration(
    case: str, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """With one text's combinations bounded to 4, the model gives up these fixtures' joined
    texts, ``$(eval)``s, path joins and command-line words (each of several arguments of three
    values); one configuration computes each again from the values that hold there, as the
    oracle."""
    monkeypatch.setattr(substitution_args, "MAX_COMBINATIONS", 4)
    test_fixture_restricted_matches_the_oracle(case, tmp_path)


@pytest.mark.parametrize(
    "case",
    ["namespaces-pushed-from-values", "command-line-words-with-spaces", "names-launch-ros-refuses"],
)
def test_values_no_file_names_are_computed_in_each_configuration(case: str, tmp_path: Path) -> None:
    """Values outside every domain (the ``<other>`` value a text typed in ``rosvar
    configure`` takes) are terms of the model, pushed namespaces and command-line words
    included; one configuration computes them, as the oracle."""
    files, given = CASES[case]
    package = _workspace(tmp_path, files)
    analysis = Analysis(discover([str(package.parent)]))
    for main in entries(package):
        for arguments in given:
            check(analysis, main, arguments, package.parent, strict=True)


@pytest.mark.parametrize("suffix", [".launch.xml", ".launch.yaml", ".launch.py"])
def test_example_restricted_matches_the_oracle(suffix: str) -> None:
    analysis = Analysis(discover([str(EXAMPLE)]))
    file = EXAMPLE / "demo_pkg" / "launch" / f"top{suffix}"
    samples = list(configurations(analysis, str(file), []))
    assert len(samples) > 1
    for arguments in samples:
        check(analysis, file, arguments, EXAMPLE, strict=False)


AGREEING = [  # real files the oracle loads whose nodes rosvar gives (docs/known-differences.md)
    "clearpath_common/clearpath_control/launch/localization.launch.py",
    "clearpath_common/clearpath_control/launch/teleop_joy.launch.py",
    "clearpath_common/clearpath_manipulators_description/launch/description.launch.py",
    "clearpath_common/clearpath_platform_description/launch/description.launch.py",
    "husky/husky_base/launch/base.launch.py",
    "husky/husky_bringup/launch/accessories.launch.py",
    "husky/husky_control/launch/control.launch.py",
    "husky/husky_control/launch/teleop_base.launch.py",
    "husky/husky_control/launch/teleop_joy.launch.py",
    "husky/husky_gazebo/launch/gazebo.launch.py",
    "husky/husky_gazebo/launch/husky_playpen.launch.py",
    "husky/husky_viz/launch/view_robot_launch.py",
    "moveit2_tutorials/doc/examples/planning_scene_ros_api/launch/"
    "planning_scene_ros_api_tutorial.launch.py",
    "ros2_control_demos/example_17/bringup/launch/rrbot.launch.xml",
    "ros2_control_demos/example_17/bringup/launch/test_forward_position_controller.launch.xml",
    "ros2_control_demos/example_17/bringup/launch/test_joint_trajectory_controller.launch.xml",
    "ros2_control_demos/example_17/description/launch/view_robot.launch.xml",
    "ros2_control_demos/example_2/bringup/launch/diffbot.launch.xml",
    "ros2_control_demos/example_3/bringup/launch/rrbot_system_multi_interface.launch.py",
    "ros2_control_demos/example_7/bringup/launch/send_trajectory.launch.py",
    "ros2_control_demos/example_7/description/launch/view_r6bot.launch.py",
    "realsense-ros/realsense2_camera/examples/align_depth/rs_align_depth_launch.py",
    "realsense-ros/realsense2_camera/examples/dual_camera/rs_dual_camera_launch.py",
    "realsense-ros/realsense2_camera/examples/pointcloud/rs_pointcloud_launch.py",
    "realsense-ros/realsense2_camera/launch/rs_launch.py",
    "realsense-ros/realsense2_camera/launch/rs_multi_camera_launch.py",
    "slam_toolbox/launch/lifelong_launch.py",
    "slam_toolbox/launch/localization_launch.py",
    "slam_toolbox/launch/merge_maps_kinematic_launch.py",
    "slam_toolbox/launch/offline_launch.py",
    "slam_toolbox/launch/online_async_launch.py",
    "slam_toolbox/launch/online_sync_launch.py",
]


@pytest.mark.parametrize("relative", AGREEING)
def test_real_file_restricted_matches_the_oracle(relative: str) -> None:
    repository = DATA / relative.split("/")[0]
    analysis = Analysis(discover([str(repository)]))
    file = DATA / relative
    for arguments in configurations(analysis, str(file), []):
        check(analysis, file, arguments, repository, strict=False)
