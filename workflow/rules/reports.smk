# The version's index page (CONTRACTS.md §4). Each document's report rule lives in the
# document's own .smk file.

# reports that replicate no source document, linked from the index under "Other reports"
EXTRA_REPORTS = (
    [
        {
            "title": "Benchmark matrix",
            "href": "benchmark/index.html",
            "description": "every configured tracker variant on every dataset scenario: "
            "league tables, measured variance reduction against theory, peer libraries",
        }
    ]
    if BENCH
    else []
)


rule report_index:
    input:
        scorecard="results/scorecard.csv",
        reports=expand(f"{REPORTS}/{{doc}}/index.html", doc=DOCS),
        others=bench_targets(),
    output:
        html=f"{REPORTS}/index.html",
        scorecard=f"{REPORTS}/scorecard.csv",
    log:
        "logs/reports/index.log",
    conda:
        "../envs/abglib.yaml"
    params:
        code=code_of("render_index.py"),
        docs=DOCS,
        titles=DOC_TITLES,
        extras=EXTRA_REPORTS,
        version=VERSION,
        repo=lambda wildcards, input: REPO,
    script:
        "../scripts/render_index.py"
