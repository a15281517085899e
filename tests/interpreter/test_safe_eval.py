"""Tests for the restricted ``$(eval)`` evaluator.

The strongest evidence is differential: the same expressions and args go through Debian's real
roslaunch (``substitution_args.resolve_args`` under ``/usr/bin/python3``, one subprocess for
everything) and through :func:`evaluate`, and the results must agree.
"""

from __future__ import annotations

import json
import math
import operator
import random
import subprocess
import sys
from collections.abc import Callable, Mapping
from pathlib import Path
from typing import Any

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from rosvar.interpreter.safe_eval import (
    MAX_ITERATIONS,
    MAX_NESTING,
    EvalEnvironment,
    EvalFailed,
    EvalRefused,
    compared_literals,
    convert_auto,
    evaluate,
    evaluate_value,
    referenced_args,
    referenced_names,
)
from rosvar.interpreter.safe_eval.names import ROSLAUNCH_CALLS

ORACLE_PYTHON = "/usr/bin/python3"
PACKAGE = "my_pkg"
#: The oracle's whole environment besides PATH/HOME; our host functions read the same table.
ENV_VARS: Mapping[str, str] = {"ROSVAR_TEST_HOME": "/opt/rosvar_home", "ROSVAR_TEST_EMPTY": ""}

ORACLE_SCRIPT = r"""
import json, sys
import rospkg
from roslaunch import substitution_args
from roslaunch.loader import convert_value

request = json.load(sys.stdin)
substitution_args._rospack = rospkg.RosPack(ros_paths=[request["package_root"]])
results = []
for job in request["jobs"]:
    try:
        if job["kind"] == "eval":
            context = {"arg": dict(job["args"]), "filename": "/tmp/x.launch"}
            text = "$(eval " + job["expr"] + ")"
            results.append({"ok": True, "value": substitution_args.resolve_args(text, context)})
        else:
            value = convert_value(job["value"], "auto")
            results.append({"ok": True, "value": [type(value).__name__, repr(value)]})
    except Exception as exc:
        results.append({"ok": False, "error": type(exc).__name__ + ": " + str(exc)})
json.dump(results, sys.stdout)
"""

BASE_ARGS: Mapping[str, str] = {
    "robot": "husky",
    "sim": "true",
    "use_gui": "False",
    "n": "3",
    "rate": "10.5",
    "name": "robot_1",
    "ns": "/r1",
    "x": "1",
    "y": "2.0",
    "empty": "",
    "mode": "Fast",
    "csv": "a, b,c",
    "ver": "1_0",
    "under": "1_0.5",
    "flag": "TRUE",
    "neg": "-4",
    "pad": " 7 ",
    "deg": "90",
    "count": "007",
    "pi": "3",
    "e": "not math",
    "path": "/opt/ws/src",
}
#: Args named like builtins shadow them in roslaunch (they are looked up first).
SHADOW_ARGS: Mapping[str, str] = {**BASE_ARGS, "len": "5", "str": "text", "int": "2"}

