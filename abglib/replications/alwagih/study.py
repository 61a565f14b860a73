r"""The simulation study of Al-Wagih & Abdulla (seed 001, sections 6-7) on abglib datasets.

Runs the methods of :mod:`abglib.methods` (M1-M5, the causal M5) and two steady-state
Kalman designs on every experiment, and builds the paper's tables from the RMSEs:

* Tables 1-2: RMSE (eq 26) per experiment, coordinate and method - on one realisation,
  as the paper, and as Monte Carlo means with confidence intervals over all runs;
* Tables 3-4: averages over the experiments of the RMSE differences ``M1 - Mi`` and
  ``M2 - Mi`` (i = 3, 4, 5), with the paired t-test of section 7;
* Tables 5-6: percentage changes with respect to M1 (eq 27).

:func:`printed_consistency` recomputes Tables 3-6 from the *printed* Tables 1-2 (with the
interval their rounding allows), a check of the paper against itself.
"""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np
import pandas as pd

from ... import design, methods
from ..._checks import AbglibValueError
from ...engine import track

__all__ = [
    "BASES",
    "METHODS",
    "PAPER_METHODS",
    "compare_methods",
    "grid",
    "mc_summary",
    "paired_ttests",
    "paper_differences",
    "paper_percentages",
    "printed_consistency",
    "rank_methods",
    "run_methods",
    "sensitivity",
]

#: The paper's five methods, then the causal M5 and the two Kalman designs (beyond it).
PAPER_METHODS = ("M1", "M2", "M3", "M4", "M5")
METHODS = (*PAPER_METHODS, "M5_causal", "kalata_ab", "kalman_ss")
#: Methods the paper compares against (Tables 3-4, rows) and the compared ones (columns).
BASES = ("M1", "M2")
COMPARED = ("M3", "M4", "M5")


def grid(spec: Mapping) -> np.ndarray:
    """Evenly spaced grid ``{start, stop, n}`` (both ends included)."""
    return np.linspace(float(spec["start"]), float(spec["stop"]), int(spec["n"]))


