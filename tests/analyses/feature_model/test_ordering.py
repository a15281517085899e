"""The solver's variable order: the widest cut it leaves, against counting by hand."""

from __future__ import annotations

import random

import dd.cudd

from rosvar.analyses.feature_model.features import ArgFeature, FileFeature, ValueFeature
from rosvar.analyses.feature_model.ordering import order, widest_cut
from rosvar.logic.inputs import ArgInput


def _files(count: int, values: int) -> list[FileFeature]:
    """``count`` files, each with one arg of ``values`` values (a block of variables)."""
    manager = dd.cudd.BDD()
    files = []
    for number in range(count):
        manager.declare(f"f{number}", *(f"f{number}v{v}" for v in range(values)))
        feature = FileFeature(f"f{number}", f"f{number}.launch", manager.var(f"f{number}"))
        arg = ArgFeature(
            f"f{number}:a", feature.file, "a", ArgInput(feature.file, "a"), None, False, None
        )
        arg.values = [
            ValueFeature(f"f{number}:a={v}", str(v), str(v), v == 0, manager.var(f"f{number}v{v}"))
            for v in range(values)
        ]
        feature.args.append(arg)
        files.append(feature)
    return files


def _crossing(order_of_files: list[str], links: list[tuple[str, str]]) -> int:
    """The most links with one file at or before a file of the order and one after it."""
    position = {f: i for i, f in enumerate(order_of_files)}
    return max(
        (
            sum(
                1
                for a, b in links
                if min(position[a], position[b]) <= i < max(position[a], position[b])
            )
            for i in range(len(order_of_files))
        ),
        default=0,
    )


def test_the_widest_cut_counts_the_links_crossing_each_point_of_the_order() -> None:
    rng = random.Random(17)
    for _trial in range(30):
        files = _files(rng.randint(1, 9), rng.randint(1, 3))
        ids = [f.id for f in files]
        links = [(rng.choice(ids), rng.choice(ids)) for _ in range(rng.randint(0, 20))]
        links = [(a, b) for a, b in links if a != b]
        variables = order(files, links)
        files_in_order = [v for v in variables if v in ids]
        assert widest_cut(variables, files, links) == _crossing(files_in_order, links)


def test_a_chain_ordered_along_itself_is_crossed_once() -> None:
    files = _files(6, 2)
    chain = [(f"f{n}", f"f{n + 1}") for n in range(5)]
    assert widest_cut(order(files, chain), files, chain) == 1
    clique = [(f"f{a}", f"f{b}") for a in range(6) for b in range(a + 1, 6)]
    assert widest_cut(order(files, clique), files, clique) == 9  # 3 × 3 across the middle


def _span(
    variables: list[str], files: list[FileFeature], constraints: list[tuple[str, ...]]
) -> int:
    """The summed distance between the first and last file of each constraint."""
    ids = {f.id for f in files}
    position = {f: i for i, f in enumerate(v for v in variables if v in ids)}
    return sum(max(position[f] for f in c) - min(position[f] for f in c) for c in constraints)


def test_a_name_declared_by_many_files_pulls_as_one_constraint_not_as_every_pair() -> None:
    """Seeded workspaces of requires (pairs) and clashing names (groups of 3–6 files):
    ordering by the groups themselves leaves a shorter total span than ordering by their
    pairs, which weigh a group of six as fifteen constraints."""
    rng = random.Random(3)
    by_groups = by_pairs = 0
    for _trial in range(100):
        files = _files(rng.randint(6, 14), 1)
        ids = [f.id for f in files]
        constraints = [tuple(rng.sample(ids, 2)) for _ in range(rng.randint(1, len(ids)))]
        constraints += [tuple(rng.sample(ids, rng.randint(3, 6))) for _ in range(rng.randint(1, 3))]
        pairs = [(a, b) for c in constraints for n, a in enumerate(c) for b in c[n + 1 :]]
        by_groups += _span(order(files, constraints), files, constraints)
        by_pairs += _span(order(files, pairs), files, constraints)
    assert by_groups < by_pairs * 0.95
