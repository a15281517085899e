"""The oracle's own example (``../shared/ros2-oracle/examples``) through rosvar and the
oracle, for every combination of its launch arguments."""

from __future__ import annotations

import itertools

import pytest

from oracle.ros2_client import (
    ORACLE,
    canonical_nodes,
    requires_ros2_oracle,
    resolution_nodes,
    run_oracle,
)
from rosvar.interpreter.workspace_models import Analysis
from rosvar.workspace import discover

pytestmark = requires_ros2_oracle

PACKAGES = ORACLE / "examples" / "pkgs"
KEYS = (
    "kind",
    "package",
    "executable",
    "plugin",
    "container",
    "name",
    "namespace",
    "remappings",
    "parameters",
    "arguments",
)
SAMPLES = [
    {"sim": sim, "second": second}
    for sim, second in itertools.product(("true", "false"), ("true", "false"))
]


@pytest.mark.parametrize("suffix", [".launch.xml", ".launch.yaml", ".launch.py"])
@pytest.mark.parametrize("arguments", SAMPLES, ids=lambda a: ",".join(a.values()))
def test_example_matches_the_oracle(suffix: str, arguments: dict[str, str]) -> None:
    file = PACKAGES / "demo_pkg" / "launch" / f"top{suffix}"
    expected = run_oracle(file, arguments, [PACKAGES], strict=False)
    assert expected["ok"] and not expected["unresolved_includes"]
    analysis = Analysis(
        discover([str(PACKAGES)]), extra_values={k: [v] for k, v in arguments.items()}
    )  # the given values as known slots, as `rosvar resolve` makes them
    result = analysis.resolve([str(file)], arguments)
    assert result.ok, result.errors
    assert canonical_nodes(resolution_nodes(result)) == canonical_nodes(expected)
