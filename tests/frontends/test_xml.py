"""Tests of the safe roslaunch XML parser: trees, locations, and every refusal."""

from __future__ import annotations

import os
import random
from pathlib import Path

import pytest

from rosvar.diagnostics import Diagnostic, Location, Severity
from rosvar.frontends import xml
from rosvar.frontends.entity import ParseResult
from rosvar.frontends.xml import (
    is_launch_root,
    load_launch_file,
    parse_launch_bytes,
    parse_launch_file,
    parse_xml_bytes,
)


def codes(result: ParseResult) -> list[str]:
    return [diagnostic.code for diagnostic in result.diagnostics]


def only_error(result: ParseResult, code: str) -> str:
    """Assert the result is a single-error refusal with ``code``; return its location."""
    assert result.root is None
    assert codes(result) == [code]
    assert result.diagnostics[0].severity is Severity.ERROR
    return str(result.diagnostics[0].location)


def test_nested_locations_are_start_tag_line_and_column() -> None:
    data = b'<launch>\n  <group ns="a">\n\t<node pkg="p" type="t"/>\n  </group>\n</launch>\n'
    result = parse_launch_bytes(data, "x.launch")
    root = result.root
    assert root is not None and result.diagnostics == []
    assert str(root.location) == "x.launch:1:1"
    group = root.children[0]
    assert (group.tag, str(group.location)) == ("group", "x.launch:2:3")
    node = group.children[0]
    assert (node.tag, str(node.location)) == ("node", "x.launch:3:2")


def test_columns_count_characters_not_bytes() -> None:
    data = '<launch>\n<!-- é€ --><arg name="a"/></launch>'.encode()
    root = parse_launch_bytes(data, "f").root
    assert root is not None
    assert root.children[0].location.col == 12


def test_byte_order_mark_is_not_a_column() -> None:
    root = parse_launch_bytes(b"\xef\xbb\xbf<launch/>", "f").root
    assert root is not None and root.location.col == 1


def test_rosparam_text_joins_direct_text_and_cdata() -> None:
    data = (
        b"<launch><rosparam>a: 1\n<![CDATA[b: <2> & 3]]>\nc: &amp;x<!-- no -->"
        b"<sub>inner</sub>d</rosparam></launch>"
    )
    root = parse_launch_bytes(data, "f").root
    assert root is not None
    rosparam = root.children[0]
    assert rosparam.text == "a: 1\nb: <2> & 3\nc: &xd"
    assert rosparam.children[0].text == "inner"


def test_text_keeps_whitespace_like_minidom() -> None:
    root = parse_launch_bytes(b"<launch>\n  <arg name='a'/>\n</launch>", "f").root
    assert root is not None
    assert root.text == "\n  \n"
    assert root.children[0].text == ""


def test_attribute_order_and_raw_values_are_kept() -> None:
    data = b'<launch><node z="1" a="$(arg x)" m="&lt;" b=""/></launch>'
    root = parse_launch_bytes(data, "f").root
    assert root is not None
    node = root.children[0]
    assert list(node.attributes.items()) == [("z", "1"), ("a", "$(arg x)"), ("m", "<"), ("b", "")]


def test_namespaced_tags_stay_raw() -> None:
    root = parse_launch_bytes(b'<launch xmlns:x="u"><x:arg/></launch>', "f").root
    assert root is not None and root.children[0].tag == "x:arg"


def test_malformed_reports_expat_position() -> None:
    result = parse_launch_bytes(b"<launch>\n  <arg></node>\n</launch>", "f.launch")
    # expat points at the name after "</"
    assert only_error(result, "xml-malformed") == "f.launch:2:10"
    assert "mismatched tag" in result.diagnostics[0].message


def test_undefined_entity_is_malformed() -> None:
    only_error(parse_launch_bytes(b"<launch>&nope;</launch>", "f"), "xml-malformed")


def test_billion_laughs_is_refused_before_expansion() -> None:
    entities = '<!ENTITY lol0 "lol">' + "".join(
        f'<!ENTITY lol{i} "{f"&lol{i - 1};" * 10}">' for i in range(1, 10)
    )
    data = f'<?xml version="1.0"?>\n<!DOCTYPE launch [{entities}]>\n<launch>&lol9;</launch>'
    result = parse_launch_bytes(data.encode(), "bomb.launch")
    assert only_error(result, "xml-dtd-forbidden") == "bomb.launch:2:1"


def test_external_entity_is_refused(tmp_path: Path) -> None:
    secret = tmp_path / "secret.txt"
    secret.write_text("TOP SECRET")
    data = (
        f'<?xml version="1.0"?><!DOCTYPE launch [<!ENTITY xxe SYSTEM "{secret.as_uri()}">]>'
        '<launch><arg name="a" value="&xxe;"/></launch>'
    )
    result = parse_launch_bytes(data.encode(), "xxe.launch")
    only_error(result, "xml-dtd-forbidden")
    assert "TOP SECRET" not in result.diagnostics[0].message


