"""Checks of the communication graph and the parameters, for all configurations at once.

Each finding holds a presence condition over its entry file's args, computed on the
variational model: "two publishers" is the disjunction, over pairs of different nodes
publishing one resolved name, of both edges' conditions; "nobody publishes" is a
subscription's condition and the negation of every publication's of that name. No
configuration is enumerated; the documents read an example configuration off the
condition (``simplest_trigger``).
"""

from __future__ import annotations

import dataclasses
import difflib
import enum
import os
import re
from collections import Counter, defaultdict
from collections.abc import Callable, Iterable, Iterator, Sequence
from dataclasses import dataclass

from rosvar.analyses.communication import (
    CHANNEL,
    SIDES,
    Channel,
    Described,
    Edge,
    Gap,
    branches_remembered,
    camera_info_beside,
    entry_when,
    find_interface,
    launched_units,
    model_edges,
    node_branches,
)
from rosvar.analyses.conflicts import (
    Clash,
    Occurrence,
    clashes,
    node_occurrences,
    repeated_inclusions,
)
from rosvar.analyses.feature_model.operations import trigger
from rosvar.analyses.param_values import ParamValues
from rosvar.analyses.when import params_read
from rosvar.diagnostics import Location, Severity
from rosvar.files import Confinement
from rosvar.interpreter.model import (
    INCLUDE_UNREAD,
    ErrorEvent,
    LaunchModel,
    NodeDecl,
    ParamDecl,
    YamlDecl,
)
from rosvar.interpreter.workspace_models import collector_paused
from rosvar.logic.bdd import BDD
from rosvar.logic.conditions import ConditionSpace
from rosvar.ros import names
from rosvar.ros.version import RosVersion
from rosvar.workspace.interfaces.model import Entry, Interfaces, Origin, Role
from rosvar.workspace.paths import real_path

ROS2_BOTH_START = " (ros2 launch starts both: their parameter services and private names collide)"


class Check(enum.StrEnum):
    """What a finding is about; the values are the rule ids of the JSON and SARIF output."""

    MULTIPLE_PROVIDERS = "multiple-providers"
    NO_PROVIDER = "no-provider"
    NO_SUBSCRIBER = "no-subscriber"
    TYPE_MISMATCH = "type-mismatch"
    NODE_NAME_CLASH = "node-name-clash"
    PARAM_UNSET = "param-unset"
    PARAM_UNREAD = "param-unread"
    REMAP_UNUSED = "remap-unused"
    PARAM_FILE_UNMATCHED = "param-file-unmatched"
    LOAD_ERROR = "load-error"
    SYMBOLIC_NAME = "symbolic-name"
    WHEN_UNKNOWN = "when-unknown"
    UNREAD = "unread"


DESCRIPTIONS: dict[Check, str] = {
    Check.MULTIPLE_PROVIDERS: "several nodes publish one topic, or serve one service or action",
    Check.NO_PROVIDER: "a node subscribes to a topic (or calls a service, an action) that no "
    "launched node provides",
    Check.NO_SUBSCRIBER: "a node publishes a topic no launched node subscribes to",
    Check.TYPE_MISMATCH: "the nodes using one name disagree on its message or service type",
    Check.NODE_NAME_CLASH: "two nodes get one name: roslaunch refuses to start",
    Check.PARAM_UNSET: "a node reads a parameter without a default that no launch file sets",
    Check.PARAM_UNREAD: "a launch file sets a parameter of a node that never reads it (a "
    "misspelt name: the node runs on its default)",
    Check.REMAP_UNUSED: "a node's remap renames a name the node never uses (a typo, or "
    "another node's name: the node keeps its own)",
    Check.PARAM_FILE_UNMATCHED: "a ROS 2 node is given a parameter file with no entry for its "
    "name: the node gets none of its parameters",
    Check.LOAD_ERROR: "the launch tool refuses the entry file, for a mistake in the launch "
    "files' own text (an arg declared twice, an include given an arg it does not declare)",
    Check.SYMBOLIC_NAME: "a name could not be resolved statically: the checks skip it",
    Check.WHEN_UNKNOWN: "a hinted entry's when: reads a parameter whose value is not known: "
    "the entry is kept there",
    Check.UNREAD: "a part of the graph could not be read: a launch file rosvar could not read "
    "(malformed, or over a limit on hostile input), a robot description xacro fails on or that "
    "is read only in part, a Gazebo plugin of a library rosvar does not know",
}

PROVIDED = {Channel.TOPICS: "publish", Channel.SERVICES: "serve", Channel.ACTIONS: "serve"}
USED = {Channel.TOPICS: "subscribes to", Channel.SERVICES: "calls", Channel.ACTIONS: "calls"}


