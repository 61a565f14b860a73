"""Figures of the benchmark matrix: league heatmap and noise-versus-lag trade-off curves."""

from __future__ import annotations

import numpy as np
import pandas as pd

from ..common.plotting import WIDTH, describe, family_colour, legend_outside, plt, styled, suptitle

__all__ = ["METRIC_NAMES", "benchmark_heatmap", "tradeoff_figure"]

#: what the league's metric columns measure, for axis and colour-bar labels
METRIC_NAMES = {
    "rmse_x_smooth": "RMSE of the smoothed position x̄",
    "rmse_x_pred": "RMSE of the predicted position x_p",
    "rmse_v_smooth": "RMSE of the smoothed velocity v̄",
    "rmse_v_pred": "RMSE of the predicted velocity v_p",
    "max_x_smooth": "largest error of the smoothed position x̄",
    "max_x_pred": "largest error of the predicted position x_p",
    "noise_rms_x_smooth": "RMS noise part of the x̄ error",
    "lag_rms_x_smooth": "RMS lag part of the x̄ error",
}

_MARKERS = ["o", "s", "^", "v", "D", "P", "X", "*", "p", "h", "<", ">", "d", "8"]


@styled
def benchmark_heatmap(league: pd.DataFrame, metric: str = "rmse_x_smooth", title: str = ""):
    """Heatmap of one metric over the benchmark matrix (variants x scenarios).

    Each column (scenario) is divided by its best (smallest) value, so colours compare
    variants within a scenario; the cell text is that ratio. Diverged cells are grey and
    marked ``div``; cells where the metric is not defined (e.g. a smoothed output of a
    method that only predicts) are grey and marked ``n/a``. Rows are sorted by their
    median ratio, best first.
    """
    from matplotlib.colors import LogNorm

    if metric not in league.columns:
        raise ValueError(f"metric must be a column of the league table, got {metric!r}")
    name = METRIC_NAMES.get(metric, metric)
    piv = league.pivot(index="variant", columns="scenario", values=metric).astype(float)
    div = league.pivot(index="variant", columns="scenario", values="diverged").astype(bool)
    order = piv.div(piv.min(axis=0), axis=1).median(axis=1).sort_values().index
    piv, div = piv.loc[order], div.loc[order]
    ratio = piv.div(piv.min(axis=0), axis=1)
    h = max(3.0, 0.27 * len(piv) + 2.2)
    fig, ax = plt.subplots(figsize=(WIDTH, h))
    data = np.ma.masked_invalid(ratio.to_numpy())
    cmap = plt.get_cmap("viridis_r").with_extremes(bad="0.85")
    vmax = max(float(np.nanmax(ratio.to_numpy())) if data.count() else 2.0, 1.01)
    im = ax.imshow(data, aspect="auto", cmap=cmap, norm=LogNorm(1.0, vmax))
    for i in range(ratio.shape[0]):
        for j in range(ratio.shape[1]):
            v = ratio.iat[i, j]
            text = "div" if div.iat[i, j] else ("n/a" if not np.isfinite(v) else f"{v:.2g}")
            # white text on the dark end of the colour map, black elsewhere
            dark = np.isfinite(v) and im.norm(v) > 0.55
            ax.text(j, i, text, ha="center", va="center", fontsize=7, color="w" if dark else "k")
    ax.set_xticks(range(piv.shape[1]), piv.columns, rotation=35, ha="right")
    ax.set_yticks(range(piv.shape[0]), piv.index)
    ax.set_xlabel("scenario")
    ax.set_ylabel("variant (best median ratio first)")
    ax.grid(False)
    ax.spines[:].set_visible(False)
    from matplotlib.ticker import FuncFormatter

    bar = fig.colorbar(im, ax=ax, label=f"{name} / best in the scenario (log scale)", shrink=0.8)
    plain = FuncFormatter(lambda v, _: f"{v:g}")
    bar.ax.yaxis.set_major_formatter(plain)
    bar.ax.yaxis.set_minor_formatter(plain if vmax < 20 else FuncFormatter(lambda v, _: ""))
    suptitle(fig, title or f"{name} across the benchmark matrix, relative to the best")
    best = piv.idxmin(axis=0)
    worst = ratio.max(axis=0)
    ranked = ratio.median(axis=1).dropna().index
    na = [v for v in piv.index if piv.loc[v].isna().all()]
    describe(
        fig,
        f"Heatmap of the {name} of {len(piv)} variants (rows) in {piv.shape[1]} scenarios "
        f"(columns), each cell divided by the best of its scenario (1 = best, log colour "
        f"scale up to {vmax:.3g}). Best per scenario: "
        + "; ".join(f"{s}: {best[s]} (worst {worst[s]:.3g} times it)" for s in piv.columns)
        + (f". Best median ratio: {ranked[0]}; worst: {ranked[-1]}." if len(ranked) else ".")
        + (f" Not defined for {', '.join(na)}." if na else "")
        + (f" {int(div.to_numpy().sum())} cells diverged." if div.to_numpy().any() else ""),
    )
    return fig


