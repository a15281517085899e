"""Synthetic ROS 1 workspaces of any size, shaped like the corpus, for the scaling benchmarks.

The corpus stops at 137 launch files (Husky); the targets go to 10,000. These workspaces
keep the corpus's proportions so per-file cost stays comparable as the size grows:

* packages of ``FILES_PER_PACKAGE`` launch files, each with ``package.xml``, ``.executables``
  (the corpus convention rosvar reads) and a ``config/params.yaml`` for ``rosparam load``;
* 2-5 ``<arg>`` per file: booleans steer ``if``/``unless`` on nodes, groups and includes,
  strings end up in node names, namespaces and remaps; a few have no default (command-line
  inputs) or default to ``$(optenv ...)`` like Husky's;
* each file's nodes and parameters sit in its package's namespace (``<group ns="PKG">``,
  the multi-robot layout), and parameter names shared by several files of a package, with
  file-specific values, so files that include each other set the same parameter
  differently (conflicts for the analysis to find). Sharing stays within a package, as
  clashes stay within one robot's configurations in the corpus: a file shares a name with
  a few others (Husky: about 500 pairs for 137 files), not with every file of the
  workspace;
* inline ``<rosparam>`` YAML and ``rosparam load``;
* ``<include>`` of 1-2 files of the same or the previous package of the same *system*
  (``PACKAGES_PER_SYSTEM`` packages, about one Husky), some conditional, all passing args
  (a system's first package's "previous" is its last, so every size has one shape). A large
  workspace is many systems side by side, not one system that grows: includes do not cross
  systems, as the corpus systems do not include each other. Each file has a *level* and
  includes only lower levels, so there are no cycles and an include chain holds at most
  ``MAX_LEVEL + 1`` files, as in real systems.

Output is a pure function of ``(n_files, seed)``: each file draws from its own seeded RNG.

The *uniform* shape (:func:`generate_uniform`, ``--shape uniform``) is the one of the
workspace-scale issue instead: every file alike, with 5 args (3 booleans, 2 strings), 5
nodes each under ``if``/``unless`` of a boolean, one ``<group>`` (a namespace from an arg,
itself conditional) and one ``<include>`` passing args. Includes chain the files of a package
in runs of ``UNIFORM_CHAIN`` and the last of a run includes the package's last file, the one
file without an include, so chains stay short whatever the size.

The *ros2* shape (:func:`generate_ros2`, ``--shape ros2``) is the ROS 2 workspace of issue 19:
120 XML launch files with 1,500 args (12-13 per file: booleans, strings, numbers, ``<choice>``
lists, a few required, defaults from other args and ``$(env)``) in ament_cmake packages of 10
(``package.xml`` format 3, ``CMakeLists.txt`` with the executables, ``config/params.yaml``),
with ``<let>``, ``<group>`` + ``<push-ros-namespace>``, ``<set_remap>``, ``<node>`` with
params (inline and ``from=``) and remaps, ``if``/``unless``, and ``<include>`` of
``$(find-pkg-share)`` paths with args. A file of level L (``index % 8``) includes one file of
level L-1 and sometimes one further down, so the deepest include trees are 8 files deep, as
in the largest public ROS 2 launch trees.

Run as a script to write a workspace:
``python bench/generate.py DIR N [--seed S] [--shape corpus|uniform|ros2]``.
"""

from __future__ import annotations

import argparse
import random
import re
from dataclasses import dataclass
from pathlib import Path

FILES_PER_PACKAGE = 20
PACKAGES_PER_SYSTEM = 5
MAX_LEVEL = 3
LEVEL_WEIGHTS = (35, 30, 20, 15)  # share of files at level 0 (leaves) .. MAX_LEVEL (bringups)
EXECUTABLES = ("driver", "controller", "monitor", "relay", "bridge", "estimator", "planner")
FILE_STEMS = (
    "bringup",
    "base",
    "sensors",
    "lidar",
    "camera",
    "imu",
    "localization",
    "navigation",
    "teleop",
    "description",
    "control",
    "mapping",
    "diagnostics",
    "gazebo",
    "rviz",
)
BOOL_WORDS = (
    "sim",
    "rviz",
    "ekf",
    "lidar",
    "camera",
    "imu",
    "gps",
    "teleop",
    "nav",
    "mapping",
    "debug",
    "diagnostics",
)
STRING_ARGS = (
    ("robot_name", "robot"),
    ("robot_namespace", "husky"),
    ("camera_name", "camera"),
    ("tf_prefix", "base"),
    ("scan_topic", "scan"),
    ("map_frame", "map"),
)
# Parameters several files of a package set, each with its own value: the source of conflicts.
SHARED_PARAMS = (
    "use_sim_time",
    "robot/max_velocity",
    "robot/controller_frequency",
    "diagnostics/period",
    "tf/publish_rate",
    "navigation/planner",
)
OPTENV_RATE = 0.15  # share of string args defaulting to $(optenv ...), as in Husky
REQUIRED_RATE = 0.1  # share of args without a default (true command-line inputs)
CONDITIONAL_INCLUDE_RATE = 0.35


