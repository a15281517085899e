"""The one door to ``dd`` and the CUDD library it wraps.

Every other module uses BDDs through their operators (``& | ~``, ``==``) and ``dd``'s public
methods (``var``, ``ite``, ``dag_size``, …); whatever reaches further — creating a manager,
bounding its memory, CUDD's restrict and and-abstract, and every walk over the nodes
(complement marks, children, levels) — is here, once: cofactors, supports, evaluation under
an assignment, copies between managers, conjunction by levels, and the reading of a BDD's
nodes for an exact weighted count (``read``) and for the values each variable can take.

``read`` takes the nodes out of CUDD's memory, in the layout of the CUDD build that ``dd``
0.6.0 ships (CUDD 3.0.0), which ``dd`` does not promise to keep: ``pyproject.toml`` pins that
version of ``dd`` for it, and ``_indices`` checks the layout before every read. ``meets``,
``collect_garbage`` and ``held_nodes`` call CUDD functions ``dd`` does not wrap, on the
manager's pointer read out of ``dd``'s object (``_pointer`` checks that layout on every
call).
"""

from __future__ import annotations

import ctypes
import os
import sys
from collections.abc import Callable, Collection, Container, Iterable, Iterator, Mapping, Sequence
from contextlib import contextmanager
from functools import cache
from typing import Any, NamedTuple, Protocol, cast

import dd.cudd as _cudd

from rosvar.memo import Memo


class BDD(Protocol):
    """A diagram of ``dd.cudd`` (``dd.cudd.Function``) as rosvar uses it: ``dd`` ships no
    type information, and without one every condition would go unchecked."""

    @property
    def var(self) -> str | None:
        """The top variable (None at a constant)."""

    @property
    def low(self) -> BDD:
        """The low child of the regular node."""

    @property
    def high(self) -> BDD:
        """The high child of the regular node."""

    @property
    def negated(self) -> bool:
        """Whether the edge to the node is complemented."""

    @property
    def level(self) -> int: ...

    @property
    def bdd(self) -> Manager:
        """The manager the diagram lives in."""

    @property
    def dag_size(self) -> int: ...

    def __and__(self, other: BDD, /) -> BDD: ...

    def __or__(self, other: BDD, /) -> BDD: ...

    def __invert__(self) -> BDD: ...

    def __eq__(self, other: object, /) -> bool: ...

    def __hash__(self) -> int: ...

    def __int__(self) -> int:
        """The address of the node in CUDD's memory (``read`` walks it)."""

    def __len__(self) -> int:
        """The nodes of the diagram."""


class Manager(Protocol):
    """A ``dd.cudd`` manager (``dd.cudd.BDD``) as rosvar uses it."""

    @property
    def true(self) -> BDD: ...

    @property
    def false(self) -> BDD: ...

    @property
    def vars(self) -> Collection[str]:
        """The declared variables."""

    def var(self, name: str, /) -> BDD: ...

    def declare(self, *names: str) -> None: ...

    def insert_var(self, name: str, level: int, /) -> None: ...

    def level_of_var(self, name: str, /) -> int: ...

    def var_at_level(self, level: int, /) -> str: ...

    def ite(self, g: BDD, u: BDD, v: BDD, /) -> BDD: ...

    def cube(self, values: Mapping[str, bool], /) -> BDD: ...

    def support(self, u: BDD, /) -> set[str]: ...

    def configure(self, **settings: object) -> dict[str, Any]: ...

    # ``dd``'s own answers, which the tests take as references for rosvar's walks
    def apply(self, op: str, u: BDD, v: BDD | None = None, /) -> BDD: ...

    def let(self, definitions: Mapping[str, bool], u: BDD, /) -> BDD: ...

    def exist(self, qvars: Collection[str], u: BDD, /) -> BDD: ...

    def count(self, u: BDD, /, nvars: int | None = None) -> float: ...

    def statistics(self) -> dict[str, Any]: ...

    def __len__(self) -> int:
        """The nodes the manager holds."""


Weight = tuple[int, int]  # (weight of false, weight of true)


