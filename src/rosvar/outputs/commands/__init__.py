"""The command line's commands, one module each: what a command reads from its options,
runs and prints. The parser that reaches them is ``rosvar.outputs.cli``; each command
imports its analyses only when it runs, so ``--help`` and the other commands do not pay for
them."""