REALISTIC: list[str] = [
    "arg('robot') == 'husky'",
    "arg('robot') != 'jackal'",
    "arg('robot') == 'husky' and not arg('sim')",
    "not arg('sim')",
    "arg('sim') and not arg('use_gui')",
    "sim == true",
    "sim == 'true'",
    "arg('sim') == 'true'",
    "flag",
    "flag and use_gui",
    "robot + '/' + name",
    "ns + '/' + robot + '/cmd_vel'",
    "optenv('ROSVAR_TEST_HOME', 'd') == 'd'",
    "optenv('ROSVAR_UNSET', 'fallback')",
    "optenv('ROSVAR_UNSET')",
    "optenv('ROSVAR_TEST_EMPTY', 'x') == ''",
    "env('ROSVAR_TEST_HOME') + '/maps'",
    "env('ROSVAR_UNSET')",
    "find('my_pkg') + '/config/' + robot + '.yaml'",
    "find('no_such_pkg')",
    "dirname() + '/params.yaml'",
    "int(n) * 2",
    "n * 2",
    "n + 1",
    "radians(90)",
    "radians(deg)",
    "deg * pi / 180",
    "'%s_%s' % (robot, name)",
    "'%d' % n",
    "'%.2f' % rate",
    "'%(r)s/%(n)03d' % {'r': robot, 'n': n}",
    "len(robot) > 3",
    "mode.lower() in ['fast', 'slow']",
    "mode.lower() not in ('fast',)",
    "1 if sim else 0",
    "'gui' if use_gui else 'headless'",
    "[1, 2][0]",
    "rate * 2",
    "rate + n",
    "y / 4",
    "x == 1",
    "x == '1'",
    "x == 1.0",
    "true",
    "True and false",
    "arg('x') + 1",
    "arg('ver')",
    "ver + 'x'",
    "under * 2",
    "neg * -1",
    "abs(neg)",
    "pad",
    "count + 1",
    "pi",
    "e",
    "arg('pi')",
    "arg('e')",
    "pi * 2",
    "cos(0)",
    "sqrt(16)",
    "floor(rate)",
    "ceil(rate)",
    "log(e)",
    "hypot(3, 4)",
    "degrees(pi)",
    "isclose(0.1 + 0.2, 0.3)",
    "pow(2, 3)",
    "inf",
    "nan == nan",
    "tau / 2",
    "csv.split(',')",
    "csv.split(',')[1].strip()",
    "[s.strip() for s in csv.split(',')]",
    "','.join(['a', 'b'])",
    "'x'.join(map(str, [1, 2, 3]))",
    "'{}-{}'.format(robot, n)",
    "'{0:>8}|'.format(robot)",
    "'{r}_{n:03d}'.format(r=robot, n=n)",
    "robot.upper()",
    "robot.startswith('hus')",
    "path.endswith('/src')",
    "name.replace('_', '-')",
    "name[:5]",
    "name[-1]",
    "name[::-1]",
    "robot[0].upper() + robot[1:]",
    "str(n) + 'x'",
    "str(n).zfill(3)",
    "float(n) / 2",
    "int(rate)",
    "round(rate)",
    "round(2.675, 2)",
    "round(2.5)",
    "str(True)",
    "str(1.0)",
    "True + 1",
    "'a' * 3",
    "3 * 'ab'",
    "1 / 0",
    "undefined_arg == 1",
    "arg('undefined')",
    "7 // 2",
    "-7 // 2",
    "7 % -3",
    "2 ** 10",
    "2 ** -1",
    "10 / 4",
    "1e3",
    "0.1 + 0.2",
    "1 < n < 5",
    "1 < n > 5",
    "n is None",
    "None",
    "max(1, n, 2)",
    "min([3, 1, 2])",
    "sorted([3, 1, 2])",
    "sorted(['bb', 'a', 'ccc'], key=len, reverse=True)",
    "max(['aa', 'b'], key=len)",
    "dict(a=1)['a']",
    "{'a': 1, 'b': 2}['b']",
    "dict([('a', 1)])",
    "list('abc')",
    "list(map(int, ['1', '2']))",
    "[v for v in [1, 2, 3] if v > 1]",
    "{k: v for k, v in [('a', 1)]}",
    "{v % 2 for v in [1, 2, 3]}",
    "','.join(str(v) for v in [1, 2])",
    "[str(v) for v in [1, 2]]",
    "[v + n for v in [1]]",
    "[true for v in [1]]",
    "[radians(v) for v in [90]]",
    "[v for v in [1, 2] if v != x]",
    "empty == ''",
    "not empty",
    "bool(empty)",
    "bool('False')",
    "'us' in robot",
    "robot not in ('a', 'b')",
    "(sim or use_gui) and robot == 'husky'",
    "-rate",
    "~n",
    "int('0x1f', 16)",
    "float('inf')",
    "robot.count('u')",
    "robot.find('s')",
    "robot.index('z')",
    "mode.isdigit()",
    "n.isdigit()",
    "name.isalnum()",
    "name.title()",
    "mode.capitalize()",
    "[1, 2] + [3]",
    "(1,) * 2",
    "{1, 2} | {3}",
    "(1, 2)",
    "{'a': [1, 2]}",
    "5 if n > 2 else 6",
    "str",
    "len",
    "len('abc')",
    "'1' == 1",
    "x.lower()",
    "robot.lower() == 'husky' or robot.lower() == 'jackal'",
    " 1 + 1",
]
SHADOWING: list[str] = ["len", "len('abc')", "str", "str(1)", "int + 1", "[len(v) for v in ['ab']]"]
CONVERT_VALUES: list[str] = [
    "1", "-1", "+1", " 1 ", "007", "1_0", "1__0", "1.5", "1_0.5", ".", "1.", ".5", "nan", "inf",
    "NaN.", "1e3", "1e3.0", "true", "TRUE", "False", " true", "yes", "", "0x10", "\u0663",
    "\u0661.\u0665", "-0.0", "infinity.", "1.2.3", "0", "00",
]  # fmt: skip


# --------------------------------------------------------------------------- helpers


def host_functions(package_root: Path) -> dict[str, Callable[..., object]]:
    """Deterministic equivalents of what the oracle sees."""

    def env(name: str) -> str:
        return ENV_VARS[name]

    def optenv(name: str, default: str = "") -> str:
        return ENV_VARS.get(name, default)

    def find(package: str) -> str:
        if package != PACKAGE:
            raise KeyError(package)
        return str(package_root / package)

    def dirname() -> str:
        return "/tmp"

    def anon(name: str) -> str:
        return f"{name}_anon"

    return {"env": env, "optenv": optenv, "find": find, "dirname": dirname, "anon": anon}


def make_env(args: Mapping[str, str], package_root: Path = Path("/nonexistent")) -> EvalEnvironment:
    return EvalEnvironment(lookup_arg=args.__getitem__, functions=host_functions(package_root))


ENV = make_env(BASE_ARGS)


def refused(expr: str, env: EvalEnvironment = ENV) -> EvalRefused:
    with pytest.raises(EvalRefused) as info:
        evaluate(expr, env)
    return info.value