def run_methods(z, truth_acc, dt: float, sigma: float, cfg: Mapping) -> dict:
    """Predictions ``x_pred`` (array like ``z``) of every method of :data:`METHODS`.

    Parameters
    ----------
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
    out = {
        "M1": methods.m1(z, cfg["m1_alpha"], dt).x_pred,
        "M2": methods.m2(z, dt).x_pred,
        "M3": methods.m3(z, grid(cfg["m3_w_grid"]), dt).x_pred,
        "M4": methods.m4(
            z, cfg["m4"]["alpha0"], int(cfg["m4"]["window"]), grid(cfg["m4"]["alpha_grid"]), dt
        ).x_pred,
    }
    bank = grid(cfg["m5"]["alphas"])
    out["M5"] = methods.m5(z, bank, dt).x_pred
    out["M5_causal"] = methods.m5(
        z, bank, dt, causal=True, memory=int(cfg["m5"]["causal_memory"])
    ).x_pred
    sigma_a = max(
        float(np.sqrt(np.mean(np.square(truth_acc)))), float(cfg["kalman"]["sigma_a_floor"])
    )
    for name, gains in (
        ("kalata_ab", design.kalata_ab(sigma_a * dt**2 / sigma)),
        ("kalman_ss", design.steady_state_kalman(sigma_a**2 * dt, sigma**2, dt, 2, "continuous")),
    ):
        out[name] = track(z, gains, dt=dt, init="two_point", outputs=("x_pred",)).x_pred
    return out


def compare_methods(datasets_by_noise: Mapping, cfg: Mapping) -> pd.DataFrame:
    """RMSE (eq 26) of every method, run, coordinate and experiment (long table).

    ``datasets_by_noise``: ``{"white": [Dataset, ...], "coloured": [...]}``, experiments
    numbered 1.. in list order. Columns: noise, experiment, scenario, coord, method, run,
    rmse.
    """
    frames = []
    for noise, dss in datasets_by_noise.items():
        for e, ds in enumerate(dss, start=1):
            for c in ds.coords:
                preds = run_methods(ds.z[c], ds.truth_acc[c][0], ds.dt, ds.noise["sigma"], cfg)
                for m in METHODS:
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
    """Monte Carlo mean RMSE with a Student-t confidence interval over the runs."""
    from scipy import stats

    def agg(g):
        x = g["rmse"].to_numpy()
        n = x.size
        sem = x.std(ddof=1) / np.sqrt(n) if n > 1 else np.nan
        h = stats.t.ppf(0.5 + confidence / 2, n - 1) * sem if n > 1 else np.nan
        return pd.Series(
            {
                "runs": n,
                "mean": x.mean(),
                "std": x.std(ddof=1) if n > 1 else np.nan,
                "ci_low": x.mean() - h,
                "ci_high": x.mean() + h,
            }
        )

    keys = ["noise", "experiment", "coord", "method"]
    return rmse.groupby(keys, sort=False).apply(agg, include_groups=False).reset_index()


def _wide(table: pd.DataFrame, value: str) -> pd.DataFrame:
    return table.pivot_table(
        index=["noise", "experiment", "coord"], columns="method", values=value, sort=False
    )


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
    for (noise, coord), g in rmse_wide.groupby(level=["noise", "coord"], sort=False):
        for base in BASES:
            for m in COMPARED:
                d = (g[base] - g[m]).to_numpy()
                t, p = stats.ttest_rel(g[base].to_numpy(), g[m].to_numpy())
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


def sensitivity(datasets_by_noise: Mapping, cfg: Mapping, alphas, windows) -> pd.DataFrame:
    """How the paper's ranking depends on the settings it does not print.

    For every ``alpha_0`` (used by M1 and as M4's start) and M4 window length: the Monte
    Carlo mean RMSE of M1-M5 averaged over the experiments, per noise and coordinate, the
    ranking, and whether the paper's conclusion "M5, then M4, then M3" holds.
    """
    rows = []
    for a0 in alphas:
        for w in windows:
            c = dict(cfg)
            c["m1_alpha"] = float(a0)
            c["m4"] = dict(cfg["m4"], alpha0=float(a0), window=int(w))
            table = compare_methods(datasets_by_noise, c)
            table = table[table["method"].isin(PAPER_METHODS)]
            means = table.groupby(["noise", "coord", "method"], sort=False)["rmse"].mean()
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


# --------------------------------------------------------------------------- the printed
def _interval(f, values, half_units):
    """Range of ``f`` over the box ``values +- half_units`` (f monotone in each input)."""
    values = np.asarray(values, float)
    h = np.asarray(half_units, float)
    corners = np.array(np.meshgrid(*[[-1.0, 1.0]] * values.size)).reshape(values.size, -1).T
    vals = [f(values + c * h) for c in corners]
    return min(vals), max(vals)


def printed_consistency(t12: pd.DataFrame) -> pd.DataFrame:
    """Tables 3-6 recomputed from the printed Tables 1-2.

    Parameters
    ----------
    t12 : DataFrame
        Columns noise (``white`` = Table 1, ``coloured`` = Table 2), experiment, coord,
        method, value (float as printed), half_unit (half a unit in its last digit).

    Returns
    -------
    DataFrame
        One row per cell of Tables 3-6: table, noise, base/experiment, coord, method,
        ``central`` (from the printed values) and ``low``, ``high``: the range the
        printed rounding of the inputs allows.
    """
    need = {"noise", "experiment", "coord", "method", "value", "half_unit"}
    if not need <= set(t12.columns):
        raise AbglibValueError(f"t12 needs columns {sorted(need)}, got {list(t12.columns)}")
    rows = []
    tables = {"white": (3, 5), "coloured": (4, 6)}
    for noise, (tdiff, tpc) in tables.items():
        sub = t12[t12["noise"] == noise]
        for coord in ("X", "Y"):
            s = sub[sub["coord"] == coord]
            val = s.pivot(index="experiment", columns="method", values="value")
            hu = s.pivot(index="experiment", columns="method", values="half_unit")
            exps = list(val.index)
            for base in BASES:
                for m in COMPARED:
                    v = np.concatenate([val[base].to_numpy(), val[m].to_numpy()])
                    h = np.concatenate([hu[base].to_numpy(), hu[m].to_numpy()])
                    k = len(exps)

                    def f(x, k=k):
                        return float(np.mean(x[:k] - x[k:]))

                    lo, hi = _interval(f, v, h)
                    rows.append(
                        {
                            "table": tdiff,
                            "noise": noise,
                            "row": base,
                            "coord": coord,
                            "method": m,
                            "central": f(v),
                            "low": lo,
                            "high": hi,
                        }
                    )
            for e in exps:
                for m in COMPARED:
                    v = np.array([val.loc[e, "M1"], val.loc[e, m]])
                    h = np.array([hu.loc[e, "M1"], hu.loc[e, m]])

                    def pc(x):
                        return float(methods.percentage_change(x[0], x[1]))

                    lo, hi = _interval(pc, v, h)
                    rows.append(
                        {
                            "table": tpc,
                            "noise": noise,
                            "row": f"experiment {e}",
                            "coord": coord,
                            "method": m,
                            "central": pc(v),
                            "low": lo,
                            "high": hi,
                        }
                    )
    return pd.DataFrame(rows)
