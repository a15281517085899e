"""Queries and checks in ``rosvar serve``, answered under one tab's choices.

The query engine and the checks answer for every configuration at once, each result with its
condition over its entry file's args. A tab stands for the configurations its choices leave:
a result is listed unless it is absent from all of them (its condition and its entry file
launched), with its condition simplified by what the choices decided, an example among the
configurations left, and the ids of the graph entries it is about (the page draws them in
red). The elements and the findings are listed once, on the first question; each answer only
judges their conditions, as the graph's are judged at each step. A tab in overview mode is
told the group of each of these entries too: it may not hold them, but it draws their group.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass

from rosvar.analyses.checks import Finding, check_model
from rosvar.analyses.feature_model.operations import simplest_trigger
from rosvar.analyses.query.channels import KINDS, channel_collections
from rosvar.analyses.query.collections import Kind
from rosvar.analyses.query.evaluator import QueryEngine
from rosvar.configuration.derivation import Decisions
from rosvar.configuration.engine import ConfigurationState, Configurator
from rosvar.configuration.presence import Presence
from rosvar.configuration.view import Graph
from rosvar.diagnostics import Severity
from rosvar.logic.bdd import BDD
from rosvar.outputs.web.overview import Grouping, Packages, key_of, labels
from rosvar.workspace.interfaces.model import Interfaces

Reply = dict[str, object]
LISTED = 250
"""Results and findings an answer lists (the worst first), so that no answer grows with the
workspace: a large one's whole list of findings is megabytes; the counts cover them all."""
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
    """Queries and checks of a configurator's workspace, judged under a tab's choices."""

    def __init__(self, configurator: Configurator) -> None:
        self._configurator = configurator
        analysis = configurator.analysis
        self._entries = {entry.path: entry for entry in configurator.catalog.files}
        self._paths = {analysis.label(path): path for path in self._entries}
        self._engine: QueryEngine | None = None
        self._findings: list[Finding] | None = None

    def query(self, text: str, state: ConfigurationState, grouping: Grouping | None) -> Reply:
        """The elements ``text`` selects in the configurations ``state`` leaves, the first
        :data:`LISTED` of them, all counted (with ``grouping``, each with the ``groups`` of its
        ``ids``); raises :class:`~rosvar.analyses.query.parser.QueryError` for a query it
        refuses."""
        if self._engine is None:
            interfaces = self._configurator.graph.interfaces
            collections = None if interfaces is None else channel_collections(interfaces)
            self._engine = QueryEngine(
                self._configurator.analysis, list(self._entries), collections
            )
        decisions = self._configurator.decisions(state.choices)
        places = _Places(state.graph, grouping, self._configurator.packages)
        results = []
        for result in self._engine.run(text):
            element = result.element
            path = self._paths[element.file]
            judged = self.judge(path, result.condition, decisions)
            if judged is None:
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
                    **judged.to_json(),
                    **where,
                    **places.identify(ids),
                }
            )
        return {"query": text, "results": results[:LISTED], "total": len(results)}

    def checks(self, state: ConfigurationState, grouping: Grouping | None) -> Reply:
        """The findings of ``rosvar check`` not absent from the configurations ``state``
        leaves, the worst first (the first :data:`LISTED`, all counted); one reached from
        several entry files is listed once (from an entry file where it is present, if there
        is one). With ``grouping``, each has the ``groups`` of its ``ids``."""
        decisions = self._configurator.decisions(state.choices)
        places = _Places(state.graph, grouping, self._configurator.packages)
        shown: dict[tuple[object, ...], Reply] = {}
        for finding in self.findings():
            key = (finding.check, finding.name, finding.locations)
            earlier = shown.get(key)
            if earlier is not None and earlier["presence"] == Presence.PRESENT:
                continue
            judged = self.judge(finding.file, finding.condition, decisions)
            if judged is None or (earlier is not None and judged.presence != Presence.PRESENT):
                continue
            file_id = self._entries[finding.file].id
            first = finding.locations[0]
            ids = [
                *places.declared(Kind.NODE, (file_id, first.file, first.line), None),
                *places.named(finding.name, file_id),
            ]
            shown[key] = {
                "check": str(finding.check),
                "severity": finding.severity.value,
                "name": finding.name,
                "message": finding.message,
                "launch_file": self._configurator.analysis.label(finding.file),
                **judged.to_json(),
                "locations": [location.to_json() for location in finding.locations],
                **places.identify(list(dict.fromkeys(ids))),
            }
        order = {severity.value: rank for rank, severity in enumerate(Severity)}
        findings = sorted(  # the worst, and those present, first
            shown.values(),
            key=lambda f: (order[str(f["severity"])], f["presence"] != Presence.PRESENT),
        )
        counts = {s.value: sum(f["severity"] == s.value for f in findings) for s in Severity}
        return {"findings": findings[:LISTED], "counts": counts, "total": len(findings)}

    def findings(self) -> list[Finding]:
        """Every entry file's findings, listed on first use (each file on its own: a tab
        may launch a file without the one that includes it)."""
        if self._findings is None:
            analysis = self._configurator.analysis
            interfaces = self._configurator.graph.interfaces or Interfaces()
            confinement = analysis.workspace.confinement()
            self._findings = [
                finding
                for path in self._entries
                for finding in check_model(
                    analysis.space, analysis.model(path), interfaces, confinement
                )
            ]
        return self._findings

    def judge(self, path: str, condition: BDD, decisions: Decisions) -> Judged | None:
        """``condition`` (over the args of the entry file ``path``) where the file is
        launched, under ``decisions``; None when it is absent from every configuration."""
        configurator = self._configurator
        lowering = configurator.lowering
        fixed, bounds = lowering.lower(configurator.graph.launched[path] & condition)
        if not lowering.satisfiable(fixed):
            return None
        presence = configurator.derivation.presence(bounds, decisions).presence
        if presence == Presence.ABSENT:
            return None
        space = configurator.analysis.space
        own = space.cofactor(lowering.fix(condition), decisions.decided)
        shown = None if presence == Presence.PRESENT else configurator.views.describe(own, {})
        return Judged(presence, shown, simplest_trigger(space, own))


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