def test_a_refused_call_names_what_its_environment_allows() -> None:
    """roslaunch's ``$(eval)`` has its host functions; a symbols environment (ROS 2's
    ``$(eval)``, xacro's ``${}``) has none, and its refusal names none of them."""
    roslaunch = refused("open('x')").message
    assert roslaunch.endswith("(only " + ROSLAUNCH_CALLS + ")") and "arg/env" in roslaunch
    symbols = EvalEnvironment(ENV.lookup_arg, symbols=ENV.lookup_arg, namespaces={"math": {}})
    message = refused("open('x')", symbols).message
    assert message.startswith("calling 'open' is not allowed (only the builtins abs, all,")
    assert "math.NAME" in message and "arg" not in message.split("(only")[1]
    assert refused("open('x')").col == refused("open('x')", symbols).col == 0


def failed(expr: str, env: EvalEnvironment = ENV) -> EvalFailed:
    with pytest.raises(EvalFailed) as info:
        evaluate(expr, env)
    return info.value


def ours(expr: str, args: Mapping[str, str], package_root: Path) -> dict[str, Any]:
    try:
        return {"ok": True, "value": evaluate(expr, make_env(args, package_root))}
    except EvalFailed as exc:
        return {"ok": False, "error": exc.message}


# --------------------------------------------------------------------------- random expressions

_LEAVES = [
    "n", "rate", "sim", "robot", "x", "y", "empty", "neg", "flag", "mode", "csv", "ver", "pad",
    "0", "1", "2", "7", "-3", "2.5", "0.1", "'a'", "'ab'", "''", "'true'", "'1'", "'x,y'",
    "True", "False", "None", "true", "false", "pi", "e", "[1, 2]", "(1, 'a')", "arg('n')",
    "arg('robot')", "arg('missing')",
]  # fmt: skip
_BINOPS = ["+", "-", "*", "/", "//", "%"]
_COMPARISONS = ["==", "!=", "<", "<=", ">", ">=", "in", "not in"]
_UNARY_CALLS = [
    "int", "float", "str", "bool", "len", "abs", "round", "floor", "ceil", "sqrt", "radians",
    "degrees", "fabs", "list", "sorted",
]  # fmt: skip
_BINARY_CALLS = ["max", "min", "round", "pow", "hypot", "atan2", "fmod", "isclose", "copysign"]
_NULLARY_METHODS = ["lower", "upper", "strip", "title", "capitalize", "isdigit", "isalpha"]
_UNARY_METHODS = ["startswith", "endswith", "count", "find", "rfind", "split", "zfill", "index"]


def generate(rng: random.Random, depth: int) -> str:
    """A random expression over the allowed constructs (many of them fail; that is tested too)."""
    if depth == 0 or rng.random() < 0.2:
        return rng.choice(_LEAVES)

    def sub() -> str:
        return generate(rng, depth - 1)

    kind = rng.randrange(16)
    if kind == 0:
        return f"({sub()} {rng.choice(_BINOPS)} {sub()})"
    if kind == 1:
        return f"({sub()} ** {rng.choice(['0', '1', '2', '3', '-1', '0.5'])})"
    if kind == 2:
        return f"({sub()} {rng.choice(_COMPARISONS)} {sub()})"
    if kind == 3:
        return f"({sub()} {rng.choice(['and', 'or'])} {sub()})"
    if kind == 4:
        return f"({rng.choice(['not ', '-', '+', '~'])}{sub()})"
    if kind == 5:
        return f"({sub()} if {sub()} else {sub()})"
    if kind == 6:
        return f"{rng.choice(_UNARY_CALLS)}({sub()})"
    if kind == 7:
        return f"{rng.choice(_BINARY_CALLS)}({sub()}, {sub()})"
    if kind == 8:
        return f"({sub()})[{sub()}]"
    if kind == 9:
        return f"({sub()})[{rng.choice(['', '1', '-1'])}:{rng.choice(['', '2', '-1'])}]"
    if kind == 10:
        return f"({sub()}).{rng.choice(_NULLARY_METHODS)}()"
    if kind == 11:
        return f"({sub()}).{rng.choice(_UNARY_METHODS)}({sub()})"
    if kind == 12:
        return f"'%s-%s' % ({sub()}, {sub()})"
    if kind == 13:
        return f"'{{}}/{{}}'.format({sub()}, {sub()})"
    if kind == 14:
        return rng.choice(["[str(v) for v in ", "[v for v in ", "[v + n for v in "]) + f"{sub()}]"
    return f"[{sub()}, {sub()}]"


GENERATED: list[str] = [generate(random.Random(seed), 3) for seed in range(600)]


# --------------------------------------------------------------------------- oracle


def _oracle_available() -> bool:
    try:
        probe = subprocess.run(
            [ORACLE_PYTHON, "-I", "-c", "import rospkg, roslaunch.substitution_args"],
            capture_output=True,
            env={"PATH": "/usr/bin:/bin"},
            timeout=60,
            check=False,
        )
    except (OSError, subprocess.SubprocessError):
        return False
    return probe.returncode == 0


