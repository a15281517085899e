"""The exit codes of ``rosvar``: scripts and CI jobs branch on them, so they are one table.

0 success; 1 the analysed launch configuration fails (errors or conflicts, ``resolve``), a
choice was refused (``configure``) or a finding reaches ``--fail-on`` (``check``); 2 usage
error; 3 nothing to analyse (no launch file found, a ``--launch`` file missing); 4 the
feature model is too large to solve and the command needs its solver.
"""

EXIT_OK, EXIT_FAILS, EXIT_USAGE, EXIT_INPUT, EXIT_TOO_LARGE = 0, 1, 2, 3, 4
