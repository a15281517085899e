"""Launch files as format-neutral entity trees: what every ROS dialect's formats share.

A frontend turns a file's text into :class:`~.entity.Entity` trees with exact locations, so
the interpretation never sees a format; the safe XML reader (``xml``) serves roslaunch files,
ROS 2 XML files and ``package.xml`` alike. A dialect's own formats (ROS 2's YAML and Python)
live with the dialect.
"""