def new_manager(memory: int, cache_limit: int, initial_cache: int | None = None) -> Manager:
    """A manager told to expect ``memory`` bytes, whose computed table starts with
    ``initial_cache`` entries (None: CUDD's default) and never grows past ``cache_limit``.

    Dynamic reordering is off: every caller declares its variables in an order chosen for
    its formulas, and reordering would cost more than it saves, quadratically in the
    variables.
    """
    manager: Manager = _cudd.BDD(memory, initial_cache)
    manager.configure(reordering=False, max_cache_hard=cache_limit)
    return manager


def _names(manager: Manager) -> dict[int, str]:
    """The variables' names by CUDD index: ``dd`` keeps them in a private table."""
    names: dict[int, str] = cast(Any, manager)._var_with_index
    return names


class OutOfMemory(Exception):
    """CUDD refused to grow past the bound of :func:`memory_bound`."""


@contextmanager
def memory_bound(manager: Manager, budget: int) -> Iterator[None]:
    """Operations in ``manager`` within ``budget`` bytes, or :class:`OutOfMemory`.

    Past the bound CUDD returns NULL, which ``dd`` reports as a ValueError (operators) or a
    RuntimeError (``apply`` and the like), told from other errors by their text. The bound
    is lifted afterwards: later questions must not fail on what was built within it.
    """
    unbounded = manager.configure(max_memory=budget)["max_memory"]
    try:
        yield
    except (ValueError, RuntimeError) as error:
        if not any(sign in str(error) for sign in ("NULL", "out of memory")):
            raise
        raise OutOfMemory(f"its BDD outgrew {budget >> 20} MB") from error
    finally:
        manager.configure(max_memory=unbounded)


def restrict(u: BDD, care: BDD) -> BDD:
    """A function agreeing with ``u`` wherever ``care`` holds, usually smaller (CUDD's
    restrict, Coudert and Madre's generalised cofactor)."""
    restricted: BDD = _cudd.restrict(u, care)
    return restricted


def meets(u: BDD, v: BDD) -> bool:
    """Some assignment satisfies both ``u`` and ``v``: ``u ≤ ¬v`` refuted by CUDD's
    ``Cudd_bddLeq``, which builds no node and stops at the first path the two share.

    ``dd`` wraps no such test. Its and-abstract answers it too, but builds the cube of the
    quantified variables first through every variable of the manager (most of the time a
    clash judgement took on a workspace of a thousand variables); the conjunction itself
    is as large as the larger diagram."""
    manager = u.bdd
    if v.bdd is not manager:
        raise ValueError("the diagrams of two managers never meet")
    return not _library().Cudd_bddLeq(_pointer(manager), int(u) - 2, (int(v) - 2) ^ 1)


def collect_garbage(manager: Manager) -> None:
    """Free the nodes nothing references any more (CUDD's ``cuddGarbageCollect``, its
    computed table cleared), which ``dd`` does not wrap: CUDD collects them itself only
    once they outnumber a share of its unique table, and meanwhile new nodes take new
    memory, which CUDD never gives back."""
    _library().cuddGarbageCollect(_pointer(manager), 1)


def held_nodes(manager: Manager) -> int:
    """The nodes CUDD holds, the dead ones not collected yet included (``len`` counts the
    live ones only): what its memory grows with."""
    held: int = _library().Cudd_ReadKeys(_pointer(manager))
    return held


@cache
def _library() -> ctypes.PyDLL:
    """``dd``'s build of CUDD, whose functions are called with the GIL held (a ``PyDLL``):
    nothing else may run in the manager meanwhile."""
    library = ctypes.PyDLL(_cudd.__file__)
    library.Cudd_bddLeq.argtypes = [ctypes.c_void_p, ctypes.c_void_p, ctypes.c_void_p]
    library.Cudd_bddLeq.restype = ctypes.c_int
    library.cuddGarbageCollect.argtypes = [ctypes.c_void_p, ctypes.c_int]
    library.cuddGarbageCollect.restype = ctypes.c_int
    library.Cudd_ReadKeys.argtypes = [ctypes.c_void_p]
    library.Cudd_ReadKeys.restype = ctypes.c_uint
    return library


def _pointer(manager: Manager) -> int:
    """The ``DdManager *`` of a ``dd`` manager, read out of the object ``dd`` 0.6.0's Cython
    lays out as: the object's header (two words), its method table, the manager, then
    ``vars``, ``_index_of_var`` and ``_var_with_index`` (checked against their ids)."""
    words = _memory()
    at = id(manager) >> 3
    fields = cast(Any, manager)
    if (words[at + 4], words[at + 5], words[at + 6]) != (
        id(fields.vars),
        id(fields._index_of_var),
        id(fields._var_with_index),
    ):
        raise RuntimeError("dd lays its manager out otherwise than rosvar reads it")
    return words[at + 3]


