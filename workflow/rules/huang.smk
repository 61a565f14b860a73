# Seed 002: Huang, Yang and Ma, Research on Fixed-gain Range Tracking Loop. ENBW against xi
# (Figs 2-3), thermal-noise error (Fig 4), Tables 1-2 row by row, and the simulated range
# track (Figs 5-7).

HG = config.get("huang", {})
if "huang" in DOCS and not HG:
    raise WorkflowError("config lists huang in docs but has no huang section")


rule huang_figures:
    input:
        bandwidth_curves="results/huang/bandwidth_curves.csv",
        tables12="results/huang/tables12.csv",
        thermal="results/huang/thermal.csv",
        track="results/huang/track.csv",
        track_metrics="results/huang/track_metrics.csv",
        published=published_tables_of("huang"),
    output:
        **{
            f: report(
                f"results/huang/figures/{f}.png",
                category="Huang et al.",
                subcategory="Figures",
                labels={"figure": f},
            )
            for f in ("fig2", "fig3", "fig4", "fig5", "fig6", "fig7")
        },
    log:
        "logs/huang/figures.log",
    benchmark:
        "benchmarks/results/huang/figures.tsv"
    conda:
        "../envs/abglib.yaml"
    params:
        **script_params("huang_figures.py"),
        cfg=HG,
        dpi=config["figure_dpi"],
    run:
        run_script(input, output, params, wildcards, threads, resources, log, rule)
