"""The include memo (:mod:`rosvar.ros2.include_memo`) changes no model: random include trees
analysed with it and without it give the same models, diagrams compared in one space."""

from __future__ import annotations

import dataclasses
import random
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

import pytest

from rosvar.interpreter import interpretation, substitution_args
from rosvar.interpreter.model import LaunchModel
from rosvar.interpreter.workspace_models import Analysis
from rosvar.logic.choice import Choice
from rosvar.logic.given_up import GivenUp
from rosvar.ros2 import include_memo, substitutions
from rosvar.ros2.tags import include
from rosvar.workspace import discover

MANIFEST = """<package format="3"><name>p</name>
<export><build_type>ament_cmake</build_type></export></package>"""

VALUES = (
    "x",
    "y",
    "$(var a)",
    "$(var b)",
    "$(var c x)",
    "$(var a)_$(var b)",
    "$(eval '$(var a)' == 'x')",
    "$(env E y)",
)
FLAGS = ("true", "false", "$(var b)", "$(eval '$(var a)' == 'y')", "$(var c true)")
COMMON = ("arg", "let", "node", "include", "include", "group", "push", "remap", "parameter")
LEAKING = ("let", "push", "remap", "parameter")
"""Statements that change what every later include reads, unless in a scoped group."""
RARE = ("reset", "env", "timer", "anon", "handler", "required")
"""Statements whose effect no replay reproduces (or that read every configuration): the
walks holding them are walked every time."""


class _Writer:
    """Random launch files whose statements of every kind read the configurations ``a``,
    ``b`` and ``c`` and set ``c``, ``d`` and ``e``; each file includes the files before it,
    passing ``a`` and ``b`` most often, an include often twice alike."""

    def __init__(self, rng: random.Random, files: int, rare: float) -> None:
        self.rng = rng
        self.names = [f"f{index}.launch.xml" for index in range(files)]
        self.rare = rare

    def value(self) -> str:
        return self.rng.choice(VALUES)

    def condition(self) -> str:
        rng = self.rng
        if rng.random() < 0.6:
            return ""
        return f' {rng.choice(("if", "unless"))}="{rng.choice(FLAGS)}"'

    def file(self, index: int) -> str:
        lines = [
            '<arg name="a" default="x"><choice value="x"/><choice value="y"/></arg>',
            f'<arg name="b" default="{self.rng.choice(("true", "false"))}"/>',
        ]
        lines += self.statements(index, self.rng.randint(4, 10), 0)
        return "<launch>" + "".join(lines) + "</launch>"

    def statements(self, index: int, count: int, depth: int) -> list[str]:
        rng = self.rng
        lines: list[str] = []
        for number in range(count):
            kinds = COMMON if rng.random() >= self.rare else RARE
            kind = rng.choice(kinds)
            if kind == "include" and index == 0:
                kind = "node"
            if kind == "group" and depth > 1:
                kind = "let"
            statement = self.statement(kind, index, f"{index}_{depth}_{number}", depth)
            if kind in LEAKING and depth == 0 and rng.random() < 0.7:
                statement = ["<group>", *statement, "</group>"]  # most often scoped
            lines += statement
        return lines

    def statement(self, kind: str, index: int, tag: str, depth: int) -> list[str]:
        rng = self.rng
        when = self.condition()
        if kind == "include":
            target = self.names[rng.randrange(index)]
            passed = "".join(
                f'<arg name="{n}" value="{rng.choice(("x", "y", self.value()))}"/>'
                for n, often in (("a", 1.0), ("b", 1.0), ("c", 0.5))
                if rng.random() < often
            )
            when = when if rng.random() < 0.3 else ""
            once = f'<include file="$(dirname)/{target}"{when}>{passed}</include>'
            return [once, once] if rng.random() < 0.5 else [once]
        fields = {
            "name": rng.choice("cde"),  # the args a and b are passed (and leak) by includes
            "when": when,
            "tag": tag,
            "values": [self.value() for _ in range(3)],
            "scoped": rng.choice(("", ' scoped="false"', ' forwarding="false"')),
        }
        if kind == "group":
            scoped = fields["scoped"]
            keep = TEMPLATES["keep"] if "forwarding" in str(scoped) else ""
            body = "".join(self.statements(index, rng.randint(1, 3), depth + 1))
            return [f"<group{scoped}{{when}}>{keep}{body}</group>".format(**fields)]
        return [TEMPLATES[kind].format(**fields)]


