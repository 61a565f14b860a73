r"""The simulation study of Al-Wagih & Abdulla (seed 001, sections 6-7).

Runs the methods of :mod:`abglib.methods` (M1-M5, the causal M5) and two steady-state
Kalman designs on the ten reconstructed experiments (dataset scenarios generated in
memory with :func:`abglib.bench.datasets.generate`, deterministic and seeded, as the
``dataset`` rule writes them), and builds the paper's tables from the RMSEs:

* Tables 1-2: RMSE (eq 26) per experiment, coordinate and method - on one realisation,
  as the paper, and as Monte Carlo means with confidence intervals over all runs;
* Tables 3-4: averages over the experiments of the RMSE differences ``M1 - Mi`` and
  ``M2 - Mi`` (i = 3, 4, 5), with the paired t-test of section 7;
* Tables 5-6: percentage changes with respect to M1 (eq 27).

:class:`AlwagihStudy` holds every table of the report; its RMSEs come from a cache keyed
by the scenario and the method's own settings, so a study at another value of one
assumed input (:func:`abglib.replications.evaluate`) recomputes only the methods and
experiments that input changes.
"""

from __future__ import annotations

import copy
import json
from collections.abc import Mapping
from functools import cached_property

import numpy as np
import pandas as pd

from ... import design, methods
from ..._checks import AbglibValueError
from ...bench import datasets
from ...bench.metrics import t_quantile
from ...common.memo import lru_cache_bytes
from ...engine import track
from .._claims import Study
from .printed import BASES, COMPARED, PAPER_METHODS, printed_consistency, printed_t12

__all__ = [
    "BASES",
    "COMPARED",
    "METHODS",
    "PAPER_METHODS",
    "AlwagihStudy",
    "compare_methods",
    "grid",
    "mc_summary",
    "paired_ttests",
    "paper_differences",
    "paper_percentages",
    "rank_methods",
    "reconstructed_scenarios",
    "run_method",
    "run_methods",
    "sensitivity",
]

#: The paper's five methods, then the causal M5 and the two Kalman designs (beyond it).
METHODS = (*PAPER_METHODS, "M5_causal", "kalata_ab", "kalman_ss")
#: The config entries (``alwagih`` section) each method reads.
METHOD_SETTINGS = {
    "M1": ("m1_alpha",),
    "M2": (),
    "M3": ("m3_w_grid",),
    "M4": ("m4",),
    "M5": ("m5",),
    "M5_causal": ("m5",),
    "kalata_ab": ("kalman",),
    "kalman_ss": ("kalman",),
}


def grid(spec: Mapping) -> np.ndarray:
    """Evenly spaced grid ``{start, stop, n}`` (both ends included)."""
    return np.linspace(float(spec["start"]), float(spec["stop"]), int(spec["n"]))


