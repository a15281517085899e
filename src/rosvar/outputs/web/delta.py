"""Answers as deltas: what changed between two state documents, and how to apply it.

A click on a large workspace changes a few features and graph elements out of thousands
(Husky: 1,220 features, 8,700 graph entries, 5 MB of JSON), so the server answers a tab that
already holds a state with only the difference. The engine keeps an unchanged graph entry as
the same object from one state to the next, so most entries compare by identity and the
rest by equality; nothing is serialised to compare it.

A delta is a document of the same shape, read field by field:

* ``features``: only the features whose entry changed (the set of ids never changes);
* ``graph``: per list that changed, ``{"removed": [ids], "put": [[index, entry], ...]}``:
  entries gone, then entries added or changed with their place in the new list (entries
  keep their relative order from one state to the next, so the places are few and exact).
  An entry whose ``presence`` or ``condition`` alone changed (most changes) is sent as its
  id and these two fields, merged into the entry at that place;
* any other field: present only when its value changed, and then whole;
* ``base``: the version of the document the delta applies to (set by the sender).

:func:`patch` is the reference for the page's own ``static/js/delta.js``.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any

Document = dict[str, Any]
Entry = Mapping[str, Any]

KEYED = "features"  # a mapping id → entry
LISTS = "graph"  # a mapping kind → list of entries with an "id"
BASE = "base"
PRESENCE, CONDITION = "presence", "condition"  # the fields of graph entries most choices change


def diff(before: Document, after: Document) -> Document:
    """The fields of ``after`` that differ from ``before`` (see the module's description)."""
    delta: Document = {}
    for key, value in after.items():
        if key == KEYED:
            old = before[key]
            delta[key] = {k: v for k, v in value.items() if not _same(old.get(k), v)}
        elif key == LISTS:
            delta[key] = {}
            for kind, entries in value.items():
                change = _list_diff(before[key].get(kind, []), entries)
                if change["removed"] or change["put"]:
                    delta[key][kind] = change
        elif key not in before or not _same(before[key], value):
            delta[key] = value
    return delta


def patch(document: Document, delta: Document) -> Document:
    """``document`` updated by ``delta`` (a whole document, without ``base``, comes back as is).

    Raises ValueError when the delta was made against another version than ``document``'s.
    """
    if BASE not in delta:
        return delta
    if delta[BASE] != document.get("version"):
        raise ValueError(f"delta against version {delta[BASE]}, not {document.get('version')}")
    result = dict(document)
    for key, value in delta.items():
        if key == KEYED:
            result[key] = {**document[key], **value}
        elif key == LISTS:
            result[key] = dict(document[key])
            for kind, change in value.items():
                result[key][kind] = _list_patch(document[key].get(kind, []), change)
        elif key != BASE:
            result[key] = value
    return result


def _same(old: object, new: object) -> bool:
    return old is new or old == new


def _list_diff(before: Sequence[Entry], after: Sequence[Entry]) -> Document:
    """One walk over both lists: most entries are the same object at the same place."""
    put: list[tuple[int, Entry]] = []
    removed: list[str] = []
    places: dict[str, int] | None = None  # id → place in ``before``, built on first need
    following = 0  # place in ``before`` of the next entry not yet matched
    for index, entry in enumerate(after):
        if following < len(before) and before[following] is entry:
            following += 1
            continue
        key = entry["id"]
        if following < len(before) and before[following]["id"] == key:
            place = following
        else:
            if places is None:
                places = {old["id"]: number for number, old in enumerate(before)}
            found = places.get(key)
            if found is None:  # a new entry
                put.append((index, entry))
                continue
            place = found
            if place < following:  # entries swapped places: send the list whole
                return {"removed": list(places), "put": list(enumerate(after))}
            removed.extend(old["id"] for old in before[following:place])
        old = before[place]
        if old != entry:
            if old.keys() <= entry.keys():
                put.append((index, _update(old, entry)))
            else:  # a field went away, which a merge cannot say: the entry is sent anew
                removed.append(key)
                put.append((index, entry))
        following = place + 1
    removed.extend(old["id"] for old in before[following:])
    return {"removed": removed, "put": put}


def _update(old: Entry, new: Entry) -> Entry:
    """What to send of a changed entry: its id and verdict when nothing else changed (a copy
    and a C-level comparison: thousands of entries change on some clicks), else all of it."""
    probe = dict(new)
    probe[PRESENCE] = old.get(PRESENCE)
    probe[CONDITION] = old.get(CONDITION)
    if probe == old:
        return {"id": new["id"], PRESENCE: new[PRESENCE], CONDITION: new[CONDITION]}
    return new


def _list_patch(before: Sequence[Entry], change: Mapping[str, Any]) -> list[Entry]:
    gone = set(change["removed"])
    entries = [entry for entry in before if entry["id"] not in gone]
    # in order of place: the entries before ``index`` are already the new list's
    for index, entry in change["put"]:
        if index < len(entries) and entries[index]["id"] == entry["id"]:
            entries[index] = {**entries[index], **entry}
        else:
            entries.insert(index, entry)
    return entries
