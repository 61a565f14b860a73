# Seed 001: Al-Wagih & Abdulla, A Study of αβ Tracker with Some New Algorithms for
# Selecting α and β Parameters. Methods M1-M5 (abglib.methods) on the ten reconstructed
# experiments (dataset scenarios, generated in memory), Tables 1-6, Figures 5-8, the t-test.

AW = config.get("alwagih", {})
if "alwagih" in DOCS and not AW:
    raise WorkflowError("config lists alwagih in docs but has no alwagih section")


script_rule(
    "alwagih_figures",
    "alwagih_figures.py",
    input={
        t: f"results/alwagih/{t}.csv"
        for t in ("tracks", "mc_rmse", "table1", "table2", "causal")
    },
    output={
        name: report(
            f"results/alwagih/figures/{stem}.png",
            category="Al-Wagih",
            subcategory="Figures",
            labels={"figure": label},
        )
        for name, stem, label in (
            ("fig5", "fig5_tracks", "Figure 5"),
            ("fig6", "fig6_tracks", "Figure 6"),
            ("fig7", "fig7_rmse", "Figure 7"),
            ("fig8", "fig8_rmse", "Figure 8"),
            ("causal", "causal", "causal M5 and Kalman"),
        )
    },
    log="alwagih/figures",
    params={"dpi": config["figure_dpi"]},
)