def cofactors(u: BDD) -> tuple[BDD, BDD]:
    """The low and high cofactors of ``u`` by its top variable (``dd`` gives the children of
    its regular node, which a complemented ``u`` negates)."""
    low, high = u.low, u.high
    return (~low, ~high) if u.negated else (low, high)


def complemented(u: BDD) -> bool:
    """Whether ``u`` is the complement of its node (CUDD marks the edge, not the node)."""
    return bool(u.negated)


def regular(u: BDD) -> BDD:
    """The node of ``u``: ``u`` without its complement mark."""
    return ~u if u.negated else u


def cofactor(u: BDD, values: Mapping[str, bool]) -> BDD:
    """``u`` with the variables of ``values`` fixed, in time linear in the size of ``u``.

    CUDD's restrict to the cube of ``values``, which is the cofactor when the care set is a
    cube: ``dd``'s ``let`` spends several times longer making a cube of its own, over every
    variable of the manager.
    """
    if not values:
        return u
    cofactored: BDD = _cudd.restrict(u, cube(u.bdd, values))
    return cofactored


Literals = frozenset[tuple[str, bool]]


class Cubes:
    """The cubes of sets of literals in one manager, remembered (a bounded memo), and the
    cofactors by them: the conditions a step of the configuration engine restricts by their
    decided variables share a few sets of them (on Husky, 2,000 cofactors by 7 sets in one
    click), and building the cube was most of a cofactor."""

    def __init__(self, manager: Manager, capacity: int = 1024) -> None:
        self.manager = manager
        self._cubes: Memo[Literals, BDD] = Memo(capacity)

    def of(self, literals: Literals) -> BDD:
        """The conjunction of ``literals`` (``cube``)."""
        found = self._cubes.get(literals)
        if found is None:
            found = self._cubes[literals] = cube(self.manager, dict(literals))
        return found

    def cofactor(self, u: BDD, literals: Literals) -> BDD:
        """``u`` with the variables of ``literals`` fixed (``cofactor``)."""
        if not literals:
            return u
        cofactored: BDD = _cudd.restrict(u, self.of(literals))
        return cofactored


def cube(manager: Manager, values: Mapping[str, bool]) -> BDD:
    """The conjunction of the literals ``values``, from the deepest one up: each literal is
    then a node above the others, where in any order a conjunction rebuilt the part of the
    cube above its literal (a decided file's hundred literals took twice as long). ``dd``'s
    own ``cube`` walks every variable of the manager."""
    found = manager.true
    for name in sorted(values, key=manager.level_of_var, reverse=True):
        atom = manager.var(name)
        found &= atom if values[name] else ~atom
    return found


def evaluate(u: BDD, value: Callable[[str], object]) -> bool:
    """The truth of ``u`` where each variable ``x`` is ``value(x)`` (truthy or not): one path
    from the root down (the children are those of the regular node, so complement marks are
    counted).

    The one walker for every assignment, whether names to truths (the interpreter's
    configurations) or bit masks (the configuration engine's witnesses): the paths are
    short (most under five nodes on Husky), so a walk of CUDD's memory, which needs no
    ``dd`` object per node, saved 5 % on bit masks and lost 20 % on names, a Python call
    per node to map CUDD's index to a name (docs/performance.md)."""
    flipped = False
    while (name := u.var) is not None:
        flipped ^= bool(u.negated)
        u = u.high if value(name) else u.low
    return (not u.negated) != flipped  # the constant node is TRUE


def children_first(
    root: BDD, children: Callable[[BDD], Iterable[BDD]], done: Container[BDD]
) -> Iterator[BDD]:
    """The nodes under ``root`` not in ``done``, each after its ``children``; the caller adds
    each node it is given to ``done``. An explicit stack: no recursion limit."""
    stack = [root]
    while stack:
        node = stack[-1]
        if node in done:
            stack.pop()
            continue
        pending = [child for child in children(node) if child not in done]
        if pending:
            stack.extend(pending)
            continue
        stack.pop()
        yield node