def run_method(method: str, z, truth_acc, dt: float, sigma: float, cfg: Mapping):
    """Predictions ``x_pred`` (array like ``z``) of one method of :data:`METHODS`.

    Parameters
    ----------
    method : str
        One of :data:`METHODS`.
    z : array (runs, n)
        Measurements of one coordinate.
    truth_acc : array (n,) or (runs, n)
        True acceleration (m/s²); only its RMS enters the Kalman designs.
    dt, sigma : float
        Sample interval (s) and measurement-noise standard deviation (m).
    cfg : mapping
        The ``alwagih`` config section (``m1_alpha``, ``m3_w_grid``, ``m4``, ``m5``,
        ``kalman``).

    Notes
    -----
    ``kalata_ab``: Kalata's steady-state alpha-beta (design.kalata_ab) with tracking
    index ``Lambda = sigma_a T^2 / sigma``; ``kalman_ss``: the steady-state Kalman
    alpha-beta of the continuous white-noise-acceleration model (design.steady_state_kalman,
    ``model="continuous"``, ``q = sigma_a^2 T``). ``sigma_a`` is the RMS of the true
    acceleration over the track, floored at ``kalman.sigma_a_floor`` - a design a user
    could make knowing the target's manoeuvre level, not the realised noise.
    """
    if method == "M1":
        return methods.m1(z, cfg["m1_alpha"], dt).x_pred
    if method == "M2":
        return methods.m2(z, dt).x_pred
    if method == "M3":
        return methods.m3(z, grid(cfg["m3_w_grid"]), dt).x_pred
    if method == "M4":
        m4 = cfg["m4"]
        return methods.m4(z, m4["alpha0"], int(m4["window"]), grid(m4["alpha_grid"]), dt).x_pred
    if method in ("M5", "M5_causal"):
        bank = grid(cfg["m5"]["alphas"])
        if method == "M5":
            return methods.m5(z, bank, dt).x_pred
        return methods.m5(z, bank, dt, causal=True, memory=int(cfg["m5"]["causal_memory"])).x_pred
    if method not in ("kalata_ab", "kalman_ss"):
        raise AbglibValueError(f"method must be one of {list(METHODS)}, got {method!r}")
    sigma_a = max(
        float(np.sqrt(np.mean(np.square(truth_acc)))), float(cfg["kalman"]["sigma_a_floor"])
    )
    if method == "kalata_ab":
        gains = design.kalata_ab(sigma_a * dt**2 / sigma)
    else:
        gains = design.steady_state_kalman(sigma_a**2 * dt, sigma**2, dt, 2, "continuous")
    return track(z, gains, dt=dt, init="two_point", outputs=("x_pred",)).x_pred


def run_methods(z, truth_acc, dt: float, sigma: float, cfg: Mapping, which=METHODS) -> dict:
    """``{method: x_pred}`` of every method in ``which`` (:func:`run_method`)."""
    return {m: run_method(m, z, truth_acc, dt, sigma, cfg) for m in which}


def compare_methods(datasets_by_noise: Mapping, cfg: Mapping, which=METHODS) -> pd.DataFrame:
    """RMSE (eq 26) of every method, run, coordinate and experiment (long table).

    ``datasets_by_noise``: ``{"white": [Dataset, ...], "coloured": [...]}``, experiments
    numbered 1.. in list order. Columns: noise, experiment, scenario, coord, method, run,
    rmse.
    """
    frames = []
    for noise, dss in datasets_by_noise.items():
        for e, ds in enumerate(dss, start=1):
            for c in ds.coords:
                preds = run_methods(
                    ds.z[c], ds.truth_acc[c][0], ds.dt, ds.noise["sigma"], cfg, which
                )
                for m in which:
                    r = methods.rmse(preds[m], ds.truth_pos[c])
                    frames.append(
                        pd.DataFrame(
                            {
                                "noise": noise,
                                "experiment": e,
                                "scenario": ds.name,
                                "coord": c.upper(),
                                "method": m,
                                "run": np.arange(r.size),
                                "rmse": r,
                            }
                        )
                    )
    return pd.concat(frames, ignore_index=True)


def mc_summary(rmse: pd.DataFrame, confidence: float = 0.95) -> pd.DataFrame:
    """Monte Carlo mean RMSE with a Student-t confidence interval over the runs.

    One row per (noise, experiment, coord, method), in the order the groups first appear:
    ``runs`` (as a float, as the table always held it), ``mean``, ``std`` (ddof 1) and the
    two-sided interval ``mean -+ t_{(1+confidence)/2, runs-1} std / sqrt(runs)``; with one
    run, NaN. Each group's numbers are numpy's reductions of its runs in table order (the
    bits of the former ``groupby(...).apply``, without a Series per group: until v0.4.5
    the claims' robustness built this table for every study, ~160 groups each).
    """
    keys = ["noise", "experiment", "coord", "method"]
    # {key: its rows' positions, ascending}, in the order the groups first appear (the
    # dict's own order is not that on every pandas: 2.2 gives another)
    groups = sorted(rmse.groupby(keys, sort=False).indices.items(), key=lambda kv: kv[1][0])
    values = rmse["rmse"].to_numpy()
    cols: dict[str, list] = {k: [] for k in (*keys, "runs", "mean", "std", "ci_low", "ci_high")}
    for key, where in groups:
        x = values[where]
        n = x.size
        std = x.std(ddof=1) if n > 1 else np.nan
        h = t_quantile(0.5 + confidence / 2, n - 1) * (std / np.sqrt(n)) if n > 1 else np.nan
        mean = x.mean()
        for k, v in zip(keys, key, strict=True):
            cols[k].append(v)
        cols["runs"].append(float(n))
        cols["mean"].append(mean)
        cols["std"].append(std)
        cols["ci_low"].append(mean - h)
        cols["ci_high"].append(mean + h)
    out = pd.DataFrame(cols)
    for k in keys:  # the key columns keep the long table's dtypes
        out[k] = out[k].astype(rmse[k].dtype)
    return out


