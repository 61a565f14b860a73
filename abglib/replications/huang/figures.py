"""Figures of seed 002 (Huang, Yang and Ma): ENBW against xi, thermal error, range tracks."""

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

__all__ = [
    "huang_bandwidth_figure",
    "huang_figures",
    "huang_thermal_figure",
    "huang_track_figure",
]


_HUANG_TRACKERS = {2: "α-β", 3: "α-β-γ"}
_ROMAN = {"type1": "I", "type2": "II", "1": "I", "2": "II"}


def _family(rule: str, order: int) -> str:
    """The benchmark family of a Huang tracker: ``'Huang type II α-β-γ'``."""
    return f"Huang type {_ROMAN[rule]} {_HUANG_TRACKERS[order]}"


def _tracker_family(name: str) -> str:
    """Family of a tracker of ``track.csv`` from its name, e.g. ``abg_t2_10`` -> type II α-β-γ."""
    kind, rule = name.split("_")[:2]
    return _family(rule[1:], 3 if kind == "abg" else 2)


@styled
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
        Log ``B_n T``: solid = exact (Lyapunov), circles = the closed forms (eq 14,
        reconstructed eqs 8-13), thin dashed = eq 13 read literally; triangles = printed
        gain sets that are unstable, drawn at their nominal ``B_n T``. Legend below.
    """
    if rule not in _ROMAN:
        raise ValueError(f"rule must be one of ['type1', 'type2'], got {rule!r}")
    d = curves[curves["rule"] == rule]
    mk = marks[marks["rule"] == rule]
    fig, ax = plt.subplots(figsize=(WIDTH, 5.4))
    unstable_all = []
    for order in (2, 3):
        color = family_colour(_family(rule, order))
        c = d[d["order"] == order]
        name = _HUANG_TRACKERS[order]
        closed = "eq 14" if order == 2 else "eqs 8–13 (reconstructed)"
        ax.semilogy(c["xi"], c["bnT_exact"], "-", color=color, label=f"{name}: exact (Lyapunov)")
        ax.semilogy(
            c["xi"].iloc[::6],
            c["bnT_closed"].iloc[::6],
            "o",
            ms=3.5,
            mfc="none",
            color=color,
            label=f"{name}: {closed}",
        )
        if order == 3:
            ax.semilogy(
                c["xi"],
                c["bnT_eq13_printed"],
                "--",
                lw=0.9,
                color=color,
                alpha=0.7,
                label="α-β-γ: eq 13 read literally",
            )
        m = mk[mk["order"] == order]
        fin = m[np.isfinite(m["enbw_exact"])]
        ax.semilogy(
            fin["xi_printed"],
            fin["enbw_exact"] * dt,
            "s",
            color=color,
            ms=6,
            label=f"{name}: Table gains (printed ξ, true B_n·T)",
        )
        uns = m[~np.isfinite(m["enbw_exact"])]
        if len(uns):
            ax.semilogy(
                uns["xi_printed"],
                uns["bn_nominal_hz"] * dt,
                "v",
                color=color,
                ms=7,
                label=f"{name}: Table gains, unstable (printed ξ, nominal B_n·T)",
            )
            unstable_all += [f"{name} at printed ξ = {x:g}" for x in uns["xi_printed"]]
        ax.semilogy(
            m["xi_nominal"],
            m["bn_nominal_hz"] * dt,
            "x",
            color=REFERENCE["truth"],
            ms=7,
            label="ξ that gives the nominal ENBW" if order == 2 else None,
        )
    nominal = sorted(set(mk["bn_nominal_hz"]))
    for i, bn in enumerate(nominal):
        ax.axhline(
            bn * dt,
            color=REFERENCE["level"],
            lw=0.6,
            ls=":",
            label="nominal ENBWs of the table" if i == 0 else None,
        )
    ax.set_xlabel("ξ (smoothing factor)")
    ax.set_ylabel("B_n·T (one-sided ENBW × sample interval)")
    ax.set_xlim(0, 1)
    if title:
        suptitle(fig, title)
    # the legend in two columns, α-β (and the references) left, α-β-γ right
    h, lab = ax.get_legend_handles_labels()
    left = [i for i, x in enumerate(lab) if not x.startswith("α-β-γ")]
    right = [i for i, x in enumerate(lab) if x.startswith("α-β-γ")]
    blank = plt.Line2D([], [], alpha=0.0)
    n = max(len(left), len(right))
    hs = [h[i] for i in left] + [blank] * (n - len(left)) + [h[i] for i in right]
    hs += [blank] * (n - len(right))
    ls = [lab[i] for i in left] + [""] * (n - len(left)) + [lab[i] for i in right]
    ls += [""] * (n - len(right))
    legend_outside(fig, hs, ls, side="bottom", ncol=2)
    ab, abg = (d[d["order"] == o] for o in (2, 3))
    describe(
        fig,
        f"{title}. B_n·T on a log axis against ξ from 0 to 1 for the type {_ROMAN[rule]} "
        f"α-β and α-β-γ trackers: exact curves with the closed forms on them, B_n·T "
        f"rising from {ab['bnT_exact'].min():.2g} to {ab['bnT_exact'].max():.2g} (α-β) and "
        f"from {abg['bnT_exact'].min():.2g} to {abg['bnT_exact'].max():.2g} (α-β-γ); eq 13 "
        f"read literally falls far below. The table's gain sets are marked at their printed "
        f"ξ; nominal ENBWs {', '.join(f'{b:g}' for b in nominal)} Hz dotted"
        + (f"; unstable: {'; '.join(unstable_all)}." if unstable_all else "."),
    )
    return fig


@styled
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
    fig, ax = plt.subplots(figsize=(WIDTH, 5.6))
    ax.loglog(
        thermal["enbw_hz"],
        thermal["sigma_printed_m"],
        "-",
        color="C0",
        label="printed formula τc / (2k √((S/N)₀ F_r / B_n))",
    )
    ax.loglog(
        thermal["enbw_hz"],
        thermal["sigma_barton_m"],
        "--",
        color="C3",
        label="Barton's 2E/N₀ form (= printed formula at the two-sided ENBW)",
    )
    ax.axhline(budget_m, color=REFERENCE["level"], lw=0.8, ls=":", label=f"σ = {budget_m:g} m")
    styles = [("k", "-."), ("C0", (0, (1, 1.5))), ("C3", (0, (4, 1.5)))]
    for i, (label, bn) in enumerate(limits.items()):
        col, ls = styles[i % len(styles)]
        ax.axvline(bn, color=col, lw=1.0, ls=ls, label=f"{label}: {bn:.1f} Hz")
    ax.set_xlabel("ENBW B_n (Hz, one-sided)")
    ax.set_ylabel("thermal-noise range error σ (m)")
    if title:
        suptitle(fig, title)
    legend_outside(fig, side="bottom", ncol=1)
    lim = "; ".join(f"{k}: {v:.1f} Hz" for k, v in limits.items())
    describe(
        fig,
        f"{title}. Log-log: thermal-noise range error σ (m) against ENBW from "
        f"{thermal['enbw_hz'].min():g} to {thermal['enbw_hz'].max():g} Hz, the printed formula "
        f"and Barton's form (lower by √2), both rising as √B_n; the {budget_m:g} m budget "
        f"dotted; vertical lines at {lim}.",
    )
    return fig


@styled
def huang_track_figure(track: pd.DataFrame, panels: list, title: str = "", noisy: bool = True):
    """Range-tracking errors of the simulated track (seed 002, Figs 5-7).

    Parameters
    ----------
    track : DataFrame
        ``track.csv``: ``t`` and per tracker ``err_<name>`` (with noise) and
        ``lag_<name>`` (noise-free), truth minus predicted position, m.
    panels : list of (str, list of (name, label)[, list of (y, label)])
        One row per entry: its title, the trackers to draw and, optionally, horizontal
        reference levels (m) drawn dashed.
    noisy : bool
        Add a right-hand column with the error under thermal noise (thin) and the
        noise-free error on top; the left column shows the noise-free error on its own
        scale, so that a small lag is never hidden under the noise.
    """
    t = track["t"].to_numpy()
    ncols = 2 if noisy else 1
    fig = plt.figure(figsize=(WIDTH, 2.75 * len(panels) + 0.5))
    rows = fig.subfigures(len(panels), 1, hspace=0.02) if len(panels) > 1 else [fig]
    alt = []
    for sub, (ptitle, names, *refs) in zip(rows, panels, strict=True):
        axes = sub.subplots(1, ncols, sharex=True, squeeze=False)[0]
        for j, (y, label) in enumerate(refs[0] if refs else []):
            for ax in axes:
                ax.axhline(
                    y,
                    color=REFERENCE["level"],
                    lw=0.9,
                    ls=("--", ":")[j % 2],
                    label=label if ax is axes[0] else None,
                )
        parts = []
        if noisy:  # all the noise first, the noise-free curves over it
            for name, _ in names:
                col = family_colour(_tracker_family(name))
                axes[1].plot(t, track[f"err_{name}"], color=col, lw=0.4, alpha=0.4)
        for name, label in names:
            col = family_colour(_tracker_family(name))
            lag = track[f"lag_{name}"].to_numpy()
            axes[0].plot(t, lag, color=col, lw=1.6, label=f"{label}")
            if noisy:
                err = track[f"err_{name}"].to_numpy()
                axes[1].plot(t, lag, color=col, lw=1.4)
                parts.append(
                    f"{label}: noise-free error from {lag.min():.3g} to "
                    f"{lag.max():.3g} m, ending at {lag[-1]:.3g} m; with noise "
                    f"RMS {np.sqrt(np.mean(err**2)):.3g} m"
                )
            else:
                parts.append(f"{label}: error from {lag.min():.3g} to {lag.max():.3g} m")
        for ax in axes:
            ax.axhline(0.0, color=REFERENCE["zero"], lw=0.6)
            ax.set_xlabel("time (s)")
        axes[0].set_ylabel("range error R − R_p (m)")
        axes[0].set_title("noise-free", loc="left")
        if noisy:
            axes[1].set_title("with thermal noise (thin); noise-free on top", loc="left")
        sub.suptitle(ptitle, fontsize=9, ha="left", x=0.01)
        legend_outside(sub, side="bottom", ncol=2)
        alt.append(f"{ptitle}: " + "; ".join(parts))
    if title:
        suptitle(fig, title)
    describe(
        fig,
        f"{title}. {len(panels)} rows of range error R − R_p (m) against time "
        f"(0 to {t[-1]:g} s), noise-free on the left"
        + (", with thermal noise on the right" if noisy else "")
        + ". "
        + ". ".join(alt)
        + ".",
    )
    return fig


def huang_figures(tables: dict, published: pd.DataFrame, cfg: dict) -> dict:
    """Every figure of the report (seed 002, Figs 2-7), from the study's tables.

    Parameters
    ----------
    tables : dict
        ``bandwidth_curves``, ``tables12``, ``thermal``, ``track``, ``track_metrics``
        (``results/huang/*.csv``).
    published : DataFrame
        The transcription (:func:`abglib.replications.compare.read_published`): the stated
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
