"""Where a launch configuration is unset only as the command line leaves it
(:func:`rosvar.ros2.context.unset_as_given`): an entry file whose reads of included files'
args see nothing else is interpreted once, and gives the model that interpreting it again,
those args inputs from the start, gives."""

from __future__ import annotations

from collections import Counter
from collections.abc import Mapping
from pathlib import Path

import pytest

from ros2.test_include_memo import _plain, _write
from rosvar.interpreter.model import LaunchModel
from rosvar.interpreter.workspace_models import Analysis
from rosvar.ros2 import substitutions
from rosvar.ros2.tags import arg
from rosvar.workspace import discover


def _models(
    analysis: Analysis, paths: list[str], monkeypatch: pytest.MonkeyPatch
) -> tuple[list[object], int]:
    """The models of ``paths`` (comparable, in the analysis's space) and the passes made."""
    passes: Counter[str] = Counter()
    interpret_with = Analysis._interpret_with

    def counted(
        self: Analysis, file: str, undeclared: Mapping[str, str]
    ) -> tuple[LaunchModel, set[str]]:
        passes[file] += 1
        return interpret_with(self, file, undeclared)

    analysis._models.clear()  # interpreted again in the same space: diagrams compare
    with monkeypatch.context() as patched:
        patched.setattr(Analysis, "_interpret_with", counted)
        models = [_plain(analysis.model(path)) for path in paths]
    return models, sum(passes.values())


def _forced(monkeypatch: pytest.MonkeyPatch) -> None:
    """Every read of a launch configuration unset somewhere makes its name late, as before
    :func:`unset_as_given`: the entry file is interpreted again with it an input."""
    for module in (substitutions, arg):
        monkeypatch.setattr(module, "unset_as_given", lambda *_args: False)


def _compare(tmp_path: Path, seed: str, rare: float, monkeypatch: pytest.MonkeyPatch) -> int:
    """Models of a random include tree interpreted as they are and with every late name's
    entry file interpreted again, in one space; the interpretations skipped."""
    paths = _write(tmp_path, seed, 6, rare)
    analysis = Analysis(discover([str(tmp_path)]), env_values={"E": ["x", "y"]})
    skipped, fewer = _models(analysis, paths, monkeypatch)
    with monkeypatch.context() as patched:
        _forced(patched)
        forced, more = _models(analysis, paths, patched)
    for path, model, again in zip(paths, skipped, forced, strict=True):
        assert model == again, Path(path).name
    return more - fewer


@pytest.mark.parametrize("seed", [f"late-{n}" for n in range(24)])
def test_an_interpretation_skipped_gives_the_same_model(
    tmp_path: Path, seed: str, monkeypatch: pytest.MonkeyPatch
) -> None:
    assert _compare(tmp_path, seed, 0.1, monkeypatch) >= 0


@pytest.mark.parametrize("seed", [f"late-rare-{n}" for n in range(12)])
def test_with_resets_and_forgetting_groups_too(
    tmp_path: Path, seed: str, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Resets and groups that forget the configurations (``forwarding="false"``), timers,
    handlers, included args without a default."""
    assert _compare(tmp_path, seed, 0.5, monkeypatch) >= 0


def test_interpretations_are_skipped(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """The comparisons above are not vacuous: some entry files are interpreted once where
    every late name would have them interpreted twice."""
    skipped = sum(_compare(tmp_path / str(n), f"late-{n}", 0.1, monkeypatch) for n in range(8))
    assert skipped >= 2
