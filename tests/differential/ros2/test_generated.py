"""The generated ROS 2 workspace of issue 28 (``bench/generate.py --shape ros2-dense``: its
``$(eval)``s combine so many values that the model gives some up) against the oracle: each
launch file, interpreted once over every command line, restricted to sampled configurations
(:mod:`.samples`: the defaults, flipped booleans, other choices; and a free text for an
argument that names no values) gives the oracle's nodes, and fails where the oracle fails;
and, for a few files, what interpreting each configuration alone gives (its values known,
as ``rosvar resolve`` makes them), without the oracle.

The comparison is :func:`.repositories.compare`'s; every difference is listed at once. The
figures are in ``docs/known-differences.md``."""

from __future__ import annotations

import random
import subprocess
import sys
from pathlib import Path

import pytest

from oracle.ros2_client import canonical_nodes, requires_ros2_oracle, resolution_nodes, run_oracle
from rosvar.interpreter.resolution import Resolution
from rosvar.interpreter.workspace_models import Analysis
from rosvar.workspace import discover

from .repositories import compare
from .samples import BOOLEANS, Config, read, sample

BENCH = Path(__file__).resolve().parents[3] / "bench" / "generate.py"
FILES = 12
"""Launch files generated (issue 28's workspace has 120: the shape is the same)."""
CONFIGS = 4
"""Sampled configurations per file besides the defaults and the free text."""
FREE = "free text"
ALONE = 4
"""Files whose configurations are also interpreted alone: of those that include others, the
fewest includes first (values flow through includes, and each interpretation is short)."""
ORACLE_TIMEOUT_S = 900
"""The oracle's wall time on a deep file, on a loaded machine."""


@pytest.fixture(scope="module")
def generated(tmp_path_factory: pytest.TempPathFactory) -> Path:
    root = tmp_path_factory.mktemp("ros2-dense") / "src"
    command = [sys.executable, str(BENCH), "--shape", "ros2-dense", str(root), str(FILES)]
    subprocess.run(command, check=True, capture_output=True, timeout=120)
    return root


def configurations(root: Path) -> list[tuple[Path, Config]]:
    """Each file's defaults, :data:`CONFIGS` more of its sample (drawn by the file's name in
    the workspace, the same in every checkout) and its first argument that names no values
    given :data:`FREE`."""
    readings = {path: read(path) for path in sorted(root.rglob("*.launch.xml"))}
    found: list[tuple[Path, Config]] = []
    for path, samples in sample(readings, root).items():
        name = path.relative_to(root).as_posix()
        defaults, *rest = [s.config for s in samples]
        chosen = random.Random(name).sample(rest, min(CONFIGS, len(rest)))
        free = [
            argument.name
            for argument in readings[path].arguments.values()
            if not argument.choices and argument.default not in BOOLEANS
        ]
        extra = [{**defaults, free[0]: FREE}] if free else []
        found += [(path, config) for config in [defaults, *chosen, *extra]]
    return found


def _document(result: Resolution) -> dict[str, object]:
    """rosvar's resolution in the shape :func:`.repositories.compare` reads."""
    errors = [
        {
            "code": error.code,
            "message": error.message,
            "location": {
                "file": error.location.file,
                "line": error.location.line,
                "col": error.location.col,
            },
        }
        for error in result.errors
    ]
    return {**resolution_nodes(result), "errors": errors}


@pytest.mark.slow
@requires_ros2_oracle[0]
@requires_ros2_oracle[1]
def test_the_generated_workspace_agrees_with_the_oracle(generated: Path) -> None:
    analysis = Analysis(discover([str(generated)]))
    chosen = configurations(generated)
    assert len(chosen) >= 4 * FILES
    differences: list[str] = []
    for path, config in chosen:
        expected = run_oracle(path, config, [generated], timeout_s=ORACLE_TIMEOUT_S)
        result = analysis.resolve([str(path)], config)
        where = f"{path.relative_to(generated)} {config}"
        if not expected["ok"]:
            if result.ok:
                differences.append(f"{where}: the oracle fails ({expected.get('error')})")
            continue
        causes = compare(expected, _document(result))
        differences += [f"{where}: {cause.category}: {cause.detail}" for cause in causes]
    assert not differences, "\n".join(differences)


def test_the_model_restricted_agrees_with_each_configuration_alone(generated: Path) -> None:
    """The model over every command line restricted to a configuration (a value no file
    names is its argument's other value there) against the model where the configuration's
    values are known ones: the same success and nodes (a failure may be told at another
    place: where the model fails, or where a term is evaluated)."""
    analysis = Analysis(discover([str(generated)]))
    chosen = configurations(generated)
    includes = {path: len(read(path).includes) for path, _ in chosen}
    including = sorted((count, path) for path, count in includes.items() if count)
    picked = {path for _, path in including[:ALONE]}
    differences: list[str] = []
    for path, config in chosen:
        if path not in picked:
            continue
        alone = Analysis(analysis.workspace, extra_values={k: [v] for k, v in config.items()})
        both = [a.resolve([str(path)], config) for a in (analysis, alone)]
        shown = [(r.ok, canonical_nodes(resolution_nodes(r)) if r.ok else []) for r in both]
        if shown[0] != shown[1]:
            errors = [[str(e) for e in r.errors] for r in both]
            differences.append(f"{path.relative_to(generated)} {config}: {errors}")
    assert len(picked) == ALONE
    assert not differences, "\n".join(differences)
