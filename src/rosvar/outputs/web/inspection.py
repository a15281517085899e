"""Queries and checks in ``rosvar serve``, answered under one tab's choices.

The query engine and the checks answer for every configuration at once, each result with its
condition over its entry file's args. A tab stands for the configurations its choices leave:
a result is listed unless it is absent from all of them (its condition and its entry file
launched), with its condition simplified by what the choices decided, an example among the
configurations left, and the ids of the graph entries it is about (the page draws them in
red). The elements are listed once, on the first question; each answer only judges their
conditions, as the graph's are judged at each step. A tab in overview mode is told the group of
each of these entries too: it may not hold them, but it draws their group.

The findings of a large workspace take seconds to list (Husky with its dependencies' launch
files: 9,700 findings of 278 entry files, about 5 s of CPU), which no click should wait for:
they are listed once, in a thread of their own that takes the engine's lock for one entry file
at a time, and a question asked before they are all listed is told how far the listing is.
Each answer judges each distinct condition once, and describes only the conditions of the
findings it lists.
"""

from __future__ import annotations

import threading
import time
from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass

from rosvar.analyses.checks import Finding
from rosvar.analyses.feature_model.operations import simplest_trigger
from rosvar.analyses.graph_inputs import GraphInputs, graph_inputs
from rosvar.analyses.query.channels import KINDS
from rosvar.analyses.query.collections import Kind
from rosvar.analyses.query.evaluator import QueryEngine
from rosvar.configuration.derivation import Decisions
from rosvar.configuration.engine import ConfigurationState, Configurator
from rosvar.configuration.lowering import Bounds
from rosvar.configuration.presence import Presence, PresenceVerdict
from rosvar.configuration.view import Graph
from rosvar.diagnostics import Severity
from rosvar.interpreter.workspace_models import collector_paused
from rosvar.logic.bdd import BDD
from rosvar.outputs.documents.state import choice_document
from rosvar.outputs.web.overview import Grouping, Packages, key_of, labels
from rosvar.workspace.interfaces.model import Interfaces

Reply = dict[str, object]
LISTED = 250
"""Results and findings an answer lists (the worst first), so that no answer grows with the
workspace: a large one's whole list of findings is megabytes; the counts cover them all."""
PAUSE_S = 0.002
"""The listing thread's pause between two entry files, and again while a request is answered."""
NAMED = frozenset(KINDS.values())
"""Kinds of query results that are graph entries by their name alone."""
_Place = tuple[str, str, int]
"""Where a graph entry is declared: its entry file's id, the declaring file and line."""


@dataclass(frozen=True)
class Judged:
    """A condition under a tab's choices: its presence, how it reads with the decided
    variables in (None when present) and an example configuration among those left."""

    presence: Presence
    condition: str | None
    example: dict[str, str]

    def to_json(self) -> Reply:
        return {"presence": self.presence, "condition": self.condition, "example": self.example}


