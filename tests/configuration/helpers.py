"""Helpers for the configuration tests: a configurator whose files are named by base name."""

from __future__ import annotations

import json
import os
import random
import re
from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING, Any

from rosvar.analyses.feature_model.extraction import extract
from rosvar.configuration.choices import UserChoice
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
    model = extract(analysis, products=True)
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
        state = engine.state(chosen)
        if state.untyped:
            chosen.append(UserChoice("set", state.untyped[0], f"typed{rng.randint(0, 9)}"))
            continue
        if state.complete:
            return state
        open_ = [f for f in engine.catalog if state.features[f.id].state == "unselected"]
        known = [f for f in open_ if f.value != "<other>"]
        feature = rng.choice(known or open_)
        action = "select" if feature.kind == "value" or rng.random() < 0.2 else "deselect"
        chosen.append(UserChoice(action, feature.id))


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
        assert ours["ok"] == resolution["ok"], state.command
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
        re.sub(r"/\d+$", "", n["id"]) for n in state.graph.nodes if n["presence"] == "present"
    }
    shown = [t for t in state.graph.topics if t["presence"] == "present"]
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
