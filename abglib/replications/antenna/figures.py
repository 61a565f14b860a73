"""Figures of seed 004 (radar tracking antenna), one function per figure of the report."""

from __future__ import annotations

import numpy as np
import pandas as pd

from ...reporting.plotting import _STYLE, plt

__all__ = ["antenna_figure"]


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
        1,
        1,
        (7.0, 4.5),
    )
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
    # e below its round-off is written as the bound '<1e-10': plotted as 0
    t = t.assign(e=pd.to_numeric(t["e"], errors="coerce").fillna(0.0))
    cases = list(dict.fromkeys(t["case"]))
    fig, axes = _antenna_sweep_axes(
        "Replicates Figs I.5-I.7: tracking error e = y - z, z = 10 sin(0.1 t), Q/R = 100 "
        f"(known output and orders of prediction; {_ANTENNA_NOTE})",
        (len(cases) + 1) // 2,
        2,
        (9.0, 1.9 * ((len(cases) + 1) // 2)),
    )
    for ax, case in zip(axes.flat, cases, strict=False):
        d = t[t["case"] == case]
        ax.plot(d["t"], d["e"], lw=0.9)
        ax.set_title(case if case != "known" else "known desired output (Fig. I.5)", fontsize=8)
        ax.set_ylabel("e (-)")
        ax.set_xlabel("dimensionless time t")
    for ax in axes.flat[len(cases) :]:
        ax.set_visible(False)
    fig.tight_layout(rect=(0, 0, 1, 0.95))
    return fig


def _antenna_omega_sweep(t):
    # e_max below its round-off is written as the bound '<1e-10': not plotted
    t = t.assign(e_max=pd.to_numeric(t["e_max"], errors="coerce"))
    qrs = sorted(t["q_over_r"].unique())
    fig, axes = _antenna_sweep_axes(
        "Replicates Figs I.8 (Q/R = 100) and I.9 (Q/R = 10^4): steady-state maximum tracking "
        f"error and control against ω, amplitude 1 ({_ANTENNA_NOTE})",
        2,
        2,
        (9.0, 7.0),
    )
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
    panels = [
        ("est_err_d0", "position estimation error (Fig. I.10)"),
        ("est_err_d1", "speed estimation error (Fig. I.11)"),
        ("est_err_d2", "acceleration estimation error (Fig. I.12)"),
        ("e", "tracking error (Fig. I.13)"),
    ]
    fig, axes = _antenna_sweep_axes(
        "Replicates Figs I.10-I.13: fifth-order model, normal track, three V_w settings "
        f"({_ANTENNA_NOTE})",
        4,
        len(cases),
        (10.0, 8.5),
    )
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
        f"with Kalman estimation, amplitude 10 ({_ANTENNA_NOTE})",
        len(figs),
        2,
        (9.0, 3.0 * len(figs)),
    )
    for row, f in enumerate(figs):
        d = t[t["figure"] == f]
        for vw in dict.fromkeys(d["v_w"]):
            c = d[d["v_w"] == vw]
            axes[row, 0].loglog(c["omega"], c["e_max"], marker=".", label=f"V_w = {vw:.0e}")
            axes[row, 1].loglog(c["omega"], c["u_max"], marker=".", label=f"V_w = {vw:.0e}")
        axes[row, 0].set_title(f"Fig. {f} (a): max |e| (median over object phases)", fontsize=8)
        axes[row, 1].set_title(f"Fig. {f} (b): max |u| (median over object phases)", fontsize=8)
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
        f"amplitudes 10, 100, 1 ({_ANTENNA_NOTE})",
        len(cases),
        2,
        (9.0, 2.4 * len(cases)),
    )
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
        f"design value / real value ({_ANTENNA_NOTE})",
        2,
        3,
        (10.0, 6.0),
    )
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
        f"instead of that Kalman filter, amplitude 10, Q/R = 100 ({_ANTENNA_NOTE})",
        1,
        2,
    )
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
    "robustness": ("design_errors", _antenna_robustness),
    "abg": ("abg", _antenna_abg),
}


def antenna_figure(name: str, tables: dict):
    """One figure of the tracking-antenna report (seed 004) from the pipeline's tables.

    ``tables`` maps table stems (``taylor``, ``tracking``, ...) to DataFrames.
    """
    table, draw = _ANTENNA_FIGURES[name]
    return draw(tables[table])