@dataclass(frozen=True)
class Finding:
    """One problem of the entry ``file``, present when ``condition`` holds and the file
    loads (roslaunch does not fail on it)."""

    check: Check
    severity: Severity
    name: str
    message: str
    file: str
    condition: BDD
    locations: tuple[Location, ...]  # the first is where the problem is reported


OWN_ERRORS = frozenset(
    {
        "arg-duplicate",
        "arg-value-and-default",
        "attribute-missing",
        "ifunless-both",
        "include-arg-unused",
        "include-arg-undefined",
        "include-cycle",
        "machine-env",
        "env-invalid",
    }
)
"""Errors of the launch files' own text: they stop the launch whatever values the command
line gives (docs/diagnostics.md lists each). Not a malformed substitution: ROS 2 counts a
substitution's arguments after the values are in, so a typed text with a space makes one."""
ARG_ERRORS = frozenset({"arg-duplicate", "arg-value-and-default", "include-arg-unused"})
"""Errors about one arg: a finding is named after it."""
_SUBJECT = re.compile(r"'([^']+)'|\[([^\]]+)\]")


def _syntax(error: ErrorEvent) -> bool:
    """An ``$(eval)`` that is no Python expression: a mistake of the text too."""
    return error.code == "eval-refused" and "invalid Python expression" in error.message


@dataclass(frozen=True)
class Found:
    """A finding before it is placed in its entry file: what a dialect's own checks make
    (:data:`MODEL_CHECKS`)."""

    check: Check
    severity: Severity
    name: str
    message: str
    condition: BDD
    locations: tuple[Location, ...]


ModelCheck = Callable[[ConditionSpace, LaunchModel, Interfaces, Confinement], Iterable[Found]]
"""A check of an entry file's nodes that only their dialect's launch semantics can make
(ROS 2's parameter files, matched to the nodes as rcl matches them)."""
MODEL_CHECKS: dict[RosVersion, list[ModelCheck]] = defaultdict(list)
"""The dialects' own checks, by the ROS of the nodes they check (filled by the dialects: the
core names neither)."""


def model_check(version: RosVersion) -> Callable[[ModelCheck], ModelCheck]:
    """Register a check of the entry files whose nodes are of ``version``."""

    def register(check: ModelCheck) -> ModelCheck:
        MODEL_CHECKS[version].append(check)
        return check

    return register


class Checks:
    """The checks of a workspace's entry files, made in two passes so that a caller may take
    them a file at a time (the web UI, under its engine's lock): :meth:`gather` each file's
    edges and the parameter names it sets (a use missing in one entry file may be made by
    another: a note there), then :meth:`check` each file against them all.
    ``described``: the uses launch models make beyond their nodes' code (robot
    descriptions, bridges, controllers); ``dependency``: whether a file is a dependency's,
    not the user's (what rosvar cannot read of one is told at the user's include)."""

    def __init__(
        self,
        space: ConditionSpace,
        interfaces: Interfaces,
        confinement: Confinement,
        described: Described | None = None,
        dependency: Callable[[str], bool] = lambda _file: False,
    ) -> None:
        self.space = space
        self.interfaces = interfaces
        self.confinement = confinement
        self.described = described
        self.dependency = dependency
        self.edges: dict[str, list[Edge]] = {}
        self.partners: Partners = defaultdict(set)

    def gather(self, model: LaunchModel) -> None:
        with branches_remembered():
            edges = model_edges(self.space, model, self.interfaces, self.described)
        self.edges[model.file] = edges
        for edge in edges:
            if edge.static:
                self.partners[(edge.role, edge.name)].add(model.file)
        for name, _condition in setters(model, self.confinement):
            self.partners[(Role.PARAMS, name)].add(model.file)

    def check(self, model: LaunchModel) -> list[Finding]:
        """The findings of a gathered entry file."""
        edges = self.edges[model.file]
        with branches_remembered():
            return check_model(
                self.space,
                model,
                self.interfaces,
                self.confinement,
                edges,
                self.partners,
                self.described,
                self.dependency,
            )


@collector_paused()  # the edges of every file are kept: the collector rescanned the models' heap
def check_models(
    space: ConditionSpace,
    models: Sequence[LaunchModel],
    interfaces: Interfaces,
    confinement: Confinement,
    described: Described | None = None,
    dependency: Callable[[str], bool] = lambda _file: False,
) -> list[Finding]:
    """The findings of every entry file (:class:`Checks`); one found again through a file
    including another (same check, name and places) is reported once, for the file that is
    included."""
    found: dict[tuple[object, ...], Finding] = {}
    included = _included(models)
    ordered = sorted(models, key=lambda m: real_path(m.file) not in included)
    checks = Checks(space, interfaces, confinement, described, dependency)
    for model in ordered:
        checks.gather(model)
    for model in ordered:
        for finding in checks.check(model):
            key = (finding.check, finding.name, finding.locations)
            found.setdefault(key, finding)
    return sorted(found.values(), key=lambda f: (f.locations[0], f.check, f.name))


