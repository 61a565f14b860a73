"""The benchmark matrix: every tracker variant on every dataset scenario.

One *cell* is a (variant, scenario) pair: :func:`run_cell` designs the variant's gains
for the scenario's sample interval (:mod:`abglib.bench.variants`), runs it on the scenario's
Monte Carlo runs (an :class:`abglib.bench.datasets.Dataset`) and scores it
(:func:`abglib.bench.metrics.evaluate_cell`); :func:`check_cell` fails a fixed-gain cell on
white noise whose measured VRF is outside its simultaneous confidence interval.
:func:`league_table` ranks the variants per scenario and :func:`tradeoff_table` gives
the noise-versus-lag points of each design family.
"""

from __future__ import annotations

import threading
from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING

import numpy as np

from .._checks import AbglibValueError
from ..gains import Gains
from . import metrics, variants
from ._family import n_vrf_checks

if TYPE_CHECKING:  # pandas is imported where it is used: the workflow's parse needs none
    import pandas as pd

__all__ = [
    "cell_dataset",
    "check_cell",
    "league_table",
    "n_vrf_checks",
    "run_cell",
    "tradeoff_sweep",
    "tradeoff_table",
]

#: Columns of the league table, in order (the metrics are those of the ``all`` row).
LEAGUE_COLUMNS = (
    "scenario",
    "rank",
    "variant",
    "family",
    "rule",
    "alpha",
    "beta",
    "gamma",
    "noise_colour",
    "runs",
    "diverged",
    "rmse_x_smooth",
    "rmse_x_pred",
    "rmse_v_smooth",
    "rmse_v_pred",
    "max_x_smooth",
    "max_x_pred",
    "noise_rms_x_smooth",
    "lag_rms_x_smooth",
    "vrf_check",
    "vrf_worst_t",
)


def _gain_summary(g) -> dict:
    if g is None:
        return {"alpha": None, "beta": None, "gamma": None}
    if g.shape == ():
        return {"alpha": float(g.alpha), "beta": float(g.beta), "gamma": float(g.gamma)}
    # time-varying: the final (steady) values
    return {k: float(np.ravel(v)[-1]) for k, v in zip(("alpha", "beta", "gamma"), g, strict=True)}


def run_cell(
    dataset,
    spec: Mapping,
    variant: str,
    *,
    burn_in: int = 10,
    init: str = "two_point",
    ci_level: float = 0.95,
    chunk_runs: int = 1000,
    outputs: Sequence[str] = metrics.OUTPUTS,
) -> pd.DataFrame:
    """Metrics of one variant on one dataset, one row per coordinate plus ``all``.

    Parameters
    ----------
    dataset : abglib.bench.datasets.Dataset
        Truth and measurements ``(runs, n)`` per coordinate, ``dt``, ``noise``
        (``{"sigma", "colour", "rho"}``).
    spec : mapping
        The variant's config entry (:func:`abglib.bench.variants.variant_rule`).
    variant : str
        Its name.
    burn_in, init, ci_level, chunk_runs, outputs
        As :func:`abglib.bench.metrics.evaluate_cell`. ``init="three_point"`` needs gamma > 0,
        so alpha-beta variants fall back to ``"two_point"``.
    """
    import pandas as pd

    rule, params = variants.variant_rule(spec, variant)
    n = int(np.shape(dataset.t)[0])
    noise = dict(dataset.noise)
    colour = noise.get("colour", "white")
    model = {"model": colour, "rho": float(noise.get("rho", 0.0))}
    coords = {
        c: {
            "truth_pos": dataset.truth_pos[c],
            "truth_vel": dataset.truth_vel[c],
            "z": dataset.z[c],
            "sigma": float(noise["sigma"]),
        }
        for c in dataset.coords
    }
    gains, runner = None, None
    built = variants.variant_build(spec, dataset.dt, n, variant)
    if isinstance(built, Gains):
        gains = built
        if init == "three_point" and np.all(np.asarray(gains.gamma) == 0.0):
            init = "two_point"
    else:
        runner = built
    rows = metrics.evaluate_cell(
        coords,
        dataset.dt,
        gains=gains,
        runner=runner,
        noise=model,
        burn_in=burn_in,
        init=init,
        ci_level=ci_level,
        chunk_runs=chunk_runs,
        outputs=outputs,
    )
    head = {
        "variant": variant,
        "scenario": dataset.name,
        "rule": rule.name,
        "family": rule.family_of(params),
        **_gain_summary(gains),
        "dt": float(dataset.dt),
        "noise_colour": colour,
        "noise_rho": model["rho"],
    }
    clash = sorted(set(head) & set(rows[0]))
    if clash:
        raise AbglibValueError(f"cell columns {clash} are both head and metric columns")
    # one frame from whole rows (inserting the head columns one by one into the metrics'
    # frame split a block per column: ~5 ms of a ~30 ms cell)
    return pd.DataFrame([{**head, **r} for r in rows])