def walked_support(u: BDD) -> set[str]:
    """The variables ``u`` depends on, found by visiting its nodes: linear in ``u``'s size,
    where ``dd``'s ``support`` walks every variable of its manager in Python. The nodes
    are read in CUDD's memory, as ``layout`` reads them: a ``dd`` wrapper per child cost
    several times the walk."""
    manager = u.bdd
    words = _memory()
    true = int(manager.true) - 2
    seen = {true}
    indices: set[int] = set()
    stack = [(int(u) - 2) & ~1]
    while stack:
        node = stack.pop()
        if node in seen:
            continue
        seen.add(node)
        at = node >> 3
        indices.add(words[at] & 0xFFFFFFFF)
        stack.append(words[at + 2])  # then: never complemented
        stack.append(words[at + 3] & ~1)
    if len(seen) > 1 and not _LAYOUT_CHECKED:
        _check_layout(manager, ((int(u) - 2) & ~1) >> 3, words)
    name_of = _names(manager)
    return {name_of[index] for index in indices}


class Layout(NamedTuple):
    """A BDD's nodes in the order a walk from the root first meets them (low child first):
    each one's variable and level, and its low and high edges as references ``2 · place +
    complemented``, where place 0 is the constant TRUE and node ``i`` of the lists is place
    ``i + 1``; and the root's reference. Two BDDs with equal references and equal variables
    node for node are the same function; with equal references alone, the same function up
    to a renaming of the variables."""

    names: list[str]
    levels: list[int]
    lows: list[int]
    highs: list[int]
    root: int


def layout(u: BDD) -> Layout:
    """The :class:`Layout` of ``u``, in time linear in its size, read in CUDD's memory as
    ``read`` does (a ``dd`` wrapper per child cost several times the walk)."""
    manager = u.bdd
    words = _memory()
    true = int(manager.true) - 2
    pointer = int(u) - 2
    places = {true: 0}
    found: list[int] = []  # the nodes' word offsets
    stack = [pointer & ~1]
    while stack:
        node = stack.pop()
        if node in places:
            continue
        places[node] = len(places)
        at = node >> 3
        found.append(at)
        stack.append(words[at + 2])  # then: never complemented
        stack.append(words[at + 3] & ~1)
    if found and not _LAYOUT_CHECKED:
        _check_layout(manager, found[0], words)
    lows = []
    for at in found:
        low = words[at + 3]
        lows.append(2 * places[low & ~1] + (low & 1))
    name_of = _names(manager)
    names = [name_of[words[at] & 0xFFFFFFFF] for at in found]
    level_of = manager.level_of_var
    return Layout(
        names,
        [level_of(name) for name in names],
        lows,
        [2 * places[words[at + 2]] for at in found],
        2 * places[pointer & ~1] + (pointer & 1),
    )


_LAYOUT_CHECKED = False  # once one node passed: the layout is CUDD's, the same for all


def _check_layout(manager: Manager, at: int, words: memoryview) -> None:
    """Check the layout ``layout`` reads on one of its nodes (``_indices`` explains it)."""
    global _LAYOUT_CHECKED
    name = _names(manager)[words[at] & 0xFFFFFFFF]
    true = int(manager.true) - 2
    node = (int(manager.var(name)) - 2) >> 3
    if (words[node] & 0xFFFFFFFF, words[node + 2], words[node + 3]) != (
        words[at] & 0xFFFFFFFF,
        true,
        true ^ 1,
    ):
        raise RuntimeError("dd's CUDD lays its nodes out otherwise than rosvar reads them")
    _LAYOUT_CHECKED = True


