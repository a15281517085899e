"""Presence conditions in readable form: a short formula such as ``use_teleop=true ∧ ¬sim``.

A condition is printed modulo the facts of its space, as a prime and irredundant cover
(Minato–Morreale's, from the BDD) whose slot literals are grouped by input (``x∈{a,b}``,
``x≠c``). Conditions over the same variables share their facts, the ``<other>`` slots to
hide and the inputs' domains: :class:`Printer` computes those once per set of variables.
"""

from __future__ import annotations

import weakref
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass
from typing import NamedTuple, Protocol, cast

from rosvar.logic.atoms import PREDICATES, Atom, FileAtom, PredicateAtom, SlotAtom
from rosvar.logic.bdd import BDD, cofactors, layout, restrict
from rosvar.logic.inputs import OTHER, UNSET, ArgInput, EnvInput, Input, Slot
from rosvar.memo import Memo

BOOLEAN_WORDS = ("true", "false")
MAX_FULL = 200  # longer formulas over <other> values help nobody
MAX_CUBES = 256  # beyond this many disjuncts a formula is no longer readable
FULL_CUBES = MAX_FULL // 4  # a disjunct takes at least 4 characters (" ∨ " and a name)
TRUE_FOR_KNOWN = "true for every known value"
ENV_SET = "set"
"""An environment variable given any value (``$X set``): every slot but ``<unset>``."""
AND = "∧"
OR = " ∨ "

Domains = Mapping[Input, tuple[Slot, ...]]


class Space(Protocol):
    """What the printer reads of a condition space (``conditions.ConditionSpace``, which
    owns its printer): its constants, atoms, domains and facts."""

    @property
    def true(self) -> BDD: ...

    @property
    def false(self) -> BDD: ...

    def atom_of(self, name: str) -> Atom: ...

    def domain(self, input_: Input) -> tuple[Slot, ...]: ...

    def slot(self, input_: Input, slot: Slot) -> BDD: ...

    def support(self, u: BDD) -> set[str]: ...

    def facts(self) -> int: ...

    def facts_of(self, name: str) -> Sequence[BDD]: ...

    def care_over(self, variables: Iterable[str]) -> BDD: ...

    def care_key(self, variables: Iterable[str]) -> frozenset[object]: ...

    def care_inputs(self, variables: Iterable[str]) -> set[Input]: ...


class _TooComplex(Exception):
    """The condition has too many disjuncts to print usefully."""


@dataclass(frozen=True)
class _Context:
    """What describing a condition over some variables needs besides the condition."""

    care: BDD  # the facts over those variables
    domains: Domains  # of the inputs the facts involve
    known: BDD  # the atoms "arg x holds <other>" of those inputs, all false (a cube)
    known_care: BDD  # ``care`` with them false
    known_domains: Domains  # ``domains`` without the <other> slots of args


Shape = tuple[object, ...]  # what a description depends on (``Printer._shape``)


class _FactShape(NamedTuple):
    """A fact's diagram up to renaming, its variables' (block, place in the block), and
    where each block starts (``Printer._shape``)."""

    diagram: tuple[int, tuple[int, ...], tuple[int, ...]]
    blocks: tuple[int, ...]  # of its variables, node by node
    indices: tuple[int, ...]  # their places in their blocks
    starts: dict[int, int]