def _included(models: Iterable[LaunchModel]) -> set[str]:
    return {
        real_path(file)
        for model in models
        for include in model.includes
        for _, file in include.file
        if isinstance(file, str)
    }


Partners = defaultdict[tuple[Role, str], set[str]]
"""The entry files whose nodes use a resolved name in a role (an edge in some configuration),
and (``Role.PARAMS``) that set a parameter name."""


def check_model(
    space: ConditionSpace,
    model: LaunchModel,
    interfaces: Interfaces,
    confinement: Confinement,
    edges: Sequence[Edge] | None = None,
    partners: Partners | None = None,
    described: Described | None = None,
    dependency: Callable[[str], bool] = lambda _file: False,
) -> list[Finding]:
    """The findings of one entry file (where it loads: a failing launch has no graph);
    ``confinement``: where the files its ``<rosparam>`` loads may be read; ``partners``:
    the uses of the workspace's other entry files (a missing partner there is a note);
    ``dependency``: as :func:`check_models`."""
    if edges is None:
        edges = model_edges(space, model, interfaces, described)
    loads = model.loads if described is None else model.loads & ~described.fails(model)
    checker = _Checker(space, model, loads, confinement, partners or defaultdict(set))
    checker.unknown = _unknown_nodes(space, model, interfaces)
    checker.graph(edges)
    checker.errors()
    checker.unreadable(dependency)
    if described is not None:
        checker.gaps(described.gaps(model))
    checker.node_names()
    checker.params(interfaces)
    checker.unread(interfaces)
    checker.remaps(interfaces)
    checker.dialects(interfaces)
    checker.whens(interfaces)
    return [_told(space, finding) for finding in checker.findings]


UNTOLD = (
    " (rosvar could not tell: only a value nobody foresaw gives it, and no text rosvar tried does)"
)


def _told(space: ConditionSpace, finding: Finding) -> Finding:
    """A warning or error whose example needs an unforeseen value that no witness gives
    (no text rosvar tried makes the example's predicates hold as it asks) is a note: rosvar
    cannot tell that such a value exists."""
    if finding.severity is Severity.NOTE:
        return finding
    found = trigger(space, finding.condition)
    if found is None or not found.unwitnessed:
        return finding
    return dataclasses.replace(finding, severity=Severity.NOTE, message=finding.message + UNTOLD)


