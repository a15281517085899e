"""Baselines of ``rosvar check``: the fingerprints of an earlier run's findings, read from
its ``--format json`` or SARIF output (``--baseline``) or computed on a git revision of the
workspace (``--baseline-rev``), so that CI reports only the findings a change brings."""

from __future__ import annotations

import contextlib
import json
import os
import subprocess
import tarfile
import tempfile
from collections.abc import Iterator, Sequence

from rosvar.analyses.fingerprints import VERSION


class BaselineError(Exception):
    """The baseline cannot be read or made; the message says why, for people."""


def fingerprints_in(path: str) -> list[str]:
    """The fingerprints of the findings of ``check --format json`` or ``--format sarif``
    output at ``path`` (one per finding: alike findings repeat theirs)."""
    try:
        with open(path, encoding="utf-8") as stream:
            document = json.load(stream)
    except (OSError, UnicodeDecodeError, ValueError) as error:
        raise BaselineError(f"cannot read the baseline {path}: {error}") from None
    found: list[object] = []
    if isinstance(document, dict) and isinstance(document.get("findings"), list):
        found = [f.get("fingerprint") for f in document["findings"] if isinstance(f, dict)]
    elif isinstance(document, dict) and isinstance(document.get("runs"), list):
        for run in document["runs"]:
            for result in run.get("results", []) if isinstance(run, dict) else []:
                prints = result.get("partialFingerprints") if isinstance(result, dict) else None
                found.append(prints.get(VERSION) if isinstance(prints, dict) else None)
    else:
        raise BaselineError(f"{path} is no output of rosvar check --format json or --format sarif")
    if not all(isinstance(f, str) for f in found):
        raise BaselineError(f"{path}: a finding has no rosvar fingerprint ({VERSION})")
    return [f for f in found if isinstance(f, str)]


@contextlib.contextmanager
def revision_paths(paths: Sequence[str], revision: str) -> Iterator[list[str]]:
    """``paths`` as they are at ``revision`` of the git repositories holding them: each
    repository written with ``git archive`` into a temporary folder, removed afterwards."""
    with tempfile.TemporaryDirectory(prefix="rosvar-baseline-") as folder:
        trees: dict[str, str] = {}
        mapped = []
        for path in paths:
            top = _git(os.path.abspath(path), "rev-parse", "--show-toplevel").strip()
            if top not in trees:
                trees[top] = os.path.join(folder, str(len(trees)))
                _extract(top, revision, trees[top])
            inside = os.path.relpath(os.path.realpath(path), os.path.realpath(top))
            mapped.append(os.path.normpath(os.path.join(trees[top], inside)))
        yield mapped


def _git(where: str, *words: str) -> str:
    folder = where if os.path.isdir(where) else os.path.dirname(where)
    try:
        done = subprocess.run(
            ["git", "-C", folder, *words], capture_output=True, text=True, check=False
        )
    except OSError as error:
        raise BaselineError(f"--baseline-rev needs git: {error}") from None
    if done.returncode != 0:
        if "--show-toplevel" in words:
            raise BaselineError(f"--baseline-rev: {where} is not inside a git repository")
        raise BaselineError(f"--baseline-rev: git {' '.join(words)}: {done.stderr.strip()}")
    return done.stdout


def _extract(top: str, revision: str, target: str) -> None:
    """The tree of ``revision`` of the repository at ``top`` into ``target``."""
    try:
        _git(top, "rev-parse", "--verify", "--quiet", f"{revision}^{{commit}}")
    except BaselineError:
        raise BaselineError(f"--baseline-rev: {top} has no revision {revision}") from None
    os.makedirs(target)
    archive = os.path.join(target + ".tar")
    _git(top, "archive", "--format=tar", f"--output={archive}", revision)
    with tarfile.open(archive) as tar:
        tar.extractall(target, filter="data")
    os.remove(archive)
