# Seed 000: J. E. Steelman, Frequency Response of α-β-γ Trackers (1978).
# Figures 1-6 (one response table and one figure each); Tables 1-5, the design example, the
# equations' table of agreement and every claim (the study, one rule).

S78 = config["steelman1978"]


wildcard_constraints:
    fig="fig[1-6]",


rule steelman_frequency_response:
    output:
        data="results/steelman1978/freqresp/{fig}.csv",
    log:
        "logs/steelman1978/frequency_response_{fig}.log",
    benchmark:
        "benchmarks/results/steelman1978/frequency_response_{fig}.tsv"
    conda:
        "../envs/abglib.yaml"
    params:
        **script_params("frequency_response.py"),
        figure=lambda wildcards: S78["figures"][wildcards.fig],
        grids=S78["grids"],
        digits=config["significant_digits"],
    run:
        run_script(input, output, params, wildcards, threads, resources, log, rule)


rule steelman_figure:
    input:
        data="results/steelman1978/freqresp/{fig}.csv",
    output:
        png=report(
            "results/steelman1978/figures/{fig}.png",
            category="Steelman 1978",
            subcategory="Figures",
            labels={"figure": "{fig}"},
        ),
    log:
        "logs/steelman1978/figure_{fig}.log",
    benchmark:
        "benchmarks/results/steelman1978/figure_{fig}.tsv"
    conda:
        "../envs/abglib.yaml"
    params:
        **script_params("plot_frequency_response.py"),
        axes=lambda wildcards: S78["figures"][wildcards.fig]["axes"],
        caption=lambda wildcards: S78["figures"][wildcards.fig]["caption"],
        dpi=config["figure_dpi"],
    run:
        run_script(input, output, params, wildcards, threads, resources, log, rule)


# every table of the study (abglib.replications.steelman1978) and the judged claims
STEELMAN1978_TABLES = [
    "gains",
    "design_example",
    "tables345",
    "approximations",
    "equations",
    "stability",
]


# the study's tables; its code hash covers abglib.replications.steelman1978.study and what it
# imports, not the claims, so editing a claim reruns only steelman1978_claims
rule steelman1978_study:
    input:
        published=published_tables_of("steelman1978"),
    output:
        **{t: f"results/steelman1978/{t}.csv" for t in STEELMAN1978_TABLES},
    log:
        "logs/steelman1978/study.log",
    benchmark:
        "benchmarks/results/steelman1978/study.tsv"
    conda:
        "../envs/abglib.yaml"
    params:
        **script_params("reproduce.py", "abglib.replications.steelman1978.study"),
        doc="steelman1978",
        part="study",
        cfg=doc_config("steelman1978"),
        digits=config["significant_digits"],
    run:
        run_script(input, output, params, wildcards, threads, resources, log, rule)


# every published claim judged, and its robustness over the plausible ranges
rule steelman1978_claims:
    input:
        published=published_tables_of("steelman1978"),
    output:
        **claims_outputs("steelman1978"),
    log:
        "logs/steelman1978/claims.log",
    benchmark:
        "benchmarks/results/steelman1978/claims.tsv"
    conda:
        "../envs/abglib.yaml"
    params:
        **script_params("reproduce.py", "abglib.replications.steelman1978.claims"),
        doc="steelman1978",
        part="claims",
        cfg=doc_config("steelman1978", "robustness"),
        overrides=config["tolerance_overrides"].get("steelman1978", {}),
        digits=config["significant_digits"],
    run:
        run_script(input, output, params, wildcards, threads, resources, log, rule)


rule steelman_report:
    input:
        notebook=str(NOTEBOOKS / "steelman1978.py"),
        figures=report_figures("steelman1978"),
        tables=report_tables("steelman1978"),
    output:
        html=f"{REPORTS}/steelman1978/index.html",
        notebook=f"{REPORTS}/steelman1978/notebook.py",
        figures=expand(
            f"{REPORTS}/steelman1978/figures/{{f}}.png",
            f=REPORT_CONTENT["steelman1978"]["figures"],
        ),
        tables=expand(
            f"{REPORTS}/steelman1978/tables/{{t}}.csv",
            t=REPORT_CONTENT["steelman1978"]["tables"],
        ),
    log:
        "logs/reports/steelman1978.log",
    benchmark:
        "benchmarks/results/reports/steelman1978.tsv"
    conda:
        "../envs/abglib.yaml"
    params:
        **script_params("render_report.py", NOTEBOOKS / "steelman1978.py"),
        doc="steelman1978",
        version=VERSION,
        repo=lambda wildcards, input: REPO,
        timeout=config["notebook_timeout"],
        page=lambda wildcards, input: REPORT_PAGE("steelman1978", input),
    run:
        run_script(input, output, params, wildcards, threads, resources, log, rule)
