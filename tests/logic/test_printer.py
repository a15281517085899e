"""Presence conditions in readable form (``logic/printer.py``).

The readable form is checked two ways: a few exact strings people will read (``use_teleop ∧
¬sim``, ``model∈{a, b}``, ``x≠a``), and a round trip over randomly generated conditions: the
description is parsed back into a BDD and must mean the same as the condition (modulo the
valid configurations, and with ``known_only`` modulo the ``<other>`` slots of args).
"""

from __future__ import annotations

import itertools
import random
import re
from collections.abc import Iterable, Sequence
from pathlib import Path
from unittest.mock import patch

import pytest

from logic.spaces import (
    DOMAINS,
    HOME,
    MODEL,
    SIM,
    TELEOP,
    WORLD,
    F,
    make_space,
    random_condition,
)
from rosvar.interpreter.model import LaunchModel
from rosvar.interpreter.workspace_models import Analysis
from rosvar.logic.atoms import PREDICATES, FileAtom, PredicateAtom
from rosvar.logic.bdd import BDD
from rosvar.logic.conditions import ConditionSpace
from rosvar.logic.inputs import OTHER, UNSET, ArgInput, EnvInput, Input
from rosvar.logic.printer import Printer
from rosvar.logic.terms import Hole
from rosvar.outputs.describe import describe_model
from rosvar.workspace import discover


# -- readable descriptions ----------------------------------------------------------------------
def test_describe_booleans_as_literals() -> None:
    space = make_space()
    teleop, no_sim = space.slot(TELEOP, "true"), space.slot(SIM, "false")
    # conjuncts are ordered by input name
    assert space.describe(teleop & no_sim) == "¬sim ∧ use_teleop"
    assert space.describe(teleop) == "use_teleop"
    assert space.describe(space.slot(TELEOP, "false")) == "¬use_teleop"
    assert space.describe(teleop | space.slot(SIM, "true")) == "sim ∨ use_teleop"
    assert space.describe(teleop & ~space.slot(TELEOP, "false")) == "use_teleop"


def test_an_empty_value_is_shown_quoted() -> None:
    gripper = ArgInput("/w/a.launch.xml", "gripper")
    space = make_space({gripper: ("", "g", "h", OTHER)})
    assert space.describe(~space.slot(gripper, "")) == "gripper≠''"
    assert space.describe(space.slot(gripper, "")) == "gripper=''"


def test_describe_sets_and_exclusions() -> None:
    space = make_space()
    a, b = space.slot(MODEL, "a"), space.slot(MODEL, "b")
    assert space.describe(a | b) == "model∈{a, b}"
    assert space.describe(~a) == "model≠a"
    assert space.describe(space.slot(MODEL, UNSET)) == "model=<unset>"
    assert space.describe(space.slot(HOME, "/home/r")) == "$ROBOT_HOME=/home/r"
    assert space.describe(a, qualify=True) == f"{F}:model=a"


def test_describe_true_false_and_other_values() -> None:
    space = make_space()
    a = space.slot(MODEL, "a")
    assert space.describe(space.true) == "true"
    assert space.describe(space.false) == "false"
    assert space.describe(a & space.slot(MODEL, "b")) == "false"  # invalid, not just empty
    whole = space.false
    for slot in DOMAINS[SIM]:
        whole |= space.slot(SIM, slot)
    assert space.describe(whole) == "true"
    only_other = space.slot(WORLD, OTHER)
    assert space.describe(only_other) == "only for other values"
    assert space.describe(only_other, known_only=False) == "world=<other>"
    # known_only hides <other>: "not empty" is "other" among the known values
    assert space.describe(~space.slot(WORLD, "empty")) == "only for other values"


def test_an_environment_variable_given_any_value_reads_as_set() -> None:
    """``$X=<other>`` would say "some other value" where no value is listed: it is any."""
    free = EnvInput("TURTLEBOT3_MODEL")
    space = make_space({**DOMAINS, free: (UNSET, OTHER)})
    assert space.describe(space.slot(free, OTHER)) == "$TURTLEBOT3_MODEL set"
    assert space.describe(space.slot(free, UNSET)) == "$TURTLEBOT3_MODEL=<unset>"
    assert space.describe(~space.slot(HOME, UNSET)) == "$ROBOT_HOME set"
    assert space.describe(space.slot(HOME, OTHER)) == "$ROBOT_HOME=<other>"  # not /home/r
    teleop = space.slot(TELEOP, "true")
    assert space.describe(teleop & space.slot(free, OTHER)) == "$TURTLEBOT3_MODEL set ∧ use_teleop"


