"""Client of the ROS 2 launch oracle (``../shared/ros2-oracle``), for differential tests.

The oracle runs the real ros2/launch in its own virtual environment (``make setup`` builds
it at ``.oracle-ros2-venv``; this module builds it too when missing), one process per
launch, in a clean environment. Tests skip only when the oracle folder itself is absent.
"""

from __future__ import annotations

import functools
import json
import os
import re
import subprocess
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any

import pytest

from rosvar.interpreter.resolution import Resolution
from rosvar.outputs.documents.resolution import resolution_document

REPOSITORY = Path(__file__).resolve().parents[2]
ORACLE = REPOSITORY.parent / "shared" / "ros2-oracle"
VENV = REPOSITORY / ".oracle-ros2-venv"

KEYS = (
    "kind", "package", "executable", "plugin", "container", "name", "namespace", "remappings",
    "parameters", "arguments", "cmd",
)  # fmt: skip
"""The fields of a node compared with rosvar's; ``cmd`` only for a process (``<executable>``),
whose other fields are None (a node's holds the install path the oracle makes up)."""

ENVIRONMENT = {"PATH": "/usr/bin:/bin", "HOME": str(VENV), "PYTHONDONTWRITEBYTECODE": "1"}
"""The oracle's whole environment (a launch file's ``$(env HOME)`` reads it): rosvar's
``--env`` must give the same to compare."""

requires_ros2_oracle = [
    pytest.mark.oracle,
    pytest.mark.skipif(not ORACLE.is_dir(), reason=f"the ROS 2 oracle {ORACLE} is absent"),
]


@functools.lru_cache(maxsize=1)
def oracle_python() -> Path:
    """The oracle venv's interpreter, set up on first use (idempotent, as ``make setup``)."""
    python = VENV / "bin" / "python"
    subprocess.run(
        [str(ORACLE / "setup.sh"), str(VENV)], check=True, capture_output=True, timeout=600
    )
    return python


def run_oracle(
    file: str | os.PathLike[str],
    arguments: Mapping[str, str],
    package_paths: Sequence[str | os.PathLike[str]],
    env: Mapping[str, str] | None = None,
    strict: bool = True,
    timeout_s: float = 120,
) -> dict[str, Any]:
    """The oracle's canonical JSON for ``ros2 launch file name:=value ...``; not ``strict``,
    packages outside ``package_paths`` are placeholders (for nodes of uninstalled packages);
    ``timeout_s``: wall time (a deep include tree takes the real launch code tens of seconds)."""
    command = [str(oracle_python()), str(ORACLE / "oracle.py"), os.fspath(file)]
    command += ["--strict"] if strict else []
    command += [f"{name}:={value}" for name, value in arguments.items()]
    for path in package_paths:
        command += ["--package-path", os.fspath(path)]
    for name, value in (env or {}).items():
        command += ["--env", f"{name}={value}"]
    done = subprocess.run(
        command, capture_output=True, text=True, env=ENVIRONMENT, timeout=timeout_s
    )
    if not done.stdout.strip():
        raise RuntimeError(f"the ROS 2 oracle failed: {done.stderr[-2000:]}")
    return restored_lists(loads_repaired(done.stdout))


UNREAD_TUPLE = "tag:yaml.org,2002:python/tuple"
"""What the oracle's merging says of a parameter file launch_ros wrote from a dict holding a
list: launch_ros dumps the list as a Python tuple, which rcl reads as an array but the
oracle's own merging (``yaml.safe_load``, its code, not ROS's) refuses, losing the dict."""


def restored_lists(result: dict[str, Any]) -> dict[str, Any]:
    """The oracle's nodes with the parameters of the dicts its merging could not read back
    (:data:`UNREAD_TUPLE`) merged again, in the order the dicts were given: a dict holding
    a list is the one it lost; a later dict it read keeps its values."""
    for node in result.get("nodes", []):
        if not any(UNREAD_TUPLE in error for error in node.get("parameter_errors") or []):
            continue
        lost: dict[str, Any] = {}
        for given in node.get("inline_parameters") or []:
            flat = _flattened(given)
            if any(isinstance(value, list) for value in flat.values()):
                lost.update(flat)
            else:
                for key in flat:
                    lost.pop(key, None)
        node["parameters"] = {**(node.get("parameters") or {}), **lost}
    return result


