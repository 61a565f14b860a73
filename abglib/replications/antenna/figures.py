"""Figures of seed 004 (radar tracking antenna), one function per figure of the report."""

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
)

__all__ = ["antenna_figure"]


_ANTENNA_NOTE = "reconstructed model: the parameter values are lost in the scan"


def _order_colours(cases) -> dict:
    """Prediction orders (``'order 1'``...) in a sequential palette; the known desired
    output (the reference the predictions try to reach) black."""
    orders = [c for c in cases if c != "known"]
    cmap = plt.get_cmap("viridis")
    out = {c: cmap(0.85 * i / max(len(orders) - 1, 1)) for i, c in enumerate(orders)}
    out["known"] = REFERENCE["truth"]
    return out


def _grid(title, nrows, ncols, height, **kw):
    fig, axes = plt.subplots(nrows, ncols, figsize=(WIDTH, height), squeeze=False, **kw)
    suptitle(fig, title)
    return fig, axes


def _span(x) -> str:
    x = np.asarray(x, dtype=float)
    x = x[np.isfinite(x)]
    return f"{x.min():.3g} to {x.max():.3g}" if x.size else "no finite values"


def _antenna_taylor(t):
    cols = [c for c in t.columns if c.startswith("order")]
    colours = _order_colours([f"order {c[5:]}" for c in cols])
    fig, ax = _grid(
        "Replicates Fig. I.4: Taylor prediction of z = sin(i/100) from i = 50 (Δt = 0.01)",
        1,
        1,
        4.2,
    )
    ax = ax[0, 0]
    ax.plot(t["i"], t["z"], color=REFERENCE["truth"], lw=2.0, label="real position")
    dev = []
    for c in cols:
        ax.plot(t["i"], t[c], color=colours[f"order {c[5:]}"], label=f"prediction, order {c[5:]}")
        off = np.abs(t[c] - t["z"]) > 0.1
        first = t["i"][off].min() if off.any() else None
        dev.append(f"order {c[5:]} " + (f"from i = {first:g}" if first is not None else "never"))
    ax.set_ylim(-1.5, 1.5)
    ax.set_xlabel("sample i")
    ax.set_ylabel("object position z (-)")
    legend_outside(ax, side="right")
    describe(
        fig,
        f"Replicates Fig. I.4: the real position z = sin(i/100) for i from {t['i'].min():g} "
        f"to {t['i'].max():g} and its Taylor predictions of orders 1 to {len(cols)} made at "
        f"i = 50 (y axis cut at ±1.5). Each prediction leaves the real position by more "
        f"than 0.1: " + ", ".join(dev) + ".",
    )
    return fig


def _antenna_tracking(t):
    # e below its round-off is written as the bound '<1e-10': plotted as 0
    t = t.assign(e=pd.to_numeric(t["e"], errors="coerce").fillna(0.0))
    cases = list(dict.fromkeys(t["case"]))
    rows = (len(cases) + 1) // 2
    fig, axes = _grid(
        "Replicates Figs I.5-I.7: tracking error e = y − z, z = 10 sin(0.1 t), Q/R = 100, "
        f"known output and orders of prediction ({_ANTENNA_NOTE})",
        rows,
        2,
        1.55 * rows + 1.0,
        sharex=True,
        sharey=True,
    )
    colours = _order_colours(cases)
    tail = []
    for ax, case in zip(axes.flat, cases, strict=False):
        d = t[t["case"] == case]
        ax.plot(d["t"], d["e"], lw=0.9, color=colours[case])
        ax.set_title(case if case != "known" else "known desired output (Fig. I.5)", loc="left")
        late = d[d["t"] >= d["t"].max() / 2]
        tail.append(f"{case} {late['e'].abs().max():.2g}")
    for ax in axes[:, 0]:
        ax.set_ylabel("e (-)")
    for ax in axes[-1]:
        ax.set_xlabel("dimensionless time t")
    for ax in axes.flat[len(cases) :]:
        ax.set_visible(False)
    describe(
        fig,
        f"Replicates Figs I.5-I.7: {len(cases)} panels of the tracking error e against "
        f"time (0 to {t['t'].max():g}), e from {_span(t['e'])}; every case starts with the "
        f"same transient; largest |e| over the second half: " + ", ".join(tail) + ".",
    )
    return fig


