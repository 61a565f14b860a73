# abglib replication pipeline: config -> tracker analysis -> tables/figures -> comparison
# with the published numbers -> versioned reports (see README.md, docs/architecture.md).


configfile: "config.yaml"


include: "workflow/rules/common.smk"
include: "workflow/rules/documents.smk"
include: "workflow/rules/steelman1978.smk"
include: "workflow/rules/faa_bendix.smk"
include: "workflow/rules/huang.smk"
include: "workflow/rules/datasets.smk"
include: "workflow/rules/alwagih.smk"
include: "workflow/rules/benchmark.smk"
include: "workflow/rules/antenna.smk"
include: "workflow/rules/compare.smk"
include: "workflow/rules/reports.smk"
# last: defines every rule declared with script_rule above
include: "workflow/rules/scripts.smk"


# On a cluster (profiles/slurm) the last aggregations, the scorecard, the changes page,
# the report assets and the index page (a second or two of work in all), run in the
# submitting Snakemake process instead of as a SLURM job that would wait for a slot after
# the last document (docs/cluster.md). A local build runs every job locally anyway.
localrules:
    all,
    scorecard,
    changes,
    report_assets,
    report_index,


rule all:
    default_target: True
    input:
        all_targets(),
        bench_targets(),


onstart:
    # a local build with jobs to run (never a dry run or a no-op): the warm worker starts
    # its imports now, while the in-process jobs and the scheduler get going; the
    # scheduler wakes only when a job ends (common.smk, without_rate_limit)
    if jobs_run_here():
        warm_up()
        without_rate_limit()


onsuccess:
    if Path(f"{REPORTS}/index.html").exists():
        print(
            f"\nReports: {Path(REPORTS, 'index.html').resolve()}", file=sys.stderr
        )


onerror:
    print(
        "\nThe build stopped: a job failed (its message and log are named above) or it was "
        "interrupted.\nTo resume, run `snakemake -c2` again: finished jobs are kept and "
        "interrupted ones rerun.\nAfter a killed build (SIGKILL, a crash) run "
        "`snakemake --unlock` once first. See docs/releases.md, 'When a build is interrupted'.",
        file=sys.stderr,
    )