@pytest.fixture(scope="module")
def package_root(tmp_path_factory: pytest.TempPathFactory) -> Path:
    root = tmp_path_factory.mktemp("packages")
    (root / PACKAGE).mkdir()
    (root / PACKAGE / "package.xml").write_text(
        f'<?xml version="1.0"?><package format="2"><name>{PACKAGE}</name><version>0.0.1'
        "</version><description>d</description><maintainer email='a@b.c'>a</maintainer>"
        "<license>BSD</license></package>",
        encoding="utf-8",
    )
    return root


@pytest.fixture(scope="module")
def oracle(package_root: Path, tmp_path_factory: pytest.TempPathFactory) -> dict[str, Any]:
    """Every oracle answer, from ONE roslaunch subprocess, keyed by (kind, case)."""
    if not _oracle_available():
        pytest.skip(f"{ORACLE_PYTHON} cannot import roslaunch")
    jobs: list[dict[str, Any]] = []
    keys: list[str] = []
    for group, exprs, args in (
        ("realistic", REALISTIC, BASE_ARGS),
        ("shadowing", SHADOWING, SHADOW_ARGS),
        ("generated", GENERATED, BASE_ARGS),
    ):
        for expr in exprs:
            jobs.append({"kind": "eval", "expr": expr, "args": dict(args)})
            keys.append(f"{group}:{expr}")
    for value in CONVERT_VALUES:
        jobs.append({"kind": "convert", "value": value})
        keys.append(f"convert:{value}")
    home = tmp_path_factory.mktemp("home")
    completed = subprocess.run(
        [ORACLE_PYTHON, "-I", "-c", ORACLE_SCRIPT],
        input=json.dumps({"package_root": str(package_root), "jobs": jobs}),
        capture_output=True,
        text=True,
        env={"PATH": "/usr/bin:/bin", "HOME": str(home), "LC_ALL": "C.UTF-8", **ENV_VARS},
        timeout=300,
        check=False,
    )
    assert completed.returncode == 0, completed.stderr
    results = json.loads(completed.stdout)
    assert len(results) == len(jobs)
    return dict(zip(keys, results, strict=True))


@pytest.mark.oracle
@pytest.mark.parametrize("expr", REALISTIC)
def test_matches_roslaunch_on_realistic_expressions(
    expr: str, oracle: dict[str, Any], package_root: Path
) -> None:
    theirs = oracle[f"realistic:{expr}"]
    try:
        mine = ours(expr, BASE_ARGS, package_root)
    except EvalRefused as exc:
        pytest.fail(f"refused a realistic expression: {exc.message} (oracle: {theirs})")
    assert mine["ok"] == theirs["ok"], (mine, theirs)
    if theirs["ok"]:
        assert mine["value"] == theirs["value"]


@pytest.mark.oracle
@pytest.mark.parametrize("expr", SHADOWING)
def test_matches_roslaunch_when_args_shadow_builtins(
    expr: str, oracle: dict[str, Any], package_root: Path
) -> None:
    theirs = oracle[f"shadowing:{expr}"]
    mine = ours(expr, SHADOW_ARGS, package_root)
    assert mine["ok"] == theirs["ok"], (mine, theirs)
    if theirs["ok"]:
        assert mine["value"] == theirs["value"]


@pytest.mark.oracle
def test_matches_roslaunch_on_generated_expressions(
    oracle: dict[str, Any], package_root: Path
) -> None:
    mismatches: list[str] = []
    refusals = successes = 0
    for expr in GENERATED:
        theirs = oracle[f"generated:{expr}"]
        try:
            mine = ours(expr, BASE_ARGS, package_root)
        except EvalRefused:
            refusals += 1  # list/tuple .count()/.index() are refused, not interpreted
            continue
        successes += theirs["ok"]
        if mine["ok"] != theirs["ok"] or (theirs["ok"] and mine["value"] != theirs["value"]):
            mismatches.append(f"{expr!r}: ours={mine} roslaunch={theirs}")
    assert not mismatches, "\n".join(mismatches)
    assert refusals <= len(GENERATED) // 50
    assert successes >= len(GENERATED) // 5  # the generator must exercise the success path


@pytest.mark.oracle
@pytest.mark.parametrize("value", CONVERT_VALUES)
def test_convert_auto_matches_convert_value(value: str, oracle: dict[str, Any]) -> None:
    theirs = oracle[f"convert:{value}"]
    converted = convert_auto(value)
    assert [type(converted).__name__, repr(converted)] == theirs["value"]


# --------------------------------------------------------------------------- semantics