def paper_differences(rmse_wide: pd.DataFrame) -> pd.DataFrame:
    """Tables 3-4: average over experiments of ``RMSE_base - RMSE_Mi`` (section 7).

    ``rmse_wide``: index (noise, experiment, coord), columns methods. Returns columns
    noise, base, coord, method, mean_difference.
    """
    rows = []
    for (noise, coord), g in rmse_wide.groupby(level=["noise", "coord"], sort=False):
        for base in BASES:
            for m in COMPARED:
                rows.append(
                    {
                        "noise": noise,
                        "base": base,
                        "coord": coord,
                        "method": m,
                        "mean_difference": float((g[base] - g[m]).mean()),
                    }
                )
    return pd.DataFrame(rows)


def paired_ttests(rmse_wide: pd.DataFrame) -> pd.DataFrame:
    """The paired t-test of section 7 on the differences of Tables 3-4.

    One test per (noise, base, coord, method) over the experiments' pairs
    ``(RMSE_base, RMSE_Mi)``; two-sided p-value.
    """
    from scipy import stats

    rows = []
    pairs = [(base, m) for base in BASES for m in COMPARED]
    for (noise, coord), g in rmse_wide.groupby(level=["noise", "coord"], sort=False):
        col = {c: g[c].to_numpy() for c in (*BASES, *COMPARED)}
        # every pair's test at once, column by column (the same numbers as one call each)
        tt, pp = stats.ttest_rel(
            np.column_stack([col[base] for base, _ in pairs]),
            np.column_stack([col[m] for _, m in pairs]),
            axis=0,
        )
        for (base, m), t, p in zip(pairs, tt, pp, strict=True):
            d = col[base] - col[m]
            rows.append(
                {
                    "noise": noise,
                    "base": base,
                    "coord": coord,
                    "method": m,
                    "pairs": d.size,
                    "mean_difference": d.mean(),
                    "t": float(t),
                    "p_value": float(p),
                }
            )
    return pd.DataFrame(rows)


def paper_percentages(rmse_wide: pd.DataFrame) -> pd.DataFrame:
    """Tables 5-6: ``PC_{i,1}`` (eq 27) per experiment and coordinate, i = 3, 4, 5."""
    out = rmse_wide.reset_index()[["noise", "experiment", "coord"]].copy()
    for m in COMPARED:
        out[m] = methods.percentage_change(rmse_wide["M1"].to_numpy(), rmse_wide[m].to_numpy())
    return out


def sensitivity(mean_rmse, cfg: Mapping, alphas, windows) -> pd.DataFrame:
    """How the paper's ranking depends on the settings it does not print.

    For every ``alpha_0`` (used by M1 and as M4's start) and M4 window length: the Monte
    Carlo mean RMSE of M1-M5 averaged over the experiments, per noise and coordinate, the
    ranking, and whether the paper's conclusion "M5, then M4, then M3" holds.
    ``mean_rmse(cfg)`` gives those means as a Series indexed (noise, coord, method).
    """
    rows = []
    for a0 in alphas:
        for w in windows:
            c = dict(cfg)
            c["m1_alpha"] = float(a0)
            c["m4"] = dict(cfg["m4"], alpha0=float(a0), window=int(w))
            means = mean_rmse(c)
            for (noise, coord), g in means.groupby(level=["noise", "coord"], sort=False):
                m = {k[2]: float(v) for k, v in g.items()}
                rows.append(
                    {
                        "alpha0": float(a0),
                        "window": int(w),
                        "noise": noise,
                        "coord": coord,
                        **m,
                        "ranking": rank_methods(m),
                        "M5_then_M4_then_M3": m["M5"] < m["M4"] < m["M3"],
                    }
                )
    columns = [
        "alpha0",
        "window",
        "noise",
        "coord",
        *PAPER_METHODS,
        "ranking",
        "M5_then_M4_then_M3",
    ]
    return pd.DataFrame(rows, columns=columns)