def test_any_doctype_is_refused() -> None:
    result = parse_launch_bytes(b'<!DOCTYPE launch SYSTEM "http://x/y.dtd"><launch/>', "f")
    only_error(result, "xml-dtd-forbidden")
    only_error(parse_launch_bytes(b"<!DOCTYPE launch><launch/>", "f"), "xml-dtd-forbidden")


def test_invalid_utf8_is_located() -> None:
    result = parse_launch_bytes(b'<launch>\n  <arg name="\xff"/></launch>', "f.launch")
    assert only_error(result, "xml-encoding") == "f.launch:2:14"
    assert "0xff" in result.diagnostics[0].message


def test_latin1_without_declaration_is_an_encoding_error() -> None:
    data = '<launch>\n<arg name="café"/></launch>'.encode("latin-1")
    assert only_error(parse_launch_bytes(data, "f"), "xml-encoding") == "f:2:15"


def test_latin1_with_declaration_parses() -> None:
    data = '<?xml version="1.0" encoding="ISO-8859-1"?>\n<launch><arg name="café"/></launch>'
    result = parse_launch_bytes(data.encode("latin-1"), "f")
    assert result.root is not None and result.diagnostics == []
    assert result.root.children[0].get("name") == "café"


def test_utf16_with_bom_parses() -> None:
    data = '<?xml version="1.0" encoding="UTF-16"?>\n<launch><arg name="ü"/></launch>'
    result = parse_launch_bytes(data.encode("utf-16"), "f")
    assert result.root is not None
    assert result.root.children[0].get("name") == "ü"
    assert str(result.root.children[0].location) == "f:2:9"


@pytest.mark.parametrize("encoding", ["Shift_JIS", "no-such-encoding"])
def test_unsupported_declared_encoding(encoding: str) -> None:
    data = f'<?xml version="1.0" encoding="{encoding}"?><launch/>'.encode()
    only_error(parse_launch_bytes(data, "f"), "xml-encoding")


@pytest.mark.parametrize("data", [b"", b"  \n\t\r\n", b"\xef\xbb\xbf\n"])
def test_empty_file(data: bytes) -> None:
    only_error(parse_launch_bytes(data, "f"), "xml-empty")


def test_root_not_launch() -> None:
    result = parse_launch_bytes(b"<?xml version='1.0'?>\n<package><name>x</name></package>", "f")
    assert only_error(result, "launch-no-root") == "f:2:1"
    assert "no root <launch> tag" in result.diagnostics[0].message


def test_two_launch_elements_are_refused_like_roslaunch() -> None:
    only_error(parse_launch_bytes(b"<launch><launch/></launch>", "f"), "launch-no-root")


def test_single_wrapped_launch_is_used_like_roslaunch() -> None:
    result = parse_launch_bytes(b"<root>\n  <launch><arg name='a'/></launch></root>", "f")
    assert result.root is not None and result.root.tag == "launch"
    assert codes(result) == ["launch-nested-root"]
    assert result.diagnostics[0].severity is Severity.WARNING


def test_parse_xml_bytes_accepts_any_root() -> None:
    result = parse_xml_bytes(b"<package><name> p </name></package>", "package.xml")
    assert result.root is not None and result.root.children[0].text == " p "


def test_very_deep_nesting_is_refused_without_crashing() -> None:
    data = b"<launch>" + b"<group>" * 200_000 + b"</group>" * 200_000 + b"</launch>"
    result = parse_launch_bytes(data, "deep.launch")
    assert only_error(result, "xml-too-deep").startswith("deep.launch:1:")


def test_nesting_up_to_the_limit_is_fine() -> None:
    depth = xml.MAX_DEPTH
    data = b"<launch>" + b"<g>" * (depth - 1) + b"</g>" * (depth - 1) + b"</launch>"
    assert parse_launch_bytes(data, "f").root is not None


def test_kept_tags_are_built_and_the_rest_only_checked() -> None:
    data = (
        b"<package><name> p </name><depend>a<x>b</x></depend>"
        b"<export><build_type>ament_cmake</build_type><other/></export></package>"
    )
    keep = frozenset({"name", "export", "build_type"})
    root = parse_xml_bytes(data, "package.xml", keep).root
    assert root is not None and root.tag == "package"
    assert [c.tag for c in root.children] == ["name", "export"]
    assert root.children[0].text == " p " and root.text == ""  # no text of a skipped element
    assert [c.tag for c in root.children[1].children] == ["build_type"]
    whole = parse_xml_bytes(data, "package.xml").root
    assert whole is not None and len(whole.children) == 3
    kept = root.children[1].children[0].location
    assert kept == whole.children[2].children[0].location == Location("package.xml", 1, 60)
    # a root is built whatever its tag; what is skipped is still parsed and limited
    assert parse_xml_bytes(b"<launch/>", "f", keep).root is not None
    broken = parse_xml_bytes(b"<package><name>p</name><depend><x></depend></package>", "f", keep)
    assert codes(broken) == ["xml-malformed"]
    depth = xml.MAX_DEPTH
    deep = b"<package>" + b"<g>" * depth + b"</g>" * depth + b"</package>"
    refused = only_error(parse_xml_bytes(deep, "f", keep), "xml-too-deep")
    assert refused == only_error(parse_xml_bytes(deep, "f"), "xml-too-deep")  # the same <g>
    assert refused == f"f:1:{len(b'<package>') + 3 * (depth - 1) + 1}"
    fine = b"<package>" + b"<g>" * (depth - 1) + b"</g>" * (depth - 1) + b"</package>"
    assert parse_xml_bytes(fine, "f", keep).root is not None