@pytest.mark.parametrize(
    ("expr", "expected"),
    [
        ("True + 1", "2"),
        ("'a' * 3", "aaa"),
        ("str(True)", "True"),
        ("str(1.0)", "1.0"),
        ("x == 1", "True"),  # '1' converts to int
        ("y", "2.0"),
        ("ver", "1_0"),  # underscores keep the value a string
        ("under", "10.5"),  # ...unless it contains a '.', then float() accepts them
        ("flag", "True"),
        ("e", "2.718281828459045"),  # math shadows the arg 'e'
        ("arg('e')", "not math"),
        ("arg(name='robot')", "husky"),
        ("'' or 0", "0"),
        ("1 and 'b'", "b"),
        ("0 and 1 / 0", "0"),  # short-circuit: the division never runs
        ("1 or 1 / 0", "1"),
        ("robot if sim else 1 / 0", "husky"),
        ("1 < 2 < 3", "True"),
        ("3 > 2 > 2", "False"),
        ("[v * 2 for v in [1, 2]]", "[2, 4]"),
        ("{k: v for k, v in [('a', 1), ('b', 2)]}", "{'a': 1, 'b': 2}"),
        ("[[w for w in v] for v in ['ab']]", "[['a', 'b']]"),
        ("sorted({3, 1})", "[1, 3]"),
        ("min(v for v in [3, 1, 2])", "1"),
        ("anon('node')", "node_anon"),
        ("optenv('ROSVAR_UNSET', default='d')", "d"),
        ("prod([2, 3, 4])", "24"),
        ("prod(['ab', 2])", "abab"),
        ("'{0[1]}'.format(['a', 'b'])", "b"),
        ("~True", "-2"),
        ("'%s' % [1, 2]", "[1, 2]"),
        ("1 in (1 / v for v in [1, 0])", "True"),  # membership stops at the first match
        ("'b' in map(str, 'abc')", "True"),
        ("{(1, 2): 3}[(1, 2)]", "3"),
    ],
)
def test_semantics(expr: str, expected: str) -> None:
    assert evaluate(expr, ENV) == expected


def test_leading_blanks_are_stripped_like_eval() -> None:
    assert evaluate(" \t1 + 1", ENV) == "2"


def test_names_resolve_to_roslaunch_functions_before_args() -> None:
    env = make_env({"arg": "1", "true": "0", "radians": "5", "robot": "r"})
    assert evaluate("true", env) == "True"
    assert evaluate("radians(180) == pi", env) == "True"
    assert evaluate("arg('robot')", env) == "r"


def test_args_shadow_builtins() -> None:
    env = make_env({"len": "5"})
    assert evaluate("len", env) == "5"
    assert failed("len('abc')", env).message == "TypeError: 'int' object is not callable"
    assert evaluate("len('abc')", make_env({})) == "3"


def test_comprehension_bodies_do_not_see_args_or_eval_functions() -> None:
    # roslaunch compiles comprehension bodies with globals {} + builtins only.
    assert "not defined" in failed("[v + n for v in [1]]").message
    assert "not defined" in failed("[true for v in [1]]").message
    assert "not defined" in failed("[arg('n') for v in [1]]").message
    assert evaluate("[str(v) for v in [n]]", ENV) == "['3']"  # the first iterable is outside


def test_missing_arg_messages() -> None:
    assert failed("arg('nope')").message == "arg 'nope' is not defined"
    assert failed("nope + 1").message == "arg 'nope' is not defined"
    assert failed("1 + nope").col == 4


def test_runtime_failures_carry_python_exception_names() -> None:
    assert failed("1 / 0").message == "ZeroDivisionError: division by zero"
    assert failed("{'a': 1}['b']").message == "KeyError: 'b'"
    assert failed("int('x')").message.startswith("ValueError:")
    assert failed("'a' + 1").message.startswith("TypeError:")
    assert failed("[1][5]").message.startswith("IndexError:")
    assert failed("n.lower()").message == "AttributeError: 'int' object has no attribute 'lower'"
    assert failed("(a, b) if False else [v for v, w in [1]]").message.startswith("TypeError:")
    assert failed("[v for v, w in ['abc']]").message.startswith("ValueError: too many")


NO_ARGS: Mapping[str, str] = {}


def test_host_functions() -> None:
    env = EvalEnvironment(lookup_arg=NO_ARGS.__getitem__)
    error = refused("1 + find('p')", env)
    assert "find" in error.message
    assert error.col == 4
    assert failed("env('ROSVAR_UNSET')").message == "KeyError: 'ROSVAR_UNSET'"

    def refusing_find(package: str) -> str:
        raise EvalRefused(f"package {package} is unknown")

    env = EvalEnvironment(lookup_arg=NO_ARGS.__getitem__, functions={"find": refusing_find})
    error = refused("'x' + find('p')", env)
    assert (error.message, error.col) == ("package p is unknown", 6)


def test_lookup_arg_errors_other_than_key_error_fail() -> None:
    def broken(name: str) -> str:
        raise RuntimeError("boom")

    assert failed("x", EvalEnvironment(lookup_arg=broken)).message == "RuntimeError: boom"


# --------------------------------------------------------------------------- refusals


