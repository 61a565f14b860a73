# The version's index page (CONTRACTS.md §4). Each document's report rule lives in the
# document's own .smk file.


rule report_index:
    input:
        scorecard="results/scorecard.csv",
        reports=expand(f"{REPORTS}/{{doc}}/index.html", doc=DOCS),
    output:
        html=f"{REPORTS}/index.html",
        scorecard=f"{REPORTS}/scorecard.csv",
    log:
        "logs/reports/index.log",
    conda:
        "../envs/abglib.yaml"
    params:
        docs=DOCS,
        titles=DOC_TITLES,
        version=VERSION,
        repo=lambda wildcards, input: REPO,
    script:
        "../scripts/render_index.py"
