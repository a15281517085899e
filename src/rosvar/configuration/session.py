"""One user's history of choices: apply, undo, redo, reset.

The engine is stateless; a session only keeps the list of accepted choices and the ones
undone, and asks the engine for the state of the current list (answered from its cache
when the list was seen before).
"""

from __future__ import annotations

from rosvar.configuration.choices import UserChoice
from rosvar.configuration.engine import ConfigurationState, Configurator


class Session:
    """Undo/redo/reset over the accepted choices; refused choices are not recorded."""

    def __init__(self, configurator: Configurator) -> None:
        self.configurator = configurator
        self._done: list[UserChoice] = []
        self._undone: list[UserChoice] = []
        self._state = configurator.state([])

    @property
    def can_undo(self) -> bool:
        return bool(self._done)

    @property
    def can_redo(self) -> bool:
        return bool(self._undone)

    def current(self) -> ConfigurationState:
        return self._state

    def apply(self, choice: UserChoice) -> ConfigurationState:
        """The state with ``choice`` added; a refused choice leaves the history unchanged."""
        state = self.configurator.state([*self._done, choice])
        if state.refused:
            state.choices = list(self._done)
            return state
        self._done.append(choice)
        self._undone.clear()
        self._state = state
        return state

    def undo(self) -> ConfigurationState:
        if self._done:
            self._undone.append(self._done.pop())
            self._state = self.configurator.state(self._done)
        return self._state

    def redo(self) -> ConfigurationState:
        if self._undone:
            self._done.append(self._undone.pop())
            self._state = self.configurator.state(self._done)
        return self._state

    def reset(self) -> ConfigurationState:
        self._done.clear()
        self._undone.clear()
        self._state = self.configurator.state([])
        return self._state
