"""JSON export: keys and types of every part, the counts and findings of the solver, and the
registry that dispatches to every writer."""

from __future__ import annotations

import json
from typing import TYPE_CHECKING, Any

import pytest

from rosvar.analyses.feature_model import extraction
from rosvar.analyses.feature_model.model import FeatureModel
from rosvar.analyses.feature_model.operations import core_and_dead, count_configurations
from rosvar.outputs.exports import FORMATS, write, writer
from rosvar.outputs.exports import json as json_export
from rosvar.outputs.exports._common import Tree

from .test_uvl import tricky

if TYPE_CHECKING:
    from conftest import LaunchWorkspace  # tests/conftest.py

LOCATION = {"file": str, "line": int, "col": int}


def typed(data: dict[str, Any], schema: dict[str, Any]) -> None:
    """``data`` has exactly ``schema``'s keys, each value of its type (a tuple: any of them)."""
    assert set(data) == set(schema), set(data) ^ set(schema)
    for key, kind in schema.items():
        assert isinstance(data[key], kind), (key, data[key])


def check(model: FeatureModel) -> dict[str, Any]:
    text = write(model, "json")
    document: dict[str, Any] = json.loads(text)
    typed(
        document,
        {
            "system": str,
            "features": list,
            "constraints": list,
            "configurations": int if model.solved else type(None),
            "core": list if model.solved else type(None),
            "dead": list if model.solved else type(None),
            "conflicts": list,
            "diagnostics": list,
        },
    )
    assert len(document["diagnostics"]) == len(model.diagnostics)
    tree = Tree(model)
    assert document["system"] == tree.root
    assert document["configurations"] == count_configurations(model)
    ids = [f["id"] for f in document["features"]]
    assert ids == [e.id for e in tree.entries]
    kinds = {f["id"]: f["kind"] for f in document["features"]}
    for feature in document["features"]:
        common = {"id": str, "kind": str, "parent": (str, type(None))}
        if feature["kind"] == "file":
            typed(feature, {**common, "path": str, "args": list})
            assert feature["parent"] is None
            assert all(kinds[a] == "arg" for a in feature["args"])
        elif feature["kind"] == "arg":
            typed(
                feature,
                {
                    **common,
                    "name": str,
                    "default": (str, type(None)),
                    "boolean": bool,
                    "values": list,
                    "location": (dict, type(None)),
                },
            )
            assert kinds[feature["parent"]] == "file"
            assert all(kinds[v] == "value" for v in feature["values"])
            if feature["location"] is not None:
                typed(feature["location"], LOCATION)
        else:
            assert feature["kind"] == "value"
            typed(feature, {**common, "value": str, "default": bool})
            assert kinds[feature["parent"]] == "arg"
    assert len(document["constraints"]) == len(model.constraints)
    for constraint in document["constraints"]:
        typed(
            constraint,
            {
                "kind": str,
                "files": list,
                "condition": str,
                "unconditional": bool,
                "text": str,
                "formula": (str, type(None)),
                "locations": list,
            },
        )
        assert constraint["kind"] in ("requires", "excludes")
        assert all(kinds[f] == "file" for f in constraint["files"])
        for location in constraint["locations"]:
            typed(location, LOCATION)
    verdicts = core_and_dead(model) if model.solved else []
    for kind in ("core", "dead") if model.solved else ():
        assert [v["feature"] for v in document[kind]] == [
            v.feature for v in verdicts if v.kind == kind
        ]
        for verdict in document[kind]:
            typed(verdict, {"feature": str, "because": list})
    for conflict in document["conflicts"]:
        typed(
            conflict,
            {
                "kind": str,
                "name": str,
                "files": list,
                "condition": str,
                "trigger": dict,
                "locations": list,
            },
        )
        assert all(kinds[f] == "file" for f in conflict["files"])
        assert all(
            isinstance(k, str) and isinstance(v, str) for k, v in conflict["trigger"].items()
        )
    return document


def test_corpus(model: FeatureModel) -> None:
    check(model)


def test_examples(examples_model: FeatureModel) -> None:
    document = check(examples_model)
    assert document["configurations"] == 798
    requires = document["constraints"][0]
    assert requires == {
        "kind": "requires",
        "files": ["example/launch/mapping.launch", "example/launch/control.xml"],
        "condition": "¬sim",
        "unconditional": False,
        "text": "example/launch/mapping.launch includes example/launch/control.xml",
        "formula": "example/launch/mapping.launch:sim=false ⇒ example/launch/control.xml",
        "locations": [requires["locations"][0]],
    }
    triggers = {(c["name"], c["condition"]): c["trigger"] for c in document["conflicts"]}
    assert triggers == {
        ("/controller", "use_teleop"): {"control.xml:use_teleop": "true"},
        ("/controller", "¬use_teleop"): {"control.xml:use_teleop": "false"},
        ("/max_speed", "true"): {},
    }
    arg = next(f for f in document["features"] if f["id"] == "example/launch/control.xml:vel_topic")
    assert (arg["default"], arg["boolean"], len(arg["values"])) == ("cmd_vel", False, 2)


def test_dead_features_are_explained(dead_model: FeatureModel) -> None:
    """A file that includes two files clashing unconditionally can never be selected."""
    document = check(dead_model)
    assert [v["feature"] for v in document["dead"]] == ["pkg/launch/both.launch"]
    assert len(document["dead"][0]["because"]) == 3


def test_tricky(ws: LaunchWorkspace) -> None:
    document = check(tricky(ws))
    (conflict,) = document["conflicts"]
    assert conflict["trigger"] == {"clash.launch:on": "true"}


def test_a_model_too_large_to_solve_is_still_listed(
    ws: LaunchWorkspace, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setattr(extraction, "LINK_BUDGET", 0)
    monkeypatch.setattr(extraction, "LINKS_PER_FILE", 0)
    model = tricky(ws)
    document = check(model)
    assert not model.solved
    assert document["constraints"] and all(c["formula"] is None for c in document["constraints"])
    assert len(document["conflicts"]) == 1
    codes = [d["code"] for d in document["diagnostics"]]
    assert codes.count("model-too-large") == 1 and codes[-1] == "model-too-large", codes


def test_registry(examples_model: FeatureModel) -> None:
    assert set(FORMATS) == {"text", "json", "uvl", "featureide", "dot"}
    for name in FORMATS:
        assert write(examples_model, name) == writer(name)(examples_model)
    assert write(examples_model, "json") == json_export.write(examples_model)
    with pytest.raises(ValueError, match="unknown feature-model format 'sxfm'"):
        write(examples_model, "sxfm")
