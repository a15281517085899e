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
from rosvar.configuration.derivation import Decisions, Derivation
from rosvar.configuration.graph import (
    NAMED,
    Element,
    ElementKind,
    Failure,
    Fields,
    Render,
    Shown,
    Values,
    VariationalGraph,
    failures,
)
from rosvar.configuration.judgement import Judged, Judgement, Presences, Typed
from rosvar.configuration.lowering import Lowering
from rosvar.configuration.prefix_cache import PrefixCache
from rosvar.configuration.presence import Presence
from rosvar.interpreter.workspace_models import Analysis
from rosvar.logic.bdd import BDD, Cubes
from rosvar.logic.conditions import ConditionSpace
from rosvar.logic.inputs import OTHER, UNSET, Input
from rosvar.memo import Memo

Key = tuple[tuple[str, bool, str | None], ...]
"""A list of literals: variable, value and the ``<other>`` text it gives, if any."""
Strings = frozenset[tuple[Input, str | None]]
"""The strings of the inputs an element's terms read (None: not known yet)."""
_Entry = tuple[str, str, str | None, Strings | None, tuple[Shown, ...], tuple[str, ...]]
"""An element shown: its id, presence, condition, the strings it was rendered with, its
parts as shown and (a topic) the node variants using it that are not absent."""

_USED = frozenset(NAMED.values())
"""Kinds of elements that list the node variants using them."""

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
    services: list[Fields] = field(default_factory=list)
    actions: list[Fields] = field(default_factory=list)
    errors: list[Fields] = field(default_factory=list)


Failures = Mapping[int, tuple[Failure, ...]]
"""Element index → where the strings typed for its file's args make roslaunch stop in it."""


@dataclass(frozen=True)
class Rendering:
    """The graph entries a view's presences show, kept to render longer lists'."""

    entries: list[list[Fields]]  # per element of the graph
    starts: list[int]  # per element: where its entries start in its kind's list
    lists: dict[str, list[Fields]]  # per kind: its elements' entries
    graph: Graph  # the lists, and the failures of typed texts among the errors


class View:
    """What one list of literals shows, kept to derive longer lists' views.

    The conflicts are judged with the view; the presences of the graph's elements when
    first asked for (``Views.judgement``), and their entries, which describe the conditions
    of undetermined ones, when the graph is (``Views.rendering``): a server is ready
    without judging every element of a large workspace up front, and ``configure``
    prints its summary without describing them. The web page's overview reads the entries
    without their conditions (``Views.outline``) and has the few it lists described
    (``Views.described``): describing is most of rendering a large workspace's entries."""

    def __init__(
        self,
        decisions: Decisions,
        texts: Mapping[str, str],
        typed: Typed,
        conflicts: list[ConflictState | None],
        failures: Failures,
        before: View | None,
    ) -> None:
        self.decisions = decisions
        self.texts = texts  # arg id → its <other> text
        self.typed = typed
        self.failures = failures
        self.conflicts = conflicts  # per pair of ``Conflicts``; None: gone
        self.before = before  # until rendered: the view it is judged and rendered from
        self.presences: Judgement | None = None  # set by ``Views.judgement``
        self.rendering: Rendering | None = None  # set by ``Views.rendering``
        self.outline: Rendering | None = None  # set by ``Views.outline``


@dataclass(frozen=True)
class Summary:
    """What a view shows in numbers, made without describing any condition."""

    counts: Mapping[ElementKind, Mapping[Presence, int]]  # entries by kind and presence
    errors: list[Fields]  # the errors present: where roslaunch stops