class _Checker:
    def __init__(
        self,
        space: ConditionSpace,
        model: LaunchModel,
        loads: BDD,
        confinement: Confinement,
        partners: Partners,
    ) -> None:
        self.partners = partners
        self.unknown: list[tuple[str, str, BDD]] = []  # nodes without an interface: name, ns
        self.confinement = confinement
        self.space = space
        self.model = model
        self.loads = loads
        self.findings: list[Finding] = []
        self._said: dict[tuple[Check, Severity, str, str, Location], int] = {}
        self.symbolic: dict[Role, list[Edge]] = defaultdict(list)  # uses of unresolved names

    def add(
        self,
        check: Check,
        severity: Severity,
        name: str,
        message: str,
        condition: BDD,
        locations: Iterable[Location],
    ) -> None:
        # kept without the file's loading condition: that one spells out every env value
        # that makes some `if` invalid, which would drown the finding's own reason
        if not self.space.satisfiable(condition & self.loads):
            return
        places = tuple(locations)
        key = (check, severity, name, message, places[0])
        said = self._said.get(key)
        if said is None:
            self._said[key] = len(self.findings)
            self.findings.append(
                Finding(check, severity, name, message, self.model.file, condition, places)
            )
            return
        # one problem seen through several uses (a node subscribing one topic at two lines
        # of its source): one finding, where any of them holds, showing every place
        found = self.findings[said]
        more = tuple(p for p in places if p not in found.locations)
        self.findings[said] = dataclasses.replace(
            found, condition=found.condition | condition, locations=found.locations + more
        )

    def any(self, conditions: Iterable[BDD]) -> BDD:
        result = self.space.false
        for condition in conditions:
            result |= condition
        return result

    def graph(self, edges: Sequence[Edge]) -> None:
        by_name: dict[tuple[Channel, str], list[Edge]] = defaultdict(list)
        for edge in edges:
            if edge.static:
                by_name[(edge.channel, edge.name)].append(edge)
            else:
                self.symbolic[edge.role].append(edge)
                self.add(
                    Check.SYMBOLIC_NAME,
                    Severity.NOTE,
                    edge.name,
                    f"{edge.node} {edge.role}: '{edge.name}' is not known statically",
                    edge.condition,
                    (edge.launch, edge.source),
                )
        for (channel, name), named in sorted(by_name.items()):
            provide, use = SIDES[channel]
            providers = [e for e in named if e.role is provide]
            users = [e for e in named if e.role is use]
            self.providers(channel, name, providers)
            self.unmatched(channel, name, providers, users)
            self.types(name, named)

    def errors(self) -> None:
        """Where the launch tool refuses the entry file for a mistake of the files' own text
        (:data:`OWN_ERRORS`), whatever the command line gives: its condition and place.
        Errors a typed value, an unset variable or a missing arg makes are the command
        line's, which ``resolve`` and the configuration engine report."""
        loads, self.loads = self.loads, self.space.true
        for error in self.model.errors:
            if error.code not in OWN_ERRORS and not _syntax(error):
                continue
            subject = _SUBJECT.search(error.message) if error.code in ARG_ERRORS else None
            self.add(
                Check.LOAD_ERROR,
                Severity.ERROR,
                next(g for g in subject.groups() if g) if subject else error.code,
                f"the launch tool refuses the launch here: {error.message}",
                error.condition,
                (error.location,),
            )
        self.loads = loads

    def unreadable(self, dependency: Callable[[str], bool]) -> None:
        """What rosvar could not read of the entry file or the files it includes: malformed,
        or over a limit on hostile input (too large, too many steps, nested too deep). The
        checks see nothing of it: without this, such a workspace would pass with no
        finding. As the diagnostic, wherever the file is included; a dependency's file, as a
        warning at the user's include that reaches it (the launch itself may well work:
        the installed dependency has the file)."""
        loads, self.loads = self.loads, self.space.true
        for diagnostic in self.model.diagnostics:
            if diagnostic.code == INCLUDE_UNREAD:
                self.add(
                    Check.UNREAD,
                    Severity.WARNING,
                    diagnostic.code,
                    diagnostic.message,
                    self.any(
                        include.condition
                        for include in self.model.includes
                        if include.location == diagnostic.location and not include.resolved
                    ),
                    self._reached(diagnostic.location, dependency),
                )
            elif diagnostic.severity is Severity.ERROR:
                self.add(
                    Check.UNREAD,
                    Severity.ERROR,
                    diagnostic.code,
                    f"rosvar could not read this, the checks do not see it: {diagnostic.message}",
                    self.space.true,
                    (diagnostic.location,),
                )
        self.loads = loads

    def _reached(
        self, location: Location, dependency: Callable[[str], bool]
    ) -> tuple[Location, ...]:
        """``location`` and the includes above it up to the first in the user's files:
        the place the user can act on first."""
        chain = [location]
        while dependency(chain[0].file):
            above = next(
                (
                    include.location
                    for include in self.model.includes
                    if include.resolved
                    and any(
                        isinstance(file, str) and real_path(file) == real_path(chain[0].file)
                        for _, file in include.file
                    )
                ),
                None,
            )
            if above is None or above in chain:
                break
            chain.insert(0, above)
        return tuple(chain)

    def gaps(self, gaps: Sequence[Gap]) -> None:
        """What of the graph could not be read, where it matters (where the launch loads, and
        a description xacro fails on: that is what makes the run fail)."""
        loads, self.loads = self.loads, self.model.loads
        for gap in gaps:
            self.add(
                Check.UNREAD, gap.severity, gap.name, gap.message, gap.condition, gap.locations
            )
        self.loads = loads

    def providers(self, channel: Channel, name: str, providers: Sequence[Edge]) -> None:
        """At least two different nodes provide ``name``: a running count over the nodes.
        Boundary outputs are meant to have many (every tf broadcaster publishes ``/tf``)."""
        per_node: dict[tuple[str, Location], BDD] = defaultdict(lambda: self.space.false)
        for edge in providers:
            if edge.boundary:
                continue
            per_node[(edge.node, edge.launch)] |= edge.condition
        if len(per_node) < 2:
            return
        one = two = self.space.false
        for condition in per_node.values():
            two |= one & condition
            one |= condition
        # two declarations of one node name (ROS 2 launches both) are two providers
        nodes = Counter(node for node, _ in per_node)
        listed = ", ".join(n if k == 1 else f"{n} ×{k}" for n, k in sorted(nodes.items()))
        severity = Severity.NOTE if channel is Channel.TOPICS else Severity.WARNING
        self.add(
            Check.MULTIPLE_PROVIDERS,
            severity,
            name,
            f"{len(per_node)} nodes {PROVIDED[channel]} {name}: {listed}",
            two,
            sorted({e.launch for e in providers}),
        )

    def unmatched(
        self, channel: Channel, name: str, providers: Sequence[Edge], users: Sequence[Edge]
    ) -> None:
        provided = self.any(e.condition for e in providers)
        used = self.any(e.condition for e in users)
        provide, use = SIDES[channel]
        elsewhere = self._elsewhere(provide, name)
        for edge in users:  # from a person, a tool or another launch file: a note
            unsure = " (it uses it only if a parameter rosvar cannot know says so)"
            reason = (
                elsewhere
                or (unsure if edge.uncertain else "")
                or self._unseen(name, edge)
                or self._maybe(provide, name, edge)
            )
            self.add(
                Check.NO_PROVIDER,
                Severity.NOTE if edge.boundary or reason else Severity.WARNING,
                name,
                f"{edge.node} {USED[channel]} {name}, which no launched node provides" + reason,
                edge.condition & ~provided,
                (edge.launch, edge.source),
            )
        if channel is not Channel.TOPICS:
            return
        for edge in providers:
            if edge.boundary:
                continue  # its consumers are outside the launch files by design
            self.add(
                Check.NO_SUBSCRIBER,
                Severity.NOTE,
                name,
                f"{edge.node} publishes {name}, which no launched node subscribes to"
                + self._elsewhere(use, name),
                edge.condition & ~used,
                (edge.launch, edge.source),
            )

    def _unseen(self, name: str, edge: Edge) -> str:
        """A launched node without a known interface in the namespace of ``name``, beside
        ``edge``'s node: it may well be the partner (the GPS driver of ``/gps`` publishing
        ``fix``), which rosvar cannot see."""
        namespace = names.make_global_ns(name.rsplit(names.SEP, 1)[0] or names.SEP)
        beside = sorted(
            {
                node
                for node, node_ns, condition in self.unknown
                if node_ns == namespace and self.space.satisfiable(condition & edge.condition)
            }
        )
        if not beside:
            return ""
        if len(beside) == 1:
            return f" (unless {beside[0]}, whose interface rosvar does not know, does)"
        return f" (unless one of {', '.join(beside)}, whose interfaces rosvar does not know, does)"

    def _maybe(self, role: Role, name: str, edge: Edge) -> str:
        """A launched node using in ``role`` a name rosvar could not resolve whose known
        parts fit ``name``, beside ``edge``'s node: it may be the partner (a camera driver
        publishing ``{topic_name}``), which rosvar cannot tell."""
        beside = sorted(
            {
                (other.node, other.name)
                for other in self.symbolic[role]
                if other.node != edge.node
                and _may_be(other.name, name)
                and self.space.satisfiable(other.condition & edge.condition)
            }
        )
        if not beside:
            return ""
        node, pattern = beside[0]
        more = f" or {len(beside) - 1} more" if len(beside) > 1 else ""
        if pattern == name:  # the node's fields hold a value known per configuration only
            return f" (unless {node} does: its names depend on a value rosvar cannot know)"
        return f" (unless {node}'s '{pattern}'{more}, a name rosvar cannot resolve, is it)"

    def _elsewhere(self, role: Role, name: str) -> str:
        """Where other entry files of the workspace use ``name`` in ``role``: launch files
        meant to run together (a robot's base and an app started beside it)."""
        files = sorted(self.partners[(role, name)] - {self.model.file})
        if not files:
            return ""
        more = f" and {len(files) - 1} more" if len(files) > 1 else ""
        return f" here ({os.path.basename(files[0])}{more} does)"

    def types(self, name: str, named: Sequence[Edge]) -> None:
        by_type: dict[str, list[Edge]] = defaultdict(list)
        types_of: dict[str, set[str]] = defaultdict(set)
        for edge in named:
            if edge.type is not None:
                by_type[edge.type].append(edge)
                types_of[edge.node].add(edge.type)
        kinds = sorted(by_type)
        for i, first in enumerate(kinds):
            for second in kinds[i + 1 :]:
                a, b = by_type[first], by_type[second]
                # one node's several types are alternative code paths (robot_localization's
                # stamped_control): two nodes disagree when they share none
                both = self.any(
                    x.condition & y.condition
                    for x in a
                    for y in b
                    if not types_of[x.node] & types_of[y.node]
                )
                self.add(
                    Check.TYPE_MISMATCH,
                    Severity.ERROR,
                    name,
                    f"{name} is {first} for {_nodes(a)} but {second} for {_nodes(b)}",
                    both,
                    (a[0].launch, a[0].source, b[0].launch, b[0].source),
                )

    def node_names(self) -> None:
        """Two nodes of one name: roslaunch refuses to start, ``ros2 launch`` starts both
        (a warning: their parameters, services and logs then share one name)."""
        buckets: dict[tuple[str, str], list[Occurrence]] = defaultdict(list)
        ros2 = any(node.ros2 for node in self.model.nodes)
        for node in self.model.nodes:
            if not node.is_test:
                for occurrence in node_occurrences(self.model, node):
                    buckets[("node", occurrence.name)].append(occurrence)
        # one finding per name, every pair of nodes under it: two includes of a file whose
        # nodes each have two names are one problem, not four
        by_name: dict[str, list[Clash]] = defaultdict(list)
        for clash in clashes(buckets):
            by_name[clash.name].append(clash)
        twice: dict[str, set[str]] = defaultdict(set)  # name -> the files included twice
        for clash in repeated_inclusions(self.model, started=True):  # one node, two includes
            by_name[clash.name].append(clash)
            twice[clash.name].add(os.path.basename(clash.first.location.file))
        for name, found in by_name.items():
            places = dict.fromkeys(
                place for c in found for place in (c.second.location, c.first.location)
            )
            included = sorted(twice[name])
            reason = f" ({', '.join(included)} included twice)" if included else ""
            self.add(
                Check.NODE_NAME_CLASH,
                Severity.WARNING if ros2 else Severity.ERROR,
                name,
                f"two nodes are named {name}{reason}" + (ROS2_BOTH_START if ros2 else ""),
                self.any(c.condition for c in found),
                tuple(places),
            )

    def params(self, interfaces: Interfaces) -> None:
        """Reads without a default of names no ``<param>``/``<rosparam>`` sets (nor a
        namespace around them, nor one inside them)."""
        setters = self.setters()
        for node in self.model.nodes:
            if node.is_test:
                continue
            for edge_node, condition, reads in _param_reads(self.space, node, interfaces):
                for name, entry_location in reads:
                    set_here = self.any(c for set_name, c in setters if _covers(set_name, name))
                    # set in other configurations, or by another entry file: a choice to
                    # leave it to what runs beside (MoveIt's load_robot_description:=false)
                    elsewhere = self._set_elsewhere(name)
                    if set_here != self.space.false:
                        elsewhere = " in these configurations (it does in others)"
                    self.add(
                        Check.PARAM_UNSET,
                        Severity.NOTE if elsewhere else Severity.WARNING,
                        name,
                        f"{edge_node} reads {name}, which has no default and no launch file sets"
                        + elsewhere,
                        condition & ~set_here,
                        (node.location, entry_location),
                    )

    def unread(self, interfaces: Interfaces) -> None:
        """Parameters set in a node's private namespace that it never reads, where its every
        read is known: read off the workspace's sources, each name static. roscpp and rospy
        never complain of a parameter nobody reads, so a misspelt name leaves the node on its
        default (a catalogue entry may list only the parameters that matter: not enough)."""
        readers = list(_readers(self.space, self.model, interfaces))
        for name, condition, location in self.set_params():
            read = self.any(c for c, _n, _l, reads, _e in readers if _reads(reads, name))
            for node_condition, node, node_location, reads, every in readers:
                own = node + names.SEP
                if not every or not name.startswith(own):
                    continue
                private = [r.removeprefix(own) for r in reads if r.startswith(own)]
                near = difflib.get_close_matches(name.removeprefix(own), private, n=1)
                self.add(
                    Check.PARAM_UNREAD,
                    Severity.WARNING,
                    name,
                    f"{name} is set for {node}, which never reads it"
                    + (f" (it reads ~{near[0]})" if near else ""),
                    condition & node_condition & ~read,
                    (location, node_location),
                )
            self._above(name, condition & ~read, location, readers)

    def _above(
        self,
        name: str,
        condition: BDD,
        location: Location,
        readers: Sequence[tuple[BDD, str, Location, list[str], bool]],
    ) -> None:
        """``name`` (``N/x``) set where no launched node reads it, beside a node ``N/d`` that
        reads its private ``~x``, which no launch file sets: a setting one namespace too
        high (jackal's joystick YAML), where the node stays on its default. Not where a node
        of ``N`` whose interface is unknown may read ``x``."""
        namespace, _, last = name.rpartition(names.SEP)
        unseen = self.any(c for _n, ns, c in self.unknown if ns == namespace + names.SEP)
        setters = self.setters()
        for node_condition, node, node_location, reads, _every in readers:
            private = node + names.SEP + last
            if node.rpartition(names.SEP)[0] != namespace or private not in reads:
                continue
            unset = ~self.any(c for set_name, c in setters if _covers(set_name, private))
            self.add(
                Check.PARAM_UNREAD,
                Severity.WARNING,
                name,
                f"{name} is set where no launched node reads it, beside {node}, which reads "
                f"~{last} ({private}) and finds it unset",
                condition & node_condition & unset & ~unseen,
                (location, node_location),
            )

    def remaps(self, interfaces: Interfaces) -> None:
        """A node's own ``<remap>`` of a name it never uses (nor a name below it: an action's
        topics, a transport's), where its every use is known: read off the workspace's
        sources, each name static. The remap renames nothing, so the node keeps its own
        name (a typo, or the name another node uses)."""
        for node in self.model.nodes:
            own = [r for r in node.remaps if r.location is not None and isinstance(r.source, str)]
            if node.is_test or not own:
                continue
            for condition, launched, interface, static in launched_units(
                self.space, node, interfaces
            ):
                entries = interface.entries
                known = read_off_sources(entries) and all(e.named_by is None for e in entries)
                if not static or not known or not any(e.role in CHANNEL for e in entries):
                    continue
                used = {launched.resolve(e.name) for e in entries}
                used |= {
                    camera_info_beside(launched.resolve(e.beside))
                    for e in entries
                    if e.beside is not None
                }
                for remap in own:
                    source = launched.resolve(str(remap.source))
                    if any(source == u or source.startswith(u + names.SEP) for u in used):
                        continue
                    near = nearest(source, used)
                    target = remap.target if isinstance(remap.target, str) else "…"
                    self.add(
                        Check.REMAP_UNUSED,
                        Severity.WARNING,
                        source,
                        f"{launched.full_name} never uses {source}: its remap to {target} "
                        "renames nothing" + (f" (it uses {near})" if near else ""),
                        condition & remap.condition,
                        (remap.location or node.location, node.location),
                    )

    def dialects(self, interfaces: Interfaces) -> None:
        """The checks its nodes' dialect adds (:data:`MODEL_CHECKS`)."""
        versions = {node.schema.version for node in self.model.nodes}
        for version in sorted(versions):
            for check in MODEL_CHECKS.get(version, ()):
                for found in check(self.space, self.model, interfaces, self.confinement):
                    self.add(
                        found.check,
                        found.severity,
                        found.name,
                        found.message,
                        found.condition,
                        found.locations,
                    )

    def whens(self, interfaces: Interfaces) -> None:
        """Hinted entries kept where their ``when:`` reads a parameter whose value analysis
        cannot know (unset without a default, a typed text, an unknown ``<rosparam>``)."""
        values = ParamValues(self.space, [(self.space.true, self.model)])
        for node in self.model.nodes:
            if node.is_test:
                continue
            for condition, launched, interface, _static in launched_units(
                self.space, node, interfaces
            ):
                for entry in interface.entries:
                    if entry.when is None or not params_read(entry.when):
                        continue
                    when = entry_when(values, node, launched, interface, entry.when)
                    self.add(
                        Check.WHEN_UNKNOWN,
                        Severity.NOTE,
                        entry.name,
                        f"{launched.full_name} {entry.role} {entry.name} when {entry.when}, "
                        f"but {'; '.join(when.reasons)}: kept",
                        condition & when.unknown,
                        (node.location, entry.location),
                    )

    def setters(self) -> list[tuple[str, BDD]]:
        return setters(self.model, self.confinement)

    def set_params(self) -> list[tuple[str, BDD, Location]]:
        return set_params(self.model, self.confinement)

    def _set_elsewhere(self, name: str) -> str:
        """Where other entry files of the workspace set the parameter ``name`` (or a namespace
        around it): launch files meant to run together, one loading the robot description."""
        files = set()
        for (role, set_name), found in self.partners.items():
            if role is Role.PARAMS and _covers(set_name, name):
                files |= found
        files.discard(self.model.file)
        if not files:
            return ""
        first, *more = sorted(files)
        return f" here ({os.path.basename(first)}{f' and {len(more)} more' if more else ''} does)"


