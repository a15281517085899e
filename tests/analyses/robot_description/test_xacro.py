"""Variational xacro against the real xacro: each fixture is expanded once, and its
restriction to each sampled configuration must be what xacro prints (or fail where it does).
"""

from __future__ import annotations

from pathlib import Path

import pytest

from analyses.robot_description.harness import Config, differences, expand, one_at_a_time, pairs

PACKAGE_XML = """<?xml version="1.0"?>
<package format="2"><name>{name}</name><version>0.0.0</version><description>t</description>
<maintainer email="t@example.com">t</maintainer><license>BSD</license></package>
"""
HEAD = '<?xml version="1.0"?>\n<robot name="r" xmlns:xacro="http://ros.org/wiki/xacro">\n'


def _workspace(root: Path, files: dict[str, str]) -> Path:
    for package in {name.split("/")[0] for name in files}:
        (root / package).mkdir(parents=True, exist_ok=True)
        (root / package / "package.xml").write_text(PACKAGE_XML.format(name=package))
    for name, text in files.items():
        path = root / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
    return root


FIXTURES: dict[str, tuple[dict[str, str], dict[str, list[str]], dict[str, list[str]]]] = {
    # name: (files, the first the entry; args and their values; variables and their values)
    "args and conditions": (
        {
            "pkg/robot.xacro": HEAD
            + """
  <xacro:arg name="laser" default="$(optenv LASER 0)"/>
  <xacro:arg name="ns" default="/"/>
  <xacro:arg name="prefix" default=""/>
  <link name="$(arg prefix)base"/>
  <xacro:if value="$(arg laser)"><link name="laser"/></xacro:if>
  <xacro:unless value="$(arg laser)"><link name="no_laser"/></xacro:unless>
  <gazebo><plugin name="p" filename="libgazebo_ros_imu.so">
    <robotNamespace>$(arg ns)</robotNamespace><topicName>$(arg prefix)imu</topicName>
  </plugin></gazebo>
</robot>
""",
        },
        {"laser": ["true", "false", "1", "maybe"], "ns": ["/r1"], "prefix": ["a_"]},
        {"LASER": ["1", "0", "True", "x"]},
    ),
    "properties": (
        {
            "pkg/robot.xacro": HEAD
            + """
  <xacro:arg name="size" default="1"/>
  <xacro:property name="w" value="0.5"/>
  <xacro:property name="h" value="${w * 2}"/>
  <xacro:property name="late" value="${later + 1}"/>
  <xacro:property name="later" value="$(arg size)"/>
  <xacro:property name="quoted" value="'0.50'"/>
  <xacro:property name="under" value="1_0"/>
  <xacro:property name="word" value="True"/>
  <link name="a" w="${w}" h="${h}" late="${late}" q="${quoted}" u="${under}" b="${word}"/>
  <xacro:property name="greedy" value="${w}" lazy_eval="false"/>
  <xacro:property name="w" value="9"/>
  <link name="b" g="${greedy}" w="${w}" d="${w/2}" p="${pi/2}" m="${math.floor(2.5)}"
        r="${radians(180)}" l="${python.len('abc')}" s="${'%s_%d' % ('x', 3)}"/>
  <xacro:property name="w" default="100"/>
  <xacro:property name="fresh" default="${w + 1}"/>
  <link name="c" w="${w}" f="${fresh}" t="${size if size > 2 else -size}"/>
  <xacro:property name="fresh" remove="true"/>
  <xacro:property name="fresh" default="7"/>
  <link name="d" f="${fresh}" e="$${escaped}" n="${'$(arg size)' + 'x'}"/>
  <xacro:if value="${later > 2}"><link name="big"/></xacro:if>
</robot>
""",
        },
        {"size": ["3", "1.5", "-2", "abc"]},
        {},
    ),
    "macros and blocks": (
        {
            "pkg/robot.xacro": HEAD
            + """
  <xacro:arg name="count" default="2"/>
  <xacro:property name="rate" value="10"/>
  <xacro:macro name="wheel" params="side radius:=0.1 rate:=^ mass:=^|3 *origin **extra">
    <link name="${side}_wheel" r="${radius}" rate="${rate}" mass="${mass}">
      <xacro:insert_block name="extra"/>
    </link>
    <joint name="${side}_joint"><xacro:insert_block name="origin"/></joint>
  </xacro:macro>
  <xacro:wheel side="left">
    <origin xyz="0 1 0"/>
    <extra><material name="black"/><collision/></extra>
  </xacro:wheel>
  <xacro:wheel side="right" radius="${rate / 4}" mass="$(arg count)">
    <xacro:if value="${$(arg count) > 1}"><origin xyz="0 -1 0"/></xacro:if>
    <xacro:unless value="${$(arg count) > 1}"><origin xyz="0 -2 0"/></xacro:unless>
    <extra/>
  </xacro:wheel>
  <xacro:macro name="tower" params="n">
    <link name="level_${n}"/>
    <xacro:if value="${n > 0}"><xacro:tower n="${n - 1}"/></xacro:if>
  </xacro:macro>
  <xacro:tower n="$(arg count)"/>
  <xacro:property name="shape"><box size="1 1 1"/><sphere radius="${rate}"/></xacro:property>
  <visual><xacro:insert_block name="shape"/></visual>
  <xacro:call macro="wheel" side="called"><origin/><extra/></xacro:call>
  <xacro:macro name="scoped" params="v">
    <xacro:property name="inner" value="${v * 2}" scope="parent"/>
    <xacro:property name="top" value="${v * 3}" scope="global"/>
  </xacro:macro>
  <xacro:scoped v="2"/>
  <link name="scopes" inner="${inner}" top="${top}"/>
</robot>
""",
        },
        {"count": ["0", "3", "1"]},
        {},
    ),
    "includes, elements and attributes": (
        {
            "pkg/robot.xacro": HEAD
            + """
  <xacro:arg name="part" default="a"/>
  <xacro:arg name="tag" default="link"/>
  <xacro:include filename="parts/$(arg part).xacro"/>
  <xacro:include filename="$(find other)/urdf/other.xacro" ns="other"/>
  <xacro:other.thing name="via_ns"/>
  <xacro:part_macro/>
  <xacro:element xacro:name="$(arg tag)" name="dynamic">
    <xacro:attribute name="extra" value="${1 + 1}"/>
  </xacro:element>
  <xacro:include filename="parts/missing.xacro" optional="true"/>
  <xacro:include filename="parts/glob_*.xacro"/>
</robot>
""",
            "pkg/parts/a.xacro": """<robot xmlns:xacro="http://ros.org/wiki/xacro">
  <xacro:macro name="part_macro"><link name="part_a"/></xacro:macro>
</robot>""",
            "pkg/parts/b.xacro": """<robot xmlns:xacro="http://ros.org/wiki/xacro">
  <xacro:macro name="part_macro"><link name="part_b"/><link name="part_b2"/></xacro:macro>
</robot>""",
            "pkg/parts/glob_1.xacro": """<robot><link name="glob_1"/></robot>""",
            "pkg/parts/glob_2.xacro": """<robot><link name="glob_2"/></robot>""",
            "other/urdf/other.xacro": """<robot xmlns:xacro="http://ros.org/wiki/xacro">
  <xacro:macro name="thing" params="name"><link name="${name}_other"/></xacro:macro>
</robot>""",
        },
        {"part": ["b", "c"], "tag": ["joint", ""]},
        {},
    ),
    "substitution args": (
        {
            "pkg/robot.xacro": HEAD
            + """
  <xacro:arg name="x" default="$(env HOME_X)"/>
  <link name="$(arg x)" opt="$(optenv OPT fallback value)" find="$(find pkg)/meshes"
        ev="$(eval 1 + 2)" both="$(arg x)-$(optenv OPT)"/>
  <xacro:property name="from_arg" value="$(arg x)"/>
  <link name="p" v="${from_arg}" twice="${from_arg * 2}"/>
</robot>
""",
        },
        {"x": ["given", "4"]},
        {"HOME_X": ["h", "12"], "OPT": ["o"]},
    ),
    "failures": (
        {
            "pkg/robot.xacro": HEAD
            + """
  <xacro:arg name="mode" default="ok"/>
  <xacro:property name="zero" value="0"/>
  <xacro:if value="${'$(arg mode)' == 'divide'}"><link v="${1 / zero}"/></xacro:if>
  <xacro:if value="${'$(arg mode)' == 'undefined'}"><link v="${nothing}"/></xacro:if>
  <xacro:if value="${'$(arg mode)' == 'macro'}"><xacro:no_such_macro/></xacro:if>
  <xacro:if value="${'$(arg mode)' == 'arg'}"><link v="$(arg no_such_arg)"/></xacro:if>
  <xacro:if value="${'$(arg mode)' == 'include'}"><xacro:include filename="none.xacro"/></xacro:if>
  <link name="kept"/>
</robot>
""",
        },
        {"mode": ["divide", "undefined", "macro", "arg", "include"]},
        {},
    ),
}


