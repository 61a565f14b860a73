"""Run benchmarks/engine_speed.py at its --quick size; timings are wall clock (the median
of each row's calls over ``benchmark.speed.repeats`` rounds).

The CSV is NOT byte-reproducible (timings vary run to run); the report shows it apart
from the deterministic tables. With ``benchmark.speed.run: false`` an empty table is
written instead.
"""

import importlib.util

import pandas as pd

from abglib.common.files import atomic_output
from abglib.common.jobs import log_to

COLUMNS = ["case", "filter", "implementation", "samples_per_s", "ratio_vs_filterpy"]


def main(input, output, params, logger) -> None:
    if not params.run:
        df = pd.DataFrame(columns=COLUMNS)
    else:
        spec = importlib.util.spec_from_file_location("engine_speed", input.script)
        mod = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(mod)
        # one line per timed call, `repeats` rounds side by side with FilterPy; the report
        # shows each row's median over its calls
        calls = mod.run(quick=True, rounds=int(params.repeats))
        worst = calls.loc[calls.implementation == "filterpy", "max_rel_diff"].max()
        logger.info("largest FilterPy/abglib relative difference: %.3g", worst)
        keys = ["case", "filter", "implementation"]
        df = calls.groupby(keys, sort=False)[COLUMNS[3:]].median().reset_index()[COLUMNS]
    with atomic_output(output.speed) as tmp:
        df.to_csv(tmp, index=False, float_format="%.3g")


if "snakemake" in globals():
    _logger = log_to(snakemake.log[0])  # noqa: F821
    main(snakemake.input, snakemake.output, snakemake.params, _logger)  # noqa: F821
