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
