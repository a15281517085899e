"""Helpers of the feature model's tests: an include line, and a count by enumeration."""

from __future__ import annotations

import itertools

from rosvar.analyses.feature_model.model import FeatureModel

INCLUDE = '  <include file="$(find pkg)/launch/{target}"{attrs}/>\n'


def brute_force_count(model: FeatureModel) -> int:
    """Valid configurations by enumeration: the tree checked by hand, constraints via ``let``."""
    solver = model.solver
    names = solver.variables
    assert len(names) <= 16, "too many variables to enumerate"
    manager = solver.manager
    files = [
        (str(f.variable.var), [[str(v.variable.var) for v in arg.values] for arg in f.args])
        for f in model.files
    ]
    assert sorted(n for f, args in files for n in [f, *itertools.chain(*args)]) == sorted(names)
    total = 0
    for bits in itertools.product((False, True), repeat=len(names)):
        values = dict(zip(names, bits, strict=True))
        tree_ok = all(
            all(sum(values[v] for v in group) == (1 if values[file] else 0) for group in args)
            for file, args in files
        )
        if not tree_ok:
            continue
        if all(manager.let(values, c) == manager.true for c in solver.constraints):
            total += 1
    return total
