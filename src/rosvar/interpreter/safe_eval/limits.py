"""Resource guards: the bounds that make the evaluator refuse, never silently alter,
expressions built to exhaust memory or time, and the size estimates that check them."""

from __future__ import annotations

import ast
import io
import itertools
import re
import string
import tokenize
from collections.abc import Iterable, Mapping, Sequence
from typing import Final, cast

#: ``a ** b`` on ints is refused above this exponent (huge results, slow to compute).
MAX_POW_EXPONENT: Final = 10_000
#: Integer results of ``**``, ``*``, ``<<`` and ``prod`` are refused above this many bits.
MAX_INT_BITS: Final = 1_000_000
#: Strings/lists/tuples built by ``*``, ``+``, ``join``, ``replace``, ``zfill`` stay below this.
MAX_SEQUENCE: Final = 1_000_000
#: Text produced by ``str()``, ``%`` and ``str.format`` (estimated beforehand) stays below this.
MAX_RENDERED: Final = 2_000_000
#: Work budget of one evaluation, in characters/elements: sizes of the strings and containers
#: produced, compared, searched, ordered or rendered.  Each single result is bounded by the
#: limits above, but a comprehension could otherwise repeat expensive work many times.
MAX_WORK: Final = 20_000_000
#: Comprehension iterations plus function calls (``map``, ``key=``...) per evaluation.
MAX_ITERATIONS: Final = 100_000
#: ``factorial``/``comb``/``perm`` arguments above this are refused (their cost explodes).
MAX_COMBINATORIC_ARGUMENT: Final = 10_000
#: ``round(int, ndigits)`` computes ``10 ** -ndigits``; refused above this magnitude.
MAX_ROUND_DIGITS: Final = 10_000
#: Levels of nesting (brackets, and operators that nest in one another) of an expression,
#: well below Python's recursion limit: parsing, checking and interpreting all recurse on it,
#: and an evaluation may already run deep in nested includes.
MAX_NESTING: Final = 100

_FLAT: Final = frozenset({",", ":"})  # separate siblings: nothing after them nests in before
_OPENING: Final = frozenset({"(", "[", "{"})
_CLOSING: Final = frozenset({")", "]", "}"})
_WORD_OPERATORS: Final = frozenset({"not", "and", "or", "if", "else", "in", "is", "for", "lambda"})


def nesting(text: str) -> int:
    """An upper bound of how deep the expression's syntax tree is, from its tokens (never
    recursing): brackets, plus at each bracket level the operators since its last comma,
    each of which may nest the rest of the level one level deeper. 0 when the text does not
    tokenize (the parser then says why)."""
    levels = [0]  # per open bracket: the operators seen since its last separator
    operators = depth = 0  # operators: the sum of ``levels``
    try:
        for token in tokenize.generate_tokens(io.StringIO(text).readline):
            if token.type == tokenize.OP and token.string in _OPENING:
                levels.append(0)
            elif token.type == tokenize.OP and token.string in _CLOSING:
                operators -= levels.pop() if len(levels) > 1 else 0
            elif token.type == tokenize.OP and token.string in _FLAT:
                operators -= levels[-1]
                levels[-1] = 0
            elif token.type == tokenize.OP or (
                token.type == tokenize.NAME and token.string in _WORD_OPERATORS
            ):
                levels[-1] += 1
                operators += 1
            depth = max(depth, len(levels) - 1 + operators)
    except (tokenize.TokenError, SyntaxError):
        return 0
    return depth


class FunctionValue:
    """A function the expression holds as a value: sized by its ``repr``."""

    __slots__ = ()


class _Sizer:
    """Upper-bound estimates of ``len(str(value))``, stopping once past :data:`MAX_WORK`.

    Values are never mutated once built, so container sizes are remembered by identity (the
    container is kept alive, so its id cannot be reused): ``[big] * n``, or ``big`` rendered
    again and again by ``map(str, ...)``, is walked once per evaluation.
    """

    def __init__(self) -> None:
        self._known: dict[int, tuple[object, int]] = {}

    def size(self, item: object) -> int:
        if isinstance(item, str):
            return len(item) + 2
        if isinstance(item, bool) or item is None:
            return 5
        if isinstance(item, int):
            return item.bit_length() * 31 // 100 + 2
        if isinstance(item, float):
            return 24
        if isinstance(item, (list, tuple, set, frozenset, dict)):
            known = self._known.get(id(item))
            if known is not None:
                return known[1]
            elements: Iterable[object] = (
                itertools.chain(item.keys(), item.values()) if isinstance(item, dict) else item
            )
            total = 2 + 2 * len(item)
            for element in elements:  # common scalars inline: this loop is the hot spot
                kind = type(element)
                if kind is str:
                    total += len(cast(str, element)) + 2
                elif kind is int:
                    total += cast(int, element).bit_length() * 31 // 100 + 2
                else:
                    total += self.size(element)
                if total > MAX_WORK:
                    break
            self._known[id(item)] = (item, total)
            return total
        return len(repr(item)) if isinstance(item, FunctionValue) else 100


