"""Typed values of YAML and Python launch files written as attribute text.

XML attributes are text, which ROS 2 coerces by YAML rules where it wants a type
(``<param value="10"/>`` is the integer 10). YAML and Python launch files carry typed values
instead (``value: 10``, ``{'rate': 10}``, ``scoped=False``). Such a value becomes its canonical
YAML text (``10``, ``false``, ``1.5``, ``.inf``, ``null``, lists as flow sequences ``[1, 'a']``),
which the same coercion reads back as the same value, so the entity equals the one of the
equivalent XML file; its attribute name goes into ``Entity.typed``, so the interpreter can
still tell ``value: 10`` from ``value: "10"`` where ROS 2 does (launch_yaml refuses a typed
value where it wants a string, and never coerces a string).

The one place XML coerces what YAML and Python keep as a string is a parameter's value: a
literal string there (``value: "10"``, ``{'txt': '10'}``) stays a string, which XML writes
``<param value="10" type="str"/>``; both frontends add that ``type`` where YAML rules would
read the text as another value (:func:`reads_as_other_value`).
"""

from __future__ import annotations

import yaml

Scalar = bool | int | float | str | None
TypedValue = bool | int | float | None | list[Scalar]
"""What a typed attribute may hold: YAML scalars other than strings, and lists of scalars."""

_Dumper: type[yaml.SafeDumper] = getattr(yaml, "CSafeDumper", yaml.SafeDumper)


def typed_text(value: TypedValue | str) -> str:
    """The canonical YAML text of ``value`` (a list may hold strings, quoted when needed)."""
    text = yaml.dump(
        value, Dumper=_Dumper, default_flow_style=True, width=1 << 30, allow_unicode=True
    )
    return text.removesuffix("\n...\n").rstrip("\n")


def reads_as_other_value(literal: str, substitutions: bool = True) -> bool:
    """Whether ROS 2's YAML coercion would turn the literal string ``literal`` into another
    value (``"10"``, ``"true"``, ``" x"``, a text over lines); the empty string is kept as it
    is. ``substitutions``: whether ``$(`` starts a substitution there (a YAML file's string)
    or is text like any other (a Python string: a robot description's comment)."""
    if literal == "" or (substitutions and "$(" in literal):
        return False
    return typed_text(literal) != literal
