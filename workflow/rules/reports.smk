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
        library=LIBRARY_HASH,
        docs=DOCS,
        titles=DOC_TITLES,
        extras=EXTRA_REPORTS,
        version=VERSION,
        repo=lambda wildcards, input: REPO,
    script:
        "../scripts/render_index.py"


# ---------------------------------------------------------------- what changed (issue 13)
# the build's comparison tables against the highest version folder below this version
# under the repository's reports/ (the committed releases); none: a page saying so
from abglib.reporting.changes import comparison_tables, previous_version

CHANGES_PREVIOUS = previous_version(Path(workflow.basedir) / "reports", VERSION)


rule changes:
    input:
        comparisons=expand("results/{doc}/comparison.csv", doc=DOCS),
        previous=(
            [str(p) for p in comparison_tables(CHANGES_PREVIOUS).values()]
            if CHANGES_PREVIOUS
            else []
        ),
    output:
        csv=f"{REPORTS}/changes.csv",
        html=f"{REPORTS}/changes.html",
    log:
        "logs/reports/changes.log",
    conda:
        "../envs/abglib.yaml"
    params:
        library=LIBRARY_HASH,
        docs=DOCS,
        version=VERSION,
        previous=lambda wildcards, input: (
            str(CHANGES_PREVIOUS) if CHANGES_PREVIOUS else None
        ),
    script:
        "../scripts/changes.py"