def test_describe_predicates() -> None:
    space = make_space()
    p = space.predicate("test_nonempty", Hole(MODEL))
    assert space.describe(p) == "⟨model⟩ is set"
    assert space.describe(~p) == "¬(⟨model⟩ is set)"


def test_describe_disjunction_parenthesises_conjunctions() -> None:
    space = make_space()
    condition = (space.slot(TELEOP, "true") & space.slot(SIM, "true")) | space.slot(MODEL, "c")
    text = space.describe(condition)
    assert sorted(text.split(" ∨ ")) == ["(sim ∧ use_teleop)", "model=c"]


# -- round trip: parse a description back ------------------------------------------------------
_PART = re.compile(r"^(?P<neg>¬?)(?P<name>[$\w]+)(?:(?P<op>=|≠|∈| set$)(?P<rest>.*))?$")


def _slot_named(space: ConditionSpace, input_: Input, text: str) -> BDD:
    for slot in space.domain(input_):
        if (slot if isinstance(slot, str) else repr(slot)) == ("" if text == "''" else text):
            return space.slot(input_, slot)
    raise AssertionError(f"{text!r} is no slot of {input_}")


def parse(space: ConditionSpace, text: str) -> BDD:
    """The BDD of a description (slots only), in the grammar ``describe`` produces."""
    if text == "true":
        return space.true
    if text == "false":
        return space.false
    by_name = {str(i): i for i in space.inputs()}
    result = space.false
    for cube_text in text.split(" ∨ "):
        if cube_text.startswith("("):
            assert cube_text.endswith(")"), text
            cube_text = cube_text[1:-1]
        cube = space.true
        for part in cube_text.split(" ∧ "):
            match = _PART.match(part)
            assert match is not None, (part, text)
            input_ = by_name[match["name"]]
            op, rest = match["op"], match["rest"]
            if op is None:
                word = "false" if match["neg"] else "true"
                cube &= _slot_named(space, input_, word)
            elif op == " set":
                cube &= ~space.slot(input_, UNSET)
            elif op == "=":
                cube &= _slot_named(space, input_, rest)
            elif op == "≠":
                cube &= ~_slot_named(space, input_, rest)
            else:
                assert rest.startswith("{") and rest.endswith("}"), part
                union = space.false
                for item in rest[1:-1].split(", "):
                    union |= _slot_named(space, input_, item)
                cube &= union
        result |= cube
    return result


def _known(space: ConditionSpace) -> BDD:
    """Valid configurations in which every arg holds a known value."""
    care = space.valid
    for input_ in space.inputs():
        if isinstance(input_, ArgInput):
            care &= ~space.slot(input_, OTHER)
    return care


def _round_trip_failures(seeds: range, sound_only: bool) -> list[str]:
    """Descriptions of random conditions that do not mean their condition.

    With ``sound_only`` only the configurations a description claims but its condition lacks
    count; otherwise also those the description leaves out.
    """
    failures = []
    for seed in seeds:
        space = make_space()
        care = _known(space)
        rng = random.Random(seed)
        for _ in range(60):
            condition = random_condition(space, rng)
            for known_only, within in ((True, care), (False, space.valid)):
                text = space.describe(condition, known_only=known_only)
                if text == "false":
                    ok = not space.satisfiable(condition)
                elif text == "only for other values":
                    ok = (condition & care) == space.false and space.satisfiable(condition)
                else:
                    described = parse(space, text) & within
                    meant = condition & within
                    extra = described & ~meant
                    ok = extra == space.false and (sound_only or described == meant)
                if not ok:
                    failures.append(f"seed {seed} known_only={known_only}: {text}")
    return failures


def test_describe_claims_nothing_its_condition_lacks() -> None:
    assert _round_trip_failures(range(12), sound_only=True) == []


def test_describe_round_trip_over_random_conditions() -> None:
    assert _round_trip_failures(range(12), sound_only=False) == []


def _condition_over(space: ConditionSpace, inputs: Sequence[Input], rng: random.Random) -> BDD:
    """A random condition over ``inputs`` (stand-ins for those of ``DOMAINS``, in order)."""
    result = space.false
    for _ in range(rng.randint(1, 3)):
        cube = space.true
        for place in rng.sample(range(len(inputs)), rng.randint(1, 3)):
            domain = space.domain(inputs[place])
            union = space.false
            for slot in rng.sample(domain, rng.randint(1, len(domain) - 1)):
                union |= space.slot(inputs[place], slot)
            cube &= union if rng.random() < 0.8 else ~union
        result |= cube
    return result