TEMPLATES = {
    "arg": '<arg name="{name}" default="{values[0]}"{when}/>',
    "required": '<arg name="{name}"/>',
    "let": '<let name="{name}" value="{values[0]}"{when}/>',
    "node": '<node pkg="p" exec="e" name="n{tag}" namespace="{values[0]}"{when}>'
    '<param name="p" value="{values[1]}"/><remap from="r" to="{values[2]}"/></node>',
    "keep": '<keep name="{name}" value="{values[1]}"/>',
    "push": '<push-ros-namespace namespace="{values[0]}"/>',
    "remap": '<set_remap from="s" to="{values[0]}"{when}/>',
    "parameter": '<set_parameter name="q" value="{values[0]}"{when}/>',
    "reset": '<reset{when}><keep name="{name}" value="{values[0]}"/></reset>',
    "env": '<set_env name="E" value="{values[0]}"{when}/>',
    "timer": '<timer period="1.0"><node pkg="p" exec="t" name="t{tag}"/></timer>',
    "anon": '<node pkg="p" exec="e" name="$(anon n{tag})"/>',
    "handler": '<on_process_start target="x"><node pkg="p" exec="h" name="h{tag}"/>'
    "</on_process_start>",
}
"""Each statement but includes and groups, filled with a random name, condition, values."""


def _plain(value: object) -> object:
    """``value`` with choices as their branches and records as their fields, comparable with
    ``==`` (diagrams of one space compare as diagrams)."""
    if isinstance(value, Choice):
        return ("choice", tuple((condition, _plain(leaf)) for condition, leaf in value))
    if isinstance(value, GivenUp):  # equal only to itself: by its text and operands
        return ("given up", value.operands, _plain(value.choices))
    if dataclasses.is_dataclass(value) and not isinstance(value, type):
        fields = dataclasses.fields(value)
        return (type(value).__name__, tuple(_plain(getattr(value, f.name)) for f in fields))
    if isinstance(value, list | tuple):
        return tuple(_plain(item) for item in value)
    if isinstance(value, dict):
        return tuple((key, _plain(item)) for key, item in value.items())
    if isinstance(value, set | frozenset):
        return frozenset(value)
    return value


def _write(tmp_path: Path, seed: str, files: int, rare: float) -> list[str]:
    writer = _Writer(random.Random(f"include-memo:{seed}"), files, rare)
    package = tmp_path / "p"
    (package / "launch").mkdir(parents=True)
    (package / "package.xml").write_text(MANIFEST)
    paths = []
    for index, name in enumerate(writer.names):
        path = package / "launch" / name
        path.write_text(writer.file(index))
        paths.append(str(path))
    return paths


@contextmanager
def _counted(replays: list[int]) -> Iterator[None]:
    """Count the walks the memo replays."""
    replay = include_memo._replay

    def counted(*args: object) -> None:
        replays[0] += 1
        replay(*args)  # type: ignore[arg-type]

    with pytest.MonkeyPatch.context() as patched:
        patched.setattr(include_memo, "_replay", counted)
        yield


def _compare(tmp_path: Path, seed: str, files: int, rare: float) -> int:
    """Models with the memo and without it, in one analysis; the replays made."""
    return _compared(_write(tmp_path, seed, files, rare))[0]


def _compared(paths: list[str]) -> tuple[int, list[LaunchModel]]:
    """The replays made, and the models without the memo (equal to those with it), of the
    entry files ``paths`` analysed in this order."""
    tmp_path = Path(paths[0]).parent.parent.parent
    analysis = Analysis(discover([str(tmp_path)]), env_values={"E": ["x", "y"]})
    replays = [0]
    with _counted(replays):
        memoised = [_plain(analysis.model(path)) for path in paths]
    analysis._models.clear()  # interpreted again in the same space: diagrams compare
    with pytest.MonkeyPatch.context() as patched:
        patched.setattr(include, "walk_included", include_memo._walk)
        plain = [_plain(analysis.model(path)) for path in paths]
        models = [analysis.model(path) for path in paths]
    for path, with_memo, without in zip(paths, memoised, plain, strict=True):
        assert with_memo == without, Path(path).name
    return replays[0], models


@pytest.mark.parametrize("seed", [f"tree-{n}" for n in range(16)])
def test_random_trees_give_the_same_models(tmp_path: Path, seed: str) -> None:
    _compare(tmp_path, seed, 6, 0.1)


@pytest.mark.parametrize("seed", [f"rare-{n}" for n in range(8)])
def test_statements_no_replay_reproduces_are_walked_again(tmp_path: Path, seed: str) -> None:
    """Resets, environment variables, timers, handlers, anonymous names and included
    files' inputs everywhere."""
    _compare(tmp_path, seed, 5, 0.5)


