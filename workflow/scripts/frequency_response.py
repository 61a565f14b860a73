"""Frequency responses of one figure of seed 000 (Figs. 1-6), as a long table.

Each curve of the figure's config entry is a gain design and an output; the response
``H(e^{j wT})`` (seed 000, eqs 36-40 with z = e^{j wT}) comes from
:func:`abglib.analysis.frequency_response`. Phase is unwrapped along wT, in degrees.
"""

import numpy as np
import pandas as pd

from abglib.analysis import frequency_response
from abglib.reporting.pipeline import curve_label, gains_from_spec, log_to, wt_grid


def response_table(figure: dict, grids: dict) -> pd.DataFrame:
    """Long table ``curve, design, output, alpha, beta, gamma, wT, magnitude, phase_deg``."""
    kind = "linear" if figure["axes"] == "linear" else "log"
    wt = wt_grid(grids[kind], kind)
    frames = []
    for spec in figure["curves"]:
        gains = gains_from_spec(spec)
        h = float(spec.get("scale", 1.0)) * np.asarray(
            frequency_response(gains, spec["output"], wt)
        )
        frames.append(
            pd.DataFrame(
                {
                    "curve": curve_label(spec, gains),
                    "design": spec["design"],
                    "output": spec["output"],
                    "alpha": gains.alpha,
                    "beta": gains.beta,
                    "gamma": gains.gamma,
                    "wT": wt,
                    "magnitude": np.abs(h),
                    "phase_deg": np.degrees(np.unwrap(np.angle(h))),
                }
            )
        )
    return pd.concat(frames, ignore_index=True)


def main(output, params) -> None:
    from abglib.reporting.compare import write_csv

    write_csv(response_table(params.figure, params.grids), output.data, params.digits)


if "snakemake" in globals():
    log_to(snakemake.log[0])  # noqa: F821
    main(snakemake.output, snakemake.params)  # noqa: F821
