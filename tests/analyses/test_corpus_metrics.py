"""Metrics on the four corpus systems (``shared/corpus``; skipped where it is absent).

A is checked against ``shared/corpus/MANIFEST.md`` (harosvar's counting rule, reproduced there);
LF is the number of launch files of the system folder.
"""

from __future__ import annotations

import os
import time
from dataclasses import asdict, dataclass
from pathlib import Path

import pytest

from rosvar.analyses.feature_model.extraction import extract
from rosvar.analyses.feature_model.model import FeatureModel
from rosvar.analyses.metrics import Metrics, command_line_args, compute
from rosvar.frontends.xml import load_launch_file
from rosvar.interpreter.workspace_models import Analysis
from rosvar.workspace import discover

CORPUS = Path(__file__).resolve().parents[3] / "shared" / "corpus"
# MANIFEST.md, section 2: our LF and A per system
MANIFEST = {
    "kobuki": (24, 18),
    "turtlebot2": (52, 198),
    "lizi": (14, 66),
    "husky": (137, 391),
}
KEYS = ["LF", "LV", "LC", "LC_U", "LC_A", "A", "ACG", "AS", "AS_D", "AS_V", "IF", "IF_M"]


def system_dir(system: str) -> Path:
    directory = CORPUS / system
    if not directory.is_dir():
        pytest.skip(f"corpus system {system} not found at {directory}")
    return directory


@dataclass
class Result:
    analysis: Analysis
    model: FeatureModel
    metrics: Metrics
    seconds: float


_CACHE: dict[str, Result] = {}


def result(system: str) -> Result:
    if system not in _CACHE:
        directory = system_dir(system)
        analysis = Analysis(discover([directory], ros_package_path=""))
        start = time.perf_counter()
        model = extract(analysis)
        seconds = time.perf_counter() - start
        _CACHE[system] = Result(analysis, model, compute(analysis, model), seconds)
    return _CACHE[system]


def manifest_launch_files(directory: Path) -> list[str]:
    """MANIFEST.md's LF rule: ``.launch`` among a file name's suffixes (no hidden folders)."""
    found: list[str] = []
    for folder, dirs, files in os.walk(directory):
        dirs[:] = [d for d in dirs if not d.startswith(".")]
        found.extend(os.path.join(folder, f) for f in files if ".launch" in f)
    return sorted(found)


@pytest.mark.parametrize("system", list(MANIFEST))
def test_a_counted_as_the_manifest_says(system: str) -> None:
    """A without the feature model: every launch file as the top-level file (all four)."""
    directory = system_dir(system)
    files = discover([directory], ros_package_path="").launch_files
    total = 0
    for file in files:
        root = load_launch_file(file).root
        assert root is not None, file
        total += len(command_line_args(root))
    assert total == MANIFEST[system][1]


@pytest.mark.parametrize("system", list(MANIFEST))
def test_launch_files_are_the_manifests(system: str) -> None:
    directory = system_dir(system)
    files = discover([directory], ros_package_path="").launch_files
    assert files == manifest_launch_files(directory)
    assert len(files) == MANIFEST[system][0]


@pytest.mark.parametrize("system", list(MANIFEST))
def test_metrics_match_the_manifest_and_hold_together(system: str) -> None:
    metrics = asdict(result(system).metrics)
    assert list(metrics) == KEYS
    lf, a = MANIFEST[system]
    assert metrics["LF"] == lf
    assert metrics["A"] == a
    assert metrics["LV"] + metrics["LC"] == metrics["LF"]
    assert metrics["LC_U"] + metrics["LC_A"] == metrics["LC"]
    assert metrics["AS"] <= metrics["ACG"] <= metrics["A"]
    assert metrics["AS_D"] <= metrics["AS"]
    assert metrics["AS_V"] <= metrics["AS"]
    assert metrics["IF_M"] <= metrics["IF"]
    assert all(value >= 0 for value in metrics.values())


@pytest.mark.parametrize("system", list(MANIFEST))
def test_feature_model_covers_every_launch_file(system: str) -> None:
    found = result(system)
    assert [f.file for f in found.model.files] == found.analysis.workspace.launch_files
    ids = found.model.feature_ids()
    assert len(ids) == len(set(ids))


def test_kobuki_has_no_if_or_unless() -> None:
    """MANIFEST.md section 4: no kobuki launch file uses if=/unless=."""
    metrics = result("kobuki").metrics
    assert (metrics.IF, metrics.IF_M) == (0, 0)


def test_lizi_if_counts() -> None:
    """All 20 if=/unless= of lizi are in lizi.launch, on args a user sets (paper: IF 20, IF_M 4)."""
    metrics = result("lizi").metrics
    assert (metrics.IF, metrics.IF_M) == (20, 4)


@pytest.mark.parametrize("system", ["kobuki", "turtlebot2", "lizi"])
def test_extract_is_fast_on_small_systems(system: str) -> None:
    assert result(system).seconds < 20.0
