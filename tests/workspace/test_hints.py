"""The hints file: YAML sections ``executables``, ``args`` and ``env``; problems as diagnostics."""

from __future__ import annotations

from pathlib import Path

from rosvar.diagnostics import Location, Severity
from rosvar.workspace.hints import Hints, load_hints


def hints_from(tmp_path: Path, text: str) -> tuple[Hints, str]:
    path = tmp_path / "hints.yaml"
    path.write_text(text)
    return load_hints(str(path)), str(path)


def test_no_hints_file() -> None:
    hints = load_hints(None)
    assert (hints.executables, hints.args, hints.env, hints.diagnostics) == ({}, {}, {}, [])


def test_all_sections(tmp_path: Path) -> None:
    hints, _ = hints_from(
        tmp_path,
        "executables:\n  my_pkg: [driver_node, other_node]\n"
        "args:\n  robot: [husky, jackal]\n  bringup.launch:laser: lms1xx\n"
        "  use_sim: [true, false]\n  rate: [10, 2.5]\n"
        "env:\n  TURTLEBOT_3D_SENSOR: [kinect, astra]\n",
    )
    assert hints.diagnostics == []
    assert hints.executables == {"my_pkg": ["driver_node", "other_node"]}
    assert hints.args == {
        "robot": ["husky", "jackal"],
        "bringup.launch:laser": ["lms1xx"],  # a scalar is a list of one
        "use_sim": ["true", "false"],  # YAML booleans as roslaunch spells them
        "rate": ["10", "2.5"],
    }
    assert hints.env == {"TURTLEBOT_3D_SENSOR": ["kinect", "astra"]}


def test_empty_file(tmp_path: Path) -> None:
    hints, _ = hints_from(tmp_path, "# nothing yet\n")
    assert (hints.args, hints.diagnostics) == ({}, [])


def test_missing_file(tmp_path: Path) -> None:
    path = str(tmp_path / "absent.yaml")
    hints = load_hints(path)
    [diagnostic] = hints.diagnostics
    assert diagnostic.code == "hints-invalid" and diagnostic.severity is Severity.ERROR
    assert diagnostic.location.file == path
    assert "cannot read" in diagnostic.message


def test_invalid_yaml_points_at_its_line(tmp_path: Path) -> None:
    hints, path = hints_from(tmp_path, "args:\n  robot: [husky, jackal\n  laser: sick\n")
    [diagnostic] = hints.diagnostics
    assert diagnostic.code == "hints-invalid"
    assert diagnostic.location.file == path
    assert diagnostic.location.line == 3  # where the parser gave up
    assert str(diagnostic).startswith(f"{path}:3:")
    assert hints.args == {}


def test_not_a_mapping(tmp_path: Path) -> None:
    hints, path = hints_from(tmp_path, "- robot\n- laser\n")
    [diagnostic] = hints.diagnostics
    assert diagnostic.location == Location(path, 1, 1)
    assert "mapping" in diagnostic.message


def test_bad_sections_are_reported_and_the_rest_is_kept(tmp_path: Path) -> None:
    hints, path = hints_from(
        tmp_path,
        "args:\n  robot: [husky]\nbogus:\n  x: [1]\nenv: [A, B]\n",
    )
    assert hints.args == {"robot": ["husky"]}
    assert hints.env == {}
    messages = [d.message for d in hints.diagnostics]
    assert len(messages) == 2
    assert "unknown section 'bogus'" in messages[0]
    assert "section 'env' must map" in messages[1]
    assert all(d.location.file == path for d in hints.diagnostics)


def test_section_errors_point_at_their_lines(tmp_path: Path) -> None:
    hints, path = hints_from(
        tmp_path,
        "args:\n  robot: [husky]\nbogus:\n  x: [1]\nenv: [A, B]\n",
    )
    assert [(d.location.file, d.location.line) for d in hints.diagnostics] == [
        (path, 3),
        (path, 5),
    ]


def test_values_that_are_not_scalars_are_reported(tmp_path: Path) -> None:
    hints, _ = hints_from(tmp_path, "args:\n  robot:\n  laser: {a: b}\n  ok: [x]\n")
    assert hints.args == {"ok": ["x"]}
    assert len(hints.diagnostics) == 2


def test_unsafe_tags_are_reported_not_constructed(tmp_path: Path) -> None:
    hints, _ = hints_from(tmp_path, "args:\n  robot: !!python/name:os.system x\n  ok: [x]\n")
    assert hints.args == {"ok": ["x"]}
    assert [d.location.line for d in hints.diagnostics] == [2]