@pytest.mark.parametrize("seed", [f"limits-{n}" for n in range(8)])
def test_limits_are_met_where_a_walk_would_meet_them(
    tmp_path: Path, seed: str, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Includes, include depth and nesting bounded low: a replay must not pass a limit
    that the walk it stands for would meet from where it stands."""
    for module in (include, include_memo):
        monkeypatch.setattr(module, "MAX_INCLUDES", 12)
        monkeypatch.setattr(module, "MAX_INCLUDE_DEPTH", 4)
    monkeypatch.setattr(include_memo, "MAX_NESTING", 7)
    monkeypatch.setattr(interpretation, "MAX_NESTING", 7)
    _compare(tmp_path, seed, 7, 0.05)


def test_random_trees_are_replayed(tmp_path: Path) -> None:
    """The comparisons above are not vacuous: their walks are replayed."""
    replays = sum(_compare(tmp_path / str(n), f"tree-{n}", 6, 0.1) for n in range(8))
    assert replays >= 15


def _files(tmp_path: Path, texts: dict[str, str]) -> list[str]:
    """The launch files ``texts`` (bodies of ``<launch>``) of one package, in order."""
    package = tmp_path / "p"
    (package / "launch").mkdir(parents=True)
    (package / "package.xml").write_text(MANIFEST)
    paths = []
    for name, text in texts.items():
        path = package / "launch" / f"{name}.launch.xml"
        path.write_text(f"<launch>{text}</launch>")
        paths.append(str(path))
    return paths


def _include(name: str, passed: str = "") -> str:
    return f'<include file="$(dirname)/{name}.launch.xml">{passed}</include>'


def _codes(model: LaunchModel) -> list[str]:
    return [error.code for error in model.errors] + [d.code for d in model.diagnostics]


def test_a_replay_reads_what_the_walk_read(tmp_path: Path) -> None:
    """A file included twice with the same binding is walked once; a third include with
    another value of what it reads is walked again, and each gives its own node."""
    passed = '<arg name="a" value="{}"/>'
    main = "".join(_include("leaf", passed.format(value)) for value in "xxy")
    texts = {"leaf": '<arg name="a"/><node pkg="p" exec="e" name="n_$(var a)"/>', "main": main}
    replays, models = _compared(_files(tmp_path, texts))
    names = [node.field("name").single() for node in models[1].nodes]
    assert names == ["n_x", "n_x", "n_y"]
    assert replays == 1


def test_a_replay_reads_what_is_not_set(tmp_path: Path) -> None:
    """A walk replayed in another entry file still reads the names it read unset: an
    included file declaring one later makes it an input from the start."""
    texts = {
        "leaf": '<node pkg="p" exec="e" name="$(var q d)"/>',
        "other": _include("leaf"),
        "decl": '<arg name="q" default="z"/>',
        "main": _include("leaf") + _include("decl"),
    }
    replays, models = _compared(_files(tmp_path, texts))
    assert replays >= 1
    name = models[3].nodes[0].field("name")
    assert [leaf for _condition, leaf in name if isinstance(leaf, str)] == ["z", "d"]


def test_a_replay_warns_as_the_walk_did(tmp_path: Path) -> None:
    """A walk replayed in another entry file gives its diagnostics there too."""
    node = '<node pkg="p" exec="e" name="n" args="$(find-exec tool)"/>'
    texts = {"leaf": node, "other": _include("leaf"), "main": _include("leaf")}
    replays, models = _compared(_files(tmp_path, texts))
    assert replays >= 1
    assert "find-exec-host" in _codes(models[2])


def test_a_replay_meets_the_cycle_the_walk_would(tmp_path: Path) -> None:
    """``y`` includes ``z``, which includes ``y`` only where ``y`` did not run before:
    recorded from ``w``, then replayed where ``z`` is the entry file, it meets the cycle."""
    back = '<include file="$(dirname)/y.launch.xml" unless="$(var k 0)"/>'
    texts = {"w": _include("y"), "y": '<let name="k" value="1"/>' + _include("z"), "z": back}
    _replays, models = _compared(_files(tmp_path, texts))
    assert "include-cycle" not in _codes(models[0])
    assert "include-cycle" in _codes(models[2])


LIMITED = {
    "leaf": '<node pkg="p" exec="e" name="n"/>',
    "mid": _include("leaf") + _include("leaf"),
    "many": _include("mid") + _include("mid") + _include("mid"),
    "wrap": _include("mid"),
    "deep": _include("mid") + _include("wrap"),
}


@pytest.mark.parametrize(
    ("limit", "value", "entry"), [("MAX_INCLUDES", 5, 2), ("MAX_INCLUDE_DEPTH", 3, 4)]
)
def test_a_replay_meets_the_include_limits_the_walk_would(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, limit: str, value: int, entry: int
) -> None:
    """Replayed, a walk counts its includes and their depth as the walk would: the limit
    falls inside a walk recorded where it did not."""
    for module in (include, include_memo):
        monkeypatch.setattr(module, limit, value)
    replays, models = _compared(_files(tmp_path, LIMITED))
    assert replays >= 2
    assert "include-too-many" in _codes(models[entry])


def test_a_replay_meets_the_nesting_limit_the_walk_would(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setattr(include_memo, "MAX_NESTING", 4)
    monkeypatch.setattr(interpretation, "MAX_NESTING", 4)
    texts = {
        "leaf": '<group><group><node pkg="p" exec="e" name="n"/></group></group>',
        "main": _include("leaf") + f"<group>{_include('leaf')}</group>",
    }
    replays, models = _compared(_files(tmp_path, texts))
    assert replays == 0
    assert "nesting-too-deep" in _codes(models[1])


def test_a_replay_spends_the_value_budget_the_walk_would(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Texts the substitution memo does not keep (``$(env)``) spend the file's budget at
    each walk, replayed or not: the walk past it is not computed."""
    monkeypatch.setattr(substitution_args, "MAX_COMBINATIONS", 10)
    monkeypatch.setattr(substitution_args, "MAX_FILE_COMBINATIONS", 40)
    choices = '<choice value="x"/><choice value="y"/>'
    args = f'<arg name="a" default="x">{choices}</arg><arg name="b" default="x">{choices}</arg>'
    node = '<node pkg="p" exec="e" name="$(var a)_$(env E y)"/>'  # 3 x 2 combinations
    texts = {"leaf": node, "main": args + _include("leaf") * 8}
    replays, models = _compared(_files(tmp_path, texts))
    assert replays >= 2
    assert "value-too-complex" in _codes(models[1])


def test_a_walk_past_the_value_budget_is_not_replayed(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """A walk that met the file's budget (its text not computed) is walked again elsewhere,
    where the budget is not spent."""
    monkeypatch.setattr(substitution_args, "MAX_COMBINATIONS", 10)
    monkeypatch.setattr(substitution_args, "MAX_FILE_COMBINATIONS", 40)
    spend = '<node pkg="p" exec="e" name="$(env F y)_$(env G y)"/>' * 9  # 4 each
    spend += '<node pkg="p" exec="e" name="$(env F y)"/>'  # 2
    leaf = '<node pkg="p" exec="e" name="$(env E y)_$(env G y)"/>'
    texts = {"leaf": leaf, "other": spend + _include("leaf"), "main": _include("leaf")}
    _replays, models = _compared(_files(tmp_path, texts))
    assert "value-too-complex" in _codes(models[1])
    assert "value-too-complex" not in _codes(models[2])


def test_a_walk_that_makes_inputs_is_replayed_in_its_entry_file_only(tmp_path: Path) -> None:
    """``leaf`` makes ``q`` an input of the entry model: ``main``'s second pass (``late`` is
    read before ``decl`` declares it) replays that walk, declaration and listed arg
    included; ``other``, whose inputs are its own, walks it again."""
    leaf = '<arg name="q" default="z"/><node pkg="p" exec="e" name="n_$(var q)"/>'
    texts = {
        "leaf": leaf,
        "decl": '<arg name="late" default="w"/>',
        "main": '<node pkg="p" exec="e" name="m_$(var late d)"/>'
        + _include("leaf")
        + _include("decl"),
        "other": _include("leaf"),
    }
    paths = _files(tmp_path, texts)
    replays, models = _compared([paths[2], paths[3]])
    assert replays == 1
    for model in models:
        assert "q" in model.inputs
        assert [arg.name for arg in model.args if arg.name == "q"] == ["q"]


def test_an_entry_files_own_walks_and_texts_go_when_the_next_starts(tmp_path: Path) -> None:
    """Walks and resolved texts keyed on an entry file's inputs (here a path condition and
    a value over ``x``) serve it only: they are dropped when the analysis starts on the next
    entry file; those keyed on constants stay for every entry file (and are replayed
    there)."""
    leaf = '<arg name="a"/><node pkg="p" exec="e" name="n_$(var a)"/>'
    texts = {
        "leaf": leaf,
        "one": '<arg name="x" default="true"/><group if="$(var x)">'
        + _include("leaf", '<arg name="a" value="$(var x)"/>')
        + "</group>",
        "two": _include("leaf", '<arg name="a" value="k"/>'),
        "three": _include("leaf", '<arg name="a" value="k"/>'),
    }
    paths = _files(tmp_path, texts)
    analysis = Analysis(discover([str(tmp_path)]))
    space = analysis.space

    def varying() -> tuple[int, int]:
        walks = include_memo._table(analysis.files)
        resolved = substitutions._resolved[space]
        return sum(map(space.varies, walks)), sum(map(space.varies, resolved))

    analysis.model(paths[1])
    assert all(varying())  # one's own: over its input x
    analysis.model(paths[2])
    assert varying() == (0, 0)
    kept = len(include_memo._table(analysis.files))
    replays = [0]
    with _counted(replays):
        names = [n.field("name").single() for n in analysis.model(paths[3]).nodes]
    assert names == ["n_k"] and replays[0] == 1 and kept > 0