def setters(model: LaunchModel, confinement: Confinement) -> list[tuple[str, BDD]]:
    """The parameter names the ``<param>``s and ``<rosparam>``s of ``model`` set, each with
    its condition (a ``<rosparam>`` known only per configuration: its namespace)."""
    return [(name, condition) for name, condition, _ in set_params(model, confinement)]


def set_params(model: LaunchModel, confinement: Confinement) -> list[tuple[str, BDD, Location]]:
    """:func:`setters` with where each is set."""
    found: list[tuple[str, BDD, Location]] = []
    for param in model.params:
        where = param.location
        if isinstance(param, ParamDecl):
            found.extend(
                (name, param.condition & c, where)
                for c, name in param.name
                if isinstance(name, str)
            )
        else:
            found.extend((name, param.condition, where) for name in _yaml_names(param, confinement))
    return found


def _unknown_nodes(
    space: ConditionSpace, model: LaunchModel, interfaces: Interfaces
) -> list[tuple[str, str, BDD]]:
    """The nodes of ``model`` whose interface is unknown: full name, namespace, condition."""
    found = []
    for node in model.nodes:
        for condition, launched, _values in node_branches(space, node):
            unit = launched.unit()
            if not node.is_test and unit is not None and find_interface(interfaces, unit) is None:
                namespace = names.make_global_ns(launched.namespace)
                found.append((launched.full_name, namespace, condition))
    return found