class Printer:
    """The readable form of the conditions of one space (``conditions.ConditionSpace.describe``)."""

    def __init__(self, space: Space) -> None:
        # the space owns its printer: a strong reference back would make a cycle, and the
        # cycle collector may free CUDD's manager before the diagrams in it
        self.space = weakref.proxy(space)
        self._contexts: dict[frozenset[object], _Context] = {}
        self._facts = space.facts()
        self._by_shape: Memo[Shape, str] = Memo()
        self._variables: dict[str, tuple[int, int, Sequence[BDD]]] = {}  # see _variable
        self._block_numbers: dict[object, int] = {}
        self._block_objects: list[object] = []
        self._shown_numbered: dict[bool, list[tuple[object, ...] | None]] = {
            False: [],
            True: [],
        }  # ``_shown_of``
        self._fact_shapes: dict[BDD, _FactShape] = {}

    def describe(self, condition: BDD, qualify: bool = False, known_only: bool = True) -> str:
        """A short readable formula, e.g. ``use_teleop=true ∧ ¬sim``, modulo validity.

        With ``known_only`` (the default) arg inputs are assumed to hold one of the
        values analysis knows, which hides the rarely useful ``<other>`` refinements;
        a condition that this view would show as ``true`` but that fails for some
        other value is shown in full when that is short.

        Conditions of the same shape read the same, and are described once: every file
        that includes another conjoins the other's conditions with its own, over its own
        inputs, so a workspace holds many copies of a few shapes. What two conjunctions
        answer is answered before the shape is computed: most conditions a click of the
        configurator restricts are false or hold for other values only, each of a shape
        met once (docs/performance.md).
        """
        space = self.space
        facts = space.facts()
        if facts != self._facts:  # what was read of the facts is stale
            self._contexts.clear()
            self._variables.clear()
            self._facts = facts
        if condition == space.false:
            return "false"
        context = self._context(frozenset(space.support(condition)))
        if (condition & context.care) == space.false:  # unsatisfiable
            return "false"
        known = restrict(condition, context.known) if known_only else None
        if known is not None and (known & context.known_care) == space.false:
            return "only for other values"
        shape = self._shape(condition, qualify, known_only)
        if shape is None:
            return self._describe(condition, qualify, context, known)
        text = self._by_shape.get(shape)
        if text is None:
            text = self._by_shape[shape] = self._describe(condition, qualify, context, known)
        return text

    def _shape(self, condition: BDD, qualify: bool, known_only: bool) -> Shape | None:
        """What the description of ``condition`` depends on, the same for every condition
        that reads the same; None when two of its inputs have the same name.

        The description depends on the diagrams of the condition and of the facts over its
        variables up to a renaming of the variables, the order of those variables and of the
        other slots of their inputs (which the facts and the ``<other>`` slots bring in),
        and what the printer shows of each variable: its input's kind, name and domain, its
        predicate or its file. An input's slots are consecutive levels in domain order
        (``ConditionSpace.declare_input``; predicates are inserted after the slots of the
        inputs they read), so a variable is placed by its input's *block* and its place in
        the block, and blocks are ranked by level. The facts, a set, are sorted.
        """
        nodes = layout(condition)
        starts: dict[int, int] = {}
        facts: dict[BDD, _FactShape] = {}
        variables = self._variables
        fact_shapes = self._fact_shapes
        placements = []
        for name, level in zip(nodes.names, nodes.levels, strict=True):
            found = variables.get(name) or self._variable(name)
            placements.append(found)
            starts[found[0]] = level - found[1]
            for fact in found[2]:
                if fact not in facts:
                    facts[fact] = fact_shapes.get(fact) or self._fact_shape(fact)
        for fact_shape in facts.values():
            starts.update(fact_shape.starts)
        order = sorted(starts, key=starts.__getitem__)
        rank = {block: position for position, block in enumerate(order)}
        shown = self._shown_of(order, qualify)
        if len({text for text, *_rest in shown}) != len(shown):
            return None
        ranked = rank.__getitem__
        placed = tuple((ranked(block), index) for block, index, _facts in placements)
        return (
            qualify,
            known_only,
            (nodes.root, tuple(nodes.lows), tuple(nodes.highs), placed),
            tuple(
                sorted(
                    {
                        (*f.diagram, tuple(zip(map(ranked, f.blocks), f.indices, strict=True)))
                        for f in facts.values()
                    }
                )
            ),
            shown,
        )

    def _variable(self, name: str) -> tuple[int, int, Sequence[BDD]]:
        """Variable ``name``'s block (its input, or its own atom, by number), its place in the
        block and its facts."""
        space = self.space
        atom = space.atom_of(name)
        block: object = atom
        index = 0
        if isinstance(atom, SlotAtom):
            block = atom.input
            index = space.domain(atom.input).index(atom.slot)
        number = self._block_numbers.setdefault(block, len(self._block_numbers))
        if number == len(self._block_objects):
            self._block_objects.append(block)
        found = self._variables[name] = (number, index, tuple(space.facts_of(name)))
        return found

    def _fact_shape(self, fact: BDD) -> _FactShape:
        """What ``_shape`` reads of a fact, the same for every condition it is a fact of."""
        nodes = layout(fact)
        blocks = []
        indices = []
        starts = {}
        for name, level in zip(nodes.names, nodes.levels, strict=True):
            block, index, _facts = self._variables.get(name) or self._variable(name)
            blocks.append(block)
            indices.append(index)
            starts[block] = level - index
        found = self._fact_shapes[fact] = _FactShape(
            (nodes.root, tuple(nodes.lows), tuple(nodes.highs)),
            tuple(blocks),
            tuple(indices),
            starts,
        )
        return found

    def _shown_of(self, blocks: Sequence[int], qualify: bool) -> tuple[tuple[object, ...], ...]:
        """``_shown`` of each of ``blocks``, remembered by block number (an input's hash
        is computed in Python, and this runs for every block of every condition)."""
        known = self._shown_numbered[qualify]
        if len(known) < len(self._block_objects):
            known.extend([None] * (len(self._block_objects) - len(known)))
        shown = []
        for block in blocks:
            found = known[block]
            if found is None:
                found = known[block] = self._shown(self._block_objects[block], qualify)
            shown.append(found)
        return tuple(shown)

    def _shown(self, block: object, qualify: bool) -> tuple[object, ...]:
        """What the printer reads of a block: its name, then what else it shows or uses."""
        if isinstance(block, FileAtom):
            return (f"file {block.label}",)
        if isinstance(block, PredicateAtom):
            return (f"{block.test} {block.term}",)
        input_ = cast(Input, block)
        file = input_.file if qualify and isinstance(input_, ArgInput) else ""
        return (str(input_), type(input_).__name__, file, self.space.domain(input_))

    def _describe(self, condition: BDD, qualify: bool, context: _Context, known: BDD | None) -> str:
        """The formula of a satisfiable ``condition`` over the variables of ``context``;
        ``known``: the condition with the args' values the analysis knows (``known_only``),
        which some of them take."""
        space = self.space
        care = context.care
        if known is None:
            return self._formula(condition, care, qualify, context.domains)
        known_care = context.known_care
        if (known_care & ~known) == space.false and (care & ~condition) != space.false:
            try:  # the full formula, if it is short: a long one is not worth computing
                return self._formula(
                    condition, care, qualify, context.domains, FULL_CUBES, MAX_FULL
                )
            except _TooComplex:
                return TRUE_FOR_KNOWN
        return self._formula(known, known_care, qualify, context.known_domains)

    def _context(self, variables: frozenset[str]) -> _Context:
        """The context of conditions over ``variables``, computed once for all conditions
        with the same facts (while the space's facts stay the same: ``describe``)."""
        space = self.space
        key = space.care_key(variables)
        found = self._contexts.get(key)
        if found is not None:
            return found
        care = space.care_over(variables)
        involved = space.care_inputs(variables)
        known = space.true
        for input_ in involved:
            if isinstance(input_, ArgInput):
                known &= ~space.slot(input_, OTHER)
        context = _Context(
            care,
            {input_: space.domain(input_) for input_ in involved},
            known,
            restrict(care, known),
            {
                input_: tuple(
                    s
                    for s in space.domain(input_)
                    if s is not OTHER or isinstance(input_, EnvInput)
                )
                for input_ in involved
            },
        )
        self._contexts[key] = context
        return context

    def _formula(
        self,
        condition: BDD,
        care: BDD,
        qualify: bool,
        domains: Domains,
        budget: int | None = None,
        longest: int | None = None,
    ) -> str:
        """``condition`` modulo ``care`` as a disjunction of cubes; with a ``budget`` of cubes,
        :class:`_TooComplex` past it, else a summary past :data:`MAX_CUBES`; with ``longest``,
        :class:`_TooComplex` as soon as the cubes rendered so far make the text longer (the
        rest is not rendered)."""
        space = self.space
        if (care & ~condition) == space.false:
            return "true"
        try:
            cubes = _cover(space, condition, care, domains, budget or MAX_CUBES)
        except _TooComplex:
            if budget is not None:
                raise
            support = space.support(restrict(condition, care))
            names = sorted({str(i) for i in _inputs_of(space, support)})
            shown = ", ".join(names[:6]) + (", …" if len(names) > 6 else "")
            return f"a condition over {len(names)} inputs ({shown})"
        rendered = []
        length = -len(OR)  # of the text below: each disjunct, parenthesised if a conjunction
        for cube in cubes:
            text = _render_cube(space, cube, qualify, domains)
            rendered.append(text)
            if longest is not None:
                length += len(text) + len(OR) + (2 if len(cubes) > 1 and AND in text else 0)
                if length > longest:
                    raise _TooComplex
        if len(rendered) == 1:
            return rendered[0]
        return OR.join(f"({r})" if AND in r else r for r in sorted(rendered))


