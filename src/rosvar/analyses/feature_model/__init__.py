"""The feature model (the paper's Algorithm 1) and the questions its solver answers.

``features``: the files, args, values and cross-tree constraints; ``model``: the model with
its solver; ``extraction``: Algorithm 1; ``ordering``: the solver's variable order;
``exclusions``: the excludes constraints as the solver builds them; ``solver``: the model as
BDDs; ``counting``: exact weighted counts; ``operations``: counting, core/dead features,
explanations, simplest triggers.
"""
