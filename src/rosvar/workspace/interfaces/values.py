"""Values of names met while reading sources: static text, or text with unknown parts.

Both extractors (C++ and Python) build names by concatenation and namespace joins; an
unknown part is written ``{expression}`` so that the result is still readable and still
tells the graph that it is not a literal.
"""

from __future__ import annotations

from dataclasses import dataclass

from rosvar.ros.names import ns_join

MAX_TEXT = 4096
"""No ROS name is longer: a value built by doubling in a loop or a helper chain stops here."""


@dataclass(frozen=True)
class Text:
    """A string value; ``static`` is False when some part of it is not known."""

    value: str
    static: bool = True
    resolved: bool = False
    """Already resolved by the node (``nh.resolveName("image")``): no handle's namespace
    applies to it again."""

    @staticmethod
    def unknown(expression: str) -> Text:
        return Text("{" + " ".join(expression.split()) + "}", static=False)

    def __add__(self, other: Text) -> Text:
        value = self.value + other.value
        if len(value) > MAX_TEXT:
            return Text.unknown("…")
        return Text(value, self.static and other.static, self.resolved)

    def within(self, namespace: Text) -> Text:
        """This name as a node handle in ``namespace`` resolves it (``~``, ``/`` kept)."""
        if self.resolved or (self.static and self.value[:1] in ("/", "~")):
            return self
        if not self.static and self.value.startswith("{"):
            if namespace.value in ("", "~"):
                return Text(namespace.value + self.value, False)
            return Text(namespace.value.rstrip("/") + "/" + self.value, False)
        return Text(ns_join(namespace.value, self.value), self.static and namespace.static)


@dataclass(frozen=True)
class ParamRef:
    """The value of a parameter the code reads (``nh.param("topic", t, "scan")``,
    ``declare_parameter("topic", "scan")``, ``rospy.get_param("~topic", "scan")``): a name
    known per configuration, set by the launch files or else ``default`` (None: the
    default is the one a declaration of the parameter gives, if any)."""

    name: Text
    """The parameter's name as the node resolves it (``~topic``, ``topic``, ``/topic``)."""
    default: str | None = None


def action_type(message: str) -> str:
    """``pkg/MoveBaseAction`` names the action ``pkg/MoveBase`` (its goal, result, feedback)."""
    return (
        message[: -len("Action")] if message.endswith("Action") and message != "Action" else message
    )
