"""Python's arithmetic operators by AST node: the one table the restricted evaluators share.

``$(eval)`` (``interpreter/safe_eval``), the query language (``analyses/query``) and the static
reading of Python launch files (``ros2/frontends/python``) all compute ``+ - * / // %`` on
constants; each adds what it allows beyond these.
"""

from __future__ import annotations

import ast
import operator
from collections.abc import Callable, Mapping
from typing import Any, Final

ARITHMETIC: Final[Mapping[type[ast.operator], Callable[[Any, Any], Any]]] = {
    ast.Add: operator.add,
    ast.Sub: operator.sub,
    ast.Mult: operator.mul,
    ast.Div: operator.truediv,
    ast.FloorDiv: operator.floordiv,
    ast.Mod: operator.mod,
}