def rank_methods(means: Mapping) -> str:
    """Methods ordered from lowest to highest value, e.g. ``'M5<M4<M3<M2<M1'``."""
    return "<".join(sorted(means, key=lambda k: (means[k], k)))


# --------------------------------------------------------------------------- the study
def reconstructed_scenarios(scenarios: Mapping, cfg: Mapping) -> dict:
    """``{noise: [(name, spec), ...]}``: the experiments' dataset scenarios with the
    reconstruction knobs of ``cfg["reconstruction"]`` applied.

    ``noise_scale`` multiplies every noise sigma, ``manoeuvre_scale`` every acceleration
    (``acc`` of a segment, ``a0`` of a polynomial track), and ``coloured_rho`` replaces the
    AR(1) coefficient of the coloured experiments. At ``1, 1`` and the scenarios' own rho
    the specs are the scenarios unchanged (the data the ``dataset`` rule writes).
    """
    knobs = cfg["reconstruction"]
    out = {}
    for noise in ("white", "coloured"):
        specs = []
        for name in cfg["experiments"][noise]:
            spec = copy.deepcopy(dict(scenarios[name]))
            spec["noise"] = dict(spec["noise"])
            if float(knobs["noise_scale"]) != 1.0:
                spec["noise"]["sigma"] = float(spec["noise"]["sigma"]) * float(knobs["noise_scale"])
            if spec["noise"].get("colour") == "ar1":
                spec["noise"]["rho"] = float(knobs["coloured_rho"])
            k = float(knobs["manoeuvre_scale"])
            if k != 1.0:
                for trk in spec["tracks"].values():
                    if "a0" in trk:
                        trk["a0"] = float(trk["a0"]) * k
                    for seg in trk.get("segments", []):
                        if "acc" in seg:
                            seg["acc"] = float(seg["acc"]) * k
            specs.append((name, spec))
        out[noise] = specs
    return out


#: What depends on the published table only (:meth:`AlwagihStudy.memo`), for the last
#: published table seen (``"published"``): the studies of one evaluation share it.
_PRINTED: dict = {}


def _key(x) -> str:
    return json.dumps(x, sort_keys=True, default=str)


#: What the caches of datasets and RMSE arrays below may hold (bytes). A claims job asks
#: for the same datasets and RMSE arrays again and again (every design point and seed set
#: of the robustness and chance judgements). The small config's all fit (1,380 datasets,
#: 22 MB; 21,360 arrays): its claims job went from 16.7 s to 13.6 s, computing each once.
#: The default config's are too many to hold (8,430 distinct datasets of 1.9 MB, 80,840
#: arrays of 4 kB). Its job took 244-249 s before; 222 s with 512 and 256 MB (1.6 GB at
#: its peak), 257 s with 128 and 128 MB (1.1 GB), 201 s with these 128 and 256 MB (1.2 GB):
#: the RMSE arrays are what pays (80,840 computed, against 90,110 under 128 MB), the
#: datasets hardly (8,430 to 9,020 generations either way), 2026-12-02.
DATASET_CACHE_BYTES = 128 * 2**20
RMSE_CACHE_BYTES = 256 * 2**20


@lru_cache_bytes(DATASET_CACHE_BYTES, lambda ds: ds.nbytes)
def _dataset(name: str, spec_json: str):
    return datasets.generate(name, json.loads(spec_json))


@lru_cache_bytes(RMSE_CACHE_BYTES, lambda r: r.nbytes)
def _rmse(name: str, spec_json: str, coord: str, method: str, settings_json: str) -> np.ndarray:
    ds = _dataset(name, spec_json)
    cfg = json.loads(settings_json)
    pred = run_method(method, ds.z[coord], ds.truth_acc[coord][0], ds.dt, ds.noise["sigma"], cfg)
    r = np.asarray(methods.rmse(pred, ds.truth_pos[coord]), float)
    r.setflags(write=False)
    return r


