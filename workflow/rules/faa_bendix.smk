# Seed 003: W. Elwell (FAA Technical Center), Bendix Alpha-Beta Tracking Filter Test, and
# A. I. Sinsky's memo on the expected smoothing. Impulse and ramp responses of the eight
# gain sets, the memo's table, damping and lags.

FB = config.get("faa_bendix", {})
if "faa_bendix" in DOCS and not FB:
    raise WorkflowError("config lists faa_bendix in docs but has no faa_bendix section")


# the study's report tables (abglib.replications.faa_bendix.study.TABLES; listed here, as
# for every document, so that parsing the workflow imports no study; reproduce.py checks
# that the two lists agree)
FAA_BENDIX_TABLES = [
    "responses",
    "gains",
    "memo_table",
    "rounding",
    "row7",
    "damping_lags",
    "captions",
]


# the study's tables; its code hash covers abglib.replications.faa_bendix.study and what it
# imports, not the claims, so editing a claim reruns only faa_bendix_claims
rule faa_bendix_study:
    input:
        published=published_tables_of("faa_bendix"),
    output:
        **{t: f"results/faa_bendix/{t}.csv" for t in FAA_BENDIX_TABLES},
    log:
        "logs/faa_bendix/study.log",
    benchmark:
        "benchmarks/results/faa_bendix/study.tsv"
    conda:
        "../envs/abglib.yaml"
    params:
        **script_params("reproduce.py", "abglib.replications.faa_bendix.study"),
        doc="faa_bendix",
        part="study",
        cfg=doc_config("faa_bendix"),
        digits=config["significant_digits"],
    run:
        run_script(input, output, params, wildcards, threads, resources, log, rule)


# every published claim judged, and its robustness over the plausible ranges
rule faa_bendix_claims:
    input:
        published=published_tables_of("faa_bendix"),
    output:
        **claims_outputs("faa_bendix"),
    log:
        "logs/faa_bendix/claims.log",
    benchmark:
        "benchmarks/results/faa_bendix/claims.tsv"
    conda:
        "../envs/abglib.yaml"
    params:
        **script_params("reproduce.py", "abglib.replications.faa_bendix.claims"),
        doc="faa_bendix",
        part="claims",
        cfg=doc_config("faa_bendix", "robustness"),
        overrides=config["tolerance_overrides"].get("faa_bendix", {}),
        digits=config["significant_digits"],
    run:
        run_script(input, output, params, wildcards, threads, resources, log, rule)


rule faa_bendix_figures:
    input:
        responses="results/faa_bendix/responses.csv",
        damping_lags="results/faa_bendix/damping_lags.csv",
        captions="results/faa_bendix/captions.csv",
    output:
        impulse=report(
            "results/faa_bendix/figures/impulse.png",
            category="FAA Bendix",
            subcategory="Figures",
            labels={"figure": "impulse"},
        ),
        ramp=report(
            "results/faa_bendix/figures/ramp.png",
            category="FAA Bendix",
            subcategory="Figures",
            labels={"figure": "ramp"},
        ),
        triangle=report(
            "results/faa_bendix/figures/triangle.png",
            category="FAA Bendix",
            subcategory="Figures",
            labels={"figure": "stability triangle"},
        ),
    log:
        "logs/faa_bendix/figures.log",
    benchmark:
        "benchmarks/results/faa_bendix/figures.tsv"
    conda:
        "../envs/abglib.yaml"
    params:
        **script_params("faa_bendix_figures.py"),
        dpi=config["figure_dpi"],
    run:
        run_script(input, output, params, wildcards, threads, resources, log, rule)


rule faa_bendix_report:
    input:
        notebook=str(NOTEBOOKS / "faa_bendix.py"),
        figures=report_figures("faa_bendix"),
        tables=report_tables("faa_bendix"),
    output:
        html=f"{REPORTS}/faa_bendix/index.html",
        notebook=f"{REPORTS}/faa_bendix/notebook.py",
        figures=expand(
            f"{REPORTS}/faa_bendix/figures/{{f}}.png",
            f=REPORT_CONTENT["faa_bendix"]["figures"],
        ),
        tables=expand(
            f"{REPORTS}/faa_bendix/tables/{{t}}.csv",
            t=REPORT_CONTENT["faa_bendix"]["tables"],
        ),
    log:
        "logs/reports/faa_bendix.log",
    benchmark:
        "benchmarks/results/reports/faa_bendix.tsv"
    conda:
        "../envs/abglib.yaml"
    params:
        **script_params("render_report.py", NOTEBOOKS / "faa_bendix.py"),
        doc="faa_bendix",
        version=VERSION,
        repo=lambda wildcards, input: REPO,
        timeout=config["notebook_timeout"],
        page=lambda wildcards, input: REPORT_PAGE("faa_bendix", input),
    run:
        run_script(input, output, params, wildcards, threads, resources, log, rule)
