"""The registries of substitutions, conditions and description sources: one entry per
name, the ROS 2 dialect's substitution handlers for registered names only, and names the real
launch code exposes (read from its sources in ``../shared/ros2-oracle``)."""

from __future__ import annotations

import pytest

from ros2.api.upstream import UPSTREAM, exported_by_upstream, exposed_by_upstream
from rosvar.ros2.api.conditions import CONDITIONS
from rosvar.ros2.api.sources import SOURCES
from rosvar.ros2.api.substitutions import SUBSTITUTIONS
from rosvar.ros2.substitutions import HANDLERS, OWN, substitution


def test_every_substitution_handler_is_of_a_registered_name() -> None:
    assert set(HANDLERS) - OWN <= set(SUBSTITUTIONS.by_name)
    with pytest.raises(ValueError, match=r"\$\(nope\) is no substitution"):
        substitution("nope")
    with pytest.raises(ValueError, match=r"\$\(var\) has two handlers"):
        substitution("var")


def test_python_names_find_their_substitution() -> None:
    share = SUBSTITUTIONS.by_name["find-pkg-share"]
    assert SUBSTITUTIONS.by_python["launch_ros", "FindPackageShare"] is share
    assert SUBSTITUTIONS.by_python["ament_index_python", "get_package_share_directory"] is share
    assert SUBSTITUTIONS.by_python["os", "getenv"] is SUBSTITUTIONS.by_name["env"]
    assert CONDITIONS.by_python["launch", "LaunchConfigurationEquals"].compares
    assert CONDITIONS.by_python["launch", "LaunchConfigurationNotEquals"].attribute == "unless"
    assert CONDITIONS.by_python["launch", "UnlessCondition"].attribute == "unless"
    xml = SOURCES.by_python["launch_xml", "XMLLaunchDescriptionSource"]
    assert SOURCES.by_python["launch", "PythonLaunchDescriptionSource"] is xml


@pytest.mark.skipif(not UPSTREAM.is_dir(), reason="no ROS 2 oracle")
def test_the_real_launch_exposes_every_substitution_and_class() -> None:
    assert set(SUBSTITUTIONS.by_name) <= exposed_by_upstream("substitution")
    launch = {key for key in SUBSTITUTIONS.by_python if key[0].startswith("launch")}
    assert launch <= exported_by_upstream("substitutions", "launch", "launch_ros")
    assert set(CONDITIONS.by_python) <= exported_by_upstream("conditions", "launch")
    sources = exported_by_upstream(
        "launch_description_sources", "launch", "launch_xml", "launch_yaml"
    )
    assert set(SOURCES.by_python) <= sources
