"""xacro, for every configuration at once: the walk of ``eval_all`` over a document.

The walk follows xacro's own (``process_file``, in order): attributes, then the element's
text and children, each ``xacro:`` tag by its handler (:data:`HANDLERS`, a registry), any
other ``xacro:NAME`` as a macro call. Where xacro holds a value the walk holds a
:class:`Choice`; where xacro tests ``<xacro:if>`` the walk narrows its path condition
``pc``; where xacro raises (and prints nothing) the walk records a :class:`Failure` under
that condition and goes on with the other configurations. Files are read through rosvar's
confined reader and its safe XML parser; includes, macro nesting, the elements made and the
values computed are bounded, and what goes beyond a bound is reported and left unknown.

Known differences from xacro (none matter for the plugins read from a description): an
element's text is evaluated before its children (the XML reader keeps text and children
apart), a block inserted by ``<xacro:insert_block>`` is not evaluated a second time in the
macro's scope, ``$(dirname)`` is the including file's folder (ROS 1's xacro), and what
rosvar does not evaluate (``xacro.load_yaml``, properties of an include's namespace read as
``${ns.name}``, ``$(cwd)``) is an unknown value with a warning.
"""

from __future__ import annotations

import os
from collections.abc import Callable, Iterator, Mapping
from contextlib import contextmanager
from dataclasses import dataclass
from typing import Final, Protocol

from rosvar.analyses.robot_description.document import Description, Failure, Text, XElement
from rosvar.analyses.robot_description.evaluation import Evaluator, Value, stored_value
from rosvar.analyses.robot_description.literals import Deferred, read_literal, text_of, truth
from rosvar.analyses.robot_description.symbols import ABSENT, Lazy, Table
from rosvar.diagnostics import DiagnosticSink, Location
from rosvar.frontends.entity import Entity, ParseResult
from rosvar.interpreter.model import Raw
from rosvar.interpreter.substitution_args import Missing, Substituter, too_complex
from rosvar.logic.bdd import BDD
from rosvar.logic.choice import Choice, Fail, combine
from rosvar.logic.conditions import ConditionSpace
from rosvar.logic.inputs import OTHER, UNSET, EnvInput, Slot
from rosvar.logic.terms import Apply, Hole, Term, TermError, is_term, register

MAX_ELEMENTS: Final = 100_000
"""Elements one expansion may make (a macro that calls itself twice per level doubles them
at each level); the largest real descriptions make a few thousand."""
MAX_STEPS: Final = 500_000
"""Elements one expansion may walk, macro bodies and blocks included. Both budgets are the
whole expansion's: once one is spent, the walk stops everywhere (the rest is unknown), as
walking on without making anything would cost as much as making it."""
MAX_MACRO_DEPTH: Final = 100
"""Macro calls nested in one another; xacro itself fails a little deeper, on Python's
recursion limit, so a deeper expansion is reported and not followed."""
MAX_INCLUDE_DEPTH: Final = 64
MAX_TESTED_TERMS: Final = 32
"""Values known per configuration one ``<xacro:if>`` tests with a predicate each: each
combination of unknown values is a term of its own, and many predicates in one condition
make its BDD large."""
MAX_NESTING: Final = 400
"""Elements walked inside one another (across macros and includes): the walk recurses."""
XACRO_PREFIX: Final = "xacro:"


@dataclass(frozen=True, eq=False)
class Macro:
    """A ``<xacro:macro>``: its body, parameters (``*x`` a block, ``**x`` a block's content)
    and, per parameter, the property forwarded by ``^`` and the default's text."""

    name: str
    body: Entity
    params: tuple[str, ...]
    defaults: Mapping[str, tuple[str | None, str | None]]


@dataclass(frozen=True, eq=False)
class Block:
    """A macro's block argument: the element the call wrote, expanded in the caller."""

    element: XElement


@dataclass(frozen=True, eq=False)
class RawBlock:
    """A property without a value: its content, walked where it is inserted."""

    entity: Entity


Resolved = tuple[Macro, Table, Table] | Fail
"""A macro call's macro with the tables its body is expanded from, or xacro's failure."""
Handler = Callable[["Expansion", Entity, XElement, Table, Table], None]
HANDLERS: dict[str, Handler] = {}


def handler(tag: str) -> Callable[[Handler], Handler]:
    """Register the handler of ``xacro:tag``."""

    def register_handler(function: Handler) -> Handler:
        HANDLERS[XACRO_PREFIX + tag] = function
        return function

    return register_handler


def _truth_text(_host: object, text: str) -> str:
    try:
        return str(truth(read_literal(text)))
    except ValueError:
        raise TermError(f"{text} is not a boolean for xacro") from None


