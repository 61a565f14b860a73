# Benchmark matrix (issue 7): every tracker variant of config["benchmark"]["variants"] on
# every scenario of config["benchmark"]["scenarios"] (datasets.smk), one job per cell;
# the league table, heatmap and noise-versus-lag figure; the peers section; the report.
# Every job reads only its input files and writes only its outputs, so the matrix runs
# unchanged on a cluster through a Snakemake executor plugin (docs/cluster.md).

# The matrix's settings, checks and input functions are in common.smk.


# one job per cell, run inside Snakemake's own process (run:; the default profile sets
# force-use-threads), so the cells share one Python start-up, one import of abglib and
# one numba load; on a cluster each is a job of its own. abglib.bench.cell.cell_job
# writes the CSV atomically after the VRF build check and logs to the cell's log.
rule benchmark_cell:
    input:
        parquet="results/datasets/{scenario}.parquet",
        manifest="results/datasets/{scenario}.manifest.json",
    output:
        cell="results/benchmark/cells/{variant}/{scenario}.csv",
    log:
        "logs/benchmark/cells/{variant}/{scenario}.log",
    wildcard_constraints:
        variant="|".join(map(re.escape, BENCH_VARIANTS)) or "no-variants-configured",
        scenario="|".join(map(re.escape, BENCH_SCENARIOS)) or "no-scenarios-configured",
    # in-process, like the datasets: first, while the warm worker imports
    priority: 1
    threads: 1
    resources:
        mem_mb=bench_mem_mb,
        runtime=30,
    params:
        code=bench_cell_code,
        spec=lambda wildcards: BENCH_SPECS[wildcards.variant],
        scenario_spec=lambda wildcards: DATASET_SCENARIOS[wildcards.scenario],
        seed=lambda wildcards: int(BENCH["seed"])
        + int(DATASET_SCENARIOS[wildcards.scenario]["seed"]),
        settings={
            k: BENCH.get(k)
            for k in (
                "runs",
                "burn_in",
                "init",
                "ci_level",
                "chunk_runs",
                "family_alpha",
                "family_size",
            )
        },
        digits=config["significant_digits"],
    run:
        bench_cell(input, output, params, wildcards, threads, log)


script_rule(
    "benchmark_league",
    "benchmark_league.py",
    input={"cells": bench_cells()},
    output={
        "league": report(
            "results/benchmark/league.csv",
            category="Benchmark",
            labels={"table": "league table"},
        ),
        "cells": "results/benchmark/cells.csv",
        "tradeoff": "results/benchmark/tradeoff.csv",
        "variants": "results/benchmark/variants.csv",
    },
    log="benchmark/league",
    benchmark=False,
    threads=1,
    resources={"mem_mb": 1000, "runtime": 10},
    params={
        "variants": BENCH_VARIANTS,
        "family_alpha": BENCH.get("family_alpha"),
        "family_size": BENCH.get("family_size"),
        "rank_by": BENCH.get("rank_by"),
        "digits": config["significant_digits"],
    },
)


script_rule(
    "benchmark_tradeoff",
    "benchmark_tradeoff.py",
    input={
        "parquets": lambda wildcards: [
            dataset_files(s)[0] for s in BENCH.get("tradeoff_scenarios", [])
        ]
    },
    output={"curves": "results/benchmark/tradeoff_curves.csv"},
    log="benchmark/tradeoff",
    benchmark=False,
    threads=1,
    resources={"mem_mb": 2000, "runtime": 20},
    params={
        "families": BENCH.get("tradeoff_families"),
        "burn_in": BENCH.get("burn_in"),
        "init": BENCH.get("init"),
        "digits": config["significant_digits"],
    },
)


script_rule(
    "benchmark_figures",
    "benchmark_figures.py",
    input={
        "league": "results/benchmark/league.csv",
        "tradeoff": "results/benchmark/tradeoff.csv",
        "curves": "results/benchmark/tradeoff_curves.csv",
    },
    output={
        "heatmap": report(
            "results/benchmark/figures/heatmap.png",
            category="Benchmark",
            labels={"figure": "heatmap"},
        ),
        "tradeoff": report(
            "results/benchmark/figures/tradeoff.png",
            category="Benchmark",
            labels={"figure": "noise versus lag"},
        ),
    },
    log="benchmark/figures",
    benchmark=False,
    threads=1,
    resources={"mem_mb": 1000, "runtime": 10},
    params={
        "dpi": config["figure_dpi"],
        "rank_by": BENCH.get("rank_by"),
        "tradeoff_scenarios": BENCH.get("tradeoff_scenarios"),
    },
)


script_rule(
    "benchmark_peers",
    "benchmark_peers.py",
    output={
        "peers": report(
            "results/benchmark/peers.csv",
            category="Benchmark",
            labels={"table": "peers"},
        )
    },
    log="benchmark/peers",
    benchmark=False,
    threads=1,
    resources={"mem_mb": 1000, "runtime": 10},
    params={
        "rtol": BENCH.get("peers", {}).get("rtol"),
        "seed": BENCH.get("peers", {}).get("seed"),
        "digits": config["significant_digits"],
    },
)


# wall-clock timings: not byte-reproducible, kept out of the deterministic tables
script_rule(
    "benchmark_speed",
    "benchmark_speed.py",
    input={"script": str(Path(workflow.basedir) / "benchmarks" / "engine_speed.py")},
    output={"speed": "results/benchmark/engine_speed.csv"},
    log="benchmark/engine_speed",
    benchmark=False,
    threads=1,
    resources={"mem_mb": 2000, "runtime": 10},
    params={
        "repeats": BENCH.get("speed", {}).get("repeats", 1),
        "run": BENCH.get("speed", {}).get("run", False),
    },
)


script_rule(
    "benchmark_report",
    "render_report.py",
    NOTEBOOKS / "benchmark.py",
    input={
        "notebook": str(NOTEBOOKS / "benchmark.py"),
        "figures": [
            "results/benchmark/figures/heatmap.png",
            "results/benchmark/figures/tradeoff.png",
        ],
        "tables": [
            "results/benchmark/league.csv",
            "results/benchmark/cells.csv",
            "results/benchmark/tradeoff.csv",
            "results/benchmark/tradeoff_curves.csv",
            "results/benchmark/variants.csv",
            "results/benchmark/peers.csv",
            "results/benchmark/engine_speed.csv",
        ],
    },
    output={
        "html": f"{REPORTS}/benchmark/index.html",
        "notebook": f"{REPORTS}/benchmark/notebook.py",
        "figures": expand(
            f"{REPORTS}/benchmark/figures/{{f}}.png", f=["heatmap", "tradeoff"]
        ),
        "tables": expand(
            f"{REPORTS}/benchmark/tables/{{t}}.csv",
            t=["league", "cells", "tradeoff", "tradeoff_curves", "variants", "peers"],
        ),
    },
    log="reports/benchmark",
    benchmark=False,
    threads=1,
    resources={"mem_mb": 2000, "runtime": 20},
    params={
        "doc": "benchmark",
        "version": VERSION,
        "repo": lambda wildcards, input: REPO,
        "timeout": config["notebook_timeout"],
        "page": lambda wildcards, input: REPORT_PAGE("benchmark", input),
        "settings": {"rank_by": BENCH.get("rank_by")},
    },
)
