"""Write the outputs of every rosvar command on the corpus systems into a folder.

Refactorings must leave them byte-identical: run this before and after a change and compare
the two folders (``diff -r``). Runs the sources of this checkout (``src``) with the current
Python; the ROS 1 corpus is ``../shared/corpus`` beside the repository, the ROS 2 workspaces
are this checkout's ``tests/data/ros2``.

    python tools/snapshot_outputs.py OUT_DIR
"""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
CORPUS = (ROOT.parent / "shared" / "corpus").resolve()
EXTERNAL = CORPUS / "_external"
SYSTEMS = ("kobuki", "turtlebot2", "lizi", "husky")

RUNS: dict[str, list[str]] = {}
for system in SYSTEMS:
    path = str(CORPUS / system)
    RUNS[f"{system}.analyze.json"] = ["analyze", path, "--json"]
    RUNS[f"{system}.analyze.txt"] = ["analyze", path]
    for fmt in ("text", "json", "uvl", "featureide", "dot"):
        RUNS[f"{system}.features.{fmt}"] = ["features", path, "--format", fmt]
    RUNS[f"{system}.metrics.json"] = ["metrics", path, "--json"]
    RUNS[f"{system}.metrics.txt"] = ["metrics", path]
    RUNS[f"{system}.configure.finish.json"] = ["configure", path, "--finish", "--json"]
    RUNS[f"{system}.configure.txt"] = ["configure", path]
for system in ("kobuki", "husky"):
    path = str(CORPUS / system)
    RUNS[f"{system}.check.json"] = ["check", path, "--format", "json"]
    RUNS[f"{system}.query.nodes.json"] = ["query", path, "nodes", "--json"]

ROS2 = ROOT / "tests" / "data" / "ros2"
ROS2_SYSTEMS = (
    "clearpath_common",
    "husky",
    "moveit2_tutorials",
    "realsense-ros",
    "ros2_control_demos",
    "slam_toolbox",
)
for system in ROS2_SYSTEMS:
    path = str(ROS2 / system)
    name = f"ros2.{system}"
    RUNS[f"{name}.analyze.json"] = ["analyze", path, "--json"]
    RUNS[f"{name}.analyze.txt"] = ["analyze", path]
    for fmt in ("text", "json", "uvl"):
        RUNS[f"{name}.features.{fmt}"] = ["features", path, "--format", fmt]
    RUNS[f"{name}.metrics.json"] = ["metrics", path, "--json"]
    RUNS[f"{name}.configure.finish.json"] = ["configure", path, "--finish", "--json"]
    RUNS[f"{name}.configure.txt"] = ["configure", path]
    RUNS[f"{name}.check.json"] = ["check", path, "--format", "json"]
    for query in ("nodes", "params", "topics"):
        RUNS[f"{name}.query.{query}.json"] = ["query", path, query, "--json"]
DEMOS = ROS2 / "ros2_control_demos"
RRBOT = str(DEMOS / "example_1/bringup/launch/rrbot.launch.py")
RUNS["ros2.ros2_control_demos.resolve.rrbot.txt"] = ["resolve", str(DEMOS), "--launch", RRBOT]
RUNS["ros2.ros2_control_demos.resolve.rrbot.json"] = [
    "resolve",
    str(DEMOS),
    "--launch",
    RRBOT,
    "gui:=false",
    "--json",
]
RUNS["ros2.ros2_control_demos.resolve.xml.json"] = [
    "resolve",
    str(DEMOS),
    "--launch",
    str(DEMOS / "example_2/bringup/launch/diffbot.launch.xml"),
    "--json",
]

HUSKY = CORPUS / "husky" / "husky"
RUNS["husky.resolve.spawn.json"] = [
    "resolve",
    str(CORPUS / "husky"),
    "multimaster:=false",
    "--launch",
    str(HUSKY / "husky_gazebo/launch/spawn_husky.launch"),
    "--env",
    "ENABLE_EKF=false",
    "--json",
]
RUNS["husky.resolve.gmapping.txt"] = [
    "resolve",
    str(CORPUS / "husky"),
    "--launch",
    "husky_navigation",
    "gmapping_demo.launch",
]
PLAYPEN = str(HUSKY / "husky_gazebo/launch/husky_playpen.launch")
RUNS["husky.configure.playpen.json"] = [
    "configure",
    str(CORPUS / "husky"),
    "--select",
    PLAYPEN,
    "--json",
]
RUNS["husky.configure.playpen.finish.txt"] = [
    "configure",
    str(CORPUS / "husky"),
    "--select",
    PLAYPEN,
    "--finish",
]
KOBUKI = str(CORPUS / "kobuki")
RUNS["kobuki.resolve.all.json"] = [
    "resolve",
    KOBUKI,
    "--json",
    "--launch",
    "kobuki_node",
    "minimal.launch",
]


def main() -> int:
    out = Path(sys.argv[1])
    out.mkdir(parents=True, exist_ok=True)
    env = dict(os.environ, PYTHONPATH=str(ROOT / "src"), ROS_PACKAGE_PATH=str(EXTERNAL))
    for name, args in RUNS.items():
        done = subprocess.run(
            [sys.executable, "-m", "rosvar", *args], env=env, capture_output=True, cwd=ROOT
        )
        (out / name).write_bytes(done.stdout + f"\n[exit {done.returncode}]\n".encode())
        (out / (name + ".stderr")).write_bytes(done.stderr)
        print(f"{name}: exit {done.returncode}, {len(done.stdout)} bytes", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
