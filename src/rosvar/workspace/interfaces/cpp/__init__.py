"""C++ extraction: the ROS API calls of one executable, nodelet or component, read with
tree-sitter.

No compiler is run, so types are not known: a value is followed only as far as the source
says it statically. The package's parts, in the order they run: :mod:`.syntax` (trees),
:mod:`.unit` (a target's sources indexed, and what its entry point reaches),
:mod:`.evaluator` (values of names and node handles), :mod:`.apis` (the recognised calls),
:mod:`.collector` (calls to entries, with :mod:`.param_defaults`), :mod:`.extract` (the entry).
What cannot be decided is kept symbolic with a diagnostic.
"""
