"""Figures of the benchmark matrix: league heatmap and noise-versus-lag trade-off curves."""

from __future__ import annotations

import numpy as np
import pandas as pd

from ..reporting.plotting import _STYLE, plt

__all__ = ['benchmark_heatmap', 'tradeoff_figure']


def benchmark_heatmap(league: pd.DataFrame, metric: str = "rmse_x_smooth", title: str = ""):
    """Heatmap of one metric over the benchmark matrix (variants x scenarios).

    Each column (scenario) is divided by its best (smallest) value, so colours compare
    variants within a scenario; the cell text is that ratio. Diverged cells are grey and
    marked ``div``.
    """
    from matplotlib.colors import LogNorm

    piv = league.pivot(index="variant", columns="scenario", values=metric).astype(float)
    div = league.pivot(index="variant", columns="scenario", values="diverged").astype(bool)
    order = piv.div(piv.min(axis=0), axis=1).median(axis=1).sort_values().index
    piv, div = piv.loc[order], div.loc[order]
    ratio = piv.div(piv.min(axis=0), axis=1)
    with plt.rc_context(_STYLE):
        h = max(3.0, 0.32 * len(piv) + 1.8)
        w = max(6.0, 0.55 * piv.shape[1] + 3.5)
        fig, ax = plt.subplots(figsize=(w, h))
        data = np.ma.masked_invalid(ratio.to_numpy())
        cmap = plt.get_cmap("viridis_r").copy()
        cmap.set_bad("0.8")
        vmax = max(float(np.nanmax(ratio.to_numpy())) if data.count() else 2.0, 1.01)
        im = ax.imshow(data, aspect="auto", cmap=cmap, norm=LogNorm(1.0, vmax))
        for i in range(ratio.shape[0]):
            for j in range(ratio.shape[1]):
                v = ratio.iat[i, j]
                text = "div" if div.iat[i, j] else ("" if not np.isfinite(v) else f"{v:.2g}")
                # white text on the dark end of the colour map, black elsewhere
                dark = np.isfinite(v) and im.norm(v) > 0.6
                ax.text(j, i, text, ha="center", va="center", fontsize=6,
                        color="w" if dark else "k")
        ax.set_xticks(range(piv.shape[1]), piv.columns, rotation=60, ha="right")
        ax.set_yticks(range(piv.shape[0]), piv.index)
        ax.set_xlabel("scenario")
        ax.set_ylabel("variant")
        ax.grid(False)
        fig.colorbar(im, ax=ax, label=f"{metric} / best in scenario (log scale)")
        ax.set_title(title or f"{metric} across the benchmark matrix, relative to the best")
        fig.tight_layout()
    return fig


def tradeoff_figure(curves: pd.DataFrame, points: pd.DataFrame, scenarios, title: str = ""):
    """Noise versus lag of the smoothed position per design family, one panel per scenario.

    ``curves``: :func:`abglib.benchmark.tradeoff_sweep` (each family swept over its
    parameter, joined in order of the parameter); ``points``:
    :func:`abglib.benchmark.tradeoff_table` (the configured variants, drawn as labelled
    markers). Both axes in metres, log scale.
    """
    scenarios = [s for s in scenarios if s in set(curves["scenario"]) | set(points["scenario"])]
    fams = list(dict.fromkeys(curves["family"]))
    colours = {f: plt.get_cmap("tab10")(i % 10) for i, f in enumerate(fams)}
    n = max(len(scenarios), 1)
    cols = min(n, 3)
    rows = int(np.ceil(n / cols))
    with plt.rc_context(_STYLE):
        fig, axes = plt.subplots(rows, cols, figsize=(4.4 * cols, 3.8 * rows + 1.0), squeeze=False)
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
                    ms=4,
                    color=colours[f],
                    label=f,
                )
            p = points[points["scenario"] == sc]
            ax.plot(
                p["noise_rms"],
                p["lag_rms"].clip(lower=1e-3),
                "kx",
                ms=5,
                label="configured variants",
            )
            for r in p.itertuples():
                ax.annotate(
                    r.variant,
                    (r.noise_rms, max(r.lag_rms, 1e-3)),
                    fontsize=5,
                    xytext=(2, 2),
                    textcoords="offset points",
                )
            ax.set_xscale("log")
            ax.set_yscale("log")
            ax.set_xlabel("RMS noise part of x̄ error (m)")
            ax.set_ylabel("RMS lag part of x̄ error (m)")
            ax.set_title(sc)
        for ax in axes.ravel()[len(scenarios) :]:
            ax.set_visible(False)
        handles, labels = {}, []
        for ax in axes.ravel()[: len(scenarios)]:
            for h_, l_ in zip(*ax.get_legend_handles_labels(), strict=True):
                handles.setdefault(l_, h_)
        labels = list(handles)
        fig.legend(
            [handles[k] for k in labels],
            labels,
            loc="lower center",
            ncol=min(4, len(labels)),
            fontsize=7,
        )
        fig.suptitle(
            title
            or "Noise versus lag of x̄ per design family\n(each swept over its design parameter)"
        )
        fig.tight_layout(rect=(0, 0.06 + 0.025 * (len(labels) // 4), 1, 1))
    return fig
