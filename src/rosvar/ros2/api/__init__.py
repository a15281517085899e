"""The launch API rosvar knows, one registration per name and a registry per kind, as
launch's ``@expose_action`` and ``@expose_substitution`` expose each class to its frontends:
an action's XML/YAML tag(s), its Python class name(s) and its attributes (``actions.py``).
Every frontend and the attribute check read these registries; a new kind (substitutions,
conditions, event handlers, description sources) is one more :class:`~.registry.Registry`."""
