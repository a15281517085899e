"""An abstract interpreter of the part of Python that launch files use, over ``ast``.

The file is never executed: its syntax tree is read statement by statement with abstract
values (:mod:`~rosvar.ros2.frontends.python.values`). Constants, strings, lists, dicts,
local variables, helper functions, loops over known sequences and ``if`` on known values
are followed exactly; a value known at launch time only (``.perform(context)``) is a Python
expression over substitutions (:mod:`~rosvar.ros2.frontends.python.launch_time`), and an
``if`` on it reads both branches, each under its condition, as ``if=``/``unless=`` do;
calls go to the launch API's registry
(:mod:`~rosvar.ros2.frontends.python.calls`). Anything else (``OpaqueFunction``, files read,
other modules called, unknown names, ``while``) becomes an :class:`Unknown` with a
diagnostic at its ``file:line:col``, and the reading goes on. A step budget and a call
depth bound the work whatever the file does.
"""

from __future__ import annotations

import ast
import builtins
import contextlib
import functools
import os
import string
from collections.abc import Callable, Iterator
from typing import Any

from rosvar.arithmetic import ARITHMETIC, COMPARISONS
from rosvar.diagnostics import DiagnosticSink, Location
from rosvar.files import read_file
from rosvar.frontends.entity import Entity
from rosvar.ros2.api.registry import python_name
from rosvar.ros2.frontends.python import (
    launch_time,
    paths,
    patterns,
    reads,
    written,
    xacro_calls,
)
from rosvar.ros2.frontends.python.actions import add_actions
from rosvar.ros2.frontends.python.branches import Forwarding, Journal, Mutable, put
from rosvar.ros2.frontends.python.calls import (
    CALLS,
    NOT_FOLLOWED,
    REASONS,
    Call,
    join_path,
    path_text,
    substitution_method,
)
from rosvar.ros2.frontends.python.default_files import DefaultFiles
from rosvar.ros2.frontends.python.launch_time import OPERATORS, performed
from rosvar.ros2.frontends.python.modules import MAX_MODULE_BYTES, MAX_MODULES, ModulePath
from rosvar.ros2.frontends.python.shared_remaps import SharedRemaps
from rosvar.ros2.frontends.python.text import Sub, Text, render
from rosvar.ros2.frontends.python.values import (
    Class,
    Condition,
    Conditional,
    DataField,
    Description,
    Dynamic,
    Enumerated,
    FileHandle,
    FilePath,
    Function,
    Instance,
    Key,
    LaunchContext,
    LaunchYaml,
    Match,
    Method,
    Module,
    ModuleScope,
    Pattern,
    Scope,
    SourceFile,
    Super,
    Unknown,
    Value,
    WrittenFile,
    XacroDocument,
)

MAX_STEPS = 500_000
"""Statements and expressions read per file before giving up (``python-budget``)."""
MAX_CALL_DEPTH = 40
"""Nested calls of the file's own functions (recursion) before a call stays unknown."""
MAX_LENGTH = 100_000
"""Longest string, text or list the reading builds (``*``, ``+``, ``join``, ``range``...)."""
MAX_INT_BITS = 4096
"""Largest integer the reading computes: repeated squaring must not exhaust memory."""
CHARS_PER_STEP = 64
"""Characters of a string built that cost one step (a string is copied a word at a time)."""

MAX_UNROLLED = 8
"""Items of a launch-time list (its length known at launch time only) a loop over it reads,
each under its own test; an item beyond them is an unknown value."""

MAX_IMPORT_DEPTH = 20
"""Modules being read at once (a module importing another...): deeper imports stay symbolic."""
MODULE_NAME = "__launch__"
"""``__name__`` while the file is read: launch imports it as a module, not as ``__main__``."""
DESCRIPTION = "composable_node"
REGISTERING = frozenset({("launch", "expose_substitution"), ("launch", "expose_action")})
"""Class decorators of launch that register the class with the frontends and return it."""
"""The tag of a composable node description, which carries its own condition."""


class _Return(Exception):
    def __init__(self, value: Value) -> None:
        super().__init__()
        self.value = value


class _Break(Exception):
    pass


class _Continue(Exception):
    pass


class PythonRaise(Exception):
    """An exception the file raises: ``value`` (an object of its class, or a builtin
    exception's name as a :class:`Module`), raised at ``location``."""

    def __init__(self, value: Value, location: Location) -> None:
        super().__init__()
        self.value = value
        self.location = location

    def what(self) -> str:
        """The exception's class name, where known."""
        if isinstance(self.value, Instance):
            return self.value.cls.name
        if isinstance(self.value, Module):
            return self.value.qualified
        return "an exception"


class OutOfBudget(Exception):
    """The file needs more than :data:`MAX_STEPS` steps."""


_SCALARS = (str, int, float, bool, type(None))
_STR_METHODS = frozenset(
    {
        "join",
        "replace",
        "strip",
        "lstrip",
        "rstrip",
        "lower",
        "upper",
        "startswith",
        "endswith",
        "split",
        "format",
    }
)


def _constant(value: Value) -> bool:
    if isinstance(value, list | tuple):
        return all(_constant(item) for item in value)
    return isinstance(value, _SCALARS)


def size(value: Value) -> int:
    """The length of a string, text or sequence, the bytes of an integer; 1 otherwise."""
    if isinstance(value, str | list | tuple):
        return len(value)
    if isinstance(value, Text):
        return sum(len(part) if isinstance(part, str) else 1 for part in value.parts)
    if isinstance(value, int) and not isinstance(value, bool):
        return value.bit_length() // 8
    return 1


class Expansion:
    """The size of values with every shared part counted each time it occurs, as walking
    them (their launch elements, a parameter dict) would meet it: ``[[s] * n] * n`` is
    n * n, ``GroupAction([g, g])`` nested k deep 2^k. Each object's size is computed once
    per question; a launch element's is remembered (by its identity and number of children:
    elements are built once, descriptions only grow), so that a chain of k nested groups
    costs k, not k^2."""

    def __init__(self) -> None:
        self._elements: dict[tuple[int, int], int] = {}
        self._kept: list[Entity] = []  # ids stay unique while their objects live

    def cost(self, value: object, limit: int) -> int:
        """The expanded size of ``value`` less that of the launch elements built before that
        it holds, each credited once (they were charged when built: a chain of k groups
        costs k, two copies of one group are one group more); counting stops past
        ``limit``, so the work done is at most the size found."""
        sizes: dict[int, int] = {}
        keep: list[object] = []
        credited: set[int] = set()
        credit = 0

        def measure(item: object) -> int:
            nonlocal credit
            if isinstance(item, str):
                return 1 + len(item) // CHARS_PER_STEP
            if not isinstance(
                item, list | tuple | dict | Entity | Text | Description | Conditional
            ):
                return 1
            element = (id(item), len(item.children)) if isinstance(item, Entity) else None
            known = sizes.get(id(item)) if element is None else self._elements.get(element)
            if known is not None:
                if element is not None and id(item) not in credited:
                    credited.add(id(item))
                    credit += known
                return known
            keep.append(item)
            sizes[id(item)] = limit + credit + 1  # a container holding itself is too large
            total = 1
            for part in _parts(item):
                total += measure(part)
                if total > limit + credit:
                    return total  # not remembered: a later question may allow more
            sizes[id(item)] = total
            if element is not None and isinstance(item, Entity):
                self._elements[element] = total
                self._kept.append(item)
            return total

        return measure(value) - credit


def walked(root: Entity, limit: int) -> int:
    """The elements the interpretation walks from ``root``: a shared element once for each
    place it occurs. Counted without recursion, each element once (its count remembered by
    identity); past ``limit``, or for an element holding itself, ``limit + 1``. The charge of
    each operation credits the elements built before, which two of them holding one
    another's parts slip past (``GroupAction([g, TimerAction(period=1.0, actions=[g])])``
    sixty deep: 2^60 elements for a few steps); this counts what is walked, once."""
    counts: dict[int, int] = {}
    open_: set[int] = set()  # opened and not done: ancestors of what is being counted
    pending: list[tuple[Entity, bool]] = [(root, False)]
    while pending:
        element, done = pending.pop()
        key = id(element)
        if done:
            open_.discard(key)
            counts[key] = min(limit + 1, 1 + sum(counts[id(c)] for c in element.children))
        elif key in open_:
            return limit + 1
        elif key not in counts:
            open_.add(key)
            pending.append((element, True))
            pending.extend((child, False) for child in element.children)
    return counts[id(root)]


def _parts(item: object) -> Iterator[object]:
    if isinstance(item, dict):
        for key, value in item.items():
            yield key
            yield value
    elif isinstance(item, Entity):
        yield from item.attributes.values()
        yield from item.children
    elif isinstance(item, Text):
        yield from item.parts
    elif isinstance(item, Description):
        yield item.root
    elif isinstance(item, Conditional):  # both branches are built
        yield item.then
        yield item.otherwise
    elif isinstance(item, list | tuple):
        yield from item


_REFERENCES = (ast.Name, ast.Attribute, ast.Constant)
"""Expressions that only refer to a value already built: nothing to charge."""


def truth(value: Value) -> bool | None:
    """Python's truth of ``value``; ``None`` when it is not known statically."""
    if isinstance(value, Unknown | Module | Dynamic):  # a Module: any value of another module
        return None
    if isinstance(value, (*_SCALARS, list, tuple, dict)):
        return bool(value)
    return True  # launch objects and texts with substitutions are never empty


