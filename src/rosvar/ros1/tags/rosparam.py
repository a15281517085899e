"""``<rosparam>``: YAML (inline or from a file) as parameters; ``dump``/``delete`` act at launch."""

from __future__ import annotations

import functools
import io
import os
import stat

from rosvar.files import Confinement, FileCode, FileRefused, read_file
from rosvar.frontends.entity import Entity
from rosvar.interpreter.booleans import bool_value
from rosvar.interpreter.interpretation import Interpretation, processed, split
from rosvar.interpreter.model import ParamDecl, Raw, YamlDecl
from rosvar.logic.choice import Choice
from rosvar.ros import names
from rosvar.ros1.dialect import tag
from rosvar.ros1.rosparam_yaml import YamlInvalid, load_yaml
from rosvar.ros1.scope import Scope

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
        data = _parsed_yaml(text)
    except YamlInvalid as error:
        where = "YAML block" if not source else f"file {source}"
        raise ValueError(f"invalid YAML in {where}: {error}") from error
    if data is None:
        data = {}
    if not param and not isinstance(data, dict):
        raise ValueError("'param' attribute must be set for non-dictionary values")
    return unroll(full_param, data)


@functools.lru_cache(maxsize=1024)
def _parsed_yaml(text: str) -> object:
    """A YAML text parsed once (many files load the same parameter file in other namespaces)."""
    return load_yaml(text)


@tag("rosparam")
@processed
def handle_rosparam(it: Interpretation[Scope], entity: Entity, scope: Scope) -> None:
    it.check_attributes(entity, ATTRIBUTES)
    values = {a: it.attr(entity, a, scope) for a in ATTRIBUTES}
    subst = bool_value(it, values["subst_value"], False, "subst_value")
    for s_condition, substitute in split(it, subst):
        with it.under(s_condition):
            _load(it, entity, scope, values, substitute is True)


def _one(it: Interpretation[Scope], value: Choice[Raw] | None) -> list[tuple[object, Raw | None]]:
    if value is None:
        return [(it.space.true, None)]
    return list(split(it, value))


