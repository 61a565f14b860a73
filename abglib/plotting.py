"""Figures (the only module that imports matplotlib).

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
    "benchmark_heatmap",
    "frequency_response_figure",
    "response_grid",
    "save_figure",
    "stability_triangle",
    "tradeoff_figure",
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


# --------------------------------------------------------------------------- benchmark
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
                ax.text(j, i, text, ha="center", va="center", fontsize=6, color="k")
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
