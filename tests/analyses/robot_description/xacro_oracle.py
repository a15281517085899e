"""The real xacro (the ``xacro`` package of PyPI, ROS's own) as a test oracle.

It runs in this process with the configuration's environment and the workspace's packages
for ``$(find)``, and its output is read into the canonical form rosvar's restriction gives
(:func:`rosvar.analyses.robot_description.document.canonical`). Only tests import it.
"""

from __future__ import annotations

import contextlib
import io
import os
import xml.dom.minidom
from collections.abc import Iterator, Mapping
from dataclasses import dataclass

import xacro
import xacro.substitution_args

from rosvar.analyses.robot_description.document import Node, canonical


@dataclass(frozen=True)
class XacroFailed:
    """xacro raised: it prints nothing."""

    message: str


@contextlib.contextmanager
def _environment(env: Mapping[str, str], packages: Mapping[str, str]) -> Iterator[None]:
    saved = dict(os.environ)
    original = xacro.substitution_args._eval_find

    def find(name: str) -> str:
        return packages[name]

    os.environ.clear()
    os.environ.update({"PATH": saved.get("PATH", ""), **env})
    xacro.substitution_args._eval_find = find
    xacro.substitution_args._eval_dict["find"] = find
    try:
        yield
    finally:
        os.environ.clear()
        os.environ.update(saved)
        xacro.substitution_args._eval_find = original
        xacro.substitution_args._eval_dict["find"] = original


def run_xacro(
    file: str, mappings: Mapping[str, str], env: Mapping[str, str], packages: Mapping[str, str]
) -> Node | XacroFailed:
    """What ``xacro FILE name:=value...`` prints, canonically, or its failure."""
    with _environment(env, packages), contextlib.redirect_stderr(io.StringIO()):
        try:
            document = xacro.process_file(file, mappings=dict(mappings), verbosity=0)
        except (Exception, SystemExit) as error:  # xacro raises whatever Python raised
            return XacroFailed(f"{type(error).__name__}: {error}")
    return _node(document.documentElement)


def _node(element: xml.dom.minidom.Element) -> Node:
    texts: list[str] = []
    children: list[Node] = []
    for child in element.childNodes:
        if child.nodeType == child.TEXT_NODE:
            texts.append(child.data)
        elif child.nodeType == child.ELEMENT_NODE:
            children.append(_node(child))
    attributes = {name: str(value) for name, value in element.attributes.items()}
    return canonical(element.tagName, attributes, "".join(texts), children)
