"""ROS 2 substitutions (``$(var x)``, ``$(find-pkg-share p)``, ``$(eval ...)``, ...).

The text is parsed as launch's frontend grammar does (substitutions nest; arguments are
split at whitespace, quoted with ``'``/``"``; a backslash escapes the next character),
then every substitution is computed over all configurations with :func:`combine`.
Handlers live in :data:`SUBSTITUTIONS`, keyed by name.
"""

from __future__ import annotations

import functools
import os
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING

from rosvar.interpreter.model import Raw
from rosvar.interpreter.ros2.context import Context, optional
from rosvar.interpreter.safe_eval import EvalEnvironment, EvalFailed, EvalRefused, evaluate
from rosvar.logic.choice import Choice, Fail, combine, ite
from rosvar.logic.terms import concat

if TYPE_CHECKING:
    from rosvar.interpreter.interpretation import Interpretation

Value = Raw | Fail


class SubstitutionSyntaxError(Exception):
    """The text is not in launch's substitution grammar."""


@dataclass(frozen=True)
class Call:
    """``$(name arg ...)``: each argument a sequence of text and nested calls."""

    name: str
    arguments: tuple[Template, ...]


Template = tuple[str | Call, ...]


class _Parser:
    def __init__(self, text: str) -> None:
        self.text = text
        self.at = 0

    def template(self, stop: str = "") -> Template:
        parts: list[str | Call] = []
        buffer: list[str] = []
        text = self.text
        while self.at < len(text):
            ch = text[self.at]
            if stop and ch in stop:
                break
            if ch == "\\" and self.at + 1 < len(text):
                buffer.append(text[self.at + 1])
                self.at += 2
            elif text.startswith("$(", self.at):
                if buffer:
                    parts.append("".join(buffer))
                    buffer.clear()
                parts.append(self.call())
            else:
                buffer.append(ch)
                self.at += 1
        if buffer:
            parts.append("".join(buffer))
        return tuple(parts)

    def call(self) -> Call:
        self.at += 2
        start = self.at
        text = self.text
        while self.at < len(text) and (text[self.at].isalnum() or text[self.at] in "-_"):
            self.at += 1
        name = text[start : self.at]
        if not name:
            raise SubstitutionSyntaxError(f"a substitution has no name in [{text}]")
        arguments: list[Template] = []
        while True:
            while self.at < len(text) and text[self.at].isspace():
                self.at += 1
            if self.at >= len(text):
                raise SubstitutionSyntaxError(f"unclosed substitution in [{text}]")
            if text[self.at] == ")":
                self.at += 1
                return Call(name, tuple(arguments))
            arguments.append(self.argument())

    def argument(self) -> Template:
        parts: list[str | Call] = []
        text = self.text
        while self.at < len(text) and not text[self.at].isspace() and text[self.at] != ")":
            ch = text[self.at]
            if ch in "'\"":
                self.at += 1
                parts.extend(self.template(ch))
                if self.at >= len(text):
                    raise SubstitutionSyntaxError(f"unclosed quote in [{text}]")
                self.at += 1
            else:
                parts.extend(self.template(" \t\n)'\""))
        return tuple(parts)


@functools.lru_cache(maxsize=16384)
def parse(text: str) -> Template:
    """``text`` as a template; raises :class:`SubstitutionSyntaxError`."""
    return _Parser(text).template()


Handler = Callable[["Interpretation", Context, list[Raw]], Choice[Value]]
SUBSTITUTIONS: dict[str, Handler] = {}


def substitution(name: str) -> Callable[[Handler], Handler]:
    """Register the handler of ``$(name ...)``; it gets the arguments' texts."""

    def register(handler: Handler) -> Handler:
        SUBSTITUTIONS[name] = handler
        return handler

    return register


class Ros2Substituter:
    """Resolves attribute text in a :class:`Context`, for all configurations at once."""

    def __init__(self, host: Interpretation) -> None:
        self.host = host
        self.space = host.space

    def resolve(self, text: str | None, context: Context) -> Choice[Value] | None:
        if text is None:
            return None
        try:
            template = parse(text)
        except SubstitutionSyntaxError as error:
            return Choice.const(self.space, Fail(str(error), "substitution-invalid"))
        return self.template(template, context)

    def template(self, template: Template, context: Context) -> Choice[Value]:
        parts = [self._part(part, context) for part in template]
        if not parts:
            return Choice.const(self.space, "")
        return combine(parts, _concatenate)

    def _part(self, part: str | Call, context: Context) -> Choice[Value]:
        if isinstance(part, str):
            return Choice.const(self.space, part)
        handler = SUBSTITUTIONS.get(part.name)
        if handler is None:
            return Choice.const(
                self.space, Fail(f"unknown substitution '{part.name}'", "substitution-unknown")
            )
        arguments = [self.template(a, context) for a in part.arguments]
        if not arguments:
            return handler(self.host, context, [])
        return combine(arguments, lambda leaves: leaves).bind(
            lambda leaves: _call(handler, self.host, context, leaves)
        )


def _call(
    handler: Handler, host: Interpretation, context: Context, leaves: Sequence[Value]
) -> Choice[Value]:
    for leaf in leaves:
        if isinstance(leaf, Fail):
            return Choice.const(host.space, leaf)
    return handler(host, context, list(leaves))  # type: ignore[arg-type]  # Fails returned


def _concatenate(leaves: Sequence[Value]) -> Value:
    for leaf in leaves:
        if isinstance(leaf, Fail):
            return leaf
    if all(isinstance(leaf, str) for leaf in leaves):
        return "".join(leaves)  # type: ignore[arg-type]
    return Fail("a value depends on an input rosvar does not know", "value-unknown")


