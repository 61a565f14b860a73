"""Figures of seed 001 (Al-Wagih and Abdulla): tracks, RMSE bars, the causal M5."""

from __future__ import annotations

import numpy as np
import pandas as pd

from ...common.plotting import (
    REFERENCE,
    WIDTH,
    describe,
    family_colour,
    legend_outside,
    plt,
    shades,
    styled,
    suptitle,
)

__all__ = ["alwagih_causal", "alwagih_rmse_bars", "alwagih_tracks"]


#: legend names of the methods and designs of the study's tables
_NAMES = {
    "M5_causal": "M5 causal",
    "kalata_ab": "Kalman α-β (Kalata index)",
    "kalman_ss": "steady-state Kalman (DARE)",
    "best_of_M1_M4": "best of M1–M4",
}


def _style(m: str) -> tuple:
    """(colour, line style) of a method: the colour of its gain-design rule."""
    if m == "M5_causal":
        return shades(family_colour("M5"), 3)[2], ":"
    if m == "best_of_M1_M4":
        return "0.7", "-"
    return family_colour({"kalata_ab": "Kalata α-β", "kalman_ss": "Kalman"}.get(m, m)), (
        "--" if m == "M3" else "-"
    )


def _rms(x) -> float:
    return float(np.sqrt(np.mean(np.square(x))))


@styled
def alwagih_tracks(tracks: pd.DataFrame, methods=("M1", "M2", "M3", "M4", "M5"), title=""):
    """Actual, measured and predicted track in the X-Y plane and per coordinate (seed 001,
    Figures 5-6): ``tracks`` has columns coord, t, truth, measured and one per method.
    The legend is under the panels; the alt text gives each method's RMS error."""
    fig = plt.figure(figsize=(WIDTH, 6.2))
    gs = fig.add_gridspec(2, 2)
    ax = fig.add_subplot(gs[:, 0])
    x = tracks[tracks["coord"] == "X"].sort_values("t")
    y = tracks[tracks["coord"] == "Y"].sort_values("t")
    ax.plot(x["truth"], y["truth"], color=REFERENCE["truth"], lw=2.0, label="actual")
    ax.plot(x["measured"], y["measured"], ".", color=REFERENCE["measured"], ms=3, label="measured")
    for m in methods:
        col, ls = _style(m)
        ax.plot(x[m], y[m], color=col, ls=ls, label=f"{_NAMES.get(m, m)} predicted")
    ax.set_xlabel("X (m)")
    ax.set_ylabel("Y (m)")
    ax.set_title("track in the X-Y plane", loc="left")
    err = []
    for i, (c, d) in enumerate((("X", x), ("Y", y))):
        a = fig.add_subplot(gs[i, 1])
        a.plot(d["t"], d["measured"] - d["truth"], ".", color=REFERENCE["measured"], ms=3)
        for m in methods:
            col, ls = _style(m)
            a.plot(d["t"], d[m] - d["truth"], color=col, ls=ls)
        a.axhline(0.0, color=REFERENCE["zero"], lw=0.6)
        a.set_xlabel("t (s)")
        a.set_ylabel(f"{c} prediction error (m)")
        a.set_title(f"{c} prediction error", loc="left")
        err.append(", ".join(f"{m} {_rms(d[m] - d['truth']):.3g} m" for m in methods))
    if title:
        suptitle(fig, title)
    legend_outside(fig, side="bottom", ncol=4)
    describe(
        fig,
        f"{title}. Left: the actual track, the measurements and each method's predicted "
        f"track in the X-Y plane, X from {x['truth'].min():.0f} to {x['truth'].max():.0f} m. "
        f"Right: the X and Y prediction errors against time (0 to {x['t'].max():g} s). RMS "
        f"prediction error in X: {err[0]}; in Y: {err[1]}.",
    )
    return fig


