# The scorecard (CONTRACTS.md §3): one row per document, from the comparison tables that
# each document's <doc>_reproduce rule writes.


rule scorecard:
    input:
        comparisons=expand("results/{doc}/comparison.csv", doc=DOCS),
    output:
        scorecard=report("results/scorecard.csv", category="Comparison"),
    log:
        "logs/compare/scorecard.log",
    benchmark:
        "benchmarks/results/compare/scorecard.tsv"
    conda:
        "../envs/abglib.yaml"
    params:
        **script_params("scorecard.py"),
        digits=config["significant_digits"],
    run:
        run_script(input, output, params, wildcards, threads, resources, log, rule)


# Every table of a build and nothing else (no figures, no reports): what `abglib precision`
# builds raw and perturbed to derive each column's digits, and the pipeline test's
# perturbed build (abglib.reporting.precision.TABLE_TARGETS).
rule tables:
    input:
        "results/scorecard.csv",
        [getattr(rules, f"{doc}_study").output for doc in DOCS],
        (
            expand("results/steelman1978/freqresp/{fig}.csv", fig=S78["figures"])
            if "steelman1978" in DOCS
            else []
        ),
        (
            [
                rules.benchmark_league.output,
                rules.benchmark_tradeoff.output,
                rules.benchmark_peers.output,
            ]
            if BENCH
            else []
        ),