def _inputs_of(space: Space, variables: Iterable[str]) -> set[Input]:
    return {
        atom.input
        for atom in (space.atom_of(name) for name in variables)
        if isinstance(atom, SlotAtom)
    }


Cube = dict[object, frozenset[Slot] | bool]  # an input's slots, or a predicate's or file's truth
Literals = tuple[tuple[str, bool], ...]  # a cube over the BDD's variables


def _cover(
    space: Space,
    target: BDD,
    care: BDD,
    domains: Domains,
    budget: int = MAX_CUBES,
) -> list[Cube]:
    """A prime and irredundant cover of ``target`` modulo ``care``, grouped by input.

    Minato–Morreale's irredundant sum of products of the interval [target ∧ care,
    target ∨ ¬care], computed on the BDD itself: its size follows the diagram's, not the
    number of paths through it. Slot literals are then grouped by input (``x=a``, or the
    slots left by ``¬x=b ∧ ¬x=c``), and cubes that differ in one input's slots merged
    (``x=a ∨ x=b`` → ``x∈{a,b}``), which keeps them prime and irredundant: a merged cube
    covers exactly what its parts did.
    """
    _covered, literals = _isop(target & care, target | ~care, {}, budget)
    return _merge_cubes([_grouped(space, cube, domains) for cube in literals], domains)


