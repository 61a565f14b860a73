# Seed 001: Al-Wagih & Abdulla, A Study of αβ Tracker with Some New Algorithms for
# Selecting α and β Parameters. Methods M1-M5 (abglib.methods) on the ten reconstructed
# experiments (dataset scenarios, generated in memory), Tables 1-6, Figures 5-8, the t-test.

AW = config.get("alwagih", {})
if "alwagih" in DOCS and not AW:
    raise WorkflowError("config lists alwagih in docs but has no alwagih section")


rule alwagih_figures:
    input:
        tracks="results/alwagih/tracks.csv",
        mc_rmse="results/alwagih/mc_rmse.csv",
        table1="results/alwagih/table1.csv",
        table2="results/alwagih/table2.csv",
        causal="results/alwagih/causal.csv",
    output:
        fig5=report(
            "results/alwagih/figures/fig5_tracks.png",
            category="Al-Wagih",
            subcategory="Figures",
            labels={"figure": "Figure 5"},
        ),
        fig6=report(
            "results/alwagih/figures/fig6_tracks.png",
            category="Al-Wagih",
            subcategory="Figures",
            labels={"figure": "Figure 6"},
        ),
        fig7=report(
            "results/alwagih/figures/fig7_rmse.png",
            category="Al-Wagih",
            subcategory="Figures",
            labels={"figure": "Figure 7"},
        ),
        fig8=report(
            "results/alwagih/figures/fig8_rmse.png",
            category="Al-Wagih",
            subcategory="Figures",
            labels={"figure": "Figure 8"},
        ),
        causal=report(
            "results/alwagih/figures/causal.png",
            category="Al-Wagih",
            subcategory="Figures",
            labels={"figure": "causal M5 and Kalman"},
        ),
    log:
        "logs/alwagih/figures.log",
    benchmark:
        "benchmarks/results/alwagih/figures.tsv"
    conda:
        "../envs/abglib.yaml"
    params:
        **script_params("alwagih_figures.py"),
        dpi=config["figure_dpi"],
    run:
        run_script(input, output, params, wildcards, threads, resources, log, rule)
