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
    # repository, ROS 1 branch, folders holding the packages ("" = the repository's root)
    ("ros/robot_state_publisher", "noetic-devel", [""]),
    ("ros-drivers/joystick_drivers", "melodic-devel", ["joy"]),
]


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
            archive = _git(directory, "archive", "--format=tar", commit, *[f for f in folders if f])
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
