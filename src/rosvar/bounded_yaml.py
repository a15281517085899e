"""Limits on untrusted YAML, checked on its event stream before anything is built from it.

PyYAML's safe loaders refuse arbitrary objects but not self-reference (``&a [*a]`` builds a
list that contains itself, which every later walk recurses into forever), nor alias bombs
(a few lines whose aliases expand to billions of nodes once parameters are unrolled), nor
nesting deep enough to exhaust the recursive constructor. The event stream is flat, so
scanning it is safe at any depth; what is refused here never reaches a constructor.
"""

from __future__ import annotations

import yaml

MAX_DEPTH = 100
"""Collections nested deeper than this are refused (PyYAML constructs recursively)."""
MAX_NODES = 100_000
"""Nodes of a document with every alias expanded, as the parameters it sets would be."""

_Parser: type[yaml.SafeLoader] = getattr(yaml, "CSafeLoader", yaml.SafeLoader)


class YamlLimitError(yaml.YAMLError):
    """The YAML text is well-formed so far but goes beyond a limit (or refers to itself)."""


def safe_load(text: str) -> object:
    """``yaml.safe_load(text)`` within the limits of :func:`check_limits`: every YAML text
    rosvar reads into values (parameter files, ``-p`` values) goes through here."""
    check_limits(text)
    return yaml.load(text, Loader=_Parser)


def check_limits(text: str) -> None:
    """Raise :class:`YamlLimitError` (or the parser's ``YAMLError``) if ``text`` nests
    deeper than :data:`MAX_DEPTH`, expands to more than :data:`MAX_NODES` nodes, or has an
    alias inside the node its anchor names (a cycle)."""
    anchors: list[str | None] = []  # anchor of each open collection, outermost first
    counts: list[int] = []  # expanded size of each open collection so far
    sizes: dict[str, int] = {}  # expanded size of each anchored node, once closed
    total = 0
    parser = _Parser(text)
    try:
        while parser.check_event():
            event = parser.get_event()  # type: ignore[no-untyped-call]
            if isinstance(event, yaml.CollectionStartEvent):
                if len(anchors) >= MAX_DEPTH:
                    raise YamlLimitError(f"YAML nested more than {MAX_DEPTH} levels deep")
                anchors.append(event.anchor)
                counts.append(1)
                continue
            if isinstance(event, yaml.CollectionEndEvent):
                anchor, size = anchors.pop(), counts.pop()
                if anchor is not None:
                    sizes[anchor] = size
            elif isinstance(event, yaml.AliasEvent):
                if event.anchor in anchors:
                    raise YamlLimitError(
                        f"YAML alias *{event.anchor} refers to a node that contains it"
                    )
                size = sizes.get(str(event.anchor), 1)  # an unknown anchor: the loader says so
            elif isinstance(event, yaml.ScalarEvent):
                size = 1
                if event.anchor is not None:
                    sizes[event.anchor] = 1
            else:
                continue
            if counts:
                counts[-1] += size
                expanded = counts[-1]
            else:
                total += size
                expanded = total
            if expanded > MAX_NODES:
                raise YamlLimitError(
                    f"YAML expands to more than {MAX_NODES} nodes once aliases are resolved"
                )
    except yaml.MarkedYAMLError as error:
        # libyaml's scanner counts flow levels ahead of the events (1,000 at most): the same
        # limit, told as this module tells it (one line, not the scanner's three)
        if "maximum nesting depth" in str(error.problem):
            raise YamlLimitError(f"YAML nested more than {MAX_DEPTH} levels deep") from None
        raise
    finally:
        parser.dispose()
