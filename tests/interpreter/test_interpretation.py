"""The tag registry of the interpretation: one handler per tag."""

from __future__ import annotations

import pytest

from rosvar.interpreter.interpretation import TAGS, tag
from rosvar.ros1 import tags  # noqa: F401 - registers the tag handlers


def test_every_roslaunch_tag_has_a_handler() -> None:
    assert set(TAGS) >= {
        "arg", "env", "group", "include", "machine", "master", "node", "param", "remap",
        "rosparam", "test",
    }  # fmt: skip


def test_a_second_handler_for_a_tag_is_refused() -> None:
    handler = TAGS["node"]
    with pytest.raises(ValueError, match="registered twice"):
        tag("node")(lambda _it, _entity, _scope: None)
    assert TAGS["node"] is handler