def transfer(
    u: BDD, target: Manager, hidden: Collection[str] = (), copies: dict[BDD, BDD] | None = None
) -> BDD:
    """``∃ hidden. u`` rebuilt in ``target``, which declares the rest of its support, in time
    linear in the size of ``u``.

    ``dd``'s ``copy_bdd`` checks each support variable against ``target.vars``, a set it
    rebuilds from every declared variable on each access, and its ``exist`` builds a cube
    over every variable of the manager: both cost the managers' whole variable counts per
    call, which made building the feature model's solver quadratic in the workspace.

    Functions are rebuilt before the functions above them, so a node on a ``hidden``
    variable becomes the disjunction of its cofactors' copies, which no longer depend on
    it. Quantification does not commute with negation, so a complemented edge is its own
    function here, with its own cofactors.

    ``copies`` (from the same manager to ``target``, with the same ``hidden``) is kept
    from call to call by callers that copy many diagrams sharing parts: each part is
    then copied once.
    """
    source = u.bdd
    if copies is None:
        copies = {}
    copies.setdefault(source.true, target.true)
    copies.setdefault(source.false, target.false)
    for function in children_first(u, cofactors, copies):
        low, high = cofactors(function)
        name = function.var
        assert name is not None  # the constants are copied already
        copies[function] = (
            copies[high] | copies[low]
            if name in hidden
            else target.ite(target.var(name), copies[high], copies[low])
        )
    return copies[u]


def conjoin(manager: Manager, parts: Sequence[BDD]) -> BDD:
    """Conjunction scheduled from the bottom of the order up, by each part's top variable.

    Each intermediate result is then the conjunction of every part lying below some
    level, never a part reaching far up without those that prune it — the result
    does not grow beyond the final diagram's width (ordering by the deepest
    variable instead made intermediate results many times the final one).

    The parts sharing a top variable are conjoined first, among themselves: a conjunction
    walks the result down from that variable, once for them all instead of once each.
    """
    result = manager.true
    group = manager.true
    level = None
    for part in _bottom_up(manager, parts):
        top = _top(manager, part)
        if top != level:
            result &= group
            group, level = part, top
        else:
            group &= part
    return result & group


def conjoin_within(manager: Manager, parts: Sequence[BDD], nodes: int) -> BDD | None:
    """``conjoin``, or None once the conjunction grows past ``nodes`` nodes (looked at every
    ``SIZE_CHECKS`` parts): tells a diagram too large to use without building all of it."""
    result = manager.true
    for number, part in enumerate(_bottom_up(manager, parts), start=1):
        result &= part
        if number % SIZE_CHECKS == 0 and result.dag_size > nodes:
            return None
    return None if result.dag_size > nodes else result


SIZE_CHECKS = 32


def _bottom_up(manager: Manager, parts: Sequence[BDD]) -> list[BDD]:
    """``parts`` by their top variable, deepest first (``conjoin``'s schedule)."""
    return sorted(parts, key=lambda part: _top(manager, part), reverse=True)


def _top(manager: Manager, part: BDD) -> int:
    """The level of ``part``'s top variable (its root's); -1 for a constant."""
    return -1 if part in (manager.true, manager.false) else int(part.level)


# -- the nodes of a BDD as plain lists, read in CUDD's memory ------------------------------------


class Nodes(NamedTuple):
    """A BDD's nodes, children first after the constant TRUE (place 0): each one's level, low
    and high child (places; a complemented edge as ``~place``); and the root's place
    (complemented likewise). The level of TRUE is the manager's number of variables.

    ``arrays``: the three lists as numpy arrays when numpy read them (``_by_levels``, a
    level after the other): what goes through them a level at a time (``taken``, the
    count's ``_evaluated``) then takes them as they are, where converting each list
    again cost about as much as reading it."""

    levels: list[int]
    lows: list[int]
    highs: list[int]
    root: int
    arrays: tuple[Any, Any, Any] | None = None


READ_BY_LEVELS_FROM = 100_000
"""Nodes from which ``read`` takes a diagram level by level in numpy: below, numpy's import
costs more time and memory than it saves (docs/performance.md)."""


def read(manager: Manager, u: BDD, levels: Collection[int]) -> Nodes:
    """The nodes of ``u``, whose support lies within ``levels``.

    The nodes are read in CUDD's memory (``_memory``, layout checked by ``_indices``),
    not through ``dd``'s wrappers: a wrapper per child (a Python object, a reference
    taken and dropped) made reading a node cost twice its arithmetic. Safe while
    ``u`` is referenced, since nothing runs in CUDD meanwhile: its nodes can be
    neither freed nor moved. ``int`` of a ``dd`` function is its pointer plus 2, and
    CUDD marks a complemented edge in the pointer's lowest bit (``then`` edges never
    are). A large diagram is read a level at a time (``_by_levels``), a small one node
    by node (``_Reader``).
    """
    if u.dag_size >= READ_BY_LEVELS_FROM:
        return _by_levels(manager, u, levels)
    reader = _Reader(_indices(manager, levels), int(manager.true) - 2, len(manager.vars))
    pointer = int(u) - 2
    negated = pointer & 1
    root = reader.found.get(pointer ^ negated)
    if root is None:
        limit = sys.getrecursionlimit()
        sys.setrecursionlimit(limit + len(levels))
        try:
            root = reader.visit(pointer ^ negated)
        finally:
            sys.setrecursionlimit(limit)
    root = ~root if negated else root
    return Nodes(reader.levels, reader.lows, reader.highs, root)


