"""What a user says while configuring: select, deselect, unselect or set one feature.

Choices are plain data. The engine replays a list of them in order, so a stateless caller
(the CLI) and a stateful one (a web session with undo/redo) ask the same question.
"""

from __future__ import annotations

from dataclasses import dataclass
from enum import StrEnum


class Action(StrEnum):
    """What a choice does to its feature."""

    SELECT = "select"
    DESELECT = "deselect"
    UNSELECT = "unselect"
    SET = "set"


class ChoiceError(ValueError):
    """A choice that names no feature or is malformed (a usage error, not a refusal)."""


@dataclass(frozen=True)
class UserChoice:
    """``feature`` is a feature id (``FILE``, ``FILE:ARG``, ``FILE:ARG=VALUE``).

    For ``set`` it is ``FILE:ARG`` and ``value`` the value: a known one selects that value
    feature, any other text selects the arg's ``<other>`` value with that text.
    """

    action: Action
    feature: str
    value: str | None = None

    @staticmethod
    def parse(action: str, text: str) -> UserChoice:
        """``set`` takes ``FILE:ARG=VALUE``; the other actions a feature id."""
        try:
            known = Action(action)
        except ValueError:
            raise ChoiceError(f"unknown action {action!r} (one of {', '.join(Action)})") from None
        if known != Action.SET:
            return UserChoice(known, text)
        feature, sep, value = text.partition("=")
        if not sep or ":" not in feature:
            raise ChoiceError(f"set expects FILE:ARG=VALUE, got {text!r}")
        return UserChoice(Action.SET, feature, value)


@dataclass(frozen=True)
class Refusal:
    """A choice that contradicted the model given the choices before it; it was not applied."""

    choice: UserChoice
    reason: str