@styled
def tradeoff_figure(curves: pd.DataFrame, points: pd.DataFrame, scenarios, title: str = ""):
    """Noise versus lag of the smoothed position per design family, one panel per scenario.

    ``curves``: :func:`abglib.bench.benchmark.tradeoff_sweep` (each family swept over its
    parameter, joined in order of the parameter); ``points``:
    :func:`abglib.bench.benchmark.tradeoff_table` (the configured variants, one marker shape
    each, in the colour of their family, named in the legend: no labels on the data).
    Both axes in metres, log scale; the legend fills the panel left free, or sits under
    the panels.
    """
    scenarios = [s for s in scenarios if s in set(curves["scenario"]) | set(points["scenario"])]
    fams = list(dict.fromkeys(curves["family"]))
    variants = list(dict.fromkeys(points["variant"]))
    marker = {v: _MARKERS[i % len(_MARKERS)] for i, v in enumerate(variants)}
    n = max(len(scenarios), 1)
    cols = 1 if n == 1 else 2
    rows = int(np.ceil(n / cols))
    spare = rows * cols > n
    fig, axes = plt.subplots(
        rows, cols, figsize=(WIDTH, 3.3 * rows + 0.9 + 1.2 * (not spare)), squeeze=False
    )
    alt = []
    for ax, sc in zip(axes.ravel(), scenarios, strict=False):
        d = curves[curves["scenario"] == sc]
        for f in fams:
            e = d[d["family"] == f].sort_values("value")
            if e.empty:
                continue
            ax.plot(
                e["noise_rms"],
                e["lag_rms"].clip(lower=1e-3),
                ".-",
                ms=3,
                color=family_colour(f),
                label=f,
            )
        p = points[points["scenario"] == sc]
        for r in p.itertuples():
            ax.plot(
                r.noise_rms,
                max(r.lag_rms, 1e-3),
                marker[r.variant],
                ms=6,
                mfc=family_colour(r.variant),
                mec="k",
                mew=0.6,
                ls="none",
                label=r.variant,
            )
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_title(sc, loc="left")
        if len(p):
            b = p.loc[p["rmse"].idxmin()]
            alt.append(
                f"{sc}: configured variants from noise {p['noise_rms'].min():.3g} to "
                f"{p['noise_rms'].max():.3g} m and lag {p['lag_rms'].min():.3g} to "
                f"{p['lag_rms'].max():.3g} m, lowest RMSE {b['variant']} "
                f"({b['rmse']:.3g} m)"
            )
    for ax in axes[:, 0]:
        ax.set_ylabel("RMS lag part of x̄ error (m)")
    for ax in axes[-1]:
        ax.set_xlabel("RMS noise part of x̄ error (m)")
    if spare:
        for ax in axes[-1, 1:]:
            ax.set_xlabel("")
        axes[-2, -1].set_xlabel("RMS noise part of x̄ error (m)")
    handles = {}
    for ax in axes.ravel()[: len(scenarios)]:
        for h_, l_ in zip(*ax.get_legend_handles_labels(), strict=True):
            handles.setdefault(l_, h_)
    fam_labels = [x for x in handles if x in fams]
    var_labels = [x for x in handles if x not in fams]
    labels = fam_labels + var_labels
    hs = [handles[k] for k in labels]
    for ax in axes.ravel()[len(scenarios) :]:
        ax.axis("off")
    if spare:  # the legend in the free panel, which holds no data
        free = axes.ravel()[-1]
        free.legend(
            hs,
            labels,
            loc="center",
            ncol=2,
            fontsize=7,
            title="design families (curves) and configured variants (markers)",
        )
    else:
        legend_outside(fig, hs, labels, side="bottom", ncol=3, fontsize=7)
    suptitle(
        fig,
        title or "Noise versus lag of x̄ per design family (each swept over its design parameter)",
    )
    describe(
        fig,
        f"Log-log noise versus lag (RMS, m) of the smoothed position, one panel per scenario "
        f"({', '.join(scenarios)}): one curve per design family ({', '.join(fams)}) swept over "
        f"its design parameter, and a marker per configured variant. " + "; ".join(alt) + ".",
    )
    return fig