class Interpreter:
    """Reads one file; diagnostics go to ``sink``."""

    def __init__(
        self, filename: str, text: str, sink: DiagnosticSink, modules: ModulePath | None = None
    ) -> None:
        self.filename = filename
        self.file = SourceFile(filename, text.splitlines())
        """The file whose code is being read (a module's, in its functions)."""
        self.sink = sink
        self.modules = modules
        self.loaded: dict[str, ModuleScope | None] = {}
        """Modules read (``None``: not found or not readable), by qualified name."""
        self.loading = 0
        self.paths: list[str] = [os.path.dirname(filename)]
        """Directories searched for modules before the packages (``sys.path`` appends)."""
        self.steps = 0
        self.statement: ast.stmt | None = None
        self.expansion = Expansion()
        self.depth = 0
        self.guards: list[Text] = []
        """The Python tests of the launch-time ``if``s being read, innermost last."""
        self.journals: list[Journal] = []
        """The mutable values changed by each launch-time branch being read, innermost last."""
        self.forwarding = Forwarding()
        """Mutable values that stand for a choice of values (see :mod:`.branches`)."""
        self.created: dict[int, tuple[Entity, tuple[Text, ...]]] = {}
        """Actions made under guards, with the guards (so a branch does not guard twice)."""
        self.descriptions: dict[int, tuple[Entity, tuple[Text, ...]]] = {}
        self.rereading: Callable[[str], str] | None = None
        """Set where a ``perform`` is read again in one configuration (:mod:`.performs`):
        a file it writes is that file, not its deferred text; it gives the text of a path
        naming a file written so (``WRITTEN_PATH``)."""
        self.yielded: list[list[Value]] = []
        """What each generator being called has yielded, innermost last."""
        self.default_files = DefaultFiles()
        """Launch arguments' defaults, for the files a function opens by them."""
        self.remaps = SharedRemaps()
        """The remaps made of each pair object, for those the file gives several nodes."""
        """Composable node descriptions made conditional, by id: the description as written
        and the tests of its condition."""
        self.statements: dict[type[ast.stmt], Callable[[Any, Scope], None]] = {
            ast.Expr: self._expression_statement,
            ast.Assign: self._assign,
            ast.AnnAssign: self._ann_assign,
            ast.AugAssign: self._aug_assign,
            ast.Delete: self._delete,
            ast.Return: self._return,
            ast.For: self._for,
            ast.FunctionDef: self._function_def,
            ast.ClassDef: self._class_def,
            ast.Import: self._import,
            ast.ImportFrom: self._import_from,
            ast.Try: self._try,
            ast.With: self._with,
            ast.Raise: self._raise,
            ast.Break: self._break,
            ast.Continue: self._continue,
            ast.Pass: lambda node, scope: None,
            ast.Assert: lambda node, scope: None,
            ast.Global: lambda node, scope: None,
            ast.Nonlocal: lambda node, scope: None,
        }
        self.expressions: dict[type[ast.expr], Callable[[Any, Scope], Value]] = {
            ast.Constant: self._constant,
            ast.Name: self._name,
            ast.JoinedStr: self._joined_str,
            ast.BinOp: self._bin_op,
            ast.UnaryOp: self._unary_op,
            ast.BoolOp: self._bool_op,
            ast.Compare: self._compare,
            ast.IfExp: self._if_exp,
            ast.List: self._sequence,
            ast.Tuple: lambda node, scope: tuple(self._elements(node.elts, scope)),
            ast.Set: self._sequence,
            ast.Dict: self._dict,
            ast.Subscript: self._subscript,
            ast.Attribute: self._attribute,
            ast.Call: self._call,
            ast.ListComp: self._comprehension,
            ast.GeneratorExp: self._comprehension,
            ast.SetComp: self._comprehension,
            ast.DictComp: self._comprehension,
            ast.NamedExpr: self._named_expr,
            ast.Yield: self._yield,
            ast.YieldFrom: self._yield,
        }

    # ------------------------------------------------------------------ helpers

    def location(self, node: ast.AST) -> Location:
        line = getattr(node, "lineno", 1)
        offset = getattr(node, "col_offset", 0)  # in UTF-8 bytes
        lines = self.file.lines
        text = lines[line - 1] if 0 < line <= len(lines) else ""
        column = len(text.encode()[:offset].decode(errors="replace"))
        return Location(self.file.filename, line, column + 1)

    def not_followed(self, what: str, node: ast.AST) -> Unknown:
        self.sink.warning(NOT_FOLLOWED, f"{what} is not followed", self.location(node))
        return Unknown(what)

    def step(self, count: int = 1) -> None:
        self.steps += count
        if self.steps > MAX_STEPS:
            raise OutOfBudget

    def touch(self, value: Mutable) -> None:
        """Called before ``value`` changes in place: a branch being read keeps its content
        (the copy counted against the budget)."""
        if self.journals:
            self.step(1 + len(value.attributes if isinstance(value, Instance) else value))
            self.journals[-1].touch(value, self.forwarding)

    def resolved(self, value: Value) -> Value:
        """The value a mutable value stands for since a launch-time branch changed it."""
        return self.forwarding.resolved(value)

    def settled(self, value: Value) -> Value:
        """``value`` with every value inside it that a launch-time branch changed into a
        choice replaced by that choice (new lists, dicts and choices where one changed;
        each container a step): what leaves the reading, to the launch API, holds no
        stale value."""
        done: dict[int, Value] = {}

        def settle(item: Value) -> Value:
            item = self.resolved(item)
            if not isinstance(item, list | tuple | dict | Conditional):
                return item
            if id(item) in done:
                return done[id(item)]
            done[id(item)] = item  # a container holding itself stays itself
            self.step()
            result: Value = item
            if isinstance(item, Conditional):
                sides = settle(item.then), settle(item.otherwise)
                if sides[0] is not item.then or sides[1] is not item.otherwise:
                    result = Conditional(item.test, sides[0], sides[1])
            elif isinstance(item, dict):
                pairs = {key: settle(inner) for key, inner in item.items()}
                if any(pairs[key] is not inner for key, inner in item.items()):
                    result = pairs
            else:
                items = [settle(inner) for inner in item]
                if any(new is not old for new, old in zip(items, item, strict=True)):
                    result = items if isinstance(item, list) else tuple(items)
            done[id(item)] = result
            return result

        return settle(value)

    def charge(self, value: object) -> None:
        """Count the expanded size of a value an operation built or walked, so that work
        multiplied by sharing or by long operands (``l == l``, ``l[:]``, ``s.split()``)
        is bounded by the same budget as the statements."""
        self.steps += self.expansion.cost(value, MAX_STEPS - self.steps) - 1
        if self.steps > MAX_STEPS:
            raise OutOfBudget

    # ------------------------------------------------------------------ statements

    def run_module(self, tree: ast.Module) -> Scope:
        # the file's path is a Python string, not a substitution object
        scope = Scope({"__name__": MODULE_NAME, "__file__": performed(Text.of(Sub("filename")))})
        try:
            self.block(tree.body, scope)
        except _Return:
            pass
        except (_Break, _Continue):
            pass
        return scope

    def block(self, body: list[ast.stmt], scope: Scope, tail: bool = False) -> None:
        """The statements of ``body``; ``tail`` when it is a function's body, whose rest an
        ``if`` returning in one branch only reads in the other."""
        for index, statement in enumerate(body):
            self.step()
            self.statement = statement  # where a budget runs out
            if isinstance(statement, ast.If):
                if self._if(statement, scope, body[index + 1 :] if tail else None):
                    return
                continue
            handler = self.statements.get(type(statement))
            if handler is None:
                self.not_followed(f"a '{type(statement).__name__}' statement", statement)
                continue
            handler(statement, scope)

    def assign(self, target: ast.expr, value: Value, scope: Scope) -> None:
        if isinstance(target, ast.Name):
            scope.names[target.id] = value
        elif isinstance(target, ast.Tuple | ast.List):
            items: list[Value]
            if isinstance(value, list | tuple) and len(value) == len(target.elts):
                items = [self.resolved(item) for item in value]
            else:
                if not isinstance(value, Unknown):
                    value = self.not_followed("unpacking of a value of unknown length", target)
                items = [value] * len(target.elts)
            for element, item in zip(target.elts, items, strict=True):
                self.assign(element, item, scope)
        elif isinstance(target, ast.Attribute):
            owner = self.expr(target.value, scope)
            if isinstance(owner, Instance):
                self.touch(owner)
                owner.attributes[target.attr] = value
            elif isinstance(owner, Class | ModuleScope):
                owner.scope.names[target.attr] = value
            elif isinstance(owner, Conditional):
                self.distribute(
                    [owner], lambda values: self._set_attribute(values[0], target, value), target
                )
            elif not isinstance(owner, Unknown):
                self.not_followed(f"assignment to an attribute of a {type(owner).__name__}", target)
        elif isinstance(target, ast.Subscript):
            container = self.expr(target.value, scope)
            index = self.expr(target.slice, scope)
            self.distribute(
                [container, index],
                lambda values: self._set_item(values[0], values[1], value, target),
                target,
            )
        else:
            self.not_followed(f"assignment to a '{type(target).__name__}'", target)

    def _set_attribute(self, owner: Value, target: ast.Attribute, value: Value) -> Value:
        if isinstance(owner, Instance):
            self.touch(owner)
            owner.attributes[target.attr] = value
        elif not isinstance(owner, Unknown):
            self.not_followed(f"assignment to an attribute of a {type(owner).__name__}", target)
        return None

    def _set_item(self, container: Value, index: Value, value: Value, target: ast.AST) -> Value:
        """``container[index] = value``."""
        if isinstance(container, dict):
            index = _dict_key(index)
        if isinstance(container, dict) and isinstance(index, Key):
            self.touch(container)
            container[index] = value
            return None
        if isinstance(container, list) and isinstance(index, int) and _within(container, index):
            self.touch(container)
            container[index] = value
            return None
        if not isinstance(container, Unknown):
            self.not_followed("assignment to an item of an unknown container", target)
        return None

    def _delete(self, node: ast.Delete, scope: Scope) -> None:
        """``del name``, ``del d[key]``, ``del l[i]``."""
        for target in node.targets:
            if isinstance(target, ast.Name):
                scope.names.pop(target.id, None)
            elif isinstance(target, ast.Subscript) and not isinstance(target.slice, ast.Slice):
                self._delete_subscript(target, scope)
            else:
                self.not_followed(f"'del' of a '{type(target).__name__}'", target)

    def _delete_subscript(self, target: ast.Subscript, scope: Scope) -> None:
        container = self.expr(target.value, scope)
        index = self.expr(target.slice, scope)
        self.distribute(
            [container, index],
            lambda values: self._delete_item(values[0], values[1], target),
            target,
        )

    def _delete_item(self, container: Value, index: Value, target: ast.AST) -> Value:
        if isinstance(container, dict) and isinstance(index, Key) and index in container:
            self.touch(container)
            del container[index]
            return None
        if isinstance(container, list) and isinstance(index, int) and _within(container, index):
            self.touch(container)
            del container[index]
            return None
        if not isinstance(container, Unknown):
            self.not_followed("'del' of an item not known statically", target)
        return None

    def _expression_statement(self, node: ast.Expr, scope: Scope) -> None:
        self.expr(node.value, scope)

    def _assign(self, node: ast.Assign, scope: Scope) -> None:
        value = self.expr(node.value, scope)
        for target in node.targets:
            self.assign(target, value, scope)

    def _ann_assign(self, node: ast.AnnAssign, scope: Scope) -> None:
        if node.value is not None:
            self.assign(node.target, self.expr(node.value, scope), scope)

    def _aug_assign(self, node: ast.AugAssign, scope: Scope) -> None:
        current = self.expr(node.target, scope)
        right = self.expr(node.value, scope)
        if isinstance(current, list | Conditional) and isinstance(node.op, ast.Add):
            extended = self.distribute(  # += extends the list in place
                [current], lambda values: self._extend(values[0], right, node), node
            )
            if not isinstance(extended, Unknown):
                return
        value = self.binary(node.op, current, right, node)
        self.assign(node.target, value, scope)

    def _extend(self, receiver: Value, items: Value, node: ast.AST) -> Value:
        """``receiver += items`` on a list: the list extended; anything else, unknown."""
        if not isinstance(receiver, list):
            return Unknown("not a list")
        return self.call_method(Method(receiver, "extend"), [items], {}, node)

    def _return(self, node: ast.Return, scope: Scope) -> None:
        raise _Return(None if node.value is None else self.expr(node.value, scope))

    def _if(self, node: ast.If, scope: Scope, rest: list[ast.stmt] | None) -> bool:
        """Reads the ``if``; whether it read ``rest`` too (the rest of a function's body,
        read in the branch that does not return, when one branch does)."""
        value = self.tested(self.expr(node.test, scope), node.test)
        if isinstance(value, Dynamic):
            return self._branches(
                value.source,
                lambda: self.block(node.body, scope),
                lambda: self.block(node.orelse, scope),
                node,
                scope,
                rest,
            )
        test = truth(value)
        if test is None:
            self.not_followed("an 'if' on a value not known statically (neither branch)", node)
        else:
            self.block(node.body if test else node.orelse, scope, tail=rest is not None)
        return False

    def tested(self, value: Value, node: ast.AST) -> Value:
        """The truth of a value chosen at launch time (a launch-time boolean), else itself."""
        if not isinstance(value, Conditional):
            return value

        def truth_of(values: list[Value]) -> Value:
            test = truth(values[0])
            return Unknown("a condition not known statically") if test is None else test

        return self.distribute([value], truth_of, node)

    def _branches(
        self,
        test: Text,
        then_run: Callable[[], None],
        otherwise_run: Callable[[], None],
        node: ast.AST,
        scope: Scope,
        rest: list[ast.stmt] | None,
    ) -> bool:
        """Both branches of an ``if`` on a launch-time value, each under its condition and
        on its own copy of what it changes (:mod:`.branches`); the names they set, the
        values they change and what they return, chosen by ``test`` after."""
        before = dict(scope.names)
        then, then_journal, _ = self._branch(launch_time.truth(test), then_run, node)
        after_then = dict(scope.names)
        scope.names = dict(before)
        otherwise, otherwise_journal, _ = self._branch(
            launch_time.negated(test), otherwise_run, node
        )
        returned = (then is not None, otherwise is not None)
        if returned == (True, False) or returned == (False, True):
            if rest is None:
                self.merge(test, then_journal, otherwise_journal, node)
                value = self.not_followed(
                    "a 'return' in one branch of an 'if' on a launch-time value, in a loop "
                    "or a nested block",
                    node,
                )
                raise _Return(value)
            tail = rest
            if then is None:  # the rest after the 'then' branch, under its test
                scope.names = after_then
                then, _, _ = self._branch(
                    launch_time.truth(test), lambda: self.block(tail, scope), node, then_journal
                )
                then = then or _Return(None)
            else:
                otherwise, _, _ = self._branch(
                    launch_time.negated(test),
                    lambda: self.block(tail, scope),
                    node,
                    otherwise_journal,
                )
                otherwise = otherwise or _Return(None)
        self.merge(test, then_journal, otherwise_journal, node)
        if then is not None and otherwise is not None:
            raise _Return(self.choose(test, then.value, otherwise.value, node))
        after_otherwise = scope.names
        scope.names = {}
        for name in {**after_then, **after_otherwise}:
            if name not in after_then or name not in after_otherwise:
                scope.names[name] = after_then.get(name, after_otherwise.get(name))
            else:
                scope.names[name] = self.choose(test, after_then[name], after_otherwise[name], node)
        return rest is not None and returned != (False, False)

    def _branch(
        self,
        test: Text,
        run: Callable[[], Value],
        node: ast.AST,
        journal: Journal | None = None,
    ) -> tuple[_Return | None, Journal, Value]:
        """``run`` read under ``test``, on its own copy of what it changes (``journal``:
        reading on in a branch read before); what it returns (``return``), the journal of
        the values it changed (put back as they were) and the value ``run`` gives."""
        journal = Journal() if journal is None else journal
        journal.reopen(self.forwarding)
        self.guards.append(test)
        self.journals.append(journal)
        returned: _Return | None = None
        value: Value = None
        try:
            value = run()
        except _Return as raised:
            returned = raised
        except (_Break, _Continue):
            self.not_followed(
                "a 'break' or 'continue' under an 'if' on a launch-time value",
                self.statement or node,
            )
        finally:
            self.guards.pop()
            self.journals.pop()
            journal.close(self.forwarding)
        return returned, journal, value

    def merge(self, test: Text, then: Journal, otherwise: Journal, node: ast.AST) -> None:
        """Each value either branch changed holds the choice of the two branches' contents
        under ``test`` (a branch that did not change it leaves what it held before)."""
        changed = {**otherwise.before, **then.before}
        for key, (value, before) in changed.items():
            self.touch(value)  # an enclosing branch keeps what it held before
            then_items, then_to = then.after.get(key, before)
            other_items, other_to = otherwise.after.get(key, before)
            if then_to is None and other_to is None:
                merged = self._merged(test, value, then_items, other_items, node)
                if merged is not None:
                    put(value, (merged, None), self.forwarding)
                    continue
            sides = [
                _whole(items, to) for items, to in ((then_items, then_to), (other_items, other_to))
            ]
            self.forwarding.forward(value, self.choose(test, sides[0], sides[1], node))

    def _merged(
        self,
        test: Text,
        value: Mutable,
        then: list[Value] | dict[Key, Value] | dict[str, Value],
        otherwise: list[Value] | dict[Key, Value] | dict[str, Value],
        node: ast.AST,
    ) -> list[Value] | dict[Key, Value] | dict[str, Value] | None:
        """The items of ``value`` chosen item by item, where the branches' contents have the
        same shape (lists of one length, dicts of the same keys, any attributes); a list
        whose branches add or remove launch actions only keeps both branches' actions, each
        under its test; ``None`` where the whole value must be chosen."""
        if isinstance(then, list) and isinstance(otherwise, list):
            if len(then) == len(otherwise):
                return [self.choose(test, a, b, node) for a, b in zip(then, otherwise, strict=True)]
            start = 0
            while start < min(len(then), len(otherwise)) and _same(then[start], otherwise[start]):
                start += 1
            end = 0
            while end < min(len(then), len(otherwise)) - start and _same(
                then[-1 - end], otherwise[-1 - end]
            ):
                end += 1
            middles = (then[start : len(then) - end], otherwise[start : len(otherwise) - end])
            if _actions(middles[0]) is None or _actions(middles[1]) is None:
                return None
            chosen = [
                *self._guarded_items(launch_time.truth(test), middles[0], node),
                *self._guarded_items(launch_time.negated(test), middles[1], node),
            ]
            return [*then[:start], *chosen, *then[len(then) - end :]]
        if isinstance(then, dict) and isinstance(otherwise, dict):
            if set(then) != set(otherwise) and not isinstance(value, Instance):
                return None
            missing = Unknown("an attribute set in one branch of a launch-time 'if' only")
            return {
                key: self.choose(test, then.get(key, missing), otherwise.get(key, missing), node)
                for key in dict.fromkeys([*then, *otherwise])
            }
        return None

    def guard(self) -> Text:
        """The conjunction of the tests being read under."""
        test = self.guards[0]
        for other in self.guards[1:]:
            test = Text.of("(", test, ") and (", other, ")")
        return test

    def choose(self, test: Text, then: Value, otherwise: Value, node: ast.AST) -> Value:
        """``then`` where the Python ``test`` holds at launch time, else ``otherwise``: a
        Python expression where both have one (scalars), the actions of both each under
        its test (a launch description of them where both are one), else a
        :class:`Conditional` (lists, dicts: each branch's value whole)."""
        if then is otherwise:  # one object, maybe changed by the branches: itself
            return then
        then, otherwise = self.resolved(then), self.resolved(otherwise)
        if _same(then, otherwise):
            return then
        actions = [_actions(then), _actions(otherwise)]
        if actions[0] is not None and actions[1] is not None:
            children = self.each_guarded(test, actions[0], actions[1], node)
            group = _group(children, None, self.location(node), self.sink)
            if isinstance(then, Description) and isinstance(otherwise, Description):
                # each branch returns its own LaunchDescription (realsense's rs_launch.py)
                return Description(Entity("launch", {}, self.location(node), [group]))
            return (
                [group]
                if isinstance(then, list | tuple) or isinstance(otherwise, list | tuple)
                else group
            )
        if isinstance(then, list | tuple | dict | Conditional) or isinstance(
            otherwise, list | tuple | dict | Conditional
        ):
            return Conditional(test, then, otherwise)
        sources = [_branch_source(then), _branch_source(otherwise)]
        if sources[0] is not None and sources[1] is not None:
            kinds = {launch_time.kind_of(then), launch_time.kind_of(otherwise)}
            return launch_time.chosen(
                test, sources[0], sources[1], kinds.pop() if len(kinds) == 1 else None
            )
        return Conditional(test, then, otherwise)

    def each_guarded(
        self, test: Text, then: list[Entity], otherwise: list[Entity], node: ast.AST
    ) -> list[Entity]:
        """The actions of both branches, each under its branch's test."""
        self.guards.append(launch_time.truth(test))
        try:
            children = [self.guarded_action(action, node) for action in then]
            self.guards[-1] = launch_time.negated(test)
            return children + [self.guarded_action(action, node) for action in otherwise]
        finally:
            self.guards.pop()

    def _guarded_items(self, test: Text, items: list[Value], node: ast.AST) -> list[Value]:
        """``items`` (actions, lists of them) under ``test``, as they are nested."""
        self.guards.append(test)
        try:
            return [self._guarded_item(item, node) for item in items]
        finally:
            self.guards.pop()

    def _guarded_item(self, item: Value, node: ast.AST) -> Value:
        if isinstance(item, Entity):
            return self.guarded_action(item, node)
        if isinstance(item, list | tuple):
            inner = [self._guarded_item(part, node) for part in item]
            return inner if isinstance(item, list) else tuple(inner)
        return self.guarded_item(item, node)

    def guarded_action(self, action: Entity, node: ast.AST) -> Entity:
        """``action`` under the guards being read (unless it was made under them)."""
        if not self.guards:
            return action
        made = self.created.get(id(action))
        guards = tuple(self.guards)
        if made is not None and made[0] is action and made[1][: len(guards)] == guards:
            return action
        if action.tag == DESCRIPTION and not {"if", "unless"} & set(action.attributes):
            return self._guarded_description(action, guards)
        group = _group([action], self.guard(), self.location(node), self.sink)
        self.created[id(group)] = (group, guards)
        return group

    def _guarded_description(self, action: Entity, guards: tuple[Text, ...]) -> Entity:
        """A composable node description under ``guards`` (and those it was made under):
        a copy with that condition as its own, since a container holds no group."""
        original, before = self.descriptions.get(id(action), (action, ()))
        tests = before + tuple(test for test in guards if test not in before)
        conjunction = tests[0]
        for test in tests[1:]:
            conjunction = Text.of("(", conjunction, ") and (", test, ")")
        attributes = {**original.attributes, "if": render(launch_time.condition(conjunction))}
        copy = Entity(original.tag, attributes, original.location, original.children)
        copy.text, copy.typed = original.text, original.typed
        self.created[id(copy)] = (copy, guards)
        self.descriptions[id(copy)] = (original, tests)
        return copy

    def guarded_item(self, item: Value, node: ast.AST) -> Value:
        """An item added to a list (or a description) under the guards being read: actions
        under them (the branch's list may be kept whole); any other value as it is (the
        branch changes its own copy of the list)."""
        if not self.guards:
            return item
        if isinstance(item, Entity):
            return self.guarded_action(item, node)
        if isinstance(item, Description):
            return [self.guarded_action(action, node) for action in item.root.children]
        return item

    def _for(self, node: ast.For, scope: Scope) -> None:
        self._loop(node, self.expr(node.iter, scope), scope)

    def _loop(self, node: ast.For, iterable: Value, scope: Scope) -> None:
        """The loop over ``iterable``; over a value chosen at launch time, the loop over
        each branch's value, each under its test, as an ``if`` would read them."""
        if isinstance(iterable, Conditional):
            then, otherwise = self.resolved(iterable.then), self.resolved(iterable.otherwise)
            self._branches(
                iterable.test,
                lambda: self._loop(node, then, scope),
                lambda: self._loop(node, otherwise, scope),
                node,
                scope,
                None,
            )
            return
        if isinstance(iterable, Dynamic | Enumerated):
            self.unrolled(iterable, functools.partial(self._body, node, scope), node, scope)
            self.block(node.orelse, scope)
            return
        items = self.iterate(iterable, node.iter)
        if items is None:
            return
        for item in items:
            self.assign(node.target, item, scope)
            try:
                self.block(node.body, scope)
            except _Break:
                return
            except _Continue:
                continue
        self.block(node.orelse, scope)

    def _body(self, node: ast.For, scope: Scope, item: Value) -> None:
        """The loop's body for one item of a launch-time list."""
        self.assign(node.target, item, scope)
        try:
            self.block(node.body, scope)
        except _Continue:
            pass
        except _Break:
            self.not_followed("a 'break' in a loop over a launch-time list", node)

    def unrolled(
        self,
        iterable: Dynamic | Enumerated,
        run: Callable[[Value], None],
        node: ast.AST,
        scope: Scope,
    ) -> None:
        """A loop over a launch-time list of unknown length (``yaml.load`` or ``split`` of
        a launch configuration, or its ``enumerate``): ``run`` of each of its first
        :data:`MAX_UNROLLED` items (with its index), each as an ``if len(x) > i`` would read
        it; an item beyond them is unknown, so that what is made of it fails where it is
        needed, in the configurations that give it."""
        items = iterable.items if isinstance(iterable, Enumerated) else iterable
        kind = str if items.kind is list else None
        for index in range(MAX_UNROLLED + 1):
            test = Text.of("len(", items.source, f") > {index}")
            item: Value = Dynamic(Text.of("(", items.source, f")[{index}]"), kind)
            if index == MAX_UNROLLED:
                item = Unknown(f"an item beyond the first {MAX_UNROLLED} of a launch-time list")
            if isinstance(iterable, Enumerated):
                item = (iterable.start + index, item)
            self._branches(test, functools.partial(run, item), lambda: None, node, scope, None)

    def _break(self, node: ast.Break, scope: Scope) -> None:
        raise _Break

    def _continue(self, node: ast.Continue, scope: Scope) -> None:
        raise _Continue

    def _function_def(self, node: ast.FunctionDef, scope: Scope) -> None:
        getter = [self.expr(d, scope) for d in node.decorator_list] == [Module("property")]
        if node.decorator_list and not getter:
            scope.names[node.name] = self.not_followed(f"decorated function {node.name}()", node)
            return
        arguments = node.args
        positional = [*arguments.posonlyargs, *arguments.args]
        defaults: dict[str, Value] = {}
        for argument, default in zip(
            positional[len(positional) - len(arguments.defaults) :],
            arguments.defaults,
            strict=True,
        ):
            defaults[argument.arg] = self.expr(default, scope)
        for argument, kw_default in zip(arguments.kwonlyargs, arguments.kw_defaults, strict=True):
            if kw_default is not None:
                defaults[argument.arg] = self.expr(kw_default, scope)
        function = Function(
            node, scope, defaults, self.file, getter=getter, generator=_yields(node)
        )
        scope.names[node.name] = function

    def _class_def(self, node: ast.ClassDef, scope: Scope) -> None:
        decorators = [self.expr(_called(d), scope) for d in node.decorator_list]
        decorators = [
            d
            for d in decorators
            if not (isinstance(d, Module) and python_name(d.qualified) in REGISTERING)
        ]
        if node.keywords or any(d != Module("dataclasses.dataclass") for d in decorators):
            scope.names[node.name] = self.not_followed(f"decorated class {node.name}", node)
            return
        bases = [self.expr(base, scope) for base in node.bases]
        cls = Class(node.name, bases, Scope(parent=scope))
        body = node.body
        if decorators:
            cls.fields = [_data_field(statement) for statement in body if _annotated(statement)]
            body = [s for s in body if not (_annotated(s) and _field_call(s) is not None)]
        with contextlib.suppress(_Return, _Break, _Continue):  # as Python, which refuses them
            self.block(body, cls.scope)
        for value in cls.scope.names.values():
            if isinstance(value, Function):
                value.owner = cls
        scope.names[node.name] = cls

    def _import(self, node: ast.Import, scope: Scope) -> None:
        for alias in node.names:
            if alias.asname is not None:
                scope.names[alias.asname] = self.module(alias.name, node) or Module(alias.name)
            else:
                top = alias.name.partition(".")[0]
                self.module(alias.name, node)  # read the submodule too
                scope.names[top] = self.module(top, node) or Module(top)

    def _import_from(self, node: ast.ImportFrom, scope: Scope) -> None:
        module = "." * node.level + (node.module or "")
        if node.level:
            module = self._absolute(node.level, node.module or "")
        found = self.module(module, node) if module else None
        for alias in node.names:
            if alias.name == "*":
                if found is not None:
                    scope.names.update(
                        (name, value)
                        for name, value in found.scope.names.items()
                        if not name.startswith("_")
                    )
                else:
                    self.not_followed(f"'from {module} import *'", node)
                continue
            name = alias.asname or alias.name
            if found is not None and alias.name in found.scope.names:
                scope.names[name] = found.scope.names[alias.name]
            else:
                submodule = self.module(f"{module}.{alias.name}", node) if found else None
                scope.names[name] = submodule or Module(f"{module}.{alias.name}")

    def _absolute(self, level: int, name: str) -> str:
        """A relative import's module, named from the current module's package."""
        found, package = False, ""
        for qualified, module in self.loaded.items():
            if module is not None and module.scope.names.get("__file__") == self.file.filename:
                found, package = True, qualified
                if not self.file.filename.endswith("__init__.py"):
                    package = package.rpartition(".")[0]
        if not found:
            return "." * level + name  # the launch file itself is no package
        for _ in range(level - 1):
            package = package.rpartition(".")[0]
        return f"{package}.{name}" if name else package

    def path_of(self, value: Value) -> str | None:
        """The absolute path ``value`` names, where known statically (a literal, the file's
        directory, a package's share directory, each with a literal tail)."""
        if isinstance(value, Dynamic):
            value = value.text
        if isinstance(value, FilePath):
            value = path_text(value)
        if isinstance(value, Text) and value.literal() is not None:
            value = value.literal()
        if isinstance(value, str):
            return value if os.path.isabs(value) else None
        if not isinstance(value, Text) or not value.parts:
            return None
        first, rest = value.parts[0], value.parts[1:]
        if not isinstance(first, Sub) or not all(isinstance(part, str) for part in rest):
            return None  # a substitution after the head: named at launch time
        tail = "".join(str(part) for part in rest)
        if first.name == "dirname" and not first.args:
            return os.path.dirname(self.file.filename) + tail
        package = first.args[0].literal() if len(first.args) == 1 else None
        if first.name == "find-pkg-share" and package and self.modules is not None:
            found = self.modules.packages.get(package)
            return None if found is None else found + tail
        return None

    def module(self, qualified: str, node: ast.AST) -> ModuleScope | None:
        """The module ``qualified`` of the workspace, read once; ``None`` if it is none (it
        stays a symbolic :class:`Module`) or cannot be read (reported)."""
        if qualified in self.loaded:
            return self.loaded[qualified]
        if self.modules is None or qualified.startswith("."):
            return None
        path = self.modules.find(qualified, self.paths)
        if path is None:
            self.loaded[qualified] = None
            return None
        if len(self.loaded) >= MAX_MODULES or self.loading >= MAX_IMPORT_DEPTH:
            self.not_followed(f"module {qualified} (beyond the bound on modules read)", node)
            return None
        where = self.location(node)
        try:
            if self.modules.confinement is not None:
                self.modules.confinement.check(path)
            text = read_file(path, limit=MAX_MODULE_BYTES).decode("utf-8-sig")
            tree = ast.parse(text, path)
        except (OSError, UnicodeDecodeError, SyntaxError, ValueError, RecursionError) as error:
            self.sink.warning(
                "python-module", f"module {qualified} ({path}) is not read: {error}", where
            )
            self.loaded[qualified] = None
            return None
        module = ModuleScope(qualified, Scope({"__name__": qualified, "__file__": path}))
        self.loaded[qualified] = module  # before its body: an import cycle sees it partial
        outer, guards = self.file, self.guards
        self.file, self.guards = SourceFile(path, text.splitlines()), []
        self.loading += 1
        try:
            self.block(tree.body, module.scope)
        except (_Return, _Break, _Continue):
            pass
        finally:
            self.file, self.guards = outer, guards
            self.loading -= 1
        return module

    def _raise(self, node: ast.Raise, scope: Scope) -> None:
        """``raise E(...)``: the exception, caught by an ``except`` of its class or a base."""
        if self.guards:
            self.not_followed("a 'raise' under an 'if' on a launch-time value", node)
            return
        exception: Value = None
        if node.exc is not None:
            called = node.exc.func if isinstance(node.exc, ast.Call) else node.exc
            kind = self.expr(called, scope)
            exception = kind if _builtin_exception(kind) else self.expr(node.exc, scope)
        raise PythonRaise(exception, self.location(node))

    def _try(self, node: ast.Try, scope: Scope) -> None:
        """The body; where it raises, the first handler catching the exception, as Python."""
        try:
            try:
                self.block(node.body, scope)
            except PythonRaise as raised:
                handler = self._handler(node.handlers, raised.value, scope)
                if handler is None:
                    raise
                if handler.name is not None:
                    scope.names[handler.name] = raised.value
                self.block(handler.body, scope)
            else:
                self.block(node.orelse, scope)
        finally:
            self.block(node.finalbody, scope)

    def _handler(
        self, handlers: list[ast.ExceptHandler], exception: Value, scope: Scope
    ) -> ast.ExceptHandler | None:
        for handler in handlers:
            if handler.type is None:
                return handler
            kinds = self.expr(handler.type, scope)
            answers = [
                _catches(kind, exception)
                for kind in (kinds if isinstance(kinds, tuple) else (kinds,))
            ]
            if True in answers:
                return handler
            if None in answers:
                self.not_followed("an 'except' of an exception not known statically", handler)
                return None
        return None

    def _with(self, node: ast.With, scope: Scope) -> None:
        for item in node.items:
            value = self.expr(item.context_expr, scope)
            if item.optional_vars is not None:
                if not isinstance(value, Unknown | FileHandle | WrittenFile):
                    value = self.not_followed("a 'with' context manager", item.context_expr)
                self.assign(item.optional_vars, value, scope)
        self.block(node.body, scope)

    # ------------------------------------------------------------------ expressions

    def expr(self, node: ast.expr, scope: Scope) -> Value:
        self.step()
        handler = self.expressions.get(type(node))
        if handler is None:
            return self.not_followed(f"a '{type(node).__name__}' expression", node)
        value = self.resolved(handler(node, scope))
        if not isinstance(node, _REFERENCES):
            self.charge(value)
        return value

    def distribute(
        self, values: list[Value], operation: Callable[[list[Value]], Value], node: ast.AST
    ) -> Value:
        """``operation`` of ``values``, where one is chosen at launch time (a
        :class:`Conditional`): the operation of each branch's value, under its test, then
        their choice."""
        for index, value in enumerate(values):
            if isinstance(value, Conditional):
                branches = []
                for test, side in (
                    (launch_time.truth(value.test), value.then),
                    (launch_time.negated(value.test), value.otherwise),
                ):
                    self.guards.append(test)
                    try:
                        chosen = [*values[:index], self.resolved(side), *values[index + 1 :]]
                        branches.append(self.distribute(chosen, operation, node))
                    finally:
                        self.guards.pop()
                return self.choose(value.test, branches[0], branches[1], node)
        return operation(values)

    def _constant(self, node: ast.Constant, scope: Scope) -> Value:
        if isinstance(node.value, _SCALARS):
            return node.value
        return self.not_followed(f"a {type(node.value).__name__} constant", node)

    def _name(self, node: ast.Name, scope: Scope) -> Value:
        found, value = scope.lookup(node.id)
        if found:
            return value
        if node.id in BUILTINS or hasattr(builtins, node.id):
            return Module(node.id)  # a call of a builtin not in BUILTINS is reported as such
        return self.not_followed(f"name '{node.id}'", node)

    def _joined_str(self, node: ast.JoinedStr, scope: Scope) -> Value:
        parts: list[Value] = []
        for value in node.values:
            if isinstance(value, ast.FormattedValue):
                if value.format_spec is not None or value.conversion not in (-1, ord("s")):
                    return self.not_followed("a formatted value with a format", value)
                parts.append(self.stringify(self.expr(value.value, scope), value))
            else:
                parts.append(self.expr(value, scope))
        return self.concatenate(parts, node)

    def stringify(self, value: Value, node: ast.AST) -> Value:
        """``str(value)`` where it is known."""
        if isinstance(value, _SCALARS):
            return str(value)
        if isinstance(value, Dynamic):
            return launch_time.stringified(value)
        if isinstance(value, Text | Unknown):
            return value
        if isinstance(value, FilePath):
            return paths.as_string(value)
        if isinstance(value, Conditional):
            return self.distribute([value], lambda values: self.stringify(values[0], node), node)
        return self.not_followed(f"str() of a {type(value).__name__}", node)

    def concatenate(self, parts: list[Value], node: ast.AST) -> Value:
        if sum(size(part) for part in parts) > MAX_LENGTH:
            return self.not_followed(f"a string longer than {MAX_LENGTH}", node)
        if all(isinstance(part, str) for part in parts):
            return "".join(str(part) for part in parts)
        texts: list[str | Text] = []
        for part in parts:
            if isinstance(part, Unknown):
                return part
            if isinstance(part, Dynamic):
                part = launch_time.as_text(part)
            elif not isinstance(part, str | Text):
                return self.not_followed(f"a {type(part).__name__} in a string", node)
            texts.append(part)
        if any(isinstance(part, Dynamic) for part in parts):
            return launch_time.concatenated([Text.of(text) for text in texts])
        return Text.of(*texts)

    def binary(self, op: ast.operator, left: Value, right: Value, node: ast.AST) -> Value:
        if isinstance(left, Conditional) or isinstance(right, Conditional):
            return self.distribute(
                [left, right], lambda values: self.binary(op, values[0], values[1], node), node
            )
        if isinstance(left, Unknown):
            return left
        if isinstance(right, Unknown):
            return right
        if isinstance(left, Dynamic) or isinstance(right, Dynamic):
            return self.launch_time_operation(OPERATORS.get(type(op)), left, right, node)
        if isinstance(op, ast.Add) and (isinstance(left, Text) or isinstance(right, Text)):
            return self.concatenate([left, right], node)
        if isinstance(op, ast.Div) and (isinstance(left, FilePath) or isinstance(right, FilePath)):
            parts = (paths.of_value(left), paths.of_value(right))
            if parts[0] is not None and parts[1] is not None:
                return paths.join(parts[0], parts[1])  # pathlib's '/'
        if isinstance(op, ast.Div) and isinstance(left, Text) and isinstance(right, str | Text):
            return join_path(left, Text.of(right))  # PathSubstitution(...) / 'config'

        function = ARITHMETIC.get(type(op))
        if function is not None and _constant(left) and _constant(right):
            if self._too_large(op, left, right):
                return self.not_followed("a value too large to compute", node)
            if isinstance(op, ast.Mod) and isinstance(left, str):
                return self.not_followed("'%' formatting", node)
            try:
                result: Value = function(left, right)
            except (TypeError, ValueError, ArithmeticError) as error:
                return self.not_followed(f"an operation that fails ({error})", node)
            return result
        if isinstance(op, ast.Add) and size(left) + size(right) > MAX_LENGTH:
            return self.not_followed(f"a list longer than {MAX_LENGTH}", node)
        if isinstance(op, ast.Add) and isinstance(left, list) and isinstance(right, list):
            return left + right
        if isinstance(op, ast.Add) and isinstance(left, tuple) and isinstance(right, tuple):
            return left + right
        return self.not_followed(f"operator {type(op).__name__}", node)

    def launch_time_operation(
        self, operator: str | None, left: Value, right: Value, node: ast.AST
    ) -> Value:
        """``left <operator> right`` where one is a launch-time value: a string joined
        (``+``), any other operation an expression."""
        kinds = (launch_time.kind_of(left), launch_time.kind_of(right))
        strings = all(
            isinstance(side, Text) or kind is str
            for side, kind in zip((left, right), kinds, strict=True)
        )
        if operator == "+" and strings:
            return self.concatenate([left, right], node)
        sources = (launch_time.source(left), launch_time.source(right))
        if operator is None or sources[0] is None or sources[1] is None:
            return self.not_followed(f"operator {operator} on a launch-time value", node)
        kind = launch_time.arithmetic_kind(operator, *kinds)
        return launch_time.binary(operator, sources[0], sources[1], kind)

    @staticmethod
    def _too_large(op: ast.operator, left: Value, right: Value) -> bool:
        """Whether an operation on constants would build a result over the limits."""
        if isinstance(op, ast.Mult):
            if isinstance(left, int) and isinstance(right, int):
                return left.bit_length() + right.bit_length() > MAX_INT_BITS
            if not isinstance(left, str | list | tuple) and not isinstance(
                right, str | list | tuple
            ):
                return False  # numbers: a float's size is bounded
            count = right if isinstance(right, int) else left
            sequence = left if count is right else right
            return not isinstance(count, int) or size(sequence) * max(count, 0) > MAX_LENGTH
        if isinstance(op, ast.Add):
            return size(left) + size(right) > max(MAX_LENGTH, MAX_INT_BITS)
        return False

    def _bin_op(self, node: ast.BinOp, scope: Scope) -> Value:
        return self.binary(node.op, self.expr(node.left, scope), self.expr(node.right, scope), node)

    def _unary_op(self, node: ast.UnaryOp, scope: Scope) -> Value:
        operand = self.expr(node.operand, scope)
        if isinstance(node.op, ast.Not):
            operand = self.tested(operand, node.operand)
        if isinstance(operand, Dynamic) and isinstance(node.op, ast.Not | ast.USub):
            if isinstance(node.op, ast.Not):
                return Dynamic(launch_time.negated(operand.source), bool)
            return Dynamic(Text.of("-(", operand.source, ")"), operand.kind)
        if isinstance(node.op, ast.Not):
            test = truth(operand)
            return Unknown("not of an unknown value") if test is None else not test
        if isinstance(operand, int | float) and isinstance(node.op, ast.USub | ast.UAdd):
            return -operand if isinstance(node.op, ast.USub) else operand
        return self.not_followed(f"operator {type(node.op).__name__}", node)

    def _bool_op(self, node: ast.BoolOp, scope: Scope) -> Value:
        value: Value = None
        launch_time_values: list[Value] = []  # from the first launch-time operand on
        for operand in node.values:
            value = self.expr(operand, scope)
            if launch_time_values or isinstance(value, Dynamic):
                launch_time_values.append(value)
                continue
            test = truth(value)
            if test is None:
                return Unknown("a condition not known statically")
            if test is isinstance(node.op, ast.Or):
                return value
        if not launch_time_values:
            return value
        sources = [launch_time.source(item) for item in launch_time_values]
        kinds = {launch_time.kind_of(item) for item in launch_time_values}
        parts: list[str | Text] = []
        for index, item_source in enumerate(sources):
            if item_source is None:
                return self.not_followed("a launch object in a launch-time condition", node)
            word = " and " if isinstance(node.op, ast.And) else " or "
            parts.extend([word, "(", item_source, ")"] if index else ["(", item_source, ")"])
        return Dynamic(Text.of(*parts), kinds.pop() if len(kinds) == 1 else None)

    def _compare(self, node: ast.Compare, scope: Scope) -> Value:
        operands = [self.expr(operand, scope) for operand in (node.left, *node.comparators)]
        return self.distribute(operands, lambda values: self._compared(node, values), node)

    def _compared(self, node: ast.Compare, operands: list[Value]) -> Value:
        if any(isinstance(operand, Dynamic) for operand in operands):
            return self._launch_time_comparison(node, operands)
        return self._compare_values(node, operands)

    def _launch_time_comparison(self, node: ast.Compare, operands: list[Value]) -> Value:
        """A comparison chain with a launch-time operand, as Python writes it."""
        parts: list[str | Text] = []
        for index, operand in enumerate(operands):
            operand_source = launch_time.source(operand)
            if operand_source is None:
                return self.not_followed("a comparison of a launch-time value", node)
            if index:
                parts.append(f" {OPERATORS[type(node.ops[index - 1])]} ")
            parts.extend(["(", operand_source, ")"])
        return Dynamic(Text.of(*parts), bool)

    def _compare_values(self, node: ast.Compare, operands: list[Value]) -> Value:
        left = operands[0]
        for op, right in zip(node.ops, operands[1:], strict=True):
            self.charge((left, right))  # a comparison walks both
            if _none_identity(op, left, right):  # `x is not None` of a launch object
                if isinstance(op, ast.Is):
                    return False
                left = right
                continue
            if not (_constant(left) or isinstance(left, dict)) or not (
                _constant(right) or isinstance(right, dict)
            ):
                return Unknown("a comparison of values not known statically")
            try:
                if not COMPARISONS[type(op)](left, right):
                    return False
            except TypeError as error:
                return self.not_followed(f"a comparison that fails ({error})", node)
            left = right
        return True

    def _if_exp(self, node: ast.IfExp, scope: Scope) -> Value:
        value = self.tested(self.expr(node.test, scope), node.test)
        if isinstance(value, Dynamic):
            test = value.source
            _, then_journal, then = self._branch(
                launch_time.truth(test), lambda: self.expr(node.body, scope), node
            )
            _, otherwise_journal, otherwise = self._branch(
                launch_time.negated(test), lambda: self.expr(node.orelse, scope), node
            )
            self.merge(test, then_journal, otherwise_journal, node)
            return self.choose(test, then, otherwise, node)
        known = truth(value)
        if known is None:
            return self.not_followed("a conditional expression on an unknown value", node)
        return self.expr(node.body if known else node.orelse, scope)

    def _elements(self, nodes: list[ast.expr], scope: Scope) -> list[Value]:
        items: list[Value] = []
        for element in nodes:
            if isinstance(element, ast.Starred):
                expanded = self.iterate(self.expr(element.value, scope), element)
                items.extend(expanded if expanded is not None else [Unknown("*unknown")])
            else:
                items.append(self.expr(element, scope))
        return items

    def _sequence(self, node: ast.List | ast.Set, scope: Scope) -> Value:
        return self._elements(node.elts, scope)

    def _dict(self, node: ast.Dict, scope: Scope) -> Value:
        result: dict[Key, Value] = {}
        for key_node, value_node in zip(node.keys, node.values, strict=True):
            value = self.expr(value_node, scope)
            if key_node is None:
                if isinstance(value, dict):
                    result.update(value)
                else:
                    self.not_followed("'**' of a value that is not a known dict", value_node)
                continue
            name = _dict_key(self.expr(key_node, scope))
            if isinstance(name, Key):
                result[name] = value
            else:
                self.not_followed(f"a dict key that is a {type(name).__name__}", key_node)
        return result

    def _subscript(self, node: ast.Subscript, scope: Scope) -> Value:
        container = self.expr(node.value, scope)
        if isinstance(node.slice, ast.Slice):
            bounds = [
                None if part is None else self.expr(part, scope)
                for part in (node.slice.lower, node.slice.upper, node.slice.step)
            ]
            return self.distribute(
                [container, *bounds], lambda values: self._slice(values[0], values[1:], node), node
            )
        index = self.expr(node.slice, scope)
        if isinstance(container, Module) and container.qualified.startswith("typing."):
            return container  # a type annotation (Union[str, int]): nothing launched
        return self.distribute(
            [container, index], lambda values: self._item(values[0], values[1], node), node
        )

    def _slice(self, container: Value, bounds: list[Value], node: ast.AST) -> Value:
        """``container[lower:upper:step]``."""
        numbers = [bound for bound in bounds if bound is None or isinstance(bound, int)]
        if isinstance(container, str | list | tuple) and len(numbers) == len(bounds):
            return container[slice(*numbers)]
        if isinstance(container, Dynamic) and all(
            bound is None or isinstance(bound, int) for bound in bounds
        ):
            written = ":".join("" if bound is None else str(bound) for bound in bounds)
            return Dynamic(Text.of("(", container.source, f")[{written}]"), container.kind)
        return self.not_followed("a slice of a value not known statically", node)

    def _item(self, container: Value, index: Value, node: ast.AST) -> Value:
        """``container[index]``."""
        if container == Module("os.environ") and isinstance(index, str | Text):
            return performed(Text.of(Sub("env", (Text.of(index),))))
        if container == Method(LaunchContext(), "launch_configurations"):
            return _configuration(self, node, index)
        if isinstance(container, Dynamic) or isinstance(index, Dynamic):
            return self._launch_time_item(container, index, node)
        if isinstance(container, LaunchYaml) and isinstance(index, str | int):
            return LaunchYaml(container.path, (*container.keys, index))
        try:
            if isinstance(container, dict) and isinstance(index, Key):
                return container[index]
            if isinstance(container, str | list | tuple) and isinstance(index, int):
                return container[index]
        except (KeyError, IndexError):
            return self.not_followed(f"a missing item {index!r}", node)
        if isinstance(container, Unknown):
            return container
        return self.not_followed("an item of a value not known statically", node)

    def _launch_time_item(self, container: Value, index: Value, node: ast.AST) -> Value:
        sources = (launch_time.source(container), launch_time.source(index))
        if sources[0] is None or sources[1] is None:
            return self.not_followed("an item of a launch-time value", node)
        kind = str if launch_time.kind_of(container) in (str, list) else None
        return Dynamic(Text.of("(", sources[0], ")[", sources[1], "]"), kind)

    def _attribute(self, node: ast.Attribute, scope: Scope) -> Value:
        owner = self.expr(node.value, scope)
        if isinstance(owner, Module):
            return Module(f"{owner.qualified}.{node.attr}")
        if isinstance(owner, Unknown):
            return owner
        if isinstance(owner, FilePath) and node.attr not in paths.METHODS:
            return paths.attribute(self, owner, node.attr, node)
        if isinstance(owner, WrittenFile) and node.attr == "name":
            return owner  # the file's name stands for the file written
        if isinstance(owner, ModuleScope):
            if node.attr in owner.scope.names:
                return owner.scope.names[node.attr]
            qualified = f"{owner.qualified}.{node.attr}"
            return self.module(qualified, node) or self.not_followed(f"name {qualified}", node)
        if isinstance(owner, Instance) and node.attr in owner.attributes:
            return owner.attributes[node.attr]
        if isinstance(owner, Instance | Class | Super):
            if isinstance(owner, Super):
                found, value = _class_lookup(owner.owner, node.attr, after=True)
            else:
                found, value = _class_lookup(
                    owner.cls if isinstance(owner, Instance) else owner, node.attr
                )
            if isinstance(value, Function) and value.getter and not isinstance(owner, Class):
                instance = owner.instance if isinstance(owner, Super) else owner
                return self.call_function(value, [instance], {}, node)  # a @property
            if found and not isinstance(value, Function):
                return value
        return Method(owner, node.attr)

    def _named_expr(self, node: ast.NamedExpr, scope: Scope) -> Value:
        value = self.expr(node.value, scope)
        self.assign(node.target, value, scope)
        return value

    def _comprehension(
        self, node: ast.ListComp | ast.GeneratorExp | ast.SetComp | ast.DictComp, scope: Scope
    ) -> Value:
        """The comprehension; over a value chosen at launch time, that of each branch's
        value, chosen."""
        first = node.generators[0]
        iterable = self.expr(first.iter, scope)
        if isinstance(iterable, Dynamic | Enumerated) and not isinstance(node, ast.DictComp):
            results: list[Value] = []

            def add(item: Value) -> None:
                items = self._comprehended(node, [item], scope)
                if isinstance(items, list):
                    self.touch(results)
                    results.extend(items)

            self.unrolled(iterable, add, node, scope)
            return self.resolved(results)
        return self.distribute(
            [iterable], lambda values: self._comprehended(node, values[0], scope), node
        )

    def _comprehended(
        self,
        node: ast.ListComp | ast.GeneratorExp | ast.SetComp | ast.DictComp,
        iterable: Value,
        scope: Scope,
    ) -> Value:
        inner = Scope(parent=scope)
        results: list[Value] = []
        pairs: dict[Key, Value] = {}
        for _ in self._generate(node.generators, inner, (iterable,)):
            if isinstance(node, ast.DictComp):
                name = self.expr(node.key, inner)
                if isinstance(name, Key):
                    pairs[name] = self.expr(node.value, inner)
                else:
                    return self.not_followed("a dict key not known statically", node.key)
            else:
                results.append(self.expr(node.elt, inner))
        return pairs if isinstance(node, ast.DictComp) else results

    def _generate(
        self,
        generators: list[ast.comprehension],
        scope: Scope,
        iterable: tuple[Value] | None = None,
    ) -> Iterator[None]:
        """The bindings of the comprehension's generators; ``iterable``: the first's value."""
        if not generators:
            yield None
            return
        first, rest = generators[0], generators[1:]
        given = self.expr(first.iter, scope) if iterable is None else iterable[0]
        items = self.iterate(given, first.iter)
        for item in items or []:
            self.assign(first.target, item, scope)
            tests = [truth(self.expr(test, scope)) for test in first.ifs]
            if None in tests:
                self.not_followed("a comprehension filter not known statically", first)
                return
            if all(tests):
                yield from self._generate(rest, scope)

    def iterate(self, value: Value, node: ast.AST) -> list[Value] | None:
        if isinstance(value, list | tuple):
            return [self.resolved(item) for item in value]
        if isinstance(value, str):
            return list(value)
        if isinstance(value, dict):
            return list(value)
        if isinstance(value, FileHandle):  # its lines, as Python iterates a text file
            text = reads.text(self, value, node)
            return list(text.splitlines(keepends=True)) if isinstance(text, str) else None
        if isinstance(value, Dynamic | Enumerated):
            self.not_followed("iteration over a launch-time value (its length is not known)", node)
        elif not isinstance(value, Unknown):
            self.not_followed(f"iteration over a {type(value).__name__}", node)
        return None

    # ------------------------------------------------------------------ calls

    def _call(self, node: ast.Call, scope: Scope) -> Value:
        if isinstance(node.func, ast.Name) and node.func.id == "super" and not node.args:
            found, owner = scope.lookup("__class__")
            _, instance = scope.lookup("__self__")
            if found and isinstance(owner, Class):
                return Super(instance, owner)
            return self.not_followed("super() outside a method", node)
        callee = self.expr(node.func, scope)
        args = self._elements(node.args, scope)
        kwargs: dict[str, Value] = {}
        for keyword in node.keywords:
            value = self.expr(keyword.value, scope)
            if keyword.arg is not None:
                kwargs[keyword.arg] = value
            elif isinstance(value, dict) and all(isinstance(name, str) for name in value):
                kwargs.update({str(name): item for name, item in value.items()})
            else:
                self.not_followed("'**' of a value that is not a known dict", keyword)
        return self.invoke(callee, args, kwargs, node)

    def invoke(
        self, callee: Value, args: list[Value], kwargs: dict[str, Value], node: ast.AST
    ) -> Value:
        if isinstance(callee, Unknown):
            return callee
        if isinstance(callee, Function):
            return self.call_function(callee, args, kwargs, node)
        if isinstance(callee, Method):
            return self.call_method(callee, args, kwargs, node)
        if isinstance(callee, Class):
            return self.instantiate(callee, args, kwargs, node)
        if isinstance(callee, Module):
            builtin = BUILTINS.get(callee.qualified) or CALLING.get(python_name(callee.qualified))
            if builtin is not None:
                return self.distribute(
                    args, lambda values: builtin(self, values, kwargs, node), node
                )
            call = Call(callee.qualified, args, kwargs, self.location(node), self.sink, self.remaps)
            builder = CALLS.get(python_name(callee.qualified))
            if builder is not None:
                call.args = [self.settled(arg) for arg in args]
                call.kwargs = {name: self.settled(arg) for name, arg in kwargs.items()}
                made = builder(call)
                if isinstance(made, Entity) and made.tag == "arg":
                    self.default_files.declare(
                        args[0] if args else kwargs.get("name"), call.arg(1, "default_value", None)
                    )
                return self.guarded_action(made, node) if isinstance(made, Entity) else made
            reason = REASONS.get(python_name(callee.qualified))
            return self.not_followed(reason or f"call to {callee.qualified}()", node)
        return self.not_followed(f"call of a {type(callee).__name__}", node)

    def call_function(
        self, function: Function, args: list[Value], kwargs: dict[str, Value], node: ast.AST
    ) -> Value:
        if self.depth >= MAX_CALL_DEPTH:
            return self.not_followed(f"recursion of {function.node.name}()", node)
        arguments = function.node.args
        positional = [argument.arg for argument in (*arguments.posonlyargs, *arguments.args)]
        scope = Scope(dict(function.defaults), function.scope)
        if function.owner is not None and args:  # for super(): the class and the instance
            scope.names["__class__"], scope.names["__self__"] = function.owner, args[0]
        for name, value in zip(positional, args, strict=False):
            scope.names[name] = value
        if arguments.vararg is not None:
            scope.names[arguments.vararg.arg] = tuple(args[len(positional) :])
        elif len(args) > len(positional):
            return self.not_followed(f"too many arguments to {function.node.name}()", node)
        extra: dict[Key, Value] = {}
        names = {*positional, *(argument.arg for argument in arguments.kwonlyargs)}
        for name, value in kwargs.items():
            if name in names:
                scope.names[name] = value
            else:
                extra[name] = value
        if arguments.kwarg is not None:
            scope.names[arguments.kwarg.arg] = extra
        elif extra:
            return self.not_followed(f"unexpected arguments to {function.node.name}()", node)
        missing = names - scope.names.keys()
        if missing:
            return self.not_followed(
                f"{function.node.name}() without {', '.join(sorted(missing))}", node
            )
        self.depth += 1
        outer, self.file = self.file, function.file
        if function.generator:
            self.yielded.append([])
        try:
            self.block(function.node.body, scope, tail=True)
        except _Return as returned:
            if not function.generator:
                return returned.value
        finally:
            self.depth -= 1
            self.file = outer
        return self.yielded.pop() if function.generator else None

    def _yield(self, node: ast.Yield | ast.YieldFrom, scope: Scope) -> Value:
        """What a generator yields, kept for its call (the value sent back is ``None``)."""
        value = None if node.value is None else self.expr(node.value, scope)
        if not self.yielded:
            return self.not_followed("'yield' outside a function", node)
        items = self.iterate(value, node) if isinstance(node, ast.YieldFrom) else [value]
        if items is None:
            return self.not_followed("'yield from' of unknown items", node)
        if len(self.yielded[-1]) + len(items) > MAX_LENGTH:
            return self.not_followed(f"a generator of more than {MAX_LENGTH} items", node)
        self.yielded[-1].extend(items)
        return None

    def instantiate(
        self, cls: Class, args: list[Value], kwargs: dict[str, Value], node: ast.AST
    ) -> Value:
        """An object of ``cls``, its ``__init__`` read; a launch ``Substitution`` subclass is
        the text its ``perform`` gives, an ``Action`` subclass the actions its ``execute``
        returns, read where it stands (as launch performs and executes them)."""
        instance = Instance(cls)
        found, init = _class_lookup(cls, "__init__")
        if found and isinstance(init, Function):
            self.call_function(init, [instance, *args], kwargs, node)
        elif cls.fields is not None:
            self._data_init(cls, cls.fields, instance, args, kwargs, node)
        else:
            instance.made = self._base_init(cls, args, kwargs, node)
        bases = _launch_bases(cls)
        call = Call(cls.name, [], {}, self.location(node), self.sink)
        found, perform = _class_lookup(cls, "perform")
        if any(base.endswith("Substitution") for base in bases) and isinstance(perform, Function):
            return self._performed(cls, perform, instance, args, kwargs, node)
        found, execute = _class_lookup(cls, "execute")
        entity = ("Action", "LaunchDescriptionEntity")
        if any(base.endswith(entity) for base in bases) and isinstance(execute, Function):
            actions = self.call_function(execute, [instance, LaunchContext()], {}, node)
            if isinstance(actions, Unknown):
                return actions
            actions = self.settled(actions)
            return _group(
                [] if actions is None else _actions(actions) or [], None, call.location, self.sink
            )
        if instance.made is not None:  # an action or substitution of launch, as its base
            return instance.made
        return instance

    def _performed(
        self,
        cls: Class,
        perform: Function,
        instance: Instance,
        args: list[Value],
        kwargs: dict[str, Value],
        node: ast.AST,
    ) -> Value:
        """The text ``perform`` gives; where it gives a file it writes, that file, its text
        computed per configuration (:mod:`.written`): this reading's diagnostics of it,
        made of values not known yet, are left out."""
        if self.rereading is not None:
            made = self.call_function(perform, [instance, LaunchContext()], {}, node)
            if isinstance(made, WrittenFile):
                return made
            return Call(cls.name, [], {}, self.location(node), self.sink).text(made)
        if written.writes_file(perform.node):
            return written.deferred(self, cls, args, kwargs, node)
        outer, self.sink = self.sink, DiagnosticSink()
        try:
            made = self.call_function(perform, [instance, LaunchContext()], {}, node)
        finally:
            scratch, self.sink = self.sink, outer
        if written.written_in(made):
            return written.deferred(self, cls, args, kwargs, node)
        self.sink.items.extend(scratch.items)
        return Call(cls.name, [], {}, self.location(node), self.sink).text(made)

    def _base_init(
        self, cls: Class, args: list[Value], kwargs: dict[str, Value], node: ast.AST
    ) -> Value:
        """What the constructor of the launch class ``cls`` derives from makes of ``args``
        (its ``super().__init__(...)``, or the class's own call without an ``__init__``):
        a subclass of ``DeclareLaunchArgument`` declares the argument, of ``Node`` is that
        node; ``None`` where the base is no launch action or substitution."""
        for base in _launch_bases(cls):
            builder = CALLS.get(python_name(base))
            if builder is not None:
                call = Call(cls.name, args, kwargs, self.location(node), self.sink, self.remaps)
                made = builder(call)
                return self.guarded_action(made, node) if isinstance(made, Entity) else made
        return None

    def call_method(
        self, method: Method, args: list[Value], kwargs: dict[str, Value], node: ast.AST
    ) -> Value:
        receiver, name = method.receiver, method.name
        if isinstance(receiver, Instance | Class | Super):
            return self._call_class_method(receiver, name, args, kwargs, node)
        if isinstance(receiver, Condition) and name == "evaluate":
            literal = receiver.text.literal()
            if literal is not None:  # launch's truth of a known text
                return (literal.strip().lower() in ("true", "1")) == (receiver.attribute == "if")
            return launch_time.evaluated(receiver.attribute, receiver.text)
        if isinstance(receiver, FileHandle) and name == "read" and not args:
            return reads.text(self, receiver, node)
        if isinstance(receiver, WrittenFile) and name == "write":
            return written.write(self, receiver, args, node)
        if isinstance(receiver, WrittenFile | FileHandle) and name in ("close", "flush"):
            return None
        if isinstance(receiver, FilePath) and name in paths.METHODS:
            return paths.METHODS[name](self, receiver, args, node)
        if isinstance(receiver, Pattern) and name in patterns.METHODS:
            return patterns.METHODS[name](self, receiver, args, node)
        if isinstance(receiver, Match):
            return patterns.match_method(self, receiver, name, args, node)
        if isinstance(receiver, XacroDocument) and name in ("toxml", "toprettyxml"):
            return xacro_calls.document_text(receiver)
        if isinstance(receiver, Description) and name in ("add_action", "add_entity") and args:
            call = Call(f"LaunchDescription.{name}", args, kwargs, self.location(node), self.sink)
            add_actions(call, receiver.root, [self.guarded_item(args[0], node)])
            return None
        if isinstance(receiver, Conditional) or (
            isinstance(receiver, str | list | tuple | dict | Dynamic)
            and any(isinstance(arg, Conditional) for arg in args)
        ):
            return self.distribute(
                [receiver, *args],
                lambda values: self.call_method(Method(values[0], name), values[1:], kwargs, node),
                node,
            )
        if isinstance(receiver, list) and name in LIST_METHODS:
            return LIST_METHODS[name](self, receiver, args, node)
        if isinstance(receiver, dict):
            return self._dict_method(receiver, name, args, kwargs, node)
        if isinstance(receiver, Text) and name == "perform":
            return performed(receiver)  # the value at launch time, which the text stands for
        method_of = substitution_method(receiver, name) if isinstance(receiver, Text) else None
        if method_of is not None:
            call = Call(name, args, kwargs, self.location(node), self.sink)
            return method_of(call)
        if isinstance(receiver, LaunchContext) and name == "perform_substitution" and args:
            return performed(Call(name, args, kwargs, self.location(node), self.sink).text(args[0]))
        if receiver == Method(LaunchContext(), "launch_configurations") and name == "get" and args:
            return _configuration(self, node, *args[:2])
        if isinstance(receiver, str) and name in _STR_METHODS:
            return self._str_method(receiver, name, args, kwargs, node)
        if isinstance(receiver, Dynamic) and name in launch_time.STRING_METHODS and not kwargs:
            sources = [launch_time.source(arg) for arg in args]
            given = [arg_source for arg_source in sources if arg_source is not None]
            if len(given) == len(sources):
                return launch_time.method(receiver, name, given)
        if type(receiver) in _PLAIN_TYPES and not hasattr(type(receiver), name):
            return self.raises("AttributeError", node)  # as `try: d.keys() except ...` expects
        return self.not_followed(f"method {name}() of a {type(receiver).__name__}", node)

    def raises(self, kind: str, node: ast.AST) -> Value:
        """Python's exception ``kind`` raised by an operation of a builtin where ``node`` is;
        under a launch-time ``if`` it is raised in some configurations only: not followed."""
        if self.guards:
            return self.not_followed(f"an operation raising {kind} under a launch-time 'if'", node)
        raise PythonRaise(Module(kind), self.location(node))

    def _data_init(
        self,
        cls: Class,
        fields: list[DataField],
        instance: Instance,
        args: list[Value],
        kwargs: dict[str, Value],
        node: ast.AST,
    ) -> None:
        """The ``__init__`` a ``@dataclass`` makes: each field from its argument, or its
        default (read in the class body's scope), or its factory called."""
        if len(args) > len(fields) or set(kwargs) - {f.name for f in fields}:
            self.not_followed(f"arguments of {cls.name}() that are not its fields", node)
        for index, data in enumerate(fields):
            if index < len(args):
                value = args[index]
            elif data.name in kwargs:
                value = kwargs[data.name]
            elif data.default is None:
                value = self.not_followed(f"{cls.name}() without {data.name}", node)
            elif data.factory:
                factory = self.expr(data.default, cls.scope)
                value = self.invoke(factory, [], {}, node)
            else:
                value = self.expr(data.default, cls.scope)
            instance.attributes[data.name] = value

    def _call_class_method(
        self,
        receiver: Instance | Class | Super,
        name: str,
        args: list[Value],
        kwargs: dict[str, Value],
        node: ast.AST,
    ) -> Value:
        if isinstance(receiver, Super):
            found, function = _class_lookup(receiver.owner, name, after=True)
            bound = [receiver.instance]
        else:
            cls = receiver.cls if isinstance(receiver, Instance) else receiver
            found, function = _class_lookup(cls, name)
            bound = [receiver] if isinstance(receiver, Instance) else []
        if isinstance(function, Function):
            return self.call_function(function, [*bound, *args], kwargs, node)
        if isinstance(receiver, Super) and name == "__init__":
            made = self._base_init(receiver.owner, args, kwargs, node)
            if isinstance(receiver.instance, Instance) and made is not None:
                receiver.instance.made = made
            return None
        if found:
            return self.invoke(function, args, kwargs, node)
        return self.not_followed(f"method {name}() of {type(receiver).__name__.lower()}", node)

    def _dict_method(
        self,
        receiver: dict[Key, Value],
        name: str,
        args: list[Value],
        kwargs: dict[str, Value],
        node: ast.AST,
    ) -> Value:
        if name == "items":
            return [(name_, value) for name_, value in receiver.items()]
        if name == "keys":
            return list(receiver)
        if name == "values":
            return list(receiver.values())
        if name == "copy":
            return dict(receiver)
        if name == "get" and args and isinstance(args[0], Key):
            return receiver.get(args[0], args[1] if len(args) > 1 else None)
        if name == "update" and len(args) <= 1 and all(isinstance(a, dict) for a in args):
            self.touch(receiver)
            for mapping in [*args, kwargs]:
                receiver.update(mapping)  # type: ignore[arg-type]
            return None
        if name == "setdefault" and 1 <= len(args) <= 2 and isinstance(args[0], Key):
            if args[0] not in receiver:
                self.touch(receiver)
            return receiver.setdefault(args[0], args[1] if len(args) > 1 else None)
        if name == "pop" and 1 <= len(args) <= 2 and isinstance(args[0], Key):
            if args[0] in receiver:
                self.touch(receiver)
                return receiver.pop(args[0])
            if len(args) == 2:
                return args[1]
            return self.not_followed(f"dict.pop() of a missing key {args[0]!r}", node)
        if name == "clear" and not args:
            self.touch(receiver)
            receiver.clear()
            return None
        return self.not_followed(f"method {name}() of a dict", node)

    def remove(self, receiver: list[Value], item: Value, node: ast.AST) -> Value:
        """``receiver.remove(item)``; for a launch-time ``item``, the list stands for the
        choice, item by item, of the list without it (the first equal one), and a value
        that says launch fails where none is equal."""
        if not isinstance(item, Dynamic):
            for index, present in enumerate(receiver):
                if _same(present, item):
                    self.touch(receiver)
                    del receiver[index]
                    return None
            if _constant(item) and all(_constant(present) for present in receiver):
                return self.not_followed("list.remove() of a value not in the list", node)
            return self.not_followed("list.remove() of a value not known statically", node)
        sources = [launch_time.source(present) for present in receiver]
        known = [source for source in sources if source is not None]
        if len(known) < len(sources):
            return self.not_followed("list.remove() of a launch-time value", node)
        self.step(len(receiver) ** 2)
        # where no item is equal launch fails: a value that fails where its text is needed
        chosen: Value = [Unknown("list.remove() of a value not in the list, where launch fails")]
        for index in reversed(range(len(receiver))):
            test = Text.of("(", item.source, ") == (", known[index], ")")
            chosen = Conditional(test, [*receiver[:index], *receiver[index + 1 :]], chosen)
        self.touch(receiver)
        self.forwarding.forward(receiver, chosen)
        return None

    def _format(
        self, template: str, args: list[Value], kwargs: dict[str, Value], node: ast.AST
    ) -> Value:
        """``str.format`` with plain fields (``{}``, ``{0}``, ``{name}``), no format specs."""
        parts: list[Value] = []
        automatic = 0
        try:
            fields = list(string.Formatter().parse(template))
        except ValueError as error:
            return self.not_followed(f"str.format() that fails ({error})", node)
        for literal, field, spec, conversion in fields:
            parts.append(literal)
            if field is None:
                continue
            if spec or conversion:
                return self.not_followed("str.format() with a format", node)
            if field == "":
                field, automatic = str(automatic), automatic + 1
            if field.isdigit() and int(field) < len(args):
                parts.append(self.stringify(args[int(field)], node))
            elif field in kwargs:
                parts.append(self.stringify(kwargs[field], node))
            else:
                return self.not_followed(f"str.format() field {{{field}}}", node)
        return self.concatenate(parts, node)

    def _str_method(
        self, receiver: str, name: str, args: list[Value], kwargs: dict[str, Value], node: ast.AST
    ) -> Value:
        if name == "join" and len(args) == 1:
            items = self.iterate(args[0], node)
            if items is None:
                return Unknown("join of unknown items")
            parts: list[Value] = []
            for index, item in enumerate(items):
                parts.extend([receiver, item] if index else [item])
            return self.concatenate(parts, node)
        if name == "format":
            return self._format(receiver, args, kwargs, node)
        if size(receiver) * max([1, *(size(arg) for arg in args)]) > MAX_LENGTH:
            return self.not_followed(f"str.{name}() of long strings", node)
        if all(_constant(arg) for arg in args) and not kwargs:
            try:
                result: Value = getattr(receiver, name)(*args)
            except (TypeError, ValueError) as error:
                return self.not_followed(f"str.{name}() that fails ({error})", node)
            return result
        return self.not_followed(f"str.{name}() of values not known statically", node)


