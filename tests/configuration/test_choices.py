"""Choices as the command line and the web API spell them."""

from __future__ import annotations

import pytest

from rosvar.configuration.choices import Action, ChoiceError, UserChoice


def test_parse_choices() -> None:
    assert UserChoice.parse("set", "a.launch:x=a=b") == UserChoice(Action.SET, "a.launch:x", "a=b")
    assert UserChoice.parse("select", "a.launch:x=1") == UserChoice(Action.SELECT, "a.launch:x=1")
    for action, text in (("set", "a.launch"), ("set", "a.launch:x"), ("pick", "a.launch")):
        with pytest.raises(ChoiceError):
            UserChoice.parse(action, text)