@dataclass(frozen=True)
class _Arg:
    name: str
    boolean: bool
    default: str | None  # None: must be given on the command line or by the includer


@dataclass(frozen=True)
class _Plan:
    index: int
    package: str
    name: str
    level: int
    args: tuple[_Arg, ...]

    @property
    def find_path(self) -> str:
        return f"$(find {self.package})/launch/{self.name}"


def _package_name(number: int) -> str:
    return f"gen_pkg_{number:04d}"


def _plan_args(rng: random.Random) -> tuple[_Arg, ...]:
    count = rng.randint(2, 5)
    n_bool = rng.randint(1, count - 1)
    args: list[_Arg] = []
    for word in rng.sample(BOOL_WORDS, n_bool):
        default = None if rng.random() < REQUIRED_RATE else rng.choice(("true", "false"))
        args.append(_Arg(f"use_{word}", True, default))
    for name, value in rng.sample(STRING_ARGS, count - n_bool):
        roll = rng.random()
        if roll < REQUIRED_RATE:
            default = None
        elif roll < REQUIRED_RATE + OPTENV_RATE:
            default = f"$(optenv {name.upper()} {value})"
        else:
            default = value
        args.append(_Arg(name, False, default))
    return tuple(args)


def _plan(n_files: int, seed: int) -> list[_Plan]:
    plans: list[_Plan] = []
    for index in range(n_files):
        rng = random.Random(f"plan:{seed}:{index}")
        number, position = divmod(index, FILES_PER_PACKAGE)
        level = rng.choices(range(MAX_LEVEL + 1), weights=LEVEL_WEIGHTS)[0]
        stem = FILE_STEMS[position % len(FILE_STEMS)]
        suffix = ".launch.xml" if rng.random() < 0.1 else ".launch"
        name = f"{stem}_{position:02d}{suffix}"
        plans.append(_Plan(index, _package_name(number), name, level, _plan_args(rng)))
    return plans


def _include_candidates(plans: list[_Plan], plan: _Plan) -> list[_Plan]:
    """Lower-level files of this package or of the previous one in its system (the
    system's last, for its first).

    Levels alone rule out cycles; wrapping around gives a system's first package the same
    choice as every other, so the include shape does not depend on the workspace size.
    """
    number = plan.index // FILES_PER_PACKAGE
    first = number - number % PACKAGES_PER_SYSTEM
    packages_total = (len(plans) + FILES_PER_PACKAGE - 1) // FILES_PER_PACKAGE
    in_system = min(PACKAGES_PER_SYSTEM, packages_total - first)
    previous = first + (number - first - 1) % in_system
    packages = dict.fromkeys((previous, number))
    return [
        candidate
        for package in packages
        for candidate in plans[package * FILES_PER_PACKAGE : (package + 1) * FILES_PER_PACKAGE]
        if candidate.level < plan.level
    ]


class _Writer:
    """Accumulates indented XML lines for one launch file."""

    def __init__(self) -> None:
        self.lines: list[str] = []

    def add(self, depth: int, text: str) -> None:
        self.lines.append("  " * depth + text)


def _condition(rng: random.Random, bools: list[_Arg], rate: float) -> str:
    if not bools or rng.random() >= rate:
        return ""
    keyword = rng.choice(("if", "if", "unless"))
    return f' {keyword}="$(arg {rng.choice(bools).name})"'


def _string_ref(rng: random.Random, strings: list[_Arg], fallback: str) -> str:
    return f"$(arg {rng.choice(strings).name})" if strings else fallback


def _render_include(
    out: _Writer, rng: random.Random, plan: _Plan, target: _Plan, bools: list[_Arg]
) -> None:
    condition = _condition(rng, bools, CONDITIONAL_INCLUDE_RATE)
    out.add(1, f'<include file="{target.find_path}"{condition}>')
    own = {arg.name: arg for arg in plan.args}
    for arg in target.args:
        if arg.default is not None and rng.random() < 0.4:
            continue  # leave the included file's default in place
        mine = own.get(arg.name)
        if mine is not None and rng.random() < 0.7:
            value = f"$(arg {mine.name})"
        elif arg.boolean:
            value = rng.choice(("true", "false"))
        else:
            value = f"{arg.name.split('_')[0]}_{plan.index % 7}"
        out.add(2, f'<arg name="{arg.name}" value="{value}"/>')
    out.add(1, "</include>")


