"""Figures 1-6 of seed 000: the responses' data and the drawing.

``response_table``  the frequency responses of one figure's curves, as a long table
``draw``            magnitude and phase of one figure (imports matplotlib when called)
"""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np
import pandas as pd

from ...analysis import frequency_response
from ...bench.variants import gains_from_spec
from ...gains import Gains
from .study import wt_grid

__all__ = ["OUTPUT_LABELS", "curve_label", "draw", "response_table"]

#: How each transfer-function output is written in seed 000 (times the curve's scale).
OUTPUT_LABELS = {
    "x_smooth": "X̄/X",
    "x_pred": "X_p/X",
    "v_smooth": "T·V̄/X",
    "a_smooth": "T²·Ā/X",
}


def curve_label(spec: Mapping, gains: Gains) -> str:
    """Legend text of a config curve, e.g. ``'X̄/X, standard α-β-γ, α=0.3'``."""
    scale = float(spec.get("scale", 1.0))
    out = OUTPUT_LABELS[spec["output"]]
    if scale != 1.0:
        out = f"{scale:g}·{out}"
    name = {"standard_abg": "standard α-β-γ", "standard_ab": "standard α-β", "qd": "QD"}
    label = f"{out}, {name[spec['design']]}, α={float(gains.alpha):.4g}"
    if spec["design"] == "qd" and "m" in spec:
        label += f" (m={float(spec['m']):g})"
    return label


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
    from ...common.plotting import frequency_response_figure

    return frequency_response_figure(data, axes, caption)