def _antenna_omega_sweep(t):
    # e_max below its round-off is written as the bound '<1e-10': not plotted
    t = t.assign(e_max=pd.to_numeric(t["e_max"], errors="coerce"))
    qrs = sorted(t["q_over_r"].unique())
    fig, axes = _grid(
        "Replicates Figs I.8 (Q/R = 100) and I.9 (Q/R = 10⁴): steady-state maximum tracking "
        f"error and control against ω, amplitude 1 ({_ANTENNA_NOTE})",
        len(qrs),
        2,
        2.6 * len(qrs) + 1.2,
        sharex=True,
    )
    colours = _order_colours(list(dict.fromkeys(t["case"])))
    for row, qr in enumerate(qrs):
        d = t[t["q_over_r"] == qr]
        for case in dict.fromkeys(d["case"]):
            c = d[d["case"] == case]
            style = dict(color=colours[case], lw=2.0 if case == "known" else 1.4)
            axes[row, 0].loglog(c["omega"], c["e_max"], label=case, **style)
            axes[row, 1].semilogx(c["omega"], c["u_max"], label=case, **style)
        axes[row, 0].set_title(f"(a) max |e|, Q/R = {qr:g}", loc="left")
        axes[row, 1].set_title(f"(b) max |u|, Q/R = {qr:g}", loc="left")
        axes[row, 0].set_ylabel("max |e| / amplitude")
        axes[row, 1].set_ylabel("max |u| (-)")
    for ax in axes[-1]:
        ax.set_xlabel("frequency ratio ω")
    legend_outside(fig, *axes[0, 0].get_legend_handles_labels(), side="bottom", ncol=len(colours))
    at1 = t[t["omega"] == t["omega"].max()]
    describe(
        fig,
        f"Replicates Figs I.8-I.9: log-log max |e| and log-linear max |u| against ω from "
        f"{t['omega'].min():g} to {t['omega'].max():g}, one row per Q/R "
        f"({', '.join(f'{q:g}' for q in qrs)}), one curve per case; the error grows with ω "
        f"and falls with the order of prediction; at ω = {t['omega'].max():g} max |e| spans "
        f"{_span(at1['e_max'])} and max |u| {_span(at1['u_max'])}.",
    )
    return fig


def _antenna_kalman_vw(t):
    d = t[t["figure"] == "I.10-I.13"]
    cases = list(dict.fromkeys(d["case"]))
    panels = [
        ("est_err_d0", "position estimation error (Fig. I.10)", "z"),
        ("est_err_d1", "speed estimation error (Fig. I.11)", "ż"),
        ("est_err_d2", "acceleration estimation error (Fig. I.12)", "z̈"),
        ("e", "tracking error (Fig. I.13)", "e"),
    ]
    fig, axes = _grid(
        "Replicates Figs I.10-I.13: fifth-order model, normal track, three V_w settings; rows: "
        "estimation errors of position, speed, acceleration and the tracking error "
        f"({_ANTENNA_NOTE})",
        4,
        len(cases),
        7.6,
        sharex=True,
        sharey="row",
    )
    rms = []
    for j, case in enumerate(cases):
        c = d[d["case"] == case]
        axes[0, j].set_title(case.replace(", ", "\n"), fontsize=8)
        for i, (col, _lab, sym) in enumerate(panels):
            axes[i, j].plot(c["t"], c[col], lw=0.6, color=family_colour("Kalman"))
            if j == 0:
                axes[i, j].set_ylabel(f"error of {sym} (-)" if col != "e" else "e (-)")
        rms.append(
            f"{case}: RMS position error {np.sqrt(np.mean(c['est_err_d0'] ** 2)):.3g}, "
            f"RMS tracking error {np.sqrt(np.mean(c['e'] ** 2)):.3g}"
        )
    for ax in axes[-1]:
        ax.set_xlabel("t (in units of 1/ω₀)")
    describe(
        fig,
        f"Replicates Figs I.10-I.13: a grid of 4 rows (estimation errors of position, speed "
        f"and acceleration, then the tracking error) by {len(cases)} columns (V_w settings) "
        f"against time; " + "; ".join(rms) + ".",
    )
    return fig


