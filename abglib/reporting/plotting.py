"""Shared figure style and saving (matplotlib is imported only here and by the figure modules).

Computing and plotting are separate (python-control style): the workflow computes a
response table, this module draws it. Every figure is saved by :func:`save_figure`,
which writes a PNG without metadata (no software version or timestamp), atomically.
"""

from __future__ import annotations

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pandas as pd  # noqa: E402

__all__ = [
    "frequency_response_figure",
    "save_figure",
]

# a fixed style so that a rebuild draws identical pixels whatever the user's matplotlibrc
_STYLE = {
    "figure.figsize": (7.0, 6.0),
    "font.size": 9,
    "axes.grid": True,
    "grid.alpha": 0.35,
    "legend.fontsize": 8,
    "lines.linewidth": 1.3,
    "svg.hashsalt": "abglib",
}


def save_figure(fig, path, dpi: int = 110) -> None:
    """Save ``fig`` as a deterministic PNG at ``path`` (temp file, then ``os.replace``)."""
    from .pipeline import atomic_output

    try:
        with atomic_output(path) as tmp:
            fig.savefig(tmp, dpi=dpi, format="png", metadata={"Software": None})
    finally:
        plt.close(fig)


def frequency_response_figure(data: pd.DataFrame, axes: str, title: str = ""):
    """Magnitude (top) and phase (bottom) of one or more frequency responses.

    Parameters
    ----------
    data : DataFrame
        Long table with columns ``curve`` (legend label), ``wT`` (rad/sample),
        ``magnitude`` (linear) and ``phase_deg`` (unwrapped), in plotting order.
    axes : {'linear', 'bode'}
        ``'linear'``: linear magnitude and omega*T axes (seed 000, Fig. 1);
        ``'bode'``: magnitude in dB against log omega*T (seed 000, Figs. 2-6).
    title : str
        Figure title (the caption of the source figure).

    Returns
    -------
    matplotlib.figure.Figure
    """
    if axes not in ("linear", "bode"):
        raise ValueError(f"axes must be one of ['linear', 'bode'], got {axes!r}")
    with plt.rc_context(_STYLE):
        fig, (ax_mag, ax_ph) = plt.subplots(2, 1, sharex=True, layout="constrained")
        for label, d in data.groupby("curve", sort=False):
            wt = d["wT"].to_numpy()
            mag = d["magnitude"].to_numpy()
            if axes == "bode":
                ax_mag.semilogx(wt, 20.0 * np.log10(mag), label=label)
                ax_ph.semilogx(wt, d["phase_deg"], label=label)
            else:
                ax_mag.plot(wt, mag, label=label)
                ax_ph.plot(wt, d["phase_deg"], label=label)
        if axes == "bode":
            ax_mag.set_ylabel("magnitude (dB)")
            ax_mag.axhline(-3.0, color="0.5", lw=0.8, ls="--")
        else:
            ax_mag.set_ylabel("magnitude")
            ax_mag.axhline(2.0**-0.5, color="0.5", lw=0.8, ls="--")
        ax_ph.set_ylabel("phase (degrees)")
        ax_ph.set_xlabel("ωT (radians per sample)")
        ax_mag.legend(loc="best")
        if title:
            ax_mag.set_title(title, fontsize=9)
    return fig


# ----------------------------------------------------------- FAA Bendix report (seed 003)
