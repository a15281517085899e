"""The ``$ rosvar ...`` examples of README.md and docs/*.md show what rosvar prints today.

Each fenced block that starts with ``$ rosvar`` is run from the repository root (paths in it
relative to the root, the corpus at ``../shared/corpus``, ``ROS_PACKAGE_PATH`` empty) and its
output compared with the lines shown: a line ``...`` stands for any number of lines, and
``$ echo $?`` for the exit code. Commands with ``--json``, a pipe or ``-o`` show excerpts or
write files: they are only run. Commands on the Husky corpus are few and slow: run with the
corpus' other tests, skipped where it is absent.
"""

from __future__ import annotations

import re
import shlex
from dataclasses import dataclass, field
from pathlib import Path

import pytest

from rosvar.outputs.cli import main

REPO = Path(__file__).resolve().parents[2]
DOCUMENTS = [REPO / "README.md", *sorted((REPO / "docs").glob("*.md"))]
ELISION = "..."


@dataclass
class Example:
    """One ``$ rosvar`` command of a document, with the output and exit code it shows."""

    where: str
    words: list[str]
    piped: bool
    shown: list[str] = field(default_factory=list)
    code: int | None = None

    @property
    def compared(self) -> bool:
        return not self.piped and not ({"--json", "-o", "serve"} & set(self.words))


def examples() -> list[Example]:
    found: list[Example] = []
    for document in DOCUMENTS:
        blocks = re.findall(r"^```\n(.*?)^```", document.read_text(), re.MULTILINE | re.DOTALL)
        for block in blocks:
            if not block.startswith("$ rosvar "):
                continue
            lines = block.replace("\\\n", " ").splitlines()
            for line in lines:
                if line.startswith("$ echo $?"):
                    continue
                if line.startswith("$ "):
                    command = line[2:].split("#")[0]
                    where = f"{document.name}: {line[:70]}"
                    words = shlex.split(command.split("|")[0])[1:]
                    found.append(Example(where, words, "|" in command))
                elif found[-1].code is None and line.strip().isdigit() and _after_echo(lines, line):
                    found[-1].code = int(line)
                else:
                    found[-1].shown.append(line.rstrip())
    return found


def _after_echo(lines: list[str], line: str) -> bool:
    index = lines.index(line)
    return index > 0 and lines[index - 1].startswith("$ echo $?")


def matches(shown: list[str], actual: list[str]) -> bool:
    """``actual`` as ``shown``, where a ``...`` line stands for any lines."""
    if not shown:
        return not actual
    if shown[0].strip() == ELISION:
        return any(matches(shown[1:], actual[n:]) for n in range(len(actual) + 1))
    return bool(actual) and actual[0] == shown[0] and matches(shown[1:], actual[1:])


EXAMPLES = examples()


@pytest.mark.parametrize("example", EXAMPLES, ids=[e.where for e in EXAMPLES])
def test_the_documented_output_is_the_real_one(
    example: Example,
    capsys: pytest.CaptureFixture[str],
    monkeypatch: pytest.MonkeyPatch,
    tmp_path: Path,
) -> None:
    paths = [w for w in example.words if w.startswith("../shared/corpus")]
    if any(not (REPO / p).exists() for p in paths):
        pytest.skip("the corpus is not at ../shared/corpus")
    if any(w.startswith("/") for w in example.words):
        pytest.skip("a workspace of the reader's (an absolute path)")
    if "serve" in example.words:
        pytest.skip("serve runs until stopped (tests/outputs/web run it)")
    monkeypatch.setenv("ROS_PACKAGE_PATH", "")
    words = example.words
    if "-o" in words:  # the file it writes goes to a temporary folder
        monkeypatch.chdir(tmp_path)
        words = [str(REPO / w) if (REPO / w).exists() else w for w in words]
    else:
        monkeypatch.chdir(REPO)
    code = main(words)
    out, _err = capsys.readouterr()
    if example.code is not None:
        assert code == example.code
    else:
        assert code == 0
    if example.compared:
        actual = [line.rstrip() for line in out.splitlines()]
        shown = example.shown
        while shown and not shown[-1]:
            shown = shown[:-1]
        assert matches(shown, actual), "\n".join(actual)


def test_elision_matches_any_lines() -> None:
    assert matches(["a", "...", "d"], ["a", "b", "c", "d"])
    assert matches(["a", "...", "d"], ["a", "d"])
    assert not matches(["a", "...", "d"], ["a", "b"])
    assert not matches(["a"], ["a", "b"])
