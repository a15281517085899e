"""The ROS 2 substitution grammar: nesting, quoting, escapes."""

from __future__ import annotations

import random
from pathlib import Path

import pytest

from oracle.ros2_client import ORACLE, run_oracle
from ros2.tags.launches import Launch, launch
from rosvar.interpreter.model import LaunchModel
from rosvar.interpreter.safe_eval import EvalEnvironment, evaluate
from rosvar.interpreter.substitution_args import MAX_TERM_DEPTH
from rosvar.interpreter.workspace_models import Analysis
from rosvar.memo import Memo
from rosvar.outputs.describe import describe_model
from rosvar.ros2 import substitutions
from rosvar.ros2.substitutions import Call, SubstitutionSyntaxError, SubstitutionTooDeep, parse
from rosvar.workspace import discover

MANIFEST = """<package format="3"><name>p</name>
<export><build_type>ament_cmake</build_type></export></package>"""


def test_nested_and_quoted_arguments() -> None:
    assert parse("a$(var x)b") == ("a", Call("var", (("x",),)), "b")
    assert parse("$(eval '\\'$(var r)\\' == 1')") == (
        Call("eval", (("'", Call("var", (("r",),)), "' == 1"),)),
    )
    assert parse("$(env A 'b c')") == (Call("env", (("A",), ("b c",))),)


@pytest.mark.parametrize("text", ["$(var x", "$( x)", "$(env 'a)"])
def test_malformed_text_is_refused(text: str) -> None:
    with pytest.raises(SubstitutionSyntaxError):
        parse(text)


def test_nesting_is_bounded_before_the_parser_recurses_too_deep() -> None:
    """Each nested ``$(...)`` is a frame of the parser, and of every walk of its values: 100
    levels (the limit of a value's terms), where 3,000 ended in a RecursionError."""
    nested = "$(var " * MAX_TERM_DEPTH + "x" + ")" * MAX_TERM_DEPTH
    assert parse(nested)[0] == Call("var", (parse(nested[6:-1]),))
    for deeper in (MAX_TERM_DEPTH + 1, 3000):
        with pytest.raises(SubstitutionTooDeep, match="nested more than 100 levels"):
            parse("a $(not " * deeper + "true" + ")" * deeper)


def test_anon_names_are_kept_per_id_and_scoped_by_groups(tmp_path: Path) -> None:
    (tmp_path / "package.xml").write_text(MANIFEST)
    file = tmp_path / "a.launch.xml"
    file.write_text(
        """<launch>
          <node pkg="p" exec="e" name="$(anon n)"/>
          <node pkg="p" exec="e" name="$(anon n)" namespace="x"/>
          <group><node pkg="p" exec="e" name="$(anon m)" namespace="y"/></group>
          <node pkg="p" exec="e" name="$(anon m)" namespace="z"/>
        </launch>"""
    )
    result = Analysis(discover([str(tmp_path)])).resolve([str(file)])
    names = [node.own_name for node in result.nodes]
    assert names[0] == names[1] and names[2] != names[3]
    assert all(str(name).startswith(("n_", "m_")) for name in names)


def test_find_exec_is_kept_as_its_text_with_a_warning(tmp_path: Path) -> None:
    """The PATH that ``$(find-exec)`` searches is the launching machine's: the value stays
    the substitution's text, inside a ``$(command)`` too, and the launch goes on."""
    (tmp_path / "package.xml").write_text(MANIFEST)
    file = tmp_path / "a.launch.xml"
    file.write_text(
        """<launch><arg name="tool" default="xacro"/>
          <node pkg="p" exec="e" name="n">
            <param name="d" value="$(command '$(find-exec $(var tool)) f.xacro')"/>
          </node>
          <node pkg="p" exec="e" name="m" args="$(find-exec)"/>
        </launch>"""
    )
    analysis = Analysis(discover([str(tmp_path)]), extra_values={"tool": ["ros2"]})
    result = analysis.resolve([str(file)], {"tool": "ros2"})
    assert result.nodes[0].parameters == {"d": "$(command $(find-exec ros2) f.xacro)"}
    assert [error.code for error in result.errors] == ["substitution-invalid"]


