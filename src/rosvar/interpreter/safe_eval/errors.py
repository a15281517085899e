"""What the restricted evaluator raises: refusals and run-time failures."""

from __future__ import annotations

from typing import Final

_UNPLACED: Final = -1  # column of an error raised where no AST node is at hand


class EvalRefused(Exception):
    """The expression uses something the restricted evaluator does not allow, or is not Python.

    ``col`` is the 0-based character offset in the expression text of the offending construct.
    Host callables may raise it without a column; the evaluator then fills in the call's.
    """

    def __init__(self, message: str, col: int = _UNPLACED) -> None:
        super().__init__(message)
        self.message = message
        self.col = col


class CallRefused(EvalRefused):
    """A call of ``name``, which the whitelist does not hold: an evaluation says what its
    environment allows instead (:func:`~rosvar.interpreter.safe_eval.names.allowed_calls`)."""

    def __init__(self, name: str, message: str, col: int = _UNPLACED) -> None:
        super().__init__(message, col)
        self.name = name


class EvalFailed(Exception):
    """The expression is allowed but fails at run time where Python/roslaunch would raise.

    ``col`` is the 0-based character offset of the failing construct, for diagnostics.
    """

    def __init__(self, message: str, col: int = _UNPLACED) -> None:
        super().__init__(message)
        self.message = message
        self.col = col