def check_cell(cell: pd.DataFrame, threshold: float, colours: Sequence[str] = ("white",)) -> None:
    """Raise :class:`abglib.bench.metrics.VRFMismatchError` if a fixed-gain VRF check fails.

    ``threshold`` is the simultaneous ``|t|`` bound (:func:`abglib.bench.metrics.fail_threshold`);
    only cells whose noise colour is in ``colours`` are checked (white noise: exact theory).
    """
    colour = str(cell["noise_colour"].iloc[0])
    # only the columns the check reads (a whole cell's records cost ~15 ms)
    wanted = ["coord", "fixed_gain"] + [
        f"vrf_{o}_{k}" for o in metrics.OUTPUTS for k in ("t", "measured", "theory")
    ]
    cols = [c for c in wanted if c in cell.columns]
    bad = metrics.vrf_failures(cell[cols].to_dict("records"), threshold, colours, colour)
    if bad:
        lines = [
            f"  coord {c}, {o}: measured VRF {m:.6g} vs exact {th:.6g} (t = {t:.2f}, "
            f"bound {threshold:.2f})"
            for c, o, m, th, t in bad
        ]
        raise metrics.VRFMismatchError(
            f"variant {cell['variant'].iloc[0]!r} on scenario {cell['scenario'].iloc[0]!r}: "
            "the measured variance reduction of a fixed-gain tracker on white noise is outside "
            "its simultaneous confidence interval around abglib.analysis.vrf - a bug in the "
            "engine, the metrics or the theory:\n" + "\n".join(lines)
        )


def _vrf_summary(cell: pd.DataFrame, threshold: float) -> tuple[str, float | None]:
    per = cell[cell["coord"] != "all"]
    ts = per[[f"vrf_{o}_t" for o in metrics.OUTPUTS]].to_numpy(dtype=float)
    ts = ts[np.isfinite(ts)]
    if ts.size == 0:
        fixed = bool(per["fixed_gain"].iloc[0]) if len(per) else False
        if bool(per["diverged"].iloc[0]):
            return "n/a (unstable)", None
        return ("n/a (too few samples)" if fixed else "n/a (not fixed-gain)"), None
    worst = float(ts[np.argmax(np.abs(ts))])
    return ("pass" if abs(worst) <= threshold else "outside"), worst


def league_table(
    cells: Sequence[pd.DataFrame], threshold: float, rank_by: str = "rmse_x_smooth"
) -> pd.DataFrame:
    """Per scenario, the variants ranked by ``rank_by`` (``all`` row; diverged last)."""
    import pandas as pd

    if not cells:
        raise AbglibValueError("league_table needs at least one cell")
    rows = []
    for cell in cells:
        rec = cell[cell["coord"] == "all"].iloc[0].to_dict()
        if rank_by not in rec:
            raise AbglibValueError(f"rank_by must be a metric column, got {rank_by!r}")
        rec["vrf_check"], rec["vrf_worst_t"] = _vrf_summary(cell, threshold)
        rows.append(rec)
    df = pd.DataFrame(rows)
    df["_key"] = df[rank_by].astype(float).where(~df["diverged"].astype(bool), np.inf)
    df["_key"] = df["_key"].fillna(np.inf)
    df = df.sort_values(["scenario", "_key", "variant"], kind="mergesort")
    df["rank"] = df.groupby("scenario").cumcount() + 1
    return df[list(LEAGUE_COLUMNS)].reset_index(drop=True)


def tradeoff_table(cells: Sequence[pd.DataFrame], output: str = "x_smooth") -> pd.DataFrame:
    """Noise-versus-lag points: per (scenario, variant), the RMS of the noise part and of
    the lag part of the error (``all`` row; linear, non-diverged trackers only)."""
    import pandas as pd

    rows = []
    for cell in cells:
        rec = cell[cell["coord"] == "all"].iloc[0]
        if bool(rec["diverged"]) or pd.isna(rec[f"noise_rms_{output}"]):
            continue
        rows.append(
            {
                "scenario": rec["scenario"],
                "variant": rec["variant"],
                "family": rec["family"],
                "output": output,
                "noise_rms": float(rec[f"noise_rms_{output}"]),
                "lag_rms": float(rec[f"lag_rms_{output}"]),
                "rmse": float(rec[f"rmse_{output}"]),
            }
        )
    return pd.DataFrame(
        rows, columns=["scenario", "variant", "family", "output", "noise_rms", "lag_rms", "rmse"]
    )


