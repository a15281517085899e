"""Variability as logic: presence conditions as BDDs over the configuration's inputs, and
values that differ between configurations.

Every question of the kind "can this happen?" is asked of a BDD (``conditions``, through
``bdd``, the one door to ``dd``), never answered by enumerating configurations; a value that
varies is a :class:`~.choice.Choice` of ``(condition, value)`` branches, and one not known
yet a term (``terms``) that configurations make concrete.
"""
