"""ROS 2's term functions of one input related by their cells (``ros2/term_cells.py``): an
``IfCondition`` over an argument and one over a ``PythonExpression`` of it come out together
only as some text of the argument makes them, so a value nobody foresaw no longer makes both
true when no text does; where one does, the finding's example is that text, and the real
ros2/launch (the oracle) agrees that it gives the finding."""

from __future__ import annotations

from pathlib import Path

from oracle.ros2_client import requires_ros2_oracle, run_oracle
from rosvar.analyses.checks import UNTOLD, Check, Finding, check_models
from rosvar.diagnostics import Severity
from rosvar.interpreter.workspace_models import Analysis
from rosvar.outputs.describe import possible_errors
from rosvar.outputs.documents.findings import finding_document
from rosvar.workspace import discover
from rosvar.workspace.interfaces.model import Interfaces
from workspace.interfaces.ros2_packages import MANIFEST

PYTHON = """
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, GroupAction
from launch.conditions import IfCondition
from launch.substitutions import LaunchConfiguration, PythonExpression
from launch_ros.actions import Node

def generate_launch_description():
    flag = LaunchConfiguration("flag")
    return LaunchDescription([
        DeclareLaunchArgument("flag", default_value="False"),
        GroupAction(condition=IfCondition(PythonExpression(SECOND)), actions=[
            Node(package="demo", executable="map_server", name="map_server")]),
        Node(package="demo", executable="map_server", name="map_server",
             condition=IfCondition(flag)),
    ])
"""
XML = """<launch>
  <arg name="flag" default="False"/>
  <group if="$(eval 'not $(var flag)')">
    <node pkg="demo" exec="map_server" name="map_server"/>
  </group>
  <node pkg="demo" exec="map_server" name="map_server" if="$(var flag)"/>
</launch>"""


def _clashes(tmp_path: Path, name: str, text: str) -> tuple[Analysis, Path, list[Finding]]:
    package = tmp_path / "pkg"
    (package / "launch").mkdir(parents=True, exist_ok=True)
    (package / "package.xml").write_text(MANIFEST.format(name="pkg", build="ament_python"))
    file = package / "launch" / name
    file.write_text(text)
    analysis = Analysis(discover([tmp_path], ros_package_path=""))
    model = analysis.model(str(file))
    findings = check_models(analysis.space, [model], Interfaces(), analysis.workspace.confinement())
    return analysis, file, [f for f in findings if f.check is Check.NODE_NAME_CLASH]


def test_an_if_and_its_negation_never_clash(tmp_path: Path) -> None:
    """nav2's localization_launch.py: a group under ``not use_composition`` and a node under
    ``use_composition``. No text makes ``not X`` truthy Python while X reads as true to
    ``IfCondition`` (``True`` gives ``not True``, ``true`` and ``TRUE`` no Python at all)."""
    python = PYTHON.replace("SECOND", "['not ', flag]")
    assert _clashes(tmp_path, "a.launch.py", python)[2] == []
    assert _clashes(tmp_path, "a.launch.xml", XML)[2] == []


def test_without_the_relation_they_would_clash_for_other_values(tmp_path: Path) -> None:
    """The test above can fail: an expression that does not negate the argument clashes."""
    python = PYTHON.replace("SECOND", "[flag, ' == 1']")  # True or 1: true both ways
    _analysis, _file, [clash] = _clashes(tmp_path, "a.launch.py", python)
    assert clash.name == "/map_server"


@requires_ros2_oracle[0]
@requires_ros2_oracle[1]
def test_a_clash_only_an_unforeseen_text_gives_shows_that_text(tmp_path: Path) -> None:
    """``PythonExpression([flag, ' == 1'])`` and ``IfCondition(flag)``: no foreseen value
    (``False``) makes both true, unforeseen ones do (``True``, ``1``): the example gives such
    a text, and ros2/launch given it starts both nodes."""
    python = PYTHON.replace("SECOND", "[flag, ' == 1']")
    analysis, file, [clash] = _clashes(tmp_path, "a.launch.py", python)
    example = finding_document(clash, analysis.space)["example"]
    assert isinstance(example, dict)
    [text] = [value for key, value in example.items() if key.endswith(":flag")]
    assert text not in ("<other>", "False")
    result = run_oracle(file, {"flag": text}, [tmp_path], strict=False)
    names = [node.get("name") for node in result["nodes"]]
    assert names.count("map_server") == 2, (text, result)


def test_a_clash_no_witness_gives_is_a_note_rosvar_could_not_tell(tmp_path: Path) -> None:
    """ros_gz_sim's gz_server.launch.py: ``not use_composition`` against ``use_composition
    and own_container``, a predicate of two inputs that no fact relates. Only unforeseen
    values could give the clash and no text tried does: a note saying so, not a warning."""
    python = PYTHON.replace("SECOND", "[flag, ' and ', LaunchConfiguration('own')]")
    python = python.replace(
        "condition=IfCondition(flag)", "condition=IfCondition(PythonExpression(['not ', flag]))"
    )
    python = python.replace(
        'DeclareLaunchArgument("flag", default_value="False"),',
        'DeclareLaunchArgument("flag", default_value="False"), '
        'DeclareLaunchArgument("own", default_value="False"),',
    )
    analysis, _file, [clash] = _clashes(tmp_path, "a.launch.py", python)
    assert clash.severity is Severity.NOTE
    assert clash.message.endswith(UNTOLD)
    example = finding_document(clash, analysis.space)["example"]
    assert isinstance(example, dict) and "<other>" in example.values()


def test_a_python_comparison_of_a_launch_time_string_is_true_or_false(tmp_path: Path) -> None:
    """realsense's rs_launch.py: ``if os.getenv('ROS_DISTRO') == 'dashing'``. The Python
    frontend quotes the launch-time text (``repr``) into the expression, so no text makes it
    anything but ``True`` or ``False``: no 'not a bool' error for an unforeseen value."""
    package = tmp_path / "pkg"
    (package / "launch").mkdir(parents=True)
    (package / "package.xml").write_text(MANIFEST.format(name="pkg", build="ament_python"))
    file = package / "launch" / "a.launch.py"
    file.write_text(
        "import os\n"
        "from launch import LaunchDescription\n"
        "from launch_ros.actions import Node\n\n"
        "def generate_launch_description():\n"
        "    nodes = []\n"
        "    if os.getenv('ROS_DISTRO') == 'dashing' or os.getenv('ROS_DISTRO') == 'foxy':\n"
        "        nodes.append(Node(package='pkg', executable='x', name='old'))\n"
        "    else:\n"
        "        nodes.append(Node(package='pkg', executable='x', name='new'))\n"
        "    return LaunchDescription(nodes)\n"
    )
    analysis = Analysis(discover([tmp_path], ros_package_path=""))
    model = analysis.model(str(file))
    assert len(model.nodes) == 2
    assert [(e.code, analysis.space.describe(e.condition)) for e in possible_errors(model)] == []
