"""``real_path`` and ``Confinement.resolve``: the same answers as ``os.path.realpath``, with a
cache per directory."""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from rosvar.files import Confinement
from rosvar.workspace.paths import real_path


@pytest.fixture
def tree(tmp_path: Path) -> Path:
    """Directories, a file, and symlinks to a directory, to a file and to themselves."""
    (tmp_path / "a/b/c").mkdir(parents=True)
    (tmp_path / "a/b/c/f.launch").write_text("<launch/>")
    (tmp_path / "link").symlink_to(tmp_path / "a/b")
    (tmp_path / "a/b/flink").symlink_to("c/f.launch")
    (tmp_path / "loop").symlink_to(tmp_path / "loop")
    return tmp_path


@pytest.mark.parametrize(
    "relative",
    [
        "a/b/c/f.launch",
        "link/c/f.launch",  # a symlinked directory
        "link/flink",  # a symlinked file, relative target, reached through a symlink
        "link/../a",  # '..' after a symlink: the target's parent, not the link's
        "link/c/../flink",
        "a/./b",
        "a//b/c",
        "missing/x",
        "link/",
        "loop/x",
    ],
)
def test_same_as_os_realpath(tree: Path, relative: str) -> None:
    path = f"{tree}/{relative}"  # a fresh directory per test: nothing cached yet
    first = real_path(path)
    assert first == os.path.realpath(path)
    assert real_path(path) == first  # from the cache
    confinement = Confinement.of([str(tree)])  # the same resolution, kept for one analysis
    assert confinement.resolve(path) == first
    assert confinement.resolve(path) == first


def test_relative_paths_are_resolved_from_the_working_directory(
    tree: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    for directory in (tree, tree / "a/b/c"):  # the same text, another meaning
        monkeypatch.chdir(directory)
        assert real_path("link/flink") == os.path.realpath("link/flink")
