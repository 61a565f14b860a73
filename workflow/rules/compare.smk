# The scorecard (CONTRACTS.md §3): one row per document, from the comparison tables that
# each document's <doc>_reproduce rule writes.


script_rule(
    "scorecard",
    "scorecard.py",
    input={"comparisons": expand("results/{doc}/comparison.csv", doc=DOCS)},
    output={"scorecard": report("results/scorecard.csv", category="Comparison")},
    log="compare/scorecard",
    params={"digits": config["significant_digits"]},
)


# Every table of a build and nothing else (no figures, no reports): what `abglib precision`
# builds raw and perturbed to derive each column's digits, and the pipeline test's
# perturbed build (abglib.reporting.precision.TABLE_TARGETS).
rule tables:
    input:
        "results/scorecard.csv",
        [list(SCRIPT_RULES[f"{doc}_study"]["output"].values()) for doc in DOCS],
        (
            expand("results/steelman1978/freqresp/{fig}.csv", fig=S78["figures"])
            if "steelman1978" in DOCS
            else []
        ),
        (
            [
                list(SCRIPT_RULES[r]["output"].values())
                for r in ("benchmark_league", "benchmark_tradeoff", "benchmark_peers")
            ]
            if BENCH
            else []
        ),
