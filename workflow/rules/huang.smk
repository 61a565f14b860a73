# Seed 002: Huang, Yang and Ma, Research on Fixed-gain Range Tracking Loop. ENBW against xi
# (Figs 2-3), thermal-noise error (Fig 4), Tables 1-2 row by row, and the simulated range
# track (Figs 5-7).

HG = config.get("huang", {})
if "huang" in DOCS and not HG:
    raise WorkflowError("config lists huang in docs but has no huang section")

HUANG_TABLES = [
    "bandwidth_curves",
    "thermal",
    "tables12",
    "enbw_routes",
    "track",
    "track_metrics",
]


# the study's tables; its code hash covers abglib.replications.huang.study and what it
# imports, not the claims, so editing a claim reruns only huang_claims
rule huang_study:
    input:
        published=published_tables_of("huang"),
    output:
        **{t: f"results/huang/{t}.csv" for t in HUANG_TABLES},
    log:
        "logs/huang/study.log",
    benchmark:
        "benchmarks/results/huang/study.tsv"
    conda:
        "../envs/abglib.yaml"
    params:
        **script_params("reproduce.py", "abglib.replications.huang.study"),
        doc="huang",
        part="study",
        cfg=doc_config("huang"),
        digits=config["significant_digits"],
    run:
        run_script(input, output, params, wildcards, threads, resources, log, rule)


# every published claim judged, and its robustness over the plausible ranges
rule huang_claims:
    input:
        published=published_tables_of("huang"),
    output:
        **claims_outputs("huang"),
    log:
        "logs/huang/claims.log",
    benchmark:
        "benchmarks/results/huang/claims.tsv"
    conda:
        "../envs/abglib.yaml"
    params:
        **script_params("reproduce.py", "abglib.replications.huang.claims"),
        doc="huang",
        part="claims",
        cfg=doc_config("huang", "robustness"),
        overrides=config["tolerance_overrides"].get("huang", {}),
        digits=config["significant_digits"],
    run:
        run_script(input, output, params, wildcards, threads, resources, log, rule)


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


rule huang_report:
    input:
        notebook=str(NOTEBOOKS / "huang.py"),
        figures=report_figures("huang"),
        tables=report_tables("huang"),
    output:
        html=f"{REPORTS}/huang/index.html",
        notebook=f"{REPORTS}/huang/notebook.py",
        figures=expand(
            f"{REPORTS}/huang/figures/{{f}}.png",
            f=REPORT_CONTENT["huang"]["figures"],
        ),
        tables=expand(
            f"{REPORTS}/huang/tables/{{t}}.csv",
            t=REPORT_CONTENT["huang"]["tables"],
        ),
    log:
        "logs/reports/huang.log",
    benchmark:
        "benchmarks/results/reports/huang.tsv"
    conda:
        "../envs/abglib.yaml"
    params:
        **script_params("render_report.py", NOTEBOOKS / "huang.py"),
        doc="huang",
        version=VERSION,
        repo=lambda wildcards, input: REPO,
        timeout=config["notebook_timeout"],
        page=lambda wildcards, input: REPORT_PAGE("huang", input),
    run:
        run_script(input, output, params, wildcards, threads, resources, log, rule)