_PLAIN_TYPES = (str, int, float, bool, type(None), list, tuple, dict)
"""Python's types of the values the reading keeps as themselves."""


def _builtin_exception(kind: Value) -> bool:
    """Whether ``kind`` is one of Python's exception classes (``KeyError``)."""
    if not isinstance(kind, Module):
        return False
    found = getattr(builtins, kind.qualified, None)
    return isinstance(found, type) and issubclass(found, BaseException)


def _catches(kind: Value, exception: Value) -> bool | None:
    """Whether ``except kind`` catches ``exception``; ``None`` where not known."""
    if isinstance(exception, Instance):
        if isinstance(kind, Class):
            return kind is exception.cls or _derives(exception.cls, kind)
        names = [Module(name) for name in _launch_bases(exception.cls)]
        return any(_catches(kind, name) for name in names if _builtin_exception(name))
    if _builtin_exception(exception) and isinstance(exception, Module):
        if isinstance(kind, Class):
            return False
        if _builtin_exception(kind) and isinstance(kind, Module):
            return issubclass(
                getattr(builtins, exception.qualified), getattr(builtins, kind.qualified)
            )
    return None


def _dict_key(value: Value) -> Value:
    """A launch-time string as a dict's key is the text of its substitutions (moveit's
    ``Xacro.perform`` keys its mappings by ``perform_substitutions(...)``)."""
    if isinstance(value, Dynamic) and value.kind is str and value.text is not None:
        return value.text
    return value


