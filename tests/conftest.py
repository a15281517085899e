"""Shared fixtures: a throw-away ROS workspace for launch files written inline by a test.

``ws`` (a :class:`LaunchWorkspace` under ``tmp_path``) writes launch files into a package,
analyses them with one :class:`~rosvar.interpreter.workspace_models.Analysis`, restricts the model
to configurations and, where the roslaunch oracle is available, compares a restriction with the
real roslaunch (``tests/oracle``) using the differential harness's :func:`compare`.
``bdd_reader`` runs a test with each of ``bdd.read``'s two ways of reading a diagram.

The directory ``tests/`` is put on ``sys.path`` so that test modules (which pytest imports in
``importlib`` mode, outside any package) can import ``oracle.client`` like the harness does.
"""

from __future__ import annotations

import sys
from collections.abc import Iterable, Mapping
from pathlib import Path
from typing import Any

import pytest

from rosvar.interpreter.model import LaunchModel
from rosvar.interpreter.resolution import Resolution
from rosvar.interpreter.workspace_models import Analysis
from rosvar.outputs.documents.resolution import resolution_document
from rosvar.ros1.resolve import resolve
from rosvar.workspace import discover

TESTS = Path(__file__).resolve().parent
if str(TESTS) not in sys.path:
    sys.path.insert(0, str(TESTS))

from differential.harness import compare  # noqa: E402

# Third-party launch files (``tests/data/ros2``): data, although some are named ``test_*.py``.
collect_ignore = ["data"]
from oracle.client import shared_oracle  # noqa: E402


def pytest_addoption(parser: pytest.Parser) -> None:
    parser.addoption(
        "--ros2-full",
        action="store_true",
        help="also run the whole real-repository ROS 2 differential (tests marked ros2_full)",
    )


def pytest_collection_modifyitems(config: pytest.Config, items: list[pytest.Item]) -> None:
    """The whole real-repository differential (most of an hour) only on request."""
    if config.getoption("--ros2-full"):
        return
    skip = pytest.mark.skip(reason="the whole ROS 2 differential: run with --ros2-full")
    for item in items:
        if "ros2_full" in item.keywords:
            item.add_marker(skip)


PACKAGE_XML = """<?xml version="1.0"?>
<package format="2">
  <name>{name}</name>
  <version>0.0.0</version>
  <description>test package</description>
  <maintainer email="test@example.com">test</maintainer>
  <license>BSD</license>
</package>
"""

Config = Mapping[str, str]


class LaunchWorkspace:
    """Packages and launch files under one root directory."""

    def __init__(self, root: Path) -> None:
        self.root = root
        self._analysis: Analysis | None = None

    def package(self, name: str = "pkg") -> Path:
        directory = self.root / name
        if not (directory / "package.xml").is_file():
            directory.mkdir(parents=True, exist_ok=True)
            (directory / "package.xml").write_text(PACKAGE_XML.format(name=name))
        return directory

    def launch(self, name: str, body: str, package: str = "pkg") -> str:
        """Write ``<launch>BODY</launch>`` as ``PACKAGE/launch/NAME``; returns its path."""
        return self.write(f"launch/{name}", f"<launch>\n{body}\n</launch>\n", package)

    def write(self, relative: str, text: str | bytes, package: str = "pkg") -> str:
        path = self.package(package) / relative
        path.parent.mkdir(parents=True, exist_ok=True)
        if isinstance(text, bytes):
            path.write_bytes(text)
        else:
            path.write_text(text)
        self._analysis = None
        return str(path)

    # -- rosvar ------------------------------------------------------------------------------
    def analysis(self, **options: Any) -> Analysis:
        """One analysis of the whole workspace (cached until a file is written)."""
        if options:
            return Analysis(discover([self.root], ros_package_path=""), **options)
        if self._analysis is None:
            self._analysis = Analysis(discover([self.root], ros_package_path=""))
        return self._analysis

    def model(self, file: str) -> LaunchModel:
        return self.analysis().model(file)

    def resolve(
        self, file: str, args: Config | None = None, env: Config | None = None
    ) -> Resolution:
        """The restriction of the shared variational model to one configuration."""
        return resolve(self.analysis(), [file], dict(args or {}), dict(env or {}))

    def resolve_fresh(
        self, file: str, args: Config | None = None, env: Config | None = None
    ) -> Resolution:
        """As ``rosvar resolve`` does: the given values become known slots of a new analysis."""
        analysis = self.analysis(
            extra_values={k: [v] for k, v in (args or {}).items()},
            env_values={k: [v] for k, v in (env or {}).items()},
        )
        return resolve(analysis, [file], dict(args or {}), dict(env or {}))

    # -- roslaunch --------------------------------------------------------------------------
    def oracle(self, file: str, configs: Iterable[tuple[Config, Config]]) -> list[dict[str, Any]]:
        jobs = [
            {
                "id": index,
                "roots": [str(self.root)],
                "files": [file],
                "args": dict(args),
                "env": dict(env),
                "rescan": True,
            }
            for index, (args, env) in enumerate(configs)
        ]
        return shared_oracle().run(jobs)

    def assert_agrees(
        self,
        file: str,
        configs: Iterable[Config | tuple[Config, Config]],
        modes: Iterable[str] = ("shared", "fresh"),
    ) -> list[dict[str, Any]]:
        """rosvar and roslaunch agree in every configuration (``(args, env)`` or just args).

        ``modes``: ``shared`` restricts one variational model (the given values are mostly
        ``<other>`` slots), ``fresh`` analyses again with the given values as known slots (as
        ``rosvar resolve`` does). Returns the oracle's results.
        """
        chosen = set(modes)
        pairs: list[tuple[Config, Config]] = [
            c if isinstance(c, tuple) else (c, {}) for c in configs
        ]
        results = self.oracle(file, pairs)
        problems = []
        for (args, env), theirs in zip(pairs, results, strict=True):
            for label in sorted(chosen):
                resolver = self.resolve if label == "shared" else self.resolve_fresh
                ours = resolver(file, args, env)
                differences = compare(resolution_document(ours), theirs)
                if differences:
                    problems.append(f"args={dict(args)} env={dict(env)} [{label}]: {differences}")
        assert problems == [], "\n".join(problems)
        return results


@pytest.fixture
def ws(tmp_path: Path) -> LaunchWorkspace:
    return LaunchWorkspace(tmp_path / "ws")


@pytest.fixture(params=["node by node", "by levels"])
def bdd_reader(request: pytest.FixtureRequest, monkeypatch: pytest.MonkeyPatch) -> str:
    """``bdd.read`` either way, whatever the diagram's size: a Python call per node, or a
    level at a time in numpy."""
    from rosvar.logic import bdd

    by_levels = request.param == "by levels"
    monkeypatch.setattr(bdd, "READ_BY_LEVELS_FROM", 0 if by_levels else 10**9)
    return str(request.param)