@pytest.mark.parametrize(
    ("expr", "col", "fragment"),
    [
        ("x.__class__", 2, "double underscore"),
        ("__import__('os')", 0, "double underscore"),
        ("'a' + '__'", 7, "double underscore"),
        ("os.system('ls')", 3, "method 'system'"),
        ("robot.upper", 6, "attribute access '.upper'"),
        ("(1).real", 4, "attribute access '.real'"),
        ("robot.encode()", 6, "method 'encode'"),
        ("open('f')", 0, "calling 'open'"),
        ("exec('1')", 0, "calling 'exec'"),
        ("eval('1')", 0, "calling 'eval'"),
        ("getattr(x, 'y')", 0, "calling 'getattr'"),
        ("globals()", 0, "calling 'globals'"),
        ("1 + sum([1])", 4, "calling 'sum'"),
        ("x(1)", 0, "calling 'x'"),
        ("[len][0]('a')", 0, "only named functions"),
        ("lambda: 1", 0, "lambda"),
        ("map(lambda v: v, [1])", 4, "lambda"),
        ("(y := 1)", 1, ":="),
        ("[*csv]", 1, "starred"),
        ("max(*[1, 2])", 4, "starred"),
        ("dict(**{'a': 1})", 5, "keyword unpacking"),
        ("{**{'a': 1}}", 3, "dict unpacking"),
        ("f'{x}'", 0, "f-strings"),
        ("1j", 0, "complex literals"),
        ("b'x'", 0, "bytes literals"),
        ("...", 0, "ellipsis literals"),
        ("a @ b", 0, "MatMult"),
        ("[v for v in [1] for w in [2]]", 0, "single 'for'"),
        ("[v for v.x in [1]]", 7, "only assign to names"),
        ("import os", 0, "invalid Python expression"),
        ("1 +", 0, "invalid Python expression"),
        ("a + (", 4, "invalid Python expression"),
        ("  a + (", 6, "invalid Python expression"),
        ("'é' + open('x')", 6, "calling 'open'"),
        ("(1,\n lambda: 2)", 5, "lambda"),
        ("pi()", 0, "calling 'pi'"),
        ("print", 0, "builtin 'print'"),
        ("[1, 2].count(1)", 7, "only allowed on str values"),
    ],
)
def test_refusals(expr: str, col: int, fragment: str) -> None:
    error = refused(expr)
    assert fragment in error.message
    assert error.col == col
    if fragment not in ("builtin 'print'", "only allowed on str values"):  # run-time checks
        with pytest.raises(EvalRefused):
            referenced_args(expr)  # static refusals are reported before evaluation


def test_dunder_message_matches_roslaunch() -> None:
    assert refused("a__b").message == "$(eval ...) may not contain double underscore expressions"


# --------------------------------------------------------------------------- resource guards


@pytest.mark.parametrize(
    "expr",
    [
        "2 ** 10001",
        "(10 ** 100) ** 10000",
        "1 << 2000000",
        "(10 ** 10000) ** 10 * (10 ** 10000) ** 10 * (10 ** 10000) ** 10 * (10 ** 10000) ** 10",
        "'a' * 1000001",
        "1000001 * 'a'",
        "[0] * 2000000",
        "('ab',) * 1000001",
        "('a' * 1000000) + 'b'",
        "'x'.join(['a' * 600000, 'b' * 600000])",
        "('a' * 1000).replace('', 'b' * 1000)",
        "'x'.zfill(2000000)",
        "'%20000000d' % 1",
        "'%*d' % (5, 1)",
        "'%(a)s' * 20 % {'a': 'x' * 1000000}",
        "'{:20000000}'.format(1)",
        "'{0}{0}{0}{0}{0}{0}{0}{0}{0}{0}{0}'.format('a' * 1000000)",
        "'{:{}}'.format(1, 5)",
        "'{0.real}'.format(1)",
        "str([[0] * 1000000] * 5)",
        "[[0] * 1000000] * 5",
        "factorial(100000)",
        "comb(20000, 3)",
        "round(1, -100000)",
        "prod([10 ** 9000] * 200)",
        "prod(['a', 1000, 1001])",
        "[v for v in 'a' * 200000]",
        "len([0 for v in 'a' * 60000] + [0 for v in 'a' * 60000])",
        "len(list(map(abs, [0] * 200000)))",
        "sorted([0] * 200000, key=abs)",
        "len([('a' * 1000000).upper() for v in 'a' * 1000])",
        "len(list(map(str, [[0] * 300000] * 1000)))",
        "[[0] * 1000000] * 1000 == [[0] * 1000000] * 1000",
        "('x' * 1000000) in ['x' * 999999 + 'y'] * 1000000",
        "len([('a' * 1000000) == ('a' * 999999 + 'a') for v in 'a' * 100000])",
        "len([('a' * 1000000).count('b') for v in 'a' * 100000])",
        "sorted([[0] * 1000000] * 1000)",
        "sorted(v for v in [[0] * 1000000] * 100000)",
        "len(dict([((0,) * 1000000, 1)] * 1000000))",
        "('a' * 1000000) in (('a' * 999999) + 'b' for v in 'a' * 100000)",
    ],
)
def test_resource_guards_refuse(expr: str) -> None:
    refused(expr)