def tradeoff_sweep(
    datasets: Sequence, families: Mapping, *, burn_in: int = 10, init: str = "two_point"
) -> pd.DataFrame:
    """Noise-versus-lag curves: each design family swept over its parameter.

    Parameters
    ----------
    datasets : sequence of abglib.bench.datasets.Dataset
        The scenarios of the trade-off figure.
    families : mapping
        ``label -> {rule: ..., <fixed parameters>, sweep: {<parameter>: [values]}}``; each
        value of the swept parameter is one variant (:mod:`abglib.bench.variants`).
    burn_in, init
        As :func:`run_cell`.

    Returns
    -------
    DataFrame
        ``scenario, family, parameter, value, noise_rms, lag_rms, rmse`` of the smoothed
        position (``all`` row), one row per (scenario, family, value); points where the
        rule cannot realise the value for the scenario's ``dt`` are skipped.
    """
    import pandas as pd

    rows = []
    for label, fam in families.items():
        fam = dict(fam)
        sweep = fam.pop("sweep", None)
        if not isinstance(sweep, Mapping) or len(sweep) != 1:
            raise AbglibValueError(
                f"trade-off family {label!r} needs sweep: {{<parameter>: [values]}}, got {sweep!r}"
            )
        ((param, values),) = sweep.items()
        for ds in datasets:
            for v in values:
                spec = {**fam, param: v}
                try:
                    cell = run_cell(
                        ds,
                        spec,
                        f"{label} {param}={v}",
                        burn_in=burn_in,
                        init=init,
                        outputs=("x_smooth",),
                    )
                except AbglibValueError:
                    continue
                rec = cell[cell["coord"] == "all"].iloc[0]
                if bool(rec["diverged"]) or pd.isna(rec["noise_rms_x_smooth"]):
                    continue
                rows.append(
                    {
                        "scenario": ds.name,
                        "family": label,
                        "parameter": param,
                        "value": float(v),
                        "noise_rms": float(rec["noise_rms_x_smooth"]),
                        "lag_rms": float(rec["lag_rms_x_smooth"]),
                        "rmse": float(rec["rmse_x_smooth"]),
                    }
                )
    return pd.DataFrame(
        rows, columns=["scenario", "family", "parameter", "value", "noise_rms", "lag_rms", "rmse"]
    )


#: Bytes of regenerated datasets :func:`cell_dataset` keeps in the process for the next
#: cells of the same scenario (the cells of a sweep run as threads of one process).
DATASET_CACHE_BYTES = 2_000_000_000

_dataset_cache: dict = {}  # key -> Dataset, oldest first
_dataset_locks: dict = {}  # key -> Lock: one generation per key, the other threads wait
_cache_lock = threading.Lock()


def _dataset_bytes(ds) -> int:
    return sum(
        a.nbytes for d in (ds.truth_pos, ds.truth_vel, ds.truth_acc, ds.z) for a in d.values()
    )


def _read_only(ds):
    for d in (ds.truth_pos, ds.truth_vel, ds.truth_acc, ds.z):
        for a in d.values():
            a.setflags(write=False)
    return ds


def cell_dataset(parquet, scenario: str, spec: Mapping, runs=None, seed=None):
    """The dataset of one benchmark cell: the stored Parquet file, or, when the config
    overrides the Monte Carlo size (``benchmark.runs``), the scenario regenerated from its
    spec with that many runs and the seed ``seed``.

    A regenerated dataset is kept (read-only, up to ``DATASET_CACHE_BYTES``, least
    recently used dropped first) for the other cells of the scenario in this process: the
    same spec, runs and seed give the same dataset, so it is generated once per scenario."""
    import json

    from . import datasets

    if not runs:
        return datasets.read(parquet)
    key = (scenario, json.dumps(dict(spec), sort_keys=True, default=str), int(runs), int(seed))
    with _cache_lock:
        lock = _dataset_locks.setdefault(key, threading.Lock())
    with lock:
        with _cache_lock:
            if key in _dataset_cache:
                _dataset_cache[key] = _dataset_cache.pop(key)  # most recently used last
                return _dataset_cache[key]
        ds = _read_only(datasets.generate(scenario, {**spec, "runs": int(runs)}, seed=int(seed)))
        with _cache_lock:
            _dataset_cache[key] = ds
            while sum(map(_dataset_bytes, _dataset_cache.values())) > DATASET_CACHE_BYTES:
                _dataset_cache.pop(next(iter(_dataset_cache)))
        return ds