@cache
def _memory() -> memoryview:
    """The process's memory as 64-bit words, for reading CUDD's nodes where they lie.

    Only the words of live nodes are ever read (``read``): the view maps no memory
    of its own, it only spares a ``ctypes`` call per read.
    """
    everything = (ctypes.c_uint64 * (sys.maxsize // 8)).from_address(0)
    return memoryview(everything).cast("B").cast("Q")


def _indices(manager: Manager, levels: Iterable[int]) -> dict[int, int]:
    """CUDD's index of each level's variable, read off its node ``x ? TRUE : FALSE``, which
    also checks the layout ``read`` relies on: a CUDD node is its variable's index (32 bits,
    then the reference count's), the next node in its hash chain, then its ``then`` and
    ``else`` children (64-bit pointers)."""
    words = _memory()
    true = int(manager.true) - 2
    found = {}
    for level in levels:
        node = (int(manager.var(manager.var_at_level(level))) - 2) >> 3
        if (words[node + 2], words[node + 3]) != (true, true ^ 1):
            raise RuntimeError("dd's CUDD lays its nodes out otherwise than rosvar reads them")
        found[words[node] & 0xFFFFFFFF] = level
    return found


def without_blas_threads() -> None:
    """Called before numpy is imported, which rosvar leaves to the first need (its import is
    slow, and every command would otherwise pay for it at start-up): only its element-wise
    integer operations are used, so its BLAS is kept from starting a worker thread per
    core."""
    os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")


def _by_levels(manager: Manager, u: BDD, levels: Collection[int]) -> Nodes:
    """``read`` with numpy, from the top level down: every parent of a node lies above
    it, so when a level is reached all its nodes are known, gathered from the children
    of the levels above. Each level is one batch of array operations, where ``_Reader``
    spends a Python call per node; the nodes are listed deepest level first."""
    without_blas_threads()
    import numpy as np

    words = _words()
    index_of = _indices(manager, levels)
    level_at = np.full(max(index_of, default=0) + 1, -1, dtype=np.int64)  # index → level
    for index, level in index_of.items():
        level_at[index] = level
    true = int(manager.true) - 2
    pointer = int(u) - 2
    negated = pointer & 1
    start = pointer ^ negated
    waiting: dict[int, list[Any]] = {}  # a level → arrays of (regular) addresses of its nodes
    if start != true:
        waiting[index_of[int(words[(start >> 3) - 1]) & 0xFFFFFFFF]] = [np.asarray([start])]
    found = []  # (level, its nodes' addresses, their then and else words), top level first
    for level in sorted(levels):
        batches = waiting.pop(level, None)
        if batches is None:
            continue
        nodes = np.unique(np.concatenate(batches))
        at = (nodes >> 3) - 1  # the index word of each node (``_words`` starts at 8)
        highs, lows = words[at + 2], words[at + 3]
        found.append((level, nodes, highs, lows))
        children = np.concatenate([highs, lows & ~1])
        children = children[children != true]
        below = level_at[words[(children >> 3) - 1] & 0xFFFFFFFF]
        by_level = np.argsort(below)
        below, children = below[by_level], children[by_level]
        cuts = (np.flatnonzero(below[1:] != below[:-1]) + 1).tolist()
        for first, end in zip([0, *cuts], [*cuts, len(children)], strict=True):
            if first < end:
                waiting.setdefault(int(below[first]), []).append(children[first:end])
    found.reverse()  # children first
    bottom = len(manager.vars)
    addresses = np.concatenate([np.asarray([true]), *(nodes for _, nodes, _, _ in found)])
    ranked = np.argsort(addresses)  # places by address, to find each child's place
    sorted_addresses = addresses[ranked]

    def places(edges: Any) -> Any:
        return ranked[np.searchsorted(sorted_addresses, edges)]

    all_highs = np.concatenate([np.zeros(1, dtype=np.int64)] + [h for _, _, h, _ in found])
    all_lows = np.concatenate([np.zeros(1, dtype=np.int64)] + [w for _, _, _, w in found])
    high_places = places(all_highs)
    low_places = places(all_lows & ~1)
    low_places = np.where(all_lows & 1, ~low_places, low_places)
    high_places[0] = low_places[0] = 0  # the constant's own children: none
    level_at = np.repeat(
        np.asarray([bottom, *(level for level, _, _, _ in found)], dtype=np.int64),
        [1, *(len(nodes) for _, nodes, _, _ in found)],
    )
    levels_listed = [bottom]  # each level one int object, not one per node as ``tolist``'s
    for level, nodes, _, _ in found:
        levels_listed += [level] * len(nodes)
    root = int(places(np.asarray([start]))[0])
    return Nodes(
        levels_listed,
        low_places.tolist(),
        high_places.tolist(),
        ~root if negated else root,
        (level_at, low_places, high_places),
    )


@cache
def _words() -> Any:
    """``_memory`` as a numpy array of 64-bit words, for reading many nodes at once; it
    starts at the address 8 (numpy takes an address 0 for no memory at all)."""
    import numpy as np

    everything = (ctypes.c_int64 * (sys.maxsize // 8 - 1)).from_address(8)
    return np.frombuffer(memoryview(everything), dtype=np.int64)


class _Reader:
    """``read``'s lists as they grow. A class, not a closure over ``read``'s locals: a
    recursive closure keeps them in a cycle only the collector frees, the manager
    included."""

    __slots__ = ("found", "highs", "level_of", "levels", "lows", "words")

    def __init__(self, level_of: dict[int, int], true: int, bottom: int) -> None:
        self.words = _memory()
        self.level_of = level_of  # a variable's index → its level
        self.found = {true: 0}  # regular node's address → its place
        self.levels, self.lows, self.highs = [bottom], [0], [0]

    def visit(self, node: int) -> int:
        """Place the node at address ``node`` after its children. Recursive, since a stack
        kept by hand was slower (the depth is at most the number of variables)."""
        words, found = self.words, self.found
        at = node >> 3
        low, high = words[at + 3], words[at + 2]
        negated = low & 1
        if negated:
            low ^= 1
        low_place = found.get(low)
        if low_place is None:
            low_place = self.visit(low)
        high_place = found.get(high)
        if high_place is None:
            high_place = self.visit(high)
        found[node] = place = len(self.levels)
        self.levels.append(self.level_of[words[at] & 0xFFFFFFFF])
        self.lows.append(~low_place if negated else low_place)
        self.highs.append(high_place)
        return place


def taken(
    levels: Sequence[int],
    lows: Sequence[int],
    highs: Sequence[int],
    root: int,
    level_of: Mapping[str, int],
    arrays: tuple[Any, Any, Any] | None = None,
) -> dict[str, set[bool]]:
    """For each variable of ``level_of`` (``read``'s levels, covering the diagram's support),
    the values it takes in some assignment satisfying the diagram ``levels, lows, highs,
    root`` (as ``read`` gives it): those of the edges from its nodes to anything but
    FALSE, and both where a path to TRUE skips its level.

    One pass over the lists from the root down (``read`` lists children first), marking
    whether each node is reached as itself, as its complement or both: every function
    but FALSE is satisfiable, so the polarity only tells whether an edge to the constant
    is one to FALSE: no stack, and no set of the (node, polarity) pairs seen. A diagram
    numpy read (``arrays``, as ``read`` gives them) is gone down a level at a time in numpy
    (``_reached_by_levels``)."""
    if not level_of:
        return {}
    top = min(level_of.values())
    bottom = max(level_of.values()) + 1
    if root == ~0:  # FALSE: nothing satisfies it
        return {name: set() for name in level_of}
    place = ~root if root < 0 else root
    polarity = 2 if root < 0 else 1
    if arrays is None:
        falses, trues, free = _reached(levels, lows, highs, place, polarity, top, bottom)
    else:
        falses, trues, free = _reached_by_levels(*arrays, place, polarity, top, bottom)
    values: dict[int, set[bool]] = {}
    running = 0
    for level in range(top, bottom):
        running += free[level - top]
        found = {False, True} if running > 0 else set()
        if falses[level - top]:
            found.add(False)
        if trues[level - top]:
            found.add(True)
        values[level] = found
    return {name: values[level] for name, level in level_of.items()}


Reached = tuple[Sequence[bool], Sequence[bool], Sequence[int]]
"""What ``taken`` gathers going down: per level from the top one, whether an edge of value
false (true) leaves it for a satisfiable child; and a difference array over the levels, +1
where the levels an edge skips begin and −1 past them."""


def _reached(
    levels: Sequence[int],
    lows: Sequence[int],
    highs: Sequence[int],
    root: int,
    polarity: int,
    top: int,
    bottom: int,
) -> Reached:
    """``taken``'s pass from the root (place ``root``, reached with ``polarity``) down, a
    node at a time."""
    falses = [False] * (bottom - top)  # levels with an edge of that value to a satisfiable child
    trues = [False] * (bottom - top)
    free = [0] * (bottom - top + 1)  # difference array over the levels some edge skips
    reached = bytearray(len(levels))  # per place: 1 reached as itself, 2 as its complement
    reached[root] = polarity
    free[0] += 1  # the levels above the root are free
    free[(levels[root] if root else bottom) - top] -= 1
    for place in range(len(levels) - 1, 0, -1):
        polarity = reached[place]
        if not polarity:
            continue
        here = levels[place] - top
        low, high = lows[place], highs[place]
        if high or polarity & 1:  # a then edge is never complemented: FALSE only as ~TRUE
            trues[here] = True
            free[here + 1] += 1
            free[(levels[high] if high else bottom) - top] -= 1
            reached[high] |= polarity
        if low < 0:
            low, polarity = ~low, (polarity & 1) << 1 | polarity >> 1
        if low or polarity & 1:
            falses[here] = True
            free[here + 1] += 1
            free[(levels[low] if low else bottom) - top] -= 1
            reached[low] |= polarity
    return falses, trues, free


def _reached_by_levels(
    levels: Any,
    lows: Any,
    highs: Any,
    root: int,
    polarity: int,
    top: int,
    bottom: int,
) -> Reached:
    """``_reached`` with numpy: the nodes of a level at once, from the top level down
    (every parent lies above its children, so a level's nodes are reached in full before
    it is gone down from)."""
    import numpy as np

    level_at = np.array(levels, dtype=np.int64)  # a copy:
    level_at[0] = bottom  # TRUE's level, as the free levels count it
    low_at, high_at = lows, highs
    by_level = np.argsort(level_at[1:], kind="stable") + 1  # top level first
    cuts = np.flatnonzero(np.diff(level_at[by_level])) + 1
    falses, trues = [False] * (bottom - top), [False] * (bottom - top)
    reached = np.zeros(len(levels), dtype=np.uint8)
    reached[root] = polarity
    starts, ends = [np.asarray([top])], [level_at[root : root + 1]]  # levels above the root
    for places in np.split(by_level, cuts):
        found = reached[places]
        live = found != 0
        if not live.any():
            continue
        places, found = places[live], found[live]
        here = int(level_at[places[0]])
        highs_here = high_at[places]
        leaving = (highs_here != 0) | (found & 1 != 0)  # a then edge: FALSE only as ~TRUE
        if leaving.any():
            trues[here - top] = True
            np.bitwise_or.at(reached, highs_here[leaving], found[leaving])
            starts.append(np.full(np.count_nonzero(leaving), here + 1))
            ends.append(level_at[highs_here[leaving]])
        lows_here = low_at[places]
        negated = lows_here < 0
        lows_here = np.where(negated, ~lows_here, lows_here)
        found = np.where(negated, (found & 1) << 1 | found >> 1, found)
        leaving = (lows_here != 0) | (found & 1 != 0)
        if leaving.any():
            falses[here - top] = True
            np.bitwise_or.at(reached, lows_here[leaving], found[leaving])
            starts.append(np.full(np.count_nonzero(leaving), here + 1))
            ends.append(level_at[lows_here[leaving]])
    size = bottom - top + 1
    free = np.bincount(np.concatenate(starts) - top, minlength=size) - np.bincount(
        np.concatenate(ends) - top, minlength=size
    )
    return falses, trues, free.tolist()