@pytest.mark.parametrize(
    ("expr", "expected"),
    [
        ("len(str(2 ** 10000)) if False else 2 ** 10000 > 0", "True"),
        ("len('a' * 1000000)", "1000000"),
        ("len([0] * 1000000)", "1000000"),
        (f"len([v for v in 'a' * {MAX_ITERATIONS - 10}])", str(MAX_ITERATIONS - 10)),
        ("round(1234, -2)", "1200"),
        ("factorial(10)", "3628800"),
        ("2.5 ** 2", "6.25"),
        ("2 ** -2", "0.25"),
    ],
)
def test_resource_guards_allow_reasonable_work(expr: str, expected: str) -> None:
    assert evaluate(expr, ENV) == expected


@pytest.mark.parametrize(
    "expr",
    [
        "(" * 5000 + "1" + ")" * 5000,
        "[" * 5000 + "]" * 5000,
        "{" * 5000 + "}" * 5000,
        "-" * 50000 + "1",
        "not " * 5000 + "1",
        "+".join(["1"] * 50000),
        "a" + ".b" * 5000,
        "(" * MAX_NESTING + "-1" + ")" * MAX_NESTING,
    ],
)
def test_nesting_beyond_the_limit_is_refused_before_parsing(expr: str) -> None:
    with pytest.raises(EvalRefused, match=f"nested more than {MAX_NESTING} levels deep"):
        evaluate(expr, ENV)