def _isop(
    lower: BDD, upper: BDD, memo: dict[tuple[BDD, BDD], tuple[BDD, list[Literals]]], budget: int
) -> tuple[BDD, list[Literals]]:
    """The function and cubes of an irredundant cover ``c``, ``lower ≤ c ≤ upper`` (Minato's
    recursion: the cubes that need the top variable false, those that need it true, then
    those that need neither for what is left)."""
    manager = lower.bdd
    if lower == manager.false:
        return manager.false, []
    if upper == manager.true:
        return manager.true, [()]
    found = memo.get((lower, upper))
    if found is not None:
        return found
    name = lower.var if upper.var is None or lower.level <= upper.level else upper.var
    assert name is not None  # neither is a constant: those returned above
    lower_0, lower_1 = _split(lower, name)
    upper_0, upper_1 = _split(upper, name)
    cover_0, cubes_0 = _isop(lower_0 & ~upper_1, upper_0, memo, budget)
    cover_1, cubes_1 = _isop(lower_1 & ~upper_0, upper_1, memo, budget)
    rest = (lower_0 & ~cover_0) | (lower_1 & ~cover_1)
    cover_both, cubes_both = _isop(rest, upper_0 & upper_1, memo, budget)
    cubes = [
        *(((name, False), *cube) for cube in cubes_0),
        *(((name, True), *cube) for cube in cubes_1),
        *cubes_both,
    ]
    if len(cubes) > budget:
        raise _TooComplex
    result = manager.ite(manager.var(name), cover_1, cover_0) | cover_both, cubes
    memo[lower, upper] = result
    return result


def _split(u: BDD, name: str) -> tuple[BDD, BDD]:
    """The cofactors of ``u`` by ``name``, which is ``u``'s top variable or above it."""
    return cofactors(u) if u.var == name else (u, u)


def _grouped(space: Space, literals: Literals, domains: Domains) -> Cube:
    """A cube of atoms as one entry per input (its possible slots), predicate and file."""
    cube: Cube = {}
    negated: dict[Input, set[Slot]] = {}
    for name, value in literals:
        atom = space.atom_of(name)
        if isinstance(atom, PredicateAtom | FileAtom):
            cube[atom] = value
        elif value:
            cube[atom.input] = frozenset([atom.slot])
        else:
            negated.setdefault(atom.input, set()).add(atom.slot)
    for input_, slots in negated.items():
        if input_ not in cube:
            cube[input_] = frozenset(s for s in domains[input_] if s not in slots)
    return cube


def _render_cube(
    space: Space,
    cube: Cube,
    qualify: bool,
    domains: Domains,
) -> str:
    parts = []
    for key, value in sorted(cube.items(), key=lambda kv: _sort_key(kv[0])):
        if isinstance(key, FileAtom):
            parts.append(key.label if value else f"¬{key.label}")
        elif isinstance(key, PredicateAtom):
            _test, display = PREDICATES[key.test]
            text = display.format(key.term)
            parts.append(text if value else f"¬({text})")
        else:
            assert isinstance(value, frozenset)
            input_ = cast(Input, key)
            parts.append(_render_slots(input_, value, domains[input_], qualify))
    return f" {AND} ".join(parts)


