"""Safe roslaunch XML parser: bytes to :class:`Entity` trees with exact locations.

roslaunch reads files with minidom, which expands entities and reports errors as
exceptions. Here expat is driven directly so that every element keeps its
``file:line:col``, any DTD is refused before it can expand anything (billion laughs,
external entities), and every problem becomes a :class:`Diagnostic`: the analysis of
a workspace must survive hostile or broken files. Refusing every DTD is stricter than
``defusedxml`` (which forbids only entity declarations and external references) and
keeps expat's positions, so that package is not a dependency.
"""

from __future__ import annotations

import os
import re
from collections import OrderedDict
from collections.abc import Callable
from typing import Any, NoReturn
from xml.parsers import expat

from rosvar.diagnostics import Diagnostic, Location, Severity
from rosvar.files import MAX_FILE_BYTES, FileCode, FileRefused, open_regular, read_file
from rosvar.frontends.entity import Entity, ParseResult
from rosvar.memo import Memo

MAX_DEPTH: int = 1000
"""Deeper element nesting is refused (``xml-too-deep``). roslaunch itself fails at about
990 levels (minidom's ``getElementsByTagName`` recurses once per level), so nothing it
accepts is refused here; code that recurses over the tree must allow for this depth."""

CACHE_SIZE: int = 32768  # more than the largest workspace benchmarked: an eviction re-parses
"""Parsed files kept by :func:`load_launch_file` (the interpreter re-reads includes)."""

NO_ROOT_MESSAGE = "Invalid roslaunch XML syntax: no root <launch> tag"

_UTF8_BOM = b"\xef\xbb\xbf"
_XML_DECL_ENCODING = re.compile(rb"<\?xml[^>]*?\sencoding\s*=\s*[\"']([A-Za-z][A-Za-z0-9._-]*)")
_ENCODING_ERRORS = frozenset(
    {
        expat.errors.codes[expat.errors.XML_ERROR_UNKNOWN_ENCODING],
        expat.errors.codes[expat.errors.XML_ERROR_INCORRECT_ENCODING],
    }
)


class _Refused(Exception):
    """Raised inside expat handlers: the only way to stop pyexpat mid-document."""

    def __init__(self, diagnostic: Diagnostic) -> None:
        super().__init__(diagnostic.message)
        self.diagnostic = diagnostic


def _error(code: str, message: str, location: Location) -> ParseResult:
    return ParseResult(None, [Diagnostic(code, Severity.ERROR, message, location)])


def _declared_encoding(data: bytes) -> str | None:
    match = _XML_DECL_ENCODING.match(data, 0, 512)
    return match.group(1).decode("ascii") if match else None


def _offset_location(data: bytes, offset: int, filename: str) -> Location:
    """Line and column (in characters, as expat counts them) of a byte offset."""
    line_start = data.rfind(b"\n", 0, offset) + 1
    line = data.count(b"\n", 0, offset) + 1
    return Location(filename, line, len(data[line_start:offset].decode("utf-8", "replace")) + 1)


def _prepare(data: bytes, filename: str) -> bytes | ParseResult:
    """Drop a UTF-8 byte order mark and report invalid UTF-8 by position.

    Without this, expat counts the mark as a column and says only "invalid token"
    for a Latin-1 file that lacks its encoding declaration.
    """
    if data[:2] in (b"\xff\xfe", b"\xfe\xff", b"<\x00", b"\x00<"):
        return data  # UTF-16: expat detects and decodes it itself
    bom = len(_UTF8_BOM) if data.startswith(_UTF8_BOM) else 0
    declared = _declared_encoding(data[bom:])
    if declared is not None and declared.lower().replace("_", "-") not in ("utf-8", "utf8"):
        return data  # expat decodes the declared encoding (or reports it unknown)
    data = data[bom:]
    try:
        data.decode("utf-8")
    except UnicodeDecodeError as exc:
        return _error(
            "xml-encoding",
            f"invalid {declared or 'UTF-8'} byte 0x{data[exc.start]:02x} at byte offset "
            f'{exc.start + bom} (declare the real encoding, e.g. <?xml version="1.0" '
            'encoding="ISO-8859-1"?>)',
            _offset_location(data, exc.start, filename),
        )
    return data