def _antenna_kalman_sweep(t):
    figs = list(dict.fromkeys(t["figure"]))
    fig, axes = _grid(
        "Replicates Figs I.14 (5th order, Q/R = 100), I.15 (5th, 10⁴), I.16 (3rd, 100): "
        f"with Kalman estimation, amplitude 10, median over object phases ({_ANTENNA_NOTE})",
        len(figs),
        2,
        2.3 * len(figs) + 1.2,
        sharex=True,
    )
    for row, f in enumerate(figs):
        d = t[t["figure"] == f]
        vws = list(dict.fromkeys(d["v_w"]))
        greys = [plt.get_cmap("viridis")(0.85 * k / max(len(vws) - 1, 1)) for k in range(len(vws))]
        for vw, col in zip(vws, greys, strict=True):
            c = d[d["v_w"] == vw]
            kw = dict(marker=".", color=col, label=f"V_w = {vw:.0e}")
            axes[row, 0].loglog(c["omega"], c["e_max"], **kw)
            axes[row, 1].loglog(c["omega"], c["u_max"], **kw)
        axes[row, 0].set_title(f"Fig. {f} (a): max |e|", loc="left")
        axes[row, 1].set_title(f"Fig. {f} (b): max |u|", loc="left")
        axes[row, 0].set_ylabel("max |e| (-)")
        axes[row, 1].set_ylabel("max |u| (-)")
        legend_outside(axes[row, 1], side="right")
    for ax in axes[-1]:
        ax.set_xlabel("frequency ratio ω")
    describe(
        fig,
        f"Replicates Figs I.14-I.16: {len(figs)} rows of log-log max |e| and max |u| against "
        f"ω from {t['omega'].min():g} to {t['omega'].max():g}, one curve per V_w; max |e| "
        f"stays near {t[t['omega'] == t['omega'].min()]['e_max'].median():.2g} at low ω and "
        f"rises to {_span(t[t['omega'] == t['omega'].max()]['e_max'])} at ω = "
        f"{t['omega'].max():g}.",
    )
    return fig


def _antenna_amplitude(t):
    d = t[t["figure"] == "I.17-I.19"]
    cases = list(dict.fromkeys(d["case"]))
    fig, axes = _grid(
        "Replicates Figs I.17-I.19: optimal settings (5th order, Q/R = 100), ω = 0.1, "
        f"amplitudes 10, 100, 1 ({_ANTENNA_NOTE})",
        len(cases),
        2,
        1.9 * len(cases) + 1.0,
        sharex=True,
    )
    col = family_colour("Kalman")
    peaks = []
    for row, case in enumerate(cases):
        c = d[d["case"] == case]
        axes[row, 0].plot(c["t"], c["e"], lw=0.6, color=col)
        axes[row, 1].plot(c["t"], c["u"], lw=0.6, color=col)
        axes[row, 0].set_title(f"tracking error, {case}", loc="left")
        axes[row, 1].set_title(f"control input, {case}", loc="left")
        axes[row, 0].set_ylabel("e (-)")
        axes[row, 1].set_ylabel("u (-)")
        peaks.append(f"{case}: max |e| {c['e'].abs().max():.3g}, max |u| {c['u'].abs().max():.3g}")
    for ax in axes[-1]:
        ax.set_xlabel("t (in units of 1/ω₀)")
    describe(
        fig,
        "Replicates Figs I.17-I.19: tracking error (left) and control input (right) "
        "against time, one row per amplitude; " + "; ".join(peaks) + ".",
    )
    return fig


def _antenna_robustness(t):
    names = list(dict.fromkeys(t["parameter"]))
    fig, axes = _grid(
        "Replicates Figs I.20 (β_d), I.21 (β_a), I.22 (p_a) and app. H's p_f, β_f, κ: "
        f"max |e| against design value / real value, capped at 10³ ({_ANTENNA_NOTE})",
        2,
        3,
        5.0,
    )
    col = family_colour("Kalman")
    windows = []
    for ax, name in zip(axes.flat, names, strict=False):
        d = t[t["parameter"] == name]
        e = d["e_max"].replace(np.inf, np.nan).clip(upper=1e3)
        ax.loglog(d["factor"], e, ".-", color=col, ms=3, label="max |e| (simulated)")
        stable = d["stable"].astype(bool)
        un = d[~stable]
        ax.loglog(
            un["factor"],
            e[un.index].fillna(1e3),
            "x",
            color="#d62728",
            label="unstable (spectral radius > 1)",
        )
        ax.axvline(1.0, color=REFERENCE["zero"], lw=0.6)
        if name == "p_a":  # the stable window is narrow: zoom in (Fig. I.22)
            ax.set_xscale("linear")
            ax.set_xlim(0.95, 1.05)
        ax.set_title(name, loc="left")
        f = d["factor"][stable]
        # the plotted grid points, not the edges: stability.csv locates each edge between
        # the last stable and the first unstable grid point
        inside = (d["factor"] >= f.min()) & (d["factor"] <= f.max()) if len(f) else stable
        which = "every" if bool(stable[inside].all()) else "some"
        windows.append(
            f"{name} stable at {which} plotted factor from {f.min():g} to {f.max():g}"
            if len(f)
            else f"{name} stable at no plotted factor"
        )
    for ax in axes[:, 0]:
        ax.set_ylabel("max |e| (-)")
    for ax in axes[-1]:
        ax.set_xlabel("multiplication factor")
    for ax in axes.flat[len(names) :]:
        ax.set_visible(False)
    legend_outside(fig, *axes.flat[0].get_legend_handles_labels(), side="bottom", ncol=2)
    describe(
        fig,
        "Replicates Figs I.20-I.22 and appendix H: one panel per model parameter, the "
        "simulated max |e| (capped at 1000) against the factor between design and real "
        "value, unstable settings crossed; " + "; ".join(windows) + " (the outermost stable "
        "grid points; the stability edges between grid points, refined by root finding, are "
        "in the stability table).",
    )
    return fig


