"""Inline ROS 2 launch files for the tests of the tags: one package in a throw-away workspace,
its model over every command line, and rosvar against the real ros2/launch (the oracle) for
given launch arguments: the variational model restricted to them (``rosvar resolve``'s
resolution, where they are known values, and the model over every command line) must
start what the oracle starts, or fail where it fails."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import pytest

from differential.ros2.test_fixtures import PACKAGE_XML
from oracle.ros2_client import ORACLE, canonical_nodes, resolution_nodes, run_oracle
from rosvar.interpreter.model import LaunchModel
from rosvar.interpreter.workspace_models import Analysis
from rosvar.logic.bdd import BDD
from rosvar.logic.inputs import Slot
from rosvar.ros.version import RosVersion
from rosvar.workspace import discover


@dataclass
class Launch:
    """``main`` (and the files beside it) in package ``pkg``, analysed over every command
    line (arguments in ``values`` are known values of their domains)."""

    analysis: Analysis
    main: Path

    @property
    def model(self) -> LaunchModel:
        return self.analysis.model(str(self.main))

    def implies(self, condition: BDD, then: BDD) -> bool:
        """Whether every valid configuration (one value per input) satisfying ``condition``
        satisfies ``then``."""
        return self.analysis.space.valid_implies(~condition | then)

    def same(self, condition: BDD, other: BDD) -> bool:
        """Whether the two hold in the same valid configurations."""
        return self.implies(condition, other) and self.implies(other, condition)

    def never(self, condition: BDD) -> bool:
        """Whether no valid configuration satisfies ``condition``."""
        return not self.analysis.space.satisfiable(condition)

    def given(self, name: str, value: Slot) -> BDD:
        """Where the command line gives ``name:=value`` (or leaves it out: ``UNSET``, or
        gives a value the files do not name: ``OTHER``)."""
        return self.analysis.space.slot(self.model.inputs[name], value)

    def matches_oracle(self, arguments: Mapping[str, str], strict: bool = True) -> dict[str, Any]:
        """The oracle's result for ``arguments``, after checking that rosvar's model
        restricted to them agrees with it (success and the nodes started, or failure)."""
        if not ORACLE.is_dir():
            pytest.skip(f"the ROS 2 oracle {ORACLE} is absent")
        expected = run_oracle(self.main, arguments, [self.main.parent.parent], strict=strict)
        workspace = self.analysis.workspace
        # the given values are known values of the model, as `rosvar resolve` makes them
        known = Analysis(workspace, extra_values={k: [v] for k, v in arguments.items()})
        # and the model over every command line restricted to them (a value no file names is
        # its argument's other value there)
        for analysis in (known, self.analysis):
            result = analysis.resolve([str(self.main)], arguments)
            assert result.ok == expected["ok"], (arguments, expected.get("error"), result.errors)
            if result.ok:
                nodes = canonical_nodes(resolution_nodes(result))
                assert nodes == canonical_nodes(expected), arguments
        return expected


def launch(
    tmp_path: Path,
    main: str,
    suffix: str = ".launch.xml",
    files: Mapping[str, str] | None = None,
    values: Mapping[str, list[str]] | None = None,
) -> Launch:
    package = tmp_path / "ws" / "pkg"
    package.mkdir(parents=True)
    (package / "package.xml").write_text(PACKAGE_XML)
    for name, text in (files or {}).items():
        (package / name).write_text(text)
    entry = package / f"main{suffix}"
    entry.write_text(main)
    workspace = discover([str(package.parent)])
    assert workspace.ros_version is RosVersion.ROS2
    return Launch(Analysis(workspace, extra_values=values), entry)
