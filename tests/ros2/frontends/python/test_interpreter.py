"""The abstract interpreter of Python launch files, on its own: what it follows computes
exactly what Python computes (the expressions below are evaluated by both), and what it does
not follow is an unknown value with a diagnostic at its place, never a wrong value, within a
bounded amount of work."""

from __future__ import annotations

import ast

import pytest

from rosvar.diagnostics import Diagnostic, DiagnosticSink
from rosvar.ros2.frontends.python import interpreter
from rosvar.ros2.frontends.python.interpreter import Interpreter, OutOfBudget
from rosvar.ros2.frontends.python.text import Text, render
from rosvar.ros2.frontends.python.values import Dynamic, Module, Unknown, Value


def run(text: str) -> tuple[dict[str, Value], list[Diagnostic]]:
    """The module-level names after reading ``text``, and the diagnostics."""
    sink = DiagnosticSink()
    scope = Interpreter("t.launch.py", text, sink).run_module(ast.parse(text))
    return scope.names, sink.items


FOLLOWED = [
    "1 + 2 * 3",
    "2.5 * 2.0 * True",
    "max(1, 2.5) + min([3, 1, 2])",
    "sorted(['b', 'a'])",
    "7 // 2 - 7 % 3",
    "-7 // 2",
    "7 / 2",
    "0.1 + 0.2",
    "3 - True",
    "'a' + 'b' * 3",
    "'é' * 2",
    "'x' * 0",
    "[1, 2] + [3]",
    "(1, 2) * 2",
    "1 < 2 <= 2 != 3",
    "'a' < 'b'",
    "[1] == [1]",
    "'x' in 'xyz'",
    "3 not in [1, 2]",
    "None is None",
    "0 or 'fallback'",
    "'' and 'never'",
    "[] or [1]",
    "not []",
    "-(-3)",
    "'a' if 1 > 2 else 'b'",
    "1 if [] else 2",
    "'/'.join(['a', 'b'])",
    "'{}-{}'.format('a', 1)",
    "f'{1 + 1}x'",
    "'A_b'.lower().replace('_', '-')",
    "'a b  c'.split()",
    "'a,b'.split(',')",
    "' s '.strip()",
    "'x'.startswith('x') and 'y'.endswith('y')",
    "[i * 2 for i in range(4) if i != 2]",
    "[x for x in 'ab']",
    "{k: v for k, v in [('a', 1)]}",
    "len('abc') + len([1])",
    "str(3) + str(True)",
    "int('7') + float('1.5')",
    "bool('')",
    "tuple([1, 2])",
    "dict(a=1)['a']",
    "list(range(3))[-1]",
    "list(zip([1, 2], 'ab'))",
    "list(enumerate('ab'))",
    "'abcdef'[1:4]",
    "'abc'[-1]",
    "[1, 2, 3][::2]",
    "[1, 2][True]",
    "(1, [2])[1][0]",
    "{'a': 1}.get('b', 2)",
    "{'a': [1]}['a'] + [2]",
    "list({'a': 1}.keys())",
    "list({'a': 1}.values())",
    "1e3",
]


@pytest.mark.parametrize("expression", FOLLOWED)
def test_a_followed_expression_computes_what_python_computes(expression: str) -> None:
    names, diagnostics = run(f"v = {expression}\n")
    expected = eval(expression)  # the test's own constant expression, never a file's
    assert (names["v"], type(names["v"])) == (expected, type(expected))
    assert diagnostics == []


NOT_FOLLOWED = {
    "2 ** 10": "operator Pow",
    "'%s-%d' % ('a', 1)": "'%' formatting",
    "{'a': 1} | {'b': 2}": "operator BitOr",
    "abs(-2)": "call to abs()",
    "sorted([2, {}])": "sorted() of values not known statically",
    "open('/etc/passwd').read()": "a read of /etc/passwd (no workspace)",
    "__import__('os')": "call to __import__()",
}


@pytest.mark.parametrize("expression", sorted(NOT_FOLLOWED))
def test_what_is_not_followed_is_unknown_with_a_diagnostic_at_its_place(expression: str) -> None:
    names, diagnostics = run(f"x = 1\nv = {expression}\n")
    assert isinstance(names["v"], Unknown) and NOT_FOLLOWED[expression] in names["v"].what
    assert [(d.code, d.location.line, d.location.col) for d in diagnostics][:1] == [
        ("python-not-followed", 2, 5)
    ]


