"""rosvar: variability analysis of ROS applications.

Layers, each importing only the ones before it:
``workspace`` (packages, launch files) → ``frontends`` (file formats to entities) →
``logic`` (presence conditions, conditional values) → ``interpreter`` (variational
roslaunch semantics) → ``analyses`` (resolution, conflicts, features, metrics) →
``configuration`` (multi-step configuration) → ``outputs`` (CLI, exports, web).
"""

__version__ = "0.1.0"
