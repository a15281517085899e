"""``rosvar.ros.names`` against Debian's ``rosgraph.names`` (and roslaunch's ``LoaderContext``).

All reference answers come from ONE ``/usr/bin/python3`` subprocess that receives every input as
JSON and answers with the result (or the exception's type) of each function. The inputs are
generated: every short string over an alphabet of the characters that matter to ROS names
(``/``, ``~``, ``_``, a letter, a digit) plus hand-picked oddities (unicode, spaces, newlines).
"""

from __future__ import annotations

import itertools
import json
import os
import subprocess
from collections.abc import Callable
from typing import Any

import pytest

from rosvar.ros import names

SYSTEM_PYTHON = "/usr/bin/python3"

REFERENCE = r"""
import json, sys
import rosgraph.names as n
from roslaunch.loader import LoaderContext

def call(function, *args):
    try:
        return {"ok": function(*args)}
    except Exception as error:
        return {"error": type(error).__name__}

def child(parent, ns):
    return LoaderContext(parent, "f.launch").child(ns).ns

data = json.load(sys.stdin)
out = {
    "ns_join": [call(n.ns_join, a, b) for a, b in data["pairs"]],
    "canonicalize_name": [call(n.canonicalize_name, s) for s in data["names"]],
    "make_global_ns": [call(n.make_global_ns, s) for s in data["names"]],
    "is_legal_name": [call(n.is_legal_name, s) for s in data["names"]],
    # rosgraph returns the falsy name itself for ''; only the truth value is the contract
    "is_global": [call(lambda s: bool(n.is_global(s)), s) for s in data["names"]],
    "is_private": [call(lambda s: bool(n.is_private(s)), s) for s in data["names"]],
    "child": [call(child, a, b) for a, b in data["children"]],
    "parent_ns": [call(lambda p: LoaderContext(p, "f.launch").ns, a) for a, _ in data["children"]],
    "load_mappings": [call(n.load_mappings, argv) for argv in data["argvs"]],
    "settable": [call(lambda s: s in n.load_mappings([s + ":=x"]), s) for s in data["names"]],
}
json.dump(out, sys.stdout)
"""

ALPHABET = ("a", "/", "~", "_", "1")
ODDITIES = (
    "",
    "foo",
    "/foo/bar",
    "foo/bar/",
    "//foo//bar//",
    "~foo",
    "~/foo",
    "/~foo",
    "foo~",
    "__ns",
    "_private",
    "ä",
    "aä",
    "a b",
    "a-b",
    "a.b",
    "1abc",
    "a\n",
    "\na",
    "a\t",
    "/" * 5,
    "robot_1/base_link",
)


def _short_strings(max_length: int) -> list[str]:
    out = [""]
    for length in range(1, max_length + 1):
        out.extend("".join(p) for p in itertools.product(ALPHABET, repeat=length))
    return out


NAMES = list(dict.fromkeys([*_short_strings(4), *ODDITIES]))
PAIR_PARTS = list(dict.fromkeys([*_short_strings(2), *ODDITIES]))
PAIRS = [(a, b) for a in PAIR_PARTS for b in PAIR_PARTS]
# roslaunch's contexts always start from a namespace that make_global_ns accepts
PARENTS = ["/", "/a/", "/robot/arm/", "a", "", "/a//b/"]
CHILDREN = [(p, c) for p in PARENTS for c in PAIR_PARTS]

WORDS = [
    "a:=b",
    "/a:=/b",
    "~a:=b",
    "_a:=1",
    "__ns:=/robot",
    "__name:=n",
    "_:=x",
    "a:=",
    ":=b",
    "a:=b:=c",
    " a:=b",
    "a :=b",
    "a:= b ",
    "1a:=b",
    "a-b:=c",
    "a/b:=c/d",
    "a",
    "a=b",
    "äb:=c",
    "aä:=c",
    "a:=b\n",
    "a:=b\nc",
    "a\n:=b",
    "x:=ü",
    "a:=b c",
    "--flag",
    "__log:=/tmp/x",
]
ARGVS = [[w] for w in WORDS] + [
    ["a:=1", "a:=2"],
    ["a:=1", "_a:=2", "b:=3"],
    ["pkg", "file.launch", "x:=y", "__ns:=/n"],
    [],
]


@pytest.fixture(scope="module")
def reference() -> dict[str, list[dict[str, Any]]]:
    if not os.access(SYSTEM_PYTHON, os.X_OK):
        pytest.skip("no /usr/bin/python3")
    payload = {
        "pairs": PAIRS,
        "names": NAMES,
        "children": CHILDREN,
        "argvs": ARGVS,
    }
    proc = subprocess.run(
        [SYSTEM_PYTHON, "-c", REFERENCE],
        input=json.dumps(payload),
        capture_output=True,
        text=True,
        timeout=120,
        env={"PATH": "/usr/bin:/bin", "HOME": "/tmp"},
        check=False,
    )
    if proc.returncode != 0:
        if "ModuleNotFoundError" in proc.stderr or "ImportError" in proc.stderr:
            pytest.skip("rosgraph/roslaunch not importable by /usr/bin/python3")
        raise AssertionError(f"reference process failed:\n{proc.stderr}")
    result: dict[str, list[dict[str, Any]]] = json.loads(proc.stdout)
    return result


