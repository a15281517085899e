"""Actions that change nothing a launch starts: ``<log>`` (``LogInfo``), ``<set_use_sim_time>``
(the launch's own ROS node's parameter, not its nodes') and ``<set_ros_log_dir>``. They are
accepted, as launch accepts them, and their attributes are read for the errors they raise."""

from __future__ import annotations

from rosvar.frontends.entity import Entity
from rosvar.interpreter.interpretation import Interpretation, processed
from rosvar.ros2.context import Context
from rosvar.ros2.dialect import tag

READ = {"log": "message", "set_use_sim_time": "value", "set_ros_log_dir": "new_log_dir"}


@tag("log")
@tag("set_use_sim_time")
@tag("set_ros_log_dir")
@processed
def inert(it: Interpretation[Context], entity: Entity, context: Context) -> None:
    it.required(entity, READ[entity.tag], context)
