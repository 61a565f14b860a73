# Seed 002: Huang, Yang and Ma, Research on Fixed-gain Range Tracking Loop. ENBW against xi
# (Figs 2-3), thermal-noise error (Fig 4), Tables 1-2 row by row, and the simulated range
# track (Figs 5-7).

HG = config.get("huang", {})
if "huang" in DOCS and not HG:
    raise WorkflowError("config lists huang in docs but has no huang section")


script_rule(
    "huang_figures",
    "huang_figures.py",
    input={
        **{
            t: f"results/huang/{t}.csv"
            for t in (
                "bandwidth_curves",
                "tables12",
                "thermal",
                "track",
                "track_metrics",
            )
        },
        "published": published_tables_of("huang"),
    },
    output={
        f: report(
            f"results/huang/figures/{f}.png",
            category="Huang et al.",
            subcategory="Figures",
            labels={"figure": f},
        )
        for f in ("fig2", "fig3", "fig4", "fig5", "fig6", "fig7")
    },
    log="huang/figures",
    params={"cfg": HG, "dpi": config["figure_dpi"]},
)
