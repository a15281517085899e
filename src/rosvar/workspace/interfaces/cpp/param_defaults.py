"""What a C++ parameter read falls back to when the parameter is unset: a literal default,
the expression that computes it, or the code that handles an unset one.
"""

from __future__ import annotations

from tree_sitter import Node

from rosvar.workspace.interfaces.cpp import syntax
from rosvar.workspace.interfaces.cpp.evaluator import Evaluator
from rosvar.workspace.interfaces.cpp.unit import Function
from rosvar.workspace.interfaces.model import Default, Expression
from rosvar.workspace.interfaces.values import Text

_TESTING = frozenset({"unary_expression", "parenthesized_expression", "binary_expression"})
_FAILING = ("ROS_ERROR", "ROS_FATAL", "exit", "abort", "ros::shutdown")


def result_test(call: Node) -> Node | None:
    """The expression that tests ``call``'s result (``!nh.getParam(...)`` in an ``if``): the
    code handles an unset parameter. None when the result is dropped (the variable silently
    keeps its value) or when the branch taken when unset fails (returns, throws, logs an
    error): the parameter is required."""
    node, negated = call, False
    while node.parent is not None and node.parent.type in _TESTING:
        node = node.parent
        negated ^= node.type == "unary_expression" and syntax.text(node).startswith("!")
    parent = node.parent
    if parent is None or parent.type in ("expression_statement", "compound_statement"):
        return None
    statement = parent.parent if parent.type == "condition_clause" else None
    if statement is not None and statement.type == "if_statement":
        unset = statement.child_by_field_name("consequence" if negated else "alternative")
        if unset is not None and any(_fails(n) for n in syntax.walk_all(unset)):
            return None
    return node


def dropped(call: Node) -> bool:
    """Whether ``call``'s result is dropped (``nh.getParam("x", v);``): unset, the parameter
    leaves ``v`` as it was, so the code goes on with that value."""
    parent = call.parent
    return parent is not None and parent.type == "expression_statement"


def guard_of(call: Node, name: Node) -> Node | None:
    """The condition of an enclosing ``if`` that asks whether parameter ``name`` is set
    (``if (nh.hasParam("x")) nh.getParam("x", v);``)."""
    node = call.parent
    while node is not None and node.type != "function_definition":
        if node.type == "if_statement":
            condition = node.child_by_field_name("condition")
            text = syntax.text(condition) if condition is not None else ""
            if "hasParam(" + syntax.text(name) in text.replace(" ", ""):
                return condition
        node = node.parent
    return None


def _fails(node: Node) -> bool:
    if node.type in ("return_statement", "throw_statement"):
        return True
    callee = node.child_by_field_name("function") if node.type == "call_expression" else None
    return callee is not None and syntax.text(callee).startswith(_FAILING)


def default(node: Node | None, evaluator: Evaluator, function: Function) -> Default | None:
    if node is None:
        return None
    held = _parameter_value(node)
    if held is not None:
        return default(held, evaluator, function)
    text = syntax.text(node)
    if node.type in ("true", "false"):
        return node.type == "true"
    if node.type == "number_literal":
        number = text.rstrip("fFlLuU")
        try:
            return int(number, 0)
        except ValueError:
            try:
                return float(number)
            except ValueError:
                return Expression(text)
    value = evaluator.evaluate(node, function)
    if isinstance(value, Text) and value.static:
        return value.value
    return Expression(text)


def _parameter_value(node: Node) -> Node | None:
    """The value ``rclcpp::ParameterValue(value)`` holds (nav2 declares its parameters so:
    ``declare_parameter("speed_limit_topic", rclcpp::ParameterValue("speed_limit"))``)."""
    if node.type != "call_expression":
        return None
    callee, arguments = node.child_by_field_name("function"), node.child_by_field_name("arguments")
    if callee is None or arguments is None or arguments.named_child_count != 1:
        return None
    return (
        arguments.named_children[0]
        if syntax.last(syntax.text(callee)) == "ParameterValue"
        else None
    )