def _flattened(parameters: Mapping[str, Any], prefix: str = "") -> dict[str, Any]:
    """Nested parameter dicts as rcl names them (``a.b``)."""
    flat: dict[str, Any] = {}
    for key, value in parameters.items():
        if isinstance(value, Mapping):
            flat.update(_flattened(value, f"{prefix}{key}."))
        else:
            flat[f"{prefix}{key}"] = value
    return flat


GENERATED = re.compile(r'<generated:\d+>"')
"""The oracle names its generated files ``<generated:N>`` by replacing their path in its JSON
text up to the next quote, which also swallows the backslash of an escaped quote that ends
a path inside a message (a YAML error naming the file): that quote must be escaped again."""


def loads_repaired(text: str) -> dict[str, Any]:
    """The oracle's JSON, with the quotes its file renaming unescaped escaped again, each at
    the place where the text stops being valid JSON (bounded: once per renamed file)."""
    for _ in range(text.count("<generated:") + 1):
        try:
            result: dict[str, Any] = json.loads(text)
            return result
        except json.JSONDecodeError as error:
            broken = list(GENERATED.finditer(text, 0, error.pos + 1))
            if not broken:
                raise
            quote = broken[-1].end() - 1
            text = f"{text[:quote]}\\{text[quote:]}"
    result = json.loads(text)
    return result


def rosvar_nodes(document: Mapping[str, Any]) -> dict[str, Any]:
    """``rosvar resolve --json``'s nodes (``docs/json-schema.md``; in-process, the same
    document from :func:`~rosvar.outputs.documents.resolution.resolution_document`) as the
    oracle records them: :data:`KEYS`, a node's own name from its fully qualified one (None
    where its code names it), ``executable``, ``remappings`` in order; a process has only
    its ``kind``, ``cmd`` and what it shares with nodes."""
    nodes = []
    for node in document.get("nodes", []):
        record = {key: node.get(key) for key in ("kind", "plugin", "container", "arguments", "cmd")}
        if node.get("kind") != "process":
            fqn = node.get("fqn")
            record.update(
                package=node.get("package"),
                executable=node.get("type"),
                name=None if fqn is None else str(fqn).rsplit("/", 1)[-1],
                namespace=node.get("namespace"),
                remappings=[list(pair) for pair in node.get("remaps", [])],
                parameters=node.get("parameters"),
            )
        nodes.append(record)
    return {"nodes": nodes}


def resolution_nodes(result: Resolution) -> dict[str, Any]:
    """In-process, rosvar's nodes by the same route: the ``resolve --json`` document."""
    return rosvar_nodes(resolution_document(result))


MISSING_EXECUTABLE = re.compile(r"/__missing_exec__/([^\s\\\"'/]+)")
"""The oracle's stand-in for ``$(find-exec NAME)`` not on its clean ``PATH``."""


def canonical_nodes(result: Mapping[str, Any]) -> list[dict[str, Any]]:
    """The compared fields (:data:`KEYS`) of the oracle's nodes, in a stable order; the same
    function makes rosvar's comparable (a ``nodes`` list of dicts as well). An executable
    the oracle did not find on its ``PATH`` reads as rosvar's ``$(find-exec NAME)``, which
    leaves the host's ``PATH`` to the host."""
    nodes = [
        {key: node.get(key) if key != "cmd" or node.get("kind") == "process" else None
         for key in KEYS}
        for node in result.get("nodes", [])
    ]  # fmt: skip
    text = MISSING_EXECUTABLE.sub(r"$(find-exec \1)", json.dumps(nodes))
    return sorted(json.loads(text), key=lambda n: json.dumps(n, sort_keys=True))