ListMethod = Callable[[Interpreter, list[Value], list[Value], ast.AST], Value]


def _append(
    interpreter: Interpreter, receiver: list[Value], args: list[Value], node: ast.AST
) -> Value:
    if len(args) != 1:
        return interpreter.not_followed("list.append() of other than one value", node)
    interpreter.touch(receiver)
    receiver.append(interpreter.guarded_item(args[0], node))
    return None


def _insert(
    interpreter: Interpreter, receiver: list[Value], args: list[Value], node: ast.AST
) -> Value:
    if len(args) != 2 or not isinstance(args[0], int):
        return interpreter.not_followed("list.insert() at a place not known statically", node)
    interpreter.touch(receiver)
    receiver.insert(args[0], interpreter.guarded_item(args[1], node))
    return None


def _extend(
    interpreter: Interpreter, receiver: list[Value], args: list[Value], node: ast.AST
) -> Value:
    items = interpreter.iterate(args[0], node) if len(args) == 1 else None
    if items is not None and len(receiver) + len(items) > MAX_LENGTH:
        return interpreter.not_followed(f"a list longer than {MAX_LENGTH}", node)
    interpreter.touch(receiver)
    for item in items if items is not None else [Unknown("*unknown")]:
        receiver.append(interpreter.guarded_item(item, node))
    return None