@pytest.mark.parametrize("fixture", sorted(FIXTURES))
def test_fixture_agrees_with_xacro(tmp_path: Path, fixture: str) -> None:
    files, args, env = FIXTURES[fixture]
    root = _workspace(tmp_path / "ws", files)
    entry = str(root / next(iter(files)))
    configurations = pairs(args, env)
    for mode in ("known values", "other values"):
        expanded = expand([root], entry, args, env if mode == "known values" else {})
        unknown: list[Config] = []
        assert differences(expanded, configurations, unknown) == [], mode
        assert unknown == [] or fixture == "includes, elements and attributes", unknown
    assert expanded.description.root is not None  # the test can fail: something was expanded


CORPUS = Path(__file__).resolve().parents[4] / "shared" / "corpus"  # ../shared of the checkout
MAX_CONFIGURATIONS = 40


def _corpus_files() -> list[str]:
    if not CORPUS.is_dir():
        return []
    return sorted(str(p) for p in CORPUS.rglob("*.xacro"))


@pytest.mark.skipif(not CORPUS.is_dir(), reason="corpus not available")
@pytest.mark.parametrize("system", ["husky", "kobuki", "turtlebot2", "lizi", "_external"])
def test_corpus_files_agree_with_xacro(system: str) -> None:
    """Every xacro file of the corpus as an entry, in sampled configurations."""
    from analyses.robot_description.harness import read_inputs

    roots = [CORPUS / name for name in ("husky", "kobuki", "turtlebot2", "lizi", "_external")]
    compared = 0
    for file in _corpus_files():
        if not file.startswith(str(CORPUS / system) + "/"):
            continue
        expanded = expand(roots, file, {}, {})
        args, env = read_inputs([file, *expanded.description.files[1:]])
        values = {name: ["true"] for name in args}
        variables = {name: ["1", "0"] for name in env}
        configurations = one_at_a_time(values, variables)
        stride = max(1, len(configurations) // MAX_CONFIGURATIONS)
        configurations = configurations[::stride]  # the defaults first, then spread out
        # a package outside the corpus (ur_description...): unknown where xacro fails
        elsewhere = any(d.code == "package-unknown" for d in expanded.description.diagnostics)
        for mode in ("known values", "other values"):
            expanded = expand(roots, file, values, variables if mode == "known values" else {})
            unknown: list[Config] = []
            assert differences(expanded, configurations, unknown) == [], (file, mode)
            assert elsewhere or len(unknown) * 10 <= len(configurations), (file, unknown)
            compared += len(configurations) - len(unknown)
    assert compared > 0
