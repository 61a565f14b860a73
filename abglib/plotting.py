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
    "alwagih_causal",
    "alwagih_rmse_bars",
    "alwagih_tracks",
    "benchmark_heatmap",
    "antenna_figure",
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


# ----------------------------------------------------------- Huang et al. report (seed 002)
__all__ += ["huang_bandwidth_figure", "huang_thermal_figure", "huang_track_figure"]

_HUANG_TRACKERS = {2: "α-β", 3: "α-β-γ"}


def huang_bandwidth_figure(
    curves: pd.DataFrame, rule: str, marks: pd.DataFrame, dt: float, title: str = ""
):
    """``B_n T`` against ``xi`` for one selection rule, both trackers (seed 002, Figs 2-3).

    Parameters
    ----------
    curves : DataFrame
        ``bandwidth_curves.csv``: ``rule, order, xi, bnT_exact, bnT_closed,
        bnT_eq13_printed``.
    rule : {'type1', 'type2'}
    marks : DataFrame
        ``tables12.csv``: the printed Tables 1-2 cells, drawn at their printed ``xi`` with
        their exact ``B_n T`` (stable sets) and at the ``xi`` of the nominal ENBW.
    dt : float
        The sample interval ``T`` of the tables (``B_n`` in Hz times ``T``).
    title : str

    Returns
    -------
    matplotlib.figure.Figure
        Log ``B_n T``: solid = exact (Lyapunov), dots = the closed forms (eq 14,
        reconstructed eqs 8-13), thin dashed = eq 13 read literally.
    """
    d = curves[curves["rule"] == rule]
    mk = marks[marks["rule"] == rule]
    with plt.rc_context(_STYLE):
        fig, ax = plt.subplots(figsize=(7.0, 4.8), layout="constrained")
        for order, color in ((2, "C0"), (3, "C3")):
            c = d[d["order"] == order]
            name = _HUANG_TRACKERS[order]
            closed = "eq 14" if order == 2 else "eqs 8–13 (reconstructed)"
            ax.semilogy(
                c["xi"], c["bnT_exact"], "-", color=color, label=f"{name}: exact (Lyapunov)"
            )
            ax.semilogy(
                c["xi"].iloc[::6], c["bnT_closed"].iloc[::6], "o", ms=3.5, mfc="none",
                color=color, label=f"{name}: {closed}",
            )
            if order == 3:
                ax.semilogy(
                    c["xi"], c["bnT_eq13_printed"], "--", lw=0.9, color="C1",
                    label="α-β-γ: eq 13 read literally",
                )
            m = mk[mk["order"] == order]
            fin = m[np.isfinite(m["enbw_exact"])]
            ax.semilogy(
                fin["xi_printed"], fin["enbw_exact"] * dt,
                "s", color=color, ms=6, label=f"{name}: Table gains (printed ξ, true B_n T)",
            )
            ax.semilogy(
                m["xi_nominal"], m["bn_nominal_hz"] * dt, "x", color="k", ms=7,
                label="ξ that gives the nominal 2/10/20 Hz" if order == 2 else None,
            )
            for r in m[~np.isfinite(m["enbw_exact"])].itertuples(index=False):
                ax.annotate(
                    f"printed ξ={r.xi_printed:g}: unstable", (r.xi_printed, r.bn_nominal_hz * dt),
                    xytext=(5, 5), textcoords="offset points", fontsize=7, color=color,
                )
                ax.plot([r.xi_printed], [r.bn_nominal_hz * dt], "v", color=color, ms=6)
        for bn in (2, 10, 20):
            ax.axhline(bn * dt, color="0.6", lw=0.6, ls=":")
        ax.set_xlabel("ξ (smoothing factor)")
        ax.set_ylabel("B_n·T (one-sided ENBW × sample interval)")
        ax.set_xlim(0, 1)
        ax.legend(loc="best", fontsize=7)
        if title:
            ax.set_title(title, fontsize=9)
    return fig