class Inspector:
    """Queries and checks of a configurator's workspace, judged under a tab's choices.

    ``lock`` is the engine's (the API's): the findings are listed in a thread of their own
    that holds it for one entry file at a time, and waits while ``asked()`` says a request
    is being answered or waits for the lock."""

    def __init__(
        self,
        configurator: Configurator,
        lock: threading.Lock,
        asked: Callable[[], bool] = lambda: False,
    ) -> None:
        self._configurator = configurator
        analysis = configurator.analysis
        self._entries = {entry.path: entry for entry in configurator.catalog.files}
        self._paths = {analysis.label(path): path for path in self._entries}
        self._engine: QueryEngine | None = None
        self._inputs: GraphInputs | None = None
        self._findings = _Findings(configurator, list(self._entries), lock, asked, self.inputs)
        self._lowered: dict[tuple[str, BDD], tuple[BDD, Bounds] | None] = {}

    def query(self, text: str, state: ConfigurationState, grouping: Grouping | None) -> Reply:
        """The elements ``text`` selects in the configurations ``state`` leaves, the first
        :data:`LISTED` of them, all counted (with ``grouping``, each with the ``groups`` of its
        ``ids``); raises :class:`~rosvar.analyses.query.parser.QueryError` for a query it
        refuses."""
        if self._engine is None:
            interfaces = self._configurator.graph.interfaces
            collections = None if interfaces is None else self.inputs().collections()
            self._engine = QueryEngine(
                self._configurator.analysis, list(self._entries), collections
            )
        decisions = self._configurator.decisions(state.choices)
        places = _Places(state.outline, grouping, self._configurator.packages)
        results = []
        for result in self._engine.run(text):
            element = result.element
            path = self._paths[element.file]
            verdict = self.verdict(path, result.condition, decisions)
            if verdict is None:
                continue
            location = element.location
            where = {} if location is None else {"file": location.file, "line": location.line}
            file_id = self._entries[path].id
            if element.kind in (Kind.NODE, Kind.PARAM) and location is not None:
                place = (file_id, location.file, location.line)
                ids = places.declared(Kind(element.kind), place, element.name)
            else:
                ids = places.named(element.name) if element.kind in NAMED else []
            results.append(
                {
                    "kind": str(element.kind),
                    "name": element.name,
                    "launch_file": element.file,
                    **self.judged(result.condition, verdict).to_json(),
                    **where,
                    **places.identify(ids),
                }
            )
        return {"query": text, "results": results[:LISTED], "total": len(results)}

    def inputs(self) -> GraphInputs:
        """What the checks and queries read beside the models, as ``rosvar check`` and
        ``rosvar query`` have it (the simulation with them), built on the first question
        (under the engine's lock, as both ask)."""
        if self._inputs is None:
            interfaces = self._configurator.graph.interfaces or Interfaces()
            self._inputs = graph_inputs(self._configurator.analysis, interfaces)
        return self._inputs

    def checks(self, state: ConfigurationState, grouping: Grouping | None) -> Reply:
        """The findings of ``rosvar check`` not absent from the configurations ``state``
        leaves, the worst first (the first :data:`LISTED`, all counted), and the ``choices``
        of the state judged; one reached from several entry files is listed once (from an
        entry file where it is present, if there is one). With ``grouping``, each has the
        ``groups`` of its ``ids``. While the findings are being listed: ``{"pending": [files
        done, files]}`` (the listing starts with the first question)."""
        choices = [choice_document(choice) for choice in state.choices]
        found = self._findings.listed()
        if found is None:
            return {"pending": list(self._findings.progress()), "choices": choices}
        decisions = self._configurator.decisions(state.choices)
        verdicts: dict[tuple[str, BDD], PresenceVerdict | None] = {}
        shown: dict[tuple[object, ...], tuple[Finding, PresenceVerdict]] = {}
        for finding in found:
            key = (finding.check, finding.name, finding.locations)
            earlier = shown.get(key)
            if earlier is not None and earlier[1].presence == Presence.PRESENT:
                continue
            judging = (finding.file, finding.condition)
            if judging not in verdicts:  # findings of one place share their condition
                verdicts[judging] = self.verdict(finding.file, finding.condition, decisions)
            verdict = verdicts[judging]
            if verdict is None or (earlier is not None and verdict.presence != Presence.PRESENT):
                continue
            shown[key] = (finding, verdict)
        order = {severity: rank for rank, severity in enumerate(Severity)}
        ranked = sorted(  # the worst, and those present, first
            shown.values(),
            key=lambda f: (order[f[0].severity], f[1].presence != Presence.PRESENT),
        )
        counts = {s.value: sum(f.severity == s for f, _ in ranked) for s in Severity}
        places = _Places(state.outline, grouping, self._configurator.packages)
        listed = [self._finding(f, verdict, places) for f, verdict in ranked[:LISTED]]
        return {"findings": listed, "counts": counts, "total": len(ranked), "choices": choices}

    def _finding(self, finding: Finding, verdict: PresenceVerdict, places: _Places) -> Reply:
        file_id = self._entries[finding.file].id
        first = finding.locations[0]
        ids = [
            *places.declared(Kind.NODE, (file_id, first.file, first.line), None),
            *places.named(finding.name, file_id),
        ]
        return {
            "check": str(finding.check),
            "severity": finding.severity.value,
            "name": finding.name,
            "message": finding.message,
            "launch_file": self._configurator.analysis.label(finding.file),
            **self.judged(finding.condition, verdict).to_json(),
            "locations": [location.to_json() for location in finding.locations],
            **places.identify(list(dict.fromkeys(ids))),
        }

    def verdict(self, path: str, condition: BDD, decisions: Decisions) -> PresenceVerdict | None:
        """The presence of ``condition`` (over the args of the entry file ``path``) where the
        file is launched, under ``decisions``; None when it is absent from every
        configuration."""
        key = (path, condition)
        if key not in self._lowered:  # what the solver reads of it never changes
            lowering = self._configurator.lowering
            fixed, bounds = lowering.lower(self._configurator.graph.launched[path] & condition)
            self._lowered[key] = (fixed, bounds) if lowering.satisfiable(fixed) else None
        lowered = self._lowered[key]
        if lowered is None:
            return None
        verdict = self._configurator.derivation.presence(lowered[1], decisions)
        return None if verdict.presence == Presence.ABSENT else verdict

    def judged(self, condition: BDD, verdict: PresenceVerdict) -> Judged:
        """How ``condition`` reads under its ``verdict`` (the decided variables in) and an
        example among the configurations left."""
        configurator = self._configurator
        fixed = configurator.lowering.fix(condition)
        own = configurator.analysis.space.cofactor(fixed, verdict.values)
        present = verdict.presence == Presence.PRESENT
        shown = None if present else configurator.views.describe(fixed, verdict.values)
        return Judged(verdict.presence, shown, simplest_trigger(configurator.analysis.space, own))