@pytest.mark.parametrize(
    ("expr", "expected"),
    [
        ("-" * MAX_NESTING + "1", "1"),
        ("[" * MAX_NESTING + "]" * MAX_NESTING, "[" * MAX_NESTING + "]" * MAX_NESTING),
        ("+".join(["1"] * MAX_NESTING), str(MAX_NESTING)),
        ("[" + ", ".join(["1 + 1"] * 1000) + "][999]", "2"),  # siblings do not nest
    ],
)
def test_nesting_at_the_limit_evaluates_deep_in_a_stack(expr: str, expected: str) -> None:
    """The limit leaves room below Python's recursion limit for a caller already deep in
    nested includes."""

    def nested(levels: int) -> str:
        return evaluate(expr, ENV) if levels == 0 else nested(levels - 1)

    assert nested(sys.getrecursionlimit() // 2) == expected


def test_large_int_to_str_fails_like_python() -> None:
    # Python 3.11 limits int -> str conversion to 4300 digits; roslaunch would fail the same way.
    assert evaluate("len(str(10 ** 4299))", ENV) == "4300"
    assert failed("10 ** 4300").message.startswith("ValueError")


# --------------------------------------------------------------------------- static analyses


@pytest.mark.parametrize(
    ("expr", "expected"),
    [
        ("arg('robot') == 'husky'", {"robot"}),
        ("arg('a') == b and c", {"a", "b", "c"}),
        ("pi + e + tau + true + False + str(q) + radians(r)", {"q", "r"}),
        ("env('X') + optenv('Y', z) + find('p') + anon('n') + dirname()", {"z"}),
        ("arg(name)", {"name"}),
        ("arg(name='k')", {"k"}),
        ("[v for v in items if v != skip]", {"items"}),
        ("[arg('hidden') for v in items]", {"items"}),
        ("{k: v for k, v in pairs}", {"pairs"}),
        ("s.lower() in ['true', '1']", {"s"}),
        ("sum", {"sum"}),  # may read an arg 'sum' (the builtin itself is refused)
        ("1 + 1", set()),
    ],
)
def test_referenced_args(expr: str, expected: set[str]) -> None:
    assert referenced_args(expr) == frozenset(expected)


@pytest.mark.parametrize(
    ("expr", "expected"),
    [
        ("arg('robot') == 'husky'", {"robot": {"husky"}}),
        ("x == 2", {"x": {"2"}}),
        ("sim and x == 'a'", {"x": {"a"}}),
        ("'a' != x", {"x": {"a"}}),
        ("x == -1.5", {"x": {"-1.5"}}),
        ("x == true", {"x": {"True"}}),
        ("mode in ('a', 'b')", {"mode": {"a", "b"}}),
        ("arg('m') not in ['a', 1, other]", {"m": {"a", "1"}}),
        ("str(n).lower() == 'true' or int(k) != 3", {"n": {"true"}, "k": {"3"}}),
        ("x == 1 and x == 2 or y == 'q'", {"x": {"1", "2"}, "y": {"q"}}),
        ("1 < x == 2", {"x": {"2"}}),
        ("x == y", {}),
        ("pi == 3", {}),
        ("[v for v in l if v == 'a']", {}),
        ("arg(name) == 'a'", {}),
        ("len(x) == 2", {}),
    ],
)
def test_compared_literals(expr: str, expected: dict[str, set[str]]) -> None:
    assert compared_literals(expr) == expected


def test_static_analyses_refuse() -> None:
    with pytest.raises(EvalRefused):
        compared_literals("open('x') == 1")
    with pytest.raises(EvalRefused):
        referenced_args("x.__class__")


# --------------------------------------------------------------------------- properties

_TOKENS = [
    "a", "n", "rate", "robot", "1", "0", "2.5", "'s'", "'%s'", "'{}'", "+", "-", "*", "/", "//",
    "%", "**", "==", "<", " in ", " not ", " and ", " or ", " if ", " else ", "(", ")", "[", "]",
    "{", "}", ",", ":", ".", "lower()", "join", "format", "str", "int", "len", "arg", "env",
    "radians", "for", " v ", "lambda", "__", "@", "\n", "'", '"', "\\", "é", "\x00", "\udc80",
    " ",
]  # fmt: skip


@settings(max_examples=400, deadline=None)
@given(st.lists(st.sampled_from(_TOKENS), max_size=14).map("".join))
def test_arbitrary_text_never_escapes_the_contract(text: str) -> None:
    try:
        assert isinstance(evaluate(text, ENV), str)
    except EvalRefused as exc:
        assert 0 <= exc.col <= len(text)
    except EvalFailed:
        pass
    try:
        referenced_args(text)
        compared_literals(text)
    except EvalRefused as exc:
        assert 0 <= exc.col <= len(text)


@settings(max_examples=200, deadline=None)
@given(st.text(max_size=20))
def test_arg_values_go_through_convert_auto(value: str) -> None:
    env = make_env({"v": value})
    assert evaluate("arg('v')", env) == str(convert_auto(value))
    assert evaluate("v", env) == str(convert_auto(value))
    converted = convert_auto(value)
    if isinstance(converted, str):
        assert converted == value


_ARITHMETIC: dict[str, Callable[[Any, Any], Any]] = {
    "+": operator.add,
    "-": operator.sub,
    "*": operator.mul,
    "/": operator.truediv,
    "//": operator.floordiv,
    "%": operator.mod,
    "<": operator.lt,
    "==": operator.eq,
}
_NUMBERS = st.one_of(
    st.integers(-(10**12), 10**12),
    st.floats(allow_nan=False, allow_infinity=False, min_value=-1e12, max_value=1e12),
)


@settings(max_examples=300, deadline=None)
@given(_NUMBERS, st.sampled_from(sorted(_ARITHMETIC)), _NUMBERS)
def test_arithmetic_matches_python(left: float, op: str, right: float) -> None:
    try:
        expected: str | None = str(_ARITHMETIC[op](left, right))
    except ArithmeticError:
        expected = None
    expr = f"({left!r}) {op} ({right!r})"
    if expected is None:
        with pytest.raises(EvalFailed):
            evaluate(expr, ENV)
    else:
        assert evaluate(expr, ENV) == expected


@pytest.mark.parametrize(
    "expr",
    [
        "max([9999]*1000000, key=factorial)",
        "sorted([9999]*100000, key=factorial)",
        "min([9999]*100000, key=perm)",
        "list(map(comb, [9999]*100000, [5000]*100000))",
        "list(map(gcd, [3**9000]*100000, [2**9000]*100000))",
    ],
)
def test_work_inside_callbacks_is_charged(expr: str) -> None:
    assert "units of work" in refused(expr).message


def test_big_integer_results_are_charged_but_small_ones_pass() -> None:
    assert evaluate("max([99]*1000, key=factorial)", ENV) == "99"


# -- a symbols environment (xacro's ${}) -----------------------------------------------------


def _symbols(values: Mapping[str, object]) -> EvalEnvironment:
    def symbols(name: str) -> object:
        return values[name]

    return EvalEnvironment(
        lookup_arg=lambda name: "arg value",
        symbols=symbols,
        namespaces={"math": {"pi": "pi", "floor": "floor"}, "python": {"len": "len"}},
    )


@pytest.mark.parametrize(
    ("expr", "values", "expected"),
    [
        ("w * 2", {"w": 0.5}, 1.0),  # typed, not converted from text
        ("flag and n > 1", {"flag": True, "n": 3}, True),
        ("pi", {}, math.pi),  # a global where no property has the name
        ("pi", {"pi": 3}, 3),  # a property hides the global
        ("math.pi / 2", {}, math.pi / 2),
        ("math.floor(2.5) + python.len('ab')", {}, 4),
        ("[x * 2 for x in items]", {"items": [1, 2]}, [2, 4]),
        ("'%s_link' % prefix", {"prefix": "base"}, "base_link"),
    ],
)
def test_symbols_are_typed_properties(
    expr: str, values: Mapping[str, object], expected: object
) -> None:
    assert evaluate_value(expr, _symbols(values)) == expected


@pytest.mark.parametrize(
    ("expr", "error"),
    [
        ("true", EvalFailed),  # xacro has no lower-case booleans, nor args by name
        ("arg_name", EvalFailed),
        ("math.tau", EvalRefused),  # a member the environment does not offer
        ("other.x", EvalRefused),  # no namespace of that name
        ("w.real", EvalRefused),
    ],
)
def test_symbols_environment_knows_nothing_else(expr: str, error: type[Exception]) -> None:
    with pytest.raises(error):
        evaluate_value(expr, _symbols({"w": 1.5}))


def test_referenced_names_include_calls_and_namespaces() -> None:
    names = referenced_names("max(a, b) + math.pi + [c for c in d]", frozenset({"math"}))
    assert names == {"max", "a", "b", "math", "d"}
