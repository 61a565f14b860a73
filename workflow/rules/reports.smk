import os

# The version's index page (CONTRACTS.md §4). Each document's report rule lives in the
# document's own .smk file.

# reports that replicate no source document, listed on the index after the documents
EXTRA_REPORTS = (
    [{"doc": "benchmark", "title": "Benchmark matrix", "href": "benchmark/index.html"}]
    if BENCH
    else []
)
# every report in the order of the index (its neighbours' links follow it)
REPORT_ORDER = [*DOCS, *(["benchmark"] if BENCH else [])]
REPORT_TITLES = {**DOC_TITLES, "benchmark": "Benchmark matrix"}


def made_by(paths):
    """{file name: (rule, script)} of the rule that writes each path (showyourwork-style
    captions: each figure and table names the rule and script that made it)."""
    out = {}
    for path in paths:
        for r in workflow.rules:
            if r.name.endswith("_report") or not r.is_producer(path):
                continue
            script = ""
            if r.script:
                full = Path(r.snakefile).parent / r.script
                script = os.path.relpath(os.path.normpath(full), workflow.basedir)
            out[Path(path).name] = (r.name, script)
            break
    return out


def report_page(doc, input):
    """Params of a report rule: its neighbours on the index and the rules behind its
    figures and tables."""
    i = REPORT_ORDER.index(doc)
    nav = {
        rel: {"doc": REPORT_ORDER[j], "title": REPORT_TITLES.get(REPORT_ORDER[j])}
        for rel, j in (("prev", i - 1), ("next", i + 1))
        if 0 <= j < len(REPORT_ORDER)
    }
    return {"nav": nav, "made_by": made_by([*input.figures, *input.tables])}


rule report_assets:
    output:
        css=f"{REPORTS}/assets/report.css",
        js=f"{REPORTS}/assets/report.js",
    log:
        "logs/reports/assets.log",
    conda:
        "../envs/abglib.yaml"
    params:
        library=LIBRARY_HASH,
    script:
        "../scripts/render_assets.py"


rule report_index:
    input:
        scorecard="results/scorecard.csv",
        reports=expand(f"{REPORTS}/{{doc}}/index.html", doc=DOCS),
        others=bench_targets(),
        assets=rules.report_assets.output,
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
        order=REPORT_ORDER,
        version=VERSION,
        repo=lambda wildcards, input: REPO,
    script:
        "../scripts/render_index.py"
