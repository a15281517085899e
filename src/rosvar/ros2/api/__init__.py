"""The launch API rosvar knows, one registration per name and a registry per kind, as
launch's ``@expose_action`` and ``@expose_substitution`` expose each class to its frontends:
actions with their XML/YAML tags, Python class names and attributes (``actions.py``),
substitutions with their ``$(name)`` and Python callables (``substitutions.py``), conditions
(``conditions.py``) and description sources (``sources.py``). Every frontend, the attribute
check and the dialect's handlers read these registries; a new kind (event handlers) is one
more :class:`~.registry.Registry`."""