def parse_xml_bytes(data: bytes, filename: str, keep: frozenset[str] | None = None) -> ParseResult:
    """Parse any XML document safely into an :class:`Entity` tree (no root-tag check).

    Shared by launch files and ``package.xml`` so both get the same safety rules. ``keep``:
    the tags of the elements below the root that the caller reads; the others (and what
    they hold) are parsed and checked as well, but not built.
    """
    return _parse(data, filename, None, keep)[0]


def _parse(
    data: bytes, filename: str, watch: str | None, keep: frozenset[str] | None = None
) -> tuple[ParseResult, list[Entity]]:
    """Parse, also collecting the elements tagged ``watch`` (spares a second tree walk)."""
    watched: list[Entity] = []
    if not data.removeprefix(_UTF8_BOM).strip():
        return _error("xml-empty", "file is empty", Location(filename, 1, 1)), watched
    prepared = _prepare(data, filename)
    if isinstance(prepared, ParseResult):
        return prepared, watched
    data = prepared

    parser = expat.ParserCreate()
    parser.buffer_text = True
    parser.buffer_size = 1 << 16
    parser.SetParamEntityParsing(expat.XML_PARAM_ENTITY_PARSING_NEVER)

    # The document node is a sentinel parent, so the handlers never test for "no root yet";
    # texts[0] likewise swallows the whitespace around the root element.
    document = Entity("#document", {}, Location(filename))
    stack: list[Entity] = [document]
    texts: list[list[str] | None] = [None]  # a list once an element has text (few do)

    def start(tag: str, attributes: dict[str, str]) -> None:
        entity = Entity(
            tag,
            attributes,
            Location(filename, parser.CurrentLineNumber, parser.CurrentColumnNumber + 1),
            [],  # (the default's factory is a call more per element)
        )
        stack[-1].children.append(entity)
        if tag == watch:
            watched.append(entity)
        if len(stack) > MAX_DEPTH:
            raise _Refused(_too_deep(entity.location))
        stack.append(entity)
        texts.append(None)

    def end(tag: str) -> None:
        parts = texts.pop()
        if parts:
            stack[-1].text = "".join(parts)
        stack.pop()

    def characters(text: str) -> None:
        parts = texts[-1]
        if parts is None:
            texts[-1] = [text]
        else:
            parts.append(text)

    def refuse_dtd(*_: object) -> NoReturn:
        # expat reports the end of the DOCTYPE's opening; point at "<!DOCTYPE" when visible.
        offset = data.find(b"<!DOCTYPE")
        if offset >= 0:
            location = _offset_location(data, offset, filename)
        else:
            location = Location(filename, parser.CurrentLineNumber, parser.CurrentColumnNumber + 1)
        raise _Refused(
            Diagnostic(
                "xml-dtd-forbidden",
                Severity.ERROR,
                "DOCTYPE declarations are not allowed: roslaunch files never need one, "
                "and refusing them rules out entity expansion and external entities",
                location,
            )
        )

    skipped = 0  # elements open inside one that is not kept

    def start_kept(tag: str, attributes: dict[str, str]) -> None:
        nonlocal skipped
        if not skipped and (len(stack) == 1 or tag in keep):  # type: ignore[operator]
            start(tag, attributes)
            return
        skipped += 1
        if len(stack) + skipped > MAX_DEPTH + 1:
            where = Location(filename, parser.CurrentLineNumber, parser.CurrentColumnNumber + 1)
            raise _Refused(_too_deep(where))

    def end_kept(tag: str) -> None:
        nonlocal skipped
        if skipped:
            skipped -= 1
        else:
            end(tag)

    def characters_kept(text: str) -> None:
        if not skipped:
            characters(text)

    if keep is None:
        parser.StartElementHandler = start
        parser.EndElementHandler = end
        parser.CharacterDataHandler = characters
    else:
        parser.StartElementHandler = start_kept
        parser.EndElementHandler = end_kept
        parser.CharacterDataHandler = characters_kept
    parser.StartDoctypeDeclHandler = refuse_dtd
    parser.EntityDeclHandler = refuse_dtd
    parser.ExternalEntityRefHandler = refuse_dtd

    try:
        parser.Parse(data, True)
    except _Refused as refused:
        return ParseResult(None, [refused.diagnostic]), []
    except expat.ExpatError as exc:
        location = Location(filename, exc.lineno, exc.offset + 1)
        reason = expat.ErrorString(exc.code)
        if exc.code in _ENCODING_ERRORS:
            return _error("xml-encoding", f"bad encoding: {reason}", location), []
        return _error("xml-malformed", f"malformed XML: {reason}", location), []
    # pyexpat: "multi-byte encodings are not supported"
    except (ValueError, LookupError) as unsupported:
        return _error(
            "xml-encoding", f"unsupported encoding: {unsupported}", Location(filename, 1, 1)
        ), []
    except RecursionError:
        return _error("xml-too-deep", "document too deeply nested", Location(filename, 1, 1)), []
    finally:
        # The handlers refer to the parser: without this cycle the parser is freed at once
        # instead of waiting for the cyclic collector.
        parser.StartElementHandler = parser.EndElementHandler = None
        parser.CharacterDataHandler = parser.StartDoctypeDeclHandler = None
        parser.EntityDeclHandler = parser.ExternalEntityRefHandler = None
    return ParseResult(document.children[0] if document.children else None), watched


