"""What a list of user literals shows: the graph's entries and the clashes, step after step.

A view is derived from the view of the longest earlier list it extends (a prefix: more
literals only remove configurations). Presences and clashes are judged again only where
the new literals reach (see ``presence`` and ``conflicts``), and an element is rendered
again only when its verdict or the strings its fields read changed: every other entry
stays the same object, so a client can tell what changed by identity.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field
from itertools import accumulate, chain

from rosvar.configuration.catalog import Catalog, FileEntry
from rosvar.configuration.conflicts import Conflicts, ConflictState
from rosvar.configuration.derivation import Decisions, Derivation, Presence
from rosvar.configuration.graph import Element, ElementKind, Fields, Shown, Values, VariationalGraph
from rosvar.configuration.lowering import Lowering
from rosvar.configuration.prefix_cache import PrefixCache
from rosvar.configuration.presence import Judged, Judgement, Presences, Typed
from rosvar.interpreter.workspace_models import Analysis
from rosvar.logic.bdd import BDD
from rosvar.logic.inputs import OTHER, UNSET, Input
from rosvar.memo import Memo

Key = tuple[tuple[str, bool, str | None], ...]
"""A list of literals: variable, value and the ``<other>`` text it gives, if any."""
Strings = frozenset[tuple[Input, str | None]]
"""The strings of the inputs an element's terms read (None: not known yet)."""
_Entry = tuple[str, str, str | None, Strings | None, tuple[Shown, ...], tuple[str, ...]]
"""An element shown: its id, presence, condition, the strings it was rendered with, its
parts as shown and (a topic) the node variants using it that are not absent."""

VIEW_SHARE = 4
"""A view holds the entries rendered anew at its step: thousands when a typed value changes
the strings of a file's params (MBs on Husky). So a quarter as many views are kept as the
engine's other answers per list of choices, at least ``MIN_VIEWS``; a view forgotten is
derived again from the longest earlier one kept."""
MIN_VIEWS = 16
RENDERINGS = 2
"""Renderings of entries remembered per element of the graph (at least ``MIN_RENDERINGS``):
a step meets again those of the states around it, and no more are worth their memory."""
MIN_RENDERINGS = 1_000


@dataclass
class Graph:
    """Element variants with their presence; ``errors`` are where roslaunch would stop."""

    nodes: list[Fields] = field(default_factory=list)
    tests: list[Fields] = field(default_factory=list)
    params: list[Fields] = field(default_factory=list)
    topics: list[Fields] = field(default_factory=list)
    errors: list[Fields] = field(default_factory=list)

    def to_json(self) -> dict[str, object]:
        return {
            "nodes": self.nodes,
            "tests": self.tests,
            "params": self.params,
            "topics": self.topics,
            "errors": self.errors,
        }


@dataclass(frozen=True)
class View:
    """What one list of literals shows, kept to derive longer lists' views."""

    decisions: Decisions
    texts: Mapping[str, str]  # arg id → its <other> text
    typed: Typed
    presences: Judgement
    entries: list[list[Fields]]  # per element of the graph
    starts: list[int]  # per element: where its entries start in its kind's list
    conflicts: list[ConflictState | None]  # per pair of ``Conflicts``; None: gone
    graph: Graph


