"""The benchmark matrix's family of VRF checks, for the Bonferroni bound of
:func:`abglib.bench.metrics.fail_threshold`: the estimates a cell scores, and how many
checks a matrix can hold.

Imports nothing: the workflow checks the family's size while Snakemake parses it
(``workflow/rules/common.smk``), and importing :mod:`abglib.bench.metrics` there (scipy,
pandas, the exact analysis) cost every parse in a new working directory about a second.
"""

from __future__ import annotations

#: Estimates scored against the truth (:mod:`abglib.bench.metrics`).
OUTPUTS = ("x_smooth", "x_pred", "v_smooth", "v_pred")


def n_vrf_checks(n_variants: int, n_scenarios: int, max_coords: int = 2) -> int:
    """Upper bound on the number of VRF checks in the matrix (for the Bonferroni bound):
    one per variant, scenario, coordinate and scored estimate."""
    return int(n_variants) * int(n_scenarios) * int(max_coords) * len(OUTPUTS)