def huang_thermal_figure(thermal: pd.DataFrame, budget_m: float, limits: dict, title: str = ""):
    """Thermal-noise range error against ENBW (seed 002, Fig 4).

    Parameters
    ----------
    thermal : DataFrame
        ``thermal.csv``: ``enbw_hz, sigma_printed_m, sigma_barton_m``.
    budget_m : float
        The error budget of the text (7 m).
    limits : dict
        ``{label: ENBW in Hz}`` vertical lines (the paper's 40 Hz, the computed limits).
    """
    with plt.rc_context(_STYLE):
        fig, ax = plt.subplots(figsize=(7.0, 4.6), layout="constrained")
        ax.loglog(thermal["enbw_hz"], thermal["sigma_printed_m"], "C0-",
                  label="printed formula τc / (2k √((S/N)₀ F_r / B_n))")
        ax.loglog(thermal["enbw_hz"], thermal["sigma_barton_m"], "C3--",
                  label="Barton's 2E/N₀ form (= printed formula at the two-sided ENBW)")
        ax.axhline(budget_m, color="0.3", lw=0.8, ls=":", label=f"σ = {budget_m:g} m")
        for i, (label, bn) in enumerate(limits.items()):
            ax.axvline(bn, color=f"C{i + 4}", lw=0.9, ls="-.", label=f"{label}: {bn:.1f} Hz")
        ax.set_xlabel("ENBW B_n (Hz, one-sided)")
        ax.set_ylabel("thermal-noise range error σ (m)")
        ax.legend(loc="upper left", fontsize=7)
        if title:
            ax.set_title(title, fontsize=9)
    return fig


def huang_track_figure(track: pd.DataFrame, panels: list, title: str = "", noisy: bool = True):
    """Range-tracking errors of the simulated track (seed 002, Figs 5-7).

    Parameters
    ----------
    track : DataFrame
        ``track.csv``: ``t`` and per tracker ``err_<name>`` (with noise) and
        ``lag_<name>`` (noise-free), truth minus predicted position, m.
    panels : list of (str, list of (name, label)[, list of (y, label)])
        One panel per entry: its title, the trackers to draw and, optionally, horizontal
        reference levels (m) drawn dashed.
    noisy : bool
        Draw the noisy error (thin) under the noise-free one (thick).
    """
    style = dict(_STYLE, **{"figure.figsize": (8.0, 2.6 * len(panels) + 0.6)})
    with plt.rc_context(style):
        fig, axes = plt.subplots(len(panels), 1, layout="constrained", squeeze=False)
        t = track["t"].to_numpy()
        for ax, (ptitle, names, *refs) in zip(axes[:, 0], panels, strict=True):
            for j, (y, label) in enumerate(refs[0] if refs else []):
                ax.axhline(y, color=f"C{j + 5}", lw=1.0, ls="--", label=label)
            for i, (name, label) in enumerate(names):
                if noisy:
                    ax.plot(t, track[f"err_{name}"], color=f"C{i}", lw=0.4, alpha=0.45)
                ax.plot(
                    t, track[f"lag_{name}"], color=f"C{i}", lw=1.6, label=f"{label} (noise-free)"
                )
            ax.axhline(0.0, color="k", lw=0.6)
            ax.set_ylabel("range error R − R_p (m)")
            ax.set_title(ptitle, fontsize=9)
            ax.legend(loc="best", fontsize=7)
        axes[-1, 0].set_xlabel("time (s)")
        if title:
            fig.suptitle(title, fontsize=9)
    return fig


# --------------------------------------------------------------------------- seed 001
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
# --------------------------------------------------------------------------- seed 004
_ANTENNA_NOTE = "reconstructed model: the parameter values are lost in the scan"


def _antenna_sweep_axes(fig_title, nrows=1, ncols=2, figsize=(9.0, 4.0)):
    with plt.rc_context(_STYLE):
        fig, axes = plt.subplots(nrows, ncols, figsize=figsize, squeeze=False)
    import textwrap

    fig.suptitle(textwrap.fill(fig_title, width=int(14 * figsize[0])), fontsize=9)
    return fig, axes


def _antenna_taylor(t):
    fig, ax = _antenna_sweep_axes(
        "Replicates Fig. I.4: Taylor prediction of z = sin(i/100) from i = 50 (Δt = 0.01)",
        1, 1, (7.0, 4.5))
    ax = ax[0, 0]
    ax.plot(t["i"], t["z"], "k", lw=2.0, label="real position")
    for c in [c for c in t.columns if c.startswith("order")]:
        ax.plot(t["i"], t[c], label=f"prediction ({c[5:]})")
    ax.set_ylim(-1.5, 1.5)
    ax.set_xlabel("sample i")
    ax.set_ylabel("object position z (-)")
    ax.legend(ncol=2)
    return fig