def _sort_key(key: object) -> tuple[int, str, str]:
    """Files, then inputs, then predicates, each by name; ties (an arg of the same name in
    two files, two tests of one term) in a fixed order too."""
    if isinstance(key, FileAtom):
        return (-1, key.label, key.file)
    if isinstance(key, PredicateAtom):
        return (1, str(key.term), key.test)
    return (0, str(key), key.file if isinstance(key, ArgInput) else "")


def _merge_cubes(cubes: list[Cube], domains: Domains) -> list[Cube]:
    """Join cubes that differ only in the slots of one input (x=a ∨ x=b → x∈{a,b}).

    Only cubes over the same keys can join (prime cubes never differ in one predicate
    alone), and cubes are bucketed by everything but one key, so each round is linear in
    the number of cubes rather than quadratic.
    """
    by_keys: dict[frozenset[object], list[Cube]] = {}
    for cube in cubes:
        by_keys.setdefault(frozenset(cube), []).append(cube)
    if all(len(group) == 1 for group in by_keys.values()):
        return cubes
    changed = True
    while changed and len(cubes) > 1:
        changed = False
        keys = {key for cube in cubes for key in cube}
        for key in sorted(keys, key=_sort_key):
            buckets: dict[frozenset[tuple[object, object]], list[int]] = {}
            for index, cube in enumerate(cubes):
                rest = frozenset((k, v) for k, v in cube.items() if k != key)
                buckets.setdefault(rest, []).append(index)
            merged_any = False
            result: list[Cube] = []
            for members in buckets.values():
                current = cubes[members[0]]
                for other_index in members[1:]:
                    joined = _merge_pair(current, cubes[other_index], domains)
                    if joined is None:
                        result.append(cubes[other_index])
                    else:
                        current = joined
                        merged_any = True
                result.append(current)
            if merged_any:
                cubes = result
                changed = True
    return cubes


def _merge_pair(a: Cube, b: Cube, domains: Domains) -> Cube | None:
    keys = set(a) | set(b)
    differing = [k for k in keys if a.get(k) != b.get(k)]
    if len(differing) != 1:
        return None
    key = differing[0]
    va, vb = a.get(key), b.get(key)
    if isinstance(key, PredicateAtom | FileAtom) or va is None or vb is None:
        # p ∧ rest ∨ ¬p ∧ rest = rest
        if isinstance(va, bool) and isinstance(vb, bool):
            return {k: v for k, v in a.items() if k != key}
        return None
    assert isinstance(va, frozenset) and isinstance(vb, frozenset)
    union = va | vb
    merged = dict(a)
    if len(union) == len(domains[key]):  # type: ignore[index]
        del merged[key]
    else:
        merged[key] = union
    return merged


def _slot_text(slot: Slot) -> str:
    """A slot as the condition shows it: the empty text as ``''``, not as nothing."""
    if isinstance(slot, str):
        return slot or "''"
    return repr(slot)


def _render_slots(
    input_: Input, slots: frozenset[Slot], domain: tuple[Slot, ...], qualify: bool
) -> str:
    name = str(input_)
    if qualify and isinstance(input_, ArgInput):
        name = f"{input_.file}:{input_.name}"
    if isinstance(input_, EnvInput) and UNSET in domain and slots == set(domain) - {UNSET}:
        return f"{name} {ENV_SET}"  # not `$X=<other>` where no value is listed: any value
    if len(slots) == 1:
        (slot,) = slots
        if isinstance(slot, str) and slot.lower() in BOOLEAN_WORDS and _is_boolean(domain):
            return name if slot.lower() == "true" else f"¬{name}"
        return f"{name}={_slot_text(slot)}"
    excluded = [s for s in domain if s not in slots]
    if len(excluded) == 1:
        return f"{name}≠{_slot_text(excluded[0])}"
    ordered = [s for s in domain if s in slots]
    return f"{name}∈{{{', '.join(_slot_text(s) for s in ordered)}}}"


def _is_boolean(domain: tuple[Slot, ...]) -> bool:
    words = {s.lower() for s in domain if isinstance(s, str)}
    return bool(words) and words <= {"true", "false"}
