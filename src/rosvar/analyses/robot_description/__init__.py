"""Robot descriptions (URDF and xacro) read variationally, and what they launch.

A launch file loads a robot description with ``<param command="$(find xacro)/xacro FILE
name:=$(arg x)">`` (ROS 2: ``$(command 'xacro ...')``); a spawner hands it to Gazebo, whose
model plugins (an IMU, a laser, a camera, a drive) then publish and subscribe like nodes.
rosvar never runs the command: it expands the xacro file itself, for every configuration at
once (:mod:`.xacro`), with the launch file's args as the xacro args, and reads the plugins
(:mod:`.plugins`) and ``ros_gz_bridge`` bridges (:mod:`.bridges`) as interfaces of the node
that loads them (:mod:`.edges`).
"""
