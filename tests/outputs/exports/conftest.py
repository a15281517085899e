"""Fixtures for the feature-model exports: models of examples/ and the corpus, flamapy readers,
and configuration counting over what flamapy read.

flamapy is a test-only dependency (flamapy-fm: its UVL and FeatureIDE readers). No flamapy
counting plugin (flamapy-bdd, flamapy-sat) is installed, so :func:`count` builds a BDD from the
*flamapy* model (tree relations with their cardinalities, constraint ASTs) with ``dd`` and counts
it: the semantics checked is the one flamapy read, independently of rosvar's own solver.
"""

from __future__ import annotations

import itertools
import os
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

import dd.cudd as cudd
import pytest

from rosvar.analyses.feature_model.counting import CountedDiagram
from rosvar.analyses.feature_model.extraction import extract
from rosvar.analyses.feature_model.model import FeatureModel
from rosvar.interpreter.workspace_models import Analysis
from rosvar.workspace import discover

REPO = Path(__file__).resolve().parents[3]
CORPUS = Path(os.environ.get("ROSVAR_CORPUS", REPO.parent / "shared" / "corpus")).resolve()
SYSTEMS = ["examples", "kobuki", "lizi", "turtlebot2"]

_MODELS: dict[str, FeatureModel] = {}


def system_root(system: str) -> Path:
    return REPO / "examples" if system == "examples" else CORPUS / system


def load(system: str) -> FeatureModel:
    """The feature model of ``system`` (extracted once per session); skips without the corpus."""
    if system not in _MODELS:
        root = system_root(system)
        if not root.is_dir():
            pytest.skip(f"no corpus at {root} (set ROSVAR_CORPUS)")
        _MODELS[system] = extract(Analysis(discover([str(root)])))
    return _MODELS[system]


@pytest.fixture(params=SYSTEMS)
def system(request: pytest.FixtureRequest) -> str:
    return str(request.param)


@pytest.fixture
def model(system: str) -> FeatureModel:
    return load(system)


@pytest.fixture
def examples_model() -> FeatureModel:
    return load("examples")


@pytest.fixture
def dead_model(ws: Any) -> FeatureModel:
    """``both.launch`` includes two files clashing unconditionally: it can never be selected."""
    ws.launch(
        "both.launch",
        '  <include file="$(find pkg)/launch/a.launch"/>\n'
        '  <include file="$(find pkg)/launch/b.launch"/>',
    )
    for name in ("a.launch", "b.launch"):
        ws.launch(name, '  <node pkg="pkg" type="t" name="same"/>')
    return extract(ws.analysis())


# -- flamapy ---------------------------------------------------------------------------------


class Flamapy:
    """flamapy's readers (writing the text under a temporary folder) and model counting."""

    def __init__(self, directory: Path) -> None:
        self.directory = directory

    def uvl(self, text: str) -> Any:
        path = self.directory / "model.uvl"
        path.write_text(text, encoding="utf-8")
        return _transformations().UVLReader(str(path)).transform()

    def featureide(self, text: str) -> Any:
        path = self.directory / "model.xml"
        path.write_text(text, encoding="utf-8")
        return _transformations().FeatureIDEReader(str(path)).transform()

    @staticmethod
    def names(fm: Any) -> list[str]:
        return [f.name for f in fm.get_features()]

    @staticmethod
    def count(fm: Any) -> int:
        return count(fm)

    @staticmethod
    def brute_force_count(fm: Any) -> int:
        return brute_force_count(fm)


@pytest.fixture
def flamapy(tmp_path: Path) -> Flamapy:
    pytest.importorskip("flamapy.metamodels.fm_metamodel", reason="flamapy-fm is a test extra")
    return Flamapy(tmp_path)


def _cardinality(manager: Any, children: list[Any], low: int, high: int) -> Any:
    """Between ``low`` and ``high`` of ``children`` hold (``high`` -1: no upper bound).

    Built from the last child up, ``within[c]`` meaning "the children so far, plus ``c``
    chosen before them, stay within the bounds" (a loop: a recursive closure would tie its
    BDDs and their manager into a cycle that the collector frees in any order).
    """
    high = len(children) if high < 0 else high
    counts = range(len(children) + 1)
    within = [manager.true if low <= c <= high else manager.false for c in counts]
    for child in reversed(children):
        within = [
            (child & within[c + 1]) | (~child & within[c]) if c < len(children) else within[c]
            for c in counts
        ]
    return within[0]


