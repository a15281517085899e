"""The environment a product of the configuration engine runs in.

The engine's products are launched as their command says: each environment variable holds
the value the user gave (``--env``), or is unset, as ``rosvar resolve`` takes it. The
paper's feature model leaves the environment free (its atoms quantified out); the engine's
fixes it, or a clash that only an environment nobody sets would avoid (an include of
``$(optenv BASE kobuki).launch`` that a value of ``BASE`` would turn to the other file)
is never excluded, and the engine offers a product that roslaunch refuses.
"""

from __future__ import annotations

from collections.abc import Mapping

from rosvar.logic.atoms import PredicateAtom
from rosvar.logic.conditions import ConditionSpace, decide_predicate
from rosvar.logic.inputs import EnvInput, Input
from rosvar.logic.terms import term_inputs


def fixed_environment(
    space: ConditionSpace, env: Mapping[str, str], host: object = None
) -> dict[str, bool]:
    """The truth of every atom that only reads the environment (its slots, predicates on
    its values), each variable holding its value in ``env`` or unset; ``host`` decides
    ``$(find)`` in predicates."""
    concrete: dict[Input, str] = {}
    fixed: dict[str, bool] = {}
    for input_ in space.inputs():
        if not isinstance(input_, EnvInput):
            continue
        value = env.get(input_.name)
        if value is not None:
            concrete[input_] = value
        held = space.held(input_, value)
        for slot, variable in space.slot_atoms(input_):
            fixed[str(variable.var)] = slot == held
    for atom in space.atoms():
        if isinstance(atom, PredicateAtom) and _reads_only_environment(atom):
            fixed[space.variable_name(atom)] = decide_predicate(atom, concrete, host)
    return fixed


def _reads_only_environment(atom: PredicateAtom) -> bool:
    inputs = term_inputs(atom.term)
    return bool(inputs) and all(isinstance(i, EnvInput) for i in inputs)
