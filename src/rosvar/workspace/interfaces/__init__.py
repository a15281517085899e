"""The interfaces of the nodes a workspace provides (topics, services, actions, parameters),
read from their sources without building or running them: CMake targets and nodelet plugins
say which sources make which executable, C++ (tree-sitter) and Python (``ast``) sources say
what each one uses; the bundled catalogue stands in for third-party nodes, the hints file
overrides both.
"""
