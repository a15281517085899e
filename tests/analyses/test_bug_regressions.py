"""The regression set of real bugs (``tests/data/bugs/<name>/``, docs/checks.md): each folder
holds a misconfiguration fixed in a public ROS repository, as the workspace before the fix
(``buggy/``) and after it (``fixed/``), its ``SOURCE.md`` and ``bug.json``.

Each bug is checked the way a CI job checks a pull request: ``rosvar check`` of one version
with the other's ``--format json`` output as ``--baseline``. The buggy version's new findings
must name every misconfigured name of ``bug.json`` and the fixed version's must name none, so a
finding both versions share (noise) never counts as detecting the bug. A bug rosvar cannot
find yet says why in ``"undetected"`` and is a strict xfail: it fails once rosvar finds it,
so the list of what is missing stays true.
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import pytest

from rosvar.outputs.cli import main
from rosvar.outputs.commands.exit_codes import EXIT_FAILS, EXIT_OK
from rosvar.ros.version import RosVersion
from rosvar.workspace import discover

BUGS = Path(__file__).resolve().parent.parent / "data" / "bugs"
VERSIONS = ("buggy", "fixed")


@dataclass(frozen=True)
class Bug:
    """One folder of the set, as its ``bug.json`` describes it."""

    folder: Path
    dialect: RosVersion
    check_args: tuple[str, ...]
    names: tuple[str, ...]
    undetected: str | None

    @classmethod
    def read(cls, folder: Path) -> Bug:
        data = json.loads((folder / "bug.json").read_text(encoding="utf-8"))
        unknown = set(data) - {"dialect", "check_args", "names", "undetected"}
        assert not unknown, f"{folder.name}/bug.json: unknown keys {sorted(unknown)}"
        return cls(
            folder=folder,
            dialect=RosVersion(data["dialect"]),
            check_args=tuple(data.get("check_args", ())),
            names=tuple(data["names"]),
            undetected=data.get("undetected"),
        )


def _bugs() -> list[Bug]:
    return [Bug.read(folder) for folder in sorted(BUGS.iterdir()) if folder.is_dir()]


def _params() -> list[Any]:
    return [
        pytest.param(
            bug,
            id=bug.folder.name,
            marks=[pytest.mark.xfail(strict=True, reason=bug.undetected)] if bug.undetected else [],
        )
        for bug in _bugs()
    ]


@pytest.fixture
def hermetic(monkeypatch: pytest.MonkeyPatch) -> pytest.MonkeyPatch:
    """No package of the machine's ROS environment joins a fixture's workspace."""
    monkeypatch.delenv("ROS_PACKAGE_PATH", raising=False)
    monkeypatch.delenv("AMENT_PREFIX_PATH", raising=False)
    return monkeypatch


def _check(
    bug: Bug,
    version: str,
    capsys: pytest.CaptureFixture[str],
    monkeypatch: pytest.MonkeyPatch,
    baseline: Path | None = None,
) -> str:
    """``rosvar check . <check_args> --format json [--baseline FILE]`` run in the version's
    folder, as a CI job runs it at the root of its checkout; its output."""
    monkeypatch.chdir(bug.folder / version)
    argv = ["check", ".", *bug.check_args, "--format", "json"]
    if baseline is not None:
        argv += ["--baseline", str(baseline)]
    code = main(argv)
    out, err = capsys.readouterr()
    assert code in (EXIT_OK, EXIT_FAILS), err
    return out


def _new_names(
    bug: Bug,
    version: str,
    other: str,
    tmp_path: Path,
    capsys: pytest.CaptureFixture[str],
    monkeypatch: pytest.MonkeyPatch,
) -> set[str]:
    """The names of the findings ``version`` has beyond ``other``'s (its baseline)."""
    baseline = tmp_path / f"{other}.json"
    baseline.write_text(_check(bug, other, capsys, monkeypatch))
    findings: list[dict[str, Any]] = json.loads(
        _check(bug, version, capsys, monkeypatch, baseline)
    )["findings"]
    return {finding["name"] for finding in findings}


@pytest.mark.parametrize("bug", _params())
def test_the_bug_is_new_in_its_buggy_version_and_gone_in_its_fix(
    bug: Bug, tmp_path: Path, capsys: pytest.CaptureFixture[str], hermetic: pytest.MonkeyPatch
) -> None:
    brought = _new_names(bug, "buggy", "fixed", tmp_path, capsys, hermetic)
    assert set(bug.names) <= brought, f"not found: {sorted(set(bug.names) - brought)}"
    left = _new_names(bug, "fixed", "buggy", tmp_path, capsys, hermetic)
    assert not set(bug.names) & left, f"the fix still has: {sorted(set(bug.names) & left)}"


@pytest.mark.parametrize("bug", [pytest.param(b, id=b.folder.name) for b in _bugs()])
def test_each_bug_folder_follows_the_convention(bug: Bug, hermetic: pytest.MonkeyPatch) -> None:
    """Both versions, a source, names to look for, and the dialect its packages say."""
    assert (bug.folder / "SOURCE.md").is_file()
    assert bug.names and all(isinstance(name, str) and name for name in bug.names)
    assert bug.undetected is None or bug.undetected.strip()
    for version in VERSIONS:
        workspace = discover([bug.folder / version], ros_package_path="", ament_prefix_path="")
        assert workspace.ros_version is bug.dialect, version