def _load(
    it: Interpretation[Scope],
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


def read_text(path: str, confinement: Confinement) -> str:
    """A parameter file's text as ``open(path).read()`` gives it, through
    :func:`rosvar.files.read_file`'s checks; cached while unchanged (many includes load
    the same files). Raises ``OSError`` (:class:`FileRefused` included)."""
    confinement.check(path)
    info = os.stat(path)
    return _read_text(path, info.st_mtime_ns, info.st_size)


def _regular_file(path: str) -> os.stat_result | None:
    """``os.stat`` of ``path`` if it is a regular file (``os.path.isfile``, keeping the
    answer: reading the file then needs no second ``stat``)."""
    try:
        info = os.stat(path)
    except (OSError, ValueError):
        return None
    return info if stat.S_ISREG(info.st_mode) else None


@functools.lru_cache(maxsize=1024)
def _read_text(path: str, _mtime: int, _size: int) -> str:
    with io.TextIOWrapper(io.BytesIO(read_file(path))) as text:  # open()'s decoding
        return text.read()


class FileNotRead(ValueError):
    """``<rosparam file>`` names a file that rosvar's rules forbid reading."""

    def __init__(self, refused: FileRefused) -> None:
        super().__init__(refused.message)
        self.code = refused.code


class MissingFile(ValueError):
    """``<rosparam file>`` names a file that does not exist."""


def load_rosparam(
    command: str,
    ns: str | None,
    file: str | None,
    param: str | None,
    text: str,
    scope_ns: str,
    confinement: Confinement,
) -> list[tuple[str, object]]:
    """``Loader.load_rosparam`` for concrete strings: the params set, or ValueError as roslaunch.

    ``text`` is the inline body (or, with ``subst_value``, the already substituted
    file content, in which case ``file`` is None). A file ``confinement`` forbids is a
    :class:`FileNotRead`, whether it exists or not.
    """
    if command not in ("load", "dump", "delete"):
        raise ValueError("command must be 'load', 'dump', or 'delete'")
    info = None
    if file is not None:
        if command == "load":
            try:
                confinement.check(file)
            except FileRefused as refused:
                raise FileNotRead(refused) from None
            info = _regular_file(file)
            if info is None:
                raise MissingFile(f"file does not exist [{file}]")
        if command == "delete":
            raise ValueError("'file' attribute is invalid with 'delete' command.")
    if command != "load":
        return []
    param_name = names.ns_join(ns or "", param or "")
    if file is not None and info is not None:
        try:
            text = _read_text(file, info.st_mtime_ns, info.st_size)
        except FileRefused as refused:
            raise FileNotRead(refused) from None
        except OSError as error:
            raise ValueError(str(error)) from None
    full = names.ns_join(scope_ns, param_name) if param_name else scope_ns
    return yaml_params(text, full, param_name, file or "")


def _load_one(
    it: Interpretation[Scope],
    entity: Entity,
    scope: Scope,
    command: Raw,
    ns: Raw | None,
    file: Raw | None,
    param: Raw | None,
    substitute: bool,
) -> None:
    text: Raw = entity.text
    if substitute and isinstance(file, str) and command == "load":
        try:
            text = read_text(file, it.workspace.confinement())
        except FileRefused as refused:
            _not_read(it, file, refused.code, refused.message)
            return
        except OSError as error:
            it.fail(it.space.true, "file-unreadable", f"error loading <rosparam> tag: {error}")
            return
        file = None
    if substitute:
        if not isinstance(file, str | None):
            it.warn(
                "rosparam-unknown",
                "<rosparam subst_value> of a file only known per configuration is not analysed",
            )
            return
        resolved = it.resolve(str(text), scope, "<rosparam> body")
        assert resolved is not None
        texts: Choice[Raw] = resolved
    else:
        texts = Choice.const(it.space, text)
    for t_condition, body in split(it, texts):
        for n_condition, scope_ns in split(it, scope.ns):
            with it.under(t_condition & n_condition):
                _emit(it, entity, scope_ns, command, ns, file, param, body)


def _emit(
    it: Interpretation[Scope],
    entity: Entity,
    scope_ns: Raw,
    command: Raw,
    ns: Raw | None,
    file: Raw | None,
    param: Raw | None,
    body: Raw,
) -> None:
    parts = (scope_ns, command, ns, file, param, body)
    if not all(isinstance(part, str) or part is None for part in parts):
        it.model.params.append(
            YamlDecl(
                it.pc, entity.location, scope_ns, command, ns, file, param, body, load_rosparam
            )
        )
        return
    loaded = it.files.kept(__name__)
    values = loaded.get(parts)
    if values is None:
        try:
            pairs = load_rosparam(
                str(command),
                ns if isinstance(ns, str) else None,
                file if isinstance(file, str) else None,
                param if isinstance(param, str) else None,
                str(body),
                str(scope_ns),
                it.workspace.confinement(),
            )
        except FileNotRead as refused:
            _not_read(it, str(file), refused.code, str(refused))
            return
        except ValueError as error:
            code = "file-missing" if isinstance(error, MissingFile) else "rosparam-invalid"
            it.fail(it.space.true, code, f"error loading <rosparam> tag: {error}")
            return
        # loaded once per analysis (an included file loads its parameters for each includer)
        space = it.space
        values = loaded[parts] = [
            (Choice.const(space, k), Choice.const(space, v)) for k, v in pairs
        ]
    pc, location = it.pc, entity.location
    it.model.params.extend([ParamDecl(pc, location, name, value) for name, value in values])


def _not_read(it: Interpretation[Scope], file: str, code: FileCode, message: str) -> None:
    """A file rosvar refuses to read: outside the workspace, its parameters are unknown
    (a warning, as for a file only known per configuration); otherwise roslaunch could
    not load it either (an error event)."""
    if code == FileCode.OUTSIDE:
        it.warn(code, f"<rosparam> file {file} is not read: {message}")
    else:
        it.fail(it.space.true, code, f"error loading <rosparam> tag: {file}: {message}")