def test_conditions_of_one_shape_read_as_each_alone() -> None:
    """Conditions over another file's inputs of the same names and domains are described
    once for both (the printer's shapes); over a domain in another order, or another
    name, they are not: each reads as it does described by a printer of its own."""
    other, third = "/ws/pkg/launch/other.launch", "/ws/pkg/launch/third.launch"
    copies = [list(DOMAINS)]
    copies.append([ArgInput(other, i.name) if isinstance(i, ArgInput) else i for i in DOMAINS])
    renamed: dict[Input, Input] = {MODEL: ArgInput(third, "robot"), SIM: ArgInput(third, "sim")}
    copies.append([renamed.get(i, i) for i in DOMAINS])
    domains = dict(DOMAINS)
    for inputs in copies[1:]:
        for original, input_ in zip(DOMAINS, inputs, strict=True):
            domains.setdefault(input_, DOMAINS[original])
    domains[ArgInput(third, "sim")] = ("true", "false", OTHER)  # another order
    space = make_space(domains)
    shared = 0
    for seed in range(40):
        texts = []
        for inputs in copies:
            condition = _condition_over(space, inputs, random.Random(seed))
            for known_only in (True, False):
                text = space.describe(condition, known_only=known_only)
                alone = Printer(space).describe(condition, known_only=known_only)
                assert text == alone, f"seed {seed}: {text!r} != {alone!r}"
                texts.append(text)
        shared += texts[0] == texts[2] and texts[1] == texts[3]
    # the copy of the same names reads the same, but where the shared $ROBOT_HOME, declared
    # between the copies, sits elsewhere in the variable order than in the first copy
    assert shared >= 30


def test_describe_keeps_every_needed_cube() -> None:
    x, y, z = ArgInput(F, "x"), ArgInput(F, "y"), ArgInput(F, "z")
    space = make_space({x: ("a", "b", "c"), y: ("a", "b", "c"), z: ("a", "b")})

    def any_of(input_: Input, *slots: str) -> BDD:
        result = space.false
        for slot in slots:
            result |= space.slot(input_, slot)
        return result

    condition = (
        (any_of(x, "a") & any_of(y, "a", "c"))
        | (any_of(x, "b") & any_of(y, "b"))
        | (any_of(y, "a", "b") & any_of(z, "a"))
    )
    text = space.describe(condition)
    # x=c ∧ y=a ∧ z=a satisfies the condition (third disjunct): its description must say so
    witness = any_of(x, "c") & any_of(y, "a") & any_of(z, "a")
    assert space.satisfiable(condition & witness)
    assert (parse(space, text) & witness & space.valid) != space.false, text


def test_describe_says_when_other_values_matter() -> None:
    space = make_space()
    only_known = space.slot(WORLD, "empty")
    assert space.describe(only_known, known_only=False) == "world=empty"
    assert space.describe(only_known) != space.describe(space.true)


# -- every description of the corpus, read back -------------------------------------------------
CORPUS = Path(__file__).resolve().parents[2].parent / "shared" / "corpus"
SUMMARIES = ("only for other values", "true for every known value", "a condition over ")


