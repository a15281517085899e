"""Helpers for the configuration tests: a configurator whose files are named by base name."""

from __future__ import annotations

import os
from collections.abc import Mapping
from typing import TYPE_CHECKING

from rosvar.analyses.features import extract
from rosvar.configuration.choices import UserChoice
from rosvar.configuration.engine import ConfigurationState, Configurator

if TYPE_CHECKING:
    from conftest import LaunchWorkspace


def configurator(ws: LaunchWorkspace, env: Mapping[str, str] | None = None) -> Configurator:
    """Feature ids read ``a.launch``, ``a.launch:x``, ``a.launch:x=1``."""
    analysis = ws.analysis()
    model = extract(analysis)
    spelling = {os.path.realpath(f.file): os.path.basename(f.file) for f in model.files}
    return Configurator(analysis, model, env, spelling)


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
