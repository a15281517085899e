"""The analysis of a workspace's launch files (:mod:`rosvar.interpreter.workspace_models`)."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

NAMES = [f"arg_{letter}{index}" for index in range(4) for letter in "qzam"]


def test_args_read_before_an_include_declares_them_keep_one_order(tmp_path: Path) -> None:
    """ROS 2 args that an included file declares and the entry file reads before are
    interpreted again as the command line's: their order (the inputs', the feature model's)
    is the same whatever the hash seed, which orders Python's sets of strings."""
    package = tmp_path / "p"
    package.mkdir()
    (package / "package.xml").write_text(
        "<package format='3'><name>p</name>"
        "<export><build_type>ament_cmake</build_type></export></package>"
    )
    declared = "".join(f'<arg name="{name}" default="x"/>' for name in NAMES)
    nodes = "".join(f'<node pkg="p" exec="e" name="{name}" if="$(var {name})"/>' for name in NAMES)
    (package / "inc.launch.xml").write_text(f"<launch>{declared}{nodes}</launch>")
    read = "".join(f'<let name="c_{name}" value="$(var {name} d)"/>' for name in NAMES)
    include = '<include file="$(dirname)/inc.launch.xml"/>'
    (package / "entry.launch.xml").write_text(f"<launch>{read}{include}</launch>")
    outputs = {
        subprocess.run(
            [sys.executable, "-m", "rosvar", "features", str(tmp_path), "--format", "uvl"],
            capture_output=True,
            text=True,
            check=True,
            env={**os.environ, "PYTHONHASHSEED": str(seed)},
        ).stdout
        for seed in range(1, 5)
    }
    assert len(outputs) == 1
    (uvl,) = outputs
    assert all(f"entry%2Elaunch%2Exml:{name}=true" in uvl for name in NAMES)
