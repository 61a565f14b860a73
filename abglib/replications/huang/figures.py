"""Figures of seed 002 (Huang, Yang and Ma): ENBW against xi, thermal error, range tracks."""

from __future__ import annotations

import numpy as np
import pandas as pd

from ...reporting.plotting import _STYLE, plt

__all__ = [
    "huang_bandwidth_figure",
    "huang_figures",
    "huang_thermal_figure",
    "huang_track_figure",
]



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
                label="ξ that gives the nominal ENBW" if order == 2 else None,
            )
            for r in m[~np.isfinite(m["enbw_exact"])].itertuples(index=False):
                ax.annotate(
                    f"printed ξ={r.xi_printed:g}: unstable", (r.xi_printed, r.bn_nominal_hz * dt),
                    xytext=(5, 5), textcoords="offset points", fontsize=7, color=color,
                )
                ax.plot([r.xi_printed], [r.bn_nominal_hz * dt], "v", color=color, ms=6)
        for bn in sorted(set(mk["bn_nominal_hz"])):
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


def huang_figures(tables: dict, published: pd.DataFrame, cfg: dict) -> dict:
    """Every figure of the report (seed 002, Figs 2-7), from the study's tables.

    Parameters
    ----------
    tables : dict
        ``bandwidth_curves``, ``tables12``, ``thermal``, ``track``, ``track_metrics``
        (``results/huang/*.csv``).
    published : DataFrame
        The transcription (:func:`abglib.reporting.compare.read_published`): the stated
        ENBW limit of Fig 4 is drawn from it.
    cfg : dict
        The ``huang`` config section.

    Returns
    -------
    dict
        ``{"fig2": Figure, ..., "fig7": Figure}``.
    """
    from .printed import bandwidth_for_sigma, steady_state_lag_huang

    radar, sim = cfg["radar"], cfg["simulation"]
    dt = 1.0 / radar["fr_hz"]
    out = {}
    for rule, name, roman in (("type1", "fig2", "I"), ("type2", "fig3", "II")):
        title = (
            f"Replicates seed 002, Fig {name[-1]}: relation of B_n·T and ξ (type {roman} "
            "parameters selecting), α-β and α-β-γ"
        )
        out[name] = huang_bandwidth_figure(
            tables["bandwidth_curves"], rule, tables["tables12"], dt, title
        )

    budget = cfg["sigma_budget_m"]
    stated = float(published.set_index("key").loc["fig4.enbw_limit", "published"])
    args = (radar["fr_hz"], radar["tau_s"], radar["snr_db"], radar["k"])
    limits = {
        f"paper: 'ENBW should be under {stated:g}Hz'": stated,
        f"printed formula, σ = {budget:g} m": bandwidth_for_sigma(budget, *args),
        f"Barton form, σ = {budget:g} m": bandwidth_for_sigma(budget, *args, form="barton"),
    }
    title = (
        "Replicates seed 002, Fig 4: thermal-noise range error against ENBW\n"
        f"(F_r = {radar['fr_hz']:g} Hz, τ = {radar['tau_s'] * 1e6:g} µs, "
        f"(S/N)₀ = {radar['snr_db']:g} dB, k = {radar['k']:g})"
    )
    out["fig4"] = huang_thermal_figure(tables["thermal"], budget, limits, title)

    trk, m = tables["track"], tables["track_metrics"].set_index("tracker")
    accel, gate = cfg["target"]["accel"], float(m["gate_m"].iloc[0])

    def lag(name):
        return steady_state_lag_huang(m.loc[name, "beta"], accel, dt)

    def gains(name):
        r = m.loc[name]
        g = f", {r['gamma_h']:.3g}" if r["gamma_h"] else ""
        return f"({r['alpha']:.3g}, {r['beta']:.3g}{g}), ENBW {r['enbw_hz']:.3g} Hz"

    f5, lo = f"{sim['fig5_enbw_hz']:g}", f"{sim['low_enbw_hz']:g}"
    ab5, abg5p, ab2 = f"ab_t2_{f5}_printed", f"abg_t2_{f5}_printed", f"ab_t2_{lo}_printed"
    panels = [
        (
            f"type II, ENBW {f5} Hz: α-β (printed gains) vs α-β-γ (gains of a true {f5} Hz)",
            [(ab5, f"α-β printed {gains(ab5)}"), (f"abg_t2_{f5}", f"α-β-γ type II, true {f5} Hz")],
            [(lag(ab5), f"A/(βF_r²) = {lag(ab5):.2f} m")],
        ),
        (
            f"type II α-β-γ with the gains printed for {f5} Hz: their true ENBW is "
            f"{m.loc[abg5p, 'enbw_hz']:.0f} Hz",
            [(abg5p, f"α-β-γ printed {gains(abg5p)}")],
        ),
        (
            f"type II, ENBW {lo} Hz: the initial error of α-β",
            [(ab2, f"α-β printed {gains(ab2)}"), (f"abg_t2_{lo}", f"α-β-γ type II, true {lo} Hz")],
            [
                (lag(ab2), f"A/(βF_r²) = {lag(ab2):.1f} m"),
                (gate, f"assumed discriminator edge {gate:.1f} m"),
            ],
        ),
    ]
    title = (
        f"Replicates seed 002, Fig 5: performances of tracking loops (A = {accel:g} m/s², "
        f"B = {cfg['target']['jerk']:g} m/s³, thin: with thermal noise)"
    )
    out["fig5"] = huang_track_figure(trk, panels, title)
    for rule, name in (("1", "fig6"), ("2", "fig7")):
        roman = "I" * int(rule)
        panels = [
            (
                f"type {roman} α-β-γ, true ENBW {bn:g} Hz",
                [(f"abg_t{rule}_{bn:g}", f"type {roman}, {bn:g} Hz")],
            )
            for bn in sim["residual_enbw_hz"]
        ]
        title = (
            f"Replicates seed 002, Fig {name[-1]}: tracking position residual error "
            f"(type {roman} parameters selecting), thin: with thermal noise"
        )
        out[name] = huang_track_figure(trk, panels, title)
    return out
