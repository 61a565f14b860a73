"""Imported first by the warm worker's fork server (:data:`.workers.PRELOAD`): the
server's environment, which every job forked from it inherits, and only theirs.

matplotlib draws on Agg there (``MPLBACKEND``, unless the caller chose a backend): a job
has no display. Set in the server, not in the process that starts it: there (Snakemake's
own process, or a test session's worker) it leaked into every later subprocess, and a
Jupyter kernel started afterwards drew no inline figures (a test worker ran the
fork-server tests, then the kernel-engine test, whose kernel showed no figure:
2026-12-03)."""

import os

os.environ.setdefault("MPLBACKEND", "Agg")