class AlwagihStudy(Study):
    """Everything seed 001's claims and report read, computed lazily from the config
    (``alwagih`` and ``datasets`` sections) and the published tables."""

    doc = "alwagih"

    def memo(self, key, compute, printed: bool = False):
        """``compute()``, once per study under ``key`` (the claims' selections from its
        tables: each is asked for hundreds of times); ``printed=True``: once for every
        study of the same published table (what depends on the printed numbers only, the
        same for each study :func:`abglib.replications.evaluate` makes at another input).
        """
        if printed:
            if _PRINTED.get("published") is not self.published:
                _PRINTED.clear()
                _PRINTED["published"] = self.published
            cache = _PRINTED
        else:
            cache = self.__dict__.setdefault("_memo", {})
        if key not in cache:
            cache[key] = compute()
        return cache[key]

    # ------------------------------------------------------------ the reconstruction
    @cached_property
    def scenarios(self) -> dict:
        return reconstructed_scenarios(self.config["datasets"]["scenarios"], self.cfg)

    def rmse(self, method: str, cfg: Mapping | None = None) -> pd.DataFrame:
        """RMSE (eq 26) of one method on every run, coordinate and experiment (long table:
        noise, experiment, scenario, coord, method, run, rmse); ``cfg`` replaces the
        ``alwagih`` section (the sensitivity sweep)."""
        labels, values = self._runs(method, cfg)
        sizes = [r.size for r in values]
        names = ("noise", "experiment", "scenario", "coord")
        table = {
            k: np.repeat(np.array([lab[i] for lab in labels]), sizes) for i, k in enumerate(names)
        }
        return pd.DataFrame(
            table
            | {
                "method": method,
                "run": np.concatenate([np.arange(n) for n in sizes]),
                "rmse": np.concatenate(values),
            }
        )

    @cached_property
    def _series(self) -> list:
        """``(noise, experiment, scenario, COORD, spec_json)`` of every series, in table order."""
        out = []
        for noise, specs in self.scenarios.items():
            for e, (name, spec) in enumerate(specs, start=1):
                sj = _key(spec)
                out.extend((noise, e, name, c, sj) for c in sorted(spec["tracks"]))
        return out

    def _runs(self, method: str, cfg: Mapping | None = None) -> tuple[list, list]:
        """Labels ``(noise, experiment, scenario, COORD)`` of every series and the RMSE of
        ``method`` on each of its runs (arrays, from the cache), in table order."""
        cfg = self.cfg if cfg is None else cfg
        settings = _key({k: cfg[k] for k in METHOD_SETTINGS[method]})
        labels = [(noise, e, name, c.upper()) for noise, e, name, c, _ in self._series]
        values = [_rmse(name, sj, c, method, settings) for _, _, name, c, sj in self._series]
        return labels, values

    def _means(self, method: str, cfg: Mapping | None, group) -> dict:
        """``{group(label): mean RMSE}`` of ``method`` over the runs of every series whose
        label (``noise, experiment, scenario, COORD``) falls in the group, by pandas' own
        grouped mean (the numbers ``groupby(...).mean()`` of the long table gives: the
        values of a group in table order), without building that table."""
        labels, values = self._runs(method, cfg)
        keys = list(dict.fromkeys(group(lab) for lab in labels))
        code = {k: i for i, k in enumerate(keys)}
        codes = np.repeat([code[group(lab)] for lab in labels], [v.size for v in values])
        means = pd.Series(np.concatenate(values)).groupby(codes, sort=True).mean().to_numpy()
        return dict(zip(keys, means, strict=True))

    def _wide_of(self, cell) -> pd.DataFrame:
        """M1-M5 by series: index (noise, experiment, coord), ``cell(method)`` giving
        ``{(noise, experiment, scenario, COORD): value}``."""
        cols = {m: cell(m) for m in PAPER_METHODS}
        labels = list(cols["M1"])
        index = pd.MultiIndex.from_tuples(
            [(n, e, c) for n, e, _, c in labels], names=["noise", "experiment", "coord"]
        )
        return pd.DataFrame(
            {m: [cols[m][lab] for lab in labels] for m in PAPER_METHODS},
            index=index,
            columns=pd.Index(list(PAPER_METHODS), name="method"),
        )

    @cached_property
    def paper_rmse(self) -> pd.DataFrame:
        return pd.concat([self.rmse(m) for m in PAPER_METHODS], ignore_index=True)

    @cached_property
    def all_rmse(self) -> pd.DataFrame:
        extra = [self.rmse(m) for m in METHODS if m not in PAPER_METHODS]
        return pd.concat([self.paper_rmse, *extra], ignore_index=True)

    @cached_property
    def mc(self) -> pd.DataFrame:
        """Monte Carlo mean RMSE of M1-M5: index (noise, experiment, coord), columns methods
        (the pivot of :attr:`paper_rmse` by its mean, computed from the cached runs)."""
        return self._wide_of(lambda m: self._means(m, None, lambda lab: lab))

    @cached_property
    def real(self) -> pd.DataFrame:
        """RMSE of M1-M5 on the configured realisation (the paper's single run)."""
        run = int(self.cfg["realisation"])

        def cell(m):
            labels, values = self._runs(m)
            return {lab: v[run] for lab, v in zip(labels, values, strict=True)}

        return self._wide_of(cell)

    @cached_property
    def ttests(self) -> pd.DataFrame:
        """Section 7's paired t-tests on the realisation."""
        return paired_ttests(self.real)

    @cached_property
    def summary(self) -> pd.DataFrame:
        return mc_summary(self.all_rmse, float(self.cfg["confidence"]))

    def mean_rmse(self, cfg: Mapping) -> pd.Series:
        """Monte Carlo mean RMSE of M1-M5 averaged over the experiments at ``cfg``,
        indexed (noise, coord, method)."""
        keys, values = [], []
        for m in PAPER_METHODS:
            means = self._means(m, cfg, lambda lab: (lab[0], lab[3]))
            keys.extend((noise, coord, m) for noise, coord in means)
            values.extend(means.values())
        index = pd.MultiIndex.from_tuples(keys, names=["noise", "coord", "method"])
        return pd.Series(values, index=index, name="rmse")

    @cached_property
    def m5_bank(self) -> pd.DataFrame:
        """Monte Carlo mean RMSE of M5 (averaged over the experiments) per bank size K
        (``m5_bank_sizes``, alphas evenly spaced on the configured interval)."""
        rows = []
        for k in self.cfg["m5_bank_sizes"]:
            cfg = dict(
                self.cfg, m5=dict(self.cfg["m5"], alphas=dict(self.cfg["m5"]["alphas"], n=int(k)))
            )
            g = self._means("M5", cfg, lambda lab: (lab[0], lab[3]))
            for (noise, coord), v in g.items():
                rows.append({"noise": noise, "coord": coord, "K": int(k), "M5": float(v)})
        return pd.DataFrame(rows)

    # ------------------------------------------------------------ the printed tables
    @property
    def t12(self) -> pd.DataFrame:
        return self.memo("t12", lambda: printed_t12(self.published), printed=True)

    @property
    def printed_wide(self) -> pd.DataFrame:
        """Printed Tables 1-2: index (noise, experiment, coord), columns M1-M5."""
        return self.memo(
            "printed_wide", lambda: _wide(self.t12, "value")[list(PAPER_METHODS)], printed=True
        )

    @property
    def consistency(self) -> pd.DataFrame:
        return self.memo("consistency", lambda: printed_consistency(self.t12), printed=True)

    @property
    def printed_ttests(self) -> pd.DataFrame:
        """Section 7's paired t-tests on the printed Tables 1-2 themselves."""
        return self.memo("printed_ttests", lambda: paired_ttests(self.printed_wide), printed=True)

    # ------------------------------------------------------------ report tables
    def tracks(self) -> pd.DataFrame:
        """Tracks of the figure experiment (Figures 5-6): one realisation, every method."""
        e = int(self.cfg["figure_experiment"])
        run = int(self.cfg["realisation"])
        frames = []
        for noise, specs in self.scenarios.items():
            name, spec = specs[e - 1]
            ds = _dataset(name, _key(spec))
            for c in ds.coords:
                z = ds.z[c][run : run + 1]
                preds = run_methods(z, ds.truth_acc[c][0], ds.dt, ds.noise["sigma"], self.cfg)
                f = pd.DataFrame(
                    {
                        "noise": noise,
                        "experiment": e,
                        "coord": c.upper(),
                        "t": ds.t,
                        "truth": ds.truth_pos[c][run],
                        "measured": ds.z[c][run],
                    }
                )
                for m in METHODS:
                    f[m] = preds[m][0]
                frames.append(f)
        return pd.concat(frames, ignore_index=True)

    def experiments(self) -> pd.DataFrame:
        """The reconstructed experiments as used (after the reconstruction knobs): noise,
        sampling and the largest acceleration per coordinate with how long it acts."""
        rows = []
        for noise, specs in self.scenarios.items():
            for e, (name, spec) in enumerate(specs, start=1):
                ds = _dataset(name, _key(spec))
                row = {
                    "noise": noise,
                    "experiment": e,
                    "scenario": name,
                    "dt": ds.dt,
                    "n_samples": ds.n_samples,
                    "runs": ds.runs,
                    "sigma": float(spec["noise"]["sigma"]),
                    "rho": float(spec["noise"].get("rho", 0.0)),
                }
                for c in ("x", "y"):
                    acc = np.asarray(ds.truth_acc[c][0], float)
                    row[f"{c}_max_abs_acc"] = float(np.max(np.abs(acc)))
                    row[f"{c}_accelerating_s"] = float(np.sum(np.abs(acc) > 1e-9) * ds.dt)
                rows.append(row)
        return pd.DataFrame(rows)

    def settings(self) -> pd.DataFrame:
        """The methods' settings (config ``alwagih``) as a name/value table for the report."""
        c = self.cfg
        items = {
            "m1_alpha": c["m1_alpha"],
            "m3_w_points": c["m3_w_grid"]["n"],
            "m4_alpha0": c["m4"]["alpha0"],
            "m4_window": c["m4"]["window"],
            "m4_alpha_points": c["m4"]["alpha_grid"]["n"],
            "m4_alpha_low": c["m4"]["alpha_grid"]["start"],
            "m4_alpha_high": c["m4"]["alpha_grid"]["stop"],
            "m5_K": c["m5"]["alphas"]["n"],
            "m5_alpha_low": c["m5"]["alphas"]["start"],
            "m5_alpha_high": c["m5"]["alphas"]["stop"],
            "m5_causal_memory": c["m5"]["causal_memory"],
            "kalman_sigma_a_floor": c["kalman"]["sigma_a_floor"],
            "realisation": c["realisation"],
            "confidence": c["confidence"],
        }
        return pd.DataFrame({"name": list(items), "value": [float(v) for v in items.values()]})

    #: Weights of the transient term in Benedict and Bordner's criterion (below): they
    #: put the optimal alpha between about 0.2 and 0.95, the span of eq 23a's (0, 1].
    BB_WEIGHTS = (1e-3, 1e-2, 0.1, 1.0, 10.0)

    @cached_property
    def benedict_bordner_optima(self) -> pd.DataFrame:
        """Minimisers of Benedict and Bordner's criterion against eq 23b (seed 001, §5.1).

        For each weight ``lam`` of :data:`BB_WEIGHTS`, the gains ``(alpha, beta)``
        minimising ``VRF_pred + lam * D2`` - the steady-state variance of the one-step
        prediction per unit noise variance (:func:`abglib.analysis.vrf`, Lyapunov) plus
        ``lam`` times the sum of squared prediction errors after a unit velocity step
        (``abglib.track`` on the ramp ``z_n = n`` from a zero state, T = 1) - found by
        Nelder-Mead over the stability region, and the beta of eq 23b at that alpha.
        The criterion is the one of the reference the paper cites for eq 23b (Benedict
        and Brodner [1962]); the paper itself says only "the mean square error".
        """
        from scipy.optimize import minimize

        from ...analysis import is_stable, vrf
        from ...gains import Gains

        ramp = np.arange(500, dtype=float)  # the slowest transient (|pole| <= 0.89) is gone

        def cost(p, lam):
            g = Gains(float(p[0]), float(p[1]))
            if not (0.0 < p[0] < 2.0 and p[1] > 0.0) or not is_stable(g):
                return np.inf
            err = ramp - track(ramp, g, outputs=("x_pred",)).x_pred
            return float(vrf(g)["x_pred"]) + lam * float(np.sum(err**2))

        rows = []
        for lam in self.BB_WEIGHTS:
            r = minimize(
                cost,
                [0.5, 0.2],
                args=(lam,),
                method="Nelder-Mead",
                options={"xatol": 1e-10, "fatol": 1e-14, "maxiter": 4000},
            )
            a, b = (float(v) for v in r.x)
            b23 = float(design.benedict_bordner(a).beta) if a <= 1.0 else np.nan
            rows.append(
                {"weight": lam, "alpha": a, "beta": b, "beta_eq23b": b23, "rel_gap": b / b23 - 1}
            )
        return pd.DataFrame(rows)

    def tables(self) -> dict[str, pd.DataFrame]:
        one = self.all_rmse[self.all_rmse["run"] == int(self.cfg["realisation"])]
        real_all = _wide(one, "rmse")[list(METHODS)]
        mc_all = _wide(self.summary, "mean")[list(METHODS)]
        out = {
            "table1": real_all.xs("white", level="noise").reset_index(),
            "table2": real_all.xs("coloured", level="noise").reset_index(),
            "mc_rmse": self.summary,
        }
        diffs, pcs = [], []
        for label, wide in (("realisation", self.real), ("monte_carlo", self.mc)):
            d = paper_differences(wide)
            d.insert(0, "basis", label)
            diffs.append(d)
            p = paper_percentages(wide)
            p.insert(0, "basis", label)
            pcs.append(p)
        d = paper_differences(self.printed_wide)
        d.insert(0, "basis", "printed_tables_1_2")
        diffs.append(d)
        out["tables34"] = pd.concat(diffs, ignore_index=True)
        tests = []
        for label, t in (("realisation", self.ttests), ("printed_tables_1_2", self.printed_ttests)):
            t = t.copy()
            t.insert(0, "basis", label)
            tests.append(t)
        out["ttests"] = pd.concat(tests, ignore_index=True)
        out["tables56"] = pd.concat(pcs, ignore_index=True)
        out["consistency"] = self.consistency
        out["causal"] = causal_table(mc_all)
        sens = self.cfg["sensitivity"]
        out["sensitivity"] = sensitivity(self.mean_rmse, self.cfg, sens["alpha0"], sens["window"])
        out["m5_bank"] = self.m5_bank
        out["tracks"] = self.tracks()
        out["experiments"] = self.experiments()
        out["settings"] = self.settings()
        return out


def _wide(table: pd.DataFrame, value: str, aggfunc="first") -> pd.DataFrame:
    return table.pivot_table(
        index=["noise", "experiment", "coord"],
        columns="method",
        values=value,
        sort=False,
        aggfunc=aggfunc,
    )


def causal_table(wide: pd.DataFrame) -> pd.DataFrame:
    """Share of M5's advantage over the best of M1-M4 that the causal M5 keeps (Monte
    Carlo means; beyond the paper)."""
    out = wide.reset_index()[["noise", "experiment", "coord"]].copy()
    best_other = wide[["M1", "M2", "M3", "M4"]].min(axis=1).to_numpy()
    out["best_of_M1_M4"] = best_other
    for m in ("M5", "M5_causal", "kalata_ab", "kalman_ss"):
        out[m] = wide[m].to_numpy()
    gain = best_other - out["M5"].to_numpy()
    out["share_of_M5_advantage_kept"] = np.where(
        gain > 0, (best_other - out["M5_causal"].to_numpy()) / np.where(gain > 0, gain, 1), np.nan
    )
    return out
