"""Properties computed on first use, in the compiled build as well.

mypyc compiles ``functools.cached_property`` as a plain property, computed again at every
access (the feature model's formulas, the counted diagrams). This module is left as Python
(setup.py), and classes using it are Python classes when compiled
(``mypyc_attr(native_class=False)``): the property is then the standard library's, whose
value is kept in the instance's ``__dict__``.
"""

from __future__ import annotations

from collections.abc import Callable
from functools import cached_property
from typing import Any, TypeVar

T = TypeVar("T")


def lazy_property(compute: Callable[[Any], T]) -> T:
    """``functools.cached_property``, under a name that compiled code leaves alone."""
    return cached_property(compute)  # type: ignore[return-value]
