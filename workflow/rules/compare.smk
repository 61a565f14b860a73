# Published versus reproduced (CONTRACTS.md §3): one comparison table per document and the
# scorecard.


rule comparison:
    input:
        published=published_tables,
        reproduced="results/{doc}/reproduced.csv",
        alternatives="results/{doc}/alternatives.csv",
    output:
        comparison=report(
            "results/{doc}/comparison.csv",
            category="Comparison",
            labels={"document": "{doc}"},
        ),
    log:
        "logs/compare/{doc}.log",
    benchmark:
        "benchmarks/results/compare/{doc}.tsv"
    conda:
        "../envs/abglib.yaml"
    params:
        library=LIBRARY_HASH,
        doc="{doc}",
        overrides=lambda wildcards: config["tolerance_overrides"].get(wildcards.doc, {}),
        digits=config["significant_digits"],
    script:
        "../scripts/compare.py"


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
        library=LIBRARY_HASH,
        digits=config["significant_digits"],
    script:
        "../scripts/scorecard.py"