def _remove(
    interpreter: Interpreter, receiver: list[Value], args: list[Value], node: ast.AST
) -> Value:
    if len(args) != 1:
        return interpreter.not_followed("list.remove() of other than one value", node)
    return interpreter.remove(receiver, args[0], node)


def _pop(
    interpreter: Interpreter, receiver: list[Value], args: list[Value], node: ast.AST
) -> Value:
    index = args[0] if args else -1
    if len(args) > 1 or not isinstance(index, int) or not -len(receiver) <= index < len(receiver):
        return interpreter.not_followed("list.pop() at a place not known statically", node)
    interpreter.touch(receiver)
    return receiver.pop(index)


def _clear(
    interpreter: Interpreter, receiver: list[Value], args: list[Value], node: ast.AST
) -> Value:
    interpreter.touch(receiver)
    receiver.clear()
    return None


def _copied(
    interpreter: Interpreter, receiver: list[Value], args: list[Value], node: ast.AST
) -> Value:
    return list(receiver)


def _index(
    interpreter: Interpreter, receiver: list[Value], args: list[Value], node: ast.AST
) -> Value:
    if len(args) == 1:
        for index, present in enumerate(receiver):
            if _same(present, args[0]):
                return index
    return interpreter.not_followed("list.index() of a value not known in the list", node)


