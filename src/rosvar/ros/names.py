"""ROS graph resource names, with exactly rosgraph's rules.

roslaunch builds every node, param and remap name with these few operations;
any deviation (a lost trailing slash, a different join) would change which
names clash, so they are reimplemented here to the letter and tested against
``rosgraph.names``.
"""

from __future__ import annotations

import re

SEP = "/"
PRIVATE = "~"
_LEGAL = re.compile(r"[~/A-Za-z][\w/]*")
_MAPPED = re.compile(r"([~/A-Za-z]|_|__)[\w/]*")
"""The source of a command line's ``name:=value`` word (:func:`command_line_mappings`)."""


def is_global(name: str) -> bool:
    return name[:1] == SEP


def is_private(name: str) -> bool:
    return name[:1] == PRIVATE


def ns_join(ns: str, name: str) -> str:
    """``name`` inside namespace ``ns``; global and private names are not joined."""
    if is_private(name) or is_global(name):
        return name
    if ns == PRIVATE:
        return PRIVATE + name
    if not ns:
        return name
    if ns[-1] == SEP:
        return ns + name
    return ns + SEP + name


def make_global_ns(name: str) -> str:
    """``foo`` → ``/foo/``; a private name cannot be a namespace."""
    if is_private(name):
        raise ValueError(f"cannot turn [{name}] into a global name")
    if not is_global(name):
        name = SEP + name
    if name[-1] != SEP:
        name += SEP
    return name


def canonicalize_name(name: str) -> str:
    """Drop repeated and trailing slashes."""
    if not name or name == SEP:
        return name
    parts = [p for p in name.split(SEP) if p]
    return (SEP if name[0] == SEP else "") + SEP.join(parts)


def is_legal_name(name: str) -> bool:
    if name == "":
        return True
    return _LEGAL.fullmatch(name) is not None and "//" not in name


def namespaces_of(name: str) -> list[str]:
    """Every enclosing namespace of a global name, outermost first (``/a/b`` → ``/``, ``/a/``)."""
    if not name or name == SEP:
        return []
    parts = name.strip(SEP).split(SEP)[:-1]
    result = [SEP]
    current = SEP
    for part in parts:
        current = current + part + SEP
        result.append(current)
    return result


def child_namespace(ns: str, child: str | None) -> str:
    """The namespace of a child context (``<group ns>``, ``<node ns>``, ``<include ns>``)."""
    if not child:
        return ns
    if child[0] == SEP:
        return make_global_ns(child)
    return make_global_ns(ns_join(ns, child))


def settable(name: str) -> bool:
    """Whether ``name:=value`` on roslaunch's command line reaches the arg ``name``.

    roslaunch reads its command line as ROS remappings: ``3d_sensor:=x`` (a digit
    first) or ``_private:=x`` never reach an arg.
    """
    # command_line_mappings([f"{name}:=x"]) holds ``name`` exactly when this holds: the
    # word's pattern stops at its first ':', and a name it matches has no space to strip
    return _MAPPED.fullmatch(name) is not None and not (
        len(name) > 1 and name[0] == "_" and name[1] != "_"
    )


def command_line_mappings(argv: list[str]) -> dict[str, str]:
    """``name:=value`` words as roslaunch reads them (``_private`` words are params, dropped)."""
    mappings: dict[str, str] = {}
    for word in argv:
        if ":=" not in word or not re.fullmatch(r"([~/A-Za-z]|_|__)[\w/]*:=.*", word):
            continue
        parts = [p.strip() for p in word.split(":=")]
        if len(parts) != 2:
            continue
        src, dst = parts
        if src and dst and not (len(src) > 1 and src[0] == "_" and src[1] != "_"):
            mappings[src] = dst
    return mappings