def test_statements_loops_and_functions_are_followed() -> None:
    names, diagnostics = run(
        """
def scaled(values, factor=2, *, offset=0):
    result = []
    for value in values:
        if value == 3:
            continue
        if value > 4:
            break
        result.append(value * factor + offset)
    return result

total = 0
for index, item in enumerate(scaled([1, 2, 3, 4, 5, 6], offset=1)):
    total += index * item
a, (b, c) = 'x', ['y', 'z']
with_default = {}.get('missing', 'fallback')
"""
    )
    assert names["total"] == sum(i * v for i, v in enumerate([3, 5, 9]))
    assert (names["a"], names["b"], names["c"]) == ("x", "y", "z")
    assert names["with_default"] == "fallback"
    assert diagnostics == []


def test_a_branch_on_an_unknown_value_is_reported_and_neither_is_taken() -> None:
    names, diagnostics = run(
        "import os\nx = 'before'\nif open('f'):\n    x = 'then'\nelse:\n    x = 'else'\n"
    )
    assert names["x"] == "before"
    assert [d.message for d in diagnostics if d.location.line == 3] == [
        "open() of a path not known statically is not followed",
        "an 'if' on a value not known statically (neither branch) is not followed",
    ]
    assert isinstance(names["os"], Module)


def test_recursion_stops_at_the_call_depth(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(interpreter, "MAX_CALL_DEPTH", 5)
    names, diagnostics = run("def f(n):\n    return f(n + 1)\n\nv = f(0)\n")
    assert isinstance(names["v"], Unknown)
    assert [d.message for d in diagnostics] == ["recursion of f() is not followed"]


def test_the_step_budget_bounds_the_work(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(interpreter, "MAX_STEPS", 1000)
    run("total = 0\nfor i in range(100):\n    total += i\n")  # within the budget
    with pytest.raises(OutOfBudget):
        run("total = 0\nfor i in range(10000):\n    total += i\n")


def test_values_stay_within_the_length_and_size_bounds(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(interpreter, "MAX_LENGTH", 100)
    names, diagnostics = run("short = 'ab' * 50\nlong = 'ab' * 51\nmany = list(range(101))\n")
    assert names["short"] == "ab" * 50
    assert isinstance(names["long"], Unknown) and isinstance(names["many"], Unknown)
    assert len(diagnostics) == 2


def test_launch_time_values_are_expressions_and_what_they_cannot_be_is_reported() -> None:
    names, diagnostics = run(
        "from launch.substitutions import LaunchConfiguration as L\n"
        "def f(context):\n"
        "    v = L('x').perform(context)\n"
        "    for c in v:\n"
        "        pass\n"
        "    for i in [1]:\n"
        "        if v == 'a':\n"
        "            return 1\n"
        "    return 2\n"
        "w = f(None)\n"
        "n = float(L('y').perform(None)) * 2 > 1 and not L('z').perform(None)\n"
    )
    assert isinstance(names["w"], Unknown)
    assert [(d.location.line, d.message) for d in diagnostics] == [  # line 3: read per item
        (
            7,
            "a 'return' in one branch of an 'if' on a launch-time value, in a loop or a nested "
            "block is not followed",
        ),
    ]
    n = names["n"]
    assert isinstance(n, Dynamic) and n.kind is bool
    assert render(n.source) == (
        "(((float($(rosvar-python-string $(var y)))) * (2)) > (1)) and "
        "(not ($(rosvar-python-string $(var z))))"
    )


def test_find_package_find_is_the_named_packages_directory() -> None:
    names, diagnostics = run(
        "from launch_ros.substitutions import FindPackagePrefix, FindPackageShare\n"
        "a = FindPackageShare('x').find('y')\n"
        "b = FindPackagePrefix('x').find(package_name='z')\n"
        "c = FindPackageShare('x').describe()\n"
    )
    a, b = names["a"], names["b"]
    assert isinstance(a, Text) and render(a) == "$(find-pkg-share y)"
    assert isinstance(b, Text) and render(b) == "$(find-pkg-prefix z)"
    assert isinstance(names["c"], Unknown)
    assert [d.message for d in diagnostics] == ["method describe() of a Text is not followed"]


RAISING = """
class NotFound(KeyError):
    pass

def load(name):
    if name == 'missing':
        raise NotFound(name)
    return name

def first(*names):
    for name in names:
        try:
            return load(name)
        except (ValueError, NotFound) as error:
            last = error
        finally:
            pass
    return None

def builtin():
    try:
        raise KeyError('k')
    except LookupError:
        return 'caught'

def passes():
    try:
        load('missing')
    except ValueError:
        return 'wrong'

try:
    v = (first('missing', 'found'), first('missing'), builtin())
except Exception:
    v = 'never'
"""


def test_raise_is_caught_by_the_handler_of_its_class_or_a_base() -> None:
    names, diagnostics = run(RAISING)
    scope: dict[str, object] = {}
    exec(RAISING, scope)  # the oracle: Python itself, on a file that launches nothing
    assert names["v"] == scope["v"] == ("found", None, "caught")
    assert diagnostics == []


def test_an_exception_nothing_catches_fails_the_file_at_its_raise() -> None:
    text = RAISING + "\ndef generate_launch_description():\n    return passes()\n"
    sink = DiagnosticSink()
    reader = Interpreter("t.launch.py", text, sink)
    assert interpreter.entry_point(reader, ast.parse(text)) is None
    assert [(d.code, d.message, d.location.line) for d in sink.items] == [
        ("python-launch-raises", "the file raises NotFound, which nothing catches", 7)
    ]


def test_getenv_is_a_launch_time_string_empty_without_a_default() -> None:
    names, diagnostics = run(
        "import os\na = os.getenv('SIM', 'false')\nb = os.environ.get('R', 'r0')\n"
        "c = os.getenv('ROS_DISTRO')\nd = a == 'true'\n"
    )
    a, b, c, d = (names[n] for n in "abcd")
    assert isinstance(a, Dynamic) and a.text is not None and render(a.text) == "$(env SIM false)"
    assert isinstance(b, Dynamic) and b.kind is str
    assert isinstance(c, Dynamic) and c.text is not None  # None where unset: ''
    assert render(c.text) == "$(env ROS_DISTRO '')"
    assert isinstance(d, Dynamic) and d.kind is bool
    assert diagnostics == []


def test_a_property_is_read_as_an_attribute_of_the_object() -> None:
    names, diagnostics = run(
        "class Base:\n"
        "    def __init__(self, source):\n"
        "        self.__source = source\n"
        "    @property\n"
        "    def name(self):\n"
        "        return self.__source + '.yaml'\n"
        "class Derived(Base):\n"
        "    @property\n"
        "    def name(self):\n"
        "        return 'x/' + super().name\n"
        "v = Derived('params').name\n"
        "w = Base('p').name.upper()\n"
    )
    assert (names["v"], names["w"]) == ("x/params.yaml", "P.YAML")
    assert diagnostics == []


LEAVES = """
class Ref:
    def __init__(self, d, k):
        self.d, self.k = d, k
    def set(self, v):
        self.d[self.k] = v
def leaves(data):
    try:
        for key in data.keys():
            for inner in leaves(data[key]):
                yield inner
            yield Ref(data, key)
    except AttributeError:
        return
def number(text):
    try:
        return float(text) if '.' in text else int(text)
    except ValueError:
        return text
def gen():
    yield from range(3)
    yield 7
data = {'a': {'rate': '2.5', 'name': 'x'}, 'b': {'count': '3'}}
for ref in leaves(data):
    if not isinstance(ref.d[ref.k], dict):
        ref.set(number(ref.d[ref.k]))
v = (data, list(gen()), [r.k for r in leaves(data)])
"""


def test_generators_and_the_exceptions_of_builtins_are_followed_as_python_runs_them() -> None:
    """A helper walking a dict by a generator, which ends at a leaf's ``AttributeError``,
    converting texts to numbers where ``ValueError`` says they are none."""
    names, diagnostics = run(LEAVES)
    scope: dict[str, object] = {}
    exec(LEAVES, scope)  # the oracle: Python itself, on a file that launches nothing
    assert names["v"] == scope["v"]
    assert diagnostics == []


def test_a_launch_object_is_never_none() -> None:
    names, diagnostics = run(
        "from launch.substitutions import LaunchConfiguration\n"
        "ns = LaunchConfiguration('namespace')\n"
        "v = (ns is not None, ns is None, None is not ns, 1 is None)\n"
    )
    assert names["v"] == (True, False, True, False)
    assert diagnostics == []
