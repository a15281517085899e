"""GETVALUES: the values of an arg's xor-group (the interpreter's input domains).

The default; literals passed by including files; ``true``/``false`` for ``if``/``unless``;
literals an ``$(eval)`` compares with; param types; a package's executables for a node type;
existing files for a path pattern; values from a hints file; and always ``<other>``.
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING

from rosvar.analyses.feature_model.extraction import extract
from rosvar.interpreter.domains import PARAM_TYPES
from rosvar.interpreter.workspace_models import Analysis
from rosvar.logic.inputs import OTHER, UNSET, EnvInput, Slot
from rosvar.workspace import discover
from rosvar.workspace.hints import load_hints
from workspace.interfaces.ros2_packages import MANIFEST

if TYPE_CHECKING:
    from conftest import LaunchWorkspace


def domain(
    ws: LaunchWorkspace, file: str, name: str, analysis: Analysis | None = None
) -> tuple[Slot, ...]:
    analysis = analysis or ws.analysis()
    return analysis.model(str(ws.root / "pkg" / "launch" / file)).domains[name]


def literals(slots: tuple[Slot, ...]) -> set[str]:
    return {s for s in slots if isinstance(s, str)}


def test_default_comes_first_and_other_last(ws: LaunchWorkspace) -> None:
    ws.launch("a.launch", '  <arg name="robot" default="kobuki"/>\n  <arg name="frame"/>')
    assert domain(ws, "a.launch", "robot") == ("kobuki", OTHER)
    # without a default, "not given" is a slot of its own
    assert domain(ws, "a.launch", "frame") == (UNSET, OTHER)


def test_literals_passed_by_including_files(ws: LaunchWorkspace) -> None:
    ws.launch(
        "b.launch", '  <arg name="mode" default="eco"/>\n  <param name="mode" value="$(arg mode)"/>'
    )
    ws.launch(
        "a1.launch",
        '  <include file="$(find pkg)/launch/b.launch"><arg name="mode" value="turbo"/></include>',
    )
    ws.launch(
        "a2.launch",
        '  <group ns="g">\n'
        '    <include file="$(dirname)/b.launch"><arg name="mode" value="sport"/></include>\n'
        "  </group>\n"
        '  <arg name="m" default="x"/>\n'
        '  <include file="$(find pkg)/launch/b.launch">\n'
        '    <arg name="mode" value="$(arg m)"/>\n'
        "  </include>",
    )
    assert domain(ws, "b.launch", "mode") == ("eco", "sport", "turbo", OTHER)


def test_true_and_false_where_an_arg_decides_if_or_unless(ws: LaunchWorkspace) -> None:
    ws.launch(
        "a.launch",
        '  <arg name="cam"/>\n  <arg name="sim" default="false"/>\n'
        '  <node pkg="pkg" type="t" name="c" if="$(arg cam)"/>\n'
        '  <group unless="$(arg sim)"><node pkg="pkg" type="t" name="hw"/></group>',
    )
    assert domain(ws, "a.launch", "cam") == ("true", "false", UNSET, OTHER)
    assert domain(ws, "a.launch", "sim") == ("false", "true", OTHER)


def test_literals_an_eval_compares_with(ws: LaunchWorkspace) -> None:
    ws.launch(
        "a.launch",
        '  <arg name="mapper" default="gmapping"/>\n'
        '  <node pkg="pkg" type="t" name="m"\n'
        "        if=\"$(eval mapper == 'karto' or mapper == 'hector')\"/>\n"
        '  <param name="p"\n'
        "         value=\"$(eval 'yes' if arg('mapper') == 'cartographer' else 'no')\"/>",
    )
    assert domain(ws, "a.launch", "mapper") == (
        "gmapping",
        "cartographer",
        "hector",
        "karto",
        OTHER,
    )


def test_param_type_enumeration(ws: LaunchWorkspace) -> None:
    ws.launch(
        "a.launch",
        '  <arg name="t" default="str"/>\n  <param name="p" value="1" type="$(arg t)"/>',
    )
    slots = domain(ws, "a.launch", "t")
    assert slots[0] == "str" and slots[-1] is OTHER
    assert literals(slots) == set(PARAM_TYPES)


def make_driver_package(ws: LaunchWorkspace) -> None:
    ws.package("drv")
    ws.write(".executables", "alpha_driver\nlisted_tool\n", package="drv")
    script = Path(ws.write("scripts/beta_driver", "#!/bin/sh\n", package="drv"))
    script.chmod(0o755)
    ws.write("scripts/notes_driver", "not executable, not Python\n", package="drv")
    ws.write("nodes/gamma_driver.py", "", package="drv")
    ws.write(
        "CMakeLists.txt",
        "project(drv)\nadd_executable(${PROJECT_NAME}_delta_driver src/d.cpp)\n"
        "add_executable(eps_driver src/e.cpp)\n",
        package="drv",
    )
    ws.write(
        "setup.py",
        "setup(\n    entry_points={\n        'console_scripts': [\n"
        "            'zeta_driver = drv.zeta:main',\n        ],\n    },\n)\n",
        package="drv",
    )


def test_node_type_pattern_takes_the_packages_executables(ws: LaunchWorkspace) -> None:
    make_driver_package(ws)
    ws.launch(
        "a.launch",
        '  <arg name="model" default="alpha"/>\n'
        '  <node pkg="drv" type="$(arg model)_driver" name="driver"/>\n'
        '  <arg name="exe" default="listed_tool"/>\n'
        '  <node pkg="drv" type="$(arg exe)" name="whole"/>',
    )
    assert domain(ws, "a.launch", "model") == (
        "alpha",
        "beta",
        "drv_delta",
        "eps",
        "zeta",
        OTHER,
    )
    exe = domain(ws, "a.launch", "exe")
    assert exe[0] == "listed_tool" and exe[-1] is OTHER
    assert literals(exe) == {
        "alpha_driver",
        "listed_tool",
        "beta_driver",
        "gamma_driver.py",
        "drv_delta_driver",
        "eps_driver",
        "zeta_driver",
    }


def test_node_type_of_an_unknown_package_gives_no_values(ws: LaunchWorkspace) -> None:
    ws.launch(
        "a.launch",
        '  <arg name="model" default="alpha"/>\n'
        '  <node pkg="nowhere" type="$(arg model)_driver" name="driver"/>',
    )
    assert domain(ws, "a.launch", "model") == ("alpha", OTHER)


def test_file_path_pattern_takes_the_files_that_exist(ws: LaunchWorkspace) -> None:
    for name in ("kobuki.launch", "create.launch", "roomba.launch.xml", "README.md"):
        ws.write(f"launch/robots/{name}", "<launch/>\n")
    ws.launch(
        "a.launch",
        '  <arg name="robot" default="kobuki"/>\n'
        '  <include file="$(find pkg)/launch/robots/$(arg robot).launch"/>',
    )
    # roomba.launch.xml does not end with ".launch", README.md neither
    assert domain(ws, "a.launch", "robot") == ("kobuki", "create", OTHER)


def test_file_path_pattern_with_prefix_and_suffix(ws: LaunchWorkspace) -> None:
    for name in ("base_kobuki.launch.xml", "base_create.launch.xml", "other_x.launch.xml"):
        ws.write(f"launch/includes/{name}", "<launch/>\n")
    ws.launch(
        "a.launch",
        '  <arg name="base"/>\n'
        '  <include file="$(find pkg)/launch/includes/base_$(arg base).launch.xml"/>',
    )
    assert domain(ws, "a.launch", "base") == ("create", "kobuki", UNSET, OTHER)


def test_every_arg_keeps_an_other_slot(ws: LaunchWorkspace) -> None:
    ws.launch(
        "a.launch",
        '  <arg name="b" default="true"/>\n  <arg name="t" default="int"/>\n'
        '  <node pkg="pkg" type="t" name="n" if="$(arg b)"/>\n'
        '  <param name="p" value="1" type="$(arg t)"/>',
    )
    model = extract(ws.analysis())
    for feature in model.files:
        for arg in feature.args:
            assert arg.values[-1].slot is OTHER
            assert arg.values[-1].value == "<other>"
    for name in ("b", "t"):
        assert domain(ws, "a.launch", name)[-1] is OTHER


def test_pass_all_args_passes_the_includers_literal_defaults(ws: LaunchWorkspace) -> None:
    ws.launch(
        "a.launch",
        '  <arg name="x" default="fast"/>\n'
        '  <include file="$(find pkg)/launch/b.launch" pass_all_args="true"/>',
    )
    ws.launch(
        "b.launch", '  <arg name="x" default="slow"/>\n  <node pkg="pkg" type="t" name="$(arg x)"/>'
    )
    assert domain(ws, "b.launch", "x") == ("slow", "fast", OTHER)


# -- hints ------------------------------------------------------------------------------------
HINTS = """\
executables:
  drv: [omega_driver]