def test_package_paths_of_an_installed_package_are_below_its_prefix(tmp_path: Path) -> None:
    """``$(find-pkg-prefix)`` and ``$(exec-in-pkg)`` of an installed package are its install
    prefix and ``lib/<package>`` there; a source package's folder stands for its prefix."""
    (tmp_path / "ws" / "package.xml").parent.mkdir()
    (tmp_path / "ws" / "package.xml").write_text(MANIFEST)
    installed = tmp_path / "opt" / "share" / "q"
    installed.mkdir(parents=True)
    (installed / "package.xml").write_text(MANIFEST.replace("<name>p<", "<name>q<"))
    file = tmp_path / "ws" / "a.launch.xml"
    file.write_text(
        """<launch>
          <executable cmd="$(exec-in-pkg run q) $(find-pkg-prefix q)" name="a"/>
          <executable cmd="$(exec-in-pkg run p) $(find-pkg-prefix p)" name="b"/>
        </launch>"""
    )
    workspace = discover([str(tmp_path / "ws")], deps=[str(tmp_path / "opt" / "share")])
    result = Analysis(workspace).resolve([str(file)])
    prefix, source = tmp_path / "opt", tmp_path / "ws"
    assert [node.attributes["cmd"] for node in result.nodes] == [
        [f"{prefix}/lib/q/run", str(prefix)],
        [f"{source}/lib/p/run", str(source)],
    ]


def test_file_content_is_read_only_inside_the_workspace(tmp_path: Path) -> None:
    """``$(file-content)`` reads through the workspace's gate: a file outside it is refused
    and nothing of it is told; a relative path (the launching directory's) is not known: the
    parameter is left out."""
    (tmp_path / "ws").mkdir()
    (tmp_path / "ws" / "package.xml").write_text(MANIFEST)
    (tmp_path / "ws" / "robot.urdf").write_text("<robot name='r'/>")
    (tmp_path / "secret.txt").write_text("SECRET")
    file = tmp_path / "ws" / "a.launch.xml"
    file.write_text(
        """<launch><node pkg="p" exec="e" name="n">
          <param name="inside" value="$(file-content $(find-pkg-share p)/robot.urdf)"/>
        </node>
        <node pkg="p" exec="e" name="m">
          <param name="outside" value="$(file-content $(dirname)/../secret.txt)"/></node>
        <node pkg="p" exec="e" name="k">
          <param name="relative" value="$(file-content robot.urdf)"/></node>
        </launch>"""
    )
    result = Analysis(discover([str(tmp_path / "ws")])).resolve([str(file)])
    assert [node.parameters for node in result.nodes] == [{"inside": "<robot name='r'/>"}, {}, {}]
    assert [error.code for error in result.errors] == [
        "file-outside-workspace",
        "substitution-unsupported",
    ]
    assert "SECRET" not in repr(result.errors)


_TEXTS = (
    "lit",
    "$(var a)",
    "$(var c)",
    "$(var p q)",
    "$(var a)_$(var c)",
    "$(eval '$(var a)' == 'x')",
    "$(eval '$(var b)' == 'true' and '$(var p q)' != 'r')",
    "$(dirname)/f",
    "$(filename)",
    "$(var undefined)",
    "$(var $(var a) d)",
    "$(var q d)",
    "$(anon n)",
)
_FLAGS = ("$(var b)", "$(eval '$(var a)' == 'y')", "$(eval '$(var p true)' == 'true')", "true")


def _random_file(rng: random.Random, includes: list[str], statements: int) -> str:
    """A launch file of ``<let>``s, nodes and includes whose texts read the same launch
    configurations under values that change between them (and between includers)."""
    lines = ['<arg name="a" default="x"><choice value="x"/><choice value="y"/></arg>']
    lines.append('<arg name="b" default="true"/>')
    for index in range(statements):
        text = rng.choice(_TEXTS)
        kind = rng.randrange(5)
        if kind == 0:
            lines.append(f'<let name="{rng.choice("acpxy")}" value="{text}"/>')
        elif kind == 4:  # declared here, read before by an includer: an input of the entry
            lines.append('<arg name="q" default="z"/>')
        elif kind == 1:
            lines.append(f'<node pkg="p" exec="e" name="n{index}" namespace="/{text}"/>')
        elif kind == 2 and includes:
            passed = f'<arg name="p" value="{rng.choice(_TEXTS)}"/>'
            target = rng.choice(includes)
            lines.append(
                f'<include file="$(dirname)/{target}" if="{rng.choice(_FLAGS)}">{passed}</include>'
            )
        else:
            inner = f'<let name="c" value="{text}"/><node pkg="p" exec="e" name="g{index}"/>'
            lines.append(f'<group if="{rng.choice(_FLAGS)}">{inner}</group>')
    return "<launch>" + "".join(lines) + "</launch>"