def _antenna_abg(t):
    fig, axes = _grid(
        "Beyond the source: critically damped α-β-γ with the ENBW of a Kalman object predictor "
        f"instead of that Kalman filter, amplitude 10, Q/R = 100 ({_ANTENNA_NOTE})",
        1,
        2,
        3.9,
        sharex=True,
    )
    kal, abg = family_colour("Kalman"), family_colour("standard α-β-γ")
    curves = [
        ("kalman5", "Kalman, 5th-order model", dict(color=kal)),
        ("abg5", "α-β-γ, ENBW of the 5th-order Kalman", dict(color=abg)),
        ("kalman2", "Kalman, 2nd-order model", dict(color=kal, ls="--")),
        ("abg2", "α-β-γ, ENBW of the 2nd-order Kalman", dict(color=abg, ls="--")),
    ]
    for key, label, style in curves:
        axes[0, 0].loglog(t["omega"], t[f"e_max_{key}"], marker=".", label=label, **style)
        axes[0, 1].loglog(t["omega"], t[f"u_max_{key}"], marker=".", label=label, **style)
    axes[0, 0].set_ylabel("max |e| (-)")
    axes[0, 1].set_ylabel("max |u| (-)")
    for ax in axes[0]:
        ax.set_xlabel("frequency ratio ω")
    legend_outside(fig, *axes[0, 0].get_legend_handles_labels(), side="bottom", ncol=2)
    lo = t[t["omega"] == t["omega"].min()].iloc[0]
    describe(
        fig,
        f"Beyond the source: log-log max |e| (left) and max |u| (right) against ω from "
        f"{t['omega'].min():g} to {t['omega'].max():g} for the Kalman filters of the 5th- and "
        f"2nd-order models and the critically damped α-β-γ trackers of the same ENBW; at "
        f"ω = {lo['omega']:g} max |e| is {lo['e_max_kalman5']:.3g} (Kalman 5th) against "
        f"{lo['e_max_abg5']:.3g} (α-β-γ), and {lo['e_max_kalman2']:.3g} (Kalman 2nd) against "
        f"{lo['e_max_abg2']:.3g} (α-β-γ).",
    )
    return fig


_ANTENNA_FIGURES = {
    "taylor": ("taylor", _antenna_taylor),
    "tracking": ("tracking", _antenna_tracking),
    "omega_sweep": ("omega_sweep", _antenna_omega_sweep),
    "kalman_vw": ("kalman_runs", _antenna_kalman_vw),
    "kalman_sweep": ("kalman_sweep", _antenna_kalman_sweep),
    "amplitude": ("kalman_runs", _antenna_amplitude),
    "robustness": ("design_errors", _antenna_robustness),
    "abg": ("abg", _antenna_abg),
}


def antenna_figure(name: str, tables: dict):
    """One figure of the tracking-antenna report (seed 004) from the pipeline's tables.

    ``tables`` maps table stems (``taylor``, ``tracking``, ...) to DataFrames.
    """
    if name not in _ANTENNA_FIGURES:
        raise ValueError(f"name must be one of {sorted(_ANTENNA_FIGURES)}, got {name!r}")
    table, draw = _ANTENNA_FIGURES[name]
    return styled(draw)(tables[table])