def _too_deep(location: Location) -> Diagnostic:
    return Diagnostic(
        "xml-too-deep",
        Severity.ERROR,
        f"elements nested more than {MAX_DEPTH} levels deep",
        location,
    )


def parse_launch_bytes(data: bytes, filename: str) -> ParseResult:
    """Parse a roslaunch file held in memory; ``filename`` is used in every Location.

    roslaunch takes the single ``<launch>`` element anywhere in the document, so a
    ``<launch>`` wrapped in another element is accepted (with a warning) and two
    ``<launch>`` elements are refused, exactly as roslaunch does.
    """
    result, launches = _parse(data, filename, "launch")
    root = result.root
    if root is None or (len(launches) == 1 and launches[0] is root):
        return result
    if len(launches) != 1:
        reason = "no <launch> element" if not launches else f"{len(launches)} <launch> elements"
        return _error(
            "launch-no-root",
            f"{NO_ROOT_MESSAGE} (root element is <{root.tag}>; {reason})",
            root.location,
        )
    launch = launches[0]
    warning = Diagnostic(
        "launch-nested-root",
        Severity.WARNING,
        f"<launch> is not the root element (<{root.tag}> is); roslaunch still uses it",
        launch.location,
    )
    return ParseResult(launch, [*result.diagnostics, warning])


def read_bytes(
    path: str | os.PathLike[str],
    limit: int | None = None,
    resolve: Callable[[str], str] | None = None,
) -> bytes | ParseResult:
    """A whole regular file within the size limit (:func:`rosvar.files.read_file`; a
    frontend may ask for less), or the refusal as a :class:`ParseResult`; shared by every
    frontend. ``resolve``: how the caller resolves paths (``os.path.realpath``, kept)."""
    name = os.fspath(path)
    try:
        real = None if resolve is None else resolve(name)
        return read_file(name, limit=MAX_FILE_BYTES if limit is None else limit, real=real)
    except FileRefused as refused:
        message = refused.message
        if refused.code == FileCode.UNREADABLE:
            message = f"cannot read file: {message}"
        return _error(refused.code, message, Location(name, 1, 1))
    except ValueError as exc:  # e.g. an embedded NUL in the name
        return _error("file-unreadable", f"cannot read file: {exc}", Location(name, 1, 1))
    except OSError as failure:
        reason = failure.strerror or str(failure)
        return _error("file-unreadable", f"cannot read file: {reason}", Location(name, 1, 1))


def parse_xml_file(
    path: str | os.PathLike[str],
    resolve: Callable[[str], str] | None = None,
    keep: frozenset[str] | None = None,
) -> ParseResult:
    """Read and safely parse any XML file (e.g. ``package.xml``); never raises. ``resolve``
    as :func:`read_bytes`'s, ``keep`` as :func:`parse_xml_bytes`'s."""
    data = read_bytes(path, resolve=resolve)
    if isinstance(data, ParseResult):
        return data
    return parse_xml_bytes(data, os.fspath(path), keep)


def parse_launch_file(
    path: str | os.PathLike[str], resolve: Callable[[str], str] | None = None
) -> ParseResult:
    """Read and parse a roslaunch file; Locations use ``path`` as given. Never raises."""
    data = read_bytes(path, resolve=resolve)
    if isinstance(data, ParseResult):
        return data
    return parse_launch_bytes(data, os.fspath(path))