register("xacro_truth", _truth_text)


class Files(Protocol):
    """What the walk reads through: the analysis' files, packages and environment."""

    space: ConditionSpace

    def parse(self, path: str) -> ParseResult | str: ...

    def find_package(self, name: str) -> str | None: ...

    def env_domain(self, name: str) -> tuple[Slot, ...]: ...


class Expansion:
    """One run of xacro over one document, for every configuration at once."""

    def __init__(
        self,
        reader: Files,
        file: str,
        args: dict[str, Choice[Raw | Missing]],
        condition: BDD,
        plain: bool = False,
        root: Entity | None = None,
    ) -> None:
        """``plain``: a document read as it is (a URDF file a spawner reads, a parameter's
        text), no xacro tag nor substitution evaluated; ``root``: its tree, when it is no
        file."""
        self.reader = reader
        self.plain = plain
        self.root = root
        self.unexpanded = False  # a xacro tag met in a plain document (reported once)
        self.space = reader.space
        self.file = file
        self.condition = condition
        self.args = args
        self.pc = condition
        self.failures: list[Failure] = []
        self.unknown = self.space.false
        self.sink = DiagnosticSink()
        self.stack: list[tuple[str, str]] = []  # the files being walked: as named, real
        self.read: list[str] = []
        self.depth = 0
        self.nesting = 0
        self.steps = 0
        self.made = 0
        self.exhausted = False  # a budget of the whole expansion is spent
        self._location = Location(file)
        self._limited: set[str] = set()
        self.evaluator = Evaluator(self, Substituter(self))
        self.symbols = Table(self.space, None, condition)
        self.macros = Table(self.space, None, condition)

    # -- what evaluation and substitution need ---------------------------------------------
    @property
    def location(self) -> Location:
        return self._location

    @property
    def filename(self) -> str:
        return self.stack[-1][0] if self.stack else self.file

    def find_package(self, name: str) -> str | None:
        return self.reader.find_package(name)

    def env_value(self, name: str) -> Choice[Raw | None]:
        input_ = EnvInput(name)
        self.space.declare_input(input_, self.reader.env_domain(name))
        branches: list[tuple[BDD, Raw | None]] = []
        for slot, atom in self.space.slot_atoms(input_):
            if slot is UNSET:
                branches.append((atom, None))
            elif slot is OTHER:
                branches.append((atom, Hole(input_)))
            else:
                assert isinstance(slot, str)
                branches.append((atom, slot))
        return Choice.of(branches)

    def new_anon(self, anon_id: str) -> Choice[Raw]:
        raise AssertionError("xacro has no $(anon): refused before substitution")

    def note_unknown_package(self, name: str) -> None:
        self.sink.warning(
            "package-unknown",
            f"package '{name}' is not in the workspace; $(find {name}) stays symbolic",
            self.location,
        )

    def note_too_complex(self, message: str) -> None:
        self.unsupported(message)

    def unsupported(self, message: str) -> None:
        self.sink.warning("xacro-unsupported", message, self.location)
        self.unknown |= self.pc

    # -- the run ---------------------------------------------------------------------------
    def run(self) -> Description:
        root = self.root if self.root is not None else self.load(self.file)
        element = None
        if root is not None:
            element = XElement(root.tag, self.pc, root.location)
            self.stack.append((self.file, os.path.realpath(self.file)))
            with self.at(root):
                self.body(root, element, self.macros, self.symbols)
        self.close()
        return Description(
            self.file,
            self.condition,
            element,
            self.failures,
            self.sink.items,
            self.read,
            unknown=self.unknown,
        )

    def close(self) -> None:
        """Break the cycles (tables and namespaces, the evaluator and its substituter): left
        to the garbage collector, they could free BDDs after their manager."""
        self.symbols.clear()
        self.macros.clear()
        del self.evaluator

    def load(self, path: str) -> Entity | None:
        """A file's root element, or None after recording why xacro fails on it."""
        parsed = self.reader.parse(path)
        if isinstance(parsed, str):
            self.fail(self.space.true, f"cannot read {parsed}", "xacro-file-unreadable")
            return None
        for diagnostic in parsed.diagnostics:
            self.sink.add(diagnostic)
        if parsed.root is None:
            reason = parsed.diagnostics[0].message if parsed.diagnostics else "no root element"
            self.fail(self.space.true, f"XML parsing error in {path}: {reason}", "xacro-invalid")
            return None
        if path not in self.read:
            self.read.append(path)
        return parsed.root

    # -- state -----------------------------------------------------------------------------
    @contextmanager
    def under(self, condition: BDD) -> Iterator[bool]:
        """Narrow the path condition; yields whether anything is left to walk."""
        saved = self.pc
        self.pc = saved & condition
        try:
            yield self.pc != self.space.false
        finally:
            self.pc = saved

    @contextmanager
    def at(self, entity: Entity) -> Iterator[None]:
        saved = self._location
        self._location = entity.location
        try:
            yield
        finally:
            self._location = saved

    def fail(self, condition: BDD, message: str, code: str = "xacro-error") -> None:
        """xacro raises here where ``condition`` holds on the path; where a part before was
        not followed (an include of an unknown file), this may be its doing: unknown."""
        where = self.pc & condition & ~self.unknown
        if where != self.space.false:
            self.failures.append(Failure(where, self.location, message))
            self.sink.warning(code, f"xacro fails here: {message}", self.location)

    def limit(self, message: str) -> bool:
        """Report a bound reached (once per kind) and leave this part unknown."""
        if message not in self._limited:
            self._limited.add(message)
            self.sink.warning("xacro-too-large", f"{message}: not expanded further", self.location)
        self.unknown |= self.pc
        return False

    def strip(self, value: Choice[Value]) -> Choice[Value]:
        """``value`` without its failing branches, each recorded."""
        kept: list[tuple[BDD, Value]] = []
        for condition, leaf in value:
            if isinstance(leaf, Fail):
                self.fail(condition, leaf.message)
            else:
                kept.append((condition, leaf))
        return Choice.of(kept, self.space.false)

    def eval(self, text: str, symbols: Table) -> Choice[Value]:
        return self.strip(self.evaluator.text(text, symbols))

    def texts(self, text: str, symbols: Table) -> Choice[Text]:
        """``str(eval_text(text))``: the text xacro writes."""
        if self.plain:
            return Choice.const(self.space, text)
        return self.eval(text, symbols).map(text_of)

    def words(self, text: str, symbols: Table) -> Iterator[tuple[BDD, str]]:
        """A text that names something (a property, a file, a tag), per configuration; an
        unknown one is reported and left out."""
        for condition, value in self.texts(text, symbols):
            if isinstance(value, str):
                yield condition, value
            else:
                with self.under(condition):
                    self.unsupported(f"{text} names something only known per configuration")

    def truth(self, value: Choice[Value], text: str) -> tuple[BDD, BDD]:
        """Where ``value`` is true, where false, for xacro (``get_boolean_value``); a value
        known per configuration is true where a predicate on its term holds (at most
        :data:`MAX_TESTED_TERMS` of them: the others, together, on one unknown atom)."""
        true = false = self.space.false
        tested = 0
        for condition, leaf in value:
            if isinstance(leaf, Fail):
                self.fail(condition, leaf.message)
            elif isinstance(leaf, Deferred) or is_term(leaf):
                tested += 1
                with self.under(condition):
                    term = self._tested(leaf, text, tested)
                yes = self.space.predicate("xacro-true", term)
                if opaque(term):  # never computed: either way, and the rest unknown
                    true |= condition & yes
                    false |= condition & ~yes
                    with self.under(condition):
                        self.unknown |= self.pc
                    continue
                no = self.space.predicate("xacro-false", term)
                self.space.constrain(~(yes & no))
                true |= condition & yes
                false |= condition & no
                message = f'Xacro conditional "{text}" is not a boolean expression'
                self.fail(condition & ~yes & ~no, message)
            else:
                try:
                    holds = truth(leaf)
                except ValueError:
                    self.fail(
                        condition,
                        f'Xacro conditional "{text}" evaluated to "{leaf}", '
                        "which is not a boolean expression.",
                    )
                    continue
                if holds:
                    true |= condition
                else:
                    false |= condition
        return true, false

    def _tested(self, leaf: object, text: str, count: int) -> Term:
        """The term whose truth decides ``leaf`` (a deferred value's, read as a literal)."""
        if count > MAX_TESTED_TERMS:
            self.unsupported(f"{text} is not computed: over {MAX_TESTED_TERMS} unknown values")
            return too_complex(f"{text} at {self.location}")
        if isinstance(leaf, Deferred):
            return Apply("xacro_truth", (leaf.term,), str(leaf.term))
        assert isinstance(leaf, Hole | Apply)
        return leaf

    def step(self) -> bool:
        self.steps += 1
        if self.exhausted:
            return False
        if self.steps > MAX_STEPS:
            self.exhausted = True
            return self.limit(f"more than {MAX_STEPS} elements walked")
        return True

    # -- the walk --------------------------------------------------------------------------
    def body(self, entity: Entity, element: XElement, macros: Table, symbols: Table) -> None:
        """``eval_all`` of an element that is kept: attributes, text, children."""
        for name, value in entity.attributes.items():
            if not name.startswith(XACRO_PREFIX) and name != "xmlns:xacro":
                element.attributes[name] = self.texts(value, symbols)
        self.contents(entity, element, macros, symbols)

    def contents(self, entity: Entity, parent: XElement, macros: Table, symbols: Table) -> None:
        """An element's text and children into ``parent`` (its own, or the one it is spliced
        into: a macro's body, an ``<xacro:if>``, an included document)."""
        if entity.text:
            text = entity.text
            value = self.texts(text, symbols) if "$" in text else Choice.const(self.space, text)
            parent.texts.append((self.pc, value))
        if self.nesting >= MAX_NESTING:
            self.limit(f"elements nested more than {MAX_NESTING} deep")
            return
        self.nesting += 1
        try:
            for child in entity.children:
                if self.pc == self.space.false or not self.step():
                    return
                with self.at(child):
                    self.element(child, parent, macros, symbols)
        finally:
            self.nesting -= 1

    def element(self, entity: Entity, parent: XElement, macros: Table, symbols: Table) -> None:
        found = None if self.plain else HANDLERS.get(entity.tag)
        if found is not None:
            found(self, entity, parent, macros, symbols)
        elif entity.tag.startswith(XACRO_PREFIX) and not self.plain:
            self.call(entity, entity.tag[len(XACRO_PREFIX) :], parent, macros, symbols)
        elif entity.tag.startswith(XACRO_PREFIX) and self.plain and not self.unexpanded:
            self.unexpanded = True
            self.sink.warning(
                "description-unexpanded",
                f"<{entity.tag}> in a description read as it is: xacro never expands it",
                self.location,
            )
        else:
            self.made += 1
            if self.made > MAX_ELEMENTS:
                self.limit(f"more than {MAX_ELEMENTS} elements made")
                self.exhausted = True  # the walk stops: see MAX_STEPS
                return
            element = XElement(entity.tag, self.pc, entity.location)
            parent.children.append(element)
            self.body(entity, element, macros, symbols)

    def required(self, entity: Entity, *names: str) -> list[str] | None:
        """The attributes xacro requires of ``entity`` (a failure when one is missing)."""
        values = [entity.get(name) for name in names]
        for name, value in zip(names, values, strict=True):
            if value is None:
                self.fail(self.space.true, f"{entity.tag}: missing attribute '{name}'")
                return None
        return values  # type: ignore[return-value]

    # -- macro calls -----------------------------------------------------------------------
    def call(
        self, entity: Entity, name: str, parent: XElement, macros: Table, symbols: Table
    ) -> None:
        """``handle_macro_call``: the macro of that name (in a namespace for ``ns.name``)."""
        for condition, found in self.macro(name, macros, symbols):
            with self.under(condition) as live:
                if not live:
                    continue
                if isinstance(found, Fail):
                    self.fail(self.space.true, found.message)
                    continue
                macro, scoped_macros, scoped_symbols = found
                if self.depth >= MAX_MACRO_DEPTH:
                    self.limit(f"macro calls nested more than {MAX_MACRO_DEPTH} deep")
                    continue
                self.depth += 1
                try:
                    self.expand(
                        macro, entity, parent, macros, symbols, scoped_macros, scoped_symbols
                    )
                finally:
                    self.depth -= 1

    def macro(self, name: str, macros: Table, symbols: Table) -> Choice[Resolved]:
        """``resolve_macro``: the macro and the tables its body is expanded from."""
        unknown = Fail(f"unknown macro name: {XACRO_PREFIX}{name}")
        parts = name.split(".")

        def found(leaf: object, tables: tuple[Table, Table]) -> Choice[Resolved]:
            if isinstance(leaf, Macro):
                return Choice.const(self.space, (leaf, *tables))
            return Choice.const(self.space, unknown)

        def direct(leaf: object) -> Choice[Resolved]:
            if leaf is ABSENT and len(parts) > 1:
                return self._namespaced(parts, macros, symbols, found)
            return found(leaf, (macros, symbols))

        return macros.lookup(name, self.pc, _no_lazy).bind(direct)

    def _namespaced(
        self,
        parts: list[str],
        macros: Table,
        symbols: Table,
        found: Callable[[object, tuple[Table, Table]], Choice[Resolved]],
    ) -> Choice[Resolved]:
        unknown = Fail(f"unknown macro name: {XACRO_PREFIX}{'.'.join(parts)}")
        if len(parts) == 1:
            return macros.lookup(parts[0], self.pc, _no_lazy).bind(
                lambda leaf: found(leaf, (macros, symbols))
            )
        head, rest = parts[0], parts[1:]
        inner_macros = macros.lookup(head, self.pc, _no_lazy)
        inner_symbols = symbols.lookup(head, self.pc, self.evaluator.lazy)

        def step(pair: list[object]) -> Choice[Resolved]:
            table_m, table_s = pair
            if isinstance(table_m, Table) and isinstance(table_s, Table):
                return self._namespaced(rest, table_m, table_s, found)
            return Choice.const(self.space, unknown)

        pairs = combine([inner_macros, inner_symbols], list)
        return pairs.bind(step)

    def expand(
        self,
        macro: Macro,
        call: Entity,
        parent: XElement,
        caller_macros: Table,
        caller_symbols: Table,
        macros: Table,
        symbols: Table,
    ) -> None:
        scoped_symbols = symbols.child(self.pc)
        scoped_macros = macros.child(self.pc)
        params = list(macro.params)
        for name, value in call.attributes.items():
            if name not in params:
                self.fail(self.space.true, f'Invalid parameter "{name}"')
                return
            params.remove(name)
            scoped_symbols.set(name, self.eval(value, caller_symbols).map(stored_value), self.pc)
        holder = XElement("#call", self.pc, call.location)
        self.contents(call, holder, caller_macros, caller_symbols)
        self.blocks(macro, [p for p in params if p.startswith("*")], holder, scoped_symbols)
        undefined = []
        for param in params:
            if param.startswith("*"):
                continue
            forward, default = macro.defaults.get(param, (None, None))
            if forward is None and default is None:
                undefined.append(param)
                continue
            scoped_symbols.set(param, self.default(forward, default, caller_symbols), self.pc)
        if undefined:
            self.fail(self.space.true, f"Undefined parameters [{','.join(undefined)}]")
            return
        for value in macro.body.attributes.values():  # xacro evaluates them, then drops them
            self.eval(value, scoped_symbols)
        self.contents(macro.body, parent, scoped_macros, scoped_symbols)

    def default(self, forward: str | None, default: str | None, symbols: Table) -> Choice[Value]:
        """``eval_default_arg``: the caller's property forwarded by ``^``, else the default
        evaluated in the caller's scope."""
        if forward is None:
            assert default is not None
            return self.eval(default, symbols).map(stored_value)
        value = symbols.lookup(forward, self.pc, self.evaluator.lazy)

        def fallback(leaf: object) -> Choice[Value]:
            if leaf is not ABSENT:
                return Choice.const(self.space, leaf)
            if default is not None:
                return self.eval(default, symbols).map(stored_value)
            return Choice.const(self.space, Fail(f"Undefined property to forward: {forward}"))

        return self.strip(value.bind(fallback))

    def blocks(
        self, macro: Macro, block_params: list[str], holder: XElement, symbols: Table
    ) -> None:
        """The call's elements as the block parameters, in order; where there are fewer or
        more elements than block parameters, xacro fails."""
        count: Choice[int] = Choice.const(self.space, 0)
        assigned: dict[str, list[tuple[BDD, object]]] = {p: [] for p in block_params}
        for child in holder.children:
            for index, param in enumerate(block_params):
                taken = _counted(count, index) & child.condition
                if taken != self.space.false:
                    assigned[param].append((taken, Block(child)))
            count = Choice.of(
                [(c & child.condition, n + 1) for c, n in count]
                + [(c & ~child.condition, n) for c, n in count]
            )
        self.fail(count.where(lambda n: n < len(block_params)), "Not enough blocks")
        self.fail(count.where(lambda n: n > len(block_params)), "Unused block")
        for param, branches in assigned.items():
            taken_all = self.space.false
            for condition, _block in branches:
                taken_all |= condition
            value = Choice.of([*branches, (~taken_all, ABSENT)], self.space.false)
            symbols.set(param, value, self.pc)


def opaque(term: object) -> bool:
    """Whether a term holds a value rosvar never computes (over its limits, unsupported);
    walked without recursion: a recursive macro nests terms deeply."""
    pending = [term]
    seen: set[int] = set()
    while pending:
        item = pending.pop()
        if isinstance(item, Apply) and id(item) not in seen:
            if item.function == "too_complex":
                return True
            seen.add(id(item))
            pending.extend(item.operands)
    return False


def _counted(count: Choice[int], index: int) -> BDD:
    return count.where(lambda n: n == index)


def _no_lazy(lazy: Lazy, table: Table) -> Choice[object]:
    raise AssertionError("macro tables hold no lazy properties")