@pytest.mark.parametrize("seed", range(24))
def test_resolved_texts_are_reused_only_where_they_read_the_same(
    tmp_path: Path, seed: int, monkeypatch: pytest.MonkeyPatch
) -> None:
    """The memo of resolved texts changes no model: random include trees (texts reading
    configurations that includers and ``<let>``s set differently, ``$(dirname)`` in two
    folders, substitutions it does not keep) analysed with it and without it."""
    rng = random.Random(seed)
    package = tmp_path / "pkg"
    (package / "sub").mkdir(parents=True)
    (package / "package.xml").write_text(MANIFEST)
    (package / "sub" / "leaf.launch.xml").write_text(_random_file(rng, [], 4))
    (package / "sub" / "mid.launch.xml").write_text(_random_file(rng, ["leaf.launch.xml"], 6))
    (package / "mid.launch.xml").write_text(_random_file(rng, ["sub/leaf.launch.xml"], 6))
    includes = ["mid.launch.xml", "sub/mid.launch.xml", "sub/leaf.launch.xml"]
    (package / "main.launch.xml").write_text(_random_file(rng, includes, 16))
    workspace = discover([str(package)])

    def models() -> list[dict[str, object]]:
        return [describe_model(model) for model in Analysis(workspace).all_models()]

    memoised = models()
    with monkeypatch.context() as patched:
        patched.setattr(substitutions, "_reads", lambda _text: None)
        assert models() == memoised


def _models(tmp_path: Path, files: dict[str, str]) -> dict[str, LaunchModel]:
    package = tmp_path / "pkg"
    package.mkdir()
    (package / "package.xml").write_text(MANIFEST)
    for name, text in files.items():
        (package / name).write_text(f"<launch>{text}</launch>")
    models = Analysis(discover([str(package)])).all_models()
    return {Path(model.file).name: model for model in models}


def test_a_name_read_through_a_substitution_is_read_again(tmp_path: Path) -> None:
    """``$(var $(var a))`` reads a configuration its text does not name: never reused."""
    node = '<node pkg="p" exec="e" name="$(var $(var a) d)"/>'
    lets = '<let name="a" value="x"/><let name="x" value="{}"/>'
    main = lets.format("one") + node + lets.format("two") + node
    model = _models(tmp_path, {"main.launch.xml": main})["main.launch.xml"]
    names = [describe_model(model)["nodes"][i]["name"] for i in (0, 1)]  # type: ignore[index]
    assert names == ["one", "two"]


def test_a_reused_text_still_reads_what_is_not_set(tmp_path: Path) -> None:
    """An included file's arg read before its declaration is an input of the entry file
    (``unset_reads``): also where the text was resolved before, by another entry file."""
    read = '<node pkg="p" exec="e" name="$(var q d)"/>'
    files = {
        "a.launch.xml": read,
        "leaf.launch.xml": '<arg name="q" default="z"/>',
        "main.launch.xml": read + '<include file="$(dirname)/leaf.launch.xml"/>',
    }
    models = _models(tmp_path, files)
    assert describe_model(models["a.launch.xml"])["nodes"][0]["name"] == "d"  # type: ignore[index]
    read_in_main = describe_model(models["main.launch.xml"])["nodes"][0]["name"]  # type: ignore[index]
    assert [value["value"] for value in read_in_main] == ["z", "d", "⟨q⟩"]


