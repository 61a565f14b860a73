"""Figures 1-6 of seed 000: the responses' data and the drawing.

``response_table``  the frequency responses of one figure's curves, as a long table
``draw``            magnitude and phase of one figure (imports matplotlib when called)
"""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np
import pandas as pd

from ...analysis import frequency_response
from ...reporting.pipeline import curve_label, gains_from_spec, wt_grid

__all__ = ["draw", "response_table"]


def response_table(figure: Mapping, grids: Mapping) -> pd.DataFrame:
    """Long table ``curve, design, output, alpha, beta, gamma, wT, magnitude, phase_deg``.

    Each curve of the figure's config entry is a gain design and an output; the response
    ``H(e^{jωT})`` is that of seed 000, eqs 36-40 with z = e^{jωT}
    (:func:`abglib.analysis.frequency_response`), times the curve's ``scale``. Phase is
    unwrapped along ωT, in degrees.
    """
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


def draw(data: pd.DataFrame, axes: str, caption: str = ""):
    """One of Figs. 1-6 from its :func:`response_table` (linear axes or a Bode plot)."""
    from ...reporting.plotting import frequency_response_figure

    return frequency_response_figure(data, axes, caption)