def test_garbage_never_raises() -> None:
    rng = random.Random(1234)
    seed = b'<?xml version="1.0"?><launch><arg name="a"/><![CDATA[x]]><!--c--></launch>'
    for _ in range(500):
        data = bytearray(seed)
        for _ in range(rng.randint(1, 6)):
            data[rng.randrange(len(data))] = rng.randrange(256)
        result = parse_launch_bytes(bytes(data), "fuzz")
        assert (result.root is None) == any(
            d.severity is Severity.ERROR for d in result.diagnostics
        )


def test_parse_file_uses_the_given_path(tmp_path: Path) -> None:
    path = tmp_path / "a.launch"
    path.write_bytes(b"<launch>\n <arg name='a'/></launch>")
    result = parse_launch_file(path)
    assert result.root is not None
    assert str(result.root.children[0].location) == f"{path}:2:2"


def test_too_large_is_refused_before_reading(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    path = tmp_path / "big.launch"
    path.write_bytes(b"<launch>" + b" " * 100 + b"</launch>")
    monkeypatch.setattr(xml, "MAX_FILE_BYTES", 50)
    result = parse_launch_file(path)
    assert only_error(result, "file-too-large") == f"{path}:1:1"
    assert "50" in result.diagnostics[0].message


def test_missing_file_is_unreadable(tmp_path: Path) -> None:
    result = parse_launch_file(tmp_path / "nope.launch")
    only_error(result, "file-unreadable")
    assert os.strerror(2) in result.diagnostics[0].message


def test_directory_is_unreadable(tmp_path: Path) -> None:
    only_error(parse_launch_file(tmp_path), "file-unreadable")
    only_error(load_launch_file(tmp_path), "file-unreadable")


def test_cache_returns_same_tree_until_the_file_changes(tmp_path: Path) -> None:
    xml.clear_cache()
    path = tmp_path / "c.launch"
    path.write_bytes(b"<launch><arg name='a'/></launch>")
    first = load_launch_file(path)
    again = load_launch_file(str(path))
    assert first.root is not None and again.root is first.root
    again.diagnostics.append(Diagnostic("x", Severity.NOTE, "mine", Location("c")))
    assert load_launch_file(path).diagnostics == []  # callers get their own list

    stat = path.stat()
    path.write_bytes(b"<launch><arg name='a'/><arg name='b'/></launch>")
    os.utime(path, ns=(stat.st_atime_ns, stat.st_mtime_ns + 1_000_000_000))
    changed = load_launch_file(path)
    assert changed.root is not None and changed.root is not first.root
    assert [child.get("name") for child in changed.root.children] == ["a", "b"]

    path.write_bytes(b"<launch>")
    os.utime(path, ns=(stat.st_atime_ns, stat.st_mtime_ns + 2_000_000_000))
    only_error(load_launch_file(path), "xml-malformed")


def test_cache_is_bounded(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    xml.clear_cache()
    monkeypatch.setattr(xml, "CACHE_SIZE", 3)
    for index in range(6):
        path = tmp_path / f"{index}.launch"
        path.write_bytes(b"<launch/>")
        assert load_launch_file(path).root is not None
    assert len(xml._cache) == 3
    xml.clear_cache()


@pytest.mark.parametrize(
    ("content", "expected"),
    [
        (b'<?xml version="1.0"?>\n<!-- c -->\n<launch><arg name="a"/></launch>', True),
        (b"<launch>" + b"<group/>" * 5000, True),  # only the first tag matters
        (b"<package><name>launch</name></package>", False),
        (b'<library path="lib"><class name="launch"/></library>', False),
        (b"<launchx/>", False),
        (b"<!DOCTYPE launch><launch/>", True),  # listed, so the DTD gets reported
        (b'<!DOCTYPE x [<!ENTITY a "b">]><x/>', False),
        (b"", False),
        (b"\xff\xfe garbage", False),
        ('<?xml version="1.0" encoding="UTF-16"?><launch/>'.encode("utf-16"), True),
    ],
)
def test_is_launch_root(tmp_path: Path, content: bytes, expected: bool) -> None:
    path = tmp_path / "f.xml"
    path.write_bytes(content)
    assert is_launch_root(path) is expected


def test_is_launch_root_never_raises(tmp_path: Path) -> None:
    assert is_launch_root(tmp_path / "missing.xml") is False
    assert is_launch_root(tmp_path) is False
    fifo = tmp_path / "fifo.xml"
    os.mkfifo(fifo)
    assert is_launch_root(fifo) is False
    only_error(parse_launch_file(fifo), "file-unreadable")
