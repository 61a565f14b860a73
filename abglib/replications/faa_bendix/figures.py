"""Figures of seed 003 (FAA Bendix test): impulse/ramp response grids and the stability triangle."""

from __future__ import annotations

import numpy as np
import pandas as pd

from ...reporting.plotting import _STYLE, plt

__all__ = ["draw_all", "response_grid", "stability_triangle"]


_BENDIX_LABELS = {
    "x_smooth": "smoothed position X(K)",
    "v_smooth": "smoothed velocity XD(KB)",
    "x_pred": "predicted position XP(K)",
}


def response_grid(data: pd.DataFrame, kind: str, sfy: dict, title: str = ""):
    """Small multiples of one test input: a row per gain set, a column per graph.

    Parameters
    ----------
    data : DataFrame
        ``responses.csv``: ``table, period_s, alpha, beta, input, k, t, z, x_smooth,
        v_smooth, x_pred``.
    kind : {'impulse', 'ramp'}
    sfy : dict
        ``{period_s: SFY}``, the captions' scale factor: the y grid is drawn every SFY.
    title : str

    Returns
    -------
    matplotlib.figure.Figure
        Solid: the captions' two-digit gains (the runs the letter report plotted);
        dashed: the memo's three-digit gains. Markers at the samples (the program plots
        points at t = kT).
    """
    d = data[data["input"] == kind]
    periods = sorted(d["period_s"].unique())
    outs = list(_BENDIX_LABELS)
    style = dict(_STYLE, **{"figure.figsize": (9.0, 1.55 * len(periods) + 0.8), "font.size": 7})
    with plt.rc_context(style):
        fig, axes = plt.subplots(len(periods), 3, layout="constrained", squeeze=False)
        for i, p in enumerate(periods):
            dp = d[d["period_s"] == p]
            cap = dp[dp["table"] == "captions"]
            memo = dp[dp["table"] == "memo"]
            step = float(sfy[p])
            for j, out in enumerate(outs):
                ax = axes[i, j]
                ax.plot(
                    cap["t"],
                    cap[out],
                    "o-",
                    ms=2.0,
                    lw=0.9,
                    color="C0",
                    label=f"captions α={cap['alpha'].iloc[0]:.2f} β={cap['beta'].iloc[0]:.2f}",
                )
                ax.plot(
                    memo["t"],
                    memo[out],
                    "--",
                    lw=0.9,
                    color="C3",
                    label=f"memo α={memo['alpha'].iloc[0]:.3f} β={memo['beta'].iloc[0]:.3f}",
                )
                lo = min(cap[out].min(), memo[out].min(), 0.0)
                hi = max(cap[out].max(), memo[out].max(), 0.0)
                lo, hi = np.floor(lo / step) * step, np.ceil(hi / step) * step
                if hi - lo < step:
                    hi = lo + step
                ax.set_ylim(lo - 0.02 * (hi - lo), hi + 0.02 * (hi - lo))
                ticks = np.arange(lo, hi + step / 2, step)
                if ticks.size > 12:  # label every few divisions, keep the grid at SFY
                    ax.set_yticks(ticks, minor=True)
                    ax.set_yticks(ticks[:: int(np.ceil(ticks.size / 6))])
                    ax.grid(True, which="minor", alpha=0.15)
                else:
                    ax.set_yticks(ticks)
                if i == 0:
                    ax.set_title(_BENDIX_LABELS[out])
                if j == 0:
                    ax.set_ylabel(f"T={p} s\nSFY={step:.2f}")
                if i == len(periods) - 1:
                    ax.set_xlabel("t (s)")
                ax.tick_params(labelsize=6)
                if j == 2:
                    ax.legend(loc="upper right", fontsize=5, frameon=False)
        if title:
            fig.suptitle(title, fontsize=9)
    return fig


def stability_triangle(table: pd.DataFrame, title: str = ""):
    """The gain sets in the alpha-beta stability triangle.

    Parameters
    ----------
    table : DataFrame
        ``damping_lags.csv``: at least ``period_s, alpha, beta``.

    Returns
    -------
    matplotlib.figure.Figure
        Triangle ``0 < alpha < 2, 0 < beta < 4 - 2 alpha`` (seed 000, eqs 45-48 at
        gamma = 0), the critically damped curve ``beta = 2 - alpha - 2 sqrt(1 - alpha)``
        (seed 001, eq 20) and its upper twin, the Benedict-Bordner curve
        ``beta = alpha^2 / (2 - alpha)``; complex poles (underdamped) between the two
        critical-damping curves.
    """
    a = np.linspace(0.0, 1.0, 401)
    a2 = np.linspace(0.0, 1.999, 801)
    with plt.rc_context(_STYLE):
        fig, (ax, axz) = plt.subplots(1, 2, figsize=(10.0, 4.8), layout="constrained")
        for axis, zoom in ((ax, False), (axz, True)):
            axis.plot([0, 2, 0, 0], [0, 0, 4, 0], "k-", lw=1.0, label="stability triangle")
            axis.fill_between(
                a,
                2 - a - 2 * np.sqrt(1 - a),
                2 - a + 2 * np.sqrt(1 - a),
                color="C0",
                alpha=0.12,
                label="complex poles (underdamped)",
            )
            axis.plot(a, 2 - a - 2 * np.sqrt(1 - a), "C0-", label="critically damped")
            axis.plot(a, 2 - a + 2 * np.sqrt(1 - a), "C0:", lw=1.0)
            axis.plot(a2, a2**2 / (2 - a2), "C2--", label="Benedict–Bordner")
            axis.plot(
                table["alpha"], table["beta"], "o", color="C3", ms=4, label="Bendix gain sets"
            )
            for r in table.itertuples(index=False):
                axis.annotate(
                    f"{r.period_s} s",
                    (r.alpha, r.beta),
                    textcoords="offset points",
                    xytext=(4, -8),
                    fontsize=7,
                )
            axis.set_xlabel("α")
            axis.set_ylabel("β")
            if zoom:
                axis.set_xlim(0.2, 0.72)
                axis.set_ylim(0.0, 1.0)
                axis.set_title("detail")
            else:
                axis.set_xlim(0, 2.05)
                axis.set_ylim(0, 4.1)
                axis.legend(loc="upper right")
        if title:
            fig.suptitle(title, fontsize=9)
    return fig


def draw_all(responses: pd.DataFrame, damping_lags: pd.DataFrame, captions: pd.DataFrame) -> dict:
    """The report's three figures, by output name: ``impulse``, ``ramp`` (response grids
    with the captions' SFY, from ``captions.csv``) and ``triangle``."""
    figs = {}
    for kind in ("impulse", "ramp"):
        c = captions[captions["input"] == kind]
        sfy = dict(zip(c["period_s"], c["sfy"], strict=True))
        title = (
            f"{kind.upper()} RESPONSE OF THE BENDIX ALPHA-BETA FILTER, "
            f"T = {min(sfy)}-{max(sfy)} s (y grid every SFY, the captions' scale factor)"
        )
        figs[kind] = response_grid(responses, kind, sfy, title)
    figs["triangle"] = stability_triangle(
        damping_lags, "The eight Bendix gain sets (memo) in the α-β plane"
    )
    return figs
