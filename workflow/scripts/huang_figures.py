"""Draw the Huang et al. report's figures (seed 002) from the tables of huang.py."""

import pandas as pd

from abglib.reporting.pipeline import log_to


def main(input, output, params) -> None:
    from abglib.analysis import steady_state_lag_huang
    from abglib.replications.huang import study as huang
    from abglib.replications.huang.figures import (
        huang_bandwidth_figure,
        huang_thermal_figure,
        huang_track_figure,
    )
    from abglib.reporting.plotting import save_figure

    radar, sim = params.cfg["radar"], params.cfg["simulation"]
    dt = 1.0 / radar["fr_hz"]
    curves = pd.read_csv(input.bandwidth_curves)
    tab = pd.read_csv(input.tables12)
    for rule, out, roman, fig in (("type1", output.fig2, "I", 2), ("type2", output.fig3, "II", 3)):
        title = (
            f"Replicates seed 002, Fig {fig}: relation of B_n·T and ξ (type {roman} parameters "
            "selecting), α-β and α-β-γ"
        )
        save_figure(huang_bandwidth_figure(curves, rule, tab, dt, title), out, dpi=params.dpi)

    budget = params.cfg["sigma_budget_m"]
    args = (radar["fr_hz"], radar["tau_s"], radar["snr_db"], radar["k"])
    limits = {
        "paper: 'ENBW should be under 40Hz'": 40.0,
        f"printed formula, σ = {budget:g} m": huang.bandwidth_for_sigma(budget, *args),
        f"Barton form, σ = {budget:g} m": huang.bandwidth_for_sigma(budget, *args, form="barton"),
    }
    title = (
        "Replicates seed 002, Fig 4: thermal-noise range error against ENBW\n"
        f"(F_r = {radar['fr_hz']:g} Hz, τ = {radar['tau_s'] * 1e6:g} µs, "
        f"(S/N)₀ = {radar['snr_db']:g} dB, k = {radar['k']:g})"
    )
    save_figure(
        huang_thermal_figure(pd.read_csv(input.thermal), budget, limits, title),
        output.fig4,
        dpi=params.dpi,
    )

    trk = pd.read_csv(input.track)
    accel = params.cfg["target"]["accel"]
    gate = huang.C_LIGHT * radar["tau_s"] / 2.0 * params.cfg["gate_fraction_of_pulse"]

    def lag(beta):
        return steady_state_lag_huang(beta, accel, dt)

    f5 = sim["fig5_enbw_hz"]
    lo = sim["low_enbw_hz"]
    panels = [
        (
            f"type II, ENBW {f5:g} Hz: α-β (printed gains) vs α-β-γ (gains of a true {f5:g} Hz)",
            [
                ("ab_t2_10_printed", "α-β (0.098, 0.0025), ENBW 9.85 Hz"),
                ("abg_t2_10", f"α-β-γ type II, true ENBW {f5:g} Hz"),
            ],
            [(lag(0.0025), f"A/(βF_r²) = {lag(0.0025):.2f} m (the paper's 4.44 m)")],
        ),
        (
            "type II α-β-γ with the gains printed for 10 Hz: their true ENBW is 287 Hz",
            [("abg_t2_10_printed", "α-β-γ printed (0.83, 0.47, 0.046), ENBW 287 Hz")],
        ),
        (
            f"type II, ENBW {lo:g} Hz: the '111 m initial error' of α-β",
            [
                ("ab_t2_2_printed", "α-β (0.02, 0.0001), ENBW 1.90 Hz"),
                ("abg_t2_2", f"α-β-γ type II, true ENBW {lo:g} Hz"),
            ],
            [
                (lag(0.0001), f"A/(βF_r²) = {lag(0.0001):.1f} m (the paper's 111 m)"),
                (gate, f"discriminator edge cτ/4 = {gate:.1f} m"),
            ],
        ),
    ]
    title = (
        "Replicates seed 002, Fig 5: performances of tracking loops "
        f"(A = {params.cfg['target']['accel']:g} m/s², B = {params.cfg['target']['jerk']:g} m/s³, "
        "thin: with thermal noise)"
    )
    save_figure(huang_track_figure(trk, panels, title), output.fig5, dpi=params.dpi)
    for rule, out, fig in (("1", output.fig6, 6), ("2", output.fig7, 7)):
        roman = "I" * int(rule)
        panels = [
            (
                f"type {roman} α-β-γ, true ENBW {bn:g} Hz",
                [(f"abg_t{rule}_{bn:g}", f"type {roman}, {bn:g} Hz")],
            )
            for bn in sim["residual_enbw_hz"]
        ]
        title = (
            f"Replicates seed 002, Fig {fig}: tracking position residual error "
            f"(type {roman} parameters selecting), thin: with thermal noise"
        )
        save_figure(huang_track_figure(trk, panels, title), out, dpi=params.dpi)


if "snakemake" in globals():
    log_to(snakemake.log[0])  # noqa: F821
    main(snakemake.input, snakemake.output, snakemake.params)  # noqa: F821
