"""The solver's variable order: linked files close together, components apart.

A constraint between files is cheap for a BDD only if their variables are close in the
order: every constraint pending across a level can double the diagram's width there.
"""

from __future__ import annotations

from collections import deque
from collections.abc import Iterable, Mapping, Sequence

from rosvar.analyses.feature_model.features import FileFeature

FORCE_ROUNDS = 100
FORCE_PATIENCE = 10  # rounds without a shorter span before FORCE stops


def order(features: Sequence[FileFeature], constraints: Iterable[Sequence[str]]) -> list[str]:
    """Feature variables in file blocks: linked files close together, components apart.

    ``constraints``: the files (feature ids) each cross-tree constraint mentions — two for a
    requires, every file declaring a clashing name for its at-most-one. Cuthill–McKee (a
    breadth-first search from a file with few links) finds the components and a first
    order of each; FORCE then refines it (``_force``). The components go smallest first,
    so that conjoining them never passes below the largest diagram (a conjunction walks
    every part of one operand lying above the other's variables).
    """
    edges = [tuple(dict.fromkeys(files)) for files in constraints]
    edges = [files for files in dict.fromkeys(edges) if len(files) > 1]
    neighbours: dict[str, set[str]] = {f.id: set() for f in features}
    touching: dict[str, list[tuple[str, ...]]] = {f.id: [] for f in features}
    for files in edges:
        for file in files:
            neighbours[file].update(files)
            touching[file].append(files)
    for file, linked in neighbours.items():
        linked.discard(file)
    by_id = {f.id: f for f in features}
    visited: set[str] = set()
    components: list[list[str]] = []
    for start in sorted(by_id, key=lambda f: (len(neighbours[f]), f)):
        if start in visited:
            continue
        visited.add(start)
        component: list[str] = []
        queue = deque([start])
        while queue:
            current = queue.popleft()
            component.append(current)
            for nxt in sorted(neighbours[current] - visited, key=lambda f: (len(neighbours[f]), f)):
                visited.add(nxt)
                queue.append(nxt)
        components.append(_force(component, touching))
    blocks = [[name for i in files for name in by_id[i].variable_names()] for files in components]
    blocks.sort(key=len)
    return [name for block in blocks for name in block]


def _force(files: list[str], touching: Mapping[str, list[tuple[str, ...]]]) -> list[str]:
    """FORCE (Aloul, Markov and Sakallah, 2003) on one component's files.

    Each round puts every constraint at the centre of its files, moves every file to the
    mean of its constraints' centres and ranks the files by that; the order with the
    shortest total span (the summed distance between the first and last file of each
    constraint) is kept, and the search stops once spans stop shrinking. Linear in the
    constraints' sizes per round. A clashing name is one constraint over all the files
    declaring it, not a pull between each pair of them: taken pairwise, a name declared by
    ten files weighed as 45 links and dragged its files together at the cost of every
    other constraint (docs/performance.md, "Feature model", variable order).
    """
    edges = list(dict.fromkeys(edge for f in files for edge in touching[f]))
    if not edges:
        return files
    position = {f: i for i, f in enumerate(files)}

    def span() -> int:
        total = 0
        for edge in edges:
            places = [position[f] for f in edge]
            total += max(places) - min(places)
        return total

    best, shortest, stale = files, span(), 0
    for _round in range(FORCE_ROUNDS):
        if stale == FORCE_PATIENCE:
            break
        pull = dict.fromkeys(files, 0.0)
        for edge in edges:
            centre = sum(position[f] for f in edge) / len(edge)
            for file in edge:
                pull[file] += centre
        files = sorted(files, key=lambda f: (pull[f] / len(touching[f]), position[f]))
        position = {f: i for i, f in enumerate(files)}
        length = span()
        best, shortest, stale = (
            (files, length, 0) if length < shortest else (best, shortest, stale + 1)
        )
    return best


def widest_cut(
    order: Sequence[str], features: Sequence[FileFeature], links: Iterable[Sequence[str]]
) -> int:
    """The most links (pairs of feature ids) crossing one point of ``order`` (variable names,
    a file's variable first in its block): the width a diagram in that order may need
    there is exponential in it, each pending constraint doubling it at worst."""
    level = {name: position for position, name in enumerate(order)}
    start = {f.id: level[f.variable_names()[0]] for f in features}
    change = [0] * (len(order) + 1)
    for a, b in links:
        first, last = sorted((start[a], start[b]))
        change[first] += 1
        change[last] -= 1
    widest = crossing = 0
    for delta in change:
        crossing += delta
        widest = max(widest, crossing)
    return widest
