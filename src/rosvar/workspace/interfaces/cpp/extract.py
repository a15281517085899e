"""C++ extraction's entry point: the interface of the code one entry function reaches."""

from __future__ import annotations

from rosvar.diagnostics import DiagnosticSink, Location
from rosvar.workspace.interfaces.cpp.collector import Collector
from rosvar.workspace.interfaces.cpp.evaluator import Evaluator
from rosvar.workspace.interfaces.cpp.unit import Unit
from rosvar.workspace.interfaces.lifecycle import with_lifecycle
from rosvar.workspace.interfaces.model import Extracted, Role


def extract_node(
    unit: Unit,
    entry: str,
    owner: str | None,
    sink: DiagnosticSink,
    where: Location,
    ros2: bool = False,
) -> Extracted:
    """The interface of the code reachable from function ``entry`` (of class ``owner``),
    and the node's own name (ROS 2); ``ros2``: rclcpp code, whose node has one namespace."""
    starts = [f for f in unit.functions.get(entry, []) if owner is None or f.owner == owner]
    if owner is not None:
        starts += unit.functions.get(owner, [])  # the nodelet's constructor runs first
    if not starts:
        what = f"{owner}::{entry}" if owner else entry
        sink.warning(
            "interface-no-entry",
            f"no definition of {what} in the sources; every function of them is read",
            where,
        )
        starts = [f for functions in unit.functions.values() for f in functions]
    reached = unit.reachable(starts)
    evaluator = Evaluator(unit, reached)
    collector = Collector(unit, evaluator, sink, ros2=ros2)
    built: set[str] = set()
    for function in sorted(reached, key=lambda f: (f.file, f.node.start_byte)):
        if not evaluator.constructed(function):
            continue  # a constructor overload no reached code calls with its arguments
        collector.scan(function)
        if function.owner == function.name and function.owner not in built:
            built.add(function.owner)
            collector.members(function.owner)
    declared = {e.name for e in collector.entries if e.role is Role.PARAMS}
    reads = [read for read in collector.reads if read.name not in declared]
    names = {name.value for name in collector.node_names if name.static}
    node_name = names.pop() if len(names) == 1 else None
    entries = collector.entries + reads
    if collector.lifecycle is not None:
        entries = with_lifecycle(entries, collector.lifecycle)
    return Extracted(entries, node_name)