class Descriptions:
    """Conditions simplified for people, remembered.

    Apart from :class:`Views` because every verdict keeps ``describe`` until it is shown: a
    bound method of the views would make each view a reference cycle, which leaves the
    solver's diagrams to the cycle collector, and that may free CUDD's manager before them."""

    def __init__(self, space: ConditionSpace) -> None:
        self.space = space
        self._described: Memo[tuple[BDD, frozenset[tuple[str, bool]]], str] = Memo()
        self._simplified: Memo[BDD, str] = Memo()  # a condition cofactored → its description
        self._cubes = Cubes(space.bdd)  # of the decided literals conditions are simplified by

    def describe(self, condition: BDD, values: Mapping[str, bool]) -> str:
        """``condition`` simplified under ``values`` (decided variables)."""
        literals = frozenset(values.items())
        key = (condition, literals)
        text = self._described.get(key)
        if text is None:
            restricted = self._cubes.cofactor(condition, literals)
            text = self._simplified.get(restricted)  # other values often leave the same
            if text is None:
                text = self._simplified[restricted] = self.space.describe(restricted)
            self._described[key] = text
        return text


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
        render: Render,
    ) -> None:
        """``cached``: how many answers per list of choices the engine keeps
        (``engine.CACHED_FEATURES``); views keep a share of it. ``render``: the elements'
        entries, as the presentation shows them."""
        self.analysis = analysis
        self.render = render
        self.catalog = catalog
        self.graph = graph
        self.lowering = lowering
        self.conflicts = conflicts
        self.describe = Descriptions(analysis.space).describe
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
        self._index_of = index_of = {
            element.id: index for index, element in enumerate(graph.elements)
        }
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
        self._failure_entries: Memo[tuple[str, int, Failure, Shown], Fields] = Memo(renderings)
        self._symbolic = Values(lowering.concrete, lowering.host)  # no arg's string known
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
        """The view from ``before`` (an earlier list of the same literals, or none): its
        conflicts judged, its graph left to ``judgement`` and ``rendering``."""
        typed = self._typed(texts)
        if before is None:
            conflicts = self.conflicts.judge(decisions, typed, self.describe)
        else:
            conflicts = self.conflicts.judge(
                decisions, typed, self.describe, (before.decisions, before.typed, before.conflicts)
            )
        failures = self.failures(decisions, texts, before)
        return View(decisions, texts, typed, conflicts, failures, before)

    def failures(
        self, decisions: Decisions, texts: Mapping[str, str], before: View | None = None
    ) -> Failures:
        """The elements whose strings make roslaunch stop: only a text typed for an
        ``<other>`` value can (the model's own values were checked as it was interpreted,
        each failure an error of the model under its condition). From ``before``, only the
        elements reading an arg whose text or decided value changed are checked again."""
        if before is None:
            return self._check(decisions, texts, set(texts))
        if not texts and not before.failures:
            return before.failures
        reach = {
            a for a in texts.keys() | before.texts.keys() if texts.get(a) != before.texts.get(a)
        }
        if texts:
            changed = decisions.decided.items() ^ before.decisions.decided.items()
            reach.update(variable for variable, _value in changed)
        return self._check(decisions, texts, reach, before.failures)

    def stops(self, decisions: Decisions, texts: Mapping[str, str], arg: str) -> list[Failure]:
        """The failures the text typed for ``arg`` brings into every product ``decisions``
        leave (each present there)."""
        typed = self._typed(texts)
        return [
            failure
            for index, failed in self._check(decisions, texts, {arg}).items()
            for failure in failed
            if self.presences.presence(self._condition_of(index, failure), decisions, typed)
            == Presence.PRESENT
        ]

    def _check(
        self,
        decisions: Decisions,
        texts: Mapping[str, str],
        reach: Iterable[str],
        before: Failures | None = None,
    ) -> Failures:
        """``before`` with the elements reading an arg or value variable of ``reach`` checked
        again under ``texts`` (the elements of a file with no text typed fail nowhere)."""
        again = {index for key in reach for index in self._reading.get(key, ())}
        if not again and before is not None:
            return before
        found = dict(before or {})
        typed = self._typed(texts)
        values: dict[str, Values] = {}
        for index in again:
            found.pop(index, None)
            element = self.graph.elements[index]
            mine = typed.get(element.entry)
            if not mine or element.inputs.isdisjoint(mine):
                continue
            given = values.get(element.entry)
            if given is None:
                given = values[element.entry] = self._values(element.entry, decisions, texts)
            failed = failures(element.content, given)
            if failed:
                found[index] = tuple(failed)
        return found

    def failure_entries(self, view: View, presences: Judgement) -> list[Fields]:
        """The errors of ``view``'s failing elements that are not absent, each with the
        presence of its element (or of the part it is in)."""
        shown: list[Fields] = []
        for index, failed in sorted(view.failures.items()):
            element = self.graph.elements[index]
            for number, failure in enumerate(failed):
                condition = self._condition_of(index, failure)
                where = presences.verdicts[condition].shown
                if where[0] == Presence.ABSENT:
                    continue
                key = (element.id, number, failure, where)
                entry = self._failure_entries.get(key)
                if entry is None:
                    [shown_error] = self.render(failure.error, self._symbolic, ())
                    entry = self._failure_entries[key] = {
                        **shown_error,
                        "presence": where[0],
                        "condition": where[1],
                        "id": f"{element.id}!{number}",
                    }
                shown.append(entry)
        return shown

    def judgement(self, view: View) -> Judgement:
        """``view``'s presences, judged on first use with those of the earlier views it is
        derived from that are not yet (oldest first: each from the one before)."""
        pending = []
        later: View | None = view
        while later is not None and later.presences is None:
            pending.append(later)
            later = later.before
        for later in reversed(pending):
            before = later.before
            earlier = None
            if before is not None:
                assert before.presences is not None
                earlier = (before.decisions, before.typed, before.presences)
            later.presences = self.presences.judge(
                later.decisions, later.typed, self.describe, earlier
            )
        assert view.presences is not None
        return view.presences

    def rendering(self, view: View) -> Rendering:
        """``view``'s entries, rendered on first use with those of the earlier views it is
        derived from that are not yet (oldest first: each from the one before, which is
        then let go)."""
        pending = []
        later: View | None = view
        while later is not None and later.rendering is None:
            pending.append(later)
            later = later.before
        for later in reversed(pending):
            later.rendering = self._rendering_of(later, later.before, described=True)
            later.before = None
        assert view.rendering is not None
        return view.rendering

    def outline(self, view: View) -> Rendering:
        """``view``'s entries without their conditions (``condition`` None: not described),
        from the earlier views' entries as ``rendering`` makes them (described or not). The
        views it is derived from are kept (``rendering`` may still be asked for), at most
        ``MIN_VIEWS`` of them."""
        pending = []
        later: View | None = view
        while later is not None and later.outline is None and later.rendering is None:
            pending.append(later)
            later = later.before
        for later in reversed(pending):
            later.outline = self._rendering_of(later, later.before, described=False)
        cut: View | None = view
        for _ in range(MIN_VIEWS):
            cut = None if cut is None else cut.before
        if cut is not None:
            cut.before = None
        found = view.outline or view.rendering
        assert found is not None
        return found

    def described(self, view: View, ids: Iterable[str]) -> dict[str, Fields]:
        """The entries ``ids`` of ``view`` as ``rendering`` makes them (conditions described),
        made for those alone."""
        presences = self.judgement(view)
        outline = self.outline(view)
        values: dict[str, Values] = {}
        found: dict[str, Fields] = {}
        for id_ in ids:
            index, number = self._index_of.get(id_), "0"
            if index is None:  # a variant after the first: ELEMENT/NUMBER
                element_id, _, number = id_.rpartition("/")
                index = self._index_of[element_id]
            entries = self._entries_of(index, presences, outline.entries, values, view, True)
            found[id_] = entries[int(number)]
        return found

    def summary(self, view: View) -> Summary:
        """How many entries of each kind ``view`` shows with each presence (a part's
        presence does not change how many), and its errors present."""
        verdicts = self.judgement(view).verdicts
        counts = {kind: dict.fromkeys(Presence, 0) for kind in ElementKind}
        errors: list[Fields] = []
        values: dict[str, Values] = {}
        for index, element in enumerate(self.graph.elements):
            judged = verdicts[self.presences.of_element[index]]
            presence = judged.verdict.presence
            if presence == Presence.ABSENT and element.kind == ElementKind.ERROR:
                continue
            given = self._given(element, presence, values, view.decisions, view.texts)
            if presence == Presence.PRESENT and element.kind == ElementKind.ERROR:
                shown = self._element_entries(element, judged.shown, (), given, ())
                errors.extend(shown)
            else:
                parts = self.presences.of_parts[index]
                shown = self.render(
                    element.content,
                    given or self._symbolic,
                    [(verdicts[c].verdict.presence, None) for c in parts],
                )
            counts[element.kind][presence] += len(shown)
        for index, failed in view.failures.items():
            for failure in failed:
                condition = self._condition_of(index, failure)
                if verdicts[condition].verdict.presence == Presence.PRESENT:
                    errors.extend(self.render(failure.error, self._symbolic, ()))
        return Summary(counts, errors)

    def _condition_of(self, index: int, failure: Failure) -> int:
        """The condition (of ``presences``) under which a failure of element ``index`` is
        met: its element's, or its part's."""
        if failure.part is None:
            return self.presences.of_element[index]
        return self.presences.of_parts[index][failure.part]

    def _given(
        self,
        element: Element,
        presence: Presence,
        values: dict[str, Values],
        decisions: Decisions,
        texts: Mapping[str, str],
    ) -> Values | None:
        """The concrete strings ``element`` is shown with (None: symbolic), made once per
        file into ``values``."""
        if presence == Presence.ABSENT or not element.inputs:
            return None
        found = values.get(element.entry)
        if found is None:
            found = values[element.entry] = self._values(element.entry, decisions, texts)
        return found

    def _rendering_of(self, view: View, before: View | None, described: bool) -> Rendering:
        """``view``'s entries, from those of ``before`` (rendered, or outlined when not
        ``described``) if any; ``described``: with their conditions."""
        presences = self.judgement(view)
        earlier = None
        if before is not None:
            earlier = before.rendering if described else before.outline or before.rendering
        if earlier is None:
            entries: list[list[Fields]] = [[] for _ in self.graph.elements]
            again: Iterable[int] = range(len(self.graph.elements))
        else:
            assert before is not None and before.presences is not None
            entries = list(earlier.entries)
            again = self._rerendered(
                view.decisions, view.texts, before, before.presences, presences, described
            )
        values: dict[str, Values] = {}
        moved: dict[ElementKind, list[int]] = {}  # per kind: the elements rendered anew
        for index in again:  # in graph order: a topic comes after its nodes
            found = self._entries_of(index, presences, entries, values, view, described)
            if found is not entries[index]:
                moved.setdefault(self.graph.elements[index].kind, []).append(index)
            entries[index] = found
        lists, starts = self._lists(entries, earlier, moved)
        shown = {f"{kind}s": listed for kind, listed in lists.items()}
        failing = self.failure_entries(view, presences)
        if failing:
            shown["errors"] = [*shown.get("errors", []), *failing]
        return Rendering(entries, starts, lists, Graph(**shown))

    def _entries_of(
        self,
        index: int,
        presences: Judgement,
        entries: list[list[Fields]],
        values: dict[str, Values],
        view: View,
        described: bool,
    ) -> list[Fields]:
        """The entries of element ``index`` under ``presences`` (``entries``: those of the
        elements before it, for a topic's nodes), described or not."""
        element = self.graph.elements[index]
        judged = presences.verdicts[self.presences.of_element[index]]
        parts = tuple(
            _shown(presences.verdicts[c], described) for c in self.presences.of_parts[index]
        )
        users = (
            tuple(
                self.graph.elements[n].id
                for n in self._users.get(index, ())
                if entries[n] and entries[n][0]["presence"] != Presence.ABSENT
            )
            if element.kind in _USED  # a node's users are its topics: not listed
            else ()
        )
        presence = judged.verdict.presence
        given = self._given(element, presence, values, view.decisions, view.texts)
        return self._element_entries(element, _shown(judged, described), parts, given, users)

    def _lists(
        self,
        entries: list[list[Fields]],
        before: Rendering | None,
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
                earlier = before.lists[kind]
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
        earlier: Judgement,
        presences: Judgement,
        described: bool,
    ) -> list[int]:
        """Elements whose verdict (its description too when ``described``) or read strings
        differ from ``before`` (and the topics of nodes among them, whose lists of nodes may
        change), in graph order."""
        again: set[int] = set()
        for condition in presences.judged:
            judged, was = presences.verdicts[condition], earlier.verdicts[condition]
            if judged is not was and _shown(judged, described) != _shown(was, described):
                again.update(self._elements_of[condition])
        changed = decisions.decided.items() ^ before.decisions.decided.items()
        for variable, _value in changed:
            again.update(self._reading.get(variable, ()))
        for arg in texts.keys() | before.texts.keys():
            if texts.get(arg) != before.texts.get(arg):
                again.update(self._reading.get(arg, ()))
        for index in list(again):
            if self.graph.elements[index].kind not in _USED:
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
        shown: Shown,
        parts: tuple[Shown, ...],
        given: Values | None,
        users: tuple[str, ...],
    ) -> list[Fields]:
        """The element's graph entries with the strings ``given`` (``_given``): none for an
        absent error, else one per variant (a topic's with ``users``, its node variants not
        absent).

        Made once per verdict and strings its terms read: the same entries serve every
        state that shows them (a session's later clicks, and other sessions, meet them
        again)."""
        presence, condition = shown
        if presence == Presence.ABSENT and element.kind == ElementKind.ERROR:
            return []
        strings = frozenset((i, given.concrete.get(i)) for i in element.inputs) if given else None
        key = (element.id, presence, condition, strings, parts, users)
        entries = self._entries.get(key)
        if entries is None:
            variants = self._fields(element, given, strings, parts)
            extra: Fields = {"nodes": list(users)} if element.kind in _USED else {}
            entries = self._entries[key] = [
                {
                    **fields,
                    **extra,
                    "presence": presence,
                    "condition": condition,
                    "id": element.id if number == 0 else f"{element.id}/{number}",
                }
                for number, fields in enumerate(variants)
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
            found = self.render(element.content, given or self._symbolic, parts)
            self._rendered[key] = found
        return found


def _shown(judged: Judged, described: bool) -> Shown:
    """What entries show of a verdict: its presence, and its condition when ``described``."""
    return judged.shown if described else (judged.verdict.presence, None)
