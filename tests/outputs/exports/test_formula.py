"""Constraints as formulas: each exported formula means its solver constraint inside the feature
tree, whatever the BDD; shapes are the compact ones (implications, ``!(a & b)``)."""

from __future__ import annotations

from typing import Any

from hypothesis import given, settings
from hypothesis import strategies as st

from rosvar.analyses.feature_model.model import FeatureModel
from rosvar.outputs.exports._common import Tree
from rosvar.outputs.exports._formula import (
    LOGIC_OPERATORS,
    And,
    Implies,
    Not,
    Or,
    Var,
    compact,
    exported,
    render,
    to_bdd,
)

from .conftest import load


def test_exported_formulas_mean_the_constraints(model: FeatureModel) -> None:
    tree = Tree(model)
    care = model.solver.tree
    constraints = exported(tree)
    assert [c.source for c in constraints] == [
        n for n, c in enumerate(model.solver.constraints) if c != model.solver.manager.true
    ]
    for constraint in constraints:
        assert constraint.source is not None
        u = model.solver.constraints[constraint.source]
        assert (to_bdd(tree, constraint.formula) & care) == (u & care)


def test_examples_shapes(examples_model: FeatureModel) -> None:
    tree = Tree(examples_model)
    formulas = [c.formula for c in exported(tree)]
    assert formulas == [
        Implies(Var("example/launch/mapping.launch:sim=false"), Var("example/launch/control.xml")),
        Implies(Var("example/launch/robot.launch"), Var("example/launch/control.xml")),
        Not(And((Var("example/launch/control.xml"), Var("example/launch/teleop_only.launch")))),
    ]
    assert render(formulas[0], str, LOGIC_OPERATORS) == (
        "example/launch/mapping.launch:sim=false ⇒ example/launch/control.xml"
    )


def test_render_parenthesises_by_precedence() -> None:
    a, b, c = Var("a"), Var("b"), Var("c")
    assert render(Implies(And((a, b)), Or((b, c))), str) == "a & b => b | c"
    assert render(And((Or((a, b)), c)), str) == "(a | b) & c"
    assert render(Not(Or((a, b))), str) == "!(a | b)"
    assert render(Implies(Implies(a, b), c), str) == "(a => b) => c"
    assert render(Not(Not(a)), str) == "!(!a)"


literals = st.tuples(st.integers(min_value=0, max_value=63), st.booleans())
cubes = st.lists(literals, min_size=1, max_size=4)
formulas = st.lists(cubes, min_size=0, max_size=5)


@settings(max_examples=150, deadline=None)
@given(formulas)
def test_any_bdd_compacts_to_an_equivalent_formula(dnf: list[list[tuple[int, bool]]]) -> None:
    model = load("examples")
    tree = Tree(model)
    manager = model.solver.manager
    variables = model.solver.variables
    u: Any = manager.false
    for cube in dnf:
        term = manager.true
        for index, positive in cube:
            variable = manager.var(variables[index % len(variables)])
            term &= variable if positive else ~variable
        u |= term
    care = model.solver.tree
    formula = compact(tree, u)
    if formula is None:
        assert (care & ~u) == manager.false
    else:
        assert (to_bdd(tree, formula) & care) == (u & care)
