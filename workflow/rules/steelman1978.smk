# Seed 000: J. E. Steelman, Frequency Response of α-β-γ Trackers (1978).
# Figures 1-6 (one response table and one figure each); Tables 1-5, the design example, the
# equations' table of agreement and every claim: the study, claims and report rules are
# generated for every document in documents.smk.

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
