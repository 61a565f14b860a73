from functools import partial
from hashlib import sha256

from abglib.reporting.pipeline import report_page

# The version's index page (CONTRACTS.md §4). Each document's report rule is declared in
# documents.smk.

# reports that replicate no source document, listed on the index after the documents
EXTRA_REPORTS = (
    [{"doc": "benchmark", "title": "Benchmark matrix", "href": "benchmark/index.html"}]
    if BENCH
    else []
)
# every report in the order of the index (its neighbours' links follow it)
REPORT_ORDER = [*DOCS, *(["benchmark"] if BENCH else [])]
REPORT_TITLES = {**DOC_TITLES, "benchmark": "Benchmark matrix"}


# params of each <doc>_report rule: its neighbours and the rules behind its files
REPORT_PAGE = partial(report_page, workflow, REPORT_ORDER, REPORT_TITLES)


ASSETS = script_rule(
    "report_assets",
    "render_assets.py",
    output={
        "css": f"{REPORTS}/assets/report.css",
        "js": f"{REPORTS}/assets/report.js",
    },
    log="reports/assets",
    benchmark=False,
    params={
        # the stylesheet and script themselves (not Python: hashed by content)
        "assets": sha256(
            b"".join(
                f.read_bytes()
                for f in sorted((ABGLIB_DIR / "reporting/assets").glob("*"))
            )
        ).hexdigest(),
    },
)


script_rule(
    "report_index",
    "render_index.py",
    input={
        "scorecard": "results/scorecard.csv",
        "reports": expand(f"{REPORTS}/{{doc}}/index.html", doc=DOCS),
        "others": bench_targets(),
        "assets": list(ASSETS["output"].values()),
    },
    output={
        "html": f"{REPORTS}/index.html",
        "scorecard": f"{REPORTS}/scorecard.csv",
    },
    log="reports/index",
    benchmark=False,
    params={
        "docs": DOCS,
        "titles": DOC_TITLES,
        "extras": EXTRA_REPORTS,
        "order": REPORT_ORDER,
        "version": VERSION,
        "repo": lambda wildcards, input: REPO,
    },
)


# ---------------------------------------------------------------- what changed (issue 13)
# the build's comparison tables against the highest version folder below this version
# under the repository's reports/ (the committed releases); none: a page saying so
from abglib.reporting.versions import comparison_tables, previous_version

CHANGES_PREVIOUS = previous_version(Path(workflow.basedir) / "reports", VERSION)


script_rule(
    "changes",
    "changes.py",
    input={
        "assets": list(ASSETS["output"].values()),
        "comparisons": expand("results/{doc}/comparison.csv", doc=DOCS),
        "previous": (
            [str(p) for p in comparison_tables(CHANGES_PREVIOUS).values()]
            if CHANGES_PREVIOUS
            else []
        ),
    },
    output={"csv": f"{REPORTS}/changes.csv", "html": f"{REPORTS}/changes.html"},
    log="reports/changes",
    benchmark=False,
    params={
        "docs": DOCS,
        "version": VERSION,
        "previous": lambda wildcards, input: (
            str(CHANGES_PREVIOUS) if CHANGES_PREVIOUS else None
        ),
    },
)
