"""The launch model's typed node fields: one definition, read per variant or over every
configuration, giving the same in each configuration."""

from __future__ import annotations

from collections.abc import Sequence

import pytest

from logic.spaces import make_space
from rosvar.interpreter.model import NodeField, NodeSchema, Raw, constant_field
from rosvar.logic.choice import Choice
from rosvar.logic.conditions import ConditionSpace
from rosvar.logic.inputs import ArgInput, Input
from rosvar.ros.version import RosVersion

F = "/ws/pkg/launch/main.launch"
NS = ArgInput(F, "ns")
NAME = ArgInput(F, "name")
DOMAINS: dict[Input, tuple[str, ...]] = {NS: ("/", "/a/"), NAME: ("x", "y")}


def joined(values: Sequence[Raw | None]) -> Raw | None:
    namespace, name = values
    return None if name is None else f"{namespace}{name}"


@pytest.fixture
def space() -> ConditionSpace:
    return make_space(DOMAINS)


def field_of(space: ConditionSpace, input_: ArgInput) -> Choice[Raw | None]:
    return Choice.of([(space.slot(input_, slot), slot) for slot in DOMAINS[input_]])


def test_a_field_read_as_it_is_stays_the_shared_choice(space: ConditionSpace) -> None:
    fields = {"ns": field_of(space, NS)}
    accessor = NodeField(("ns",))
    assert accessor.over(fields) is fields["ns"]
    assert accessor.of({"ns": "/a/"}) == "/a/"
    assert accessor.of({}) is None


def test_a_computed_field_over_every_configuration_is_its_value_in_each(
    space: ConditionSpace,
) -> None:
    fields = {"ns": field_of(space, NS), "name": field_of(space, NAME)}
    accessor = NodeField(("ns", "name"), joined)
    over = accessor.over(fields)
    seen = set()
    for ns in DOMAINS[NS]:
        for name in DOMAINS[NAME]:
            assert isinstance(ns, str) and isinstance(name, str)
            assignment = space.assignment({NS: ns, NAME: name})
            [value] = [v for c, v in over if space.evaluate(c, assignment)]
            assert value == accessor.text({"ns": ns, "name": name}) == f"{ns}{name}"
            seen.add(value)
    assert seen == {"/x", "/y", "/a/x", "/a/y"}


def test_a_constant_field_holds_everywhere(space: ConditionSpace) -> None:
    accessor = constant_field(None)
    assert accessor.of({"ns": "/"}) is None
    [(condition, value)] = accessor.over({"ns": field_of(space, NS)})
    assert condition == space.true and value is None


def test_a_schema_reads_only_the_fields_it_launches() -> None:
    plain = NodeField(("name",))
    with pytest.raises(ValueError, match="namespace"):
        NodeSchema(
            RosVersion.ROS1,
            package=plain,
            executable=plain,
            name=plain,
            namespace=NodeField(("namespace",)),
            full_name=plain,
            label=plain,
            args=plain,
            plugin=constant_field(None),
            lifecycle=constant_field(None),
            launched=("name",),
        )