def _count(
    interpreter: Interpreter, receiver: list[Value], args: list[Value], node: ast.AST
) -> Value:
    if len(args) == 1 and _constant(args[0]) and all(_constant(item) for item in receiver):
        return sum(1 for item in receiver if _same(item, args[0]))
    return interpreter.not_followed("list.count() of values not known statically", node)


LIST_METHODS: dict[str, ListMethod] = {
    "append": _append,
    "insert": _insert,
    "extend": _extend,
    "remove": _remove,
    "pop": _pop,
    "clear": _clear,
    "copy": _copied,
    "index": _index,
    "count": _count,
}
"""Methods of a list the reading follows; those that change it touch it first (a
launch-time branch keeps its own copy)."""


def _none_identity(op: ast.cmpop, left: Value, right: Value) -> bool:
    """Whether ``left op right`` asks if a value known never to be ``None`` (a launch
    object, a substitution's text, an object) is ``None``: never."""
    if not isinstance(op, ast.Is | ast.IsNot) or (left is None) == (right is None):
        return False
    other = right if left is None else left
    return not isinstance(other, Unknown | Dynamic | Conditional)


def _yields(function: ast.FunctionDef) -> bool:
    """Whether ``function`` is a generator: a ``yield`` in its body, not in a nested scope."""
    pending: list[ast.AST] = list(function.body)
    while pending:
        node = pending.pop()
        if isinstance(node, ast.Yield | ast.YieldFrom):
            return True
        if not isinstance(node, ast.FunctionDef | ast.AsyncFunctionDef | ast.ClassDef | ast.Lambda):
            pending.extend(ast.iter_child_nodes(node))
    return False


