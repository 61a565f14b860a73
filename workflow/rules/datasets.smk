# Simulated radar datasets (abglib.bench.datasets): one Parquet file and one JSON manifest per
# scenario of config["datasets"]["scenarios"]. Other stages take their inputs through
# dataset_files(name) (common.smk).


# The job is tiny (milliseconds of numpy), so it runs inside Snakemake (run:) instead of
# paying a Python start-up per scenario; the science is abglib.bench.datasets.
rule dataset:
    output:
        parquet="results/datasets/{scenario}.parquet",
        manifest="results/datasets/{scenario}.manifest.json",
    log:
        "logs/datasets/{scenario}.log",
    wildcard_constraints:
        scenario="|".join(DATASET_SCENARIOS) or "no-scenarios-configured",
    # in-process jobs first: they run while the warm worker imports (onstart, ~4 s), which
    # script jobs would only wait for
    priority: 2
    params:
        code=code_of("abglib.bench.datasets"),
        spec=lambda wildcards: DATASET_SCENARIOS[wildcards.scenario],
    run:
        from abglib.bench.datasets import build

        build(
            wildcards.scenario, params.spec, output.parquet, output.manifest, log[0]
        )


rule datasets:
    input:
        [f for name in DATASET_SCENARIOS for f in dataset_files(name)],
