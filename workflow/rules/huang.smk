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
    "checks",
]


rule huang_reproduce:
    input:
        published=sorted(str(f) for f in (PUBLISHED / "huang").glob("*.csv")),
    output:
        **{
            t: report(
                f"results/huang/{t}.csv",
                category="Huang et al.",
                subcategory="Tables",
                labels={"table": t},
            )
            for t in HUANG_TABLES
        },
        reproduced="results/huang/reproduced.csv",
        alternatives="results/huang/alternatives.csv",
    log:
        "logs/huang/reproduce.log",
    benchmark:
        "benchmarks/results/huang/reproduce.tsv"
    conda:
        "../envs/abglib.yaml"
    params:
        library=LIBRARY_HASH,
        cfg=HG,
        digits=config["significant_digits"],
    script:
        "../scripts/huang.py"


rule huang_figures:
    input:
        bandwidth_curves="results/huang/bandwidth_curves.csv",
        tables12="results/huang/tables12.csv",
        thermal="results/huang/thermal.csv",
        track="results/huang/track.csv",
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
        library=LIBRARY_HASH,
        cfg=HG,
        dpi=config["figure_dpi"],
    script:
        "../scripts/huang_figures.py"


rule huang_report:
    input:
        notebook=str(NOTEBOOKS / "huang.py"),
        figures=report_figures("huang"),
        tables=report_tables("huang"),
    output:
        html=f"{REPORTS}/huang/index.html",
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
        library=LIBRARY_HASH,
        doc="huang",
        version=VERSION,
        repo=lambda wildcards, input: REPO,
        timeout=config["notebook_timeout"],
    script:
        "../scripts/render_report.py"