class Views:
    """Every list of literals' view, each derived from the longest earlier list's."""

    def __init__(
        self,
        analysis: Analysis,
        catalog: Catalog,
        graph: VariationalGraph,
        lowering: Lowering,
        derivation: Derivation,
        conflicts: Conflicts,
        cached: int,
    ) -> None:
        """``cached``: how many answers per list of choices the engine keeps
        (``engine.CACHED_FEATURES``); views keep a share of it."""
        self.analysis = analysis
        self.catalog = catalog
        self.graph = graph
        self.lowering = lowering
        self.conflicts = conflicts
        self._described: Memo[tuple[BDD, frozenset[tuple[str, bool]]], str] = Memo()
        self._simplified: Memo[BDD, str] = Memo()  # a condition cofactored → its description
        self.presences = Presences(graph.elements, derivation, lowering)
        self._elements_of: list[list[int]] = [[] for _ in self.presences.conditions]
        for index, condition in enumerate(self.presences.of_element):
            self._elements_of[condition].append(index)
        for index, parts in enumerate(self.presences.of_parts):
            for condition in set(parts):
                self._elements_of[condition].append(index)
        self._paths = {entry.path: entry for entry in catalog.files}
        self._files = {entry.id: entry for entry in catalog.files}
        self._reading: dict[str, list[int]] = {}  # value variable or arg id → elements
        self._of_kind: dict[ElementKind, list[int]] = {}
        for index, element in enumerate(graph.elements):
            self._of_kind.setdefault(element.kind, []).append(index)
            if not element.inputs:
                continue
            entry = self._paths[element.entry]
            for arg in entry.feature.args:
                if arg.input in element.inputs:
                    arg_id = f"{entry.id}:{arg.name}"
                    for feature, _value in catalog.values_of(arg_id):
                        self._reading.setdefault(feature.variable, []).append(index)
                    self._reading.setdefault(arg_id, []).append(index)
        index_of = {element.id: index for index, element in enumerate(graph.elements)}
        self._users: dict[int, list[int]] = {}  # topic → its nodes, node → its topics
        for index, element in enumerate(graph.elements):
            for node in element.nodes:
                self._users.setdefault(index, []).append(index_of[node])
                self._users.setdefault(index_of[node], []).append(index)
        renderings = max(MIN_RENDERINGS, RENDERINGS * len(graph.elements))
        self._rendered: Memo[tuple[str, Strings | None, tuple[Shown, ...]], list[Fields]] = Memo(
            renderings
        )
        self._entries: Memo[_Entry, list[Fields]] = Memo(renderings)
        self.initial = self._derive(derivation.initial, {}, None)
        self._views: PrefixCache[tuple[str, bool, str | None], View] = PrefixCache(
            self.initial, max(MIN_VIEWS, cached // VIEW_SHARE)
        )

    def view(self, key: Key, decisions: Decisions, texts: Mapping[str, str]) -> View:
        """The view of the literals ``key`` (whose solver answer is ``decisions``)."""
        length, before = self._views.longest(key)
        if length == len(key):
            return before
        view = self._derive(decisions, texts, before)
        self._views.put(key, view)
        return view

    def describe(self, condition: BDD, values: Mapping[str, bool]) -> str:
        """``condition`` simplified under ``values`` (decided variables), for people."""
        key = (condition, frozenset(values.items()))
        text = self._described.get(key)
        if text is None:
            space = self.analysis.space
            restricted = space.cofactor(condition, values)
            text = self._simplified.get(restricted)  # other values often leave the same
            if text is None:
                text = self._simplified[restricted] = space.describe(restricted)
            self._described[key] = text
        return text

    def arg_text(
        self, entry: FileEntry, name: str, decisions: Decisions, texts: Mapping[str, str]
    ) -> str | None:
        """The string an arg is given (or defaults to), once its value is decided."""
        arg_id = f"{entry.id}:{name}"
        value = self.catalog.chosen(arg_id, decisions.decided)
        if value is None:
            return None
        if value.slot is OTHER:
            return texts.get(arg_id)
        if value.slot is UNSET:
            return self.analysis.model(entry.path).unset_defaults.get(name)
        return str(value.slot)

    def _derive(self, decisions: Decisions, texts: Mapping[str, str], before: View | None) -> View:
        """The view from ``before`` (an earlier list of the same literals, or none)."""
        typed = self._typed(texts)
        if before is None:
            presences = self.presences.judge(decisions, typed, self.describe)
            conflicts = self.conflicts.judge(decisions, typed, self.describe)
            entries: list[list[Fields]] = [[] for _ in self.graph.elements]
            again: Iterable[int] = range(len(self.graph.elements))
        else:
            presences = self.presences.judge(
                decisions, typed, self.describe, (before.decisions, before.typed, before.presences)
            )
            conflicts = self.conflicts.judge(
                decisions, typed, self.describe, (before.decisions, before.typed, before.conflicts)
            )
            entries = list(before.entries)
            again = self._rerendered(decisions, texts, before, presences)
        values: dict[str, Values] = {}
        moved: dict[ElementKind, list[int]] = {}  # per kind: the elements rendered anew
        for index in again:  # in graph order: a topic comes after its nodes
            element = self.graph.elements[index]
            judged = presences.verdicts[self.presences.of_element[index]]
            if element.entry not in values and element.inputs:
                values[element.entry] = self._values(element.entry, decisions, texts)
            parts = tuple(presences.verdicts[c].shown for c in self.presences.of_parts[index])
            users = tuple(
                self.graph.elements[n].id
                for n in self._users.get(index, ())
                if entries[n] and entries[n][0]["presence"] != Presence.ABSENT
            )
            found = self._element_entries(
                element, judged, parts, values, users if element.kind == ElementKind.TOPIC else ()
            )
            if found is not entries[index]:
                moved.setdefault(element.kind, []).append(index)
            entries[index] = found
        lists, starts = self._lists(entries, before, moved)
        graph = Graph(**{f"{kind}s": listed for kind, listed in lists.items()})
        return View(decisions, texts, typed, presences, entries, starts, conflicts, graph)

    def _lists(
        self,
        entries: list[list[Fields]],
        before: View | None,
        moved: Mapping[ElementKind, list[int]],
    ) -> tuple[dict[str, list[Fields]], list[int]]:
        """Each kind's list of entries, and where each element's start in it. A kind whose
        elements rendered anew kept their number of entries is the earlier list with those
        replaced in place (a step changes a few of a large workspace's many entries); one
        without any is the earlier list itself."""
        lists: dict[str, list[Fields]] = {}
        starts = [0] * len(entries) if before is None else before.starts
        for kind, indices in self._of_kind.items():
            if before is not None:
                earlier = getattr(before.graph, f"{kind}s")
                changed = moved.get(kind, ())
                if all(len(entries[i]) == len(before.entries[i]) for i in changed):
                    listed = list(earlier) if changed else earlier
                    for index in changed:
                        start = starts[index]
                        listed[start : start + len(entries[index])] = entries[index]
                    lists[kind] = listed
                    continue
                if starts is before.starts:
                    starts = list(starts)
            lengths = [len(entries[i]) for i in indices]
            for index, start in zip(indices, accumulate(lengths, initial=0), strict=False):
                starts[index] = start
            lists[kind] = list(chain.from_iterable(map(entries.__getitem__, indices)))
        return lists, starts

    def _rerendered(
        self,
        decisions: Decisions,
        texts: Mapping[str, str],
        before: View,
        presences: Judgement,
    ) -> list[int]:
        """Elements whose verdict or read strings differ from ``before`` (and the topics of
        nodes among them, whose lists of nodes may change), in graph order."""
        again: set[int] = set()
        for condition in presences.judged:
            judged, earlier = presences.verdicts[condition], before.presences.verdicts[condition]
            if judged is not earlier and judged.shown != earlier.shown:
                again.update(self._elements_of[condition])
        changed = decisions.decided.items() ^ before.decisions.decided.items()
        for variable, _value in changed:
            again.update(self._reading.get(variable, ()))
        for arg in texts.keys() | before.texts.keys():
            if texts.get(arg) != before.texts.get(arg):
                again.update(self._reading.get(arg, ()))
        for index in list(again):
            if self.graph.elements[index].kind != ElementKind.TOPIC:
                again.update(self._users.get(index, ()))
        return sorted(again)

    def _typed(self, texts: Mapping[str, str]) -> Typed:
        """Entry file → the ``<other>`` texts typed for its args."""
        typed: dict[str, dict[Input, str]] = {}
        for arg_id, text in texts.items():
            path = self._files[self.catalog.features[arg_id].file].path
            typed.setdefault(path, {})[self.catalog.args[arg_id][0].input] = text
        return typed

    def _values(self, path: str, decisions: Decisions, texts: Mapping[str, str]) -> Values:
        """Concrete strings of a file's inputs as far as the choices fix them."""
        entry = self._paths[path]
        concrete: dict[Input, str] = dict(self.lowering.concrete)
        for arg in entry.feature.args:
            text = self.arg_text(entry, arg.name, decisions, texts)
            if text is not None:
                concrete[arg.input] = text
        return Values(concrete, self.lowering.host)

    def _element_entries(
        self,
        element: Element,
        judged: Judged,
        parts: tuple[Shown, ...],
        values: Mapping[str, Values],
        users: tuple[str, ...],
    ) -> list[Fields]:
        """The element's graph entries: none for an absent error, else one per variant
        (a topic's with ``users``, its node variants not absent).

        Made once per verdict and strings its terms read: the same entries serve every
        state that shows them (a session's later clicks, and other sessions, meet them
        again)."""
        presence, condition = judged.shown
        if presence == Presence.ABSENT and element.kind == ElementKind.ERROR:
            return []
        given = values[element.entry] if presence != Presence.ABSENT and element.inputs else None
        strings = frozenset((i, given.concrete.get(i)) for i in element.inputs) if given else None
        key = (element.id, presence, condition, strings, parts, users)
        entries = self._entries.get(key)
        if entries is None:
            shown = self._fields(element, given, strings, parts)
            extra: Fields = {"nodes": list(users)} if element.kind == ElementKind.TOPIC else {}
            entries = self._entries[key] = [
                {
                    **fields,
                    **extra,
                    "presence": presence,
                    "condition": condition,
                    "id": element.id if number == 0 else f"{element.id}/{number}",
                }
                for number, fields in enumerate(shown)
            ]
        return entries

    def _fields(
        self,
        element: Element,
        given: Values | None,
        strings: Strings | None,
        parts: tuple[Shown, ...],
    ) -> list[Fields]:
        """The element's fields: with the strings ``given`` for its inputs, or symbolic
        (``given`` None), and its parts as they are shown. Rendered once per combination
        of the strings its terms read and its parts' presences."""
        key = (element.id, strings, parts)
        found = self._rendered.get(key)
        if found is None:
            values = given or Values(self.lowering.concrete, self.lowering.host)
            found = element.fields(values, parts)
            self._rendered[key] = found
        return found
