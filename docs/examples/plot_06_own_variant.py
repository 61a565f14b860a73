"""
Your own variant in the benchmark
=================================

A benchmark variant is a config entry: a design rule and its parameters
(:mod:`abglib.bench.variants`; ``config.yaml``, ``benchmark: variants:``). Adding one to the
config schedules exactly its cells; here the same library calls run without Snakemake on a
small scenario: a dataset (:func:`abglib.bench.datasets.generate`), one cell per variant
(:func:`abglib.bench.benchmark.run_cell`) and the league table
(:func:`abglib.bench.benchmark.league_table`), with the build's VRF check at the
Bonferroni threshold of :func:`abglib.bench.metrics.fail_threshold`. The check needs enough
samples after the tracker's start-up transient: the Simpson variant's small gains settle
slowly, so on this short scenario its check says ``n/a (too few samples)``.
"""

import matplotlib.pyplot as plt

from abglib.bench import benchmark, datasets, metrics, variants

scenario = {
    "description": "constant acceleration (2 m/s^2 in x), white noise",
    "dt": 1.0,
    "n_samples": 200,
    "runs": 50,
    "seed": 7102,
    "noise": {"sigma": 10.0, "colour": "white"},
    "tracks": {
        "x": {"kind": "constant_acceleration", "p0": 0.0, "v0": 100.0, "a0": 2.0},
        "y": {"kind": "constant_velocity", "p0": 0.0, "v0": 50.0},
    },
}
specs = {
    # two variants of config.yaml ...
    "std_ab_a0.3": {"rule": "standard_alpha", "alpha": 0.3, "order": 2},
    "bb_a0.5": {"rule": "benedict_bordner", "alpha": 0.5},
    # ... and your own: an alpha-beta-gamma tracker with Simpson's gamma rule
    "my_simpson_a0.4": {"rule": "simpson", "alpha": 0.4, "gamma": 0.02},
}

data = datasets.generate("demo_ca", scenario)
threshold = metrics.fail_threshold(scenario["runs"], n_checks=2 * len(specs), family_alpha=1e-3)
cells = []
for name, spec in specs.items():
    variants.check_variant(spec, scenario["dt"], scenario["n_samples"], name=name)
    cell = benchmark.run_cell(data, spec, name)
    benchmark.check_cell(cell, threshold)  # the measured VRF agrees with the exact one
    cells.append(cell)
league = benchmark.league_table(cells, threshold)
print(league[["rank", "variant", "family", "rmse_x_smooth", "vrf_check"]].to_string())

fig, ax = plt.subplots(figsize=(7, 3.5))
table = league.set_index("variant")
ax.barh(table.index, table["rmse_x_smooth"], color="C0")
ax.set_xlabel("RMSE of the smoothed position, x and y (m)")
ax.set_title(f"scenario {data.name}: {scenario['runs']} runs of {scenario['n_samples']} samples")
fig.tight_layout()
plt.show()
