"""Questions over the variational models, answered for all configurations at once:
conflicts by resolved name, the communication graph and its checks, the feature model and
its solver, the paper's metrics, queries.

Each answer carries the condition under which it holds; none enumerates configurations.
The analyses read the dialect-neutral model: what only one ROS means is the dialects'.
"""