_UNRESOLVED = re.compile(r"\{[^{}]*\}")
"""The parts of a symbolic name rosvar could not resolve (``/{topic_name}``)."""


def _may_be(symbolic: str, name: str) -> bool:
    """Whether a symbolic name can be ``name``: its known parts in place, each unresolved
    part any non-empty text."""
    known = _UNRESOLVED.split(symbolic)
    pattern = ".+".join(re.escape(part) for part in known)
    return re.fullmatch(pattern, name) is not None


def _nodes(edges: Sequence[Edge]) -> str:
    return ", ".join(sorted({e.node for e in edges}))


def nearest(name: str, used: Iterable[str]) -> str | None:
    """The used name whose last part is closest to ``name``'s (a typo, or the right name in
    another namespace)."""
    last = {u.rsplit(names.SEP, 1)[-1]: u for u in sorted(used)}
    near = difflib.get_close_matches(name.rsplit(names.SEP, 1)[-1], list(last), n=1)
    return last[near[0]] if near else None


def read_off_sources(entries: Iterable[Entry]) -> bool:
    """Whether rosvar knows these uses exactly: each read off the workspace's sources (a
    catalogue entry may list only the ones that matter) and each name static."""
    return all(e.static and e.origin is Origin.SOURCE for e in entries)


def _reads(reads: Iterable[str], name: str) -> bool:
    return any(_covers(read, name) for read in reads)