@styled
def alwagih_rmse_bars(summary: pd.DataFrame, realisation: pd.DataFrame, methods, title=""):
    """RMSE of the methods per experiment, X and Y (seed 001, Figures 7-8): bars are the
    Monte Carlo means with their confidence intervals, dots the single realisation."""
    fig, axes = plt.subplots(1, 2, figsize=(WIDTH, 4.2))
    best = []
    for ax, c in zip(axes, ("X", "Y"), strict=True):
        s = summary[summary["coord"] == c]
        r = realisation[realisation["coord"] == c].set_index("experiment")
        exps = sorted(s["experiment"].unique())
        width = 0.8 / len(methods)
        for j, m in enumerate(methods):
            d = s[s["method"] == m].set_index("experiment").loc[exps]
            pos = np.arange(len(exps)) + (j - (len(methods) - 1) / 2) * width
            col, _ = _style(m)
            err = np.vstack([d["mean"] - d["ci_low"], d["ci_high"] - d["mean"]])
            ax.bar(
                pos,
                d["mean"],
                width,
                color=col,
                yerr=err,
                capsize=1.5,
                error_kw={"lw": 0.8},
                label=_NAMES.get(m, m),
            )
            ax.plot(
                pos,
                r.loc[exps, m],
                ".",
                color=REFERENCE["truth"],
                ms=3.5,
                label="one realisation (the paper's table)" if j == 0 else None,
            )
        ax.set_xticks(np.arange(len(exps)), [str(e) for e in exps])
        ax.set_xlabel("experiment")
        ax.set_ylabel(f"RMSE of the {c} prediction (m)")
        ax.set_yscale("log")
        ax.set_title(f"{c} coordinate", loc="left")
        ax.grid(False, axis="x")
        mean = s.groupby("method")["mean"].mean().reindex(list(methods))
        best.append(
            f"in {c}, mean over experiments lowest for {mean.idxmin()} "
            f"({mean.min():.3g} m), highest for {mean.idxmax()} ({mean.max():.3g} m)"
        )
    if title:
        suptitle(fig, title)
    legend_outside(fig, side="bottom", ncol=len(methods) + 1)
    describe(
        fig,
        f"{title}. Two panels (X, Y) of bars on a log axis: the Monte Carlo mean RMSE of "
        f"the prediction of each method per experiment with its confidence interval, and "
        f"a dot for the single realisation; " + "; ".join(best) + ".",
    )
    return fig


@styled
def alwagih_causal(causal: pd.DataFrame, title=""):
    """Monte Carlo mean RMSE of M5, the causal M5, the best of M1-M4 and the two Kalman
    designs per experiment and coordinate (``causal`` table of the seed 001 study)."""
    cols = ["best_of_M1_M4", "M5", "M5_causal", "kalata_ab", "kalman_ss"]
    fig, axes = plt.subplots(1, 2, figsize=(WIDTH, 4.2), sharey=True)
    summary = []
    for ax, noise in zip(axes, ("white", "coloured"), strict=True):
        d = causal[causal["noise"] == noise]
        labels = [f"{e}{c}" for e, c in zip(d["experiment"], d["coord"], strict=True)]
        width = 0.8 / len(cols)
        for j, col in enumerate(cols):
            pos = np.arange(len(d)) + (j - (len(cols) - 1) / 2) * width
            ax.bar(
                pos,
                d[col],
                width,
                color=_style(col)[0],
                label=_NAMES.get(col, col),
                hatch="///" if col == "M5_causal" else None,
                edgecolor="white",
                lw=0,
            )
        ax.set_xticks(np.arange(len(d)), labels)
        ax.set_xlabel("experiment and coordinate")
        ax.set_yscale("log")
        ax.set_title(f"{noise} noise", loc="left")
        ax.grid(False, axis="x")
        means = d[cols].mean()
        summary.append(
            f"{noise} noise: mean over cells M5 {means['M5']:.3g} m, causal M5 "
            f"{means['M5_causal']:.3g} m, best of M1–M4 {means['best_of_M1_M4']:.3g} m, "
            f"Kalata {means['kalata_ab']:.3g} m, DARE Kalman {means['kalman_ss']:.3g} m"
        )
    axes[0].set_ylabel("Monte Carlo mean RMSE (m)")
    if title:
        suptitle(fig, title)
    legend_outside(fig, side="bottom", ncol=3)
    describe(
        fig,
        f"{title}. Two panels (white, coloured noise) of bars on a log axis, one group per "
        f"experiment and coordinate: " + "; ".join(summary) + ".",
    )
    return fig
