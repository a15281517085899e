"""``<rosparam>``: YAML (inline or from a file) as parameters; ``dump``/``delete`` act at launch."""

from __future__ import annotations

import functools
import os

import yaml

from rosvar.frontends.entity import Entity
from rosvar.interpreter.interpretation import Interpretation, split, tag
from rosvar.interpreter.model import ParamDecl, Raw, YamlDecl
from rosvar.interpreter.scope import Scope
from rosvar.interpreter.tags.common import bool_value
from rosvar.interpreter.values import load_yaml
from rosvar.logic.choice import Choice
from rosvar.logic.terms import Term
from rosvar.ros import names

ATTRIBUTES = ("command", "ns", "file", "param", "subst_value")


def unroll(name: str, value: object) -> list[tuple[str, object]]:
    """``Loader.add_param``: dicts become one param per leaf (raises like roslaunch)."""
    if not name:
        raise ValueError("no parameter name specified")
    if name == "/" and not isinstance(value, dict):
        raise ValueError("Cannot load non-dictionary types into global namespace '/'")
    if isinstance(value, dict):
        result: list[tuple[str, object]] = []
        for key, item in value.items():
            result.extend(unroll(names.ns_join(name, str(key)), item))
        return result
    return [(names.canonicalize_name(name), value)]


@functools.lru_cache(maxsize=4096)
def yaml_params(text: str, full_param: str, param: str, source: str) -> list[tuple[str, object]]:
    """What ``load_rosparam`` sets for a concrete YAML text (cached: callers must not mutate)."""
    try:
        data = load_yaml(text)
    except yaml.YAMLError as error:
        where = "YAML block" if not source else f"file {source}"
        raise ValueError(f"invalid YAML in {where}: {error}") from error
    if data is None:
        data = {}
    if not param and not isinstance(data, dict):
        raise ValueError("'param' attribute must be set for non-dictionary values")
    return unroll(full_param, data)


@tag("rosparam")
def handle_rosparam(it: Interpretation, entity: Entity, scope: Scope) -> None:
    with it.under(it.condition_of(entity, scope)) as live:
        if not live:
            return
        it.check_attributes(entity, ATTRIBUTES)
        values = {a: it.attr(entity, a, scope) for a in ATTRIBUTES}
        subst = bool_value(it, values["subst_value"], False, "subst_value")
        for s_condition, substitute in split(it, subst):
            with it.under(s_condition):
                _load(it, entity, scope, values, substitute is True)


def _one(it: Interpretation, value: Choice[Raw] | None) -> list[tuple[object, Raw | None]]:
    if value is None:
        return [(it.space.true, None)]
    return list(split(it, value))


def _load(
    it: Interpretation,
    entity: Entity,
    scope: Scope,
    values: dict[str, Choice[Raw] | None],
    substitute: bool,
) -> None:
    for c_cmd, command in _one(it, values["command"]):
        for c_ns, ns in _one(it, values["ns"]):
            for c_file, file in _one(it, values["file"]):
                for c_param, param in _one(it, values["param"]):
                    with it.under(c_cmd & c_ns & c_file & c_param) as live:  # type: ignore[operator]
                        if live:
                            _load_one(
                                it, entity, scope, command or "load", ns, file, param, substitute
                            )


def _load_one(
    it: Interpretation,
    entity: Entity,
    scope: Scope,
    command: Raw,
    ns: Raw | None,
    file: Raw | None,
    param: Raw | None,
    substitute: bool,
) -> None:
    true = it.space.true
    if not all(isinstance(v, str) or v is None for v in (command, ns, file, param)):
        it.warn("rosparam-unknown", "<rosparam> attributes are only known per configuration")
        return
    assert isinstance(command, str)
    if command not in ("load", "dump", "delete"):
        it.fail(
            true,
            "rosparam-invalid",
            "error loading <rosparam> tag: command must be 'load', 'dump', or 'delete'",
        )
        return
    if file is not None:
        assert isinstance(file, str)
        if command == "load" and not os.path.isfile(file):
            it.fail(
                true, "file-missing", f"error loading <rosparam> tag: file does not exist [{file}]"
            )
            return
        if command == "delete":
            it.fail(
                true,
                "rosparam-invalid",
                "error loading <rosparam> tag: 'file' attribute is invalid with 'delete' command.",
            )
            return
    if command != "load":
        return
    param_name = names.ns_join(ns or "", param or "")  # type: ignore[arg-type]
    if file is not None:
        try:
            with open(file) as handle:
                text: Raw = handle.read()
        except OSError as error:
            it.fail(true, "file-unreadable", f"error loading <rosparam> tag: {error}")
            return
    else:
        text = entity.text
    full_params = (
        it.lift("ns_join", scope.ns, Choice.const(it.space, param_name)) if param_name else scope.ns
    )
    texts: Choice[Raw] = Choice.const(it.space, text)
    if substitute:
        resolved = it.resolve(text, scope, "<rosparam> body")  # type: ignore[arg-type]
        assert resolved is not None
        texts = resolved
    for t_condition, body in split(it, texts):
        for p_condition, full in split(it, full_params):
            with it.under(t_condition & p_condition):
                if not isinstance(body, str) or not isinstance(full, str):
                    it.model.params.append(
                        YamlDecl(
                            it.pc, entity.location, Choice.const(it.space, full), param_name, body
                        )
                    )
                    continue
                try:
                    pairs = yaml_params(body, full, param_name, file or "")
                except ValueError as error:
                    it.fail(true, "rosparam-invalid", f"error loading <rosparam> tag: {error}")
                    continue
                for key, value in pairs:
                    it.model.params.append(
                        ParamDecl(
                            it.pc,
                            entity.location,
                            Choice.const(it.space, key),
                            Choice.const(it.space, value),
                            "rosparam",
                        )
                    )


_ = Term
