"""``<param>``: one parameter, typed as roslaunch types it; ``command=`` is never run."""

from __future__ import annotations

from rosvar.files import Confinement, FileCode, FileRefused, read_file
from rosvar.frontends.entity import Entity
from rosvar.interpreter.interpretation import Interpretation, processed, split
from rosvar.interpreter.model import Binary, DeferredValue, ParamDecl, ParamSource, Raw
from rosvar.logic.choice import Choice, Fail
from rosvar.logic.terms import Apply, TermError, register
from rosvar.ros import names
from rosvar.ros1.dialect import tag
from rosvar.ros1.rosparam_yaml import load_yaml
from rosvar.ros1.scope import PrivateParam, Scope
from rosvar.ros1.tags.rosparam import read_text
from rosvar.ros1.typed_values import convert_scalar

ATTRIBUTES = ("name", "value", "type", "textfile", "binfile", "command")
SOURCES = tuple(ParamSource)  # iterating the enum itself costs a generator per <param>


def convert_value(value: str, type_: str) -> object:
    """roslaunch's ``convert_value``: ``auto`` guesses int, float, bool, then str."""
    type_ = type_.lower()
    if type_ == "yaml":
        return load_yaml(value)  # YamlInvalid is a ValueError, as roslaunch's are
    return convert_scalar(value, type_)


def param_value(kind: ParamSource, raw: str, ptype: str, confinement: Confinement) -> object:
    """``Loader.param_value`` for a concrete string; raises ValueError/OSError as roslaunch
    (and :class:`FileRefused` for a file rosvar's rules forbid reading)."""
    if kind == ParamSource.VALUE:
        return convert_value(raw.strip(), ptype)
    if kind == ParamSource.TEXTFILE:  # read once while unchanged: every includer loads it again
        return convert_value(read_text(raw, confinement), ptype)
    if kind == ParamSource.BINFILE:
        return Binary(read_file(raw, confinement))
    return convert_value(f"__command__({raw})", ptype)


def _unread(_host: object, kind: str, path: str, reason: str) -> str:
    raise TermError(f"{kind} {path} was not read: {reason}")


register("unread", _unread)


def _value_choice(
    it: Interpretation[Scope], kind: ParamSource, raw: Choice[Raw], ptype: str
) -> Choice[object]:
    def convert(leaf: Raw) -> object:
        if not isinstance(leaf, str):
            return (
                DeferredValue(leaf, ptype, kind, param_value)
                if kind in (ParamSource.VALUE, ParamSource.COMMAND)
                else Fail(
                    f"{kind} path {leaf} is only known per configuration", "param-unknown-file"
                )
            )
        try:
            if kind is ParamSource.VALUE:  # reads no file: no confinement to ask for
                return convert_value(leaf.strip(), ptype)
            return param_value(kind, leaf, ptype, it.workspace.confinement())
        except FileRefused as refused:
            if refused.code != FileCode.OUTSIDE:
                return Fail(f"Invalid <param> tag: {leaf}: {refused.message}", refused.code)
            it.warn(refused.code, f"{kind} {leaf} is not read: {refused.message}")
            return Apply("unread", (kind, leaf, refused.message), f"⟨{kind} {leaf}⟩")
        except (ValueError, OSError) as error:
            return Fail(f"Invalid <param> tag: {error}", "param-invalid")

    return it.strip(raw.map(convert))


def add_private(
    it: Interpretation[Scope], params: list[PrivateParam], key: str, value: Choice[object]
) -> None:
    """``LoaderContext.add_param``: a later ``~key`` hides an earlier one."""
    for param in params:
        if param.key == key:
            break
    else:  # (most keys are new: nothing to hide)
        params.append(PrivateParam(it.pc, key, value, it.location))
        return
    kept = []
    for param in params:
        if param.key == key:
            param = PrivateParam(param.condition & ~it.pc, key, param.value, param.location)
            if param.condition == it.space.false:
                continue
        kept.append(param)
    kept.append(PrivateParam(it.pc, key, value, it.location))
    params[:] = kept


@processed
def handle_param(
    it: Interpretation[Scope], entity: Entity, scope: Scope, force_local: bool
) -> None:
    it.check_attributes(entity, ATTRIBUTES)
    ptype = (entity.get("type") or "auto").lower().strip()
    attributes = entity.attributes
    present = [(k, it.attr(entity, k, scope)) for k in SOURCES if k in attributes]
    if len(present) != 1:
        it.fail(
            it.space.true,
            "param-invalid",
            "<param> tag must have one and only one of value/textfile/binfile.",
        )
        return
    kind, raw = present[0]
    assert raw is not None
    if not entity.has("name"):
        it.fail(
            it.space.true,
            "attribute-missing",
            "<param> tag is missing required attribute: 'name'",
        )
        return
    names_choice = it.resolve((entity.get("name") or "").strip(), scope, "<param> name")
    assert names_choice is not None
    value = _value_choice(it, kind, raw, ptype)
    if not value.branches:
        return
    for condition, name in split(it, names_choice):
        with it.under(condition):
            private = isinstance(name, str) and names.is_private(name)
            if private or force_local:
                key = names.canonicalize_name(name) if isinstance(name, str) else name
                if isinstance(key, str):
                    add_private(it, scope.params, key, value)
                else:
                    it.warn(
                        "param-name-unknown",
                        f"param name {key} is only known per configuration",
                    )
            else:
                joined = it.lift("ns_join", scope.ns, Choice.const(it.space, name))
                full = it.lift("canonicalize", joined)
                textfile = raw if kind == ParamSource.TEXTFILE else None
                it.model.params.append(ParamDecl(it.pc, entity.location, full, value, textfile))


@tag("param")
def handle_param_tag(it: Interpretation[Scope], entity: Entity, scope: Scope) -> None:
    handle_param(it, entity, scope, force_local=False)
