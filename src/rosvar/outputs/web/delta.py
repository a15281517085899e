"""Answers as deltas: what changed between two state documents, and how to apply it.

A click on a large workspace changes a few features and graph elements out of thousands
(megabytes of JSON in all), so the server answers a tab that
already holds a state with only the difference. The engine keeps an unchanged graph entry as
the same object from one state to the next, so most entries compare by identity and the
rest by equality; nothing is serialised to compare it.

A delta is a document of the same shape, read field by field:

* ``features``: only the features whose entry changed (the set of ids never changes); in
  overview mode a string (one character per feature), sent whole when it changed;
* ``graph``: per list that changed, ``{"removed": [ids], "added": [[index, entry], ...],
  "changed": [[index, fields], ...]}``: entries gone; entries new, inserted at their place
  in the new list in order (entries keep their relative order from one state to the next,
  so this rebuilds the new list's order exactly); then fields merged into the entry at a
  place. Most changes are of ``presence`` and ``condition`` alone, and only these two
  fields are sent then (the ids, long paths, would be most of the answer);
* ``conflicts`` (entries without ids): ``{"removed": [places], "added": [[index, entry],
  ...]}``: the entries at those places of the old list dropped, then the new entries inserted
  at their place in the new list, in order. A choice judges a few of the hundreds of clashes
  again (Husky + ``_external``: 28 of 631 conflicts, 10 of 412 KB);
* any other field: present only when its value changed, and then whole;
* ``base``: the version of the document the delta applies to (set by the sender).

:func:`patch` is the reference for the page's own ``static/js/delta.js``.
"""

from __future__ import annotations

from collections import deque
from collections.abc import Mapping, Sequence
from itertools import compress
from operator import is_not
from typing import Any

Document = dict[str, Any]
Entry = Mapping[str, Any]

KEYED = "features"  # a mapping id → entry
LISTS = "graph"  # a mapping kind → list of entries with an "id"
SEQUENCES = frozenset({"conflicts"})  # lists of entries without an id, matched by value
BASE = "base"
PRESENCE, CONDITION = "presence", "condition"  # the fields of graph entries most choices change


def diff(before: Document, after: Document) -> Document:
    """The fields of ``after`` that differ from ``before`` (see the module's description)."""
    delta: Document = {}
    for key, value in after.items():
        if key == KEYED and isinstance(value, Mapping):
            old = before[key]
            delta[key] = {k: v for k, v in value.items() if not _same(old.get(k), v)}
        elif key == LISTS:
            delta[key] = {}
            for kind, entries in value.items():
                change = _list_diff(before[key].get(kind, []), entries)
                if any(change.values()):
                    delta[key][kind] = change
        elif key not in before or not _same(before[key], value):
            sequence = key in SEQUENCES and isinstance(value, list)
            delta[key] = _sequence_diff(before[key], value) if sequence else value
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
        if key == KEYED and isinstance(value, Mapping):
            result[key] = {**document[key], **value}
        elif key == LISTS:
            result[key] = dict(document[key])
            for kind, change in value.items():
                result[key][kind] = _list_patch(document[key].get(kind, []), change)
        elif key in SEQUENCES and isinstance(value, Mapping):
            result[key] = _sequence_patch(document[key], value)
        elif key != BASE:
            result[key] = value
    return result


def _same(old: object, new: object) -> bool:
    return old is new or old == new


def _list_diff(before: Sequence[Entry], after: Sequence[Entry]) -> Document:
    """One walk over both lists: most entries are the same object at the same place."""
    removed: list[str] = []
    added: list[tuple[int, Entry]] = []
    changed: list[tuple[int, Entry]] = []
    if len(before) == len(after):  # the usual step: entries replaced in place, found in C
        differ = list(compress(range(len(after)), map(is_not, before, after)))
        if all(before[i]["id"] == after[i]["id"] for i in differ):
            for index in differ:
                _compare(index, before[index], after[index], removed, added, changed)
            return {"removed": removed, "added": added, "changed": changed}
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
            if found is None:
                added.append((index, entry))
                continue
            place = found
            if place < following:  # entries swapped places: send the list whole
                return {"removed": list(places), "added": list(enumerate(after)), "changed": []}
            removed.extend(old["id"] for old in before[following:place])
        _compare(index, before[place], entry, removed, added, changed)
        following = place + 1
    removed.extend(old["id"] for old in before[following:])
    return {"removed": removed, "added": added, "changed": changed}


def _compare(
    index: int,
    old: Entry,
    new: Entry,
    removed: list[str],
    added: list[tuple[int, Entry]],
    changed: list[tuple[int, Entry]],
) -> None:
    """An entry that kept its id, now at ``index``: what of it to send, if anything."""
    if old != new:
        if old.keys() <= new.keys():
            changed.append((index, _changes(old, new)))
        else:  # a field went away, which a merge cannot say: the entry is sent anew
            removed.append(new["id"])
            added.append((index, new))


def _changes(old: Entry, new: Entry) -> Entry:
    """What to send of a changed entry: its verdict when nothing else changed (a copy and a
    C-level comparison: thousands of entries change on some clicks), else all of it."""
    probe = dict(new)
    probe[PRESENCE] = old.get(PRESENCE)
    probe[CONDITION] = old.get(CONDITION)
    if probe == old:
        return {PRESENCE: new[PRESENCE], CONDITION: new[CONDITION]}
    return new


def _list_patch(before: Sequence[Entry], change: Mapping[str, Any]) -> list[Entry]:
    gone = set(change["removed"])
    entries = [entry for entry in before if entry["id"] not in gone]
    for index, entry in change["added"]:  # in order of place: those before are in place
        entries.insert(index, entry)
    for index, fields in change["changed"]:
        entries[index] = {**entries[index], **fields}
    return entries


def _sequence_diff(before: Sequence[Entry], after: Sequence[Entry]) -> Document:
    """The places of ``before`` dropped and the entries of ``after`` inserted that make
    ``after``: its entries found in ``before``, by value, in order."""
    places: dict[object, deque[int]] = {}
    for place, entry in enumerate(before):
        places.setdefault(_frozen(entry), deque()).append(place)
    removed: list[int] = []
    added: list[tuple[int, Entry]] = []
    following = 0  # place in ``before`` of the next entry not yet matched
    for index, entry in enumerate(after):
        found = places.get(_frozen(entry))
        while found and found[0] < following:
            found.popleft()
        if not found:
            added.append((index, entry))
            continue
        place = found.popleft()
        removed.extend(range(following, place))
        following = place + 1
    removed.extend(range(following, len(before)))
    return {"removed": removed, "added": added}


def _sequence_patch(before: Sequence[Entry], change: Mapping[str, Any]) -> list[Entry]:
    gone = set(change["removed"])
    entries = [entry for place, entry in enumerate(before) if place not in gone]
    for index, entry in change["added"]:  # in order of place: those before are in place
        entries.insert(index, entry)
    return entries


def _frozen(value: object) -> object:
    """``value`` (JSON: lists, mappings, scalars) as a hashable key."""
    if isinstance(value, list | tuple):
        return tuple(_frozen(item) for item in value)
    if isinstance(value, Mapping):
        return tuple((key, _frozen(item)) for key, item in value.items())
    return value