def _transformations() -> Any:
    from flamapy.metamodels.fm_metamodel import transformations

    return transformations


def _operations() -> Any:
    from flamapy.core.models import ast

    return ast.ASTOperation


def _ast(manager: Any, node: Any) -> Any:
    ASTOperation = _operations()
    if not node.is_op():
        return manager.var(str(node.data))
    operation = node.data
    if operation == ASTOperation.NOT:
        return ~_ast(manager, node.left)
    left, right = _ast(manager, node.left), _ast(manager, node.right)
    if operation == ASTOperation.AND:
        return left & right
    if operation == ASTOperation.OR:
        return left | right
    if operation in (ASTOperation.IMPLIES, ASTOperation.REQUIRES):
        return ~left | right
    if operation == ASTOperation.EXCLUDES:
        return ~left | ~right
    if operation == ASTOperation.EQUIVALENCE:
        return left.equiv(right)
    if operation == ASTOperation.XOR:
        return left ^ right
    raise AssertionError(f"unexpected operation {operation}")


def count(fm: Any) -> int:
    """Configurations of a flamapy feature model, counted on a BDD of its semantics."""
    manager = cudd.BDD()
    manager.configure(reordering=False)
    features = list(_depth_first(fm.root))
    manager.declare(*(f.name for f in features))
    formula = manager.var(fm.root.name)
    for feature in features:
        parent = manager.var(feature.name)
        for relation in feature.get_relations():
            children = [manager.var(c.name) for c in relation.children]
            for child in children:
                formula &= ~child | parent
            group = _cardinality(manager, children, relation.card_min, relation.card_max)
            formula &= ~parent | group
    for constraint in fm.get_constraints():
        formula &= _ast(manager, constraint.ast.root)
    return CountedDiagram(manager, formula, {f.name: (1, 1) for f in features}).first


def _depth_first(feature: Any) -> Iterator[Any]:
    yield feature
    for relation in feature.get_relations():
        for child in relation.children:
            yield from _depth_first(child)


def brute_force_count(fm: Any) -> int:
    """Configurations by enumerating the tree's products and evaluating each constraint
    (no BDD at all: a cross-check of :func:`count` on small models)."""
    ASTOperation = _operations()

    def products(feature: Any) -> Iterator[frozenset[str]]:
        choices: list[list[frozenset[str]]] = []
        for relation in feature.get_relations():
            options: list[frozenset[str]] = []
            high = relation.card_max if relation.card_max >= 0 else len(relation.children)
            for size in range(relation.card_min, high + 1):
                for chosen in itertools.combinations(relation.children, size):
                    for parts in itertools.product(*(list(products(c)) for c in chosen)):
                        options.append(frozenset().union(*parts))
            choices.append(options)
        for parts in itertools.product(*choices):
            yield frozenset({feature.name}).union(*parts)

    def holds(node: Any, selected: frozenset[str]) -> bool:
        if not node.is_op():
            return str(node.data) in selected
        operation = node.data
        left = holds(node.left, selected)
        if operation == ASTOperation.NOT:
            return not left
        right = holds(node.right, selected)
        results: dict[Any, Callable[[], bool]] = {
            ASTOperation.AND: lambda: left and right,
            ASTOperation.OR: lambda: left or right,
            ASTOperation.IMPLIES: lambda: (not left) or right,
            ASTOperation.REQUIRES: lambda: (not left) or right,
            ASTOperation.EXCLUDES: lambda: not (left and right),
            ASTOperation.EQUIVALENCE: lambda: left == right,
            ASTOperation.XOR: lambda: left != right,
        }
        return results[operation]()

    constraints = fm.get_constraints()
    return sum(
        all(holds(c.ast.root, product) for c in constraints) for product in products(fm.root)
    )
