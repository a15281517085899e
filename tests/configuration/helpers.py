"""Helpers for the configuration tests: a configurator whose files are named by base name."""

from __future__ import annotations

import json
import os
import random
import re
from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING, Any

from json_view import read
from rosvar.analyses.conflicts import node_occurrences
from rosvar.analyses.feature_model.extraction import extract
from rosvar.configuration.choices import Action, UserChoice
from rosvar.configuration.command import given
from rosvar.configuration.engine import ConfigurationState, Configurator
from rosvar.interpreter.workspace_models import Analysis
from rosvar.outputs.documents.resolution import resolution_document
from rosvar.outputs.web.entries import render
from rosvar.ros import names
from rosvar.ros1.resolve import resolve
from rosvar.workspace.interfaces.extraction import extract_interfaces

if TYPE_CHECKING:
    from conftest import LaunchWorkspace


def configurator(
    ws: LaunchWorkspace, env: Mapping[str, str] | None = None, interfaces: bool = False
) -> Configurator:
    """Feature ids read ``a.launch``, ``a.launch:x``, ``a.launch:x=1``; with ``interfaces``,
    the nodes' topics read from the workspace's sources."""
    analysis = ws.analysis()
    model = extract(analysis, products=True, env=env)
    spelling = {os.path.realpath(f.file): os.path.basename(f.file) for f in model.files}
    found = extract_interfaces(analysis.workspace.packages.values()) if interfaces else None
    return Configurator(analysis, model, env, spelling, interfaces=found, render=render)


def choices(*words: str) -> list[UserChoice]:
    """``choices("select a.launch", "set a.launch:x=1")``."""
    found = []
    for word in words:
        action, _, text = word.partition(" ")
        found.append(UserChoice.parse(action, text))
    return found


def run(engine: Configurator, *words: str) -> ConfigurationState:
    return engine.state(choices(*words))


def states(state: ConfigurationState) -> dict[str, str]:
    """Decided feature id → state, ``*`` marking derived ones."""
    return {
        k: v.state + ("*" if v.derived else "")
        for k, v in state.features.items()
        if v.state != "unselected"
    }


def present(state: ConfigurationState, kind: str = "nodes") -> dict[str, str]:
    """Element name → presence, for the elements not absent."""
    elements = getattr(state.graph, kind)
    return {e["name"]: e["presence"] for e in elements if e["presence"] != "absent"}


def random_product(engine: Configurator, rng: random.Random) -> ConfigurationState:
    """A complete product reached by random choices, as a user clicking around would.

    Known values are preferred to ``<other>``; an ``<other>`` value that gets selected all
    the same is given a typed text. Files are selected one time in five: products of a few
    files, as people build them (and which load more often than a dozen files together).
    """
    chosen: list[UserChoice] = []
    while True:
        state = typed_in(engine, chosen, rng)
        if state.complete:
            return state
        open_ = [f for f in engine.catalog if state.features[f.id].state == "unselected"]
        known = [f for f in open_ if f.value != "<other>"]
        feature = rng.choice(known or open_)
        action = Action.SELECT if feature.kind == "value" or rng.random() < 0.2 else Action.DESELECT
        chosen.append(UserChoice(action, feature.id))


def product_of_files(engine: Configurator, rng: random.Random, count: int) -> ConfigurationState:
    """A complete product of ``count`` entry files picked at random (fewer when the others
    are ruled out), finished with defaults as ``--finish`` does, every ``<other>`` value
    left open typed: the products people build from a bringup and a few sensors. After the
    first, files that load a node name a picked one loads are picked first: those are the
    ones that can clash, through the files they include too (issue 30)."""
    models = {f.id: engine.analysis.model(f.path) for f in engine.catalog.files}
    loads = {
        file: {o.name for node in model.nodes for o in node_occurrences(model, node)}
        for file, model in models.items()
    }
    chosen: list[UserChoice] = []
    names: set[str] = set()
    picked = 0
    while picked < count:
        state = engine.state(chosen)
        open_ = [f.id for f in engine.catalog.files if state.features[f.id].state == "unselected"]
        if not open_:
            break
        near = [f for f in open_ if loads[f] & names]
        file = rng.choice(near or open_)
        chosen.append(UserChoice(Action.SELECT, file))
        if len(engine.state(chosen).refused) == len(state.refused):
            picked += 1
            names |= loads[file]
    chosen += engine.completion(chosen)
    return typed_in(engine, chosen, rng)


TEXTS = ("typed{}", "{}", "True", "{}.5")
"""What is typed for an ``<other>`` value (``{}`` a random digit), the next one while the
engine refuses it (every product left would fail by it): a word first, as people type
names; ``True``, which is no known value where ``true`` is."""