args:
  robot: [husky, jackal]
  a.launch:laser: lms1xx
  b.launch:laser: [sick]
env:
  ROBOT_KIND: [wheeled, legged]
"""


def hinted_analysis(ws: LaunchWorkspace, tmp_path: Path) -> Analysis:
    path = tmp_path / "hints.yaml"
    path.write_text(HINTS)
    hints = load_hints(str(path))
    assert hints.diagnostics == []
    workspace = discover([ws.root], ros_package_path="")
    return Analysis(workspace, hints.args, hints.env, hints.executables)


def test_hints_add_values(ws: LaunchWorkspace, tmp_path: Path) -> None:
    ws.package("drv")
    ws.launch(
        "a.launch",
        '  <arg name="robot" default="kobuki"/>\n  <arg name="laser" default="none"/>\n'
        '  <arg name="model" default="alpha"/>\n'
        '  <node pkg="pkg" type="t" name="$(arg robot)"/>\n'
        '  <param name="laser" value="$(arg laser)"/>\n'
        '  <node pkg="drv" type="$(arg model)_driver" name="d"/>\n'
        '  <param name="kind" value="$(env ROBOT_KIND)"/>',
    )
    analysis = hinted_analysis(ws, tmp_path)
    assert domain(ws, "a.launch", "robot", analysis) == ("kobuki", "husky", "jackal", OTHER)
    # FILE:arg applies to the args of that file only
    assert domain(ws, "a.launch", "laser", analysis) == ("none", "lms1xx", OTHER)
    assert domain(ws, "a.launch", "model", analysis) == ("alpha", "omega", OTHER)
    assert analysis.space.domain(EnvInput("ROBOT_KIND")) == ("wheeled", "legged", UNSET, OTHER)
    # and they are values of the feature model
    model = extract(analysis)
    [feature] = model.files
    robot = next(a for a in feature.args if a.name == "robot")
    assert [v.value for v in robot.values] == ["kobuki", "husky", "jackal", "<other>"]


def test_without_hints_the_env_domain_is_unset_and_other(ws: LaunchWorkspace) -> None:
    ws.launch("a.launch", '  <param name="kind" value="$(env ROBOT_KIND)"/>')
    analysis = ws.analysis()
    analysis.model(str(ws.root / "pkg" / "launch" / "a.launch"))
    assert analysis.space.domain(EnvInput("ROBOT_KIND")) == (UNSET, OTHER)


def test_domains_do_not_depend_on_the_order_files_are_analysed(ws: LaunchWorkspace) -> None:
    ws.launch(
        "b.launch", '  <arg name="mode" default="eco"/>\n  <param name="m" value="$(arg mode)"/>'
    )
    ws.launch(
        "a.launch",
        '  <include file="$(find pkg)/launch/b.launch"><arg name="mode" value="turbo"/></include>',
    )
    first = ws.analysis()
    b = str(ws.root / "pkg" / "launch" / "b.launch")
    early = first.model(b).domains["mode"]  # b before its includer was analysed
    assert early == ("eco", "turbo", OTHER)


def _fresh(ws: LaunchWorkspace) -> Analysis:
    return Analysis(discover([ws.root], ros_package_path=""))


def test_forwarded_args_range_over_the_values_of_the_args_they_reach(ws: LaunchWorkspace) -> None:
    """``<arg name="y" value="$(arg x)"/>`` in an include: ``x`` takes the included file's
    values of ``y``, along chains of includes; asked in either order, the same domains."""
    ws.launch(
        "c.launch",
        '  <arg name="z" default="slow"/>\n'
        '  <node pkg="pkg" type="t" name="n" if="$(eval z == \'fast\')"/>',
    )
    ws.launch(
        "b.launch",
        '  <arg name="y"/>\n'
        '  <include file="$(dirname)/c.launch"><arg name="z" value="$(arg y)"/></include>',
    )
    ws.launch(
        "a.launch",
        '  <arg name="x" default="medium"/>\n'
        '  <include file="$(dirname)/b.launch"><arg name="y" value="$(arg x)"/></include>',
    )
    expected = {
        "a.launch": ("x", ("medium", "fast", "slow", OTHER)),
        "b.launch": ("y", ("fast", "slow", UNSET, OTHER)),
        "c.launch": ("z", ("slow", "fast", OTHER)),
    }
    for order in (["a.launch", "b.launch", "c.launch"], ["c.launch", "b.launch", "a.launch"]):
        analysis = _fresh(ws)
        for file in order:
            name, slots = expected[file]
            assert domain(ws, file, name, analysis) == slots


def test_forwarded_args_in_a_loop_end(ws: LaunchWorkspace) -> None:
    """Files forwarding args to each other in a loop: each chain stops where it comes back,
    so the domain of ``y`` met on the chain from ``x`` misses what only ``x`` reaches (``z``'s
    values): it is not the domain of ``y`` asked for itself, which has them."""
    ws.launch("c.launch", '  <arg name="z" default="cz"/>')
    ws.launch(
        "a.launch",
        '  <arg name="x" default="ax"/>\n'
        '  <include file="$(dirname)/b.launch" if="false"><arg name="y" value="$(arg x)"/>'
        "</include>\n"
        '  <include file="$(dirname)/c.launch"><arg name="z" value="$(arg x)"/></include>',
    )
    ws.launch(
        "b.launch",
        '  <arg name="y" default="by"/>\n'
        '  <include file="$(dirname)/a.launch" if="false"><arg name="x" value="$(arg y)"/>'
        "</include>",
    )
    for order in (["a.launch", "b.launch"], ["b.launch", "a.launch"]):
        analysis = _fresh(ws)
        for file in order:
            name = "x" if file == "a.launch" else "y"
            assert literals(domain(ws, file, name, analysis)) == {"ax", "by", "cz"}


def test_literals_a_ros2_eval_compares_with(tmp_path: Path) -> None:
    """ROS 2's ``$(eval)`` substitutes the arg's text into its Python: XML quotes it
    (``'$(var mode)'``), the Python frontend writes its ``repr`` (a comparison of a
    ``perform``'s string); either way the literals compared with are values, as roslaunch's
    ``$(eval)``'s are."""
    package = tmp_path / "pkg"
    (package / "launch").mkdir(parents=True)
    (package / "package.xml").write_text(MANIFEST.format(name="pkg", build="ament_python"))
    (package / "launch" / "a.launch.xml").write_text(
        '<launch><arg name="mode" default="auto"/><arg name="n" default="1"/>\n'
        '<node pkg="pkg" exec="x" name="x" if="$(eval &quot;\'$(var mode)\' == \'fast\''
        " or '$(var mode)' in ['slow'] or $(var n) == 3&quot;)\"/></launch>\n"
    )
    (package / "launch" / "b.launch.py").write_text(
        "from launch import LaunchDescription\n"
        "from launch.actions import DeclareLaunchArgument, OpaqueFunction\n"
        "from launch.substitutions import LaunchConfiguration\n"
        "from launch_ros.actions import Node\n\n"
        "def setup(context):\n"
        "    if LaunchConfiguration('use_a').perform(context) == 'true':\n"
        "        return [Node(package='pkg', executable='x', name='with_a')]\n"
        "    return []\n\n"
        "def generate_launch_description():\n"
        "    return LaunchDescription([DeclareLaunchArgument('use_a', default_value='false'),\n"
        "                              OpaqueFunction(function=setup)])\n"
    )
    analysis = Analysis(discover([tmp_path], ros_package_path=""))
    xml = analysis.model(str(package / "launch" / "a.launch.xml"))
    python = analysis.model(str(package / "launch" / "b.launch.py"))
    assert xml.domains["mode"] == ("auto", "fast", "slow", OTHER)
    assert literals(xml.domains["n"]) == {"1", "3"}
    assert python.domains["use_a"] == ("false", "true", OTHER)
    [node] = python.nodes
    assert analysis.space.describe(node.condition) == "use_a"