class _Findings:
    """Every entry file's findings (each file on its own: a tab may launch a file without the
    one that includes it), listed once by a thread of their own, a file at a time under the
    engine's lock: every file's edges gathered, then each file checked against them all, as
    ``rosvar check`` does (:class:`~rosvar.analyses.checks.Checks`)."""

    def __init__(
        self,
        configurator: Configurator,
        paths: list[str],
        lock: threading.Lock,
        asked: Callable[[], bool],
        inputs: Callable[[], GraphInputs],
    ) -> None:
        self._configurator = configurator
        self._inputs = inputs
        self._paths = paths
        self._lock = lock
        self._asked = asked
        self._found: list[Finding] = []
        self._done = 0
        self._failure: BaseException | None = None
        self._thread: threading.Thread | None = None

    def listed(self) -> list[Finding] | None:
        """All of them; None while they are being listed (the first call starts it)."""
        if self._thread is None:
            self._thread = threading.Thread(target=self._list, name="findings", daemon=True)
            self._thread.start()
        if self._failure is not None:
            raise self._failure
        return self._found if self._done == 2 * len(self._paths) else None

    def progress(self) -> tuple[int, int]:
        """Entry files listed, of all (each is gathered, then checked: half a file a step)."""
        return self._done // 2, len(self._paths)

    def _list(self) -> None:
        analysis = self._configurator.analysis
        try:
            with self._lock:
                checks = self._inputs().checks()
            for gathering in (True, False):
                for path in self._paths:
                    with self._lock, collector_paused():  # as the API's calls (api.py)
                        model = analysis.model(path)
                        if gathering:
                            checks.gather(model)
                        else:
                            self._found.extend(checks.check(model))
                    self._done += 1
                    self._pause()
        except Exception as error:  # told to the next question, as its own failure would be
            self._failure = error

    def _pause(self) -> None:
        """Between two entry files: requests first (they would share the processor, and
        a lock is not fair: taking it again at once could keep it)."""
        time.sleep(PAUSE_S)
        while self._asked():
            time.sleep(PAUSE_S)


class _Places:
    """The entries of one state's graph by where they are declared and by name, and (with
    a grouping) the group of each node and param."""

    def __init__(self, graph: Graph, grouping: Grouping | None, named: Packages) -> None:
        self._declared: dict[tuple[Kind, *_Place], list[tuple[str, str]]] = {}
        self._named: dict[tuple[str, str], list[str]] = {}  # (entry file id or "", name) → ids
        self._grouping = grouping
        self._groups: dict[str, str] = {}
        lists: Sequence[tuple[Kind | None, Iterable[Mapping[str, object]]]] = (
            (Kind.NODE, graph.nodes),
            (Kind.NODE, graph.tests),
            (Kind.PARAM, graph.params),
            (None, graph.topics),
            (None, graph.services),
            (None, graph.actions),
        )
        for kind, entries in lists:
            for entry in entries:
                if entry["presence"] == Presence.ABSENT:
                    continue
                id_, name = str(entry["id"]), str(entry["name"])
                file_id = ""  # names of topics, services and actions are the workspace's
                if kind is not None:
                    file_id = id_.split("|", 1)[0]
                    place = (kind, file_id, str(entry["filename"]), int(str(entry["line"])))
                    self._declared.setdefault(place, []).append((name, id_))
                    if grouping is not None:
                        self._groups[id_] = key_of(labels(grouping, entry, named))
                self._named.setdefault((file_id, name), []).append(id_)

    def declared(self, kind: Kind, place: _Place, name: str | None) -> list[str]:
        """Ids of the entries of ``kind`` declared at ``place`` (named ``name``, unless None
        or a name awaiting an input, ``⟨arg⟩``)."""
        found = self._declared.get((kind, *place), [])
        if name is None or "⟨" in name:
            return [id_ for _name, id_ in found]
        return [id_ for shown, id_ in found if shown == name]

    def identify(self, ids: list[str]) -> Reply:
        """``ids``, and in overview mode their ``groups`` (None: a topic, service or action,
        which the page draws one by one)."""
        if self._grouping is None:
            return {"ids": ids}
        return {"ids": ids, "groups": [self._groups.get(id_) for id_ in ids]}

    def named(self, name: str, file_id: str | None = None) -> list[str]:
        """Ids of the topics, services and actions named ``name`` (and, with ``file_id``, of
        the nodes and params of that entry file)."""
        return [
            *self._named.get(("", name), []),
            *(self._named.get((file_id, name), []) if file_id else []),
        ]
