"""The cells of ROS 2's term functions of one input (:mod:`rosvar.logic.cells`): so that
``IfCondition(use_composition)`` and ``IfCondition(PythonExpression(['not ',
use_composition]))`` are related for a value nobody foresaw, as two ``$(eval)``s of roslaunch
are.

``PythonExpression`` (``ros2-eval``) splices the text into Python source: what tells its
results apart is the Python the text spells (a truthy or falsy literal, ``None``, a name that
fails) and the constants written beside it (``'humble' == '`` ... ``'``); the boolean
substitutions (``NotSubstitution``, ``EqualsSubstitution``...) read the text as YAML's
booleans and numbers, and compare it with their literal operands.
"""

from __future__ import annotations

import re
from collections.abc import Hashable, Iterable
from typing import Final

from rosvar.logic.cells import LITERAL_CELLS, Cells, literal_operands, register_cells, spellings
from rosvar.logic.inputs import Input
from rosvar.logic.terms import Apply
from rosvar.ros2.boolean_substitutions import FUNCTIONS
from rosvar.ros2.frontends.python.text import PYTHON_STRING

PYTHON_TEXTS: Final = ("True", "False", "None", "0", "1", "2", "-1", "0.5", "''", "[]", "x")
"""Python a text may spell: literals true and false, a number of each sign, a name."""
QUOTE_BREAKING: Final = ("' or '", '" or "', "'", '"')
"""Texts that leave a quoted literal they are spliced into (``'p$(var x)s' == 'a'`` is
``'p'`` for the first, not a boolean; a lone quote fails the expression)."""
YAML_BOOLEANS: Final = spellings(("true", "false", "yes", "no", "on", "off", "1", "0"))
"""What launch's typed ``bool`` reads (YAML 1.1's words, ``1`` and ``0``), as people write
them."""
_TOKENS: Final = re.compile(r"'([^']*)'|\"([^\"]*)\"|([-+]?\d+(?:\.\d+)?|\w+)")


def _spliced_constants(term: Apply, input_: Input) -> frozenset[Hashable] | None:
    """The words, numbers and quoted texts of the Python written beside the input's text
    (``'not '``, ``' == 7'``), or beside its ``repr`` (the Python frontend's launch-time
    strings): what the expression may compare it with."""
    literals = literal_operands(term, input_, quoting=(PYTHON_STRING,))
    if literals is None:
        return None
    found: set[Hashable] = set()
    for literal in literals:
        assert isinstance(literal, str)
        for quoted, double, word in _TOKENS.findall(literal):
            found.add(quoted or double or word)
    return frozenset(found)


def _python_witnesses(constants: Iterable[Hashable]) -> tuple[str, ...]:
    return (*PYTHON_TEXTS, *QUOTE_BREAKING, *(c for c in constants if isinstance(c, str)))


def _boolean_witnesses(constants: Iterable[Hashable]) -> tuple[str, ...]:
    texts = [c for c in constants if isinstance(c, str)]
    numbers = [f"{t}.0" for t in texts if t.lstrip("+-").isdigit()]  # equals compares numbers
    return (*YAML_BOOLEANS, *texts, *numbers)


register_cells("ros2-eval", Cells(_spliced_constants, _python_witnesses))
register_cells("ros2-text-equals", LITERAL_CELLS)
for _name in FUNCTIONS:
    register_cells(f"ros2-{_name}", Cells(literal_operands, _boolean_witnesses))