def _called(decorator: ast.expr) -> ast.expr:
    """The decorator's callee (``@dataclass(slots=True)``: ``dataclass``)."""
    return decorator.func if isinstance(decorator, ast.Call) else decorator


def _annotated(statement: ast.stmt) -> bool:
    return isinstance(statement, ast.AnnAssign) and isinstance(statement.target, ast.Name)


def _field_call(statement: ast.stmt) -> ast.Call | None:
    """``field(...)`` as an annotated assignment's value, if it is."""
    value = statement.value if isinstance(statement, ast.AnnAssign) else None
    if isinstance(value, ast.Call) and isinstance(value.func, ast.Name | ast.Attribute):
        name = value.func.id if isinstance(value.func, ast.Name) else value.func.attr
        return value if name == "field" else None
    return None


def _data_field(statement: ast.stmt) -> DataField:
    assert isinstance(statement, ast.AnnAssign) and isinstance(statement.target, ast.Name)
    call = _field_call(statement)
    if call is None:
        return DataField(statement.target.id, statement.value, factory=False)
    keywords = {keyword.arg: keyword.value for keyword in call.keywords}
    if "default_factory" in keywords:
        return DataField(statement.target.id, keywords["default_factory"], factory=True)
    return DataField(statement.target.id, keywords.get("default"), factory=False)


def _class_lookup(cls: Class, name: str, after: bool = False) -> tuple[bool, Value]:
    """``name`` in ``cls`` or its bases (depth first, as Python's order for single bases);
    ``after``: in its bases only (``super()``)."""
    if not after and name in cls.scope.names:
        return True, cls.scope.names[name]
    for base in cls.bases:
        if isinstance(base, Class):
            found, value = _class_lookup(base, name)
            if found:
                return True, value
    return False, None


def _launch_bases(cls: Class) -> list[str]:
    """The qualified names of the launch (or other symbolic) classes ``cls`` derives from."""
    names: list[str] = []
    for base in cls.bases:
        if isinstance(base, Module):
            names.append(base.qualified)
        elif isinstance(base, Class):
            names += _launch_bases(base)
    return names


def _branch_source(value: Value) -> Text | None:
    """The Python source of a value a branch gives; a text of substitutions is the string
    it gives at launch time."""
    if isinstance(value, Text):
        return launch_time.quoted(value)
    return launch_time.source(value)


def _whole(items: list[Value] | dict[Key, Value] | dict[str, Value], to: Value) -> Value:
    """A branch's value of a list or dict: the value it was forwarded to, else a new one
    holding its items."""
    if to is not None:
        return to
    if isinstance(items, list):
        return list(items)
    whole: dict[Key, Value] = {}
    whole.update(items.items())
    return whole


def _within(items: list[Value], index: int) -> bool:
    return -len(items) <= index < len(items)


def _same(one: Value, other: Value) -> bool:
    """Whether two values are the same for every launch: one object, or equal constants."""
    if one is other:
        return True
    return _constant(one) and _constant(other) and type(one) is type(other) and one == other


def _actions(value: Value) -> list[Entity] | None:
    """The actions ``value`` is (an action, a list of them, nothing); ``None`` if it is not."""
    if value is None:
        return []
    if isinstance(value, Entity):
        return [value]
    if isinstance(value, Description):
        return list(value.root.children)
    if isinstance(value, list | tuple):
        actions: list[Entity] = []
        for item in value:
            inner = _actions(item)
            if inner is None:
                return None
            actions += inner
        return actions
    return None


def _group(
    actions: list[Entity], test: Text | None, location: Location, sink: DiagnosticSink
) -> Entity:
    """An unscoped group of ``actions``, as launch runs the actions a branch adds: in the
    same launch configurations; under ``test`` if given."""
    kwargs: dict[str, Value] = {"actions": list(actions), "scoped": False}
    if test is not None:
        kwargs["condition"] = Condition("if", launch_time.condition(test))
    made = CALLS[("launch", "GroupAction")](Call("GroupAction", [], kwargs, location, sink))
    assert isinstance(made, Entity)
    return made


def _str(
    interpreter: Interpreter, args: list[Value], kwargs: dict[str, Value], node: ast.AST
) -> Value:
    return interpreter.stringify(args[0], node) if len(args) == 1 else ""


def _convert(kind: type[int] | type[float] | type[bool]) -> Builtin:
    def convert(
        interpreter: Interpreter, args: list[Value], kwargs: dict[str, Value], node: ast.AST
    ) -> Value:
        if len(args) == 1 and isinstance(args[0], str | int | float | bool):
            try:
                return kind(args[0])
            except ValueError:
                return interpreter.raises("ValueError", node)
        if not args:
            return kind()
        if len(args) == 1 and isinstance(args[0], Dynamic):
            return launch_time.call(kind.__name__, [args[0].source])
        return interpreter.not_followed(f"{kind.__name__}() of a value not known statically", node)

    return convert


def _len(
    interpreter: Interpreter, args: list[Value], kwargs: dict[str, Value], node: ast.AST
) -> Value:
    if len(args) == 1 and isinstance(args[0], str | list | tuple | dict):
        return len(args[0])
    if len(args) == 1 and isinstance(args[0], Dynamic):
        return launch_time.call("len", [args[0].source])
    return interpreter.not_followed("len() of a value not known statically", node)


def _range(
    interpreter: Interpreter, args: list[Value], kwargs: dict[str, Value], node: ast.AST
) -> Value:
    if 1 <= len(args) <= 3 and all(isinstance(arg, int) for arg in args):
        numbers = range(*(int(arg) for arg in args if isinstance(arg, int)))
        if len(numbers) <= MAX_LENGTH:
            return list(numbers)
    return interpreter.not_followed("range() of values not known statically", node)


def _collection(kind: type[list[Value]] | type[tuple[Value, ...]]) -> Builtin:
    def collect(
        interpreter: Interpreter, args: list[Value], kwargs: dict[str, Value], node: ast.AST
    ) -> Value:
        if not args:
            return kind()
        items = interpreter.iterate(args[0], node)
        return Unknown(f"{kind.__name__}() of unknown items") if items is None else kind(items)

    return collect


def _dict_builtin(
    interpreter: Interpreter, args: list[Value], kwargs: dict[str, Value], node: ast.AST
) -> Value:
    """``dict(mapping)``, ``dict(pairs)``, then keywords."""
    result: dict[Key, Value] = {}
    if args and isinstance(args[0], dict):
        result.update(args[0])
    elif args:
        pairs = interpreter.iterate(args[0], node)
        if pairs is None or not all(
            isinstance(pair, list | tuple) and len(pair) == 2 and isinstance(pair[0], Key)
            for pair in pairs
        ):
            return interpreter.not_followed("dict() of a value that is not pairs", node)
        result.update((pair[0], pair[1]) for pair in pairs)  # type: ignore[index,misc]
    result.update(kwargs)
    return result