_CacheKey = tuple[str, int, int, int, int]
_cache: OrderedDict[_CacheKey, ParseResult] = OrderedDict()


def load_launch_file(
    path: str | os.PathLike[str], resolve: Callable[[str], str] | None = None
) -> ParseResult:
    """Like :func:`parse_launch_file`, but cached while the file is unchanged.

    The key is (name as given, device, inode, mtime_ns, size): the name is part of
    it because it appears in every Location; the inode stands for the real file
    (cheaper than resolving symlinks on every include). The returned tree is shared between callers
    and must be treated as read-only; the diagnostics list is a fresh copy.
    """
    name = os.fspath(path)
    try:
        info = os.stat(name)
        key: _CacheKey = (name, info.st_dev, info.st_ino, info.st_mtime_ns, info.st_size)
    except (OSError, ValueError):
        return parse_launch_file(name, resolve)
    cached = _cache.get(key)
    if cached is None:
        cached = parse_launch_file(name, resolve)
        if any(d.code == "file-unreadable" for d in cached.diagnostics):
            return cached  # permissions may change without touching mtime
        _cache[key] = cached
        if len(_cache) > CACHE_SIZE:
            _cache.popitem(last=False)
    else:
        _cache.move_to_end(key)
    return ParseResult(cached.root, list(cached.diagnostics))


def clear_cache() -> None:
    """Forget every cached parse (tests, or after editing files in place)."""
    _cache.clear()


class Snapshot:
    """Launch files as one analysis reads them: each loaded through the cache once, then
    taken as unchanged. An analysis is one moment, and it loads a file again for every
    include of it and every question about it: the cache's ``stat`` each time cost more
    than the rest of the lookup. The results are shared: read-only, diagnostics included.
    """

    __slots__ = ("_loaded", "_loader", "tables")

    def __init__(self, loader: Callable[[str], ParseResult] | None = None) -> None:
        self._loaded: dict[str, ParseResult] = {}
        self._loader = loader or load_launch_file  # ROS 2 passes the frontend registry's
        self.tables: dict[str, object] = {}
        """What the walks over these files keep of them (the ROS 2 include memo, keyed by
        the parsed files): it lives as long as they do, and no longer."""

    def kept(self, owner: str) -> Memo[Any, Any]:
        """The memo ``owner`` (a module's name) keeps of these files' walks, made on first
        use: it lives as long as they do, and no longer."""
        table = self.tables.get(owner)
        if not isinstance(table, Memo):
            table = self.tables[owner] = Memo()
        return table

    def load(self, path: str) -> ParseResult:
        result = self._loaded.get(path)
        if result is None:
            result = self._loaded[path] = self._loader(path)
        return result


class _FirstTag(Exception):
    def __init__(self, tag: str) -> None:
        super().__init__(tag)
        self.tag = tag


def is_launch_root(path: str | os.PathLike[str]) -> bool:
    """Cheaply tell whether an ``*.xml`` file is a launch file; never raises.

    Only the prolog and the first start tag are read. A DOCTYPE naming ``launch``
    counts as a launch file, so that the parser later reports the forbidden DTD
    instead of the file silently vanishing from discovery.
    """
    parser = expat.ParserCreate()
    parser.SetParamEntityParsing(expat.XML_PARAM_ENTITY_PARSING_NEVER)

    def first_tag(tag: str, *_: object) -> NoReturn:
        raise _FirstTag(tag)

    def refuse(*_: object) -> NoReturn:
        raise _FirstTag("")

    parser.StartElementHandler = first_tag
    parser.StartDoctypeDeclHandler = first_tag
    parser.EntityDeclHandler = refuse
    parser.ExternalEntityRefHandler = refuse
    try:
        with open_regular(os.fspath(path)) as handle:
            chunk = handle.read(8192)
            if len(chunk) < 8192 and b"launch" not in chunk and b"\0" not in chunk:
                return False  # whole file seen, no UTF-16: it cannot have a <launch> root
            while chunk:
                parser.Parse(chunk, False)
                chunk = handle.read(8192)
            parser.Parse(b"", True)
    except _FirstTag as found:
        return found.tag == "launch"
    except (OSError, ValueError, expat.ExpatError, RecursionError):
        return False
    return False