def _render_node(
    out: _Writer,
    rng: random.Random,
    depth: int,
    plan: _Plan,
    number: int,
    bools: list[_Arg],
    strings: list[_Arg],
) -> None:
    executable = rng.choice(EXECUTABLES)
    if strings and rng.random() < 0.5:
        name = f"{_string_ref(rng, strings, '')}_{executable}_{number}"
    else:
        name = f"{plan.name.split('_')[0]}_{executable}_{number}"
    condition = _condition(rng, bools, 0.4)
    attributes = f'pkg="{plan.package}" type="{executable}" name="{name}" output="screen"'
    out.add(depth, f"<node {attributes}{condition}>")
    for key in rng.sample(("rate", "frame_id", "timeout", "queue_size", "verbose"), 2):
        value = (
            f"{_string_ref(rng, strings, 'base')}_link"
            if key == "frame_id"
            else str(rng.randint(1, 100))
        )
        out.add(depth + 1, f'<param name="{key}" value="{value}"/>')
    if rng.random() < 0.6:
        topic = _string_ref(rng, strings, "cmd_vel")
        out.add(depth + 1, f'<remap from="input" to="{topic}/data"/>')
    if rng.random() < 0.35:
        out.add(depth + 1, "<rosparam>")
        out.add(depth + 2, f"gains: {{p: {rng.randint(1, 9)}.0, i: 0.{rng.randint(0, 9)}, d: 0.0}}")
        out.add(depth + 2, "limits:")
        out.add(depth + 3, f"max_velocity: {rng.randint(1, 3)}.{rng.randint(0, 9)}")
        out.add(depth + 3, f"max_acceleration: {rng.randint(1, 5)}.0")
        out.add(depth + 2, f"joints: [joint_{number}_a, joint_{number}_b]")
        out.add(depth + 1, "</rosparam>")
    out.add(depth, "</node>")


def _render(plans: list[_Plan], plan: _Plan, seed: int) -> str:
    rng = random.Random(f"file:{seed}:{plan.index}")
    bools = [arg for arg in plan.args if arg.boolean]
    strings = [arg for arg in plan.args if not arg.boolean]
    out = _Writer()
    out.add(0, '<?xml version="1.0"?>')
    out.add(0, f"<!-- Synthetic launch file (bench/generate.py), level {plan.level}. -->")
    out.add(0, "<launch>")
    for arg in plan.args:
        default = "" if arg.default is None else f' default="{arg.default}"'
        out.add(1, f'<arg name="{arg.name}"{default}/>')
    candidates = _include_candidates(plans, plan)
    if candidates:  # outside the package's group: each file names its own namespace
        for target in rng.sample(candidates, min(len(candidates), rng.randint(1, 2))):
            out.add(0, "")
            _render_include(out, rng, plan, target, bools)
    out.add(0, "")
    out.add(1, f'<group ns="{plan.package}">')
    for name in rng.sample(SHARED_PARAMS, rng.randint(1, 2)):
        value = f"$(arg {bools[0].name})" if name == "use_sim_time" else str(plan.index % 5)
        out.add(2, f'<param name="{name}" value="{value}"/>')
    if rng.random() < 0.5:
        out.add(2, f'<rosparam command="load" file="$(find {plan.package})/config/params.yaml"/>')
    number = 0
    for _ in range(rng.randint(1, 2)):
        out.add(0, "")
        ns = _string_ref(rng, strings, "robot") if rng.random() < 0.6 else f"ns_{plan.index % 9}"
        out.add(2, f'<group ns="{ns}"{_condition(rng, bools, 0.3)}>')
        out.add(3, f'<param name="robot/max_velocity" value="{rng.randint(1, 4)}.0"/>')
        for _ in range(rng.randint(1, 2)):
            _render_node(out, rng, 3, plan, number, bools, strings)
            number += 1
        out.add(2, "</group>")
    if rng.random() < 0.5:
        out.add(0, "")
        _render_node(out, rng, 2, plan, number, bools, strings)
    out.add(1, "</group>")
    out.add(0, "</launch>")
    return "\n".join(out.lines) + "\n"


def _package_xml(name: str) -> str:
    return (
        '<?xml version="1.0"?>\n<package format="2">\n'
        f"  <name>{name}</name>\n  <version>0.0.1</version>\n"
        f"  <description>Synthetic package {name} for rosvar benchmarks.</description>\n"
        '  <maintainer email="bench@example.com">bench</maintainer>\n'
        "  <license>Apache-2.0</license>\n  <buildtool_depend>catkin</buildtool_depend>\n"
        "</package>\n"
    )


_PARAMS_YAML = """\
robot:
  max_velocity: 1.0
  controller_frequency: 20.0
sensors:
  - {name: front_lidar, rate: 10}
  - {name: imu, rate: 100}
"""


