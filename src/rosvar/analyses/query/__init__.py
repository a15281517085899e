"""Queries over the variational model (``rosvar query``): which elements match, and when.

``parser`` turns the text into a checked syntax tree, ``collections`` lists what queries range
over (a registry other analyses extend), ``evaluator`` evaluates a query over conditional
values. See docs/queries.md.
"""