def _enumerate(
    interpreter: Interpreter, args: list[Value], kwargs: dict[str, Value], node: ast.AST
) -> Value:
    """``enumerate(items, start=0)``; of a launch-time list, its items as a loop reads
    them (:class:`Enumerated`)."""
    start = args[1] if len(args) > 1 else kwargs.get("start", 0)
    if not args or not isinstance(start, int) or isinstance(start, bool):
        return interpreter.not_followed("enumerate() of these arguments", node)
    if isinstance(args[0], Dynamic):
        return Enumerated(args[0], start)
    items = interpreter.iterate(args[0], node)
    if items is None:
        return Unknown("enumerate()")
    return [(i, v) for i, v in enumerate(items, start)]


def _zip(
    interpreter: Interpreter, args: list[Value], kwargs: dict[str, Value], node: ast.AST
) -> Value:
    columns = [interpreter.iterate(arg, node) for arg in args]
    if any(column is None for column in columns):
        return Unknown("zip()")
    return [tuple(row) for row in zip(*(column or [] for column in columns), strict=False)]


def _chain(
    interpreter: Interpreter, args: list[Value], kwargs: dict[str, Value], node: ast.AST
) -> Value:
    """``itertools.chain(a, b, ...)``: the items of each in turn (a list: read once)."""
    items: list[Value] = []
    for arg in args:
        part = interpreter.iterate(arg, node)
        if part is None:
            return Unknown("itertools.chain() of unknown items")
        if len(items) + len(part) > MAX_LENGTH:
            return interpreter.not_followed(f"a list longer than {MAX_LENGTH}", node)
        items += part
    return items


def _sys_path(
    interpreter: Interpreter, args: list[Value], kwargs: dict[str, Value], node: ast.AST
) -> Value:
    """``sys.path.append(d)`` (``insert(i, d)``): later imports search ``d`` too, where it is
    known (a literal, the file's directory, a package's share directory below)."""
    directory = interpreter.path_of(args[-1]) if args else None
    if directory is not None:
        interpreter.paths.append(directory)
    return None


def _copy(deep: bool) -> Builtin:
    def copy(
        interpreter: Interpreter, args: list[Value], kwargs: dict[str, Value], node: ast.AST
    ) -> Value:
        """``copy.copy``/``copy.deepcopy`` of lists, tuples and dicts (sharing kept, as
        Python's memo keeps it; each copied container a step); anything else is itself
        (immutable to the reading)."""
        if len(args) != 1:
            return interpreter.not_followed("copy() of other than one value", node)
        copies: dict[int, Value] = {}

        def copied(value: Value, depth: int) -> Value:
            if not isinstance(value, list | tuple | dict) or (not deep and depth > 0):
                return value
            if id(value) in copies:
                return copies[id(value)]
            interpreter.step()
            if isinstance(value, dict):
                mapping: dict[Key, Value] = {}
                copies[id(value)] = mapping
                mapping.update((key, copied(item, depth + 1)) for key, item in value.items())
                return mapping
            items = [copied(item, depth + 1) for item in value]
            result: Value = items if isinstance(value, list) else tuple(items)
            copies[id(value)] = result
            return result

        return copied(args[0], 0)

    return copy


def _print(
    interpreter: Interpreter, args: list[Value], kwargs: dict[str, Value], node: ast.AST
) -> Value:
    """``print`` and ``logging``'s messages: nothing the launch is made of."""
    return None


_TYPES: dict[str, type] = {
    "str": str,
    "int": int,
    "float": float,
    "bool": bool,
    "dict": dict,
    "list": list,
    "tuple": tuple,
}
_PATH_TYPES = frozenset({"pathlib.Path", "pathlib.PurePath", "pathlib.PosixPath"})


def _is_instance(value: Value, kind: Value) -> bool | None:
    """``isinstance(value, kind)`` for one type; ``None`` where not known."""
    if isinstance(kind, Class):
        if not isinstance(value, Instance):
            return False if isinstance(value, _SCALARS) else None
        return kind is value.cls or _derives(value.cls, kind)
    if not isinstance(kind, Module):
        return None
    if kind.qualified in _PATH_TYPES:
        return isinstance(value, FilePath)
    python_type = _TYPES.get(kind.qualified)
    if python_type is None:
        return None
    if isinstance(value, (*_SCALARS, list, tuple, dict)):
        return isinstance(value, python_type)
    if isinstance(value, Dynamic):
        return None if value.kind is None else issubclass(value.kind, python_type)
    if isinstance(value, Text):  # a substitution object, or the string of a literal
        return python_type is str if value.literal() is not None else False
    if isinstance(value, Unknown | Module | Instance):
        return None
    return False  # a launch object or a path


def _derives(cls: Class, base: Class) -> bool:
    return any(b is base or (isinstance(b, Class) and _derives(b, base)) for b in cls.bases)


def _isinstance(
    interpreter: Interpreter, args: list[Value], kwargs: dict[str, Value], node: ast.AST
) -> Value:
    """``isinstance(value, T)`` (``T`` a builtin type, a path, a class of the file or its
    modules, or a tuple of them); a text of substitutions is a substitution object."""
    if len(args) != 2 or kwargs:
        return interpreter.not_followed("isinstance() of other than two arguments", node)
    kinds = args[1] if isinstance(args[1], tuple) else (args[1],)
    answers = [_is_instance(args[0], kind) for kind in kinds]
    if True in answers:
        return True
    if None in answers:
        return interpreter.not_followed("isinstance() of a value or type not known", node)
    return False


def _quantifier(everything: bool) -> Builtin:
    def quantify(
        interpreter: Interpreter, args: list[Value], kwargs: dict[str, Value], node: ast.AST
    ) -> Value:
        """``all(items)``/``any(items)``, stopping where Python stops."""
        items = interpreter.iterate(args[0], node) if len(args) == 1 else None
        if items is None:
            return Unknown("all() or any() of unknown items")
        for item in items:
            test = truth(item)
            if test is None:
                return interpreter.not_followed("all() or any() of values not known", node)
            if test is not everything:
                return test
        return everything

    return quantify


def _ordering(name: str) -> Builtin:
    def order(
        interpreter: Interpreter, args: list[Value], kwargs: dict[str, Value], node: ast.AST
    ) -> Value:
        """``min``/``max`` (of arguments or one sequence) and ``sorted`` of constants."""
        items = interpreter.iterate(args[0], node) if len(args) == 1 else list(args)
        if items is None or kwargs or (not items and name != "sorted"):
            return interpreter.not_followed(f"{name}() of values not known statically", node)
        if not all(_constant(item) for item in items):
            return interpreter.not_followed(f"{name}() of values not known statically", node)
        interpreter.charge(items)
        try:
            result: Value = getattr(builtins, name)(items)
        except TypeError as error:
            return interpreter.not_followed(f"{name}() that fails ({error})", node)
        return result

    return order


def _path_function(function: paths.PathMethod) -> Builtin:
    def call(
        interpreter: Interpreter, args: list[Value], kwargs: dict[str, Value], node: ast.AST
    ) -> Value:
        if len(args) != 1:
            return interpreter.not_followed("os.path of other than one path", node)
        return function(interpreter, args[0], [], node)

    return call


def _configuration(
    interpreter: Interpreter, node: ast.AST, name: Value, default: Value = None
) -> Value:
    """``context.launch_configurations[name]`` (``.get(name, default)``): ``$(var name)``."""
    if not isinstance(name, str):
        return interpreter.not_followed("a launch configuration named by a non-string", node)
    if default is None:
        return performed(Text.of(Sub("var", (Text.of(name),))))
    if isinstance(default, Dynamic) and default.text is not None:
        default = default.text
    if not isinstance(default, str | Text):
        return interpreter.not_followed("a launch configuration's non-string default", node)
    return performed(Text.of(Sub("var", (Text.of(name), Text.of(default)))))


def _opaque_function(
    interpreter: Interpreter, args: list[Value], kwargs: dict[str, Value], node: ast.AST
) -> Value:
    """``OpaqueFunction(function=f, args=..., kwargs=...)``: launch calls ``f(context, ...)``
    where the action stands and visits the actions it returns there, in the same launch
    configurations: the file's own ``f`` is read now, its actions an unscoped group."""
    call = Call("OpaqueFunction", args, kwargs, interpreter.location(node), interpreter.sink)
    function = call.arg(0, "function")
    given, named = call.arg(1, "args", []), call.arg(2, "kwargs", {})
    if not isinstance(function, Function):
        return call.not_followed(f"OpaqueFunction of a {type(function).__name__}")
    if not isinstance(given, list | tuple) or not isinstance(named, dict):
        return call.not_followed("OpaqueFunction arguments not known statically")
    if not all(isinstance(name, str) for name in named):
        return call.not_followed("OpaqueFunction keyword names not known statically")
    arguments = [LaunchContext(), *given]
    keywords = {str(k): v for k, v in named.items()}
    files = interpreter.default_files
    wanted, files.wanted = files.wanted, set()
    actions = interpreter.call_function(function, arguments, keywords, node)
    opened, files.wanted = files.wanted, wanted | files.wanted
    test = None if files.assuming else files.assume(opened, interpreter.path_of)
    if test is None:
        return (
            actions
            if isinstance(actions, Unknown)
            else _function_group(interpreter, call, actions, None)
        )
    try:  # again, each file its default names read (the first reading holds elsewhere)
        assumed = interpreter.call_function(function, arguments, keywords, node)
    finally:
        files.assuming = {}
    return _function_group(
        interpreter,
        call,
        [
            _function_group(interpreter, call, assumed, Condition("if", test)),
            _function_group(interpreter, call, actions, Condition("unless", test)),
        ],
        None,
    )


def _function_group(
    interpreter: Interpreter, call: Call, actions: Value, condition: Condition | None
) -> Value:
    """The unscoped group of the actions a function returns (none if unknown), under
    ``condition`` if given."""
    if isinstance(actions, Unknown) or actions is None:
        actions = []
    actions = interpreter.settled(actions)
    kwargs: dict[str, Value] = {"actions": actions, "scoped": False}
    if condition is not None:
        kwargs["condition"] = condition
    group = Call("GroupAction", [], kwargs, call.location, call.sink)
    return CALLS[("launch", "GroupAction")](group)


Builtin = Callable[[Interpreter, list[Value], dict[str, Value], ast.AST], Value]

CALLING: dict[tuple[str, str], Builtin] = {("launch", "OpaqueFunction"): _opaque_function}
"""Callables of the launch API that call back into the file (by (package, name))."""

BUILTINS: dict[str, Builtin] = {
    "str": _str,
    "int": _convert(int),
    "float": _convert(float),
    "bool": _convert(bool),
    "len": _len,
    "range": _range,
    "list": _collection(list),
    "tuple": _collection(tuple),
    "dict": _dict_builtin,
    "enumerate": _enumerate,
    "zip": _zip,
    "print": _print,
    "open": reads.open_file,
    "yaml.safe_load": reads.load_yaml,
    "yaml.load": reads.load_yaml,
    "itertools.chain": _chain,
    "copy.copy": _copy(deep=False),
    "copy.deepcopy": _copy(deep=True),
    "sys.path.append": _sys_path,
    "sys.path.insert": _sys_path,
    "isinstance": _isinstance,
    "min": _ordering("min"),
    "max": _ordering("max"),
    "sorted": _ordering("sorted"),
    "all": _quantifier(True),
    "any": _quantifier(False),
    "pathlib.Path": paths.construct,
    "pathlib.PurePath": paths.construct,
    "pathlib.PosixPath": paths.construct,
    "pathlib.Path.home": paths.home,
    "os.path.expanduser": paths.expanduser,
    **{name: _path_function(function) for name, function in paths.FUNCTIONS.items()},
    "re.compile": patterns.compile_pattern,
    "tempfile.NamedTemporaryFile": written.temporary_file,
    "yaml.dump": written.dump_yaml,
    "yaml.safe_dump": written.dump_yaml,
    **{f"re.{name}": patterns.module_function(name) for name in patterns.METHODS},
    "xacro.process_file": xacro_calls.process_file,
    **{f"logging.{level}": _print for level in ("debug", "info", "warning", "error")},
}
"""Python's builtins the reading follows (a call of any other is not followed)."""


def entry_point(interpreter: Interpreter, tree: ast.Module) -> Entity | None:
    """The ``launch`` element ``generate_launch_description()`` returns, or ``None``."""
    try:
        return _entry_point(interpreter, tree)
    except PythonRaise as raised:  # as launch, which fails to load the file
        message = f"the file raises {raised.what()}, which nothing catches"
        interpreter.sink.error("python-launch-raises", message, raised.location)
        return None


def _entry_point(interpreter: Interpreter, tree: ast.Module) -> Entity | None:
    scope = interpreter.run_module(tree)
    found, function = scope.lookup("generate_launch_description")
    where = Location(interpreter.filename, 1, 1)
    if not (found and isinstance(function, Function)):
        interpreter.sink.error(
            "python-launch-entry", "no function generate_launch_description()", where
        )
        return None
    result = interpreter.call_function(function, [], {}, function.node)
    if isinstance(result, Description):
        interpreter.step(walked(result.root, MAX_STEPS - interpreter.steps))
        interpreter.remaps.mark(result.root)
        return result.root
    if not isinstance(result, Unknown):
        interpreter.sink.error(
            "python-launch-entry",
            "generate_launch_description() does not return a LaunchDescription",
            interpreter.location(function.node),
        )
    return None
