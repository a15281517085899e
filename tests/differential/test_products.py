"""Complete products reached through the configuration engine, loaded by the real roslaunch.

On each corpus system a few products are reached by seeded random choices (as a user
clicking around would, see ``tests/configuration/helpers.py``). The files and args of each
of their command lines go to the roslaunch oracle, whose nodes and params must equal the
present elements of the engine's graph — or both must refuse the product.
"""

from __future__ import annotations

import os
import random

import pytest

from configuration.helpers import anon_free, product, random_product
from rosvar.analyses.feature_model.extraction import extract
from rosvar.configuration.command import given
from rosvar.configuration.engine import Configurator
from rosvar.interpreter.workspace_models import Analysis
from rosvar.outputs.web.entries import render
from rosvar.workspace import discover

from .harness import (
    CORPUS,
    CORPUS_SYSTEMS,
    SEED,
    compare,
    requires_oracle,
    shared_oracle,
    system_runs,
)

pytestmark = requires_oracle
PRODUCTS = 3


@pytest.mark.parametrize("system", CORPUS_SYSTEMS)
def test_engine_products_load_as_in_roslaunch(system: str) -> None:
    if not (CORPUS / system).is_dir() or not (CORPUS / "_external").is_dir():
        pytest.skip(f"corpus not found at {CORPUS}")
    problems: list[str] = []
    compared = 0
    for run in system_runs(system):
        roots = [os.path.realpath(r) for r in run.roots]
        env = {**run.env, "ROS_PACKAGE_PATH": ":".join(roots)}  # the oracle's environment
        analysis = Analysis(
            discover(roots, ros_package_path=""), env_values={k: [v] for k, v in env.items()}
        )
        engine = Configurator(
            analysis, extract(analysis, files=run.files(), products=True), env, render=render
        )
        rng = random.Random(f"{SEED}:{run.name}")
        cases = []
        for _ in range(PRODUCTS):
            state = random_product(engine, rng)
            for members in state.commands:
                cases.append((state.command, product(state, [m.spelled for m in members]), members))
        jobs = [
            {
                "id": index,
                "roots": roots,
                "files": [m.path for m in members],
                "args": given(members),
                "env": dict(run.env),
            }
            for index, (_command, _ours, members) in enumerate(cases)
        ]
        for (command, ours, _members), theirs in zip(cases, shared_oracle().run(jobs), strict=True):
            if theirs.get("outside"):
                continue  # roslaunch failed for a reason outside the launch files
            compared += 1
            differences = compare(anon_free(ours), anon_free(theirs))
            problems += [f"{run.name}: {command}: {line}" for line in differences]
    assert problems == []
    assert compared > 0