def _antenna_tracking(t):
    cases = list(dict.fromkeys(t["case"]))
    fig, axes = _antenna_sweep_axes(
        "Replicates Figs I.5-I.7: tracking error e = y - z, z = 10 sin(0.1 t), Q/R = 100 "
        f"(known output and orders of prediction; {_ANTENNA_NOTE})",
        (len(cases) + 1) // 2, 2, (9.0, 1.9 * ((len(cases) + 1) // 2)))
    for ax, case in zip(axes.flat, cases, strict=False):
        d = t[t["case"] == case]
        ax.plot(d["t"], d["e"], lw=0.9)
        ax.set_title(case if case != "known" else "known desired output (Fig. I.5)", fontsize=8)
        ax.set_ylabel("e (-)")
        ax.set_xlabel("dimensionless time t")
    for ax in axes.flat[len(cases):]:
        ax.set_visible(False)
    fig.tight_layout(rect=(0, 0, 1, 0.95))
    return fig


def _antenna_omega_sweep(t):
    qrs = sorted(t["q_over_r"].unique())
    fig, axes = _antenna_sweep_axes(
        "Replicates Figs I.8 (Q/R = 100) and I.9 (Q/R = 10^4): steady-state maximum tracking "
        f"error and control against ω, amplitude 1 ({_ANTENNA_NOTE})", 2, 2, (9.0, 7.0))
    for row, qr in enumerate(qrs):
        d = t[t["q_over_r"] == qr]
        for case in dict.fromkeys(d["case"]):
            c = d[d["case"] == case]
            style = dict(color="k", lw=2.0) if case == "known" else {}
            axes[row, 0].loglog(c["omega"], c["e_max"], label=case, **style)
            axes[row, 1].semilogx(c["omega"], c["u_max"], label=case, **style)
        axes[row, 0].set_title(f"(a) max |e|, Q/R = {qr:g}", fontsize=8)
        axes[row, 1].set_title(f"(b) max |u|, Q/R = {qr:g}", fontsize=8)
        axes[row, 0].set_ylabel("max |e| / amplitude")
        axes[row, 1].set_ylabel("max |u| (-)")
        for ax in axes[row]:
            ax.set_xlabel("frequency ratio ω")
    axes[0, 0].legend(ncol=2)
    fig.tight_layout(rect=(0, 0, 1, 0.95))
    return fig


def _antenna_kalman_vw(t):
    d = t[t["figure"] == "I.10-I.13"]
    cases = list(dict.fromkeys(d["case"]))
    panels = [("est_err_d0", "position estimation error (Fig. I.10)"),
              ("est_err_d1", "speed estimation error (Fig. I.11)"),
              ("est_err_d2", "acceleration estimation error (Fig. I.12)"),
              ("e", "tracking error (Fig. I.13)")]
    fig, axes = _antenna_sweep_axes(
        "Replicates Figs I.10-I.13: fifth-order model, normal track, three V_w settings "
        f"({_ANTENNA_NOTE})", 4, len(cases), (10.0, 8.5))
    for j, case in enumerate(cases):
        c = d[d["case"] == case]
        for i, (col, lab) in enumerate(panels):
            axes[i, j].plot(c["t"], c[col], lw=0.7)
            axes[i, j].set_title(f"{lab}\n{case}", fontsize=7)
            axes[i, j].set_xlabel("t (in units of 1/ω₀)")
            label = "e (-)" if col == "e" else f"error of z^({col[-1]}) (-)"
            axes[i, j].set_ylabel(label)
    fig.tight_layout(rect=(0, 0, 1, 0.95))
    return fig


def _antenna_kalman_sweep(t):
    figs = list(dict.fromkeys(t["figure"]))
    fig, axes = _antenna_sweep_axes(
        "Replicates Figs I.14 (5th order, Q/R = 100), I.15 (5th, 10^4), I.16 (3rd, 100): "
        f"with Kalman estimation, amplitude 10 ({_ANTENNA_NOTE})", len(figs), 2,
        (9.0, 3.0 * len(figs)))
    for row, f in enumerate(figs):
        d = t[t["figure"] == f]
        for vw in dict.fromkeys(d["v_w"]):
            c = d[d["v_w"] == vw]
            axes[row, 0].loglog(c["omega"], c["e_max"], marker=".", label=f"V_w = {vw:.0e}")
            axes[row, 1].loglog(c["omega"], c["u_max"], marker=".", label=f"V_w = {vw:.0e}")
        axes[row, 0].set_title(f"Fig. {f} (a): max |e|", fontsize=8)
        axes[row, 1].set_title(f"Fig. {f} (b): max |u|", fontsize=8)
        axes[row, 0].set_ylabel("max |e| (-)")
        axes[row, 1].set_ylabel("max |u| (-)")
        axes[row, 0].legend()
        for ax in axes[row]:
            ax.set_xlabel("frequency ratio ω")
    fig.tight_layout(rect=(0, 0, 1, 0.95))
    return fig


def _antenna_amplitude(t):
    d = t[t["figure"] == "I.17-I.19"]
    cases = list(dict.fromkeys(d["case"]))
    fig, axes = _antenna_sweep_axes(
        "Replicates Figs I.17-I.19: optimal settings (5th order, Q/R = 100), ω = 0.1, "
        f"amplitudes 10, 100, 1 ({_ANTENNA_NOTE})", len(cases), 2, (9.0, 2.4 * len(cases)))
    for row, case in enumerate(cases):
        c = d[d["case"] == case]
        axes[row, 0].plot(c["t"], c["e"], lw=0.7)
        axes[row, 1].plot(c["t"], c["u"], lw=0.7)
        axes[row, 0].set_title(f"tracking error, {case}", fontsize=8)
        axes[row, 1].set_title(f"control input, {case}", fontsize=8)
        axes[row, 0].set_ylabel("e (-)")
        axes[row, 1].set_ylabel("u (-)")
        for ax in axes[row]:
            ax.set_xlabel("t (in units of 1/ω₀)")
    fig.tight_layout(rect=(0, 0, 1, 0.95))
    return fig


def _antenna_robustness(t):
    names = list(dict.fromkeys(t["parameter"]))
    fig, axes = _antenna_sweep_axes(
        "Replicates Figs I.20 (β_d), I.21 (β_a), I.22 (p_a) and app. H's p_f, β_f, κ: "
        f"design value / real value ({_ANTENNA_NOTE})", 2, 3, (10.0, 6.0))
    for ax, name in zip(axes.flat, names, strict=False):
        d = t[t["parameter"] == name]
        e = d["e_max"].replace(np.inf, np.nan).clip(upper=1e3)
        ax.loglog(d["factor"], e, ".-", label="max |e| (simulated)")
        un = d[~d["stable"].astype(bool)]
        if len(un):
            ax.loglog(un["factor"], e[un.index].fillna(1e3), "rx", label="unstable (radius > 1)")
        ax.axvline(1.0, color="k", lw=0.6)
        if name == "p_a":  # the stable window is narrow: zoom in (Fig. I.22)
            ax.set_xscale("linear")
            ax.set_xlim(0.95, 1.05)
        ax.set_title(f"{name} (max |e| capped at 1e3)", fontsize=8)
        ax.set_xlabel("multiplication factor")
        ax.set_ylabel("max |e| (-)")
    axes.flat[0].legend(loc="upper right", fontsize=7)
    fig.tight_layout(rect=(0, 0, 1, 0.95))
    return fig


def _antenna_abg(t):
    fig, axes = _antenna_sweep_axes(
        "Beyond the source: critically damped α-β-γ with the ENBW of a Kalman object predictor "
        f"instead of that Kalman filter, amplitude 10, Q/R = 100 ({_ANTENNA_NOTE})", 1, 2)
    curves = [
        ("kalman5", "Kalman, 5th-order model", dict(color="C0")),
        ("abg5", "α-β-γ, ENBW of the 5th-order Kalman", dict(color="C0", ls="--")),
        ("kalman2", "Kalman, 2nd-order model", dict(color="C1")),
        ("abg2", "α-β-γ, ENBW of the 2nd-order Kalman", dict(color="C1", ls="--")),
    ]
    for key, label, style in curves:
        axes[0, 0].loglog(t["omega"], t[f"e_max_{key}"], marker=".", label=label, **style)
        axes[0, 1].loglog(t["omega"], t[f"u_max_{key}"], marker=".", label=label, **style)
    axes[0, 0].set_ylabel("max |e| (-)")
    axes[0, 1].set_ylabel("max |u| (-)")
    for ax in axes[0]:
        ax.set_xlabel("frequency ratio ω")
    axes[0, 0].legend(fontsize=7)
    fig.tight_layout(rect=(0, 0, 1, 0.9))
    return fig


_ANTENNA_FIGURES = {
    "taylor": ("taylor", _antenna_taylor),
    "tracking": ("tracking", _antenna_tracking),
    "omega_sweep": ("omega_sweep", _antenna_omega_sweep),
    "kalman_vw": ("kalman_runs", _antenna_kalman_vw),
    "kalman_sweep": ("kalman_sweep", _antenna_kalman_sweep),
    "amplitude": ("kalman_runs", _antenna_amplitude),
    "robustness": ("robustness", _antenna_robustness),
    "abg": ("abg", _antenna_abg),
}


def antenna_figure(name: str, tables: dict):
    """One figure of the tracking-antenna report (seed 004) from the pipeline's tables.

    ``tables`` maps table stems (``taylor``, ``tracking``, ...) to DataFrames.
    """
    table, draw = _ANTENNA_FIGURES[name]
    return draw(tables[table])