def test_an_expression_is_evaluated_once_per_text(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """``$(eval)`` reads nothing but its text: one evaluation serves every file and
    configuration meeting the same text, failures included."""
    texts: list[str] = []

    def counted(text: str, environment: EvalEnvironment) -> str:
        texts.append(text)
        return evaluate(text, environment)

    monkeypatch.setattr(substitutions, "evaluate", counted)
    monkeypatch.setattr(substitutions, "_evaluated", Memo[str, object]())
    name = "$(eval &quot;'$(var a)' * 2&quot;)"
    node = f'<node pkg="p" exec="e" name="{name}" namespace="/$(eval 1/0)"/>'
    arg = '<arg name="a" default="x"><choice value="x"/><choice value="y"/></arg>'
    models = _models(tmp_path, {"one.launch.xml": arg + node, "two.launch.xml": arg + node})
    for model in models.values():
        assert describe_model(model)["nodes"][0]["name"][0]["value"] == "xx"  # type: ignore[index]
        assert "eval-failed" in [error.code for error in model.errors]
    assert sorted(texts) == ["'x' * 2", "'y' * 2", "1/0"]


PYTHON_EXPRESSIONS = """<launch><arg name="names" default="a_b_a"/><arg name="pick" default="0"/>
  <node pkg="pkg" exec="e" name="n$(eval 'len(set(\\'$(var names)\\'.split(\\'_\\')))')"/>
  <node pkg="pkg" exec="e"
        name="s$(eval 'sorted(set(\\'$(var names)\\'.split(\\'_\\')))[$(var pick)]')"/>
  <node pkg="pkg" exec="e" name="m$(eval 'int(math.floor(pi * 100))')"/>
  <node pkg="pkg" exec="e" name="t$(eval 'len(tuple(frozenset(\\'$(var names)\\')))')"/>
  <node pkg="pkg" exec="e" name="b$(eval 'any(c == \\'b\\' for c in \\'$(var names)\\')')"
        if="$(eval 'all(c != \\'z\\' for c in \\'$(var names)\\')')"/>
  <node pkg="pkg" exec="e" name="x" if="$(eval 'true')"/>
</launch>"""


@pytest.mark.oracle
@pytest.mark.parametrize("arguments", [{}, {"names": "c_d", "pick": "1"}, {"names": "z"}])
def test_python_expressions_see_what_ros2_launch_gives_them(
    tmp_path: Path, arguments: dict[str, str]
) -> None:
    """``$(eval)`` as ``PythonExpression`` evaluates it: Python's builtins (``set``,
    ``tuple``, ``any``...), ``math``'s names bare and as ``math.X``; ``true`` is no name
    there (the launch fails, unlike roslaunch's ``$(eval)``)."""
    it = launch(tmp_path, PYTHON_EXPRESSIONS)
    assert not it.matches_oracle(arguments)["ok"]  # $(eval 'true'): a NameError
    it = launch(tmp_path / "ok", PYTHON_EXPRESSIONS.replace("'true'", "'True'"))
    expected = it.matches_oracle(arguments)
    assert expected["ok"] and len(expected["nodes"]) >= 4


def test_what_the_restricted_evaluator_refuses_is_eval_refused(tmp_path: Path) -> None:
    """An ``$(eval)`` over the evaluator's nesting limit, or calling what it does not allow,
    is rosvar's refusal (Python may well run it: 150 brackets are within its parser's
    200), not the expression failing as it does in Python (``1/0``)."""
    deep = "(" * 150 + "1" + ")" * 150
    texts = {"deep": deep, "call": "open(0)", "zero": "1/0"}
    nodes = "".join(
        f'<node pkg="p" exec="e" name="n" namespace="/$(eval \'{text}\')"/>'
        for text in texts.values()
    )
    model = _models(tmp_path, {"main.launch.xml": nodes})["main.launch.xml"]
    found = [(error.code, error.message.split(": ", 2)[-1][:32]) for error in model.errors]
    assert found == [
        ("eval-refused", "expression is nested more than 1"),
        ("eval-refused", "calling 'open' is not allowed (o"),
        ("eval-failed", "ZeroDivisionError: division by z"),
    ]


EVAL_MODULES_XML = """<launch><arg name="x" default="4"/>
  <node pkg="pkg" exec="e" name="n" namespace="/a$(eval {})"/></launch>"""
EVAL_MODULES_PY = """from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration, PythonExpression
from launch_ros.actions import Node


def generate_launch_description():
    x = LaunchConfiguration('x')
    return LaunchDescription([
        DeclareLaunchArgument('x', default_value='4'),
        Node(package='pkg', executable='e', name='n', namespace=['/a', PythonExpression({})]),
    ])
"""
EVAL_MODULES = {  # the expression's arguments, and whether launch fails
    "math given": (".launch.xml", "'int(sqrt($(var x)))' 'math'", True),
    "math and a blank": (".launch.xml", "'int(sqrt($(var x)))' ' math '", True),
    "no module": (".launch.xml", "'$(var x) * 3' ''", True),
    "no math": (".launch.xml", "'int(sqrt($(var x)))' ''", False),
    "no math by its name": (".launch.xml", "'int(math.pi) + $(var x)' ''", False),
    "an empty name": (".launch.xml", "'$(var x)' 'math, '", False),
    "python list": (".launch.py", "['int(sqrt(', x, '))'], python_modules=['math']", True),
    "python text": (".launch.py", "['2 * ', x], 'math'", True),
    "python none": (".launch.py", "['int(sqrt(', x, '))'], []", False),
}


@pytest.mark.parametrize("case", sorted(EVAL_MODULES))
def test_eval_takes_the_modules_it_may_use(tmp_path: Path, case: str) -> None:
    """``$(eval EXPR MODULES)``, ``PythonExpression(expr, python_modules)``: ``math`` given
    (or not) decides whether its names are defined, as the oracle evaluates them, which
    fails with the same error."""
    suffix, arguments, runs = EVAL_MODULES[case]
    main = (EVAL_MODULES_XML if suffix == ".launch.xml" else EVAL_MODULES_PY).format(arguments)
    it = launch(tmp_path, main, suffix=suffix)
    for given in ({}, {"x": "9"}):
        expected = it.matches_oracle(given)
        assert expected["ok"] is runs
        errors = it.analysis.resolve([str(it.main)], given).errors
        messages = [error.message.rsplit("): ", 1)[-1] for error in errors]
        assert messages == ([] if runs else [f"{expected['error_type']}: {expected['error']}"])


def test_a_module_rosvar_does_not_model_is_refused_naming_it(tmp_path: Path) -> None:
    """Launch imports ``os`` and runs; rosvar knows ``math`` only, so it says it cannot tell
    (``eval-refused``), not that the launch fails."""
    it = launch(tmp_path, EVAL_MODULES_XML.format("'int(pi) + $(var x)' 'math, os'"))
    [error] = it.analysis.resolve([str(it.main)], {}).errors
    assert error.code == "eval-refused"
    assert error.message.endswith("module 'os' is not modelled by rosvar (only math)")
    assert launch_oracle_ok(it)


def test_a_refused_call_names_what_ros2_evaluates(tmp_path: Path) -> None:
    """ROS 2's ``$(eval)`` has none of roslaunch's functions (``arg``, ``env``...): its
    refusal names the builtins and math's functions, which it has."""
    it = launch(tmp_path, EVAL_MODULES_XML.format("'hex($(var x))'"))
    [error] = it.analysis.resolve([str(it.main)], {}).errors
    assert error.code == "eval-refused"
    allowed = error.message.split("calling 'hex' is not allowed (only ")[1]
    assert allowed.startswith("the builtins abs, all, any, bool") and "math.NAME" in allowed
    assert not {"arg", "env", "optenv", "find", "anon", "dirname"} & set(allowed.split("/"))


def launch_oracle_ok(it: Launch) -> bool:
    """Whether the real launch runs ``it`` with its defaults."""
    if not ORACLE.is_dir():
        pytest.skip(f"the ROS 2 oracle {ORACLE} is absent")
    return bool(run_oracle(it.main, {}, [it.main.parent.parent])["ok"])


BACKSLASHES = r"""<launch>
  <arg name="ext" default="png"/>
  <node pkg="pkg" exec="e" name="n" namespace="a\b">
    <param name="plain" value="a\\b"/>
    <param name="typed" value="C:\\ros\\x" type="str"/>
    <param name="lone" value="a\b"/>
    <param name="pattern" value=".*\\.$(var ext)"/>
  </node>
</launch>"""


@pytest.mark.oracle
def test_a_backslash_escapes_the_next_character_in_every_text(tmp_path: Path) -> None:
    """launch's grammar reads ``\\x`` as ``x`` in a text with no substitution too
    (``value="a\\\\b"`` is ``a\\b``), as in one with substitutions."""
    it = launch(tmp_path, BACKSLASHES)
    expected = it.matches_oracle({})
    [node] = expected["nodes"]
    assert node["parameters"]["plain"] == "a\\b"
    result = it.analysis.resolve([str(it.main)], {})
    [resolved] = result.nodes
    assert resolved.parameters is not None
    assert resolved.parameters["typed"] == "C:\\ros\\x"
