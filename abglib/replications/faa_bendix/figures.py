"""Figures of seed 003 (FAA Bendix test): impulse/ramp response grids and the stability triangle."""

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
    styled,
    suptitle,
    tint,
)

__all__ = ["draw_all", "response_grid", "stability_triangle"]


_BENDIX_LABELS = {
    "x_smooth": "smoothed position X(K)",
    "v_smooth": "smoothed velocity XD(KB)",
    "x_pred": "predicted position XP(K)",
}


def _gain_colours() -> tuple:
    """Captions' gains: the Bendix colour; the memo's: a light shade of it."""
    base = family_colour("Bendix α-β")
    return base, tint(base, 0.5)


def _g(x: float, digits: int) -> str:
    return f"{x:.{digits}f}".lstrip("0")


@styled
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
        Solid with dots: the captions' two-digit gains (the runs the letter report
        plotted); dashed, lighter: the memo's three-digit gains. The gains of each row are
        written at its right; one legend under the grid.
    """
    if kind not in ("impulse", "ramp"):
        raise ValueError(f"kind must be one of ['impulse', 'ramp'], got {kind!r}")
    d = data[data["input"] == kind]
    periods = sorted(d["period_s"].unique())
    outs = list(_BENDIX_LABELS)
    c_cap, c_memo = _gain_colours()
    fig, axes = plt.subplots(
        len(periods), 3, figsize=(WIDTH, 1.3 * len(periods) + 1.1), squeeze=False
    )
    diff = {}
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
                ms=1.8,
                lw=1.0,
                color=c_cap,
                label="captions' two-digit gains",
            )
            ax.plot(
                memo["t"], memo[out], "--", lw=1.0, color=c_memo, label="memo's three-digit gains"
            )
            diff[out] = max(
                diff.get(out, 0.0),
                float(np.max(np.abs(cap[out].to_numpy() - memo[out].to_numpy()))) / step,
            )
            lo = min(cap[out].min(), memo[out].min(), 0.0)
            hi = max(cap[out].max(), memo[out].max(), 0.0)
            lo, hi = np.floor(lo / step) * step, np.ceil(hi / step) * step
            if hi - lo < step:
                hi = lo + step
            ax.set_ylim(lo - 0.02 * (hi - lo), hi + 0.02 * (hi - lo))
            ticks = np.arange(lo, hi + step / 2, step)
            if ticks.size > 6:  # label every few divisions, keep the grid at SFY
                ax.set_yticks(ticks, minor=True)
                ax.set_yticks(ticks[:: int(np.ceil(ticks.size / 4))])
                ax.grid(True, which="minor", alpha=0.15)
            else:
                ax.set_yticks(ticks)
            ax.tick_params(labelsize=7)
            if i == 0:
                ax.set_title(_BENDIX_LABELS[out], fontsize=8)
            if j == 0:
                ax.set_ylabel(f"T = {p:g} s\nSFY {step:g}", fontsize=8)
            if i == len(periods) - 1:
                ax.set_xlabel("t (s)", fontsize=8)
        a, b = cap["alpha"].iloc[0], cap["beta"].iloc[0]
        am, bm = memo["alpha"].iloc[0], memo["beta"].iloc[0]
        axes[i, 2].text(
            1.04,
            0.5,
            f"α {_g(a, 2)} | {_g(am, 3)}\nβ {_g(b, 2)} | {_g(bm, 3)}",
            transform=axes[i, 2].transAxes,
            va="center",
            ha="left",
            fontsize=7,
        )
    axes[0, 2].text(
        1.04,
        1.0,
        "captions |\nmemo",
        transform=axes[0, 2].transAxes,
        va="bottom",
        ha="left",
        fontsize=7,
        style="italic",
    )
    if title:
        suptitle(fig, title)
    legend_outside(fig, *axes[0, 0].get_legend_handles_labels(), side="bottom", ncol=2)
    describe(
        fig,
        f"{title}. A grid of {len(periods)} rows (update periods "
        f"{min(periods):g} to {max(periods):g} s) by 3 columns (smoothed position, smoothed "
        f"velocity, predicted position) of the {kind} response against time, with the "
        f"captions' two-digit gains and the memo's three-digit gains; the largest gap "
        f"between the two is "
        + ", ".join(f"{v:.2g} SFY ({_BENDIX_LABELS[k]})" for k, v in diff.items())
        + ".",
    )
    return fig


@styled
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
        critical-damping curves. The full plane left, the gain sets' detail (with their
        periods) right, the legend under both.
    """
    a = np.linspace(0.0, 1.0, 401)
    a2 = np.linspace(0.0, 1.999, 801)
    crit, bb, bendix = (
        family_colour(f) for f in ("standard α-β", "Benedict-Bordner α-β", "Bendix α-β")
    )
    fig, (ax, axz) = plt.subplots(1, 2, figsize=(WIDTH, 4.4))
    for axis, zoom in ((ax, False), (axz, True)):
        axis.plot(
            [0, 2, 0, 0],
            [0, 0, 4, 0],
            "-",
            color=REFERENCE["truth"],
            lw=1.0,
            label="stability triangle",
        )
        axis.fill_between(
            a,
            2 - a - 2 * np.sqrt(1 - a),
            2 - a + 2 * np.sqrt(1 - a),
            color=crit,
            alpha=0.12,
            lw=0,
            label="complex poles (underdamped)",
        )
        axis.plot(a, 2 - a - 2 * np.sqrt(1 - a), "-", color=crit, label="critically damped α-β")
        axis.plot(a, 2 - a + 2 * np.sqrt(1 - a), ":", color=crit, lw=1.0)
        axis.plot(a2, a2**2 / (2 - a2), "--", color=bb, label="Benedict–Bordner")
        axis.plot(
            table["alpha"], table["beta"], "o", color=bendix, ms=4, label="Bendix gain sets (memo)"
        )
        axis.set_xlabel("α")
        axis.set_ylabel("β")
        if zoom:
            for r in table.itertuples(index=False):
                axis.annotate(
                    f"{r.period_s:g} s",
                    (r.alpha, r.beta),
                    textcoords="offset points",
                    xytext=(5, -3),
                    fontsize=7,
                )
            axis.set_xlim(0.2, 0.72)
            axis.set_ylim(0.0, 1.0)
            axis.set_title("detail, with the update periods", loc="left")
        else:
            axis.set_xlim(0, 2.05)
            axis.set_ylim(0, 4.1)
            axis.set_title("the whole triangle", loc="left")
    if title:
        suptitle(fig, title)
    legend_outside(fig, *ax.get_legend_handles_labels(), side="bottom", ncol=3)
    under = int((table["beta"] > 2 - table["alpha"] - 2 * np.sqrt(1 - table["alpha"])).sum())
    above_bb = int((table["beta"] > table["alpha"] ** 2 / (2 - table["alpha"])).sum())
    describe(
        fig,
        f"{title}. The α-β plane with the stability triangle (α from 0 to 2, β up to "
        f"4 − 2α), the critically damped curve, the underdamped region and the "
        f"Benedict–Bordner curve; the {len(table)} Bendix gain sets, α from "
        f"{table['alpha'].min():g} to {table['alpha'].max():g} and β from "
        f"{table['beta'].min():g} to {table['beta'].max():g}, all inside the triangle; "
        f"{under} lie in the underdamped region and {above_bb} above the Benedict–Bordner "
        f"curve. Right: the detail, each set labelled with its update period.",
    )
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