class _Reader:
    """Reads descriptions of conditions of ``space`` back into BDDs: every literal the
    printer can write (slots, predicates, files), looked up by its text among the atoms of
    the condition and its facts.

    Two atoms may print alike (an ``$(eval)`` over an arg bound to an environment variable
    and the same one over the arg itself): :meth:`readings` gives a BDD per way of telling
    them apart, and one of them must be the condition.
    """

    def __init__(self, space: ConditionSpace, variables: Iterable[str], qualify: bool) -> None:
        self.space = space
        self.atoms: dict[str, list[BDD]] = {}
        inputs = set()
        for name in variables:
            atom = space.atom_of(name)
            if isinstance(atom, PredicateAtom):
                text = PREDICATES[atom.test][1].format(atom.term)
            elif isinstance(atom, FileAtom):
                text = atom.label
            else:
                inputs.add(atom.input)
                continue
            if space.bdd.var(name) not in self.atoms.setdefault(text, []):
                self.atoms[text].append(space.bdd.var(name))
        self.named = {
            (f"{i.file}:{i.name}" if qualify and isinstance(i, ArgInput) else str(i)): i
            for i in inputs
        }

    def readings(self, text: str) -> list[BDD]:
        alike = sorted(t for t, atoms in self.atoms.items() if len(atoms) > 1 and t in text)
        results = []
        for picks in itertools.product(*(range(len(self.atoms[t])) for t in alike)):
            chosen = {t: self.atoms[t][pick] for t, pick in zip(alike, picks, strict=True)}
            results.append(self._read(text, chosen))
        return results

    def _read(self, text: str, chosen: dict[str, BDD]) -> BDD:
        result = self.space.false
        for cube_text in text.split(" ∨ "):
            if cube_text.startswith("(") and cube_text.endswith(")") and "∧" in cube_text:
                cube_text = cube_text[1:-1]
            cube = self.space.true
            for part in cube_text.split(" ∧ "):
                cube &= self._literal(part, chosen)
            result |= cube
        return result

    def _atom(self, text: str, chosen: dict[str, BDD]) -> BDD | None:
        found = self.atoms.get(text)
        return None if found is None else chosen.get(text, found[0])

    def _literal(self, part: str, chosen: dict[str, BDD]) -> BDD:
        space, named = self.space, self.named
        if part.startswith("¬(") and part.endswith(")"):
            atom = self._atom(part[2:-1], chosen)
            if atom is not None:
                return ~atom
        atom = self._atom(part, chosen)
        if atom is not None:
            return atom
        atom = self._atom(part[1:], chosen) if part.startswith("¬") else None
        if atom is not None:
            return ~atom
        if part.endswith(" set") and part.removesuffix(" set") in named:
            return ~space.slot(named[part.removesuffix(" set")], UNSET)
        for op in ("∈", "≠", "="):
            name, found, rest = part.partition(op)
            if found and name in named:
                input_ = named[name]
                if op == "=":
                    return _slot_named(space, input_, rest)
                if op == "≠":
                    return ~_slot_named(space, input_, rest)
                union = space.false
                texts = rest[1:-1].split(", ")
                for slot in space.domain(input_):
                    if (slot if isinstance(slot, str) else repr(slot)) in texts:
                        union |= space.slot(input_, slot)
                return union
        name = part.removeprefix("¬")
        assert name in named, (part, sorted(named))
        word = "false" if part.startswith("¬") else "true"  # in any case: True, FALSE, …
        input_ = named[name]
        slots = [s for s in space.domain(input_) if isinstance(s, str) and s.lower() == word]
        assert len(slots) == 1, (part, space.domain(input_))
        return space.slot(input_, slots[0])


def _check_descriptions(models: Sequence[LaunchModel]) -> tuple[int, list[str]]:
    """Describe every model as ``analyze --json`` does, then read every description back and
    compare it with its condition modulo the facts (and, for the default view, with every
    arg holding a known value). Returns how many were checked and the failures."""
    space = models[0].space
    seen: dict[tuple[BDD, bool, bool], str] = {}
    describe = Printer.describe

    def recording(self: Printer, condition: BDD, qualify: bool = False, known: bool = True) -> str:
        text = describe(self, condition, qualify, known)
        seen[condition, qualify, known] = text
        return text

    with patch.object(Printer, "describe", recording):
        for model in models:
            describe_model(model)
    failures = []
    for (condition, qualify, known_only), text in seen.items():
        inputs = space.care_inputs(space.support(condition))
        names = [str(i) for i in inputs]
        if len(set(names)) < len(names) and not qualify:
            text, qualify = space.describe(condition, qualify=True, known_only=known_only), True
        care = space.care(condition)
        for input_ in inputs:
            care &= space.input_constraint(input_)
        known = care
        if known_only:
            for input_ in inputs:
                if isinstance(input_, ArgInput):
                    known &= ~space.slot(input_, OTHER)
        if text == "false":
            ok = (condition & care) == space.false
        elif text == "only for other values":
            ok = (condition & known) == space.false and (condition & care) != space.false
        elif text == "true for every known value":
            ok = (known & ~condition) == space.false and (care & ~condition) != space.false
        elif text.startswith("a condition over "):
            ok = True  # a summary of a formula too long to read
        else:
            variables = space.support(care) | space.support(condition)
            within = care if (known & ~condition) == space.false else known
            reader = _Reader(space, variables, qualify)
            readings = [space.true] if text == "true" else reader.readings(text)
            # a "true for every known value" shown in full is the whole formula
            ok = any((described & within) == (condition & within) for described in readings)
        if not ok:
            failures.append(f"{text!r} (known_only={known_only})")
    return len(seen), failures


@pytest.mark.parametrize("system", ["kobuki", "turtlebot2", "lizi", "husky"])
def test_every_corpus_description_means_its_condition(system: str) -> None:
    if not (CORPUS / system).is_dir():
        pytest.skip(f"corpus not found at {CORPUS}")
    workspace = discover([CORPUS / system], deps=[CORPUS / "_external"], ros_package_path="")
    checked, failures = _check_descriptions(Analysis(workspace).all_models())
    assert checked > 40
    assert failures == []
