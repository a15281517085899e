"""Regenerate the bundled catalogue of third-party ROS 1 node interfaces.

Runs rosvar's own extractor on public sources: each repository below is expected as a
mirror (``/work/.mirror/OWNER+NAME/repo``, a bare git directory as the ``fetch`` tool leaves
it, or any clone given with ``--mirrors``); the named branch is exported to a temporary folder
(nothing fetched is kept or committed), its packages are extracted, and every entry's file
becomes a permanent URL at the exported commit. Review the result by hand before committing:

    python tools/build_catalogue.py > src/rosvar/workspace/interfaces/catalogue/ros1.json
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile

from rosvar.workspace import discover
from rosvar.workspace.interfaces.extraction import extract_interfaces

SOURCES: list[tuple[str, str, list[str]]] = [
    # repository, ROS 1 branch, folders holding the packages ("" = the repository's root):
    # every package that a launch file of the corpus (its four systems and _external) starts
    # a node of, ordered by how often, whose sources the corpus does not hold
    ("ros/robot_state_publisher", "melodic-devel", [""]),
    ("ros/joint_state_publisher", "noetic-devel", ["joint_state_publisher"]),
    ("ros-simulation/gazebo_ros_pkgs", "melodic-devel", ["gazebo_ros"]),
    ("ros-planning/navigation", "melodic-devel", ["amcl", "map_server", "move_base"]),
    ("ros-perception/slam_gmapping", "melodic-devel", ["gmapping"]),
    ("ros-drivers/joystick_drivers", "melodic-devel", ["joy"]),
    ("ros/diagnostics", "noetic-devel", ["diagnostic_aggregator"]),
    ("ros/geometry", "melodic-devel", ["tf"]),
    ("ros/geometry2", "melodic-devel", ["tf2_ros"]),
    ("ros/ros_comm", "melodic-devel", ["tools/topic_tools"]),
    ("ros-controls/ros_control", "melodic-devel", ["controller_manager"]),
    ("ros-perception/image_pipeline", "melodic", ["image_proc", "depth_image_proc"]),
    ("ros-perception/image_common", "noetic-devel", ["image_transport"]),
    ("ros-planning/robot_pose_ekf", "master", [""]),
    ("ros-perception/depthimage_to_laserscan", "melodic-devel", [""]),
    ("ros-perception/pointcloud_to_laserscan", "lunar-devel", [""]),
    ("cra-ros-pkg/robot_localization", "melodic-devel", [""]),
    ("ros-teleop/twist_mux", "melodic-devel", [""]),
    ("ros-teleop/teleop_twist_joy", "melodic-devel", [""]),
    ("ros-drivers/urg_node", "melodic-devel", [""]),
    ("CCNYRoboticsLab/imu_tools", "melodic", ["imu_filter_madgwick"]),
    ("ros-perception/imu_pipeline", "noetic-devel", ["imu_transformer"]),
    ("tu-darmstadt-ros-pkg/hector_slam", "melodic-devel", ["hector_mapping"]),
    ("ros-visualization/interactive_marker_twist_server", "kinetic-devel", [""]),
]

SKIPPED = [":(exclude,glob)**/test/**", ":(exclude,glob)**/*.bag"]
"""Tests are no launched nodes; large files may be absent from a mirror."""

REVIEWED_ROLES = (
    "publishes",
    "subscribes",
    "services",
    "clients",
    "action_servers",
    "action_clients",
    "params",
)
REVIEW: dict[tuple[str, str], dict[str, list[dict[str, object]]]] = {
    # Found by reading the sources, for what the extractor cannot see (tf broadcasters,
    # urdf's initParam); each with the line that does it.
    ("robot_state_publisher", "robot_state_publisher"): {
        "publishes": [
            {
                "name": "/tf",
                "type": "tf2_msgs/TFMessage",
                "file": "src/robot_state_publisher.cpp",
                "line": 141,
            },
            {
                "name": "/tf_static",
                "type": "tf2_msgs/TFMessage",
                "file": "src/robot_state_publisher.cpp",
                "line": 163,
            },
        ],
        "params": [
            {
                "name": "robot_description",
                "default": None,
                "file": "src/robot_state_publisher_node.cpp",
                "line": 58,
            },
        ],
    },
}


def _git(directory: str, *arguments: str) -> bytes:
    return subprocess.run(
        ["git", "--git-dir", directory, *arguments], check=True, capture_output=True
    ).stdout


def build(mirrors: str) -> dict[str, object]:
    nodes: list[dict[str, object]] = []
    for repository, branch, folders in SOURCES:
        directory = os.path.join(mirrors, repository.replace("/", "+"), "repo")
        commit = _git(directory, "rev-parse", branch).decode().strip()
        with tempfile.TemporaryDirectory() as checkout:
            paths = [folder for folder in folders if folder] or ["."]
            archive = _git(directory, "archive", "--format=tar", commit, *paths, *SKIPPED)
            subprocess.run(["tar", "-x", "-C", checkout], input=archive, check=True)
            roots = [os.path.join(checkout, folder) for folder in folders]
            packages = discover(roots, ros_package_path="").packages.values()
            interfaces = extract_interfaces(packages)
            for diagnostic in interfaces.diagnostics:
                print(f"{repository}: {diagnostic}", file=sys.stderr)
            for node in interfaces.nodes:
                document = node.to_json()
                for role, entries in REVIEW.get((node.package, node.executable), {}).items():
                    added = document[role]
                    assert isinstance(added, list)
                    added.extend(
                        {**e, "file": os.path.join(checkout, str(e["file"]))} for e in entries
                    )
                document["repository"] = f"https://github.com/{repository}"
                document["commit"] = commit
                for key, value in document.items():
                    if key in REVIEWED_ROLES and isinstance(value, list):
                        for entry in value:
                            relative = os.path.relpath(entry["file"], checkout)
                            entry["file"] = (
                                f"https://github.com/{repository}/blob/{commit}/{relative}"
                            )
                            entry["origin"] = "catalogue"
                nodes.append(document)
    return {"catalogue": nodes}


def main() -> int:
    options = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    options.add_argument("--mirrors", default="/work/.mirror", help="folder of the mirrors")
    arguments = options.parse_args()
    print(json.dumps(build(arguments.mirrors), indent=1, ensure_ascii=False))
    return 0


if __name__ == "__main__":
    sys.exit(main())
