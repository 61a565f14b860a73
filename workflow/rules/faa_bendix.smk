# Seed 003: W. Elwell (FAA Technical Center), Bendix Alpha-Beta Tracking Filter Test, and
# A. I. Sinsky's memo on the expected smoothing. Impulse and ramp responses of the eight
# gain sets, the memo's table, damping and lags.

FB = config.get("faa_bendix", {})
if "faa_bendix" in DOCS and not FB:
    raise WorkflowError("config lists faa_bendix in docs but has no faa_bendix section")


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
