"""rosvar: variability analysis of ROS applications.

Layers, each importing only the ones before it (README, Layout): base modules →
``frontends`` (file formats to entities) → ``workspace`` (packages, launch files) → ``logic``
(presence conditions, conditional values) → ``interpreter`` (the variational walk) →
``analyses`` (conflicts, communication, features, metrics, queries) → the dialects ``ros1``
and ``ros2`` (what each ROS's launch files mean) → ``configuration`` (multi-step
configuration) → ``outputs`` (CLI, exports, web). The core never imports a dialect: it finds
them in a registry, which :mod:`rosvar.dialects` fills.
"""

from rosvar import dialects as _dialects  # noqa: F401 - registers the shipped dialects

__version__ = "0.1.0"