def _ours(function: Callable[..., Any], *args: Any) -> dict[str, Any]:
    try:
        return {"ok": function(*args)}
    except Exception as error:  # the exception type is part of the contract
        return {"error": type(error).__name__}


def _mismatches(
    inputs: list[Any], ours: list[dict[str, Any]], theirs: list[dict[str, Any]]
) -> list[str]:
    assert len(ours) == len(theirs) == len(inputs)
    return [
        f"{value!r}: rosvar {mine} rosgraph {reference}"
        for value, mine, reference in zip(inputs, ours, theirs, strict=True)
        if mine != reference
    ]


def test_reference_was_generated_over_many_inputs(
    reference: dict[str, list[dict[str, Any]]],
) -> None:
    assert len(NAMES) > 700 and len(PAIRS) > 1000
    # the generated set reaches every interesting outcome, so the comparisons below bite
    assert {"error": "ValueError"} in reference["make_global_ns"]
    assert {"ok": True} in reference["is_legal_name"]
    assert {"ok": False} in reference["is_legal_name"]
    assert {"error": "ValueError"} in reference["child"]


def test_ns_join(reference: dict[str, list[dict[str, Any]]]) -> None:
    ours = [_ours(names.ns_join, a, b) for a, b in PAIRS]
    assert _mismatches(PAIRS, ours, reference["ns_join"]) == []


@pytest.mark.parametrize(
    "function",
    ["canonicalize_name", "make_global_ns", "is_legal_name", "is_global", "is_private"],
)
def test_single_name_functions(function: str, reference: dict[str, list[dict[str, Any]]]) -> None:
    ours = [_ours(getattr(names, function), name) for name in NAMES]
    assert _mismatches(NAMES, ours, reference[function]) == []


def test_make_global_ns_refuses_private_names() -> None:
    for name in ("~", "~a", "~/a"):
        with pytest.raises(ValueError, match=r"cannot turn \[~"):
            names.make_global_ns(name)
    assert names.make_global_ns("") == "/"
    assert names.make_global_ns("a/b") == "/a/b/"


def test_child_namespace_is_loader_context_child(
    reference: dict[str, list[dict[str, Any]]],
) -> None:
    """``child_namespace(parent.ns, ns)`` is ``LoaderContext(parent).child(ns).ns``."""
    ours = []
    for (parent, child), parent_ns in zip(CHILDREN, reference["parent_ns"], strict=True):
        assert "ok" in parent_ns, parent
        ours.append(_ours(names.child_namespace, parent_ns["ok"], child or None))
    assert _mismatches(CHILDREN, ours, reference["child"]) == []


def test_command_line_mappings_is_load_mappings(
    reference: dict[str, list[dict[str, Any]]],
) -> None:
    plain = [i for i, argv in enumerate(ARGVS) if not any("\n" in w for w in argv)]
    ours = [_ours(names.command_line_mappings, ARGVS[i]) for i in plain]
    theirs = [reference["load_mappings"][i] for i in plain]
    assert _mismatches([ARGVS[i] for i in plain], ours, theirs) == []
    # a sanity check that the comparison has teeth: these are the documented rules
    assert names.command_line_mappings(["_a:=1", "__ns:=/r", "a:=b:=c", "x:= y "]) == {
        "__ns": "/r",
        "x": "y",
    }


def test_command_line_mappings_with_newlines_is_load_mappings(
    reference: dict[str, list[dict[str, Any]]],
) -> None:
    chosen = [i for i, argv in enumerate(ARGVS) if any("\n" in w for w in argv)]
    assert chosen
    ours = [_ours(names.command_line_mappings, ARGVS[i]) for i in chosen]
    theirs = [reference["load_mappings"][i] for i in chosen]
    assert _mismatches([ARGVS[i] for i in chosen], ours, theirs) == []


def test_settable_is_what_load_mappings_sets(
    reference: dict[str, list[dict[str, Any]]],
) -> None:
    ours = [_ours(names.settable, name) for name in NAMES]
    assert _mismatches(NAMES, ours, reference["settable"]) == []
    assert {"a", "__ns", "/a", "~a"} <= {n for n in NAMES if names.settable(n)}
    assert not {"", "_a", "1a", "a b", "a\n"} & {n for n in NAMES if names.settable(n)}


def test_namespaces_of() -> None:
    assert names.namespaces_of("/a/b/c") == ["/", "/a/", "/a/b/"]
    assert names.namespaces_of("/a") == ["/"]
    assert names.namespaces_of("/") == []
    assert names.namespaces_of("") == []
    # every listed namespace is what make_global_ns makes of a prefix of the name
    for name in ("/robot/arm/joint", "/x"):
        for ns in names.namespaces_of(name):
            assert name.startswith(ns) and names.make_global_ns(ns) == ns
