"""Complete products reached through the configuration engine, loaded by the real roslaunch.

On each corpus system a few products are reached by seeded random choices (as a user
clicking around would, see ``tests/configuration/helpers.py``), and a few of two and three
entry files picked at random and finished with defaults (files that clash only through a
file both include were offered together: issue 30). The files and args of each of their
command lines go to the roslaunch oracle, whose nodes and params must equal the present
elements of the engine's graph — or both must refuse the product.
"""

from __future__ import annotations

import json
import os
import random
from collections.abc import Callable

import pytest

from configuration.helpers import anon_free, product, product_of_files, random_product
from rosvar.analyses.feature_model.extraction import extract
from rosvar.configuration.choices import Action, UserChoice
from rosvar.configuration.command import given
from rosvar.configuration.engine import ConfigurationState, Configurator
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
PRODUCTS_OF_FILES = 3  # of two entry files, and as many of three


@pytest.mark.parametrize("system", CORPUS_SYSTEMS)
def test_engine_products_load_as_in_roslaunch(system: str) -> None:
    compare_products(
        system, lambda engine, rng: [random_product(engine, rng) for _ in range(PRODUCTS)]
    )


@pytest.mark.parametrize("system", CORPUS_SYSTEMS)
def test_products_of_two_and_three_entry_files_load_as_in_roslaunch(system: str) -> None:
    compare_products(
        system,
        lambda engine, rng: [
            product_of_files(engine, rng, count)
            for count in (2, 3)
            for _ in range(PRODUCTS_OF_FILES)
        ],
    )


def test_files_that_include_one_file_are_not_a_product_roslaunch_refuses_them() -> None:
    """husky_playpen.launch and husky_empty_world.launch both include spawn_husky.launch
    (and gazebo_ros's empty_world.launch): roslaunch refuses them together ("multiple nodes
    named [/gazebo]"), and the engine takes the second one out."""
    if not (CORPUS / "husky").is_dir() or not (CORPUS / "_external").is_dir():
        pytest.skip(f"corpus not found at {CORPUS}")
    [run] = system_runs("husky")
    roots = [os.path.realpath(r) for r in run.roots]
    analysis = Analysis(discover(roots, ros_package_path=""))
    engine = Configurator(
        analysis, extract(analysis, files=run.files(), products=True), render=render
    )
    gazebo = os.path.join(roots[0], "husky", "husky_gazebo", "launch")
    [playpen, empty] = [
        next(f for f in engine.catalog.files if f.path == os.path.join(gazebo, name))
        for name in ("husky_playpen.launch", "husky_empty_world.launch")
    ]
    state = engine.state([UserChoice(Action.SELECT, playpen.id)])
    assert state.features[empty.id].state == "deselected" and state.features[empty.id].derived
    [refusal] = engine.state(
        [UserChoice(Action.SELECT, playpen.id), UserChoice(Action.SELECT, empty.id)]
    ).refused
    assert "both load node /base_controller_spawner, node /ekf_localization, node /gazebo" in (
        refusal.reason
    )
    job = {"id": 0, "roots": roots, "files": [playpen.path, empty.path], "args": {}, "env": {}}
    [theirs] = shared_oracle().run([job])
    assert not theirs["ok"] and "multiple nodes named [/gazebo]" in json.dumps(theirs)


def compare_products(
    system: str, products: Callable[[Configurator, random.Random], list[ConfigurationState]]
) -> None:
    """The command lines of the ``products`` the engine reaches on ``system`` against the
    oracle's loading of them."""
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
            analysis, extract(analysis, files=run.files(), products=True, env=env), render=render
        )
        rng = random.Random(f"{SEED}:{run.name}")
        cases = []
        for state in products(engine, rng):
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