def generate_workspace(root: Path, n_files: int, seed: int = 0) -> list[Path]:
    """Write ``n_files`` launch files in packages below ``root``; returns their paths."""
    plans = _plan(n_files, seed)
    written: list[Path] = []
    for number in range((n_files + FILES_PER_PACKAGE - 1) // FILES_PER_PACKAGE):
        package = root / _package_name(number)
        (package / "launch").mkdir(parents=True, exist_ok=True)
        (package / "config").mkdir(exist_ok=True)
        (package / "package.xml").write_text(_package_xml(package.name), encoding="utf-8")
        (package / ".executables").write_text("\n".join(EXECUTABLES) + "\n", encoding="utf-8")
        (package / "config" / "params.yaml").write_text(_PARAMS_YAML, encoding="utf-8")
    for plan in plans:
        path = root / plan.package / "launch" / plan.name
        path.write_text(_render(plans, plan, seed), encoding="utf-8")
        written.append(path)
    return written


UNIFORM_CHAIN = 5  # files of a package that include each other in a row
UNIFORM_BOOLS = ("use_sim", "use_lidar", "use_teleop")
UNIFORM_STRINGS = (("robot_name", "robot"), ("robot_ns", "base"))


def _uniform_launch(package: str, position: int, last: int, rng: random.Random) -> str:
    """One launch file of the uniform shape; ``last`` is the package's last position."""

    def condition() -> str:
        return f'{rng.choice(("if", "unless"))}="$(arg {rng.choice(UNIFORM_BOOLS)})"'

    out = _Writer()
    out.add(0, '<?xml version="1.0"?>')
    out.add(0, "<launch>")
    for name in UNIFORM_BOOLS:
        out.add(1, f'<arg name="{name}" default="{rng.choice(("true", "false"))}"/>')
    for name, value in UNIFORM_STRINGS:
        out.add(1, f'<arg name="{name}" default="{value}_{position}"/>')
    if position != last:  # the end of a run includes the package's last file
        target = last if position % UNIFORM_CHAIN == UNIFORM_CHAIN - 1 else position + 1
        out.add(
            1,
            f'<include file="$(find {package})/launch/uniform_{target:02d}.launch" {condition()}>',
        )
        out.add(2, f'<arg name="use_sim" value="$(arg {rng.choice(UNIFORM_BOOLS)})"/>')
        out.add(2, '<arg name="robot_name" value="$(arg robot_name)"/>')
        out.add(1, "</include>")
    for number in range(5):  # two nodes outside the group, three in it
        if number == 2:
            out.add(1, f'<group ns="$(arg robot_ns)" if="$(arg {rng.choice(UNIFORM_BOOLS)})">')
        depth = 1 if number < 2 else 2
        executable = rng.choice(EXECUTABLES)
        name = f"{executable}_{number}"
        if number % 2:
            name = f"$(arg robot_name)_{name}"
        out.add(depth, f'<node pkg="{package}" type="{executable}" name="{name}" {condition()}>')
        out.add(depth + 1, f'<param name="rate" value="{rng.randint(1, 100)}"/>')
        out.add(depth, "</node>")
    out.add(1, "</group>")
    out.add(0, "</launch>")
    return "\n".join(out.lines) + "\n"


def generate_uniform(root: Path, n_files: int, seed: int = 0) -> list[Path]:
    """Write ``n_files`` launch files of the uniform shape below ``root``; returns their paths."""
    written: list[Path] = []
    for number in range((n_files + FILES_PER_PACKAGE - 1) // FILES_PER_PACKAGE):
        package = root / _package_name(number)
        (package / "launch").mkdir(parents=True, exist_ok=True)
        (package / "package.xml").write_text(_package_xml(package.name), encoding="utf-8")
        (package / ".executables").write_text("\n".join(EXECUTABLES) + "\n", encoding="utf-8")
        count = min(FILES_PER_PACKAGE, n_files - number * FILES_PER_PACKAGE)
        for position in range(count):
            rng = random.Random(f"uniform:{seed}:{number}:{position}")
            path = package / "launch" / f"uniform_{position:02d}.launch"
            path.write_text(
                _uniform_launch(package.name, position, count - 1, rng), encoding="utf-8"
            )
            written.append(path)
    return written


ROS2_FILES = 120  # the size: the largest public ROS 2 launch trees
ROS2_ARGS_PER_FILE = 12.5  # 1,500 args in 120 files
ROS2_FILES_PER_PACKAGE = 10
ROS2_PACKAGES_PER_SYSTEM = 3
ROS2_MAX_LEVEL = 7  # include chains of up to 8 files
ROS2_SECOND_INCLUDE_RATE = 0.4  # a second, shallower include: trees, not only chains
ROS2_REQUIRED_RATE = 0.05
ROS2_BOOLS = (
    "use_sim_time", "use_rviz", "use_lidar", "use_camera", "use_imu", "use_gps",
    "use_teleop", "use_nav", "use_slam", "use_composition", "use_respawn", "use_diagnostics",
)  # fmt: skip
ROS2_STRINGS = (
    ("namespace", "robot"), ("robot_name", "rover"), ("base_frame", "base_link"),
    ("odom_frame", "odom"), ("map_frame", "map"), ("scan_topic", "scan"),
    ("cmd_vel_topic", "cmd_vel"), ("log_level", "info"), ("serial_port", "/dev/ttyUSB0"),
    ("world_frame", "world"),
)  # fmt: skip
ROS2_NUMBERS = (("rate", "10.0"), ("timeout", "0.5"), ("max_speed", "1.0"), ("queue", "10"))
ROS2_CHOICES = (
    ("mode", ("fast", "balanced", "accurate")),
    ("robot_model", ("a200", "j100", "w200")),
    ("lidar_model", ("vlp16", "ouster", "hokuyo")),
    ("controller", ("diff_drive", "ackermann")),
)
ROS2_STEMS = (
    "bringup", "robot", "drivers", "sensors", "lidar", "camera", "localization",
    "navigation", "control", "teleop",
)  # fmt: skip


@dataclass(frozen=True)
class _Ros2Arg:
    name: str
    default: str | None  # None: the includer (or the command line) must give it
    values: tuple[str, ...]  # what an includer may pass: ``choices``, booleans, others
    choices: bool = False


@dataclass(frozen=True)
class _Ros2Plan:
    index: int
    package: str
    name: str
    level: int
    args: tuple[_Ros2Arg, ...]

    @property
    def share_path(self) -> str:
        return f"$(find-pkg-share {self.package})/launch/{self.name}"


def _ros2_package(number: int) -> str:
    return f"ros2_pkg_{number:03d}"


def _ros2_args(rng: random.Random, count: int) -> tuple[_Ros2Arg, ...]:
    pool: list[_Ros2Arg] = [_Ros2Arg(name, rng.choice(("true", "false")), ("true", "false"))
                            for name in ROS2_BOOLS]  # fmt: skip
    pool += [_Ros2Arg(name, value, (f"{value}_a", f"{value}_b")) for name, value in ROS2_STRINGS]
    pool += [_Ros2Arg(name, value, ("1", "20")) for name, value in ROS2_NUMBERS]
    pool += [_Ros2Arg(name, values[0], values, True) for name, values in ROS2_CHOICES]
    chosen = rng.sample(pool, count)
    # namespace first when present: other defaults may refer to it
    chosen.sort(key=lambda arg: arg.name != "namespace")
    args = []
    for arg in chosen:
        default = arg.default
        if rng.random() < ROS2_REQUIRED_RATE:
            default = None
        elif arg.name == "map_frame" and chosen[0].name == "namespace":
            default = "$(var namespace)/map"  # a default built from another arg
        elif arg.name == "log_level":
            default = "$(env ROS_LOG_LEVEL info)"
        args.append(_Ros2Arg(arg.name, default, arg.values, arg.choices))
    return tuple(args)


def _ros2_plan(n_files: int, seed: int) -> list[_Ros2Plan]:
    total_args = round(n_files * ROS2_ARGS_PER_FILE)
    base, extra = divmod(total_args, n_files)
    plans = []
    for index in range(n_files):
        rng = random.Random(f"ros2-plan:{seed}:{index}")
        number, position = divmod(index, ROS2_FILES_PER_PACKAGE)
        name = f"{ROS2_STEMS[position % len(ROS2_STEMS)]}_{position:02d}.launch.xml"
        level = index % (ROS2_MAX_LEVEL + 1)
        args = _ros2_args(rng, base + (index < extra))
        plans.append(_Ros2Plan(index, _ros2_package(number), name, level, args))
    return plans


def _ros2_candidates(plans: list[_Ros2Plan], plan: _Ros2Plan) -> list[_Ros2Plan]:
    """The files ``plan`` may include: those of its package and of the previous one of its
    system (the system's last, for its first)."""
    number = plan.index // ROS2_FILES_PER_PACKAGE
    first = number - number % ROS2_PACKAGES_PER_SYSTEM
    packages_total = (len(plans) + ROS2_FILES_PER_PACKAGE - 1) // ROS2_FILES_PER_PACKAGE
    in_system = min(ROS2_PACKAGES_PER_SYSTEM, packages_total - first)
    previous = first + (number - first - 1) % in_system
    return [
        other
        for package in dict.fromkeys((number, previous))
        for other in plans[
            package * ROS2_FILES_PER_PACKAGE : (package + 1) * ROS2_FILES_PER_PACKAGE
        ]
    ]


def _ros2_includes(plans: list[_Ros2Plan], plan: _Ros2Plan, rng: random.Random) -> list[_Ros2Plan]:
    """One file a level down (so a level-L file roots an include tree L+1 deep), sometimes
    one more further down; from this package or the previous one of its system."""
    if plan.level == 0:
        return []
    candidates = _ros2_candidates(plans, plan)
    below = [other for other in candidates if other.level == plan.level - 1]
    chosen = [rng.choice(below)]
    further = [other for other in candidates if other.level < plan.level - 1]
    if further and rng.random() < ROS2_SECOND_INCLUDE_RATE:
        chosen.append(rng.choice(further))
    return chosen


def _ros2_condition(rng: random.Random, bools: list[_Ros2Arg], rate: float) -> str:
    if not bools or rng.random() >= rate:
        return ""
    return f' {rng.choice(("if", "if", "unless"))}="$(var {rng.choice(bools).name})"'


def _ros2_value(rng: random.Random, args: dict[str, _Ros2Arg], wanted: str, fallback: str) -> str:
    return f"$(var {wanted})" if wanted in args else fallback


def _ros2_node(out: _Writer, rng: random.Random, depth: int, plan: _Ros2Plan, number: int) -> None:
    args = {arg.name: arg for arg in plan.args}
    bools = [arg for arg in plan.args if arg.values == ("true", "false")]
    executable = rng.choice(EXECUTABLES)
    name = f"{executable}_{number}"
    if "robot_name" in args and rng.random() < 0.4:
        name = f"$(var robot_name)_{name}"
    condition = _ros2_condition(rng, bools, 0.4)
    out.add(depth, f'<node pkg="{plan.package}" exec="{executable}" name="{name}" '
                   f'output="screen"{condition}>')  # fmt: skip
    sim_time = _ros2_value(rng, args, "use_sim_time", "false")
    out.add(depth + 1, f'<param name="use_sim_time" value="{sim_time}"/>')
    frame = _ros2_value(rng, args, "base_frame", "base_link")
    out.add(depth + 1, f'<param name="frame_id" value="$(var frame_prefix){frame}"/>')
    rate = _ros2_value(rng, args, "rate", str(rng.randint(1, 50)))
    out.add(depth + 1, f'<param name="rate" value="{rate}"/>')
    if rng.random() < 0.5:
        out.add(depth + 1, f'<param from="$(find-pkg-share {plan.package})/config/params.yaml"/>')
    scan = _ros2_value(rng, args, "scan_topic", "scan")
    out.add(depth + 1, f'<remap from="scan" to="{scan}"/>')
    if rng.random() < 0.5:
        out.add(
            depth + 1,
            f'<remap from="cmd_vel" to="{_ros2_value(rng, args, "cmd_vel_topic", "cmd_vel")}"/>',
        )
    out.add(depth, "</node>")


def _ros2_include(
    out: _Writer, rng: random.Random, plan: _Ros2Plan, target: _Ros2Plan, flag: str = ""
) -> None:
    """``flag``: a computed boolean of the includer (the dense shape), which it passes to
    about half of the included file's boolean args."""
    bools = [arg for arg in plan.args if arg.values == ("true", "false")]
    own = {arg.name for arg in plan.args}
    out.add(1, f'<include file="{target.share_path}"{_ros2_condition(rng, bools, 0.35)}>')
    for arg in target.args:
        if arg.default is not None and rng.random() < 0.4 and not flag:
            continue  # the included file's default stays (the dense shape passes every arg)
        if flag and arg.values == ("true", "false") and rng.random() < 0.5:
            value = f"$(var {flag})"
        elif arg.name in own and rng.random() < 0.7:
            value = f"$(var {arg.name})"
        else:
            value = rng.choice(arg.values)
        out.add(2, f'<arg name="{arg.name}" value="{value}"/>')
    out.add(1, "</include>")


@dataclass(frozen=True)
class _Dense:
    """What the dense shape gives a file: its includes (chosen for the whole workspace, to
    reach its include count) and its ``$(eval)``s: 1 is a computed flag (a ``<let>``) passed
    to the included files, 2 also a group's condition."""

    includes: tuple[_Ros2Plan, ...]
    evals: int


FLAG = "active"  # the dense shape's computed <let>


def _ros2_eval(rng: random.Random, plan: _Ros2Plan, joint: str, flag: str = "") -> str:
    """A ``$(eval)`` of four of the file's args (a boolean one is true, ``joint`` each other
    one differs from or equals one of its values), and of ``flag`` (a ``<let>``) if given."""
    bools = [arg for arg in plan.args if arg.values == ("true", "false")] or list(plan.args)
    first = rng.choice(bools)
    second, third, fourth = rng.sample([arg for arg in plan.args if arg is not first], 3)
    tests = [f"'$(var {flag})' == 'True'"] if flag else []
    tests += [
        f"'$(var {first.name})' == 'true'",
        f"'$(var {second.name})' != '{second.values[0]}'",
        f"'$(var {third.name})' == '{third.values[-1]}'",
        f"'$(var {fourth.name})' != '{fourth.values[0]}'",
    ]
    return f"$(eval &quot;{f' {joint} '.join(tests)}&quot;)"  # one argument, as launch takes


def _ros2_launch(
    plans: list[_Ros2Plan], plan: _Ros2Plan, seed: int, dense: _Dense | None = None
) -> str:
    rng = random.Random(f"ros2-file:{seed}:{plan.index}")
    args = {arg.name: arg for arg in plan.args}
    bools = [arg for arg in plan.args if arg.values == ("true", "false")]
    out = _Writer()
    out.add(0, '<?xml version="1.0"?>')
    out.add(0, f"<!-- Synthetic ROS 2 launch file (bench/generate.py), level {plan.level}. -->")
    out.add(0, "<launch>")
    for arg in plan.args:
        default = "" if arg.default is None else f' default="{arg.default}"'
        described = f' description="{arg.name.replace("_", " ")}"'
        if arg.choices:
            out.add(1, f'<arg name="{arg.name}"{default}{described}>')
            for value in arg.values:
                out.add(2, f'<choice value="{value}"/>')
            out.add(1, "</arg>")
        else:
            out.add(1, f'<arg name="{arg.name}"{default}{described}/>')
    prefix = _ros2_value(rng, args, "robot_name", "robot")
    out.add(1, f'<let name="frame_prefix" value="{prefix}_"/>')
    flag = ""
    if dense is not None:
        flag = FLAG
        out.add(1, f'<let name="{FLAG}" value="{_ros2_eval(rng, plan, "and")}"/>')
    targets = _ros2_includes(plans, plan, rng) if dense is None else dense.includes
    for target in targets:
        out.add(0, "")
        _ros2_include(out, rng, plan, target, flag)
    number = 0
    for group in range(rng.randint(1, 2)):
        out.add(0, "")
        if dense is not None and dense.evals > 1 and group == 0:
            condition = f' if="{_ros2_eval(rng, plan, "or", FLAG)}"'
        else:
            condition = _ros2_condition(rng, bools, 0.5)
        out.add(1, f"<group{condition}>")
        namespace = _ros2_value(rng, args, "namespace", f"ns_{plan.index % 9}")
        out.add(2, f'<push-ros-namespace namespace="{namespace}"/>')
        if rng.random() < 0.3:
            out.add(2, f'<set_remap from="tf" to="/{namespace}/tf"/>')
        for _ in range(rng.randint(1, 2)):
            _ros2_node(out, rng, 2, plan, number)
            number += 1
        out.add(1, "</group>")
    if rng.random() < 0.5:
        out.add(0, "")
        _ros2_node(out, rng, 1, plan, number)
    out.add(0, "</launch>")
    return "\n".join(out.lines) + "\n"


def _ros2_package_xml(name: str, depends: list[str]) -> str:
    lines = [
        '<?xml version="1.0"?>',
        '<package format="3">',
        f"  <name>{name}</name>",
        "  <version>0.0.1</version>",
        f"  <description>Synthetic ROS 2 package {name} for rosvar benchmarks.</description>",
        '  <maintainer email="bench@example.com">bench</maintainer>',
        "  <license>Apache-2.0</license>",
        "  <buildtool_depend>ament_cmake</buildtool_depend>",
        "  <depend>rclcpp</depend>",
        *(f"  <exec_depend>{depend}</exec_depend>" for depend in depends),
        "  <export>",
        "    <build_type>ament_cmake</build_type>",
        "  </export>",
        "</package>",
    ]
    return "\n".join(lines) + "\n"


def _ros2_cmake(name: str) -> str:
    targets = " ".join(EXECUTABLES)
    lines = [
        "cmake_minimum_required(VERSION 3.8)",
        f"project({name})",
        "find_package(ament_cmake REQUIRED)",
        "find_package(rclcpp REQUIRED)",
        *(f"add_executable({exe} src/{exe}.cpp)" for exe in EXECUTABLES),
        f"install(TARGETS {targets} DESTINATION lib/${{PROJECT_NAME}})",
        "install(DIRECTORY launch config DESTINATION share/${PROJECT_NAME})",
        "ament_package()",
    ]
    return "\n".join(lines) + "\n"


_ROS2_PARAMS_YAML = """\
/**:
  ros__parameters:
    max_velocity: 1.0
    controller_frequency: 20.0
    sensors: [front_lidar, imu]
"""


def generate_ros2(root: Path, n_files: int = ROS2_FILES, seed: int = 0) -> list[Path]:
    """Write a colcon workspace's ``src`` of ``n_files`` ROS 2 XML launch files below
    ``root``; returns their paths."""
    plans = _ros2_plan(n_files, seed)
    texts = {plan.index: _ros2_launch(plans, plan, seed) for plan in plans}
    return _write_ros2(root, plans, texts)


ROS2_DENSE_INCLUDES_PER_FILE = 340 / 120  # issue 28's system: 340 includes in 120 files
ROS2_DENSE_EVALS_PER_FILE = 180 / 120  # and 180 $(eval)s


def _dense_includes(plans: list[_Ros2Plan], seed: int) -> dict[int, list[_Ros2Plan]]:
    """Each file above level 0 includes one file a level down, then, in turns (deepest files
    first), one more of its lower-level candidates until the workspace holds its count."""
    total = round(len(plans) * ROS2_DENSE_INCLUDES_PER_FILE)
    chosen: dict[int, list[_Ros2Plan]] = {}
    spare: dict[int, list[_Ros2Plan]] = {}
    deep = sorted((p for p in plans if p.level), key=lambda p: (-p.level, p.index))
    for plan in deep:
        rng = random.Random(f"ros2-dense:{seed}:{plan.index}")
        first = _ros2_includes(plans, plan, rng)[0]
        candidates = [
            other
            for other in _ros2_candidates(plans, plan)
            if other.level < plan.level and other is not first
        ]
        # taken from the end: the files a level down first, so include trees are bushy
        order = rng.sample(candidates, len(candidates))
        order.sort(key=lambda other: other.level)
        chosen[plan.index], spare[plan.index] = [first], order
    count = len(deep)
    while count < total and any(spare.values()):
        for plan in deep:
            if spare[plan.index] and count < total:
                chosen[plan.index].append(spare[plan.index].pop())
                count += 1
    return chosen


def generate_ros2_dense(root: Path, n_files: int = ROS2_FILES, seed: int = 0) -> list[Path]:
    """The ROS 2 workspace of issue 28's slow system: :func:`generate_ros2`'s files with
    denser include trees (340 includes in 120 files) and ``$(eval)``s (180) whose values
    flow into the included files' args."""
    plans = _ros2_plan(n_files, seed)
    includes = _dense_includes(plans, seed)
    evals = round(n_files * ROS2_DENSE_EVALS_PER_FILE) - n_files  # files with a second one
    texts = {
        plan.index: _ros2_launch(
            plans,
            plan,
            seed,
            _Dense(tuple(includes.get(plan.index, ())), 1 + (plan.index % 2 == 0 and evals > 0)),
        )
        for plan in plans
    }
    return _write_ros2(root, plans, texts)


def _write_ros2(root: Path, plans: list[_Ros2Plan], texts: dict[int, str]) -> list[Path]:
    n_files = len(plans)
    written: list[Path] = []
    for number in range((n_files + ROS2_FILES_PER_PACKAGE - 1) // ROS2_FILES_PER_PACKAGE):
        name = _ros2_package(number)
        package = root / name
        (package / "launch").mkdir(parents=True, exist_ok=True)
        (package / "config").mkdir(exist_ok=True)
        mine = plans[number * ROS2_FILES_PER_PACKAGE : (number + 1) * ROS2_FILES_PER_PACKAGE]
        depends = sorted(
            {p for plan in mine for p in re.findall(r"find-pkg-share (\w+)", texts[plan.index])}
            - {name}
        )
        (package / "package.xml").write_text(_ros2_package_xml(name, depends), encoding="utf-8")
        (package / "CMakeLists.txt").write_text(_ros2_cmake(name), encoding="utf-8")
        (package / "config" / "params.yaml").write_text(_ROS2_PARAMS_YAML, encoding="utf-8")
    for plan in plans:
        path = root / plan.package / "launch" / plan.name
        path.write_text(texts[plan.index], encoding="utf-8")
        written.append(path)
    return written


SHAPES = {
    "corpus": generate_workspace,
    "uniform": generate_uniform,
    "ros2": generate_ros2,
    "ros2-dense": generate_ros2_dense,
}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("root", type=Path)
    parser.add_argument("n_files", type=int)
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--shape", choices=sorted(SHAPES), default="corpus")
    options = parser.parse_args()
    paths = SHAPES[options.shape](options.root, options.n_files, options.seed)
    print(f"{len(paths)} launch files written below {options.root}")


if __name__ == "__main__":
    main()
