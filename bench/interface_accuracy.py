"""Precision and recall of interface extraction on public repositories the tests do not cover.

``interface_truth.json`` lists, per executable (repository, branch, commit), the uses its
sources make, read by hand: ``[role, name]`` with the name as the node writes it,
``param:NAME`` for a name that is parameter NAME's value, ``*`` for a name only known at run
time (a symbolic entry of that role matches it). The repositories are exported from their
mirrors (the bare git directories the ``fetch`` tool leaves in ``/work/.mirror``; blobs a
mirror lacks are skipped), every package found is extracted as ``rosvar interfaces`` does,
and each executable's uses (parameters left out) are compared with the truth: a use is a
(role, name) pair; a symbolic one counts as ``*``. Prints per ROS version and language, per
set (``development``: read while extending the extractor; ``held-out``: measured once, after
it) and overall. Method and figures: docs/interfaces.md.

    PYTHONPATH=src python bench/interface_accuracy.py [--mirrors /work/.mirror]
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
from collections import defaultdict
from pathlib import Path
from typing import Any

from rosvar.workspace import discover
from rosvar.workspace.interfaces.extraction import extract_interfaces
from rosvar.workspace.interfaces.model import NodeInterface, Role

TRUTH = Path(__file__).with_name("interface_truth.json")
USES = [role for role in Role if role is not Role.PARAMS]
try:  # the lifecycle interface rcl adds, not counted on either side (docs/interfaces.md)
    from rosvar.workspace.interfaces.lifecycle import LIFECYCLE_USES

    NOT_COUNTED = {(str(role), name) for role, name, _type in LIFECYCLE_USES}
except ImportError:  # an older rosvar measured: it adds none
    NOT_COUNTED = set()


def export(mirror: str, commit: str, target: str) -> None:
    """The tree of ``commit`` into ``target``, each blob the mirror has."""
    listing = subprocess.run(
        ["git", "--git-dir", mirror, "ls-tree", "-r", "-z", commit],
        capture_output=True,
        check=True,
    ).stdout
    for item in listing.split(b"\0"):
        if not item:
            continue
        meta, path = item.split(b"\t", 1)
        mode, kind, sha = meta.split()
        if kind != b"blob" or mode == b"120000":
            continue
        blob = subprocess.run(
            ["git", "--git-dir", mirror, "cat-file", "blob", sha], capture_output=True
        )
        if blob.returncode != 0:
            continue  # large files a mirror leaves out
        file = os.path.join(target, path.decode())
        os.makedirs(os.path.dirname(file), exist_ok=True)
        with open(file, "wb") as handle:
            handle.write(blob.stdout)


def uses(node: NodeInterface) -> set[tuple[str, str]]:
    found = set()
    for entry in node.entries:
        if entry.role not in USES:
            continue
        named = getattr(entry, "named_by", None)  # an older rosvar measured: none
        if named is not None:
            name = "param:" + named.parameter
        elif not entry.static:
            name = "*"
        else:
            name = entry.name
        found.add((str(entry.role), name))
    return found - NOT_COUNTED


def main() -> int:
    options = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    options.add_argument("--mirrors", default="/work/.mirror")
    options.add_argument("--verbose", action="store_true", help="each executable's misses")
    arguments = options.parse_args()
    truth = json.loads(TRUTH.read_text())["executables"]
    counts: dict[tuple[str, ...], list[int]] = defaultdict(lambda: [0, 0, 0])
    by_checkout: dict[tuple[str, str], list[dict[str, Any]]] = defaultdict(list)
    for item in truth:
        by_checkout[(item["repository"], item["commit"])].append(item)
    for (repository, commit), items in sorted(by_checkout.items()):
        mirror = os.path.join(arguments.mirrors, repository.replace("/", "+"), "repo")
        with tempfile.TemporaryDirectory() as checkout:
            export(mirror, commit, checkout)
            packages = discover([checkout], ros_package_path="").packages.values()
            try:
                nodes = extract_interfaces(packages).nodes
            except Exception as error:  # an older rosvar measured may fail: nothing found
                print(f"{repository}: extraction failed: {error!r}", file=sys.stderr)
                nodes = []
        for item in items:
            found = next((n for n in nodes if n.executable == item["executable"]), None)
            extracted = uses(found) if found is not None else set()
            expected = {(role, name) for role, name in item["uses"]}
            hit = len(extracted & expected)
            row = [hit, len(extracted - expected), len(expected - extracted)]
            group = (f"ROS {item['ros']} {item['language']}",)
            keys: list[tuple[str, ...]] = [
                group,
                (item["set"],),
                ("overall",),
                (*group, item["set"]),
            ]
            for key in keys:
                for index in range(3):
                    counts[key][index] += row[index]
            if arguments.verbose and (row[1] or row[2]):
                print(f"{repository} {item['executable']}:", file=sys.stderr)
                print(f"  extra {sorted(extracted - expected)}", file=sys.stderr)
                print(f"  missed {sorted(expected - extracted)}", file=sys.stderr)
    print("| sources | uses | precision | recall |")
    print("|---|---|---|---|")
    for name in sorted(counts, key=lambda k: (len(k), k)):
        hit, extra, missed = counts[name]
        precision = hit / (hit + extra) if hit + extra else 1.0
        recall = hit / (hit + missed) if hit + missed else 1.0
        print(f"| {' '.join(name)} | {hit + missed} | {precision:.2f} | {recall:.2f} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