def _fail(host: Interpretation, message: str, code: str) -> Choice[Value]:
    return Choice.const(host.space, Fail(message, code))


@substitution("var")
def _var(host: Interpretation, context: Context, args: list[Raw]) -> Choice[Value]:
    if len(args) != 1 or not isinstance(args[0], str):
        return _fail(host, "$(var) takes one argument", "substitution-invalid")
    name = args[0]
    value = context.configurations.get(name)
    if value is None:
        return _fail(host, f"launch configuration '{name}' does not exist", "var-undefined")
    return value.map(
        lambda leaf: (
            Fail(f"launch configuration '{name}' does not exist", "var-undefined")
            if leaf is None
            else leaf
        )
    )


@substitution("env")
def _env(host: Interpretation, context: Context, args: list[Raw]) -> Choice[Value]:
    if not 1 <= len(args) <= 2 or not isinstance(args[0], str):
        return _fail(host, "$(env) takes one or two arguments", "substitution-invalid")
    name, default = args[0], args[1] if len(args) == 2 else None
    value = context.env.get(name)
    if value is None:
        value = host.env_value(name)

    def pick(leaf: Raw | None) -> Value:
        if leaf is not None:
            return leaf
        if default is not None:
            return default
        return Fail(f"environment variable '{name}' does not exist", "env-undefined")

    return value.map(pick)


def _package(host: Interpretation, args: list[Raw], what: str) -> Choice[Value]:
    if len(args) != 1 or not isinstance(args[0], str):
        return _fail(host, f"$({what}) takes one argument", "substitution-invalid")
    path = host.find_package(args[0])
    if path is None:
        return _fail(host, f"package '{args[0]}' not found", "package-not-found")
    return Choice.const(host.space, path)


@substitution("find-pkg-share")
def _share(host: Interpretation, context: Context, args: list[Raw]) -> Choice[Value]:
    return _package(host, args, "find-pkg-share")  # the source folder stands for the share


@substitution("find-pkg-prefix")
def _prefix(host: Interpretation, context: Context, args: list[Raw]) -> Choice[Value]:
    return _package(host, args, "find-pkg-prefix")


@substitution("dirname")
def _dirname(host: Interpretation, context: Context, args: list[Raw]) -> Choice[Value]:
    return Choice.const(host.space, os.path.dirname(os.path.abspath(context.filename)))


@substitution("filename")
def _filename(host: Interpretation, context: Context, args: list[Raw]) -> Choice[Value]:
    return Choice.const(host.space, os.path.abspath(context.filename))


@substitution("command")
def _command(host: Interpretation, context: Context, args: list[Raw]) -> Choice[Value]:
    """Never run: the value is the text a dry run shows, ``$(command TEXT)`` (as the oracle
    records it), so the launch around it is analysed; a warning says it is not known."""
    if not 1 <= len(args) <= 2:
        return _fail(
            host, "$(command) takes a command and an optional on_stderr", "command-invalid"
        )
    host.warn("command-not-run", "$(command) is never run by rosvar: its output is not known")
    return Choice.const(host.space, concat(["$(command ", args[0], ")"]))


@substitution("find-exec")
def _find_exec(host: Interpretation, context: Context, args: list[Raw]) -> Choice[Value]:
    """Never searched: the executable is looked up on the ``PATH`` of the machine that
    launches, which rosvar does not read; its value is the text ``$(find-exec NAME)``, as
    ``$(command)``'s is, so the launch around it is analysed."""
    if len(args) != 1:
        return _fail(host, "$(find-exec) takes one argument", "substitution-invalid")
    host.warn(
        "exec-not-searched",
        "$(find-exec) is never searched by rosvar: the PATH is the launching machine's",
    )
    return Choice.const(host.space, concat(["$(find-exec ", args[0], ")"]))


@substitution("eval")
def _eval(host: Interpretation, context: Context, args: list[Raw]) -> Choice[Value]:
    if len(args) != 1 or not isinstance(args[0], str):
        return _fail(host, "$(eval) takes one argument", "substitution-invalid")
    try:
        return Choice.const(host.space, evaluate(args[0], EvalEnvironment(_no_arg)))
    except (EvalFailed, EvalRefused) as error:
        return _fail(host, f"$(eval {args[0]}): {error}", "eval-failed")


def _no_arg(name: str) -> str:
    raise KeyError(name)  # ROS 2 expressions read launch configurations only through $(var)


@substitution("anon")
def _anon(host: Interpretation, context: Context, args: list[Raw]) -> Choice[Value]:
    """One name per id, kept as the launch configuration ``anon<id>`` (so groups scope it);
    a counter stands for launch's host, pid and random part, as for ROS 1."""
    if len(args) != 1 or not isinstance(args[0], str):
        return _fail(host, "$(anon) takes one argument", "substitution-invalid")
    key = "anon" + args[0]
    old = context.configurations.get(key)
    unset = host.space.true if old is None else old.where(lambda leaf: leaf is None)
    if unset != host.space.false:
        with host.under(unset) as live:
            if live:
                fresh = optional(host.new_anon(context, args[0]))
                before = old if old is not None else Choice.const(host.space, None)
                context.configurations[key] = ite(host.space, host.pc, fresh, before)
    return context.configurations[key].map(_present)


def _present(leaf: Raw | None) -> Value:
    return Fail("anonymous name not set", "value-unknown") if leaf is None else leaf
