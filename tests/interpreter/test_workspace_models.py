"""The analysis of a workspace's launch files (:mod:`rosvar.interpreter.workspace_models`)."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from collections import Counter
from collections.abc import Mapping
from pathlib import Path

import pytest

from rosvar.interpreter.model import LaunchModel
from rosvar.interpreter.workspace_models import Analysis
from rosvar.outputs.describe import describe_model
from rosvar.workspace import discover
from workspace.interfaces.ros2_packages import MANIFEST

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


def test_an_entry_file_is_interpreted_again_only_for_late_names(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Each pass of ``Analysis._interpret`` walks the whole include tree again (on
    ros2dense-120 the passes thrown away were half the CPU): an entry file is interpreted
    once unless an included file's arg is read before its declaration, then once more with
    it an input from the start. A change that saves a pass lowers these counts."""
    package = tmp_path / "p"
    package.mkdir()
    (package / "package.xml").write_text(MANIFEST.format(name="p", build="ament_cmake"))
    (package / "inc.launch.xml").write_text(
        '<launch><arg name="late" default="x"/><arg name="other" default="y"/>'
        '<node pkg="p" exec="e" name="n_$(var late)_$(var other)"/></launch>'
    )
    include = '<include file="$(dirname)/inc.launch.xml"/>'
    (package / "once.launch.xml").write_text(f"<launch>{include}{include}</launch>")
    (package / "twice.launch.xml").write_text(
        f'<launch><let name="seen" value="$(var late d)"/>{include}</launch>'
    )
    passes: Counter[str] = Counter()
    interpret_with = Analysis._interpret_with

    def counted(
        self: Analysis, file: str, undeclared: Mapping[str, str]
    ) -> tuple[LaunchModel, set[str]]:
        passes[Path(file).name] += 1
        return interpret_with(self, file, undeclared)

    monkeypatch.setattr(Analysis, "_interpret_with", counted)
    analysis = Analysis(discover([tmp_path], ros_package_path=""))
    models = {Path(model.file).name: model for model in analysis.all_models()}
    assert passes == {"inc.launch.xml": 1, "once.launch.xml": 1, "twice.launch.xml": 2}
    assert {"late", "other"} <= models["twice.launch.xml"].inputs.keys()


def test_a_late_name_set_on_a_path_has_one_branch_order_in_both_passes(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """An includer sets ``late`` on a path before the included file declares it, and a second
    declaration finds it unset (no default where the command line does not give it): the
    first pass builds its value over the unset one at the declaration, the second over the
    command line's from the start. Both must order the branches alike, so that a pass
    that gives the same model gives it in the same order."""
    package = tmp_path / "p"
    package.mkdir()
    (package / "package.xml").write_text(MANIFEST.format(name="p", build="ament_cmake"))
    (package / "inc.launch.xml").write_text(
        '<launch><arg name="late"/><node pkg="p" exec="e" name="n_$(var late)"/></launch>'
    )
    (package / "again.launch.xml").write_text('<launch><arg name="late"/></launch>')
    inc = '<include file="$(dirname)/inc.launch.xml"'
    (package / "entry.launch.xml").write_text(
        '<launch><arg name="on" default="true"/>'
        f'{inc} if="$(var on)"><arg name="late" value="zzz"/></include>'
        '<include file="$(dirname)/again.launch.xml"/>'
        f'{inc} unless="$(var on)"><arg name="late" value="aaa"/></include></launch>'
    )
    described: list[str] = []
    interpret_with = Analysis._interpret_with

    def kept(
        self: Analysis, file: str, undeclared: Mapping[str, str]
    ) -> tuple[LaunchModel, set[str]]:
        model, late = interpret_with(self, file, undeclared)
        if Path(file).name == "entry.launch.xml":
            described.append(json.dumps(describe_model(model), default=str))
        return model, late

    monkeypatch.setattr(Analysis, "_interpret_with", kept)
    Analysis(discover([tmp_path], ros_package_path="")).model(str(package / "entry.launch.xml"))
    assert len(described) == 2  # the second declaration makes "late" late
    first, second = described
    assert "n_zzz" in first and "n_aaa" in first
    assert first == second
