# Seed 001: Al-Wagih & Abdulla, A Study of αβ Tracker with Some New Algorithms for
# Selecting α and β Parameters. Methods M1-M5 (abglib.methods) on the ten reconstructed
# experiments (dataset scenarios, datasets.smk), Tables 1-6, Figures 5-8, the t-test.

AW = config.get("alwagih", {})
if "alwagih" in DOCS and not AW:
    raise WorkflowError("config lists alwagih in docs but has no alwagih section")


def alwagih_datasets(noise):
    """Parquet files of the white or coloured experiments (manifests beside them)."""
    return [dataset_files(name)[0] for name in AW.get("experiments", {}).get(noise, [])]


def alwagih_manifests(wildcards):
    return [
        dataset_files(name)[1]
        for noise in ("white", "coloured")
        for name in AW["experiments"][noise]
    ]


rule alwagih_reproduce:
    input:
        published=sorted(str(f) for f in (PUBLISHED / "alwagih").glob("*.csv")),
        white=alwagih_datasets("white"),
        coloured=alwagih_datasets("coloured"),
        manifests=alwagih_manifests,
    output:
        reproduced="results/alwagih/reproduced.csv",
        alternatives="results/alwagih/alternatives.csv",
        rmse_runs="results/alwagih/rmse_runs.parquet",
        table1=report(
            "results/alwagih/table1.csv",
            category="Al-Wagih",
            subcategory="Tables",
            labels={"table": "Table 1"},
        ),
        table2=report(
            "results/alwagih/table2.csv",
            category="Al-Wagih",
            subcategory="Tables",
            labels={"table": "Table 2"},
        ),
        mc_rmse=report(
            "results/alwagih/mc_rmse.csv",
            category="Al-Wagih",
            subcategory="Tables",
            labels={"table": "Monte Carlo RMSE"},
        ),
        tables34="results/alwagih/tables34.csv",
        ttests="results/alwagih/ttests.csv",
        tables56="results/alwagih/tables56.csv",
        consistency="results/alwagih/consistency.csv",
        causal="results/alwagih/causal.csv",
        sensitivity="results/alwagih/sensitivity.csv",
        tracks="results/alwagih/tracks.csv",
    log:
        "logs/alwagih/reproduce.log",
    benchmark:
        "benchmarks/results/alwagih/reproduce.tsv"
    conda:
        "../envs/abglib.yaml"
    params:
        library=LIBRARY_HASH,
        cfg=AW,
        digits=config["significant_digits"],
    script:
        "../scripts/alwagih.py"


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
        library=LIBRARY_HASH,
        dpi=config["figure_dpi"],
    script:
        "../scripts/alwagih_figures.py"


rule alwagih_report:
    input:
        notebook=str(NOTEBOOKS / "alwagih.py"),
        figures=report_figures("alwagih"),
        tables=report_tables("alwagih"),
    output:
        html=f"{REPORTS}/alwagih/index.html",
        figures=expand(
            f"{REPORTS}/alwagih/figures/{{f}}.png",
            f=REPORT_CONTENT["alwagih"]["figures"],
        ),
        tables=expand(
            f"{REPORTS}/alwagih/tables/{{t}}.csv",
            t=REPORT_CONTENT["alwagih"]["tables"],
        ),
    log:
        "logs/reports/alwagih.log",
    benchmark:
        "benchmarks/results/reports/alwagih.tsv"
    conda:
        "../envs/abglib.yaml"
    params:
        library=LIBRARY_HASH,
        doc="alwagih",
        version=VERSION,
        repo=lambda wildcards, input: REPO,
        timeout=config["notebook_timeout"],
    script:
        "../scripts/render_report.py"