def _small_number(digits: str) -> int:
    """A width/precision from a format string; absurdly long digit runs count as too big."""
    return int(digits) if len(digits) <= 8 else MAX_WORK + 1


def _repeat_size(sequence: object, count: object) -> int:
    if isinstance(sequence, (str, list, tuple)) and isinstance(count, int):
        return len(sequence) * count
    return 0


def _binop_refusal(op: ast.operator, left: object, right: object, sizer: _Sizer) -> str | None:
    """Why ``left op right`` would produce a result too large to compute, if it would."""
    if isinstance(op, ast.Pow) and isinstance(left, int) and isinstance(right, int):
        if right > MAX_POW_EXPONENT:
            return f"exponent {right} of ** exceeds the limit of {MAX_POW_EXPONENT}"
        if right > 0 and left.bit_length() * right > MAX_INT_BITS:
            return f"result of ** would exceed {MAX_INT_BITS} bits"
    elif isinstance(op, ast.Mult):
        if isinstance(left, int) and isinstance(right, int):
            if left.bit_length() + right.bit_length() > MAX_INT_BITS:
                return f"result of * would exceed {MAX_INT_BITS} bits"
        elif max(_repeat_size(left, right), _repeat_size(right, left)) > MAX_SEQUENCE:
            return f"repetition would exceed {MAX_SEQUENCE} elements"
    elif isinstance(op, ast.Add):
        if (
            isinstance(left, (str, list, tuple))
            and isinstance(right, (str, list, tuple))
            and len(left) + len(right) > MAX_SEQUENCE
        ):
            return f"concatenation would exceed {MAX_SEQUENCE} elements"
    elif isinstance(op, ast.LShift):
        if (
            isinstance(left, int)
            and isinstance(right, int)
            and left
            and right > 0
            and left.bit_length() + right > MAX_INT_BITS
        ):
            return f"result of << would exceed {MAX_INT_BITS} bits"
    elif isinstance(op, ast.Mod) and isinstance(left, str):
        return _printf_refusal(left, right, sizer)
    return None


_PRINTF_SPEC: Final = re.compile(
    r"%(?:\([^)]*\))?[-#0 +]*(?P<width>\*|\d+)?(?:\.(?P<precision>\*|\d*))?[hlL]?.?", re.DOTALL
)


def _printf_refusal(template: str, values: object, sizer: _Sizer) -> str | None:
    """Refuse ``%``-formatting whose output would exceed :data:`MAX_RENDERED`."""
    padding = 0
    fields = 0
    for match in _PRINTF_SPEC.finditer(template):
        width, precision = match["width"] or "", match["precision"] or ""
        if "*" in width + precision:
            return "'*' widths in %-formatting are not supported"
        padding += _small_number(width or "0") + _small_number(precision or "0")
        fields += 1
        if padding > MAX_RENDERED:
            break
    # A tuple's items are consumed once each; a mapping's values may be reused by every field.
    if isinstance(values, tuple):
        inserted = sizer.size(values)
    elif isinstance(values, Mapping):
        inserted = fields * sizer.size(values)
    else:
        inserted = sizer.size(values)
    if len(template) + padding + inserted > MAX_RENDERED:
        return f"%-formatting would produce more than {MAX_RENDERED} characters"
    return None


_FORMATTER: Final = string.Formatter()


def _has_attribute_access(field_name: str) -> bool:
    in_brackets = False
    for char in field_name:
        if char == "[":
            in_brackets = True
        elif char == "]":
            in_brackets = False
        elif char == "." and not in_brackets:
            return True
    return False


def _format_refusal(
    template: str, args: Sequence[object], kwargs: Mapping[str, object], sizer: _Sizer
) -> str | None:
    """Refuse ``str.format`` that reaches attributes or would exceed :data:`MAX_RENDERED`."""
    try:
        fields = list(_FORMATTER.parse(template))
    except ValueError:
        return None  # str.format itself reports the malformed template
    total = len(template)
    sizes: dict[int | str, int] = {}
    auto = 0
    for _literal, name, spec, _conversion in fields:
        if name is None:
            continue
        if _has_attribute_access(name):
            return f"attribute access in format field '{{{name}}}' is not allowed"
        if spec and "{" in spec:
            return "nested replacement fields in a format spec are not supported"
        total += sum(_small_number(digits) for digits in re.findall(r"\d+", spec or ""))
        head = re.split(r"[.\[]", name, maxsplit=1)[0]
        key: int | str
        if not head:
            key, auto = auto, auto + 1
        elif head.isdecimal() and len(head) <= 8:
            key = int(head)
        else:
            key = head
        if key not in sizes:
            if isinstance(key, int):
                sizes[key] = sizer.size(args[key]) if key < len(args) else 0
            else:
                sizes[key] = sizer.size(kwargs[key]) if key in kwargs else 0
        total += sizes[key]
        if total > MAX_RENDERED:
            return f"str.format would produce more than {MAX_RENDERED} characters"
    return None
