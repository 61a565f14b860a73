# Simulated radar datasets (abglib.datasets): one Parquet file and one JSON manifest per
# scenario of config["datasets"]["scenarios"]. Other stages take their inputs through
# dataset_files(name) (common.smk).


rule dataset:
    output:
        parquet="results/datasets/{scenario}.parquet",
        manifest="results/datasets/{scenario}.manifest.json",
    log:
        "logs/datasets/{scenario}.log",
    benchmark:
        "benchmarks/results/datasets/{scenario}.tsv"
    wildcard_constraints:
        scenario="|".join(DATASET_SCENARIOS) or "no-scenarios-configured",
    conda:
        "../envs/abglib.yaml"
    params:
        spec=lambda wildcards: DATASET_SCENARIOS[wildcards.scenario],
    script:
        "../scripts/dataset.py"


rule datasets:
    input:
        [f for name in DATASET_SCENARIOS for f in dataset_files(name)],
