# Seed 001: Al-Wagih & Abdulla, A Study of αβ Tracker with Some New Algorithms for
# Selecting α and β Parameters. Methods M1-M5 (abglib.methods) on the ten reconstructed
# experiments (dataset scenarios, generated in memory), Tables 1-6, Figures 5-8, the t-test.

AW = config.get("alwagih", {})
if "alwagih" in DOCS and not AW:
    raise WorkflowError("config lists alwagih in docs but has no alwagih section")


# every table the study writes (abglib.replications.alwagih.study.AlwagihStudy.tables);
# the study generates the ten experiments in memory from config["datasets"] (seeded, the
# same data as the dataset rule writes)
ALWAGIH_TABLES = [
    "table1",
    "table2",
    "mc_rmse",
    "tables34",
    "ttests",
    "tables56",
    "consistency",
    "causal",
    "sensitivity",
    "m5_bank",
    "tracks",
    "experiments",
    "settings",
]


# the study's tables; its code hash covers abglib.replications.alwagih.study and what it
# imports, not the claims, so editing a claim reruns only alwagih_claims
rule alwagih_study:
    input:
        published=published_tables_of("alwagih"),
    output:
        **{t: f"results/alwagih/{t}.csv" for t in ALWAGIH_TABLES},
    log:
        "logs/alwagih/study.log",
    benchmark:
        "benchmarks/results/alwagih/study.tsv"
    conda:
        "../envs/abglib.yaml"
    params:
        **script_params("reproduce.py", "abglib.replications.alwagih.study"),
        doc="alwagih",
        part="study",
        cfg=doc_config("alwagih", "datasets"),
        digits=config["significant_digits"],
    run:
        run_script(input, output, params, wildcards, threads, resources, log, rule)


# every published claim judged, and its robustness over the plausible ranges
rule alwagih_claims:
    input:
        published=published_tables_of("alwagih"),
    output:
        **claims_outputs("alwagih"),
    log:
        "logs/alwagih/claims.log",
    benchmark:
        "benchmarks/results/alwagih/claims.tsv"
    conda:
        "../envs/abglib.yaml"
    params:
        **script_params("reproduce.py", "abglib.replications.alwagih.claims"),
        doc="alwagih",
        part="claims",
        cfg=doc_config("alwagih", "datasets", "robustness"),
        overrides=config["tolerance_overrides"].get("alwagih", {}),
        digits=config["significant_digits"],
    run:
        run_script(input, output, params, wildcards, threads, resources, log, rule)


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


rule alwagih_report:
    input:
        notebook=str(NOTEBOOKS / "alwagih.py"),
        figures=report_figures("alwagih"),
        tables=report_tables("alwagih"),
    output:
        html=f"{REPORTS}/alwagih/index.html",
        notebook=f"{REPORTS}/alwagih/notebook.py",
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
        **script_params("render_report.py", NOTEBOOKS / "alwagih.py"),
        doc="alwagih",
        version=VERSION,
        repo=lambda wildcards, input: REPO,
        timeout=config["notebook_timeout"],
        page=lambda wildcards, input: REPORT_PAGE("alwagih", input),
    run:
        run_script(input, output, params, wildcards, threads, resources, log, rule)
