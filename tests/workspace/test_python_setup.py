"""setup.py and setup.cfg read without running them: entry points and scripts however the
strings are written."""

from __future__ import annotations

from rosvar.workspace.python_setup import console_scripts, setup_scripts

SETUP = """\
from setuptools import setup
package_name = 'demo_py'
setup(
    name=package_name,
    entry_points={
        'console_scripts': [
            'talker = ' 'demo_py.talker:main',
            'listener = \\
demo_py.listener:main',
            'relay = ' + package_name + '.relay:main',
            f'echo = {package_name}.echo:main',
            computed(),
        ],
        'other_group': ['not_a_script = demo_py.x:main'],
    },
)
"""


def test_console_scripts_however_the_strings_are_written() -> None:
    assert console_scripts(SETUP, "") == {
        "talker": "demo_py.talker",
        "listener": "demo_py.listener",
        "relay": "demo_py.relay",
        "echo": "demo_py.echo",
    }


def test_setup_cfg_and_a_python2_setup_py() -> None:
    cfg = "[options.entry_points]\nconsole_scripts =\n    node = pkg.node:main\n"
    assert console_scripts("", cfg) == {"node": "pkg.node"}
    python2 = "print 'x'\nsetup(entry_points={'console_scripts': ['a = pkg.a:main']})\n"
    assert console_scripts(python2, "") == {"a": "pkg.a"}


def test_scripts_of_setup_py() -> None:
    text = "SCRIPTS = ['scripts/a', 'scripts/' 'b']\nsetup(scripts=SCRIPTS)\nsetup(scripts=x)\n"
    assert setup_scripts(text) == ["scripts/a", "scripts/b"]
    assert setup_scripts("setup(") == []