def _covers(set_name: str, read: str) -> bool:
    return set_name == read or read.startswith(set_name + "/") or set_name.startswith(read + "/")


def _yaml_names(param: YamlDecl, confinement: Confinement) -> list[str]:
    """The names a ``<rosparam>`` sets, when all its parts are known; else the namespace it
    loads into, which then counts as setting everything below it."""
    parts = [param.scope_ns, param.command, param.ns, param.file, param.param, param.text]
    known = [part for part in parts if part is None or isinstance(part, str)]
    if len(known) == len(parts):
        scope_ns, command, ns, file, name, text = known
        try:
            pairs = param.load(str(command), ns, file, name, str(text), str(scope_ns), confinement)
        except ValueError:
            return []
        return [names.canonicalize_name(key) for key, _ in pairs]
    scope = param.scope_ns if isinstance(param.scope_ns, str) else names.SEP
    return [names.canonicalize_name(scope)]


def _readers(
    space: ConditionSpace, model: LaunchModel, interfaces: Interfaces
) -> Iterator[tuple[BDD, str, Location, list[str], bool]]:
    """Per branch of each ROS 1 node with a known interface: its condition, full name and
    place, the parameters it reads (resolved, static names), and whether those are all it
    reads: every read static, and all read off the workspace's sources."""
    for node in model.nodes:
        if node.is_test:
            continue
        for condition, launched, interface, static in launched_units(space, node, interfaces):
            if not static or launched.ros2:
                continue
            params = interface.of(Role.PARAMS)
            every = read_off_sources(params) and any(
                e.origin is Origin.SOURCE for e in interface.entries
            )
            reads = [launched.resolve(e.name) for e in params if e.static]
            yield condition, launched.full_name, node.location, reads, every


def _param_reads(
    space: ConditionSpace, node: NodeDecl, interfaces: Interfaces
) -> list[tuple[str, BDD, list[tuple[str, Location]]]]:
    """Per branch of a node's fields: its name, condition and the params it reads without
    a default (nodes and names known statically only)."""
    return [
        (
            launched.full_name,
            condition,
            [
                (launched.resolve(e.name), e.location)
                for e in interface.of(Role.PARAMS)
                if e.default is None and e.static
            ],
        )
        for condition, launched, interface, static in launched_units(space, node, interfaces)
        if static and not launched.ros2  # ROS 2's parameters are the node's own, not global
    ]
