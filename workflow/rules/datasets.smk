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
    params:
        library=LIBRARY_HASH,
        spec=lambda wildcards: DATASET_SCENARIOS[wildcards.scenario],
    run:
        from abglib.bench import datasets

        ds = datasets.generate(wildcards.scenario, params.spec)
        datasets.write(ds, output.parquet, output.manifest)
        Path(log[0]).write_text(
            f"wrote {output.parquet}: {ds.runs} runs x {ds.n_samples} samples, "
            f"coords {ds.coords}, noise {ds.noise}\n",
            encoding="utf-8",
        )


rule datasets:
    input:
        [f for name in DATASET_SCENARIOS for f in dataset_files(name)],
