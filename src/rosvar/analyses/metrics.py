"""The paper's evaluation metrics (Tables I and II), computed from the feature model.

Launch files: LF (all), LV (never in a conflict), LC (at least one potential
conflict), LC_U (at least one unconditional conflict), LC_A (every conflict
depends on arg values). Command-line args: A (what a user can set, counted per
file as the corpus manifest describes), ACG (those that affect the computation
graph), AS (ACG args that need non-Boolean values), AS_D (AS with a default),
AS_V (AS with values inferred besides the default), IF (times ACG args decide an
``if``/``unless``, in a file and its inclusions), IF_M (the most for one arg).
"""

from __future__ import annotations

from collections import Counter
from dataclasses import dataclass

from rosvar.analyses.feature_model.features import ConstraintKind
from rosvar.analyses.feature_model.model import FeatureModel
from rosvar.frontends.entity import Entity
from rosvar.interpreter.workspace_models import Analysis
from rosvar.logic.atoms import SlotAtom
from rosvar.logic.inputs import OTHER, UNSET, ArgInput

TRUE_LITERALS = ("true", "1")
FALSE_LITERALS = ("false", "0")


@dataclass
class Metrics:
    LF: int
    LV: int
    LC: int
    LC_U: int
    LC_A: int
    A: int
    ACG: int
    AS: int
    AS_D: int
    AS_V: int
    IF: int
    IF_M: int


def command_line_args(root: Entity) -> set[str]:
    """Args a user can set on this file's command line (the paper's A, per file).

    Declarations without ``value=``, directly under ``<launch>`` or a ``<group>``,
    and not switched off by a literal ``if``/``unless``.
    """
    names: set[str] = set()
    pending = [root]  # a stack, not recursion: groups nest as deep as the parser allows
    while pending:
        for child in pending.pop().children:
            test_if, test_unless = child.get("if"), child.get("unless")
            if test_if is not None and test_if.strip().lower() not in TRUE_LITERALS:
                continue
            if test_unless is not None and test_unless.strip().lower() not in FALSE_LITERALS:
                continue
            if child.tag == "arg" and child.get("value") is None and child.get("name"):
                names.add(child.get("name") or "")
            elif child.tag == "group":
                pending.append(child)
    return names


def compute(analysis: Analysis, model: FeatureModel) -> Metrics:
    files = [f.file for f in model.files]
    in_conflict: dict[str, list[bool]] = {}
    for constraint in model.constraints:
        if constraint.kind != ConstraintKind.EXCLUDES:
            continue
        for file_id in constraint.files:
            in_conflict.setdefault(file_id, []).append(constraint.unconditional)
    lc = len(in_conflict)
    lc_u = sum(1 for flags in in_conflict.values() if any(flags))
    a = acg = as_ = as_d = as_v = 0
    decided: Counter[ArgInput] = Counter()
    for feature in model.files:
        root = analysis.files.load(feature.file).root  # the dialect's frontend for the file
        settable = command_line_args(root) if root is not None else set()
        a += len(settable)
        features = {arg.name: arg for arg in feature.args if arg.name in settable}
        acg += len(features)
        for arg in features.values():
            if arg.boolean:
                continue
            as_ += 1
            if arg.default is not None:
                as_d += 1
            literals = {v.value for v in arg.values if v.slot is not OTHER and v.slot is not UNSET}
            if literals - {arg.default}:
                as_v += 1
        launch_model = analysis.model(feature.file)
        wanted = {arg.input for arg in features.values()}
        for decision in launch_model.decisions:
            inputs = {
                atom.input
                for atom in (model.space.atom_of(n) for n in model.space.support(decision.outcome))
                if isinstance(atom, SlotAtom) and isinstance(atom.input, ArgInput)
            }
            for input_ in inputs & wanted:
                decided[input_] += 1
    return Metrics(
        LF=len(files),
        LV=len(files) - lc,
        LC=lc,
        LC_U=lc_u,
        LC_A=lc - lc_u,
        A=a,
        ACG=acg,
        AS=as_,
        AS_D=as_d,
        AS_V=as_v,
        IF=sum(decided.values()),
        IF_M=max(decided.values(), default=0),
    )
