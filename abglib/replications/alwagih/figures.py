"""Figures of seed 001 (Al-Wagih and Abdulla): tracks, RMSE bars, the causal M5."""

from __future__ import annotations

import numpy as np
import pandas as pd

from ...reporting.plotting import _STYLE, plt

__all__ = ["alwagih_causal", "alwagih_rmse_bars", "alwagih_tracks"]


_METHOD_STYLE = {
    "M1": ("tab:blue", "-"),
    "M2": ("tab:orange", "-"),
    "M3": ("tab:green", "--"),
    "M4": ("tab:red", "-"),
    "M5": ("tab:purple", "-"),
    "M5_causal": ("tab:brown", ":"),
    "kalata_ab": ("tab:gray", "-."),
    "kalman_ss": ("black", ":"),
}


def alwagih_tracks(tracks: pd.DataFrame, methods=("M1", "M2", "M3", "M4", "M5"), title=""):
    """Actual, measured and predicted track in the X-Y plane and per coordinate (seed 001,
    Figures 5-6): ``tracks`` has columns coord, t, truth, measured and one per method."""
    with plt.rc_context(_STYLE):
        fig = plt.figure(figsize=(9.0, 7.0))
        gs = fig.add_gridspec(2, 2)
        ax = fig.add_subplot(gs[:, 0])
        x = tracks[tracks["coord"] == "X"].sort_values("t")
        y = tracks[tracks["coord"] == "Y"].sort_values("t")
        ax.plot(x["truth"], y["truth"], color="k", lw=2.0, label="actual")
        ax.plot(x["measured"], y["measured"], ".", color="0.5", ms=3, label="measured")
        for m in methods:
            col, ls = _METHOD_STYLE[m]
            ax.plot(x[m], y[m], color=col, ls=ls, label=f"{m} predicted")
        ax.set_xlabel("X (m)")
        ax.set_ylabel("Y (m)")
        ax.legend(loc="best")
        for i, (c, d) in enumerate((("X", x), ("Y", y))):
            a = fig.add_subplot(gs[i, 1])
            for m in methods:
                col, ls = _METHOD_STYLE[m]
                a.plot(d["t"], d[m] - d["truth"], color=col, ls=ls, label=m)
            a.plot(d["t"], d["measured"] - d["truth"], ".", color="0.5", ms=3, label="measured")
            a.set_xlabel("t (s)")
            a.set_ylabel(f"{c} prediction error (m)")
        fig.suptitle(title)
        fig.tight_layout()
    return fig


def alwagih_rmse_bars(summary: pd.DataFrame, realisation: pd.DataFrame, methods, title=""):
    """RMSE of the methods per experiment, X and Y (seed 001, Figures 7-8): bars are the
    Monte Carlo means with their confidence intervals, dots the single realisation."""
    with plt.rc_context(_STYLE):
        fig, axes = plt.subplots(1, 2, figsize=(10.0, 4.5))
        for ax, c in zip(axes, ("X", "Y"), strict=True):
            s = summary[summary["coord"] == c]
            r = realisation[realisation["coord"] == c].set_index("experiment")
            exps = sorted(s["experiment"].unique())
            width = 0.8 / len(methods)
            for j, m in enumerate(methods):
                d = s[s["method"] == m].set_index("experiment").loc[exps]
                pos = np.arange(len(exps)) + (j - (len(methods) - 1) / 2) * width
                col, _ = _METHOD_STYLE[m]
                err = np.vstack([d["mean"] - d["ci_low"], d["ci_high"] - d["mean"]])
                ax.bar(pos, d["mean"], width, color=col, yerr=err, capsize=2, label=m)
                ax.plot(pos, r.loc[exps, m], "k.", ms=4)
            ax.set_xticks(np.arange(len(exps)), [str(e) for e in exps])
            ax.set_xlabel("experiment")
            ax.set_ylabel(f"RMSE of the {c} prediction (m)")
            ax.set_yscale("log")
            ax.set_title(f"{c} coordinate")
        axes[0].legend(loc="best")
        fig.suptitle(
            f"{title}\n(bars: Monte Carlo mean with confidence interval; dots: one realisation)"
        )
        fig.tight_layout()
    return fig


def alwagih_causal(causal: pd.DataFrame, title=""):
    """Monte Carlo mean RMSE of M5, the causal M5, the best of M1-M4 and the two Kalman
    designs per experiment and coordinate (``causal`` table of the seed 001 study)."""
    cols = ["best_of_M1_M4", "M5", "M5_causal", "kalata_ab", "kalman_ss"]
    colours = ["tab:green", "tab:purple", "tab:brown", "tab:gray", "black"]
    with plt.rc_context(_STYLE):
        fig, axes = plt.subplots(1, 2, figsize=(10.0, 4.5), sharey=True)
        for ax, noise in zip(axes, ("white", "coloured"), strict=True):
            d = causal[causal["noise"] == noise]
            labels = [f"{e}{c}" for e, c in zip(d["experiment"], d["coord"], strict=True)]
            width = 0.8 / len(cols)
            for j, (col, colour) in enumerate(zip(cols, colours, strict=True)):
                pos = np.arange(len(d)) + (j - (len(cols) - 1) / 2) * width
                ax.bar(pos, d[col], width, color=colour, label=col)
            ax.set_xticks(np.arange(len(d)), labels)
            ax.set_xlabel("experiment and coordinate")
            ax.set_ylabel("Monte Carlo mean RMSE (m)")
            ax.set_yscale("log")
            ax.set_title(f"{noise} noise")
        handles, labels = axes[0].get_legend_handles_labels()
        fig.legend(handles, labels, loc="lower center", ncol=len(cols))
        fig.suptitle(title)
        fig.tight_layout(rect=(0, 0.07, 1, 1))
    return fig
