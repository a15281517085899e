"""Text report: the counts, the tree with ✓ defaults, constraints with readable conditions,
core/dead features with their reasons and conflicts with their simplest trigger."""

from __future__ import annotations

from typing import TYPE_CHECKING

import pytest

from rosvar.analyses.feature_model import extraction
from rosvar.analyses.feature_model.model import FeatureModel
from rosvar.analyses.feature_model.operations import count_configurations
from rosvar.outputs.describe import count_text
from rosvar.outputs.exports import text
from rosvar.outputs.exports._common import conflicts

from .test_uvl import tricky

if TYPE_CHECKING:
    from conftest import LaunchWorkspace  # tests/conftest.py


def sections(report: str) -> dict[str, list[str]]:
    """Blocks separated by blank lines, keyed by their first line."""
    blocks = [block.splitlines() for block in report.strip().split("\n\n")]
    return {block[0]: block[1:] for block in blocks}


def test_examples(examples_model: FeatureModel) -> None:
    report = sections(text.write(examples_model))
    assert report["Feature model of examples"] == [
        "  4 launch files, 7 arg features, 18 values",
        "  3 constraints: 1 excludes (0 conditional), 2 requires (1 conditional)",
        "  798 valid configurations",
    ]
    tree = report["Tree (files optional, one value per arg, ✓ default)"]
    start = tree.index("    example/launch/control.xml")
    assert tree[start : start + 4] == [
        "    example/launch/control.xml",
        "      use_teleop (boolean)",
        "        ✓ true",
        "          false",
    ]
    constraints = report["Constraints"]
    assert constraints[0] == (
        "  requires example/launch/mapping.launch → example/launch/control.xml, when ¬sim"
    )
    assert "  excludes example/launch/control.xml ⊗ example/launch/teleop_only.launch, always" in (
        constraints
    )
    assert report["Core and dead features"] == [
        "  none: every feature can be selected and deselected"
    ]
    conflicts = report["Conflicts (name clashes)"]
    assert conflicts[0].startswith("  node /controller: example/launch/control.xml:6:3 and ")
    assert conflicts[1] == "    simplest trigger: control.xml:use_teleop=true"
    assert conflicts[-1] == "    simplest trigger: any values"


def test_corpus(model: FeatureModel) -> None:
    report = text.write(model)
    count = count_configurations(model)
    assert count is not None
    assert f"  {count_text(count)} valid configurations\n" in report
    for file in model.files:
        assert f"\n    {file.id}\n" in report
    assert report.count("\n    simplest trigger: ") == len(conflicts(model))


def test_dead_feature_with_reasons(dead_model: FeatureModel) -> None:
    report = sections(text.write(dead_model))
    assert report["Core and dead features"] == [
        "  dead pkg/launch/both.launch",
        "    because pkg/launch/both.launch includes pkg/launch/a.launch",
        "    because pkg/launch/both.launch includes pkg/launch/b.launch",
        "    because pkg/launch/a.launch and pkg/launch/b.launch both declare node /same",
    ]


def test_a_model_too_large_to_solve_is_reported_unknown(
    ws: LaunchWorkspace, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setattr(extraction, "LINK_BUDGET", 0)
    monkeypatch.setattr(extraction, "LINKS_PER_FILE", 0)
    model = tricky(ws)
    report = sections(text.write(model))
    assert report["Feature model of ws"][-1] == "  unknown number of valid configurations"
    assert report["Core and dead features"] == [
        "  unknown: the model is too large to solve (see the diagnostics)"
    ]
    assert len(report["Conflicts (name clashes)"]) == 2  # the clash and its trigger
    assert [d for d in report["Diagnostics"] if d.endswith("[model-too-large]")] == [
        report["Diagnostics"][-1]
    ]


def test_a_file_that_cannot_be_read_is_listed_with_its_problem(ws: LaunchWorkspace) -> None:
    """The file's problem is in the report, at its id as the tree shows it, line and column."""
    ws.launch("broken.launch", '  <node pkg="pkg" type="t" name="n">\n')  # never closed
    report = sections(text.write(extraction.extract(ws.analysis())))
    [problem] = report["Diagnostics"]
    assert problem.startswith("  pkg/launch/broken.launch:4:"), problem
    assert problem.endswith("[xml-malformed]")