def typed_in(
    engine: Configurator, chosen: list[UserChoice], rng: random.Random
) -> ConfigurationState:
    """The state after ``chosen`` with a text typed (appended) for every ``<other>`` value
    that waits for one. Where every text is refused (an arg naming a folder: any other text
    names a file that is not there), the choice of ``<other>`` is taken back, as a user
    would, and the product finished with defaults again; where ``<other>`` was no choice,
    the state is left waiting for a text (``untyped``)."""
    state = engine.state(chosen)
    attempt = 0
    while state.untyped:
        arg = state.untyped[0]
        if attempt == len(TEXTS):
            other = UserChoice(Action.UNSELECT, f"{arg}=<other>")
            if other in chosen or other.feature not in {c.feature for c in chosen}:
                return state
            chosen.append(other)
            chosen += engine.completion(chosen)
            state, attempt = engine.state(chosen), 0
            continue
        chosen.append(UserChoice(Action.SET, arg, TEXTS[attempt].format(rng.randint(0, 9))))
        refused = len(state.refused)
        state = engine.state(chosen)
        attempt = attempt + 1 if len(state.refused) > refused else 0
    return state


PRESENCE_FIELDS = ("presence", "condition", "id")
ANON = re.compile(r"_anon\d+(?!\w)")  # the interpreter's names for ``$(anon base)``


def product(state: ConfigurationState, members: Sequence[str] | None = None) -> dict[str, Any]:
    """The present elements, shaped like ``rosvar resolve --json`` (of some launched files).

    ``ok`` is false when an error is present or two present nodes share a name.
    """

    def mine(element: Mapping[str, Any]) -> bool:
        return members is None or str(element["id"]).split("|")[0] in members

    def bare(elements: list[dict[str, Any]]) -> list[dict[str, Any]]:
        return [
            {k: v for k, v in e.items() if k not in PRESENCE_FIELDS}
            for e in elements
            if e["presence"] == "present" and mine(e)
        ]

    nodes = bare(state.graph.nodes)
    errors = bare(state.graph.errors)
    entries: dict[str, set[str]] = {}  # name → the entry files whose models have it
    twice: set[str] = set()
    for node in (n for n in state.graph.nodes if n["presence"] == "present" and mine(n)):
        name, entry = str(node["name"]), str(node["id"]).split("|")[0]
        files = entries.setdefault(name, set())
        # $(anon) names of different files on one command line are different for roslaunch
        if entry in files or (files and not ANON.search(name)):
            twice.add(name)
        files.add(entry)
    return {
        "ok": not errors and not twice,
        "nodes": nodes,
        "tests": bare(state.graph.tests),
        "params": {p["name"]: p["value"] for p in bare(state.graph.params)},
        "errors": errors,
        "conflicts": [{"kind": "node-name", "name": name} for name in sorted(twice)],
    }


def canonical(entries: Sequence[Mapping[str, Any]]) -> list[str]:
    return sorted(json.dumps(e, sort_keys=True) for e in entries)


def _unknowable(errors: Sequence[Mapping[str, Any]]) -> bool:
    """Whether ``errors`` are all of values rosvar cannot know (a package not found)."""
    return bool(errors) and all(error["code"] == "value-unknown" for error in errors)


def same_as_resolve(analysis: Analysis, state: ConfigurationState) -> int:
    """A complete product's graph against ``rosvar resolve`` of its command lines: both must
    agree on whether each command line loads, and one that loads must give the graph's
    present nodes, tests, params and topics. Returns how many command lines loaded."""
    compared = 0
    topics: set[str] | None = set() if state.commands else None  # None: not compared
    for members in state.commands:
        resolution = anon_free(
            resolution_document(resolve(analysis, [m.path for m in members], given(members)))
        )
        ours = anon_free(product(state, [m.spelled for m in members]))
        if ours["ok"] and not resolution["ok"] and _unknowable(resolution["errors"]):
            # what rosvar cannot see (a package outside the roots) stops roslaunch: the
            # product says that parts of it are unknown, and never that it launches
            assert state.unknown and state.launches is not True, state.command
            topics = None
            continue
        assert ours["ok"] == resolution["ok"], state.command
        assert resolution["ok"] or state.launches is not True, state.command
        if not resolution["ok"]:
            topics = None
            continue
        assert canonical(ours["nodes"]) == canonical(resolution["nodes"]), state.command
        assert canonical(ours["tests"]) == canonical(resolution["tests"]), state.command
        assert ours["params"] == resolution["params"], state.command
        if topics is not None:
            topics |= {
                _topic(node, target)
                for node in resolution["nodes"]
                for _source, target in node["remaps"]
            }
        compared += 1
    # an entry's id is its element's, or the element's with /N for its variant N
    present = {
        re.sub(r"/\d+$", "", str(n["id"])) for n in state.graph.nodes if n["presence"] == "present"
    }
    shown = [read(t) for t in state.graph.topics if t["presence"] == "present"]
    assert all(set(t["nodes"]) <= present for t in shown), state.command
    if topics is not None:
        assert {anon_free(t["name"]) for t in shown} == topics, state.command
    return compared


def anon_free(document: Any) -> Any:
    """``document`` with the numbers of ``$(anon)`` names dropped: the engine numbers them per
    file, ``rosvar resolve`` and the oracle per command line (roslaunch draws random ones)."""
    return json.loads(ANON.sub("_anon", json.dumps(document)))


def _topic(node: Mapping[str, Any], target: str) -> str:
    """The topic a resolved node remaps to (as roslaunch resolves a remap's target)."""
    if target.startswith("~"):
        return names.ns_join(str(node["name"]) + "/", target[1:])
    return names.ns_join(str(node["namespace"]), target)
