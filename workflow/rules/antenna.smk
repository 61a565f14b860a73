# Seed 004: LQ preview control and Kalman estimation for a radar tracking antenna. The
# model's parameter values are lost in the scan; config.yaml's antenna.parameters holds the
# reconstruction, the report the reasoning.

AN = config.get("antenna", {})
if "antenna" in DOCS and not AN:
    raise WorkflowError("config lists antenna in docs but has no antenna section")

# the study's tables (abglib.replications.antenna.study.TABLES); app. H's design-error
# sweep is design_errors (robustness.csv is the claim model's sweep over assumed inputs)
ANTENNA_TABLES = [
    "parameters",
    "checks",
    "taylor",
    "tracking",
    "omega_sweep",
    "vw_search",
    "kalman_runs",
    "kalman_sweep",
    "design_errors",
    "stability",
    "abg",
]


# the study's tables; its code hash covers abglib.replications.antenna.study and what it
# imports, not the claims, so editing a claim reruns only antenna_claims
rule antenna_study:
    input:
        published=published_tables_of("antenna"),
    output:
        **{t: f"results/antenna/{t}.csv" for t in ANTENNA_TABLES},
    log:
        "logs/antenna/study.log",
    benchmark:
        "benchmarks/results/antenna/study.tsv"
    conda:
        "../envs/abglib.yaml"
    params:
        **script_params("reproduce.py", "abglib.replications.antenna.study"),
        doc="antenna",
        part="study",
        cfg=doc_config("antenna"),
        digits=config["significant_digits"],
    run:
        run_script(input, output, params, wildcards, threads, resources, log, rule)


# every published claim judged, and its robustness over the plausible ranges
rule antenna_claims:
    input:
        published=published_tables_of("antenna"),
    output:
        **claims_outputs("antenna"),
    log:
        "logs/antenna/claims.log",
    benchmark:
        "benchmarks/results/antenna/claims.tsv"
    # the build's longest job (~30 s of ~120 job-seconds): first, so that it never ends
    # the build alone
    priority: 3
    conda:
        "../envs/abglib.yaml"
    params:
        **script_params("reproduce.py", "abglib.replications.antenna.claims"),
        doc="antenna",
        part="claims",
        cfg=doc_config("antenna", "robustness"),
        overrides=config["tolerance_overrides"].get("antenna", {}),
        digits=config["significant_digits"],
    run:
        run_script(input, output, params, wildcards, threads, resources, log, rule)


rule antenna_figures:
    input:
        **{t: f"results/antenna/{t}.csv" for t in ANTENNA_TABLES},
    output:
        **{
            f: report(
                f"results/antenna/figures/{f}.png",
                category="Tracking antenna",
                subcategory="Figures",
                labels={"figure": f},
            )
            for f in REPORT_CONTENT["antenna"]["figures"]
        },
    log:
        "logs/antenna/figures.log",
    benchmark:
        "benchmarks/results/antenna/figures.tsv"
    conda:
        "../envs/abglib.yaml"
    params:
        **script_params("antenna_figures.py"),
        dpi=config["figure_dpi"],
    run:
        run_script(input, output, params, wildcards, threads, resources, log, rule)


rule antenna_report:
    input:
        notebook=str(NOTEBOOKS / "antenna.py"),
        figures=report_figures("antenna"),
        tables=report_tables("antenna"),
    output:
        html=f"{REPORTS}/antenna/index.html",
        notebook=f"{REPORTS}/antenna/notebook.py",
        figures=expand(
            f"{REPORTS}/antenna/figures/{{f}}.png",
            f=REPORT_CONTENT["antenna"]["figures"],
        ),
        tables=expand(
            f"{REPORTS}/antenna/tables/{{t}}.csv",
            t=REPORT_CONTENT["antenna"]["tables"],
        ),
    log:
        "logs/reports/antenna.log",
    benchmark:
        "benchmarks/results/reports/antenna.tsv"
    conda:
        "../envs/abglib.yaml"
    params:
        **script_params("render_report.py", NOTEBOOKS / "antenna.py"),
        doc="antenna",
        version=VERSION,
        repo=lambda wildcards, input: REPO,
        timeout=config["notebook_timeout"],
        page=lambda wildcards, input: REPORT_PAGE("antenna", input),
    run:
        run_script(input, output, params, wildcards, threads, resources, log, rule)
